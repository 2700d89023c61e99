#!/usr/bin/env bash
# The C API (contact-bounce-c) from C:
#  - on the host: examples/c/api_test.c, compiled with -Werror against the static library,
#    checks that bad inputs (NULL, NaN, out of range) return their error codes and prints the
#    lines of every tier and of the debouncer, which must be those the Rust core prints
#    (examples/lines.rs); the header also compiles as C++;
#  - on a Cortex-M4F under QEMU: examples/c/cortex_m.c (no C library), built with
#    arm-none-eabi-gcc against the library built for thumbv7em-none-eabihf, prints every tier's
#    and the debouncer's lines, which must be the host's;
#  - on the Arduino Uno: examples/c/uno.c, built with avr-gcc against the library built for
#    avr-none (nightly), runs in simavr and must print the host's lean-path and debouncer lines.
# Neither firmware may link panic code (the library and the core have no panicking path).
# The header itself is checked current by `cargo test -p contact-bounce-c`.
set -euo pipefail
cd "$(dirname "$0")/.."
C=contact-bounce-c
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

cargo build --quiet --release -p contact-bounce-c
cc -std=c99 -Wall -Wextra -Werror -pedantic -I"$C/include" -I"$C/examples/c" \
  "$C/examples/c/api_test.c" target/release/libcontact_bounce_c.a -lm -lpthread -ldl -o "$tmp/api_test"
"$tmp/api_test" > "$tmp/c"
cargo run --quiet --release -p contact-bounce-c --example lines > "$tmp/rust"
if ! diff -u "$tmp/rust" "$tmp/c"; then
  echo "FAIL: the C API printed other lines than the Rust core" >&2
  exit 1
fi
echo "ok: the C API on the host ($(wc -l < "$tmp/c") lines, as the Rust core; bad inputs give their codes)"
printf '#include "contact_bounce.h"\nint main() { cb_pin p; return cb_pin_init(&p, false) == CB_OK ? 0 : 1; }\n' > "$tmp/cpp.cpp"
c++ -std=c++11 -Wall -Werror -I"$C/include" "$tmp/cpp.cpp" target/release/libcontact_bounce_c.a -lpthread -ldl -o "$tmp/cpp"
"$tmp/cpp"
echo "ok: the header compiles and links as C++"

# Cortex-M4F under QEMU, C with no C library (arm-none-eabi-gcc from Debian's packages).
if ! command -v arm-none-eabi-gcc >/dev/null || ! command -v qemu-system-arm >/dev/null; then
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends gcc-arm-none-eabi qemu-system-arm >/dev/null
fi
rustup target add thumbv7em-none-eabihf >/dev/null 2>&1
cargo build --quiet --profile firmware -p contact-bounce-c --target thumbv7em-none-eabihf
arm-none-eabi-gcc -mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16 -Os -std=gnu99 \
  -Wall -Wextra -Werror -ffreestanding -ffunction-sections -fdata-sections -nostdlib -Wa,--noexecstack \
  -I"$C/include" -I"$C/examples/c" "$C/examples/c/cortex_m.c" -T "$C/examples/c/cortex_m.ld" \
  -Wl,--gc-sections target/thumbv7em-none-eabihf/firmware/libcontact_bounce_c.a -o "$tmp/cortex_m.elf"
arm-none-eabi-size "$tmp/cortex_m.elf"
# The C examples format nothing through Rust: panic code in them would be the library's.
no_panic() {
  if "$2" "$1" | grep -q 'core9panicking'; then
    echo "FAIL: $1 links a panic path (core::panicking): the library must have none" >&2
    exit 1
  fi
}
no_panic "$tmp/cortex_m.elf" arm-none-eabi-nm
timeout 300 qemu-system-arm -cpu cortex-m4 -machine mps2-an386 -nographic \
  -semihosting-config enable=on,target=native -kernel "$tmp/cortex_m.elf" > "$tmp/cortex_m"
if ! diff -u "$tmp/rust" "$tmp/cortex_m"; then
  echo "FAIL: the C API on the Cortex-M4F printed other lines than the Rust core on the host" >&2
  exit 1
fi
echo "ok: the C API on the Cortex-M4F under QEMU ($(wc -l < "$tmp/cortex_m") lines, as on the host)"

# shellcheck source=scripts/avr-toolchain.sh
source scripts/avr-toolchain.sh
avr_toolchain "the C API on the Uno"
cargo +nightly build --quiet --profile firmware -p contact-bounce-c --target avr-none -Zbuild-std=core
# As .cargo/config.toml does for Rust firmware: avr-libc's single-precision routines, square
# root and memory copies, marked undefined before -lm and -lc, are taken instead of the
# library's generic ones.
uno() {
  avr-gcc -mmcu=atmega328p -Os -std=gnu99 -Wall -Wextra -Werror -ffunction-sections -fdata-sections \
    -I"$C/include" -I"$C/examples/c" "$C/examples/c/uno.c" -Wl,--gc-sections \
    -Wl,-u,__addsf3,-u,__subsf3,-u,__mulsf3,-u,__divsf3,-u,__eqsf2,-u,__nesf2,-u,__ltsf2,-u,__lesf2,-u,__gtsf2,-u,__gesf2,-u,__unordsf2,-u,__floatsisf,-u,__floatunsisf,-u,__fixsfsi,-u,__fixunssfsi,-u,sqrtf,-u,memcpy,-u,memmove,-u,memset \
    -lm -lc target/avr-none/firmware/libcontact_bounce_c.a -lm "$@"
}
uno -o "$tmp/uno.elf"
avr-size "$tmp/uno.elf"
no_panic "$tmp/uno.elf" avr-nm
timeout 300 simavr -m atmega328p -f 16000000 "$tmp/uno.elf" > "$tmp/raw" 2>&1 || true
sed -e 's/\x1b\[[0-9;]*m//g' "$tmp/raw" | grep -v -e '^Loaded ' -e '^$' | sed -e 's/\.$//' > "$tmp/uno"
{ grep -E ' tb1v | restitution-averaged | closed-preload |^pin ' "$tmp/rust"; echo done; } > "$tmp/want"
if ! diff -u "$tmp/want" "$tmp/uno"; then
  echo "FAIL: the C API on the Uno printed other lines than the host" >&2
  exit 1
fi
echo "ok: the C API on the Uno in simavr ($(wc -l < "$tmp/want") lines, as on the host)"

# The Arduino library layout, and its example sketch compiled as the Arduino build does.
scripts/arduino-library.sh "$tmp/arduino/ContactBounce"
