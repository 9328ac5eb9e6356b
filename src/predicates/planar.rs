//! Certified signs of the planar orientation and incircle determinants of rational points.
//!
//! Each predicate climbs the ladder ([`decide`]): an f64 filter with a proven error bound
//! (proofs/B25, B26), MPFR interval enclosures at rising precision (proofs/B20), and the
//! exact determinant in `rug::Rational`. Points are exact rationals; `f64` coordinates are
//! converted exactly.

use super::filter::Ring;
use super::filter::{self, U};
use super::ladder::{decide, Ladder, SignPredicate};
use crate::scalar::{Certified, Precision, Sign};
use rug::Rational;

/// A point with exact rational coordinates `[x, y]`.
pub type Point = [Rational; 2];

/// The exact point of a finite `f64` pair, `None` for NaN or ±∞.
pub fn point_from_f64(x: f64, y: f64) -> Option<Point> {
    Some([Rational::from_f64(x)?, Rational::from_f64(y)?])
}

/// `(b − a) × (c − a) = (bx−ax)(cy−ay) − (by−ay)(cx−ax)`, in this evaluation order (the
/// order proofs/B25 analyses).
fn orient_value<T: Ring>(v: &[T; 6]) -> T {
    let [ax, ay, bx, by, cx, cy] = v;
    let d1 = bx.clone() - ax;
    let d2 = cy.clone() - ay;
    let d3 = by.clone() - ay;
    let d4 = cx.clone() - ax;
    d1 * &d2 - &(d3 * &d4)
}

/// Twice the signed area of the triangle `a, b, c`: positive when `a, b, c` turn
/// counterclockwise, zero when they are collinear (docs/catalogue.md §9).
///
/// ```
/// use penner::predicates::ladder::{decide, Ladder};
/// use penner::predicates::planar::{point_from_f64, Orient2d};
/// use penner::scalar::Sign;
/// let p = |x, y| point_from_f64(x, y).unwrap();
/// // Exactly collinear in the rationals (not in binary64 after rounding 0.1, 0.2, 0.3).
/// let third = rug::Rational::from((1, 3));
/// let q = [third.clone(), third.clone()];
/// let o = Orient2d::new(&p(0.0, 0.0), &q, &p(1.0, 1.0));
/// assert_eq!(decide(&o, &Ladder::default()).value(), Some(Sign::Zero));
/// let o = Orient2d::new(&p(0.0, 0.0), &p(1.0, 0.0), &p(0.0, 1.0));
/// assert_eq!(decide(&o, &Ladder::default()).value(), Some(Sign::Positive));
/// ```
#[derive(Clone, Debug)]
pub struct Orient2d {
    v: [Rational; 6],
    approx: Option<[f64; 6]>,
}

/// Filter constant of [`Orient2d`]: `|det − fl(det)| ≤ 2⁻⁵⁰·T` (`8u`), proofs/B25.
pub const ORIENT2D_FILTER: f64 = 8.0 * U;
/// Filter constant of [`InCircle`]: `|det − fl(det)| ≤ 2⁻⁴⁹·P` (`16u`), proofs/B26.
pub const INCIRCLE_FILTER: f64 = 16.0 * U;

/// The coordinates `[x₀, y₀, x₁, y₁, …]` of `K` points as `N = 2K` rationals.
fn coordinates<const K: usize, const N: usize>(points: [&Point; K]) -> [Rational; N] {
    std::array::from_fn(|i| points[i / 2][i % 2].clone())
}

impl Orient2d {
    /// The orientation question for `a, b, c`.
    pub fn new(a: &Point, b: &Point, c: &Point) -> Orient2d {
        let v = coordinates([a, b, c]);
        // proof: B25 (inputs: nonzero coordinates in [2^-450, 2^500])
        let approx = filter::inputs_in_range(&v, -450, 500);
        Orient2d { v, approx }
    }

    /// The exact determinant.
    pub fn exact_value(&self) -> Rational {
        orient_value(&self.v)
    }

    /// The filter with its bound multiplied by `factor`; `factor < 1` is unsound and exists
    /// only so tests can show that the proven bound is needed.
    #[doc(hidden)]
    pub fn filter_scaled(&self, factor: f64) -> Option<Sign> {
        let x = self.approx?;
        let value = orient_value(&x);
        let [ax, ay, bx, by, cx, cy] = x.map(f64::abs);
        // T = (|bx|+|ax|)(|cy|+|ay|) + (|by|+|ay|)(|cx|+|ax|), proofs/B25.
        let t = (bx + ax) * (cy + ay) + (by + ay) * (cx + ax);
        filter::decide(value, filter::next_up(ORIENT2D_FILTER * t) * factor)
    }
}

impl SignPredicate for Orient2d {
    fn filter(&self) -> Option<Sign> {
        // proof: B25
        self.filter_scaled(1.0)
    }
    fn enclosure_sign(&self, prec: Precision) -> Option<Sign> {
        filter::sign_of(&orient_value(&filter::enclose(&self.v, prec)))
    }
    fn exact_sign(&self) -> Option<Sign> {
        Some(Sign::of_ordering(self.exact_value().cmp0()))
    }
}

