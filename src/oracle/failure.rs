//! Failure files: what `penner check` writes when a check fails — the check, the
//! precision, every witness, and a shrunk surface that still fails — and what
//! `penner replay` reads back.
//!
//! Format (`"penner_failure": 1`):
//! ```json
//! { "penner_failure": 1, "check": "T01", "precision": "mpfr-256",
//!   "source": "my_surface.json", "source_faces": 20,
//!   "witnesses": [ { "element": "v3", "detail": "…", "value": 1e-3 } ],
//!   "surface": { "vertices": 4, "faces": [[0,1,2], …], "gluing": [[[0,0],[1,2]], …],
//!                "squared_lengths": ["2", "9/4", …] } }
//! ```
//! `surface` is a surface in the JSON surface format (`docs/surface-format.md`), so it can
//! be cut out and given to `penner check` as it is.

use super::precision::{parse_list, Prec};
use crate::io::strict_json::{self, JsonError};
use crate::io::{json as surface_json, Surface};
use crate::theorems::Witness;
use serde_json::{json, Value};

/// Why a failure file was refused.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{0}")]
pub struct FailureFileError(pub String);

fn bad(msg: impl Into<String>) -> FailureFileError {
    FailureFileError(msg.into())
}

/// Version of the failure-file format.
pub const FORMAT_VERSION: u64 = 1;

/// The fields of a failure file; any other is refused.
const FIELDS: [&str; 7] = [
    "penner_failure",
    "check",
    "precision",
    "source",
    "source_faces",
    "witnesses",
    "surface",
];

/// A failure file's contents.
#[derive(Clone, Debug, PartialEq)]
pub struct Failure {
    /// Catalogue ID of the failing check.
    pub check: String,
    /// The precision it failed at.
    pub precision: Prec,
    /// Where the original surface came from.
    pub source: String,
    /// Number of faces of the original surface.
    pub source_faces: usize,
    /// Every witness of the failure on the original surface.
    pub witnesses: Vec<Witness>,
    /// The shrunk surface that still fails.
    pub surface: Surface,
}

impl Failure {
    /// As JSON (see the module documentation).
    pub fn to_json(&self) -> Value {
        json!({
            "penner_failure": FORMAT_VERSION,
            "check": self.check,
            "precision": self.precision.to_string(),
            "source": self.source,
            "source_faces": self.source_faces,
            "witnesses": self.witnesses,
            "surface": surface_json::to_value(&self.surface),
        })
    }

    /// Read a failure file's text; `name` names the file in messages. A repeated key
    /// ([`crate::io::strict_json`]) or an unknown field is refused.
    pub fn parse(text: &str, name: &str) -> Result<Failure, FailureFileError> {
        let v = strict_json::parse(text).map_err(|e| match e {
            JsonError::Syntax(e) => bad(format!("{name}:{}:{}: {e}", e.line(), e.column())),
            JsonError::DuplicateKey(d) => bad(format!("{name}: {d}")),
        })?;
        match v.get("penner_failure").and_then(Value::as_u64) {
            Some(FORMAT_VERSION) => {}
            Some(other) => {
                return Err(bad(format!(
                    "{name}: failure-file version {other} is not supported (this build reads version {FORMAT_VERSION})"
                )))
            }
            None => {
                return Err(bad(format!(
                    "{name}: not a penner failure file (no \"penner_failure\": {FORMAT_VERSION})"
                )))
            }
        }
        if let Some(key) = v
            .as_object()
            .and_then(|o| o.keys().find(|k| !FIELDS.contains(&k.as_str())))
        {
            return Err(bad(format!(
                "{name}: {key}: unknown field (a failure file has {})",
                FIELDS.join(", ")
            )));
        }
        let check = v["check"]
            .as_str()
            .ok_or_else(|| bad(format!("{name}: `check` must be a catalogue ID string")))?
            .to_string();
        let precision = v["precision"]
            .as_str()
            .ok_or_else(|| bad(format!("{name}: `precision` must be a string")))
            .and_then(|p| parse_list(p).map_err(|e| bad(format!("{name}: precision: {e}"))))?;
        let [precision] = precision[..] else {
            return Err(bad(format!("{name}: `precision` must name one precision")));
        };
        let witnesses: Vec<Witness> = serde_json::from_value(v["witnesses"].clone())
            .map_err(|e| bad(format!("{name}: witnesses: {e}")))?;
        let surface = surface_json::from_value(&v["surface"])
            .map_err(|e| bad(format!("{name}: surface: {e}")))?;
        Ok(Failure {
            check,
            precision,
            source: v["source"].as_str().unwrap_or("").to_string(),
            source_faces: v["source_faces"].as_u64().unwrap_or(0) as usize,
            witnesses,
            surface,
        })
    }
}
