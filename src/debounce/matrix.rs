//! A keyboard matrix debouncer that learns once for all its keys: [`LearningMatrix`].
//!
//! Every key of a matrix is the same switch, so what one key shows of its bounce holds for the
//! others: the matrix keeps one model of the switch (what [`crate::debounce::learn`]'s learner keeps per
//! key: a [`Learned`], the [`LearnerPrior`] and the two windows, 20 bytes) and, per key, one byte
//! and three bits. It converges in the first [`MATRIX_WARM_UP`] (20) edges of any keys, not of
//! each key.
//!
//! The rules are the learner's (see [`crate::debounce::learn`]), with the event's details a key cannot
//! keep in a byte given up:
//! - **Every change that lasts a tap is reported, and the first change of an edge at once.** A
//!   key reports its first change (from the scan it is seen in) and then looks at its contact
//!   again after its window, never longer than the fastest tap. A change that began inside the
//!   window is reported when the window ends.
//! - **The shared windows grow only from what a finger cannot do.** Inside a window, the last
//!   scan the contact read the other level ends the bounce seen so far: the model's longest
//!   bounce of that kind grows to it at once. The windows keep the prior (or more, if the switch
//!   shows more) for the first [`MATRIX_WARM_UP`] edges reported, of any keys and either kind;
//!   after, each is 3/2 of the longest bounce of its kind seen plus at most one scan.
//! - **A key whose bounce outgrows the shared model widens its own window.** An edge that came
//!   less than a tap after the one before and is undone in less than a tap is the switch's own
//!   reversion (two false edges: no real tap is that short). While the model warms up, and
//!   when the reversion lasted no longer than its kind's window, it is the switch type's: the
//!   shared model grows to cover it (from the window, where it began at the earliest). A
//!   reversion longer than the type's whole window is the key's alone: that key is widened to
//!   the fastest tap (one bit), its bounce no longer feeds the model, and [`Scan::widened`] says so
//!   ([`LearningMatrix::is_widened`], [`LearningMatrix::widened`]). One worn key thus costs the
//!   other keys nothing.
//!
//! Input: one scan as row bitmaps (bit `c` of row `r` set: the key at row `r`, column `c` reads
//! closed), in `u8`, `u16` or `u32` ([`Row`]), scanned at a steady period (the fastest tap is in
//! scans: at most [`MAX_TAP`]). Output: [`KeyEvent`]s offered to an [`EventSink`]: a
//! [`heapless::Vec`] of fixed capacity, or any closure, for example one that enqueues into a
//! `heapless::spsc::Queue` from a scan interrupt to the main loop. A full sink delays a key's
//! edge to a later scan ([`Scan::deferred`]); it never loses one.
//!
//! Memory: `COLS`-bit rows of three bitmaps (level, event in progress, widened) and a byte per
//! key (scans since the key's last edge, and whether that edge came less than a tap after the
//! one before). A 10 x 10 matrix in `u16` rows is 180 bytes (`size_of`, tested): 1.6 bytes a key
//! and the 20-byte model.

use crate::debounce::learn::{grow, Learned, LearnerPrior, Tail, WARM_UP};
use crate::debounce::Edge;
use crate::physics::error::{Error, Parameter, Reason};

/// The longest fastest tap a matrix takes (scans): a key counts its scans in seven bits. At a
/// 1 ms scan the default tap is 31 scans; a matrix scanned more often than every 0.25 ms can
/// give the learner every second or fourth scan.
pub const MAX_TAP: u16 = 126;

/// Edges of any keys and either kind before the shared windows leave the prior: twice the single
/// learner's [`WARM_UP`], so about as many of each kind.
#[allow(clippy::as_conversions)] // (`u16::from` is not `const`)
pub const MATRIX_WARM_UP: u16 = 2 * WARM_UP as u16;

mod sealed {
    pub trait Sealed {}
    impl Sealed for u8 {}
    impl Sealed for u16 {}
    impl Sealed for u32 {}
}

/// A row of the matrix as a bitmap: `u8`, `u16` or `u32` (columns at most its bits).
pub trait Row: sealed::Sealed + Copy + Default + Into<u32> {
    /// Its bits: the most columns a row can have.
    const BITS: u32;
    /// The low bits of `bits`.
    fn truncate(bits: u32) -> Self;
}

