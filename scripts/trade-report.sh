#!/usr/bin/env bash
# One command for the speed/accuracy trade: the accuracy sweep of every tier (f64, f32 with
# libm, f32 with micromath) against the exact reference, criterion benchmarks on the host, and
# the peer (scipy's solve_ivp) on the same scenes, merged into docs/reports/trade-report.md and
# docs/reports/trade-pareto.svg. Installs scipy and numpy (PyPI) if missing. Takes a few minutes.
#
# Usage: scripts/trade-report.sh [--quick]
#   --quick: the pipeline once, no timing (benchmarks in test mode, the peer on one scene), into
#            a temporary directory: what CI runs.
set -euo pipefail
cd "$(dirname "$0")/.."
quick=0
[ "${1:-}" = "--quick" ] && quick=1
python3 -c "import scipy, numpy" 2>/dev/null || python3 -m pip install --quiet scipy numpy ||
  python3 -m pip install --quiet --break-system-packages scipy numpy
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cargo run --quiet --release -p host-tests --bin trade -- --scenes "$tmp/scenes.json" > "$tmp/libm.json"
cargo run --quiet --release -p host-tests --features contact-bounce/micromath --bin trade > "$tmp/micromath.json"
if [ "$quick" = 1 ]; then
  cargo bench --quiet -p host-tests --bench tiers -- --test > "$tmp/bench.log"
  python3 scripts/peer.py "$tmp/scenes.json" "$tmp/peer.json" --only "tactile dome"
  python3 scripts/trade-report.py "$tmp/libm.json" "$tmp/micromath.json" "$tmp/peer.json" "$tmp"
  test -s "$tmp/trade-report.md" && test -s "$tmp/trade-pareto.svg"
  echo "trade report pipeline ran (quick: nothing timed, docs/ untouched)"
  exit 0
fi
cargo bench --quiet -p host-tests --bench tiers > "$tmp/bench.log"
python3 scripts/peer.py "$tmp/scenes.json" "$tmp/peer.json"
python3 scripts/trade-report.py "$tmp/libm.json" "$tmp/micromath.json" "$tmp/peer.json" docs/reports
echo "wrote docs/reports/trade-report.md and docs/reports/trade-pareto.svg"
