//! Compact exact coordinates: a decimal literal `m·10ᵉ` with at most 18 digits is kept as
//! an `i64` mantissa and an exponent; any other literal (longer, a fraction) is kept as an
//! exact [`Rational`]. Both denote exactly the value [`parse_rational`] gives, and every
//! literal the fast path does not take goes through [`parse_rational`], so the accepted
//! literals, their values and the errors are those of the exact parser.
//!
//! Squared distances of such points are integers times a power of ten, computed in
//! `u128`/`i128` when they fit ([`squared_distance`]), and rounded to `f64` correctly
//! ([`decimal_to_f64`]).

use crate::scalar::{parse_rational, NumberError};
use rug::{Integer, Rational};

/// Most digit characters a literal may have to take the fast path (`10¹⁸ < 2⁶³`).
const FAST_DIGITS: usize = 18;
/// Largest |written exponent| the fast path takes (far inside [`crate::scalar::MAX_EXPONENT`]).
const FAST_EXPONENT: i32 = 4000;

/// An exact coordinate: `mantissa · 10^exponent`, or an exact rational.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Coordinate {
    /// `mantissa · 10^exponent` exactly (`|mantissa| < 10¹⁸`).
    Decimal {
        /// The digits as an integer, with the sign.
        mantissa: i64,
        /// The decimal exponent, fraction digits folded in (`1.25` → `125·10⁻²`).
        exponent: i32,
    },
    /// Any other exact value (a long literal, a fraction `p/q`).
    Exact(Box<Rational>),
}

impl Coordinate {
    /// The exact value.
    pub fn to_rational(&self) -> Rational {
        match self {
            Coordinate::Decimal { mantissa, exponent } => {
                let m = Integer::from(*mantissa);
                let p = Integer::from(Integer::u_pow_u(10, exponent.unsigned_abs()));
                if *exponent >= 0 {
                    Rational::from(m * p)
                } else {
                    Rational::from((m, p))
                }
            }
            Coordinate::Exact(q) => (**q).clone(),
        }
    }
}

impl std::fmt::Display for Coordinate {
    /// An exact literal that [`parse_rational`] reads back to the same value: `me<exp>`
    /// for a decimal, `p/q` for a rational.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Coordinate::Decimal {
                mantissa,
                exponent: 0,
            } => write!(f, "{mantissa}"),
            Coordinate::Decimal { mantissa, exponent } => write!(f, "{mantissa}e{exponent}"),
            Coordinate::Exact(q) => write!(f, "{q}"),
        }
    }
}

/// Parse an exact coordinate: the literals of [`parse_rational`], with the same values and
/// the same errors; `[+-]? d* (. d*)? ([eE] [+-]? d+)?` with at most 18 digits and a small
/// exponent is read without big numbers.
///
/// ```
/// use penner::io::decimal::{parse_coordinate, Coordinate};
/// assert_eq!(parse_coordinate("-1.25e3").unwrap(),
///            Coordinate::Decimal { mantissa: -125, exponent: 1 });
/// assert_eq!(parse_coordinate("1/3").unwrap().to_rational(), rug::Rational::from((1, 3)));
/// assert_eq!(parse_coordinate("1e"), Err(penner::scalar::parse_rational("1e").unwrap_err()));
/// ```
pub fn parse_coordinate(tok: &str) -> Result<Coordinate, NumberError> {
    if let Some((mantissa, exponent)) = fast_decimal(tok.as_bytes()) {
        return Ok(Coordinate::Decimal { mantissa, exponent });
    }
    parse_rational(tok).map(|q| Coordinate::Exact(Box::new(q)))
}

