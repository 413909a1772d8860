#!/usr/bin/env python3
"""A 6-node triangle membrane written for ParaView: meshes a quarter cylinder with
Mesh.ElementOrder = 2 (tunica mesh), inflates it, and reads every frame with VTK's own
reader (python3-vtk9): every cell is a VTK_QUADRATIC_TRIANGLE (22) of 6 points, the grid
holds every node of the mesh, and the cell stresses are finite.

usage: vtk_reads_quadratic_triangles.py TUNICA SCRATCH_DIR"""
import math
import os
import shutil
import subprocess
import sys

try:
    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
    from vtkmodules.util.numpy_support import vtk_to_numpy
except ImportError:
    sys.exit("python3-vtk9 is not installed: run tools/install-deps.sh")

tunica, scratch = sys.argv[1:3]
shutil.rmtree(scratch, ignore_errors=True)
os.makedirs(scratch)
geo = os.path.join(scratch, "quarter.geo")
open(geo, "w").write("""Mesh.ElementOrder = 2;
lc = 0.4;
Point(1) = {0, 0, 0, lc}; Point(2) = {1, 0, 0, lc}; Point(3) = {0, 1, 0, lc};
Circle(1) = {2, 1, 3};
out[] = Extrude {0, 0, 2} { Curve{1}; };
Physical Surface("wall") = {out[1]};
Physical Curve("bottom") = {1};
Physical Curve("top") = {out[0]};
Physical Curve("x0") = {out[2]};
Physical Curve("y0") = {out[3]};
""")
msh = os.path.join(scratch, "quarter.msh")
subprocess.run([tunica, "mesh", geo, "-o", msh], check=True)
deck = os.path.join(scratch, "tube.yaml")
open(deck, "w").write("""title: quadratic triangles in ParaView
units: {length: mm, force: N}
materials:
  rubber: {type: neo_hookean, mu: 0.1 MPa}
parts:
  wall:
    element: membrane
    material: rubber
    thickness: 0.05 mm
    mesh: {type: gmsh, file: quarter.msh, surface: wall}
    frame: {type: cylindrical, axis: [0, 0, 1]}
boundary:
  ends: {node_set: bottom, dofs: [z]}
  top: {node_set: top, dofs: [z]}
  sym_x: {node_set: x0, dofs: [x]}
  sym_y: {node_set: y0, dofs: [y]}
loads:
  lumen: {type: pressure, part: wall}
steps:
  - {name: stretch, increments: 4, set: {top: 0.4 mm, lumen: 2 kPa}}
  - {name: inflate, increments: 2, set: {lumen: 3 kPa}}
output:
  vtk_format: ascii
  history:
    - {quantity: pressure, load: lumen, unit: kPa}
""")
subprocess.run([tunica, "run", deck, "-q", "-o", os.path.join(scratch, "out")], check=True)

nodes = None
with open(msh) as f:  # the number of nodes the surface uses: every node of this mesh
    lines = f.read().split("\n")
    i = lines.index("$Nodes")
    nodes = int(lines[i + 1].split()[1])

frames = sorted(n for n in os.listdir(os.path.join(scratch, "out", "vtk")) if n.endswith(".vtu"))
if not frames:
    sys.exit("no frames written")
for name in frames:
    r = vtkXMLUnstructuredGridReader()
    r.SetFileName(os.path.join(scratch, "out", "vtk", name))
    r.Update()
    if r.GetErrorCode() != 0:
        sys.exit(f"VTK could not read {name}")
    g = r.GetOutput()
    types = set(vtk_to_numpy(g.GetCellTypesArray()).tolist())
    if types != {22}:
        sys.exit(f"{name}: cell types {types}, expected only 22 (VTK_QUADRATIC_TRIANGLE)")
    for c in range(g.GetNumberOfCells()):
        if g.GetCell(c).GetNumberOfPoints() != 6:
            sys.exit(f"{name}: cell {c} has {g.GetCell(c).GetNumberOfPoints()} points")
    if g.GetNumberOfPoints() != nodes:
        sys.exit(f"{name}: {g.GetNumberOfPoints()} points, the mesh has {nodes} nodes")
    data = g.GetCellData()
    stress = [data.GetArrayName(i) for i in range(data.GetNumberOfArrays()) if data.GetArrayName(i).startswith("sigma_1")]
    if not stress:
        sys.exit(f"{name}: no sigma_1 array")
    values = vtk_to_numpy(data.GetArray(stress[0]))
    if not all(math.isfinite(v) for v in values.tolist()):
        sys.exit(f"{name}: {stress[0]} is not finite")
print(f"VTK read {len(frames)} frames of {g.GetNumberOfCells()} quadratic triangles ({nodes} nodes); "
      f"{stress[0]} up to {values.max():.4g}")
