//! `Л` on `Dual<f64>` and `Dual<Dd>` without MPFR (proofs/B30): the value from the
//! binary64 (B53) or double-double (B55) path of `special::lobachevsky` (passed in by its
//! caller, so this module imports nothing of it), the derivative `d·Л′(v)` with
//! `Л′(v) = −log|2 sin v|` evaluated in the same backend.
//!
//! The generic path of `special::lobachevsky` reduces the argument in MPFR and rounds its value
//! through a rational for every dual number; this one keeps both parts in the backend's own
//! arithmetic. It declines (`None`) for every other type, and for a `Dd` argument whose
//! sine is below `2⁻³⁰` in magnitude (near a multiple of π, where the absolute floor of
//! B12 would cost relative accuracy in `log|2 sin v|`) or whose value path declines.
//!
//! ```
//! use penner::scalar::{Dual, Real};
//! use penner::special::lobachevsky;
//! // Л′(π/6) = −log(2 sin π/6) = 0 and Л′(π/4) = −log √2.
//! let y = lobachevsky(&Dual::variable(std::f64::consts::FRAC_PI_6));
//! assert!(y.d.abs() < 1e-15);
//! let y = lobachevsky(&Dual::variable(std::f64::consts::FRAC_PI_4));
//! assert!((y.d + 0.5 * 2f64.ln()).abs() < 1e-15);
//! ```

use crate::scalar::{Dd, Dual, Real};
use std::any::Any;

/// `|sin v|` below which the `Dd` derivative goes the generic way (proof: B30).
const DD_MIN_SINE: f64 = 9.313_225_746_154_785e-10; // 2⁻³⁰

/// `Dual { v: Л(v), d: d·(−log|2 sin v|) }` for a scalar backend `S` (`f64` or `Dd`),
/// or `None` when the value or the sine leaves the fast path's range (proof: B30).
fn fast<S: Real>(x: &Dual<S>, min_sine: f64, value: fn(&S) -> S) -> Option<Dual<S>> {
    let s = x.v.sin();
    // NaN compares false: it leaves the fast path too.
    if s.approx_f64()
        .abs()
        .partial_cmp(&min_sine)
        .is_none_or(std::cmp::Ordering::is_lt)
    {
        return None;
    }
    let v = value(&x.v);
    if !v.approx_f64().is_finite() {
        return None;
    }
    let slope = -(s * &x.v.lit(2.0)).abs().ln();
    Some(Dual::new(v, x.d.clone() * &slope))
}

/// `Л(x)` with its derivative when `T` is `Dual<f64>` or `Dual<Dd>` (proofs/B30), the
/// value by `value_f64` or `value_dd` (`Л` on that backend); `None` for every other type
/// and outside the fast path's range (module doc).
pub(crate) fn lobachevsky_dual<T: Real>(
    x: &T,
    value_f64: fn(&f64) -> f64,
    value_dd: fn(&Dd) -> Dd,
) -> Option<T> {
    let any = x as &dyn Any;
    if let Some(d) = any.downcast_ref::<Dual<f64>>() {
        let y = fast(d, f64::MIN_POSITIVE, value_f64)?;
        return (&y as &dyn Any).downcast_ref::<T>().cloned();
    }
    if let Some(d) = any.downcast_ref::<Dual<Dd>>() {
        let y = fast(d, DD_MIN_SINE, value_dd)?;
        return (&y as &dyn Any).downcast_ref::<T>().cloned();
    }
    None
}
