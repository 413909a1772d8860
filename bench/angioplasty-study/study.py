#!/usr/bin/env python3
"""The paper's angioplasty example (Holzapfel et al. 1996, §4.2) under every reading of what
its text leaves open: the plaque moduli's unit, the plaque outline, the balloon's Mooney–Rivlin
constants and the surface of the balloon that touches the plaque. Each combination is a copy of
examples/balloon-angioplasty.yaml with only those values changed, run with the deck's settings;
the table gives how far it got, the peak balloon–plaque contact pressure over the inflation
(the paper: 0.419 N/mm² at 2.05 N/mm²), the lumen at the stenosis centre, the contact force.

    python3 bench/angioplasty-study/study.py build/tunica OUTDIR [--only SUBSTRING] [--jobs 2] [--reuse]

Writes OUTDIR/<case>.yaml, OUTDIR/<case>/ (the run), OUTDIR/study.md (the table) and
OUTDIR/study-peaks.png (the kPa cases' peak contact pressures); --reuse takes the runs already there.
docs/examples/angioplasty-study.md discusses the result."""
import argparse, csv, math, os, re, subprocess, sys, time
from concurrent.futures import ThreadPoolExecutor

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BASE = os.path.join(ROOT, "examples", "balloon-angioplasty.yaml")
PAPER_PEAK = 0.419  # N/mm², paper §4.2

# Plaque moduli as printed, "G = 500 N/m², K = 724.6 N/m²": the unit read as printed (Pa),
# as kPa (the example's choice) and as N/mm² (= MPa).
PLAQUE_UNITS = ["Pa", "kPa", "MPa"]

# Balloon constants, printed "b1/b2 = 113.225": the ratio read three ways, each at the
# example's initial shear modulus μ = 2 (b1 + b2) = 5 MPa; the example's own constants and the
# two softer balloons of the same ratio 4.
BALLOONS = {
    "r113": (2.5 * 113.225 / 114.225, 2.5 / 114.225),
    "r11.3": (2.5 * 11.3225 / 12.3225, 2.5 / 12.3225),
    "r1/13": (2.5 / 14.225, 2.5 * 13.225 / 14.225),
    "deck": (2.0, 0.5),
    "soft1.5": (1.5, 0.375),
    "soft1.0": (1.0, 0.25),
}

# Plaque outline: the example's cosine bump over the whole 3.8 mm, or the paper's "circularly
# shaped with radius 0.28 mm": a circular mound of radius 0.28 mm whose deepest point is the
# lumen radius 0.39 mm, on the 0.01 mm layer that covers the rest of the stenosis.
R_ENDS, R_CENTRE, RHO, Z0, Z1 = 0.6096, 0.39, 0.28, 0.1, 3.9


def circular_outline(rows=300):
    zc, rc = 0.5 * (Z0 + Z1), R_CENTRE + RHO
    pts = []
    for j in range(rows + 1):
        z = Z0 + (Z1 - Z0) * j / rows
        s = z - zc
        r = R_ENDS if abs(s) >= RHO else min(R_ENDS, rc - math.sqrt(RHO * RHO - s * s))
        pts.append(f"[{r:.6f} mm, {z:.6f} mm]")
    return "[" + ", ".join(pts) + "]"


# Contact at the balloon's mid-surface (offset 0, the example) or its outer surface (offset
# H/2 = 0.05 mm). The stress-free balloon's outer surface (0.40 mm) would start 0.01 mm inside
# the lumen (0.39 mm); for the outer-surface reading the balloon's mid-surface radius is
# therefore 0.34 mm, its outer surface touching the lumen at the start.
SURFACES = ["mid", "outer"]

# With the plaque in kPa these also run with two-pass balloon–plaque contact (`passes: 2`): the
# soft balloons, which stop in one-pass contact, the deck's and the plausible ratio 11.3225.
TWO_PASS_BALLOONS = ["r11.3", "deck", "soft1.5", "soft1.0"]


def replace_once(text, old, new):
    if text.count(old) != 1:
        sys.exit(f"study.py: '{old}' occurs {text.count(old)} times in {BASE}, expected once")
    return text.replace(old, new)