/// `(m, e)` with value `m·10ᵉ` for a well-formed short decimal literal; `None` for
/// anything else (which the exact parser then reads or refuses).
fn fast_decimal(b: &[u8]) -> Option<(i64, i32)> {
    let mut i = 0;
    let negative = match b.first()? {
        b'-' => {
            i = 1;
            true
        }
        b'+' => {
            i = 1;
            false
        }
        _ => false,
    };
    let mut m: i64 = 0;
    let mut digits = 0usize;
    while let Some(&c) = b.get(i).filter(|c| c.is_ascii_digit()) {
        if digits == FAST_DIGITS {
            return None;
        }
        m = m * 10 + i64::from(c - b'0');
        digits += 1;
        i += 1;
    }
    let mut frac = 0i32;
    if b.get(i) == Some(&b'.') {
        i += 1;
        while let Some(&c) = b.get(i).filter(|c| c.is_ascii_digit()) {
            if digits == FAST_DIGITS {
                return None;
            }
            m = m * 10 + i64::from(c - b'0');
            digits += 1;
            frac += 1;
            i += 1;
        }
    }
    if digits == 0 {
        return None;
    }
    let mut exp: i32 = 0;
    if matches!(b.get(i), Some(b'e' | b'E')) {
        i += 1;
        let mut exp_negative = false;
        if let Some(&s @ (b'+' | b'-')) = b.get(i) {
            exp_negative = s == b'-';
            i += 1;
        }
        let start = i;
        while let Some(&c) = b.get(i).filter(|c| c.is_ascii_digit()) {
            exp = exp * 10 + i32::from(c - b'0');
            i += 1;
            if exp > FAST_EXPONENT {
                return None;
            }
        }
        if i == start {
            return None;
        }
        if exp_negative {
            exp = -exp;
        }
    }
    if i != b.len() {
        return None;
    }
    Some((if negative { -m } else { m }, exp - frac))
}

/// `10ᵏ` for `0 ≤ k ≤ 38`, the powers that fit `i128`.
const POW10: [i128; 39] = {
    let mut t = [1i128; 39];
    let mut k = 1;
    while k < 39 {
        t[k] = t[k - 1] * 10;
        k += 1;
    }
    t
};

/// `10ᵏ` when it fits `i128`.
fn pow10(k: u32) -> Option<i128> {
    POW10.get(k as usize).copied()
}

/// The mantissas of `cs` (all [`Coordinate::Decimal`]) brought to their smallest exponent
/// `E`: `(m_i · 10^(e_i − E), E)`, or `None` when one is not a decimal or does not fit.
pub fn common_scale<const N: usize>(cs: [&Coordinate; N]) -> Option<([i128; N], i32)> {
    let mut me = [(0i64, 0i32); N];
    for (k, c) in cs.iter().enumerate() {
        match c {
            Coordinate::Decimal { mantissa, exponent } => me[k] = (*mantissa, *exponent),
            Coordinate::Exact(_) => return None,
        }
    }
    let e = me.iter().map(|&(_, e)| e).min()?;
    let mut out = [0i128; N];
    for (k, &(m, ek)) in me.iter().enumerate() {
        let shift = u32::try_from(ek - e).ok()?;
        out[k] = i128::from(m).checked_mul(pow10(shift)?)?;
    }
    Some((out, e))
}

/// The squared distance `|b − a|²` of two points as `(N, E)` with value `N · 10^(2E)`,
/// computed in integers; `None` when a coordinate is not a decimal or a step overflows.
pub fn squared_distance(a: &[Coordinate; 3], b: &[Coordinate; 3]) -> Option<(u128, i32)> {
    let (m, e) = common_scale([&a[0], &a[1], &a[2], &b[0], &b[1], &b[2]])?;
    let mut n: u128 = 0;
    for k in 0..3 {
        let d = m[3 + k].checked_sub(m[k])?.unsigned_abs();
        n = n.checked_add(d.checked_mul(d)?)?;
    }
    Some((n, e))
}

