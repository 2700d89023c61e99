//! A debouncer that learns its own switch and never loses a real press: it reports each change
//! at once (as [`Mode::HoldOff`](crate::Mode::HoldOff) does), watches the bounce that follows,
//! and sets the next window from what the switch has shown, per key, in a few bytes and integer
//! operations.
//!
//! Two time scales meet in a key: the contact's own bounce (microseconds to a few milliseconds
//! of flights, and on some switches reversions of tens of milliseconds) and the hand's taps (no
//! real tap is down or up for less than about 31 ms: 16 taps a second is the known record). The
//! learner is told the fastest tap ([`LearnerPrior`], in samples) and keeps these rules:
//!
//! - **A window is never longer than the fastest tap, and a change that lasts a tap is always
//!   reported.** The first change of an edge is reported at once, and a real tap's next change
//!   comes a tap later, after the window has ended. A change that begins inside a window is
//!   reported when the window ends, or sooner once it has lasted a tap; that edge's own window
//!   runs from its report, so a real tap right after it can be reported late (by at most what
//!   the edge was), never lost, whatever the prior.
//! - **Windows grow only from what a finger cannot do.** An excursion of the contact away from
//!   the reported level that starts less than a tap after the edge and comes back in less than
//!   a tap is the switch's own: the window of that edge's kind grows to cover it (to
//!   3/2 of the time from the edge to its end, plus at most one sample, and at most a tap). An
//!   edge whose new level lasted a tap or longer is a tap, whatever came before: it never makes
//!   a window grow, so no train of real taps can, and 10,000 clean taps leave the windows at one
//!   sample.
//! - **Where the switch reverts for as long as a tap, it says so.** Each kind keeps the longest
//!   of the switch's own reversions ([`Tail::reversion`]) and how many lasted at least half the
//!   fastest tap ([`Tail::long_reversions`]): such a switch will also revert for longer, and
//!   those reversions look like taps to any rule that sees only timing (they are reported, as a
//!   tap of that length would be). [`Tail::reverts_like_a_tap`] tells the firmware.
//!
//! The window starts at the prior (samples: for example the switch type's window, or one from
//! a capture; at most a tap) and keeps it for the first [`WARM_UP`] events of a kind, widened at
//! once if the switch shows more; after that it is 3/2 of the longest bounce seen (`m + (m - 1)
//! / 2` samples for `m` seen, one sample for none).
//!
//! Every rule is in samples and in the fastest tap: nothing depends on how long a sample is, so
//! the same learner serves a reed (microseconds) and a contactor (a tenth of a second) at the
//! sampling period each needs, with the fastest tap in that period's samples
//! ([`LearnerPrior::at_period`] takes the default, [`FASTEST_TAP_NS`]; a switch no hand
//! operates takes the fastest change it must report). A period change is
//! [`Learned::rescale`]d. Taps faster than the fastest tap it is told are taken for the switch's
//! own bounce, and can be lost: tell it the fastest tap its users make.

use embedded_hal::digital::InputPin;

use crate::debounce::{Edge, Polarity, Windows};
use crate::physics::error::{Error, Parameter, Reason};

/// Events of a kind before its window leaves the prior.
pub const WARM_UP: u8 = 10;

/// The fastest real tap (ns), down or up: 16 taps a second, the known record of a human hand,
/// is 31 ms down and 31 ms up. `docs/human-timing.md` gives the sources.
pub const FASTEST_TAP_NS: u32 = 31_000_000;

/// What a learner starts from, in samples: the prior press and release windows and the
/// fastest real tap.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct LearnerPrior {
    press: u16,
    release: u16,
    fastest_tap: u16,
}

impl LearnerPrior {
    /// Prior windows of `press` and `release` samples, and a fastest tap of `fastest_tap`
    /// samples: a change that lasts that many samples is always reported.
    ///
    /// # Errors
    /// [`Parameter::Time`] with [`Reason::NotPositive`] for a 0, and with
    /// [`Reason::OutOfRange`] above [`Windows::MAX_TICKS`].
    pub const fn new(press: u16, release: u16, fastest_tap: u16) -> Result<Self, Error> {
        if press == 0 || release == 0 || fastest_tap == 0 {
            return Err(Error::new(Parameter::Time, Reason::NotPositive));
        }
        if press > Windows::MAX_TICKS
            || release > Windows::MAX_TICKS
            || fastest_tap > Windows::MAX_TICKS
        {
            return Err(Error::new(Parameter::Time, Reason::OutOfRange));
        }
        Ok(Self {
            press,
            release,
            fastest_tap,
        })
    }

