#!/usr/bin/env python3
"""What a user gets without flags (issue 24 item 6: "the drivers and the report show it").

Runs `rfm_solve FILE` and `fem_solve FILE`, with no option but --output, on every problem file
of verification/problems, and records for each solver its exit status, wall time, the
discretization it chose (the RFM's degree and policy, the FEM's dofs), the indicator, the
diagnostics' status with the checks that raised a warning (`diagnostics.warnings`), or the
failure's message, and the samples. Where both give samples, the largest difference of a
stress component over the samples, relative to the largest |stress| of the FEM's samples
(samples at vertices, which have no value, left out). One JSON file for the report
(reports/make_report.py, section 11):

    python3 verification/defaults.py --rfm-solve build/bin/rfm_solve \\
        --fem-solve build/bin/fem_solve --out reports/data/defaults.json

Run by README command (1) (reports/CMakeLists.txt, step `defaults`). A run that takes longer
than --timeout seconds (120) is stopped and reported as such. Exit status 1 when a solver
crashes or exits with a status other than 0 (a result) or 3 (a numerical failure, said), or
writes no result: every problem file of the repository must be accepted (no exit 2).
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
STRESSES = ("sigma_rr", "sigma_zz", "sigma_tt", "sigma_rz")


def run(solver, problem, timeout):
    """The solver on the problem file at its defaults: (exit status, or None when it ran past
    `timeout` seconds and was stopped; wall time [s]; the result JSON or None; the last line of
    stderr)."""
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "result.json")
        t0 = time.monotonic()
        try:
            proc = subprocess.run([solver, problem, "--output", out], stdout=subprocess.DEVNULL,
                                  stderr=subprocess.PIPE, text=True, timeout=timeout)
        except subprocess.TimeoutExpired as e:
            stderr = e.stderr.decode() if isinstance(e.stderr, bytes) else (e.stderr or "")
            lines = [line for line in stderr.splitlines() if line.strip()]
            return None, time.monotonic() - t0, None, lines[-1] if lines else ""
        wall = time.monotonic() - t0
        result = None
        if os.path.exists(out):
            with open(out) as f:
                result = json.load(f)
    lines = [line for line in proc.stderr.splitlines() if line.strip()]
    return proc.returncode, wall, result, lines[-1] if lines else ""


def summary(exit_status, wall, result, last_line):
    """The record of one run: what the report shows."""
    record = {"exit": exit_status, "wall_s": wall}
    if exit_status is None:
        record["message"] = f"stopped after {wall:.0f} s (the report's limit); its last line: {last_line}"
        return record
    if result is None:
        record["message"] = last_line
        return record
    d = result.get("diagnostics", {})
    record["status"] = d.get("status")
    record["message"] = d.get("message", "")
    record["checks"] = [w["check"] for w in d.get("warnings", [])]
    disc = result.get("discretization", {})
    for key in ("degree", "degree_policy", "dofs", "N", "unknowns"):
        if key in disc:
            record[key] = disc[key]
    if "functionals" in result:
        record["reissner"] = result["functionals"].get("reissner")
        record["indicator"] = result["functionals"].get("indicator")
    at_vertices = {(s["r"], s["z"]) for s in d.get("samples_at_vertices", [])}
    record["samples"] = [{k: s[k] for k in ("r", "z") + STRESSES if k in s}
                         for s in result.get("samples", []) if (s["r"], s["z"]) not in at_vertices]
    return record


def sample_difference(rfm, fem):
    """max |rfm - fem| over the samples and stress components / max |fem stress|; None when
    either has none."""
    a, b = rfm.get("samples", []), fem.get("samples", [])
    if not a or len(a) != len(b):
        return None
    scale = max(abs(s[c]) for s in b for c in STRESSES)
    if scale == 0.0:
        return None
    return max(abs(x[c] - y[c]) for x, y in zip(a, b) for c in STRESSES) / scale


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--rfm-solve", required=True)
    ap.add_argument("--fem-solve", required=True)
    ap.add_argument("--problems", default=os.path.join(HERE, "problems"))
    ap.add_argument("--out", required=True)
    ap.add_argument("--timeout", type=float, default=120.0,
                    help="seconds a run may take before it is stopped and reported as such (default 120)")
    args = ap.parse_args()

    cases = {}
    bad = []
    for name in sorted(os.listdir(args.problems)):
        if not name.endswith(".json"):
            continue
        problem = os.path.join(args.problems, name)
        case = {}
        for solver, path in (("rfm", args.rfm_solve), ("fem", args.fem_solve)):
            exit_status, wall, result, last = run(path, problem, args.timeout)
            case[solver] = summary(exit_status, wall, result, last)
            if exit_status is not None and (exit_status not in (0, 3) or result is None):
                bad.append(f"{solver} on {name}: exit {exit_status}, {'no result' if result is None else ''} {last}")
            print(f"defaults: {name}: {solver} exit {exit_status} in {wall:.1f} s, "
                  f"{case[solver].get('status')}", file=sys.stderr, flush=True)
        if case["rfm"]["exit"] == 0 and case["fem"]["exit"] == 0 and "samples" in case["rfm"]:
            case["samples_rfm_vs_fem"] = sample_difference(case["rfm"], case["fem"])
        cases[name] = case
    out = {"driver": "defaults", "mode": "full", "threads": 1, "timeout_s": args.timeout,
           "environment": {k: os.environ[k] for k in ("OPENBLAS_NUM_THREADS", "DEAL_II_NUM_THREADS")
                           if k in os.environ},
           "cases": cases}
    os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
    tmp = args.out + ".tmp"
    with open(tmp, "w") as f:
        json.dump(out, f, indent=1)
    os.replace(tmp, args.out)
    if bad:
        print("defaults: FAIL\n  " + "\n  ".join(bad), file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
