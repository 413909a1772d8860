#!/usr/bin/env python3
"""CalculiX peer run: thin neo-Hookean sphere inflated to lambda = 1.2 (theory manual (8.3)).

Octant x, y, z >= 0 of a sphere (R = 1, H = 0.01) with symmetry BCs on the three
coordinate planes, meshed exactly like Tunica's `octant` generator
(src/mesh/surface_generators.cpp, cube_sphere with full = false): three cube faces
x = 1, y = 1, z = 1, each an n x n grid with the equal-angle coordinate
u(a) = tan((pi/4) a / n), projected radially onto the sphere; coordinates on the
symmetry planes are exactly 0. Quads are ordered counterclockwise about the outward
normal, as in Tunica. S8R mid-side nodes use the same construction on the 2n lattice
(i.e. the equal-angle coordinate at half indices).

Shells carry the exact sphere normal at every node (*NORMAL). Material
*HYPERELASTIC, NEO HOOKE with C10 = mu/2, D1 = 2/K (K from nu). Moduli and pressure
are scaled by SCALE (default 1e6: mu = 1e6) because ccx treats small residuals as
zero; the stretch at a given p/mu is unchanged. The pressure is p(lambda_target) of
the closed form p = 2 mu (H/R)(1/lambda - 1/lambda^7), a follower *DLOAD on the
shells, ramped over the step (*STATIC, automatic increments, initial = maximum =
1/increments).

Usage: sphere_ccx.py --n N [--elem S4|S8R] [--nu 0.499] [--incs 10] [--tol tight|default]
                     [--dir DIR] [--timeout 600] [--no-run]
Prints one summary block (and a machine-readable line starting with RESULT).
"""
import argparse
import math
import os
import re
import subprocess
import sys
import time


R, H, MU_PHYS, LAMBDA_TARGET = 1.0, 0.01, 1.0, 1.2


def p_closed(lam, mu):
    return 2.0 * mu * (H / R) * (1.0 / lam - lam ** -7)


def octant_mesh(n, quadratic):
    """Nodes (m x 3 array) and elements (list of corner [+ mid-side] node indices, 0-based)."""
    m = 2 * n if quadratic else n
    u = [math.tan((math.pi / 4) * a / m) for a in range(m + 1)]
    u[0], u[m] = 0.0, 1.0
    side = m + 1
    index, nodes = {}, []

    def node(l):
        key = (l[0] * side + l[1]) * side + l[2]
        if key not in index:
            c = [u[l[0]], u[l[1]], u[l[2]]]
            s = R / math.sqrt(c[0] ** 2 + c[1] ** 2 + c[2] ** 2)
            x = [0.0 if ci == 0.0 else ci * s for ci in c]
            index[key] = len(nodes)
            nodes.append(x)
        return index[key]

    elems = []
    s = 2 if quadratic else 1
    for axis in range(3):  # octant: only the faces x = 1, y = 1, z = 1 (sgn = +1)
        e1, e2 = (axis + 1) % 3, (axis + 2) % 3
        for b in range(n):
            for a in range(n):
                def at(p, q):
                    l = [0, 0, 0]
                    l[axis] = m
                    l[e1] = p
                    l[e2] = q
                    return node(l)
                A, B = s * a, s * b
                corners = [at(A, B), at(A + s, B), at(A + s, B + s), at(A, B + s)]
                if quadratic:
                    mids = [at(A + 1, B), at(A + s, B + 1), at(A + 1, B + s), at(A, B + 1)]
                    elems.append(corners + mids)
                else:
                    elems.append(corners)
    return nodes, elems


