#!/usr/bin/env python3
"""Output that scales with the run: times the increments of one long run of a
tiny model (the rat aorta example, 1 element, its inflation step in 100,000
increments, a ParaView frame every 10,000) and compares the wall time per
increment near increment 1,000 with that near increment 100,000. Every
increment appends to history.csv and newton.csv and rewrites restart.txt, all
synced, so the time per increment is mostly fsync; it must not grow with the
length of the files (target: within 20 %).

usage: bench/output_scaling.py [TUNICA] [INCREMENTS]   (default build/tunica, 100000)"""
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
tunica = sys.argv[1] if len(sys.argv) > 1 else os.path.join(root, "build", "tunica")
increments = int(sys.argv[2]) if len(sys.argv) > 2 else 100_000
window = 200  # increments averaged at each end
early = 1_000

work = tempfile.mkdtemp(prefix="tunica-output-scaling-")
deck = os.path.join(work, "long.yaml")
text = open(os.path.join(root, "examples", "rat-aorta-inflation.yaml")).read()
text = text.replace("increments: 20", f"increments: {increments}")
text = text.replace("output:\n", "output:\n  vtk_every: 10000\n  vtk_segments: 8\n", 1)
open(deck, "w").write(text)
out = os.path.join(work, "out")

done = re.compile(r"^step 2 'inflation' increment (\d+) ")
stamps = {}
start = time.monotonic()
p = subprocess.Popen([tunica, "run", deck, "-o", out, "-j", "1"], stdout=subprocess.PIPE, text=True)
for line in p.stdout:
    m = done.match(line)
    if m:
        stamps[int(m.group(1))] = time.monotonic()
if p.wait() != 0:
    sys.exit(f"tunica exited with {p.returncode}")
total = time.monotonic() - start


def per_increment(last):
    return (stamps[last] - stamps[last - window]) / window


near_early = per_increment(early + window // 2)
near_end = per_increment(increments)
sizes = {f: os.path.getsize(os.path.join(out, f)) for f in ("history.csv", "newton.csv", "restart.txt", "frames.csv")}
print(f"{increments} increments in {total:.1f} s")
print(f"time per increment, increments {early - window // 2 + 1}-{early + window // 2}: {1e3 * near_early:.3f} ms")
print(f"time per increment, increments {increments - window + 1}-{increments}: {1e3 * near_end:.3f} ms")
print(f"ratio end / early: {near_end / near_early:.3f} (target within 0.8-1.2)")
print("files at the end: " + ", ".join(f"{f} {s} bytes" for f, s in sizes.items()))
shutil.rmtree(work)
sys.exit(0 if 0.8 <= near_end / near_early <= 1.2 else 1)
