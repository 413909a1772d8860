#!/usr/bin/python3
"""Pressure-stretch curve of the 3-D balloon under volume control.

Usage: /usr/bin/python3 tools/figures/sphere3d_figures.py RESULT_DIR OUT_DIR

Reads RESULT_DIR/history.csv of `tunica run examples/balloon-sphere-3d.yaml -o
RESULT_DIR` (columns pressure_kPa, volume_mm3), takes lambda = (V/V0)^(1/3) from
the enclosed volume of the faceted octant, and writes OUT_DIR/balloon-sphere-3d.png:
the FE points over the thin neo-Hookean sphere's closed form
p = 2 mu (H/R)(1/lambda - 1/lambda^7) (theory manual (8.3), evaluated here), through the
pressure maximum at lambda = 7^(1/6). Prints the largest relative error.
"""

import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from vtu import read_csv  # noqa: E402

MU_KPA, R_MM, H_MM = 1000.0, 1.0, 0.01


def p_closed_form(lam):
    return 2.0 * MU_KPA * (H_MM / R_MM) * (1.0 / lam - lam ** -7)


def main(result_dir, out_dir):
    h = read_csv(os.path.join(result_dir, "history.csv"))
    lam = np.cbrt(h["volume_mm3"] / h["volume_mm3"][0])
    p = h["pressure_kPa"]
    err = np.abs(p[1:] - p_closed_form(lam[1:])) / p_closed_form(lam[1:])
    curve = np.linspace(1.0, max(2.2, lam.max()), 300)
    fig, ax = plt.subplots(figsize=(5.5, 4.0))
    ax.plot(curve, p_closed_form(curve), "-", color="0.3", label="closed form (thin neo-Hookean sphere)")
    ax.plot(lam, p, "o", ms=4, mfc="none", label="Tunica 3-D membranes, volume control")
    peak = 7.0 ** (1.0 / 6.0)
    ax.axvline(peak, ls=":", color="0.5")
    ax.set_xlabel(r"stretch $\lambda = (V/V_0)^{1/3}$")
    ax.set_ylabel("pressure (kPa)")
    ax.legend(loc="lower right", fontsize=8)
    ax.grid(alpha=0.3)
    os.makedirs(out_dir, exist_ok=True)
    fig.savefig(os.path.join(out_dir, "balloon-sphere-3d.png"), dpi=150, bbox_inches="tight")
    print("3-D balloon: %d increments to lambda = %.3f, max relative pressure error %.3e" % (len(p) - 1, lam[-1], err.max()))


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
