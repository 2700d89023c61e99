//! Scene files with ranges: any number of a scene may be a distribution,
//! `{"min": a, "max": b}` (uniform on [a, b]) or `{"value": x, "spread": s}` (uniform on
//! x (1 +- s)). A scene is then a template: its nominal scene takes the midpoints, and samples
//! draw every distribution independently.

use serde_json::{Map, Value};

use contact_bounce::Threshold;

use crate::scene::input::{FieldError, Placement, SceneInput, Spring};

/// A number of the scene: fixed, or uniform on an interval.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Dist {
    /// Uniform on [lo, hi].
    Uniform {
        /// Low end.
        lo: f64,
        /// High end.
        hi: f64,
    },
}

impl Dist {
    /// The midpoint.
    #[must_use]
    pub fn nominal(&self) -> f64 {
        match *self {
            Self::Uniform { lo, hi } => 0.5 * (lo + hi),
        }
    }
    /// Half the width over the midpoint (0 when the midpoint is 0).
    #[must_use]
    pub fn relative_half_width(&self) -> f64 {
        match *self {
            Self::Uniform { lo, hi } => {
                let mid = self.nominal();
                if mid == 0.0 {
                    0.0
                } else {
                    (0.5 * (hi - lo) / mid).abs()
                }
            }
        }
    }
    fn draw(&self, u: f64) -> f64 {
        match *self {
            Self::Uniform { lo, hi } => lo + u * (hi - lo),
        }
    }
}

/// A scene with distributions, parsed once: the Monte Carlo varies its typed parameters, never
/// JSON.
#[derive(Debug, Clone, PartialEq)]
pub struct Template {
    /// The scene, distributions replaced by their nominal values.
    nominal: SceneInput,
    /// Each distribution, in the order of the scene's keys.
    params: Vec<Range>,
}

/// One ranged parameter of a [`Template`].
#[derive(Debug, Clone, PartialEq)]
pub struct Range {
    /// The field as written in the scene (`mass`, `kernel.tau`).
    pub field: String,
    /// The parameter it sets.
    pub param: Param,
    /// Its distribution.
    pub dist: Dist,
}

/// A number of a scene that a range can set: the scene keys of `eval`, nested ones as
/// `kernel.tau`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[allow(missing_docs)]
pub enum Param {
    Omega,
    Mass,
    Stiffness,
    Gap,
    PreloadForce,
    Restitution,
    DampingRatio,
    ClosingSpeed,
    ThresholdImpulse,
    ThresholdFraction,
    KernelKappa,
    KernelTau,
    KernelState,
    M1,
    C1,
    D1,
    M2,
    C2,
    D2,
    X2,
    V2,
}

impl Param {
    /// The parameter at `field` (keys joined by dots), if `scene` has that number.
    fn of(field: &str, scene: &SceneInput) -> Option<Self> {
        let p = match field {
            "omega" => Self::Omega,
            "mass" => Self::Mass,
            "stiffness" => Self::Stiffness,
            "gap" => Self::Gap,
            "preload_force" => Self::PreloadForce,
            "restitution" => Self::Restitution,
            "damping_ratio" => Self::DampingRatio,
            "closing_speed" => Self::ClosingSpeed,
            "threshold_impulse" => Self::ThresholdImpulse,
            "threshold_fraction" => Self::ThresholdFraction,
            "kernel.kappa" => Self::KernelKappa,
            "kernel.tau" => Self::KernelTau,
            "kernel.state" => Self::KernelState,
            "two_body.m1" => Self::M1,
            "two_body.c1" => Self::C1,
            "two_body.d1" => Self::D1,
            "two_body.m2" => Self::M2,
            "two_body.c2" => Self::C2,
            "two_body.d2" => Self::D2,
            "two_body.x2" => Self::X2,
            "two_body.v2" => Self::V2,
            _ => return None,
        };
        let mut probe = scene.clone();
        p.set(&mut probe, 0.5).then_some(p)
    }

