//! T27 (notes §1.6.2, Eq. 15): the shear coordinate `2 s_ij = λ_jk − λ_ki + λ_il − λ_lj`
//! of the Penner coordinates `λ = 2 log ℓ` equals `log c_ij`, with the length cross ratio
//! `c_ij = ℓ_il ℓ_jk / (ℓ_ki ℓ_lj)` (docs/catalogue.md §4, §6).
//!
//! Numerical, at MPFR precision `p` with `u = 2⁻ᵖ`: the two evaluations may differ by at
//! most `8u (Σ|ln ℓ| + |ln c| + 1)` (proof: B64).

use super::bounds::eps;
use super::report::Tally;
use super::{Settings, Verdict};
use crate::mesh::Mesh;
use crate::predicates::delaunay::QuadEdges;
use crate::scalar::{Mpfr, Real};

/// Compare shear (from Penner coordinates) with the log cross ratio on every interior edge.
pub fn check_shear_log_cross_ratio(mesh: &Mesh, lengths: &[Mpfr], settings: &Settings) -> Verdict {
    verify_shear_log_cross_ratio(mesh, lengths, lengths, settings)
}

/// The comparison of T27 with the two sides taken from possibly different metrics: the
/// shear `s_ij` from the Penner coordinates of `shear_lengths`, the cross ratio `c_ij` from
/// `ratio_lengths` (the theorem is the case of one metric), with the tolerance of B64.
pub fn verify_shear_log_cross_ratio(
    mesh: &Mesh,
    shear_lengths: &[Mpfr],
    ratio_lengths: &[Mpfr],
    settings: &Settings,
) -> Verdict {
    let lengths = shear_lengths;
    if lengths.len() != mesh.n_edges()
        || ratio_lengths.len() != mesh.n_edges()
        || lengths.is_empty()
    {
        return Verdict::NotApplicable {
            reason: "one length per edge is required".into(),
        };
    }
    // 8u = ε/2 with ε = 16u carried scaled by 2^s (proofs/B40 "Range", B64).
    let half_eps = 0.5 * eps::<Mpfr>(lengths[0].ctx());
    let mut tally = Tally::new(false, Mpfr::precision_bits(lengths[0].ctx()));
    for e in mesh.edges() {
        let Some(q) = QuadEdges::of(mesh, e) else {
            continue;
        };
        let l = q.lengths(lengths);
        let lam = |x: &Mpfr| x.ln() * &x.lit(2.0);
        let two_s = lam(l.jk) - &lam(l.ki) + &lam(l.il) - &lam(l.lj);
        let s = two_s / &l.ij.lit(2.0);
        let r = q.lengths(ratio_lengths);
        let c = (r.il.clone() * r.jk) / &(r.ki.clone() * r.lj);
        let log_c = c.ln();
        let sum_abs: f64 = [l.jk, l.ki, l.il, l.lj]
            .iter()
            .map(|x| x.ln().abs().approx_f64())
            .sum();
        // proof: B64
        let tol = settings.slack * half_eps * (sum_abs + log_c.abs().approx_f64() + 1.0);
        tally.within(e.to_string(), "shear − log cross ratio", &(s - &log_c), tol);
    }
    tally.verdict()
}
