#!/usr/bin/env bash
# The C API (contact-bounce-c) from C:
#  - on the host: examples/c/api_test.c, compiled with -Werror against the static library,
#    checks that bad inputs (NULL, NaN, out of range) return their error codes and prints the
#    lines of every tier and of the debouncer, which must be those the Rust core prints
#    (examples/lines.rs); the header also compiles as C++;
#  - on a Cortex-M4F and a Cortex-M0 under QEMU: examples/c/cortex_m.c (no C library), built
#    with arm-none-eabi-gcc against the library built for thumbv7em-none-eabihf and
#    thumbv6m-none-eabi, prints every tier's, the debouncer's and the learner's lines, which must
#    be the host's;
#  - on the Arduino Uno: examples/c/uno.c, built with avr-gcc against the library built for
#    avr-none (nightly), runs in simavr and must print the host's lean-path and debouncer lines.
# Neither firmware may link panic code (the library and the core have no panicking path).
# It also measures what fits the Uno from C: each entry point alone in a minimal program, linked
# as uno.c is (`--write` saves that table to docs/reports/c-api-uno.md).
# The header itself is checked current by `cargo test -p contact-bounce-c`.
#
# Usage: scripts/c-api.sh [--write]
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

# Cortex-M4F and Cortex-M0 under QEMU, C with no C library (arm-none-eabi-gcc from Debian's
# packages). QEMU has no Cortex-M0+ machine; the M0's microbit runs the same ARMv6-M code.
if ! command -v arm-none-eabi-gcc >/dev/null || ! command -v qemu-system-arm >/dev/null; then
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends gcc-arm-none-eabi qemu-system-arm >/dev/null
fi
# The C examples format nothing through Rust: panic code in them would be the library's.
no_panic() {
  local symbols # read whole first: grep -q in a pipe under pipefail makes nm's SIGPIPE the status
  symbols=$("$2" "$1")
  if grep -q 'core9panicking' <<<"$symbols"; then
    echo "FAIL: $1 links a panic path (core::panicking): the library must have none" >&2
    exit 1
  fi
}
cortex_m() { # name, Rust target, QEMU cpu, QEMU machine, gcc's target flags...
  local name=$1 target=$2 cpu=$3 machine=$4
  shift 4
  rustup target add "$target" >/dev/null 2>&1
  cargo build --quiet --profile firmware -p contact-bounce-c --target "$target"
  arm-none-eabi-gcc "$@" -mthumb -Os -std=gnu99 \
    -Wall -Wextra -Werror -ffreestanding -ffunction-sections -fdata-sections -nostdlib -Wa,--noexecstack \
    -I"$C/include" -I"$C/examples/c" "$C/examples/c/cortex_m.c" -T "$C/examples/c/cortex_m.ld" \
    -Wl,--gc-sections "target/$target/firmware/libcontact_bounce_c.a" -lgcc -o "$tmp/$cpu.elf"
  arm-none-eabi-size "$tmp/$cpu.elf"
  no_panic "$tmp/$cpu.elf" arm-none-eabi-nm
  timeout 300 qemu-system-arm -cpu "$cpu" -machine "$machine" -nographic \
    -semihosting-config enable=on,target=native -kernel "$tmp/$cpu.elf" > "$tmp/$cpu"
  if ! diff -u "$tmp/rust" "$tmp/$cpu"; then
    echo "FAIL: the C API on the $name printed other lines than the Rust core on the host" >&2
    exit 1
  fi
  echo "ok: the C API on the $name under QEMU ($(wc -l < "$tmp/$cpu") lines, as on the host)"
}
cortex_m Cortex-M4F thumbv7em-none-eabihf cortex-m4 mps2-an386 -mcpu=cortex-m4 -mfloat-abi=hard -mfpu=fpv4-sp-d16
cortex_m Cortex-M0 thumbv6m-none-eabi cortex-m0 microbit -mcpu=cortex-m0plus

