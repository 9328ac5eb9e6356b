//! The binary64 nearest to an exact rational, the one conversion ℚ → `f64` of the library.
//!
//! IEEE 754 round to nearest, ties to even, with gradual underflow and overflow: the
//! result is the finite binary64 nearest to `q` (ties to the one with an even
//! significand), `±0` below half the smallest subnormal, and `±∞` from `MAX + ulp(MAX)/2`
//! on. `rug::Rational::to_f64` truncates instead, and rounding to 53 bits first and then
//! into the subnormal range rounds twice: `(3/2 − 2⁻⁶⁰)·2⁻¹⁰⁷⁴` would become the tie
//! `(3/2)·2⁻¹⁰⁷⁴` and then `2·2⁻¹⁰⁷⁴` instead of `2⁻¹⁰⁷⁴`.

use rug::float::Round;
use rug::{Float, Rational};

/// The binary64 nearest to `q`, ties to even (module docs; proof: B19). MPFR rounds `q` to 53 bits
/// once, recording the direction; `subnormalize_ieee_round` uses that direction to round
/// into binary64's subnormal range without a second rounding error; the value is then a
/// binary64 (or beyond `MAX`, giving `±∞`) and its conversion exact.
///
/// ```
/// use penner::scalar::nearest_f64;
/// use rug::Rational;
/// assert_eq!(nearest_f64(&Rational::from((1, 10))), 0.1);
/// // 2⁵³ + 1 lies halfway between 2⁵³ and 2⁵³ + 2: the even significand wins.
/// assert_eq!(nearest_f64(&Rational::from((1u64 << 53) + 1)), 9007199254740992.0);
/// ```
pub fn nearest_f64(q: &Rational) -> f64 {
    let (mut x, dir) = Float::with_val_round(53, q, Round::Nearest);
    x.subnormalize_ieee_round(dir, Round::Nearest);
    x.to_f64()
}
