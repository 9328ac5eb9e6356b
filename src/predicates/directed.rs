//! Outward-rounded MPFR enclosures for the polynomial predicates and flips of this layer.
//!
//! The enclosure type is the crate's one interval type, [`Interval<Mpfr>`]: every endpoint
//! is rounded outward by MPFR (`Round::Down` below, `Round::Up` above), so the exact value
//! of an expression evaluated on enclosed inputs lies in the result (proof: B20 for each
//! operation, B62 for the predicates and flips built on them). This module adds the few
//! constructors and tests those need.
//!
//! ```
//! use penner::predicates::directed::{enclose_f64, overlaps, scaled_length};
//! use penner::scalar::{Precision, Sign};
//! let p = Precision::new(128).unwrap();
//! // e^{(400 + 400)/2} · 1 = e^400, far beyond f64, enclosed without overflow.
//! let big = scaled_length(1.0, 400.0, 400.0, p);
//! assert_eq!(big.sign(), Some(Sign::Positive));
//! assert!(overlaps(&enclose_f64(2.0, p), &enclose_f64(2.0, p)));
//! assert!(!overlaps(&enclose_f64(2.0, p), &enclose_f64(3.0, p)));
//! ```

use crate::scalar::{Interval, IntervalBound, Mpfr, Precision, Real, Sign};
use std::cmp::Ordering;

/// The point enclosure `[x, x]` of a finite `f64` (exact at any precision ≥ 53 bits).
pub fn enclose_f64(x: f64, prec: Precision) -> Interval<Mpfr> {
    Interval::point(Mpfr::from_f64(x, prec))
}

/// The enclosure of `e^{(u_i+u_j)/2} · ℓ` for finite `f64` inputs (docs/catalogue.md §4): the sum
/// and the exponential are rounded outward, halving and the product with the point `ℓ`
/// too (proof: B62). MPFR's exponent range keeps `|u|` far beyond 800 finite.
pub fn scaled_length(length: f64, u_i: f64, u_j: f64, prec: Precision) -> Interval<Mpfr> {
    let half = (enclose_f64(u_i, prec) + &enclose_f64(u_j, prec)) * &enclose_f64(0.5, prec);
    half.exp() * &enclose_f64(length, prec)
}

/// Whether two valid enclosures share a point (then their exact values may be equal);
/// `false` if either is invalid. Any bound type ([`IntervalBound`]: MPFR, or `f64` with
/// directed rounding by error terms, B21).
pub fn overlaps<B: IntervalBound>(a: &Interval<B>, b: &Interval<B>) -> bool {
    a.is_valid()
        && b.is_valid()
        && a.lo().cmp_bound(b.hi()).is_some_and(Ordering::is_le)
        && b.lo().cmp_bound(a.hi()).is_some_and(Ordering::is_le)
}

/// Whether every point of `a` lies strictly below every point of `b` (both valid).
pub fn strictly_below<B: IntervalBound>(a: &Interval<B>, b: &Interval<B>) -> bool {
    a.is_valid() && b.is_valid() && a.hi().cmp_bound(b.lo()) == Some(Ordering::Less)
}

/// `a / b` when `b` is certified strictly positive; `None` otherwise or when the quotient
/// is invalid.
pub fn div_positive<B: IntervalBound>(a: &Interval<B>, b: &Interval<B>) -> Option<Interval<B>> {
    if b.sign() != Some(Sign::Positive) {
        return None;
    }
    valid(a.clone() / b)
}

/// `Some(x)` when `x` is a valid enclosure (no domain error occurred), `None` otherwise.
pub fn valid<B: IntervalBound>(x: Interval<B>) -> Option<Interval<B>> {
    x.is_valid().then_some(x)
}
