//! The Delaunay predicate and the triangle inequality on lengths kept with their exponent
//! apart ([`ExpLength`], `ℓ = m·2ᵏ`), for conformally scaled metrics far beyond binary64's
//! range.
//!
//! Each quadrilateral is shifted by its largest exponent `E`: the images `m·2^{k−E}` lie in
//! `(0, 1)`, exactly while they are normal, and `P` (homogeneous of degree 4) is multiplied
//! by `2^{−4E} > 0`, so its sign is unchanged (proof: B67). The rungs are then those of
//! [`crate::predicates::delaunay`]: the f64 filter on the images when they lie in
//! `[2⁻²⁰⁰, 1)` (B61), MPFR enclosures and exact rationals of the shifted values otherwise.
//!
//! ```
//! use penner::predicates::delaunay::Quad;
//! use penner::predicates::delaunay_exp::ExpQuad;
//! use penner::predicates::ladder::{decide, Ladder};
//! use penner::scalar::exp_length::ExpLength;
//! use penner::scalar::Sign;
//! // A thin rhombus (long diagonal 1.9, sides 1) scaled by e^{700} at every vertex.
//! let s = |x: f64| ExpLength::scaled(x, 700.0, 700.0).unwrap();
//! let q = Quad { ij: s(1.9), jk: s(1.0), ki: s(1.0), il: s(1.0), lj: s(1.0) };
//! assert_eq!(decide(&ExpQuad(q.as_refs()), &Ladder::default()).value(), Some(Sign::Negative));
//! ```

use super::delaunay::{enclose_p, exact_p, filter_f64_in_range, in_filter_range, Quad};
use super::ladder::{Ladder, SignPredicate};
use super::triangle::{strict_triangle, strict_triangle_f64};
use crate::scalar::exp_length::ExpLength;
use crate::scalar::{Certified, Interval, Precision, Sign, Stage};

/// The largest exponent of the five lengths.
#[inline]
fn top_exponent(q: &Quad<&ExpLength>) -> i32 {
    q.to_array().iter().map(|l| l.exponent()).max().unwrap_or(0)
}

/// The Delaunay predicate `P ≥ 0` on five exponent-apart lengths `[ij, jk, ki, il, lj]`.
#[derive(Clone, Copy, Debug)]
pub struct ExpQuad<'a>(pub Quad<&'a ExpLength>);

impl ExpQuad<'_> {
    /// The shifted images `m·2^{k−E}`, when all lie in the filter's range (then they are
    /// the exact shifted values).
    #[inline]
    pub fn shifted_f64(&self) -> Option<[f64; 5]> {
        let e = top_exponent(&self.0);
        let s = self.0.to_array().map(|l| l.shifted(e));
        s.iter().all(|&x| in_filter_range(x)).then_some(s)
    }
}

impl SignPredicate for ExpQuad<'_> {
    #[inline]
    fn filter(&self) -> Option<Sign> {
        // proof: B67 (exact shift), B61 (the filter on the images).
        filter_f64_in_range(self.shifted_f64()?)
    }
    fn enclosure_sign(&self, prec: Precision) -> Option<Sign> {
        let e = top_exponent(&self.0);
        let ins = self
            .0
            .to_array()
            .map(|l| Interval::<crate::scalar::Mpfr>::from_rational(&l.shifted_rational(e), prec));
        enclose_p(&ins).sign()
    }
    fn exact_sign(&self) -> Option<Sign> {
        let e = top_exponent(&self.0);
        let [a, b, c, d, f] = self.0.to_array().map(|l| l.shifted_rational(e));
        Some(Sign::of_ordering(exact_p([&a, &b, &c, &d, &f]).cmp0()))
    }
}

/// Whether three exponent-apart lengths are the sides of a non-degenerate triangle,
/// certified: on the shifted binary64 images by monotone rounding when they are normal
/// (B66, B67), otherwise on the exact shifted rationals through the ladder.
pub fn strict_triangle_exp(sides: [&ExpLength; 3], ladder: &Ladder) -> Certified<bool> {
    let e = sides.iter().map(|l| l.exponent()).max().unwrap_or(0);
    let [a, b, c] = sides.map(|l| l.shifted(e));
    if a.is_normal() && b.is_normal() && c.is_normal() && strict_triangle_f64(a, b, c) {
        return Certified::Known {
            value: true,
            stage: Stage::Filter,
        };
    }
    let [a, b, c] = sides.map(|l| l.shifted_rational(e));
    strict_triangle(&a, &b, &c, ladder)
}
