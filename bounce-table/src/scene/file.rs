//! Reading switches: the built-in catalogue, or a scene file (TOML, JSON or JSON Lines) whose
//! entries use the keys of `eval` and may carry ranges (see [`crate::scene::spreads`]).

use serde_json::{json, Value};

use crate::scene::input::{FieldError, FlatScene};
use crate::scene::spreads::Template;

/// One switch to analyse.
#[derive(Debug, Clone, PartialEq)]
pub struct Entry {
    /// Its name (or "entry N").
    pub name: String,
    /// Its scene, with ranges.
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

/// One line: control characters in names and keys from the file are shown escaped.
impl std::fmt::Display for FileError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        use crate::support::strict::printable;
        write!(f, "{}", printable(&self.file))?;
        if !self.place.is_empty() {
            write!(f, ": {}", printable(&self.place))?;
        }
        if !self.field.is_empty() {
            write!(f, ": {}", printable(&self.field))?;
        }
        write!(f, ": {}", printable(&self.message))
    }
}

/// The catalogue's typical switches, each parameter over its assumed range
/// ([`crate::scene::priors::CATALOGUE_RANGES`]): their windows are a high percentile over those ranges.
#[must_use]
pub fn catalogue() -> Vec<Entry> {
    contact_bounce::scene::catalogue::ALL
        .iter()
        .filter_map(|s| {
            let r = crate::scene::priors::CATALOGUE_RANGES;
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
            Template::parse(&scene, s.name).ok().map(|template| Entry {
                name: s.name.to_owned(),
                template,
            })
        })
        .collect()
}

/// One entry of a scene file (its place `index`, from 0), parsed: a table/object whose
/// ranges parse. [`check`] says whether its nominal scene makes a scene.
fn entry_of(file: &str, index: usize, scene: Value) -> Result<Entry, FileError> {
    let name = scene
        .get("name")
        .and_then(Value::as_str)
        .map_or_else(|| format!("entry {}", index + 1), str::to_owned);
    let fault = |field: String, message: String| FileError {
        file: file.to_owned(),
        place: format!("entry {} ({name})", index + 1),
        field,
        message,
    };
    if !scene.is_object() {
        return Err(fault(
            String::new(),
            "a switch must be a table/object".to_owned(),
        ));
    }
    match Template::from_value(scene, &name) {
        Ok(template) => Ok(Entry { name, template }),
        Err(FieldError { field, message }) => Err(fault(field, message)),
    }
}

/// A JSON Lines entry read flat ([`FlatScene`]), named as [`entry_of`] names it; `None` where
/// the line needs the full reading, or has a fault (which the full reading names).
fn flat_entry(line: &str, index: usize) -> Option<Entry> {
    let mut flat = FlatScene::read(line)?;
    let name = flat
        .take_name()
        .unwrap_or_else(|| format!("entry {}", index + 1));
    let template = Template::from_flat(&flat, &name).ok()?;
    Some(Entry { name, template })
}

/// Whether an entry's nominal scene makes a scene (the fault of an entry that parsed).
///
/// # Errors
/// The field at fault.
pub fn check(entry: &Entry) -> Result<(), FieldError> {
    entry.template.nominal().core::<f64>()?;
    Ok(())
}

/// The entries of a scene file, one at a time, each parsed or its fault (not yet
/// [`check`]ed): a JSON Lines file is read a line at a time, so its length does not bound the
/// memory a run takes. [`Entries::next_raw`] gives them unparsed, to parse on any thread.
pub struct Entries {
    file: std::sync::Arc<str>,
    source: Source,
    index: usize,
}

enum Source {
    /// Entries ready (the catalogue).
    Ready(std::vec::IntoIter<Entry>),
    /// The entries of a whole document (TOML, JSON).
    Document(std::vec::IntoIter<Value>),
    /// A JSON Lines file (or text): its lines and the number of the last read.
    Lines(
        Box<dyn Iterator<Item = std::io::Result<String>> + Send>,
        usize,
    ),
}

/// An entry as read from its file, not yet parsed: [`Raw::entry`] parses it.
pub struct Raw {
    file: std::sync::Arc<str>,
    index: usize,
    item: Item,
}

enum Item {
    Ready(Entry),
    Value(Value),
    /// A line of a JSON Lines file, and its number.
    Line(String, usize),
    Fault(FileError),
}

impl Raw {
    /// The entry, parsed, or its fault (naming the file, and the entry or line).
    ///
    /// # Errors
    /// As [`Entries`].
    pub fn entry(&self) -> Result<Entry, FileError> {
        match &self.item {
            Item::Ready(e) => Ok(e.clone()),
            Item::Value(v) => entry_of(&self.file, self.index, v.clone()),
            Item::Line(l, number) => match flat_entry(l, self.index) {
                Some(entry) => Ok(entry),
                None => self.line_entry(l, *number),
            },
            Item::Fault(e) => Err(e.clone()),
        }
    }

