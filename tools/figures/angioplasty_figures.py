#!/usr/bin/python3
"""Figures of the balloon-angioplasty example (theory manual §12.2; the paper's Figs. 4 and 5).

Usage: /usr/bin/python3 tools/figures/angioplasty_figures.py RESULT_DIR OUT_DIR

Reads RESULT_DIR/history.csv and RESULT_DIR/vtk/meridian_*.vtu written by
`tunica run examples/balloon-angioplasty.yaml -o RESULT_DIR` (the deck writes the
ParaView files) and writes to OUT_DIR

  angioplasty-deformed.png  the r-z plane at full balloon pressure (last increment):
                            artery and balloon mid-surfaces, the plaque's elements
                            coloured by the radial Cauchy stress sigma_rr, over the
                            outlines before inflation (end of the plaque step)
  angioplasty-contact-zone.png   close-up of the same around the contact zone
  angioplasty-contact-pressure.png  contact pressure against z at full balloon
                            pressure: balloon-plaque pair (at the balloon's nodes,
                            i.e. on the plaque's lumen) and plaque-artery pair (at
                            the plaque's outer nodes), with the paper's peak
                            0.419 N/mm2 as a reference line
  angioplasty-history.png   peak contact pressures and lumen radius against the
                            balloon pressure

and prints the values it plotted (peak pressures, where they are, the lumen).

Everything plotted comes from the output files. The parts are told apart without the
deck: the plaque is the part with quadrilateral (solid) cells, the balloon is the
membrane part that reaches the axis (its poles), the artery the other membrane. The
only number written here is the paper's reported peak contact pressure (0.419 N/mm2,
Holzapfel et al. 1996, §4.2), drawn as a reference line.
"""

import glob
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from vtu import read_csv, read_vtu  # noqa: E402

PAPER_PEAK_N_PER_MM2 = 0.419  # Holzapfel et al. (1996), §4.2: maximum contact pressure

plt.rcParams.update({"font.size": 11, "axes.labelsize": 12, "axes.titlesize": 12, "legend.fontsize": 10})


def column(h, prefix):
    keys = [k for k in h if k == prefix or k.startswith(prefix + "_")]
    if not keys:
        sys.exit("angioplasty_figures: no history column %s* (have %s)" % (prefix, ", ".join(h)))
    return keys[0], h[keys[0]]


def unit_of(key, prefix):
    u = key[len(prefix) + 1 :]
    return {"MPa": "N/mm²", "N_per_mm2": "N/mm²", "mm": "mm", "N": "N", "kPa": "kPa"}.get(u, u)


class Frame:
    """One meridian VTU: the parts, as chains (membranes) or quadrilaterals (the plaque)."""

    def __init__(self, path):
        self.x, cells, self.pd, self.cd = read_vtu(path)
        self.r, self.z = self.x[:, 0], self.x[:, 2]
        part = self.cd["part"].astype(int)
        self.quads = {}
        self.lines = {}
        for c, p in zip(cells, part):
            (self.quads if len(c) == 4 else self.lines).setdefault(p, []).append(c)
        self.cell_part = part

    def chain(self, p):
        """The nodes of membrane part p in mesh order (its line cells share end nodes)."""
        segs = self.lines[p]
        return np.array([s[0] for s in segs] + [segs[-1][1]])

    def field(self, prefix):
        for d in (self.cd, self.pd):
            for k in d:
                if k.startswith(prefix):
                    return k, d[k]
        sys.exit("angioplasty_figures: no array %s* in the VTU" % prefix)


def identify(ref):
    (plaque,) = ref.quads.keys()
    membranes = sorted(ref.lines.keys())
    balloon = min(membranes, key=lambda p: ref.r[ref.chain(p)].min())
    (artery,) = [p for p in membranes if p != balloon]
    return artery, plaque, balloon


def plaque_surfaces(ref, plaque):
    """Inner and outer boundary node chains of the structured plaque grid (in z order):
    per row of equal reference z, the nodes of least and largest r."""
    nodes = np.unique(np.concatenate(ref.quads[plaque]))
    zr = np.round(ref.z[nodes], 9)
    inner, outer = [], []
    for zz in np.unique(zr):
        row = nodes[zr == zz]
        inner.append(row[np.argmin(ref.r[row])])
        outer.append(row[np.argmax(ref.r[row])])
    return np.array(inner), np.array(outer)


