#!/usr/bin/env python3
"""Writes the analog capture fixtures of bounce-table/tests/fixtures/scope/: a synthetic switch
seen through a pull-up (open: 5 V through an RC of 6 us; closed: 0 V through 0.1 us), sampled
every 0.5 us with 5 mV of noise, exported the way each scope writes its CSV (Rigol, Siglent,
Keysight, Tektronix's two layouts, plain time,volts), and `expected.json`: the level changes an
input with thresholds LOW/HIGH sees, solved on the exact exponentials (not on the samples), for
the default thresholds (30 % / 70 % of the 0-5 V swing) and the ATmega328P's at 5 V (0.3 / 0.6
VCC), with the dips that cross one threshold only. Seeded: the files are the same every run.

    python3 scripts/scope-fixtures.py        # rewrites the fixtures
    python3 scripts/scope-fixtures.py DIR    # writes them in DIR instead
"""
import json
import math
import os
import random
import sys

OUT = os.path.join(os.path.dirname(__file__), "..", "bounce-table", "tests", "fixtures", "scope")
if len(sys.argv) > 1:
    OUT = sys.argv[1]  # elsewhere: CI regenerates them and compares
VCC, TAU_OPEN, TAU_CLOSED = 5.0, 6e-6, 1e-7
STEP, START, SAMPLES = 5e-7, -2e-5, 301
NOISE = 5e-3
THRESHOLDS = {"swing": (0.3 * VCC, 0.7 * VCC), "atmega328p": (0.3 * VCC, 0.6 * VCC)}


def schedule(rng, kind, marginal):
    """Contact changes (s) from t = 0, alternating from the state the kind starts in."""
    t, changes = 0.0, [0.0]
    if kind == "press":
        # Openings of 12 us rise to 4.3 V, past both thresholds; 6.4 us reach 3.28 V (past the
        # ATmega's 3.0 V, short of the default 3.5 V); 3.5 us reach 2.2 V (past 1.5 V only).
        # Each stays clear of a threshold by more than a sample's rise (0.5 us), so the samples
        # see what the exact waveform does.
        openings = [12e-6] * rng.randint(0, 2) + marginal
        rng.shuffle(openings)
        for o in openings:
            t += rng.uniform(5e-6, 15e-6)  # closed
            changes.append(t)
            t += o  # open
            changes.append(t)
    else:
        for _ in range(rng.randint(1, 4)):
            t += rng.uniform(12e-6, 16e-6)  # open: past both thresholds
            changes.append(t)
            t += rng.uniform(3e-7, 1.5e-6)  # closed: v falls through both within 0.3 us
            changes.append(t)
    return changes


def segments(kind, changes):
    """(start time, v at start, target, tau) of each stretch, from START."""
    closed = kind == "release"  # the state before the first change
    v = 0.0 if closed else VCC
    out, t0 = [], START
    for c in changes + [math.inf]:
        target, tau = (0.0, TAU_CLOSED) if closed else (VCC, TAU_OPEN)
        out.append((t0, v, target, tau, c))
        if c == math.inf:
            break
        v = target + (v - target) * math.exp(-(c - t0) / tau)
        t0, closed = c, not closed
    return out


def voltage(segs, t):
    for t0, v0, target, tau, end in segs:
        if t0 <= t < end:
            return target + (v0 - target) * math.exp(-(t - t0) / tau)
    raise ValueError(t)


def levels(segs, low, high):
    """The changes and one-threshold dips of the exact waveform: (changes, marginal count)."""
    state = segs[0][1] >= high
    changes, marginal, dipping = [], 0, False
    end_of_trace = START + STEP * (SAMPLES - 1)
    for t0, v0, target, tau, end in segs:
        end = min(end, end_of_trace)
        if t0 >= end:
            continue
        v_end = target + (v0 - target) * math.exp(-(end - t0) / tau)

        def at(level):
            return t0 + tau * math.log((v0 - target) / (level - target))

        # Each stretch is monotone: from v0 towards target.
        if state:
            if v_end <= low < v0:
                changes.append(at(low))
                state, dipping = False, False
            elif v_end < high <= v0:
                dipping = True
            elif dipping and v_end >= high > v0:
                marginal, dipping = marginal + 1, False
        else:
            if v_end >= high > v0:
                changes.append(at(high))
                state, dipping = True, False
            elif v_end > low >= v0:
                dipping = True
            elif dipping and v_end <= low < v0:
                marginal, dipping = marginal + 1, False
    return changes, marginal


