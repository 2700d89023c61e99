//! A debouncer that learns its own switch: it reports each change at once (as
//! [`Mode::HoldOff`](crate::Mode::HoldOff) does), watches the bounce that follows, and sets
//! the next window from what it has seen, per key, in a few bytes and integer operations.
//!
//! What it keeps per kind (press, release), in samples ([`Learned`]): how many events it has
//! seen, how many bounced again after a quiet gap (a late burst), the longest bounce without
//! and with a late burst. From that:
//!
//! - The window starts at a prior, given by the caller in samples (for example the P99.9 of
//!   the switch type's bounce, or a window from a capture), and keeps it for the first
//!   [`WARM_UP`] events of a kind.
//! - After that it tightens to 3/2 of the longest bounce seen (`m + (m - 1) / 2` samples for
//!   `m` seen: at most 3/2 of the bounce plus one sample, whatever the sampling phase). A late
//!   burst that lasts more than [`LATE_GAP`] times the longest plain burst is a different
//!   mechanism (an actuator's rebound) whose scale one or two events cannot tell: once a kind
//!   has shown one, the window stays at the prior until [`LATE_EVIDENCE`] late bursts have
//!   been seen, and then covers the longest of them times 3/2.
//! - It never goes below the longest bounce seen, and when a bounce outlasts the prior, the
//!   window covers it times 3/2.
//! - It widens at once: while the contact keeps changing, the event lasts until it has been
//!   quiet for [`LATE_GAP`] times its first burst (at least [`LATE_GAP`] samples, and at least
//!   the prior over [`LATE_GAP_PRIOR_SHARE`]) past the window; and when a bounce comes after
//!   that (the edge it gives is false), the contact returns within that same quiet after the
//!   false event's watch: the event before it is then counted as a late burst that lasted
//!   until then (up to the prior: a quick double tap looks the same), which sends its kind's
//!   window back to the prior until [`LATE_EVIDENCE`] are seen.
//!
//! Every rule is in samples and ratios of samples: nothing depends on how long a sample is,
//! so the same learner serves a reed (microseconds) and a contactor (a tenth of a second) at
//! the sampling period each needs. A period change is [`Learned::rescale`]d. The prior's share
//! in the late-burst gap keeps what counts as a late burst the same however finely one switch
//! is sampled: without it, sampled every 10 us, the push button of `docs/replay.md` showed three
//! late bursts by its 12th release (one at 1 ms), and the learner trusted them too early.

use embedded_hal::digital::InputPin;

use crate::debounce::{Edge, Polarity, Windows};
use crate::error::{Error, Parameter, Reason};

/// Events of a kind before its window leaves the prior.
pub const WARM_UP: u8 = 10;
/// Late bursts of a kind before their scale is trusted.
pub const LATE_EVIDENCE: u8 = 3;
/// A quiet gap of at least this many times the first burst (and this many samples) before a
/// change makes that change a late burst; the same quiet ends an event past its window.
pub const LATE_GAP: u16 = 4;
/// The late-burst gap is also at least the kind's prior window over this: a floor in the
/// switch's own time scale (the prior carries it), so that what counts as a late burst does not
/// depend on how finely the contact is sampled (for the hand-operated prior, 157 ms / 32 =
/// 4.9 ms).
pub const LATE_GAP_PRIOR_SHARE: u16 = 32;

/// What the learner has seen of one kind, in samples.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Tail {
    /// Events seen (saturating).
    pub events: u8,
    /// Events with a late burst (saturating).
    pub late: u8,
    /// The longest bounce of an event without a late burst.
    pub burst: u16,
    /// The longest bounce of an event with a late burst.
    pub late_bounce: u16,
}

/// The window `m` samples of bounce ask for: `m + (m - 1) / 2` (one sample for none), at most
/// [`Windows::MAX_TICKS`]. A bounce seen over `m` samples lasted more than `m - 1` sampling
/// periods (its first and last change each fall anywhere in a sample), so this is at most 3/2
/// of the bounce plus one sample, and never less than what was seen.
const fn grow(m: u16) -> u16 {
    if m == 0 {
        return 1;
    }
    min(m.saturating_add((m - 1) / 2), Windows::MAX_TICKS)
}