def draw(ax, before, now, parts, srr, norm, lw=1.6, edges=False):
    artery, plaque, balloon = parts
    inner, outer = plaque_surfaces(before, plaque)
    # Outlines before inflation.
    kw = dict(color="0.55", lw=1.0, ls="--")
    ax.plot(before.z[before.chain(artery)], before.r[before.chain(artery)], **kw, label="before inflation")
    ax.plot(before.z[before.chain(balloon)], before.r[before.chain(balloon)], **kw)
    ax.plot(before.z[inner], before.r[inner], **kw)
    ax.plot(before.z[outer], before.r[outer], **kw)
    # Deformed: plaque coloured by sigma_rr, artery and balloon mid-surfaces.
    polys = [np.column_stack((now.z[q], now.r[q])) for q in now.quads[plaque]]
    coll = PolyCollection(polys, array=srr, cmap="viridis", norm=norm,
                          edgecolors="0.3" if edges else "face", linewidths=0.15 if edges else 0.3)
    ax.add_collection(coll)
    ax.plot(now.z[now.chain(artery)], now.r[now.chain(artery)], color="tab:red", lw=lw, label="artery (mid-surface)")
    ax.plot(now.z[now.chain(balloon)], now.r[now.chain(balloon)], color="tab:blue", lw=lw,
            label="balloon (mid-surface)")
    ax.set_aspect("equal")
    ax.set_xlabel("z (mm)")
    ax.set_ylabel("r (mm)")
    return coll


