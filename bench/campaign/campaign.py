#!/usr/bin/env python3
"""Convergence campaign: decks a user would write from the user guide, each run with the
default solver settings (no `solver` section), and a table of what happened: converged or
not, increments, Newton iterations per increment, failed attempts (cut-backs and plain-start retries), the observed order, wall time.

    python3 bench/campaign/campaign.py build/tunica OUTDIR [--only SUBSTRING] [--jobs 1]

Writes OUTDIR/<deck>.yaml, OUTDIR/<deck>/ (the run) and OUTDIR/campaign.md (the table). It is
its own target, not part of the test suite (the largest decks take minutes)."""
import argparse, csv, itertools, math, os, subprocess, sys, time

MATERIALS = {
    # name: (material line, pressure target with unit, thickness, radius for tubes/spheres)
    "neo_hookean": ("{type: neo_hookean, mu: 1 MPa}", "10 kPa", "0.1 mm", "2 mm"),
    "mooney_rivlin": ("{type: mooney_rivlin, b1: 0.5 MPa, b2: 0.05 MPa}", "10 kPa", "0.1 mm", "2 mm"),
    "ogden": ("{type: ogden, mu: [0.63 MPa, 0.0012 MPa, -0.01 MPa], alpha: [1.3, 5.0, -2.0]}", "8 kPa", "0.1 mm", "2 mm"),
    "fung": ("{type: fung, c: 61.163 kPa, a1: 0.68238, a2: 0.60558, a4: 0.1067}", "120 mmHg", "0.122 mm", "0.763 mm"),
    "hgo": ("{type: hgo, mu: 30 kPa, k1: 100 kPa, k2: 5, beta: 40 deg, kappa: 0.1}", "120 mmHg", "0.3 mm", "2 mm"),
}

FRAME = "    frame: {type: cylindrical, axis: [0, 0, 1]}\n"


def tube_closed(mat, around, along, shape, increments):
    m, p, h, r = MATERIALS[mat]
    return f"""title: campaign closed tube, {mat}, {around}x{along} {shape}, {increments} increment(s)
units: {{length: mm, force: N}}
materials:
  wall: {m}
parts:
  vessel:
    element: membrane
    material: wall
    thickness: {h}
    mesh: {{type: tube, radius: {r}, length: 5 mm, around: {around}, along: {along}, shape: {shape}}}
{FRAME}boundary:
  bottom: {{node_set: vessel.bottom, dofs: [x, y, z]}}
  top: {{node_set: vessel.top, dofs: [x, y, z]}}
loads:
  blood: {{type: pressure, part: vessel, volume_axis: [0, 0, 1]}}
steps:
  - {{name: inflation, increments: {increments}, set: {{blood: {p}}}}}
output: {{vtk: false, history: [{{quantity: volume, load: blood, unit: mm^3}}]}}
"""


def tube_quarter_prestretch(mat, around, along, shape, increments):
    m, p, h, r = MATERIALS[mat]
    return f"""title: campaign quarter tube, {mat}, prestretch 1.3 then inflation, {around}x{along} {shape}
units: {{length: mm, force: N}}
materials:
  wall: {m}
parts:
  vessel:
    element: membrane
    material: wall
    thickness: {h}
    mesh: {{type: tube, radius: {r}, length: 2 mm, sector: 90 deg, around: {around}, along: {along}, shape: {shape}}}
{FRAME}boundary:
  sym_x: {{node_set: vessel.x0, dofs: [x]}}
  sym_y: {{node_set: vessel.y0, dofs: [y]}}
  base: {{node_set: vessel.bottom, dofs: [z]}}
  stretch: {{node_set: vessel.top, dofs: [z]}}
loads:
  blood: {{type: pressure, part: vessel, volume_axis: [0, 0, 1]}}
steps:
  - {{name: prestretch, increments: {max(1, increments // 2)}, set: {{stretch: 0.6 mm, blood: 1 kPa}}}}
  - {{name: inflation, increments: {increments}, set: {{blood: {p}}}}}
output: {{vtk: false}}
"""


