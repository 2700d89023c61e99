//! The calibration's fit on captures synthesised from the exact reference: a Newton-impact
//! switch (preload, no damping) recorded as an instant close at each impact and an open flight
//! between impacts. The fit must recover R and the scale v0 / (Omega^2 |Delta|), say that the
//! impact model holds, and its held-out predictions must match.

mod common;

use bounce_table::calibrate::{group, validations, ImpactFit};
use bounce_table::capture::{Event, Kind};
use host_tests::reference::{simulate_observed, OneBody, DEFAULT_BUDGET};

const OMEGA: f64 = 2.0 * std::f64::consts::PI * 1000.0;
const DELTA: f64 = -1e-4;

/// A press of the switch: the impact times from the reference, each a close and an instant
/// reopening (a zero-length closed interval, below any resolution).
fn press(restitution: f64, closing_speed: f64, start: f64) -> Event {
    let scene = OneBody {
        omega: OMEGA,
        delta: DELTA,
        restitution,
        zeta: 0.0,
        closing_speed,
        threshold: None,
    };
    let mut changes = Vec::new();
    simulate_observed(&scene, DEFAULT_BUDGET, |t, _| {
        changes.push(start + t);
        changes.push(start + t);
    })
    .expect("the reference simulates it");
    changes.pop(); // the contact stays closed after the last resolved impact
    Event {
        switch: "synthetic".into(),
        origin: String::new(),
        kind: Kind::Press,
        changes,
    }
}

#[test]
fn the_fit_recovers_restitution_and_scale_from_a_newton_switch() {
    for (r, v0) in [(0.7, 0.01), (0.5, 0.02), (0.9, 0.005)] {
        let events: Vec<Event> = (0..10).map(|i| press(r, v0, f64::from(i))).collect();
        let groups = group(&events, 1e-12);
        let d: Vec<_> = groups.values().flatten().collect();
        let fit = ImpactFit::new(&d);
        // A preload flight lasts (2 / Omega) atan(j) with j = v / (Omega |Delta|), so the ratio
        // of successive flights is R only to first order: off by at most j^2 (1 - R^2) / 3.
        let j = r * v0 / (OMEGA * DELTA.abs());
        let bound = j * j * (1.0 - r * r) / 3.0 + 1e-9;
        let got = fit.restitution.unwrap();
        assert!(
            (got / r - 1.0).abs() <= bound,
            "R {r}: fitted {got}, bound {bound:e}"
        );
        assert!(fit.holds(), "R {r}: {fit:?}");
        // Scale: first flight / (2 R) = v0 / (Omega^2 |Delta|), again to O(j^2 / 3).
        let scale = fit.first_flight.unwrap() / (2.0 * got);
        let want = v0 / (OMEGA * OMEGA * DELTA.abs());
        assert!(
            (scale / want - 1.0).abs() <= j * j / 3.0 + bound,
            "R {r}: scale {scale:e} vs {want:e}"
        );
        // Identical presses: both held-out predictors reproduce the other half, to the rounding
        // of times stored as start + t (starts up to 9 s, bounces ~1e-5 s: 4 eps 9 / 1e-5).
        let rounding = 4.0 * f64::EPSILON * 9.0 / d[0].bounce;
        for check in validations(&d, 7) {
            for (e, m) in check.empirical.iter().zip(check.model.iter()) {
                assert!((e.unwrap() - 1.0).abs() <= rounding, "{check:?}");
                // The model sums the geometric flights: the reference's Zeno end to O(j^2 / 3)
                // for the first flight and for the sum, plus the fitted R's error carried
                // through 1 / (1 - R); and the capture misses the Zeno tail the reference sums
                // instead of resolving (at most the last flight times R / (1 - R)).
                let carried = r / (1.0 - r) * (got / r - 1.0).abs();
                let last = d[0].flights.last().unwrap();
                let tail = last * r / (1.0 - r) / d[0].bounce;
                let tolerance = 2.0 * j * j / 3.0 + carried + tail + 1e-9;
                assert!((m.unwrap() - 1.0).abs() <= tolerance, "{check:?}");
            }
        }
    }
}

#[test]
fn flights_that_do_not_shrink_are_not_called_an_impact_model() {
    // A press whose open intervals grow and shrink at random: the ratios straddle 1.
    let changes: Vec<f64> = [0.0, 1.0, 5.0, 6.0, 8.0, 9.0, 21.0, 22.0, 23.0, 24.0, 40.0]
        .iter()
        .map(|t| t * 1e-5)
        .collect();
    let events: Vec<Event> = (0..4)
        .map(|i| Event {
            switch: "chatter".into(),
            origin: String::new(),
            kind: Kind::Press,
            changes: changes.iter().map(|t| t + f64::from(i)).collect(),
        })
        .collect();
    let groups = group(&events, 1e-6);
    let d: Vec<_> = groups.values().flatten().collect();
    let fit = ImpactFit::new(&d);
    assert!(!fit.holds(), "{fit:?}");
}

#[test]
fn exported_windows_compile_as_c_and_rust() {
    let events: Vec<Event> = (0..6).map(|i| press(0.7, 0.01, f64::from(i))).collect();
    let groups = group(&events, 1e-12);
    let dir = std::env::temp_dir().join(format!("calibrate-export-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let header = dir.join("windows.h");
    std::fs::write(
        &header,
        bounce_table::calibrate::export(&groups, 0.99, 1, false),
    )
    .unwrap();
    let c = dir.join("use.c");
    std::fs::write(
        &c,
        format!(
            "#include \"{}\"\nunsigned long long w(void) {{ return SYNTHETIC_PRESS_WINDOW_NS; }}\n",
            header.display()
        ),
    )
    .unwrap();
    common::compile_c(&c, &dir);
    let rs = dir.join("windows.rs");
    let constants = bounce_table::calibrate::export(&groups, 0.99, 1, true);
    std::fs::write(
        &rs,
        format!("{constants}\npub fn w() -> u64 {{ SYNTHETIC_PRESS_WINDOW_NS }}\n"),
    )
    .unwrap();
    common::compile_rust(&rs, &dir);
    // The window is the bounce of these identical presses (nanoseconds, rounded up).
    let bounce = groups.values().flatten().next().unwrap().bounce;
    let want = format!(
        "SYNTHETIC_PRESS_WINDOW_NS: u64 = {};",
        (bounce * 1e9).ceil()
    );
    assert!(constants.contains(&want), "{constants}");
}

#[test]
fn the_plot_draws_the_observed_and_the_modelled_distribution() {
    let events: Vec<Event> = (0..6).map(|i| press(0.7, 0.01, f64::from(i))).collect();
    let groups = group(&events, 1e-12);
    let ((switch, kind), d) = groups.iter().next().unwrap();
    let svg = bounce_table::calibrate::plot(switch, *kind, d);
    assert!(svg.starts_with("<svg") && svg.trim_end().ends_with("</svg>"));
    assert!(
        svg.contains("observed") && svg.contains("impact model"),
        "{svg}"
    );
    assert_eq!(
        svg.matches("<circle").count(),
        6,
        "one dot per bouncing event"
    );
}