    /// Prior windows of `press` and `release` samples at a sampling period of `period_ns`
    /// nanoseconds, with the default fastest tap ([`FASTEST_TAP_NS`]) in whole samples of that
    /// period (rounded down: a tap of that length is seen for at least that many samples).
    ///
    /// ```
    /// use contact_bounce::LearnerPrior;
    /// let prior = LearnerPrior::at_period(157, 157, 1_000_000)?; // 157 ms at 1 ms samples
    /// assert_eq!(prior.fastest_tap(), 31);
    /// # Ok::<(), contact_bounce::Error>(())
    /// ```
    ///
    /// # Errors
    /// As [`LearnerPrior::new`]; [`Parameter::SamplePeriod`] with [`Reason::NotPositive`] for
    /// a period of 0, and with [`Reason::OutOfRange`] for one longer than the fastest tap or so
    /// short that the tap exceeds [`Windows::MAX_TICKS`] samples.
    pub const fn at_period(press: u16, release: u16, period_ns: u32) -> Result<Self, Error> {
        if period_ns == 0 {
            return Err(Error::new(Parameter::SamplePeriod, Reason::NotPositive));
        }
        let tap = FASTEST_TAP_NS / period_ns;
        // (a `const fn`: `as`, after the range check; `Windows::MAX_TICKS` fits a u32)
        #[allow(clippy::as_conversions)]
        let most = Windows::MAX_TICKS as u32;
        if tap == 0 || tap > most {
            return Err(Error::new(Parameter::SamplePeriod, Reason::OutOfRange));
        }
        #[allow(clippy::cast_possible_truncation, clippy::as_conversions)]
        Self::new(press, release, tap as u16)
    }

    /// From the windows of a [`Windows`] (its mode is not used) and a fastest tap in samples.
    ///
    /// # Errors
    /// As [`LearnerPrior::new`].
    pub const fn from_windows(windows: &Windows, fastest_tap: u16) -> Result<Self, Error> {
        Self::new(windows.press(), windows.release(), fastest_tap)
    }

    /// The press prior (samples).
    #[must_use]
    pub const fn press(&self) -> u16 {
        self.press
    }

    /// The release prior (samples).
    #[must_use]
    pub const fn release(&self) -> u16 {
        self.release
    }

    /// The fastest real tap (samples).
    #[must_use]
    pub const fn fastest_tap(&self) -> u16 {
        self.fastest_tap
    }
}

/// What the learner has seen of one kind (press or release), in samples.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Tail {
    /// Events seen (saturating).
    pub events: u8,
    /// The switch's own reversions of at least half the fastest tap (saturating).
    pub long_reversions: u8,
    /// The longest bounce: from an edge to the end of its last excursion shorter than a tap.
    pub bounce: u16,
    /// The longest of the switch's own reversions: an excursion away from the reported level
    /// that came back in less than the fastest tap.
    pub reversion: u16,
}

/// The window `m` samples of bounce ask for: `m + (m - 1) / 2` (one sample for none), at most
/// [`Windows::MAX_TICKS`]. A bounce seen over `m` samples lasted more than `m - 1` sampling
/// periods (its first and last change each fall anywhere in a sample), so this is at most 3/2
/// of the bounce plus one sample, and never less than what was seen.
pub(crate) const fn grow(m: u16) -> u16 {
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
    /// The window this tail gives with the kind's `prior` and the fastest tap `tap` (samples;
    /// see [`crate::debounce::learn`]): never longer than the tap.
    #[must_use]
    pub const fn window(&self, prior: u16, tap: u16) -> u16 {
        let seen = grow(self.bounce);
        let window = if self.events < WARM_UP {
            max(prior, seen)
        } else {
            seen
        };
        min(window, tap)
    }

    /// The switch has reverted for at least half the fastest tap of `prior`: it will also
    /// revert for as long as a tap, and those reversions are reported as taps (false edges that
    /// no rule on timing alone can tell from real taps).
    #[must_use]
    pub const fn reverts_like_a_tap(&self, prior: &LearnerPrior) -> bool {
        self.long_reversions > 0 && self.reversion.saturating_mul(2) >= prior.fastest_tap
    }

    const fn from_bytes(b: [u8; 6]) -> Self {
        Self {
            events: b[0],
            long_reversions: b[1],
            bounce: u16::from_le_bytes([b[2], b[3]]),
            reversion: u16::from_le_bytes([b[4], b[5]]),
        }
    }

    const fn from_words(counts: u16, bounce: u16, reversion: u16) -> Self {
        let [events, long_reversions] = counts.to_le_bytes();
        Self {
            events,
            long_reversions,
            bounce,
            reversion,
        }
    }

    const fn valid(self) -> bool {
        self.bounce <= Windows::MAX_TICKS && self.reversion <= Windows::MAX_TICKS
    }

    /// A reversion of the switch's own, `lasted` samples, with `tap` the fastest tap.
    pub(crate) fn reverted(&mut self, lasted: u16, tap: u16) {
        self.reversion = max(self.reversion, min(lasted, Windows::MAX_TICKS));
        if lasted.saturating_mul(2) >= tap {
            self.long_reversions = self.long_reversions.saturating_add(1);
        }
    }
}

