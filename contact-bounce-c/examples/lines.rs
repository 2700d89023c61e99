//! The lines the C examples print (`examples/c/lines.h`), computed by the Rust core directly:
//! `scripts/c-api.sh` checks that the C API gives the same on the host and on the Uno.
//! The switches and samples are those of `examples/c/switches.h`.

use contact_bounce::{
    tiers::preload_restitution_bounce_seconds, tiers::preload_viscous_bounce_time,
    tiers::AutoTiers, tiers::DEFAULT_MAX_IMPACTS, tiers::EXACT_MAX_IMPACTS, Contact, Edge, Error,
    Frequency, Margin, Method, Mode, Nodes, Offset, Parameter, Prediction, Preloaded, Reason,
    Restitution, Scene, State, Threshold, Tolerance, Viscous, Window, Windows,
};

/// mass, stiffness, offset, R, zeta, closing speed, threshold fraction (0: none).
const SWITCHES: [[f32; 7]; 3] = [
    [5e-5, 5000.0, -2e-4, 0.7, 0.03, 0.5, 0.0],
    [1e-3, 100.0, 1e-4, 0.8, 0.05, 0.3, 0.01],
    [2e-6, 400.0, -5e-5, 0.6, 0.0, 0.2, 0.0],
];

const SAMPLES: [u8; 20] = [0, 1, 0, 1, 1, 0, 1, 1, 1, 1, 1, 1, 0, 1, 0, 0, 0, 0, 0, 0];

fn contact(s: [f32; 7]) -> Result<(Contact<f32>, Option<Viscous<f32>>), Error> {
    let [mass, stiffness, offset, r, zeta, v0, fraction] = s;
    let contact = Contact {
        frequency: Frequency::MassStiffness { mass, stiffness },
        offset: Offset::Delta(offset),
        restitution: Restitution::Coefficient(r),
        closing_speed: v0,
        threshold: if fraction == 0.0 {
            Threshold::None
        } else {
            Threshold::FractionOfFirst(fraction)
        },
    };
    Ok((contact, Viscous::optional(zeta)?))
}

fn scene(s: [f32; 7]) -> Result<Scene<f32, Option<Viscous<f32>>>, Error> {
    contact(s).and_then(|(contact, damping)| Scene::new(contact, damping))
}

/// The C API's `cb_code` of an error's reason.
fn code(e: Error) -> u8 {
    contact_bounce_c::cb_error::from(e).code()
}

fn line(index: usize, tier: &str, p: &Prediction<f32>) -> String {
    #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
    let end_ns = p.end_time.seconds().map_or(0, |t| (t * 1e9_f32) as u32);
    let ticks = Margin::new(1.5_f32, 0.0)
        .and_then(|m| Window::from_prediction(p, &m, 1e-5))
        .map_or(0, |w| w.ticks());
    format!("switch {index} {tier} end_ns {end_ns} ticks {ticks}")
}

/// A time alone as a line, "switch S TIER end_ns N ticks K", or its error, "switch S TIER error
/// PARAMETER CODE" (the C API numbers the reason; it names the parameters as the core does, but
/// Delta by its field, `offset`).
fn time_line(index: usize, tier: &str, time: Result<f32, Error>) -> String {
    match time {
        Ok(t) => {
            #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
            let end_ns = (t * 1e9_f32) as u32;
            let ticks = Margin::new(1.5_f32, 0.0)
                .and_then(|m| Window::from_seconds(t, &m, 1e-5))
                .map_or(0, |w| w.ticks());
            format!("switch {index} {tier} end_ns {end_ns} ticks {ticks}")
        }
        Err(e) if e.parameter() == Parameter::Delta => {
            format!("switch {index} {tier} error offset {}", code(e))
        }
        Err(e) => format!("switch {index} {tier} error {} {}", e.parameter(), code(e)),
    }
}

fn main() -> Result<(), Error> {
    for (i, s) in SWITCHES.into_iter().enumerate() {
        let [mass, stiffness, offset, r, zeta, v0, _] = s;
        let lean = Preloaded {
            mass,
            stiffness,
            preload_force: -offset * stiffness,
            closing_speed: v0,
            restitution: r,
            damping_ratio: zeta,
        };
        let tb1v = preload_viscous_bounce_time(&lean).map(|e| e.time);
        println!("{}", time_line(i, "tb1v", tb1v));
        // Restitution alone: the switch's damping left out.
        let averaged = preload_restitution_bounce_seconds(&Preloaded {
            damping_ratio: 0.0,
            ..lean
        });
        println!("{}", time_line(i, "restitution-averaged", averaged));
        // The closed tier's time on a preloaded switch (`cb_preload_seconds_closed`).
        let closed_preload = contact(s).and_then(|(contact, damping)| {
            let time = Scene::new_preload(contact, damping)?.bounce_time(Method::Closed);
            time.ok_or(Error::new(Parameter::Time, Reason::Endless))
        });
        println!("{}", time_line(i, "closed-preload", closed_preload));
        let scene = scene(s)?;
        for (tier, method) in [
            ("closed", Method::Closed),
            ("averaged", Method::Averaged(Nodes::N8)),
            (
                "map",
                Method::Map {
                    max_impacts: DEFAULT_MAX_IMPACTS,
                },
            ),
            (
                "exact",
                Method::Exact {
                    max_impacts: EXACT_MAX_IMPACTS,
                },
            ),
            ("auto", Method::Auto(Tolerance::new(0.01)?)),
        ] {
            println!("{}", line(i, tier, &scene.predict(method)));
        }
        let lean = scene.predict_auto_among::<{ AutoTiers::EXACT }>(Tolerance::new(0.01)?);
        println!("{}", line(i, "auto-exact", &lean));
    }
    for (mode, name) in [(Mode::Confirm, "confirm"), (Mode::HoldOff, "hold-off")] {
        let windows = Windows::new(3, 3, mode)?;
        let mut state = State::new(false);
        for (i, &s) in SAMPLES.iter().enumerate() {
            if let Some(edge) = state.update(s != 0, &windows) {
                let edge = match edge {
                    Edge::Press => "press",
                    Edge::Release => "release",
                };
                println!("pin {name} {i} {edge}");
            }
        }
    }
    learner_lines()?;
    Ok(())
}

/// `learner_lines` of `examples/c/lines.h`, through the core's learner.
fn learner_lines() -> Result<(), contact_bounce::Error> {
    let prior = contact_bounce::LearnerPrior::at_period(31, 31, 1_000_000)?;
    let mut key = contact_bounce::LearningState::new(false);
    let mut x: u32 = 2_463_534_242;
    let mut next = || {
        x ^= x << 13;
        x ^= x >> 17;
        x ^= x << 5;
        x
    };
    let mut i = 0;
    for k in 0..80 {
        let down = 31 + next() % 40;
        let up = 31 + next() % 40;
        for j in 0..down + up {
            let closed = if j < down {
                !(j == 1 || (k % 5 == 4 && (8..20).contains(&j)))
            } else {
                j - down == 2
            };
            if let Some(edge) = key.update(closed, &prior) {
                let edge = match edge {
                    Edge::Press => "press",
                    Edge::Release => "release",
                };
                println!("learner {i} {edge}");
            }
            i += 1;
        }
    }
    let (press, release) = key.learned().windows(&prior);
    let flags = u8::from(key.learned().reverts_like_a_tap(&prior));
    println!("learner windows {press} {release} flags {flags}");
    let saved: Vec<String> = key
        .learned()
        .to_bytes()
        .iter()
        .map(ToString::to_string)
        .collect();
    println!("learner saved {}", saved.join(" "));
    Ok(())
}
