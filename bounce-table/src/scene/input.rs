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

/// A value of a scene object, as the reading of a scene sees it.
pub(crate) enum Item<'a, O: ?Sized> {
    /// `null`.
    Null,
    /// A number (`None`: not representable as an `f64`).
    Number(Option<f64>),
    /// A string.
    Str(&'a str),
    /// A nested object.
    Object(&'a O),
    /// Anything else (an array, a boolean).
    Other,
}

/// A scene object: a JSON object, or a [`FlatScene`] read straight from a line.
pub(crate) trait Object {
    /// The value of `key`, if given.
    fn item(&self, key: &str) -> Option<Item<'_, Self>>;
    /// The first key not in `allowed`.
    fn key_outside(&self, allowed: &[&str]) -> Option<&str>;
}

impl Object for Map<String, Value> {
    fn item(&self, key: &str) -> Option<Item<'_, Self>> {
        self.get(key).map(|v| match v {
            Value::Null => Item::Null,
            Value::Number(n) => Item::Number(n.as_f64()),
            Value::String(s) => Item::Str(s),
            Value::Object(o) => Item::Object(o),
            Value::Array(_) | Value::Bool(_) => Item::Other,
        })
    }
    fn key_outside(&self, allowed: &[&str]) -> Option<&str> {
        self.keys()
            .map(String::as_str)
            .find(|k| !allowed.contains(k))
    }
}

/// The keys a scene line gives plain numbers under, at its top level: [`KEYS`] but `name`,
/// `kernel` and `two_body`.
const FLAT: &[&str] = KEYS.split_at(1).1.split_at(KEYS.len() - 3).0;

/// A scene line whose values are all plain (a number or null under a key of [`FLAT`], a
/// string or null under `name`), read straight from its text into fixed slots: no JSON tree,
/// no map, no string but the name. [`FlatScene::read`] gives `None` for any other line (a
/// range, a nested object, an unknown or repeated key, a literal that underflows, text that is
/// not JSON): the full reading ([`crate::support::strict::json`], [`SceneInput::from_json`]) takes
/// those, and says what is wrong. A line both read is the same scene.
#[derive(Debug, Default)]
pub(crate) struct FlatScene {
    /// `name`: `Some(None)` where given as null.
    name: Option<Option<String>>,
    /// The values of [`FLAT`]'s keys, in its order, likewise.
    numbers: [Option<Option<f64>>; FLAT.len()],
}

/// A key of a flat line: 0 for `name`, else 1 + its place in [`FLAT`].
struct FlatKey(usize);

impl<'de> serde::Deserialize<'de> for FlatKey {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct KeyVisitor;
        impl serde::de::Visitor<'_> for KeyVisitor {
            type Value = FlatKey;
            fn expecting(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                f.write_str("a top-level scene key with a plain value")
            }
            fn visit_str<E: serde::de::Error>(self, key: &str) -> Result<FlatKey, E> {
                if key == "name" {
                    return Ok(FlatKey(0));
                }
                FLAT.iter()
                    .position(|k| *k == key)
                    .map(|i| FlatKey(i + 1))
                    .ok_or_else(|| E::custom("not a flat key"))
            }
        }
        d.deserialize_identifier(KeyVisitor)
    }
}

impl<'de> serde::Deserialize<'de> for FlatScene {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct LineVisitor;
        impl<'de> serde::de::Visitor<'de> for LineVisitor {
            type Value = FlatScene;
            fn expecting(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                f.write_str("a scene object with plain values")
            }
            fn visit_map<A: serde::de::MapAccess<'de>>(
                self,
                mut map: A,
            ) -> Result<FlatScene, A::Error> {
                use serde::de::Error;
                let mut scene = FlatScene::default();
                while let Some(FlatKey(k)) = map.next_key()? {
                    let repeated = || A::Error::custom("a key given twice");
                    if k == 0 {
                        if scene.name.is_some() {
                            return Err(repeated());
                        }
                        scene.name = Some(map.next_value()?);
                    } else {
                        let slot = scene
                            .numbers
                            .get_mut(k - 1)
                            .ok_or_else(|| A::Error::custom("no such key"))?;
                        if slot.is_some() {
                            return Err(repeated());
                        }
                        *slot = Some(map.next_value()?);
                    }
                }
                Ok(scene)
            }
        }
        d.deserialize_map(LineVisitor)
    }
}

impl FlatScene {
    /// The line read flat, or `None` where it needs the full reading (see [`FlatScene`]).
    pub(crate) fn read(text: &str) -> Option<Self> {
        let mut d = serde_json::Deserializer::from_str(text);
        let scene = <Self as serde::Deserialize>::deserialize(&mut d).ok()?;
        d.end().ok()?;
        // A literal that is not zero but reads as 0 (`1e-400`) must be refused, as the full
        // reading does: only a value read as 0 can be one, so a line with a 0 takes the full
        // reading (no scan of every line's text for such literals).
        let zero = scene
            .numbers
            .iter()
            .any(|n| n.flatten().is_some_and(|x| x == 0.0));
        (!zero).then_some(scene)
    }

    /// Its name, if given as a string, taken out (the scene then reads the default name,
    /// which the caller makes this one).
    pub(crate) fn take_name(&mut self) -> Option<String> {
        self.name.take().flatten()
    }
}