const fn max(a: u16, b: u16) -> u16 {
    if a > b {
        a
    } else {
        b
    }
}

const fn min(a: u16, b: u16) -> u16 {
    if a < b {
        a
    } else {
        b
    }
}

impl Tail {
    /// The longest bounce seen (samples).
    #[must_use]
    pub const fn longest(&self) -> u16 {
        max(self.burst, self.late_bounce)
    }

    /// The window this tail gives with `prior` (samples; see [`crate::learn`]).
    #[must_use]
    pub const fn window(&self, prior: u16) -> u16 {
        let seen = self.longest();
        if seen >= prior {
            return grow(seen);
        }
        // Late bursts far beyond the plain bursts are another mechanism, whose scale a few
        // cannot tell; late bursts on the plain bursts' scale are more of the same.
        let apart = self.late > 0 && self.late_bounce > LATE_GAP.saturating_mul(max(self.burst, 1));
        let trusted = if self.events < WARM_UP || (apart && self.late < LATE_EVIDENCE) {
            prior
        } else {
            grow(seen)
        };
        // Never below what was seen (a watch of `seen` samples covers a change seen at `seen`),
        // nor below one sample.
        max(min(trusted, prior), max(seen, 1))
    }

    const fn from_bytes(b: [u8; 6]) -> Self {
        Self {
            events: b[0],
            late: b[1],
            burst: u16::from_le_bytes([b[2], b[3]]),
            late_bounce: u16::from_le_bytes([b[4], b[5]]),
        }
    }

    const fn valid(self) -> bool {
        self.late <= self.events
            && self.burst <= Windows::MAX_TICKS
            && self.late_bounce <= Windows::MAX_TICKS
    }

    fn record(&mut self, bounce: u16, late: bool) {
        self.events = self.events.saturating_add(1);
        if late {
            self.late = self.late.saturating_add(1);
            self.late_bounce = max(self.late_bounce, bounce);
        } else {
            self.burst = max(self.burst, bounce);
        }
    }
}

/// What a learner has learned of a switch: press and release [`Tail`]s. Twelve bytes to save
/// (for example in EEPROM) and restore, so a reboot does not start from the prior.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Learned {
    /// Presses (makes).
    pub press: Tail,
    /// Releases (breaks).
    pub release: Tail,
}

impl Learned {
    /// The saved form: press then release, each events, late, burst and late bounce (little
    /// endian).
    #[must_use]
    pub const fn to_bytes(&self) -> [u8; 12] {
        let (p, r) = (self.press, self.release);
        let (pb, pl, rb, rl) = (
            p.burst.to_le_bytes(),
            p.late_bounce.to_le_bytes(),
            r.burst.to_le_bytes(),
            r.late_bounce.to_le_bytes(),
        );
        [
            p.events, p.late, pb[0], pb[1], pl[0], pl[1], r.events, r.late, rb[0], rb[1], rl[0],
            rl[1],
        ]
    }

    /// Restores [`Learned::to_bytes`].
    ///
    /// # Errors
    /// [`Parameter::Time`] with [`Reason::OutOfRange`] when the bytes cannot have been saved by
    /// a learner (more late bursts than events, a bounce longer than
    /// [`Windows::MAX_TICKS`]): erased or corrupted storage.
    pub const fn from_bytes(b: [u8; 12]) -> Result<Self, Error> {
        let press = Tail::from_bytes([b[0], b[1], b[2], b[3], b[4], b[5]]);
        let release = Tail::from_bytes([b[6], b[7], b[8], b[9], b[10], b[11]]);
        if press.valid() && release.valid() {
            Ok(Self { press, release })
        } else {
            Err(Error::new(Parameter::Time, Reason::OutOfRange))
        }
    }