# shellcheck source=scripts/avr-toolchain.sh
source scripts/avr-toolchain.sh
avr_toolchain "the C API on the Uno"
cargo +nightly build --quiet --profile firmware -p contact-bounce-c --target avr-none -Zbuild-std=core
# As .cargo/config.toml does for Rust firmware: avr-libc's single-precision routines, square
# root and memory copies, marked undefined before -lm and -lc, are taken instead of the
# library's generic ones.
uno() { # source, then avr-gcc's other arguments
  local source=$1
  shift
  avr-gcc -mmcu=atmega328p -Os -std=gnu99 -Wall -Wextra -Werror -ffunction-sections -fdata-sections \
    -I"$C/include" -I"$C/examples/c" "$source" -Wl,--gc-sections \
    -Wl,-u,__addsf3,-u,__subsf3,-u,__mulsf3,-u,__divsf3,-u,__eqsf2,-u,__nesf2,-u,__ltsf2,-u,__lesf2,-u,__gtsf2,-u,__gesf2,-u,__unordsf2,-u,__floatsisf,-u,__floatunsisf,-u,__fixsfsi,-u,__fixunssfsi,-u,sqrtf,-u,memcpy,-u,memmove,-u,memset \
    -lm -lc target/avr-none/firmware/libcontact_bounce_c.a -lm "$@"
}
uno "$C/examples/c/uno.c" -o "$tmp/uno.elf"
avr-size "$tmp/uno.elf"
read -r uno_text uno_data _ < <(avr-size "$tmp/uno.elf" | tail -n 1)
no_panic "$tmp/uno.elf" avr-nm
timeout 300 simavr -m atmega328p -f 16000000 "$tmp/uno.elf" > "$tmp/raw" 2>&1 || true
sed -e 's/\x1b\[[0-9;]*m//g' "$tmp/raw" | grep -v -e '^Loaded ' -e '^$' | sed -e 's/\.$//' > "$tmp/uno"
{ grep -E ' tb1v | restitution-averaged | closed-preload |^pin |^learner ' "$tmp/rust"; echo done; } > "$tmp/want"
if ! diff -u "$tmp/want" "$tmp/uno"; then
  echo "FAIL: the C API on the Uno printed other lines than the host" >&2
  exit 1
fi
echo "ok: the C API on the Uno in simavr ($(wc -l < "$tmp/want") lines, as on the host)"

# What fits the Uno from C: each entry point alone in a minimal program (its inputs read from
# volatiles, floats or integers as it takes them, so nothing is folded away; its outputs stored
# to them), linked as uno.c is. The
# library's share is the program's flash (text and initialised data) minus that of the same
# program with no call. RAM is the data and bss before any stack.
calls=(
  "\`cb_preload_viscous_bounce_seconds\`|out_e = cb_preload_viscous_bounce_seconds(&lean, &s); out_f = s;"
  "\`cb_preload_viscous_bounce_time\`|out_e = cb_preload_viscous_bounce_time(&lean, &est); out_f = est.time + est.expected_error;"
  "\`cb_preload_restitution_bounce_seconds\`|out_e = cb_preload_restitution_bounce_seconds(&lean, &s); out_f = s;"
  "\`cb_switch_check\`|out_e = cb_switch_check(&sw);"
  "\`cb_preload_seconds_closed\`|out_e = cb_preload_seconds_closed(&sw, &s); out_f = s;"
  "\`cb_preload_seconds_averaged\`|out_e = cb_preload_seconds_averaged(&sw, &s); out_f = s;"
  "\`cb_preload_seconds_map\`|out_e = cb_preload_seconds_map(&sw, &s); out_f = s;"
  "\`cb_preload_seconds_exact\`|out_e = cb_preload_seconds_exact(&sw, &s); out_f = s;"
  "\`cb_bounce_seconds_closed\`|out_e = cb_bounce_seconds_closed(&sw, &s); out_f = s;"
  "\`cb_bounce_seconds_exact\`|out_e = cb_bounce_seconds_exact(&sw, &s); out_f = s;"
  "\`cb_predict_closed\`|out_e = cb_predict_closed(&sw, &p); out_f = p.end_time;"
  "\`cb_predict_averaged\`|out_e = cb_predict_averaged(&sw, &p); out_f = p.end_time;"
  "\`cb_predict_map\`|out_e = cb_predict_map(&sw, &p); out_f = p.end_time;"
  "\`cb_predict_exact\`|out_e = cb_predict_exact(&sw, &p); out_f = p.end_time;"
  "\`cb_predict_auto_exact\`|out_e = cb_predict_auto_exact(&sw, in[0], &p); out_f = p.end_time;"
  "\`cb_predict_auto\`|out_e = cb_predict_auto(&sw, in[0], &p); out_f = p.end_time;"
  "the debouncer (\`cb_windows_init\`, \`cb_pin_init\`, \`cb_pin_update\`)|out_e = cb_windows_init(&w, n[0], n[1], CB_MODE_CONFIRM); out_e += cb_pin_init(&pin, n[2] != 0); out_e += cb_pin_update(&pin, n[3] != 0, &w);"
  "the learner (\`cb_learner_prior_init\`, \`cb_learner_init\`, \`cb_learner_update\`, \`cb_learner_flags\`, \`cb_learner_save\`, \`cb_learner_restore\`)|out_e = cb_learner_prior_init(&lp, n[0], n[1], n[2]); out_e += cb_learner_init(&key, n[3] != 0); out_e += cb_learner_update(&key, n[4] != 0, &lp); out_e += cb_learner_flags(&key, &lp); out_e += cb_learner_save(&key, &saved); out_e += cb_learner_restore(&key, n[5] != 0, &saved);"
)
one() { # C statements -> text data bss of the minimal program around them
  cat > "$tmp/one.c" <<C_PROGRAM
#include <stdint.h>
#include "contact_bounce.h"
volatile float in[7];
volatile uint16_t n[6];
volatile float out_f;
volatile uint16_t out_e;
int main(void) {
    cb_switch sw = {in[0], in[1], in[2], in[3], in[4], in[5], in[6]};
    cb_preloaded lean = {in[0], in[1], in[2], in[3], in[4], in[5]};
    float s = 0.0f;
    cb_prediction p;
    cb_estimate est;
    cb_windows w;
    cb_pin pin;
    cb_learner_prior lp;
    cb_learner key;
    cb_learned saved;
    (void)sw; (void)lean; (void)s; (void)p; (void)est; (void)w; (void)pin; (void)lp; (void)key; (void)saved;
    $1
    for (;;) {
    }
}
C_PROGRAM
  # (--noinhibit-exec: a program that does not fit is linked all the same, to be measured.)
  rm -f "$tmp/one.elf"
  uno "$tmp/one.c" -Wl,--noinhibit-exec -o "$tmp/one.elf" 2> "$tmp/one.log" || true
  if [ ! -s "$tmp/one.elf" ]; then
    echo "FAIL: the minimal Uno program around '$1' did not link:" >&2
    tail -n 20 "$tmp/one.log" >&2
    exit 1
  fi
  avr-size "$tmp/one.elf" | tail -n 1 | awk '{ print $1, $2, $3 }'
}
read -r empty_text empty_data _ < <(one "")
empty=$((empty_text + empty_data))
fits="$tmp/fits.md"
{
  echo "| entry point | library's flash (B) | program's flash (B) | RAM before the stack (B) | fits the Uno |"
  echo "|---|---:|---:|---:|---|"
} > "$fits"
for entry in "${calls[@]}"; do
  read -r text data bss < <(one "${entry#*|}")
  flash=$((text + data))
  ram=$((data + bss))
  verdict=yes
  if [ "$flash" -gt 32768 ]; then
    verdict="no: $((flash - 32768)) B over"
  elif [ "$ram" -gt 1536 ]; then
    verdict="no: RAM (more than 1.5 KB before the stack)"
  fi
  echo "| ${entry%%|*} | $((flash - empty)) | $flash | $ram | $verdict |" >> "$fits"
