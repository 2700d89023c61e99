//! The host's exact reference (`contact-bounce-reference`, an event-driven simulation) on a
//! scene as the tool reads it: what the table mode, its plots and `eval --method reference` compare
//! the core's tiers with.

use contact_bounce::scene::Dissipation;
use contact_bounce_reference::{self as reference, OneBody};

use crate::scene::input::{FieldError, SceneInput, Spring};

/// The exact reference's input for one body with viscous damping (or none), from the core's
/// scene as the core validated it: the one place a scene crosses to the reference's
/// one-body simulation. (A kernel or a second body is not read here: see [`outcome`].)
pub(crate) fn one_body<D: contact_bounce::scene::Dissipation<f64>>(
    scene: &contact_bounce::Scene<f64, D>,
) -> OneBody {
    OneBody {
        omega: scene.omega(),
        delta: scene.delta(),
        restitution: scene.restitution(),
        zeta: scene.dissipation().damping_ratio(),
        closing_speed: scene.closing_speed(),
        threshold: scene.threshold_impulse(),
    }
}

/// The exact reference's outcome for a scene (one body, two bodies, or one body with a kernel).
///
/// # Errors
/// The field at fault, or the reference's failure (with an empty field).
pub fn outcome(input: &SceneInput) -> Result<reference::Outcome, FieldError> {
    if input.kernel.is_some() && matches!(input.spring, Spring::TwoBody(..)) {
        return Err(FieldError {
            field: "kernel".to_owned(),
            message: "the exact reference simulates a kernel on one body only".to_owned(),
        });
    }
    // Validate (and derive Omega, Delta, P_end) exactly as the core does.
    let scene = input.core::<f64>()?;
    let failed = |e: reference::Failure| FieldError {
        field: String::new(),
        message: e.to_string(),
    };
    let out = if let Some(kernel) = input.kernel {
        let k = reference::hereditary::Kernelled {
            omega: scene.omega(),
            zeta: scene.dissipation().damping_ratio(),
            delta: scene.delta(),
            restitution: scene.restitution(),
            closing_speed: scene.closing_speed(),
            kappa: kernel.kappa,
            tau: kernel.tau,
            state: kernel.state,
            threshold: scene.threshold_impulse(),
        };
        reference::hereditary::simulate(&k, reference::DEFAULT_BUDGET).map_err(failed)?
    } else if let Spring::TwoBody(b, x2, v2) = input.spring {
        let pair = reference::two_body::TwoBodies {
            m: [b.m1, b.m2],
            c: [b.c1, b.c2],
            d: [b.d1, b.d2],
            delta: scene.delta(),
            restitution: scene.restitution(),
            closing_speed: scene.closing_speed(),
            x2,
            v2,
            threshold: scene.threshold_impulse(),
        };
        reference::two_body::simulate(&pair, reference::DEFAULT_BUDGET).map_err(failed)?
    } else {
        reference::simulate(&one_body(&scene), reference::DEFAULT_BUDGET).map_err(failed)?
    };
    Ok(out)
}
