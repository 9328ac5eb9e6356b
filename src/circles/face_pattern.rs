//! Circle patterns with one circle per face (notes §1.4.2, Rivin's coherent angle systems;
//! Bobenko–Springborn 2004): given an intersection angle `Φ_e ∈ (0, π)` per edge of a
//! triangulated disk, find circle radii `r_f = e^{ρ_f}`, one per face, whose circles meet
//! at the vertices with these angles; the corner angles of the triangulation follow
//! (proofs/T14, B86). `f64` only: a numerical reconstruction, checked against a stated
//! first-order bound.
//!
//! **Angles from radii.** Two face circles `j, k` across an interior edge `e` meet at the
//! edge's endpoints `p, q`. In the triangle of the centres `c_j, c_k` and `p` the sides at
//! `p` are `r_j, r_k` and the angle at `p` is `Φ_e`; the angle at `c_j` is the corner
//! angle `α_j` opposite `e` in face `j` (half the central angle of the chord `pq`):
//! `α_j = atan2(sin Φ_e, e^{ρ_j − ρ_k} − cos Φ_e)`, and `α_j + α_k = π − Φ_e` (Rivin's
//! compatibility condition). A boundary edge has `α_j = π − Φ_e` (notes' convention).
//!
//! **Equations.** Every face's three corner angles sum to `π`:
//! `F_f(ρ) = Σ_{e ∈ f} α_f^e(ρ) − π = 0`. With `x = ρ_j − ρ_k`,
//! `∂α_j/∂ρ_j = −w_e`, `∂α_j/∂ρ_k = w_e`, `w_e = sin Φ_e / (2(cosh x − cos Φ_e)) > 0`:
//! `−∂F/∂ρ` is a weighted Laplacian of the dual graph (the Hessian of Bobenko–Springborn's
//! convex functional), positive definite after fixing `ρ` of one face (the global scale).
//! Newton with a backtracking line search on `‖F‖₂` solves it.
//!
//! **A necessary condition.** `Σ_f F_f = Σ_e (π − Φ_e) − Fπ` does not depend on `ρ`
//! (each interior edge contributes `α_j + α_k = π − Φ_e`): angles with
//! `ΣΦ ≠ (E − F)π` admit no solution ([`FacePatternError::AngleSum`]).

use super::layout::third_corner;
use crate::geometry::unfold::dual_breadth_first;
use crate::mesh::{HalfEdge, Mesh};
use crate::scalar::dense::solve_spd;
use std::f64::consts::PI;

/// Why no face circle pattern was computed.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum FacePatternError {
    /// The number of angles is not the number of edges.
    #[error("expected {expected} intersection angles (one per edge), got {got}")]
    Count {
        /// Edges of the mesh.
        expected: usize,
        /// Angles given.
        got: usize,
    },
    /// An angle outside the open interval `(0, π)` or not finite.
    #[error("edge e{edge}: intersection angle {phi} is outside (0, π)")]
    AngleOutOfRange {
        /// The edge.
        edge: usize,
        /// The angle.
        phi: f64,
    },
    /// The mesh is not a triangulated disk.
    #[error("not a triangulated disk: Euler characteristic {chi}, {loops} boundary loop(s)")]
    NotADisk {
        /// Euler characteristic.
        chi: i64,
        /// Boundary loops.
        loops: usize,
    },
    /// `Σ_f F_f = Σ_e (π − Φ_e) − Fπ` is not zero (module docs): no radii solve the system.
    #[error("the face equations sum to {defect:.3e} for every radius (Σ_e (π − Φ_e) ≠ Fπ): no angle system exists")]
    AngleSum {
        /// `Σ_e (π − Φ_e) − Fπ`.
        defect: f64,
    },
    /// Newton did not reach the tolerance.
    #[error("Newton stopped after {iterations} iterations at residual {residual:.3e}")]
    NoConvergence {
        /// Iterations made.
        iterations: usize,
        /// `max_f |F_f|` at the end.
        residual: f64,
    },
}

/// A solved face circle pattern.
#[derive(Clone, Debug)]
pub struct FacePattern {
    /// `ρ_f = ln r_f` per face (`ρ_0 = 0`).
    pub rho: Vec<f64>,
    /// The corner angle opposite each face half-edge `h` (the angle of `h`'s face at the
    /// vertex not on `h`), indexed by half-edge; NaN on boundary half-edges.
    pub opposite: Vec<f64>,
    /// Newton iterations.
    pub iterations: usize,
    /// `max_f |F_f|` at the solution.
    pub residual: f64,
    /// `‖F‖₂` at the solution.
    pub residual_l2: f64,
}

