//! Error-free transformations and the double-word algorithms of Joldes, Muller and Popescu,
//! "Tight and rigorous error bounds for basic building blocks of double-word arithmetic",
//! ACM TOMS 44(2), 2017 (JMP17). Every function states its bound and the `proofs/` file.
//!
//! All algorithms assume round-to-nearest binary64, an exact fused multiply-add
//! (`f64::mul_add`, correctly rounded on every platform) and no overflow or underflow.

use super::Dd;

/// `a + b = s + e` exactly, with `s = RN(a + b)` (Knuth's TwoSum, 6 flops, no ordering
/// condition). proof: B01
#[inline]
pub(crate) fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let ap = s - b;
    let bp = s - ap;
    (s, (a - ap) + (b - bp))
}

/// `a + b = s + e` exactly when `|a| ≥ |b|` (or `a = 0`), with `s = RN(a + b)`
/// (Dekker's Fast2Sum). proof: B01
#[inline]
pub(crate) fn fast_two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    (s, b - (s - a))
}

/// `a · b = p + e` exactly, with `p = RN(a · b)`, via one FMA. proof: B02
#[cfg(target_feature = "fma")]
#[inline]
pub(crate) fn two_prod(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    (p, a.mul_add(b, -p))
}

/// `a · b = p + e` exactly, with `p = RN(a · b)`, by Dekker's product with Veltkamp's
/// splitting: the same `(p, e)` as the FMA form (both are exact), without the library call
/// that `f64::mul_add` becomes when the target lacks hardware FMA. Needs
/// `|a|, |b| < 2⁹⁹⁶` besides B02's hypotheses. proof: B02
#[cfg(not(target_feature = "fma"))]
#[inline]
pub(crate) fn two_prod(a: f64, b: f64) -> (f64, f64) {
    /// Veltkamp's constant `2²⁷ + 1`: splits a binary64 into two 26-bit halves.
    const SPLIT: f64 = 134_217_729.0;
    let split = |x: f64| {
        let c = SPLIT * x;
        let h = c - (c - x);
        (h, x - h)
    };
    if a.abs() > SPLIT_MAX || b.abs() > SPLIT_MAX {
        return two_prod_large(a, b);
    }
    let p = a * b;
    let (ah, al) = split(a);
    let (bh, bl) = split(b);
    (p, ((ah * bh - p) + ah * bl + al * bh) + al * bl)
}

/// Largest factor Veltkamp's splitting takes without overflowing `(2²⁷ + 1)·x`: 2⁹⁹⁵.
/// proof: B02
#[cfg(not(target_feature = "fma"))]
const SPLIT_MAX: f64 = f64::from_bits((1023 + 995) << 52);

/// [`two_prod`] with a factor above 2⁹⁹⁵: that factor is scaled by 2⁻⁶⁴ (exact), the
/// product taken, and both words scaled back (exact; `RN` commutes with the scaling since
/// the scaled product `≥ 2⁹³¹·2⁻¹⁰⁷⁴` stays normal). Two factors above 2⁹⁹⁵ overflow.
/// proof: B02
#[cfg(not(target_feature = "fma"))]
#[cold]
fn two_prod_large(a: f64, b: f64) -> (f64, f64) {
    /// 2⁻⁶⁴ and 2⁶⁴.
    const DOWN: f64 = f64::from_bits((1023 - 64) << 52);
    const UP: f64 = f64::from_bits((1023 + 64) << 52);
    let (a, b) = if a.abs() >= b.abs() { (a, b) } else { (b, a) };
    if b.abs() > SPLIT_MAX || !a.is_finite() || !b.is_finite() {
        return (a * b, 0.0);
    }
    let (p, e) = two_prod(a * DOWN, b);
    (p * UP, e * UP)
}

/// JMP17 Algorithm 4 (DWPlusFP): `x + y` for a double-word `x` and a float `y`, relative
/// error ≤ 2u². proof: B03
#[inline]
pub(crate) fn add_f64(x: Dd, y: f64) -> Dd {
    let (sh, sl) = two_sum(x.hi, y);
    let v = x.lo + sl;
    let (hi, lo) = fast_two_sum(sh, v);
    if hi.is_finite() {
        Dd { hi, lo }
    } else {
        overflowed(sh, x.hi + y)
    }
}

/// The result of a sum or product whose leading word is not finite: `±∞` (trailing word
/// 0) with the sign of the finite rounded leading part `lead` when that overflowed later,
/// otherwise the IEEE value `ieee` of the leading words (∞ for an overflow or an infinite
/// operand, NaN for ∞ − ∞, 0·∞ or NaN). proof: B04
#[cold]
fn overflowed(lead: f64, ieee: f64) -> Dd {
    if lead.is_finite() {
        Dd::from_f64(f64::INFINITY.copysign(lead))
    } else {
        Dd::from_f64(ieee)
    }
}

