#!/usr/bin/env python3
"""Reads the .vtu frames Tunica writes in each output.vtk_format with VTK's own
reader (vtkXMLUnstructuredGridReader, python3-vtk9) and checks that the binary
and compressed files hold the same points, cells and arrays as the ascii one.

usage: vtk_reads_every_format.py TUNICA DECK SCRATCH_DIR
Fails when the vtk module is missing: tools/install-deps.sh installs python3-vtk9."""
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

tunica, deck, scratch = sys.argv[1:4]
shutil.rmtree(scratch, ignore_errors=True)
os.makedirs(scratch)
text = open(deck).read().replace("output:\n", "output:\n  vtk_segments: 8\n  vtk_format: FORMAT\n", 1)
formats = ["ascii", "binary", "compressed"]
for f in formats:
    path = os.path.join(scratch, f + ".yaml")
    open(path, "w").write(text.replace("FORMAT", f))
    subprocess.run([tunica, "run", path, "-q", "-o", os.path.join(scratch, f)], check=True)


def read(path):
    r = vtkXMLUnstructuredGridReader()
    r.SetFileName(path)
    r.Update()
    if r.GetErrorCode() != 0:
        raise SystemExit(f"VTK could not read {path}")
    g = r.GetOutput()
    arrays = {"Points": vtk_to_numpy(g.GetPoints().GetData()),
              "connectivity": vtk_to_numpy(g.GetCells().GetConnectivityArray()),
              "types": vtk_to_numpy(g.GetCellTypesArray())}
    for kind, data in (("point", g.GetPointData()), ("cell", g.GetCellData())):
        for i in range(data.GetNumberOfArrays()):
            arrays[kind + ":" + data.GetArrayName(i)] = vtk_to_numpy(data.GetArray(i))
    return g.GetNumberOfPoints(), g.GetNumberOfCells(), arrays


checked = 0
for name in sorted(os.listdir(os.path.join(scratch, "ascii", "vtk"))):
    ref_points, ref_cells, ref = read(os.path.join(scratch, "ascii", "vtk", name))
    if ref_points == 0 or ref_cells == 0 or len(ref) < 20:
        raise SystemExit(f"{name}: VTK read {ref_points} points, {ref_cells} cells, {len(ref)} arrays from the ascii file")
    for f in formats[1:]:
        points, cells, arrays = read(os.path.join(scratch, f, "vtk", name))
        if (points, cells) != (ref_points, ref_cells) or arrays.keys() != ref.keys():
            raise SystemExit(f"{f}/{name}: another grid than the ascii file")
        for key, a in ref.items():
            b = arrays[key]
            same = a.shape == b.shape and all(
                (x == y) or (isinstance(x, float) and math.isnan(x) and math.isnan(y))
                for x, y in zip(a.ravel().tolist(), b.ravel().tolist()))
            if not same:
                raise SystemExit(f"{f}/{name}: array {key} differs from the ascii file")
        checked += 1
print(f"VTK read {checked} binary/compressed frames, identical to the ascii ones")
