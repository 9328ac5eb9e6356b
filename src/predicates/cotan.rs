//! Certified sign of a cotan weight `w_ij = ½(cot α_k + cot α_l)` from squared lengths.

use super::filter::{self, Ring};
use super::ladder::{decide, Ladder, SignPredicate};
use crate::mesh::{Edge, Mesh};
use crate::scalar::{Certified, Precision, Real, Sign};
use rug::Rational;

/// `16·Area²` of a triangle from its squared sides:
/// `P = 2(a²b² + b²c² + c²a²) − a⁴ − b⁴ − c⁴` (Heron, docs/catalogue.md §1), in any ring (exact in ℚ,
/// an enclosure on intervals).
fn heron16<T: Ring>(a2: &T, b2: &T, c2: &T) -> T {
    let s = a2.clone() * b2 + &(b2.clone() * c2) + &(c2.clone() * a2);
    let sq = a2.clone() * a2 + &(b2.clone() * b2) + &(c2.clone() * c2);
    s.clone() + &s - &sq
}

/// `N = b² + c² − a²` and `P = 16·Area²` of a triangle `[a², b², c²]`.
fn np<T: Ring>(t: &[T; 3]) -> (T, T) {
    let n = t[1].clone() + &t[2] - &t[0];
    let p = heron16(&t[0], &t[1], &t[2]);
    (n, p)
}

/// The sign of `cot α_k + cot α_l` for interior edge `ij` between triangles with squared
/// sides `(ℓ_ij², ℓ_jk², ℓ_ki²)` and `(ℓ_ij², ℓ_il², ℓ_lj²)`.
///
/// With `N = b² + c² − a²` and `P = 16·Area²` (so `cot = N / √P`), the sign of
/// `N_1/√P_1 + N_2/√P_2` is that of `N_1 √P_2 + N_2 √P_1`: the common sign of `N_1, N_2` when
/// they agree, else the sign of `N_1² P_2 − N_2² P_1` times the sign of the larger term's `N`
/// (proofs/B49). Everything is a polynomial in the squared lengths, so the exact rung
/// decides in ℚ. The interval rung encloses `N_1 √P_2 + N_2 √P_1` directly with outward
/// rounding (once both `P` are certainly positive); a cocircular pair (value 0) is decided
/// there only when the enclosure is the point 0, otherwise it goes on to ℚ.
#[derive(Clone, Debug, PartialEq)]
pub struct CotanWeightSign {
    /// Squared sides `[ij, jk, ki]` of the first triangle.
    pub first: [Rational; 3],
    /// Squared sides `[ij, il, lj]` of the second triangle (same `ij`).
    pub second: [Rational; 3],
}

impl CotanWeightSign {
    /// The exact sign, or `None` when a triangle is degenerate or violates the triangle
    /// inequality (`P ≤ 0`), where the cotangent is undefined.
    pub fn sign_exact(&self) -> Option<Sign> {
        let (n1, p1) = np(&self.first);
        let (n2, p2) = np(&self.second);
        if p1.cmp0().is_le() || p2.cmp0().is_le() {
            return None;
        }
        let s1 = Sign::of_ordering(n1.cmp0());
        let s2 = Sign::of_ordering(n2.cmp0());
        if s1 == s2 || s2 == Sign::Zero {
            return Some(s1);
        }
        if s1 == Sign::Zero {
            return Some(s2);
        }
        // Opposite signs: compare magnitudes |N_1|√P_2 vs |N_2|√P_1 by their squares.
        let t1 = Rational::from(&n1 * &n1) * &p2;
        let t2 = Rational::from(&n2 * &n2) * &p1;
        Some(match t1.cmp(&t2) {
            std::cmp::Ordering::Greater => s1,
            std::cmp::Ordering::Less => s2,
            std::cmp::Ordering::Equal => Sign::Zero,
        })
    }
}

impl SignPredicate for CotanWeightSign {
    fn enclosure_sign(&self, prec: Precision) -> Option<Sign> {
        // proof: B49 (interval rung)
        let (n1, p1) = np(&filter::enclose(&self.first, prec));
        let (n2, p2) = np(&filter::enclose(&self.second, prec));
        if p1.sign() != Some(Sign::Positive) || p2.sign() != Some(Sign::Positive) {
            return None;
        }
        let w = n1 * &p2.sqrt() + &(n2 * &p1.sqrt());
        filter::sign_of(&w)
    }
    fn exact_sign(&self) -> Option<Sign> {
        self.sign_exact()
    }
}

/// The certified sign of the cotan weight `w_e` of every interior edge from rational
/// squared lengths `sq[e] = ℓ_e²` (docs/catalogue.md §3), decided on the ladder; `None` on boundary
/// edges. A weight whose triangles are degenerate is `Undecided`.
pub fn cotan_weight_signs(
    mesh: &Mesh,
    sq: &[Rational],
    ladder: &Ladder,
) -> Vec<Option<Certified<Sign>>> {
    mesh.edges()
        .map(|e: Edge| {
            if mesh.is_boundary_edge(e) {
                return None;
            }
            let h = e.side(0);
            let t = h.twin();
            let l = |g: crate::mesh::HalfEdge| sq[g.edge().idx()].clone();
            let p = CotanWeightSign {
                first: [l(h), l(mesh.next(h)), l(mesh.prev(h))],
                second: [l(t), l(mesh.next(t)), l(mesh.prev(t))],
            };
            Some(decide(&p, ladder))
        })
        .collect()
}
