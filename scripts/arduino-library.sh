#!/usr/bin/env bash
# Assembles the Arduino library in target/arduino/ContactBounce (or $1): library.properties,
# examples/ and README from contact-bounce-c/arduino/ContactBounce, the generated header, and
# one precompiled static library per board family, in the folder the Arduino builder looks in
# for that family's boards (src/{build.mcu}, or src/{build.mcu}/{fpu}-{float-abi}: the
# library's README says how the builder picks it). Then, for each board below, it picks the
# folder as the builder would (both rules: arduino-cli 0.11 to 1.5.0 and the Arduino IDE
# 1.8.13 on, and arduino-cli 1.5.1 on), compiles every example for that board with Debian's
# cross compiler and the board's flags against a stand-in core (contact-bounce-c/arduino/
# stand-in: only the AVR core installs from Debian's packages), links it as the board's
# platform links a precompiled library (-L the folder, the library's ldflags, -lContactBounce),
# and runs it: the AVR boards in simavr, the Cortex-M boards in QEMU (the M0+ boards on QEMU's
# Cortex-M0, the same instructions). The stand-in taps a bouncing button 40 times (keys of a
# 4x4 matrix for Keypad); LearnButton and Keypad must report exactly those 40 presses, in order;
# PhysicsWindow must lose none (a physics window may let bounces through: its count is shown).
# ESP32-C3 (riscv32) is compiled and linked only: no simulator here runs it. Last, the AVR
# boards' examples are built with the real Arduino AVR core (Debian's arduino-core-avr) and
# must fit the board.
#
# Usage: scripts/arduino-library.sh [OUT]
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-target/arduino/ContactBounce}
lib=ContactBounce
C=contact-bounce-c