    /// Sets this parameter of `scene` to `x`; false where the scene has no such number (a
    /// mass on a scene given by omega, a kernel's tau on a scene without a kernel).
    fn set(self, scene: &mut SceneInput, x: f64) -> bool {
        let slot = match (self, &mut scene.spring, &mut scene.placement) {
            (Self::Omega, Spring::Omega(w), _) => w,
            (Self::Mass, Spring::MassStiffness(m, _), _) => m,
            (Self::Stiffness, Spring::MassStiffness(_, k), _) => k,
            (Self::Gap, _, Placement::Gap(d)) => d,
            (Self::PreloadForce, _, Placement::PreloadForce(f)) => f,
            (Self::Restitution, ..) => &mut scene.restitution,
            (Self::DampingRatio, ..) => &mut scene.damping_ratio,
            (Self::ClosingSpeed, ..) => &mut scene.closing_speed,
            (Self::ThresholdImpulse, ..) => match &mut scene.threshold {
                Threshold::Impulse(p) => p,
                _ => return false,
            },
            (Self::ThresholdFraction, ..) => match &mut scene.threshold {
                Threshold::FractionOfFirst(f) => f,
                _ => return false,
            },
            (Self::KernelKappa | Self::KernelTau | Self::KernelState, ..) => {
                let Some(k) = scene.kernel.as_mut() else {
                    return false;
                };
                match self {
                    Self::KernelKappa => &mut k.kappa,
                    Self::KernelTau => &mut k.tau,
                    _ => k.state.get_or_insert(0.0),
                }
            }
            (Self::M1, Spring::TwoBody(b, ..), _) => &mut b.m1,
            (Self::C1, Spring::TwoBody(b, ..), _) => &mut b.c1,
            (Self::D1, Spring::TwoBody(b, ..), _) => &mut b.d1,
            (Self::M2, Spring::TwoBody(b, ..), _) => &mut b.m2,
            (Self::C2, Spring::TwoBody(b, ..), _) => &mut b.c2,
            (Self::D2, Spring::TwoBody(b, ..), _) => &mut b.d2,
            (Self::X2, Spring::TwoBody(_, x2, _), _) => x2,
            (Self::V2, Spring::TwoBody(_, _, v2), _) => v2,
            _ => return false,
        };
        *slot = x;
        true
    }
}

fn number(v: &Value, field: &str) -> Result<f64, FieldError> {
    v.as_f64()
        .filter(|x| x.is_finite())
        .ok_or_else(|| FieldError {
            field: field.to_owned(),
            message: "must be a finite number".to_owned(),
        })
}

fn distribution(object: &Map<String, Value>, field: &str) -> Result<Option<Dist>, FieldError> {
    let keys: Vec<&str> = object.keys().map(String::as_str).collect();
    let bad = |message: &str| FieldError {
        field: field.to_owned(),
        message: message.to_owned(),
    };
    match keys.as_slice() {
        ["min", "max"] | ["max", "min"] => {
            let (lo, hi) = (
                number(&object["min"], &format!("{field}.min"))?,
                number(&object["max"], &format!("{field}.max"))?,
            );
            if lo > hi {
                return Err(bad("min must not exceed max"));
            }
            Ok(Some(Dist::Uniform { lo, hi }))
        }
        ["value", "spread"] | ["spread", "value"] => {
            let value = number(&object["value"], &format!("{field}.value"))?;
            let spread = number(&object["spread"], &format!("{field}.spread"))?;
            if !(0.0..1.0).contains(&spread) {
                return Err(bad("spread must be in [0, 1) (a relative half-width)"));
            }
            let (a, b) = (value * (1.0 - spread), value * (1.0 + spread));
            Ok(Some(Dist::Uniform {
                lo: a.min(b),
                hi: a.max(b),
            }))
        }
        _ if keys.iter().any(|k| matches!(*k, "min" | "max" | "spread")) => Err(bad(
            "a range is {\"min\": a, \"max\": b} or {\"value\": x, \"spread\": s}",
        )),
        _ => Ok(None),
    }
}

