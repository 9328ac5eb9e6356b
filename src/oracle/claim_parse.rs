//! The parse error of the claim protocol and the field readers shared by the claim parser
//! [`super::claim`] and the per-kind parsers [`super::claim_circles`] and
//! [`super::claim_hyperbolic`].

use crate::io::json::exact_number;
use crate::io::ReadError;
use rug::Rational;
use serde_json::Value;

/// Why a claim was refused (bad input): the JSON path of the offending value and why.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{0}")]
pub struct ClaimError(pub String);

impl From<ReadError> for ClaimError {
    fn from(e: ReadError) -> ClaimError {
        ClaimError(e.to_string())
    }
}

/// A refusal with this message.
pub(super) fn err(msg: impl Into<String>) -> ClaimError {
    ClaimError(msg.into())
}

pub(super) fn numbers(
    v: &Value,
    path: &str,
    expected: usize,
    what: &str,
) -> Result<Vec<Rational>, ClaimError> {
    let arr = v.as_array().ok_or_else(|| {
        err(format!(
            "{path}: expected an array with one entry per {what}"
        ))
    })?;
    if arr.len() != expected {
        return Err(err(format!(
            "{path}: {} entries, but the surface has {expected} {what}(s)",
            arr.len()
        )));
    }
    arr.iter()
        .enumerate()
        .map(|(i, x)| exact_number(x, &format!("{path}[{i}]")).map_err(ClaimError::from))
        .collect()
}

pub(super) fn epsilon(v: &Value) -> Result<Rational, ClaimError> {
    let e = exact_number(
        v.get("epsilon")
            .ok_or_else(|| err("epsilon: required for this claim kind"))?,
        "epsilon",
    )?;
    if e.cmp0() == std::cmp::Ordering::Less {
        return Err(err(format!("epsilon: must be ≥ 0, found {e}")));
    }
    Ok(e)
}

/// The array of edge indices at `key`.
pub(crate) fn edge_indices(v: &Value, key: &str) -> Result<Vec<usize>, ClaimError> {
    v.get(key)
        .ok_or_else(|| err(format!("{key}: required")))?
        .as_array()
        .ok_or_else(|| err(format!("{key}: expected an array of edge indices")))?
        .iter()
        .enumerate()
        .map(|(k, x)| {
            x.as_u64()
                .map(|i| i as usize)
                .ok_or_else(|| err(format!("{key}[{k}]: expected a non-negative integer")))
        })
        .collect()
}
