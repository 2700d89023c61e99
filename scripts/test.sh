#!/usr/bin/env bash
# Every test and check that CI runs, on a fresh machine: installs what it needs (rustup targets
# and components, mpmath for the table generators, scipy for the trade report's peer, Chromium
# and selenium for the page's browser test), then runs
# the host tests and doctests, clippy and rustdoc with -D warnings, the no_std builds for every
# Cortex-M target and feature set, the firmware (QEMU, simavr), the size, cost and trade reports,
# and checks that the committed generated and measured tables are current.
# Exits non-zero on the first failure; ends with "N passed, N failed" for the tests it ran.
set -euo pipefail
cd "$(dirname "$0")/.."

targets=(thumbv6m-none-eabi thumbv7m-none-eabi thumbv7em-none-eabihf)
step() { printf '\n==> %s\n' "$*"; }

step "toolchain: targets and components"
rustup target add "${targets[@]}"
rustup component add clippy rustfmt llvm-tools
# (a system Python that refuses pip, PEP 668, gets --break-system-packages: CI machines are throwaway)
pip_install() { python3 -m pip install --quiet "$@" || python3 -m pip install --quiet --break-system-packages "$@"; }
python3 -c "import mpmath" 2>/dev/null || pip_install mpmath
python3 -c "import scipy, numpy" 2>/dev/null || pip_install scipy numpy
python3 -c "import vcd" 2>/dev/null || pip_install pyvcd==0.5.1

# Property tests explore a fixed seed in CI (reproducible); run them without it locally to
# explore new cases (failures are kept in host-tests/tests/*.proptest-regressions and replayed).
export PROPTEST_RNG_SEED="${PROPTEST_RNG_SEED:-20261121}"

log=$(mktemp)
trap 'rm -f "$log"' EXIT

step "format"
cargo fmt --all -- --check

step "host tests and doctests (workspace)"
cargo test --workspace 2>&1 | tee -a "$log"

step "unit tests with the micromath backend (doctests assert libm figures)"
cargo test -p contact-bounce --features micromath --lib 2>&1 | tee -a "$log"

step "the debouncers that wait for their pin (feature async): unit tests and doctests"
cargo test -p contact-bounce --features async --lib wait 2>&1 | tee -a "$log"
cargo test -p contact-bounce --features async --doc wait 2>&1 | tee -a "$log"

step "clippy -D warnings (host, all targets, and all features; thumbv7em, all features)"
cargo clippy --workspace --all-targets -- -D warnings
cargo clippy -p contact-bounce --all-features --all-targets -- -D warnings
cargo clippy -p contact-bounce --all-features --target thumbv7em-none-eabihf -- -D warnings

step "rustdoc -D warnings"
RUSTDOCFLAGS="-D warnings" cargo doc --quiet --no-deps -p contact-bounce --all-features
RUSTDOCFLAGS="-D warnings" cargo doc --quiet --no-deps -p contact-bounce-c
RUSTDOCFLAGS="-D warnings" cargo doc --quiet --no-deps -p bounce-table -p contact-bounce-reference

step "no_std builds for every target and feature set"
for target in "${targets[@]}"; do
  for features in "" "--no-default-features" "--features micromath" "--features defmt" "--features async" "--all-features"; do
    echo "  $target ${features:-(default)}"
    # shellcheck disable=SC2086
    cargo build --quiet -p contact-bounce --target "$target" $features
  done
done

step "the embassy example (examples/embassy-button: the learner on an nRF52840 pin, feature async) builds and links"
cargo build --quiet --release --target thumbv7em-none-eabihf --manifest-path examples/embassy-button/Cargo.toml \
  --target-dir target/embassy
# The symbols are read whole before grep: `nm | grep -q` under pipefail fails on nm's SIGPIPE.
embassy_symbols=$("$(rustc --print sysroot)/lib/rustlib/$(rustc -vV | sed -n 's/^host: //p')/bin/llvm-nm" \
  target/embassy/thumbv7em-none-eabihf/release/embassy-button)