fn walk(
    value: &mut Value,
    path: &mut Vec<String>,
    params: &mut Vec<(Vec<String>, Dist)>,
) -> Result<(), FieldError> {
    let Value::Object(object) = value else {
        return Ok(());
    };
    // Only objects inside can be ranges (or hold them): numbers and strings are skipped
    // without a path.
    for (key, child) in object.iter_mut() {
        if let Value::Object(inner) = child {
            path.push(key.clone());
            let field = path.join(".");
            if let Some(dist) = distribution(inner, &field)? {
                *child = Value::from(dist.nominal());
                params.push((path.clone(), dist));
            } else {
                walk(child, path, params)?;
            }
            path.pop();
        }
    }
    Ok(())
}

impl Template {
    /// Reads a scene object with distributions.
    ///
    /// # Errors
    /// A malformed distribution, or the nominal scene's first missing, mistyped, unknown or
    /// conflicting field (as [`SceneInput::from_json`]), naming its field.
    pub fn parse(scene: &Value, default_name: &str) -> Result<Self, FieldError> {
        Self::from_value(scene.clone(), default_name)
    }

    /// A line read flat ([`crate::scene::input::FlatScene`]): no ranges.
    ///
    /// # Errors
    /// As [`SceneInput::from_json`].
    pub(crate) fn from_flat(
        flat: &crate::scene::input::FlatScene,
        default_name: &str,
    ) -> Result<Self, FieldError> {
        Ok(Self {
            nominal: SceneInput::from_object(flat, default_name)?,
            params: Vec::new(),
        })
    }

    /// As [`Template::parse`], taking the scene.
    ///
    /// # Errors
    /// As [`Template::parse`].
    pub fn from_value(mut nominal: Value, default_name: &str) -> Result<Self, FieldError> {
        let mut found = Vec::new();
        walk(&mut nominal, &mut Vec::new(), &mut found)?;
        let nominal = SceneInput::from_json(&nominal, default_name)?;
        let params = found
            .into_iter()
            .map(|(path, dist)| {
                let field = path.join(".");
                match Param::of(&field, &nominal) {
                    Some(param) => Ok(Range { field, param, dist }),
                    // Not reached: a range is read where the scene reads a number.
                    None => Err(FieldError {
                        field,
                        message: "cannot take a range".to_owned(),
                    }),
                }
            })
            .collect::<Result<_, _>>()?;
        Ok(Self { nominal, params })
    }
    /// The nominal scene.
    #[must_use]
    pub fn nominal(&self) -> &SceneInput {
        &self.nominal
    }
    /// The distributions.
    #[must_use]
    pub fn params(&self) -> &[Range] {
        &self.params
    }
    /// Sample `index` of a run seeded with `seed`, written over `scene`, which must be this
    /// template's nominal scene or an earlier sample of it (every ranged parameter is drawn
    /// again): the same for any thread that draws it.
    pub fn sample_into(&self, seed: u64, index: u64, scene: &mut SceneInput) {
        let mut rng =
            SplitMix(seed ^ index.wrapping_mul(0x9E37_79B9_7F4A_7C15) ^ 0xD1B5_4A32_D192_ED03);
        for r in &self.params {
            r.param.set(scene, r.dist.draw(rng.unit()));
        }
    }
    /// Sample `index` of a run seeded with `seed` (as [`Template::sample_into`]).
    #[must_use]
    pub fn sample(&self, seed: u64, index: u64) -> SceneInput {
        let mut out = self.nominal.clone();
        self.sample_into(seed, index, &mut out);
        out
    }
    /// The nominal scene with parameter `k` multiplied by `factor`.
    #[must_use]
    pub fn scaled(&self, k: usize, factor: f64) -> SceneInput {
        let mut out = self.nominal.clone();
        if let Some(r) = self.params.get(k) {
            r.param.set(&mut out, r.dist.nominal() * factor);
        }
        out
    }
}

/// SplitMix64: small, fast and good enough for Monte Carlo draws and seeded splits; the same
/// sequence for the same seed everywhere.
#[derive(Debug, Clone)]
pub struct SplitMix(pub u64);

