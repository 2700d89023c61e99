//! Strict reading of scene files: what `serde_json` and `toml` accept but a scene must not.
//!
//! - A key given twice in one JSON object (JSON keeps the last one silently): refused.
//! - A number literal (JSON or TOML) that underflows to 0 or that has no finite value (`1e-400`
//!   parses as 0): refused, so a nonzero gap never becomes no gap.
//! - TOML's `nan` and `inf`: refused by the path of the field that holds them.

use std::fmt;

use serde::de::{self, Deserialize, Deserializer, MapAccess, SeqAccess, Visitor};
use serde_json::{Map, Value};

/// A JSON value read with duplicate keys refused.
struct Strict(Value);

struct StrictVisitor;

impl<'de> Visitor<'de> for StrictVisitor {
    type Value = Value;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a JSON value")
    }
    fn visit_bool<E>(self, v: bool) -> Result<Value, E> {
        Ok(Value::Bool(v))
    }
    fn visit_i64<E>(self, v: i64) -> Result<Value, E> {
        Ok(Value::from(v))
    }
    fn visit_u64<E>(self, v: u64) -> Result<Value, E> {
        Ok(Value::from(v))
    }
    fn visit_f64<E>(self, v: f64) -> Result<Value, E> {
        Ok(Value::from(v))
    }
    fn visit_str<E>(self, v: &str) -> Result<Value, E> {
        Ok(Value::String(v.to_owned()))
    }
    fn visit_string<E>(self, v: String) -> Result<Value, E> {
        Ok(Value::String(v))
    }
    fn visit_unit<E>(self) -> Result<Value, E> {
        Ok(Value::Null)
    }
    fn visit_none<E>(self) -> Result<Value, E> {
        Ok(Value::Null)
    }
    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Value, A::Error> {
        let mut out = Vec::new();
        while let Some(Strict(v)) = seq.next_element()? {
            out.push(v);
        }
        Ok(Value::Array(out))
    }
    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Value, A::Error> {
        let mut out = Map::new();
        while let Some(key) = map.next_key::<String>()? {
            if out.contains_key(&key) {
                return Err(de::Error::custom(format!(
                    "the key \"{key}\" is given twice in one object"
                )));
            }
            let Strict(v) = map.next_value()?;
            out.insert(key, v);
        }
        Ok(Value::Object(out))
    }
}

impl<'de> Deserialize<'de> for Strict {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        d.deserialize_any(StrictVisitor).map(Strict)
    }
}

/// The first number literal of `text` (JSON, outside strings) that is not zero but reads as
/// zero, with its line (from 1).
fn underflow(text: &str) -> Option<(usize, String)> {
    let bytes = text.as_bytes();
    let (mut i, mut line, mut in_string) = (0, 1, false);
    while i < bytes.len() {
        let c = bytes[i];
        if c == b'\n' {
            line += 1;
        }
        if in_string {
            match c {
                b'\\' => i += 1,
                b'"' => in_string = false,
                _ => {}
            }
            i += 1;
            continue;
        }
        if c == b'"' {
            in_string = true;
            i += 1;
            continue;
        }
        if c == b'-' || c.is_ascii_digit() {
            let start = i;
            while i < bytes.len()
                && matches!(bytes[i], b'0'..=b'9' | b'-' | b'+' | b'.' | b'e' | b'E')
            {
                i += 1;
            }
            let literal = &text[start..i];
            let mut parts = literal.split(['e', 'E']);
            let mantissa = parts.next().unwrap_or("");
            let nonzero = mantissa.bytes().any(|b| (b'1'..=b'9').contains(&b));
            // A nonzero literal of L characters is at least 10^-L times 10^exponent, so it can
            // read as 0 (below 2.5e-324) only if L + |exponent| > 323: an exponent of three
            // significant digits or more, or a literal of over 200 characters. Only those are
            // parsed (most literals are not: this scan runs on every line of a scene file).
            let exponent = parts.next().unwrap_or("");
            let long_exponent = exponent
                .trim_start_matches(['-', '+'])
                .trim_start_matches('0')
                .len()
                >= 3;
            if nonzero
                && (long_exponent || literal.len() > 200)
                && literal.parse::<f64>().is_ok_and(|v| v == 0.0)
            {
                return Some((line, literal.to_owned()));
            }
            continue;
        }
        i += 1;
    }
    None
}

/// `text` with its control characters escaped (`\n`, `\u{1b}`): a name or key from a file,
/// echoed in a one-line message, can neither break the line nor drive the terminal.
#[must_use]
pub fn printable(text: &str) -> std::borrow::Cow<'_, str> {
    if text.chars().any(char::is_control) {
        text.chars()
            .map(|c| {
                if c.is_control() {
                    c.escape_default().to_string()
                } else {
                    c.to_string()
                }
            })
            .collect::<String>()
            .into()
    } else {
        text.into()
    }
}

/// Parses JSON strictly (see the module docs).
///
/// # Errors
/// The line (from 1) and what is wrong.
pub fn json(text: &str) -> Result<Value, (usize, String)> {
    if let Some((line, literal)) = underflow(text) {
        return Err((
            line,
            format!("{literal} is not zero but reads as 0: out of range"),
        ));
    }
    let mut d = serde_json::Deserializer::from_str(text);
    let Strict(v) =
        Strict::deserialize(&mut d).map_err(|e| (e.line(), format!("not JSON: {e}")))?;
    d.end().map_err(|e| (e.line(), format!("not JSON: {e}")))?;
    Ok(v)
}

