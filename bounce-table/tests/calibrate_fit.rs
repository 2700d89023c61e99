//! The calibration's fit on captures synthesised from the exact reference: a Newton-impact
//! switch (preload, no damping) recorded as an instant close at each impact and an open flight
//! between impacts. The fit must recover R and the scale v0 / (Omega^2 |Delta|), say that the
//! impact model holds, and its held-out predictions must match.

mod common;

use bounce_table::capture::{Edge, Event};
use bounce_table::render::emit::Lang;
use bounce_table::scene::spreads::SplitMix;
use bounce_table::stats::{
    group, random_splits, reopening_threshold, validations, window, BounceModel, ImpactFit,
    LogNormal,
};
use contact_bounce_reference::{simulate_observed, OneBody, DEFAULT_BUDGET};

const OMEGA: f64 = 2.0 * std::f64::consts::PI * 1000.0;
const DELTA: f64 = -1e-4;
/// The burst gap: the default of `calibrate`.
const GAP: f64 = 5e-3;

/// A press of the switch: the impact times from the reference, the contact closed at each
/// impact for `dwell` times the flight that follows it, then open for that flight. `dwell = 0`
/// is a Newton impact (a zero-length closed interval, below any resolution).
fn press_with_dwell(restitution: f64, closing_speed: f64, start: f64, dwell: f64) -> Event {
    let scene = OneBody {
        omega: OMEGA,
        delta: DELTA,
        restitution,
        zeta: 0.0,
        closing_speed,
        threshold: None,
    };
    let mut impacts = Vec::new();
    simulate_observed(&scene, DEFAULT_BUDGET, |t, _| impacts.push(t))
        .expect("the reference simulates it");
    // Times from the first change are summed first, and the start added once to each: every
    // change then carries one rounding at the start's magnitude, however many flights.
    let mut now = 0.0;
    let mut changes = vec![start];
    for w in impacts.windows(2) {
        let flight = w[1] - w[0];
        now += dwell * flight;
        changes.push(start + now);
        now += flight;
        changes.push(start + now);
    }
    // The contact stays closed after the last resolved impact.
    Event {
        switch: "synthetic".into(),
        origin: String::new(),
        kind: Edge::Press,
        changes,
        section: None,
    }
}

fn press(restitution: f64, closing_speed: f64, start: f64) -> Event {
    press_with_dwell(restitution, closing_speed, start, 0.0)
}

#[test]
fn the_fit_recovers_restitution_and_scale_from_a_newton_switch() {
    for (r, v0) in [(0.7, 0.01), (0.5, 0.02), (0.9, 0.005)] {
        let events: Vec<Event> = (0..10).map(|i| press(r, v0, f64::from(i))).collect();
        let groups = group(&events, 1e-12, GAP);
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
            kind: Edge::Press,
            changes: changes.iter().map(|t| t + f64::from(i)).collect(),
            section: None,
        })
        .collect();
    let groups = group(&events, 1e-6, GAP);
    let d: Vec<_> = groups.values().flatten().collect();
    let fit = ImpactFit::new(&d);
    assert!(!fit.holds(), "{fit:?}");
}

