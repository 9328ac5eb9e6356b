//! Exact parsing of decimal and fraction literals into [`rug::Rational`].
//!
//! Accepted forms (no surrounding whitespace; ASCII only):
//!
//! | form | examples | value |
//! |---|---|---|
//! | integer | `7`, `-12`, `+3` | itself |
//! | decimal | `1.25`, `-.5`, `5.`, `0.1` | exactly the decimal written (`0.1` = 1/10) |
//! | scientific | `7e-3`, `1E+30`, `-2.5e-30` | `m · 10^e` exactly |
//! | fraction | `3/2`, `-3/2`, `6/4` | `p / q` reduced, `q > 0` |
//!
//! Refused with a [`NumberError`]: the empty string, `nan`/`inf`/`infinity` (any case),
//! hexadecimal, missing digits (`.`, `1e`, `e5`), signs in a denominator, a zero
//! denominator, anything trailing, more than [`MAX_DIGITS`] digits, and a decimal exponent
//! whose size exceeds [`MAX_EXPONENT`] (so `1e999999999` cannot exhaust memory).

use rug::{Integer, Rational};

/// Largest accepted |decimal exponent| (after folding in the fraction digits).
pub const MAX_EXPONENT: i64 = 10_000;
/// Largest accepted number of digits in one literal.
pub const MAX_DIGITS: usize = 10_000;

/// Why a string is not an exact number literal.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum NumberError {
    /// The string is empty.
    #[error("empty number")]
    Empty,
    /// NaN or infinity: not a real number.
    #[error("`{0}` is not a finite number")]
    NotFinite(String),
    /// Not of an accepted form.
    #[error("`{text}` is not a number: {reason} at byte {position}")]
    Invalid {
        /// The literal (shortened to 40 characters).
        text: String,
        /// Byte offset of the problem.
        position: usize,
        /// What was expected.
        reason: &'static str,
    },
    /// Exponent out of range.
    #[error("`{text}`: exponent beyond ±{MAX_EXPONENT}")]
    ExponentTooLarge {
        /// The literal (shortened to 40 characters).
        text: String,
    },
    /// Too many digits.
    #[error("number with more than {MAX_DIGITS} digits")]
    TooManyDigits,
    /// `p/0`.
    #[error("`{0}`: zero denominator")]
    ZeroDenominator(String),
}

fn short(s: &str) -> String {
    let mut out: String = s.chars().take(40).collect();
    if out.len() < s.len() {
        out.push('…');
    }
    out
}

/// Parse an exact rational literal (see the module documentation for the grammar).
///
/// ```
/// use penner::scalar::parse_rational;
/// use rug::Rational;
/// assert_eq!(parse_rational("1.25").unwrap(), Rational::from((5, 4)));
/// assert_eq!(parse_rational("-3/2").unwrap(), Rational::from((-3, 2)));
/// assert_eq!(parse_rational("7e-3").unwrap(), Rational::from((7, 1000)));
/// assert!(parse_rational("1e999999999").is_err());
/// assert!(parse_rational("NaN").is_err());
/// ```
pub fn parse_rational(s: &str) -> Result<Rational, NumberError> {
    if s.is_empty() {
        return Err(NumberError::Empty);
    }
    let lower = s.trim_start_matches(['+', '-']).to_ascii_lowercase();
    if matches!(lower.as_str(), "nan" | "inf" | "infinity" | "snan" | "qnan") {
        return Err(NumberError::NotFinite(short(s)));
    }
    if let Some((p, q)) = s.split_once('/') {
        let num = parse_decimal(p, s, 0)?;
        let off = p.len() + 1;
        let q_bytes = q.as_bytes();
        if q_bytes.is_empty() || !q_bytes.iter().all(u8::is_ascii_digit) {
            let position = off
                + q_bytes
                    .iter()
                    .position(|b| !b.is_ascii_digit())
                    .unwrap_or(0);
            return Err(NumberError::Invalid {
                text: short(s),
                position,
                reason: "the denominator must be digits only",
            });
        }
        if !num.is_integer() || p.contains(['.', 'e', 'E']) {
            return Err(NumberError::Invalid {
                text: short(s),
                position: 0,
                reason: "a fraction needs an integer numerator",
            });
        }
        let den = digits_to_integer(q)?;
        if den == 0 {
            return Err(NumberError::ZeroDenominator(short(s)));
        }
        return Ok(Rational::from((num.into_numer_denom().0, den)));
    }
    parse_decimal(s, s, 0)
}