    /// The same bounces in samples of another period: `times` old samples are `per` new ones
    /// (sampling twice as often: 2 and 1). Rounds up, saturates at [`Windows::MAX_TICKS`].
    ///
    /// # Errors
    /// [`Parameter::Time`] with [`Reason::NotPositive`] when `times` or `per` is 0.
    pub fn rescale(&self, times: u16, per: u16) -> Result<Self, Error> {
        if times == 0 || per == 0 {
            return Err(Error::new(Parameter::Time, Reason::NotPositive));
        }
        let scale = |x: u16| {
            let v = (u32::from(x) * u32::from(times)).div_ceil(u32::from(per));
            u16::try_from(v.min(u32::from(Windows::MAX_TICKS))).unwrap_or(Windows::MAX_TICKS)
        };
        let tail = |t: Tail| Tail {
            burst: scale(t.burst),
            late_bounce: scale(t.late_bounce),
            ..t
        };
        Ok(Self {
            press: tail(self.press),
            release: tail(self.release),
        })
    }

    /// The press and release windows with the priors of `prior` (its mode is not used).
    #[must_use]
    pub const fn windows(&self, prior: &Windows) -> (u16, u16) {
        (
            self.press.window(prior.press()),
            self.release.window(prior.release()),
        )
    }
}

const LEVEL: u8 = 1;
const RAW: u8 = 2;
const ACTIVE: u8 = 4;
const LATE: u8 = 8;
const RECENT: u8 = 16;

/// One key's learning debouncer state (see [`crate::learn`]): what it learned and the event in
/// progress. 24 bytes; integer-only per sample.
///
/// ```
/// use contact_bounce::{Edge, LearningState, Mode, Windows};
/// // Prior: 8 samples each way. The press bounces for 2 samples each time.
/// let prior = Windows::new(8, 8, Mode::HoldOff)?;
/// let mut key = LearningState::new(false);
/// for _ in 0..12 {
///     let mut press = [true; 20];
///     press[1] = false;
///     let edges: Vec<_> = press.iter().filter_map(|&s| key.update(s, &prior)).collect();
///     assert_eq!(edges, [Edge::Press]);
///     let release = [false; 20];
///     let edges: Vec<_> = release.iter().filter_map(|&s| key.update(s, &prior)).collect();
///     assert_eq!(edges, [Edge::Release]);
/// }
/// // Ten presses in, the press window is 2 + (2 - 1) / 2 = 2 samples, not the prior's 8.
/// assert_eq!(key.learned().windows(&prior), (2, 1));
/// # Ok::<(), contact_bounce::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct LearningState {
    learned: Learned,
    /// Samples since the event's edge (saturating; no longer counted once the event has been
    /// over for a quiet interval).
    since: u16,
    /// When the event's last change was seen.
    last: u16,
    /// When its first burst's last change was seen.
    burst_end: u16,
    /// When it ends, unless the contact keeps changing.
    guard: u16,
    /// Samples from the previous event's edge to the current one's (counted up to one quiet
    /// interval past its watch: a lower bound beyond).
    previous_span: u16,
    /// LEVEL (debounced closed), RAW (last sample closed), ACTIVE (an event in progress),
    /// LATE (it has a late burst), RECENT (an event ended less than a quiet interval ago).
    flags: u8,
}

impl LearningState {
    /// A key settled at `closed` (its contact closed or not), with nothing learned.
    #[must_use]
    pub const fn new(closed: bool) -> Self {
        Self::restore(
            closed,
            Learned {
                press: Tail {
                    events: 0,
                    late: 0,
                    burst: 0,
                    late_bounce: 0,
                },
                release: Tail {
                    events: 0,
                    late: 0,
                    burst: 0,
                    late_bounce: 0,
                },
            },
        )
    }

    /// A key settled at `closed` that has learned `learned` (for example restored with
    /// [`Learned::from_bytes`]).
    #[must_use]
    pub const fn restore(closed: bool, learned: Learned) -> Self {
        let level = if closed { LEVEL | RAW } else { 0 };
        Self {
            learned,
            since: u16::MAX,
            last: 0,
            burst_end: 0,
            guard: 0,
            previous_span: u16::MAX,
            flags: level,
        }
    }

    /// What it has learned.
    #[must_use]
    pub const fn learned(&self) -> Learned {
        self.learned
    }

