#!/usr/bin/python3
"""Figures of the spherical-balloon example against the thin-sphere closed form.

Usage: /usr/bin/python3 tools/figures/balloon_figures.py RESULT_DIR OUT_DIR [CONVERGENCE_DIR]

Reads RESULT_DIR/history.csv written by
`tunica run examples/balloon-sphere.yaml -o RESULT_DIR` (columns step, increment,
time, pressure_kPa, equator_radius_mm, sigma_hoop_max_MPa, thickness_min_mm)
and writes to OUT_DIR

  balloon-sphere-pressure-stretch.png   p vs lambda: FE points over the closed-form
                                        curve, drawn past the pressure maximum

and prints the largest relative error of the FE pressure against the closed form.

If CONVERGENCE_DIR is given, it holds one run of the same deck per mesh, in
subdirectories named elements-N (N = number of elements; tools/make-figures.sh
makes them); the script then also writes

  balloon-sphere-convergence.png        max relative pressure error vs N, log-log,
                                        with a slope -2 reference line

and prints each mesh's error, the observed rate between successive meshes and the
least-squares slope of log(error) against log(N).

The closed form (theory manual (8.3)) is evaluated here, independently of the C++ code:
a thin incompressible neo-Hookean sphere of radius R and thickness H inflated to
the stretch lambda = r/R carries p = 2 mu (H/R) (1/lambda - 1/lambda^7), with its
maximum at lambda = 7^(1/6). lambda is the FE equator radius over R.
"""

import csv
import math
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.ticker  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

# Example data (examples/balloon-sphere.yaml), in kPa and mm.
MU_KPA = 1000.0  # mu = 1 MPa
R_MM = 1.0  # mid-surface radius
H_MM = 0.01  # wall thickness
LAMBDA_PEAK = 7.0 ** (1.0 / 6.0)
LAMBDA_CURVE_MAX = 2.2

LEGEND_FE = "Tunica FE ({n} elements)"
LEGEND_CF = "closed form (thin neo-Hookean sphere)"


def p_closed_form(lam):
    """Internal pressure (kPa) at the stretch lam, theory manual (8.3)."""
    lam = np.asarray(lam, dtype=float)
    return 2.0 * MU_KPA * (H_MM / R_MM) * (1.0 / lam - lam ** -7)


P_PEAK = float(p_closed_form(LAMBDA_PEAK))


def read_history(result_dir):
    path = os.path.join(result_dir, "history.csv")
    try:
        with open(path, newline="") as f:
            rows = list(csv.DictReader(f))
    except OSError as e:
        sys.exit(f"{path}: {e.strerror} (run tunica on examples/balloon-sphere.yaml first)")
    if not rows:
        sys.exit(f"{path}: no data rows")
    cols = ["step", "pressure_kPa", "equator_radius_mm"]
    missing = [c for c in cols if c not in rows[0]]
    if missing:
        sys.exit(f"{path}: missing column(s) {', '.join(missing)} (is this a run of examples/balloon-sphere.yaml?)")
    loaded = [r for r in rows if int(r["step"]) >= 1]  # step 0 is the unloaded reference state
    if not loaded:
        sys.exit(f"{path}: no converged increments (did the run finish?)")
    p = np.array([float(r["pressure_kPa"]) for r in loaded])
    lam = np.array([float(r["equator_radius_mm"]) for r in loaded]) / R_MM
    return p, lam


def read_optional(result_dir, column):
    """A further history column over the loaded increments, or None if the run did not write it."""
    with open(os.path.join(result_dir, "history.csv"), newline="") as f:
        rows = [r for r in csv.DictReader(f) if int(r["step"]) >= 1]
    if not rows or column not in rows[0]:
        return None
    return np.array([float(r[column]) for r in rows])


def errors(p, lam):
    """Relative error of the FE pressure against the closed form at the FE stretch."""
    ref = p_closed_form(lam)
    return np.abs(p - ref) / np.abs(ref)


