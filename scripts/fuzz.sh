#!/usr/bin/env bash
# The seeded random harness of host-tests/tests/fuzz.rs, long: FUZZ_SCENES scenes per float
# (default 1,000,000; each is predicted by four tiers, alone, with a kernel and as two bodies,
# in f32 and f64), as many raw bit patterns and edge values into every constructor and const
# fn, and the debouncer and learner on a twentieth as many random windows; then the C API's
# harness (contact-bounce-c/tests/fuzz.rs) on as many raw switches and ten times as many
# debouncer states. CI runs the same tests with 10,000 scenes. Prints the counts and fault classes; fails on any fault.
set -euo pipefail
cd "$(dirname "$0")/.."
export FUZZ_SCENES="${FUZZ_SCENES:-1000000}"
cargo test --release -p host-tests --test fuzz -- --nocapture 2>&1 |
  grep -E "predictions checked|test result|faults|^ +[0-9]+ |panicked"
cargo test --release -p contact-bounce-c --test fuzz -- --nocapture 2>&1 |
  grep -E "C API|test result|faults|^  |panicked"
