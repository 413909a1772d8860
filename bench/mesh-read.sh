#!/usr/bin/env bash
# Time to read a large surface mesh: Tunica's own .msh reader (build/tunica-bench-mesh,
# bench/mesh_read.cpp: read, parse, groups, node sets, the file's checks) against the
# Gmsh SDK's reader (bench/mesh_read_gmsh.cpp: open, nodes, elements), on a tube meshed
# with the given lc (mm; 0.02 gives about 9 x 10^4 triangles), 4.1 ASCII and binary.
#   bash bench/mesh-read.sh [LC_MM]     (Release build in build/)
set -euo pipefail
cd "$(dirname "$0")/.."
cmake --build build --target tunica tunica-bench-mesh >/dev/null
lc="${1:-0.05}"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cat > "$work/tube.geo" <<GEO
lc = $lc;
Point(1) = {1, 0, 0, lc}; Point(2) = {0, 0, 0, lc}; Point(3) = {-1, 0, 0, lc};
Circle(1) = {1, 2, 3}; Circle(2) = {3, 2, 1};
Extrude {0, 0, 5} { Curve{1, 2}; }
Physical Surface("wall") = Surface{:};
Physical Curve("bottom") = {1, 2};
GEO
g++ -O2 bench/mesh_read_gmsh.cpp -o "$work/gmsh_read" -lgmsh
for format in "" "--binary"; do
  build/tunica mesh "$work/tube.geo" -o "$work/tube.msh" $format >/dev/null
  echo "== 4.1 ${format:-ASCII}: $(du -h "$work/tube.msh" | cut -f1)"
  for k in 1 2 3; do
    /usr/bin/time -f "  (%e s wall, %M kB peak)" build/tunica-bench-mesh "$work/tube.msh" | sed 's/^/tunica reader: /'
    /usr/bin/time -f "  (%e s wall, %M kB peak)" "$work/gmsh_read" "$work/tube.msh" | sed 's/^/gmsh SDK:      /'
  done
done