#[test]
fn exported_windows_compile_as_c_and_rust() {
    let events: Vec<Event> = (0..10).map(|i| press(0.7, 0.01, f64::from(i))).collect();
    let groups = group(&events, 1e-12, GAP);
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("calibrate-export-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let header = dir.join("windows.h");
    std::fs::write(
        &header,
        bounce_table::commands::calibrate::export(&groups, 0.99, None, Lang::C, "synthetic.jsonl")
            .unwrap(),
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
    let constants = bounce_table::commands::calibrate::export(
        &groups,
        0.99,
        None,
        Lang::Rust,
        "synthetic.jsonl",
    )
    .unwrap();
    std::fs::write(
        &rs,
        format!("{constants}\npub fn w() -> u64 {{ SYNTHETIC_PRESS_WINDOW_NS }}\n"),
    )
    .unwrap();
    common::compile_rust(&rs, &dir);
    // The window exported is the recommended one (nanoseconds, rounded up), at least the
    // bounce of these identical presses.
    // A capture in the wrong unit (times a billion times too long): refused, not a
    // saturated number.
    let long: Vec<Event> = (0..10)
        .map(|i| {
            let start = f64::from(i) * 1e13;
            Event {
                switch: "long".to_owned(),
                origin: format!("event {i}"),
                kind: Edge::Press,
                changes: vec![start, start + 1e11, start + 2e11, start + 3e11],
                section: None,
            }
        })
        .collect();
    let long_groups = group(&long, 1e-12, GAP);
    let refused =
        bounce_table::commands::calibrate::export(&long_groups, 0.99, None, Lang::C, "long.csv")
            .unwrap_err();
    assert!(
        refused.contains("beyond a 64-bit count of nanoseconds"),
        "{refused}"
    );
    let d: Vec<_> = groups.values().flatten().collect();
    let window = bounce_table::stats::window(&d, 0.99);
    let recommended = window.recommended();
    assert!(recommended >= d[0].bounce && recommended >= window.predictive.unwrap());
    let want = format!(
        "SYNTHETIC_PRESS_WINDOW_NS: u64 = {};",
        (recommended * 1e9).ceil()
    );
    assert!(constants.contains(&want), "{constants}");
    // Kept when an assertion fails, to look at; removed when the test passes.
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn the_plot_draws_the_observed_and_the_modelled_distribution() {
    let events: Vec<Event> = (0..10).map(|i| press(0.7, 0.01, f64::from(i))).collect();
    let groups = group(&events, 1e-12, GAP);
    let ((switch, kind), d) = groups.iter().next().unwrap();
    let svg = bounce_table::commands::calibrate::plot(switch, *kind, d, 0.99);
    assert!(svg.starts_with("<svg") && svg.trim_end().ends_with("</svg>"));
    assert!(
        svg.contains("observed") && svg.contains("impact model") && svg.contains("fitted model"),
        "{svg}"
    );
    // Data dots are translucent; the legend's is not.
    assert_eq!(
        svg.matches("fill-opacity").count(),
        10,
        "one dot per bouncing event"
    );
    let window = bounce_table::stats::window(&d.iter().collect::<Vec<_>>(), 0.99);
    assert!(
        svg.contains(&format!(
            "window {} (P99 of the fitted model)",
            bounce_table::render::plot::time(window.recommended())
        )),
        "the window is marked: {svg}"
    );
}

#[test]
fn the_fitted_model_adds_the_dwell_a_newton_impact_lacks() {
    let (r, v0) = (0.7, 0.01);
    for dwell in [0.0, 0.5, 2.0] {
        let events: Vec<Event> = (0..10)
            .map(|i| press_with_dwell(r, v0, f64::from(i), dwell))
            .collect();
        let groups = group(&events, 1e-12, GAP);
        let d: Vec<_> = groups.values().flatten().collect();
        let model = BounceModel::fit(&d);
        assert!(model.impact, "{model:?}");
        assert_eq!((model.clean, model.single, model.late), (0.0, 1.0, 0.0));
        // Closed time is `dwell` times every flight: the closed share is `dwell`, to rounding.
        let share = model.closed_share.unwrap();
        assert!((share - dwell).abs() <= 1e-9, "dwell {dwell}: {share}");
        // The burst is the impact model's flights times 1 + dwell, so it misses the observed
        // bounce (1 + dwell) * sum of flights only as the impact model alone does (see above:
        // O(j^2) in the flights, the fitted R carried through 1 / (1 - R), the Zeno tail).
        let fit = ImpactFit::new(&d);
        let j = r * v0 / (OMEGA * DELTA.abs());
        let carried = r / (1.0 - r) * (fit.restitution.unwrap() / r - 1.0).abs();
        let tail = d[0].flights.last().unwrap() * r / (1.0 - r) * (1.0 + dwell) / d[0].bounce;
        let tolerance = 2.0 * j * j / 3.0 + carried + tail + 1e-9;
        for q in [0.5, 0.9, 0.99] {
            let got = model.quantile(q).unwrap() / d[0].bounce;
            assert!(
                (got - 1.0).abs() <= tolerance,
                "dwell {dwell}, q {q}: {got}"
            );
        }
        for check in validations(&d, 3) {
            for f in check.fitted {
                assert!((f.unwrap() - 1.0).abs() <= tolerance, "{check:?}");
            }
        }
        // Over many halvings too: every one predicts, within the same tolerance.
        let [_, _, fitted] = random_splits(&d, 3, 20);
        for r in fitted {
            let r = r.unwrap();
            assert_eq!(r.predicted, 20);
            assert!(
                (r.p10 - 1.0).abs() <= tolerance && (r.p90 - 1.0).abs() <= tolerance,
                "{r:?}"
            );
        }
    }
}

/// A standard normal draw (Box-Muller).
fn normal(rng: &mut SplitMix) -> f64 {
    let u = 1.0 - rng.unit();
    let v = rng.unit();
    (-2.0 * u.ln()).sqrt() * (2.0 * std::f64::consts::PI * v).cos()
}

#[test]
fn the_fitted_model_recovers_a_known_mixture_of_clean_edges_bursts_and_late_bursts() {
    // 30 % clean, 50 % one burst log-normal (100 us x/ e^0.5), 20 % late burst: the gap
    // (5 ms) plus a log-normal excess (45 ms x/ e^0.3), settling for at least the gap (the
    // late burst's last interval starts 50 us before its end, and the excess is at least
    // that: 1.1e-3 of its median is 23 standard deviations below it).
    let (n, clean, single) = (4000, 0.3, 0.5);
    let (burst_mu, burst_sigma) = ((100e-6_f64).ln(), 0.5);
    let (late_mu, late_sigma) = ((45e-3_f64).ln(), 0.3);
    let mut rng = SplitMix(11);
    let events: Vec<Event> = (0..n)
        .map(|i| {
            let t = f64::from(i);
            let u = rng.unit();
            let changes = if u < clean {
                vec![t]
            } else if u < clean + single {
                let b = (burst_mu + burst_sigma * normal(&mut rng)).exp();
                vec![t, t + b / 3.0, t + b]
            } else {
                let b = GAP + (late_mu + late_sigma * normal(&mut rng)).exp();
                vec![t, t + 20e-6, t + 40e-6, t + b - 10e-6, t + b]
            };
            Event {
                switch: "mixture".into(),
                origin: String::new(),
                kind: Edge::Press,
                changes,
                section: None,
            }
        })
        .collect();
    let groups = group(&events, 1e-9, GAP);
    let d: Vec<_> = groups.values().flatten().collect();
    let m = BounceModel::fit(&d);
    assert!(!m.impact, "{m:?}");
    // Every estimate within 4 standard errors: shares sqrt(p (1 - p) / n), a log-normal's mu
    // sigma / sqrt(k) and its sigma about sigma / sqrt(2 k), k the events of that part.
    let nf = f64::from(n);
    let share = |p: f64| 4.0 * (p * (1.0 - p) / nf).sqrt();
    assert!((m.clean - clean).abs() <= share(clean), "{m:?}");
    assert!((m.single - single).abs() <= share(single), "{m:?}");
    assert!((m.late - 0.2).abs() <= share(0.2), "{m:?}");
    assert_eq!(
        (m.burst.unwrap().floor, m.late_bounce.unwrap().floor),
        (0.0, GAP)
    );
    for (fit, mu, sigma, p) in [
        (m.burst.unwrap(), burst_mu, burst_sigma, single),
        (m.late_bounce.unwrap(), late_mu, late_sigma, 0.2),
    ] {
        let k = p * nf;
        assert!((fit.mu - mu).abs() <= 4.0 * sigma / k.sqrt(), "{fit:?}");
        assert!(
            (fit.sigma - sigma).abs() <= 4.0 * sigma / (2.0 * k).sqrt(),
            "{fit:?}"
        );
    }
}

#[test]
fn a_bounce_shorter_than_the_resolution_is_fitted_with_the_clean_edges() {
    // 40 events: 20 clean, 16 one-burst log-normal (20 us x/ e^0.5), and 4 whose whole bounce
    // is a glitch of 0.4 to 1.6 us, under the 3 us resolution (all their intervals chatter).
    // The glitches are not timed: fitted as clean, the burst part is the 16 timed bursts
    // alone. Fitted as bursts, the glitches would spread the part over four decades in ln t
    // and push its P99 far past every timed burst.
    let mut rng = SplitMix(5);
    let mut events = Vec::new();
    let mut timed = Vec::new();
    for i in 0..40 {
        let t = f64::from(i);
        let changes = match i % 10 {
            0..=4 => vec![t],
            5 => vec![t, t + 0.4e-6 * f64::from(i / 10 + 1)],
            _ => {
                let b = ((20e-6_f64).ln() + 0.5 * normal(&mut rng)).exp();
                timed.push(b);
                vec![t, t + b / 3.0, t + b]
            }
        };
        events.push(Event {
            switch: "glitchy".into(),
            origin: String::new(),
            kind: Edge::Release,
            changes,
            section: None,
        });
    }
    let groups = group(&events, 3e-6, GAP);
    let d: Vec<_> = groups.values().flatten().collect();
    let m = BounceModel::fit(&d);
    assert!((m.clean - 24.0 / 40.0).abs() < 1e-12, "{m:?}");
    assert!((m.single - 16.0 / 40.0).abs() < 1e-12, "{m:?}");
    // The same fit as to the timed bursts alone (up to the rounding of t + b - t at t <= 39 s).
    let (got, want) = (m.burst.unwrap(), LogNormal::fit(&timed).unwrap());
    assert_eq!(got.n, 16);
    assert!(
        (got.mu - want.mu).abs() < 1e-9 && (got.sigma - want.sigma).abs() < 1e-9,
        "{m:?}"
    );
    let w = window(&d, 0.99);
    assert_eq!(w.bouncing, 16);
    let largest = timed.iter().copied().fold(0.0, f64::max);
    assert!(w.recommended() >= largest, "{w:?}");
    // The glitches fitted as bursts instead: the same rule's P99 is at least 3 times higher.
    let as_bursts = group(&events, 1e-9, GAP);
    let all: Vec<_> = as_bursts.values().flatten().collect();
    let wide = window(&all, 0.99);
    assert!(
        wide.recommended() > 3.0 * w.recommended(),
        "{wide:?} vs {w:?}"
    );
}

#[test]
fn the_mixture_quantile_is_the_inverse_of_its_distribution() {
    let l = |mu: f64, sigma: f64| LogNormal {
        mu,
        sigma,
        floor: 0.0,
        n: 10,
    };
    // Clean 30 %, the rest one log-normal: the quantile is analytic. Standard normal points:
    // Phi(1) = 0.841344746068543, Phi(2.326347874040841) = 0.99.
    let m = BounceModel {
        events: 10,
        clean: 0.3,
        single: 0.7,
        late: 0.0,
        burst: Some(l(-7.0, 0.8)),
        late_bounce: None,
        reopened: 0.0,
        reopened_bounce: None,
        reopening_dwell: None,
        reopening: None,
        impact: false,
        closed_share: None,
        predictive: None,
    };
    for (p, z) in [
        (0.5, 0.0),
        (0.841_344_746_068_543, 1.0),
        (0.99, 2.326_347_874_040_841),
    ] {
        let got = m.quantile(0.3 + 0.7 * p).unwrap();
        let want = (-7.0_f64 + 0.8 * z).exp();
        assert!((got / want - 1.0).abs() <= 1e-9, "p {p}: {got} vs {want}");
    }
    assert_eq!(m.quantile(0.3), Some(0.0));
    assert_eq!(m.quantile(0.1), Some(0.0));
    // Two parts: the distribution at the quantile is the probability asked.
    let two = BounceModel {
        single: 0.5,
        late: 0.2,
        late_bounce: Some(l(-3.0, 1.5)),
        ..m.clone()
    };
    for q in [0.31, 0.5, 0.9, 0.99, 0.999, 1.0] {
        let t = two.quantile(q).unwrap();
        assert!((two.cdf(t).unwrap() - q).abs() <= 1e-9, "q {q}: t {t}");
    }
    // A part that occurs but could not be fitted: no quantile, no distribution.
    let unfitted = BounceModel {
        late_bounce: None,
        ..two.clone()
    };
    assert_eq!(unfitted.quantile(0.9), None);
    assert_eq!(unfitted.cdf(1.0), None);
    // No events: nothing to say.
    let empty = BounceModel::fit(&[]);
    assert_eq!(empty.quantile(0.5), None);
    // A log-normal needs three positive, finite durations.
    assert_eq!(LogNormal::fit(&[1e-3, 2e-3]), None);
    assert_eq!(LogNormal::fit(&[1e-3, 0.0, 2e-3]), None);
    assert_eq!(LogNormal::fit(&[1e-3, f64::NAN, 2e-3]), None);
    let same = LogNormal::fit(&[1e-3; 3]).unwrap();
    assert_eq!(
        (same.sigma, same.cdf(0.999e-3), same.cdf(1e-3)),
        (0.0, 0.0, 1.0)
    );
}

/// A press of a stuck pair that may reopen: a Newton burst (the reference's impacts, with a
/// short closed contact time of `contact` s at each), then, if `reopen`, the contact holds for
/// `hold` s, opens again and makes a second, smaller burst.
fn two_stage_press(start: f64, v0: f64, contact: f64, reopen: Option<(f64, f64)>) -> Event {
    let burst = |v: f64, from: f64, changes: &mut Vec<f64>| {
        let scene = OneBody {
            omega: OMEGA,
            delta: DELTA,
            restitution: 0.6,
            zeta: 0.0,
            closing_speed: v,
            threshold: None,
        };
        let mut impacts = Vec::new();
        simulate_observed(&scene, DEFAULT_BUDGET, |t, _| impacts.push(t))
            .expect("the reference simulates it");
        let mut now = from;
        for w in impacts.windows(2).take(8) {
            now += contact;
            changes.push(now);
            now += w[1] - w[0];
            changes.push(now);
        }
        now
    };
    let mut changes = vec![start];
    let end = burst(v0, start, &mut changes);
    if let Some((hold, v1)) = reopen {
        // Closed since `end`: the second burst's first opening ends the hold.
        burst(v1, end + hold - contact, &mut changes);
    }
    Event {
        switch: "two-stage".into(),
        origin: String::new(),
        kind: Edge::Press,
        changes,
        section: None,
    }
}

#[test]
fn a_stuck_pair_that_reopens_is_a_part_of_its_own() {
    // 40 % of presses reopen: the pair holds 400 us (about 19 times the first flight, 2 j / Omega
    // = 21 us at j = R v0 / (Omega |Delta|) = 0.067) and bounces again at a third of the speed;
    // the others settle after the first burst. Closing speeds vary by +-10 %, holds by +-10 %,
    // contact times are 5 us.
    let mut rng = SplitMix(5);
    let events: Vec<Event> = (0..40)
        .map(|i| {
            let v0 = 0.07 * (1.0 + 0.2 * (rng.unit() - 0.5));
            let reopen = (i % 5 < 2).then(|| (400e-6 * (1.0 + 0.2 * (rng.unit() - 0.5)), v0 / 3.0));
            two_stage_press(f64::from(i), v0, 5e-6, reopen)
        })
        .collect();
    let groups = group(&events, 3e-6, GAP);
    let d: Vec<_> = groups.values().flatten().collect();
    let one_burst: Vec<_> = d.iter().copied().filter(|x| x.bounce > 0.0).collect();
    // The holds: 5 us beside ~21 us flights when plain (a share of at most 0.3), 15-24 times
    // the longest flight when reopening; the threshold falls between.
    let c = reopening_threshold(&one_burst).expect("the data ask for the split");
    assert!(c > 0.3 && c < 24.0, "{c}");
    let m = BounceModel::fit(&d);
    assert!(
        (m.reopened - 0.4).abs() < 1e-12 && (m.single - 0.6).abs() < 1e-12,
        "{m:?}"
    );
    let dwell = m.reopening_dwell.unwrap();
    assert!((dwell / 400e-6 - 1.0).abs() <= 0.1, "{dwell}");
    // Two narrow parts: the window stays near the longest reopening, where one log-normal over
    // both modes reaches much further.
    let w = window(&d, 0.99).recommended();
    let largest = d.iter().map(|x| x.bounce).fold(0.0, f64::max);
    assert!(w < 1.3 * largest, "{w} vs {largest}");
    let one = LogNormal::fit(&d.iter().map(|x| x.bounce).collect::<Vec<_>>()).unwrap();
    let one_p99 = (one.mu + 2.326 * one.sigma).exp();
    assert!(w < one_p99, "{w} vs one log-normal's {one_p99}");

    // The same presses with no reopening: the holds are all contact times, nothing splits.
    let plain: Vec<Event> = (0..40)
        .map(|i| {
            two_stage_press(
                f64::from(i),
                0.07 * (1.0 + 0.01 * f64::from(i % 7)),
                5e-6,
                None,
            )
        })
        .collect();
    let groups = group(&plain, 3e-6, GAP);
    let d: Vec<_> = groups.values().flatten().collect();
    assert_eq!(reopening_threshold(&d), None);
    let m = BounceModel::fit(&d);
    assert_eq!((m.reopened, m.single), (0.0, 1.0));
}

#[test]
fn a_later_half_that_never_bounced_is_said_so_not_divided_by() {
    // Ten bouncing presses, then ten clean ones (a single change each).
    let mut events: Vec<Event> = (0..10).map(|i| press(0.7, 0.01, f64::from(i))).collect();
    events.extend((10..20).map(|i| Event {
        switch: "synthetic".into(),
        origin: format!("event {i}"),
        kind: Edge::Press,
        changes: vec![f64::from(i)],
        section: None,
    }));
    let groups = group(&events, 1e-12, GAP);
    let text = bounce_table::commands::calibrate::summary(&groups, 0.99, GAP, None);
    assert!(
        text.contains("covers 10 of the 10 later presses, none of which bounced")
            && !text.contains("inf times"),
        "{text}"
    );
}

#[test]
fn the_bounce_is_counted_per_section_of_the_protocol() {
    // Six releases in section "slow" (four clean, two bouncing once for 200 us), then four in
    // section "fast" (one clean, three bouncing again 10 ms after a first burst: late bursts).
    let release = |i: u32, section: &str, changes: Vec<f64>| Event {
        switch: "synthetic".into(),
        origin: format!("event {i}"),
        kind: Edge::Release,
        changes: changes.iter().map(|t| t + f64::from(i)).collect(),
        section: Some(section.into()),
    };
    let mut events: Vec<Event> = (0..4).map(|i| release(i, "slow", vec![0.0])).collect();
    events.extend((4..6).map(|i| release(i, "slow", vec![0.0, 1e-4, 2e-4])));
    events.push(release(6, "fast", vec![0.0]));
    events.extend((7..10).map(|i| release(i, "fast", vec![0.0, 1e-4, 2e-4, 10.2e-3, 10.3e-3])));
    let groups = group(&events, 3e-6, GAP);
    let text = bounce_table::commands::calibrate::by_section(&groups);
    // The earlier half is the first five releases, all slow.
    assert!(
        text.contains(
            "| synthetic | release | slow | 5 / 1 | 4 | 0 | - | 0.00 us | 200.00 us | 200.00 us |"
        ),
        "{text}"
    );
    assert!(
        text.contains("| synthetic | release | fast | 0 / 4 | 1 | 3 | - | 10.300 ms | 10.300 ms | 10.300 ms |"),
        "{text}"
    );
    // One section, or none named: nothing to compare.
    let one: Vec<Event> = events
        .iter()
        .cloned()
        .map(|e| Event {
            section: Some("slow".into()),
            ..e
        })
        .collect();
    assert_eq!(
        bounce_table::commands::calibrate::by_section(&group(&one, 3e-6, GAP)),
        ""
    );
    let none: Vec<Event> = events
        .into_iter()
        .map(|e| Event { section: None, ..e })
        .collect();
    assert_eq!(
        bounce_table::commands::calibrate::by_section(&group(&none, 3e-6, GAP)),
        ""
    );
}

#[test]
fn a_late_burst_exactly_a_gap_long_keeps_the_fit() {
    // Releases on a clock whose ticks divide the gap: four bursts of 0.1-0.4 ms, three late
    // bursts 8-20 ms long, and one whose two changes are exactly the gap apart. That one has
    // no excess over the gap: the late part is then the whole bounce's log-normal, and the
    // model still gives a window (with the gap as floor it had none).
    let release = |i: u32, changes: Vec<f64>| Event {
        switch: "ticks".into(),
        origin: format!("event {i}"),
        kind: Edge::Release,
        changes,
        section: None,
    };
    let mut events = vec![
        release(0, vec![0.0, 1e-4]),
        release(1, vec![0.0, 1e-4, 2e-4]),
        release(2, vec![0.0, 3e-4]),
        release(3, vec![0.0, 1e-4, 4e-4]),
        release(4, vec![0.0, 8e-3]),
        release(5, vec![0.0, 1e-4, 12e-3]),
        release(6, vec![0.0, 20e-3]),
        release(7, vec![0.0, GAP]),
    ];
    events.push(release(8, vec![0.0]));
    let groups = group(&events, 1e-9, GAP);
    let d: Vec<_> = groups.values().flatten().collect();
    let m = BounceModel::fit(&d);
    assert_eq!(
        m.late_bounce.map(|l| (l.floor, l.n)),
        Some((0.0, 4)),
        "{m:?}"
    );
    let w = window(&d, 0.99);
    assert!(w.predictive.is_some_and(|p| p >= 20e-3), "{w:?}");
    // Without the exact one, the late part is the excess over the gap.
    events.pop();
    events.pop();
    let groups = group(&events, 1e-9, GAP);
    let d: Vec<_> = groups.values().flatten().collect();
    assert_eq!(
        BounceModel::fit(&d).late_bounce.map(|l| (l.floor, l.n)),
        Some((GAP, 3))
    );
}
