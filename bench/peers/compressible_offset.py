#!/usr/bin/env python3
"""Closed-form pressure of a thin sphere of CalculiX's compressible NEO HOOKE
(W = C10 (I1bar - 3) + (J - 1)^2 / D1, plane stress through the thickness) at lambda,
relative to the incompressible closed form p = 2 mu (H/R)(1/lambda - 1/lambda^7).
This is the error the material model alone gives, whatever the mesh."""
import sys
mu, H, lam = 1.0, 0.01, 1.2
for nu in [float(v) for v in (sys.argv[1:] or ["0.499", "0.4999"])]:
    C10, K = mu / 2, 2 * mu * (1 + nu) / (3 * (1 - 2 * nu))
    D1 = 2 / K
    def s(l3):
        J = lam * lam * l3
        I1 = (2 * lam * lam + l3 * l3) * J ** (-2 / 3)
        dev = lambda a: 2 * C10 / J * (J ** (-2 / 3) * a * a - I1 / 3)
        return dev(lam) + 2 / D1 * (J - 1), dev(l3) + 2 / D1 * (J - 1)
    a, b = 0.5 / lam ** 2, 2 / lam ** 2
    for _ in range(200):
        m = (a + b) / 2
        a, b = (a, m) if s(m)[1] > 0 else (m, b)
    p = 2 * s(m)[0] * m * H / lam
    thin = 2 * mu * H * (1 / lam - lam ** -7)
    print(f"nu = {nu}: thickness stretch {m:.8f} (incompressible {1 / lam ** 2:.8f}), "
          f"p/p_incompressible - 1 = {p / thin - 1:+.3e}")
