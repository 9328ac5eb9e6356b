//! T14 (notes §1.4.2; Rivin 1994, Bobenko–Springborn 2004): the intersection angles
//! `Φ_e` of the circumcircles of a planar Delaunay triangulation determine it up to
//! similarity — the face circle pattern with these angles ([`solve_face_pattern`]) has the
//! triangulation's corner angles, and unfolding it reproduces the points (proofs/T14).
//!
//! [`check_rivin_angles`] certifies the input first — every face positively oriented and
//! every interior edge strictly locally Delaunay, by exact planar predicates, so every
//! `Φ_e ∈ (0, π)` — then computes `Φ` in `f64`, reconstructs, and compares
//! ([`compare_reconstruction`]) corner angles and positions (after the least-squares
//! similarity, Procrustes with scale) with the input against the first-order bounds of
//! proofs/B86. Within them: `Holds`, numerical. Beyond them: `Undecided` (a first-order
//! bound is no proof). Angles whose sum identity `Σ_e (π − Φ_e) = Fπ` is violated beyond
//! the rigorous rounding bound admit no angle system: `Fails`, certified.

use super::{Verdict, Witness};
use crate::circles::face_pattern::{
    angle_sum_bound, face_angle_dphi, face_weight, grounded_matrix, intersection_angles,
    opposite_angles_of_points, solve_face_pattern, unfold, FacePattern, FacePatternError,
};
use crate::mesh::Mesh;
use crate::predicates::ladder::Ladder;
use crate::predicates::planar::{incircle, orient2d, point_from_f64};
use crate::scalar::dense::solve_spd;
use crate::scalar::Sign;
use std::f64::consts::PI;

/// Coordinates must be integers of absolute value below `2²⁴`: differences, cross and dot
/// products of two differences are then exact in binary64 (`< 2⁵¹`), so each input corner
/// angle is one `atan2` of exact arguments (proofs/B86 §2).
pub const COORDINATE_LIMIT: f64 = 16_777_216.0;

/// Largest face count for the dense `‖A⁻¹‖∞` of the bound (proofs/B86 §2); larger inputs
/// are `Undecided`.
pub const DENSE_FACE_LIMIT: usize = 2000;

/// Unit roundoff of binary64.
const U: f64 = f64::EPSILON / 2.0;

/// Error of one computed `Φ_e` from integer points: two `atan2` of exact arguments within
/// 4 ulp each (B22, `≤ 8uπ` each), three roundings `≤ uπ` each, `fl(π)` within `0.4uπ`:
/// `δΦ = 20uπ` (proofs/B86 §2).
pub const PHI_ERROR: f64 = 20.0 * U * PI;

/// Error of one input corner angle (the reference): one `atan2` of exact arguments, within
/// 4 ulp (B22): `8uπ` (proofs/B86 §2).
pub const REFERENCE_ANGLE_ERROR: f64 = 8.0 * U * PI;

/// Safety factor on the first-order bounds of proofs/B86 (second-order terms).
pub const FIRST_ORDER_FACTOR: f64 = 2.0;

/// What the reconstruction measured.
#[derive(Clone, Debug)]
pub struct RivinReport {
    /// The verdict.
    pub verdict: Verdict,
    /// Newton iterations of the face pattern.
    pub iterations: usize,
    /// Largest `|α̂ − α|` over corners.
    pub angle_error: f64,
    /// Largest ratio `|α̂ − α| / bound` over corners (≤ 1 within the bound).
    pub angle_ratio: f64,
    /// Largest distance between an input point and its reconstruction after the
    /// least-squares similarity.
    pub position_error: f64,
    /// The bound on it (proofs/B86 §3).
    pub position_bound: f64,
}

fn witness(element: String, detail: String, value: f64) -> Witness {
    Witness {
        element,
        detail,
        value,
    }
}

fn report(verdict: Verdict) -> RivinReport {
    RivinReport {
        verdict,
        iterations: 0,
        angle_error: f64::NAN,
        angle_ratio: f64::NAN,
        position_error: f64::NAN,
        position_bound: f64::NAN,
    }
}

