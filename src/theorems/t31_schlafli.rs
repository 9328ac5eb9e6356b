//! T31 — Schläfli's formula for one triangle (notes §1.6.3, Eqs. 16–17; docs/catalogue.md §7):
//! `f(x) = ½ Σ α_m x_m + Σ Л(α_m)` has `∂f/∂x_m = α_m/2` (`x = 2 log ℓ`), checked with
//! dual numbers against the closed-form (half-angle) angles.
//!
//! API:
//! - `pub fn check_schlafli<T: Real>(mesh: &Mesh, lengths: &[T], settings: &Settings) -> Verdict`
//! - `pub fn verify_schlafli<T: Real>(mesh: &Mesh, lengths: &[T], half_angles: &[T], settings: &Settings) -> Verdict`

use super::bounds::{eps, SAFETY};
use super::energy_bounds::schlafli_error;
use super::report::{check_lengths, lengths_out_of_range, Tally};
use super::verdict::{Settings, Verdict};
use crate::mesh::Mesh;
use crate::scalar::{Dual, Real};
use crate::variational::triangle::{
    angles_from_log_lengths, shape, shifted_lengths, triangle_energy, Shape,
};

/// The claimed half-angles `α/2` per half-edge (the corner opposite `h` in its face, with
/// the degenerate extension of [`crate::variational::triangle`]); zero on boundary
/// half-edges.
pub fn half_angles<T: Real>(mesh: &Mesh, lengths: &[T]) -> Vec<T> {
    let Some(z) = lengths.first() else {
        return Vec::new();
    };
    let mut out = vec![z.zero_like(); mesh.n_halfedges()];
    let half = z.lit(0.5);
    for f in mesh.faces() {
        let hs = mesh.face_halfedges(f);
        let x = hs.map(|h| lengths[h.edge().idx()].ln() * &z.lit(2.0));
        let a = angles_from_log_lengths(&x);
        for m in 0..3 {
            out[hs[m].idx()] = a[m].clone() * &half;
        }
    }
    out
}

/// T31, numerical: [`verify_schlafli`] against [`half_angles`].
pub fn check_schlafli<T: Real>(mesh: &Mesh, lengths: &[T], settings: &Settings) -> Verdict {
    let h = half_angles(mesh, lengths);
    verify_schlafli(mesh, lengths, &h, settings)
}

/// T31 against claimed half-angles (one per half-edge): for every face and side `m`, the
/// dual-number derivative of [`triangle_energy`] along `e_m` must equal the claimed
/// `α_m/2` within proofs/B56 ([`schlafli_error`]); on a degenerate face (`f = ½πx_m`)
/// within `SAFETY·2επ`. Each half-edge that does not is a witness.
pub fn verify_schlafli<T: Real>(
    mesh: &Mesh,
    lengths: &[T],
    half_angles: &[T],
    settings: &Settings,
) -> Verdict {
    if let Some(v) = check_lengths(mesh, lengths).or_else(|| lengths_out_of_range(lengths)) {
        return v;
    }
    if half_angles.len() != mesh.n_halfedges() {
        return Verdict::NotApplicable {
            reason: format!(
                "{} half-angles given for {} half-edges",
                half_angles.len(),
                mesh.n_halfedges()
            ),
        };
    }
    let ctx = lengths[0].ctx();
    let (e, bits) = (eps::<T>(ctx), T::precision_bits(ctx));
    let mut tally = Tally::new(false, bits);
    for f in mesh.faces() {
        let hs = mesh.face_halfedges(f);
        let x: [T; 3] = hs.map(|h| lengths[h.edge().idx()].ln() * &lengths[0].lit(2.0));
        let xf = x.clone().map(|v| v.approx_f64());
        let lf = shifted_lengths(&x).map(|v| v.approx_f64());
        let degenerate = matches!(shape(&shifted_lengths(&x)), Shape::Degenerate(_));
        for m in 0..3 {
            let xd: [Dual<T>; 3] = [0, 1, 2].map(|k| {
                let d = if k == m {
                    x[k].one_like()
                } else {
                    x[k].zero_like()
                };
                Dual::new(x[k].clone(), d)
            });
            let df = triangle_energy(&xd).d;
            let tol = if degenerate {
                SAFETY * 2.0 * e * std::f64::consts::PI
            } else {
                let a = angles_from_log_lengths(&xd);
                let af = [0, 1, 2].map(|k| a[k].v.approx_f64());
                let ad = [0, 1, 2].map(|k| a[k].d.approx_f64());
                let dir = [0, 1, 2].map(|k| if k == m { 1.0 } else { 0.0 });
                schlafli_error(xf, dir, lf, af, ad, bits, e)
            };
            let err = df - &half_angles[hs[m].idx()];
            tally.within(
                format!("{}", hs[m]),
                "∂f/∂x − α/2",
                &err,
                settings.slack * tol,
            );
        }
    }
    tally.verdict()
}
