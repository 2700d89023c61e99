// The debouncers' share of the cost examples (cost.rs under QEMU, uno_cost*.rs in simavr):
// 1000 samples of the same pseudo-random input through our debouncer, through debouncr's
// 16-sample debouncer, and through the sample loop alone (subtracted by the report), marked
// `first` .. `first + 4` (`run`); then the learning debouncer on the same input, and the
// idle path, 1000 samples of a settled open contact, through our debouncer, the learner and
// the loop alone (`run_learner`).

use contact_bounce::{LearnerPrior, LearningState, Mode, State, Windows};
use core::hint::black_box;

/// 1000 samples of a bouncing input (a 32-bit xorshift, biased to runs).
fn samples(mut seed: u32) -> impl Iterator<Item = bool> {
    (0..1000).map(move |_| {
        seed ^= seed << 13;
        seed ^= seed >> 17;
        seed ^= seed << 5;
        seed & 0x7 != 0
    })
}

#[inline(always)]
pub fn run(mark: impl Fn(u8), first: u8) {
    if let Ok(windows) = Windows::new(black_box(12), black_box(12), Mode::Confirm) {
        let mut state = State::new(false);
        mark(first);
        for s in samples(black_box(0x1234_5678)) {
            black_box(state.update(black_box(s), &windows));
        }
        mark(first + 1);
    }
    let mut theirs = debouncr::debounce_16(false);
    mark(first + 2);
    for s in samples(black_box(0x1234_5678)) {
        black_box(theirs.update(black_box(s)));
    }
    mark(first + 3);
    // The loop alone: the samples without a debouncer.
    for s in samples(black_box(0x1234_5678)) {
        black_box(s);
    }
    mark(first + 4);
}

/// 1000 samples of a settled open contact through `update` (true when it reports an edge): the
/// idle path. A function of its own, not inlined, so that every idle path is measured in the
/// same small frame, its state where `update` keeps it, with the input hidden from the
/// optimiser alone; the count of edges (none) is the result.
#[inline(never)]
fn idle(mut update: impl FnMut(bool) -> bool) -> u16 {
    let mut edges = 0u16;
    for _ in 0..1000u16 {
        edges += u16::from(update(black_box(false)));
    }
    edges
}

/// The learning debouncer on the same input, then the idle path (a settled open contact)
/// through our debouncer, the learner and the loop alone ([`idle`]), and the bouncing input's
/// loop alone, marked `first` .. `first + 5`.
#[inline(always)]
pub fn run_learner(mark: impl Fn(u8), first: u8) {
    if let Ok(prior) = LearnerPrior::new(black_box(12), black_box(12), black_box(31)) {
        let mut key = LearningState::new(false);
        mark(first);
        for s in samples(black_box(0x1234_5678)) {
            black_box(key.update(black_box(s), &prior));
        }
        mark(first + 1);
        // The idle path: settled, no edge in progress.
        if let Ok(windows) = Windows::new(black_box(12), black_box(12), Mode::Confirm) {
            let mut state = State::new(false);
            black_box(idle(|s| state.update(s, &windows).is_some()));
        }
        mark(first + 2);
        let mut key = LearningState::new(false);
        black_box(idle(|s| key.update(s, &prior).is_some()));
        mark(first + 3);
        black_box(idle(|s| s));
        mark(first + 4);
        // The bouncing input's loop alone, for the learner's net cost.
        for s in samples(black_box(0x1234_5678)) {
            black_box(s);
        }
        mark(first + 5);
    }
}
