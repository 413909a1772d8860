#!/bin/bash
# Tunica side of the CalculiX comparison: the same thin neo-Hookean sphere octant
# (R = 1 mm, H = 0.01 mm, mu = 1 MPa, mesh {type: octant, n: N} = 3 N^2 quads,
# whole-sphere equivalent 24 N^2), 4-node incompressible membranes, pressure-controlled
# to p = 2 mu (H/R)(1/1.2 - 1.2^-7) in INCS equal increments (default 10, as the
# CalculiX run), default Newton tolerances (residual 1e-9, energy 1e-15).
#
# Usage: sphere_tunica.sh N [INCS] [DIR]
# Prints elements, increments, Newton iterations, wall time, peak RSS, pressure
# reached, lambda reached (mean nodal radius of the last surface .vtu; also the pole),
# and the relative error of p against the closed form at the reached lambda.
set -euo pipefail
N=${1:?usage: sphere_tunica.sh N [INCS] [DIR]}
INCS=${2:-10}
DIR=${3:-results/peers/tunica_n${N}_i${INCS}}
TUNICA=${TUNICA:-./build/tunica}
mkdir -p "$DIR"
DECK="$DIR/sphere.yaml"
P=$(python3 -c 'l=1.2; print(repr(2*1.0*0.01*(1/l-l**-7)))')   # MPa = N/mm^2

cat > "$DECK" <<EOF
# Thin neo-Hookean sphere octant inflated by a follower pressure to lambda = 1.2
# (theory manual (8.3)): p = 2 mu (H/R)(1/lambda - 1/lambda^7) = $P MPa.
title: neo-Hookean sphere octant n=$N to lambda 1.2 (pressure control, $INCS increments)
units: {length: mm, force: N}
materials:
  rubber: {type: neo_hookean, mu: 1 MPa}
parts:
  balloon:
    element: membrane
    material: rubber
    thickness: 0.01 mm
    mesh: {type: octant, radius: 1 mm, n: $N}
boundary:
  sym_x: {node_set: balloon.x0, dofs: [x]}
  sym_y: {node_set: balloon.y0, dofs: [y]}
  sym_z: {node_set: balloon.z0, dofs: [z]}
loads:
  inflation: {type: pressure, part: balloon}
steps:
  - name: inflate
    increments: $INCS
    set: {inflation: $P}
output:
  history:
    - {quantity: pressure, load: inflation}
    - {quantity: position_z, node_set: balloon.pole, name: pole_z}
    - {quantity: lambda_1, part: balloon}
    - {quantity: lambda_2, part: balloon}
EOF

rm -f "$DIR/history.csv" "$DIR/newton.csv"
set +e
/usr/bin/time -v "$TUNICA" run "$DECK" -o "$DIR" -q > "$DIR/tunica.log" 2> "$DIR/time.txt"
RC=$?
set -e

python3 - "$DIR" "$N" "$RC" "$(dirname "$0")" <<'PY'
import csv, glob, math, sys
d, n, rc = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
sys.path.insert(0, sys.argv[4])
from equal_accuracy import radii  # reads every .vtu format Tunica writes (appended raw, zlib, ascii)
R, H, mu = 1.0, 0.01, 1.0
pc = lambda l: 2 * mu * (H / R) * (1 / l - l ** -7)
wall = rss = None
for line in open(f"{d}/time.txt"):
    line = line.strip()
    if line.startswith("Elapsed (wall clock) time"):
        parts = [float(v) for v in line.split(": ", 1)[1].split(":")]
        wall = sum(v * 60 ** (len(parts) - 1 - i) for i, v in enumerate(parts))
    elif line.startswith("Maximum resident set size"):
        rss = int(line.split(":")[1]) / 1024.0
hist = list(csv.DictReader(open(f"{d}/history.csv")))
newt = list(csv.DictReader(open(f"{d}/newton.csv")))
last = hist[-1]
incs = sum(1 for r in hist if int(r["step"]) > 0)
iters = sum(1 for r in newt if int(r["iteration"]) > 0)           # corrections = linear solves
cut = sum(1 for r in newt if int(r["iteration"]) == 0 and int(r["attempt"]) > 0)
pcol = [k for k in last if k.startswith("pressure")][0]
p = float(last[pcol])
lam_pole = float(last[[k for k in last if k.startswith("pole_z")][0]]) / R
lam12 = 0.5 * (float(last["lambda_1"]) + float(last["lambda_2"]))

def vtu_points_radius(path):
    """Mean and spread of the nodal radius of the deformed surface."""
    r = radii(path)
    return sum(r) / len(r), max(r) - min(r), len(r)

vtus = sorted(glob.glob(f"{d}/vtk/surface_*.vtu"))
try:
    lam, spread, nn = vtu_points_radius(vtus[-1])
    lam /= R
    ref, _, _ = vtu_points_radius(vtus[0])
    src = f"mean nodal radius of {vtus[-1].split('/')[-1]} ({nn} nodes; reference mean {ref:.12f})"
except Exception as e:  # fall back on the element stretches
    lam, spread, src = lam12, float("nan"), f"mean of lambda_1, lambda_2 ({e})"
err = (p - pc(lam)) / pc(lam)
ne = 3 * n * n
ok = "completed" if rc == 0 and abs(float(last["time"]) - 1.0) < 1e-12 else f"INCOMPLETE (exit {rc})"
print(f"status              {ok}")
print(f"elements            {ne} membrane quads (octant; whole-sphere equivalent {8 * ne})")
print(f"increments          {incs} converged ({cut} cut-back attempts)")
print(f"Newton iterations   {iters} (newton.csv rows with iteration >= 1, failed attempts included)")
print(f"wall time           {wall:.1f} s")
print(f"peak RSS            {rss:.0f} MB")
print(f"pressure reached    {p / mu:.8g} mu")
print(f"lambda reached      {lam:.8f} ({src}; pole {lam_pole:.8f}; element mean {lam12:.8f}; max-min radius {spread:.2e} R)")
print(f"p error vs closed   {err:+.3e} (at lambda reached; at pole lambda {(p - pc(lam_pole)) / pc(lam_pole):+.3e})")
print(f"RESULT code=tunica n={n} elements={ne} whole={8 * ne} incs={incs} iters={iters} wall={wall:.1f} "
      f"rss_mb={rss:.0f} p_mu={p / mu:.8g} lam={lam:.8f} err={err:+.3e} status={ok.split()[0]}")
PY
