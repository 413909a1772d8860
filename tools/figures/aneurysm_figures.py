#!/usr/bin/python3
"""Figures of the fusiform-aneurysm example.

Usage: /usr/bin/python3 tools/figures/aneurysm_figures.py RESULT_DIR OUT_DIR

Reads RESULT_DIR/history.csv (columns pressure_mmHg, volume_mm3, ...) and the
first and last RESULT_DIR/vtk/surface_*.vtu written by
`tunica run examples/aneurysm.yaml --allow-scripts -o RESULT_DIR`, and writes to OUT_DIR

  aneurysm-stress.png           deformed wall at the last increment coloured by the
                                maximum in-plane principal Cauchy stress (kPa), cut
                                open along y < 0 to show the inside
  aneurysm-pressure-volume.png  pressure against enclosed volume
  aneurysm-profile.png          radius of the wall against z, reference and loaded

and prints the peak stress, where it sits, and the volume change.
"""

import glob
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from vtu import read_csv, read_vtu  # noqa: E402


def main(result_dir, out_dir):
    os.makedirs(out_dir, exist_ok=True)
    frames = sorted(glob.glob(os.path.join(result_dir, "vtk", "surface_*.vtu")))
    if not frames:
        sys.exit("aneurysm_figures: no vtk/surface_*.vtu in " + result_dir)
    X, _, _, _ = read_vtu(frames[0])
    x, cells, _, cd = read_vtu(frames[-1])
    key = next(k for k in cd if k.startswith("sigma_max"))
    scale = 1e3 if key.endswith("N_per_mm2") else 1.0  # MPa → kPa
    smax = cd[key] * scale
    h = read_csv(os.path.join(result_dir, "history.csv"))

    # Deformed surface, cut open (cells with centroid y < 0 are drawn; the viewer looks from −y).
    centroids = np.array([x[c].mean(axis=0) for c in cells])
    keep = centroids[:, 1] <= 0.0
    polys = [x[c] for c, k in zip(cells, keep) if k]
    vals = smax[keep]
    fig = plt.figure(figsize=(7.5, 6.0))
    ax = fig.add_subplot(projection="3d")
    norm = plt.Normalize(vals.min(), vals.max())
    coll = Poly3DCollection(polys, facecolors=plt.cm.viridis(norm(vals)), edgecolors="none")
    ax.add_collection3d(coll)
    lo, hi = x.min(axis=0), x.max(axis=0)
    mid, half = (lo + hi) / 2, (hi - lo).max() / 2
    ax.set_xlim(mid[0] - half, mid[0] + half)
    ax.set_ylim(mid[1] - half, mid[1] + half)
    ax.set_zlim(mid[2] - half, mid[2] + half)
    ax.set_box_aspect((1, 1, 1))
    ax.view_init(elev=15, azim=60)  # from the cut side (+y): the inner surface of the y ≤ 0 half
    ax.set_xlabel("x (mm)")
    ax.set_ylabel("y (mm)")
    ax.set_zlabel("z (mm)")
    sm = plt.cm.ScalarMappable(norm=norm, cmap="viridis")
    fig.colorbar(sm, ax=ax, shrink=0.7, label="max. principal Cauchy stress (kPa)")
    ax.set_title("Fusiform aneurysm at %.0f mmHg (wall cut open at y = 0)" % h["pressure_mmHg"][-1])
    fig.savefig(os.path.join(out_dir, "aneurysm-stress.png"), dpi=150, bbox_inches="tight")
    plt.close(fig)

    fig, ax = plt.subplots(figsize=(5.5, 4.0))
    ax.plot(h["volume_mm3"] / 1e3, h["pressure_mmHg"], "o-", ms=3)
    ax.set_xlabel("enclosed volume (mL)")
    ax.set_ylabel("pressure (mmHg)")
    ax.grid(alpha=0.3)
    ax.set_title("Pressure–volume curve")
    fig.savefig(os.path.join(out_dir, "aneurysm-pressure-volume.png"), dpi=150, bbox_inches="tight")
    plt.close(fig)

    fig, ax = plt.subplots(figsize=(6.0, 3.5))
    for P, label in ((X, "reference"), (x, "%.0f mmHg" % h["pressure_mmHg"][-1])):
        r = np.hypot(P[:, 0], P[:, 1])
        order = np.argsort(P[:, 2])
        z = P[order, 2]
        bins = np.linspace(z.min(), z.max(), 81)
        idx = np.digitize(z, bins)
        zz = [z[idx == i].mean() for i in np.unique(idx)]
        rr = [r[order][idx == i].max() for i in np.unique(idx)]
        ax.plot(zz, rr, label=label)
    ax.set_xlabel("z (mm)")
    ax.set_ylabel("radius (mm)")
    ax.legend()
    ax.grid(alpha=0.3)
    fig.savefig(os.path.join(out_dir, "aneurysm-profile.png"), dpi=150, bbox_inches="tight")
    plt.close(fig)

    k = int(np.argmax(smax))
    print("peak max-principal Cauchy stress %.1f kPa at z = %.2f mm, radius %.2f mm; volume %.1f -> %.1f mm^3 (+%.1f %%)"
          % (smax[k], centroids[k, 2], np.hypot(*centroids[k, :2]), h["volume_mm3"][0], h["volume_mm3"][-1],
             100 * (h["volume_mm3"][-1] / h["volume_mm3"][0] - 1)))


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