def acquisition(rng, kind, marginal):
    segs = segments(kind, schedule(rng, kind, marginal))
    times = [START + i * STEP for i in range(SAMPLES)]
    volts = [voltage(segs, t) + rng.gauss(0.0, NOISE) for t in times]
    expected = {"kind": kind, "closed_before": kind == "release"}
    for name, (low, high) in THRESHOLDS.items():
        changes, dips = levels(segs, low, high)
        expected[name] = {"changes": changes, "marginal": dips}
    return times, volts, expected


def rigol(times, volts):
    rows = ["X,CH1,Start,Increment,", f"Sequence,Volt,{times[0]:.6e},{STEP:.6e},"]
    rows += [f"{i},{v:.4e}," for i, v in enumerate(volts)]
    return rows


def siglent(times, volts):
    rows = [f"Record Length,Analog:{len(times)}", f"Sample Interval,{STEP:.6e}",
            "Vertical Units,V", "Source,CH1", "Second,Volt"]
    return rows + [f"{t:.9e},{v:.5f}" for t, v in zip(times, volts)]


def keysight(times, volts):
    # A second channel: a slow sine the reader must leave alone unless asked.
    rows = ["x-axis,1,2", "second,Volt,Volt"]
    return rows + [f"{t:.9e},{v:.6e},{1.65 + math.sin(t * 2e4):.6e}" for t, v in zip(times, volts)]


def tektronix(times, volts):
    settings = [("Record Length", f"{len(times):.6e}", "Points"),
                ("Sample Interval", f"{STEP:.6e}", "s"),
                ("Trigger Point", f"{-START / STEP:.6e}", "Samples"),
                ("", "", ""), ("", "", ""), ("", "", ""),
                ("Source", "CH1", ""), ("Vertical Units", "V", ""),
                ("Vertical Scale", "1.000000e+00", ""), ("Vertical Offset", "0.000000e+00", ""),
                ("Horizontal Units", "s", ""), ("Horizontal Scale", "1.500000e-05", ""),
                ("Pt Fmt", "Y", ""), ("Yzero", "0.000000e+00", ""), ("Probe Atten", "1.000000e+01", "")]
    rows = []
    for i, (t, v) in enumerate(zip(times, volts)):
        a, b, c = settings[i] if i < len(settings) else ("", "", "")
        rows.append(f"{a},{b},{c},{t:.9f},{v:.5f},")
    return rows


def tektronix_mso(times, volts):
    rows = ["Model,MSO44", "Firmware Version,1.00", "", "Waveform Type,ANALOG", "Point Format,Y",
            "Horizontal Units,s", f"Horizontal Scale,{1.5e-5:e}", f"Sample Interval,{STEP:e}",
            f"Record Length,{len(times)}", "Gating,0.0% to 100.0%", "Probe Attenuation,10",
            "Vertical Units,V", "Vertical Offset,0", "Vertical Scale,1", "Label,", "TIME,CH1"]
    return rows + [f"{t:.9e},{v:.5e}" for t, v in zip(times, volts)]


def plain(times, volts):
    return ["time,volts"] + [f"{t:.9e},{v:.5f}" for t, v in zip(times, volts)]


def main():
    os.makedirs(OUT, exist_ok=True)
    rng = random.Random(20261205)
    # rigol.csv: 20 acquisitions appended one after the other, 10 presses and 10 releases (the
    # windows need 10 of a kind), 4 of the presses with dips short of a threshold.
    marginal = [[6.4e-6], [], [3.5e-6], [], [6.4e-6, 3.5e-6], [], [], [], [], []]
    rows, expected = [], []
    for k in range(10):
        for kind in ("press", "release"):
            times, volts, e = acquisition(rng, kind, marginal[k] if kind == "press" else [])
            rows += rigol(times, volts)
            expected.append(e)
    files = {"rigol.csv": rows}
    # One acquisition per other export: a press with both kinds of dip.
    singles = {}
    for name, write in [("siglent.csv", siglent), ("keysight.csv", keysight),
                        ("tektronix.csv", tektronix), ("tektronix-mso.csv", tektronix_mso),
                        ("volts.csv", plain)]:
        times, volts, e = acquisition(rng, "press", [6.4e-6, 3.5e-6])
        files[name] = write(times, volts)
        singles[name] = e
    for name, rows in files.items():
        with open(os.path.join(OUT, name), "w", newline="\n") as f:
            f.write("\n".join(rows) + "\n")
    with open(os.path.join(OUT, "expected.json"), "w") as f:
        json.dump({"step": STEP, "thresholds": THRESHOLDS, "rigol.csv": expected, **singles},
                  f, indent=1)
        f.write("\n")


if __name__ == "__main__":
    main()
