#!/usr/bin/python3
"""Figures and table of the rat-aorta example against the thin-tube closed form.

Usage: /usr/bin/python3 tools/figures/rat_aorta_figures.py RESULT_DIR OUT_DIR

Reads RESULT_DIR/history.csv and RESULT_DIR/newton.csv written by
`tunica run examples/rat-aorta-inflation.yaml -o RESULT_DIR` and writes to OUT_DIR:

  rat-aorta-fig1.png   S_theta vs E_theta (analogue of Holzapfel et al. 1996, Fig. 1)
  rat-aorta-fig2.png   S_z vs E_theta (analogue of Fig. 2)
  rat-aorta-table1.md  Newton residuals of the increments 90->100 and 100->110 mmHg
                       (analogue of Table 1) with two estimates of the convergence order

and prints the largest relative differences between the finite element values
and the closed form over the inflation increments.

The closed form (theory manual (8.1)) is computed here, independently of the C++ code:
at fixed axial stretch lambda_z, equilibrium of a thin tube gives
S_theta = p R lambda_z / H; Fung's two-dimensional law (theory manual (3.2))
S1 = 2c (a1 E1 + a4 E2) e^Q is then solved for E1 = E_theta by bisection.
"""

import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

# Example data (theory manual §12.1; examples/rat-aorta-inflation.yaml), SI-derived units kPa and mm.
C_KPA = 61.163  # c = 0.61163e5 Pa
A1, A2, A4 = 0.68238, 0.60558, 0.1067
R_MM = 0.763  # mid-surface radius (D - H)/2
H_MM = 0.122  # wall thickness
LAMBDA_Z = 1.6
E_Z = 0.5 * (LAMBDA_Z**2 - 1.0)
# 1 mmHg as UDUNITS-2 defines it (the unit Tunica converts with): 1 mm x 13595.10 kg/m^3 x 9.80665 m/s^2.
MMHG_KPA = 1e-3 * 13595.10 * 9.80665 * 1e-3
P_MAX_MMHG = 200.0

INFLATION_STEP = 2
TABLE_INCREMENTS = ((10, "90 → 100 mmHg"), (11, "100 → 110 mmHg"))
ROUNDOFF = 1e-13  # relative residuals below this are round-off

LEGEND_FE = "Tunica FE (1 element)"
LEGEND_CF = "closed form (thin tube)"


def fung_q(e1, e2):
    return A1 * e1 * e1 + A2 * e2 * e2 + 2.0 * A4 * e1 * e2


def fung_s1(e1, e2=E_Z):
    """Circumferential 2nd Piola-Kirchhoff stress (kPa), theory manual (3.2) / paper eq. (25)."""
    return 2.0 * C_KPA * (A1 * e1 + A4 * e2) * np.exp(fung_q(e1, e2))


def fung_s2(e1, e2=E_Z):
    """Axial 2nd Piola-Kirchhoff stress (kPa), theory manual (3.2) / paper eq. (25)."""
    return 2.0 * C_KPA * (A4 * e1 + A2 * e2) * np.exp(fung_q(e1, e2))


def hoop_stress_closed_form(p_kpa):
    """Thin tube at fixed lambda_z: p r = sigma_theta h  =>  S_theta = p R lambda_z / H."""
    return p_kpa * R_MM * LAMBDA_Z / H_MM


def solve_e_theta(s_target):
    """E1 with S1(E1, E_Z) = s_target, by bisection (S1 increases with E1: dS1/dE1 = D11 > 0)."""
    lo = -A4 * E_Z / A1  # S1 = 0: the prestretched state at p = 0
    if s_target <= 0.0:
        return lo
    hi = lo + 0.1
    while fung_s1(hi) < s_target:
        hi += 2.0 * (hi - lo)
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if fung_s1(mid) < s_target:
            lo = mid
        else:
            hi = mid
        if hi - lo <= 4e-16 * max(1.0, abs(mid)):
            break
    return 0.5 * (lo + hi)


def read_csv(path):
    try:
        with open(path, newline="") as f:
            rows = list(csv.DictReader(f))
    except OSError as e:
        sys.exit(f"{path}: {e.strerror} (run tunica on examples/rat-aorta-inflation.yaml first)")
    if not rows:
        sys.exit(f"{path}: no data rows")
    return rows


def need(rows, path, columns):
    missing = [c for c in columns if c not in rows[0]]
    if missing:
        sys.exit(f"{path}: missing column(s) {', '.join(missing)} (is this a run of examples/rat-aorta-inflation.yaml?)")


