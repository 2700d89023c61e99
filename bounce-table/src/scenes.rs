//! Reading switches: the built-in catalogue, or a scene file (TOML, JSON or JSON Lines) whose
//! entries use the keys of `eval` and may carry tolerances (see [`crate::spreads`]).

use serde_json::{json, Value};

use crate::scene_input::FieldError;
use crate::spreads::Template;

/// One switch to analyse.
#[derive(Debug, Clone)]
pub struct Entry {
    /// Its name (or "entry N").
    pub name: String,
    /// Its scene, with tolerances.
    pub template: Template,
}

/// A scene file's fault: where, and what.
#[derive(Debug, Clone, PartialEq)]
pub struct FileError {
    /// The file.
    pub file: String,
    /// "entry N (name)", "line N", or empty.
    pub place: String,
    /// The field, or empty.
    pub field: String,
    /// What is wrong.
    pub message: String,
}

impl std::fmt::Display for FileError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}", self.file)?;
        if !self.place.is_empty() {
            write!(f, ": {}", self.place)?;
        }
        if !self.field.is_empty() {
            write!(f, ": {}", self.field)?;
        }
        write!(f, ": {}", self.message)
    }
}

/// The catalogue's typical switches, each parameter over its assumed range
/// ([`crate::priors::CATALOGUE_RANGES`]): their windows are a high percentile over those ranges.
#[must_use]
pub fn catalogue() -> Vec<Entry> {
    contact_bounce::catalogue::ALL
        .iter()
        .filter_map(|s| {
            let r = crate::priors::CATALOGUE_RANGES;
            let around = |x: f64, spread: f64| json!({"value": x, "spread": spread});
            // R within +-0.1, inside (0, 1).
            let restitution = json!({
                "min": (s.restitution - r.restitution).max(0.01),
                "max": (s.restitution + r.restitution).min(0.99),
            });
            let scene = json!({
                "name": s.name,
                "mass": around(s.mass, r.mass),
                "stiffness": around(s.stiffness, r.stiffness),
                "preload_force": around(s.preload_force, r.preload_force),
                "restitution": restitution,
                "damping_ratio": around(s.damping_ratio, r.damping_ratio),
                "closing_speed": around(s.closing_speed, r.closing_speed),
            });
            Template::parse(&scene).ok().map(|template| Entry {
                name: s.name.to_owned(),
                template,
            })
        })
        .collect()
}

fn entries_of(file: &str, scenes: Vec<Value>) -> Result<Vec<Entry>, Vec<FileError>> {
    let mut out = Vec::new();
    let mut errors = Vec::new();
    for (i, scene) in scenes.into_iter().enumerate() {
        let name = scene
            .get("name")
            .and_then(Value::as_str)
            .map_or_else(|| format!("entry {}", i + 1), str::to_owned);
        let place = format!("entry {} ({name})", i + 1);
        if !scene.is_object() {
            errors.push(FileError {
                file: file.to_owned(),
                place,
                field: String::new(),
                message: "a switch must be a table/object".to_owned(),
            });
            continue;
        }
        // Validate the nominal scene now, so every entry's fault is reported at once.
        let checked = Template::parse(&scene).and_then(|t| {
            crate::scene_input::SceneInput::from_json(t.nominal(), &name)?.core::<f64>()?;
            Ok(t)
        });
        match checked {
            Ok(template) => out.push(Entry { name, template }),
            Err(FieldError { field, message }) => errors.push(FileError {
                file: file.to_owned(),
                place,
                field,
                message,
            }),
        }
    }
    if out.is_empty() && errors.is_empty() {
        errors.push(FileError {
            file: file.to_owned(),
            place: String::new(),
            field: String::new(),
            message: "no switches in the file".to_owned(),
        });
    }
    if errors.is_empty() {
        Ok(out)
    } else {
        Err(errors)
    }
}

/// Reads a scene file: `.toml` (an array of `[[switch]]` tables), `.json` (an array of
/// objects, or an object with a `switch` array) or `.jsonl` (one object a line).
///
/// # Errors
/// Every fault found, each naming the file, the entry (or line) and the field.
pub fn read(path: &str) -> Result<Vec<Entry>, Vec<FileError>> {
    let fail = |place: String, message: String| {
        vec![FileError {
            file: path.to_owned(),
            place,
            field: String::new(),
            message,
        }]
    };
    let text = std::fs::read_to_string(path)
        .map_err(|e| fail(String::new(), format!("cannot read it: {e}")))?;
    let scenes: Vec<Value> = if path.ends_with(".toml") {
        // TOML reads 1e-400 as 0 without a word: a nonzero gap would become no gap.
        if let Some((line, literal)) = crate::strict::toml_underflow(&text) {
            return Err(fail(
                format!("line {line}"),
                format!("{literal} is not zero but reads as 0: out of range"),
            ));
        }
        let doc: toml::Table = toml::from_str(&text).map_err(|e| {
            let line = e.span().map_or(0, |s| {
                text[..s.start.min(text.len())].lines().count().max(1)
            });
            fail(format!("line {line}"), e.message().to_owned())
        })?;
        let mut keys = doc.keys().filter(|k| k.as_str() != "switch");
        if let Some(k) = keys.next() {
            return Err(fail(
                String::new(),
                format!("unknown top-level key '{k}': switches go in [[switch]] tables"),
            ));
        }
        match doc.get("switch") {
            Some(toml::Value::Array(items)) => {
                // NaN and inf have no JSON form: they would vanish into null (an optional
                // field silently absent). Refused by name.
                for (i, item) in items.iter().enumerate() {
                    if let Some(field) = crate::strict::toml_non_finite(item) {
                        return Err(vec![FileError {
                            file: path.to_owned(),
                            place: format!("entry {}", i + 1),
                            field,
                            message: "NaN and inf are not numbers a scene can take".to_owned(),
                        }]);
                    }
                }
                items
                    .iter()
                    .map(|v| serde_json::to_value(v).unwrap_or(Value::Null))
                    .collect()
            }
            _ => return Err(fail(String::new(), "no [[switch]] tables".to_owned())),
        }
    } else if path.ends_with(".jsonl") {
        let mut scenes = Vec::new();
        for (i, line) in text
            .lines()
            .enumerate()
            .filter(|(_, l)| !l.trim().is_empty())
        {
            scenes.push(
                crate::strict::json(line)
                    .map_err(|(_, message)| fail(format!("line {}", i + 1), message))?,
            );
        }
        scenes
    } else {
        let doc: Value = crate::strict::json(&text)
            .map_err(|(line, message)| fail(format!("line {line}"), message))?;
        match doc {
            Value::Array(items) => items,
            Value::Object(mut o) => match o.remove("switch") {
                Some(Value::Array(items)) => items,
                _ => {
                    return Err(fail(
                        String::new(),
                        "expected an array of switches, or an object with a \"switch\" array"
                            .to_owned(),
                    ))
                }
            },
            _ => {
                return Err(fail(
                    String::new(),
                    "expected an array of switches".to_owned(),
                ))
            }
        }
    };
    entries_of(path, scenes)
}
