//! A C API for `contact-bounce`: predict a switch's bounce with one tier, turn it into a
//! debounce window in ticks, and debounce each pin, from C or C++ firmware.
//!
//! Build the static library (`libcontact_bounce_c.a`) for your target and include
//! `include/contact_bounce.h`, which is generated from this file and checked current by the
//! tests. Everything is single precision (`float`), as on Arduino-class boards.
//!
//! The rules, as in the Rust crate:
//! - Every invalid input gives a [`cb_error`] naming the parameter and the reason: a NULL
//!   pointer, NaN, infinity, a value out of its range. Nothing panics, nothing returns NaN.
//! - A switch is validated on every call that takes one (its cost is in the crate's cost
//!   report); `cb_switch_check` validates it once, to report a bad one at start-up.
//! - One function per tier, so a firmware links only the tiers it calls (with
//!   `-Wl,--gc-sections`, which the Arduino build uses).
//!
//! This crate holds no `unsafe` block: C pointers arrive as `Option<&T>` (NULL is `None`). The
//! only items the `unsafe_code` lint flags are the exported symbols (`#[no_mangle]`), each
//! allowed where it stands.
#![cfg_attr(any(target_os = "none", target_arch = "avr"), no_std)]
#![deny(unsafe_code)]
#![warn(missing_docs)]
// The C names are the API: `cb_switch`, `CB_OK`, ...
#![allow(non_camel_case_types)]

use contact_bounce::{
    debounce::learn::Learned,
    scene::{AnySign, OffsetSign, Preload, Regime},
    tiers::preload_restitution_bounce_seconds,
    tiers::preload_viscous_bounce_seconds,
    tiers::preload_viscous_bounce_time,
    tiers::AutoTiers,
    tiers::Tier,
    tiers::DEFAULT_MAX_IMPACTS,
    tiers::EXACT_MAX_IMPACTS,
    Contact, Edge, Error, Frequency, LearnerPrior, LearningState, Margin, Method, Mode, Nodes,
    Offset, Parameter, Prediction, Preloaded, Reason, Restitution, Scene, State, Threshold,
    Tolerance, Viscous, Window, Windows,
};

/// A panic cannot happen (the core and this crate have no panicking path); on a bare-metal
/// target a static library still needs a handler. It stops the core.
#[cfg(any(target_os = "none", target_arch = "avr"))]
#[panic_handler]
fn panic(_: &core::panic::PanicInfo) -> ! {
    loop {}
}

/// A switch in SI units: one moving contact (effective mass on a spring), its stop, the impact
/// law, viscous damping and how fast it closes.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct cb_switch {
    /// Effective (moving) mass, kg (> 0).
    pub mass: f32,
    /// Effective stiffness of the contact spring, N/m (> 0).
    pub stiffness: f32,
    /// Where the stop is from the spring's free rest position, m: a gap > 0, a preload < 0
    /// (preload force / stiffness), grazing 0.
    pub offset: f32,
    /// Coefficient of restitution R, in (0, 1].
    pub restitution: f32,
    /// Viscous damping ratio zeta (>= 0; 0 for none).
    pub damping_ratio: f32,
    /// Closing speed at the first impact, m/s (> 0).
    pub closing_speed: f32,
    /// The impacts that count: those whose impulse is above this fraction of the first, in
    /// (0, 1); 0 for no threshold (then a regime that never ends by itself is an error).
    pub threshold_fraction: f32,
}

/// Which parameter an error names (`CB_PARAM_NONE` when there is no error).
#[repr(u8)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum cb_parameter {
    /// No parameter: no error.
    CB_PARAM_NONE = 0,
    /// A pointer argument was NULL.
    CB_PARAM_POINTER,
    /// `mass`.
    CB_PARAM_MASS,
    /// `stiffness`.
    CB_PARAM_STIFFNESS,
    /// `offset`.
    CB_PARAM_OFFSET,
    /// `restitution`.
    CB_PARAM_RESTITUTION,
    /// `damping_ratio`.
    CB_PARAM_DAMPING_RATIO,
    /// `closing_speed`.
    CB_PARAM_CLOSING_SPEED,
    /// `threshold_fraction`.
    CB_PARAM_THRESHOLD,
    /// The tolerance asked of `cb_predict_auto`.
    CB_PARAM_TOLERANCE,
    /// A window's margin factor.
    CB_PARAM_MARGIN_FACTOR,
    /// A window's extra time.
    CB_PARAM_MARGIN_EXTRA,
    /// The sample (tick) period.
    CB_PARAM_SAMPLE_PERIOD,
    /// A time: the bounce a window must cover, or a window in ticks.
    CB_PARAM_TIME,
    /// The debouncer's mode.
    CB_PARAM_MODE,
    /// The preload force of `cb_preload_viscous_bounce_time`.
    CB_PARAM_PRELOAD_FORCE,
    /// A parameter this header does not know (a newer core).
    CB_PARAM_OTHER,
}

/// Why (`CB_OK` when there is no error).
#[repr(u8)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum cb_code {
    /// No error.
    CB_OK = 0,
    /// A pointer argument was NULL.
    CB_ERR_NULL,
    /// NaN.
    CB_ERR_NAN,
    /// Infinite.
    CB_ERR_INFINITE,
    /// Must be > 0.
    CB_ERR_NOT_POSITIVE,
    /// Must be >= 0.
    CB_ERR_NEGATIVE,
    /// Outside its allowed interval.
    CB_ERR_OUT_OF_RANGE,
    /// The regime never ends by itself: give a threshold.
    CB_ERR_THRESHOLD_REQUIRED,
    /// Valid alone, but it overflows (or loses all precision) with the other parameters.
    CB_ERR_OVERFLOW,
    /// The threshold is at or above the first impulse: no impact would count.
    CB_ERR_ABOVE_FIRST_IMPULSE,
    /// The bounce never ends, so no finite window exists.
    CB_ERR_ENDLESS,
    /// A reason this header does not know (a newer core).
    CB_ERR_OTHER,
}

