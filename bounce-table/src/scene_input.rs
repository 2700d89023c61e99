//! Scenes as JSON objects (the keys of `eval`, SI units), checked field by field.

use contact_bounce::{
    scene::AnyDissipation, scene::TwoBody, Contact, Frequency, Hereditary, Offset, Restitution,
    Scene, Threshold, Viscous,
};
use serde_json::{Map, Value};

/// A field that is missing, mistyped, unknown or invalid.
#[derive(Debug, Clone, PartialEq)]
pub struct FieldError {
    /// The field, as written in the scene (`two_body.m1` for nested ones); empty for the line.
    pub field: String,
    /// What is wrong.
    pub message: String,
}

impl FieldError {
    fn new(field: &str, message: impl Into<String>) -> Self {
        Self {
            field: field.to_owned(),
            message: message.into(),
        }
    }
}

impl From<contact_bounce::Error> for FieldError {
    fn from(e: contact_bounce::Error) -> Self {
        Self::new(e.parameter().name(), e.to_string())
    }
}

/// Where the natural frequency comes from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Spring {
    /// `omega`.
    Omega(f64),
    /// `mass` and `stiffness`.
    MassStiffness(f64, f64),
    /// `two_body`, with body 2's initial position and velocity.
    TwoBody(TwoBody<f64>, f64, f64),
}

/// `gap` or `preload_force`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Placement {
    /// Delta (m).
    Gap(f64),
    /// Preload force (N).
    PreloadForce(f64),
}

/// `kernel`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Kernel {
    /// kappa (1/s^3).
    pub kappa: f64,
    /// tau (s).
    pub tau: f64,
    /// The initial internal state y (m s), if given.
    pub state: Option<f64>,
}

/// One scene, as read.
#[derive(Debug, Clone, PartialEq)]
pub struct SceneInput {
    /// `name`, or "line N".
    pub name: String,
    /// Where the natural frequency comes from (`omega`, `mass` and `stiffness`, or
    /// `two_body`).
    pub spring: Spring,
    /// Gap or preload.
    pub placement: Placement,
    /// R.
    pub restitution: f64,
    /// zeta (0 when absent; not with `two_body`).
    pub damping_ratio: f64,
    /// v0 (m/s).
    pub closing_speed: f64,
    /// Threshold.
    pub threshold: Threshold<f64>,
    /// Relaxation kernel.
    pub kernel: Option<Kernel>,
}

const KEYS: [&str; 13] = [
    "name",
    "omega",
    "mass",
    "stiffness",
    "gap",
    "preload_force",
    "restitution",
    "damping_ratio",
    "closing_speed",
    "threshold_impulse",
    "threshold_fraction",
    "kernel",
    "two_body",
];

fn number(object: &Map<String, Value>, key: &str, prefix: &str) -> Result<Option<f64>, FieldError> {
    match object.get(key) {
        None | Some(Value::Null) => Ok(None),
        Some(Value::Number(n)) => n.as_f64().map(Some).ok_or_else(|| {
            FieldError::new(&format!("{prefix}{key}"), "is not a representable number")
        }),
        Some(_) => Err(FieldError::new(
            &format!("{prefix}{key}"),
            "must be a number",
        )),
    }
}

fn required(object: &Map<String, Value>, key: &str, prefix: &str) -> Result<f64, FieldError> {
    number(object, key, prefix)?
        .ok_or_else(|| FieldError::new(&format!("{prefix}{key}"), "is required"))
}

fn only_keys(
    object: &Map<String, Value>,
    allowed: &[&str],
    prefix: &str,
) -> Result<(), FieldError> {
    match object.keys().find(|k| !allowed.contains(&k.as_str())) {
        Some(k) => Err(FieldError::new(
            &format!("{prefix}{k}"),
            format!(
                "is not a scene key (expected one of {})",
                allowed.join(", ")
            ),
        )),
        None => Ok(()),
    }
}

