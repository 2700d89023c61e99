//! Debouncers that wait for their pin (feature `async`): `next_edge().await` sleeps until the
//! contact leaves its debounced level ([`Wait`], an interrupt in an async HAL), then samples it
//! every period ([`DelayNs`]) until the change is debounced and its bounce has been watched,
//! and returns the edge. Between events nothing runs; during one, it samples at the period a
//! polled debouncer would use, through the same state, so a window or a prior in samples means
//! the same here (its samples start when the pin wakes it, so their phase is not the polled
//! ones': an edge may come up to a period apart, or, with a confirm window on a bouncing
//! contact, up to the bounce apart; the tests measure both).
//!
//! Either strategy: [`Windowed`] (the 2-byte [`State`] with [`Windows`], from physics or a
//! capture) or [`Learning`] (the [`LearningState`] with a [`LearnerPrior`]).
//!
//! ```
//! use contact_bounce::debounce::wait::{AsyncDebouncer, Learning};
//! use contact_bounce::{debounce::Polarity, Edge, LearnerPrior};
//! use core::num::NonZeroU32;
//! use embedded_hal_mock::eh1::delay::NoopDelay;
//! use embedded_hal_mock::eh1::digital::{Mock, State as Level, Transaction};
//! // An active-low button, open: read once, then the wait returns when it is pressed, and the
//! // learner reports a change at the first sample after a settled time.
//! let mut pin = Mock::new(&[
//!     Transaction::get(Level::High),
//!     Transaction::wait_for_state(Level::Low),
//!     Transaction::get(Level::Low),
//! ]);
//! let prior = LearnerPrior::new(2, 2, 10)?;
//! let period = NonZeroU32::new(1_000_000).unwrap(); // 1 ms samples
//! let mut button =
//!     AsyncDebouncer::new(pin.clone(), NoopDelay, Learning::new(prior), Polarity::ActiveLow, period)
//!         .unwrap();
//! assert_eq!(embassy_futures::block_on(button.next_edge()), Ok(Edge::Press));
//! pin.done();
//! # Ok::<(), contact_bounce::Error>(())
//! ```

use core::num::NonZeroU32;

use embedded_hal::digital::InputPin;
use embedded_hal_async::delay::DelayNs;
use embedded_hal_async::digital::Wait;

use crate::debounce::learn::read;
use crate::debounce::Polarity;
use crate::{Edge, LearnerPrior, LearningState, State, Windows};

/// What an [`AsyncDebouncer`] runs its samples through. Implemented by [`Windowed`] and
/// [`Learning`].
pub trait Strategy: sealed::Sealed {
    /// A key settled at `closed` (the contact as first read).
    fn settle(&mut self, closed: bool);
    /// One sample; the edge it debounces, if any.
    fn sample(&mut self, closed: bool) -> Option<Edge>;
    /// The debounced level.
    fn is_closed(&self) -> bool;
    /// No change is in progress: a sample at the debounced level would change nothing, so the
    /// debouncer may wait for the pin instead of sampling it.
    fn is_settled(&self) -> bool;
}

mod sealed {
    pub trait Sealed {}
    impl Sealed for super::Windowed {}
    impl Sealed for super::Learning {}
}

/// The 2-byte debouncer ([`State`]) with fixed windows.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Windowed {
    state: State,
    windows: Windows,
}

impl Windowed {
    /// Fixed `windows` (samples of the debouncer's period).
    #[must_use]
    pub const fn new(windows: Windows) -> Self {
        Self {
            state: State::new(false),
            windows,
        }
    }

    /// The state.
    #[must_use]
    pub const fn state(&self) -> State {
        self.state
    }
}

impl Strategy for Windowed {
    fn settle(&mut self, closed: bool) {
        self.state = State::new(closed);
    }
    fn sample(&mut self, closed: bool) -> Option<Edge> {
        self.state.update(closed, &self.windows)
    }
    fn is_closed(&self) -> bool {
        self.state.is_closed()
    }
    fn is_settled(&self) -> bool {
        self.state.is_settled()
    }
}

/// The learning debouncer ([`LearningState`]) from a prior.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Learning {
    state: LearningState,
    prior: LearnerPrior,
}

impl Learning {
    /// From `prior` (samples of the debouncer's period), with nothing learned.
    #[must_use]
    pub const fn new(prior: LearnerPrior) -> Self {
        Self {
            state: LearningState::new(false),
            prior,
        }
    }

    /// From `prior`, having learned `state`'s learning (for example restored from storage).
    #[must_use]
    pub const fn restore(prior: LearnerPrior, state: LearningState) -> Self {
        Self { state, prior }
    }

    /// The state (what it learned: [`LearningState::learned`]).
    #[must_use]
    pub const fn state(&self) -> LearningState {
        self.state
    }
}

impl Strategy for Learning {
    fn settle(&mut self, closed: bool) {
        self.state.settle(closed);
    }
    fn sample(&mut self, closed: bool) -> Option<Edge> {
        self.state.update(closed, &self.prior)
    }
    fn is_closed(&self) -> bool {
        self.state.is_closed()
    }
    fn is_settled(&self) -> bool {
        self.state.is_settled()
    }
}

