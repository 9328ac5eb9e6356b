//! T08: the lengths of a circle pattern (notes Eq. 9,
//! `ℓ_ij² = r_i² + r_j² + 2 r_i r_j cos Φ_ij`) satisfy the strict triangle inequalities in
//! every face when every `Φ ∈ [0, π/2]` (notes §1.4.2; proofs/T08).
//!
//! Each face is decided from its squared lengths: exactly (the ladder of
//! [`strict_triangle_sq`]) when the radii are rational and every `cos Φ` is rational
//! ([`cos_pi_exact`]), otherwise by the sign of an MPFR interval enclosure of
//! `16·Area² = 2(AB + BC + CA) − (A² + B² + C²)` (proofs/B20).

use super::{Settings, Verdict, Witness};
use crate::circles::metric::{cos_pi, cos_pi_exact};
use crate::mesh::Mesh;
use crate::predicates::triangle::strict_triangle_sq;
use crate::scalar::{Certified, Interval, Mpfr, Precision, Real, Sign, Stage};
use rug::Rational;

type I = Interval<Mpfr>;

/// Whether each face of `mesh` is a non-degenerate triangle for the pattern lengths of
/// radii `r` (per vertex) and angles `Φ_e = phi[e]·π` (any `Φ`, also outside `[0, π/2]`):
/// certified `true`/`false` per face, or undecided. `bits` is the MPFR precision of the
/// enclosures used for irrational `cos Φ`.
pub fn face_triangle_signs(
    mesh: &Mesh,
    r: &[Rational],
    phi: &[Rational],
    bits: u32,
    s: &Settings,
) -> Vec<Certified<bool>> {
    let prec = Precision::new(u64::from(bits.max(53))).ok();
    let cos_exact: Vec<Option<Rational>> = phi.iter().map(cos_pi_exact).collect();
    // One enclosure of `cos Φ` per distinct angle (the same function of the same input:
    // the same enclosure), not one per face side.
    let mut cos_memo: std::collections::HashMap<&Rational, I> = std::collections::HashMap::new();
    let mut count = s.progress.counter("faces", mesh.n_faces());
    let signs = mesh
        .faces()
        .map(|f| {
            count.add(1);
            let hs = mesh.face_halfedges(f);
            let ends = hs.map(|h| (mesh.tail(h).idx(), mesh.tip(h).idx(), h.edge().idx()));
            if ends.iter().all(|&(_, _, e)| cos_exact[e].is_some()) {
                let sq = ends.map(|(i, j, e)| {
                    let c = cos_exact[e].clone().unwrap_or_default();
                    Rational::from(&r[i] * &r[i])
                        + Rational::from(&r[j] * &r[j])
                        + Rational::from(&r[i] * &r[j]) * c * 2u32
                });
                return strict_triangle_sq(&sq[0], &sq[1], &sq[2], &s.ladder);
            }
            let Some(prec) = prec else {
                return Certified::Undecided { bits_tried: 0 };
            };
            let sq = ends.map(|(i, j, e)| {
                let (ri, rj) = (I::from_rational(&r[i], prec), I::from_rational(&r[j], prec));
                let c: I = cos_memo
                    .entry(&phi[e])
                    .or_insert_with(|| cos_pi(&phi[e], prec))
                    .clone();
                ri.clone() * &ri + &(rj.clone() * &rj) + &(ri * &rj * &c * &I::from_f64(2.0, prec))
            });
            let [a, b, c] = &sq;
            let two = I::from_f64(2.0, prec);
            let area16 = (a.clone() * b + &(b.clone() * c) + &(c.clone() * a)) * &two
                - &(a.clone() * a + &(b.clone() * b) + &(c.clone() * c));
            let positive = [a, b, c, &area16].map(I::sign);
            if positive.iter().all(|x| *x == Some(Sign::Positive)) {
                Certified::Known {
                    value: true,
                    stage: Stage::Interval { bits },
                }
            } else if positive
                .iter()
                .any(|x| matches!(x, Some(Sign::Negative | Sign::Zero)))
            {
                Certified::Known {
                    value: false,
                    stage: Stage::Interval { bits },
                }
            } else {
                Certified::Undecided { bits_tried: bits }
            }
        })
        .collect();
    count.finish();
    signs
}

/// The verdict of [`face_triangle_signs`]: `Fails` (certified) listing every face proved
/// not to be a strict triangle, `Undecided` listing the faces left open.
pub fn verify_faces(mesh: &Mesh, signs: &[Certified<bool>], bits: u32) -> Verdict {
    let mut fails = Vec::new();
    let mut open = Vec::new();
    for (f, sign) in mesh.faces().zip(signs) {
        match sign {
            Certified::Known { value: true, .. } => {}
            Certified::Known { value: false, .. } => fails.push(Witness {
                element: format!("f{}", f.idx()),
                detail: "pattern lengths violate a strict triangle inequality".into(),
                value: 0.0,
            }),
            Certified::Undecided { .. } => open.push(Witness {
                element: format!("f{}", f.idx()),
                detail: "triangle inequality not decided".into(),
                value: f64::NAN,
            }),
        }
    }
    Verdict::certified(fails, open, bits)
}

/// T08 on one pattern: `NotApplicable` unless every radius is positive and every
/// `Φ ∈ [0, π/2]`; otherwise [`verify_faces`] of [`face_triangle_signs`].
pub fn check_circle_pattern_lengths(
    mesh: &Mesh,
    r: &[Rational],
    phi: &[Rational],
    bits: u32,
    s: &Settings,
) -> Verdict {
    if r.len() != mesh.n_vertices() || phi.len() != mesh.n_edges() {
        return Verdict::NotApplicable {
            reason: "one radius per vertex and one angle per edge are needed".into(),
        };
    }
    if let Some(v) = r.iter().position(|x| *x <= 0) {
        return Verdict::NotApplicable {
            reason: format!("v{v}: radius not positive"),
        };
    }
    let half = Rational::from((1, 2));
    if let Some(e) = phi.iter().position(|q| *q < 0 || *q > half) {
        return Verdict::NotApplicable {
            reason: format!("e{e}: Φ outside [0, π/2], where T08 says nothing"),
        };
    }
    verify_faces(mesh, &face_triangle_signs(mesh, r, phi, bits, s), bits)
}

/// The radii `r_v = 1 + ((5v + 2) mod 7)/4` and angles `Φ_e = ((3e + 1) mod 5)/8 · π`
/// (both in their ranges, irregular, exact) used by the registry entry of T08.
pub fn fixed_pattern(mesh: &Mesh) -> (Vec<Rational>, Vec<Rational>) {
    let r = (0..mesh.n_vertices())
        .map(|v| Rational::from((4 + ((5 * v + 2) % 7) as i64, 4)))
        .collect();
    let phi = (0..mesh.n_edges())
        .map(|e| Rational::from((((3 * e + 1) % 5) as i64, 8)))
        .collect();
    (r, phi)
}