/// JMP17 Algorithm 6 (AccurateDWPlusDW): `x + y`, relative error ≤ 3u² + 13u³ even under
/// cancellation. proof: B04
#[inline]
pub(crate) fn add(x: Dd, y: Dd) -> Dd {
    let (sh, sl) = two_sum(x.hi, y.hi);
    let (th, tl) = two_sum(x.lo, y.lo);
    let c = sl + th;
    let (vh, vl) = fast_two_sum(sh, c);
    let w = tl + vl;
    let (hi, lo) = fast_two_sum(vh, w);
    if hi.is_finite() {
        Dd { hi, lo }
    } else {
        overflowed(sh, x.hi + y.hi)
    }
}

/// JMP17 Algorithm 9 (DWTimesFP3, with FMA): `x · y` for a float `y`, relative error ≤ 2u².
/// proof: B05
#[inline]
pub(crate) fn mul_f64(x: Dd, y: f64) -> Dd {
    let (ch, cl1) = two_prod(x.hi, y);
    let cl3 = x.lo.mul_add(y, cl1);
    let (hi, lo) = fast_two_sum(ch, cl3);
    if hi.is_finite() {
        Dd { hi, lo }
    } else {
        overflowed(ch, x.hi * y)
    }
}

/// JMP17 Algorithm 12 (DWTimesDW3, with FMA): `x · y`, relative error ≤ 5u² (JMP17),
/// improved to 4u² by Muller and Rideau (TOMS 2022). proof: B06
#[inline]
pub(crate) fn mul(x: Dd, y: Dd) -> Dd {
    let (ch, cl1) = two_prod(x.hi, y.hi);
    let tl0 = x.lo * y.lo;
    let tl1 = x.hi.mul_add(y.lo, tl0);
    let cl2 = x.lo.mul_add(y.hi, tl1);
    let cl3 = cl1 + cl2;
    let (hi, lo) = fast_two_sum(ch, cl3);
    if hi.is_finite() {
        Dd { hi, lo }
    } else {
        overflowed(ch, x.hi * y.hi)
    }
}

/// JMP17 Algorithm 18 (DWDivDW3, with FMA): `x / y`, relative error ≤ 9.8u² when no
/// intermediate underflows. The first step of [`div`]; exposed only as the negative control
/// of its accuracy test. proof: B07
#[doc(hidden)]
#[inline]
pub fn div_jmp17(x: Dd, y: Dd) -> Dd {
    let th = 1.0 / y.hi;
    // Exact: 1 − y_h·t_h is representable and the FMA rounds once.
    let rh = (-y.hi).mul_add(th, 1.0);
    let rl = -(y.lo * th);
    let (eh, el) = fast_two_sum(rh, rl);
    let d = mul_f64(Dd { hi: eh, lo: el }, th);
    let m = add_f64(d, th);
    mul(x, m)
}

/// Operands with `2⁻⁴⁰⁰ ≤ |hi| < 2⁴⁰⁰` take the direct path of [`div`]; no intermediate
/// of Alg. 18 or of the correction then leaves the normal range. proof: B17
const DIV_DIRECT_MIN: f64 = f64::from_bits((1023 - 400) << 52);
/// Upper end of the direct range of [`div`], `2⁴⁰⁰`.
const DIV_DIRECT_MAX: f64 = f64::from_bits((1023 + 400) << 52);

/// `x / y`: JMP17 Alg. 18 followed by one correction with the residual `x − y·q` summed
/// from error-free products, relative error ≤ u² + 2⁹u³ for `2⁻⁹⁰⁰ ≤ |x/y| ≤ 2¹⁰²³`.
/// Operands outside `[2⁻⁴⁰⁰, 2⁴⁰⁰)` are scaled by powers of two first; zeros, infinities
/// and NaN follow the IEEE quotient of the leading words. proof: B17
#[inline]
pub(crate) fn div(x: Dd, y: Dd) -> Dd {
    let (ax, ay) = (x.hi.abs(), y.hi.abs());
    if (DIV_DIRECT_MIN..DIV_DIRECT_MAX).contains(&ax)
        && (DIV_DIRECT_MIN..DIV_DIRECT_MAX).contains(&ay)
    {
        div_corrected(x, y)
    } else {
        div_scaled(x, y)
    }
}