grep -q ' T Reset$' <<<"$embassy_symbols" || { echo "FAIL: the embassy example has no Reset" >&2; exit 1; }

step "MSRV: the core builds for every Cortex-M target and passes its tests on Rust $(sed -n 's/^rust-version = "\(.*\)"/\1/p' Cargo.toml)"
msrv=$(sed -n 's/^rust-version = "\(.*\)"/\1/p' Cargo.toml)
rustup toolchain install "$msrv" --profile minimal
rustup target add --toolchain "$msrv" "${targets[@]}"
for target in "${targets[@]}"; do
  echo "  $target (all features) on $msrv"
  cargo +"$msrv" build --quiet -p contact-bounce --target "$target" --all-features --target-dir target/msrv
done
cargo +"$msrv" test -p contact-bounce --target-dir target/msrv 2>&1 | tee -a "$log"

step "firmware size report (fails if restitution-only firmware links a sine; docs/guide-firmware.md and docs/reports/size-report.md current)"
sizes=$(scripts/size-report.sh)
echo "$sizes"
python3 - "$sizes" <<'PY'
import sys
rows = [l for l in sys.argv[1].splitlines() if l.startswith("| thumb")]
for path in ("docs/guide-firmware.md", "docs/reports/size-report.md"):
    text = open(path).read()
    missing = [r for r in rows if r not in text]
    if missing or not rows:
        sys.exit(path + " size table differs from scripts/size-report.sh (run it with --write):\n" + "\n".join(missing))
PY

step "firmware under QEMU prints the host's lines (thumbv6m, thumbv7m, thumbv7em)"
scripts/firmware.sh

step "a firmware that depends on the crate links its own memory.x, not ours (a missing one fails)"
app=$(mktemp -d)
mkdir -p "$app/src" "$app/.cargo"
cat > "$app/Cargo.toml" <<TOML
[package]
name = "dependent-app"
version = "0.1.0"
edition = "2021"
[dependencies]
contact-bounce = { path = "$PWD" }
cortex-m = "0.7"
cortex-m-rt = "0.7"
panic-halt = "1"
TOML
printf '[target.thumbv7m-none-eabi]\nrustflags = ["-C", "link-arg=-Tlink.x"]\n' > "$app/.cargo/config.toml"
printf '#![no_std]\n#![no_main]\nuse panic_halt as _;\n#[cortex_m_rt::entry]\nfn main() -> ! {\n    let _ = contact_bounce::debounce::window::window_ticks(1e-3, 1.5, 1e-4);\n    loop {}\n}\n' > "$app/src/main.rs"
if (cd "$app" && cargo build --quiet --release --target thumbv7m-none-eabi > "$app/log" 2>&1); then
  echo "FAIL: a dependent firmware without memory.x linked (it was given ours)" >&2
  exit 1
elif ! grep -q "memory.x" "$app/log"; then
  echo "FAIL: the dependent firmware failed for another reason:" >&2
  tail -20 "$app/log" >&2
  exit 1
fi
echo "ok: without its own memory.x, the dependent firmware does not link"
rm -rf "$app"

step "firmware on the Arduino Uno (simavr) prints the host's lines"
scripts/uno.sh

step "the C API from C: host checks and lines, C++ header, the Uno in simavr"
scripts/c-api.sh

step "cost report runs and its Cortex-M rows are current (instructions under QEMU, flash per firmware and per tier)"
costs=$(scripts/cost-report.sh)
# (The Uno's rows depend on the nightly of the day, installed fresh on CI: not compared with a
# fresh run; the guide's Uno rows are compared with the report's.)
python3 - "$costs" "$sizes" <<'PY'
import sys
rows = [l for l in sys.argv[1].splitlines() if l.startswith("| thumb")]
doc = open("docs/reports/cost-report.md").read()
missing = [r for r in rows if r not in doc]
if missing or not rows:
    sys.exit("docs/reports/cost-report.md differs from scripts/cost-report.sh (run it with --write):\n" + "\n".join(missing))
