//! One runnable check of the catalogue as the registry lists it, the `at_precision!` macro
//! that runs a check body in the backend of a precision, and the fixed scale factors of
//! the conformal checks: the leaf shared by [`super::registry`] and the check modules
//! (`checks*.rs`, `controls/`).

use super::precision::Prec;
use crate::io::Surface;
use crate::theorems::{Settings, Verdict};
use rug::Rational;

/// Scale factors s_v = e^{u_v/2} = 1 + ((7v + 3) mod 5 − 2)/20 ∈ {9/10, …, 11/10}: a fixed,
/// irregular, exactly rational pattern. The ratio max/min < 1.23 keeps the triangles of
/// well-shaped surfaces triangles after scaling.
pub fn scale_factors(n: usize) -> Vec<Rational> {
    (0..n)
        .map(|v| {
            let k = ((7 * v + 3) % 5) as i64 - 2;
            Rational::from((20 + k, 20))
        })
        .collect()
}

/// One runnable check of the catalogue.
#[derive(Clone, Copy, Debug)]
pub struct Check {
    /// Catalogue ID, `T01` … `T36` (docs/catalogue.md, `proofs/`).
    pub id: &'static str,
    /// Short statement, for tables.
    pub title: &'static str,
    /// Runs the check on a case at one precision; `None` when the check has no form at
    /// that precision (e.g. an exact-only check at `f64`) — the row is then left out.
    pub run: fn(&Surface, Prec, &Settings) -> Option<Verdict>,
}

/// Run `$body` with `$l` bound to the case's lengths in the backend of `$prec`
/// (`Vec<f64>`, `Vec<Dd>` or `Vec<Mpfr>`); `$t` names the backend type inside `$body`.
/// At `Prec::Exact` the macro yields `None` (use the check's exact form instead).
#[allow(unused_macros)]
macro_rules! at_precision {
    ($prec:expr, $case:expr, |$l:ident : $t:ident| $body:expr) => {
        match $prec {
            $crate::oracle::precision::Prec::F64 => {
                type $t = f64;
                let $l: Vec<$t> = $case.lengths::<$t>(());
                $body
            }
            $crate::oracle::precision::Prec::Dd => {
                type $t = $crate::scalar::Dd;
                let $l: Vec<$t> = $case.lengths::<$t>(());
                $body
            }
            $crate::oracle::precision::Prec::Mpfr(p) => {
                type $t = $crate::scalar::Mpfr;
                let $l: Vec<$t> = $case.lengths::<$t>(p);
                $body
            }
            $crate::oracle::precision::Prec::Exact => None,
        }
    };
}