    /// The debounced contact: closed or open.
    #[must_use]
    pub const fn is_closed(&self) -> bool {
        self.flags & LEVEL != 0
    }

    /// No event is in progress: the last edge's bounce has been watched to its end.
    #[must_use]
    pub const fn is_settled(&self) -> bool {
        self.flags & ACTIVE == 0
    }

    /// Settles the key at `closed` without reporting an edge, keeping what it learned (for
    /// example after a sleep in which the pin was not sampled).
    pub fn settle(&mut self, closed: bool) {
        *self = Self::restore(closed, self.learned);
    }

    /// Feeds one sample (`true`: the contact reads closed) with the caller's prior windows in
    /// samples (the mode of `prior` is not used: this learner always reports at once); returns
    /// the edge it debounces, if any.
    // Always inlined: the idle path is the cost of nearly every sample, a few instructions
    // inline (docs/cost-report.md) where a call would cost more than the path.
    #[allow(clippy::inline_always)]
    #[inline(always)]
    pub fn update(&mut self, closed: bool, prior: &Windows) -> Option<Edge> {
        // The idle path, inlined and read-only: settled long enough ago, and the sample reads
        // the level (as the last one did).
        if self.flags & (ACTIVE | RECENT) == 0 && closed == self.is_closed() {
            return None;
        }
        self.watch(closed, *prior)
    }

    /// The quiet (samples) that makes a change a late burst and ends an event: [`LATE_GAP`]
    /// times the first burst, at least [`LATE_GAP`] samples and the prior of the kind the
    /// contact is in over [`LATE_GAP_PRIOR_SHARE`].
    fn quiet(&self, prior: Windows) -> u16 {
        let own = if self.is_closed() {
            prior.press()
        } else {
            prior.release()
        };
        max(
            LATE_GAP.saturating_mul(max(self.burst_end, 1)),
            own / LATE_GAP_PRIOR_SHARE,
        )
    }

    /// [`LearningState::update`] while an edge is in progress or starts.
    #[inline(never)]
    fn watch(&mut self, closed: bool, prior: Windows) -> Option<Edge> {
        let changed = closed != (self.flags & RAW != 0);
        self.flags = if closed {
            self.flags | RAW
        } else {
            self.flags & !RAW
        };
        if self.flags & ACTIVE != 0 {
            self.since = self.since.saturating_add(1);
            if changed {
                let quiet = self.quiet(prior);
                if self.flags & LATE == 0 && self.since - self.last >= quiet {
                    self.flags |= LATE;
                }
                if self.flags & LATE == 0 {
                    self.burst_end = self.since;
                }
                self.last = self.since;
                // Widen at once: quiet past the last change before the event ends.
                let quiet = self.quiet(prior);
                self.guard = max(self.guard, self.last.saturating_add(quiet));
            }
            if self.since < self.guard {
                return None;
            }
            let late = self.flags & LATE != 0;
            let tail = if self.is_closed() {
                &mut self.learned.press
            } else {
                &mut self.learned.release
            };
            tail.record(min(self.last, Windows::MAX_TICKS), late);
            self.flags = (self.flags & !(ACTIVE | LATE)) | RECENT;
            // This sample may already show the next change: fall through.
        } else {
            self.since = self.since.saturating_add(1);
        }
        // Until one quiet interval after the watch, a change is that event's late bounce
        // (below); after it, the idle path needs no count.
        let quiet = self.quiet(prior);
        let recent = self.flags & RECENT != 0 && self.since <= self.guard.saturating_add(quiet);
        if !recent {
            // No longer counted: `since` stays a lower bound of the time since the edge.
            self.flags &= !RECENT;
        }
        if closed == self.is_closed() {
            return None;
        }
        // The contact comes back within one quiet interval after the watch of the event that
        // just ended: that event's edge was false, a late bounce of the event before it (of
        // this edge's kind), which lasted at least until now. Counted up to the prior only: a
        // genuine quick double tap looks the same and must not ratchet the window up; it only
        // sends it back to the prior.
        if recent {
            let (tail, cap) = if closed {
                (&mut self.learned.press, prior.press())
            } else {
                (&mut self.learned.release, prior.release())
            };
            let bounce = min(self.previous_span.saturating_add(self.since), cap);
            if tail.late < tail.events {
                tail.late += 1;
            }
            tail.late_bounce = max(tail.late_bounce, bounce);
        }
        let (press, release) = self.learned.windows(&prior);
        let (edge, window) = if closed {
            (Edge::Press, press)
        } else {
            (Edge::Release, release)
        };
        self.flags = (self.flags & RAW) | ACTIVE | if closed { LEVEL } else { 0 };
        self.previous_span = self.since;
        self.since = 0;
        self.last = 0;
        self.burst_end = 0;
        self.guard = window;
        Some(edge)
    }
}

