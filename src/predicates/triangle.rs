//! Certified triangle inequalities for rational side lengths, rational squared lengths and
//! the stored lengths of any [`Real`] backend.
//!
//! Each predicate climbs the ladder ([`decide`]): an f64 filter with a proven error bound
//! (proofs/B23, B24), MPFR interval enclosures (proofs/B20), and the exact value in
//! `rug::Rational`.

use super::delaunay::f64_exact;
use super::filter::{self, Ring, U};
use super::ladder::{decide, Ladder, SignPredicate};
use crate::scalar::{Certified, Precision, Real, Sign, Stage};
use rug::Rational;

/// Filter constant of [`TriangleSlack`]: `|v − fl(v)| ≤ 4u·(|a|+|b|+|c|)`, proofs/B23.
pub const SLACK_FILTER: f64 = 4.0 * U;
/// Filter constant of [`TriangleAreaSq`]: `|E − fl(E)| ≤ 8u·(|A|+|B|+|C|)²`, proofs/B24.
pub const AREA_SQ_FILTER: f64 = 8.0 * U;

/// `b + c − a` in this evaluation order (proofs/B23).
fn slack_value<T: Ring>(v: &[T; 3]) -> T {
    let [a, b, c] = v;
    b.clone() + c - a
}

/// `2(AB + BC + CA) − (A² + B² + C²)` in this evaluation order (proofs/B24).
fn area_sq_value<T: Ring>(v: &[T; 3]) -> T {
    let [a, b, c] = v;
    let s = a.clone() * b + &(b.clone() * c) + &(c.clone() * a);
    let q = a.clone() * a + &(b.clone() * b) + &(c.clone() * c);
    s.clone() + &s - &q
}

/// The slack `b + c − a` of the triangle inequality `a ≤ b + c` for rational side lengths
/// (docs/catalogue.md §1): positive for a strict inequality, zero for a degenerate (flat) triangle.
///
/// ```
/// use penner::predicates::ladder::{decide, Ladder};
/// use penner::predicates::triangle::TriangleSlack;
/// use penner::scalar::Sign;
/// use rug::Rational;
/// let q = |n: i64, d: i64| Rational::from((n, d));
/// // 1/3 + 2/3 − 1 = 0 exactly, though not in binary64.
/// let s = TriangleSlack::new(&q(1, 1), &q(1, 3), &q(2, 3));
/// assert_eq!(decide(&s, &Ladder::default()).value(), Some(Sign::Zero));
/// ```
#[derive(Clone, Debug)]
pub struct TriangleSlack {
    v: [Rational; 3],
    approx: Option<[f64; 3]>,
}

impl TriangleSlack {
    /// The slack `b + c − a`.
    pub fn new(a: &Rational, b: &Rational, c: &Rational) -> TriangleSlack {
        let v = [a.clone(), b.clone(), c.clone()];
        // proof: B23 (inputs: nonzero in [2^-900, 2^1000])
        let approx = filter::inputs_in_range(&v, -900, 1000);
        TriangleSlack { v, approx }
    }

    /// The exact slack.
    pub fn exact_value(&self) -> Rational {
        slack_value(&self.v)
    }

    /// The filter with its bound multiplied by `factor`; `factor < 1` is unsound and exists
    /// only so tests can show that the proven bound is needed.
    #[doc(hidden)]
    pub fn filter_scaled(&self, factor: f64) -> Option<Sign> {
        let x = self.approx?;
        let [a, b, c] = x.map(f64::abs);
        filter::decide(
            slack_value(&x),
            filter::next_up(SLACK_FILTER * (a + b + c)) * factor,
        )
    }
}

impl SignPredicate for TriangleSlack {
    fn filter(&self) -> Option<Sign> {
        // proof: B23
        self.filter_scaled(1.0)
    }
    fn enclosure_sign(&self, prec: Precision) -> Option<Sign> {
        filter::sign_of(&slack_value(&filter::enclose(&self.v, prec)))
    }
    fn exact_sign(&self) -> Option<Sign> {
        Some(Sign::of_ordering(self.exact_value().cmp0()))
    }
}