impl Object for FlatScene {
    fn item(&self, key: &str) -> Option<Item<'_, Self>> {
        if key == "name" {
            return self
                .name
                .as_ref()
                .map(|n| n.as_deref().map_or(Item::Null, Item::Str));
        }
        let i = FLAT.iter().position(|k| *k == key)?;
        self.numbers
            .get(i)
            .copied()
            .flatten()
            .map(|n| n.map_or(Item::Null, |x| Item::Number(Some(x))))
    }
    fn key_outside(&self, _allowed: &[&str]) -> Option<&str> {
        // Only `name` and the keys of `FLAT` are read, and every scene object takes those.
        None
    }
}

fn number<O: Object + ?Sized>(
    object: &O,
    key: &str,
    prefix: &str,
) -> Result<Option<f64>, FieldError> {
    match object.item(key) {
        None | Some(Item::Null) => Ok(None),
        Some(Item::Number(n)) => n.map(Some).ok_or_else(|| {
            FieldError::new(&format!("{prefix}{key}"), "is not a representable number")
        }),
        Some(_) => Err(FieldError::new(
            &format!("{prefix}{key}"),
            "must be a number",
        )),
    }
}

fn required<O: Object + ?Sized>(object: &O, key: &str, prefix: &str) -> Result<f64, FieldError> {
    number(object, key, prefix)?
        .ok_or_else(|| FieldError::new(&format!("{prefix}{key}"), "is required"))
}

fn only_keys<O: Object + ?Sized>(
    object: &O,
    allowed: &[&str],
    prefix: &str,
) -> Result<(), FieldError> {
    match object.key_outside(allowed) {
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
        Self::from_object(object, default_name)
    }

    /// Reads a scene from a scene object (a JSON object, or a line read flat).
    ///
    /// # Errors
    /// As [`SceneInput::from_json`].
    pub(crate) fn from_object<O: Object + ?Sized>(
        object: &O,
        default_name: &str,
    ) -> Result<Self, FieldError> {
        only_keys(object, &KEYS, "")?;
        let name = match object.item("name") {
            None | Some(Item::Null) => default_name.to_owned(),
            Some(Item::Str(s)) => s.to_owned(),
            Some(_) => return Err(FieldError::new("name", "must be a string")),
        };
        let has = |k: &str| object.item(k).is_some_and(|v| !matches!(v, Item::Null));
        let spring = if let Some(two) = object.item("two_body").filter(|v| !matches!(v, Item::Null))
        {
            for k in ["omega", "mass", "stiffness", "damping_ratio"] {
                if has(k) {
                    return Err(conflict("two_body", k));
                }
            }
            let Item::Object(body) = two else {
                return Err(FieldError::new("two_body", "must be an object"));
            };
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
        let kernel = match object.item("kernel").filter(|v| !matches!(v, Item::Null)) {
            None => None,
            Some(k) => {
                let Item::Object(k) = k else {
                    return Err(FieldError::new("kernel", "must be an object"));
                };
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
            if let (Some(value), Some(range)) = (self.value_of(parameter), parameter.accepted()) {
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
        self.with_core(|scene| *scene)
    }

    /// The scene's prediction by `method` (as [`SceneInput::core`], then `predict`, without
    /// moving the scene out: the Monte Carlo's path).
    ///
    /// # Errors
    /// As [`SceneInput::core`].
    pub fn predict<F: contact_bounce::Float>(
        &self,
        method: contact_bounce::Method<F>,
    ) -> Result<contact_bounce::Prediction<F>, FieldError> {
        self.with_core(|scene| scene.predict(method))
    }

    /// `f` of the core's scene, used where it was built: a `Scene` is a couple of hundred bytes,
    /// and each `?` or `map_err` it passed through by value was a copy (about a fifth of a
    /// Monte Carlo sample's time went to them).
    pub(crate) fn with_core<F: contact_bounce::Float, R>(
        &self,
        f: impl FnOnce(&Scene<F, AnyDissipation<F>>) -> R,
    ) -> Result<R, FieldError> {
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
        let frequency = match self.spring {
            Spring::TwoBody(b, _, _) => {
                let bodies = TwoBody {
                    m1: c("two_body.m1", b.m1)?,
                    c1: c("two_body.c1", b.c1)?,
                    d1: c("two_body.d1", b.d1)?,
                    m2: c("two_body.m2", b.m2)?,
                    c2: c("two_body.c2", b.c2)?,
                    d2: c("two_body.d2", b.d2)?,
                };
                // Matched by reference: bound by value, the scene is copied out of its `Result`.
                return match &Scene::two_body(bodies, offset, restitution, v0, threshold, kernel) {
                    Ok(scene) => Ok(f(scene)),
                    Err(e) => Err(self.fault(*e)),
                };
            }
            Spring::Omega(w) => Frequency::Omega(c("omega", w)?),
            Spring::MassStiffness(m, k) => Frequency::MassStiffness {
                mass: c("mass", m)?,
                stiffness: c("stiffness", k)?,
            },
        };
        let viscous = Viscous::optional(c("damping_ratio", self.damping_ratio)?)
            .map_err(|e| self.fault(e))?;
        let contact = Contact {
            frequency,
            offset,
            restitution,
            closing_speed: v0,
            threshold,
        };
        match &Scene::new(contact, (viscous, kernel)) {
            Ok(scene) => Ok(f(scene)),
            Err(e) => Err(self.fault(*e)),
        }
    }
}
