#!/usr/bin/env bash
# One command for the aneurysm example: installs what is missing, builds Release
# (if ./build/tunica is missing), runs examples/aneurysm.yaml into
# results/aneurysm and draws its figures into docs/figures.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install-deps.sh
[ -x ./build/tunica ] || bash tools/build.sh
time ./build/tunica run examples/aneurysm.yaml --allow-scripts -o results/aneurysm -q
/usr/bin/python3 tools/figures/aneurysm_figures.py results/aneurysm docs/figures
echo "results in results/aneurysm (history.csv, newton.csv, surface.pvd for ParaView); figures in docs/figures/aneurysm-*.png"
