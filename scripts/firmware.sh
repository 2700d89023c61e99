#!/usr/bin/env bash
# Runs the firmware examples under QEMU for thumbv6m, thumbv7m and thumbv7em and checks that
# each prints exactly what the same example prints on the host. Installs qemu-system-arm if
# missing (Debian).
set -euo pipefail
cd "$(dirname "$0")/.."

if ! command -v qemu-system-arm >/dev/null; then
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends qemu-system-arm >/dev/null
fi

targets=(thumbv6m-none-eabi thumbv7m-none-eabi thumbv7em-none-eabihf)
examples=(predict debounce_trace)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failed=0
for example in "${examples[@]}"; do
  cargo run --quiet --example "$example" > "$tmp/host"
  for target in "${targets[@]}"; do
    if ! timeout 300 cargo run --quiet --profile firmware --example "$example" --target "$target" > "$tmp/$target" 2> "$tmp/$target.err"; then
      echo "FAIL: $example on $target exited non-zero:" >&2
      tail -5 "$tmp/$target.err" >&2
      failed=1
    elif ! diff -u "$tmp/host" "$tmp/$target"; then
      echo "FAIL: $example on $target printed other lines than the host" >&2
      failed=1
    else
      echo "ok: $example on $target ($(wc -l < "$tmp/host") lines, as on the host)"
    fi
  done
done
exit "$failed"