def deck(unit, outline, balloon, surface, passes=1):
    s = open(BASE, encoding="utf-8").read()
    s = replace_once(s, "mu: 500 kPa, kappa: 724.6 kPa", f"mu: 500 {unit}, kappa: 724.6 {unit}")
    b1, b2 = BALLOONS[balloon]
    s = replace_once(s, "b1: 2.0 MPa, b2: 0.5 MPa", f"b1: {b1:.6g} MPa, b2: {b2:.6g} MPa")
    if outline == "circular":
        s = replace_once(s, "inner: {radius_ends: 0.6096 mm, radius_centre: 0.39 mm, shape: cosine}",
                         f"inner: {circular_outline()}")
    if surface == "outer":
        s = replace_once(s, "radius: 0.35 mm, start_angle", "radius: 0.34 mm, start_angle")
        s = replace_once(s, "    penalty: 2e3 N/mm^3\n    offset: 0 mm", "    penalty: 2e3 N/mm^3\n    offset: 0.05 mm")
    # The deck's balloon–plaque pair has two passes (the reverse pass, theory manual §9.1); the
    # study runs one or two.
    s = replace_once(s, "    passes: 2\n", f"    passes: {passes}\n")
    # The lumen radius at the stenosis centre: the plaque's inner node on its middle row.
    s = replace_once(s, "  balloon_poles: {part: balloon, nodes: [0, 101]}",
                     "  balloon_poles: {part: balloon, nodes: [0, 101]}\n  lumen_centre: {part: plaque, nodes: [900]}")
    s = replace_once(s, "    - {quantity: position_r, node_set: plaque.inner, reduce: min, name: lumen_min, unit: mm}",
                     "    - {quantity: position_r, node_set: plaque.inner, reduce: min, name: lumen_min, unit: mm}\n"
                     "    - {quantity: position_r, node_set: lumen_centre, reduce: max, name: lumen_centre, unit: mm}")
    return s


def run_case(tunica, outdir, name, text, reuse=False):
    path = os.path.join(outdir, name + ".yaml")
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)
    run_dir = os.path.join(outdir, name)
    done = os.path.join(run_dir, "study-run.txt")  # exit code, wall time, the run's last message
    if reuse and os.path.exists(done):
        code, wall, msg = open(done, encoding="utf-8").read().split("\n", 2)
        code, wall = int(code), float(wall)
    else:
        t0 = time.time()
        p = subprocess.run([tunica, "run", "-q", "-j", "1", path, "-o", run_dir], capture_output=True, text=True)
        code, wall = p.returncode, time.time() - t0
        msg = p.stderr.strip().splitlines()[-1] if p.stderr.strip() else ""
        with open(done, "w", encoding="utf-8") as f:
            f.write(f"{code}\n{wall}\n{msg}")
    row = {"case": name, "exit": code, "wall": wall, "why": ""}
    if code != 0:
        # The run's own diagnosis (solver/failure_hints.cpp): a pressure maximum, a one-pass
        # contact whose slave nodes lie far apart on the master, or the last attempt's failure.
        spacing = re.search(r"lie on average ([0-9.]+) master segments apart", msg)
        if "likely at a maximum" in msg:
            row["why"] = "pressure maximum (limit point)"
        elif spacing:
            row["why"] = f"contact: slave nodes {spacing.group(1)} master segments apart" + \
                         (" (p still rising)" if "still rises" in msg else "")
        elif "still rises" in msg:
            row["why"] = "p still rising; a local failure"
        else:
            head = msg.split("): ", 1)[-1]
            row["why"] = head.split(";")[0][:80]
    hist = os.path.join(run_dir, "history.csv")
    rows = list(csv.DictReader(open(hist))) if os.path.exists(hist) else []
    infl = [r for r in rows if r["step"] == "3"]
    if infl:
        last = infl[-1]
        row["p_reached"] = float(last["pressure_MPa"])
        pcs = [abs(float(r["pc_balloon_plaque_MPa"])) for r in infl]
        row["peak"] = max(pcs)
        row["peak_at_p"] = float(infl[pcs.index(row["peak"])]["pressure_MPa"])
        touch = [float(r["pressure_MPa"]) for r in infl if abs(float(r["pc_balloon_plaque_MPa"])) > 0]
        row["touch_p"] = touch[0] if touch else None
        row["lumen"] = float(last["lumen_centre_mm"])
        row["lumen0"] = float(rows[0]["lumen_centre_mm"])
        row["force"] = abs(float(last["force_balloon_plaque_N"]))
    return row