/// `16·Area² = 2(AB + BC + CA) − (A² + B² + C²)` of a triangle with squared side lengths
/// `A = a², B = b², C = c²` (Heron's formula, docs/catalogue.md §1). For `A, B, C ≥ 0` it equals
/// `(a+b+c)(−a+b+c)(a−b+c)(a+b−c)`: positive exactly when the three strict triangle
/// inequalities hold, zero for a degenerate triangle.
///
/// ```
/// use penner::predicates::ladder::{decide, Ladder};
/// use penner::predicates::triangle::TriangleAreaSq;
/// use penner::scalar::Sign;
/// use rug::Rational;
/// let q = |n: i64| Rational::from(n);
/// // Sides 1, 2, 3 (squares 1, 4, 9) are flat; sides 3, 4, 5 are not.
/// assert_eq!(decide(&TriangleAreaSq::new(&q(1), &q(4), &q(9)), &Ladder::default()).value(), Some(Sign::Zero));
/// assert_eq!(decide(&TriangleAreaSq::new(&q(9), &q(16), &q(25)), &Ladder::default()).value(), Some(Sign::Positive));
/// ```
#[derive(Clone, Debug)]
pub struct TriangleAreaSq {
    v: [Rational; 3],
    approx: Option<[f64; 3]>,
}

impl TriangleAreaSq {
    /// `16·Area²` from squared lengths `A, B, C`.
    pub fn new(a2: &Rational, b2: &Rational, c2: &Rational) -> TriangleAreaSq {
        let v = [a2.clone(), b2.clone(), c2.clone()];
        // proof: B24 (inputs: nonzero in [2^-450, 2^450])
        let approx = filter::inputs_in_range(&v, -450, 450);
        TriangleAreaSq { v, approx }
    }

    /// The exact value of `16·Area²`.
    pub fn exact_value(&self) -> Rational {
        area_sq_value(&self.v)
    }

    /// The filter with its bound multiplied by `factor` (see [`TriangleSlack::filter_scaled`]).
    #[doc(hidden)]
    pub fn filter_scaled(&self, factor: f64) -> Option<Sign> {
        let x = self.approx?;
        let [a, b, c] = x.map(f64::abs);
        let s = a + b + c;
        filter::decide(
            area_sq_value(&x),
            filter::next_up(AREA_SQ_FILTER * (s * s)) * factor,
        )
    }
}

impl SignPredicate for TriangleAreaSq {
    fn filter(&self) -> Option<Sign> {
        // proof: B24
        self.filter_scaled(1.0)
    }
    fn enclosure_sign(&self, prec: Precision) -> Option<Sign> {
        filter::sign_of(&area_sq_value(&filter::enclose(&self.v, prec)))
    }
    fn exact_sign(&self) -> Option<Sign> {
        Some(Sign::of_ordering(self.exact_value().cmp0()))
    }
}

/// Combine certified facts with "and": `Known(false)` as soon as one is certainly false,
/// `Known(true)` when all are certainly true (stage: the highest rung used), else
/// `Undecided`.
fn all_positive(parts: &[Certified<Sign>]) -> Certified<bool> {
    let mut stage = Stage::Filter;
    let mut undecided = None;
    for p in parts {
        match p {
            Certified::Known { value, stage: s } => {
                if *value != Sign::Positive {
                    return Certified::Known {
                        value: false,
                        stage: *s,
                    };
                }
                stage = higher(stage, *s);
            }
            Certified::Undecided { bits_tried } => undecided = Some(*bits_tried),
        }
    }
    match undecided {
        Some(bits_tried) => Certified::Undecided { bits_tried },
        None => Certified::Known { value: true, stage },
    }
}