fn conflict(a: &str, b: &str) -> FieldError {
    FieldError::new(b, format!("cannot be given with {a}"))
}

impl SceneInput {
    /// Reads a scene from a JSON value.
    ///
    /// # Errors
    /// The first missing, mistyped, unknown or conflicting field.
    pub fn from_json(value: &Value, default_name: &str) -> Result<Self, FieldError> {
        let object = value
            .as_object()
            .ok_or_else(|| FieldError::new("", "a scene must be a JSON object"))?;
        only_keys(object, &KEYS, "")?;
        let name = match object.get("name") {
            None | Some(Value::Null) => default_name.to_owned(),
            Some(Value::String(s)) => s.clone(),
            Some(_) => return Err(FieldError::new("name", "must be a string")),
        };
        let has = |k: &str| object.get(k).is_some_and(|v| !v.is_null());
        let spring = if let Some(two) = object.get("two_body").filter(|v| !v.is_null()) {
            for k in ["omega", "mass", "stiffness", "damping_ratio"] {
                if has(k) {
                    return Err(conflict("two_body", k));
                }
            }
            let body = two
                .as_object()
                .ok_or_else(|| FieldError::new("two_body", "must be an object"))?;
            only_keys(
                body,
                &["m1", "c1", "d1", "m2", "c2", "d2", "x2", "v2"],
                "two_body.",
            )?;
            let p = "two_body.";
            Spring::TwoBody(
                TwoBody {
                    m1: required(body, "m1", p)?,
                    c1: required(body, "c1", p)?,
                    d1: number(body, "d1", p)?.unwrap_or(0.0),
                    m2: required(body, "m2", p)?,
                    c2: required(body, "c2", p)?,
                    d2: number(body, "d2", p)?.unwrap_or(0.0),
                },
                number(body, "x2", p)?.unwrap_or(0.0),
                number(body, "v2", p)?.unwrap_or(0.0),
            )
        } else if has("omega") {
            for k in ["mass", "stiffness"] {
                if has(k) {
                    return Err(conflict("omega", k));
                }
            }
            Spring::Omega(required(object, "omega", "")?)
        } else if has("mass") || has("stiffness") {
            Spring::MassStiffness(
                required(object, "mass", "")?,
                required(object, "stiffness", "")?,
            )
        } else {
            return Err(FieldError::new(
                "omega",
                "is required (or mass and stiffness, or two_body)",
            ));
        };
        let placement = match (
            number(object, "gap", "")?,
            number(object, "preload_force", "")?,
        ) {
            (Some(_), Some(_)) => return Err(conflict("gap", "preload_force")),
            (Some(gap), None) => Placement::Gap(gap),
            (None, Some(force)) => Placement::PreloadForce(force),
            (None, None) => return Err(FieldError::new("gap", "is required (or preload_force)")),
        };
        let threshold = match (
            number(object, "threshold_impulse", "")?,
            number(object, "threshold_fraction", "")?,
        ) {
            (Some(_), Some(_)) => return Err(conflict("threshold_impulse", "threshold_fraction")),
            (Some(p), None) => Threshold::Impulse(p),
            (None, Some(f)) => Threshold::FractionOfFirst(f),
            (None, None) => Threshold::None,
        };
        let kernel = match object.get("kernel").filter(|v| !v.is_null()) {
            None => None,
            Some(k) => {
                let k = k
                    .as_object()
                    .ok_or_else(|| FieldError::new("kernel", "must be an object"))?;
                only_keys(k, &["kappa", "tau", "state"], "kernel.")?;
                Some(Kernel {
                    kappa: required(k, "kappa", "kernel.")?,
                    tau: required(k, "tau", "kernel.")?,
                    state: number(k, "state", "kernel.")?,
                })
            }
        };
        Ok(Self {
            name,
            spring,
            placement,
            restitution: required(object, "restitution", "")?,
            damping_ratio: number(object, "damping_ratio", "")?.unwrap_or(0.0),
            closing_speed: required(object, "closing_speed", "")?,
            threshold,
            kernel,
        })
    }