def write_deck(path, n, elem, nu, incs, tol, scale):
    quadratic = elem.upper() == "S8R"
    X, E = octant_mesh(n, quadratic)
    mu = MU_PHYS * scale
    K = 2.0 * mu * (1.0 + nu) / (3.0 * (1.0 - 2.0 * nu))
    C10, D1 = mu / 2.0, 2.0 / K
    p = p_closed(LAMBDA_TARGET, mu)
    out = []
    w = out.append
    w("*HEADING")
    w(f"Neo-Hookean sphere octant, {elem}, n={n}, {len(E)} elements, to lambda={LAMBDA_TARGET}")
    w("*NODE, NSET=NALL")
    for i, x in enumerate(X):
        w(f"{i + 1}, {x[0]:.15g}, {x[1]:.15g}, {x[2]:.15g}")
    w(f"*ELEMENT, TYPE={elem.upper()}, ELSET=EALL")
    for k, e in enumerate(E):
        w(f"{k + 1}, " + ", ".join(str(i + 1) for i in e))
    for name, ax in (("NX0", 0), ("NY0", 1), ("NZ0", 2)):
        ids = [i + 1 for i in range(len(X)) if X[i][ax] == 0.0]
        w(f"*NSET, NSET={name}")
        for j in range(0, len(ids), 10):
            w(", ".join(str(v) for v in ids[j:j + 10]))
    pole = [i + 1 for i in range(len(X)) if X[i][0] == 0.0 and X[i][1] == 0.0][0]
    w("*NSET, NSET=POLE")
    w(str(pole))
    w("*NORMAL")  # exact sphere normal at every node of every element
    for k, e in enumerate(E):
        for i in e:
            ln = math.sqrt(sum(v * v for v in X[i]))
            nrm = [v / ln for v in X[i]]
            w(f"{k + 1}, {i + 1}, {nrm[0]:.15g}, {nrm[1]:.15g}, {nrm[2]:.15g}")
    w("*MATERIAL, NAME=RUBBER")
    w("*HYPERELASTIC, NEO HOOKE")
    w(f"{C10:.12g}, {D1:.12g}")  # ccx rejects number fields longer than 20 characters
    w("*SHELL SECTION, ELSET=EALL, MATERIAL=RUBBER")
    w(f"{H:.15g}")
    w("*BOUNDARY")  # symmetry: the expanded through-thickness nodes lie in the plane too
    w("NX0, 1, 1")
    w("NY0, 2, 2")
    w("NZ0, 3, 3")
    w("*STEP, NLGEOM, INC=1000")
    w("*STATIC")
    dt = 1.0 / incs
    w(f"{dt:.15g}, 1.0, 1e-6, {dt:.15g}")
    if tol == "tight":
        # R_n (residual vs average force), C_n (correction vs largest increment
        # displacement); defaults 0.005 and 0.01 are too loose for an accuracy comparison.
        w("*CONTROLS, PARAMETERS=FIELD")
        w("1e-6, 1e-5")
    w("*DLOAD")
    w(f"EALL, P, {p:.15g}")
    w("*NODE PRINT, NSET=NALL")
    w("U")
    w("*END STEP")
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")
    return X, E, mu, p, pole


def parse_time_v(text):
    wall = rss = None
    for line in text.splitlines():
        line = line.strip()
        if line.startswith("Elapsed (wall clock) time"):
            t = line.split(": ", 1)[1].strip()
            parts = [float(v) for v in t.split(":")]
            wall = sum(v * 60 ** (len(parts) - 1 - i) for i, v in enumerate(parts))
        elif line.startswith("Maximum resident set size"):
            rss = int(line.split(":")[1]) / 1024.0  # MB (kbytes / 1024)
    return wall, rss


def parse_dat(path, X):
    """Last displacement block of the .dat: returns (time, U array)."""
    with open(path) as f:
        txt = f.read()
    blocks = re.split(r"\n\s*displacements \(vx,vy,vz\) for set NALL and time\s+", txt)
    if len(blocks) < 2:
        return None, None
    last = blocks[-1]
    t = float(last.split()[0])
    U = [[float('nan')] * 3 for _ in X]
    for line in last.splitlines()[1:]:
        f = line.split()
        if len(f) == 4:
            try:
                U[int(f[0]) - 1] = [float(v) for v in f[1:]]
            except ValueError:
                pass
    return t, U


def read_results(d, job, X, mu, p, pole):
    """What a finished ccx run in d reached: increments, iterations, step time, lambda and the p error.

    .sta: converged increments; .cvg: one line per Newton iteration (failed attempts included).
    lambda = mean radius of all shell nodes (the mid-surface) from the last *NODE PRINT U block;
    err = (p applied - p_closed(lambda)) / p_closed(lambda), p applied = p x step time;
    err_worst = the same at the one node whose radius gives the largest |error| (lambda = r_i / R).
    """
    incs = atts = 0  # converged increments; attempts that did not converge (ATT "1U": cut back)
    sta_iters = 0
    sta = os.path.join(d, job + ".sta")
    if os.path.exists(sta):
        for line in open(sta):
            f = line.split()
            if len(f) >= 7 and f[0].isdigit() and f[1].isdigit():
                if f[2].endswith("U"):
                    atts += 1
                else:
                    incs += 1
                    sta_iters += int(f[3])
    iters = 0
    cvg = os.path.join(d, job + ".cvg")
    if os.path.exists(cvg):
        for line in open(cvg):
            f = line.split()
            if len(f) >= 7 and all(x.isdigit() for x in f[:4]):
                iters += 1
    dat = os.path.join(d, job + ".dat")
    t, U = parse_dat(dat, X) if os.path.exists(dat) else (None, None)
    status = "completed" if t is not None and abs(t - 1.0) < 1e-9 else "INCOMPLETE"
    if t is not None:
        r = [math.sqrt(sum((x[k] + u[k]) ** 2 for k in range(3))) for x, u in zip(X, U)]
        lam_mean = sum(r) / len(r) / R
        lam_pole = r[pole - 1] / R
        p_reached = p * t
        err = (p_reached - p_closed(lam_mean, mu)) / p_closed(lam_mean, mu)
        spread = (max(r) - min(r)) / R
        err_worst = max((p_reached / p_closed(ri / R, mu) - 1.0 for ri in r), key=abs)
    else:
        lam_mean = lam_pole = p_reached = err = spread = err_worst = float("nan")
    return dict(incs=incs, attempts=atts, iters=iters, sta_iters=sta_iters, t=t, status=status, lam=lam_mean,
                lam_pole=lam_pole, p_reached=p_reached, err=err, spread=spread, err_worst=err_worst)