    /// A line read in full (a JSON value, then a scene): what a line not read flat takes,
    /// and what names a line's fault.
    fn line_entry(&self, l: &str, number: usize) -> Result<Entry, FileError> {
        match crate::support::strict::json(l) {
            Ok(v) => entry_of(&self.file, self.index, v),
            Err((_, message)) => Err(FileError {
                file: self.file.to_string(),
                place: format!("line {number}"),
                field: String::new(),
                message,
            }),
        }
    }

    /// The file it is read from.
    #[must_use]
    pub fn file(&self) -> &str {
        &self.file
    }

    /// Its place in the file, from 0 (blank lines do not count).
    #[must_use]
    pub fn index(&self) -> usize {
        self.index
    }
}

impl Entries {
    /// The entries of JSON Lines held in memory, named `file` in faults (the page in `web/`
    /// gives its scene lines this way, for the same reading a `.jsonl` file gets).
    #[must_use]
    pub fn from_json_lines(file: &str, text: &str) -> Self {
        let lines: Vec<std::io::Result<String>> = text.lines().map(|l| Ok(l.to_owned())).collect();
        Self {
            file: file.into(),
            source: Source::Lines(Box::new(lines.into_iter()), 0),
            index: 0,
        }
    }

    /// The catalogue's entries, as a file's.
    #[must_use]
    pub fn catalogue() -> Self {
        Self {
            file: "catalogue".into(),
            source: Source::Ready(catalogue().into_iter()),
            index: 0,
        }
    }

    /// The next entry, unparsed.
    pub fn next_raw(&mut self) -> Option<Raw> {
        let item = match &mut self.source {
            Source::Ready(items) => Item::Ready(items.next()?),
            Source::Document(items) => Item::Value(items.next()?),
            Source::Lines(lines, number) => loop {
                let line = lines.next()?;
                *number += 1;
                match line {
                    Err(e) => {
                        // An unreadable file gives the same error at every line: end here.
                        let fault = Item::Fault(FileError {
                            file: self.file.to_string(),
                            place: format!("line {number}"),
                            field: String::new(),
                            message: format!("cannot read it: {e}"),
                        });
                        self.source = Source::Document(Vec::new().into_iter());
                        break fault;
                    }
                    Ok(l) if l.trim().is_empty() => {}
                    Ok(l) => break Item::Line(l, *number),
                }
            },
        };
        let raw = Raw {
            file: self.file.clone(),
            index: self.index,
            item,
        };
        self.index += 1;
        Some(raw)
    }
}

impl Iterator for Entries {
    type Item = Result<Entry, FileError>;

    fn next(&mut self) -> Option<Self::Item> {
        self.next_raw().map(|raw| raw.entry())
    }
}

/// Reads a scene file: `.toml` (an array of `[[switch]]` tables), `.json` (an array of
/// objects, or an object with a `switch` array) or `.jsonl` (one object a line).
///
/// # Errors
/// Every fault found, each naming the file, the entry (or line) and the field.
pub fn read(path: &str) -> Result<Vec<Entry>, Vec<FileError>> {
    let mut entries = Vec::new();
    let mut errors = Vec::new();
    for (i, entry) in open(path)?.enumerate() {
        match entry.and_then(|e| match check(&e) {
            Ok(()) => Ok(e),
            Err(FieldError { field, message }) => Err(FileError {
                file: path.to_owned(),
                place: format!("entry {} ({})", i + 1, e.name),
                field,
                message,
            }),
        }) {
            Ok(e) => entries.push(e),
            Err(e) => errors.push(e),
        }
    }
    if entries.is_empty() && errors.is_empty() {
        errors.push(FileError {
            file: path.to_owned(),
            place: String::new(),
            field: String::new(),
            message: "no switches in the file".to_owned(),
        });
    }
    if errors.is_empty() {
        Ok(entries)
    } else {
        Err(errors)
    }
}

