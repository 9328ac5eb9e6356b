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

#[cfg(test)]
mod tests {
    use super::{decide, in_range, input};
    use crate::scalar::nearest_f64;
    use crate::scalar::Sign;
    use rug::{Integer, Rational};

    /// B23's hypothesis `|x − q| ≤ u|x|`: the filter input is the *nearest* binary64 value,
    /// on the fast path (dyadic, at most 53 bits) and off it. `1/10` and
    /// `1 + 3·2⁻⁵⁴` (55 significant bits) round up, so truncation would be one ulp off;
    /// subnormal and overflowing values are refused, zero is kept.
    #[test]
    fn term_b23_filter_input_is_the_nearest_normal_binary64() {
        let two_54 = Rational::from(Integer::from(1) << 54u32);
        let cases = [
            Rational::from((1, 10)),
            Rational::from((-1, 10)),
            (Rational::from(Integer::from(1) << 54u32) + 3u32) / &two_54,
            Rational::from((1, 3)),
            Rational::from((3, 4)),
            Rational::from(12345),
        ];
        for q in &cases {
            let x = input(q).expect("a normal value");
            assert_eq!(x, nearest_f64(q), "{q}");
            // The nearest value, so within half an ulp: |x − q| ≤ u|x|.
            let err = (Rational::from_f64(x).unwrap() - q.clone()).abs();
            let half_ulp = Rational::from_f64(x.abs() * f64::EPSILON / 2.0).unwrap();
            assert!(err <= half_ulp, "{q}");
        }
        // Controls: 1/10 and 1 + 3·2⁻⁵⁴ are not their truncations.
        assert_ne!(input(&cases[0]), Some(cases[0].to_f64()));
        assert_ne!(input(&cases[2]), Some(1.0));
        assert_eq!(input(&Rational::new()), Some(0.0));
        let tiny = Rational::from((1, Integer::from(1) << 1070u32));
        assert_eq!(input(&tiny), None);
        let huge = Rational::from(Integer::from(1) << 1100u32);
        assert_eq!(input(&huge), None);
    }

    /// The magnitude guard of the filters' proofs: 0, or `2^lo ≤ |x| < 2^hi` for a normal
    /// `x`, either sign; the ends, subnormals, NaN and infinities are decided as stated.
    #[test]
    fn term_filter_magnitude_guard_is_the_stated_exponent_range() {
        let (lo, hi) = (-10, 10);
        for x in [
            0.0,
            -0.0,
            1.0,
            -1.0,
            2f64.powi(-10),
            2f64.powi(10) * (1.0 - f64::EPSILON),
        ] {
            assert!(in_range(x, lo, hi), "{x:e}");
        }
        for x in [
            2f64.powi(-11),
            2f64.powi(-10) * (1.0 - f64::EPSILON),
            2f64.powi(10),
            -2f64.powi(10),
            f64::MIN_POSITIVE / 2.0,
            f64::NAN,
            f64::INFINITY,
            f64::NEG_INFINITY,
        ] {
            assert!(!in_range(x, lo, hi), "{x:e}");
        }
        // A subnormal is refused even when the range would reach it.
        assert!(!in_range(f64::MIN_POSITIVE / 4.0, -1100, 0));
        assert!(in_range(f64::MIN_POSITIVE, -1100, 0));
    }

    /// The filter's decision: a sign only when `|value| > bound` strictly (the error bound
    /// allows the true value anywhere in `[value − bound, value + bound]`, which contains 0
    /// when `|value| = bound`), and never for a NaN or infinite value or bound.
    #[test]
    fn term_filter_decides_only_strictly_beyond_the_error_bound() {
        assert_eq!(decide(1.5, 1.0), Some(Sign::Positive));
        assert_eq!(decide(-1.5, 1.0), Some(Sign::Negative));
        for (value, bound) in [
            (1.0, 1.0),
            (-1.0, 1.0),
            (0.5, 1.0),
            (0.0, 0.0),
            (f64::INFINITY, 1.0),
            (f64::NEG_INFINITY, 1.0),
            (f64::NAN, 1.0),
            (1.0, f64::INFINITY),
            (1.0, f64::NAN),
        ] {
            assert_eq!(decide(value, bound), None, "{value} ± {bound}");
        }
    }
}