/// `det [[adx, ady, adx²+ady²], [bdx, bdy, …], [cdx, cdy, …]]` with `·d = · − d`, expanded as
/// `alift·(bdx·cdy − cdx·bdy) + blift·(cdx·ady − adx·cdy) + clift·(adx·bdy − bdx·ady)`
/// (the order proofs/B26 analyses).
fn incircle_value<T: Ring>(v: &[T; 8]) -> T {
    let [ax, ay, bx, by, cx, cy, dx, dy] = v;
    let adx = ax.clone() - dx;
    let ady = ay.clone() - dy;
    let bdx = bx.clone() - dx;
    let bdy = by.clone() - dy;
    let cdx = cx.clone() - dx;
    let cdy = cy.clone() - dy;
    let alift = adx.clone() * &adx + &(ady.clone() * &ady);
    let blift = bdx.clone() * &bdx + &(bdy.clone() * &bdy);
    let clift = cdx.clone() * &cdx + &(cdy.clone() * &cdy);
    let bc = bdx.clone() * &cdy - &(cdx.clone() * &bdy);
    let ca = cdx * &ady - &(adx.clone() * &cdy);
    let ab = adx * &bdy - &(bdx * &ady);
    alift * &bc + &(blift * &ca) + &(clift * &ab)
}

/// The incircle determinant of `a, b, c, d`: for `a, b, c` counterclockwise it is positive
/// when `d` lies strictly inside their circumcircle, zero when on it, negative outside
/// (the sign flips for clockwise `a, b, c`), docs/catalogue.md §9.
///
/// ```
/// use penner::predicates::ladder::{decide, Ladder};
/// use penner::predicates::planar::{point_from_f64, InCircle};
/// use penner::scalar::Sign;
/// let p = |x, y| point_from_f64(x, y).unwrap();
/// let (a, b, c) = (p(1.0, 0.0), p(0.0, 1.0), p(-1.0, 0.0));
/// let l = Ladder::default();
/// assert_eq!(decide(&InCircle::new(&a, &b, &c, &p(0.0, 0.5)), &l).value(), Some(Sign::Positive));
/// assert_eq!(decide(&InCircle::new(&a, &b, &c, &p(0.0, -1.0)), &l).value(), Some(Sign::Zero));
/// assert_eq!(decide(&InCircle::new(&a, &b, &c, &p(0.0, -1.5)), &l).value(), Some(Sign::Negative));
/// ```
#[derive(Clone, Debug)]
pub struct InCircle {
    v: [Rational; 8],
    approx: Option<[f64; 8]>,
}

impl InCircle {
    /// The incircle question for `d` against the circle through `a, b, c`.
    pub fn new(a: &Point, b: &Point, c: &Point, d: &Point) -> InCircle {
        let v = coordinates([a, b, c, d]);
        // proof: B26 (inputs: nonzero coordinates in [2^-190, 2^248])
        let approx = filter::inputs_in_range(&v, -190, 248);
        InCircle { v, approx }
    }

    /// The exact determinant.
    pub fn exact_value(&self) -> Rational {
        incircle_value(&self.v)
    }

    /// The filter's error bound `next_up(16u·P̃)` (proofs/B26), `None` when a coordinate is
    /// outside the filter's input window.
    #[doc(hidden)]
    pub fn filter_bound(&self) -> Option<f64> {
        let [ax, ay, bx, by, cx, cy, dx, dy] = self.approx?.map(f64::abs);
        // Majorant with Σ = |·| + |d·| per coordinate, proofs/B26.
        let (sax, say, sbx, sby, scx, scy) = (ax + dx, ay + dy, bx + dx, by + dy, cx + dx, cy + dy);
        let p = (sax * sax + say * say) * (sbx * scy + scx * sby)
            + (sbx * sbx + sby * sby) * (scx * say + sax * scy)
            + (scx * scx + scy * scy) * (sax * sby + sbx * say);
        Some(filter::next_up(INCIRCLE_FILTER * p))
    }

    /// The filter with its bound multiplied by `factor` (see [`Orient2d::filter_scaled`]).
    #[doc(hidden)]
    pub fn filter_scaled(&self, factor: f64) -> Option<Sign> {
        let value = incircle_value(&self.approx?);
        filter::decide(value, self.filter_bound()? * factor)
    }
}

impl SignPredicate for InCircle {
    fn filter(&self) -> Option<Sign> {
        // proof: B26
        self.filter_scaled(1.0)
    }
    fn enclosure_sign(&self, prec: Precision) -> Option<Sign> {
        filter::sign_of(&incircle_value(&filter::enclose(&self.v, prec)))
    }
    fn exact_sign(&self) -> Option<Sign> {
        Some(Sign::of_ordering(self.exact_value().cmp0()))
    }
}

/// Certified sign of [`Orient2d`] for `a, b, c`.
pub fn orient2d(a: &Point, b: &Point, c: &Point, ladder: &Ladder) -> Certified<Sign> {
    decide(&Orient2d::new(a, b, c), ladder)
}

/// Certified sign of [`InCircle`] for `a, b, c, d`.
pub fn incircle(a: &Point, b: &Point, c: &Point, d: &Point, ladder: &Ladder) -> Certified<Sign> {
    decide(&InCircle::new(a, b, c, d), ladder)
}
