#!/usr/bin/env bash
# Reproduces the tables and the figure of docs/performance.md:
#   bash bench/run.sh [--quick]
# Builds Release (tools/build.sh), runs tunica-bench on the generated Fung tube at
# 10k, 100k and 1M triangles (6 increments to 120 mmHg) and the neo-Hookean sphere
# octant (n = 14, 20, 41, 58; 10 increments to λ = 1.2), with 1 and 2 threads and
# each solver on the mid sizes, appends every run to results/bench/bench.csv, then
# draws docs/figures/performance-scaling.png and prints the Markdown tables.
# The 100k and 1M tubes also run with --paired (a bare factorization timed next to each of the
# run's: the ratio free of the machine's speed drift). --quick skips the 1M-triangle tube
# (about 40 minutes of the whole: 15 plain, 25 paired).
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/build.sh >/dev/null
B=./build/tunica-bench
mkdir -p results/bench
CSV=results/bench/bench.csv
rm -f "$CSV"
# The tables are for 2 threads (the machine's cores); THREADS=N runs them on N.
B="$B --threads ${THREADS:-2}"
for t in 10000 100000; do $B tube --triangles $t --csv "$CSV"; done
$B tube --triangles 100000 --paired --csv "$CSV"
./build/tunica-bench tube --triangles 100000 --threads 1 --csv "$CSV"
$B tube --triangles 100000 --solver umfpack --csv "$CSV"
$B tube --triangles 100000 --symmetrized --csv "$CSV"
for n in 14 20 41 58; do $B sphere --n $n --csv "$CSV"; done
$B sphere --n 41 --solver umfpack --csv "$CSV"
# The fewest increments: the whole load in one (the comparison with CalculiX, docs/performance.md).
for n in 14 20 41 58; do $B sphere --n $n --increments 1 --csv "$CSV"; done
if [ "${1:-}" != "--quick" ]; then
  $B tube --triangles 1000000 --csv "$CSV"
  $B tube --triangles 1000000 --paired --csv "$CSV"
fi
/usr/bin/python3 bench/plot.py "$CSV" docs/figures/performance-scaling.png
