#!/usr/bin/env bash
# Regenerates docs/reports/replay.md: `bounce-table replay` on the shared real capture
# (../shared/data/bouncy-button-uno.jsonl, not part of the repository: see docs/reports/calibration.md
# for its source and licence), and the checks of what the rows must show. Prints the document;
# --write writes docs/reports/replay.md and the Pareto plots in docs/reports/replay/.
set -euo pipefail
cd "$(dirname "$0")/.."
capture=${CAPTURE:-../shared/data/bouncy-button-uno.jsonl}
[ -f "$capture" ] || { echo "no capture at $capture (set CAPTURE=...)" >&2; exit 1; }
bin() { cargo run --quiet --release -p bounce-table -- "$@"; }
# The push button's name gives no type: say it (the capture's notes call it a push button).
run() { bin replay --switch-type push-button "$@" "$capture"; }
table=$(run)
checks=$(run --format json | python3 -c '
import json, sys
rows = [json.loads(l) for l in sys.stdin]
groups = {}
for r in rows:
    groups.setdefault((r["switch"], r["kind"]), []).append(r)
ours = ("calibrated", "physics", "learned")
print("| switch | kind | calibrated false edges (hold-off / confirm) | faster calibrated latency P99 | peers with 0 false edges (of %d) | their lowest latency P99 | holds |" % sum(1 for r in next(iter(groups.values())) if not r["debouncer"].startswith(ours)))
print("|---|---|---:|---:|---:|---:|---|")
ok = True
for (sw, kind), g in groups.items():
    cal = {r["debouncer"]: r for r in g if r["debouncer"].startswith("calibrated")}
    peers = [r for r in g if not r["debouncer"].startswith(ours)]
    clean = [r for r in peers if r["false_edges"] == 0]
    fastest = min(r["latency_p99_s"] for r in cal.values())
    best = min((r["latency_p99_s"] for r in clean), default=None)
    holds = all(r["false_edges"] == 0 for r in cal.values()) and (best is None or fastest <= best)
    ok &= holds
    f = lambda x: "-" if x is None else "%.3g ms" % (x * 1e3)
    print("| %s | %s | %d / %d | %s | %d | %s | %s |" % (sw, kind, cal["calibrated hold-off"]["false_edges"], cal["calibrated confirm"]["false_edges"], f(fastest), len(clean), f(best), "yes" if holds else "NO"))
print()
print("Every switch and kind: " + ("the calibrated rows have no false edge, and the faster is at least as fast as every peer without one." if ok else "NOT every calibrated row holds (see the last column)."))
')
# The learner at three time scales: the capture as it is, contactor-like (x10) and reed-like (x0.1).
learned=$(for scale in 1 10 0.1; do run --format json --time-scale "$scale" --min-tap "$(python3 -c "print(31e-3 * $scale)")" | python3 -c '
import json, sys
scale = sys.argv[1]
rows = [json.loads(l) for l in sys.stdin]
groups = {}
for r in rows:
    groups.setdefault((r["switch"], r["kind"]), []).append(r)
for (sw, kind), g in groups.items():
    learned = next(r for r in g if r["debouncer"] == "learned")
    peers = [r for r in g if not r["debouncer"].startswith(("calibrated", "physics", "learned"))]
    fewest = min(r["false_edges"] for r in peers)
    clean = [r["latency_p99_s"] for r in peers if r["false_edges"] == 0]
    best = min(clean, default=None)
    f = lambda x: "-" if x is None else "%.3g ms" % (x * 1e3)
    print("| x%s | %s | %s | %d | %d | %s | %s | %s |" % (scale, sw, kind, learned["false_edges"], fewest, f(learned["latency_p99_s"]), f(best), f(learned["window_s"])))
' "$scale"; done)
# Tapped like a key: every debouncer on seeded tap sequences spliced from the later tests.
taps=$(run --taps --window 157e-3)
tapchecks=$(run --taps --window 157e-3 --format json | python3 -c '
import json, sys
rows = [json.loads(l) for l in sys.stdin]
groups = {}
for r in rows:
    groups.setdefault((r["switch"], r["regime"]), []).append(r)
print("| switch | regime | learned: missed taps | false edges | correct taps | press latency P99 | release latency P99 | rows with both fewer missed taps and fewer false edges | holds |")
print("|---|---|---:|---:|---:|---:|---:|---|---|")
ok = True
for (sw, regime), g in groups.items():
    l = next(r for r in g if r["debouncer"] == "learned")
    better = [r["debouncer"] for r in g if r["missed"] < l["missed"] and r["false_edges"] < l["false_edges"]]
    clean = "rocker" in sw or sw == "no-bounce control"
    holds = l["missed"] == 0 and not better and (not clean or l["false_edges"] == 0)
    ok &= holds
    f = lambda x: "-" if x is None else "%.3g ms" % (x * 1e3)
    print("| %s | %s | %d | %d | %d | %s | %s | %s | %s |" % (sw, regime, l["missed"], l["false_edges"], l["correct"], f(l["press_latency_p99_s"]), f(l["release_latency_p99_s"]), ", ".join(better) or "none", "yes" if holds else "NO"))
print()
print("Every switch and regime: " + ("the learner loses no tap, no row has both fewer missed taps and fewer false edges, and on the rocker and the control it has no false edge." if ok else "NOT every learned row holds (see the last column)."))
')
# The push button in docs/guide-firmware.md: the learner against the windows people use.
tapreadme=$(run --taps --window 157e-3 --format json | python3 -c '
import json, sys
rows = [json.loads(l) for l in sys.stdin]
names = [("learned", "learned"), ("qmk sym_eager_pk", "QMK 5 ms (eager)"), ("qmk sym_defer_pk", "QMK 5 ms (defer)"), ("bounce2 stable", "Bounce2 10 ms"), ("zephyr gpio-keys", "Zephyr 30 ms"), ("calibrated hold-off", "calibrated hold-off"), ("physics-prior hold-off", "prior of the type, 31 ms, hold-off"), ("fixed 157.000 ms hold-off", "157 ms, hold-off")]
print("| push button, 1,000 taps: missed / false edges | " + " | ".join(n for _, n in names) + " |")
print("|---|" + "---:|" * len(names))
by = {}
for r in rows:
    if "rocker" not in r["switch"] and r["switch"] != "no-bounce control":
        by.setdefault(r["regime"], {})[r["debouncer"]] = r
for regime, g in by.items():
    print("| %s | " % regime + " | ".join("%d / %d" % (g[d]["missed"], g[d]["false_edges"]) for d, _ in names) + " |")
')
# Any prior from 5 to 157 ms, at 1 ms and 0.1 ms samples.
sweep=$(for period in 1e-3 1e-4; do for prior in 5e-3 20e-3 50e-3 157e-3; do run --taps --format json --sample-period "$period" --prior "$prior" | python3 -c '
import json, sys
period, prior = float(sys.argv[1]), float(sys.argv[2])
rows = [json.loads(l) for l in sys.stdin]
groups = {}
for r in rows:
    groups.setdefault((r["switch"], r["regime"]), []).append(r)
missed = clean_false = 0
push = []
better = []
for (sw, regime), g in groups.items():
    l = next(r for r in g if r["debouncer"] == "learned")
    missed += l["missed"]
    if "rocker" in sw or sw == "no-bounce control":
        clean_false += l["false_edges"]
    else:
        push.append(str(l["false_edges"]))
    better += ["%s %s" % (regime, r["debouncer"]) for r in g if r["missed"] < l["missed"] and r["false_edges"] < l["false_edges"]]
holds = missed == 0 and clean_false == 0 and not better
print("| %g ms | %g ms | %d | %d | %s | %s | %s |" % (period * 1e3, prior * 1e3, missed, clean_false, " / ".join(push), ", ".join(better) or "none", "yes" if holds else "NO"))
' "$period" "$prior"; done; done)
curve=$(run --format curve | python3 -c '
import csv, sys
rows = list(csv.DictReader(sys.stdin))
groups = {}
for r in rows:
    groups.setdefault((r["switch"], r["kind"]), []).append(r)
marks = [1, 5, 10, 11, 20]
print("| switch | kind | " + " | ".join("after event %d" % m for m in marks) + " | after the last | false edges in events 1-10 | after |")
print("|---|---|" + "---:|" * (len(marks) + 3))
f = lambda x: "%.3g ms" % (float(x) * 1e3)
for (sw, kind), g in groups.items():
    cells = [f(g[m - 1]["window_s"]) if m <= len(g) else "-" for m in marks]
    early = sum(int(r["false_edges"]) for r in g[:10])
    late = sum(int(r["false_edges"]) for r in g[10:])
    print("| %s | %s | %s | %s | %d | %d |" % (sw, kind, " | ".join(cells), f(g[-1]["window_s"]), early, late))
')
# The firmware recipe's physics window (the tactile dome's 180 us at 10 us samples) as it is.
fixed=$(run --sample-period 1e-5 --window 180e-6 | python3 -c '
import sys
groups = {}
for l in sys.stdin:
    c = [x.strip() for x in l.strip().strip("|").split("|")]
    if len(c) == 9 and c[4].isdigit():
        groups.setdefault((c[0], c[1]), {})[c[2]] = c
print("| switch | kind | tests | 180 us hold-off: false edges (tests with them) | 180 us confirm | calibrated hold-off | learned |")
print("|---|---|---:|---:|---:|---:|---:|")
cell = lambda r: "%s (%s)" % (r[5], r[6])
for (sw, kind), g in groups.items():
    h, c = g["fixed 180.00 us hold-off"], g["fixed 180.00 us confirm"]
    print("| %s | %s | %s | %s | %s | %s | %s |" % (sw, kind, h[4], cell(h), cell(c), cell(g["calibrated hold-off"]), cell(g["learned"])))
slips = ["%s %s, %s: %s in %s of %s tests" % (sw, kind, d, g[d][5], g[d][6], g[d][4]) for (sw, kind), g in groups.items() for d in ("calibrated hold-off", "learned") if g[d][5] != "0"]
print()
print("Sampled every 10 us instead of 1 ms, " + ("our calibrated and learned rows have no false edge." if not slips else "false edges of our calibrated or learned rows: " + "; ".join(slips) + " (at 1 ms samples: the rows above)."))
')
summary=$(bin calibrate "$capture" | sed -n '/^# Summary/,/^## Description/p' | sed '1d;$d')
doc=$(cat <<MD
# Replay: debouncers on a real capture

Generated by \`scripts/replay-report.sh --write\`, which runs:

\`\`\`sh
bounce-table replay --switch-type push-button ../shared/data/bouncy-button-uno.jsonl
bounce-table replay --switch-type push-button --format json ../shared/data/bouncy-button-uno.jsonl
bounce-table replay --switch-type push-button --format json --time-scale 10 --min-tap 0.31 ../shared/data/bouncy-button-uno.jsonl   # and 0.1
bounce-table replay --switch-type push-button --format curve ../shared/data/bouncy-button-uno.jsonl
bounce-table replay --switch-type push-button --sample-period 1e-5 --window 180e-6 ../shared/data/bouncy-button-uno.jsonl
bounce-table calibrate ../shared/data/bouncy-button-uno.jsonl
bounce-table replay --taps --window 157e-3 --switch-type push-button ../shared/data/bouncy-button-uno.jsonl   # and --format json
bounce-table replay --taps --switch-type push-button --format json --sample-period 1e-4 --prior 5e-3 ../shared/data/bouncy-button-uno.jsonl   # priors 5-157 ms, 1 and 0.1 ms
\`\`\`

The capture is the one of \`docs/reports/calibration.md\`: a push button and a snap-action rocker, 230
press/release tests logged by an Arduino Uno. For each switch and kind, the earlier half of the
tests in capture order calibrates; the later half is replayed. Every polled debouncer samples
every 1 ms (the scan rate of the keyboard firmwares) at a phase that changes from test to test
and is the same for every debouncer; the two \`gpio-keys\` are interrupt-driven and see every
change. "false edges": reported edges beyond the one true edge of each test; latency: from the
first contact change to the first reported edge. The peers are re-implemented from their
documentation at their defaults (\`bounce-table/src/commands/replay/peers/\` says how each works); debouncr
is the crate itself. \`physics-prior\` is the window the switch's type gives without a capture
(\`bounce-table/src/scene/priors.rs\`): the P99.9 of a survey of 18 hand-operated switches, whose
worst bounced 157 ms, at most the fastest real tap (31 ms), so that a user can type with it.
\`learned\` is the core's learning debouncer (\`LearningState\`): it starts from that prior at
the switch's first test and learns online through every test in capture order, press and
release, never seeing a test before it happens; it is scored on the same later tests as every
other row, by which time it has lived through the earlier ones.

These rows score isolated presses: every debouncer starts settled and has all the time it wants
after each test, so a window long enough always looks perfect here. A key in use is pressed
again soon after it is released: "Tapped like a key", below, scores what each window costs
then.

## The rows

$table

## What the rows must show

$checks

## Tapped like a key

The capture's later presses and releases spliced into seeded sequences of 1,000 taps per
switch and regime, with human timing (\`docs/human-timing.md\`), and a switch with no bounce at
all as a control; every debouncer runs through each whole sequence without a reset, sampling
every 1 ms at one phase for all (\`bounce-table/src/commands/replay/taps.rs\` says how the taps are spliced and
scored). Per tap: \`missed\`, no press reported between the previous tap's release and its own
(a real press lost); \`false edges\`, presses beyond one and releases beyond one; \`correct\`,
exactly one press and one release, in order. The learner starts from the switch type's prior
(31 ms) and is told that no real tap is shorter than 31 ms. \`fixed 157.000 ms\` is our
debouncer with the survey's worst switch as its window, the type's prior before it was capped at
the fastest tap.

$taps

### What the learner must show

It loses no tap, anywhere; on the rocker and the control it has no false edge; on the push
button no row has both fewer missed taps and fewer false edges.

$tapchecks

From any prior, at 1 ms and 0.1 ms samples (\`--prior\`, \`--sample-period\`; push button false edges
for typing / fast taps / double-clicks / holds):

| period | prior | taps lost (every switch and regime) | false edges on the rocker and the control | push button false edges | rows with both fewer missed taps and fewer false edges | holds |
|---|---|---:|---:|---|---|---|
$sweep

The push button against the windows people use (missed taps / false edges, of 1,000 taps; the
table of \`docs/guide-firmware.md\`):

$tapreadme

The push button's contact opens for 18-88 ms in the middle of about a quarter of its presses,
and closes again for 14-33 ms after some releases: reversions as long as a human tap. A window
that swallows them swallows real taps of that length too (157 ms and the calibrated windows
lose up to 72 % of fast taps), and a window that keeps every tap lets the longer ones
through as false edges. The learner takes the second side of that trade, and says so
(\`reverts_like_a_tap\`, the line below the rows).

## The learner on isolated presses

Scored like every row above, at three time scales: the capture as it is, every time multiplied
by 10 (a contactor-like switch) and by 0.1 (a reed-like one), all sampled every 1 ms, the prior
and the fastest tap (\`--min-tap\`) scaled with the capture. Its window never exceeds the
fastest tap, so on the push button it lets through the reversions that last longer than a tap
(the peers with no false edge here, Zephyr's 30 ms and debouncr's 16 samples, lose 29 % and
12 % of the push button's fast taps above).

| time scale | switch | kind | learned false edges | fewest false edges of a peer | learned latency P99 | lowest latency P99 of a clean peer | window learned by the last test |
|---|---|---|---:|---:|---:|---:|---:|
$learned

Its window against the tests it has lived through (\`--format curve\`: the window of each test's
kind after the test, and the false edges of each test), per kind, counting that kind's events:

$curve

Warm-up: it keeps the prior (at most the fastest tap) for its first 10 events of a kind, then
tightens to 3/2 of the longest bounce it has seen, counting only excursions that came back in
less than a tap.

## A window from physics alone

The README's firmware recipe computes the tactile dome's window from the impact model: 115 us
of bounce, 180 us with a 1.5 margin, at 10 us samples. \`--window 180e-6\` replays our
debouncer with that window as it is, every debouncer sampling every 10 us, on the same later
tests (false edges, and in brackets the tests that have any). The impact model explains the
first flights of a contact; real contacts also dwell, chatter and bounce again later, which a
window from typical parameters does not cover: calibrate from a capture, or let the debouncer
learn.

$fixed

## calibrate's windows, fitted on the earlier half

From \`bounce-table calibrate\` with default options: the window each switch and kind gets from
all its tests, and the same rule fitted on the earlier half against the later half.

$summary

Plots (\`--plot docs/reports/replay\`): false edges against latency P99 per switch and kind, ours and
the peers, with the Pareto front and the rows on it named, in \`docs/reports/replay/\`; with \`--taps\`,
missed taps against false edges per switch and regime (\`*-taps.svg\`).
MD
)
if [ "${1:-}" = "--write" ]; then
  printf '%s\n' "$doc" > docs/reports/replay.md
  run --plot docs/reports/replay > /dev/null
  run --taps --plot docs/reports/replay > /dev/null
else
  printf '%s\n' "$doc"
fi
