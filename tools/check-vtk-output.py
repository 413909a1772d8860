#!/usr/bin/python3
"""Reads every frame of a run's ParaView output with VTK's own XML reader (Debian
package python3-vtk9, not installed by the build: apt-get install python3-vtk9)
and prints, per series, the frames read and the range of the hoop Cauchy stress.
Usage: /usr/bin/python3 tools/check-vtk-output.py RESULT_DIR"""
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import vtk

out = Path(sys.argv[1])
for series in ("meridian", "surface"):
    frames = ET.parse(out / f"{series}.pvd").getroot().findall(".//DataSet")
    lo, hi = float("inf"), float("-inf")
    for ds in frames:
        reader = vtk.vtkXMLUnstructuredGridReader()
        reader.SetFileName(str(out / ds.get("file")))
        reader.Update()
        grid = reader.GetOutput()
        if grid.GetNumberOfCells() == 0 or reader.GetErrorCode():
            sys.exit(f"{ds.get('file')}: VTK could not read it")
        arr = next(grid.GetCellData().GetArray(i) for i in range(grid.GetCellData().GetNumberOfArrays())
                   if grid.GetCellData().GetArrayName(i).startswith("sigma_hoop"))
        a, b = arr.GetRange()
        lo, hi = min(lo, a), max(hi, b)
    print(f"{series}: {len(frames)} frames read by VTK {vtk.vtkVersion.GetVTKVersion()}; "
          f"hoop Cauchy stress from {lo:.6g} to {hi:.6g}")