    /// The core's scene, in `f64` or `f32` (values rounded to the nearest f32; one out of its
    /// range is an error naming the field).
    ///
    /// # Errors
    /// The core's validation error, as the field it names.
    /// The model's refusal as a field error: one out of range says the value given and what
    /// the model takes ("restitution 1.2 is out of range: the model takes [1e-6, 1] ...").
    fn fault(&self, e: contact_bounce::Error) -> FieldError {
        let parameter = e.parameter();
        if e.reason() == contact_bounce::Reason::OutOfRange {
            if let (Some(value), Some(range)) = (self.value_of(parameter), accepted(parameter)) {
                let name = parameter.name();
                // As written in a scene file: 1.2, 1e-7, 1e31 (not 0.0000001).
                let shown = if value == 0.0 || (1e-4..1e7).contains(&value.abs()) {
                    format!("{value}")
                } else {
                    format!("{value:e}")
                };
                return FieldError::new(
                    name,
                    format!("{name} {shown} is out of range: the model takes {range}"),
                );
            }
        }
        e.into()
    }

    /// The value given for a parameter, if this scene has it.
    fn value_of(&self, parameter: contact_bounce::Parameter) -> Option<f64> {
        use contact_bounce::Parameter as P;
        Some(match (parameter, self.spring, self.placement) {
            (P::Omega, Spring::Omega(w), _) => w,
            (P::Mass, Spring::MassStiffness(m, _), _) => m,
            (P::Stiffness, Spring::MassStiffness(_, k), _) => k,
            (P::Delta, _, Placement::Gap(d)) => d,
            (P::PreloadForce, _, Placement::PreloadForce(f)) => f,
            (P::Restitution, ..) => self.restitution,
            (P::DampingRatio, ..) => self.damping_ratio,
            (P::ClosingSpeed, ..) => self.closing_speed,
            (P::ThresholdFraction, ..) => match self.threshold {
                Threshold::FractionOfFirst(f) => f,
                _ => return None,
            },
            (P::ThresholdImpulse, ..) => match self.threshold {
                Threshold::Impulse(p) => p,
                _ => return None,
            },
            (P::KernelAmplitude, ..) => self.kernel?.kappa,
            (P::KernelTimeConstant, ..) => self.kernel?.tau,
            (P::Mass1, Spring::TwoBody(b, ..), _) => b.m1,
            (P::Stiffness1, Spring::TwoBody(b, ..), _) => b.c1,
            (P::Damping1, Spring::TwoBody(b, ..), _) => b.d1,
            (P::Mass2, Spring::TwoBody(b, ..), _) => b.m2,
            (P::Stiffness2, Spring::TwoBody(b, ..), _) => b.c2,
            (P::Damping2, Spring::TwoBody(b, ..), _) => b.d2,
            _ => return None,
        })
    }