need=()
command -v avr-gcc >/dev/null || need+=(gcc-avr avr-libc)
command -v simavr >/dev/null || need+=(simavr)
command -v arm-none-eabi-gcc >/dev/null || need+=(gcc-arm-none-eabi)
[ -d /usr/lib/arm-none-eabi/newlib ] || need+=(libnewlib-arm-none-eabi)
command -v qemu-system-arm >/dev/null || need+=(qemu-system-arm)
command -v riscv64-unknown-elf-gcc >/dev/null || need+=(gcc-riscv64-unknown-elf)
[ -f /usr/lib/picolibc/riscv64-unknown-elf/picolibc.specs ] || need+=(picolibc-riscv64-unknown-elf)
if [ ${#need[@]} -gt 0 ]; then
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${need[@]}" >/dev/null
fi
# shellcheck source=scripts/avr-toolchain.sh
source scripts/avr-toolchain.sh
avr_toolchain "the Arduino library"
rustup target add thumbv6m-none-eabi thumbv7em-none-eabi thumbv7em-none-eabihf riscv32imc-unknown-none-elf >/dev/null 2>&1

rm -rf "$out"
mkdir -p "$(dirname "$out")"
cp -r "$C/arduino/ContactBounce" "$out"
cp "$C/include/contact_bounce.h" "$out/src/"

# The archives: Rust target (and its flags) -> folders under src/.
archive() { # folder target [RUSTFLAGS] [cargo +toolchain and -Z flags...]
  local folder=$1 target=$2 flags=${3:-}
  shift 3
  local dir=target/arduino-build/${folder//[^a-z0-9]/_}
  if [ -n "$flags" ]; then
    RUSTFLAGS="$flags" cargo "$@" build --quiet --profile firmware -p contact-bounce-c --target "$target" --target-dir "$dir"
  else
    cargo "$@" build --quiet --profile firmware -p contact-bounce-c --target "$target" --target-dir "$dir"
  fi
  mkdir -p "$out/src/$folder"
  cp "$dir/$target/firmware/libcontact_bounce_c.a" "$out/src/$folder/lib$lib.a"
}
# The Uno's is built with .cargo/config.toml's flags for avr-none (target-cpu=atmega328p).
archive atmega328p avr-none "" +nightly -Zbuild-std=core
archive atmega2560 avr-none "-C target-cpu=atmega2560" +nightly -Zbuild-std=core
archive cortex-m0plus thumbv6m-none-eabi ""
# Cortex-M4 with the FPU: hard-float calls (the Uno R4's RA4M1, SAMD51, nRF52 cores that pass
# -mfloat-abi=hard) in src/cortex-m4, the builder's fallback; float arguments in integer
# registers (softfp: the mbed core of the Nano 33 BLE) in the folders its two rules name.
archive cortex-m4 thumbv7em-none-eabihf ""
archive cortex-m4/fpv4-sp-d16-softfp thumbv7em-none-eabi "-C target-cpu=cortex-m4"
mkdir -p "$out/src/cortex-m4/-mfpu=fpv4-sp-d16--mfloat-abi=softfp"
cp "$out/src/cortex-m4/fpv4-sp-d16-softfp/lib$lib.a" "$out/src/cortex-m4/-mfpu=fpv4-sp-d16--mfloat-abi=softfp/"
archive esp32c3 riscv32imc-unknown-none-elf ""
# On AVR, avr-libc's hand-written float routines, square root and memory copies are smaller and
# several times faster than the generic ones compiler-builtins puts in the archive (weak): made
# local to their objects, the archive leaves them undefined for the platform's -lm and -lc,
# which every AVR link recipe puts after the libraries. (The repository's own C builds mark
# them undefined instead, with -Wl,-u; as the library's ldflags that would pull the C library's
# float routines into every sketch on the other families.)
avr_libc=(__addsf3 __subsf3 __mulsf3 __divsf3 __eqsf2 __nesf2 __ltsf2 __lesf2 __gtsf2 __gesf2
  __unordsf2 __floatsisf __floatunsisf __fixsfsi __fixunssfsi sqrtf memcpy memmove memset)
find "$out/src" -name "lib$lib.a" | while read -r a; do
  case $a in
    */atmega*)
      avr-strip --strip-debug "$a"
      avr-objcopy "${avr_libc[@]/#/--localize-symbol=}" "$a"
      ;;
    */esp32c3/*) riscv64-unknown-elf-strip --strip-debug "$a" ;;
    *) arm-none-eabi-strip --strip-debug "$a" ;;
  esac
done

# The boards: name | architecture | build.mcu | build.fpu | build.float-abi (each "-" when the
# board does not define it, empty when it defines it empty) | the compiler's target flags (as the platform's recipe passes them)
# | how it runs. From each core's boards.txt and platform.txt (the library's README cites them).
boards=(
  "Uno|avr|atmega328p|-|-|-mmcu=atmega328p|simavr atmega328p"
  "Mega 2560|avr|atmega2560|-|-|-mmcu=atmega2560|simavr atmega2560"
  "Zero (SAMD21)|samd|cortex-m0plus|-|-|-mcpu=cortex-m0plus -mthumb|qemu cortex-m0 microbit"
  "Nano RP2040 Connect (mbed)|mbed_nano|cortex-m0plus|||-mcpu=cortex-m0plus -mthumb|qemu cortex-m0 microbit"
  "Pico (mbed)|mbed_rp2040|cortex-m0plus|||-mcpu=cortex-m0plus -mthumb|qemu cortex-m0 microbit"
  "Pico (RP2040 core)|rp2040|cortex-m0plus|-|-|-mcpu=cortex-m0plus -mthumb|qemu cortex-m0 microbit"
  "Nano 33 BLE (nRF52840, mbed)|mbed_nano|cortex-m4|-mfpu=fpv4-sp-d16|-mfloat-abi=softfp|-mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=softfp|qemu cortex-m4 mps2-an386"
  "Uno R4 Minima (RA4M1)|renesas_uno|cortex-m4|-mfpu=fpv4-sp-d16|-mfloat-abi=hard|-mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard|qemu cortex-m4 mps2-an386"
  "ESP32-C3|esp32|esp32c3|-|-|-march=rv32imc -mabi=ilp32|none"
)

# The folder the builder links for a board, by rule "recipe" (arduino-cli 0.11 to 1.5.0, the
# Arduino IDE 1.8.13 on: the values of -mfpu= and -mfloat-abi= in the compile command) or
# "properties" (arduino-cli 1.5.1 on: build.fpu and build.float-abi as they are when the board
# defines both, else the compile command's); src/{build.mcu} when the FPU folder is missing.
folder() { # rule mcu fpu float-abi flags
  local rule=$1 mcu=$2 fpu=$3 abi=$4 flags=$5 spec="" f="" a=""
  if [ "$rule" = properties ] && [ "$fpu" != - ] && [ "$abi" != - ]; then
    spec="$fpu-$abi"
  else
    for w in $flags; do
      case $w in -mfpu=*) [ -z "$f" ] && f=${w#*=} ;; -mfloat-abi=*) [ -z "$a" ] && a=${w#*=} ;; esac
    done
    [ -n "$f" ] && [ -n "$a" ] && spec="$f-$a"
  fi
  if [ -n "$spec" ] && [ -f "$out/src/$mcu/$spec/lib$lib.a" ]; then
    echo "$out/src/$mcu/$spec"
  elif [ -f "$out/src/$mcu/lib$lib.a" ]; then
    echo "$out/src/$mcu"
  fi
}

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
ldflags=$(sed -n 's/^ldflags=//p' "$out/library.properties")
archs=$(sed -n 's/^architectures=//p' "$out/library.properties")
stand_in=$C/arduino/stand-in
want=$(for i in $(seq 0 39); do echo "press $((i + 1))"; done)
want_keys=$(for i in $(seq 0 39); do echo "key $((i % 16)) press $((i + 1))"; done)
failed=0
for board in "${boards[@]}"; do
  IFS='|' read -r name arch mcu fpu abi flags run <<< "$board"
  case ",$archs," in *",$arch,"*) ;; *)
    echo "FAIL: library.properties' architectures ($archs) lacks $arch ($name)" >&2
    exit 1
    ;;
  esac
  dirs=()
  for rule in recipe properties; do
    d=$(folder "$rule" "$mcu" "${fpu:-}" "${abi:-}" "$flags")
    if [ -z "$d" ]; then
      echo "FAIL: $name: no precompiled folder under the $rule rule" >&2
      exit 1
    fi
    dirs+=("$d")
  done
  # The compiler, its flags for sketches and the stand-in (C++ as the platforms compile .ino),
  # and the link, as each platform's recipe orders it: objects, then the library's flags.
  case $arch in
    avr)
      cxx=(avr-g++ -Os -std=gnu++11 -fno-exceptions -ffunction-sections -fdata-sections
        -fno-threadsafe-statics -flto $flags -DF_CPU=16000000L -DARDUINO=10819 -DARDUINO_ARCH_AVR)
      link=(avr-gcc -Os -flto -fuse-linker-plugin -Wl,--gc-sections $flags)
      post=(-lm)
      ;;
    esp32)
      cxx=(riscv64-unknown-elf-g++ -Os -std=gnu++17 -fno-exceptions -fno-rtti -ffunction-sections
        -fdata-sections $flags --specs=picolibc.specs -DARDUINO=10819 -DARDUINO_ARCH_ESP32)
      link=(riscv64-unknown-elf-gcc -Os $flags --specs=picolibc.specs -Wl,--gc-sections)
      post=(-lm)
      ;;
    *)
      cxx=(arm-none-eabi-g++ -Os -std=gnu++11 -fno-exceptions -fno-rtti -ffunction-sections
        -fdata-sections -fno-threadsafe-statics $flags -DARDUINO=10819 "-DARDUINO_ARCH_${arch^^}")
      link=(arm-none-eabi-gcc -Os $flags -nostartfiles --specs=nano.specs --specs=nosys.specs
        -Wl,--gc-sections -T "$C/examples/c/cortex_m.ld")
      post=(-lm)
      ;;
  esac
  for sketch in "$out"/examples/*/*.ino; do
    example=$(basename "$sketch" .ino)
    matrix=()
    [ "$example" = Keypad ] && matrix=(-DSTAND_IN_MATRIX)
    for d in $(printf '%s\n' "${dirs[@]}" | sort -u); do
      b="$tmp/$arch-$mcu-$example"
      "${cxx[@]}" -Wall -Werror -c -x c++ -include Arduino.h -I"$stand_in" -I"$out/src" "$sketch" -o "$b.o"
      "${cxx[@]}" -Wall -Werror -c "${matrix[@]}" -I"$stand_in" "$stand_in/stand_in.cpp" -o "$b-core.o"
      # shellcheck disable=SC2086 # the library's ldflags are words
      "${link[@]}" "$b.o" "$b-core.o" "-L$d" $ldflags "-l$lib" "${post[@]}" -o "$b.elf"
      rel=${d#"$out"/}
      case $run in
        simavr*)
          timeout 120 simavr -m "${run#simavr }" -f 16000000 "$b.elf" > "$b.raw" 2>&1 || true
          sed -e 's/\x1b\[[0-9;]*m//g' "$b.raw" | grep -v -e '^Loaded ' -e '^$' | sed -e 's/\.$//' > "$b.log"
          ;;
        qemu*)
          read -r _ cpu machine <<< "$run"
          timeout 120 qemu-system-arm -cpu "$cpu" -machine "$machine" -nographic \
            -semihosting-config enable=on,target=native -kernel "$b.elf" > "$b.log"
          ;;
        none)
          echo "ok: $example for the $name ($rel): compiled and linked ($(wc -c < "$b.elf") bytes of ELF; not run)"
          continue
          ;;
      esac
      if ! grep -qx end "$b.log"; then
        echo "FAIL: $example on the $name ($rel) did not run to its end:" >&2
        tail -n 5 "$b.log" >&2
        failed=1
        continue
      fi
      case $example in
        LearnButton) got=$(grep '^press ' "$b.log"); expected=$want ;;
        Keypad) got=$(grep '^key ' "$b.log"); expected=$want_keys ;;
        *) got=""; expected="" ;;
      esac
      if [ "$got" != "$expected" ]; then
        echo "FAIL: $example on the $name ($rel) reported other presses than the 40 taps:" >&2
        diff <(echo "$expected") <(echo "$got") | head -n 10 >&2
        failed=1
        continue
      fi
      n=$(grep -c '^press \|^key ' "$b.log" || true)
      if [ "$example" = PhysicsWindow ]; then
        if [ "$n" -lt 40 ]; then
          echo "FAIL: PhysicsWindow on the $name ($rel) lost presses: $n of 40" >&2
          failed=1
          continue
        fi
        echo "ok: $example on the $name ($rel): $n presses for 40 taps ($((n - 40)) bounces let through: $(grep '^window' "$b.log"))"
      else
        echo "ok: $example on the $name ($rel): the 40 taps, in order ($(head -n 1 "$b.log"))"
      fi
    done
  done
