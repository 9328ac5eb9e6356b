//! T30 (docs/catalogue.md §7): identities of Lobachevsky's function `Л` at given arguments `x` —
//! oddness `Л(−x) = −Л(x)`, π-periodicity `Л(x + π) = Л(x)`, reflection
//! `Л(π − x) = −Л(x)`, the multiplication formula `Л(nx) = n Σ_{k<n} Л(x + kπ/n)`
//! (`n = 2…7`), and agreement of two independent evaluations (the ζ-series of
//! [`crate::special::lobachevsky`] and the tangent-number series of
//! [`crate::special::lobachevsky_tangent_series`]).
//!
//! [`check_lobachevsky`] compares at the working precision against the tolerance of B54;
//! an identity beyond it is re-examined by enclosures ([`check_lobachevsky_certified`]'s
//! comparison), so a numerical run never refutes: it `fails` only when the enclosures of
//! both sides are disjoint. [`check_lobachevsky_certified`] encloses every `Л` over an
//! outward-rounded argument (proofs/B52): an identity holds when the enclosures overlap
//! and fails only when they are disjoint.
//!
//! ```
//! use penner::theorems::t30_lobachevsky::{check_lobachevsky, check_lobachevsky_certified};
//! use rug::Rational;
//! assert!(check_lobachevsky(&[0.25_f64, 3.0, -100.5], false).holds());
//! let x = [Rational::from((1, 3)), Rational::from(7)];
//! assert!(check_lobachevsky_certified(&x, 128, false).holds());
//! // One argument off by 1 %: the enclosures are disjoint.
//! assert!(check_lobachevsky_certified(&x, 128, true).fails());
//! ```

use super::bounds::{eps, eps_shift, SAFETY};
use super::{Verdict, Witness};
use crate::predicates::tolerance::abs_at_most_scaled;
use crate::scalar::{Interval, Mpfr, Precision, Real};
use crate::special::{lobachevsky, lobachevsky_enclosure, lobachevsky_tangent_series};
use rug::{Float, Rational};

/// An argument `m·x + π·a/b` of one `Л` in an identity.
#[derive(Clone, Copy, Debug)]
struct Arg {
    m: i32,
    a: i32,
    b: i32,
}

/// `Σ cᵢ Л(argᵢ) = 0`, with a name.
struct Identity {
    name: String,
    terms: Vec<(i32, Arg)>,
}

fn arg(m: i32, a: i32, b: i32) -> Arg {
    Arg { m, a, b }
}

/// The identities of T30 at one argument.
fn identities() -> Vec<Identity> {
    let mut out = vec![
        Identity {
            name: "Л(−x) = −Л(x)".into(),
            terms: vec![(1, arg(-1, 0, 1)), (1, arg(1, 0, 1))],
        },
        Identity {
            name: "Л(x + π) = Л(x)".into(),
            terms: vec![(1, arg(1, 1, 1)), (-1, arg(1, 0, 1))],
        },
        Identity {
            name: "Л(π − x) = −Л(x)".into(),
            terms: vec![(1, arg(-1, 1, 1)), (1, arg(1, 0, 1))],
        },
    ];
    for n in 2..=7 {
        let mut terms = vec![(1, arg(n, 0, 1))];
        terms.extend((0..n).map(|k| (-n, arg(1, k, n))));
        out.push(Identity {
            name: format!("Л({n}x) = {n} Σ_k Л(x + kπ/{n})"),
            terms,
        });
    }
    out
}

/// The factor applied to `x` in the last term of every identity by the negative control.
fn wrong_factor() -> Rational {
    Rational::from((101, 100))
}

/// `m·x + π·a/b` in the backend of `x`; `x` already perturbed by the caller if needed.
fn eval_arg<T: Real>(x: &T, g: Arg) -> T {
    let mut y = x.clone() * &x.lit(f64::from(g.m));
    if g.a != 0 {
        let pi = T::pi(x.ctx()) * &x.lit(f64::from(g.a)) / &x.lit(f64::from(g.b));
        y += &pi;
    }
    y
}

/// B54: `|Л(a) − Л(b)| ≤ ω(h) = h (1 + log 2 + log(π/h))` for `|a − b| ≤ h ≤ π/2`,
/// evaluated with `h` scaled by `2ˢ` (the log of the true `h` is `log h_s − s log 2`).
// proof: B54
fn modulus(h_scaled: f64, shift: u32) -> f64 {
    if h_scaled == 0.0 {
        return 0.0;
    }
    h_scaled
        * (1.0
            + std::f64::consts::LN_2
            + (std::f64::consts::PI / h_scaled).ln()
            + f64::from(shift) * std::f64::consts::LN_2)
}