def main(result_dir, out_dir):
    os.makedirs(out_dir, exist_ok=True)
    frames = sorted(glob.glob(os.path.join(result_dir, "vtk", "meridian_*.vtu")))
    h = read_csv(os.path.join(result_dir, "history.csv"))
    if len(frames) != len(h["step"]):
        sys.exit("angioplasty_figures: %d VTU frames but %d history rows in %s (does the deck write vtk?)"
                 % (len(frames), len(h["step"]), result_dir))
    last_step = h["step"].max()
    i_before = int(np.nonzero(h["step"] == last_step - 1)[0][-1])  # end of the plaque step
    before, now = Frame(frames[i_before]), Frame(frames[-1])
    parts = identify(before)
    artery, plaque, balloon = parts
    kp, p = column(h, "pressure")
    p_full = p[-1]
    pu = unit_of(kp, "pressure")

    srr_key, srr_all = now.field("sigma_rr")
    srr = srr_all[now.cell_part == plaque]
    su = "N/mm²" if srr_key.endswith("N_per_mm2") else srr_key.split("_")[-1]
    norm = plt.Normalize(srr.min(), srr.max())

    # (a) the whole model.
    fig, ax = plt.subplots(figsize=(11, 3.6))
    coll = draw(ax, before, now, parts, srr, norm)
    ax.set_xlim(min(before.z.min(), now.z.min()) - 0.05, max(before.z.max(), now.z.max()) + 0.05)
    ax.set_ylim(0, max(before.r.max(), now.r.max()) + 0.05)
    fig.colorbar(coll, ax=ax, label="plaque σ_rr (%s)" % su, fraction=0.03, pad=0.01)
    ax.legend(loc="upper center", ncol=3, bbox_to_anchor=(0.5, -0.28), frameon=False)
    ax.set_title("Deformed configuration at balloon pressure %.2f %s" % (p_full, pu))
    fig.savefig(os.path.join(out_dir, "angioplasty-deformed.png"), dpi=150, bbox_inches="tight")
    plt.close(fig)

    # (b) close-up of the contact zone: the balloon's extent, padded.
    bz, br = now.z[now.chain(balloon)], now.r[now.chain(balloon)]
    zc = 0.5 * (bz.min() + bz.max())
    half = 0.5 * (bz.max() - bz.min()) + 0.15
    fig, ax = plt.subplots(figsize=(8, 5.2))
    coll = draw(ax, before, now, parts, srr, norm, lw=2.0, edges=True)
    ax.set_xlim(zc - half, zc + half)
    ax.set_ylim(0.25, max(now.r[now.chain(artery)].max(), before.r[before.chain(artery)].max()) + 0.03)
    fig.colorbar(coll, ax=ax, label="plaque σ_rr (%s)" % su, fraction=0.046, pad=0.02)
    ax.legend(loc="lower left", framealpha=0.9)
    ax.set_title("Contact zone at balloon pressure %.2f %s" % (p_full, pu))
    fig.savefig(os.path.join(out_dir, "angioplasty-contact-zone.png"), dpi=150, bbox_inches="tight")
    plt.close(fig)

    # (c) contact pressure along z at full pressure.
    cp_key, cp = now.field("contact_pressure")
    cu = "N/mm²" if cp_key.endswith("N_per_mm2") else cp_key.split("_")[-1]
    bal = now.chain(balloon)
    _, outer = plaque_surfaces(before, plaque)
    fig, ax = plt.subplots(figsize=(7.5, 4.5))
    ax.plot(now.z[bal], cp[bal], "o-", ms=3.5, color="tab:blue", label="balloon–plaque (plaque lumen)")
    ax.plot(now.z[outer], cp[outer], "s-", ms=2.5, color="tab:red", label="plaque–artery (artery wall)")
    ax.axhline(PAPER_PEAK_N_PER_MM2, color="k", ls="--", lw=1.2,
               label="paper's maximum, %.3f N/mm²" % PAPER_PEAK_N_PER_MM2)
    zs = now.z[bal][cp[bal] > 0]
    if zs.size:
        ax.set_xlim(zs.min() - 0.4, zs.max() + 0.4)
    ax.set_ylim(bottom=0, top=1.15 * max(PAPER_PEAK_N_PER_MM2, cp.max()))
    ax.set_xlabel("z (mm)")
    ax.set_ylabel("contact pressure (%s)" % cu)
    ax.grid(alpha=0.3)
    ax.legend(loc="upper right")
    ax.set_title("Contact pressure at balloon pressure %.2f %s" % (p_full, pu))
    fig.savefig(os.path.join(out_dir, "angioplasty-contact-pressure.png"), dpi=150, bbox_inches="tight")
    plt.close(fig)

    # (d) history against the balloon pressure (the angioplasty step).
    s = h["step"] == last_step
    kb, pcb = column(h, "pc_balloon_plaque")
    ka, pca = column(h, "pc_plaque_artery")
    kl, lumen = column(h, "lumen_min")
    fig, ax = plt.subplots(figsize=(7.0, 4.5))
    ax.plot(p[s], pcb[s], "o-", ms=3.5, color="tab:blue", label="max. contact pressure balloon–plaque")
    ax.plot(p[s], pca[s], "s-", ms=3, color="tab:red", label="max. contact pressure plaque–artery")
    ax.axhline(PAPER_PEAK_N_PER_MM2, color="k", ls="--", lw=1.2, label="paper's maximum, %.3f N/mm²" % PAPER_PEAK_N_PER_MM2)
    ax.set_xlabel("balloon pressure (%s)" % pu)
    ax.set_ylabel("contact pressure (%s)" % unit_of(kb, "pc_balloon_plaque"))
    ax.set_ylim(bottom=0)
    ax.grid(alpha=0.3)
    ax2 = ax.twinx()
    ax2.plot(p[s], lumen[s], "-", color="tab:green", lw=2, label="minimum lumen radius")
    ax2.set_ylabel("minimum lumen radius (%s)" % unit_of(kl, "lumen_min"), color="tab:green")
    l1, n1 = ax.get_legend_handles_labels()
    l2, n2 = ax2.get_legend_handles_labels()
    ax.legend(l1 + l2, n1 + n2, loc="upper left")
    ax.set_title("Angioplasty step")
    fig.savefig(os.path.join(out_dir, "angioplasty-history.png"), dpi=150, bbox_inches="tight")
    plt.close(fig)

    kb_top = int(np.argmax(cp[bal]))
    print("balloon pressure %.4g %s; balloon-plaque contact pressure max %.4g %s at z = %.3f mm "
          "(%d balloon nodes in contact, z = %.3f ... %.3f mm); plaque-artery max %.4g %s at z = %.3f mm; "
          "plaque sigma_rr %.4g ... %.4g %s; lumen min %.4f -> %.4f mm; history peak balloon-plaque %.4g %s at p = %.4g"
          % (p_full, pu, cp[bal].max(), cu, now.z[bal][kb_top], zs.size, zs.min() if zs.size else np.nan,
             zs.max() if zs.size else np.nan, cp[outer].max(), cu, now.z[outer][int(np.argmax(cp[outer]))],
             srr.min(), srr.max(), su, lumen[i_before], lumen[-1], pcb.max(), cu, p[int(np.argmax(pcb))]))


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
