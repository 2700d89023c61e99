#!/usr/bin/env bash
# Assembles the Arduino library (the layout `arduino-cli compile` takes: library.properties,
# src/ with the header and src/atmega328p/libContactBounce.a, examples/) in
# target/arduino/ContactBounce (or $1), from contact-bounce-c/arduino/ContactBounce, the
# generated header and the static library built for the Uno (nightly). Then compiles and links
# its example sketch with avr-g++ as the Arduino build does (the .ino as C++, the Uno's flags),
# with only the library and <stdint.h>: no board core. Needs what scripts/c-api.sh installs.
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-target/arduino/ContactBounce}
rm -rf "$out"
mkdir -p "$(dirname "$out")"
cp -r contact-bounce-c/arduino/ContactBounce "$out"
cp contact-bounce-c/include/contact_bounce.h "$out/src/"
cargo +nightly build --quiet --profile firmware -p contact-bounce-c --target avr-none -Zbuild-std=core
mkdir -p "$out/src/atmega328p"
cp target/avr-none/firmware/libcontact_bounce_c.a "$out/src/atmega328p/libContactBounce.a"
avr-strip --strip-debug "$out/src/atmega328p/libContactBounce.a"

# The sketch as the Arduino build compiles it for the Uno (arduino:avr 1.8 platform flags).
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
flags=(-g -Os -w -std=gnu++11 -fpermissive -fno-exceptions -ffunction-sections -fdata-sections
  -fno-threadsafe-statics -Wno-error=narrowing -flto -mmcu=atmega328p -DF_CPU=16000000L
  -DARDUINO=10607 -DARDUINO_AVR_UNO -DARDUINO_ARCH_AVR)
sketch=$out/examples/PhysicsWindow/PhysicsWindow.ino
avr-g++ -c "${flags[@]}" -x c++ -I"$out/src" "$sketch" -o "$tmp/sketch.o"
# The board core's main(): setup() once, then loop() forever.
printf 'void setup(); void loop();\nint main() { setup(); for (;;) loop(); }\n' > "$tmp/main.cpp"
avr-g++ -c "${flags[@]}" "$tmp/main.cpp" -o "$tmp/main.o"
ldflags=$(sed -n 's/^ldflags=//p' "$out/library.properties")
# shellcheck disable=SC2086 # the library's ldflags are words
avr-gcc -w -Os -g -flto -fuse-linker-plugin -Wl,--gc-sections -mmcu=atmega328p "$tmp/sketch.o" \
  "$tmp/main.o" $ldflags "$out/src/atmega328p/libContactBounce.a" -lm -o "$tmp/sketch.elf"
avr-size "$tmp/sketch.elf"
echo "ok: the Arduino library in $out; its example sketch compiles and links for the Uno"