def octant(mat, n, shape, increments):
    m, p, h, r = MATERIALS[mat]
    return f"""title: campaign sphere octant, {mat}, n {n} {shape}, {increments} increment(s)
units: {{length: mm, force: N}}
materials:
  wall: {m}
parts:
  balloon:
    element: membrane
    material: wall
    thickness: {h}
    mesh: {{type: octant, radius: {r}, n: {n}, shape: {shape}}}
{FRAME}boundary:
  sym_x: {{node_set: balloon.x0, dofs: [x]}}
  sym_y: {{node_set: balloon.y0, dofs: [y]}}
  sym_z: {{node_set: balloon.z0, dofs: [z]}}
loads:
  inflation: {{type: pressure, part: balloon}}
steps:
  - {{name: inflate, increments: {increments}, set: {{inflation: {p}}}}}
output: {{vtk: false}}
"""


def axisym_tube(mat, elements, increments):
    m, p, h, r = MATERIALS[mat]
    return f"""title: campaign axisymmetric tube, {mat}, {elements} elements
units: {{length: mm, force: N}}
materials:
  wall: {m}
parts:
  wall:
    element: axisymmetric_membrane
    material: wall
    thickness: {h}
    mesh: {{type: line, from: [{r}, 0 mm], to: [{r}, 2 mm], elements: {elements}}}
boundary:
  base: {{node_set: wall.start, dofs: [z]}}
  stretch: {{node_set: wall.end, dofs: [z]}}
loads:
  lumen: {{type: pressure, part: wall}}
steps:
  - {{name: prestretch, increments: {max(1, increments // 2)}, set: {{stretch: 0.6 mm}}}}
  - {{name: inflation, increments: {increments}, set: {{lumen: {p}}}}}
output: {{vtk: false}}
"""


def hgo_artery(prestretch_increments, inflation_increments):
    """A 3-D HGO artery as the user guide describes one: R 1.5 mm, H 0.3 mm, 32 x 40 quads,
    fibres at ±40°, stretched to λz = 1.1 under 1 kPa, then inflated to 150 mmHg."""
    return f"""title: campaign HGO artery, 32x40 quads, lambda_z 1.1 then 150 mmHg
units: {{length: mm, force: N}}
materials:
  wall: {MATERIALS["hgo"][0]}
parts:
  artery:
    element: membrane
    material: wall
    thickness: 0.3 mm
    mesh: {{type: tube, radius: 1.5 mm, length: 10 mm, around: 32, along: 40, shape: quad}}
{FRAME}boundary:
  bottom: {{node_set: artery.bottom, dofs: [x, y, z]}}
  top_xy: {{node_set: artery.top, dofs: [x, y]}}
  top: {{node_set: artery.top, dofs: [z]}}
loads:
  blood: {{type: pressure, part: artery, volume_axis: [0, 0, 1]}}
steps:
  - {{name: prestretch, increments: {prestretch_increments}, set: {{top: 1 mm, blood: 1 kPa}}}}
  - {{name: inflation, increments: {inflation_increments}, set: {{blood: 150 mmHg}}}}
output: {{vtk: false}}
"""


def sac_axisym(elements, whole):
    """A Mooney-Rivlin sac (R 4 mm, H 0.05 mm) inflated under volume control from rest to
    lambda = 2.5, past its pressure maximum: the whole meridian or the upper half."""
    start = -90 if whole else 0
    south = "  south: {node_set: sac.start, dofs: [r, z]}\n" if whole else "  equator: {node_set: sac.start, dofs: [z]}\n"
    volume = "4188.790205" if whole else "2094.395102"
    return f"""title: campaign Mooney-Rivlin sac, {'whole' if whole else 'half'} meridian of {elements}, volume control from rest
units: {{length: mm, force: N}}
materials:
  wall: {{type: mooney_rivlin, b1: 150 kPa, b2: 30 kPa}}
parts:
  sac:
    element: axisymmetric_membrane
    material: wall
    thickness: 0.05 mm
    mesh: {{type: arc, center: [0 mm, 0 mm], radius: 4 mm, start_angle: {start} deg, end_angle: 90 deg, elements: {elements}}}
boundary:
{south}  north: {{node_set: sac.end, dofs: [r]}}
loads:
  blood: {{type: pressure, part: sac}}
steps:
  - {{name: inflate, increments: 10, volume_control: {{load: blood, volume: {volume} mm^3}}}}
output: {{vtk: false}}
"""