def fmt(v, f):
    return "—" if v is None else format(v, f)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("tunica")
    ap.add_argument("outdir")
    ap.add_argument("--only", default="")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--reuse", action="store_true", help="take the runs already in OUTDIR (table and figure only)")
    a = ap.parse_args()
    os.makedirs(a.outdir, exist_ok=True)
    cases = []
    for unit in PLAQUE_UNITS:
        for outline in ["cosine", "circular"]:
            # The printed unit (Pa) makes the plaque 10⁴ times softer than the wall: run with the
            # example's balloon only, to show it.
            for balloon in (["deck"] if unit == "Pa" else BALLOONS):
                for surface in SURFACES:
                    name = f"plaque-{unit}-{outline}-balloon-{balloon.replace('/', '_')}-{surface}"
                    if a.only in name:
                        cases.append((name, (unit, outline, balloon, surface, 1)))
                    # Two-pass contact for the balloons that stop in one-pass contact (kPa plaque).
                    if unit == "kPa" and balloon in TWO_PASS_BALLOONS and a.only in name + "-2pass":
                        cases.append((name + "-2pass", (unit, outline, balloon, surface, 2)))
    with ThreadPoolExecutor(max_workers=a.jobs) as ex:
        futs = [(c, ex.submit(run_case, a.tunica, a.outdir, c[0], deck(*c[1]), a.reuse)) for c in cases]
        results = []
        for (name, key), fu in futs:
            r = fu.result()
            r["key"] = key
            results.append(r)
            print(f"{name}: exit {r['exit']}, p {fmt(r.get('p_reached'), '.4g')} N/mm², peak "
                  f"{fmt(r.get('peak'), '.4g')} N/mm², {r['wall']:.1f} s", flush=True)
    lines = ["| plaque G, K unit | outline | balloon b₁ / b₂ (MPa) | contact surface | passes | exit | pressure reached (N/mm²) "
             "| first contact at p (N/mm²) | peak contact pressure (N/mm²) | at p (N/mm²) | lumen at centre (mm) "
             "| lumen gain (mm) | contact force (N) | stopped by | wall s |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in results:
        unit, outline, balloon, surface, passes = r["key"]
        b1, b2 = BALLOONS[balloon]
        lumen = r.get("lumen")
        gain = lumen - r["lumen0"] if lumen is not None else None
        lines.append(
            f"| {unit} | {outline} | {b1:.4g} / {b2:.4g} ({balloon}) | {surface} | {passes} | {r['exit']} | "
            f"{fmt(r.get('p_reached'), '.4g')} | {fmt(r.get('touch_p'), '.3g')} | {fmt(r.get('peak'), '.4g')} | "
            f"{fmt(r.get('peak_at_p'), '.3g')} | {fmt(lumen, '.4f')} | {fmt(gain, '.4f')} | {fmt(r.get('force'), '.4g')} | {r['why'] or '—'} | "
            f"{r['wall']:.0f} |")
    reached = [r for r in results if r["exit"] == 0 and r.get("peak") is not None]
    if reached:
        best = min(reached, key=lambda r: abs(r["peak"] - PAPER_PEAK))
        lines += ["", f"{len(reached)} of {len(results)} cases reach 2.05 N/mm². Closest to the paper's "
                  f"{PAPER_PEAK} N/mm²: {best['case']}, {best['peak']:.4g} N/mm²."]
    with open(os.path.join(a.outdir, "study.md"), "w", encoding="utf-8") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))
    plot(results, os.path.join(a.outdir, "study-peaks.png"))


def plot(results, path):
    """Peak contact pressure of every kPa case, grouped by balloon, against the paper's value;
    an open marker is a run that stopped before 2.05 N/mm² (its peak up to there)."""
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("study.py: matplotlib missing (apt-get install python3-matplotlib): no figure", file=sys.stderr)
        return
    kpa = [r for r in results if r["key"][0] == "kPa" and r.get("peak") is not None]
    if not kpa:
        return
    balloons = [b for b in BALLOONS if any(r["key"][2] == b for r in kpa)]
    styles = {("cosine", "mid"): ("o", "C0"), ("cosine", "outer"): ("s", "C1"),
              ("circular", "mid"): ("^", "C2"), ("circular", "outer"): ("D", "C3")}
    fig, ax = plt.subplots(figsize=(7.5, 4.2))
    for (outline, surface), (marker, colour) in styles.items():
        xs, ys, done = [], [], []
        for i, b in enumerate(balloons):
            for r in kpa:
                if r["key"][1:] == (outline, b, surface, 1):
                    xs.append(i + 0.12 * (list(styles).index((outline, surface)) - 1.5))
                    ys.append(r["peak"])
                    done.append(r["exit"] == 0)
        ax.scatter([x for x, d in zip(xs, done) if d], [y for y, d in zip(ys, done) if d], marker=marker,
                   color=colour, label=f"{outline} outline, contact at the {surface} surface")
        ax.scatter([x for x, d in zip(xs, done) if not d], [y for y, d in zip(ys, done) if not d],
                   marker=marker, facecolors="none", edgecolors=colour)
        # Two-pass contact: a cross beside the one-pass marker.
        tx, ty = [], []
        for i, b in enumerate(balloons):
            for r in kpa:
                if r["key"][1:] == (outline, b, surface, 2) and r["exit"] == 0:
                    tx.append(i + 0.12 * (list(styles).index((outline, surface)) - 1.5) + 0.05)
                    ty.append(r["peak"])
        ax.scatter(tx, ty, marker="x", color=colour, s=22)
    ax.axhline(PAPER_PEAK, color="k", lw=0.8, ls="--", label="paper, 0.419 N/mm² at 2.05 N/mm²")
    labels = []
    for b in balloons:
        b1, b2 = BALLOONS[b]
        labels.append(f"{b}\n{b1:.3g} / {b2:.3g}")
    ax.set_xticks(range(len(balloons)), labels, fontsize=8)
    ax.set_xlabel("balloon b₁ / b₂ (MPa)")
    ax.set_ylabel("peak balloon–plaque contact pressure (N/mm²)")
    ax.set_title("Plaque G = 500 kPa, K = 724.6 kPa; open markers: stopped before 2.05 N/mm²; "
                 "×: two-pass contact", fontsize=9)
    ax.set_ylim(0, max(0.5, 1.05 * max(r["peak"] for r in kpa)))
    ax.legend(fontsize=7, loc="lower left")
    fig.tight_layout()
    fig.savefig(path, dpi=130)
    print(f"figure: {path}")


if __name__ == "__main__":
    main()