/// `α_j = atan2(sin Φ, e^{x} − cos Φ)` with `x = ρ_j − ρ_k` (module docs).
pub fn face_angle(x: f64, phi: f64) -> f64 {
    phi.sin().atan2(x.exp() - phi.cos())
}

/// `w_e = sin Φ / (2(cosh x − cos Φ))` = `−∂α_j/∂ρ_j` (module docs).
pub fn face_weight(x: f64, phi: f64) -> f64 {
    phi.sin() / (2.0 * (x.cosh() - phi.cos()))
}

/// `∂α_j/∂Φ = (e^x cos Φ − 1)/(e^{2x} − 2e^x cos Φ + 1)` (differentiating [`face_angle`]).
pub fn face_angle_dphi(x: f64, phi: f64) -> f64 {
    let ex = x.exp();
    (ex * phi.cos() - 1.0) / (ex * ex - 2.0 * ex * phi.cos() + 1.0)
}

fn check_input(mesh: &Mesh, phi: &[f64]) -> Result<(), FacePatternError> {
    if phi.len() != mesh.n_edges() {
        return Err(FacePatternError::Count {
            expected: mesh.n_edges(),
            got: phi.len(),
        });
    }
    if let Some((edge, &p)) = phi
        .iter()
        .enumerate()
        .find(|(_, p)| !p.is_finite() || **p <= 0.0 || **p >= PI)
    {
        return Err(FacePatternError::AngleOutOfRange { edge, phi: p });
    }
    let (chi, loops) = (mesh.euler_characteristic(), mesh.n_boundary_loops());
    if chi != 1 || loops != 1 {
        return Err(FacePatternError::NotADisk { chi, loops });
    }
    Ok(())
}

/// `Σ_e (π − Φ_e) − Fπ` in binary64, summed in edge order, then `F·π` subtracted.
pub fn angle_sum_defect(phi: &[f64], n_faces: usize) -> f64 {
    phi.iter().map(|p| PI - p).sum::<f64>() - n_faces as f64 * PI
}

/// A rigorous bound on the rounding error of [`angle_sum_defect`] for `E` angles in
/// `(0, π)` and `F` faces: `u·π·(1.01·E² + 3E + 3F)` (proof: B86, §1 — recursive summation
/// B41 with `γ_E ≤ 1.01·E·u`, one rounding per term, `|fl(π) − π| ≤ 0.4uπ`). A computed
/// defect above it proves `Σ_e (π − Φ_e) ≠ Fπ` for the given binary64 angles.
pub fn angle_sum_bound(n_edges: usize, n_faces: usize) -> f64 {
    let (e, f) = (n_edges as f64, n_faces as f64);
    f64::EPSILON / 2.0 * PI * (1.01 * e * e + 3.0 * e + 3.0 * f)
}

/// The corner angle opposite every face half-edge for radii `rho` (module docs).
pub fn opposite_angles(mesh: &Mesh, phi: &[f64], rho: &[f64]) -> Vec<f64> {
    mesh.halfedges()
        .map(|h| {
            let Some(f) = mesh.face(h) else {
                return f64::NAN;
            };
            let p = phi[h.edge().idx()];
            match mesh.face(h.twin()) {
                Some(g) => face_angle(rho[f.idx()] - rho[g.idx()], p),
                None => PI - p,
            }
        })
        .collect()
}

/// `F_f = Σ α − π` per face.
fn face_defects(mesh: &Mesh, opposite: &[f64]) -> Vec<f64> {
    mesh.faces()
        .map(|f| {
            mesh.face_halfedges(f)
                .iter()
                .map(|h| opposite[h.idx()])
                .sum::<f64>()
                - PI
        })
        .collect()
}

