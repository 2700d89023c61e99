//! The debouncer on bounce traces of the exact reference (the switches of docs/physics.md sec. 7,
//! sampled at several periods and phases), with windows from the core's prediction widened by
//! its expected error: no false edge, and in Confirm mode the edge comes one window after the
//! last bounce, to within a sampling period.

use contact_bounce::{scene::catalogue, Method, Mode, Tolerance};
use host_tests::reference::OneBody;
use host_tests::traces::{debounce, windows, Dwell, Trace};

fn scenes() -> Vec<(&'static str, OneBody, f64)> {
    catalogue::ALL
        .iter()
        .map(|s| {
            let reference = OneBody::typical(s);
            let scene = s.scene::<f64>().expect("catalogue scenes are valid");
            let p = scene.predict(Method::Auto(Tolerance::new(0.1).expect("valid")));
            let window =
                p.bounce_time().expect("finite") * (1.0 + p.expected_error.expect("promised"));
            (s.name, reference, window)
        })
        .collect()
}

#[test]
fn physics_windows_give_no_false_edge_and_a_window_of_latency() {
    let mut checked = 0;
    for (name, reference, window) in scenes() {
        for dwell in [Dwell::None, Dwell::FractionOfFlight(0.1)] {
            let trace = Trace::press(&reference, dwell).expect("trace");
            // Periods from a twentieth of the window to the window itself.
            for divisions in [20.0, 5.0, 1.0] {
                let period = window / divisions;
                for phase in [0.0, 0.37, 0.71] {
                    for mode in [Mode::Confirm, Mode::HoldOff] {
                        let w = windows(window, period, mode);
                        let out = debounce(&trace, period, phase * period, w);
                        assert_eq!(
                            out.false_edges, 0,
                            "{name} {dwell:?} {mode:?} period {period}: {:?}",
                            out.edges
                        );
                        if mode == Mode::Confirm {
                            let full = f64::from(w.press()) * period;
                            assert!(
                                out.settle <= full + 1e-12 * full,
                                "{name} {dwell:?}: settle {} > window {full}",
                                out.settle
                            );
                            if dwell == Dwell::None {
                                assert!(
                                    out.settle >= full - period - 1e-12 * full,
                                    "{name}: settle {} < window {full} - period",
                                    out.settle
                                );
                            }
                        } else {
                            // Hold-off settles within a period of the end of the bounce.
                            assert!(
                                out.settle <= period * (1.0 + 1e-9),
                                "{name} {dwell:?}: hold-off settles late: {}",
                                out.settle
                            );
                        }
                        checked += 1;
                    }
                }
            }
        }
    }
    assert_eq!(checked, 8 * 2 * 3 * 3 * 2);
}

#[test]
fn a_hold_off_window_shorter_than_the_bounce_reports_false_edges() {
    // The large contactor bounces ~0.1 s: a guessed 5 ms hold-off, sampled every 0.1 ms, sees
    // the contact reopen after its window and reports false edges (with conducting impacts).
    let (_, reference, window) = scenes().pop().expect("eight switches");
    let trace = Trace::press(&reference, Dwell::FractionOfFlight(0.1)).expect("trace");
    assert!(window > 0.05, "{window}");
    let period = 1e-4;
    let guessed = debounce(&trace, period, 0.0, windows(5e-3, period, Mode::HoldOff));
    assert!(guessed.false_edges > 0, "{:?}", guessed.edges);
    let physics = debounce(&trace, period, 0.0, windows(window, period, Mode::HoldOff));
    assert_eq!(physics.false_edges, 0);
}
