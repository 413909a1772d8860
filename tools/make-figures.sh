#!/usr/bin/env bash
# Regenerates docs/figures/ from the rat-aorta example: builds Tunica (Release, in build/)
# if ./build/tunica is missing, runs examples/rat-aorta-inflation.yaml into
# results/rat-aorta and plots it against the thin-tube closed form.
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
