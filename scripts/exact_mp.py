#!/usr/bin/env python3
"""A 60-digit solution of one body with viscous damping and an exponential relaxation kernel
(either may be absent), for the core's exact tier to be checked against (host-tests
`against_reference`).

    x'' + 2 zeta Omega x' + Omega^2 x = u,   u' = kappa x - u / tau,

impacts at x = Delta reverse x' times R and keep u; u at the first impact is the steady state of
the generating orbit (J = 2 v0). Between impacts the motion is the sum of the three modes of the
characteristic polynomial (roots by mpmath.polyroots, coefficients by a Vandermonde solve), the
next impact found by steps of 1/16 of a period and refined by mpmath.findroot. A Zeno tail is
summed once the departure is below 1e-15 Omega |Delta| (what that leaves out is below 1e-28 of
the bounce).

Usage: exact_mp.py OMEGA ZETA DELTA R V0 TAU KAPPA   (prints the end time and the count;
KAPPA 0 is the viscous body alone)
"""
import sys

import mpmath as mp

mp.mp.dps = 60


def solve(omega, zeta, delta, r, v0, tau, kappa):
    omega, zeta, delta, r, v0, tau, kappa = (
        mp.mpf(x) for x in (omega, zeta, delta, r, v0, tau, kappa))
    beta = 1 / tau
    roots = mp.polyroots([1, 2 * zeta * omega + beta, omega ** 2 + 2 * zeta * omega * beta,
                          beta * omega ** 2 - kappa], maxsteps=200, extraprec=80)
    period = 2 * mp.atan2(2 * v0, -2 * omega * delta) / omega
    u = kappa * (beta * delta - v0 * mp.coth(beta * period / 2)) / (beta ** 2 + omega ** 2)
    step = 2 * mp.pi / max(abs(mp.im(s)) for s in roots) / 16
    vandermonde = mp.matrix([[1, 1, 1], list(roots), [s ** 2 for s in roots]])
    speed, total, count = v0, mp.mpf(0), 1
    while True:
        a = r * speed
        g = -omega ** 2 * delta + u
        if delta < 0 and r < 1 and a < mp.mpf('1e-15') * omega * abs(delta):
            return total + 2 * a / (g * (1 - r)), None
        c = mp.lu_solve(vandermonde, mp.matrix([delta, -a, g + 2 * zeta * omega * a]))
        def mode(t, k):
            return mp.re(sum(c[i] * k(roots[i]) * mp.exp(roots[i] * t) for i in range(3)))
        def x(t):
            return mode(t, lambda s: 1) - delta
        def v(t):
            return mode(t, lambda s: s)
        low, t, rising, bracket = mp.mpf(0), step, False, None
        for _ in range(16 * 400):
            if x(t) >= 0:
                bracket = (low, t)
                break
            if rising and v(t) <= 0:
                top = mp.findroot(v, (low, t), solver='anderson')
                if x(top) >= 0:
                    bracket = (low, top)
                    break
            rising = v(t) > 0
            low, t = t, t + step
        if bracket is None:
            return total, count
        low, high = bracket
        # (x - Delta) / (a t): -1 at the departure, so the tolerance is relative to the flight.
        root = mp.findroot(lambda t: x(t) / (a * t), (max(low, high * mp.mpf('1e-12')), high),
                           solver='anderson')
        total += root
        speed = v(root)
        # (kappa = 0: no kernel, the viscous body alone; u stays 0.)
        u = mode(root, lambda s: kappa / (s + beta)) if kappa else mp.mpf(0)
        count += 1


if __name__ == '__main__':
    end, count = solve(*[float(a) for a in sys.argv[1:8]])
    print(mp.nstr(end, 30), count if count is not None else 'inf')
