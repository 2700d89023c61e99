//! Scene files with ranges: any number of a scene may be a distribution,
//! `{"min": a, "max": b}` (uniform on [a, b]) or `{"value": x, "spread": s}` (uniform on
//! x (1 +- s)). A scene is then a template: its nominal scene takes the midpoints, and samples
//! draw every distribution independently.

use serde_json::{Map, Value};

use crate::scene_input::FieldError;

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

/// A scene with distributions.
#[derive(Debug, Clone)]
pub struct Template {
    /// The scene, distributions replaced by their nominal values.
    nominal: Value,
    /// Where each distribution is (a path of keys) and what it is.
    params: Vec<(Vec<String>, Dist)>,
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

/// Sets the number at `path` in `value`.
fn set(value: &mut Value, path: &[String], x: f64) {
    let mut here = value;
    for key in path {
        match here.get_mut(key) {
            Some(next) => here = next,
            None => return,
        }
    }
    *here = Value::from(x);
}

impl Template {
    /// Reads the distributions out of a scene object.
    ///
    /// # Errors
    /// A malformed distribution, naming its field.
    pub fn parse(scene: &Value) -> Result<Self, FieldError> {
        Self::from_value(scene.clone())
    }

    /// As [`Template::parse`], taking the scene.
    ///
    /// # Errors
    /// As [`Template::parse`].
    pub fn from_value(mut nominal: Value) -> Result<Self, FieldError> {
        let mut params = Vec::new();
        walk(&mut nominal, &mut Vec::new(), &mut params)?;
        Ok(Self { nominal, params })
    }
    /// The nominal scene.
    #[must_use]
    pub fn nominal(&self) -> &Value {
        &self.nominal
    }
    /// The distributions (path, distribution).
    #[must_use]
    pub fn params(&self) -> &[(Vec<String>, Dist)] {
        &self.params
    }
    /// Sample `index` of a run seeded with `seed`: the same for any thread that draws it.
    #[must_use]
    pub fn sample(&self, seed: u64, index: u64) -> Value {
        let mut rng =
            SplitMix(seed ^ index.wrapping_mul(0x9E37_79B9_7F4A_7C15) ^ 0xD1B5_4A32_D192_ED03);
        let mut out = self.nominal.clone();
        for (path, dist) in &self.params {
            set(&mut out, path, dist.draw(rng.unit()));
        }
        out
    }
    /// The nominal scene with parameter `k` multiplied by `factor`.
    #[must_use]
    pub fn scaled(&self, k: usize, factor: f64) -> Value {
        let mut out = self.nominal.clone();
        if let Some((path, dist)) = self.params.get(k) {
            set(&mut out, path, dist.nominal() * factor);
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

    #[test]
    fn distributions_are_read_and_drawn_reproducibly() {
        let scene = json!({"name": "x", "mass": {"value": 1e-3, "spread": 0.1}, "kernel": {"tau": {"min": 1.0, "max": 3.0}, "kappa": 2.0}});
        let t = Template::parse(&scene).unwrap();
        assert_eq!(t.params().len(), 2);
        assert_eq!(t.nominal()["mass"], json!(1e-3));
        assert_eq!(t.nominal()["kernel"]["tau"], json!(2.0));
        assert_eq!(t.sample(7, 3), t.sample(7, 3));
        assert_ne!(t.sample(7, 3), t.sample(8, 3));
        for i in 0..200 {
            let s = t.sample(1, i);
            let m = s["mass"].as_f64().unwrap();
            assert!((0.9e-3..=1.1e-3).contains(&m));
            let tau = s["kernel"]["tau"].as_f64().unwrap();
            assert!((1.0..=3.0).contains(&tau));
        }
    }

    #[test]
    fn malformed_distributions_name_their_field() {
        let bad = [
            json!({"mass": {"min": 2.0, "max": 1.0}}),
            json!({"mass": {"value": 1.0, "spread": 1.5}}),
            json!({"kernel": {"tau": {"min": 1.0}}}),
            json!({"mass": {"value": "a", "spread": 0.1}}),
        ];
        let fields = ["mass", "mass", "kernel.tau", "mass.value"];
        for (scene, field) in bad.iter().zip(fields) {
            assert_eq!(Template::parse(scene).unwrap_err().field, field, "{scene}");
        }
    }
}
