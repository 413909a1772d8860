#!/usr/bin/env python3
"""Corruption campaign of the .msh reader through the command line.

Usage: python3 tools/mesh-corruption.py TUNICA [TRIALS] [WORKDIR] [ONLY]

For each shipped mesh (tests/data/meshes/**/*.msh and the aneurysm example meshed
from examples/meshes/aneurysm.geo with `tunica mesh`, in 4.1 and 2.2, ASCII and
binary), writes TRIALS copies with 8 random bytes overwritten (seeded, so the run
is repeatable), and runs `tunica check` on a deck that names each. A trial passes
when tunica exits 0 (the damage left a valid mesh) or 2 with one printable line
naming the mesh file (printable: ASCII, or UTF-8 as core/printable.cpp keeps it), within 10 s; a crash, a hang, any other exit code or message
fails it. ONLY keeps the meshes whose file name contains it. Prints one row per mesh
and exits 1 if any trial failed.
"""
import os
import random
import re
import subprocess
import sys
import time

DECK = """units: {{length: mm, force: N}}
materials:
  rubber: {{type: neo_hookean, mu: 1 MPa}}
parts:
  skin: {{element: membrane, material: rubber, thickness: 0.1 mm, frame: {frame},
         mesh: {{type: gmsh, file: {mesh}, surface: {surface}}}}}
steps:
  - {{increments: 1, set: {{}}}}
output: {{vtk: false}}
"""


def surface_of(data: bytes) -> str:
    """The first physical surface's name (the reader's order: the least tag)."""
    m = re.search(rb"\$PhysicalNames\s+\d+\s+(.*?)\$EndPhysicalNames", data, re.S)
    names = []
    for line in (m.group(1).splitlines() if m else []):
        parts = line.split(maxsplit=2)
        if len(parts) == 3 and parts[0] == b"2":
            names.append((int(parts[1]), parts[2].strip().strip(b'"').decode()))
    return sorted(names)[0][1] if names else "surface_1"


def printable_line(text: str) -> bool:
    """What core/printable.cpp's is_printable_line accepts: printable ASCII, and code points
    from U+00A0 on except surrogates, line separators and invisible format characters."""
    for c in text:
        o = ord(c)
        if 0x20 <= o < 0x7f:
            continue
        invisible = 0x200B <= o <= 0x200F or 0x2028 <= o <= 0x202E or 0x2060 <= o <= 0x206F or o in (0xFEFF, 0xAD)
        if o < 0xA0 or 0xD800 <= o <= 0xDFFF or invisible:
            return False
    return True


def main() -> int:
    tunica = os.path.abspath(sys.argv[1])
    trials = int(sys.argv[2]) if len(sys.argv) > 2 else 1000
    work = sys.argv[3] if len(sys.argv) > 3 else "/tmp/tunica-mesh-corruption"
    only = sys.argv[4] if len(sys.argv) > 4 else ""
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    os.makedirs(work, exist_ok=True)
    meshes = []
    for d, _, files in os.walk(os.path.join(root, "tests", "data", "meshes")):
        meshes += [os.path.join(d, f) for f in sorted(files) if f.endswith(".msh")]
    for version in ("4.1", "2.2"):
        for binary in (False, True):
            out = os.path.join(work, f"aneurysm-v{version}-{'binary' if binary else 'ascii'}.msh")
            if only not in os.path.basename(out):
                continue
            cmd = [tunica, "mesh", os.path.join(root, "examples", "meshes", "aneurysm.geo"), "-o", out,
                   "--msh-version", version] + (["--binary"] if binary else [])
            subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
            meshes.append(out)
    meshes = [m for m in meshes if only in os.path.basename(m)]
    failed = 0
    print(f"| mesh | bytes | trials | read | refused | failed | slowest check (s) |")
    print(f"|---|---|---|---|---|---|---|", flush=True)
    for mesh in meshes:
        original = open(mesh, "rb").read()
        surface = surface_of(original)
        frame = "{type: mesh, view: fibre}" if b'"fibre"' in original else "{type: edge}"
        rng = random.Random(f"{os.path.basename(mesh)}-20261201")
        read = refused = bad = 0
        slowest = 0.0
        name = os.path.basename(mesh)
        for t in range(trials):
            data = bytearray(original)
            for _ in range(8):
                data[rng.randrange(len(data))] = rng.randrange(256)
            path = os.path.join(work, "corrupt-" + name)
            open(path, "wb").write(bytes(data))
            deck = os.path.join(work, "deck.yaml")
            open(deck, "w").write(DECK.format(mesh=path, surface=surface, frame=frame))
            t0 = time.monotonic()
            try:
                p = subprocess.run([tunica, "check", deck], capture_output=True, timeout=10)
            except subprocess.TimeoutExpired:
                bad += 1
                print(f"  HANG: {name} trial {t}", file=sys.stderr)
                open(os.path.join(work, f"hang-{t}-{name}"), "wb").write(bytes(data))
                continue
            slowest = max(slowest, time.monotonic() - t0)
            try:
                err = p.stderr.decode("utf-8")
            except UnicodeDecodeError:
                err = p.stderr.decode("latin-1") + " [ill-formed UTF-8]"
            lines = err.splitlines()
            ok = (p.returncode == 0 and not err) or (
                p.returncode == 2 and len(lines) == 1 and path in lines[0] and printable_line(lines[0]))
            if not ok:
                bad += 1
                print(f"  FAILED: {name} trial {t}: exit {p.returncode}: {err[:300]!r}", file=sys.stderr)
                open(os.path.join(work, f"failed-{t}-{name}"), "wb").write(bytes(data))
            elif p.returncode == 0:
                read += 1
            else:
                refused += 1
        failed += bad
        print(f"| {name} | {len(original)} | {trials} | {read} | {refused} | {bad} | {slowest:.2f} |", flush=True)
    print(f"mesh corruption: {failed} failed trial(s)")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
