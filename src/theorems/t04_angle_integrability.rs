//! T04 — angle integrability (notes §1.3.1, Fig. 5): angles of a planar triangulation satisfy
//! (1) `Σ` over each triangle `= π`, (2) `Σ` around each interior vertex `= 2π`, and (3) the
//! sine closure `Π_{ijk∋i} sin α_j^{ki} / sin α_k^{ij} = 1` around each interior vertex.
//! (3) is independent of (1)–(2): Fig. 5's shape satisfies the sums and fails (3).
//!
//! API:
//! - `pub fn check_angle_integrability<T: Real>(mesh: &Mesh, angles: &[T], angle_errors: &[f64], settings: &Settings) -> Verdict`
//! - `pub fn check_angle_integrability_from_lengths<T: Real>(mesh: &Mesh, lengths: &[T], settings: &Settings) -> Verdict`

use super::bounds::{corner_angle_error, eps, sum_error, SAFETY};
use super::report::{check_lengths, lengths_out_of_range, Tally};
use super::verdict::{Settings, Verdict};
use crate::geometry::corners::halfedge_angles;
use crate::mesh::Mesh;
use crate::scalar::Real;

/// T04 on given corner angles: `angles[h]` is the angle opposite face half-edge `h` (as in
/// [`halfedge_angles`]; boundary entries ignored) and `angle_errors[h]` a bound on its error
/// (0 for exactly given angles). Tolerances (proofs/B43): sums — the input errors plus B41
/// over the terms and π; sine closure — `|P|(Σ_factors (ε + |cot α| δα) + (2n−1)ε) + ε`,
/// times [`SAFETY`]. Witnesses: `f…` (triangle sum), `v…` (vertex sum), `v…` (sine closure),
/// every failing element listed.
pub fn check_angle_integrability<T: Real>(
    mesh: &Mesh,
    angles: &[T],
    angle_errors: &[f64],
    settings: &Settings,
) -> Verdict {
    if angles.len() != mesh.n_halfedges() || angle_errors.len() != mesh.n_halfedges() {
        return Verdict::NotApplicable {
            reason: format!(
                "{} angles / {} error bounds given for {} half-edges",
                angles.len(),
                angle_errors.len(),
                mesh.n_halfedges()
            ),
        };
    }
    let Some(a0) = angles.first() else {
        return Verdict::NotApplicable {
            reason: "the mesh has no half-edges".to_string(),
        };
    };
    let ctx = a0.ctx();
    let e = eps::<T>(ctx);
    let pi = T::pi(ctx);
    let two_pi = pi.clone() * &a0.lit(2.0);
    let mut tally = Tally::new(false, T::precision_bits(ctx));
    for f in mesh.faces() {
        let hs = mesh.face_halfedges(f);
        let s = angles[hs[0].idx()].clone() + &angles[hs[1].idx()] + &angles[hs[2].idx()];
        let d = s - &pi;
        let terms = hs.iter().map(|h| angles[h.idx()].approx_f64());
        let tol = settings.slack
            * (hs.iter().map(|h| angle_errors[h.idx()]).sum::<f64>()
                + sum_error(terms.chain([std::f64::consts::PI]), e)
                + SAFETY * e * std::f64::consts::PI);
        tally.within(format!("{f}"), "triangle angle sum − π", &d, tol);
    }
    let boundary = mesh.boundary_vertices();
    // Face half-edges leaving each vertex: h = i→j in face ijk.
    let mut out: Vec<Vec<crate::mesh::HalfEdge>> = vec![Vec::new(); mesh.n_vertices()];
    for h in mesh.halfedges() {
        if !mesh.is_boundary_halfedge(h) {
            out[mesh.tail(h).idx()].push(h);
        }
    }
    for v in mesh.vertices() {
        if boundary[v.idx()] || out[v.idx()].is_empty() {
            continue;
        }
        // Angle at i is opposite next(h); at j opposite prev(h); at k opposite h.
        let mut s = a0.zero_like();
        let mut p = a0.one_like();
        let mut input_err = 0.0;
        let mut terms = Vec::new();
        let mut sine_rel = 0.0;
        for &h in &out[v.idx()] {
            let at_i = &angles[mesh.next(h).idx()];
            s += at_i;
            input_err += angle_errors[mesh.next(h).idx()];
            terms.push(at_i.approx_f64());
            let (ak, aj) = (&angles[h.idx()], &angles[mesh.prev(h).idx()]);
            p *= &(ak.sin() / &aj.sin());
            for (x, dx) in [
                (ak, angle_errors[h.idx()]),
                (aj, angle_errors[mesh.prev(h).idx()]),
            ] {
                let xf = x.approx_f64();
                sine_rel += e + (xf.cos() / xf.sin()).abs() * dx;
            }
        }
        terms.push(2.0 * std::f64::consts::PI);
        let d = s - &two_pi;
        let tol = settings.slack
            * (input_err + sum_error(terms, e) + SAFETY * e * 2.0 * std::f64::consts::PI);
        tally.within(format!("{v}"), "vertex angle sum − 2π", &d, tol);
        let n = out[v.idx()].len() as f64;
        let pf = p.approx_f64().abs();
        let dp = p - &a0.one_like();
        let tol_sine = settings.slack
            * SAFETY
            * (pf * (sine_rel + (2.0 * n - 1.0) * e) + e * (1.0 + dp.approx_f64().abs()));
        tally.within(format!("{v}"), "sine closure product − 1", &dp, tol_sine);
    }
    tally.verdict()
}

/// T04 for the angles of a metric: angles by [`halfedge_angles`] with their B40 error bounds,
/// then [`check_angle_integrability`]. Conditions (2)–(3) hold when the metric is flat at
/// every interior vertex (e.g. lengths of a planar layout).
pub fn check_angle_integrability_from_lengths<T: Real>(
    mesh: &Mesh,
    lengths: &[T],
    settings: &Settings,
) -> Verdict {
    if let Some(v) = check_lengths(mesh, lengths).or_else(|| lengths_out_of_range(lengths)) {
        return v;
    }
    let e = eps::<T>(lengths[0].ctx());
    let l = |h: crate::mesh::HalfEdge| lengths[h.edge().idx()].approx_f64();
    let errs: Vec<f64> = mesh
        .halfedges()
        .map(|h| {
            if mesh.is_boundary_halfedge(h) {
                0.0
            } else {
                corner_angle_error(l(h), l(mesh.next(h)), l(mesh.prev(h)), e)
            }
        })
        .collect();
    check_angle_integrability(mesh, &halfedge_angles(mesh, lengths), &errs, settings)
}