/// A debounced contact on an [`InputPin`] that learns its own switch's bounce (see
/// [`crate::learn`]), sampled by the caller at a period of its choosing.
///
/// ```
/// use contact_bounce::{Edge, LearningDebouncer, Mode, debounce::Polarity, Windows};
/// use embedded_hal_mock::eh1::digital::{Mock, State as Level, Transaction};
/// let levels = [Level::High, Level::Low, Level::High, Level::Low, Level::Low];
/// let mut pin = Mock::new(&levels.map(|l| Transaction::get(l)));
/// let prior = Windows::new(3, 3, Mode::HoldOff)?;
/// let mut button = LearningDebouncer::new(pin.clone(), prior, Polarity::ActiveLow).unwrap();
/// let edges: Vec<_> = (0..4).map(|_| button.update().unwrap()).collect();
/// assert_eq!(edges, [Some(Edge::Press), None, None, None]);
/// pin.done();
/// # Ok::<(), contact_bounce::Error>(())
/// ```
#[derive(Debug)]
pub struct LearningDebouncer<P> {
    pin: P,
    prior: Windows,
    polarity: Polarity,
    state: LearningState,
}

impl<P: InputPin> LearningDebouncer<P> {
    /// Reads the pin once to start settled at its level, with nothing learned.
    ///
    /// # Errors
    /// The pin's error.
    pub fn new(pin: P, prior: Windows, polarity: Polarity) -> Result<Self, P::Error> {
        Self::restore(pin, prior, polarity, Learned::default())
    }

    /// As [`LearningDebouncer::new`], with what an earlier run learned.
    ///
    /// # Errors
    /// The pin's error.
    pub fn restore(
        mut pin: P,
        prior: Windows,
        polarity: Polarity,
        learned: Learned,
    ) -> Result<Self, P::Error> {
        let closed = read(&mut pin, polarity)?;
        Ok(Self {
            pin,
            prior,
            polarity,
            state: LearningState::restore(closed, learned),
        })
    }

    /// Samples the pin once; returns the debounced edge, if any.
    ///
    /// # Errors
    /// The pin's error: the sample is skipped and the state is unchanged.
    pub fn update(&mut self) -> Result<Option<Edge>, P::Error> {
        let closed = read(&mut self.pin, self.polarity)?;
        Ok(self.state.update(closed, &self.prior))
    }

    /// The debounced contact is closed.
    #[must_use]
    pub const fn is_closed(&self) -> bool {
        self.state.is_closed()
    }

    /// What it has learned, to save.
    #[must_use]
    pub const fn learned(&self) -> Learned {
        self.state.learned()
    }

    /// The press and release windows it would use now (samples).
    #[must_use]
    pub const fn windows(&self) -> (u16, u16) {
        self.state.learned().windows(&self.prior)
    }

    /// Gives the pin back.
    pub fn free(self) -> P {
        self.pin
    }
}