/// An error: which parameter, and why, in 16 bits: the `cb_code` in the low byte, the
/// `cb_parameter` in the high byte (`CB_ERROR_CODE(e)`, `CB_ERROR_PARAMETER(e)`). 0 (`CB_OK`)
/// means success.
///
/// An integer, not a struct: a small struct returned by value is where compilers for the
/// small targets (avr-gcc and rustc on the ATmega328P) disagree on the ABI, and any 16 bits
/// from C are a valid `cb_error` on the Rust side.
#[repr(transparent)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct cb_error(pub u16);

impl cb_error {
    const fn new(code: cb_code, parameter: cb_parameter) -> Self {
        Self(((parameter as u16) << 8) | code as u16)
    }

    /// The `cb_code`.
    #[must_use]
    pub const fn code(self) -> u8 {
        self.0.to_le_bytes()[0]
    }

    /// The `cb_parameter`.
    #[must_use]
    pub const fn parameter(self) -> u8 {
        self.0.to_le_bytes()[1]
    }
}

const OK: cb_error = cb_error::new(cb_code::CB_OK, cb_parameter::CB_PARAM_NONE);

const NULL: cb_error = cb_error::new(cb_code::CB_ERR_NULL, cb_parameter::CB_PARAM_POINTER);

impl From<Error> for cb_error {
    fn from(e: Error) -> Self {
        let parameter = match e.parameter() {
            Parameter::Mass => cb_parameter::CB_PARAM_MASS,
            Parameter::Stiffness => cb_parameter::CB_PARAM_STIFFNESS,
            Parameter::Delta => cb_parameter::CB_PARAM_OFFSET,
            Parameter::Restitution | Parameter::OneMinusRestitution => {
                cb_parameter::CB_PARAM_RESTITUTION
            }
            Parameter::DampingRatio => cb_parameter::CB_PARAM_DAMPING_RATIO,
            Parameter::ClosingSpeed => cb_parameter::CB_PARAM_CLOSING_SPEED,
            Parameter::ThresholdFraction | Parameter::ThresholdImpulse | Parameter::Threshold => {
                cb_parameter::CB_PARAM_THRESHOLD
            }
            Parameter::Tolerance => cb_parameter::CB_PARAM_TOLERANCE,
            Parameter::MarginFactor => cb_parameter::CB_PARAM_MARGIN_FACTOR,
            Parameter::MarginExtra => cb_parameter::CB_PARAM_MARGIN_EXTRA,
            Parameter::SamplePeriod => cb_parameter::CB_PARAM_SAMPLE_PERIOD,
            Parameter::Time => cb_parameter::CB_PARAM_TIME,
            Parameter::PreloadForce => cb_parameter::CB_PARAM_PRELOAD_FORCE,
            _ => cb_parameter::CB_PARAM_OTHER,
        };
        let code = match e.reason() {
            Reason::NotANumber => cb_code::CB_ERR_NAN,
            Reason::Infinite => cb_code::CB_ERR_INFINITE,
            Reason::NotPositive => cb_code::CB_ERR_NOT_POSITIVE,
            Reason::Negative => cb_code::CB_ERR_NEGATIVE,
            Reason::OutOfRange => cb_code::CB_ERR_OUT_OF_RANGE,
            Reason::Required => cb_code::CB_ERR_THRESHOLD_REQUIRED,
            Reason::Overflow => cb_code::CB_ERR_OVERFLOW,
            Reason::AboveFirstImpulse => cb_code::CB_ERR_ABOVE_FIRST_IMPULSE,
            Reason::Endless => cb_code::CB_ERR_ENDLESS,
            _ => cb_code::CB_ERR_OTHER,
        };
        Self::new(code, parameter)
    }
}

/// Every `cb_parameter`, in the order of its values.
const PARAMETERS: [(cb_parameter, &core::ffi::CStr); 17] = [
    (cb_parameter::CB_PARAM_NONE, c"none"),
    (cb_parameter::CB_PARAM_POINTER, c"pointer"),
    (cb_parameter::CB_PARAM_MASS, c"mass"),
    (cb_parameter::CB_PARAM_STIFFNESS, c"stiffness"),
    (cb_parameter::CB_PARAM_OFFSET, c"offset"),
    (cb_parameter::CB_PARAM_RESTITUTION, c"restitution"),
    (cb_parameter::CB_PARAM_DAMPING_RATIO, c"damping_ratio"),
    (cb_parameter::CB_PARAM_CLOSING_SPEED, c"closing_speed"),
    (cb_parameter::CB_PARAM_THRESHOLD, c"threshold_fraction"),
    (cb_parameter::CB_PARAM_TOLERANCE, c"tolerance"),
    (cb_parameter::CB_PARAM_MARGIN_FACTOR, c"margin_factor"),
    (cb_parameter::CB_PARAM_MARGIN_EXTRA, c"margin_extra"),
    (cb_parameter::CB_PARAM_SAMPLE_PERIOD, c"sample_period"),
    (cb_parameter::CB_PARAM_TIME, c"time"),
    (cb_parameter::CB_PARAM_MODE, c"mode"),
    (cb_parameter::CB_PARAM_PRELOAD_FORCE, c"preload_force"),
    (cb_parameter::CB_PARAM_OTHER, c"other"),
];

/// The name of a `cb_parameter` as `cb_switch` and the functions spell it (a static,
/// NUL-terminated string); "unknown" for a value that is no `cb_parameter`.
#[allow(unsafe_code)]
#[no_mangle]
pub extern "C" fn cb_parameter_name(parameter: u8) -> *const core::ffi::c_char {
    PARAMETERS
        .iter()
        .find(|(p, _)| *p as u8 == parameter)
        .map_or(c"unknown", |(_, name)| name)
        .as_ptr()
}

