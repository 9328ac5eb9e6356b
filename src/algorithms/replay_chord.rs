//! Chordal flips (proof: B106): on a surface given by exact vertex positions, an edge is
//! *chordal* when its length is the straight distance `|p_u − p_v|` of its ends. Every
//! input edge is. A Euclidean flip of a hinge whose five edges are chordal and whose four
//! corners lie in one plane, the two opposite corners on opposite sides of the hinge's
//! edge, has the chord `|p_k − p_l|` as its new length: the unfolded hinge *is* the planar
//! quadrilateral. The new length is then the square root of an exact rational, and a tie
//! on a planar region of a CAD part or a mirror-symmetric scan is decided exactly
//! (B63 on rational squares) instead of staying undecided at every precision.
//!
//! ```
//! use penner::algorithms::replay_chord::planar_chord;
//! use rug::Rational;
//! let p = |x: i32, y: i32, z: i32| [Rational::from(x), Rational::from(y), Rational::from(z)];
//! // The kite (0,0,0), (4,0,0) | (2,1,0) above, (2,−1,0) below: the new diagonal is 2.
//! let (i, j, k, l) = (p(0, 0, 0), p(4, 0, 0), p(2, 1, 0), p(2, -1, 0));
//! assert_eq!(planar_chord([&i, &j, &k, &l]), Some(Rational::from(4)));
//! // Lift l out of the plane: the unfolded distance is no longer the chord.
//! let l_up = p(2, -1, 1);
//! assert_eq!(planar_chord([&i, &j, &k, &l_up]), None);
//! ```

use crate::geometry::exact3d::{opposite_in_plane, squared_distance};
use rug::Rational;

/// A point of ℝ³ with exact rational coordinates.
pub type Point = [Rational; 3];

/// The squared new length `|p_k − p_l|²` of the Euclidean flip of the hinge `i j | k l`
/// (triangles `ijk` and `jil`), given the corners' positions `[p_i, p_j, p_k, p_l]`, when
/// the four points are coplanar and `p_k`, `p_l` lie strictly on opposite sides of the
/// line `p_i p_j` ([`opposite_in_plane`], exact; proof: B106). Valid only when the five
/// lengths of the hinge are chordal; `None` otherwise (the caller then encloses the
/// unfolded distance).
pub fn planar_chord(p: [&Point; 4]) -> Option<Rational> {
    let [i, j, k, l] = p;
    opposite_in_plane(i, j, k, l).then(|| squared_distance(k, l))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algorithms::flips::euclidean_length_enclosure;
    use crate::predicates::delaunay::Quad;
    use crate::scalar::{Interval, Mpfr, Precision, Real};

    fn p(x: i64, y: i64, z: i64) -> Point {
        [Rational::from(x), Rational::from(y), Rational::from(z)]
    }

    /// The unfolded distance of the hinge with the five chordal lengths, by the flip's own
    /// interval formula at 300 bits (an independent computation of the same length).
    fn unfolded(pts: [&Point; 4]) -> Interval<Mpfr> {
        let prec = Precision::new(300).expect("bits");
        let [i, j, k, l] = pts;
        let len = |a: &Point, b: &Point| {
            crate::predicates::directed::valid(
                Interval::<Mpfr>::from_rational(&squared_distance(a, b), prec).sqrt(),
            )
            .expect("positive")
        };
        let q = Quad {
            ij: len(i, j),
            jk: len(j, k),
            ki: len(k, i),
            il: len(i, l),
            lj: len(l, j),
        };
        euclidean_length_enclosure(q.as_refs()).expect("a convex hinge")
    }

    /// proof: B106 — on planar hinges in general position in ℝ³ (a tilted plane, rational
    /// points), the chord's square lies in the square of the unfolded distance computed by
    /// the flip formula from the five chordal lengths.
    #[test]
    fn b106_the_chord_of_a_planar_hinge_is_its_unfolded_distance() {
        // The plane spanned by u = (1, 2, 3), v = (−2, 1, 1/2) through o = (5, −1, 7).
        let (u, v, o) = ([1, 2, 3], [-4, 2, 1], [5, -1, 7]);
        let at = |s: i64, t: i64| {
            [0, 1, 2].map(|c| Rational::from(o[c] * 2 + s * u[c] * 2 + t * v[c]) / 2)
        };
        for (i, j, k, l) in [
            ((0, 0), (6, 0), (2, 3), (3, -4)),
            ((0, 0), (5, 1), (1, 7), (4, -3)),
            ((-1, 2), (7, 3), (3, 9), (2, -5)),
        ] {
            let pts = [at(i.0, i.1), at(j.0, j.1), at(k.0, k.1), at(l.0, l.1)];
            let refs = [&pts[0], &pts[1], &pts[2], &pts[3]];
            let s = planar_chord(refs).expect("planar, opposite sides");
            let x = unfolded(refs);
            let sq = x.clone() * x;
            let prec = Precision::new(300).expect("bits");
            let exact = Interval::<Mpfr>::from_rational(&s, prec);
            assert!(
                sq.lo().0 <= exact.hi().0 && exact.lo().0 <= sq.hi().0,
                "chord² {s} outside the unfolded enclosure"
            );
        }
    }

    /// Controls of B106's hypotheses: a corner lifted out of the plane, both opposite
    /// corners on the same side, and a degenerate hinge each give no chord; and the lifted
    /// hinge's unfolded distance really differs from its chord.
    #[test]
    fn b106_non_planar_same_side_and_degenerate_hinges_have_no_chord() {
        let (i, j, k) = (p(0, 0, 0), p(4, 0, 0), p(2, 1, 0));
        let lifted = p(2, -1, 1);
        assert_eq!(planar_chord([&i, &j, &k, &lifted]), None);
        let x = unfolded([&i, &j, &k, &lifted]);
        let prec = Precision::new(300).expect("bits");
        let chord = Interval::<Mpfr>::from_rational(&squared_distance(&k, &lifted), prec);
        let sq = x.clone() * x;
        assert!(
            sq.lo().0 > chord.hi().0 || sq.hi().0 < chord.lo().0,
            "the control must separate"
        );
        assert_eq!(planar_chord([&i, &j, &k, &p(3, 2, 0)]), None);
        assert_eq!(planar_chord([&i, &j, &k, &p(8, 0, 0)]), None);
        assert_eq!(planar_chord([&i, &i, &k, &p(2, -1, 0)]), None);
    }
}