fn digits_to_integer(d: &str) -> Result<Integer, NumberError> {
    if d.len() > MAX_DIGITS {
        return Err(NumberError::TooManyDigits);
    }
    if d.is_empty() {
        return Ok(Integer::new());
    }
    // Only ASCII digits reach here.
    Integer::from_str_radix(d, 10).map_err(|_| NumberError::TooManyDigits)
}

/// `[+-]? (d+ (. d*)? | . d+) ([eE] [+-]? d+)?` — `full` and `base` locate errors.
fn parse_decimal(t: &str, full: &str, base: usize) -> Result<Rational, NumberError> {
    let b = t.as_bytes();
    let bad = |position: usize, reason: &'static str| NumberError::Invalid {
        text: short(full),
        position: base + position,
        reason,
    };
    let mut i = 0;
    let negative = match b.first() {
        Some(b'-') => {
            i = 1;
            true
        }
        Some(b'+') => {
            i = 1;
            false
        }
        Some(_) => false,
        None => return Err(bad(0, "expected digits")),
    };
    let int_start = i;
    while i < b.len() && b[i].is_ascii_digit() {
        i += 1;
    }
    let int_digits = &t[int_start..i];
    let mut frac_digits = "";
    if i < b.len() && b[i] == b'.' {
        i += 1;
        let fs = i;
        while i < b.len() && b[i].is_ascii_digit() {
            i += 1;
        }
        frac_digits = &t[fs..i];
    }
    if int_digits.is_empty() && frac_digits.is_empty() {
        return Err(bad(int_start, "expected digits"));
    }
    let mut exp: i64 = 0;
    if i < b.len() && (b[i] == b'e' || b[i] == b'E') {
        i += 1;
        let mut exp_neg = false;
        if i < b.len() && (b[i] == b'+' || b[i] == b'-') {
            exp_neg = b[i] == b'-';
            i += 1;
        }
        let es = i;
        while i < b.len() && b[i].is_ascii_digit() {
            // Saturate: anything past MAX_EXPONENT is refused below.
            exp = (exp * 10 + i64::from(b[i] - b'0')).min(10 * MAX_EXPONENT);
            i += 1;
        }
        if i == es {
            return Err(bad(i, "expected exponent digits"));
        }
        if exp_neg {
            exp = -exp;
        }
    }
    if i != b.len() {
        return Err(bad(i, "unexpected character"));
    }
    if int_digits.len() + frac_digits.len() > MAX_DIGITS {
        return Err(NumberError::TooManyDigits);
    }
    let scale = exp - frac_digits.len() as i64;
    if exp.abs() > MAX_EXPONENT || scale.abs() > MAX_EXPONENT + MAX_DIGITS as i64 {
        return Err(NumberError::ExponentTooLarge { text: short(full) });
    }
    let mut m = digits_to_integer(int_digits)?;
    if !frac_digits.is_empty() {
        m *= Integer::from(Integer::u_pow_u(10, frac_digits.len() as u32));
        m += digits_to_integer(frac_digits)?;
    }
    if negative {
        m = -m;
    }
    let p = Integer::from(Integer::u_pow_u(10, scale.unsigned_abs() as u32));
    Ok(if scale >= 0 {
        Rational::from(m * p)
    } else {
        Rational::from((m, p))
    })
}