def element_count(result_dir):
    """The element count of the deck that produced RESULT_DIR, from the meridian's first VTK frame."""
    vtk = os.path.join(result_dir, "vtk")
    try:
        names = sorted(n for n in os.listdir(vtk) if n.startswith("meridian") and n.endswith(".vtu"))
    except OSError:
        return None
    if not names:
        return None
    with open(os.path.join(vtk, names[0])) as f:
        m = re.search(r'NumberOfCells="(\d+)"', f.read())
    return int(m.group(1)) if m else None


def pressure_stretch_figure(path, p, lam, n_elements):
    fig, ax = plt.subplots(figsize=(6.4, 4.6), dpi=120)
    lam_cf = np.linspace(1.0, LAMBDA_CURVE_MAX, 600)
    (cf,) = ax.plot(lam_cf, p_closed_form(lam_cf), "-", color="0.2", lw=1.4, label=LEGEND_CF, zorder=1)
    label = LEGEND_FE.format(n=n_elements) if n_elements else "Tunica FE"
    (fe,) = ax.plot(lam, p, "o", ms=5.5, mfc="none", mec="tab:red", mew=1.3, label=label, zorder=3)
    ax.plot([1.0], [0.0], "o", ms=5.5, mfc="none", mec="tab:red", mew=1.3, zorder=3)  # the unloaded state
    (pk,) = ax.plot([LAMBDA_PEAK], [P_PEAK], "D", ms=6, color="tab:blue", zorder=4,
                    label=rf"pressure maximum $\lambda = 7^{{1/6}}$ = {LAMBDA_PEAK:.4f}, $p$ = {P_PEAK:.4f} kPa")
    ax.axvline(LAMBDA_PEAK, color="tab:blue", lw=0.8, ls=":", zorder=0)
    ax.axhline(P_PEAK, color="tab:blue", lw=0.8, ls=":", zorder=0)
    ax.set_xlim(0.98, LAMBDA_CURVE_MAX)
    ax.set_ylim(-0.3, 1.12 * P_PEAK)
    ax.set_xlabel(r"equator stretch $\lambda = r/R$ (–)")
    ax.set_ylabel(r"internal pressure $p$ (kPa)")
    ax.set_title("Neo-Hookean spherical balloon: pressure vs stretch\n"
                 r"$p = 2\mu\,(H/R)\,(\lambda^{-1} - \lambda^{-7})$, $\mu$ = 1 MPa, $H/R$ = 0.01", fontsize=10)
    ax.grid(True, color="0.88", lw=0.6)
    ax.legend(handles=[fe, cf, pk], loc="lower right", frameon=False, fontsize=8.5)
    ax.text(0.97, 0.36,
            rf"FE: $p$ = 0 … {p.max():.1f} kPa in {len(p)} increments" "\n"
            "(pressure control: the run must stay below the maximum)",
            transform=ax.transAxes, ha="right", va="bottom", fontsize=8, color="0.35")
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


def convergence_runs(conv_dir):
    runs = []
    try:
        names = os.listdir(conv_dir)
    except OSError as e:
        sys.exit(f"{conv_dir}: {e.strerror}")
    for name in names:
        m = re.fullmatch(r"elements-(\d+)", name)
        if m:
            p, lam = read_history(os.path.join(conv_dir, name))
            runs.append((int(m.group(1)), float(errors(p, lam).max())))
    if len(runs) < 2:
        sys.exit(f"{conv_dir}: needs at least two subdirectories elements-N with a history.csv")
    return sorted(runs)