/// Residual of one identity and its tolerance `tol` (scaled by `2ˢ`, B54), or `None` when
/// an argument's rounding error may exceed 1 (the identity is then not examined).
fn residual<T: Real>(x: &T, id: &Identity, wrong: bool) -> Option<(T, f64)> {
    let e = eps::<T>(x.ctx());
    let s = eps_shift(T::precision_bits(x.ctx()));
    let ax = x.approx_f64().abs();
    let mut sum = x.zero_like();
    let mut weight = 0.0;
    let mut tol = 0.0;
    let last = id.terms.len() - 1;
    for (i, &(c, g)) in id.terms.iter().enumerate() {
        let xi = if wrong && i == last {
            x.clone() * &T::from_rational(&wrong_factor(), x.ctx())
        } else {
            x.clone()
        };
        let l = lobachevsky(&eval_arg(&xi, g));
        let cf = f64::from(c.abs());
        // Argument error: at most 4 roundings of |m x| + π (B54).
        let h = e * (f64::from(g.m.abs()) * ax + std::f64::consts::PI);
        if s == 0 && h > 1.0 || !h.is_finite() {
            return None;
        }
        let lv = l.approx_f64().abs();
        tol += cf * (e * lv + modulus(h, s));
        weight += cf * lv;
        sum += &(l * &x.lit(f64::from(c)));
    }
    tol += (id.terms.len() as f64 + 1.0) * e * weight;
    Some((sum, SAFETY * tol))
}

/// Enclosure of `Σ cᵢ Л(argᵢ)` with outward-rounded arguments at `bits`.
fn enclosed_sum(x: &Rational, id: &Identity, bits: u32, wrong: bool) -> Option<Interval<Mpfr>> {
    let p = Precision::new(u64::from(bits)).ok()?;
    let last = id.terms.len() - 1;
    let mut sum = Interval::point(Mpfr::from_f64(0.0, p));
    for (i, &(c, g)) in id.terms.iter().enumerate() {
        let xi = if wrong && i == last {
            Rational::from(x * &wrong_factor())
        } else {
            x.clone()
        };
        let xe = Interval::<Mpfr>::from_rational(&xi, p);
        let l = lobachevsky_enclosure(&eval_arg(&xe, g));
        if !l.is_valid() {
            return None;
        }
        sum += &(l * &Interval::point(Mpfr::from_f64(f64::from(c), p)));
    }
    Some(sum)
}

fn witness(x: f64, name: &str, detail: &str, value: f64) -> Witness {
    Witness {
        element: format!("x = {x:e}"),
        detail: format!("{name}: {detail}"),
        value,
    }
}

/// The certified comparison of one identity: `Some(true)` when the enclosure of the
/// residual contains 0 and is narrow ([`decide_enclosed_residual`]), `Some(false)` when it
/// excludes 0, `None` when there is no enclosure or it is too wide to say anything.
fn certified_identity(x: &Rational, id: &Identity, bits: u32, wrong: bool) -> Option<bool> {
    decide_enclosed_residual(&enclosed_sum(x, id, bits, wrong)?, bits)
}

/// Excess bits allowed in the width of an enclosed residual at `bits` bits: an identity
/// holds only on an enclosure of width `≤ 2^(WIDTH_SLACK_BITS − bits)`. Each of the at most
/// eight enclosures of `Л` is within a few units of `2^(−bits)` (B52), so honest widths are
/// far inside; an enclosure of the whole range `[−M, M]` of `Л` is not. proof: B52
const WIDTH_SLACK_BITS: i32 = 32;

/// `Some(false)` when the enclosure excludes 0 (the identity is refuted), `Some(true)` when
/// it contains 0 and its width is at most `2^(WIDTH_SLACK_BITS − bits)`, `None` otherwise.
fn decide_enclosed_residual(sum: &Interval<Mpfr>, bits: u32) -> Option<bool> {
    if !sum.contains_zero() {
        return Some(false);
    }
    let limit = 2f64.powi(WIDTH_SLACK_BITS - i32::try_from(bits).unwrap_or(i32::MAX));
    (sum.width_f64() <= limit).then_some(true)
}