/// The switch as the core's contact and damping (the damping ratio checked).
fn parts(switch: &cb_switch) -> Result<(Contact<f32>, Option<Viscous<f32>>), Error> {
    let threshold = if switch.threshold_fraction == 0.0 {
        Threshold::None
    } else {
        Threshold::FractionOfFirst(switch.threshold_fraction)
    };
    let contact = Contact {
        frequency: Frequency::MassStiffness {
            mass: switch.mass,
            stiffness: switch.stiffness,
        },
        offset: Offset::Delta(switch.offset),
        restitution: Restitution::Coefficient(switch.restitution),
        closing_speed: switch.closing_speed,
        threshold,
    };
    Ok((contact, Viscous::optional(switch.damping_ratio)?))
}

/// A `cb_switch` as the core's scene, its sign of offset typed by `S`.
type SwitchScene<S = AnySign> = Scene<f32, Option<Viscous<f32>>, S>;

/// The switch as the core's scene, validated.
fn scene(switch: &cb_switch) -> Result<SwitchScene, Error> {
    parts(switch).and_then(|(contact, damping)| Scene::new(contact, damping))
}

/// The switch as a preloaded scene (`Scene::new_preload`: a gap or offset 0 is refused, naming
/// the offset), validated.
fn preload_scene(switch: &cb_switch) -> Result<SwitchScene<Preload>, Error> {
    parts(switch).and_then(|(contact, damping)| Scene::new_preload(contact, damping))
}

/// Validates a switch: `CB_OK`, or the first invalid parameter and why.
#[allow(unsafe_code)]
#[no_mangle]
pub extern "C" fn cb_switch_check(sw: Option<&cb_switch>) -> cb_error {
    match sw.map(scene) {
        None => NULL,
        Some(Ok(_)) => OK,
        Some(Err(e)) => e.into(),
    }
}

/// How the bounce behaves over time.
#[repr(u8)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum cb_regime {
    /// Infinitely many impacts in a finite time, then the contact stays closed.
    CB_REGIME_ZENO = 0,
    /// Finitely many impacts; the last one ends the bounce.
    CB_REGIME_LAST_IMPACT,
    /// Impacts decay but never end: the threshold ends the bounce.
    CB_REGIME_ENDLESS,
    /// No dissipation: constant impacts forever.
    CB_REGIME_PERIODIC,
    /// The contact separates once and never returns.
    CB_REGIME_SINGLE_IMPACT,
    /// A regime this header does not know (a newer core).
    CB_REGIME_OTHER,
}

/// Which tier answered.
#[repr(u8)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum cb_tier {
    /// The regime alone answered.
    CB_TIER_REGIME = 0,
    /// A closed form.
    CB_TIER_CLOSED,
    /// The averaged model.
    CB_TIER_AVERAGED,
    /// The semi-discrete map.
    CB_TIER_MAP,
    /// The exact solution.
    CB_TIER_EXACT,
    /// A tier this header does not know (a newer core).
    CB_TIER_OTHER,
}

/// `cb_prediction.flags`: the end time is finite.
pub const CB_HAS_END: u8 = 1;
/// `cb_prediction.flags`: the last impact above the threshold is at a finite time.
pub const CB_HAS_LAST_ABOVE: u8 = 2;
/// `cb_prediction.flags`: the count of impacts above the threshold is finite.
pub const CB_HAS_COUNT: u8 = 4;
/// `cb_prediction.flags`: the expected relative error is known (the scene is within the
/// tier's stated validity).
pub const CB_HAS_EXPECTED_ERROR: u8 = 8;

/// A prediction. A field whose flag is not set is 0 and means nothing.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct cb_prediction {
    /// When the bounce ends, s after the first impact (`CB_HAS_END`).
    pub end_time: f32,
    /// When the last impact above the threshold happens, s (`CB_HAS_LAST_ABOVE`).
    pub last_above_time: f32,
    /// How many impacts are above the threshold (`CB_HAS_COUNT`; a real number for the
    /// averaged tier).
    pub impacts_above: f32,
    /// The relative error to expect of the bounce time (`CB_HAS_EXPECTED_ERROR`).
    pub expected_error: f32,
    /// The regime: a `cb_regime`.
    pub regime: u8,
    /// The tier that answered: a `cb_tier`.
    pub tier: u8,
    /// `CB_HAS_*` bits.
    pub flags: u8,
}

impl From<&Prediction<f32>> for cb_prediction {
    fn from(p: &Prediction<f32>) -> Self {
        let mut flags = 0;
        let mut take = |v: Option<f32>, flag: u8| {
            v.map_or(0.0, |v| {
                flags |= flag;
                v
            })
        };
        let end_time = take(p.end_time.seconds(), CB_HAS_END);
        let last_above_time = take(p.last_above_time.seconds(), CB_HAS_LAST_ABOVE);
        let impacts_above = take(p.impacts_above.value(), CB_HAS_COUNT);
        let expected_error = take(p.expected_error, CB_HAS_EXPECTED_ERROR);
        Self {
            end_time,
            last_above_time,
            impacts_above,
            expected_error,
            regime: match p.regime {
                Regime::ZenoAccumulation => cb_regime::CB_REGIME_ZENO,
                Regime::LastImpact => cb_regime::CB_REGIME_LAST_IMPACT,
                Regime::Endless => cb_regime::CB_REGIME_ENDLESS,
                Regime::Periodic => cb_regime::CB_REGIME_PERIODIC,
                Regime::SingleImpact => cb_regime::CB_REGIME_SINGLE_IMPACT,
                _ => cb_regime::CB_REGIME_OTHER,
            } as u8,
            tier: match p.tier {
                Tier::Regime => cb_tier::CB_TIER_REGIME,
                Tier::Closed(_) => cb_tier::CB_TIER_CLOSED,
                Tier::Averaged(_) => cb_tier::CB_TIER_AVERAGED,
                Tier::Map => cb_tier::CB_TIER_MAP,
                Tier::Exact => cb_tier::CB_TIER_EXACT,
                _ => cb_tier::CB_TIER_OTHER,
            } as u8,
            flags,
        }
    }
}

/// Validates the switch, predicts with `method` and writes the prediction.
fn predict(
    sw: Option<&cb_switch>,
    out: Option<&mut cb_prediction>,
    method: impl FnOnce() -> Result<Method<f32>, Error>,
) -> cb_error {
    predict_with(sw, out, |s| Ok(s.predict(method()?)))
}