def hgo_quarter_tube(around, along):
    """An HGO quarter tube of triangles stretched from rest to lambda_z = 1.3 under 10 mmHg, then
    inflated to 120 mmHg (as the user guide's rat-aorta-3d is written)."""
    return f"""title: campaign HGO quarter tube, {around}x{along} triangles, stretch with 10 mmHg then 120 mmHg
units: {{length: mm, force: N}}
materials:
  media: {{type: hgo, mu: 30 kPa, k1: 200 kPa, k2: 8, beta: 40 deg, kappa: 0.1}}
parts:
  wall:
    element: membrane
    material: media
    thickness: 0.2 mm
    mesh: {{type: tube, radius: 1.5 mm, length: 5 mm, sector: 90 deg, around: {around}, along: {along}, shape: triangle}}
{FRAME}boundary:
  sym_x: {{node_set: wall.x0, dofs: [x]}}
  sym_y: {{node_set: wall.y0, dofs: [y]}}
  base: {{node_set: wall.bottom, dofs: [z]}}
  stretch: {{node_set: wall.top, dofs: [z]}}
loads:
  lumen: {{type: pressure, part: wall}}
steps:
  - {{name: prestretch, increments: 2, set: {{stretch: 1.5 mm, lumen: 10 mmHg}}}}
  - {{name: inflation, increments: 4, set: {{lumen: 120 mmHg}}}}
output: {{vtk: false}}
"""


def tube_stretch_alone(mat, around, along, shape):
    """A closed tube stretched to λz = 1.2 with no pressure (a step without pressure, theory manual
    §7.3), then inflated: the seventh to tenth docs-only trials' decks."""
    m, p, h, r = MATERIALS[mat]
    return f"""title: campaign closed tube, {mat}, {around}x{along} {shape}, stretch alone then inflation
units: {{length: mm, force: N}}
materials:
  wall: {m}
parts:
  vessel:
    element: membrane
    material: wall
    thickness: {h}
    mesh: {{type: tube, radius: {r}, length: 10 mm, around: {around}, along: {along}, shape: {shape}}}
{FRAME}boundary:
  sym_x: {{node_set: vessel.x0, dofs: [x]}}
  sym_y: {{node_set: vessel.y0, dofs: [y]}}
  base: {{node_set: vessel.bottom, dofs: [z]}}
  stretch: {{node_set: vessel.top, dofs: [z]}}
loads:
  blood: {{type: pressure, part: vessel, volume_axis: [0, 0, 1]}}
steps:
  - {{name: prestretch, increments: 4, set: {{stretch: 2 mm}}}}
  - {{name: inflation, increments: 10, set: {{blood: {p}}}}}
output: {{vtk: false}}
"""