done
[ "$failed" = 0 ] || exit 1

# The AVR boards with their real core: Debian's arduino-core-avr (the Arduino AVR core 1.8.x and
# its EEPROM library), compiled and linked with its platform.txt's recipes, flags and link order
# (the sketch with `#include <Arduino.h>` first, as the builder adds it). Not run: the core's
# pins read real ports, which nothing drives in simavr. What each example takes of the board, and
# how many learners fit beside LearnButton in the RAM the Arduino IDE leaves before it warns
# (75 % of it for global variables).
if [ ! -f /usr/share/arduino/hardware/arduino/avr/platform.txt ]; then
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends arduino-core-avr >/dev/null
fi
avr_platform=/usr/share/arduino/hardware/arduino/avr
version=$(sed -n 's/^version=//p' "$avr_platform/platform.txt")
for board in "Uno|atmega328p|standard|AVR_UNO|32256|2048" "Mega 2560|atmega2560|mega|AVR_MEGA2560|253952|8192"; do
  IFS='|' read -r name mcu variant id flash_max ram_max <<< "$board"
  b="$tmp/core-$mcu"
  mkdir -p "$b"
  defs=(-mmcu="$mcu" -DF_CPU=16000000L -DARDUINO=10819 "-DARDUINO_$id" -DARDUINO_ARCH_AVR)
  inc=(-I"$avr_platform/cores/arduino" -I"$avr_platform/variants/$variant")
  cflags=(-c -g -Os -w -std=gnu11 -ffunction-sections -fdata-sections -flto -fno-fat-lto-objects)
  cxxflags=(-c -g -Os -w -std=gnu++11 -fpermissive -fno-exceptions -ffunction-sections -fdata-sections
    -fno-threadsafe-statics -Wno-error=narrowing -flto)
  for f in "$avr_platform"/cores/arduino/*.{c,cpp,S}; do
    case $f in
      # (Debian's avr-gcc 5.4 does not compile WString.cpp, which asks <float.h> for DECIMAL_DIG;
      # the official toolchain's 7.3 does. The examples use no String.)
      */WString.cpp) continue ;;
      *.c) avr-gcc "${cflags[@]}" "${defs[@]}" "${inc[@]}" "$f" -o "$b/$(basename "$f").o" ;;
      *.cpp) avr-g++ "${cxxflags[@]}" "${defs[@]}" "${inc[@]}" "$f" -o "$b/$(basename "$f").o" ;;
      *.S) avr-gcc -c -g -x assembler-with-cpp -flto "${defs[@]}" "${inc[@]}" "$f" -o "$b/$(basename "$f").o" ;;
    esac
  done
  avr-gcc-ar rcs "$b/core.a" "$b"/*.o
  d=$(folder recipe "$mcu" - - "-mmcu=$mcu")
  for sketch in "$out"/examples/*/*.ino; do
    example=$(basename "$sketch" .ino)
    { echo '#include <Arduino.h>'; echo '#line 1'; cat "$sketch"; } > "$b/$example.cpp"
    avr-g++ "${cxxflags[@]}" "${defs[@]}" "${inc[@]}" -I"$avr_platform/libraries/EEPROM/src" -I"$out/src" \
      "$b/$example.cpp" -o "$b/$example.o"
    # shellcheck disable=SC2086 # the library's ldflags are words
    avr-gcc -w -Os -g -flto -fuse-linker-plugin -Wl,--gc-sections -mmcu="$mcu" -o "$b/$example.elf" \
      "$b/$example.o" "-L$d" $ldflags "-l$lib" "$b/core.a" "-L$b" -lm
    read -r text data bss _ < <(avr-size "$b/$example.elf" | tail -n 1)
    flash=$((text + data)) ram=$((data + bss))
    if [ "$flash" -gt "$flash_max" ] || [ "$ram" -gt $((ram_max * 3 / 4)) ]; then
      echo "FAIL: $example with the Arduino AVR core $version for the $name does not fit: $flash bytes of flash, $ram of RAM" >&2
      exit 1
    fi
    line="ok: $example with the Arduino AVR core $version for the $name (${d#"$out"/}): $flash of $flash_max bytes of flash, $ram of $ram_max of RAM"
    if [ "$example" = LearnButton ]; then
      line="$line; learners that fit beside it in 75 % of the RAM: $((1 + (ram_max * 3 / 4 - ram) / 24))"
    fi
    echo "$line"
  done
done
echo "ok: the Arduino library in $out: every example for every board family, in simulation where one runs"