impl Row for u8 {
    const BITS: u32 = u8::BITS;
    fn truncate(bits: u32) -> Self {
        bits.to_le_bytes()[0]
    }
}

impl Row for u16 {
    const BITS: u32 = u16::BITS;
    fn truncate(bits: u32) -> Self {
        let [a, b, _, _] = bits.to_le_bytes();
        u16::from_le_bytes([a, b])
    }
}

impl Row for u32 {
    const BITS: u32 = u32::BITS;
    fn truncate(bits: u32) -> Self {
        bits
    }
}

/// A debounced change of one key.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct KeyEvent {
    /// Its row.
    pub row: u8,
    /// Its column.
    pub col: u8,
    /// Pressed or released.
    pub edge: Edge,
}

/// Where a scan puts its events: a [`heapless::Vec`], or a closure that takes an event or hands
/// it back when it has no room (for example `|e| producer.enqueue(e)` on a
/// `heapless::spsc::Producer`).
pub trait EventSink {
    /// Takes `event`, or gives it back when full.
    fn offer(&mut self, event: KeyEvent) -> Result<(), KeyEvent>;
}

impl<const N: usize> EventSink for heapless::Vec<KeyEvent, N> {
    fn offer(&mut self, event: KeyEvent) -> Result<(), KeyEvent> {
        self.push(event)
    }
}

impl<F: FnMut(KeyEvent) -> Result<(), KeyEvent>> EventSink for F {
    fn offer(&mut self, event: KeyEvent) -> Result<(), KeyEvent> {
        self(event)
    }
}

/// What a scan did beyond its events.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[must_use = "a full sink delays edges: `deferred` says how many keys wait for room"]
pub struct Scan {
    /// Keys whose edge the sink had no room for: each is reported by a later scan (its
    /// state did not move), late by the scans it waited.
    pub deferred: u16,
    /// Keys widened by this scan: their bounce outgrew the shared model.
    pub widened: u16,
}

/// The model every key shares: 20 bytes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct Model {
    learned: Learned,
    prior: LearnerPrior,
    /// The press and release windows (scans), kept current with `learned`.
    press: u8,
    release: u8,
}

impl Model {
    fn new(prior: LearnerPrior, learned: Learned) -> Self {
        let mut m = Self {
            learned,
            prior,
            press: 0,
            release: 0,
        };
        m.refresh();
        m
    }

    /// Fewer than [`MATRIX_WARM_UP`] events have been reported: the windows keep the prior.
    fn warming_up(&self) -> bool {
        u16::from(self.learned.press.events) + u16::from(self.learned.release.events)
            < MATRIX_WARM_UP
    }

    fn refresh(&mut self) {
        let tap = self.prior.fastest_tap();
        let warming_up = self.warming_up();
        let window = |tail: &Tail, prior: u16| {
            let seen = grow(tail.bounce);
            let w = if warming_up { seen.max(prior) } else { seen };
            // At most the fastest tap, at most `MAX_TAP` (checked in `new`): a byte.
            w.min(tap).to_le_bytes()[0]
        };
        self.press = window(&self.learned.press, self.prior.press());
        self.release = window(&self.learned.release, self.prior.release());
    }

    const fn window(&self, press: bool) -> u16 {
        // (`u16::from` is not `const`)
        let w = if press { self.press } else { self.release };
        u16::from_le_bytes([w, 0])
    }

    fn tail(&mut self, press: bool) -> &mut Tail {
        self.learned.tail(press)
    }

    /// Bounce of kind `press` seen to `end` scans after its edge.
    fn bounce(&mut self, press: bool, end: u16) {
        let tail = self.tail(press);
        if end > tail.bounce {
            tail.bounce = end;
            self.refresh();
        }
    }

    /// An edge of kind `press` was reported.
    fn event(&mut self, press: bool) {
        let tail = self.tail(press);
        tail.events = tail.events.saturating_add(1);
        if !self.warming_up() {
            self.refresh();
        }
    }
}

/// A row's bitmaps.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
struct Bits<B> {
    /// The reported level (set: closed).
    level: B,
    /// An event is in progress: the key is inside a tap of its last edge.
    active: B,
    /// The key's own window is the fastest tap.
    widened: B,
}