# The firmware guide's tables quote these reports: its Cortex-M rows must be a fresh run's, its
# Uno rows (per tier, and the cycles of the debouncers) the report's.
fresh = set(rows) | {l for l in sys.argv[2].splitlines() if l.startswith("| thumb")}
guide = open("docs/guide-firmware.md").read().splitlines()
stale = [l for l in guide if l.startswith("| thumb") and l not in fresh]
uno = [l for l in guide if l.startswith(("| avr", "| 1", "| 2", "| 3", "| 4", "| 5", "| 6", "| 7", "| 8", "| 9"))]
stale += [l for l in uno if l not in doc.splitlines()]
if stale or len(uno) < 11:
    sys.exit("docs/guide-firmware.md: rows that are not the cost and size reports' (copy them from docs/reports/cost-report.md):\n" + "\n".join(stale))
PY

step "the desk tool's Monte Carlo benchmark runs (each case once, not timed)"
cargo bench --quiet -p bounce-table --bench monte_carlo -- --test > /dev/null

step "speed/accuracy trade pipeline runs (sweep, benchmarks in test mode, peer on one scene)"
scripts/trade-report.sh --quick

step "capture fixtures regenerate identically (pyvcd, Python's csv, sigrok-cli; scripts/capture-fixtures.py; the scope exports, scripts/scope-fixtures.py)"
if ! command -v sigrok-cli >/dev/null; then
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends sigrok-cli >/dev/null
fi
fixtures=$(mktemp -d)
python3 scripts/capture-fixtures.py "$fixtures"
python3 scripts/scope-fixtures.py "$fixtures/scope"
# (sigrok-cli stamps its export with the day it ran)
diff -r -I '^\$date ' "$fixtures" bounce-table/tests/fixtures
rm -rf "$fixtures"

step "the page in web/ builds (scripts/web.sh) and works in headless Chromium (web/tests/browser.py; Debian's chromium and chromium-driver, selenium from PyPI)"
if ! command -v chromium >/dev/null || ! command -v chromedriver >/dev/null; then
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends chromium chromium-driver >/dev/null
fi
python3 -c "import selenium" 2>/dev/null || pip_install selenium
scripts/web.sh
cargo build --quiet --release -p bounce-table
python3 web/tests/browser.py

step "the repository stands alone: every citation points inside it"
python3 scripts/doc-links.py

step "the core's layers: imports run down numeric, physics, scene, tiers, debounce, with no loop"
python3 scripts/layers.py

step "generated tables are current"
# (the committed files are the generators' output as rustfmt leaves it)
python3 scripts/gauss_legendre.py | rustfmt --edition 2021 | diff - src/numeric/quadrature/table.rs
python3 scripts/averaged_error_table.py | rustfmt --edition 2021 | diff - src/tiers/accuracy/zeno_table.rs
python3 scripts/flight_series.py | rustfmt --edition 2021 | diff - src/numeric/flight_series.rs
python3 measure/generate.py --check

step "measured tables are current (docs/ regenerates identically)"
cargo run --quiet --release -p host-tests --bin error-table | diff - docs/reports/error-table.md
cargo run --quiet --release -p host-tests --bin debounce-report | diff - docs/reports/debounce-comparison.md
cargo run --quiet --release -p host-tests --bin trace-data | rustfmt --edition 2021 | diff - examples/data/relay_press.rs
table=$(scripts/eval-catalogue.sh)
python3 - "$table" <<'PY'
import sys
table = sys.argv[1].strip()
for path in ("docs/guide-tiers.md", "docs/reports/eval-catalogue.md"):
    if table not in open(path).read():
        sys.exit(f"{path}: the eval table differs from scripts/eval-catalogue.sh's output")
PY