/// The first float literal of a TOML document that is not zero but reads as zero (`1e-400`),
/// with its line (from 1). `None` also where the text is not TOML (its parser says why).
#[must_use]
pub fn toml_underflow(text: &str) -> Option<(usize, String)> {
    use toml::de::{DeTable, DeValue};
    use toml::Spanned;
    fn walk<'i>(v: &Spanned<DeValue<'i>>, text: &str) -> Option<(usize, String)> {
        match v.get_ref() {
            DeValue::Float(f) => {
                let literal = f.as_str();
                let mantissa = literal.split(['e', 'E']).next().unwrap_or("");
                let nonzero = mantissa.bytes().any(|b| (b'1'..=b'9').contains(&b));
                (nonzero && literal.parse::<f64>().is_ok_and(|x| x == 0.0)).then(|| {
                    let start = v.span().start.min(text.len());
                    let line = text.get(..start).map_or(1, |t| t.lines().count().max(1));
                    (line, literal.to_owned())
                })
            }
            DeValue::Array(items) => items.iter().find_map(|i| walk(i, text)),
            DeValue::Table(t) => t.iter().find_map(|(_, i)| walk(i, text)),
            _ => None,
        }
    }
    let doc = DeTable::parse(text).ok()?;
    doc.get_ref().iter().find_map(|(_, v)| walk(v, text))
}

/// The dotted path of the first NaN or infinite float in `v`, if any.
#[must_use]
pub fn toml_non_finite(v: &toml::Value) -> Option<String> {
    match v {
        toml::Value::Float(f) if !f.is_finite() => Some(String::new()),
        toml::Value::Table(t) => t.iter().find_map(|(k, v)| {
            toml_non_finite(v).map(|p| {
                if p.is_empty() {
                    k.clone()
                } else {
                    format!("{k}.{p}")
                }
            })
        }),
        toml::Value::Array(a) => a.iter().enumerate().find_map(|(i, v)| {
            toml_non_finite(v).map(|p| {
                if p.is_empty() {
                    format!("{i}")
                } else {
                    format!("{i}.{p}")
                }
            })
        }),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn duplicates_and_underflows_are_refused_and_the_rest_reads_as_json_does() {
        let ok = r#"[{"a": 1, "b": {"c": [1.5, -2e-3, "x\"1e-400"]}}]"#;
        assert_eq!(
            json(ok),
            Ok(serde_json::from_str::<Value>(ok).unwrap_or_default())
        );
        let dup = "[{\"a\": 1,\n \"a\": 2}]";
        let (line, message) = json(dup).expect_err("duplicate");
        assert_eq!(line, 2);
        assert!(message.contains("\"a\" is given twice"), "{message}");
        let (line, message) = json("{\n\"gap\": 1e-400}").expect_err("underflow");
        assert_eq!(line, 2);
        assert!(message.contains("1e-400"), "{message}");
        // Zero written as zero is zero.
        assert!(json("{\"gap\": 0.0e-400, \"b\": 0}").is_ok());
        // Underflows the scan's shortcut must still see: padded exponents, long mantissas with
        // a short exponent, and long literals with none.
        let zeros = |n: usize| "0".repeat(n);
        for literal in [
            "1e-0000400".to_owned(),
            format!("0.{}1e-99", zeros(250)),
            format!("0.{}1", zeros(330)),
            format!("-{}e-330", "1".repeat(3)),
        ] {
            let (_, message) = json(&format!("{{\"gap\": {literal}}}")).expect_err(&literal);
            assert!(message.contains("reads as 0"), "{literal}: {message}");
        }
        // And the smallest numbers that do not underflow read as they are.
        for literal in ["5e-324", "1e-99", "4.9e-324"] {
            assert!(
                json(&format!("{{\"gap\": {literal}}}")).is_ok(),
                "{literal}"
            );
        }
        assert!(json("[1] [2]").is_err());
    }

    #[test]
    fn toml_nan_and_inf_are_found_by_path() {
        let t: toml::Table = toml::from_str("[x]\na = 1.0\nb = { c = nan }\n").unwrap_or_default();
        assert_eq!(
            toml_non_finite(&toml::Value::Table(t)),
            Some("x.b.c".to_owned())
        );
        let t: toml::Table = toml::from_str("a = [1.0, -inf]\n").unwrap_or_default();
        assert_eq!(
            toml_non_finite(&toml::Value::Table(t)),
            Some("a.1".to_owned())
        );
    }

    #[test]
    fn toml_underflows_are_found_where_they_are_and_zeros_are_not() {
        assert_eq!(toml_underflow("a = 1.0\nb = 0.0e-400\nc = 0e5\n"), None);
        assert_eq!(
            toml_underflow("a = 1.0\n\n[t]\nb = [1.0, { c = 1_0.5e-400 }]\n"),
            Some((4, "10.5e-400".to_owned()))
        );
        assert_eq!(toml_underflow("not toml = = 1e-400"), None);
    }
}
