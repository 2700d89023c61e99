//! A debouncer on a physics window: integer-only per sample, 2 bytes of state per pin.
//!
//! The window comes from a prediction ([`Window::from_prediction`]) or from the compile-time
//! [`crate::debounce::window::window_ticks`], in samples of a period the caller chooses (never assumed here).
//! Press (make) and release (break) windows are separate: release bounce differs.
//!
//! Two ways to use a window:
//! - [`Mode::Confirm`]: report a change once the pin has held the new level for the whole
//!   window. The edge comes one window after the last bounce (to within a sample), and a
//!   window shorter than the bounce is still safe unless the contact rests at the new level
//!   that long mid-bounce.
//! - [`Mode::HoldOff`]: report the first change at once (one sample of latency), then ignore
//!   the pin for the window. Safe only if the window covers the whole bounce: that is what the
//!   physics prediction is for. A guessed window shorter than the bounce reports false edges.

use embedded_hal::digital::InputPin;

use crate::debounce::window::Window;
use crate::physics::error::{Error, Parameter, Reason};

/// A debounced change of the contact (ordered: a press before a release).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum Edge {
    /// The contact closed (make).
    Press,
    /// The contact opened (break).
    Release,
}

/// Which pin level means the contact is closed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum Polarity {
    /// Closed pulls the pin low (a pull-up and a switch to ground: the usual wiring).
    ActiveLow,
    /// Closed drives the pin high.
    ActiveHigh,
}

/// How a window is used (see [`crate::debounce`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum Mode {
    /// Report after the new level held for the window.
    Confirm,
    /// Report at once, then ignore the pin for the window.
    HoldOff,
}

/// Press and release windows in samples, and the mode: configuration shared by every pin of
/// one kind of switch.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Windows {
    press: u16,
    release: u16,
    mode: Mode,
}

impl Windows {
    /// The longest window in samples (the state keeps a 15-bit counter).
    pub const MAX_TICKS: u16 = 0x7FFF;

    /// Windows of `press` and `release` samples (at most [`Windows::MAX_TICKS`]).
    ///
    /// # Errors
    /// [`Parameter::Time`] with [`Reason::OutOfRange`] above [`Windows::MAX_TICKS`].
    pub const fn new(press: u16, release: u16, mode: Mode) -> Result<Self, Error> {
        if press > Self::MAX_TICKS || release > Self::MAX_TICKS {
            return Err(Error::new(Parameter::Time, Reason::OutOfRange));
        }
        Ok(Self {
            press,
            release,
            mode,
        })
    }

    /// From two [`Window`]s (see [`Window::from_prediction`]).
    ///
    /// # Errors
    /// [`Parameter::Time`] with [`Reason::OutOfRange`] when a window exceeds
    /// [`Windows::MAX_TICKS`] samples: sample less often.
    pub fn from_windows(press: Window, release: Window, mode: Mode) -> Result<Self, Error> {
        let narrow = |w: Window| {
            u16::try_from(w.ticks()).map_err(|_| Error::new(Parameter::Time, Reason::OutOfRange))
        };
        Self::new(narrow(press)?, narrow(release)?, mode)
    }

    /// The press window (samples).
    #[must_use]
    pub const fn press(&self) -> u16 {
        self.press
    }
    /// The release window (samples).
    #[must_use]
    pub const fn release(&self) -> u16 {
        self.release
    }
    /// The mode.
    #[must_use]
    pub const fn mode(&self) -> Mode {
        self.mode
    }
}

/// A pin's debounce state: 2 bytes (the debounced level in the top bit, a 15-bit counter).
///
/// ```
/// use contact_bounce::{Edge, Mode, State, Windows};
/// let windows = Windows::new(3, 3, Mode::Confirm)?;
/// let mut state = State::new(false);
/// // Bouncing: closed, open, closed... then closed for 3 samples.
/// let samples = [true, false, true, true, false, true, true, true];
/// let edges: Vec<_> = samples.iter().map(|&s| state.update(s, &windows)).collect();
/// assert_eq!(edges.iter().flatten().collect::<Vec<_>>(), [&Edge::Press]);
/// assert_eq!(edges[7], Some(Edge::Press));
/// assert!(state.is_closed());
/// assert_eq!(core::mem::size_of::<State>(), 2);
/// # Ok::<(), contact_bounce::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct State(u16);