/// Validates the switch and writes the prediction `how` gives of its scene.
fn predict_with(
    sw: Option<&cb_switch>,
    out: Option<&mut cb_prediction>,
    how: impl FnOnce(&SwitchScene) -> Result<Prediction<f32>, Error>,
) -> cb_error {
    let (Some(sw), Some(out)) = (sw, out) else {
        return NULL;
    };
    match scene(sw).and_then(|s| how(&s)) {
        Ok(p) => {
            *out = (&p).into();
            OK
        }
        Err(e) => e.into(),
    }
}

/// The closed forms: the cheapest tier (exact sums without damping, `t_b1v` / `t_b2r` with it).
#[allow(unsafe_code)]
#[no_mangle]
pub extern "C" fn cb_predict_closed(
    sw: Option<&cb_switch>,
    out: Option<&mut cb_prediction>,
) -> cb_error {
    predict(sw, out, || Ok(Method::Closed))
}

/// The averaged model J' = E1(J), 8 Gauss-Legendre nodes per panel.
#[allow(unsafe_code)]
#[no_mangle]
pub extern "C" fn cb_predict_averaged(
    sw: Option<&cb_switch>,
    out: Option<&mut cb_prediction>,
) -> cb_error {
    predict(sw, out, || Ok(Method::Averaged(Nodes::N8)))
}

/// The semi-discrete map, impact by impact (the averaged model beyond its default cap).
#[allow(unsafe_code)]
#[no_mangle]
pub extern "C" fn cb_predict_map(
    sw: Option<&cb_switch>,
    out: Option<&mut cb_prediction>,
) -> cb_error {
    predict(sw, out, || {
        Ok(Method::Map {
            max_impacts: DEFAULT_MAX_IMPACTS,
        })
    })
}

/// The exact solution, flight by flight: expected error at the float's rounding.
#[allow(unsafe_code)]
#[no_mangle]
pub extern "C" fn cb_predict_exact(
    sw: Option<&cb_switch>,
    out: Option<&mut cb_prediction>,
) -> cb_error {
    predict(sw, out, || {
        Ok(Method::Exact {
            max_impacts: EXACT_MAX_IMPACTS,
        })
    })
}

/// The cheapest tier whose expected error is within `tolerance` (relative, e.g. 0.01); every
/// tier is linked. Check `expected_error` against the tolerance: where nothing meets it the
/// smallest expected error answers.
#[allow(unsafe_code)]
#[no_mangle]
pub extern "C" fn cb_predict_auto(
    sw: Option<&cb_switch>,
    tolerance: f32,
    out: Option<&mut cb_prediction>,
) -> cb_error {
    predict(sw, out, || Ok(Method::Auto(Tolerance::new(tolerance)?)))
}

/// As `cb_predict_auto`, weighing only the exact tier after the closed forms: the closed forms
/// where they meet `tolerance`, else the exact tier (which does on every one-body switch). No
/// map and no averaged quadrature are linked (beyond the exact tier's rest past its cap):
/// in Rust firmware 4.2-4.5 KB less than Auto among every tier on Cortex-M and 9.8 KB less on the
/// Uno (`docs/reports/cost-report.md`, auto-exact).
#[allow(unsafe_code)]
#[no_mangle]
pub extern "C" fn cb_predict_auto_exact(
    sw: Option<&cb_switch>,
    tolerance: f32,
    out: Option<&mut cb_prediction>,
) -> cb_error {
    predict_with(sw, out, |s| {
        Ok(s.predict_auto_among::<{ AutoTiers::EXACT }>(Tolerance::new(tolerance)?))
    })
}

/// Validates the switch and writes its bounce time by `method` (`Scene::bounce_time`). Always
/// inlined: each caller's method is a constant, so it links its tier alone.
#[allow(clippy::inline_always)]
#[inline(always)]
fn bounce_seconds(
    sw: Option<&cb_switch>,
    seconds: Option<&mut f32>,
    method: Method<f32>,
) -> cb_error {
    seconds_of(sw, seconds, method, scene)
}

/// As `bounce_seconds`, for a preloaded switch (its scene typed `Preload`).
#[allow(clippy::inline_always)]
#[inline(always)]
fn preload_seconds(
    sw: Option<&cb_switch>,
    seconds: Option<&mut f32>,
    method: Method<f32>,
) -> cb_error {
    seconds_of(sw, seconds, method, preload_scene)
}

/// Validates the switch by `build` and writes its bounce time by `method`.
#[allow(clippy::inline_always)]
#[inline(always)]
fn seconds_of<S: OffsetSign>(
    sw: Option<&cb_switch>,
    seconds: Option<&mut f32>,
    method: Method<f32>,
    build: fn(&cb_switch) -> Result<SwitchScene<S>, Error>,
) -> cb_error {
    let (Some(sw), Some(seconds)) = (sw, seconds) else {
        return NULL;
    };
    // (A match, not a closure: one closure type would be shared by every caller, and its one
    // instance would take the method at run time and link every tier.)
    let time = match build(sw) {
        Ok(s) => s
            .bounce_time(method)
            .ok_or(Error::new(Parameter::Time, Reason::Endless)),
        Err(e) => Err(e),
    };
    match time {
        Ok(t) => {
            *seconds = t;
            OK
        }
        Err(e) => e.into(),
    }
}

/// The bounce a window must cover (its end, else its last impact above the threshold), s, by
/// the closed forms: what `cb_predict_closed` gives, without the counts and the expected error
/// (a firmware that calls only this links neither). `cb_seconds_to_ticks` makes it a window.
#[allow(unsafe_code)]
#[no_mangle]
pub extern "C" fn cb_bounce_seconds_closed(
    sw: Option<&cb_switch>,
    seconds: Option<&mut f32>,
) -> cb_error {
    bounce_seconds(sw, seconds, Method::Closed)
}