/// `A = −∂F/∂ρ` grounded at face 0 (rows and columns of faces `1..F`), dense.
pub fn grounded_matrix(mesh: &Mesh, phi: &[f64], rho: &[f64]) -> Vec<Vec<f64>> {
    let nf = mesh.n_faces();
    let mut a = vec![vec![0.0; nf.saturating_sub(1)]; nf.saturating_sub(1)];
    for e in mesh.edges() {
        let h: HalfEdge = e.halfedge();
        let (Some(j), Some(k)) = (mesh.face(h), mesh.face(h.twin())) else {
            continue;
        };
        let (j, k) = (j.idx(), k.idx());
        let w = face_weight(rho[j] - rho[k], phi[e.idx()]);
        if j > 0 {
            a[j - 1][j - 1] += w;
        }
        if k > 0 {
            a[k - 1][k - 1] += w;
        }
        if j > 0 && k > 0 {
            a[j - 1][k - 1] -= w;
            a[k - 1][j - 1] -= w;
        }
    }
    a
}

/// Solve for the face radii from the intersection angles `phi` (one per edge, in `(0, π)`)
/// on the triangulated disk `mesh` (module docs), stopping at `max_f |F_f| ≤ tol`.
pub fn solve_face_pattern(
    mesh: &Mesh,
    phi: &[f64],
    tol: f64,
    max_iterations: usize,
) -> Result<FacePattern, FacePatternError> {
    check_input(mesh, phi)?;
    let nf = mesh.n_faces();
    let defect = angle_sum_defect(phi, nf);
    if defect.abs() > angle_sum_bound(phi.len(), nf) {
        return Err(FacePatternError::AngleSum { defect });
    }
    let norm = |v: &[f64]| v.iter().map(|x| x * x).sum::<f64>().sqrt();
    let mut rho = vec![0.0; nf];
    let mut opp = opposite_angles(mesh, phi, &rho);
    let mut f = face_defects(mesh, &opp);
    let mut iterations = 0;
    loop {
        let res = f.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
        if res <= tol || iterations >= max_iterations {
            if res > tol {
                return Err(FacePatternError::NoConvergence {
                    iterations,
                    residual: res,
                });
            }
            return Ok(FacePattern {
                rho,
                opposite: opp,
                iterations,
                residual: res,
                residual_l2: norm(&f),
            });
        }
        iterations += 1;
        let a = grounded_matrix(mesh, phi, &rho);
        // F(ρ + d) ≈ F − A d = 0  ⇒  A d = F (grounded rows).
        let Some(d) = solve_spd(&a, &f[1..]) else {
            return Err(FacePatternError::NoConvergence {
                iterations,
                residual: res,
            });
        };
        let start = norm(&f);
        let mut step = 1.0;
        loop {
            let mut trial = rho.clone();
            for (r, di) in trial[1..].iter_mut().zip(&d) {
                *r += step * di;
            }
            let o = opposite_angles(mesh, phi, &trial);
            let ft = face_defects(mesh, &o);
            if norm(&ft) < start || step < 1e-6 {
                rho = trial;
                opp = o;
                f = ft;
                break;
            }
            step /= 2.0;
        }
    }
}

/// A layout of the vertices by unfolding, with a first-order bound on each position's error.
#[derive(Clone, Debug)]
pub struct Unfolding {
    /// The position of every vertex (`None` for a vertex on no face).
    pub positions: Vec<Option<[f64; 2]>>,
    /// First-order bound on each position's error when every corner angle opposite
    /// half-edge `h` is off by at most `delta[h]`, the first edge held fixed (proofs/B86 §3).
    pub bound: Vec<f64>,
}

