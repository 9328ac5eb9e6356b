//! T33 — hyperbolic discrete metrics (notes Thm 11; BPS15 §6; docs/catalogue.md §7): the angles of a
//! hyperbolic triangle by two independent formulas agree, and the hyperbolic energy of
//! the sinh-scaled metric has gradient `Θ − θ_hyp(u)`.
//!
//! API:
//! - `pub fn check_hyperbolic<T: Real>(mesh: &Mesh, lengths: &[T], u: &[T], targets: &[T], directions: &[Vec<T>], settings: &Settings) -> Verdict`
//! - `pub fn check_hyperbolic_angles<T: Real>(mesh: &Mesh, lengths: &[T], settings: &Settings) -> Verdict`
//! - `pub fn verify_hyperbolic_gradient<T: Real>(mesh: &Mesh, lengths: &[T], u: &[T], targets: &[T], gradient: &[T], directions: &[Vec<T>], settings: &Settings) -> Verdict`

use super::bounds::{eps, sum_error, SAFETY};
use super::energy_bounds::{hyperbolic_angle_gap, hyperbolic_face_error};
use super::report::{check_lengths, lengths_out_of_range, Tally};
use super::verdict::{Settings, Verdict};
use crate::mesh::Mesh;
use crate::scalar::{Dual, Real};
use crate::variational::hyperbolic::{
    angles_half_angle, angles_law_of_cosines, energy, gradient, hyperbolic_log_length,
    length_from_log,
};
use crate::variational::triangle::{shape, Shape};

/// T33 on one input: [`check_hyperbolic_angles`] on the scaled metric's base lengths and
/// [`verify_hyperbolic_gradient`] against `Θ − θ_hyp(u)`.
pub fn check_hyperbolic<T: Real>(
    mesh: &Mesh,
    lengths: &[T],
    u: &[T],
    targets: &[T],
    directions: &[Vec<T>],
    settings: &Settings,
) -> Verdict {
    let a = check_hyperbolic_angles(mesh, lengths, settings);
    if !a.holds() {
        return a;
    }
    if u.len() != mesh.n_vertices() || targets.len() != mesh.n_vertices() {
        return Verdict::NotApplicable {
            reason: "one scale factor and one target per vertex are needed".into(),
        };
    }
    let g = gradient(mesh, lengths, u, targets);
    verify_hyperbolic_gradient(mesh, lengths, u, targets, &g, directions, settings)
}

/// The half-angle and the law-of-cosines angles of every corner agree within proofs/B58
/// ([`hyperbolic_angle_gap`]); witnesses are half-edges (the corner opposite).
pub fn check_hyperbolic_angles<T: Real>(
    mesh: &Mesh,
    lengths: &[T],
    settings: &Settings,
) -> Verdict {
    if let Some(v) = check_lengths(mesh, lengths).or_else(|| lengths_out_of_range(lengths)) {
        return v;
    }
    let ctx = lengths[0].ctx();
    let (e, bits) = (eps::<T>(ctx), T::precision_bits(ctx));
    let mut tally = Tally::new(false, bits);
    for f in mesh.faces() {
        let hs = mesh.face_halfedges(f);
        let l = hs.map(|h| lengths[h.edge().idx()].clone());
        let lf = l.clone().map(|x| x.approx_f64());
        let a = angles_half_angle(&l);
        let b = angles_law_of_cosines(&l);
        for m in 0..3 {
            let tol = settings.slack * hyperbolic_angle_gap(lf, m, e);
            tally.within(
                format!("{}", hs[m]),
                "half-angle − law of cosines",
                &(a[m].clone() - &b[m]),
                tol,
            );
        }
    }
    tally.verdict()
}

/// `∇E_hyp = g` against claimed `g`: along each direction `d`, the dual-number derivative
/// of [`energy`] equals `g·d` within the per-face bound of proofs/B58
/// ([`hyperbolic_face_error`]) plus B41 for the sums. Witnesses `d{k}`.
pub fn verify_hyperbolic_gradient<T: Real>(
    mesh: &Mesh,
    lengths: &[T],
    u: &[T],
    targets: &[T],
    claimed: &[T],
    directions: &[Vec<T>],
    settings: &Settings,
) -> Verdict {
    if let Some(v) = check_lengths(mesh, lengths).or_else(|| lengths_out_of_range(lengths)) {
        return v;
    }
    let n = mesh.n_vertices();
    if [u.len(), targets.len(), claimed.len()]
        .iter()
        .any(|&k| k != n)
        || directions.iter().any(|d| d.len() != n)
    {
        return Verdict::NotApplicable {
            reason: format!("u, targets, gradient and directions need {n} entries"),
        };
    }
    let ctx = lengths[0].ctx();
    let (e, bits) = (eps::<T>(ctx), T::precision_bits(ctx));
    let mut tally = Tally::new(false, bits);
    let lam: Vec<Dual<T>> = lengths.iter().map(|l| Dual::constant(l.clone())).collect();
    let tg: Vec<Dual<T>> = targets.iter().cloned().map(Dual::constant).collect();
    for (k, d) in directions.iter().enumerate() {
        let ud: Vec<Dual<T>> = u
            .iter()
            .zip(d)
            .map(|(a, b)| Dual::new(a.clone(), b.clone()))
            .collect();
        let Some(ed) = energy(mesh, &lam, &ud, &tg) else {
            continue;
        };
        let gd = claimed
            .iter()
            .zip(d)
            .fold(d[0].zero_like(), |s, (g, x)| s + &(g.clone() * x));
        let mut tol = 0.0;
        let mut terms = Vec::new();
        for f in mesh.faces() {
            let hs = mesh.face_halfedges(f);
            let xd: [Dual<T>; 3] = hs.map(|h| {
                let (i, j) = (mesh.tail(h).idx(), mesh.tip(h).idx());
                hyperbolic_log_length(&lam[h.edge().idx()]) + &ud[i] + &ud[j]
            });
            let ld = xd.clone().map(|x| length_from_log(&x));
            let xdot = [0, 1, 2].map(|m| xd[m].d.approx_f64());
            let lv = ld.clone().map(|x| x.v);
            if matches!(shape(&lv), Shape::Degenerate(_)) {
                // F_h = πλ_m exactly: one product and π's rounding.
                tol += SAFETY
                    * 4.0
                    * e
                    * std::f64::consts::PI
                    * xdot.iter().copied().map(f64::abs).sum::<f64>();
                continue;
            }
            let a = angles_half_angle(&ld);
            let lf = [0, 1, 2].map(|m| ld[m].v.approx_f64());
            let af = [0, 1, 2].map(|m| a[m].v.approx_f64());
            let ad = [0, 1, 2].map(|m| a[m].d.approx_f64());
            let xf = [0, 1, 2].map(|m| xd[m].v.approx_f64());
            tol += hyperbolic_face_error(xf, xdot, lf, af, ad, bits, e);
            terms.extend((0..3).map(|m| af[m] * xdot[m]));
        }
        terms.extend(
            claimed
                .iter()
                .zip(d)
                .map(|(g, x)| g.approx_f64() * x.approx_f64()),
        );
        let tol = settings.slack * (tol + 2.0 * sum_error(terms, e));
        tally.within(
            format!("d{k}"),
            "D_d E_hyp − (Θ−θ_hyp)·d",
            &(ed.d - &gd),
            tol,
        );
    }
    tally.verdict()
}