fn read<P: InputPin>(pin: &mut P, polarity: Polarity) -> Result<bool, P::Error> {
    match polarity {
        Polarity::ActiveLow => pin.is_low(),
        Polarity::ActiveHigh => pin.is_high(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::debounce::Mode;

    fn prior(ticks: u16) -> Windows {
        Windows::new(ticks, ticks, Mode::HoldOff).unwrap_or_else(|_| unreachable!())
    }

    /// One press of `bounce` (closed, open, closed... for `bounce` samples, then closed), held
    /// for `hold` samples, and a clean release held `hold` samples; the edges reported.
    fn cycle(key: &mut LearningState, p: Windows, bounce: &[bool], hold: usize) -> [usize; 2] {
        let mut edges = [0, 0];
        for &s in bounce.iter().chain(core::iter::repeat_n(&true, hold)) {
            if key.update(s, &p).is_some() {
                edges[0] += 1;
            }
        }
        for _ in 0..hold {
            if key.update(false, &p).is_some() {
                edges[1] += 1;
            }
        }
        edges
    }

    #[test]
    fn it_keeps_the_prior_while_warming_up_then_tightens_to_what_it_saw() {
        let p = prior(50);
        let mut key = LearningState::new(false);
        // Bounce: closed, open, open, closed, open, closed (last change at sample 5).
        let bounce = [true, false, false, true, false, true];
        for n in 1..=12_u8 {
            assert_eq!(cycle(&mut key, p, &bounce, 80), [1, 1]);
            let (press, release) = key.learned().windows(&p);
            if n < WARM_UP {
                assert_eq!((press, release), (50, 50), "event {n}");
            } else {
                // 5 samples of bounce: 5 + (5 - 1) / 2.
                assert_eq!((press, release), (7, 1), "event {n}");
            }
        }
        assert_eq!(key.learned().press.burst, 5);
    }

    #[test]
    fn a_bounce_that_outlasts_the_window_extends_the_event_instead_of_a_false_edge() {
        let p = prior(3);
        let mut key = LearningState::new(false);
        // Changes every 2 samples for 20 samples: far past the 3-sample window.
        let bounce: [bool; 20] = core::array::from_fn(|i| (i / 2) % 2 == 0);
        assert_eq!(cycle(&mut key, p, &bounce, 100), [1, 1]);
        // It measured the whole bounce, and the next window covers it.
        let seen = key.learned().press.burst;
        assert!(seen >= 18, "{seen}");
        assert!(key.learned().windows(&p).0 > seen);
    }

    #[test]
    fn what_counts_as_a_late_burst_does_not_depend_on_the_sampling_period() {
        // Presses in time: chatter for 0.8 ms (the contact open 0.2-0.5 ms and 0.7-0.8 ms), and
        // in half of them a burst open again from 8 to 9 ms. Sampled every 1 ms and every
        // 10 us with the same 157 ms prior, the chatter is the first burst and only the 8 ms
        // one is late: 3 late bursts in 6 presses at both periods. (Without the prior's share
        // in the gap, the 10 us samples took the chatter's 0.2 ms gap for a late burst too: 6.)
        let mut lates = [0_u8; 2];
        for (slot, period) in [1e-3, 1e-5].into_iter().enumerate() {
            let ticks = |t: f64| {
                #[allow(
                    clippy::cast_possible_truncation,
                    clippy::cast_sign_loss,
                    clippy::as_conversions
                )]
                let n = (t / period).round() as usize;
                n
            };
            let p = prior(u16::try_from(ticks(157e-3)).unwrap_or(u16::MAX));
            let mut key = LearningState::new(false);
            for late_burst in [false, true, false, true, false, true] {
                let mut samples = [true; 1000];
                for (i, s) in samples.iter_mut().enumerate() {
                    #[allow(clippy::cast_precision_loss, clippy::as_conversions)]
                    let t = (i as f64 + 0.5) * period;
                    let chatter = (0.2e-3..0.5e-3).contains(&t) || (0.7e-3..0.8e-3).contains(&t);
                    *s = !(chatter || (late_burst && (8e-3..9e-3).contains(&t)));
                }
                let bounce = samples.get(..ticks(10e-3)).unwrap_or(&[]);
                cycle(&mut key, p, bounce, ticks(200e-3));
            }
            if let Some(late) = lates.get_mut(slot) {
                *late = key.learned().press.late;
            }
        }
        assert_eq!(lates, [3, 3]);
    }

    #[test]
    fn a_late_burst_keeps_the_prior_until_three_were_seen() {
        let p = prior(100);
        let mut key = LearningState::new(false);
        let plain = [true, false, true];
        for _ in 0..WARM_UP {
            cycle(&mut key, p, &plain, 200);
        }
        assert_eq!(key.learned().windows(&p).0, 2);
        // A burst after 30 quiet samples: a late burst (quiet >= 4 x the first burst).
        let mut late = [true; 40];
        late[1] = false;
        late[33] = false;
        late[34] = false;
        // The first comes after the 4-sample window: the quiet ended the event, so it gives
        // two false edges (open, then closed again), and the contact's return sends the
        // window back to the prior at once.
        assert_eq!(cycle(&mut key, p, &late, 200)[0], 3);
        assert_eq!(key.learned().windows(&p).0, 100);
        // The prior covers the next: each is a late burst inside the watch, no false edge.
        assert_eq!(cycle(&mut key, p, &late, 200)[0], 1);
        assert_eq!(key.learned().windows(&p).0, 100);
        assert_eq!(cycle(&mut key, p, &late, 200)[0], 1);
        // Three seen: 3/2 of the longest late bounce (its last change, back to closed, at
        // sample 35).
        assert_eq!(key.learned().press.late, LATE_EVIDENCE);
        assert_eq!(key.learned().press.late_bounce, 35);
        assert_eq!(key.learned().windows(&p).0, 35 + 17);
        assert_eq!(cycle(&mut key, p, &late, 200)[0], 1);
    }

    #[test]
    fn what_it_learned_is_saved_restored_and_rescaled() {
        let learned = Learned {
            press: Tail {
                events: 12,
                late: 3,
                burst: 7,
                late_bounce: 300,
            },
            release: Tail {
                events: 11,
                late: 0,
                burst: 2,
                late_bounce: 0,
            },
        };
        let bytes = learned.to_bytes();
        assert_eq!(Learned::from_bytes(bytes), Ok(learned));
        // Erased EEPROM (0xFF) is not a learner's: a typed error, never a huge window.
        assert_eq!(
            Learned::from_bytes([0xFF; 12]),
            Err(Error::new(Parameter::Time, Reason::OutOfRange))
        );
        // Sampling twice as often: twice the samples, rounded up; saturating at the top.
        let fast = learned.rescale(2, 1).unwrap_or_else(|_| unreachable!());
        assert_eq!((fast.press.burst, fast.press.late_bounce), (14, 600));
        let slow = learned.rescale(1, 3).unwrap_or_else(|_| unreachable!());
        assert_eq!((slow.press.burst, slow.release.burst), (3, 1));
        let huge = learned
            .rescale(u16::MAX, 1)
            .unwrap_or_else(|_| unreachable!());
        assert_eq!(huge.press.late_bounce, Windows::MAX_TICKS);
        assert!(learned.rescale(0, 1).is_err() && learned.rescale(1, 0).is_err());
        let restored = LearningState::restore(true, learned);
        assert!(restored.is_closed() && restored.is_settled());
        assert_eq!(restored.learned(), learned);
    }

    #[test]
    fn a_stuck_pin_and_noise_faster_than_the_samples_are_defined() {
        let p = prior(Windows::MAX_TICKS);
        // Stuck: no edge ever.
        let mut key = LearningState::new(false);
        for _ in 0..100_000 {
            assert_eq!(key.update(false, &p), None);
        }
        // Noise: a change at every sample for longer than the counters hold. One edge, the
        // event saturates and ends, and the window stays within the counter.
        let mut key = LearningState::new(false);
        let mut edges = 0;
        for i in 0..200_000_u32 {
            edges += usize::from(key.update(i % 2 == 0, &p).is_some());
        }
        assert!(edges >= 1);
        let (press, release) = key.learned().windows(&p);
        assert!(press <= Windows::MAX_TICKS && release <= Windows::MAX_TICKS);
    }

    #[test]
    fn a_key_is_a_few_bytes() {
        assert_eq!(core::mem::size_of::<LearningState>(), 24);
        assert_eq!(core::mem::size_of::<Learned>(), 12);
    }
}
