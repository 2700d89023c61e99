// The lines of the learning debouncer, the same on the host, under QEMU and on the Uno: the
// recorded press of the signal relay (10 us samples), pressed and released 12 times from a
// 20 ms prior, with the default fastest tap (31 ms, 3,100 samples). Each press gives one edge and each release one; the press window comes down to
// 3/2 of the bounce it saw after 10 presses; what it learned is saved and restored.

use contact_bounce::{debounce::learn::Learned, LearnerPrior, LearningState};
use core::fmt::Write;

/// The recorded press (`samples` samples, 32 a word in `bits`, least significant first) at
/// sample `k`, then closed.
fn closed_at(bits: &[u32], samples: usize, k: usize) -> bool {
    match bits.get(k / 32) {
        Some(word) if k < samples => word >> (k % 32) & 1 == 1,
        _ => true,
    }
}

pub fn run(out: &mut impl Write, bits: &[u32], samples: usize) -> core::fmt::Result {
    // 20 ms of 10 us samples; each level held 30 ms, longer than any window.
    let Ok(prior) = LearnerPrior::at_period(2000, 2000, 10_000) else {
        return writeln!(out, "prior out of range");
    };
    let hold = 3000;
    let mut key = LearningState::new(false);
    for press in 1..=12 {
        write!(out, "learn {press}:")?;
        for k in 0..samples + hold {
            if let Some(edge) = key.update(closed_at(bits, samples, k), &prior) {
                write!(out, " {edge:?}@{k}")?;
            }
        }
        for k in 0..hold {
            if let Some(edge) = key.update(false, &prior) {
                write!(out, " {edge:?}@{k}")?;
            }
        }
        let (p, r) = key.learned().windows(&prior);
        writeln!(out, " windows {p}/{r}")?;
    }
    let bytes = key.learned().to_bytes();
    match Learned::from_bytes(bytes) {
        Ok(restored) if restored == key.learned() => {
            writeln!(out, "learned: {} bytes saved and restored", bytes.len())
        }
        _ => writeln!(out, "learned: restore failed"),
    }
}