def ccx_env():
    """One thread everywhere: OpenMP, ccx's own thread counts, and a threaded BLAS if any."""
    return dict(os.environ, OMP_NUM_THREADS="1", OPENBLAS_NUM_THREADS="1", CCX_NPROC_EQUATION_SOLVER="1",
                CCX_NPROC_RESULTS="1", CCX_NPROC_STIFFNESS="1")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--n", type=int, required=True, help="elements per cube-face edge (octant: 3 n^2 elements)")
    ap.add_argument("--elem", default="S4", choices=["S4", "S8R"])
    ap.add_argument("--nu", type=float, default=0.499)
    ap.add_argument("--incs", type=int, default=10)
    ap.add_argument("--tol", default="tight", choices=["tight", "default"])
    ap.add_argument("--scale", type=float, default=1e6)
    ap.add_argument("--dir", default=None)
    ap.add_argument("--timeout", type=float, default=600)
    ap.add_argument("--no-run", action="store_true")
    a = ap.parse_args()
    d = a.dir or f"results/peers/ccx_{a.elem}_n{a.n}_nu{a.nu:g}_{a.tol}"
    os.makedirs(d, exist_ok=True)
    job = "sphere"
    X, E, mu, p, pole = write_deck(os.path.join(d, job + ".inp"), a.n, a.elem, a.nu, a.incs, a.tol, a.scale)
    print(f"deck {d}/{job}.inp: octant n={a.n}, {len(E)} {a.elem} elements (whole-sphere equivalent "
          f"{8 * len(E)}), {len(X)} nodes, p_target = {p:.6g} (mu = {mu:g}), nu = {a.nu}, tol = {a.tol}")
    if a.no_run:
        return
    env = ccx_env()
    t0 = time.time()
    with open(os.path.join(d, "ccx.log"), "w") as log, open(os.path.join(d, "time.txt"), "w") as tf:
        proc = subprocess.Popen(["/usr/bin/time", "-v", "ccx", job], cwd=d, stdout=log, stderr=tf, env=env,
                                start_new_session=True)
        killed = False
        try:
            proc.wait(timeout=a.timeout)
        except subprocess.TimeoutExpired:
            os.killpg(proc.pid, 9)  # our own process group only
            proc.wait()
            killed = True
    elapsed = time.time() - t0
    wall, rss = parse_time_v(open(os.path.join(d, "time.txt")).read())
    if wall is None:
        wall = elapsed
    r = read_results(d, job, X, mu, p, pole)
    incs, atts, iters, sta_iters, t = r["incs"], r["attempts"], r["iters"], r["sta_iters"], r["t"]
    lam_mean, lam_pole, p_reached, err, spread = r["lam"], r["lam_pole"], r["p_reached"], r["err"], r["spread"]
    status = "killed after timeout" if killed else r["status"]
    print(f"status              {status} (exit {proc.returncode})")
    print(f"elements            {len(E)} {a.elem} (octant; whole-sphere equivalent {8 * len(E)})")
    print(f"increments          {incs} converged ({atts} extra attempts after cut-backs)")
    print(f"Newton iterations   {iters} (.cvg lines, failed attempts included; {sta_iters} in converged attempts)")
    print(f"wall time           {wall:.1f} s")
    print(f"peak RSS            {rss:.0f} MB" if rss else "peak RSS            n/a")
    print(f"pressure reached    {p_reached / mu:.8g} mu  (step time {t}, = {p_reached:.8g} scaled)")
    print(f"lambda reached      {lam_mean:.8f} (mean nodal radius; pole {lam_pole:.8f}; max-min radius {spread:.2e} R)")
    print(f"p error vs closed   {err:+.3e} (p applied vs 2mu(H/R)(1/lam-1/lam^7) at lambda reached)")
    print(f"RESULT code=ccx elem={a.elem} n={a.n} elements={len(E)} whole={8 * len(E)} incs={incs} iters={iters} "
          f"wall={wall:.1f} rss_mb={rss if rss else float('nan'):.0f} p_mu={p_reached / mu:.8g} lam={lam_mean:.8f} "
          f"err={err:+.3e} status={status.replace(' ', '_')}")


if __name__ == "__main__":
    sys.exit(main())
