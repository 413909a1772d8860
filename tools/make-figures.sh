#!/usr/bin/env bash
# Regenerates docs/figures/ from the gallery examples: builds Tunica (Release, in build/)
# if ./build/tunica is missing, then
#  - runs examples/rat-aorta-inflation.yaml into results/rat-aorta and plots it
#    against the thin-tube closed form;
#  - runs examples/balloon-sphere.yaml into results/balloon-sphere, and copies of it
#    with 10, 20, 40, 80 and 160 elements into results/balloon-sphere-convergence/elements-N,
#    and plots them against the thin-sphere closed form;
#  - runs examples/balloon-sphere-3d.yaml (volume control through the pressure maximum)
#    and examples/aneurysm.yaml, and draws their figures;
#  - runs a copy of examples/balloon-angioplasty.yaml with ParaView output switched on
#    (vtk: true, vtk_segments: 3) into results/angioplasty and draws its figures.
#   TUNICA=path/to/tunica   use that binary instead of ./build/tunica (no build)
#   PYTHON=path/to/python3  interpreter with matplotlib and numpy (default: Debian's /usr/bin/python3)
set -euo pipefail
cd "$(dirname "$0")/.."
python="${PYTHON:-/usr/bin/python3}"
if [ -n "${TUNICA:-}" ]; then
  tunica="$TUNICA"
  [ -x "$tunica" ] || { echo "make-figures: TUNICA=$tunica is not an executable" >&2; exit 1; }
else
  tunica=./build/tunica
  [ -x "$tunica" ] || bash tools/build.sh
fi

"$tunica" run examples/rat-aorta-inflation.yaml -o results/rat-aorta -q
"$python" tools/figures/rat_aorta_figures.py results/rat-aorta docs/figures

"$tunica" run examples/balloon-sphere.yaml -o results/balloon-sphere -q
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
conv=results/balloon-sphere-convergence
rm -rf "$conv"
for n in 10 20 40 80 160; do
  deck="$tmp/balloon-sphere-$n.yaml"
  sed "s/elements: 100}/elements: $n}/" examples/balloon-sphere.yaml >"$deck"
  grep -q "elements: $n}" "$deck" || { echo "make-figures: could not set the element count in $deck" >&2; exit 1; }
  "$tunica" run "$deck" -o "$conv/elements-$n" -q
done
"$python" tools/figures/balloon_figures.py results/balloon-sphere docs/figures "$conv"

"$tunica" run examples/balloon-sphere-3d.yaml -o results/balloon-sphere-3d -q
"$python" tools/figures/sphere3d_figures.py results/balloon-sphere-3d docs/figures

"$tunica" run examples/aneurysm.yaml --allow-scripts -o results/aneurysm -q
"$python" tools/figures/aneurysm_figures.py results/aneurysm docs/figures

angio="$tmp/balloon-angioplasty.yaml"
sed 's/^  vtk: false$/  vtk: true\n  vtk_segments: 3/' examples/balloon-angioplasty.yaml >"$angio"
grep -q "^  vtk: true$" "$angio" || { echo "make-figures: could not switch on vtk output in $angio" >&2; exit 1; }
rm -rf results/angioplasty
"$tunica" run "$angio" -o results/angioplasty -q
"$python" tools/figures/angioplasty_figures.py results/angioplasty docs/figures