done
cat "$fits"
if [ "${1:-}" = "--write" ]; then
  {
    echo "# What fits the Arduino Uno from C"
    echo
    echo "Generated by \`scripts/c-api.sh --write\` ($(rustc +nightly --version | cut -d' ' -f1-2) for avr-none,"
    echo "$(avr-gcc --version | head -n 1)). Each entry point of \`contact-bounce-c\` alone in a minimal C"
    echo "program for the ATmega328P (its inputs read from volatiles, its outputs stored to them), linked as"
    echo "\`scripts/c-api.sh\` links \`contact-bounce-c/examples/c/uno.c\`: avr-libc's float routines first, \`-Wl,--gc-sections\`."
    echo "The library's flash is the program's (code and initialised data) minus that of the same program"
    echo "with no call ($empty bytes). The Uno has 32,768 bytes of flash and 2,048 of RAM; a program that"
    echo "leaves less than 512 bytes of RAM for its stack and the application is counted as not fitting."
    echo
    cat "$fits"
    echo
    echo "A \`cb_switch\` may be a gap or a preload, with or without damping, so every entry point that"
    echo "takes one links both sides' code and the undamped sums; the \`cb_preload_*\` ones link no gap's"
    echo "code. From Rust, a scene typed by its sign and its damping (\`Scene<f32, Viscous<f32>, Preload>\`)"
    echo "links less: \`docs/reports/cost-report.md\` has each tier's firmware on the Uno that way."
    echo
    echo "The Uno example, \`contact-bounce-c/examples/c/uno.c\` (both lean paths, the closed tier through"
    echo "\`cb_preload_seconds_closed\`, the debouncer and the learner, with its UART and the lines it prints):"
    echo "$uno_text bytes of code and $uno_data of initialised data, $((uno_text + uno_data)) bytes of flash."
  } > docs/reports/c-api-uno.md
fi

# The Arduino library layout, and its example sketch compiled as the Arduino build does.
scripts/arduino-library.sh "$tmp/arduino/ContactBounce"
