//! Discrete conformal scaling (notes Eq. 10), Lemma 1 scale factors (Eq. 11) and the
//! reconstruction of scale factors from two metrics with equal cross ratios (Theorem 8).

use crate::mesh::{HalfEdge, Mesh};
use crate::scalar::{Field, Real};
use rug::Rational;

/// Conformal scaling `ℓ̃_ij = e^{(u_i+u_j)/2} ℓ_ij` (notes Eq. 10, docs/catalogue.md §4) with
/// per-vertex log scale factors `u`.
///
/// ```
/// use penner::geometry::scaling::conformal_scaling;
/// use penner::mesh::Mesh;
/// let tri = Mesh::from_faces(3, &[[0, 1, 2]]).unwrap();
/// let l = conformal_scaling(&tri, &[1.0_f64; 3], &[2.0_f64.ln() * 2.0; 3]);
/// assert!(l.iter().all(|x| (x - 4.0).abs() < 1e-14));
/// ```
pub fn conformal_scaling<T: Real>(mesh: &Mesh, lengths: &[T], u: &[T]) -> Vec<T> {
    mesh.edges()
        .map(|e| {
            let h = e.halfedge();
            let (i, j) = (mesh.tail(h).idx(), mesh.tip(h).idx());
            let half = u[i].lit(0.5);
            ((u[i].clone() + &u[j]) * &half).exp() * &lengths[e.idx()]
        })
        .collect()
}

/// Exact conformal scaling in ℚ: `ℓ̃_ij = s_i s_j ℓ_ij` with rational `s_i = e^{u_i/2}`
/// (docs/catalogue.md §4, "Exact arithmetic").
///
/// ```
/// use penner::geometry::scaling::conformal_scaling_exact;
/// use penner::mesh::Mesh;
/// use rug::Rational;
/// let tri = Mesh::from_faces(3, &[[0, 1, 2]]).unwrap();
/// let s = [Rational::from(2), Rational::from(3), Rational::from((1, 2))];
/// let l = conformal_scaling_exact(&tri, &[Rational::from(1), Rational::from(1), Rational::from(1)], &s);
/// let mut got: Vec<Rational> = l.clone();
/// got.sort();
/// assert_eq!(got, vec![Rational::from(1), Rational::from((3, 2)), Rational::from(6)]);
/// ```
pub fn conformal_scaling_exact(mesh: &Mesh, lengths: &[Rational], s: &[Rational]) -> Vec<Rational> {
    mesh.edges()
        .map(|e| {
            let h = e.halfedge();
            let (i, j) = (mesh.tail(h).idx(), mesh.tip(h).idx());
            Rational::from(&s[i] * &s[j]) * &lengths[e.idx()]
        })
        .collect()
}

/// Lemma 1 (notes Eq. 11): for one triangle `ijk` with lengths `ℓ` and `ℓ̃`, the scale factor
/// at `i` is `e^{u_i} = (ℓ̃_ij/ℓ_ij)(ℓ_jk/ℓ̃_jk)(ℓ̃_ki/ℓ_ki)`. Arguments are `[ij, jk, ki]`.
///
/// ```
/// use penner::geometry::scaling::lemma1_exp_u;
/// // ℓ̃ = 3ℓ everywhere: e^u = 3 at every corner.
/// let e = lemma1_exp_u(&[3.0_f64, 4.0, 5.0], &[9.0, 12.0, 15.0]);
/// assert!((e - 3.0).abs() < 1e-15);
/// ```
pub fn lemma1_exp_u<T: Field>(l: &[T; 3], lt: &[T; 3]) -> T {
    lt[0].clone() / &l[0] * &(l[1].clone() / &lt[1]) * &(lt[2].clone() / &l[2])
}

/// The three lengths `[ij, jk, ki]` of the face of `h = i→j`, read from `lengths`.
fn face_lengths<T: Clone>(mesh: &Mesh, lengths: &[T], h: HalfEdge) -> [T; 3] {
    [h, mesh.next(h), mesh.prev(h)].map(|g| lengths[g.edge().idx()].clone())
}

/// Scale factors reconstructed from two metrics on one triangulation (notes Theorem 8, ⇐).
///
/// Lemma 1 gives, in every face, the unique factors that relate the two metrics on that
/// face. The value at corner `i` of face `ijk` (indexed by the face half-edge `h = i→j`
/// leaving `i`) is [`lemma1_exp_u`]. Factors of neighbouring faces agree at both ends of a
/// shared edge `ij` exactly when `c_ij = c̃_ij` (notes, proof of Theorem 8), so the metrics
/// are conformally equivalent iff all corner values at each vertex coincide. This is the
/// propagation of Lemma 1 across faces done corner by corner: it needs no spanning tree and
/// is independent of the genus.
#[derive(Clone, Debug, PartialEq)]
pub struct Reconstruction<T> {
    /// Per half-edge `h` in a face: `e^{u}` at the corner `tail(h)` of that face; `None` on
    /// boundary half-edges.
    pub corner_exp_u: Vec<Option<T>>,
    /// Per vertex: the half-edge whose corner value represents `e^{u_v}` (the first face
    /// half-edge leaving `v`), or `None` for a vertex without corners.
    pub representative: Vec<Option<HalfEdge>>,
}

impl<T: Clone> Reconstruction<T> {
    /// `e^{u_v}` per vertex from the representative corners (`None` without corners).
    pub fn exp_u(&self) -> Vec<Option<T>> {
        self.representative
            .iter()
            .map(|r| r.and_then(|h| self.corner_exp_u[h.idx()].clone()))
            .collect()
    }
}

impl<T: Real> Reconstruction<T> {
    /// `u_v = ln e^{u_v}` per vertex (`None` without corners).
    pub fn u(&self) -> Vec<Option<T>> {
        self.exp_u()
            .into_iter()
            .map(|x| x.map(|x| x.ln()))
            .collect()
    }
}

/// Reconstruct scale factors from metrics `l`, `lt` on the same mesh by Lemma 1 in every
/// face (see [`Reconstruction`]); any [`Field`], exactly in ℚ for rational lengths.
pub fn reconstruct_scale_factors<T: Field>(mesh: &Mesh, l: &[T], lt: &[T]) -> Reconstruction<T> {
    let corner_exp_u = mesh
        .halfedges()
        .map(|h| {
            (!mesh.is_boundary_halfedge(h))
                .then(|| lemma1_exp_u(&face_lengths(mesh, l, h), &face_lengths(mesh, lt, h)))
        })
        .collect();
    Reconstruction {
        corner_exp_u,
        representative: representatives(mesh),
    }
}

/// Per vertex, the first face half-edge leaving it.
fn representatives(mesh: &Mesh) -> Vec<Option<HalfEdge>> {
    let mut r = vec![None; mesh.n_vertices()];
    for h in mesh.halfedges() {
        if !mesh.is_boundary_halfedge(h) {
            r[mesh.tail(h).idx()].get_or_insert(h);
        }
    }
    r
}