/// The bounce time by the averaged model, as `cb_bounce_seconds_closed`.
#[allow(unsafe_code)]
#[no_mangle]
pub extern "C" fn cb_bounce_seconds_averaged(
    sw: Option<&cb_switch>,
    seconds: Option<&mut f32>,
) -> cb_error {
    bounce_seconds(sw, seconds, Method::Averaged(Nodes::N8))
}

/// The bounce time by the map, as `cb_bounce_seconds_closed`.
#[allow(unsafe_code)]
#[no_mangle]
pub extern "C" fn cb_bounce_seconds_map(
    sw: Option<&cb_switch>,
    seconds: Option<&mut f32>,
) -> cb_error {
    bounce_seconds(
        sw,
        seconds,
        Method::Map {
            max_impacts: DEFAULT_MAX_IMPACTS,
        },
    )
}

/// The bounce time by the exact solution, as `cb_bounce_seconds_closed`.
#[allow(unsafe_code)]
#[no_mangle]
pub extern "C" fn cb_bounce_seconds_exact(
    sw: Option<&cb_switch>,
    seconds: Option<&mut f32>,
) -> cb_error {
    bounce_seconds(
        sw,
        seconds,
        Method::Exact {
            max_impacts: EXACT_MAX_IMPACTS,
        },
    )
}

/// The bounce time of a preloaded switch (`offset` < 0) by the closed forms: as
/// `cb_bounce_seconds_closed`, but a gap or an offset of 0 is `CB_PARAM_OFFSET` /
/// `CB_ERR_OUT_OF_RANGE`, and no gap's code is linked (on the Uno the closed, averaged and map
/// tiers fit from C only this way, and the exact tier not even so: `docs/reports/c-api-uno.md`).
#[allow(unsafe_code)]
#[no_mangle]
pub extern "C" fn cb_preload_seconds_closed(
    sw: Option<&cb_switch>,
    seconds: Option<&mut f32>,
) -> cb_error {
    preload_seconds(sw, seconds, Method::Closed)
}

/// The bounce time of a preloaded switch by the averaged model, as `cb_preload_seconds_closed`.
#[allow(unsafe_code)]
#[no_mangle]
pub extern "C" fn cb_preload_seconds_averaged(
    sw: Option<&cb_switch>,
    seconds: Option<&mut f32>,
) -> cb_error {
    preload_seconds(sw, seconds, Method::Averaged(Nodes::N8))
}

/// The bounce time of a preloaded switch by the map, as `cb_preload_seconds_closed`.
#[allow(unsafe_code)]
#[no_mangle]
pub extern "C" fn cb_preload_seconds_map(
    sw: Option<&cb_switch>,
    seconds: Option<&mut f32>,
) -> cb_error {
    preload_seconds(
        sw,
        seconds,
        Method::Map {
            max_impacts: DEFAULT_MAX_IMPACTS,
        },
    )
}

/// The bounce time of a preloaded switch by the exact solution, as `cb_preload_seconds_closed`.
#[allow(unsafe_code)]
#[no_mangle]
pub extern "C" fn cb_preload_seconds_exact(
    sw: Option<&cb_switch>,
    seconds: Option<&mut f32>,
) -> cb_error {
    preload_seconds(
        sw,
        seconds,
        Method::Exact {
            max_impacts: EXACT_MAX_IMPACTS,
        },
    )
}

/// Writes `ceil((margin_factor * seconds + margin_extra) / sample_period)` to `ticks`.
// Always inlined: called with its five arguments, the last goes on the stack on AVR, and
// `cb_seconds_to_ticks` built by rustc for avr-none then read a wrong pointer or period and
// reported an overflow for every input on the Uno (scripts/c-api.sh checks it there).
#[allow(clippy::inline_always)]
#[inline(always)]
fn ticks_for(
    seconds: Option<f32>,
    margin_factor: f32,
    margin_extra: f32,
    sample_period: f32,
    ticks: &mut u32,
) -> cb_error {
    let window = seconds
        .ok_or(Error::new(Parameter::Time, Reason::Endless))
        .and_then(|s| {
            Window::from_seconds(s, &Margin::new(margin_factor, margin_extra)?, sample_period)
        });
    match window {
        Ok(w) => {
            *ticks = w.ticks();
            OK
        }
        Err(e) => e.into(),
    }
}

/// The debounce window covering a prediction's bounce (its end, else its last impact above the
/// threshold) in ticks of `sample_period` seconds: `ceil((margin_factor * bounce +
/// margin_extra) / sample_period)`, at least 1 for a positive bounce. `margin_factor` >= 1,
/// `margin_extra` >= 0 s.
#[allow(unsafe_code)]
#[no_mangle]
pub extern "C" fn cb_window_ticks(
    prediction: Option<&cb_prediction>,
    margin_factor: f32,
    margin_extra: f32,
    sample_period: f32,
    ticks: Option<&mut u32>,
) -> cb_error {
    let (Some(p), Some(ticks)) = (prediction, ticks) else {
        return NULL;
    };
    let bounce = if p.flags & CB_HAS_END != 0 {
        Some(p.end_time)
    } else if p.flags & CB_HAS_LAST_ABOVE != 0 {
        Some(p.last_above_time)
    } else {
        None
    };
    ticks_for(bounce, margin_factor, margin_extra, sample_period, ticks)
}

/// The window covering `seconds` of bounce, as `cb_window_ticks` (for `cb_preload_viscous_bounce_time`).
#[allow(unsafe_code)]
#[no_mangle]
pub extern "C" fn cb_seconds_to_ticks(
    seconds: f32,
    margin_factor: f32,
    margin_extra: f32,
    sample_period: f32,
    ticks: Option<&mut u32>,
) -> cb_error {
    match ticks {
        Some(ticks) => ticks_for(
            Some(seconds),
            margin_factor,
            margin_extra,
            sample_period,
            ticks,
        ),
        None => NULL,
    }
}

/// A closed-form estimate: the time and the relative error to expect of it.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct cb_estimate {
    /// The bounce time, s.
    pub time: f32,
    /// The relative error to expect (`has_expected_error`), else 0.
    pub expected_error: f32,
    /// Whether the inputs are within the formula's stated validity (1) or not (0).
    pub has_expected_error: u8,
}

