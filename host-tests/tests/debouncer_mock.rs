//! The embedded-hal debouncer against mocked pins: polarity, both modes, both edges, and pin
//! errors passed through without touching the state.

use contact_bounce::{debounce::Polarity, Debouncer, Edge, Mode, Windows};
use embedded_hal::digital::ErrorKind;
use embedded_hal_mock::eh1::digital::{Mock, State as Level, Transaction};
use embedded_hal_mock::eh1::MockError;

fn windows(press: u16, release: u16, mode: Mode) -> Windows {
    Windows::new(press, release, mode).expect("in range")
}

#[test]
fn active_high_press_and_release_with_separate_windows() {
    use Level::{High, Low};
    // Starts low (open); press confirmed after 2 high samples, release after 4 low ones.
    let levels = [Low, High, Low, High, High, Low, High, Low, Low, Low, Low];
    let expectations: Vec<Transaction> = levels.iter().map(|&l| Transaction::get(l)).collect();
    let mut pin = Mock::new(&expectations);
    let mut button = Debouncer::new(
        pin.clone(),
        windows(2, 4, Mode::Confirm),
        Polarity::ActiveHigh,
    )
    .expect("pin");
    assert!(button.is_low() && !button.is_closed());
    let edges: Vec<Option<Edge>> = (1..levels.len())
        .map(|_| button.update().expect("pin"))
        .collect();
    assert_eq!(
        edges,
        [
            None,
            None,
            None,
            Some(Edge::Press),
            None,
            None,
            None,
            None,
            None,
            Some(Edge::Release)
        ]
    );
    assert!(button.is_low());
    pin.done();
}

#[test]
fn hold_off_reports_the_first_change_and_ignores_the_bounce() {
    use Level::{High, Low};
    // Active low: the first low sample is a press; the bounce inside the 3-sample window is
    // ignored; then a clean release.
    let levels = [High, Low, High, Low, High, Low, Low, High, High];
    let expectations: Vec<Transaction> = levels.iter().map(|&l| Transaction::get(l)).collect();
    let mut pin = Mock::new(&expectations);
    let mut button = Debouncer::new(
        pin.clone(),
        windows(3, 1, Mode::HoldOff),
        Polarity::ActiveLow,
    )
    .expect("pin");
    let edges: Vec<Option<Edge>> = (1..levels.len())
        .map(|_| button.update().expect("pin"))
        .collect();
    assert_eq!(
        edges,
        [
            Some(Edge::Press),
            None,
            None,
            None,
            None,
            None,
            Some(Edge::Release),
            None
        ]
    );
    pin.done();
}

#[test]
fn pin_errors_pass_through_and_leave_the_state_alone() {
    let expectations = [
        Transaction::get(Level::High),
        Transaction::get(Level::Low).with_error(MockError::Io(std::io::ErrorKind::Other)),
        Transaction::get(Level::Low),
    ];
    let mut pin = Mock::new(&expectations);
    let mut button = Debouncer::new(
        pin.clone(),
        windows(1, 1, Mode::Confirm),
        Polarity::ActiveLow,
    )
    .expect("pin");
    let before = button.state();
    let err = button.update().expect_err("the mock fails");
    assert_eq!(embedded_hal::digital::Error::kind(&err), ErrorKind::Other);
    assert_eq!(button.state(), before);
    assert_eq!(button.update().expect("pin"), Some(Edge::Press));
    let _ = button.free();
    pin.done();
}

#[test]
fn the_learning_debouncer_passes_pin_errors_through_and_restores_what_it_learned() {
    use contact_bounce::{debounce::learn::Learned, debounce::learn::Tail, LearningDebouncer};
    let expectations = [
        Transaction::get(Level::High),
        Transaction::get(Level::Low).with_error(MockError::Io(std::io::ErrorKind::Other)),
        Transaction::get(Level::Low),
        Transaction::get(Level::High),
    ];
    let mut pin = Mock::new(&expectations);
    // Restored with 12 presses learned at 4 samples of bounce: a press window of 4 + 3 / 2.
    let learned = Learned {
        press: Tail {
            events: 12,
            long_reversions: 0,
            bounce: 4,
            reversion: 1,
        },
        release: Tail::default(),
    };
    let prior = contact_bounce::LearnerPrior::new(50, 50, 60).expect("in range");
    let mut button =
        LearningDebouncer::restore(pin.clone(), prior, Polarity::ActiveLow, learned).expect("pin");
    assert_eq!(button.windows(), (5, 50));
    let before = button.learned();
    let err = button.update().expect_err("the mock fails");
    assert_eq!(embedded_hal::digital::Error::kind(&err), ErrorKind::Other);
    assert_eq!(button.learned(), before);
    assert!(!button.is_closed());
    // The failed sample is skipped: the next reads the press at once, the bounce after it is
    // inside the window.
    assert_eq!(button.update().expect("pin"), Some(Edge::Press));
    assert_eq!(button.update().expect("pin"), None);
    assert!(button.is_closed());
    let _ = button.free();
    pin.done();
}
