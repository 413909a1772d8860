"""Figure and tables of docs/performance.md from results/bench/bench.csv (bench/run.sh)."""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

rows = list(csv.DictReader(open(sys.argv[1])))
out = sys.argv[2]

def paired(r):
    """A --paired run: its bare factorizations were timed next to the run's (and its RSS holds two factors)."""
    return float(r.get("paired_bare_factor_s") or 0) > 0


# Scaling: default runs (2 threads, auto solver, exact tangent, default increments, not paired) of the tube.
tube = [r for r in rows if r["problem"] == "tube" and r["threads"] == "2" and r["symmetrized"] == "0"
        and r["solver"] == "cholmod" and not paired(r)]
tube.sort(key=lambda r: int(r["unknowns"]))
n = np.array([float(r["unknowns"]) for r in tube])
it = np.array([float(r["iteration_s"]) for r in tube])
fa = np.array([float(r["bare_factor_s"]) for r in tube])
asm = np.array([float(r["assembly_s"]) for r in tube])
fig, ax = plt.subplots(figsize=(6, 4.2))
ax.loglog(n, it, "o-", label="Newton iteration")
ax.loglog(n, fa, "s--", label="bare numeric factorization")
ax.loglog(n, asm, "^:", label="assembly of R and K")
if len(n) >= 2:
    k, c = np.polyfit(np.log(n), np.log(it), 1)
    ax.set_title(f"Fung tube, 120 mmHg: time per iteration ~ N^{k:.2f}")
    print(f"scaling exponent of the iteration time vs unknowns (tube): {k:.3f}")
    kf, _ = np.polyfit(np.log(n), np.log(fa), 1)
    ka, _ = np.polyfit(np.log(n), np.log(asm), 1)
    kr, _ = np.polyfit(np.log(n), np.log([float(r["run_s"]) for r in tube]), 1)
    km, _ = np.polyfit(np.log(n), np.log([float(r["peak_rss_MB"]) for r in tube]), 1)
    print(f"  bare factorization {kf:.3f}, assembly {ka:.3f}, whole run {kr:.3f}, peak memory {km:.3f}")
ax.set_xlabel("unknowns N")
ax.set_ylabel("seconds")
ax.grid(True, which="both", alpha=0.3)
ax.legend()
fig.tight_layout()
fig.savefig(out, dpi=150)

cols = ["problem", "size", "elements", "unknowns", "threads", "solver", "symmetrized", "residual_tolerance", "increments", "iterations",
        "max_iterations_per_increment", "iteration_s", "assembly_s", "factor_s", "solve_s", "bare_factor_s",
        "run_s", "peak_rss_MB", "closed_form_error"]
print("| " + " | ".join(cols) + " | iteration / factorization | iteration / paired factorization | assembly share |")
print("|" + "---|" * (len(cols) + 3))
for r in rows:
    ratio = float(r["iteration_s"]) / float(r["bare_factor_s"])
    pair = f"{float(r['iteration_s']) / float(r['paired_bare_factor_s']):.2f}" if paired(r) else "-"
    share = float(r["assembly_s"]) / float(r["iteration_s"])
    print("| " + " | ".join(r[c] for c in cols) + f" | {ratio:.2f} | {pair} | {100 * share:.1f} % |")
