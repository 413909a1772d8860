#!/usr/bin/python3
"""Parameter studies of the balloon-angioplasty example (issue #4).

Usage:
  /usr/bin/python3 tools/angioplasty_study.py penalty F1 [F2 ...]   both contact penalties x F
  /usr/bin/python3 tools/angioplasty_study.py plaque  S1 [S2 ...]   plaque mu and kappa x S
  /usr/bin/python3 tools/angioplasty_study.py summary RESULT_DIR    one row for an existing run
Options (environment): TUNICA (default ./build/tunica), DECK (default
examples/balloon-angioplasty.yaml), KEEP=DIR keeps the runs in DIR/<label> (default: a
temporary directory, removed), PLAQUE_ELEMENTS_Z=N remeshes the plaque with N (even)
elements along z instead of the deck's, moving the plaque_mid node set (z held) to the
new middle row of nodes; BALLOON_ELEMENTS=N remeshes the balloon with N elements from pole
to pole (the poles node set follows).

Each case is a copy of the deck with only the named values changed (checked), and with
ParaView output switched on (vtk_segments: 3) so that the contact pressure along the
lumen can be read. The table has, at the last converged increment:
  p_end        balloon pressure reached (N/mm^2; 2.05 when the run completes)
  pc_node      max nodal balloon-plaque contact pressure (history column pc_balloon_plaque)
  pc_node_hist the same, largest over all increments
  pc_seg       max segment-averaged contact pressure: the balloon nodes' normal forces
               (nodal pressure x current tributary area, from the VTU) summed per plaque
               lumen segment they lie over, divided by that segment's current area
  force        total balloon-plaque normal force (history column force_balloon_plaque, N)
  pen          max balloon-plaque penetration (history column pen_balloon_plaque, mm)
  lumen        minimum lumen radius (history column lumen_min, mm)
  srr_min      most compressive plaque sigma_rr (N/mm^2)
  iters        Newton iterations in the angioplasty step: total / max per increment;
               cut-backs (attempts > 0)
"""

import csv
import glob
import os
import re
import shutil
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "figures"))
from vtu import read_csv, read_vtu  # noqa: E402


def col(h, prefix):
    for k in h:
        if k == prefix or k.startswith(prefix + "_"):
            return h[k]
    raise KeyError(prefix)


def segment_peak(ref_path, vtu_path):
    """Max over the plaque's lumen segments of (sum of the balloon nodes' normal forces over
    the segment) / (segment's current area). Parts as in tools/figures/angioplasty_figures.py:
    plaque = the part with quadrilaterals, balloon = the membrane reaching the axis. The lumen
    nodes are, per row of plaque nodes of equal reference z (ref_path, the first frame), the
    node of least reference r."""
    X, _, _, _ = read_vtu(ref_path)
    x, cells, pd, cd = read_vtu(vtu_path)
    r, z = x[:, 0], x[:, 2]
    p = next(v for k, v in pd.items() if k.startswith("contact_pressure"))
    part = cd["part"].astype(int)
    plaque = np.unique(np.concatenate([c for c in cells if len(c) == 4]))
    zr = np.round(X[plaque, 2], 9)
    lumen = np.array([plaque[zr == v][np.argmin(X[plaque[zr == v], 0])] for v in np.unique(zr)])
    lines = {}
    for c, q in zip(cells, part):
        if len(c) == 2:
            lines.setdefault(q, []).append(c)
    chains = {q: np.array([s[0] for s in segs] + [segs[-1][1]]) for q, segs in lines.items()}
    b = chains[min(chains, key=lambda q: X[chains[q], 0].min())]
    seglen = np.hypot(np.diff(r[b]), np.diff(z[b]))
    trib = np.zeros(len(b))
    trib[:-1] += seglen / 2
    trib[1:] += seglen / 2
    f = p[b] * 2 * np.pi * r[b] * trib  # normal force of each balloon node (whole circumference)
    best = 0.0
    for a, c in zip(lumen[:-1], lumen[1:]):
        inside = (z[b] >= z[a]) & (z[b] < z[c])
        if inside.any():
            area = 2 * np.pi * 0.5 * (r[a] + r[c]) * np.hypot(r[c] - r[a], z[c] - z[a])
            best = max(best, f[inside].sum() / area)
    return best


def summary(d):
    h = read_csv(os.path.join(d, "history.csv"))
    with open(os.path.join(d, "newton.csv")) as fh:
        rows = list(csv.DictReader(fh))
    n = {k: np.array([float(r[k]) for r in rows]) for k in ("step", "increment", "attempt", "iteration")}
    last = int(h["step"].max())
    s = n["step"] == 3
    its = n["iteration"][s]
    inc = n["increment"][s]
    att = n["attempt"][s]
    per = [its[(inc == i) & (att == att[inc == i].max())].max() for i in np.unique(inc)]
    frames = sorted(glob.glob(os.path.join(d, "vtk", "meridian_*.vtu")))
    return {
        "p_end": col(h, "pressure")[-1] if last == 3 else 0.0,
        "pc_node": col(h, "pc_balloon_plaque")[-1],
        "pc_node_hist": col(h, "pc_balloon_plaque").max(),
        "pc_seg": segment_peak(frames[0], frames[-1]) if frames else float("nan"),
        "force": col(h, "force_balloon_plaque")[-1],
        "pen": col(h, "pen_balloon_plaque")[-1],
        "pen_pa": col(h, "pen_plaque_artery")[-1],
        "pc_pa": col(h, "pc_plaque_artery")[-1],
        "lumen": col(h, "lumen_min")[-1],
        "srr_min": col(h, "plaque_srr_min")[-1],
        "iters": "%d / %d / %d" % (int((its > 0).sum()), int(max(per)), len(set(zip(inc[att > 0], att[att > 0])))),
    }