def fe_states(result_dir):
    """The prestretched state at p = 0 (last row of step 1) and every increment of the inflation step."""
    path = os.path.join(result_dir, "history.csv")
    rows = read_csv(path)
    cols = ["step", "increment", "pressure_mmHg", "lambda_theta", "E_theta", "E_z", "S_theta_kPa", "S_z_kPa"]
    need(rows, path, cols)
    prestretched = [r for r in rows if int(r["step"]) == INFLATION_STEP - 1]
    inflation = [r for r in rows if int(r["step"]) == INFLATION_STEP]
    if not prestretched or not inflation:
        sys.exit(f"{path}: needs rows of steps {INFLATION_STEP - 1} and {INFLATION_STEP} (did the run finish?)")
    keep = [prestretched[-1]] + inflation
    optional = [c for c in ("radius_mm", "thickness_mm", "axial_force_N") if c in rows[0]]
    return {c: np.array([float(r[c]) for r in keep]) for c in cols + optional}


def compare(fe):
    """Closed-form values at the FE pressures; max relative differences over the inflation increments."""
    p_kpa = fe["pressure_mmHg"] * MMHG_KPA
    e1 = np.array([solve_e_theta(hoop_stress_closed_form(p)) for p in p_kpa])
    cf = {
        "lambda_theta": np.sqrt(1.0 + 2.0 * e1),
        "E_theta": e1,
        "S_theta_kPa": hoop_stress_closed_form(p_kpa),
        "S_z_kPa": fung_s2(e1),
        "radius_mm": R_MM * np.sqrt(1.0 + 2.0 * e1),
        "thickness_mm": H_MM / (np.sqrt(1.0 + 2.0 * e1) * LAMBDA_Z),
        # Axial wall force of an open tube: 2 pi r h sigma_z = 2 pi R H lambda_z S_z (kPa mm^2 = 1e-3 N).
        "axial_force_N": 2.0 * math.pi * R_MM * H_MM * LAMBDA_Z * fung_s2(e1) * 1e-3,
    }
    inflating = fe["pressure_mmHg"] > 0
    diffs = {}
    for key, ref in cf.items():
        if key not in fe:
            continue
        rel = np.abs(fe[key][inflating] - ref[inflating]) / np.abs(ref[inflating])
        i = int(np.argmax(rel))
        diffs[key] = (rel[i], fe["pressure_mmHg"][inflating][i])
    return cf, diffs


def closed_form_curve(n=400):
    """E_theta from its p = 0 value to its value at 200 mmHg, with S_theta and S_z along it."""
    e0 = solve_e_theta(0.0)
    e_max = solve_e_theta(hoop_stress_closed_form(P_MAX_MMHG * MMHG_KPA))
    e = np.linspace(e0, e_max, n)
    return e, fung_s1(e), fung_s2(e)


def figure(path, e_cf, s_cf, e_fe, s_fe, ylabel, title):
    fig, ax = plt.subplots(figsize=(6.4, 4.6), dpi=120)
    (cf,) = ax.plot(e_cf, s_cf, "-", color="0.2", lw=1.4, label=LEGEND_CF, zorder=1)
    (fe,) = ax.plot(e_fe, s_fe, "o", ms=5.5, mfc="none", mec="tab:red", mew=1.3, label=LEGEND_FE, zorder=2)
    ax.set_xlabel(r"circumferential Green–Lagrange strain $E_\theta$ (–)")
    ax.set_ylabel(ylabel)
    ax.set_title(title, fontsize=10)
    ax.grid(True, color="0.88", lw=0.6)
    ax.legend(handles=[fe, cf], loc="upper left", frameon=False)
    ax.text(0.98, 0.03,
            rf"$\lambda_z$ = {LAMBDA_Z:.2f}, $p$ = 0 … {P_MAX_MMHG:.0f} mmHg in 10 mmHg increments",
            transform=ax.transAxes, ha="right", va="bottom", fontsize=8, color="0.35")
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


def fmt_sci(x):
    return f"{x:.6e}"


def table_rows(newton_rows, increment):
    rows = [r for r in newton_rows if int(r["step"]) == INFLATION_STEP and int(r["increment"]) == increment]
    if not rows:
        sys.exit(f"newton.csv: no iterations of step {INFLATION_STEP}, increment {increment}")
    attempt = max(int(r["attempt"]) for r in rows)  # the converged attempt
    rows = sorted((r for r in rows if int(r["attempt"]) == attempt), key=lambda r: int(r["iteration"]))
    return attempt, [(int(r["iteration"]), float(r["residual"]), float(r["relative_residual"])) for r in rows]