/// Opens a scene file as for [`read`], and gives its entries one at a time ([`Entries`]). A
/// file with no entries gives none: the caller says so.
///
/// # Errors
/// A file that cannot be opened, or a document (TOML, JSON) that does not parse.
pub fn open(path: &str) -> Result<Entries, Vec<FileError>> {
    let fail = |place: String, message: String| {
        vec![FileError {
            file: path.to_owned(),
            place,
            field: String::new(),
            message,
        }]
    };
    if path.ends_with(".jsonl") {
        let file = std::fs::File::open(path)
            .map_err(|e| fail(String::new(), format!("cannot read it: {e}")))?;
        return Ok(Entries {
            file: path.into(),
            source: Source::Lines(
                Box::new(std::io::BufRead::lines(std::io::BufReader::new(file))),
                0,
            ),
            index: 0,
        });
    }
    let text = std::fs::read_to_string(path)
        .map_err(|e| fail(String::new(), format!("cannot read it: {e}")))?;
    let scenes: Vec<Value> = if path.ends_with(".toml") {
        // TOML reads 1e-400 as 0 without a word: a nonzero gap would become no gap.
        if let Some((line, literal)) = crate::support::strict::toml_underflow(&text) {
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
                    if let Some(field) = crate::support::strict::toml_non_finite(item) {
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
    } else {
        let doc: Value = crate::support::strict::json(&text)
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
    Ok(Entries {
        file: path.into(),
        source: Source::Document(scenes.into_iter()),
        index: 0,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn full(line: &str, index: usize) -> Result<Entry, FileError> {
        let value = crate::support::strict::json(line).map_err(|(_, message)| FileError {
            file: "t".to_owned(),
            place: String::new(),
            field: String::new(),
            message,
        })?;
        entry_of("t", index, value)
    }

    #[test]
    fn json_lines_in_memory_read_as_the_same_lines_in_a_file() {
        // Blank lines skipped, a fault named by its line, the entries indexed alike.
        let text = "\n{\"name\": \"dome\", \"mass\": 5e-05, \"stiffness\": 5000, \"preload_force\": 1.0, \"restitution\": 0.7, \"closing_speed\": 0.5}\n\n{\"omega\": 1e4}\nnot json\n";
        let dir = std::env::temp_dir().join(format!("scenes-memory-{}", std::process::id()));
        std::fs::create_dir_all(&dir).expect("a temporary directory");
        let path = dir.join("s.jsonl");
        std::fs::write(&path, text).expect("written");
        let path = path.to_string_lossy().into_owned();
        let from_file: Vec<_> = open(&path).expect("opened").collect();
        let from_memory: Vec<_> = Entries::from_json_lines(&path, text).collect();
        std::fs::remove_dir_all(&dir).ok();
        assert_eq!(from_file.len(), 3);
        assert_eq!(from_file, from_memory);
        assert!(from_memory[0].is_ok());
        let fault = from_memory[2].as_ref().expect_err("not JSON");
        assert_eq!(fault.place, "line 5");
    }

    #[test]
    fn a_line_read_flat_is_the_scene_the_full_reading_gives() {
        let lines = [
            r#"{"name": "dome", "mass": 5e-05, "stiffness": 5000, "preload_force": 1.0, "restitution": 0.7, "damping_ratio": 0.03, "closing_speed": 0.5}"#,
            r#"{"omega": 1e4, "gap": -1e-6, "restitution": 0.5, "closing_speed": 18446744073709551615, "threshold_impulse": 1e-9}"#,
            r#"{"name": null, "omega": 1e4, "gap": 2e-6, "restitution": 1, "closing_speed": 0.1, "threshold_fraction": 0.01}"#,
            r#"{"name": "a\nb \u00e9", "m\u0061ss": 1, "stiffness": 2, "preload_force": 3, "restitution": 0.5, "closing_speed": -0.5, "damping_ratio": null}"#,
        ];
        for (i, line) in lines.iter().enumerate() {
            let flat = flat_entry(line, i).expect("read flat");
            assert_eq!(Ok(flat), full(line, i), "{line}");
        }
    }

    #[test]
    fn a_line_the_flat_reading_cannot_vouch_for_takes_the_full_reading() {
        let base = r#""omega": 1e4, "gap": -1e-6, "restitution": 0.5, "closing_speed": 1"#;
        for line in [
            // Faults the full reading names: a key twice, a literal that underflows, one
            // that overflows, a string for a number, a name that is not a string, an unknown
            // key, a missing or conflicting field, not JSON.
            format!(r#"{{{base}, "gap": -2e-6}}"#),
            format!(r#"{{{base}, "damping_ratio": 1e-400}}"#),
            format!(r#"{{{base}, "damping_ratio": 1e400}}"#),
            format!(r#"{{{base}, "damping_ratio": "0.1"}}"#),
            format!(r#"{{{base}, "name": 7}}"#),
            format!(r#"{{{base}, "colour": 1}}"#),
            r#"{"omega": 1e4, "restitution": 0.5, "closing_speed": 1}"#.to_owned(),
            format!(r#"{{{base}, "preload_force": 1}}"#),
            format!(r#"{{{base}}} x"#),
            // Readings it leaves to the full one: a range, a kernel, a value read as 0.
            format!(r#"{{{base}, "damping_ratio": {{"min": 0.01, "max": 0.02}}}}"#),
            format!(r#"{{{base}, "kernel": {{"kappa": 1, "tau": 1}}}}"#),
            format!(r#"{{{base}, "damping_ratio": 0}}"#),
        ] {
            assert!(flat_entry(&line, 0).is_none(), "{line}");
        }
    }
}
