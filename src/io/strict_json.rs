//! JSON text to a [`serde_json::Value`], refusing an object with a repeated key.
//!
//! RFC 8259 §4 leaves the meaning of an object whose names repeat to the reader, and
//! readers differ: `serde_json::Value` keeps the last value, other parsers the first or
//! all of them. A client and penner could then read different documents from the same
//! bytes. Every JSON document penner reads (surfaces, claims, failure files, scale
//! factors) goes through [`parse`], which refuses a repeated key and names it, the path of
//! its object and the line.
//!
//! The value is built in one pass by a visitor like `serde_json`'s own, with one lookup
//! per object key more; paths are linked on the stack and only formatted for an error.
//!
//! ```
//! use penner::io::strict_json::{parse, JsonError};
//! assert!(parse(r#"{"a": 1, "b": {"c": 2}}"#).is_ok());
//! let Err(JsonError::DuplicateKey(d)) = parse("{\"a\": {\"c\": 1,\n \"c\": 2}}") else {
//!     panic!("a repeated key is refused")
//! };
//! assert_eq!((d.object.as_str(), d.key.as_str(), d.line), ("a", "c", 2));
//! ```

use serde::de::{self, DeserializeSeed, Deserializer, MapAccess, SeqAccess, Visitor};
use serde_json::{Map, Number, Value};
use std::cell::RefCell;
use std::fmt;

/// A key that appears twice in one JSON object.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct DuplicateKey {
    /// Path of the object holding the key (`surface`, `result.faces[2]`), empty for the
    /// top-level object.
    pub object: String,
    /// The repeated key.
    pub key: String,
    /// 1-based line of the second occurrence.
    pub line: usize,
    /// 1-based column just past the second occurrence.
    pub column: usize,
}

impl fmt::Display for DuplicateKey {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "line {} column {}: duplicate key {:?} in ",
            self.line, self.column, self.key
        )?;
        if self.object.is_empty() {
            write!(f, "the top-level object")?;
        } else {
            write!(f, "{}", self.object)?;
        }
        write!(f, " (a key may appear once per object)")
    }
}

/// Why JSON text was refused.
#[derive(Debug, thiserror::Error)]
pub enum JsonError {
    /// Not JSON (syntax, truncation, trailing characters, nesting deeper than 128).
    #[error("{0}")]
    Syntax(serde_json::Error),
    /// Well-formed JSON with a repeated key in one object.
    #[error("{0}")]
    DuplicateKey(DuplicateKey),
}

/// Parse JSON text into a value, refusing a repeated key in any object (module docs).
pub fn parse(text: &str) -> Result<Value, JsonError> {
    let found = RefCell::new(None);
    let mut de = serde_json::Deserializer::from_str(text);
    let seed = Strict {
        path: &Path::Root,
        found: &found,
    };
    let value = seed.deserialize(&mut de).and_then(|v| de.end().map(|()| v));
    value.map_err(|e| match found.into_inner() {
        Some((object, key)) => JsonError::DuplicateKey(DuplicateKey {
            object,
            key,
            line: e.line(),
            column: e.column(),
        }),
        None => JsonError::Syntax(e),
    })
}

/// The path from the document root to a value, linked through the parser's stack frames.
enum Path<'a> {
    Root,
    Key(&'a Path<'a>, &'a str),
    Index(&'a Path<'a>, usize),
}

impl fmt::Display for Path<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Path::Root => Ok(()),
            Path::Key(Path::Root, k) => write!(f, "{k}"),
            Path::Key(p, k) => write!(f, "{p}.{k}"),
            Path::Index(p, i) => write!(f, "{p}[{i}]"),
        }
    }
}

/// The visitor building one value at `path`; a duplicate key is recorded in `found`
/// (object path, key) before the error is raised, so [`parse`] can report it typed.
#[derive(Clone, Copy)]
struct Strict<'a> {
    path: &'a Path<'a>,
    found: &'a RefCell<Option<(String, String)>>,
}

impl<'de> DeserializeSeed<'de> for Strict<'_> {
    type Value = Value;

    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<Value, D::Error> {
        d.deserialize_any(self)
    }
}

impl<'de> Visitor<'de> for Strict<'_> {
    type Value = Value;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a JSON value")
    }

    fn visit_bool<E>(self, b: bool) -> Result<Value, E> {
        Ok(Value::Bool(b))
    }

    fn visit_i64<E>(self, i: i64) -> Result<Value, E> {
        Ok(Value::Number(i.into()))
    }

    fn visit_u64<E>(self, u: u64) -> Result<Value, E> {
        Ok(Value::Number(u.into()))
    }

    fn visit_f64<E>(self, x: f64) -> Result<Value, E> {
        Ok(Number::from_f64(x).map_or(Value::Null, Value::Number))
    }

    fn visit_str<E>(self, s: &str) -> Result<Value, E> {
        Ok(Value::String(s.to_owned()))
    }

    fn visit_string<E>(self, s: String) -> Result<Value, E> {
        Ok(Value::String(s))
    }

    fn visit_unit<E>(self) -> Result<Value, E> {
        Ok(Value::Null)
    }

    fn visit_none<E>(self) -> Result<Value, E> {
        Ok(Value::Null)
    }

    fn visit_some<D: Deserializer<'de>>(self, d: D) -> Result<Value, D::Error> {
        self.deserialize(d)
    }

    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Value, A::Error> {
        let mut out = Vec::with_capacity(seq.size_hint().unwrap_or(0).min(4096));
        loop {
            let path = Path::Index(self.path, out.len());
            let seed = Strict {
                path: &path,
                found: self.found,
            };
            match seq.next_element_seed(seed)? {
                Some(v) => out.push(v),
                None => return Ok(Value::Array(out)),
            }
        }
    }

    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Value, A::Error> {
        let mut out = Map::new();
        while let Some(key) = map.next_key::<String>()? {
            if out.contains_key(&key) {
                let message = format!("duplicate key {key:?}");
                *self.found.borrow_mut() = Some((self.path.to_string(), key));
                return Err(de::Error::custom(message));
            }
            let path = Path::Key(self.path, &key);
            let seed = Strict {
                path: &path,
                found: self.found,
            };
            let v = map.next_value_seed(seed)?;
            out.insert(key, v);
        }
        Ok(Value::Object(out))
    }
}
