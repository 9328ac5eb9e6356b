//! Certified comparison of computed quantities with claimed values: is |x_i − c_i| ≤ ε?
//!
//! The quantities come as rigorous enclosures (MPFR intervals) recomputed at rising
//! precision, the claimed values and ε as exact rationals. An element is decided
//! `Inside` when the enclosure proves |x − c| < ε, `Outside` when it proves |x − c| > ε;
//! otherwise more bits are tried, and an element still open at the cap is `Undecided`
//! (this includes the exact tie |x − c| = ε, which no enclosure of positive width can
//! settle).

use crate::scalar::{Certified, Interval, Mpfr, Precision, Real, Sign, Stage};
use rug::Rational;

/// Where a quantity lies relative to its claimed value.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Within {
    /// |x − c| < ε, certified.
    Inside,
    /// |x − c| > ε, certified.
    Outside,
}

/// The outcome of [`within_all`].
#[derive(Clone, Debug, PartialEq)]
pub struct Batch {
    /// One certified answer per element.
    pub answers: Vec<Certified<Within>>,
    /// The highest precision used (bits).
    pub bits: u32,
    /// Per element, |mid(x − c)| at the last precision used: for display only.
    pub discrepancy: Vec<f64>,
}

/// The decision for one element, and |mid(x − c)| for display.
fn decide_one(
    x: &Interval<Mpfr>,
    c: &Rational,
    eps: &Rational,
    prec: Precision,
) -> (Option<Within>, f64) {
    let d = x.clone() - &Interval::from_rational(c, prec);
    let shown = f64::midpoint(d.lo().approx_f64(), d.hi().approx_f64()).abs();
    (decide_sign(&d, eps, prec), shown)
}

fn decide_sign(d: &Interval<Mpfr>, eps: &Rational, prec: Precision) -> Option<Within> {
    let e = Interval::<Mpfr>::from_rational(eps, prec);
    let inside = (e.clone() - d).sign() == Some(Sign::Positive)
        && (e.clone() + d).sign() == Some(Sign::Positive);
    if inside {
        return Some(Within::Inside);
    }
    let outside = (d.clone() - &e).sign() == Some(Sign::Positive)
        || ((-d.clone()) - &e).sign() == Some(Sign::Positive);
    outside.then_some(Within::Outside)
}

/// Decide |x_i − c_i| ≤ ε for every i, where `enclose(p)` returns rigorous enclosures of
/// all x_i at precision p. Precisions double from `start_bits` to `max_bits`; enclosures
/// are recomputed only while some element is still open.
pub fn within_all(
    enclose: &mut dyn FnMut(Precision) -> Vec<Interval<Mpfr>>,
    claimed: &[Rational],
    eps: &Rational,
    start_bits: u32,
    max_bits: u32,
) -> Batch {
    let n = claimed.len();
    let mut answers: Vec<Certified<Within>> = vec![Certified::Undecided { bits_tried: 0 }; n];
    let mut discrepancy = vec![f64::NAN; n];
    let mut bits = start_bits.max(53);
    let mut used = 0;
    while bits <= max_bits {
        let Ok(prec) = Precision::new(u64::from(bits)) else {
            break;
        };
        used = bits;
        let xs = enclose(prec);
        let mut open = false;
        for i in 0..n {
            if answers[i].value().is_some() {
                continue;
            }
            let Some(x) = xs.get(i) else {
                continue;
            };
            let (decision, shown) = decide_one(x, &claimed[i], eps, prec);
            discrepancy[i] = shown;
            answers[i] = if let Some(w) = decision {
                Certified::Known {
                    value: w,
                    stage: Stage::Interval { bits },
                }
            } else {
                open = true;
                Certified::Undecided { bits_tried: bits }
            };
        }
        if !open {
            break;
        }
        bits = bits.saturating_mul(2);
    }
    Batch {
        answers,
        bits: used,
        discrepancy,
    }
}
