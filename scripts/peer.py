#!/usr/bin/env python3
"""The peer: what a user without this crate would do. A general-purpose event-driven
simulation with scipy's solve_ivp (RK45, an impact event with restarts, tight tolerances) on
the scenes `trade --scenes` exports, timed per scene and compared with the exact reference.

Near a Zeno accumulation a general-purpose integrator can only stop: it stops once the
departure speed falls below 1e-6 Omega |Delta| (where the exact reference starts summing its
tail) or after 20000 impacts, and reports the last impact as the end.

Usage: python3 scripts/peer.py SCENES.json OUT.json [--only NAME ...]
Installs nothing: scripts/trade-report.sh installs scipy and numpy.
"""
import json
import math
import sys
import time

import numpy as np
from scipy.integrate import solve_ivp


def simulate(s):
    omega, delta, r, zeta, v0 = s["omega"], s["delta"], s["restitution"], s["zeta"], s["closing_speed"]
    threshold = s["threshold"]
    scale = omega * abs(delta) if delta != 0 else omega * 1e-3
    period = 2 * math.pi / omega

    def rhs(t, y):
        return [y[1], -2 * zeta * omega * y[1] - omega * omega * y[0]]

    def hit(t, y):
        return y[0] - delta

    hit.terminal = True
    hit.direction = 1
    t, speed = 0.0, v0
    last_above, end = 0.0, None
    impacts = 1
    while True:
        departure = r * speed
        if delta < 0 and r < 1 and departure < 1e-6 * scale:
            end = t
            break
        if impacts > 20000:
            end = None if delta >= 0 and zeta == 0 else t
            break
        # Search at most two periods ahead (an undamped gap returns within one), skipping the
        # impact point itself.
        sol = solve_ivp(rhs, (0.0, 2 * period), [delta, -departure], events=hit, rtol=1e-10,
                        atol=1e-12 * max(abs(delta), departure / omega, 1e-30), max_step=period / 16)
        if sol.t_events[0].size == 0:
            end = t  # no return: the last impact ended the bounce
            break
        t += float(sol.t_events[0][0])
        speed = float(sol.y_events[0][0][1])
        impacts += 1
        p = (1 + r) * speed
        if threshold is None or p >= threshold:
            last_above = t
        elif s["regime"] == "endless":
            break
    return end, last_above


def relative(x, truth):
    if truth is None or x is None:
        return None
    if truth == 0:
        return 0.0 if x == 0 else float("inf")
    return abs(x / truth - 1)


def main():
    scenes = json.load(open(sys.argv[1]))
    only = set(sys.argv[sys.argv.index("--only") + 1:]) if "--only" in sys.argv else None
    out = []
    for s in scenes:
        if only is not None and s["name"] not in only:
            continue
        if s["regime"] in ("single_impact", "periodic"):
            continue
        runs = []
        for _ in range(3):
            start = time.perf_counter()
            end, last_above = simulate(s)
            runs.append(time.perf_counter() - start)
        out.append({
            "name": s["name"], "regime": s["regime"], "seconds": float(np.median(runs)),
            "end_error": relative(end, s["end_time"]),
            "last_above_error": relative(last_above, s["last_above_time"]) if s["threshold"] is not None else None,
        })
    json.dump(out, open(sys.argv[2], "w"), indent=1)


if __name__ == "__main__":
    main()