/// Whether the triangle `a b c` is non-degenerate (`(b − a) × (c − a) ≠ 0`), decided in
/// integers; `None` when a coordinate is not a decimal or a step overflows. For points,
/// `16·area² = 2(AB + BC + CA) − (A² + B² + C²) = 4|(b − a) × (c − a)|²` on the squared
/// side lengths `A, B, C` (Lagrange's identity), so this is the sign test of
/// [`super::surface::validate_metric`].
pub fn non_degenerate(
    a: &[Coordinate; 3],
    b: &[Coordinate; 3],
    c: &[Coordinate; 3],
) -> Option<bool> {
    let (m, _) = common_scale([
        &a[0], &a[1], &a[2], &b[0], &b[1], &b[2], &c[0], &c[1], &c[2],
    ])?;
    let narrow = || -> Option<bool> {
        let u = [
            m[3].checked_sub(m[0])?,
            m[4].checked_sub(m[1])?,
            m[5].checked_sub(m[2])?,
        ];
        let v = [
            m[6].checked_sub(m[0])?,
            m[7].checked_sub(m[1])?,
            m[8].checked_sub(m[2])?,
        ];
        for (i, j) in [(1, 2), (2, 0), (0, 1)] {
            let w = u[i]
                .checked_mul(v[j])?
                .checked_sub(u[j].checked_mul(v[i])?)?;
            if w != 0 {
                return Some(true);
            }
        }
        Some(false)
    };
    // Past i128 (mantissas aligned across distant exponents): the products in 256-bit
    // integers, `u_i·v_j = u_j·v_i` iff their signs and magnitudes agree; big integers
    // only when a difference itself overflows.
    narrow()
        .or_else(|| {
            let d = |i: usize, j: usize| m[i].checked_sub(m[j]);
            let u = [d(3, 0)?, d(4, 1)?, d(5, 2)?];
            let v = [d(6, 0)?, d(7, 1)?, d(8, 2)?];
            let product = |x: i128, y: i128| {
                (
                    x.signum() * y.signum(),
                    mul_wide(x.unsigned_abs(), y.unsigned_abs()),
                )
            };
            Some(
                [(1, 2), (2, 0), (0, 1)]
                    .iter()
                    .any(|&(i, j)| product(u[i], v[j]) != product(u[j], v[i])),
            )
        })
        .or_else(|| {
            let z = |k: usize| Integer::from(m[k]);
            let u = [z(3) - z(0), z(4) - z(1), z(5) - z(2)];
            let v = [z(6) - z(0), z(7) - z(1), z(8) - z(2)];
            Some(
                [(1, 2), (2, 0), (0, 1)]
                    .iter()
                    .any(|&(i, j)| Integer::from(&u[i] * &v[j]) != Integer::from(&u[j] * &v[i])),
            )
        })
}

/// `a·b` exactly, as four little-endian 64-bit limbs: with `a = a₁2⁶⁴ + a₀`,
/// `b = b₁2⁶⁴ + b₀`, `ab = a₁b₁2¹²⁸ + (a₁b₀ + a₀b₁)2⁶⁴ + a₀b₀`.
fn mul_wide(a: u128, b: u128) -> [u64; 4] {
    let (a0, a1) = (u128::from(a as u64), a >> 64);
    let (b0, b1) = (u128::from(b as u64), b >> 64);
    let mut r = [0u64; 4];
    add_at(&mut r, 0, a0 * b0);
    add_at(&mut r, 1, a1 * b0);
    add_at(&mut r, 1, a0 * b1);
    add_at(&mut r, 2, a1 * b1);
    r
}

/// `r ← r + t·2^(64·at)`; returns `false` when the sum overflows 256 bits.
fn add_at(r: &mut [u64; 4], at: usize, t: u128) -> bool {
    let mut carry = t;
    for limb in r.iter_mut().skip(at) {
        let s = u128::from(*limb) + u128::from(carry as u64);
        *limb = s as u64;
        carry = (carry >> 64) + (s >> 64);
        if carry == 0 {
            return true;
        }
    }
    carry == 0
}

/// The squared distance `|b − a|² = N · 10^(2E)` of two points as `(N, E)` with `N` as
/// four little-endian 64-bit limbs (`N < 2²⁵⁶`): the sum of the squared differences of the
/// mantissas aligned to their smallest exponent `E` ([`common_scale`]), exact where
/// [`squared_distance`]'s `u128` overflows (e.g. 17-digit mantissas across exponents
/// `10⁻⁵` and `10⁰`); `None` when a coordinate is not a decimal or the alignment or a
/// difference overflows `i128`.
pub fn squared_distance_wide(a: &[Coordinate; 3], b: &[Coordinate; 3]) -> Option<([u64; 4], i32)> {
    let (m, e) = common_scale([&a[0], &a[1], &a[2], &b[0], &b[1], &b[2]])?;
    let mut n = [0u64; 4];
    for k in 0..3 {
        let d = m[3 + k].checked_sub(m[k])?.unsigned_abs();
        let [d0, d1, d2, d3] = mul_wide(d, d);
        let ok = add_at(&mut n, 0, u128::from(d0) | (u128::from(d1) << 64))
            && add_at(&mut n, 2, u128::from(d2) | (u128::from(d3) << 64));
        if !ok {
            return None;
        }
    }
    Some((n, e))
}

