//! Shared pieces of the f64 filters: input conversion and the filter decision.

use crate::scalar::{Interval, Mpfr, Precision, Real, Sign};
use rug::Rational;

/// The ring operations the determinant formulas need, so one formula serves `f64` (the
/// filter), `Interval<Mpfr>` (the enclosure) and `rug::Rational` (the exact value).
pub(crate) use crate::scalar::Ring;

pub(crate) use crate::scalar::interval::next_up_f64 as next_up;

/// Unit roundoff of binary64, `u = 2⁻⁵³`.
pub(crate) const U: f64 = f64::EPSILON / 2.0;

/// The f64 nearest to `q` when it is usable by a filter: `q = 0` exactly, or the nearest
/// value is a normal number (so `|x − q| ≤ u|x|`, proofs/B23). `None` otherwise (subnormal,
/// zero for a nonzero `q`, or overflow).
pub(crate) fn input(q: &Rational) -> Option<f64> {
    if q.cmp0().is_eq() {
        return Some(0.0);
    }
    // Fast path: a dyadic rational with at most 53 significant bits is exactly an f64
    // (truncating conversion is then exact); this covers every input that came from an f64.
    if q.denom().is_power_of_two() && q.numer().significant_bits() <= 53 {
        let x = q.to_f64();
        if x.is_normal() {
            return Some(x);
        }
    }
    let x = crate::scalar::nearest_f64(q);
    x.is_normal().then_some(x)
}

/// The f64 inputs of a filter, all usable, or `None`.
pub(crate) fn inputs<const N: usize>(qs: &[Rational; N]) -> Option<[f64; N]> {
    let mut out = [0.0; N];
    for (o, q) in out.iter_mut().zip(qs) {
        *o = input(q)?;
    }
    Some(out)
}

/// The f64 inputs of a filter when all are usable and each is 0 or within
/// `2^lo_exp ≤ |x| < 2^hi_exp` (the magnitude hypotheses of the filter's proof), or `None`.
pub(crate) fn inputs_in_range<const N: usize>(
    qs: &[Rational; N],
    lo_exp: i32,
    hi_exp: i32,
) -> Option<[f64; N]> {
    inputs(qs).filter(|x| x.iter().all(|&t| in_range(t, lo_exp, hi_exp)))
}

/// Whether `x` is 0 or `2^lo_exp ≤ |x| ≤ 2^hi_exp` (magnitude guards of the filters).
pub(crate) fn in_range(x: f64, lo_exp: i32, hi_exp: i32) -> bool {
    if x == 0.0 {
        return true;
    }
    // The unbiased exponent of a normal f64: 2^e ≤ |x| < 2^(e+1).
    let e = ((x.to_bits() >> 52) & 0x7ff) as i32 - 1023;
    x.is_normal() && e >= lo_exp && e < hi_exp
}

/// The sign of `value` when `|value| > bound`, the filter's decision; `None` otherwise
/// (including NaN or infinite values).
pub(crate) fn decide(value: f64, bound: f64) -> Option<Sign> {
    if !value.is_finite() || !bound.is_finite() {
        return None;
    }
    if value > bound {
        Some(Sign::Positive)
    } else if -value > bound {
        Some(Sign::Negative)
    } else {
        None
    }
}

/// Enclosures of the inputs at `prec` bits (proofs/B20).
pub(crate) fn enclose<const N: usize>(qs: &[Rational; N], prec: Precision) -> [Interval<Mpfr>; N] {
    std::array::from_fn(|i| Interval::<Mpfr>::from_rational(&qs[i], prec))
}

/// The sign of an enclosure (`None` if it straddles 0 or is invalid).
pub(crate) fn sign_of(x: &Interval<Mpfr>) -> Option<Sign> {
    debug_assert!(Interval::<Mpfr>::precision_bits(x.ctx()) >= 53);
    x.sign()
}
