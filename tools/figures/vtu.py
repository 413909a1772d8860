"""Reads the VTK XML UnstructuredGrid files Tunica writes (inline binary,
base64 of a UInt64 byte count followed by the values), with numpy only.

    points, cells, point_data, cell_data = read_vtu(path)

points: (n, 3) float64; cells: list of node-index arrays (one per cell);
point_data / cell_data: dict name -> (n, components) or (n,) float64 arrays.
"""

import base64
import re
import struct

import numpy as np

_TYPES = {"Float64": np.float64, "Int64": np.int64, "UInt8": np.uint8}
_ARRAY = re.compile(
    r'<DataArray type="(\w+)" Name="([^"]+)" NumberOfComponents="(\d+)" format="binary">\s*([A-Za-z0-9+/=]*)\s*</DataArray>'
)


def _decode(kind, text, components):
    raw = base64.b64decode(text)
    (count,) = struct.unpack("<Q", raw[:8])
    values = np.frombuffer(raw[8 : 8 + count], dtype=_TYPES[kind])
    return values.reshape(-1, components) if components > 1 else values


def read_vtu(path):
    with open(path) as f:
        text = f.read()
    sections = {}
    for name in ("Points", "Cells", "PointData", "CellData"):
        m = re.search(r"<%s[^>]*>(.*?)</%s>" % (name, name), text, re.S)
        sections[name] = m.group(1) if m else ""
    arrays = {}
    for section, body in sections.items():
        arrays[section] = {m.group(2): _decode(m.group(1), m.group(4), int(m.group(3))) for m in _ARRAY.finditer(body)}
    points = arrays["Points"]["Points"]
    conn = arrays["Cells"]["connectivity"]
    offsets = arrays["Cells"]["offsets"]
    starts = np.concatenate(([0], offsets[:-1]))
    cells = [conn[s:e] for s, e in zip(starts, offsets)]
    return points, cells, arrays["PointData"], arrays["CellData"]


def read_csv(path):
    """history.csv as a dict column -> numpy array."""
    import csv

    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}
