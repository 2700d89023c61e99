#!/usr/bin/env bash
# Renders the plots a reader meets first as PNG, into docs/png/, from the SVGs the tool writes
# (docs/plots, docs/reports/calibration and docs/reports/replay, which CI regenerates and compares), and writes
# each source's SHA-256 into docs/png/SOURCES. CI checks those hashes (--check), so a PNG whose
# SVG has changed since it was rendered fails the tests. Rendering needs rsvg-convert (Debian:
# apt-get install librsvg2-bin); the check needs only sha256sum.
set -euo pipefail
cd "$(dirname "$0")/.."
sources=(
  docs/plots/my_tactile_button-envelope.svg
  docs/plots/my_tactile_button-motion.svg
  docs/reports/calibration/bbb_sample_v0_3_0_banggood_1276758_rocker-press.svg
  docs/reports/replay/bbb_sample_v0_2_3_2024_02_24-release-replay.svg
)
if [ "${1:-}" = "--check" ]; then
  sha256sum --check --quiet docs/png/SOURCES || {
    echo "docs/png: a PNG is older than its SVG; run scripts/plot-png.sh" >&2
    exit 1
  }
  exit 0
fi
command -v rsvg-convert > /dev/null || {
  echo "rsvg-convert not found (Debian: apt-get install librsvg2-bin)" >&2
  exit 1
}
mkdir -p docs/png
for svg in "${sources[@]}"; do
  rsvg-convert --width 900 --background-color white "$svg" -o "docs/png/$(basename "$svg" .svg).png"
done
sha256sum "${sources[@]}" > docs/png/SOURCES
