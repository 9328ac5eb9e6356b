//! The precisions a check runs at: `f64`, double-double, or MPFR at a chosen bit count,
//! and the parser of the comma list users write (`f64,dd,128,256`).

use super::{Precision, PrecisionError};
use std::fmt;

/// One working precision.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Prec {
    /// IEEE binary64, unit roundoff 2⁻⁵³.
    F64,
    /// Double-double ([`crate::scalar::Dd`]), unit roundoff about 2⁻¹⁰⁴.
    Dd,
    /// MPFR ([`crate::scalar::Mpfr`]) at this many bits, unit roundoff 2⁻ᵖ.
    Mpfr(Precision),
    /// Exact rational arithmetic (checks that have an exact form; needs rational lengths).
    Exact,
}

impl Prec {
    /// Significand bits: 53, 106 or p; 0 for exact arithmetic.
    pub fn bits(self) -> u32 {
        match self {
            Prec::F64 => 53,
            Prec::Dd => 106,
            Prec::Mpfr(p) => p.bits(),
            Prec::Exact => 0,
        }
    }
}

impl fmt::Display for Prec {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Prec::F64 => f.write_str("f64"),
            Prec::Dd => f.write_str("dd"),
            Prec::Mpfr(p) => write!(f, "mpfr-{}", p.bits()),
            Prec::Exact => f.write_str("exact"),
        }
    }
}

/// Why a precision list was refused.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum PrecListError {
    /// The list has no entries.
    #[error("the precision list is empty (expected e.g. `f64,dd,256`)")]
    Empty,
    /// An entry is neither `f64`, `dd`, `exact`, `mpfr-<bits>` nor a bit count.
    #[error("precision `{0}` is not `f64`, `dd`, `exact` or a number of bits such as `256`")]
    Unknown(String),
    /// A bit count outside the supported range.
    #[error("precision `{entry}`: {source}")]
    Range {
        /// The entry as written.
        entry: String,
        /// The range error.
        source: PrecisionError,
    },
}

/// Parse a comma-separated precision list: `f64`, `dd`, a bit count (`128`), `mpfr-128`
/// or `exact`, in any order; repeats are dropped, the order is kept.
///
/// ```
/// use penner::oracle::precision::{parse_list, Prec};
/// let l = parse_list("f64, dd,256").unwrap();
/// assert_eq!(l.iter().map(ToString::to_string).collect::<Vec<_>>(), ["f64", "dd", "mpfr-256"]);
/// assert!(parse_list("99999999").is_err());
/// ```
pub fn parse_list(s: &str) -> Result<Vec<Prec>, PrecListError> {
    let mut out = Vec::new();
    for raw in s.split(',') {
        let entry = raw.trim();
        if entry.is_empty() {
            continue;
        }
        let p = parse_one(entry)?;
        if !out.contains(&p) {
            out.push(p);
        }
    }
    if out.is_empty() {
        return Err(PrecListError::Empty);
    }
    Ok(out)
}

fn parse_one(entry: &str) -> Result<Prec, PrecListError> {
    let lower = entry.to_ascii_lowercase();
    match lower.as_str() {
        "f64" | "double" => return Ok(Prec::F64),
        "dd" | "double-double" => return Ok(Prec::Dd),
        "exact" | "q" => return Ok(Prec::Exact),
        _ => {}
    }
    let digits = lower.strip_prefix("mpfr-").unwrap_or(&lower);
    if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) {
        return Err(PrecListError::Unknown(entry.to_string()));
    }
    // Saturate absurd digit strings; the range check rejects them.
    let bits = digits.parse::<u64>().unwrap_or(u64::MAX);
    Precision::new(bits)
        .map(Prec::Mpfr)
        .map_err(|source| PrecListError::Range {
            entry: entry.to_string(),
            source,
        })
}

/// The default ladder of `penner check`: `f64`, `dd`, MPFR-256.
pub const DEFAULT_LIST: &str = "f64,dd,256";

/// Every precision the report on the built-in corpus runs: the default ladder plus
/// MPFR-128 and exact arithmetic.
pub const REPORT_LIST: &str = "f64,dd,128,256,exact";
