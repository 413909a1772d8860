#!/usr/bin/env bash
# One command: install what is missing, build Release, run the rat-aorta example.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install-deps.sh
bash tools/build.sh
time ./build/tunica run examples/rat-aorta-inflation.yaml -o results/rat-aorta
echo "results in results/rat-aorta (history.csv, newton.csv, *.pvd for ParaView)"