fn rank(s: Stage) -> u64 {
    match s {
        Stage::Filter => 0,
        Stage::Interval { bits } => u64::from(bits),
        Stage::Exact => u64::MAX,
    }
}

fn higher(a: Stage, b: Stage) -> Stage {
    if rank(b) > rank(a) {
        b
    } else {
        a
    }
}

/// Whether `a, b, c` are the side lengths of a non-degenerate triangle: all three slacks
/// `b + c − a`, `c + a − b`, `a + b − c` certified positive (docs/catalogue.md §1).
pub fn strict_triangle(
    a: &Rational,
    b: &Rational,
    c: &Rational,
    ladder: &Ladder,
) -> Certified<bool> {
    all_positive(&[
        decide(&TriangleSlack::new(a, b, c), ladder),
        decide(&TriangleSlack::new(b, c, a), ladder),
        decide(&TriangleSlack::new(c, a, b), ladder),
    ])
}

/// Whether squared lengths `A, B, C` belong to a non-degenerate triangle: `A, B, C > 0` and
/// `16·Area² > 0` ([`TriangleAreaSq`]); the signs of `A, B, C` are read exactly.
pub fn strict_triangle_sq(
    a2: &Rational,
    b2: &Rational,
    c2: &Rational,
    ladder: &Ladder,
) -> Certified<bool> {
    let exact = |q: &Rational| Certified::Known {
        value: Sign::of_ordering(q.cmp0()),
        stage: Stage::Filter,
    };
    all_positive(&[
        exact(a2),
        exact(b2),
        exact(c2),
        decide(&TriangleAreaSq::new(a2, b2, c2), ladder),
    ])
}

/// Whether `x < y + z` is proved by one rounded `f64` addition: for binary64 `x, y, z`,
/// rounding to nearest is monotone, so `y + z ≤ x` would give `fl(y + z) ≤ fl(x) = x`;
/// hence `x < fl(y + z)` implies `x < y + z` (proof: B66). `false` proves nothing.
#[allow(clippy::inline_always)] // hot path of the flip loop (measured)
#[inline(always)]
pub fn shorter_than_sum_f64(x: f64, y: f64, z: f64) -> bool {
    x < y + z
}

/// The three strict triangle inequalities of sides `a, b, c` (binary64): `a < fl(b + c)`
/// and `fl(|b − c|) < a`, each proved by monotonicity of rounding to nearest as in
/// [`shorter_than_sum_f64`] (`|b − c| ≥ a` would give `fl(|b − c|) ≥ a`); `false` proves
/// nothing (proof: B66).
#[allow(clippy::inline_always)] // hot path of the flip loop (measured)
#[inline(always)]
pub fn strict_triangle_f64(a: f64, b: f64, c: f64) -> bool {
    shorter_than_sum_f64(a, b, c) & ((b - c).abs() < a)
}

/// Whether three lengths of any [`Real`] backend are the sides of a non-degenerate
/// triangle (all three slacks `b + c − a > 0`, docs/catalogue.md §1), certified: first by
/// [`strict_triangle_f64`] when the values are binary64 numbers exactly (53-bit point
/// backends, normal range; proof: B66), then on their exact rational values through the
/// ladder of [`strict_triangle`]. `Undecided` for values without a rational value
/// (enclosures).
pub fn strict_triangle_real<T: Real>(sides: [&T; 3], ladder: &Ladder) -> Certified<bool> {
    if f64_exact::<T>(sides[0].ctx()) {
        let [a, b, c] = sides.map(Real::approx_f64);
        if a.is_normal() && b.is_normal() && c.is_normal() && strict_triangle_f64(a, b, c) {
            return Certified::Known {
                value: true,
                stage: Stage::Filter,
            };
        }
    }
    match sides.map(Real::to_rational) {
        [Some(a), Some(b), Some(c)] => strict_triangle(&a, &b, &c, ladder),
        _ => Certified::Undecided { bits_tried: 0 },
    }
}
