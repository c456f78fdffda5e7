#!/usr/bin/env python3
"""The FEM reference at scale (issue 25): adaptive against uniform refinement, and wall time and
memory against dofs on one and two MPI processes.

Runs build/bin/fem_solve (serially, and under the MPI launcher with -np 1 and 2) on three
problem files of verification/problems and writes one JSON file for the report
(reports/make_report.py, section "The FEM reference at scale"):

* the paper's die (die_paper.json): the contact force P, uniform levels 1-5 and the energy-
  adaptive cycles from level 1 (tolerance 1e-8); the reference is uniform level 6 (1.36 M dofs,
  under mpirun);
* the thick sphere (sphere_thick.json): the energy against its closed form (Lame's sphere),
  uniform levels 0-6 and the adaptive cycles from level 0;
* the filleted groove (filleted_groove_shaft_tension.json): K_t = sigma_zz at the groove's root
  over the net-section stress, uniform levels 0-3 and goal-oriented adaptive runs (the samples'
  stresses, tolerance 1e-7) and energy-adaptive (1e-8) cycles from level 0 (at most 2e5 dofs);
  the reference is the Richardson extrapolation of
  uniform levels 1-3 with their observed order.

Every run records dofs, processes, the linear solver, assembly and solve times [s], the wall
time of the whole command [s] and the peak memory summed over the processes [bytes].

    python3 benchmarks/fem_scaling.py --fem-solve build/bin/fem_solve \\
        --mpirun "mpirun --allow-run-as-root --oversubscribe" --out reports/data/fem_scaling.json

Run by `cmake --build --preset benchmarks` (target run_benchmarks); about 10 minutes on the
project's 2-core machine. Timings are only comparable within one run.
"""
import argparse
import datetime
import json
import math
import os
import shlex
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
PROBLEMS = os.path.join(HERE, "..", "verification", "problems")


def run(args, fem_solve, mpirun, np_, extra):
    """fem_solve on PROBLEM with `extra` arguments; np_ = 0: serial. The result JSON plus the
    command's wall time."""
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "result.json")
        cmd = ([] if np_ == 0 else shlex.split(mpirun) + ["-np", str(np_)]) + [fem_solve] + extra + [
            "--output", out]
        t0 = time.monotonic()
        proc = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        wall = time.monotonic() - t0
        if proc.returncode != 0:
            sys.exit(f"fem_scaling: {' '.join(cmd)} exited {proc.returncode}:\n{proc.stderr[-2000:]}")
        with open(out) as f:
            result = json.load(f)
    result["wall_s"] = wall
    print(f"fem_scaling: np {np_ or 'serial'} {' '.join(extra[1:])}: {result['discretization']['dofs']} dofs, "
          f"{wall:.1f} s", file=sys.stderr, flush=True)
    return result


def record(result, value):
    d, t = result["discretization"], result["timing"]
    return {"dofs": d["dofs"], "cells": d["cells"], "processes": d.get("processes", 1),
            "linear_solver": d.get("linear_solver"), "linear_iterations": d.get("linear_iterations", 0),
            "assembly_s": t["assembly_s"], "solve_s": t["solve_s"], "wall_s": result["wall_s"],
            "peak_memory_bytes": t.get("peak_memory_bytes_all_processes", t.get("peak_memory_bytes")),
            "value": value}


def sphere_energy():
    """Lame's thick sphere of sphere_thick.json: the Lagrange functional per radian of the
    modelled hemisphere, -W/2 with W = p_a u(a) a^2 - p_b u(b) b^2."""
    with open(os.path.join(PROBLEMS, "sphere_thick.json")) as f:
        p = json.load(f)
    e, nu = p["material"]["youngs_modulus"], p["material"]["poisson_ratio"]
    a, b = 0.1, 0.2
    pa, pb = p["boundary"]["inner"]["pressure"], p["boundary"]["outer"]["pressure"]
    big_b = (pa - pb) / (2 * (1 / a**3 - 1 / b**3))
    big_a = -pb + 2 * big_b / b**3
    u = lambda r: r / e * ((1 - 2 * nu) * big_a + (1 + nu) * big_b / r**3)
    return -(pa * u(a) * a**2 - pb * u(b) * b**2) / 2


def groove_kt(result):
    # Net-section stress t R^2 / (R - depth)^2: R = 0.05 m, root at r = 0.04 m, t = 10 MPa.
    net = 1e7 * 0.05**2 / 0.04**2
    return result["samples"][0]["sigma_zz"] / net


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--fem-solve", required=True)
    ap.add_argument("--mpirun", required=True, help="the launcher and its flags, without -np")
    ap.add_argument("--out", required=True)
    ap.add_argument("--cases", default="die,sphere,groove",
                    help="comma-separated subset; the others are kept from an existing --out file")
    args = ap.parse_args()
    cases = set(args.cases.split(","))
    fs, mr = args.fem_solve, args.mpirun
    prob = lambda name: os.path.join(PROBLEMS, name + ".json")
    data = {"date": datetime.datetime.now(datetime.timezone.utc).isoformat(timespec="seconds"),
            "cores": os.cpu_count(), "cases": {}}
    if cases != {"die", "sphere", "groove"} and os.path.exists(args.out):
        with open(args.out) as f:
            old = json.load(f)
        data["cases"] = old["cases"]
        data["date"] = old["date"] + ", " + args.cases + " " + data["date"]

    # 1. The paper's die: P.
    if "die" in cases:
        run_die(args, fs, mr, prob, data)
    if "sphere" in cases:
        run_sphere(args, fs, mr, prob, data)
    if "groove" in cases:
        run_groove(args, fs, mr, prob, data)
    write(args, data)


