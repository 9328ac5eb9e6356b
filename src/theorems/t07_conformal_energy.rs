//! T07 — `E_C = E_D − A` for piecewise-linear maps `f: V → ℂ` (notes §1.3.3): the cotan
//! Dirichlet energy minus the signed area of the image equals the Cauchy–Riemann energy
//! `Σ_t ½ Area_t |∂_x f + i ∂_y f|²` computed triangle by triangle.
//!
//! API:
//! - `pub fn check_conformal_energy<T: Real>(mesh: &Mesh, lengths: &[T], f: &[[T; 2]], settings: &Settings) -> Verdict`
//! - `pub fn verify_conformal_energy<T: Real>(terms: &EnergyTerms<T>, settings: &Settings) -> Verdict`

use super::bounds::{corner_angle_error, cot_error, eps, sum_error, EPS_F64, SAFETY};
use super::report::{check_lengths, lengths_out_of_range, Tally};
use super::verdict::{Settings, Verdict};
use crate::geometry::cotan::cotan_weights;
use crate::geometry::energy::{cauchy_riemann_energy, dirichlet_energy, signed_area};
use crate::mesh::Mesh;
use crate::scalar::Real;

/// The two sides of T07 with the error bound of their difference (proofs/B48).
#[derive(Clone, Debug, PartialEq)]
pub struct EnergyTerms<T> {
    /// `E_D(f)` from cotan weights.
    pub dirichlet: T,
    /// Signed area `A(f)` from the boundary.
    pub area: T,
    /// `E_CR(f)`, the Cauchy–Riemann form.
    pub cauchy_riemann: T,
    /// Bound on `|fl(E_D − A − E_CR) − (E_D − A − E_CR)|`.
    pub error_bound: f64,
}

/// T07, numerical: computes [`EnergyTerms`] and runs [`verify_conformal_energy`].
///
/// ```
/// use penner::mesh::Mesh;
/// use penner::theorems::{t07_conformal_energy::check_conformal_energy, Settings};
/// let tri = Mesh::from_faces(3, &[[0, 1, 2]]).unwrap();
/// let f = [[0.0_f64, 0.0], [2.0, 1.0], [-1.0, 3.0]];
/// assert!(check_conformal_energy(&tri, &[1.0_f64; 3], &f, &Settings::default()).holds());
/// ```
pub fn check_conformal_energy<T: Real>(
    mesh: &Mesh,
    lengths: &[T],
    f: &[[T; 2]],
    settings: &Settings,
) -> Verdict {
    if let Some(v) = check_lengths(mesh, lengths).or_else(|| lengths_out_of_range(lengths)) {
        return v;
    }
    if f.len() != mesh.n_vertices() {
        return Verdict::NotApplicable {
            reason: format!("{} map values for {} vertices", f.len(), mesh.n_vertices()),
        };
    }
    let w = cotan_weights(mesh, lengths);
    let (Some(dirichlet), Some(area), Some(cauchy_riemann)) = (
        dirichlet_energy(mesh, &w, f),
        signed_area(mesh, f),
        cauchy_riemann_energy(mesh, lengths, f),
    ) else {
        return Verdict::NotApplicable {
            reason: "empty map".to_string(),
        };
    };
    let terms = EnergyTerms {
        error_bound: energy_error_bound(mesh, lengths, f),
        dirichlet,
        area,
        cauchy_riemann,
    };
    verify_conformal_energy(&terms, settings)
}

/// The comparison of T07: `|E_D − A − E_CR| ≤ slack × error_bound` (witness `surface`).
pub fn verify_conformal_energy<T: Real>(terms: &EnergyTerms<T>, settings: &Settings) -> Verdict {
    let d = terms.dirichlet.clone() - &terms.area - &terms.cauchy_riemann;
    let mut tally = Tally::new(false, T::precision_bits(d.ctx()));
    tally.within(
        "surface",
        "E_D − A − E_CR",
        &d,
        settings.slack * terms.error_bound,
    );
    tally.verdict()
}