/// The byte of a key: scans since its last edge (7 bits, saturating) ...
const SINCE: u8 = 0x7F;
/// ... and whether that edge came less than a tap after the one before.
const QUICK: u8 = 0x80;

/// A matrix of `ROWS` x `COLS` keys of one switch type that learns its switch once for all its
/// keys (see [`crate::debounce::matrix`]).
///
/// ```
/// use contact_bounce::debounce::matrix::{KeyEvent, LearningMatrix};
/// use contact_bounce::{Edge, LearnerPrior};
/// // 1 ms scans: a 10-scan prior window, 31-scan fastest tap.
/// let prior = LearnerPrior::new(10, 10, 31)?;
/// let mut keys = LearningMatrix::<u16, 4, 12>::new(prior)?;
/// let mut events = heapless::Vec::<KeyEvent, 8>::new();
/// // Row 2, column 5 closes, bounces open on the next scan, and stays closed.
/// for row2 in [1 << 5, 0, 1 << 5, 1 << 5] {
///     let scan = keys.scan(&[0, 0, row2, 0], &mut events);
///     assert_eq!(scan.deferred, 0);
/// }
/// assert_eq!(events, [KeyEvent { row: 2, col: 5, edge: Edge::Press }]);
/// # Ok::<(), contact_bounce::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct LearningMatrix<B: Row, const ROWS: usize, const COLS: usize> {
    model: Model,
    rows: [Bits<B>; ROWS],
    keys: [[u8; COLS]; ROWS],
}

impl<B: Row, const ROWS: usize, const COLS: usize> LearningMatrix<B, ROWS, COLS> {
    /// Every key settled open, nothing learned.
    ///
    /// # Errors
    /// [`Parameter::Time`] with [`Reason::OutOfRange`] for a fastest tap above [`MAX_TAP`].
    /// (More columns than `B` has bits, or more than 256 rows, do not compile.)
    pub fn new(prior: LearnerPrior) -> Result<Self, Error> {
        Self::restore(prior, Learned::default(), [B::default(); ROWS])
    }

    /// Every key settled open, with what a matrix of this switch learned ([`Self::learned`],
    /// saved for example with [`Learned::to_bytes`]) and its widened keys ([`Self::widened`]; bits
    /// beyond the columns are ignored).
    ///
    /// # Errors
    /// As [`LearningMatrix::new`].
    pub fn restore(
        prior: LearnerPrior,
        learned: Learned,
        widened: [B; ROWS],
    ) -> Result<Self, Error> {
        #[allow(clippy::as_conversions, clippy::cast_possible_truncation)] // `COLS` <= 32 first
        const {
            assert!(
                COLS <= 32 && COLS as u32 <= B::BITS,
                "more columns than the row type has bits"
            );
            assert!(ROWS <= 256, "more than 256 rows");
        }
        if prior.fastest_tap() > MAX_TAP {
            return Err(Error::new(Parameter::Time, Reason::OutOfRange));
        }
        let mut rows = [Bits::default(); ROWS];
        for (bits, w) in rows.iter_mut().zip(widened) {
            bits.widened = B::truncate(w.into() & Self::COLUMNS);
        }
        Ok(Self {
            model: Model::new(prior, learned),
            rows,
            keys: [[0; COLS]; ROWS],
        })
    }

    /// The columns' bits.
    const COLUMNS: u32 = if COLS >= 32 {
        u32::MAX
    } else {
        (1 << COLS) - 1
    };

    /// Settles every key at the level `rows` reads, reporting nothing and keeping what was
    /// learned (at start-up, with keys held down, or after a sleep without scans).
    pub fn settle(&mut self, rows: &[B; ROWS]) {
        for (bits, &raw) in self.rows.iter_mut().zip(rows) {
            bits.level = B::truncate(raw.into() & Self::COLUMNS);
            bits.active = B::default();
        }
    }

    /// Feeds one scan; offers each debounced change to `events`, in row then column order.
    pub fn scan(&mut self, rows: &[B; ROWS], events: &mut impl EventSink) -> Scan {
        let mut out = Scan::default();
        for (r, ((bits, keys), &raw)) in self
            .rows
            .iter_mut()
            .zip(&mut self.keys)
            .zip(rows)
            .enumerate()
        {
            let raw = raw.into() & Self::COLUMNS;
            // The fast path of nearly every row: no key changed, none in an event.
            if (raw ^ bits.level.into()) | bits.active.into() == 0 {
                continue;
            }
            // `r` < 256 (checked when built).
            let row = r.to_le_bytes()[0];
            scan_row(&mut self.model, bits, keys, row, raw, events, &mut out);
        }
        out
    }

