#!/usr/bin/env python3
"""Writes the capture fixtures of bounce-table's importer tests with independent writers: a VCD
by pyvcd (the `vcd` package on PyPI), a CSV by Python's csv module, and a VCD exported by
sigrok-cli (the logic analyzer suite's command line) from one synthetic capture (three presses
and releases, bounce, sub-resolution chatter, a second 1-bit signal and a bus in the pyvcd
VCD), plus the changes they encode (expected.json).

sigrok-cli imports the pyvcd VCD without the bus (its VCD input takes 1-bit signals only) at
10 MHz (every change of the capture falls on a 100 ns sample) and exports it as sigrok does:
value changes on the time stamp's line, a `$date` of the day it ran (CI's diff ignores that
line) and, in version 0.7, a `META samplerate` line ahead of the header.

Usage: python3 scripts/capture-fixtures.py [DIR]   (default bounce-table/tests/fixtures)
Needs: pip install pyvcd==0.5.1, and sigrok-cli 0.7.2 (Debian 12: apt-get install sigrok-cli),
the versions the committed fixtures were written with.
"""
import csv
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

from vcd import VCDWriter

out = sys.argv[1] if len(sys.argv) > 1 else "bounce-table/tests/fixtures"
os.makedirs(out, exist_ok=True)

# Level changes of the switch pin (pull-up: 1 = open), in integer nanoseconds: each event is its
# start time and the offsets of its changes.
EVENTS = [
    (100_000_000, [0, 12_000, 15_000, 60_000, 61_000]),  # press: bounce, 1 us chatter
    (600_000_000, [0, 2_500, 4_000]),  # release: a short bounce
    (1_200_000_000, [0]),  # press: clean
    (1_700_000_000, [0, 800, 1_600, 1_000_000, 1_000_900]),  # release: chatter, a late re-close
]
# (a press ends closed and a release open: an odd number of changes each)
changes = []
level = 1
for start, offsets in EVENTS:
    for o in offsets:
        level ^= 1
        changes.append((start + o, level))

with open(os.path.join(out, "button.vcd"), "w") as f:
    with VCDWriter(f, timescale="1 ns", date="2026-11-21", comment="contact-bounce fixture") as w:
        sw = w.register_var("top", "sw", "wire", size=1, init=1)
        led = w.register_var("top", "led", "wire", size=1, init=0)
        bus = w.register_var("top", "bus", "wire", size=8, init=0)
        for i, (t, v) in enumerate(changes):
            w.change(sw, t, v)
            if i % 3 == 0:
                w.change(led, t, i % 2)
                w.change(bus, t, i % 256)

with open(os.path.join(out, "button.csv"), "w", newline="") as f:
    w = csv.writer(f)
    w.writerow(["time", "level"])
    w.writerow([0.0, 1])
    for t, v in changes:
        w.writerow([repr(t * 1e-9), v])

with open(os.path.join(out, "expected.json"), "w") as f:
    json.dump({"closed_before": False, "changes_ns": [t for t, _ in changes]}, f, indent=1)
    f.write("\n")

sigrok = shutil.which("sigrok-cli")
if sigrok is None:
    sys.exit("capture-fixtures.py: sigrok-cli not found (Debian: apt-get install sigrok-cli)")
with open(os.path.join(out, "button.vcd")) as f:
    one_bit = f.read().replace("$var wire 8 # bus $end\n", "")
one_bit = re.sub(r"^b\S+ #\n", "", one_bit, flags=re.M)
# A capture runs on after its last edge; sigrok exports samples up to the last time stamp only,
# so the source ends 100 ms after the last change.
one_bit += "#%d\n" % (changes[-1][0] + 100_000_000)
with tempfile.TemporaryDirectory() as tmp:
    src = os.path.join(tmp, "button-1bit.vcd")
    with open(src, "w") as f:
        f.write(one_bit)
    subprocess.run(
        [sigrok, "-i", src, "-I", "vcd:downsample=100", "-O", "vcd",
         "-o", os.path.join(out, "button-sigrok.vcd")],
        check=True,
    )
