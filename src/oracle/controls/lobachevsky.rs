//! T30-NC: the identities of T30 with the argument of one side multiplied by 101/100.

use crate::io::Surface;
use crate::oracle::checks_lobachevsky::t30_at;
use crate::oracle::precision::Prec;
use crate::oracle::registry::Check;
use crate::theorems::{Settings, Verdict};

#[allow(clippy::unnecessary_wraps)] // the registry's signature
fn t30_nc(case: &Surface, prec: Prec, _: &Settings) -> Option<Verdict> {
    Some(t30_at(case, prec, true))
}

/// The T30 control.
pub fn controls() -> Vec<Check> {
    vec![Check {
        id: "T30-NC",
        title: "control: one side's argument × 1.01",
        run: t30_nc,
    }]
}