step "docs/reports/calibration.md, docs/reports/replay.md, their plots and the guides' replay and tap tables are current, and the keyboard matrix typed on the real switches (need the shared capture, ../shared/data)"
if [ -f ../shared/data/bouncy-button-uno.jsonl ]; then
  scripts/calibration-report.sh | diff - docs/reports/calibration.md
  replay=$(scripts/replay-report.sh)
  diff <(printf '%s\n' "$replay") docs/reports/replay.md
  plots=$(mktemp -d)
  cargo run --quiet --release -p bounce-table -- calibrate --plot "$plots/calibration" ../shared/data/bouncy-button-uno.jsonl > /dev/null
  cargo run --quiet --release -p bounce-table -- replay --switch-type push-button --plot "$plots/replay" ../shared/data/bouncy-button-uno.jsonl > /dev/null
  cargo run --quiet --release -p bounce-table -- replay --taps --switch-type push-button --plot "$plots/replay" ../shared/data/bouncy-button-uno.jsonl > /dev/null
  diff -r "$plots/calibration" docs/reports/calibration
  diff -r "$plots/replay" docs/reports/replay
  rm -rf "$plots"
  # The keyboard matrix: 100 keys of each real switch typed on (bounce-table/tests/matrix.rs).
  # (an absolute path: the test runs in its package's directory)
  CAPTURE="$PWD/../shared/data/bouncy-button-uno.jsonl" cargo test --quiet -p bounce-table --test matrix -- --ignored --nocapture
  python3 - "$replay" <<'PY'
import sys
doc = sys.argv[1]
shown = doc.split("## What the rows must show", 1)[-1].split("## Tapped like a key", 1)[0]
rows = [l for l in shown.splitlines() if l.startswith("| bbb") and l.endswith(("| yes |", "| NO |"))]
guide = open("docs/guide-desk-tool.md").read()
missing = [r for r in rows if r not in guide]
if missing or not rows:
    sys.exit("docs/guide-desk-tool.md: the replay table differs from scripts/replay-report.sh:\n" + "\n".join(missing))
if any(r.endswith("| NO |") for r in rows):
    sys.exit("replay: a calibrated row has false edges or is slower than a clean peer:\n" + "\n".join(rows))
# The learner tapped like a key: per switch and regime, and from every prior and period swept.
taps = doc.split("## Tapped like a key", 1)[-1].split("## The learner on isolated presses", 1)[0]
learned = [l for l in taps.splitlines() if l.endswith(("| yes |", "| NO |"))]
if len(learned) != 12 + 8 or any(r.endswith("| NO |") for r in learned):
    sys.exit("replay --taps: the learner lost a tap, has a false edge on a clean switch, or another row has fewer missed taps and fewer false edges:\n" + "\n".join(learned))
table = [l for l in taps.splitlines() if l.startswith(("| push button", "| typing", "| fast-taps", "| double-click", "| hold"))]
firmware = open("docs/guide-firmware.md").read()
missing = [r for r in table if r not in firmware]
if missing or len(table) != 5:
    sys.exit("docs/guide-firmware.md: the tap table differs from scripts/replay-report.sh:\n" + "\n".join(missing))
PY
else
  echo "SKIPPED: no ../shared/data/bouncy-button-uno.jsonl on this machine (not part of the repository)"
fi

step "the desk tool guide's bounce-table example and its plots (docs/plots) are current, and docs/png's SVGs unchanged"
plots=$(mktemp -d)
example=$(cargo run --quiet --release -p bounce-table -- bounce-table/scenes/example.toml --plot "$plots")
diff -r "$plots" docs/plots
rm -rf "$plots"
scripts/plot-png.sh --check
python3 - "$example" <<'PY'
import sys
if sys.argv[1].strip() not in open("docs/guide-desk-tool.md").read():
    sys.exit("docs/guide-desk-tool.md: the bounce-table example differs from the command's output")
PY

step "main job runs"
cargo run --quiet --release -p bounce-table > /dev/null

# Sum cargo's "test result: ok. N passed; M failed; ..." lines.
awk '/^test result:/ { for (i = 1; i <= NF; i++) { if ($i ~ /^passed;?$/) p += $(i-1); if ($i ~ /^failed;?$/) f += $(i-1) } }
     END { printf "\nAll checks passed.\n%d passed, %d failed\n", p, f }' "$log"