const CLOSED: u16 = 0x8000;
const COUNT: u16 = 0x7FFF;

impl State {
    /// A pin whose contact is (`true`) or is not closed, settled.
    #[must_use]
    pub const fn new(closed: bool) -> Self {
        Self(if closed { CLOSED } else { 0 })
    }

    /// The debounced contact: closed or open.
    #[must_use]
    pub const fn is_closed(&self) -> bool {
        self.0 & CLOSED != 0
    }

    /// No change is in progress: no window is counting (confirm: the contact last read the
    /// debounced level; hold-off: the window after the last edge has run out), so a sample at
    /// the debounced level changes nothing.
    #[must_use]
    pub const fn is_settled(&self) -> bool {
        self.0 & COUNT == 0
    }

    /// The state as 16 bits, to keep it where a Rust type cannot go (a C struct, backup RAM).
    #[must_use]
    pub const fn to_bits(self) -> u16 {
        self.0
    }

    /// The state from [`State::to_bits`]. Every `u16` is a valid state: the top bit is the
    /// debounced level and the rest a counter that `update` only counts down or resets, so
    /// bits not made by `to_bits` cannot make it fail, only start mid-window.
    #[must_use]
    pub const fn from_bits(bits: u16) -> Self {
        Self(bits)
    }

    /// Feeds one sample (`true`: the contact reads closed); returns the edge it debounces, if
    /// any. A handful of integer operations; no failure.
    pub fn update(&mut self, closed: bool, windows: &Windows) -> Option<Edge> {
        let stable = self.is_closed();
        // The edge and its window are chosen only once a change is seen: almost every sample
        // agrees with a settled contact (a key is idle far longer than it bounces).
        let change = |stable: bool| {
            if stable {
                (Edge::Release, windows.release)
            } else {
                (Edge::Press, windows.press)
            }
        };
        match windows.mode {
            Mode::Confirm => {
                if closed == stable {
                    self.0 &= CLOSED;
                    return None;
                }
                let (edge, window) = change(stable);
                let count = (self.0 & COUNT) + 1; // <= MAX_TICKS + 1: no overflow of the 15 bits
                if count >= window {
                    self.0 = if closed { CLOSED } else { 0 };
                    Some(edge)
                } else {
                    self.0 = (self.0 & CLOSED) | count;
                    None
                }
            }
            Mode::HoldOff => {
                if self.0 & COUNT > 0 {
                    self.0 -= 1;
                    return None;
                }
                if closed == stable {
                    return None;
                }
                let (edge, window) = change(stable);
                // The window that follows this edge: the bounce of the change just seen.
                self.0 = (if closed { CLOSED } else { 0 }) | window.min(COUNT);
                Some(edge)
            }
        }
    }
}

/// A debounced contact on an [`InputPin`], sampled by the caller at a period of its choosing
/// (the windows are in those samples).
///
/// ```
/// use contact_bounce::{Debouncer, Edge, Mode, debounce::Polarity, Windows};
/// use embedded_hal_mock::eh1::digital::{Mock, State as Level, Transaction};
/// // An active-low button: reads high (open), then bounces low/high, then stays low.
/// let levels = [Level::High, Level::Low, Level::High, Level::Low, Level::Low, Level::Low];
/// let mut pin = Mock::new(&levels.map(|l| Transaction::get(l)));
/// let windows = Windows::new(3, 3, Mode::Confirm)?;
/// let mut button = Debouncer::new(pin.clone(), windows, Polarity::ActiveLow).unwrap();
/// let mut edges = Vec::new();
/// for _ in 0..5 {
///     edges.push(button.update().unwrap());
/// }
/// assert_eq!(edges, [None, None, None, None, Some(Edge::Press)]);
/// assert!(button.is_low() && button.is_closed());
/// pin.done();
/// # Ok::<(), contact_bounce::Error>(())
/// ```
#[derive(Debug)]
pub struct Debouncer<P> {
    pin: P,
    windows: Windows,
    polarity: Polarity,
    state: State,
}