    /// The key at `row`, `col` is reported closed (`false` outside the matrix).
    pub fn is_closed(&self, row: usize, col: usize) -> bool {
        self.bit(row, col, |b| b.level)
    }

    /// The key at `row`, `col` has its own window (`false` outside the matrix).
    pub fn is_widened(&self, row: usize, col: usize) -> bool {
        self.bit(row, col, |b| b.widened)
    }

    fn bit(&self, row: usize, col: usize, of: impl Fn(&Bits<B>) -> B) -> bool {
        col < COLS
            && self
                .rows
                .get(row)
                .is_some_and(|b| (of(b).into() >> col) & 1 != 0)
    }

    /// The widened keys, as row bitmaps (to save, and to give back to [`Self::restore`]).
    pub fn widened(&self) -> [B; ROWS] {
        self.rows.map(|b| b.widened)
    }

    /// What the matrix has learned of its switch (to save).
    pub const fn learned(&self) -> Learned {
        self.model.learned
    }

    /// The prior it started from.
    pub const fn prior(&self) -> LearnerPrior {
        self.model.prior
    }

    /// The shared press and release windows (scans); a widened key's are the fastest tap.
    pub const fn windows(&self) -> (u16, u16) {
        (self.model.window(true), self.model.window(false))
    }

    /// The switch reverts for as long as a tap (see [`Tail::reverts_like_a_tap`]).
    pub const fn reverts_like_a_tap(&self) -> bool {
        self.model.learned.reverts_like_a_tap(&self.model.prior)
    }
}