/// What a learner has learned of a switch: press and release [`Tail`]s. Twelve bytes to save
/// (for example in EEPROM) and restore, so a reboot does not start from the prior.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Learned {
    /// Presses (makes).
    pub press: Tail,
    /// Releases (breaks).
    pub release: Tail,
}

impl Learned {
    /// The saved form: press then release, each events, long reversions, bounce and reversion
    /// (little endian).
    #[must_use]
    pub const fn to_bytes(&self) -> [u8; 12] {
        let (p, r) = (self.press, self.release);
        let (pb, pr, rb, rr) = (
            p.bounce.to_le_bytes(),
            p.reversion.to_le_bytes(),
            r.bounce.to_le_bytes(),
            r.reversion.to_le_bytes(),
        );
        [
            p.events,
            p.long_reversions,
            pb[0],
            pb[1],
            pr[0],
            pr[1],
            r.events,
            r.long_reversions,
            rb[0],
            rb[1],
            rr[0],
            rr[1],
        ]
    }

    /// Restores [`Learned::to_bytes`].
    ///
    /// # Errors
    /// [`Parameter::Time`] with [`Reason::OutOfRange`] when the bytes cannot have been saved by
    /// a learner (a bounce or reversion longer than [`Windows::MAX_TICKS`]): erased or
    /// corrupted storage.
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
            bounce: scale(t.bounce),
            reversion: scale(t.reversion),
            ..t
        };
        Ok(Self {
            press: tail(self.press),
            release: tail(self.release),
        })
    }

    /// The press and release windows with `prior` (samples).
    #[must_use]
    pub const fn windows(&self, prior: &LearnerPrior) -> (u16, u16) {
        (
            self.press.window(prior.press, prior.fastest_tap),
            self.release.window(prior.release, prior.fastest_tap),
        )
    }

    /// Either kind [reverts like a tap](Tail::reverts_like_a_tap).
    #[must_use]
    pub const fn reverts_like_a_tap(&self, prior: &LearnerPrior) -> bool {
        self.press.reverts_like_a_tap(prior) || self.release.reverts_like_a_tap(prior)
    }

    pub(crate) const fn tail(&mut self, press: bool) -> &mut Tail {
        if press {
            &mut self.press
        } else {
            &mut self.release
        }
    }
}

const LEVEL: u8 = 1;
const ACTIVE: u8 = 2;
const EVENT: u8 = 4;

/// One key's learning debouncer state (see [`crate::debounce::learn`]): what it learned and the event in
/// progress. 24 bytes; integer-only per sample.
///
/// ```
/// use contact_bounce::{Edge, LearnerPrior, LearningState};
/// // Prior: 8 samples each way; no real tap is shorter than 12 samples. The press bounces for
/// // 2 samples each time.
/// let prior = LearnerPrior::new(8, 8, 12)?;
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
///
/// Its layout is fixed (`#[repr(C)]`: 24 bytes, aligned as a `u16`, integers only, no padding),
/// so any 24 bytes so aligned are a valid state: a C wrapper can keep one in a `uint16_t[12]`
/// and hand it to Rust as it is, with no copy per sample.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct LearningState {
    learned: Learned,
    /// Samples since the event's edge (saturating; no longer counted once the event is over).
    since: u16,
    /// Samples in a row the contact has read the other level than the reported one.
    run: u16,
    /// This event's bounce so far: when its last excursion shorter than a tap ended.
    bounce: u16,
    /// Samples from the previous edge to this event's.
    previous: u16,
    /// Samples the contact had read this event's level before its edge was reported.
    lead: u16,
    /// LEVEL (reported closed), ACTIVE (the event is still watched), EVENT (an edge has been
    /// reported since the key was settled: there is an event to learn from).
    flags: u8,
    /// No meaning: 0 from a new state (it makes the layout free of padding).
    reserved: u8,
}

