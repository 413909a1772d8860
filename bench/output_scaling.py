#!/usr/bin/env python3
"""Output that scales with the run: times the increments of one long run of a
tiny model (the rat aorta example, 1 element, its inflation step in 100,000
increments, a ParaView frame every 10,000) and compares the wall time per
increment near increment 1,000 with that near increment 100,000. Every
increment appends to history.csv and newton.csv; every second of wall-clock
time (output.checkpoint_every_s) the files are synced and restart.txt is
rewritten. The time per increment must not grow with the length of the files:
the script fails if the end window is more than 20 % slower than the early one
(the early window, the first files' pages, is often the slower). The CPU time (user + system) of the tunica process is
sampled at the same increments too; at this model's speed a window spans a few
of the clock's ticks only.

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
window = 10_000  # increments averaged at each end: the progress lines reach this script in bursts
early = 6_000  # the window: increments 1,001-11,000, past the step's first increments

work = tempfile.mkdtemp(prefix="tunica-output-scaling-")
deck = os.path.join(work, "long.yaml")
text = open(os.path.join(root, "examples", "rat-aorta-inflation.yaml")).read()
text = text.replace("increments: 20", f"increments: {increments}")
text = text.replace("output:\n", "output:\n  vtk_every: 10000\n  vtk_segments: 8\n", 1)
open(deck, "w").write(text)
out = os.path.join(work, "out")

done = re.compile(r"^step 2 'inflation' increment (\d+) ")
stamps, cpu = {}, {}
tick_s = 1.0 / os.sysconf("SC_CLK_TCK")
wanted = {early - window // 2, early + window // 2, increments - window, increments}


def cpu_seconds(pid):
    fields = open(f"/proc/{pid}/stat").read().rsplit(")", 1)[1].split()
    return (int(fields[11]) * tick_s, int(fields[12]) * tick_s)  # utime, stime
start = time.monotonic()
p = subprocess.Popen([tunica, "run", deck, "-o", out, "-j", "1"], stdout=subprocess.PIPE, text=True)
for line in p.stdout:
    m = done.match(line)
    if m:
        k = int(m.group(1))
        stamps[k] = time.monotonic()
        if k in wanted:
            cpu[k] = cpu_seconds(p.pid)
if p.wait() != 0:
    sys.exit(f"tunica exited with {p.returncode}")
total = time.monotonic() - start


def per_increment(table, last, part=None):
    if part is None and isinstance(table[last], tuple):
        return per_increment(table, last, 0) + per_increment(table, last, 1)
    a, b = table[last - window], table[last]
    return ((b[part] - a[part]) if part is not None else (b - a)) / window


near_early = per_increment(stamps, early + window // 2)
near_end = per_increment(stamps, increments)

cpu_early = per_increment(cpu, early + window // 2)
cpu_end = per_increment(cpu, increments)
sizes = {f: os.path.getsize(os.path.join(out, f)) for f in ("history.csv", "newton.csv", "restart.txt", "frames.csv")}
print(f"{increments} increments in {total:.1f} s")
print(f"time per increment, increments {early - window // 2 + 1}-{early + window // 2}: {1e3 * near_early:.3f} ms")
print(f"time per increment, increments {increments - window + 1}-{increments}: {1e3 * near_end:.3f} ms")
print(f"ratio end / early: {near_end / near_early:.3f} (target at most 1.2)")
print(f"CPU time per increment, same windows: {1e3 * cpu_early:.3f} ms and {1e3 * cpu_end:.3f} ms, "
      f"ratio {cpu_end / cpu_early:.3f} (the clock ticks every {1e3 * tick_s:.0f} ms: "
      f"{1e3 * tick_s / window:.3f} ms per increment over a window)")
print("  of which user / system: " + " and ".join(
    f"{1e3 * per_increment(cpu, k, 0):.3f} / {1e3 * per_increment(cpu, k, 1):.3f} ms" for k in (early + window // 2, increments)))
print("files at the end: " + ", ".join(f"{f} {s} bytes" for f, s in sizes.items()))
shutil.rmtree(work)
sys.exit(0 if near_end / near_early <= 1.2 else 1)