/// T14 on the planar triangulation `mesh` of `points` (module docs).
pub fn check_rivin_angles(mesh: &Mesh, points: &[[f64; 2]]) -> RivinReport {
    if points.len() != mesh.n_vertices() {
        return report(Verdict::NotApplicable {
            reason: format!("{} points for {} vertices", points.len(), mesh.n_vertices()),
        });
    }
    if let Some(v) = points.iter().position(|p| {
        p.iter()
            .any(|x| x.fract() != 0.0 || x.abs() >= COORDINATE_LIMIT)
    }) {
        return report(Verdict::NotApplicable {
            reason: format!("v{v}: coordinates are not integers below 2²⁴ in absolute value"),
        });
    }
    let exact: Vec<_> = points
        .iter()
        .filter_map(|p| point_from_f64(p[0], p[1]))
        .collect();
    let ladder = Ladder::default();
    let (mut refused, mut undecided) = (Vec::new(), Vec::new());
    for f in mesh.faces() {
        let [a, b, c] = mesh.face_vertices(f).map(crate::mesh::Vertex::idx);
        match orient2d(&exact[a], &exact[b], &exact[c], &ladder).value() {
            Some(Sign::Positive) => {}
            Some(_) => refused.push(format!("f{}: not positively oriented", f.idx())),
            None => undecided.push(witness(
                format!("f{}", f.idx()),
                "orientation undecided".into(),
                f64::NAN,
            )),
        }
    }
    for e in mesh.edges() {
        let h = e.halfedge();
        if mesh.face(h).is_none() || mesh.face(h.twin()).is_none() {
            continue;
        }
        let (i, j) = (mesh.tail(h).idx(), mesh.tip(h).idx());
        let k = mesh.tip(mesh.next(h)).idx();
        let l = mesh.tip(mesh.next(h.twin())).idx();
        match incircle(&exact[i], &exact[j], &exact[k], &exact[l], &ladder).value() {
            Some(Sign::Negative) => {}
            Some(Sign::Zero) => refused.push(format!(
                "e{}: cocircular (Φ = 0, the two face circles coincide)",
                e.idx()
            )),
            Some(Sign::Positive) => refused.push(format!("e{}: not locally Delaunay", e.idx())),
            None => undecided.push(witness(
                format!("e{}", e.idx()),
                "incircle undecided".into(),
                f64::NAN,
            )),
        }
    }
    if !refused.is_empty() {
        return report(Verdict::NotApplicable {
            reason: format!(
                "not a strictly Delaunay planar triangulation: {}",
                refused.join("; ")
            ),
        });
    }
    if !undecided.is_empty() {
        return report(Verdict::Undecided {
            bits_tried: 0,
            witnesses: undecided,
        });
    }
    let phi = intersection_angles(mesh, points);
    compare_reconstruction(mesh, points, &phi)
}

/// Reconstruct the triangulation from the intersection angles `phi` alone and compare its
/// corner angles and positions with those of `points` (integer coordinates below
/// [`COORDINATE_LIMIT`], a positively oriented triangulated disk) against the bounds of
/// proofs/B86 (module docs).
pub fn compare_reconstruction(mesh: &Mesh, points: &[[f64; 2]], phi: &[f64]) -> RivinReport {
    let nf = mesh.n_faces();
    if nf > DENSE_FACE_LIMIT {
        return report(Verdict::Undecided {
            bits_tried: 0,
            witnesses: vec![witness(
                "surface".into(),
                format!("{nf} faces: the dense bound stops at {DENSE_FACE_LIMIT}"),
                nf as f64,
            )],
        });
    }
    // A Newton stopping rule, not a verdict tolerance: the bound uses the residual reached.
    let tol = 64.0 * nf as f64 * U * PI;
    let pattern = match solve_face_pattern(mesh, phi, tol, 100) {
        Ok(p) => p,
        Err(FacePatternError::AngleSum { defect }) => {
            // proof: B86 §1 — beyond the rigorous rounding bound of the sum.
            return report(Verdict::Fails {
                certified: true,
                witnesses: vec![witness(
                    "surface".into(),
                    format!(
                        "Σ_e (π − Φ_e) − Fπ = {defect:.3e} beyond its rounding bound {:.3e}: no angle system",
                        angle_sum_bound(phi.len(), nf)
                    ),
                    defect,
                )],
            });
        }
        Err(e) => {
            return report(Verdict::Undecided {
                bits_tried: 0,
                witnesses: vec![witness("surface".into(), e.to_string(), f64::NAN)],
            })
        }
    };
    let Some(delta) = angle_error_bounds(mesh, phi, &pattern) else {
        return report(Verdict::Undecided {
            bits_tried: 0,
            witnesses: vec![witness(
                "surface".into(),
                "the grounded Jacobian did not factor".into(),
                f64::NAN,
            )],
        });
    };
    let reference = opposite_angles_of_points(mesh, points);
    let mut witnesses = Vec::new();
    let (mut angle_error, mut angle_ratio) = (0.0_f64, 0.0_f64);
    for h in mesh.halfedges() {
        if mesh.face(h).is_none() {
            continue;
        }
        let err = (pattern.opposite[h.idx()] - reference[h.idx()]).abs();
        // proof: B86 §2
        let bound = FIRST_ORDER_FACTOR * (delta[h.idx()] + REFERENCE_ANGLE_ERROR);
        angle_error = angle_error.max(err);
        angle_ratio = angle_ratio.max(err / bound);
        if err.is_nan() || err > bound {
            witnesses.push(witness(
                format!("h{}", h.idx()),
                format!("corner angle off by {err:.3e} > bound {bound:.3e}"),
                err,
            ));
        }
    }
    let unf = unfold(mesh, &pattern, &delta);
    let (position_error, position_bound, position_witnesses) =
        compare_positions(mesh, points, &unf.positions, &unf.bound);
    witnesses.extend(position_witnesses);
    let verdict = if witnesses.is_empty() {
        Verdict::Holds {
            certified: false,
            max_error: angle_error,
        }
    } else {
        Verdict::Undecided {
            bits_tried: 0,
            witnesses,
        }
    };
    RivinReport {
        verdict,
        iterations: pattern.iterations,
        angle_error,
        angle_ratio,
        position_error,
        position_bound,
    }
}