/// A debounced contact on a pin it can wait for (see [`crate::debounce::wait`]).
#[derive(Debug)]
pub struct AsyncDebouncer<P, D, K> {
    pin: P,
    delay: D,
    strategy: K,
    polarity: Polarity,
    period_ns: NonZeroU32,
}

impl<P: InputPin + Wait, D: DelayNs, K: Strategy> AsyncDebouncer<P, D, K> {
    /// Reads the pin once and settles the strategy at that level; samples every `period_ns`
    /// nanoseconds while a change is in progress (the period the strategy's windows or prior
    /// are in).
    ///
    /// # Errors
    /// The pin's error.
    pub fn new(
        mut pin: P,
        delay: D,
        mut strategy: K,
        polarity: Polarity,
        period_ns: NonZeroU32,
    ) -> Result<Self, P::Error> {
        let closed = read(&mut pin, polarity)?;
        strategy.settle(closed);
        Ok(Self {
            pin,
            delay,
            strategy,
            polarity,
            period_ns,
        })
    }

    /// Waits for the next debounced edge. Cancel-safe between samples: dropped while waiting
    /// or sleeping, it loses no state (the next call goes on from the last sample).
    ///
    /// # Errors
    /// The pin's error (the state is unchanged by the failed read or wait).
    pub async fn next_edge(&mut self) -> Result<Edge, P::Error> {
        loop {
            if self.strategy.is_settled() {
                // Nothing in progress: sleep until the pin leaves the debounced level, then
                // sample at once.
                let closed_level_is_low = self.polarity == Polarity::ActiveLow;
                if self.strategy.is_closed() == closed_level_is_low {
                    self.pin.wait_for_high().await?;
                } else {
                    self.pin.wait_for_low().await?;
                }
            } else {
                // A change in progress (this call's or the last edge's bounce): one period
                // after the last sample.
                self.delay.delay_ns(self.period_ns.get()).await;
            }
            let closed = read(&mut self.pin, self.polarity)?;
            if let Some(edge) = self.strategy.sample(closed) {
                return Ok(edge);
            }
        }
    }

    /// The debounced contact: closed or open.
    pub fn is_closed(&self) -> bool {
        self.strategy.is_closed()
    }

    /// The strategy (its state: what a learner learned).
    pub const fn strategy(&self) -> &K {
        &self.strategy
    }

