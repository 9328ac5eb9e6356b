//! `approx` comparisons for [`Dd`] and [`Mpfr`], for tests and diagnostics (never for a
//! decision of the geometry: those go through `predicates`).
//!
//! Tolerances are `f64` (any double-double or MPFR tolerance of interest, 2⁻¹⁰⁴ or 2⁻⁵¹²,
//! is a normal `f64`). Differences are formed exactly (in ℚ for [`Mpfr`], by TwoSum-based
//! arithmetic for [`Dd`] within its 3u² bound, proofs/B04).

use super::{Dd, Mpfr, Real};
use approx::{AbsDiffEq, RelativeEq, UlpsEq};
use rug::Rational;

/// `|a − b|` for double-doubles (AccurateDWPlusDW, relative error ≤ 3u²; proof: B04).
fn dd_abs_diff(a: &Dd, b: &Dd) -> Dd {
    (*a - *b).abs()
}

/// `a ≤ t` for a normalized double-double `a` and an `f64` threshold `t`.
fn dd_le(a: Dd, t: f64) -> bool {
    a.hi < t || (a.hi == t && a.lo <= 0.0)
}

impl AbsDiffEq for Dd {
    type Epsilon = f64;

    /// 2⁻¹⁰⁴, the double-double unit roundoff.
    fn default_epsilon() -> f64 {
        Dd::unit_roundoff(())
    }

    /// `|self − other| ≤ epsilon`; NaN is never equal.
    fn abs_diff_eq(&self, other: &Dd, epsilon: f64) -> bool {
        if self == other {
            return true;
        }
        dd_le(dd_abs_diff(self, other), epsilon)
    }
}

impl RelativeEq for Dd {
    /// 2⁻¹⁰⁴, the double-double unit roundoff.
    fn default_max_relative() -> f64 {
        Dd::unit_roundoff(())
    }

    /// `|a − b| ≤ epsilon` or `|a − b| ≤ max_relative · max(|a|, |b|)`.
    fn relative_eq(&self, other: &Dd, epsilon: f64, max_relative: f64) -> bool {
        if self.abs_diff_eq(other, epsilon) {
            return true;
        }
        let d = dd_abs_diff(self, other);
        let (a, b) = (self.abs(), other.abs());
        let big = if a.hi > b.hi || (a.hi == b.hi && a.lo >= b.lo) {
            a
        } else {
            b
        };
        let t = big * Dd::from_f64(max_relative);
        let slack = t - d;
        slack.hi > 0.0 || (slack.hi == 0.0 && slack.lo >= 0.0)
    }
}

/// The exact `|a − b|` of two MPFR values, or `None` if either is not finite.
fn mpfr_abs_diff(a: &Mpfr, b: &Mpfr) -> Option<Rational> {
    let d = a.to_rational()? - b.to_rational()?;
    Some(d.abs())
}

/// The exact value of an `f64` tolerance (NaN or negative tolerances accept nothing).
fn tol(t: f64) -> Option<Rational> {
    if t.is_nan() || t < 0.0 {
        return None;
    }
    Rational::from_f64(t)
}

impl AbsDiffEq for Mpfr {
    type Epsilon = f64;

    /// 0: the precision is a run-time property, so callers pass a tolerance derived from
    /// [`Real::unit_roundoff`] of the context.
    fn default_epsilon() -> f64 {
        0.0
    }

    /// `|self − other| ≤ epsilon`, decided exactly; equal infinities are equal, NaN never.
    fn abs_diff_eq(&self, other: &Mpfr, epsilon: f64) -> bool {
        if self.0.is_infinite() || other.0.is_infinite() {
            return self.0 == other.0;
        }
        match (mpfr_abs_diff(self, other), tol(epsilon)) {
            (Some(d), Some(e)) => d <= e,
            _ => false,
        }
    }
}

impl RelativeEq for Mpfr {
    /// 0, as for [`AbsDiffEq::default_epsilon`].
    fn default_max_relative() -> f64 {
        0.0
    }

    /// `|a − b| ≤ epsilon` or `|a − b| ≤ max_relative · max(|a|, |b|)`, decided exactly.
    fn relative_eq(&self, other: &Mpfr, epsilon: f64, max_relative: f64) -> bool {
        if self.abs_diff_eq(other, epsilon) {
            return true;
        }
        let (Some(d), Some(r), Some(a), Some(b)) = (
            mpfr_abs_diff(self, other),
            tol(max_relative),
            self.to_rational(),
            other.to_rational(),
        ) else {
            return false;
        };
        let big = std::cmp::max(a.abs(), b.abs());
        d <= r * big
    }
}

impl UlpsEq for Mpfr {
    /// 4 units in the last place.
    fn default_max_ulps() -> u32 {
        4
    }

    /// `abs_diff_eq(epsilon)`, or `|a − b| ≤ max_ulps · ulp(max(|a|, |b|))` where the ulp
    /// is `2^(e − p)` for a value in `[2^(e−1), 2^e)` at the larger of the two precisions.
    fn ulps_eq(&self, other: &Mpfr, epsilon: f64, max_ulps: u32) -> bool {
        if self.abs_diff_eq(other, epsilon) {
            return true;
        }
        let Some(d) = mpfr_abs_diff(self, other) else {
            return false;
        };
        let p = self.0.prec().max(other.0.prec());
        let e = match (self.0.get_exp(), other.0.get_exp()) {
            (Some(a), Some(b)) => a.max(b),
            (Some(a), None) | (None, Some(a)) => a,
            (None, None) => return false,
        };
        let ulp = Rational::from(rug::Integer::from(1)) << (e - p as i32);
        d <= ulp * max_ulps
    }
}
