//! T05, semidefiniteness of `−L` (notes §1.3.4: `fᵀ(−L)f = 2E_D(f) ≥ 0`), in time linear in
//! the mesh (proofs/B51):
//!
//! 1. **Nonnegative weights.** When every off-diagonal entry of `L` is `≥ 0` (decided
//!    exactly on the stored values), `−L = G + diag(r)` with `G` the graph Laplacian of
//!    nonnegative weights — positive semidefinite exactly — and `r` the row sums, which the
//!    zero-row-sum comparison already bounds: `−L` is within its rounding of a semidefinite
//!    matrix. Delaunay metrics take this path.
//! 2. **Per face.** `−L = Σ_f K_f`, where `K_f` is the 3×3 weighted graph Laplacian of face
//!    `f` with weights `½ cot` of its angles. A 3×3 weighted graph Laplacian is semidefinite
//!    iff `σ₁ = Σ c_i ≥ 0` and `σ₂ = Σ_{i<j} c_i c_j ≥ 0` (its nonzero eigenvalues are the roots
//!    of `λ² − σ₁λ + ¾σ₂`, up to the factor ½). For a Euclidean triangle `σ₂ = 1` identically
//!    (`α + β + γ = π`) and `σ₁ = (a² + b² + c²)/(4A) > 0`. The check compares the computed
//!    `σ₂` with 1 and `σ₁` with 0 within their B44 error bounds.
//! 3. **A claimed matrix** with a negative weight and no faces to decompose: the grounded
//!    LDLᵀ of [`super::t05_cotan_laplacian::verify_laplacian`] (bounded size); a negative
//!    pivot is a refutation only when the vector it defines has a negative quadratic form,
//!    evaluated exactly, below the matrix's own rounding allowance.

use super::bounds::{cot_error, eps, sum_error, SAFETY};
use super::report::Tally;
use super::verdict::Settings;
use crate::geometry::cotan::halfedge_cotans;
use crate::geometry::laplacian::SparseMatrix;
use crate::mesh::Mesh;
use crate::predicates::tolerance::sign_exact;
use crate::scalar::{Real, Sign};

/// Whether every off-diagonal entry of `lap` is `≥ 0`, decided exactly on the stored values
/// (`None` when an entry is not finite).
pub fn nonnegative_weights<T: Real>(lap: &SparseMatrix<T>) -> Option<bool> {
    for (i, j, v) in lap.entries() {
        if i != j && sign_exact(v)? == Sign::Negative {
            return Some(false);
        }
    }
    Some(true)
}

/// B51, per face: for every face `f` with cotangents `c₁, c₂, c₃` (by
/// [`halfedge_cotans`]), `|σ̂₂ − 1| ≤ τ₂` and `σ̂₁ > τ₁` (witness `f…`), with the B44 bounds
/// `Δc_i` of the cotangents,
/// `τ₂ = 2Σ_{i<j}(|c_i|Δc_j + |c_j|Δc_i + ε|c_i c_j|) + B41(c_i c_j, 1)` and
/// `τ₁ = Σ Δc_i + B41(c_i)`. Then `−L = Σ_f K_f` is a sum of semidefinite forms.
pub fn faces_semidefinite<T: Real>(
    mesh: &Mesh,
    lengths: &[T],
    settings: &Settings,
    tally: &mut Tally,
) {
    let Some(l0) = lengths.first() else { return };
    let e = eps::<T>(l0.ctx());
    let cots = halfedge_cotans(mesh, lengths);
    let lf = |h: crate::mesh::HalfEdge| lengths[h.edge().idx()].approx_f64();
    let one = l0.one_like();
    for f in mesh.faces() {
        let hs = mesh.face_halfedges(f);
        let c: [&T; 3] = [&cots[hs[0].idx()], &cots[hs[1].idx()], &cots[hs[2].idx()]];
        let cf = c.map(Real::approx_f64);
        let dc: [f64; 3] = [0, 1, 2].map(|k| {
            let h = hs[k];
            cot_error(lf(h), lf(mesh.next(h)), lf(mesh.prev(h)), e)
        });
        let mut sigma2 = one.zero_like();
        let mut products = Vec::with_capacity(4);
        let mut tau2 = 0.0;
        for (i, j) in [(0, 1), (1, 2), (2, 0)] {
            let p = c[i].clone() * c[j];
            products.push(p.approx_f64());
            tau2 += cf[i].abs() * dc[j] + cf[j].abs() * dc[i] + e * (cf[i] * cf[j]).abs();
            sigma2 += &p;
        }
        products.push(1.0);
        let tau2 = settings.slack * (SAFETY * tau2 + sum_error(products, e));
        tally.within(
            f.to_string(),
            "cot α cot β + cot β cot γ + cot γ cot α − 1",
            &(sigma2 - &one),
            tau2,
        );
        let sigma1 = c[0].clone() + c[1] + c[2];
        let tau1 = settings.slack * (dc.iter().sum::<f64>() + sum_error(cf, e));
        tally.positive(f.to_string(), "cot α + cot β + cot γ", &sigma1, tau1);
    }
}