/// A preloaded switch for the lean paths, in SI units: the six numbers of the Rust crate's
/// `Preloaded`, in its order (mass, stiffness, preload force, closing speed, restitution,
/// damping ratio). Fill it by name (`.closing_speed = 0.5f`): the lean functions took six
/// loose floats before, in another order than Rust's, where a swap compiled and gave a wrong
/// time.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct cb_preloaded {
    /// Effective (moving) mass, kg (> 0).
    pub mass: f32,
    /// Effective stiffness of the contact spring, N/m (> 0).
    pub stiffness: f32,
    /// Contact (preload) force at rest, N (> 0).
    pub preload_force: f32,
    /// Closing speed at the first impact, m/s (> 0).
    pub closing_speed: f32,
    /// Coefficient of restitution R, in (0, 1).
    pub restitution: f32,
    /// Viscous damping ratio zeta (>= 0; 0 for none).
    pub damping_ratio: f32,
}

impl From<&cb_preloaded> for Preloaded<f32> {
    #[inline]
    fn from(p: &cb_preloaded) -> Self {
        Preloaded {
            mass: p.mass,
            stiffness: p.stiffness,
            preload_force: p.preload_force,
            closing_speed: p.closing_speed,
            restitution: p.restitution,
            damping_ratio: p.damping_ratio,
        }
    }
}

/// The lean path: a preloaded contact's bounce time `t_b1v` (restitution and viscous damping;
/// `damping_ratio` 0 gives `t_b1`) straight from its inputs, with no scene and no tier: the
/// smallest firmware (about 4 KB of the Uno's flash from C, a tier through this API 17 KB and
/// more: `docs/reports/c-api-uno.md`). Expected error within 2.5 % plus the arctangent linearisation
/// for a small first impulse; the estimate says when the inputs are beyond that. Rust's
/// `tiers::preload_viscous_bounce_time`.
#[allow(unsafe_code)]
#[no_mangle]
pub extern "C" fn cb_preload_viscous_bounce_time(
    sw: Option<&cb_preloaded>,
    out: Option<&mut cb_estimate>,
) -> cb_error {
    let (Some(sw), Some(out)) = (sw, out) else {
        return NULL;
    };
    match preload_viscous_bounce_time(&sw.into()) {
        Ok(e) => {
            *out = cb_estimate {
                time: e.time,
                expected_error: e.expected_error.unwrap_or(0.0),
                has_expected_error: u8::from(e.expected_error.is_some()),
            };
            OK
        }
        Err(e) => e.into(),
    }
}

/// The lean path's time alone: `t_b1v` (s) as `cb_preload_viscous_bounce_time` computes it (the
/// same value, the same errors), without its expected error, into `seconds`: for firmware that
/// sets its margin itself (`cb_seconds_to_ticks`). Rust's
/// `tiers::preload_viscous_bounce_seconds`.
#[allow(unsafe_code)]
#[no_mangle]
pub extern "C" fn cb_preload_viscous_bounce_seconds(
    sw: Option<&cb_preloaded>,
    seconds: Option<&mut f32>,
) -> cb_error {
    let Some(sw) = sw else {
        return NULL;
    };
    seconds_into(seconds, || preload_viscous_bounce_seconds(&sw.into()))
}

/// A lean path's time into `out` (NULL: an error, and nothing computed).
fn seconds_into(out: Option<&mut f32>, time: impl FnOnce() -> Result<f32, Error>) -> cb_error {
    let Some(out) = out else {
        return NULL;
    };
    match time() {
        Ok(t) => {
            *out = t;
            OK
        }
        Err(e) => e.into(),
    }
}

/// The lean averaged path: a preloaded contact's bounce (s) under restitution alone, the averaged
/// model's time in closed form, straight from its inputs, with no scene and no expected error,
/// into `seconds` (for a first impulse up to the preload's scale, j0 <= 1, long by at most 4.7 %
/// at R = 0.05 and 1.7 % from R = 0.5; the averaged tier's expected error needs a scene). Its
/// `damping_ratio` must be 0 (`CB_PARAM_DAMPING_RATIO` / `CB_ERR_OUT_OF_RANGE` otherwise: the
/// path has no damping). Rust's `tiers::preload_restitution_bounce_seconds`.
#[allow(unsafe_code)]
#[no_mangle]
pub extern "C" fn cb_preload_restitution_bounce_seconds(
    sw: Option<&cb_preloaded>,
    seconds: Option<&mut f32>,
) -> cb_error {
    let Some(sw) = sw else {
        return NULL;
    };
    seconds_into(seconds, || preload_restitution_bounce_seconds(&sw.into()))
}

/// How a debounce window is used.
#[repr(u8)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum cb_mode {
    /// Report a change after the new level has held for the window.
    CB_MODE_CONFIRM = 0,
    /// Report a change at once, then ignore the pin for the window.
    CB_MODE_HOLD_OFF,
}

/// Press and release windows in samples, shared by every pin of one kind of switch. Fill it
/// with `cb_windows_init`.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct cb_windows {
    /// Press window, samples (at most `CB_MAX_WINDOW_TICKS`).
    pub press: u16,
    /// Release window, samples (at most `CB_MAX_WINDOW_TICKS`).
    pub release: u16,
    /// How the windows are used: a `cb_mode`.
    pub mode: u8,
}

/// The longest window in samples.
pub const CB_MAX_WINDOW_TICKS: u16 = 0x7FFF;
const _: () = assert!(CB_MAX_WINDOW_TICKS == Windows::MAX_TICKS);

/// The core's windows; an error when the mode is no `cb_mode` or a window is too long.
fn windows(w: cb_windows) -> Result<Windows, cb_error> {
    let mode = match w.mode {
        m if m == cb_mode::CB_MODE_CONFIRM as u8 => Mode::Confirm,
        m if m == cb_mode::CB_MODE_HOLD_OFF as u8 => Mode::HoldOff,
        _ => {
            return Err(cb_error::new(
                cb_code::CB_ERR_OUT_OF_RANGE,
                cb_parameter::CB_PARAM_MODE,
            ))
        }
    };
    Windows::new(w.press, w.release, mode).map_err(cb_error::from)
}