const _: () = assert!(
    core::mem::size_of::<LearningState>() == 24
        && core::mem::align_of::<LearningState>() == core::mem::align_of::<u16>()
);

impl LearningState {
    /// A key settled at `closed` (its contact closed or not), with nothing learned.
    #[must_use]
    pub const fn new(closed: bool) -> Self {
        Self::restore(
            closed,
            Learned {
                press: Tail {
                    events: 0,
                    long_reversions: 0,
                    bounce: 0,
                    reversion: 0,
                },
                release: Tail {
                    events: 0,
                    long_reversions: 0,
                    bounce: 0,
                    reversion: 0,
                },
            },
        )
    }

    /// A key settled at `closed` that has learned `learned` (for example restored with
    /// [`Learned::from_bytes`]).
    #[must_use]
    pub const fn restore(closed: bool, learned: Learned) -> Self {
        Self {
            learned,
            since: u16::MAX,
            run: 0,
            bounce: 0,
            previous: u16::MAX,
            lead: u16::MAX,
            flags: if closed { LEVEL } else { 0 },
            reserved: 0,
        }
    }

    /// What it has learned.
    #[must_use]
    pub const fn learned(&self) -> Learned {
        self.learned
    }

    /// The state as twelve 16-bit words, to keep it where a Rust type cannot go (a C struct,
    /// backup RAM): what it learned (each kind: events and long reversions, bounce, reversion),
    /// then the event in progress.
    #[must_use]
    pub const fn to_words(&self) -> [u16; 12] {
        let (p, r) = (self.learned.press, self.learned.release);
        [
            u16::from_le_bytes([p.events, p.long_reversions]),
            p.bounce,
            p.reversion,
            u16::from_le_bytes([r.events, r.long_reversions]),
            r.bounce,
            r.reversion,
            self.since,
            self.run,
            self.bounce,
            self.previous,
            self.lead,
            u16::from_le_bytes([self.flags, self.reserved]),
        ]
    }

    /// The state from [`LearningState::to_words`] (its inverse: every bit is kept). Any words
    /// are a valid state: every field is a saturating counter or a flag (bits other than the
    /// flags' are ignored), and every window is at most the fastest tap, so words not made by
    /// `to_words` cannot make an update fail, panic or lose a change that lasts a tap; at worst
    /// the key starts mid-event. On a little-endian target the words are the state's own memory.
    #[must_use]
    pub const fn from_words(w: [u16; 12]) -> Self {
        Self {
            learned: Learned {
                press: Tail::from_words(w[0], w[1], w[2]),
                release: Tail::from_words(w[3], w[4], w[5]),
            },
            since: w[6],
            run: w[7],
            bounce: w[8],
            previous: w[9],
            lead: w[10],
            flags: w[11].to_le_bytes()[0],
            reserved: w[11].to_le_bytes()[1],
        }
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
        self.learn_event();
        *self = Self::restore(closed, self.learned);
    }

    /// The event in progress (if an edge started one) ends: its bounce is learned.
    const fn learn_event(&mut self) {
        if self.flags & EVENT != 0 {
            let bounce = self.bounce;
            let tail = self.learned.tail(self.flags & LEVEL != 0);
            tail.events = tail.events.saturating_add(1);
            tail.bounce = max(tail.bounce, bounce);
        }
    }

    /// Feeds one sample (`true`: the contact reads closed) with the caller's prior; returns the
    /// edge it debounces, if any.
    // Always inlined: the idle path is the cost of nearly every sample, a few instructions
    // inline (docs/reports/cost-report.md) where a call would cost more than the path.
    #[allow(clippy::inline_always)]
    #[inline(always)]
    pub fn update(&mut self, closed: bool, prior: &LearnerPrior) -> Option<Edge> {
        // The idle path, inlined and read-only: settled, and the sample reads the level.
        if self.flags & ACTIVE == 0 && closed == self.is_closed() {
            return None;
        }
        self.watch(closed, *prior)
    }