/// First-order bounds `δ_h` on the error of each reconstructed corner angle against the
/// exact angle of the exact points (proofs/B86 §2): the true residual
/// `|F_f| ≤ |F̂_f| + Σ_{h ∈ f}(ε_h + D_h δΦ) + 4uπ`, `‖Δρ‖∞ ≤ ‖A⁻¹‖∞ max_f |F_f|`,
/// `δ_h = 2 w_h ‖Δρ‖∞ + D_h δΦ + ε_h`, with `w_h` the Jacobian weight, `D_h = |∂α/∂Φ|` and
/// `ε_h = u(4.5 + 8π + 8(1 + e^{−x}) w_h)` the evaluation error of `α_h`. `None` when the
/// grounded matrix does not factor.
pub fn angle_error_bounds(mesh: &Mesh, phi: &[f64], pattern: &FacePattern) -> Option<Vec<f64>> {
    let nh = mesh.n_halfedges();
    let (mut w, mut d, mut eval) = (vec![0.0; nh], vec![0.0; nh], vec![0.0; nh]);
    for h in mesh.halfedges() {
        let Some(f) = mesh.face(h) else { continue };
        let p = phi[h.edge().idx()];
        if let Some(g) = mesh.face(h.twin()) {
            let x = pattern.rho[f.idx()] - pattern.rho[g.idx()];
            w[h.idx()] = face_weight(x, p);
            d[h.idx()] = face_angle_dphi(x, p).abs();
            eval[h.idx()] = U * (4.5 + 8.0 * PI + 8.0 * (1.0 + (-x).exp()) * w[h.idx()]);
        } else {
            d[h.idx()] = 1.0;
            eval[h.idx()] = 1.4 * U * PI;
        }
    }
    let mut true_residual = 0.0_f64;
    for f in mesh.faces() {
        let hs = mesh.face_halfedges(f);
        let computed: f64 = hs.iter().map(|h| pattern.opposite[h.idx()]).sum::<f64>() - PI;
        let extra: f64 = hs
            .iter()
            .map(|h| eval[h.idx()] + d[h.idx()] * PHI_ERROR)
            .sum();
        true_residual = true_residual.max(computed.abs() + extra + 4.0 * U * PI);
    }
    let inv_norm = inverse_inf_norm(&grounded_matrix(mesh, phi, &pattern.rho))?;
    let drho = inv_norm * true_residual;
    Some(
        (0..nh)
            .map(|h| 2.0 * w[h] * drho + d[h] * PHI_ERROR + eval[h])
            .collect(),
    )
}

