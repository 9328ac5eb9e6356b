//! `E`, `∇E = Θ − θ` and the cotan Hessian in binary64 from one pass over the faces, with
//! each corner angle computed once and reused for `θ`, `Л` and the energy (proofs/B88).
//!
//! Per face with logarithmic lengths `x_m` (longest side `s`, the largest angle opposite
//! it): the sides `ℓ_m = e^{(x_m − x_s)/2}` (two `exp`, `ℓ_s = 1`), the half perimeter
//! terms `σ = ℓ₀ + ℓ₁ + ℓ₂`, `e_m = ℓ_{m+1} + ℓ_{m+2} − ℓ_m` and one square root
//! `r = √(σ e₀ e₁ e₂) = 4·Area` (Heron). The two smaller angles come from the half-angle
//! formula `tan(α_m/2) = r/(σ e_m)` (one division and one `atan` each), the largest as
//! `α_s = π − α_a − α_b`; the cotangents `cot α_m = (ℓ²_{m+1} + ℓ²_{m+2} − ℓ²_m)/r` need no
//! transcendental function. The face's term of `E` is rewritten with `Σ α_m = π` as
//! `2f − (π/2)Σ x_m = Σ (α_m − π/2)(x_m − x_s) + 2 Σ Л(α_m) − (π/2) x_s`, so a large common
//! scale `x_s` enters once, not through every product `α_m x_m`.
//!
//! Degenerate faces (a slack `e_m ≤ 0`) take the extension of
//! [`super::triangle`] (`α_m = π`, the others 0, no Hessian term), decided on the same
//! computed slacks as the generic path. The result is numerical, not certified: it differs
//! from [`energy_gradient_hessian_with`](super::energy::energy_gradient_hessian_with) at
//! `f64` by rounding, within the first-order bound of proofs/B88.
//!
//! Consumer: T32 (`theorems::t32_energy::verify_one_pass`, through the `OnePass` impl for
//! `f64`) checks this pass against the generic evaluation within that bound, as a second
//! formula inside `penner check`.
//!
//! ```
//! use penner::mesh::Mesh;
//! use penner::variational::fast_f64::energy_gradient_hessian_f64;
//! use penner::variational::pattern::HessianPattern;
//! // Two equilateral triangles glued into a sphere: cone angles 2π/3, gradient 0.
//! let m = Mesh::from_faces(3, &[[0, 1, 2], [0, 2, 1]]).unwrap();
//! let p = HessianPattern::new(&m);
//! let t = [2.0 * std::f64::consts::FRAC_PI_3; 3];
//! let parts = energy_gradient_hessian_f64(&p, &m, &[0.0; 3], &[0.0; 3], &t);
//! assert!(parts.gradient.iter().all(|g| g.abs() < 1e-15));
//! ```

use super::energy::EnergyParts;
use super::pattern::HessianPattern;
use crate::geometry::laplacian::SparseMatrix;
use crate::mesh::Mesh;
use crate::special::lobachevsky;
use std::f64::consts::{FRAC_PI_2, PI};

/// One face's share of `E`, `∇E` and the Hessian in binary64 (module doc).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FaceF64 {
    /// The angles `α_m` opposite the sides `m` (NaN when a slack is NaN).
    pub angles: [f64; 3],
    /// `cot α_m` for a proper face, `None` for a degenerate or undecided one.
    pub cot: Option<[f64; 3]>,
    /// The face's term `2f(x) − (π/2)(x₀ + x₁ + x₂)` of `E`.
    pub energy: f64,
    /// `Л(α_m)` (0 for a degenerate face).
    pub lobachevsky: [f64; 3],
}

/// The index of the largest `x_m` (the last one among equal maxima, by `total_cmp`, as
/// [`shifted_lengths`](super::triangle::shifted_lengths)).
#[inline]
fn longest(x: &[f64; 3]) -> usize {
    let mut s = 0;
    for m in 1..3 {
        if x[m].total_cmp(&x[s]).is_ge() {
            s = m;
        }
    }
    s
}