def balloon_sleeve(penalty):
    """A Mooney-Rivlin capsule balloon (R 1 mm, H 0.05 mm, 4 mm long) inflated to 0.5 MPa against a
    rigid sleeve of radius 1.3 mm in 10 increments: first contact with the user guide's penalty."""
    return f"""title: campaign balloon against a rigid sleeve, penalty {penalty} N/mm^3
units: {{length: mm, force: N}}
materials:
  balloon: {{type: mooney_rivlin, b1: 2.0 MPa, b2: 0.5 MPa}}
parts:
  balloon:
    element: axisymmetric_membrane
    material: balloon
    thickness: 0.05 mm
    mesh:
      - {{type: arc, center: [0 mm, 0 mm], radius: 1 mm, start_angle: -90 deg, end_angle: 0 deg, elements: 20}}
      - {{type: line, from: [1 mm, 0 mm], to: [1 mm, 4 mm], elements: 40}}
      - {{type: arc, center: [0 mm, 4 mm], radius: 1 mm, start_angle: 0 deg, end_angle: 90 deg, elements: 20}}
boundary:
  south: {{node_set: balloon.start, dofs: [r, z]}}
  north: {{node_set: balloon.end, dofs: [r]}}
loads:
  inflation: {{type: pressure, part: balloon}}
rigid_surfaces:
  sleeve: {{type: cylinder, radius: 1.3 mm, side: inside}}
contact:
  balloon_sleeve: {{slave: balloon, rigid: sleeve, penalty: {penalty} N/mm^3, offset: 0.025 mm}}
steps:
  - {{name: inflate, increments: 10, set: {{inflation: 0.5 MPa}}}}
output: {{vtk: false}}
"""


def capsule_in_artery(prestretch):
    """A compliant Mooney-Rivlin capsule (R 1 mm, H 0.05 mm, a 6 mm cylinder between hemispherical
    caps) filled under volume control inside a Fung artery (R 1.6 mm): past its pressure maximum it
    spreads along the artery at a nearly constant pressure (the edge of its contact zone carries
    almost no pressure). `prestretch`: the artery's axial stretch first, else none (a slack master)."""
    step = "  - {name: prestretch, increments: 4, set: {a_top: 0.6 mm}}\n" if prestretch else ""
    return f"""title: campaign capsule filling an artery{'' if prestretch else ' without prestretch'}
units: {{length: mm, force: N}}
materials:
  artery: {{type: fung, c: 40 kPa, a1: 1.0, a2: 0.8, a4: 0.1}}
  balloon: {{type: mooney_rivlin, b1: 0.5 MPa, b2: 0.05 MPa}}
parts:
  artery:
    element: axisymmetric_membrane
    material: artery
    thickness: 0.3 mm
    mesh: {{type: line, from: [1.6 mm, -2 mm], to: [1.6 mm, 10 mm], elements: 60}}
  balloon:
    element: axisymmetric_membrane
    material: balloon
    thickness: 0.05 mm
    mesh:
      - {{type: arc, center: [0 mm, 1 mm], radius: 1 mm, start_angle: -90 deg, end_angle: 0 deg, elements: 10}}
      - {{type: line, from: [1 mm, 1 mm], to: [1 mm, 7 mm], elements: 30}}
      - {{type: arc, center: [0 mm, 7 mm], radius: 1 mm, start_angle: 0 deg, end_angle: 90 deg, elements: 10}}
boundary:
  a_base: {{node_set: artery.start, dofs: [z]}}
  a_top: {{node_set: artery.end, dofs: [z]}}
  b_south: {{node_set: balloon.start, dofs: [r, z]}}
  b_north: {{node_set: balloon.end, dofs: [r]}}
loads:
  inflation: {{type: pressure, part: balloon}}
contact:
  b_a: {{slave: balloon, master: artery, master_orientation: reversed, penalty: 1e3 N/mm^3, offset: 0.175 mm}}
steps:
{step}  - {{name: dilate, increments: 20, volume_control: {{load: inflation, volume: 70 mm^3}}}}
output: {{vtk: false}}
"""


