#!/usr/bin/env python3
"""Writes reports/report.md and reports/figures/*.png from the verification drivers'
JSON results (reports/data/*.json). Run by `cmake --build --preset report` (README
command 1); needs numpy and matplotlib (Debian: python3-numpy, python3-matplotlib)."""

import argparse
import datetime
import json
import os
import platform
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

PAPER_TABLE1 = {"N": [1, 9, 64], "castigliano": [-2.028, -2.357, -2.359],
                "reissner": [-2.028, -2.357, -2.359], "lagrange": [-1.446, -2.347, -2.359],
                "exact": -2.359}


def load(data_dir, name):
    path = os.path.join(data_dir, name)
    if not os.path.exists(path):
        return None
    with open(path) as f:
        return json.load(f)


def git_revision(src):
    try:
        return subprocess.run(["git", "-C", src, "rev-parse", "--short", "HEAD"],
                              capture_output=True, text=True, check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


def save(fig, out_dir, name):
    os.makedirs(os.path.join(out_dir, "figures"), exist_ok=True)
    fig.tight_layout()
    fig.savefig(os.path.join(out_dir, "figures", name), dpi=130)
    plt.close(fig)
    return f"figures/{name}"


def degrees_of(case):
    rows = sorted(case["degrees"].values(), key=lambda d: d["degree"])
    return rows


def lame_section(lame, out_dir):
    md = ["## 1. Lame cylinder: RFM against the exact solution", ""]
    md.append("Hollow cylinder under inner/outer pressure with free ends; exact solution "
              "`verification/lame_exact.h` (DESIGN.md section 4.1). RFM on the half section "
              "z in [0, a] with a symmetry plane; N = (p+1)^2 coordinate functions per unknown "
              "component; energies in J per radian for the whole body. Stress error: relative "
              "L2 norm (weight r, Frobenius) on a 4x4-cell, 24-point Gauss rule independent of "
              "the assembly rule; max error on a 41x41 grid including the boundary.")
    md.append("")
    cases = lame["cases"]

    # Table 1 analog.
    paper = cases["paper"]
    rows = degrees_of(paper)
    pick = [r for r in rows if r["N"] in (1, 9, 64, 144, 225, 441)]
    md.append("### 1.1 Table 1 analog (paper cylinder, p_in = 10 MPa, E = 210 GPa, nu = 0.3)")
    md.append("")
    md.append("| N | " + " | ".join(str(r["N"]) for r in pick) + " | exact |")
    md.append("|---|" + "---|" * (len(pick) + 1))
    for key, label in (("castigliano", "Phi_C"), ("reissner", "Phi_R"), ("lagrange", "Phi_L")):
        md.append(f"| {label} [J] | " + " | ".join(f"{r[key]:.6f}" for r in pick) +
                  f" | {paper['exact_functional']:.6f} |")
    md.append("")
    md.append("The paper's Table 1 (its pressures and material are not stated, so only the "
              "behaviour compares): N = 1, 9, 64: Phi_C = Phi_R = -2.028, -2.357, -2.359; "
              "Phi_L = -1.446, -2.347, -2.359; exact -2.359. Ours shows the same pattern: "
              "Phi_C = Phi_R at every N (to rounding), Phi_L above the exact value and "
              "converging from above.")
    md.append("")

    # Convergence table per case.
    md.append("### 1.2 Stress errors, functionals and solver diagnostics per N")
    md.append("")
    for name, case in cases.items():
        g = case["problem"]["geometry"]
        m = case["problem"]["material"]
        l = case["problem"]["loading"]
        md.append(f"**{name}** (`{case['problem_file']}`): R1 = {g['inner_radius']} m, "
                  f"R2 = {g['outer_radius']} m, length {g['length']} m, E = {m['youngs_modulus']:.3g} Pa, "
                  f"nu = {m['poisson_ratio']}, p_in = {l.get('inner_pressure', 0):.3g} Pa, "
                  f"p_out = {l.get('outer_pressure', 0):.3g} Pa; exact Phi = {case['exact_functional']:.8f} J; "
                  f"observed rate {case['decades_per_degree']:.2f} decades of L2 error per degree.")
        md.append("")
        md.append("| p | N | L2 stress err | max stress err | Phi_R [J] | Phi_L [J] | |Phi_R - exact|/|exact| "
                  "| indicator | inf-sup | cond(K) | cond(-R11) | assembly [s] | solve [s] |")
        md.append("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
        for r in degrees_of(case):
            md.append(f"| {r['degree']} | {r['N']} | {r['stress_l2_relative']:.3e} | "
                      f"{r['stress_max_relative']:.3e} | {r['reissner']:.9f} | {r['lagrange']:.9f} | "
                      f"{r['reissner_error_relative']:.2e} | {r['indicator']:.2e} | {r['inf_sup']:.2e} | "
                      f"{r['cond_schur']:.2e} | {r['cond_stress_block']:.2e} | {r['assembly_s']:.4f} | "
                      f"{r['solve_s']:.4f} |")
        md.append("")

    # Fig. 1 analog.
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    r_exact = None
    for prof in paper["profiles_mid"]:
        p = prof["profile"]
        ax.plot(np.array(p["r"]) * 1e3, np.array(p["sigma_rr"]) / 1e6, label=f"RFM, N = {prof['N']}")
        r_exact = p
    ax.plot(np.array(r_exact["r"])[::4] * 1e3, np.array(r_exact["sigma_rr_exact"])[::4] / 1e6, "ko",
            ms=4, label="exact (Lame)")
    ax.set_xlabel("radius r [mm]")
    ax.set_ylabel("radial stress sigma_rr at z = 0 [MPa]")
    ax.set_title("Fig. 1 analog: sigma_rr(r) converging to the Lame solution")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    f1 = save(fig, out_dir, "lame_fig1_sigma_rr.png")

    # Convergence in N.
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    for name, case in cases.items():
        rows = degrees_of(case)
        ax.semilogy([r["N"] for r in rows], [r["stress_l2_relative"] for r in rows], "o-", ms=3,
                    label=f"RFM {name}")
    fem = case_fem_lame(out_dir)
    if fem:
        for deg, rows in fem.items():
            ax.semilogy([r["dofs"] for r in rows], [r["stress_l2_relative"] for r in rows], "s--",
                        ms=3, label=f"FEM Q{deg} (paper case), vs DoFs")
        ax.set_xscale("log")
    ax.set_xlabel("N (coordinate functions per component); FEM: DoFs")
    ax.set_ylabel("relative L2 stress error [-]")
    ax.set_title("Lame cylinder: stress error")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    f2 = save(fig, out_dir, "lame_convergence.png")

    # A-posteriori indicator against the true energy error.
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    for name, case in cases.items():
        rows = [r for r in degrees_of(case) if r["reissner_error_relative"] > 1e-15]
        ax.loglog([r["reissner_error_relative"] for r in rows], [r["indicator"] for r in rows], "o-",
                  ms=3, label=name)
    lims = [1e-16, 1]
    ax.loglog(lims, lims, "k:", lw=1, label="indicator = error")
    ax.set_xlabel("true energy error |Phi_R - Phi_exact| / |Phi_exact| [-]")
    ax.set_ylabel("indicator |Phi_L - Phi_C| / |Phi_R| [-]")
    ax.set_title("A-posteriori estimate against the true error")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    f3 = save(fig, out_dir, "lame_indicator.png")

    # Timings.
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    rows = degrees_of(paper)
    n = np.array([r["N"] for r in rows], float)
    for key, label in (("assembly_s", "assembly"), ("solve_s", "solve (incl. eigen diagnostics)")):
        t = np.array([r[key] for r in rows])
        ok = (n >= 64) & (t > 0)
        ax.loglog(n, np.maximum(t, 1e-6), "o-", ms=3, label=label)
        if ok.sum() >= 2:
            k, c = np.polyfit(np.log(n[ok]), np.log(t[ok]), 1)
            ax.loglog(n[ok], np.exp(c) * n[ok] ** k, "k:", lw=1)
            ax.annotate(f"slope {k:.2f}", (n[ok][-1], t[ok][-1]), fontsize=8)
    ax.set_xlabel("N (coordinate functions per component)")
    ax.set_ylabel("wall time [s]")
    ax.set_title("RFM time against N (paper cylinder, 1 thread)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    f4 = save(fig, out_dir, "lame_timing.png")

    # Stresses along the end z = a.
    end = paper["profile_end_p7"]
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    for key in ("sigma_rr", "sigma_zz", "sigma_tt", "sigma_rz"):
        ax.plot(np.array(end["r"]) * 1e3, np.array(end[key]) / 1e6, label=f"RFM {key}, N = 64")
        ax.plot(np.array(end["r"])[::5] * 1e3, np.array(end[key + "_exact"])[::5] / 1e6, "k.", ms=3)
    ax.set_xlabel("radius r [mm]")
    ax.set_ylabel("stress at the free end z = a [MPa]")
    ax.set_title("Stresses along the end (dots: exact)")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    f5 = save(fig, out_dir, "lame_end_stresses.png")

    md += [f"![Fig. 1 analog]({f1})", "", f"![convergence]({f2})", "", f"![indicator]({f3})", "",
           f"![timing]({f4})", "", f"![end stresses]({f5})", ""]
    return md


def die_section(die, out_dir):
    md = ["## 2. Die contact: the paper's problem", ""]
    prob = die["problem"]
    g, m, d = prob["geometry"], prob["material"], prob["die"]
    a = 0.5 * g["length"]
    md.append(f"Cylinder R1 = {g['inner_radius']} m, R2 = {g['outer_radius']} m, length {g['length']} m, "
              f"E = {m['youngs_modulus']:.3g} Pa, nu = {m['poisson_ratio']}, smooth parabolic die on r = R2 "
              f"with delta = {d['indentation']:.3g} m (`{die['problem_file']}`). P is the contact force of the "
              "full body [N]: `force` is the domain integral (DESIGN.md 4.3), `trace` is eq. 4.6. Functionals in "
              "J per radian. Contact check: 2001 points along r = R2.")
    md.append("")

    # Iteration 0.
    md.append("### 2.1 Iteration 0 (c = a, bilateral) against the paper")
    md.append("")
    md.append("| p | N | P [kN] | P trace [kN] | Phi_C [J] | Phi_R [J] | Phi_L [J] |")
    md.append("|---|---|---|---|---|---|---|")
    for key, r in sorted(die["iteration0"].items(), key=lambda kv: int(kv[0][1:])):
        p = int(key[1:])
        md.append(f"| {p} | {(p+1)**2} | {r['force']/1e3:.3f} | {r['force_trace']/1e3:.3f} | "
                  f"{r['castigliano']:.6f} | {r['reissner']:.6f} | {r['lagrange']:.6f} |")
    md.append("| paper | | 128.7 | | 0.0176 | 0.0176 | 0.0176 |")
    md.append("")

    # Runs.
    md.append("### 2.2 The unknown zone: c and P per method, N and quadrature")
    md.append("")
    md.append("`iterate`: the paper's successive iterations from c = a, bracketed, then bisection for both "
              "ends of the interval of c on which conditions 1.2 (no tension) and 1.3 (no penetration) hold at "
              "this N; c is its midpoint. `max-force`: golden-section maximum of P(c) (Barber).")
    md.append("")
    md.append("| method | p | N | quadrature | c/a | interval c/a | P [kN] | P trace [kN] | Phi_C [J] | Phi_R [J] | "
              "Phi_L [J] | solves | time [s] |")
    md.append("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for key, r in die["runs"].items():
        f = r["final"]
        rng = r.get("half_width_range_ratio")
        rng = f"[{rng[0]:.4f}, {rng[1]:.4f}]" if rng else "-"
        md.append(f"| {r['method']} | {r['degree']} | {r['N']} | {r['quadrature']} | {f['half_width_ratio']:.4f} | "
                  f"{rng} | {f['force']/1e3:.3f} | {f['force_trace']/1e3:.3f} | {f['castigliano']:.6f} | "
                  f"{f['reissner']:.6f} | {f['lagrange']:.6f} | {r['n_solves']} | {r['seconds']:.2f} |")
    md.append("| paper | | | | 0.543 | claims 11.6 % | 195.2 | | 0.0135 | 0.0132 | 0.0133 | | |")
    md.append("")
    md.append("Stability (absolute change of c/a, relative change of P): `" + json.dumps(die["stability"]) + "`; "
              "doubling delta: `" + json.dumps(die["delta_scaling"]) + "`.")
    md.append("")

    # Tables 2 and 3 analog: the paper-style iterations of the report's run.
    key = max((k for k in die["runs"] if k.startswith("iterate_p") and "quad2" not in k),
              key=lambda k: int(k.split("_p")[1]))
    hist = [h for h in die["runs"][key]["history"] if h["phase"] in ("iteration", "final")]
    md.append(f"### 2.3 Tables 2 and 3 analog (`{key}`, the paper's values beside)")
    md.append("")
    md.append("| step | phase | c/a | P [kN] | P trace [kN] | Phi_C [J] | Phi_R [J] | Phi_L [J] | 1.2 and 1.3 hold |")
    md.append("|---|---|---|---|---|---|---|---|---|")
    for i, h in enumerate(hist):
        md.append(f"| {i} | {h['phase']} | {h['half_width_ratio']:.4f} | {h['force']/1e3:.2f} | {h['force_trace']/1e3:.2f} | "
                  f"{h['castigliano']:.5f} | {h['reissner']:.5f} | {h['lagrange']:.5f} | {h['conditions_hold']} |")
    t2, t3 = die["paper"]["table2"], die["paper"]["table3"]
    md.append("")
    md.append("Paper, Table 2 (iterations " + ", ".join(map(str, t2["iteration"])) + "): Phi_C " +
              ", ".join(map(str, t2["castigliano"])) + "; Phi_R " + ", ".join(map(str, t2["reissner"])) +
              "; Phi_L " + ", ".join(map(str, t2["lagrange"])) + ". Table 3 (iterations 0-5, 5 = check at "
              "c = 0.48 a): P = " + ", ".join(map(str, t3["force_kN"])) + " kN; final c = 0.543 a.")
    md.append("")

    # Fig. 3 analog.
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    for i, pj in enumerate(die.get("pressure_per_iteration", [])):
        ax.plot(np.array(pj["z"]) / a, np.array(pj["p"]) / 1e6,
                label=f"{pj['phase']} {i}: c = {pj['half_width']/a:.3f} a")
    ax.axhline(0, color="k", lw=0.8)
    ax.set_xlabel("z / a [-]")
    ax.set_ylabel("contact pressure p = -sigma_rr(R2, z) [MPa]")
    ax.set_title("Fig. 3 analog: contact pressure per iteration (RFM)")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7)
    f1 = save(fig, out_dir, "die_fig3_pressure.png")

    # P(c).
    curve = die["force_curve"]
    cc = np.array([c["half_width_ratio"] for c in curve])
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    ax.plot(cc, np.array([c["force"] for c in curve]) / 1e3, "o-", ms=3, label="P(c), domain integral")
    ax.plot(cc, np.array([c["force_trace"] for c in curve]) / 1e3, "s--", ms=3, label="P(c), trace (eq. 4.6)")
    fin = die["runs"][key]["final"]
    rng = die["runs"][key].get("half_width_range_ratio")
    if rng:
        ax.axvspan(rng[0], rng[1], color="g", alpha=0.12, label="1.2 and 1.3 hold")
    ax.axvline(fin["half_width_ratio"], color="g", lw=1, label=f"iterate: c = {fin['half_width_ratio']:.3f} a")
    mf = die["runs"][key.replace("iterate", "max-force")]["final"]
    ax.plot([mf["half_width_ratio"]], [mf["force"] / 1e3], "r*", ms=10,
            label=f"max-force: c = {mf['half_width_ratio']:.3f} a, P = {mf['force']/1e3:.1f} kN")
    ax.plot([0.543], [195.2], "kx", ms=8, label="paper: 0.543 a, 195.2 kN")
    ax.set_xlabel("contact half-width c / a [-]")
    ax.set_ylabel("contact force P [kN]")
    ax.set_title("P(c) of the bilateral problem (p = 12, N = 169)")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7)
    f2 = save(fig, out_dir, "die_force_curve.png")

    # c and P against N.
    fig, axs = plt.subplots(1, 2, figsize=(9.6, 4.0))
    for method, mk in (("iterate", "o-"), ("max-force", "s--")):
        rows = sorted((r for r in die["runs"].values() if r["method"] == method and r["quadrature"] == "default"),
                      key=lambda r: r["N"])
        axs[0].plot([r["N"] for r in rows], [r["final"]["half_width_ratio"] for r in rows], mk, ms=4, label=method)
        axs[1].plot([r["N"] for r in rows], [r["final"]["force"] / 1e3 for r in rows], mk, ms=4, label=method)
    axs[0].set_xlabel("N"); axs[0].set_ylabel("c / a [-]"); axs[0].grid(True, alpha=0.3); axs[0].legend(fontsize=8)
    axs[1].set_xlabel("N"); axs[1].set_ylabel("P [kN]"); axs[1].grid(True, alpha=0.3); axs[1].legend(fontsize=8)
    fig.suptitle("Contact half-width and force against N (RFM)")
    f3 = save(fig, out_dir, "die_convergence.png")

    # sigma_rr through the thickness.
    f4 = None
    if "sigma_rr_mid" in die:
        s = die["sigma_rr_mid"]
        fig, ax = plt.subplots(figsize=(6.4, 4.4))
        ax.plot(np.array(s["r"]) * 1e3, np.array(s["sigma_rr"]) / 1e6, label=f"RFM, p = {s['degree']}")
        ax.set_xlabel("radius r [mm]")
        ax.set_ylabel("sigma_rr at z = 0 [MPa]")
        ax.set_title("Radial stress through the thickness at z = 0 (converged zone)")
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=8)
        f4 = save(fig, out_dir, "die_sigma_rr_mid.png")
    md += [f"![Fig. 3 analog]({f1})", "", f"![P(c)]({f2})", "", f"![c and P against N]({f3})", ""]
    if f4:
        md += [f"![sigma_rr]({f4})", ""]
    return md


def case_fem_lame(out_dir):
    fem = load(os.path.join(out_dir, "data"), "fem_lame_convergence.json")
    if not fem:
        return None
    return {k: v for k, v in fem.get("degrees", {}).items()}


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--data", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--build-config", required=True)
    args = ap.parse_args()

    with open(args.build_config) as f:
        config = json.load(f)
    lame = load(args.data, "lame_cylinder.json")
    die = load(args.data, "die_contact.json")
    if lame is None and die is None:
        print("make_report: no verification case is registered yet (no data in "
              f"{args.data})")

    md = ["# RFM / Reissner verification report", "",
          "Generated by README command (1) (`cmake --workflow --preset report`); do not edit by hand.", ""]
    md.append("## 0. Configuration of this run")
    md.append("")
    md.append(f"* generated: {datetime.datetime.now(datetime.timezone.utc).strftime('%Y-%m-%d %H:%M UTC')}, "
              f"git revision `{git_revision(os.path.dirname(os.path.abspath(args.out)))}`")
    for k, v in config.items():
        md.append(f"* {k}: `{v}`")
    md.append(f"* machine: `{platform.machine()}`, {os.cpu_count()} cores; Python {platform.python_version()}, "
              f"numpy {np.__version__}, matplotlib {matplotlib.__version__}")
    for d in (lame, die):
        if d:
            md.append(f"* driver `{d['driver']}` in mode `{d['mode']}`; the problem files it read are "
                      "echoed in `reports/data/*.json`")
    md.append("")
    if lame:
        md += lame_section(lame, args.out)
    if die:
        md += die_section(die, args.out)

    tmp = os.path.join(args.out, "report.md.tmp")
    with open(tmp, "w") as f:
        f.write("\n".join(md) + "\n")
    os.replace(tmp, os.path.join(args.out, "report.md"))
    print(f"make_report: wrote {os.path.join(args.out, 'report.md')}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