/// `‖A⁻¹‖∞` (largest absolute row sum of the inverse) of a symmetric positive definite `A`,
/// column by column through the Cholesky solve; `1` for an empty matrix.
fn inverse_inf_norm(a: &[Vec<f64>]) -> Option<f64> {
    let n = a.len();
    if n == 0 {
        return Some(0.0);
    }
    let mut rows = vec![0.0_f64; n];
    for i in 0..n {
        let mut e = vec![0.0; n];
        e[i] = 1.0;
        let col = solve_spd(a, &e)?;
        for (r, c) in rows.iter_mut().zip(&col) {
            *r += c.abs();
        }
    }
    Some(rows.into_iter().fold(0.0, f64::max))
}

/// Fit the similarity `z ≈ a w + b` (complex `a, b`, least squares) from the reconstructed
/// positions `w` to the input `z`, and compare each residual with
/// `2·|a₀|·√(Σ e_i²) + 64·n·u·diam`: `|a₀|` the scale of the similarity taking the first
/// laid-out edge onto the input's, `e_i` the unfolding's bounds (proofs/B86 §3). Returns
/// the largest residual, the bound and the witnesses.
fn compare_positions(
    mesh: &Mesh,
    z: &[[f64; 2]],
    w: &[Option<[f64; 2]>],
    e: &[f64],
) -> (f64, f64, Vec<Witness>) {
    let placed: Vec<usize> = (0..z.len()).filter(|&v| w[v].is_some()).collect();
    let mut missing: Vec<Witness> = (0..z.len())
        .filter(|&v| w[v].is_none())
        .map(|v| witness(format!("v{v}"), "not laid out".into(), f64::NAN))
        .collect();
    let n = placed.len() as f64;
    if placed.len() < 2 {
        return (f64::NAN, f64::NAN, missing);
    }
    let wv = |v: usize| w[v].unwrap_or([0.0, 0.0]);
    let mean = |f: &dyn Fn(usize) -> [f64; 2]| {
        let s = placed.iter().fold([0.0, 0.0], |s, &v| {
            let p = f(v);
            [s[0] + p[0], s[1] + p[1]]
        });
        [s[0] / n, s[1] / n]
    };
    let (zc, wc) = (mean(&|v| z[v]), mean(&|v| wv(v)));
    // a = Σ conj(w̃) z̃ / Σ |w̃|².
    let (mut num, mut den) = ([0.0, 0.0], 0.0);
    for &v in &placed {
        let (wx, wy) = (wv(v)[0] - wc[0], wv(v)[1] - wc[1]);
        let (zx, zy) = (z[v][0] - zc[0], z[v][1] - zc[1]);
        num[0] += wx * zx + wy * zy;
        num[1] += wx * zy - wy * zx;
        den += wx * wx + wy * wy;
    }
    let a = [num[0] / den, num[1] / den];
    let diam = placed
        .iter()
        .map(|&v| (z[v][0] - zc[0]).hypot(z[v][1] - zc[1]))
        .fold(0.0, f64::max)
        * 2.0;
    let h0 = mesh.faces().next().map(|f| mesh.face_halfedge(f));
    let a0 = h0.map_or(f64::NAN, |h| {
        let (p, q) = (mesh.tail(h).idx(), mesh.tip(h).idx());
        (z[q][0] - z[p][0]).hypot(z[q][1] - z[p][1])
            / (wv(q)[0] - wv(p)[0]).hypot(wv(q)[1] - wv(p)[1])
    });
    let spread = placed.iter().map(|&v| e[v] * e[v]).sum::<f64>().sqrt();
    // proof: B86 §3
    let bound = FIRST_ORDER_FACTOR * a0 * spread + 64.0 * n * U * diam;
    let mut worst = 0.0_f64;
    for &v in &placed {
        let (wx, wy) = (wv(v)[0] - wc[0], wv(v)[1] - wc[1]);
        let fit = [a[0] * wx - a[1] * wy + zc[0], a[0] * wy + a[1] * wx + zc[1]];
        let r = (fit[0] - z[v][0]).hypot(fit[1] - z[v][1]);
        worst = worst.max(r);
        if r.is_nan() || r > bound {
            missing.push(witness(
                format!("v{v}"),
                format!(
                    "reconstructed point off by {r:.3e} > bound {bound:.3e} after the similarity"
                ),
                r,
            ));
        }
    }
    (worst, bound, missing)
}