def run_die(args, fs, mr, prob, data):
    die = {"quantity": "P [N]", "uniform": {}, "adaptive": []}
    for np_ in (0, 1, 2):
        die["uniform"][str(np_)] = [record(r, r["contact"]["force"]) for r in
                                    (run(args, fs, mr, np_, [prob("die_paper"), "--refinements", str(level)])
                                     for level in range(1, 6))]
    ref = run(args, fs, mr, 2, [prob("die_paper"), "--refinements", "6"])
    die["reference"] = {"value": ref["contact"]["force"],
                        "what": "uniform level 6 on 2 processes (P moves in steps where the smallest contact "
                                "face halves: kappa = 1e3 E / h_min doubles, and below about 1e-7 the "
                                "differences are the penalty's rather than the mesh's)",
                        "dofs": ref["discretization"]["dofs"]}
    for np_ in (0, 2):
        ad = run(args, fs, mr, np_, [prob("die_paper"), "--refinements", "1", "--adaptive",
                                     "--adaptive-tolerance", "1e-8"])
        die["adaptive"].append({"processes": max(np_, 1), "wall_s": ad["wall_s"],
                                "cycles": [{"dofs": c["dofs"], "value": c["force"], "estimate": c["estimate"]}
                                           for c in ad["discretization"]["adaptive"]["cycles"]]})
    data["cases"]["die"] = die


def run_sphere(args, fs, mr, prob, data):
    """2. The thick sphere: the energy against the closed form."""
    exact = sphere_energy()
    sph = {"quantity": "Phi_L [J/rad]", "uniform": {}, "adaptive": [],
           "reference": {"value": exact, "what": "closed form (Lame's thick sphere)"}}
    for np_ in (0, 1, 2):
        levels = range(0, 6) if np_ == 0 else range(0, 7)
        sph["uniform"][str(np_)] = [record(r, r["functionals"]["lagrange"]) for r in
                                    (run(args, fs, mr, np_, [prob("sphere_thick"), "--refinements", str(level)])
                                     for level in levels)]
    for np_ in (0, 2):
        ad = run(args, fs, mr, np_, [prob("sphere_thick"), "--refinements", "0", "--adaptive",
                                     "--adaptive-tolerance", "1e-12", "--max-dofs", "400000"])
        # Phi_L = -U for this load: the cycles record Phi_R, which equals Phi_L to rounding here.
        sph["adaptive"].append({"processes": max(np_, 1), "wall_s": ad["wall_s"],
                                "cycles": [{"dofs": c["dofs"], "value": c["reissner"], "estimate": c["estimate"]}
                                           for c in ad["discretization"]["adaptive"]["cycles"]]})
    data["cases"]["sphere"] = sph


def run_groove(args, fs, mr, prob, data):
    """3. The filleted groove: K_t."""
    grv = {"quantity": "K_t", "uniform": {}, "adaptive": []}
    for np_ in (1, 2):
        grv["uniform"][str(np_)] = [record(r, groove_kt(r)) for r in
                                    (run(args, fs, mr, np_, [prob("filleted_groove_shaft_tension"),
                                                             "--refinements", str(level)])
                                     for level in range(0, 4))]
    k = [row["value"] for row in grv["uniform"]["2"][1:4]]  # levels 1, 2, 3
    order = math.log(abs((k[0] - k[1]) / (k[1] - k[2])), 2)
    grv["reference"] = {"value": k[2] + (k[2] - k[1]) / (2**order - 1),
                        "what": f"Richardson extrapolation of uniform levels 1-3 (observed order {order:.2f} in h)"}
    kt_per_pa = groove_kt({"samples": [{"sigma_zz": 1.0}]})  # K_t of sigma_zz = 1 Pa
    for goal, tol in (("samples", "1e-7"), ("energy", "1e-8")):
        # From level 0: a cycle refines the few cells that carry half the squared estimate,
        # so that from level 1 (83 k dofs) it takes hundreds of cycles to double the dofs.
        ad = run(args, fs, mr, 2, [prob("filleted_groove_shaft_tension"), "--refinements", "0", "--adaptive",
                                   "--adaptive-goal", goal, "--adaptive-tolerance", tol, "--max-dofs", "200000"])
        grv["adaptive"].append({"processes": 2, "goal": goal, "wall_s": ad["wall_s"],
                                "stopped": ad["discretization"]["adaptive"]["stopped"],
                                "cycles": [{"dofs": c["dofs"], "value": c["samples"][0]["sigma_zz"] * kt_per_pa,
                                            "estimate": c["estimate"]}
                                           for c in ad["discretization"]["adaptive"]["cycles"]]})
    data["cases"]["groove"] = grv


def write(args, data):
    os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
    tmp = args.out + ".tmp"
    with open(tmp, "w") as f:
        json.dump(data, f, indent=1)
    os.replace(tmp, args.out)
    print(f"fem_scaling: wrote {args.out}", file=sys.stderr)


if __name__ == "__main__":
    main()
