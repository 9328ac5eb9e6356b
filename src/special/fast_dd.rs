//! `Л` for double-double arguments in double-double arithmetic (proofs/B55), without MPFR
//! on the common path `|x| ≤ 3.9` (the angles of triangles and of ideal tetrahedra):
//! reduction `x = k·π/2 + t`, `|k| ≤ 2`, by `π/2 = P₁ + P₂ + P₃` (three binary64 numbers)
//! with an exact leading subtraction, then the two series of B52,
//!
//! * `Л(t) = t (1 − log|2t| + Σ aₙ t²ⁿ)` for even `k` (and odd `k`, `|t| > 1/2`, after
//!   `t ↦ t ∓ π/2`), `|t| ≤ 1.0708`;
//! * `Л(π/2 + t) = −t (log 2 − Σ bₙ t²ⁿ)` for odd `k`, `|t| ≤ 1/2`,
//!
//! the first terms in double-double (Horner, JMP17 products and sums, B04/B06), the terms
//! below `2⁻⁶⁰` of the leading factor in binary64. Larger arguments are reduced by the
//! Payne–Hanek reduction of `Dd` (B18: absolute error `2⁻²⁵²`, relative `u²(1 + 2⁻¹⁹)`),
//! for every finite argument. Reduced arguments below `2⁻³⁰` after the short reduction
//! and below `2⁻¹⁰⁰` after Payne–Hanek (next to a multiple of π/2) go through the MPFR
//! evaluation instead.

use super::coefficients::{table, working_precision};
use crate::scalar::{dd_reduce_payne_hanek as reduce_payne_hanek, Dd, Real};
use rug::float::Constant;
use rug::Float;
use std::sync::OnceLock;

/// Terms of the series stored: the B52 tail at `θ ≤ 0.117` after 38 terms is below
/// `2⁻¹¹⁷` of the result.
const DD_TERMS: usize = 38;

/// Largest `|x|` reduced here (`|k| ≤ 2`).
const DD_LIMIT: f64 = 3.9;

/// Smallest reduced `|t|` accepted: the reduction's absolute error, below `2⁻¹⁵⁶`, is then
/// below `2⁻¹²⁶` of `t` (B55).
const MIN_REDUCED: f64 = 9.313225746154785e-10; // 2⁻³⁰

/// Smallest reduced `|t|` accepted from the Payne–Hanek reduction: its absolute error
/// `2⁻²⁵²` (B18) is then below `2⁻¹⁵²` of `t`, under its relative error `u²(1 + 2⁻¹⁹)`.
const MIN_REDUCED_WIDE: f64 = 7.888609052210118e-31; // 2⁻¹⁰⁰

struct Consts {
    /// π/2 = p1 + p2 + p3 + O(2⁻¹⁶⁰).
    p: [f64; 3],
    /// log 2 as a double-double.
    ln2: Dd,
    a: [Dd; DD_TERMS],
    b: [Dd; DD_TERMS],
}

fn consts() -> &'static Consts {
    static C: OnceLock<Consts> = OnceLock::new();
    C.get_or_init(|| {
        let hp = Float::with_val(400, Constant::Pi) >> 1u32;
        let p1 = hp.to_f64();
        let r1 = Float::with_val(400, &hp - p1);
        let p2 = r1.to_f64();
        let r2 = Float::with_val(400, &r1 - p2);
        let p3 = r2.to_f64();
        let t = table(working_precision(106));
        let mut a = [Dd::default(); DD_TERMS];
        let mut b = [Dd::default(); DD_TERMS];
        for n in 0..DD_TERMS.min(t.a_lo.len()) {
            a[n] = Dd::from_float(&t.a_lo[n]);
            b[n] = Dd::from_float(&t.b_lo[n]);
        }
        Consts {
            p: [p1, p2, p3],
            ln2: Dd::from_float(&Float::with_val(200, Constant::Log2)),
            a,
            b,
        }
    })
}

/// Numbers of terms `(n_dd, n_all)` for the ratio `θ` of the series: terms `1..=n_dd` in
/// double-double, `n_dd+1..=n_all` in binary64; the neglected tail is below `2⁻¹¹²` and the
/// binary64 terms below `2⁻⁶⁰` (each `aₙsⁿ ≤ θⁿ`, B52).
fn term_counts(theta: f64) -> (usize, usize) {
    if theta <= 0.0 {
        return (0, 0);
    }
    let l = -theta.log2();
    let all = ((112.0 / l).ceil() as usize).clamp(1, DD_TERMS);
    let dd = ((60.0 / l).ceil() as usize).clamp(1, all);
    (dd, all)
}