def convergence_figure(path, runs, slope):
    n = np.array([r[0] for r in runs], dtype=float)
    e = np.array([r[1] for r in runs])
    fig, ax = plt.subplots(figsize=(6.4, 4.6), dpi=120)
    (fe,) = ax.loglog(n, e, "o-", ms=6, mfc="none", mec="tab:red", mew=1.3, color="tab:red", lw=1.0,
                      label=f"Tunica FE (fitted slope {slope:.2f})".replace("-", "−"), zorder=3)
    # Slope -2 reference through the geometric mean of the data, shifted down by a factor 2 to stay readable.
    n_ref = np.array([n.min(), n.max()])
    c = math.exp(np.mean(np.log(e) + 2.0 * np.log(n))) / 2.0
    (ref,) = ax.loglog(n_ref, c * n_ref ** -2.0, "--", color="0.3", lw=1.2, label=r"slope $-2$: error $\propto N^{-2}$")
    for ni, ei in zip(n, e):
        ax.annotate(f"{ei:.2e}", (ni, ei), textcoords="offset points", xytext=(6, 4), fontsize=7.5, color="0.3")
    ax.set_xticks(n)
    ax.set_xticklabels([f"{int(v)}" for v in n])
    ax.xaxis.set_minor_locator(matplotlib.ticker.NullLocator())
    ax.set_ylim(e.min() / 3.0, e.max() * 2.0)
    ax.set_xlabel(r"elements along the quarter meridian $N$")
    ax.set_ylabel(r"max relative error $|p_{FE} - p(\lambda_{FE})|\,/\,p(\lambda_{FE})$")
    ax.set_title("Neo-Hookean spherical balloon: mesh convergence\n"
                 r"largest error over the increments $p$ = 0.59 … 11.8 kPa", fontsize=10)
    ax.grid(True, which="both", color="0.88", lw=0.6)
    ax.legend(handles=[fe, ref], loc="upper right", frameon=False, fontsize=9)
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


def main(argv):
    if len(argv) not in (3, 4):
        sys.exit(f"usage: {argv[0]} RESULT_DIR OUT_DIR [CONVERGENCE_DIR]")
    result_dir, out_dir = argv[1], argv[2]
    p, lam = read_history(result_dir)
    err = errors(p, lam)
    n_elements = element_count(result_dir)
    os.makedirs(out_dir, exist_ok=True)

    pressure_stretch_figure(os.path.join(out_dir, "balloon-sphere-pressure-stretch.png"), p, lam, n_elements)
    i = int(np.argmax(err))
    print(f"FE vs closed form over the {len(p)} increments"
          + (f" ({n_elements} elements)" if n_elements else "") + ":")
    print(f"  max relative error in p: {err[i]:.3e} (at p = {p[i]:g} kPa, lambda = {lam[i]:.6f})")
    print(f"  last increment: p = {p[-1]:g} kPa, lambda = {lam[-1]:.6f}; "
          f"pressure maximum of the closed form: p = {P_PEAK:.6f} kPa at lambda = {LAMBDA_PEAK:.6f}")
    # Membrane stress and thickness of a uniformly inflated sphere: sigma = p r / (2 h), h = H / lambda^2.
    sigma = read_optional(result_dir, "sigma_hoop_max_MPa")
    if sigma is not None:
        ref = 1e-3 * p * lam**3 * R_MM / (2.0 * H_MM)
        rel = sigma / ref - 1.0
        j = int(np.argmax(np.abs(rel)))
        print(f"  sigma_hoop_max vs p lambda^3 R/(2H): largest relative difference {rel[j]:+.3e} (at p = {p[j]:g} kPa), "
              f"{rel[-1]:+.3e} at the last increment")
    thick = read_optional(result_dir, "thickness_min_mm")
    if thick is not None:
        rel = thick / (H_MM / lam**2) - 1.0
        j = int(np.argmax(np.abs(rel)))
        print(f"  thickness_min vs H/lambda^2: largest relative difference {rel[j]:+.3e} (at p = {p[j]:g} kPa)")
    wrote = ["balloon-sphere-pressure-stretch.png"]

    if len(argv) == 4:
        runs = convergence_runs(argv[3])
        n = np.array([r[0] for r in runs], dtype=float)
        e = np.array([r[1] for r in runs])
        slope = float(np.polyfit(np.log(n), np.log(e), 1)[0])
        print("mesh convergence (max relative error in p over all increments):")
        for k, (nk, ek) in enumerate(runs):
            rate = "" if k == 0 else f"   rate {math.log(runs[k - 1][1] / ek) / math.log(nk / runs[k - 1][0]):.3f}"
            print(f"  {nk:5d} elements  {ek:.3e}{rate}")
        print(f"  least-squares slope of log(error) vs log(N): {slope:.3f}")
        convergence_figure(os.path.join(out_dir, "balloon-sphere-convergence.png"), runs, slope)
        wrote.append("balloon-sphere-convergence.png")

    print(f"wrote {out_dir}/" + ", ".join(wrote))


if __name__ == "__main__":
    main(sys.argv)