    /// [`LearningState::update`] while an event is watched or an edge starts.
    #[inline(never)]
    fn watch(&mut self, closed: bool, prior: LearnerPrior) -> Option<Edge> {
        let level = self.is_closed();
        let active = self.flags & ACTIVE != 0;
        if active {
            self.since = self.since.saturating_add(1);
        }
        if closed == level {
            if self.run > 0 {
                // The contact came back in less than a tap: an excursion of the switch's own.
                let tap = prior.fastest_tap;
                self.learned.tail(level).reverted(self.run, tap);
                self.bounce = max(self.bounce, min(self.since, tap));
                self.run = 0;
            }
            if active && self.since > prior.fastest_tap {
                // Watched to its end: the idle path takes over.
                self.flags &= !ACTIVE;
            }
            return None;
        }
        self.run = self.run.saturating_add(1);
        // The event's window: what was learned of its kind changes only when an edge is
        // reported, so it is the window set at this event's edge.
        // (Only this kind's: the other's window is not needed.)
        let window = if level {
            self.learned.press.window(prior.press, prior.fastest_tap)
        } else {
            self.learned
                .release
                .window(prior.release, prior.fastest_tap)
        };
        if active && self.since < window && self.run < prior.fastest_tap {
            return None;
        }
        Some(self.report(closed, prior))
    }

    /// Reports the edge to `closed` and ends the event before it.
    fn report(&mut self, closed: bool, prior: LearnerPrior) -> Edge {
        let tap = prior.fastest_tap;
        // The event's level lasted from `lead` samples before its edge until this change began
        // (`run - 1` samples ago).
        let lasted = self
            .lead
            .saturating_add(self.since.saturating_sub(self.run.saturating_sub(1)));
        if self.flags & ACTIVE != 0 && lasted < tap && self.previous < tap {
            // Back in less than a tap, and that edge came less than a tap after the one before:
            // it was the switch's, a reversion in the event before it (whose kind this edge's
            // is), which bounced until now. (A level that began a tap or more after the edge
            // before may be a real tap whose bounce hid its first samples: it is taken as one.)
            let end = self
                .previous
                .saturating_add(self.since.saturating_sub(self.run.saturating_sub(1)));
            let before = self.learned.tail(closed);
            before.reverted(lasted, tap);
            before.bounce = max(before.bounce, min(end, tap));
        } else {
            // A real edge's event ends here.
            self.learn_event();
        }
        // The new event's window (read from what was learned, in `watch`) runs from this report.
        // An edge reported late (its change began inside the window before) can hold a real
        // tap's next change back by as much: late, never lost.
        self.previous = self.since;
        self.lead = self.run.saturating_sub(1);
        self.since = 0;
        self.run = 0;
        self.bounce = 0;
        self.flags = ACTIVE | EVENT | if closed { LEVEL } else { 0 };
        if closed {
            Edge::Press
        } else {
            Edge::Release
        }
    }
}

/// A debounced contact on an [`InputPin`] that learns its own switch's bounce (see
/// [`crate::debounce::learn`]), sampled by the caller at a period of its choosing.
///
/// ```
/// use contact_bounce::{Edge, LearnerPrior, LearningDebouncer, debounce::Polarity};
/// use embedded_hal_mock::eh1::digital::{Mock, State as Level, Transaction};
/// let levels = [Level::High, Level::Low, Level::High, Level::Low, Level::Low];
/// let mut pin = Mock::new(&levels.map(|l| Transaction::get(l)));
/// let prior = LearnerPrior::new(3, 3, 10)?;
/// let mut button = LearningDebouncer::new(pin.clone(), prior, Polarity::ActiveLow).unwrap();
/// let edges: Vec<_> = (0..4).map(|_| button.update().unwrap()).collect();
/// assert_eq!(edges, [Some(Edge::Press), None, None, None]);
/// pin.done();
/// # Ok::<(), contact_bounce::Error>(())
/// ```
#[derive(Debug)]
pub struct LearningDebouncer<P> {
    pin: P,
    prior: LearnerPrior,
    polarity: Polarity,
    state: LearningState,
}

impl<P: InputPin> LearningDebouncer<P> {
    /// Reads the pin once to start settled at its level, with nothing learned.
    ///
    /// # Errors
    /// The pin's error.
    pub fn new(pin: P, prior: LearnerPrior, polarity: Polarity) -> Result<Self, P::Error> {
        Self::restore(pin, prior, polarity, Learned::default())
    }