/// Lay out the triangulation with the corner angles of `pattern` by unfolding: face 0 with
/// its first half-edge on the positive x-axis, its length `ℓ = 2 r_0 sin α`, then
/// neighbours breadth first, each third corner by [`third_corner`] from the law of sines
/// `ℓ_pk = ℓ_pq sin α_q / sin α_k`; every vertex keeps its first position. The bound
/// propagates `e_k ≤ e_p + ρ(e_p + e_q) + ℓ_pk(δ_p + |cot α_q| δ_q + |cot α_k| δ_k)` with
/// `ρ = ℓ_pk/ℓ_pq` (proofs/B86 §3), `δ` the per-angle error bounds indexed by the half-edge
/// the angle is opposite to.
pub fn unfold(mesh: &Mesh, pattern: &FacePattern, delta: &[f64]) -> Unfolding {
    let n = mesh.n_vertices();
    let mut positions: Vec<Option<[f64; 2]>> = vec![None; n];
    let mut bound = vec![0.0; n];
    let Some(f0) = mesh.faces().next() else {
        return Unfolding { positions, bound };
    };
    let opp = |h: HalfEdge| pattern.opposite[h.idx()];
    let h0 = mesh.face_halfedge(f0);
    let l0 = 2.0 * pattern.rho[f0.idx()].exp() * opp(h0).sin();
    positions[mesh.tail(h0).idx()] = Some([0.0, 0.0]);
    positions[mesh.tip(h0).idx()] = Some([l0, 0.0]);
    // Place the corner opposite `h` (a face half-edge whose ends are placed).
    let place = |positions: &mut Vec<Option<[f64; 2]>>, bound: &mut Vec<f64>, h: HalfEdge| {
        let (p, q) = (mesh.tail(h).idx(), mesh.tip(h).idx());
        let k = mesh.tip(mesh.next(h)).idx();
        let (Some(pp), Some(pq)) = (positions[p], positions[q]) else {
            return;
        };
        if positions[k].is_some() {
            return;
        }
        // The corner at p is opposite next(h) = q→k, at q opposite prev(h), at k opposite h.
        let (hq_k, hk_p) = (mesh.next(h), mesh.prev(h));
        let (a_p, a_q, a_k) = (opp(hq_k), opp(hk_p), opp(h));
        let lpq = (pq[0] - pp[0]).hypot(pq[1] - pp[1]);
        let lpk = lpq * a_q.sin() / a_k.sin();
        let lqk = lpq * a_p.sin() / a_k.sin();
        positions[k] = Some(third_corner(pp, pq, lpk, lqk));
        let (dp, dq, dk) = (delta[hq_k.idx()], delta[hk_p.idx()], delta[h.idx()]);
        let ratio = lpk / lpq;
        bound[k] = bound[p]
            + ratio * (bound[p] + bound[q])
            + lpk * (dp + (a_q.cos() / a_q.sin()).abs() * dq + (a_k.cos() / a_k.sin()).abs() * dk);
    };
    place(&mut positions, &mut bound, h0);
    dual_breadth_first(mesh, f0, |_| true, |t| place(&mut positions, &mut bound, t));
    Unfolding { positions, bound }
}

/// `ℓ_e = 2 e^{ρ_f} sin α_f^e` from the first face of each edge.
pub fn edge_lengths(mesh: &Mesh, pattern: &FacePattern) -> Vec<f64> {
    mesh.edges()
        .map(|e| {
            let h = e.halfedge();
            let h = if mesh.face(h).is_some() { h } else { h.twin() };
            let f = mesh.face(h).map_or(0, crate::mesh::Face::idx);
            2.0 * pattern.rho[f].exp() * pattern.opposite[h.idx()].sin()
        })
        .collect()
}

/// The intersection angles of the circumcircles of the faces of the planar triangulation
/// `points` (notes §1.4.2): `Φ_e = π − α_e − β_e` on interior edges (`α_e, β_e` the
/// angles opposite `e`), `π − α_e` on boundary edges. Corner angles by
/// `atan2(|u × v|, u·v)`.
pub fn intersection_angles(mesh: &Mesh, points: &[[f64; 2]]) -> Vec<f64> {
    let opp = opposite_angles_of_points(mesh, points);
    mesh.edges()
        .map(|e| {
            let h = e.halfedge();
            let a = opp[h.idx()];
            let b = opp[h.twin().idx()];
            PI - if a.is_nan() { 0.0 } else { a } - if b.is_nan() { 0.0 } else { b }
        })
        .collect()
}

/// The corner angle opposite every face half-edge of the planar triangulation `points`
/// (NaN on boundary half-edges): at the vertex `k` not on `h = (i, j)`, the angle between
/// `p_i − p_k` and `p_j − p_k`.
pub fn opposite_angles_of_points(mesh: &Mesh, points: &[[f64; 2]]) -> Vec<f64> {
    mesh.halfedges()
        .map(|h| {
            if mesh.face(h).is_none() {
                return f64::NAN;
            }
            let (i, j) = (mesh.tail(h).idx(), mesh.tip(h).idx());
            let k = mesh.tip(mesh.next(h)).idx();
            let u = [points[i][0] - points[k][0], points[i][1] - points[k][1]];
            let v = [points[j][0] - points[k][0], points[j][1] - points[k][1]];
            (u[0] * v[1] - u[1] * v[0])
                .abs()
                .atan2(u[0] * v[0] + u[1] * v[1])
        })
        .collect()
}
