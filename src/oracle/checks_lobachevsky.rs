//! The registry entry of T30 (identities of Lobachevsky's function). T30 does not depend on
//! a surface: each case supplies arguments — its first eight edge lengths — next to two
//! fixed ones (`1/3`, `1000003/7`), so every case runs the identities on fresh numbers.

use super::check_entry::Check;
use super::precision::Prec;
use crate::io::Surface;
use crate::scalar::{Dd, Mpfr, Precision, Real};
use crate::theorems::t30_lobachevsky::{check_lobachevsky, check_lobachevsky_certified};
use crate::theorems::{Settings, Verdict};
use rug::Rational;

/// Edge lengths used as arguments per case.
const LENGTH_ARGUMENTS: usize = 8;

/// Precision of the certified (`exact`) row.
const CERTIFIED_BITS: u32 = 256;

fn fixed() -> [Rational; 2] {
    [Rational::from((1, 3)), Rational::from((1000003, 7))]
}

fn arguments<T: Real>(case: &Surface, ctx: T::Ctx) -> Vec<T> {
    let mut a: Vec<T> = case
        .lengths::<T>(ctx)
        .into_iter()
        .take(LENGTH_ARGUMENTS)
        .collect();
    a.extend(fixed().iter().map(|q| T::from_rational(q, ctx)));
    a
}

/// Runs T30 (or its control with `wrong`) at one precision.
pub fn t30_at(case: &Surface, prec: Prec, wrong: bool) -> Verdict {
    match prec {
        Prec::F64 => check_lobachevsky(&arguments::<f64>(case, ()), wrong),
        Prec::Dd => check_lobachevsky(&arguments::<Dd>(case, ()), wrong),
        Prec::Mpfr(p) => check_lobachevsky(&arguments::<Mpfr>(case, p), wrong),
        Prec::Exact => {
            let p = Precision::new(u64::from(CERTIFIED_BITS))
                .unwrap_or_else(|_| unreachable!("256 bits is in range"));
            let args: Vec<Rational> = arguments::<Mpfr>(case, p)
                .iter()
                .filter_map(Real::to_rational)
                .collect();
            check_lobachevsky_certified(&args, CERTIFIED_BITS, wrong)
        }
    }
}

#[allow(clippy::unnecessary_wraps)] // the registry's signature
fn t30(case: &Surface, prec: Prec, _: &Settings) -> Option<Verdict> {
    Some(t30_at(case, prec, false))
}

/// The T30 entry.
pub fn entries() -> Vec<Check> {
    vec![Check {
        id: "T30",
        title: "Lobachevsky Л identities",
        run: t30,
    }]
}
