//! The learning debouncer on bounce traces of the exact reference: the catalogue's switches,
//! pressed and released again and again, sampled at several periods and phases, with Newton
//! impacts and with a dwell at each impact. From a prior of ten times the bounce it reports
//! no false edge, and after its warm-up its press window is at most 3/2 of the bounce plus one
//! sample, and covers the bounce where the samples resolve it.

use contact_bounce::{debounce::learn::WARM_UP, scene::catalogue, LearnerPrior, LearningState};
use host_tests::reference::OneBody;
use host_tests::traces::{Dwell, Trace};

#[test]
fn the_learner_has_no_false_edge_and_learns_the_bounce_of_every_catalogue_switch() {
    let mut checked = 0;
    for s in &catalogue::ALL {
        for dwell in [
            Dwell::None,
            Dwell::FractionOfFlight(0.1),
            Dwell::FractionOfFlight(0.5),
        ] {
            let trace = Trace::press(&OneBody::typical(s), dwell).expect("trace");
            let bounce = trace.end;
            for divisions in [20.0, 5.0, 1.0] {
                let period = bounce / divisions;
                #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
                let prior = (10.0 * divisions).ceil() as u16;
                // (a machine's switch, not a finger's: the fastest change to report is the
                // prior's length)
                let prior = LearnerPrior::new(prior, prior, prior).expect("in range");
                let mut key = LearningState::new(false);
                // Hold each level for the prior's length and more: no quick taps.
                let hold = 3.0 * f64::from(prior.press()) * period;
                for press in 0..30_u32 {
                    // A phase that moves from press to press (golden ratio).
                    let phase = (f64::from(press + 1) * 0.618_033_988_749_895).fract() * period;
                    let mut edges = Vec::new();
                    let mut t = -2.0 * period + phase;
                    // The press: the trace's contact, then closed; then a clean release.
                    while t < hold {
                        if let Some(e) = key.update(trace.is_closed(t), &prior) {
                            edges.push(e);
                        }
                        t += period;
                    }
                    let release_edges = (0..)
                        .map(|k| f64::from(k) * period)
                        .take_while(|x| *x < hold)
                        .filter(|_| key.update(false, &prior).is_some())
                        .count();
                    assert_eq!(
                        (edges.len(), release_edges),
                        (1, 1),
                        "{} {dwell:?} period {period:e} press {press}: {edges:?}",
                        s.name
                    );
                    checked += 1;
                }
                let (press, _) = key.learned().windows(&prior);
                let learned = f64::from(press) * period;
                assert!(
                    u32::from(key.learned().press.events) >= u32::from(WARM_UP),
                    "{}",
                    s.name
                );
                assert!(
                    learned <= 1.5 * bounce + period * (1.0 + 1e-9),
                    "{} {dwell:?} period {period:e}: learned {learned:e} for a bounce of {bounce:e}",
                    s.name
                );
                // Where the samples resolve the bounce (long dwells, 20 samples to it) the
                // window covers it; Newton impacts are never sampled closed, so there the
                // contact is seen to close once, cleanly, and one sample is right.
                if dwell == Dwell::FractionOfFlight(0.5) && divisions == 20.0 {
                    assert!(learned >= bounce, "{}: {learned:e} < {bounce:e}", s.name);
                }
                if dwell == Dwell::None {
                    assert_eq!(press, 1, "{}", s.name);
                }
            }
        }
    }
    assert_eq!(checked, 8 * 3 * 3 * 30);
}