/// Whether two points differ, decided on their mantissas aligned to a common exponent
/// (`None` when a coordinate is not a decimal or the alignment overflows `i128`).
pub fn distinct_points(a: &[Coordinate; 3], b: &[Coordinate; 3]) -> Option<bool> {
    let (m, _) = common_scale([&a[0], &a[1], &a[2], &b[0], &b[1], &b[2]])?;
    Some((0..3).any(|k| m[3 + k] != m[k]))
}

/// The exact rational `n · 10^e`.
pub fn decimal_to_rational(n: u128, e: i32) -> Rational {
    let p = Integer::from(Integer::u_pow_u(10, e.unsigned_abs()));
    if e >= 0 {
        Rational::from(Integer::from(n) * p)
    } else {
        Rational::from((Integer::from(n), p))
    }
}

/// `n · 10^e` rounded to the nearest `f64` (ties to even), the value
/// `Real::from_rational` gives for `f64` — or `None` where that conversion differs from
/// correct binary64 rounding (results below `f64::MIN_POSITIVE`, where MPFR's 53-bit
/// rounding precedes the subnormal one) and callers take the exact path.
///
/// Exact operands (`n < 2⁵³`, `|e| ≤ 22`) take one IEEE multiplication or division;
/// otherwise [`wide_to_f64`] rounds the exact integer quotient or product.
pub fn decimal_to_f64(n: u128, e: i32) -> Option<f64> {
    const EXACT: [f64; 23] = [
        1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16,
        1e17, 1e18, 1e19, 1e20, 1e21, 1e22,
    ];
    if n == 0 {
        return Some(0.0);
    }
    let x = if n < (1u128 << 53) && e.unsigned_abs() <= 22 {
        let p = EXACT[e.unsigned_abs() as usize];
        if e >= 0 {
            n as f64 * p
        } else {
            n as f64 / p
        }
    } else {
        return wide_to_f64(&[n as u64, (n >> 64) as u64], e);
    };
    (x.is_finite() && x >= f64::MIN_POSITIVE).then_some(x)
}

/// Limbs of the fixed-width integers of [`wide_to_f64`] (64 bits each, little-endian):
/// room for `2²⁵⁶ · 10^WIDE_EXPONENT` and for `2²⁵⁶ · 2^s` with `2^s ≈ 2⁶⁴ · 10^WIDE_EXPONENT`.
const WIDE_LIMBS: usize = 26;
/// Largest `|e|` [`wide_to_f64`] computes; past it `n·10^e` with `n < 2²⁵⁶` is never a
/// normal `f64` (`10⁴⁰⁰ > 2¹⁰²⁴ · 2²⁵⁶` and `2²⁵⁶ · 10⁻⁴⁰⁰ < 2⁻¹⁰²²`).
const WIDE_EXPONENT: u32 = 400;
/// `10¹⁹`, the largest power of ten in a `u64`.
const TEN19: u64 = 10_000_000_000_000_000_000;

/// `x ← x · m` on the first `len` limbs; returns the new length.
fn limbs_mul(x: &mut [u64; WIDE_LIMBS], len: usize, m: u64) -> usize {
    let mut carry = 0u128;
    for limb in x.iter_mut().take(len) {
        let t = u128::from(*limb) * u128::from(m) + carry;
        *limb = t as u64;
        carry = t >> 64;
    }
    if carry != 0 {
        x[len] = carry as u64;
        len + 1
    } else {
        len
    }
}

/// `x ← ⌊x / d⌋` on the first `len` limbs; returns the new length and whether the
/// remainder is non-zero.
fn limbs_div(x: &mut [u64; WIDE_LIMBS], len: usize, d: u64) -> (usize, bool) {
    let mut rem = 0u128;
    for limb in x[..len].iter_mut().rev() {
        let cur = (rem << 64) | u128::from(*limb);
        *limb = (cur / u128::from(d)) as u64;
        rem = cur % u128::from(d);
    }
    let mut len = len;
    while len > 0 && x[len - 1] == 0 {
        len -= 1;
    }
    (len, rem != 0)
}