/// T30 at the working precision of `T` (numerical, B54); a residual beyond the tolerance
/// is re-examined by enclosures at the same precision, and reported `fails` only when the
/// enclosures are disjoint (certified), otherwise `undecided`. `wrong` perturbs the
/// argument of the last term of every identity by 1 % (the negative control T30-NC).
pub fn check_lobachevsky<T: Real>(args: &[T], wrong: bool) -> Verdict {
    let Some(first) = args.first() else {
        return Verdict::Holds {
            certified: false,
            max_error: 0.0,
        };
    };
    let bits = T::precision_bits(first.ctx()).max(64);
    let mut failures = Vec::new();
    let mut undecided = Vec::new();
    let mut max_error: f64 = 0.0;
    for x in args {
        let xf = x.approx_f64();
        let Some(q) = x.to_rational() else {
            undecided.push(witness(xf, "argument", "not a finite number", f64::NAN));
            continue;
        };
        for id in identities() {
            let Some((r, tol)) = residual(x, &id, wrong) else {
                undecided.push(witness(
                    xf,
                    &id.name,
                    "argument too large for this precision",
                    f64::NAN,
                ));
                continue;
            };
            let s = eps_shift(T::precision_bits(x.ctx()));
            match abs_at_most_scaled(&r, tol, s) {
                Some(true) => max_error = max_error.max(r.approx_f64().abs()),
                _ => match certified_identity(&q, &id, bits, wrong) {
                    Some(false) => failures.push(witness(
                        xf,
                        &id.name,
                        "enclosures of the two sides are disjoint",
                        r.approx_f64(),
                    )),
                    _ => undecided.push(witness(
                        xf,
                        &id.name,
                        "residual beyond the B54 tolerance, enclosures overlap",
                        r.approx_f64(),
                    )),
                },
            }
        }
        // Two independent evaluations.
        let ours = lobachevsky(x);
        let xe = Float::with_val(q.numer().significant_bits().max(64), &q);
        if let Some(reference) = lobachevsky_tangent_series(&xe, bits + 32) {
            let reference = T::from_rational(&reference.to_rational().unwrap_or_default(), x.ctx());
            let diff = ours.clone() - &reference;
            let tol = SAFETY * 2.0 * eps::<T>(x.ctx()) * ours.approx_f64().abs();
            let s = eps_shift(T::precision_bits(x.ctx()));
            if abs_at_most_scaled(&diff, tol, s) != Some(true) {
                let detail = "the ζ-series and the tangent-number series disagree beyond B54";
                undecided.push(witness(xf, "two evaluations", detail, diff.approx_f64()));
            }
        }
    }
    if !failures.is_empty() {
        return Verdict::Fails {
            certified: true,
            witnesses: failures,
        };
    }
    if !undecided.is_empty() {
        return Verdict::Undecided {
            bits_tried: bits,
            witnesses: undecided,
        };
    }
    Verdict::Holds {
        certified: false,
        max_error,
    }
}

/// T30 certified at `bits` on exact arguments: every identity's residual is enclosed
/// (outward-rounded arguments, [`lobachevsky_enclosure`], B52); it holds when each
/// enclosure contains 0, fails (certified) when one excludes 0.
pub fn check_lobachevsky_certified(args: &[Rational], bits: u32, wrong: bool) -> Verdict {
    let mut failures = Vec::new();
    let mut undecided = Vec::new();
    for x in args {
        let xf = x.to_f64();
        for id in identities() {
            match certified_identity(x, &id, bits, wrong) {
                Some(true) => {}
                Some(false) => failures.push(witness(
                    xf,
                    &id.name,
                    "enclosures of the two sides are disjoint",
                    f64::NAN,
                )),
                None => undecided.push(witness(
                    xf,
                    &id.name,
                    "no enclosure at this precision",
                    f64::NAN,
                )),
            }
        }
    }
    Verdict::certified(failures, undecided, bits)
}

#[cfg(test)]
mod width {
    use super::*;

    /// An enclosure of the whole range of `Л` contains 0 but proves nothing: it must not
    /// certify; a residual enclosure `2^(−bits)` wide does; one excluding 0 refutes.
    #[test]
    fn t30_certified_row_needs_a_narrow_enclosure() {
        let p = Precision::new(128).expect("precision");
        let full = Interval::new(Mpfr::from_f64(-0.51, p), Mpfr::from_f64(0.51, p));
        assert_eq!(decide_enclosed_residual(&full, 128), None);
        let tiny = 2f64.powi(-128);
        let narrow = Interval::new(Mpfr::from_f64(-tiny, p), Mpfr::from_f64(tiny, p));
        assert_eq!(decide_enclosed_residual(&narrow, 128), Some(true));
        let off = Interval::new(Mpfr::from_f64(1e-3, p), Mpfr::from_f64(2e-3, p));
        assert_eq!(decide_enclosed_residual(&off, 128), Some(false));
    }
}