    pub fn core<F: contact_bounce::Float>(
        &self,
    ) -> Result<Scene<F, AnyDissipation<F>>, FieldError> {
        // A value the float cannot hold (it would round to 0, to a subnormal or to inf) is an
        // error naming its field: "mass must be > 0" for a mass of 1e-300 in f32 would name
        // the right field but the wrong fault.
        let c = |field: &str, v: f64| -> Result<F, FieldError> {
            let x = F::from_f64(v);
            let tiny = v != 0.0 && x.abs() < F::MIN_POSITIVE;
            if v.is_finite() && (tiny || !x.is_finite()) {
                let float = if F::EPSILON.to_f64() > 1e-10 {
                    "f32"
                } else {
                    "f64"
                };
                return Err(FieldError::new(
                    field,
                    format!("{v:e} is beyond {float}'s normal range (use --precision f64)"),
                ));
            }
            Ok(x)
        };
        let offset = match self.placement {
            Placement::Gap(d) => Offset::Delta(c("gap", d)?),
            Placement::PreloadForce(f) => Offset::PreloadForce(c("preload_force", f)?),
        };
        let threshold = match self.threshold {
            Threshold::None => Threshold::None,
            Threshold::Impulse(p) => Threshold::Impulse(c("threshold_impulse", p)?),
            Threshold::FractionOfFirst(f) => {
                Threshold::FractionOfFirst(c("threshold_fraction", f)?)
            }
        };
        let kernel = match self.kernel {
            Some(k) => Some(
                Hereditary::exponential(c("kernel.kappa", k.kappa)?, c("kernel.tau", k.tau)?)
                    .map_err(|e| self.fault(e))?,
            ),
            None => None,
        };
        let restitution = Restitution::Coefficient(c("restitution", self.restitution)?);
        let v0 = c("closing_speed", self.closing_speed)?;
        let one_body = |frequency: Frequency<F>| -> Result<_, FieldError> {
            let viscous = Some(
                Viscous::new(c("damping_ratio", self.damping_ratio)?).map_err(|e| self.fault(e))?,
            );
            let contact = Contact {
                frequency,
                offset,
                restitution,
                closing_speed: v0,
                threshold,
            };
            Scene::new(contact, (viscous, kernel)).map_err(|e| self.fault(e))
        };
        let scene = match self.spring {
            Spring::TwoBody(b, _, _) => {
                let bodies = TwoBody {
                    m1: c("two_body.m1", b.m1)?,
                    c1: c("two_body.c1", b.c1)?,
                    d1: c("two_body.d1", b.d1)?,
                    m2: c("two_body.m2", b.m2)?,
                    c2: c("two_body.c2", b.c2)?,
                    d2: c("two_body.d2", b.d2)?,
                };
                Scene::two_body(bodies, offset, restitution, v0, threshold, kernel)
                    .map_err(|e| self.fault(e))?
            }
            Spring::Omega(w) => one_body(Frequency::Omega(c("omega", w)?))?,
            Spring::MassStiffness(m, k) => one_body(Frequency::MassStiffness {
                mass: c("mass", m)?,
                stiffness: c("stiffness", k)?,
            })?,
        };
        Ok(scene)
    }
}

/// What the model takes for a parameter it can refuse as out of range, in a scene file's terms.
fn accepted(parameter: contact_bounce::Parameter) -> Option<String> {
    use contact_bounce::{
        scene::LARGEST_DAMPING, scene::PHYSICAL_RANGE, scene::SMALLEST_RATE,
        scene::SMALLEST_RESTITUTION, Parameter as P,
    };
    let (lo, hi) = PHYSICAL_RANGE;
    Some(match parameter {
        P::Omega
        | P::Mass
        | P::Stiffness
        | P::PreloadForce
        | P::ClosingSpeed
        | P::ThresholdImpulse
        | P::KernelTimeConstant
        | P::Mass1
        | P::Stiffness1
        | P::Mass2
        | P::Stiffness2 => format!("values in [{lo:e}, {hi:e}]"),
        P::Damping1 | P::Damping2 => format!("0 or values in [{lo:e}, {hi:e}]"),
        P::Delta => format!("0 (grazing) or |gap| in [{lo:e}, {hi:e}]"),
        P::Restitution => format!(
            "R in [{SMALLEST_RESTITUTION:e}, 1], with 1 - R either 0 or at least {SMALLEST_RATE:e}"
        ),
        P::DampingRatio => format!("0 or values in [{SMALLEST_RATE:e}, {LARGEST_DAMPING:e}]"),
        P::ThresholdFraction => "values in (0, 1)".to_owned(),
        P::KernelAmplitude => {
            "kappa tau below Omega^2 (the kernel's static stiffness must leave the spring a \
             restoring force)"
                .to_owned()
        }
        _ => return None,
    })
}