def decks():
    out = {}
    for mat in MATERIALS:
        out[f"closed-tube-{mat}-tri-64x16-10inc"] = tube_closed(mat, 64, 16, "staggered_triangle", 10)
        out[f"closed-tube-{mat}-quad-64x16-1inc"] = tube_closed(mat, 64, 16, "quad", 1)
        out[f"quarter-tube-{mat}-quad-16x8"] = tube_quarter_prestretch(mat, 16, 8, "quad", 6)
        out[f"quarter-tube-{mat}-tri-16x8"] = tube_quarter_prestretch(mat, 16, 8, "triangle", 6)
        out[f"octant-{mat}-quad-n12-1inc"] = octant(mat, 12, "quad", 1)
        out[f"octant-{mat}-tri-n12-10inc"] = octant(mat, 12, "triangle", 10)
        out[f"axisym-tube-{mat}-20"] = axisym_tube(mat, 20, 10)
    for mat in ("hgo", "neo_hookean"):
        out[f"closed-tube-{mat}-tri-256x64-10inc"] = tube_closed(mat, 256, 64, "staggered_triangle", 10)
        out[f"octant-{mat}-quad-n58-10inc"] = octant(mat, 58, "quad", 10)
    # Triangle HGO tubes inflated from rest in one increment (the default stiffened start), and
    # one of about 100k elements (2 x 512 x 100 = 102,400 triangles).
    out["closed-tube-hgo-tri-192x48-1inc"] = tube_closed("hgo", 192, 48, "staggered_triangle", 1)
    out["closed-tube-hgo-tri-256x64-1inc"] = tube_closed("hgo", 256, 64, "staggered_triangle", 1)
    out["closed-tube-hgo-tri-512x100-10inc"] = tube_closed("hgo", 512, 100, "staggered_triangle", 10)
    # The HGO artery of the user guide in one increment per step, and in 5 + 10.
    out["hgo-artery-quad-32x40-1+1inc"] = hgo_artery(1, 1)
    out["hgo-artery-quad-32x40-5+10inc"] = hgo_artery(5, 10)
    # Volume control from rest through the pressure maximum on fine meridians, and an HGO quarter
    # tube stretched from rest (the fifth docs-only trial's decks).
    out["sac-mooney_rivlin-axisym-whole-1000-volume-10inc"] = sac_axisym(1000, True)
    out["sac-mooney_rivlin-axisym-half-500-volume-10inc"] = sac_axisym(500, False)
    out["quarter-tube-hgo-tri-50x200-stretch-10mmHg"] = hgo_quarter_tube(50, 200)
    # Closed tubes stretched with no pressure, then inflated.
    out["closed-tube-hgo-quad-128x40-stretch-alone"] = tube_stretch_alone("hgo", 128, 40, "quad")
    out["closed-tube-fung-tri-48x12-stretch-alone"] = tube_stretch_alone("fung", 48, 12, "triangle")
    out["closed-tube-neo_hookean-tri-64x16-stretch-alone"] = tube_stretch_alone("neo_hookean", 64, 16, "staggered_triangle")
    # A balloon meeting a rigid sleeve with the guide's penalty and ten times it.
    out["balloon-sleeve-penalty-1e5"] = balloon_sleeve("1e5")
    out["balloon-sleeve-penalty-1e6"] = balloon_sleeve("1e6")
    # A compliant capsule filled under volume control inside an artery, with and without the
    # artery's prestretch (the sixteenth docs-only trial's deck): its contact front chatters.
    out["capsule-artery-volume-prestretched"] = capsule_in_artery(True)
    out["capsule-artery-volume-slack"] = capsule_in_artery(False)
    # The shipped examples as they are, and the angioplasty balloon made softer.
    here = os.path.dirname(os.path.abspath(__file__))
    examples = os.path.join(here, "..", "..", "examples")
    for f in sorted(os.listdir(examples)):
        if f.endswith(".yaml"):
            text = open(os.path.join(examples, f)).read()
            text = text.replace("file: meshes/", "file: " + os.path.join(os.path.abspath(examples), "meshes") + "/")
            out["example-" + f[:-5]] = text
    angioplasty = out["example-balloon-angioplasty"]
    for b1, b2 in (("1.5", "0.375"), ("1.0", "0.25")):
        soft = angioplasty.replace(
            "balloon: {type: mooney_rivlin, b1: 2.0 MPa, b2: 0.5 MPa}", f"balloon: {{type: mooney_rivlin, b1: {b1} MPa, b2: {b2} MPa}}")
        if soft == angioplasty:
            sys.exit("campaign.py: the balloon material of examples/balloon-angioplasty.yaml has changed; update the soft decks")
        out[f"angioplasty-balloon-b1-{b1}-b2-{b2}"] = soft
    return out