/// B48: bound on the rounding error of `E_D − A − E_CR` as computed by
/// [`check_conformal_energy`] (derivation in proofs/B48).
pub fn energy_error_bound<T: Real>(mesh: &Mesh, lengths: &[T], f: &[[T; 2]]) -> f64 {
    let e = eps::<T>(lengths[0].ctx());
    let l: Vec<f64> = lengths.iter().map(Real::approx_f64).collect();
    let fv: Vec<[f64; 2]> = f
        .iter()
        .map(|z| [z[0].approx_f64(), z[1].approx_f64()])
        .collect();
    let lh = |h: crate::mesh::HalfEdge| l[h.edge().idx()];
    // E_D: per edge Δw|d|² + 6ε|w||d|², then the sum.
    let mut ed_terms = Vec::new();
    let mut ed_err = 0.0;
    for edge in mesh.edges() {
        let mut w = 0.0;
        let mut dw = 0.0;
        for h in [edge.side(0), edge.side(1)] {
            if !mesh.is_boundary_halfedge(h) {
                let (a, b, c) = (lh(h), lh(mesh.next(h)), lh(mesh.prev(h)));
                w += 0.5 * (b * b + c * c - a * a) / (4.0 * triangle_area(a, b, c));
                dw += 0.5 * cot_error(a, b, c, e) + e * w.abs();
            }
        }
        let h = edge.halfedge();
        let (i, j) = (mesh.tail(h).idx(), mesh.tip(h).idx());
        let d2 = (fv[j][0] - fv[i][0]).powi(2) + (fv[j][1] - fv[i][1]).powi(2);
        ed_err += 0.5 * (dw * d2 + 6.0 * e * w.abs() * d2);
        ed_terms.push(0.5 * w * d2);
    }
    // A: per boundary edge 2ε(|x_i y_j| + |y_i x_j|), then the sum.
    let mut a_terms = Vec::new();
    for h in mesh.halfedges() {
        if !mesh.is_boundary_halfedge(h) && mesh.is_boundary_halfedge(h.twin()) {
            let (i, j) = (mesh.tail(h).idx(), mesh.tip(h).idx());
            a_terms.push(0.5 * ((fv[i][0] * fv[j][1]).abs() + (fv[i][1] * fv[j][0]).abs()));
        }
    }
    let a_err = 2.0 * e * a_terms.iter().sum::<f64>() + sum_error(a_terms.iter().copied(), e);
    // E_CR: layout error δ = ℓ_ki(Δα_i + 3ε) in p_k, then re/im, then the quotient.
    let mut cr_terms = Vec::new();
    let mut cr_err = 0.0;
    for face in mesh.faces() {
        let [hij, hjk, hki] = mesh.face_halfedges(face);
        let (lij, ljk, lki) = (lh(hij), lh(hjk), lh(hki));
        let alpha = crate::geometry::triangle::corner_angle(&ljk, &lki, &lij);
        let delta = lki * (corner_angle_error(ljk, lki, lij, e) + 3.0 * e);
        let p = [
            [0.0, 0.0],
            [lij, 0.0],
            [lki * alpha.cos(), lki * alpha.sin()],
        ];
        let area2 = lij * p[2][1];
        let idx = [
            mesh.tail(hij).idx(),
            mesh.tail(hjk).idx(),
            mesh.tail(hki).idx(),
        ];
        let (mut re, mut im, mut dre) = (0.0, 0.0, 0.0);
        for m in 0..3 {
            let (a, b) = (p[(m + 1) % 3], p[(m + 2) % 3]);
            let (ex, ey) = (b[0] - a[0], b[1] - a[1]);
            let z = fv[idx[m]];
            let fz = z[0].abs() + z[1].abs();
            dre += fz * (4.0 * delta + 8.0 * e * (ex.abs() + ey.abs()));
            re += -z[0] * ey - z[1] * ex;
            im += -z[1] * ey + z[0] * ex;
        }
        let num = re * re + im * im;
        let dnum = 2.0 * (re.abs() + im.abs()) * dre + 2.0 * dre * dre + 3.0 * e * num;
        let term = num / (4.0 * area2);
        let darea = lij * delta + 2.0 * e * area2.abs();
        // The quotient's first-order error needs a relative area error ≤ 1/8 (proofs/B48),
        // for the backend and for this evaluation from f64 approximations (B40).
        let kappa = darea / (e * area2.abs());
        if (kappa * EPS_F64)
            .partial_cmp(&0.125)
            .is_none_or(std::cmp::Ordering::is_gt)
        {
            return f64::INFINITY;
        }
        cr_err += dnum / (4.0 * area2.abs()) + term.abs() * (darea / area2.abs() + 2.0 * e);
        cr_terms.push(term);
    }
    let total = ed_err
        + sum_error(ed_terms.iter().copied(), e)
        + a_err
        + cr_err
        + sum_error(cr_terms.iter().copied(), e);
    let mags = ed_terms.iter().map(|x: &f64| x.abs()).sum::<f64>()
        + a_terms.iter().sum::<f64>()
        + cr_terms.iter().map(|x: &f64| x.abs()).sum::<f64>();
    SAFETY * (total + 2.0 * e * mags)
}

/// Heron area in `f64` for the bound (Kahan's ordering).
fn triangle_area(a: f64, b: f64, c: f64) -> f64 {
    crate::geometry::triangle::kahan_area(&a, &b, &c)
}