def edit(text, what, factor):
    out, count = text, 0
    if what == "penalty":
        def rep(m):
            return "penalty: %.6g N/mm^3" % (float(m.group(1)) * factor)
        out, count = re.subn(r"penalty: ([0-9.eE+-]+) N/mm\^3", rep, out)
        expect = 2
    else:
        def rep(m):
            return "plaque: {type: neo_hookean_solid, mu: %.6g kPa, kappa: %.6g kPa}" % (
                float(m.group(1)) * factor, float(m.group(2)) * factor)
        out, count = re.subn(r"plaque: \{type: neo_hookean_solid, mu: ([0-9.eE+-]+) kPa, kappa: ([0-9.eE+-]+) kPa\}",
                             rep, out)
        expect = 1
    if count != expect:
        sys.exit("angioplasty_study: found %d (not %d) %s values to change" % (count, expect, what))
    nz = os.environ.get("PLAQUE_ELEMENTS_Z")
    if nz:
        nz = int(nz)
        m = re.search(r"elements_r: (\d+)\n      elements_z: (\d+)\n", out)
        if not m or nz % 2:
            sys.exit("angioplasty_study: cannot set the plaque's elements_z to %s" % nz)
        nr = int(m.group(1))
        row = [nz // 2 * (nr + 1) + i for i in range(nr + 1)]
        out = out.replace(m.group(0), "elements_r: %d\n      elements_z: %d\n" % (nr, nz))
        old = [int(m.group(2)) // 2 * (nr + 1) + i for i in range(nr + 1)]
        mid = "plaque_mid: {part: plaque, nodes: [%s]}"
        if (mid % ", ".join(map(str, old))) not in out:
            sys.exit("angioplasty_study: plaque_mid is not the middle row of the deck's plaque")
        out = out.replace(mid % ", ".join(map(str, old)), mid % ", ".join(map(str, row)))
    nb = os.environ.get("BALLOON_ELEMENTS")
    if nb:
        m = re.search(r"end_angle: 90 deg, elements: (\d+)\}", out)
        poles = "balloon_poles: {part: balloon, nodes: [0, %s]}"
        if not m or (poles % m.group(1)) not in out:
            sys.exit("angioplasty_study: cannot set the balloon's element count to %s" % nb)
        out = out.replace(poles % m.group(1), poles % int(nb))
        out = out.replace(m.group(0), "end_angle: 90 deg, elements: %d}" % int(nb))
    out, nv = re.subn(r"\n  vtk: false\n", "\n  vtk: true\n  vtk_segments: 3\n", out)
    if nv != 1:
        sys.exit("angioplasty_study: could not switch on vtk output")
    return out


HEAD = ("| {what} | p reached (N/mm²) | max nodal p_c (N/mm²) | max nodal p_c over the step (N/mm²) | "
        "max segment-averaged p_c (N/mm²) | contact force (N) | max penetration (mm) | lumen radius (mm) | "
        "min σ_rr plaque (N/mm²) | iterations: total / max per incr. / cut-backs |")


def row(label, s):
    return ("| %s | %.4g | %.4g | %.4g | %.4g | %.4g | %.3g | %.4f | %.4g | %s |"
            % (label, s["p_end"], s["pc_node"], s["pc_node_hist"], s["pc_seg"], s["force"], s["pen"], s["lumen"],
               s["srr_min"], s["iters"]))


def main(argv):
    if len(argv) >= 2 and argv[0] == "summary":
        print(HEAD.format(what="run"))
        print("|" + "---|" * 10)
        for d in argv[1:]:
            print(row(d, summary(d)))
        return
    if len(argv) < 2 or argv[0] not in ("penalty", "plaque"):
        sys.exit(__doc__)
    what, factors = argv[0], [float(a) for a in argv[1:]]
    tunica = os.environ.get("TUNICA", "./build/tunica")
    deck = os.environ.get("DECK", "examples/balloon-angioplasty.yaml")
    base = open(deck).read()
    keep = os.environ.get("KEEP")
    work = keep or tempfile.mkdtemp()
    os.makedirs(work, exist_ok=True)
    label = "penalty × " if what == "penalty" else "plaque μ, κ × "
    print(HEAD.format(what="penalties" if what == "penalty" else "plaque moduli"))
    print("|" + "---|" * 10)
    try:
        for f in factors:
            name = "%s-%g" % (what, f)
            path = os.path.join(work, name + ".yaml")
            with open(path, "w") as o:
                o.write(edit(base, what, f))
            out = os.path.join(work, name)
            rc = subprocess.run(["nice", "-n", "19", tunica, "run", path, "-o", out, "-q"],
                                stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
            note = "" if rc.returncode == 0 else " (exit %d)" % rc.returncode
            print(row(label + "%g%s" % (f, note), summary(out)), flush=True)
    finally:
        if not keep:
            shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main(sys.argv[1:])
