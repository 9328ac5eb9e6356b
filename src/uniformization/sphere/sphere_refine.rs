//! Mixed-precision refinement of the sphere target's disk problem and its certificate at
//! high precision. proof: B91
//!
//! The disk's metric in MPFR (the midpoints of enclosures of the exact input replayed to
//! `T₀`, B73 (a), or the binary64 lengths of the solve), the Hessian on the free disk
//! vertices factored once in `f64`, the residuals `2π − θ(u)` in MPFR
//! ([`super::refine::refine_problem`]); nothing is factored in MPFR. The refined `u`,
//! taken exactly, is then certified (B76 on the enclosed metric,
//! [`super::dirichlet_certificate::certify_disk_near`]): the refinement itself proves
//! nothing.

use super::certificate::{CertificateOutcome, I};
use super::dirichlet::free_index;
use super::dirichlet_certificate::{certify_disk_near, DiskCertificateData, DiskMetric};
use super::input_metric::replay_enclosed;
use super::refine::{carry_lengths_from, refine_problem, Problem, RefineError, Refinement};
use super::sphere::SphereUniformization;
use crate::scalar::{Mpfr, Precision, Real};
use rug::Rational;

/// The exact input metric of `sol` as a [`DiskMetric`]: `enclosures` enclose the lengths of
/// the surface `sol` was solved from (on its triangulation `mesh`), replayed through the
/// solve's Euclidean flips with certified convex quadrilaterals (B73 (a)), then through its
/// Ptolemy flips up to the last flip at the pole ([`DiskMetric::of_solution`], B93).
/// `Err(reason)` when a flip is not admitted or the flips do not reach the solve's `T₀`.
pub fn input_disk_metric(
    sol: &SphereUniformization,
    mesh: &crate::mesh::Mesh,
    enclosures: Vec<I>,
) -> Result<DiskMetric, String> {
    let (t0, l0) = replay_enclosed(mesh, enclosures, &sol.euclidean_sequence)?;
    if t0.face_list() != sol.initial_mesh.face_list() {
        return Err("the Euclidean flips do not reproduce the solve's T₀".into());
    }
    DiskMetric::of_solution(sol, l0)
}

/// The midpoint of an enclosure, in MPFR.
fn mid(x: &I) -> Mpfr {
    (x.lo().clone() + x.hi()) * &x.lo().lit(0.5)
}

/// Refine the disk problem of `sol` in MPFR at `prec` to `max |2π − θ| ≤ tolerance` over
/// the free vertices (at most `max_iterations` steps), for `metric` (midpoints) or, when
/// `None`, the binary64 lengths of `T₀` (carried through the flips at the pole in
/// intervals when there are any, as the certificate takes them). The Dirichlet values are
/// `−2 log ℓ_{a v∞}` in MPFR.
pub fn refine_disk(
    sol: &SphereUniformization,
    metric: Option<&DiskMetric>,
    prec: Precision,
    tolerance: f64,
    max_iterations: usize,
) -> Result<Refinement<Mpfr>, RefineError> {
    let disk = &sol.disk;
    let own = if metric.is_none() && sol.star_prefix > 0 {
        let l0 = sol
            .initial_lengths
            .iter()
            .map(|&x| I::from_f64(x, prec))
            .collect();
        Some(
            DiskMetric::of_solution(sol, l0).map_err(|_| RefineError::Replay {
                index: 0,
                edge: sol.flip_sequence.first().map_or(0, |e| e.0),
            })?,
        )
    } else {
        None
    };
    let metric = metric.or(own.as_ref());
    let (lengths, pole): (Vec<Mpfr>, Vec<Option<Mpfr>>) = match metric {
        Some(m) => (
            m.lengths.iter().map(mid).collect(),
            m.pole_length.iter().map(|l| l.as_ref().map(mid)).collect(),
        ),
        None => (
            disk.lengths
                .iter()
                .map(|&x| Mpfr::from_f64(x, prec))
                .collect(),
            disk.pole_length
                .iter()
                .map(|l| l.map(|x| Mpfr::from_f64(x, prec)))
                .collect(),
        ),
    };
    let (mut mesh, mut base) =
        carry_lengths_from(&disk.mesh, lengths, &sol.solution.flip_sequence)?;
    let minus_two = Mpfr::from_f64(-2.0, prec);
    let u: Vec<Mpfr> = sol
        .solution
        .u
        .iter()
        .zip(&pole)
        .map(|(&x, l)| match l {
            Some(l) => l.clone().ln() * &minus_two,
            None => Mpfr::from_f64(x, prec),
        })
        .collect();
    let (free, free_idx) = free_index(&sol.fixed);
    let two_pi = Mpfr::pi(prec) * &Mpfr::from_f64(2.0, prec);
    let theta_target = vec![two_pi; u.len()];
    // The star of v∞ may not flip: the disk's triangulation stays fixed (B74, B91).
    let problem = Problem {
        mesh: &mut mesh,
        base: &mut base,
        free: &free,
        free_idx: &free_idx,
        theta_target: &theta_target,
        measured: &free,
        keep_delaunay: false,
    };
    refine_problem(problem, u, prec, tolerance, max_iterations).map(|(r, _)| r)
}

/// The result of [`prove_disk`].
#[derive(Clone, Debug)]
pub struct DiskProof {
    /// The certificate data at the refined `u`.
    pub data: DiskCertificateData,
    /// Its outcome.
    pub outcome: CertificateOutcome,
    /// `max |2π − θ|` at the refined `u` (estimated in MPFR, as `f64`), after each step.
    pub history: Vec<f64>,
}

/// Refine at `prec` ([`refine_disk`], tolerance `tolerance`, 30 steps), then certify the
/// refined `u` in interval arithmetic at the same precision for `metric`
/// ([`certify_disk_near`]). proof: B91, B76
pub fn prove_disk(
    sol: &SphereUniformization,
    metric: Option<&DiskMetric>,
    prec: Precision,
    tolerance: f64,
) -> Result<DiskProof, RefineError> {
    let bits = prec.bits();
    let r = refine_disk(sol, metric, prec, tolerance, 30)?;
    let u: Vec<Rational> =
        r.u.iter()
            .map(|x| x.to_rational().unwrap_or_default())
            .collect();
    let (data, outcome) = certify_disk_near(sol, metric, &u, r.residual_max(), bits);
    Ok(DiskProof {
        data,
        outcome,
        history: r.history,
    })
}
