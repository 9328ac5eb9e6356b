//! Numerical comparisons against a derived tolerance, decided exactly on the stored value.

use crate::scalar::Real;
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