    /// The pin, the delay and the strategy back.
    pub fn free(self) -> (P, D, K) {
        (self.pin, self.delay, self.strategy)
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;
    use crate::Mode;
    use core::cell::Cell;
    use core::convert::Infallible;
    use std::rc::Rc;
    use std::vec::Vec;

    /// A push button tapped by a hand: `taps` taps, press to press 149-179 ms, held 35-94 ms,
    /// up at least 55 ms (so each tap and gap lasts more than the fastest tap, 31 ms), each press bouncing for up to 4.5 ms and each release for up to 3 ms, the contact
    /// changing every 100 to 340 us meanwhile; then, from the end of the run (`end`), pressed
    /// for good, so that a wait always returns. Closed at `t` nanoseconds?
    fn closed_at(t: u64, taps: u64) -> bool {
        let first = 300_000_000_u64;
        if t >= end(taps) {
            return true;
        }
        if t < first {
            return false;
        }
        let slot = (t - first) / 150_000_000;
        for k in slot.saturating_sub(1)..=slot {
            if k >= taps {
                continue;
            }
            let s = first + k * 150_000_000 + (k * 7919 % 30) * 1_000_000;
            let h = 35_000_000 + (k * 37 % 60) * 1_000_000;
            let (pb, rb) = (
                500_000 + k * 1_237_000 % 4_000_000,
                300_000 + k * 911_000 % 2_700_000,
            );
            let flip = 100_000 + (k % 5) * 60_000;
            if t < s || t >= s + h + rb {
                continue;
            }
            return if t < s + pb {
                ((t - s) / flip).is_multiple_of(2)
            } else if t < s + h {
                true
            } else {
                !((t - s - h) / flip).is_multiple_of(2)
            };
        }
        false
    }

    /// Simulated time shared by the pin and the delay, and the reads counted.
    #[derive(Clone)]
    struct Clock {
        now: Rc<Cell<u64>>,
        reads: Rc<Cell<u64>>,
        taps: u64,
    }

    struct Pin(Clock);
    struct Delay(Clock);

    impl embedded_hal::digital::ErrorType for Pin {
        type Error = Infallible;
    }
    impl InputPin for Pin {
        fn is_high(&mut self) -> Result<bool, Infallible> {
            self.is_low().map(|low| !low)
        }
        fn is_low(&mut self) -> Result<bool, Infallible> {
            self.0.reads.set(self.0.reads.get() + 1);
            Ok(closed_at(self.0.now.get(), self.0.taps)) // active low
        }
    }
    /// The end of a run of `taps` taps, ns.
    fn end(taps: u64) -> u64 {
        300_000_000 + taps * 150_000_000 + 500_000_000
    }

    impl Pin {
        /// Advances time (in 10 us steps) until the pin reads `low`.
        fn until(&mut self, low: bool) {
            while closed_at(self.0.now.get(), self.0.taps) != low {
                self.0.now.set(self.0.now.get() + 10_000);
            }
        }
    }
    impl Wait for Pin {
        async fn wait_for_high(&mut self) -> Result<(), Infallible> {
            self.until(false);
            Ok(())
        }
        async fn wait_for_low(&mut self) -> Result<(), Infallible> {
            self.until(true);
            Ok(())
        }
        async fn wait_for_rising_edge(&mut self) -> Result<(), Infallible> {
            unimplemented!()
        }
        async fn wait_for_falling_edge(&mut self) -> Result<(), Infallible> {
            unimplemented!()
        }
        async fn wait_for_any_edge(&mut self) -> Result<(), Infallible> {
            unimplemented!()
        }
    }
    impl DelayNs for Delay {
        async fn delay_ns(&mut self, ns: u32) {
            self.0.now.set(self.0.now.get() + u64::from(ns));
        }
    }

    /// The edges `taps` taps give through `strategy` at 1 ms samples, each with its time (ns),
    /// and the pin reads taken.
    fn run<K: Strategy>(strategy: K, taps: u64) -> (Vec<(Edge, u64)>, u64) {
        let clock = Clock {
            now: Rc::new(Cell::new(0)),
            reads: Rc::new(Cell::new(0)),
            taps,
        };
        let period = NonZeroU32::new(1_000_000).unwrap_or_else(|| unreachable!());
        let mut d = AsyncDebouncer::new(
            Pin(clock.clone()),
            Delay(clock.clone()),
            strategy,
            Polarity::ActiveLow,
            period,
        )
        .unwrap_or_else(|_| unreachable!());
        let end = end(taps);
        let mut edges = Vec::new();
        while clock.now.get() < end {
            let Ok(edge) = embassy_futures::block_on(d.next_edge());
            if clock.now.get() < end {
                edges.push((edge, clock.now.get()));
            }
        }
        (edges, clock.reads.get())
    }

    /// The same taps polled every period through the same strategy.
    fn polled<K: Strategy>(mut strategy: K, taps: u64) -> Vec<(Edge, u64)> {
        strategy.settle(false);
        (0..end(taps) / 1_000_000)
            .filter_map(|i| {
                let t = i * 1_000_000;
                strategy.sample(closed_at(t, taps)).map(|e| (e, t))
            })
            .collect()
    }

    fn alternating(edges: &[(Edge, u64)], taps: usize) {
        assert_eq!(edges.len(), 2 * taps, "{edges:?}");
        for (i, (e, _)) in edges.iter().enumerate() {
            assert_eq!(
                *e,
                if i % 2 == 0 {
                    Edge::Press
                } else {
                    Edge::Release
                }
            );
        }
    }

    #[test]
    fn the_learner_waiting_keeps_every_tap_and_samples_only_during_events() {
        let prior = LearnerPrior::at_period(31, 31, 1_000_000).unwrap_or_else(|_| unreachable!());
        let (edges, reads) = run(Learning::new(prior), 200);
        alternating(&edges, 200);
        let polled = polled(Learning::new(prior), 200);
        alternating(&polled, 200);
        // Each edge within a sample period of the polled one (the samples start at the wake).
        for ((e, t), (p, u)) in edges.iter().zip(&polled) {
            assert_eq!(e, p);
            assert!(t.abs_diff(*u) <= 1_000_000, "{t} {u}");
        }
        // Sampled only while an event is watched (its bounce, then a tap, 31 samples, after
        // each edge): at most 40 reads an edge, where polling reads 30,800 times in all (13,202
        // reads measured: the 400 edges' watching; these taps come every 150 ms, so a quiet
        // keyboard saves far more).
        assert!(reads < 400 * 40, "{reads}");
    }

    #[test]
    fn fixed_windows_waiting_debounce_as_polled() {
        for mode in [Mode::Confirm, Mode::HoldOff] {
            let windows = Windows::new(6, 6, mode).unwrap_or_else(|_| unreachable!());
            let (edges, _) = run(Windowed::new(windows), 100);
            alternating(&edges, 100);
            let polled = polled(Windowed::new(windows), 100);
            // Hold-off reports the first change a sample sees: within a period of the polled
            // one. Confirm reports a window after the last bounce a sample sees, and samples at
            // another phase may see another last bounce: within the longest bounce (4.5 ms)
            // and a period.
            let bound = match mode {
                Mode::HoldOff => 1_000_000,
                Mode::Confirm => 5_500_000,
            };
            for ((e, t), (p, u)) in edges.iter().zip(&polled) {
                assert_eq!(e, p);
                assert!(t.abs_diff(*u) <= bound, "{mode:?} {t} {u}");
            }
        }
    }
}
