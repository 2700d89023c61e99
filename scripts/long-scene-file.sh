#!/usr/bin/env bash
# The desk tool on a long scene file: N lines (default 1,000,000) of JSON Lines, the catalogue's
# switches renamed, through `bounce-table FILE`; prints the wall time and the peak resident
# memory (GNU time), and fails if the output has not one row per switch.
#
# Usage: scripts/long-scene-file.sh [N]
set -euo pipefail
cd "$(dirname "$0")/.."
n="${1:-1000000}"
command -v /usr/bin/time >/dev/null || { echo "needs GNU time (apt-get install time)" >&2; exit 1; }
cargo build --quiet --release -p bounce-table
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
python3 - "$n" "$tmp/long.jsonl" <<'PY'
import sys
n, path = int(sys.argv[1]), sys.argv[2]
lines = [l.rstrip("\n") for l in open("bounce-table/scenes/catalogue.jsonl") if l.strip()]
with open(path, "w") as f:
    for i in range(n):
        _, rest = lines[i % len(lines)].split(",", 1)
        f.write('{"name": "switch %d",%s\n' % (i, rest))
PY
/usr/bin/time -f "%e s wall, %M KB peak resident" target/release/bounce-table "$tmp/long.jsonl" \
  > "$tmp/out.txt" 2> "$tmp/time.txt"
rows=$(grep -c "^switch [0-9]" "$tmp/out.txt" || true)
echo "$n switches: $(tail -n 1 "$tmp/time.txt"), $rows rows"
[ "$rows" = "$n" ] || { echo "FAIL: $rows rows for $n switches" >&2; exit 1; }
