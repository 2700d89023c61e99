#!/usr/bin/env bash
# Builds examples/uno.rs, uno_learn.rs and uno_auto.rs for the Arduino Uno (nightly, avr-none,
# -Zbuild-std=core, linked by avr-gcc), runs each in simavr and checks it prints what the same
# example prints on the host.
# Installs gcc-avr, avr-libc and simavr if missing (Debian) and rust-src for the nightly.
# Without a nightly toolchain (none can be fetched on some machines) it says SKIPPED loudly.
set -euo pipefail
cd "$(dirname "$0")/.."

# shellcheck source=scripts/avr-toolchain.sh
source scripts/avr-toolchain.sh
avr_toolchain "the Uno check"

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# The stack's peak (tools/simavr-cycles.c, libsimavr): a run that takes the stack down into
# .data and .bss would overwrite them without a fault.
if [ ! -f /usr/include/simavr/sim_avr.h ]; then
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends libsimavr-dev >/dev/null
fi
gcc -O2 -o "$tmp/simavr-cycles" tools/simavr-cycles.c -lsimavr
for example in uno uno_learn uno_auto; do
  cargo +nightly build --quiet --profile firmware --example "$example" --target avr-none -Zbuild-std=core
  elf=target/avr-none/firmware/examples/$example.elf
  avr-size "$elf"
  read -r text data bss _ < <(avr-size "$elf" | tail -n 1)
  if ! stack=$("$tmp/simavr-cycles" "$elf" 2> /dev/null | sed -n 's/^stack //p') || ! [[ $stack =~ ^[0-9]+$ ]]; then
    echo "FAIL: $example: its stack peak could not be measured (it did not finish in 2e9 cycles)" >&2
    exit 1
  fi
  # The ATmega328P: 32 KB of flash (.text and .data's initial values), 2 KB of RAM.
  echo "$example: flash $((text + data)) of 32768 bytes; RAM $((data + bss)) (.data, .bss) + $stack (stack peak) = $((data + bss + stack)) of 2048 bytes"
  if [ $((data + bss + stack)) -gt 2048 ] || [ $((text + data)) -gt 32768 ]; then
    echo "FAIL: $example does not fit the Uno" >&2
    exit 1
  fi
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