/// [`FaceF64`] of the face with logarithmic lengths `x = [x₀, x₁, x₂]` (module doc).
#[inline]
pub fn face_f64(x: &[f64; 3]) -> FaceF64 {
    let s = longest(x);
    let d = [x[0] - x[s], x[1] - x[s], x[2] - x[s]];
    // The same side lengths as the generic path (`exp((x_m − x_s)·½)`, `ℓ_s = 1`).
    let l = [0, 1, 2].map(|m| if m == s { 1.0 } else { (d[m] * 0.5).exp() });
    let e = [0, 1, 2].map(|m| l[(m + 1) % 3] + l[(m + 2) % 3] - l[m]);
    let undecided = e.iter().any(|v| v.is_nan());
    if let Some(m) = (0..3).find(|&m| e[m] <= 0.0) {
        let mut angles = [0.0; 3];
        angles[m] = PI;
        // 2f − (π/2)Σx = π x_m − (π/2)Σx = Σ(α − π/2)d − (π/2)x_s.
        let energy = [0, 1, 2]
            .map(|k| (angles[k] - FRAC_PI_2) * d[k])
            .iter()
            .sum::<f64>()
            - FRAC_PI_2 * x[s];
        return FaceF64 {
            angles,
            cot: None,
            energy,
            lobachevsky: [0.0; 3],
        };
    }
    if undecided {
        return FaceF64 {
            angles: [f64::NAN; 3],
            cot: None,
            energy: f64::NAN,
            lobachevsky: [f64::NAN; 3],
        };
    }
    let sigma = l[0] + l[1] + l[2];
    let r = (sigma * e[0] * e[1] * e[2]).sqrt();
    let (a, b) = ((s + 1) % 3, (s + 2) % 3);
    let mut angles = [0.0; 3];
    angles[a] = 2.0 * (r / (sigma * e[a])).atan();
    angles[b] = 2.0 * (r / (sigma * e[b])).atan();
    angles[s] = PI - angles[a] - angles[b];
    let lob = angles.map(|t| lobachevsky(&t));
    let sq = l.map(|v| v * v);
    let cot = [0, 1, 2].map(|m| (sq[(m + 1) % 3] + sq[(m + 2) % 3] - sq[m]) / r);
    let energy = (angles[a] - FRAC_PI_2) * d[a]
        + (angles[b] - FRAC_PI_2) * d[b]
        + 2.0 * (lob[0] + lob[1] + lob[2])
        - FRAC_PI_2 * x[s];
    FaceF64 {
        angles,
        cot: Some(cot),
        energy,
        lobachevsky: lob,
    }
}

/// `E`, `∇E = Θ − θ` and the Hessian `−L` at `f64` from the scaled logarithmic lengths `λ̃`
/// (one per edge), `u` and the targets `Θ`, on a pattern built once for `mesh`: faces in
/// face order, each by [`face_f64`]; `θ` accumulated per corner, `½ cot α_m` added in
/// place on the pattern. Numerical (proofs/B88), the counterpart of
/// [`energy_gradient_hessian_with`](super::energy::energy_gradient_hessian_with).
///
/// A pattern of another mesh is a programming error: it panics when its size does not fit
/// ([`HessianPattern::fits`]).
pub fn energy_gradient_hessian_f64(
    pattern: &HessianPattern,
    mesh: &Mesh,
    lt: &[f64],
    u: &[f64],
    targets: &[f64],
) -> EnergyParts<f64> {
    assert!(pattern.fits(mesh), "Hessian pattern of another mesh");
    if lt.is_empty() && u.is_empty() {
        return EnergyParts {
            energy: None,
            gradient: targets.to_vec(),
            hessian: SparseMatrix::from_triplets(mesh.n_vertices(), &[]),
        };
    }
    let mut energy = 0.0;
    let mut theta = vec![0.0; mesh.n_vertices()];
    let mut val = pattern.zeros(&0.0);
    for f in mesh.faces() {
        let hs = mesh.face_halfedges(f);
        let x = hs.map(|h| lt[h.edge().idx()]);
        let t = face_f64(&x);
        energy += t.energy;
        for m in 0..3 {
            // The corner opposite side m is at the tail of side m + 2.
            theta[mesh.tail(hs[(m + 2) % 3]).idx()] += t.angles[m];
        }
        if let Some(c) = t.cot {
            for m in 0..3 {
                pattern.add_side(mesh, &mut val, hs[m], &(0.5 * c[m]));
            }
        }
    }
    for (t, ui) in targets.iter().zip(u) {
        energy += t * ui;
    }
    let gradient = if lt.is_empty() {
        targets.to_vec()
    } else {
        theta.iter().zip(targets).map(|(th, t)| t - th).collect()
    };
    EnergyParts {
        energy: Some(energy),
        gradient,
        hessian: pattern.matrix(val),
    }
}