def summarize(run_dir):
    """(increments, iterations, max per increment, failed attempts, order) from newton.csv. The order
    is the median over the converged attempts of log r_k / log r_(k−1) for the first pair of
    relative residuals with r_(k−1) < 1e-2 and r_k > 1e-13: 2 for quadratic convergence."""
    path = os.path.join(run_dir, "newton.csv")
    if not os.path.exists(path):
        return 0, 0, 0, 0, None
    attempts, residuals = {}, {}
    with open(path) as f:
        for row in csv.DictReader(f):
            key = (int(row["step"]), int(row["increment"]), int(row["attempt"]))
            attempts[key] = max(attempts.get(key, 0), int(row["iteration"]))
            residuals.setdefault(key, []).append(float(row["relative_residual"]))
    finals = {}
    for (s, i, a), it in attempts.items():
        if (s, i) not in finals or a > finals[(s, i)][0]:
            finals[(s, i)] = (a, it)
    cutbacks = sum(1 for (s, i, a) in attempts if a > 0)
    its = [it for a, it in finals.values()]
    orders = []
    for (s, i), (a, it) in finals.items():
        r = residuals[(s, i, a)]
        # The first pair inside the basin measures the order; the last one often lands on the
        # round-off floor (1e-12 … 1e-10 relative, by model size) and reads lower.
        pairs = [(r[k - 1], r[k]) for k in range(1, len(r)) if 0 < r[k - 1] < 1e-2 and r[k] > 1e-13]
        if pairs:
            orders.append(math.log(pairs[0][1]) / math.log(pairs[0][0]))
    order = sorted(orders)[len(orders) // 2] if orders else None
    return len(finals), sum(its), max(its) if its else 0, cutbacks, order


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("tunica")
    ap.add_argument("outdir")
    ap.add_argument("--only", default="")
    args = ap.parse_args()
    os.makedirs(args.outdir, exist_ok=True)
    rows = []
    for name, text in decks().items():
        if args.only not in name:
            continue
        deck = os.path.join(args.outdir, name + ".yaml")
        with open(deck, "w") as f:
            f.write(text)
        run = os.path.join(args.outdir, name)
        t0 = time.time()
        p = subprocess.run([args.tunica, "run", deck, "-q", "--allow-scripts", "-o", run], capture_output=True, text=True)
        dt = time.time() - t0
        inc, its, most, cut, order = summarize(run)
        rows.append((name, p.returncode, inc, its, most, cut, dt, (p.stderr.strip().splitlines() or [""])[-1][:160], order))
        print(f"{name}: exit {p.returncode}, {inc} increments, {its} iterations, max {most}, {cut} failed attempts, {dt:.1f} s",
              flush=True)
    with open(os.path.join(args.outdir, "campaign.md"), "w") as f:
        f.write("| deck | exit | increments | iterations / increment | max | failed attempts | order | wall s |\n"
                "|---|---|---|---|---|---|---|---|\n")
        for name, rc, inc, its, most, cut, dt, err, order in rows:
            o = "—" if order is None else f"{order:.2f}"
            f.write(f"| {name} | {rc} | {inc} | {its / inc if inc else 0:.2f} | {most} | {cut} | {o} | {dt:.1f} |\n")
        failed = [r for r in rows if r[1] != 0]
        n = sum(r[2] for r in rows)
        f.write(f"\n{len(rows) - len(failed)} of {len(rows)} decks converged with the defaults; "
                f"{sum(r[3] for r in rows) / n if n else 0:.2f} iterations per increment over all.\n")
        for r in failed:
            f.write(f"\n- {r[0]} (exit {r[1]}): {r[7]}\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