/// `Σ_{n=1}^{all} cₙ sⁿ` with the first `dd` terms in double-double.
fn series(c: &[Dd; DD_TERMS], s: Dd, dd: usize, all: usize) -> Dd {
    let sf = s.hi;
    let mut small = 0.0_f64;
    for k in c[dd..all].iter().rev() {
        small = small.mul_add(sf, k.hi);
    }
    // small·s^(dd+1) + …: fold into the double-double Horner at degree dd.
    let mut acc = Dd::from_f64(small * sf);
    for k in c[..dd].iter().rev() {
        acc = mul(add(acc, *k), s);
    }
    acc
}

/// Knuth's TwoSum: `a + b = s + e` exactly (B01).
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

fn neg(x: Dd) -> Dd {
    -x
}

fn add(x: Dd, y: Dd) -> Dd {
    x + y
}

fn mul(x: Dd, y: Dd) -> Dd {
    x * y
}

fn add_f64(x: Dd, y: f64) -> Dd {
    x.add_f64(y)
}

/// `Л(t)` for `0 < |t| ≤ 1.0708`.
fn at_zero(t: Dd, c: &Consts) -> Dd {
    let theta = (t.hi / std::f64::consts::PI).powi(2);
    let (dd, all) = term_counts(theta);
    let s = mul(t, t);
    let p = series(&c.a, s, dd, all);
    let two_t = Dd::from_parts(2.0 * t.hi.abs(), 2.0 * t.lo * t.hi.signum());
    let lg = two_t.ln();
    let inner = add(add_f64(neg(lg), 1.0), p);
    mul(t, inner)
}

/// `Л(π/2 + t)` for `0 < |t| ≤ 1/2`.
fn at_half_pi(t: Dd, c: &Consts) -> Dd {
    let theta = (2.0 * t.hi / std::f64::consts::PI).powi(2);
    let (dd, all) = term_counts(theta);
    let s = mul(t, t);
    let q = series(&c.b, s, dd, all);
    neg(mul(t, add(c.ln2, neg(q))))
}

/// `Л(x)` in double-double, or `None` when the MPFR path must decide (reduced argument
/// below `2⁻³⁰` for `|x| ≤ 3.9`, below `2⁻¹⁰⁰` beyond, non-finite `x`).
pub(crate) fn lobachevsky_dd(x: Dd) -> Option<Dd> {
    let c = consts();
    let ax = x.hi.abs();
    if !ax.is_finite() {
        return None;
    }
    if x.hi == 0.0 {
        return Some(Dd::default());
    }
    let (t, odd) = if ax > DD_LIMIT {
        // proof: B18 (reduction), B55 (wide arguments)
        let (t, k) = reduce_payne_hanek(x);
        if t.hi.abs() < MIN_REDUCED_WIDE {
            return None;
        }
        (t, k & 1 == 1)
    } else {
        let k = (x.hi / c.p[0]).round();
        let t = if k == 0.0 {
            x
        } else {
            // x.hi − k·P₁ is exact (Sterbenz: x.hi/(k·P₁) ∈ [1/2, 2] for |k| ≤ 2, k·P₁
            // exact); the small parts are summed exactly as a double-double first.
            let a = x.hi - k * c.p[0];
            let (s, e) = two_sum(x.lo, -k * c.p[1]);
            let small = add_f64(Dd::from_parts(s, e), -k * c.p[2]);
            add(Dd::from_f64(a), small)
        };
        if k != 0.0 && t.hi.abs() < MIN_REDUCED {
            return None;
        }
        (t, k.abs() == 1.0)
    };
    if !odd {
        return Some(at_zero(t, c));
    }
    if t.hi.abs() <= 0.5 {
        return Some(at_half_pi(t, c));
    }
    // Л(π/2 + t) = Л(t ∓ π/2) with the sign of t (no cancellation: |t| > 1/2 > π/2 − 1.0708).
    let sg = t.hi.signum();
    let r = add_f64(
        add(t, Dd::from_parts(-sg * c.p[0], -sg * c.p[1])),
        -sg * c.p[2],
    );
    Some(at_zero(r, c))
}