def table1(newton_path):
    newton_rows = read_csv(newton_path)
    need(newton_rows, newton_path, ["step", "increment", "attempt", "iteration", "residual", "relative_residual"])
    out = [
        "<!-- generated by tools/figures/rat_aorta_figures.py from newton.csv; do not edit -->",
        "",
        "| increment | iteration k | ‖R_k‖ (N) | r_k = ‖R_k‖/‖R_0‖ | log r_k / log r_{k−1} | q_k |",
        "|---|---|---|---|---|---|",
    ]
    for increment, label in TABLE_INCREMENTS:
        attempt, its = table_rows(newton_rows, increment)
        r = [rel for _, _, rel in its]
        first = True
        for j, (k, res, rel) in enumerate(its):
            at_roundoff = rel < ROUNDOFF
            res_s = fmt_sci(res) + (" (round-off)" if at_roundoff else "")
            rel_s = fmt_sci(rel) + (" (round-off)" if at_roundoff else "")
            ratio = "–"
            order = "–"
            if j >= 1 and r[j - 1] < 1.0:
                ratio = "round-off" if at_roundoff else f"{math.log(r[j]) / math.log(r[j - 1]):.2f}"
            if j >= 2:
                order = ("round-off" if at_roundoff
                         else f"{math.log(r[j] / r[j - 1]) / math.log(r[j - 1] / r[j - 2]):.2f}")
            name = f"{label}" + (f" (attempt {attempt})" if attempt else "") if first else ""
            out.append(f"| {name} | {k} | {res_s} | {rel_s} | {ratio} | {order} |")
            first = False
    out += [
        "",
        "Each row holds the residual r_k after k Newton corrections (k = 0: the unbalanced force of the new load "
        "level before any correction). The two order columns use r_k as the newest residual: "
        "log r_k / log r_{k−1} tends to 2 under quadratic convergence only as r → 0 and is undefined at k = 1 "
        "(r_0 = 1); q_k = log(r_k/r_{k−1}) / log(r_{k−1}/r_{k−2}) is scale-free and equals 2 for "
        "r_k = C r_{k−1}². Residuals with r_k < 1e-13 are at round-off, where neither ratio measures the method.",
        "",
    ]
    return "\n".join(out)


def main(argv):
    if len(argv) != 3:
        sys.exit(f"usage: {argv[0]} RESULT_DIR OUT_DIR")
    result_dir, out_dir = argv[1], argv[2]
    fe = fe_states(result_dir)
    table = table1(os.path.join(result_dir, "newton.csv"))
    cf, diffs = compare(fe)
    e_cf, s1_cf, s2_cf = closed_form_curve()
    os.makedirs(out_dir, exist_ok=True)

    figure(os.path.join(out_dir, "rat-aorta-fig1.png"), e_cf, s1_cf, fe["E_theta"], fe["S_theta_kPa"],
           r"circumferential 2nd Piola–Kirchhoff stress $S_\theta$ (kPa)",
           "Analogue of Holzapfel et al. (1996), Fig. 1:\n"
           r"inflation of a prestretched rat aorta, $S_\theta$ vs $E_\theta$")
    figure(os.path.join(out_dir, "rat-aorta-fig2.png"), e_cf, s2_cf, fe["E_theta"], fe["S_z_kPa"],
           r"axial 2nd Piola–Kirchhoff stress $S_z$ (kPa)",
           "Analogue of Holzapfel et al. (1996), Fig. 2:\n"
           r"inflation of a prestretched rat aorta, $S_z$ vs $E_\theta$")
    with open(os.path.join(out_dir, "rat-aorta-table1.md"), "w") as f:
        f.write(table)

    n = int(np.sum(fe["pressure_mmHg"] > 0))
    print(f"FE vs closed form over the {n} inflation increments (max relative difference, at pressure):")
    for key in ("lambda_theta", "S_theta_kPa", "S_z_kPa", "radius_mm", "thickness_mm", "axial_force_N"):
        if key in diffs:
            rel, p = diffs[key]
            print(f"  {key:<14} {rel:.3e}  (at {p:g} mmHg)")
    print(f"prestretched state (p = 0): E_theta FE {fe['E_theta'][0]:.10f}, closed form {cf['E_theta'][0]:.10f}; "
          f"lambda_theta FE {fe['lambda_theta'][0]:.10f}, closed form {cf['lambda_theta'][0]:.10f}")
    print(f"wrote {out_dir}/rat-aorta-fig1.png, rat-aorta-fig2.png, rat-aorta-table1.md")


if __name__ == "__main__":
    main(sys.argv)
