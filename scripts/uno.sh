#!/usr/bin/env bash
# Builds examples/uno.rs for the Arduino Uno (nightly, avr-none, -Zbuild-std=core, linked by
# avr-gcc), runs it in simavr and checks it prints what the same example prints on the host.
# Installs gcc-avr, avr-libc and simavr if missing (Debian) and rust-src for the nightly.
# Without a nightly toolchain (none can be fetched on some machines) it says SKIPPED loudly.
set -euo pipefail
cd "$(dirname "$0")/.."

# shellcheck source=scripts/avr-toolchain.sh
source scripts/avr-toolchain.sh
avr_toolchain "the Uno check"

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for example in uno uno_learn; do
  cargo +nightly build --quiet --release --example "$example" --target avr-none -Zbuild-std=core
  elf=target/avr-none/release/examples/$example.elf
  avr-size "$elf"
  cargo run --quiet --example "$example" > "$tmp/host"
  # simavr prints the UART in colour, one line at a time ending in '.', then its own lines; it
  # never stops on a bad opcode, hence the timeout.
  timeout 300 simavr -m atmega328p -f 16000000 "$elf" > "$tmp/raw" 2>&1 || true
  sed -e 's/\x1b\[[0-9;]*m//g' "$tmp/raw" | grep -v -e '^Loaded ' -e '^$' | sed -e 's/\.$//' > "$tmp/uno"
  if grep -q PANIC "$tmp/uno" || ! diff -u "$tmp/host" "$tmp/uno"; then
    echo "FAIL: $example on the Uno printed other lines than the host" >&2
    exit 1
  fi
  echo "ok: $example in simavr ($(wc -l < "$tmp/host") lines, as on the host)"
done
