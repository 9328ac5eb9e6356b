//! Numerical comparisons against a derived tolerance, decided exactly on the stored value.

use crate::scalar::{Real, Sign};
use rug::Rational;

/// Whether `|x| ≤ tol`, decided exactly on the rational value of `x` (no rounding in the
/// comparison). `None` when `x` is not finite or `tol` is NaN; an infinite `tol` accepts
/// every finite `x`.
///
/// This decides a *numerical* check: the tolerance comes from a stated error bound
/// (proofs/B40–B48), so the answer is only as rigorous as that bound's hypotheses.
///
/// ```
/// use penner::predicates::tolerance::abs_at_most;
/// assert_eq!(abs_at_most(&-1e-20_f64, 1e-19), Some(true));
/// assert_eq!(abs_at_most(&1e-18_f64, 1e-19), Some(false));
/// assert_eq!(abs_at_most(&f64::NAN, 1.0), None);
/// ```
pub fn abs_at_most<T: Real>(x: &T, tol: f64) -> Option<bool> {
    abs_at_most_scaled(x, tol, 0)
}

/// Whether `|x| ≤ tol·2⁻ˢ`, decided exactly: the tolerance of a high-precision backend is
/// carried as an `f64` times an exact power of two (proofs/B40, "Range"), so it never
/// underflows, whatever the precision.
///
/// ```
/// use penner::predicates::tolerance::abs_at_most_scaled;
/// use penner::scalar::{Mpfr, Precision, Real};
/// let p = Precision::new(4096).unwrap();
/// let tiny = Mpfr::from_rational(&(rug::Rational::from(1) >> 3000u32), p); // 2⁻³⁰⁰⁰
/// assert_eq!(abs_at_most_scaled(&tiny, 1.0, 2999), Some(true));
/// assert_eq!(abs_at_most_scaled(&tiny, 1.0, 3001), Some(false));
/// ```
pub fn abs_at_most_scaled<T: Real>(x: &T, tol: f64, shift: u32) -> Option<bool> {
    let q = x.to_rational()?;
    if tol.is_nan() {
        return None;
    }
    if tol == f64::INFINITY {
        return Some(true);
    }
    let t = Rational::from_f64(tol)? >> shift;
    Some(q.abs() <= t)
}

/// The sign of `x`, decided exactly on its stored value (`None` when not finite).
///
/// ```
/// use penner::predicates::tolerance::sign_exact;
/// use penner::scalar::Sign;
/// assert_eq!(sign_exact(&-1e-300_f64), Some(Sign::Negative));
/// assert_eq!(sign_exact(&f64::NAN), None);
/// ```
pub fn sign_exact<T: Real>(x: &T) -> Option<Sign> {
    Some(Sign::of_ordering(x.to_rational()?.cmp0()))
}

/// The sign of the exact quantity whose computed value `x` is within `tol·2⁻ˢ` of it
/// (`tol` scaled as in [`abs_at_most_scaled`], proofs/B40 "Range"): `Positive` when
/// `x > tol·2⁻ˢ`, `Negative` when `x < −tol·2⁻ˢ`, `Zero` in between (the sign is not
/// decided); `None` when `x` is not finite or `tol` is not a finite nonnegative number.
///
/// ```
/// use penner::predicates::tolerance::sign_beyond;
/// use penner::scalar::Sign;
/// assert_eq!(sign_beyond(&1.0_f64, 0.5, 0), Some(Sign::Positive));
/// assert_eq!(sign_beyond(&0.25_f64, 0.5, 0), Some(Sign::Zero));
/// assert_eq!(sign_beyond(&0.25_f64, 0.5, 2), Some(Sign::Positive));
/// assert_eq!(sign_beyond(&-1.0_f64, 0.5, 0), Some(Sign::Negative));
/// ```
pub fn sign_beyond<T: Real>(x: &T, tol: f64, shift: u32) -> Option<Sign> {
    let q = x.to_rational()?;
    if !(tol.is_finite() && tol >= 0.0) {
        return None;
    }
    let t = Rational::from_f64(tol)? >> shift;
    Some(if q > t {
        Sign::Positive
    } else if q < -t {
        Sign::Negative
    } else {
        Sign::Zero
    })
}

#[cfg(test)]
mod tests {
    use super::{abs_at_most, sign_beyond};
    use crate::scalar::Sign;

    /// The contract of [`sign_beyond`] on its tolerance: a negative, NaN or infinite `tol`
    /// decides nothing (`None`). A negative tolerance accepted would call `0` positive
    /// against `−1`: a sign claimed without the margin the caller's bound needs.
    #[test]
    fn sign_beyond_refuses_tolerances_that_are_not_finite_and_nonnegative() {
        assert_eq!(sign_beyond(&0.0_f64, -1.0, 0), None);
        assert_eq!(sign_beyond(&0.0_f64, f64::NAN, 0), None);
        assert_eq!(sign_beyond(&0.0_f64, f64::INFINITY, 0), None);
        assert_eq!(sign_beyond(&0.0_f64, 1.0, 0), Some(Sign::Zero));
        assert_eq!(sign_beyond(&2.0_f64, 1.0, 0), Some(Sign::Positive));
        assert_eq!(sign_beyond(&-2.0_f64, 1.0, 1), Some(Sign::Negative));
    }

    /// At `|x| = tol·2⁻ˢ` exactly the sign is not decided: the computed value may be `tol`
    /// away from an exact zero. Deciding it there would claim a sign the bound does not give.
    #[test]
    fn sign_beyond_leaves_the_ties_at_the_tolerance_undecided() {
        assert_eq!(sign_beyond(&1.0_f64, 1.0, 0), Some(Sign::Zero));
        assert_eq!(sign_beyond(&-1.0_f64, 1.0, 0), Some(Sign::Zero));
        assert_eq!(sign_beyond(&0.25_f64, 1.0, 2), Some(Sign::Zero));
        assert_eq!(sign_beyond(&0.5_f64, 1.0, 2), Some(Sign::Positive));
    }

    /// [`abs_at_most`] decides both ways, and at the tolerance itself (`|x| = tol`) it holds.
    #[test]
    fn abs_at_most_decides_both_ways_and_holds_at_the_tolerance() {
        assert_eq!(abs_at_most(&-0.5_f64, 0.5), Some(true));
        assert_eq!(abs_at_most(&0.75_f64, 0.5), Some(false));
        assert_eq!(abs_at_most(&0.0_f64, 0.0), Some(true));
        assert_eq!(abs_at_most(&f64::INFINITY, 1.0), None);
    }
}
