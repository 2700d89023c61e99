// The keyboard matrix's share of measure/cost_matrix.rs: a 100-key matrix (10 rows of 10
// columns, u16 rows) scanned 500 times while typed on (a tap every 50 scans on another key, held
// 30 scans, its press bouncing open at scans 1 and 3 and its release closing again at 1), then
// 500 idle scans; through our `LearningMatrix`, debouncr (one 5-sample `Debouncer` per key, 1
// byte each) and a QMK-like `sym_eager_pk` (below), each offering its events to the same kind of
// `heapless::Vec`, and through the scan loop alone (subtracted by the report): `run_matrix`.

use contact_bounce::debounce::matrix::{KeyEvent, LearningMatrix};
use contact_bounce::{Edge, LearnerPrior};
use core::hint::black_box;

pub const ROWS: usize = 10;
pub const COLS: usize = 10;
pub const SCANS: u32 = 500;
type Events = heapless::Vec<KeyEvent, 8>;

/// Scan `n` of the typing: the rows read.
#[inline(always)]
fn typed(n: u32) -> [u16; ROWS] {
    let mut rows = [0u16; ROWS];
    let (tap, at) = (n / 50, n % 50);
    let key = (tap * 37 % 100) as usize;
    if (at < 30 && at != 1 && at != 3) || at == 31 {
        if let Some(r) = rows.get_mut(key / COLS) {
            *r = 1 << (key % COLS);
        }
    }
    rows
}

/// QMK's `sym_eager_pk` as its source describes it: a countdown byte per key and the debounced
/// rows; a changed key whose countdown has run out is reported at once and starts its countdown
/// (5 scans at 1 ms scans); while any countdown runs, every key's is counted down each scan.
pub struct QmkEager {
    cooked: [u16; ROWS],
    counters: [[u8; COLS]; ROWS],
    counting: bool,
}

impl QmkEager {
    pub const fn new() -> Self {
        Self {
            cooked: [0; ROWS],
            counters: [[0; COLS]; ROWS],
            counting: false,
        }
    }

    #[inline(always)]
    pub fn scan(&mut self, raw: &[u16; ROWS], events: &mut Events) {
        if self.counting {
            self.counting = false;
            for row in &mut self.counters {
                for c in row.iter_mut() {
                    if *c > 0 {
                        *c -= 1;
                        self.counting |= *c > 0;
                    }
                }
            }
        }
        for (r, ((cooked, counters), &raw)) in self
            .cooked
            .iter_mut()
            .zip(&mut self.counters)
            .zip(raw)
            .enumerate()
        {
            let delta = raw ^ *cooked;
            if delta == 0 {
                continue;
            }
            for (c, counter) in counters.iter_mut().enumerate() {
                let bit = 1u16 << c;
                if delta & bit != 0 && *counter == 0 {
                    *cooked ^= bit;
                    *counter = 5;
                    self.counting = true;
                    let edge = if *cooked & bit != 0 {
                        Edge::Press
                    } else {
                        Edge::Release
                    };
                    let _ = events.push(KeyEvent {
                        row: r as u8,
                        col: c as u8,
                        edge,
                    });
                }
            }
        }
    }
}

/// debouncr's per-key debouncer over the matrix.
#[inline(always)]
fn debouncr_scan(
    keys: &mut [[debouncr::Debouncer<u8, debouncr::Repeat5>; COLS]; ROWS],
    raw: &[u16; ROWS],
    events: &mut Events,
) {
    for (r, (row, &raw)) in keys.iter_mut().zip(raw).enumerate() {
        for (c, key) in row.iter_mut().enumerate() {
            if let Some(e) = key.update(raw & (1 << c) != 0) {
                let edge = if e == debouncr::Edge::Rising {
                    Edge::Press
                } else {
                    Edge::Release
                };
                let _ = events.push(KeyEvent {
                    row: r as u8,
                    col: c as u8,
                    edge,
                });
            }
        }
    }
}

#[inline(always)]
fn pass(mark: &impl Fn(u8), at: u8, input: impl Fn(u32) -> [u16; ROWS]) {
    // Ours.
    if let Ok(prior) = LearnerPrior::new(black_box(31), black_box(31), black_box(31)) {
        if let Ok(mut m) = LearningMatrix::<u16, ROWS, COLS>::new(prior) {
            mark(at);
            for n in 0..black_box(SCANS) {
                let mut events = Events::new();
                let _ = black_box(m.scan(&input(n), &mut events));
                black_box(&events);
            }
            black_box(&m);
        }
    }
    mark(at + 1);
    let mut keys: [[debouncr::Debouncer<u8, debouncr::Repeat5>; COLS]; ROWS] =
        core::array::from_fn(|_| core::array::from_fn(|_| debouncr::debounce_5(false)));
    for n in 0..black_box(SCANS) {
        let mut events = Events::new();
        debouncr_scan(&mut keys, &input(n), &mut events);
        black_box(&events);
    }
    black_box(&keys);
    mark(at + 2);
    let mut qmk = QmkEager::new();
    for n in 0..black_box(SCANS) {
        let mut events = Events::new();
        qmk.scan(&input(n), &mut events);
        black_box(&events);
    }
    black_box(&qmk.cooked);
    mark(at + 3);
    // The loop alone: the scans without a debouncer.
    for n in 0..black_box(SCANS) {
        let events = Events::new();
        black_box(&input(n));
        black_box(&events);
    }
    mark(at + 4);
}

/// Typing, then idle: marks `first` .. `first + 9`. Between consecutive marks: ours, debouncr,
/// QMK-like and the loop typing; our idle matrix's setup; then the same four idle.
#[inline(always)]
pub fn run_matrix(mark: impl Fn(u8), first: u8) {
    pass(&mark, first, |n| typed(black_box(n)));
    pass(&mark, first + 5, |n| {
        black_box([black_box(n) as u16 & 0; ROWS])
    });
}
