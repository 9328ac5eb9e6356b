//! Conformally scaled lengths `e^{(u_i+u_j)/2}·ℓ_ij` for the `f64` Newton solver, in
//! binary64 with the exponent kept apart ([`ExpLength`]), without MPFR. proof: B77
//!
//! `s = (u_i + u_j)/2` is split exactly into `s_hi + s_lo` (TwoSum, B01, and an exact
//! halving), then `s = k·ln 2 + r` with `k = round(s_hi/ln 2)` and the two-part constant
//! `ln 2 = LN2_HI + LN2_LO` (Cody–Waite; `k·LN2_HI` is exact for `|k| < 2²¹`), and
//! `e^s·ℓ = (e^r·m_ℓ)·2^{k + k_ℓ}` with `ℓ = m_ℓ·2^{k_ℓ}`. The relative error is at most
//! `6.2u` (`u = 2⁻⁵³`) under B22's libm allowance for `exp` (B77). The solver's lengths are
//! a heuristic for Newton; the certificate recomputes every length in interval arithmetic.

use crate::scalar::exp_length::{ExpLength, MAX_LOG_SCALE};

/// `ln 2` to 32 significant bits (fdlibm's `ln2_hi`): `k·LN2_HI` is exact for `|k| < 2²¹`.
const LN2_HI: f64 = f64::from_bits(0x3fe6_2e42_fee0_0000);
/// `ln 2 − LN2_HI`, rounded (fdlibm's `ln2_lo`).
const LN2_LO: f64 = f64::from_bits(0x3dea_39ef_3579_3c76);

/// The relative error bound of [`scaled_fast`] in units of `2⁻⁵³`. proof: B77
pub const SCALED_FAST_ULPS: f64 = 6.2;

/// `e^{(u_i+u_j)/2}·ℓ` as an [`ExpLength`], in binary64 (module doc; relative error at
/// most [`SCALED_FAST_ULPS`]·2⁻⁵³, proof: B77). `None` unless `ℓ` is positive and finite
/// and `|u_i|, |u_j| ≤` [`MAX_LOG_SCALE`].
///
/// ```
/// use penner::uniformization::scaling::scaled_fast;
/// use penner::scalar::exp_length::ExpLength;
/// let a = scaled_fast(1.5, 800.0, 790.0).unwrap();
/// let b = ExpLength::scaled(1.5, 800.0, 790.0).unwrap();
/// assert_eq!(a.exponent(), b.exponent());
/// assert!((a.mantissa() / b.mantissa() - 1.0).abs() < 1e-15);
/// ```
#[inline]
pub fn scaled_fast(length: f64, u_i: f64, u_j: f64) -> Option<ExpLength> {
    if !(length > 0.0 && length.is_finite()) {
        return None;
    }
    if !(u_i.abs() <= MAX_LOG_SCALE && u_j.abs() <= MAX_LOG_SCALE) {
        return None;
    }
    // TwoSum (B01): hi + lo = u_i + u_j exactly; the halvings are exact (|hi| ≤ 2²¹, and a
    // subnormal lo loses at most 2⁻¹⁰⁷⁵ absolutely).
    let hi = u_i + u_j;
    let z = hi - u_i;
    let lo = (u_i - (hi - z)) + (u_j - z);
    let (hi, lo) = (0.5 * hi, 0.5 * lo);
    let k = (hi * std::f64::consts::LOG2_E).round();
    // k·LN2_HI is exact; |r| ≤ ln 2/2 up to roundings (B77).
    let r = ((hi - k * LN2_HI) - k * LN2_LO) + lo;
    let l = ExpLength::from_f64(length)?;
    ExpLength::new(r.exp() * l.mantissa(), i64::from(l.exponent()) + k as i64)
}