impl<P: InputPin> Debouncer<P> {
    /// Reads the pin once to start settled at its level.
    ///
    /// # Errors
    /// The pin's error.
    pub fn new(mut pin: P, windows: Windows, polarity: Polarity) -> Result<Self, P::Error> {
        let closed = Self::read(&mut pin, polarity)?;
        Ok(Self {
            pin,
            windows,
            polarity,
            state: State::new(closed),
        })
    }

    fn read(pin: &mut P, polarity: Polarity) -> Result<bool, P::Error> {
        match polarity {
            Polarity::ActiveLow => pin.is_low(),
            Polarity::ActiveHigh => pin.is_high(),
        }
    }

    /// Samples the pin once; returns the debounced edge, if any.
    ///
    /// # Errors
    /// The pin's error (the state is unchanged).
    pub fn update(&mut self) -> Result<Option<Edge>, P::Error> {
        let closed = Self::read(&mut self.pin, self.polarity)?;
        Ok(self.state.update(closed, &self.windows))
    }

    /// The debounced contact is closed.
    #[must_use]
    pub const fn is_closed(&self) -> bool {
        self.state.is_closed()
    }

    /// The debounced pin level is high.
    #[must_use]
    pub fn is_high(&self) -> bool {
        self.state.is_closed() == (self.polarity == Polarity::ActiveHigh)
    }

    /// The debounced pin level is low.
    #[must_use]
    pub fn is_low(&self) -> bool {
        !self.is_high()
    }

    /// The state (2 bytes), e.g. to keep many pins' states in an array.
    #[must_use]
    pub const fn state(&self) -> State {
        self.state
    }

    /// Gives the pin back.
    pub fn free(self) -> P {
        self.pin
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn run(windows: Windows, samples: &[bool]) -> (State, [Option<Edge>; 32]) {
        let mut state = State::new(false);
        let mut out = [None; 32];
        for (slot, &s) in out.iter_mut().zip(samples) {
            *slot = state.update(s, &windows);
        }
        (state, out)
    }

    #[test]
    fn confirm_needs_the_whole_window() {
        let w = Windows::new(4, 2, Mode::Confirm).unwrap_or_else(|_| unreachable!());
        let samples = [
            true, true, true, false, true, true, true, true, false, true, false, false,
        ];
        let (state, edges) = run(w, &samples);
        // Press at the 4th consecutive closed sample (index 7), release after 2 open (11).
        assert_eq!(edges[7], Some(Edge::Press));
        assert_eq!(edges[11], Some(Edge::Release));
        assert_eq!(edges.iter().flatten().count(), 2);
        assert!(!state.is_closed());
    }

    #[test]
    fn hold_off_reports_at_once_then_ignores_the_window() {
        let w = Windows::new(3, 2, Mode::HoldOff).unwrap_or_else(|_| unreachable!());
        // Press at 0; samples 1..=3 ignored (the bounce); at 4 the pin reads open: a release.
        let samples = [true, false, true, false, false, false, false];
        let (_, edges) = run(w, &samples);
        assert_eq!(edges[0], Some(Edge::Press));
        assert_eq!(edges[1..4], [None, None, None]);
        assert_eq!(edges[4], Some(Edge::Release));
        // A window covering the bounce sees nothing false.
        let w = Windows::new(4, 2, Mode::HoldOff).unwrap_or_else(|_| unreachable!());
        let (state, edges) = run(w, &[true, false, true, false, true, true, true]);
        assert_eq!(edges.iter().flatten().count(), 1);
        assert!(state.is_closed());
    }

    #[test]
    fn windows_are_checked() {
        assert!(Windows::new(Windows::MAX_TICKS, 0, Mode::Confirm).is_ok());
        assert_eq!(
            Windows::new(Windows::MAX_TICKS + 1, 0, Mode::Confirm),
            Err(Error::new(Parameter::Time, Reason::OutOfRange))
        );
        let big = Window::from_ticks(40_000);
        assert!(Windows::from_windows(big, Window::from_ticks(1), Mode::HoldOff).is_err());
    }

    #[test]
    fn state_is_two_bytes() {
        assert_eq!(core::mem::size_of::<State>(), 2);
        assert!(core::mem::size_of::<Windows>() <= 6);
    }
}
