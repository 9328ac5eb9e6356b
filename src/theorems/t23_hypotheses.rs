//! The certified hypotheses of T23 on enclosures, on any interval bound: a face's strict
//! triangle inequality, the tangent of a half corner angle, and the hypotheses of T23's
//! planar lemma for one flip. Shared by [`super::t23_euclidean_flip_cone_metric`] and its
//! `f64` first rung [`super::t23_first_rung`].

use crate::predicates::delaunay::Quad;
use crate::predicates::directed::{div_positive, strictly_below, valid};
use crate::scalar::{Interval, IntervalBound, Real};

/// The enclosure of `tan(α/2) = √((a−b+c)(a+b−c) / ((a+b+c)(−a+b+c)))` for the corner
/// opposite `a` ([`corner_angle_enclosure`](super::t23_euclidean_flip_cone_metric::corner_angle_enclosure)
/// before its `atan`), on any interval bound:
/// `None` when the denominator is not certified positive or the radicand may be negative.
pub(crate) fn half_angle_tangent<B: IntervalBound>(
    a: &Interval<B>,
    b: &Interval<B>,
    c: &Interval<B>,
) -> Option<Interval<B>> {
    let num = (a.clone() - b + c) * &(a.clone() + b - c);
    let den = (a.clone() + b + c) * &(b.clone() + c - a);
    valid(div_positive(&num, &den)?.sqrt())
}

/// Whether the side enclosures `a, b, c` of a face are certified to satisfy the strict
/// triangle inequality: `y + z − x` certified positive for `(x, y, z)` = `(a, b, c)`,
/// `(b, c, a)`, `(c, a, b)`, on any interval bound.
pub(crate) fn face_certified<B: IntervalBound>(
    a: &Interval<B>,
    b: &Interval<B>,
    c: &Interval<B>,
) -> bool {
    let zero = a.zero_like();
    [(a, b, c), (b, c, a), (c, a, b)]
        .iter()
        .all(|&(x, y, z)| strictly_below(&zero, &(y.clone() + z - x)))
}

/// Whether the hypotheses of T23's planar lemma are certified on enclosures `q` of the
/// exact lengths `a = ℓ_ij, b = ℓ_jk, c = ℓ_ki, d = ℓ_il, e = ℓ_lj` of the quadrilateral of
/// a flip (proof: T23, Lemma): the triangles `(a, b, c)` and `(a, d, e)` strictly satisfy
/// the triangle inequality (`−a+b+c`, `a−b+c`, `a+b−c` and the same with `d, e` certified
/// positive), and the quadrilateral is strictly convex at `i` and `j`:
///
/// ```text
/// Q_i = d(a² + c² − b²) + c(a² + d² − e²) > 0   ⇔ α_i^{ijk} + α_i^{jil} < π,
/// Q_j = e(a² + b² − c²) + b(a² + e² − d²) > 0   ⇔ α_j^{ijk} + α_j^{jil} < π,
/// ```
///
/// (`Q_i = 2acd (cos α_i^{ijk} + cos α_i^{jil})`, law of cosines). Every sign is read from
/// an outward-rounded enclosure (proof: B20), so `true` proves the hypotheses for the exact
/// lengths; `false` means they could not be certified (or fail).
pub fn flip_hypotheses_certified<B: IntervalBound>(q: Quad<&Interval<B>>) -> bool {
    let zero = q.ij.zero_like();
    let positive = |x: &Interval<B>| strictly_below(&zero, x);
    let strict_triangle = |a: &Interval<B>, b: &Interval<B>, c: &Interval<B>| {
        positive(&(b.clone() + c - a))
            && positive(&(a.clone() - b + c))
            && positive(&(a.clone() + b - c))
    };
    let (a, b, c, d, e) = (q.ij, q.jk, q.ki, q.il, q.lj);
    let sq = |x: &Interval<B>| x.clone() * x;
    let q_i = d.clone() * &(sq(a) + &sq(c) - &sq(b)) + &(c.clone() * &(sq(a) + &sq(d) - &sq(e)));
    let q_j = e.clone() * &(sq(a) + &sq(b) - &sq(c)) + &(b.clone() * &(sq(a) + &sq(e) - &sq(d)));
    strict_triangle(a, b, c) && strict_triangle(a, d, e) && positive(&q_i) && positive(&q_j)
}