/// `n · 10^e` for an integer `n < 2²⁵⁶` given as little-endian 64-bit limbs, rounded to
/// the nearest `f64` (ties to even) — exactly, in fixed-width integers, without big
/// numbers; `None` when the result is not a normal `f64` (as [`decimal_to_f64`]).
///
/// For `e ≥ 0` the product `X = n·10^e` is formed exactly. For `e < 0` the quotient
/// `q = ⌊n·2^s / 10^|e|⌋` is formed with `s` such that `q ≥ 2⁶³`, by successive divisions
/// by `10¹⁹` (`⌊⌊x/a⌋/b⌋ = ⌊x/(ab)⌋`), with a sticky bit `σ` that is set iff a remainder
/// was non-zero (`n·2^s / 10^|e|` is not an integer). Then with `L` the bit length of
/// `q`, `m = ⌊q / 2^(L−53)⌋` is rounded up iff the next bit is 1 and (any later bit, `σ`,
/// or the last bit of `m` is 1), and the value is `m · 2^(L−53−s)`: the binary64 nearest
/// to `n·10^e` with an unbounded exponent, which is the correctly rounded `f64` whenever it
/// is normal.
///
/// ```
/// use penner::io::decimal::wide_to_f64;
/// assert_eq!(wide_to_f64(&[3, 0, 0, 0], -1), Some(0.3));
/// assert_eq!(wide_to_f64(&[0, 1], 0), Some(18446744073709551616.0)); // 2⁶⁴
/// assert_eq!(wide_to_f64(&[1], -400), None); // below the normal range
/// ```
pub fn wide_to_f64(n: &[u64], e: i32) -> Option<f64> {
    let mut len = n.len();
    while len > 0 && n[len - 1] == 0 {
        len -= 1;
    }
    if len == 0 {
        return Some(0.0);
    }
    if len > 4 || e.unsigned_abs() > WIDE_EXPONENT {
        return None;
    }
    let mut x = [0u64; WIDE_LIMBS];
    let mut sticky = false;
    let mut s: i64 = 0;
    let k = e.unsigned_abs();
    if e >= 0 {
        x[..len].copy_from_slice(&n[..len]);
        for _ in 0..k / 19 {
            len = limbs_mul(&mut x, len, TEN19);
        }
        len = limbs_mul(&mut x, len, 10u64.pow(k % 19));
    } else {
        let bits_n = 64 * len as i64 - i64::from(n[len - 1].leading_zeros());
        // 10^k < 2^(⌊3.3220·k⌋ + 1), since log₂ 10 = 3.32193… < 3.3220.
        let bits_d = i64::from(k) * 33_220 / 10_000 + 1;
        s = (64 + bits_d - bits_n).max(0);
        let (words, bits) = ((s / 64) as usize, (s % 64) as u32);
        for i in 0..len {
            x[i + words] |= n[i] << bits;
            if bits > 0 {
                x[i + words + 1] |= n[i] >> (64 - bits);
            }
        }
        len += words + 1;
        while x[len - 1] == 0 {
            len -= 1;
        }
        for _ in 0..k / 19 {
            let (l, r) = limbs_div(&mut x, len, TEN19);
            len = l;
            sticky |= r;
        }
        let (l, r) = limbs_div(&mut x, len, 10u64.pow(k % 19));
        len = l;
        sticky |= r;
    }
    let bit = |i: i64| -> bool { (x[(i / 64) as usize] >> (i % 64)) & 1 == 1 };
    let l = 64 * len as i64 - i64::from(x[len - 1].leading_zeros());
    let (mut m, mut shift) = if l <= 53 {
        (x[0], 0i64)
    } else {
        let shift = l - 53;
        let (w, b) = ((shift / 64) as usize, (shift % 64) as u32);
        let lo = x[w] >> b;
        let hi = if b > 0 && w + 1 < len {
            x[w + 1] << (64 - b)
        } else {
            0
        };
        let m = (lo | hi) & ((1u64 << 53) - 1);
        let half = bit(shift - 1);
        let rest = sticky
            || x[..((shift - 1) / 64) as usize].iter().any(|&t| t != 0)
            || x[((shift - 1) / 64) as usize] & ((1u64 << ((shift - 1) % 64)) - 1) != 0;
        (m + u64::from(half && (rest || m & 1 == 1)), shift)
    };
    if m == 1 << 53 {
        m >>= 1;
        shift += 1;
    }
    // Normalise to 53 bits (only a short exact product is shorter) and build the bits.
    let z = i64::from(m.leading_zeros()) - 11;
    m <<= z;
    let biased = shift - s - z + 52 + 1023;
    (1..=2046)
        .contains(&biased)
        .then(|| f64::from_bits(((biased as u64) << 52) | (m & ((1u64 << 52) - 1))))
}
