//! Enclosed corner cotangents from squared lengths and an enclosed area, no
//! trigonometric function: `cot α_i = (l_{i+1}² + l_{i+2}² − l_i²) / (4·Area)` with
//! `4·Area = √(s·e₀·e₁·e₂)` (docs/catalogue.md §1). proof: B34

use super::{Bounds, FaceHeron};
use crate::mesh::Mesh;
use crate::scalar::{Interval, Mpfr, Real};

type I = Interval<Mpfr>;

/// Per half-edge `h`: an enclosure of `cot α` of the corner opposite `h` in its face, for
/// every metric in the length enclosures (one per edge, all at one precision); the point
/// zero on boundary half-edges (no corner), as
/// [`halfedge_cotans`](crate::geometry::cotan::halfedge_cotans). Invalid where the face is
/// not certified a strict triangle (a side or a Heron factor `e_i` not enclosed as
/// positive). Per face: three squares, `16·Area²` and one square root; per corner two
/// additions and one division, each bound by one directed-rounding MPFR operation.
/// proof: B34
///
/// ```
/// use penner::geometry::enclosure::cotans::enclose_halfedge_cotans;
/// use penner::mesh::Mesh;
/// use penner::scalar::{Interval, Mpfr, Precision, Real};
/// let p = Precision::new(128).unwrap();
/// let tri = Mesh::from_faces(3, &[[0, 1, 2]]).unwrap();
/// let l = vec![Interval::point(Mpfr::from_f64(1.0, p)); 3];
/// let cot = enclose_halfedge_cotans(&tri, &l);
/// // cot(π/3) = 1/√3 ≈ 0.57735 on every face half-edge.
/// let face: Vec<_> = cot.iter().filter(|c| c.width_f64() > 0.0).collect();
/// assert_eq!(face.len(), 3);
/// assert!(face.iter().all(|c| (c.approx_f64() - 1.0 / 3f64.sqrt()).abs() < 1e-15));
/// ```
pub fn enclose_halfedge_cotans(mesh: &Mesh, lengths: &[I]) -> Vec<I> {
    assert_eq!(
        lengths.len(),
        mesh.n_edges(),
        "enclose_halfedge_cotans: one length per edge is required"
    );
    let Some(first) = lengths.first() else {
        return Vec::new();
    };
    let bits = first.lo().as_float().prec();
    let mut out = vec![first.zero_like(); mesh.n_halfedges()];
    let mut face = FaceHeron::new(bits);
    let z = Bounds::zero(bits);
    let (mut sq, mut area4, mut t, mut num, mut cot) = (
        [z.clone(), z.clone(), z.clone()],
        z.clone(),
        z.clone(),
        z.clone(),
        z,
    );
    for f in mesh.faces() {
        let hs = mesh.face_halfedges(f);
        let strict = face.load(hs.map(|h| &lengths[h.edge().idx()]));
        if !strict {
            for h in hs {
                out[h.idx()] = I::invalid(first.ctx());
            }
            continue;
        }
        for (q, l) in sq.iter_mut().zip(&face.l) {
            q.mul(l, l);
        }
        area4.sqrt_of(&face.area16_sq);
        for i in 0..3 {
            t.add(&sq[(i + 1) % 3], &sq[(i + 2) % 3]);
            num.sub(&t, &sq[i]);
            cot.div_positive(&num, &area4);
            out[hs[i].idx()] = cot.to_interval();
        }
    }
    out
}
