# Sourced by the Uno scripts: makes sure of a nightly toolchain with rust-src (avr-none needs
# -Zbuild-std=core) and of avr-gcc, avr-libc and simavr (Debian's packages). Without a nightly
# (none can be fetched on some machines) it says SKIPPED loudly and makes the calling script
# exit 0: `what` names what is skipped.
avr_toolchain() {
  local what=$1
  if ! grep -q '^nightly' <<<"$(rustup toolchain list)"; then
    if ! rustup toolchain install nightly --profile minimal >/dev/null 2>&1; then
      echo "SKIPPED: $what needs a nightly toolchain, and none is installed or installable here" >&2
      exit 0
    fi
  fi
  rustup component add rust-src --toolchain nightly >/dev/null
  if ! command -v simavr >/dev/null || ! command -v avr-gcc >/dev/null; then
    apt-get update -qq
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends gcc-avr avr-libc simavr >/dev/null
  fi
}