/// Fills `out` with windows of `press` and `release` samples (each at most
/// `CB_MAX_WINDOW_TICKS`, else `CB_PARAM_TIME` out of range).
#[allow(unsafe_code)]
#[no_mangle]
pub extern "C" fn cb_windows_init(
    out: Option<&mut cb_windows>,
    press: u32,
    release: u32,
    mode: u8,
) -> cb_error {
    let Some(out) = out else {
        return NULL;
    };
    let ticks = |t: u32| {
        u16::try_from(t).map_err(|_| Error::new(Parameter::Time, Reason::OutOfRange).into())
    };
    let candidate = ticks(press).and_then(|p| {
        let w = cb_windows {
            press: p,
            release: ticks(release)?,
            mode,
        };
        windows(w).map(|_| w)
    });
    match candidate {
        Ok(w) => {
            *out = w;
            OK
        }
        Err(e) => e,
    }
}

/// One pin's debouncer state: 2 bytes. Set it with `cb_pin_init`.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct cb_pin {
    /// The state; not to be read or written by the caller.
    pub state: u16,
}

/// What a sample debounced to.
#[repr(u8)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum cb_edge {
    /// No change.
    CB_EDGE_NONE = 0,
    /// The contact closed.
    CB_EDGE_PRESS,
    /// The contact opened.
    CB_EDGE_RELEASE,
    /// An argument was NULL or the windows were not made by `cb_windows_init`: the pin is
    /// unchanged.
    CB_EDGE_ERROR,
}

/// A pin settled closed (`closed` true) or open.
#[allow(unsafe_code)]
#[no_mangle]
pub extern "C" fn cb_pin_init(pin: Option<&mut cb_pin>, closed: bool) -> cb_error {
    match pin {
        Some(pin) => {
            *pin = cb_pin {
                state: State::new(closed).to_bits(),
            };
            OK
        }
        None => NULL,
    }
}

/// Feeds one sample (`closed`: the contact reads closed) and returns the edge it debounces.
#[allow(unsafe_code)]
#[no_mangle]
pub extern "C" fn cb_pin_update(
    pin: Option<&mut cb_pin>,
    closed: bool,
    windows: Option<&cb_windows>,
) -> cb_edge {
    let (Some(pin), Some(w)) = (pin, windows) else {
        return cb_edge::CB_EDGE_ERROR;
    };
    let Ok(w) = self::windows(*w) else {
        return cb_edge::CB_EDGE_ERROR;
    };
    let mut state = State::from_bits(pin.state);
    let edge = state.update(closed, &w);
    pin.state = state.to_bits();
    match edge {
        None => cb_edge::CB_EDGE_NONE,
        Some(Edge::Press) => cb_edge::CB_EDGE_PRESS,
        Some(Edge::Release) => cb_edge::CB_EDGE_RELEASE,
    }
}

/// Whether the pin is debounced closed.
#[allow(unsafe_code)]
#[no_mangle]
pub extern "C" fn cb_pin_is_closed(pin: Option<&cb_pin>) -> bool {
    pin.is_some_and(|p| State::from_bits(p.state).is_closed())
}

/// What a learning debouncer starts from, in samples: the prior press and release windows and
/// the fastest real tap (a change that lasts that long is always reported; no window is
/// longer). Set it with `cb_learner_prior_init` or `cb_learner_prior_at_period`.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct cb_learner_prior {
    /// Prior press window, samples (1 to `CB_MAX_WINDOW_TICKS`).
    pub press: u16,
    /// Prior release window, samples (1 to `CB_MAX_WINDOW_TICKS`).
    pub release: u16,
    /// The fastest real tap, samples (1 to `CB_MAX_WINDOW_TICKS`).
    pub fastest_tap: u16,
}

/// The fastest real tap by default, nanoseconds: 16 taps a second, 31 ms down and 31 ms up.
pub const CB_FASTEST_TAP_NS: u32 = 31_000_000;
const _: () = assert!(CB_FASTEST_TAP_NS == contact_bounce::debounce::learn::FASTEST_TAP_NS);

fn learner_prior(p: cb_learner_prior) -> Result<LearnerPrior, cb_error> {
    LearnerPrior::new(p.press, p.release, p.fastest_tap).map_err(cb_error::from)
}

/// A learner's prior from windows and a fastest tap in samples. `CB_ERR_NOT_POSITIVE` for a 0,
/// `CB_ERR_OUT_OF_RANGE` above `CB_MAX_WINDOW_TICKS` (both naming `CB_PARAM_TIME`); `out` is
/// written only on success.
#[allow(unsafe_code)]
#[no_mangle]
pub extern "C" fn cb_learner_prior_init(
    out: Option<&mut cb_learner_prior>,
    press: u16,
    release: u16,
    fastest_tap: u16,
) -> cb_error {
    let Some(out) = out else {
        return NULL;
    };
    match LearnerPrior::new(press, release, fastest_tap) {
        Ok(_) => {
            *out = cb_learner_prior {
                press,
                release,
                fastest_tap,
            };
            OK
        }
        Err(e) => e.into(),
    }
}

/// A learner's prior from windows in samples of `period_ns` nanoseconds, with the default
/// fastest tap (`CB_FASTEST_TAP_NS`) in whole samples of that period. Errors as
/// `cb_learner_prior_init`, and `CB_PARAM_SAMPLE_PERIOD` for a period of 0 or one longer than
/// the tap; `out` is written only on success.
#[allow(unsafe_code)]
#[no_mangle]
pub extern "C" fn cb_learner_prior_at_period(
    out: Option<&mut cb_learner_prior>,
    press: u16,
    release: u16,
    period_ns: u32,
) -> cb_error {
    let Some(out) = out else {
        return NULL;
    };
    match LearnerPrior::at_period(press, release, period_ns) {
        Ok(p) => {
            *out = cb_learner_prior {
                press: p.press(),
                release: p.release(),
                fastest_tap: p.fastest_tap(),
            };
            OK
        }
        Err(e) => e.into(),
    }
}

