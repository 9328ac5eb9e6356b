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
    // Past i128 (mantissas aligned across distant exponents): the same cross product in
    // big integers, still exact and without a rational's gcd.
    narrow().or_else(|| {
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
/// otherwise the digits are handed to the standard library's decimal reader, which rounds
/// correctly for any number of digits.
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
        let mut buf = [0u8; 64];
        let mut i = buf.len();
        let (e_digits, e_len) = itoa_i32(e);
        i -= e_len;
        buf[i..i + e_len].copy_from_slice(&e_digits[..e_len]);
        i -= 1;
        buf[i] = b'e';
        // Digits from the right in chunks of 19 (u64 arithmetic; u128 division is slow).
        let mut r = n;
        loop {
            let chunk = (r % 10_000_000_000_000_000_000) as u64;
            r /= 10_000_000_000_000_000_000;
            let mut c = chunk;
            let mut written = 0;
            while c > 0 || (r > 0 && written < 19) {
                i -= 1;
                buf[i] = b'0' + (c % 10) as u8;
                c /= 10;
                written += 1;
            }
            if r == 0 {
                break;
            }
        }
        std::str::from_utf8(&buf[i..]).ok()?.parse::<f64>().ok()?
    };
    (x.is_finite() && x >= f64::MIN_POSITIVE).then_some(x)
}

/// The decimal digits of `e` (with a sign) and their count.
fn itoa_i32(e: i32) -> ([u8; 12], usize) {
    let mut digits = [0u8; 12];
    let mut k = 0;
    let mut r = e.unsigned_abs();
    loop {
        digits[k] = b'0' + (r % 10) as u8;
        k += 1;
        r /= 10;
        if r == 0 {
            break;
        }
    }
    if e < 0 {
        digits[k] = b'-';
        k += 1;
    }
    digits[..k].reverse();
    (digits, k)
}