    /// As [`LearningDebouncer::new`], with what an earlier run learned.
    ///
    /// # Errors
    /// The pin's error.
    pub fn restore(
        mut pin: P,
        prior: LearnerPrior,
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

    /// The switch reverts for as long as a tap (see [`Tail::reverts_like_a_tap`]).
    #[must_use]
    pub const fn reverts_like_a_tap(&self) -> bool {
        self.state.learned().reverts_like_a_tap(&self.prior)
    }

    /// Gives the pin back.
    pub fn free(self) -> P {
        self.pin
    }
}

/// Whether the contact on `pin` reads closed (shared with [`crate::debounce::wait`]).
pub(crate) fn read<P: InputPin>(pin: &mut P, polarity: Polarity) -> Result<bool, P::Error> {
    match polarity {
        Polarity::ActiveLow => pin.is_low(),
        Polarity::ActiveHigh => pin.is_high(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn prior(ticks: u16, tap: u16) -> LearnerPrior {
        LearnerPrior::new(ticks, ticks, tap).unwrap_or_else(|_| unreachable!())
    }

    /// Feeds `samples`; the edges reported, with the sample index of each (at most 8: a test
    /// that sees more fails).
    fn feed(
        key: &mut LearningState,
        p: LearnerPrior,
        samples: &[bool],
    ) -> heapless::Vec<(usize, Edge), 8> {
        let mut out = heapless::Vec::new();
        for (i, &s) in samples.iter().enumerate() {
            if let Some(e) = key.update(s, &p) {
                assert!(out.push((i, e)).is_ok(), "more than 8 edges");
            }
        }
        out
    }

    /// One press of `bounce` (then closed) held `hold` samples, and a clean release held
    /// `hold` samples; the count of press and release edges reported.
    fn cycle(key: &mut LearningState, p: LearnerPrior, bounce: &[bool], hold: usize) -> [usize; 2] {
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
    fn a_prior_is_checked() {
        let time = |r| Err(Error::new(Parameter::Time, r));
        assert_eq!(LearnerPrior::new(0, 5, 31), time(Reason::NotPositive));
        assert_eq!(LearnerPrior::new(5, 5, 0), time(Reason::NotPositive));
        assert_eq!(
            LearnerPrior::new(Windows::MAX_TICKS + 1, 5, 31),
            time(Reason::OutOfRange)
        );
        assert_eq!(
            LearnerPrior::new(5, 5, Windows::MAX_TICKS + 1),
            time(Reason::OutOfRange)
        );
        let period = |r| Err(Error::new(Parameter::SamplePeriod, r));
        assert_eq!(
            LearnerPrior::at_period(5, 5, 0),
            period(Reason::NotPositive)
        );
        // Longer than a tap, and so short that a tap is more samples than the counter holds.
        assert_eq!(
            LearnerPrior::at_period(5, 5, 40_000_000),
            period(Reason::OutOfRange)
        );
        assert_eq!(
            LearnerPrior::at_period(5, 5, 100),
            period(Reason::OutOfRange)
        );
        // 0.1 ms samples: 310 samples a tap.
        assert_eq!(
            LearnerPrior::at_period(1570, 1570, 100_000).map(|p| p.fastest_tap()),
            Ok(310)
        );
    }

    #[test]
    fn it_keeps_the_prior_while_warming_up_then_tightens_to_what_it_saw() {
        let p = prior(50, 60);
        let mut key = LearningState::new(false);
        // Bounce: closed, open, open, closed, open, closed (back for good at sample 5).
        let bounce = [true, false, false, true, false, true];
        for n in 1..=12_u8 {
            assert_eq!(cycle(&mut key, p, &bounce, 80), [1, 1]);
            let (press, release) = key.learned().windows(&p);
            // (an event is learned when the next edge ends it: a press at its release, a
            // release at the next press, one cycle later)
            // 5 samples of bounce: 5 + (5 - 1) / 2.
            let want_press = if n < WARM_UP { 50 } else { 7 };
            let want_release = if n <= WARM_UP { 50 } else { 1 };
            assert_eq!((press, release), (want_press, want_release), "event {n}");
        }
        assert_eq!(key.learned().press.bounce, 5);
        // Two flights of 1 and 2 samples: no reversion like a tap.
        assert_eq!(key.learned().press.reversion, 2);
        assert!(!key.learned().reverts_like_a_tap(&p));
    }

    #[test]
    fn a_window_is_never_longer_than_the_fastest_tap_whatever_the_prior() {
        let p = prior(157, 31);
        let key = LearningState::new(false);
        assert_eq!(key.learned().windows(&p), (31, 31));
        // A switch that bounces for 100 samples: the window stays at the tap, and a change
        // that lasts a tap is reported.
        let restored = Learned {
            press: Tail {
                events: 50,
                long_reversions: 0,
                bounce: 100,
                reversion: 3,
            },
            release: Tail {
                events: 50,
                ..Tail::default()
            },
        };
        assert_eq!(restored.windows(&p), (31, 1));
    }

    #[test]
    fn ten_thousand_clean_taps_at_16_a_second_keep_every_tap_and_grow_no_window() {
        // 1 ms samples, the hand-operated prior before its cap (157 ms), the default fastest tap (31
        // samples). Taps at 16 a second: 62.5 ms a tap, down 31 or 32 samples and up the rest.
        let p = LearnerPrior::at_period(157, 157, 1_000_000).unwrap_or_else(|_| unreachable!());
        let mut key = LearningState::new(false);
        for _ in 0..500 {
            assert_eq!(key.update(false, &p), None);
        }
        let (mut presses, mut releases) = (0, 0);
        for tap in 0..10_000_u32 {
            let down = if tap % 2 == 0 { 31 } else { 32 };
            let up = if tap % 2 == 0 { 32 } else { 31 };
            for _ in 0..down {
                presses += usize::from(key.update(true, &p) == Some(Edge::Press));
            }
            for _ in 0..up {
                releases += usize::from(key.update(false, &p) == Some(Edge::Release));
            }
        }
        assert_eq!((presses, releases), (10_000, 10_000));
        let (press, release) = key.learned().windows(&p);
        assert!(press <= p.fastest_tap() && release <= p.fastest_tap());
        // A clean switch: one sample each.
        assert_eq!((press, release), (1, 1));
    }

    #[test]
    fn a_real_tap_inside_a_window_is_reported_and_never_makes_it_grow() {
        // A window of 20 samples (prior) and a fastest tap of 20: a release 5 samples after
        // the press that stays open 20 samples is reported when the window ends, at sample 20;
        // the press after it, at 25, falls in the release's window (from 20) and is reported
        // when that ends, at 40: late, not lost.
        let p = prior(20, 20);
        let mut key = LearningState::new(false);
        let mut samples = [true; 60];
        for s in samples.iter_mut().take(25).skip(5) {
            *s = false;
        }
        let edges = feed(&mut key, p, &samples);
        assert_eq!(
            edges,
            [(0, Edge::Press), (20, Edge::Release), (40, Edge::Press)]
        );
        // The release lasted a tap: nothing of it counts as bounce.
        assert_eq!(key.learned().press.bounce, 0);
        assert_eq!(key.learned().press.reversion, 0);
    }

    #[test]
    fn a_short_reversion_after_the_window_widens_it_and_a_late_glitch_does_not() {
        let p = prior(4, 31);
        let mut key = LearningState::new(false);
        let plain = [true, false, true];
        for _ in 0..WARM_UP {
            cycle(&mut key, p, &plain, 200);
        }
        assert_eq!(key.learned().windows(&p).0, 2);
        // Open for 12 samples at sample 10: after the 2-sample window, two false edges (the
        // press part shows three edges); it came back in less than a tap, within a tap of the
        // press: the switch's own. The press window grows to cover its end (sample 22):
        // 22 + 21 / 2 = 32, at most the tap.
        let mut late = [true; 60];
        for s in late.iter_mut().take(22).skip(10) {
            *s = false;
        }
        late[1] = false;
        assert_eq!(cycle(&mut key, p, &late, 200), [3, 1]);
        assert_eq!(key.learned().press.bounce, 22);
        assert_eq!(key.learned().press.reversion, 12);
        assert_eq!(key.learned().press.long_reversions, 0);
        assert_eq!(key.learned().windows(&p).0, 31);
        // Covered from then on: no false edge.
        assert_eq!(cycle(&mut key, p, &late, 200), [1, 1]);
        // A glitch of 2 samples half a second into a hold: two false edges, and no window grows.
        let mut glitch = [true; 600];
        glitch[500] = false;
        glitch[501] = false;
        let before = key.learned().windows(&p);
        assert_eq!(cycle(&mut key, p, &glitch, 100), [3, 1]);
        assert_eq!(key.learned().windows(&p), before);
    }

    #[test]
    fn a_switch_that_reverts_like_a_tap_says_so() {
        // Reversions of 20 samples where the fastest tap is 31: more than half a tap.
        let p = prior(40, 31);
        let mut key = LearningState::new(false);
        let mut press = [true; 30];
        for s in press.iter_mut().take(22).skip(2) {
            *s = false;
        }
        for _ in 0..3 {
            // Inside the window: swallowed, and counted.
            assert_eq!(cycle(&mut key, p, &press, 100), [1, 1]);
        }
        let learned = key.learned();
        assert_eq!(learned.press.reversion, 20);
        assert_eq!(learned.press.long_reversions, 3);
        assert!(learned.press.reverts_like_a_tap(&p));
        assert!(learned.reverts_like_a_tap(&p));
        assert!(!learned.release.reverts_like_a_tap(&p));
    }

    #[test]
    fn the_same_rules_hold_in_samples_at_any_period() {
        // The warm-up test's switch and taps at ten times the samples, with ten times the tap:
        // the same decisions, ten times the windows (to rounding).
        for scale in [1_usize, 10] {
            let tap = u16::try_from(31 * scale).unwrap_or(u16::MAX);
            let p = prior(u16::try_from(157 * scale).unwrap_or(u16::MAX), tap);
            let mut key = LearningState::new(false);
            let mut press = [true; 400];
            for s in press.iter_mut().take(4 * scale).skip(scale) {
                *s = false;
            }
            for _ in 0..12 {
                let bounce = press.get(..40 * scale).unwrap_or(&[]);
                assert_eq!(cycle(&mut key, p, bounce, 40 * scale), [1, 1]);
            }
            assert_eq!(
                key.learned().press.bounce,
                u16::try_from(4 * scale).unwrap_or(0)
            );
        }
    }

    #[test]
    fn what_it_learned_is_saved_restored_and_rescaled() {
        let learned = Learned {
            press: Tail {
                events: 12,
                long_reversions: 3,
                bounce: 7,
                reversion: 300,
            },
            release: Tail {
                events: 11,
                long_reversions: 0,
                bounce: 2,
                reversion: 0,
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
        assert_eq!((fast.press.bounce, fast.press.reversion), (14, 600));
        let slow = learned.rescale(1, 3).unwrap_or_else(|_| unreachable!());
        assert_eq!((slow.press.bounce, slow.release.bounce), (3, 1));
        let huge = learned
            .rescale(u16::MAX, 1)
            .unwrap_or_else(|_| unreachable!());
        assert_eq!(huge.press.reversion, Windows::MAX_TICKS);
        assert!(learned.rescale(0, 1).is_err() && learned.rescale(1, 0).is_err());
        let restored = LearningState::restore(true, learned);
        assert!(restored.is_closed() && restored.is_settled());
        assert_eq!(restored.learned(), learned);
    }

    #[test]
    fn a_stuck_pin_and_noise_faster_than_the_samples_are_defined() {
        let p = prior(Windows::MAX_TICKS, Windows::MAX_TICKS);
        // Stuck: no edge ever.
        let mut key = LearningState::new(false);
        for _ in 0..100_000 {
            assert_eq!(key.update(false, &p), None);
        }
        // Noise: a change at every sample for longer than the counters hold. One edge, the
        // window stays within the tap.
        let mut key = LearningState::new(false);
        let mut edges = 0;
        for i in 0..200_000_u32 {
            edges += usize::from(key.update(i % 2 == 0, &p).is_some());
        }
        assert!(edges >= 1);
        let (press, release) = key.learned().windows(&p);
        assert!(press <= p.fastest_tap() && release <= p.fastest_tap());
    }

    #[test]
    fn the_state_round_trips_through_words_and_any_words_are_a_state() {
        let p = prior(31, 31);
        let mut key = LearningState::new(false);
        let mut press = [true; 40];
        press[2] = false;
        for _ in 0..3 {
            cycle(&mut key, p, &press, 50);
        }
        // Mid-event too.
        key.update(true, &p);
        assert_eq!(LearningState::from_words(key.to_words()), key);
        // Arbitrary words: updates never panic, and a level held a tap is reported.
        let mut x: u32 = 0x9E37_79B9;
        for _ in 0..2000 {
            let mut w = [0_u16; 12];
            for word in &mut w {
                x ^= x << 13;
                x ^= x >> 17;
                x ^= x << 5;
                *word = x.to_le_bytes()[0].into();
                *word |= u16::from(x.to_le_bytes()[1]) << 8;
            }
            let mut key = LearningState::from_words(w);
            assert_eq!(key.to_words(), w);
            let target = !key.is_closed();
            for _ in 0..p.fastest_tap() {
                key.update(target, &p);
            }
            assert_eq!(key.is_closed(), target, "{w:?}");
        }
    }

    #[test]
    fn a_key_is_a_few_bytes() {
        assert_eq!(core::mem::size_of::<LearningState>(), 24);
        assert_eq!(core::mem::size_of::<Learned>(), 12);
        assert_eq!(core::mem::size_of::<LearnerPrior>(), 6);
    }
}