/// One key's learning debouncer: 24 bytes, aligned as a `uint16_t`. Set it with
/// `cb_learner_init` or `cb_learner_restore`.
///
/// The header declares it as `uint16_t state[12]` (written in cbindgen.toml: cbindgen cannot
/// see into the core's type); it is the core's `LearningState` itself, whose layout is fixed
/// (integers only, no padding), so any 24 bytes are a state and no sample pays for a copy.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct cb_learner {
    state: LearningState,
}
const _: () =
    assert!(size_of::<cb_learner>() == 24 && align_of::<cb_learner>() == align_of::<u16>());

impl cb_learner {
    /// The learner whose `uint16_t state[12]` are `words` (on these little-endian targets, the
    /// core's `LearningState::from_words`): for tests that write a state as C could.
    #[must_use]
    pub const fn from_words(words: [u16; 12]) -> Self {
        Self {
            state: LearningState::from_words(words),
        }
    }

    /// The words C sees in `state`.
    #[must_use]
    pub const fn to_words(&self) -> [u16; 12] {
        self.state.to_words()
    }
}

/// What a learner has learned, to save (for example in EEPROM) and restore: 12 bytes.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct cb_learned {
    /// The bytes, as `cb_learner_save` writes them.
    pub bytes: [u8; 12],
}

/// `cb_learner_flags`: the switch reverts for at least half the fastest tap, so it will also
/// revert for as long as a tap, and those reversions are reported as taps would be.
pub const CB_LEARNER_REVERTS_LIKE_A_TAP: u8 = 1;

/// A key settled closed (`closed` true) or open, with nothing learned.
#[allow(unsafe_code)]
#[no_mangle]
pub extern "C" fn cb_learner_init(learner: Option<&mut cb_learner>, closed: bool) -> cb_error {
    match learner {
        Some(l) => {
            l.state = LearningState::new(closed);
            OK
        }
        None => NULL,
    }
}

/// Feeds one sample (`closed`: the contact reads closed) and returns the edge it debounces;
/// `CB_EDGE_ERROR` (the learner unchanged) for a NULL argument or a prior not made by
/// `cb_learner_prior_init`.
#[allow(unsafe_code)]
#[no_mangle]
pub extern "C" fn cb_learner_update(
    learner: Option<&mut cb_learner>,
    closed: bool,
    prior: Option<&cb_learner_prior>,
) -> cb_edge {
    let (Some(learner), Some(prior)) = (learner, prior) else {
        return cb_edge::CB_EDGE_ERROR;
    };
    // (`ok()`: the error's code is not needed here, and its conversion costs flash.)
    let Some(prior) = LearnerPrior::new(prior.press, prior.release, prior.fastest_tap).ok() else {
        return cb_edge::CB_EDGE_ERROR;
    };
    match learner.state.update(closed, &prior) {
        None => cb_edge::CB_EDGE_NONE,
        Some(Edge::Press) => cb_edge::CB_EDGE_PRESS,
        Some(Edge::Release) => cb_edge::CB_EDGE_RELEASE,
    }
}

/// Whether the key is debounced closed (false for NULL).
#[allow(unsafe_code)]
#[no_mangle]
pub extern "C" fn cb_learner_is_closed(learner: Option<&cb_learner>) -> bool {
    learner.is_some_and(|l| l.state.is_closed())
}

/// The press and release windows the learner uses now with `prior` (samples); `press` and
/// `release` are written only on success.
#[allow(unsafe_code)]
#[no_mangle]
pub extern "C" fn cb_learner_windows(
    learner: Option<&cb_learner>,
    prior: Option<&cb_learner_prior>,
    press: Option<&mut u16>,
    release: Option<&mut u16>,
) -> cb_error {
    let (Some(l), Some(p), Some(press), Some(release)) = (learner, prior, press, release) else {
        return NULL;
    };
    match learner_prior(*p) {
        Ok(p) => {
            (*press, *release) = l.state.learned().windows(&p);
            OK
        }
        Err(e) => e,
    }
}

/// The learner's flags with `prior` (`CB_LEARNER_REVERTS_LIKE_A_TAP`); 0 for a NULL argument
/// or a bad prior.
#[allow(unsafe_code)]
#[no_mangle]
pub extern "C" fn cb_learner_flags(
    learner: Option<&cb_learner>,
    prior: Option<&cb_learner_prior>,
) -> u8 {
    match (
        learner,
        prior.and_then(|p| LearnerPrior::new(p.press, p.release, p.fastest_tap).ok()),
    ) {
        (Some(l), Some(p)) if l.state.learned().reverts_like_a_tap(&p) => {
            CB_LEARNER_REVERTS_LIKE_A_TAP
        }
        _ => 0,
    }
}

/// What the learner has learned, as 12 bytes to save.
#[allow(unsafe_code)]
#[no_mangle]
pub extern "C" fn cb_learner_save(
    learner: Option<&cb_learner>,
    out: Option<&mut cb_learned>,
) -> cb_error {
    match (learner, out) {
        (Some(l), Some(out)) => {
            out.bytes = l.state.learned().to_bytes();
            OK
        }
        _ => NULL,
    }
}

/// A key settled closed (`closed` true) or open that has learned what `cb_learner_save` saved.
/// `CB_ERR_OUT_OF_RANGE` (naming `CB_PARAM_TIME`) for bytes no learner saved (erased or
/// corrupted storage): the learner is then unchanged.
#[allow(unsafe_code)]
#[no_mangle]
pub extern "C" fn cb_learner_restore(
    learner: Option<&mut cb_learner>,
    closed: bool,
    saved: Option<&cb_learned>,
) -> cb_error {
    let (Some(l), Some(saved)) = (learner, saved) else {
        return NULL;
    };
    match Learned::from_bytes(saved.bytes) {
        Ok(learned) => {
            l.state = LearningState::restore(closed, learned);
            OK
        }
        Err(e) => e.into(),
    }
}