/// The correction step of [`div`] on operands in its direct range. proof: B17
#[inline]
fn div_corrected(x: Dd, y: Dd) -> Dd {
    let q = div_jmp17(x, y);
    // Residual r = x − y·q = (x_h − p1) + x_l − e1 − p2 − p3 − (e2 + e3 + y_l·q_l), with
    // every product but the last error-free.
    let (p1, e1) = two_prod(y.hi, q.hi);
    let (p2, e2) = two_prod(y.hi, q.lo);
    let (p3, e3) = two_prod(y.lo, q.hi);
    let small = (-y.lo).mul_add(q.lo, -(e2 + e3));
    // Exact by Sterbenz: p1 and x_h agree to within a factor 1 ± 5u.
    let s0 = x.hi - p1;
    // Cascaded TwoSum (Sum2 of Ogita, Rump and Oishi) over the five large terms.
    let (a, c1) = two_sum(s0, x.lo);
    let (a, c2) = two_sum(a, -e1);
    let (a, c3) = two_sum(a, -p2);
    let (a, c4) = two_sum(a, -p3);
    let r = a + ((((c1 + c2) + c3) + c4) + small);
    // q + r/y = x/y exactly; |r/y| ≤ 9.8u²|q|, so one rounded quotient suffices.
    let delta = r / y.hi;
    let v = q.lo + delta;
    let (hi, lo) = fast_two_sum(q.hi, v);
    Dd { hi, lo }
}

/// `|x|` as `x' · 2ᵉ` with `1 ≤ |x'_h| < 2`, for finite nonzero `x` (exact scalings).
fn split_exponent(x: Dd) -> (Dd, i32) {
    let (x, pre) = if x.hi.abs() < f64::MIN_POSITIVE {
        (x.ldexp(600), -600)
    } else {
        (x, 0)
    };
    let e = ((x.hi.to_bits() >> 52) & 0x7ff) as i32 - 1023;
    (x.ldexp(-e), e + pre)
}

/// [`div`] for operands outside the direct range: both scaled into `[1, 2)`, divided, and
/// the quotient scaled back (exact unless it leaves the normal range). proof: B17
#[cold]
fn div_scaled(x: Dd, y: Dd) -> Dd {
    if x.hi == 0.0 || y.hi == 0.0 || !x.hi.is_finite() || !y.hi.is_finite() {
        return Dd::from_f64(x.hi / y.hi);
    }
    let (xs, ex) = split_exponent(x);
    let (ys, ey) = split_exponent(y);
    div_corrected(xs, ys).ldexp(ex - ey)
}

/// Leading words below `2⁻⁹⁰⁰` go through [`sqrt`] scaled by `2⁶⁰⁰`: from here on the
/// trailing word of `x`, the residual `x_h − s_h²` and the correction are normal (or exact
/// zeros), the hypothesis of SQRTDWtoDW. proof: B08
const SQRT_DIRECT_MIN: f64 = f64::from_bits((1023 - 900) << 52);

/// Square root of a double-word `x > 0` (finite), relative error ≤ 25/8 u² for every
/// positive finite `x`: [`sqrt_direct`] on `x` when `x_h ≥ 2⁻⁹⁰⁰`, otherwise
/// `√(x·2⁶⁰⁰)·2⁻³⁰⁰`, both scalings exact (the result lies in `[2⁻⁵³⁷, 2⁵¹²)`, so both of
/// its words stay normal). proof: B08
#[inline]
pub(crate) fn sqrt(x: Dd) -> Dd {
    if x.hi < SQRT_DIRECT_MIN {
        return sqrt_direct(x.ldexp(600)).ldexp(-300);
    }
    sqrt_direct(x)
}

/// Square root of a double-word `x` with `x_h ≥ 2⁻⁹⁰⁰` by one Newton correction of
/// `RN(√x_h)` with the exact FMA residual (SQRTDWtoDW of Lefèvre, Louvet, Muller, Picot and
/// Rideau, TOMS 2023), relative error ≤ 25/8 u². proof: B08
#[inline]
fn sqrt_direct(x: Dd) -> Dd {
    let sh = x.hi.sqrt();
    // Exact: x_h − s_h² is representable (s_h = RN(√x_h), x_h ≥ 2⁻⁹⁰⁰) and the FMA
    // rounds once.
    let rho1 = (-sh).mul_add(sh, x.hi);
    let rho2 = x.lo + rho1;
    let sl = rho2 / (2.0 * sh);
    let (hi, lo) = fast_two_sum(sh, sl);
    Dd { hi, lo }
}

/// The "sloppy" double-word addition (QD's default), kept only as a negative control for
/// the accuracy tests: it has no relative error bound under cancellation.
#[doc(hidden)]
pub fn sloppy_add(x: Dd, y: Dd) -> Dd {
    let (sh, sl) = two_sum(x.hi, y.hi);
    let v = x.lo + y.lo;
    let w = sl + v;
    let (hi, lo) = fast_two_sum(sh, w);
    Dd { hi, lo }
}