impl SplitMix {
    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    /// Uniform on [0, 1).
    pub fn unit(&mut self) -> f64 {
        #[allow(clippy::cast_precision_loss)]
        let u = (self.next_u64() >> 11) as f64 / (1_u64 << 53) as f64;
        u
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    fn scene(extra: &Value) -> Value {
        let mut s = json!({"name": "x", "mass": 1e-3, "stiffness": 1e3, "gap": -1e-4,
            "restitution": 0.5, "closing_speed": 0.2, "kernel": {"tau": 1e-3, "kappa": 2.0}});
        for (k, v) in extra.as_object().unwrap() {
            s[k] = v.clone();
        }
        s
    }

    #[test]
    fn distributions_are_read_and_drawn_reproducibly() {
        let t = Template::parse(
            &scene(&json!({"mass": {"value": 1e-3, "spread": 0.1},
                "kernel": {"tau": {"min": 1.0, "max": 3.0}, "kappa": 2.0}})),
            "s",
        )
        .unwrap();
        assert_eq!(t.params().len(), 2);
        assert_eq!(t.params()[1].field, "kernel.tau");
        assert_eq!(t.nominal().spring, Spring::MassStiffness(1e-3, 1e3));
        assert_eq!(t.nominal().kernel.unwrap().tau, 2.0);
        assert_eq!(t.sample(7, 3), t.sample(7, 3));
        assert_ne!(t.sample(7, 3), t.sample(8, 3));
        let mut reused = t.nominal().clone();
        for i in 0..200 {
            let s = t.sample(1, i);
            t.sample_into(1, i, &mut reused);
            assert_eq!(s, reused);
            let Spring::MassStiffness(m, k) = s.spring else {
                panic!("{s:?}")
            };
            assert!((0.9e-3..=1.1e-3).contains(&m));
            assert_eq!(k, 1e3);
            let tau = s.kernel.unwrap().tau;
            assert!((1.0..=3.0).contains(&tau));
        }
    }

    #[test]
    fn every_number_of_a_scene_can_take_a_range() {
        let range = json!({"min": 0.5, "max": 0.7});
        let scenes = [
            json!({"omega": range, "gap": range, "restitution": range, "damping_ratio": range,
                "closing_speed": range, "threshold_fraction": range,
                "kernel": {"kappa": range, "tau": range, "state": range}}),
            json!({"mass": range, "stiffness": range, "preload_force": range,
                "restitution": 0.5, "closing_speed": 0.2, "threshold_impulse": range}),
            json!({"gap": -1e-4, "restitution": 0.5, "closing_speed": range,
                "two_body": {"m1": range, "c1": range, "d1": range, "m2": range, "c2": range,
                    "d2": range, "x2": range, "v2": range}}),
        ];
        for s in &scenes {
            let t = Template::parse(s, "s").unwrap();
            let ranged = t.params().len();
            assert_eq!(ranged, s.to_string().matches("min").count(), "{s}");
            // Each draw lands in its field: the sample differs from the nominal scene in
            // that field alone.
            for (k, r) in t.params().iter().enumerate() {
                let mut one = t.nominal().clone();
                assert!(r.param.set(&mut one, 0.25), "{}", r.field);
                assert_ne!(&one, t.nominal(), "{}", r.field);
                assert_eq!(t.scaled(k, 1.0), *t.nominal());
            }
        }
    }

    #[test]
    fn malformed_distributions_name_their_field() {
        let bad = [
            json!({"mass": {"min": 2.0, "max": 1.0}}),
            json!({"mass": {"value": 1.0, "spread": 1.5}}),
            json!({"kernel": {"tau": {"min": 1.0}}}),
            json!({"mass": {"value": "a", "spread": 0.1}}),
            json!({"name": {"min": 1.0, "max": 2.0}}),
            json!({"kernel": {"min": 1.0, "max": 2.0}}),
        ];
        let fields = ["mass", "mass", "kernel.tau", "mass.value", "name", "kernel"];
        for (extra, field) in bad.iter().zip(fields) {
            let e = Template::parse(&scene(extra), "s").unwrap_err();
            assert_eq!(e.field, field, "{extra}: {e:?}");
        }
    }
}