/// One row with a change or an event in progress (apart: the fast path stays small).
#[inline(never)]
fn scan_row<B: Row>(
    model: &mut Model,
    bits: &mut Bits<B>,
    keys: &mut [u8],
    row: u8,
    raw: u32,
    events: &mut impl EventSink,
    out: &mut Scan,
) {
    let (mut level, mut active, mut widened) =
        (bits.level.into(), bits.active.into(), bits.widened.into());
    let tap = model.prior.fastest_tap();
    // Only the keys that changed or are in an event (`raw` has no bits beyond the columns).
    let mut work = (raw ^ level) | active;
    while work != 0 {
        let c = work.trailing_zeros();
        let bit = 1u32 << c;
        work &= !bit;
        // `c` < `COLS` (no bits beyond the columns), so `key` is always there.
        let Some(key) = keys.get_mut(usize::from(c.to_le_bytes()[0])) else {
            break;
        };
        let other = (raw ^ level) & bit != 0;
        let is_active = active & bit != 0;
        // The key's level: closed, its event (if any) is a press.
        let press = level & bit != 0;
        let edge = KeyEvent {
            row,
            col: c.to_le_bytes()[0],
            edge: if press { Edge::Release } else { Edge::Press },
        };
        if !is_active {
            // Settled, and the contact changed: reported at once.
            if events.offer(edge).is_err() {
                out.deferred = out.deferred.saturating_add(1);
                continue;
            }
            level ^= bit;
            active |= bit;
            *key = 0;
            model.event(!press);
            continue;
        }
        let since = u16::from(*key & SINCE) + 1;
        let quick = *key & QUICK;
        let own = widened & bit != 0;
        let window = if own { tap } else { model.window(press) };
        if !other {
            if since > tap {
                // Watched for a tap: the key is settled.
                active &= !bit;
            }
            *key = since.min(u16::from(SINCE)).to_le_bytes()[0] | quick;
            continue;
        }
        if since < window {
            // Bounce inside the window: the contact will be back no sooner than the next scan.
            if !own {
                model.bounce(press, since + 1);
            }
            *key = since.to_le_bytes()[0] | quick;
            continue;
        }
        if events.offer(edge).is_err() {
            out.deferred = out.deferred.saturating_add(1);
            continue;
        }
        let back = !press;
        if quick != 0 && since < tap {
            // This event lasted less than a tap and its edge came less than a tap after the
            // one before: a reversion of the switch's own in that event (of kind `back`).
            if !own {
                model.tail(back).reverted(since, tap);
                let window = model.window(back);
                if model.warming_up() || since <= window {
                    // Warming up, or no longer than the window: the switch type's own, and the
                    // model grows to cover it (it began at least a window after the edge).
                    model.bounce(back, window.saturating_add(since).min(tap));
                } else {
                    // Away for longer than the type's whole window: this key alone.
                    widened |= bit;
                    out.widened = out.widened.saturating_add(1);
                }
            }
        } else {
            model.event(back);
        }
        level ^= bit;
        *key = if since < tap { QUICK } else { 0 };
    }
    bits.level = B::truncate(level);
    bits.active = B::truncate(active);
    bits.widened = B::truncate(widened);
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;
    use std::vec::Vec as StdVec;

    type Vec8 = heapless::Vec<KeyEvent, 8>;

    fn prior(window: u16, tap: u16) -> LearnerPrior {
        LearnerPrior::new(window, window, tap).unwrap_or_else(|_| unreachable!())
    }

    fn ev(row: u8, col: u8, edge: Edge) -> KeyEvent {
        KeyEvent { row, col, edge }
    }

    /// Feeds `scans` (each as rows), collecting every event; panics on a deferred one.
    fn feed<const R: usize, const C: usize>(
        m: &mut LearningMatrix<u16, R, C>,
        scans: impl IntoIterator<Item = [u16; R]>,
    ) -> StdVec<(usize, KeyEvent)> {
        let mut all = StdVec::new();
        for (i, rows) in scans.into_iter().enumerate() {
            let mut events = Vec8::new();
            let scan = m.scan(&rows, &mut events);
            assert_eq!(scan.deferred, 0);
            all.extend(events.iter().map(|&e| (i, e)));
        }
        all
    }

    /// `n` scans of one key (`row`, `col`) following `levels`, the others open.
    fn key<const R: usize>(
        row: usize,
        col: u32,
        levels: &[bool],
    ) -> impl Iterator<Item = [u16; R]> + '_ {
        levels.iter().map(move |&l| {
            let mut rows = [0; R];
            if let Some(r) = rows.get_mut(row) {
                *r = if l { 1 << col } else { 0 };
            }
            rows
        })
    }

    /// A press bouncing open for scans 1..=`bounce` (closed at 0), held `hold` scans, then a
    /// clean release held `hold` scans.
    fn tap(bounce: usize, hold: usize) -> StdVec<bool> {
        let mut v: StdVec<bool> = (0..hold).map(|i| i == 0 || i > bounce).collect();
        v.extend(core::iter::repeat_n(false, hold));
        v
    }

    #[test]
    fn a_hundred_keys_take_at_most_two_bytes_each_and_a_32_byte_model() {
        assert_eq!(core::mem::size_of::<Model>(), 20);
        let size = core::mem::size_of::<LearningMatrix<u16, 10, 10>>();
        assert_eq!(size, 20 + 3 * 2 * 10 + 100);
        assert!(size - core::mem::size_of::<Model>() <= 2 * 100);
        // A full-size keyboard's 6 x 18 in u32 rows: 108 keys.
        let size = core::mem::size_of::<LearningMatrix<u32, 6, 18>>();
        assert_eq!(size, 20 + 3 * 4 * 6 + 108);
        assert!(size - 20 <= 2 * 108);
    }

    #[test]
    fn a_fastest_tap_beyond_seven_bits_is_refused() {
        let refused = Err(Error::new(Parameter::Time, Reason::OutOfRange));
        assert_eq!(
            LearningMatrix::<u8, 2, 8>::new(prior(10, MAX_TAP + 1)),
            refused
        );
        assert!(LearningMatrix::<u8, 2, 8>::new(prior(10, MAX_TAP)).is_ok());
    }

    #[test]
    fn an_edge_is_reported_at_once_and_the_bounce_in_its_window_is_not() {
        let mut m =
            LearningMatrix::<u16, 3, 5>::new(prior(10, 31)).unwrap_or_else(|_| unreachable!());
        // Closed at 0, open at 1-3, closed from 4; released at 40, bouncing closed at 41.
        let mut levels: StdVec<bool> = (0..40).map(|i| !(1..=3).contains(&i)).collect();
        levels.extend((0..40).map(|i| i == 1));
        let got = feed(&mut m, key::<3>(1, 4, &levels));
        assert_eq!(
            got,
            [(0, ev(1, 4, Edge::Press)), (40, ev(1, 4, Edge::Release))]
        );
        // The press bounced until scan 4 (its window's bounce), the release until 2.
        assert_eq!(m.learned().press.bounce, 4);
        assert_eq!(m.learned().release.bounce, 2);
        assert_eq!(m.learned().press.events, 1);
        // Still warming up: the prior's windows.
        assert_eq!(m.windows(), (10, 10));
        assert!(!m.is_closed(1, 4) && !m.is_closed(9, 9) && !m.is_closed(1, 5));
    }

    #[test]
    fn the_shared_windows_are_learned_from_the_first_20_edges_of_any_keys() {
        let mut m =
            LearningMatrix::<u16, 4, 4>::new(prior(20, 31)).unwrap_or_else(|_| unreachable!());
        // Ten keys tapped once each, each press bouncing for 2 scans.
        for k in 0..10u32 {
            let row = usize::try_from(k / 4).unwrap_or(usize::MAX);
            let got = feed(&mut m, key::<4>(row, k % 4, &tap(2, 40)));
            assert_eq!(got.len(), 2, "key {k}: {got:?}");
        }
        // Press bounce 3 (back at scan 3): 3 + 1 = 4 scans; releases clean: 1 scan.
        assert_eq!(m.learned().press.events, WARM_UP);
        assert_eq!(m.windows(), (4, 1));
        // Clean taps at the fastest tap keep every edge, and the windows.
        let mut fast = StdVec::new();
        for _ in 0..20 {
            fast.extend(core::iter::repeat_n(true, 31));
            fast.extend(core::iter::repeat_n(false, 31));
        }
        let got = feed(&mut m, key::<4>(3, 3, &fast));
        assert_eq!(got.len(), 40);
        assert!(got.iter().enumerate().all(|(i, (at, e))| *at == 31 * i
            && e.edge
                == if i % 2 == 0 {
                    Edge::Press
                } else {
                    Edge::Release
                }));
        assert_eq!(m.windows(), (4, 1));
    }

    #[test]
    fn a_key_whose_bounce_outgrows_the_model_widens_its_own_window() {
        let mut m =
            LearningMatrix::<u16, 2, 8>::new(prior(3, 31)).unwrap_or_else(|_| unreachable!());
        for k in 0..10u32 {
            let _ = feed(&mut m, key::<2>(0, k % 8, &tap(1, 40)));
        }
        // Back at scan 2: 2 + (2 - 1) / 2 = 2 scans.
        assert_eq!(m.windows(), (2, 1));
        // Key (1, 2) reopens at 8-11 scans after its press: past the window, back in less than
        // a tap. Two false edges, and the key is widened.
        let mut worn: StdVec<bool> = (0..40).map(|i| !(8..12).contains(&i)).collect();
        worn.extend(core::iter::repeat_n(false, 40));
        let mut widened = 0;
        let mut edges = 0;
        for rows in key::<2>(1, 2, &worn) {
            let mut events = Vec8::new();
            let scan = m.scan(&rows, &mut events);
            widened += scan.widened;
            edges += events.len();
        }
        assert_eq!((edges, widened), (4, 1));
        assert!(m.is_widened(1, 2) && !m.is_widened(0, 2));
        assert_eq!(m.widened(), [0, 1 << 2]);
        // The model did not take the worn key's bounce.
        assert_eq!(m.windows(), (2, 1));
        // The same press again: the key's own window (the tap) covers it.
        let got = feed(&mut m, key::<2>(1, 2, &worn));
        assert_eq!(
            got,
            [(0, ev(1, 2, Edge::Press)), (40, ev(1, 2, Edge::Release))]
        );
        // Restored from what was saved, the key is still widened.
        let saved = LearningMatrix::<u16, 2, 8>::restore(m.prior(), m.learned(), m.widened());
        let saved = saved.unwrap_or_else(|_| unreachable!());
        assert_eq!(saved.windows(), m.windows());
        assert!(saved.is_widened(1, 2));
    }

    #[test]
    fn while_warming_up_a_late_reversion_grows_the_shared_window() {
        let mut m =
            LearningMatrix::<u16, 1, 8>::new(prior(3, 31)).unwrap_or_else(|_| unreachable!());
        let mut worn: StdVec<bool> = (0..40).map(|i| !(8..12).contains(&i)).collect();
        worn.extend(core::iter::repeat_n(false, 40));
        let got = feed(&mut m, key::<1>(0, 0, &worn));
        assert_eq!(got.len(), 4);
        // Reopened at 8 (at least the window, 3, after the press) for 4 scans: 3 + 4 = 7.
        assert_eq!(m.learned().press.bounce, 7);
        assert_eq!(m.learned().press.reversion, 4);
        assert!(!m.is_widened(0, 0));
        let got = feed(&mut m, key::<1>(0, 1, &worn));
        // 7 + 3 = 10 scans of window: the reopening at 8-11 is inside it, and seen there (back
        // at 12): 12 + 11 / 2 = 17.
        assert_eq!(m.windows().0, 17);
        assert_eq!(
            got,
            [(0, ev(0, 1, Edge::Press)), (40, ev(0, 1, Edge::Release))]
        );
    }

    #[test]
    fn a_full_sink_delays_an_edge_and_never_loses_it() {
        let mut m =
            LearningMatrix::<u8, 2, 8>::new(prior(5, 31)).unwrap_or_else(|_| unreachable!());
        let mut small = heapless::Vec::<KeyEvent, 1>::new();
        // Two keys close in the same scan: room for one.
        let scan = m.scan(&[0b11, 0], &mut small);
        assert_eq!(
            scan,
            Scan {
                deferred: 1,
                widened: 0
            }
        );
        assert_eq!(small, [ev(0, 0, Edge::Press)]);
        small.clear();
        let scan = m.scan(&[0b11, 0], &mut small);
        assert_eq!(scan.deferred, 0);
        assert_eq!(small, [ev(0, 1, Edge::Press)]);
        // A closure as the sink.
        let mut seen = 0;
        let scan = m.scan(&[0, 0b1000_0000], &mut |e: KeyEvent| {
            seen += 1;
            assert_eq!(e, ev(1, 7, Edge::Press));
            Ok(())
        });
        assert_eq!((scan.deferred, seen), (0, 1));
    }

    #[test]
    fn events_pass_through_an_spsc_queue_from_the_scan_to_the_main_loop() {
        // Room for 3 events (heapless's queue of 4 keeps one slot free).
        let mut queue = heapless::spsc::Queue::<KeyEvent, 4>::new();
        let (mut producer, mut consumer) = queue.split();
        let mut m =
            LearningMatrix::<u32, 2, 20>::new(prior(5, 31)).unwrap_or_else(|_| unreachable!());
        let mut got = StdVec::new();
        // Four keys close in one scan: the fourth waits for room, and the main loop (which
        // empties the queue between scans) gets it from the next scan.
        let mut deferred = StdVec::new();
        for n in 0..40 {
            let rows = if n < 20 {
                [1 << 19 | 1, 1 << 3 | 1 << 4]
            } else {
                [1 << 19, 1 << 3 | 1 << 4]
            };
            deferred.push(m.scan(&rows, &mut |e| producer.enqueue(e)).deferred);
            got.extend(core::iter::from_fn(|| consumer.dequeue()).map(|e| (n, e)));
        }
        assert_eq!(deferred.get(..2), Some(&[1, 0][..]));
        assert_eq!(
            got,
            [
                (0, ev(0, 0, Edge::Press)),
                (0, ev(0, 19, Edge::Press)),
                (0, ev(1, 3, Edge::Press)),
                (1, ev(1, 4, Edge::Press)),
                (20, ev(0, 0, Edge::Release)),
            ]
        );
    }

    #[test]
    fn bits_beyond_the_columns_are_not_keys() {
        let mut m =
            LearningMatrix::<u8, 1, 3>::new(prior(5, 31)).unwrap_or_else(|_| unreachable!());
        let mut events = Vec8::new();
        let _ = m.scan(&[0b1111_1000], &mut events);
        assert!(events.is_empty());
        m.settle(&[0b1111_1111]);
        assert!(m.is_closed(0, 2) && !m.is_closed(0, 3));
        let _ = m.scan(&[0b1111_1111], &mut events);
        assert!(events.is_empty());
    }
}
