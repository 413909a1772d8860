#!/usr/bin/env bash
# Time to read a large surface mesh: Tunica's own .msh reader (through `tunica check`,
# which also builds the model) against the Gmsh SDK's reader (bench/mesh_read_gmsh.cpp),
# on a tube of about 2 x 10^5 (or the given lc's) triangles in 4.1 ASCII and binary.
#   bash bench/mesh-read.sh [LC_MM]     (Release build in build/)
set -euo pipefail
cd "$(dirname "$0")/.."
lc="${1:-0.05}"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cat > "$work/tube.geo" <<GEO
lc = $lc;
Point(1) = {1, 0, 0, lc}; Point(2) = {0, 0, 0, lc}; Point(3) = {-1, 0, 0, lc};
Circle(1) = {1, 2, 3}; Circle(2) = {3, 2, 1};
out1[] = Extrude {0, 0, 5} { Curve{1}; };
out2[] = Extrude {0, 0, 5} { Curve{2}; };
Physical Surface("wall") = {out1[1], out2[1]};
Physical Curve("bottom") = {1, 2};
GEO
cat > "$work/deck.yaml" <<DECK
units: {length: mm, force: N}
materials:
  rubber: {type: neo_hookean, mu: 1 MPa}
parts:
  wall: {element: membrane, material: rubber, thickness: 0.1 mm, mesh: {type: gmsh, file: tube.msh, surface: wall}}
steps:
  - {increments: 1, set: {}}
output: {vtk: false}
DECK
g++ -O2 bench/mesh_read_gmsh.cpp -o "$work/gmsh_read" -lgmsh
for format in "" "--binary"; do
  build/tunica mesh "$work/tube.geo" -o "$work/tube.msh" $format >/dev/null
  echo "== 4.1 ${format:-ASCII}: $(du -h "$work/tube.msh" | cut -f1)"
  /usr/bin/time -f "tunica check: %e s wall, %M kB peak" build/tunica check "$work/deck.yaml"
  /usr/bin/time -f "gmsh SDK:     %e s wall, %M kB peak" "$work/gmsh_read" "$work/tube.msh"
done
