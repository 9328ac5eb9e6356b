//! Uniformization of a closed surface with prescribed cone angles (flat or cones, T24): the
//! pipeline behind `penner uniformize --flat | --targets`: the `f64`
//! solve with Ptolemy flips, refinement and a certificate about the **input's exact
//! metric** (B73 (a), B71), and the claim that `penner certify` re-checks.
//!
//! The solve sees the binary64 rounding of the input lengths (positions give square roots
//! of rational squared lengths, decimals may not be binary64). The certificate is first
//! attempted for the exact input: the solve's Euclidean flips to `T₀` are replayed on
//! enclosures of the exact lengths, each admitted only on a certified strictly convex
//! quadrilateral ([`input_on_t0`](crate::uniformization::input_metric::input_on_t0)), the refinement runs on the input lengths and the ball
//! argument on their enclosures. Only when that replay is refused (a flip whose
//! quadrilateral is not certified strictly convex for the exact lengths, e.g. an exact tie)
//! or its box does not hold is the binary64-rounded metric certified instead, and the
//! outcome says so ([`CertifiedMetric::Rounded`]).
//!
//! ```
//! use penner::io::Surface;
//! use penner::mesh::builders;
//! use penner::uniformization::pipeline::{uniformize_closed, CertifiedMetric, Options};
//! use penner::uniformization::Targets;
//! use rug::Rational;
//! // The regular tetrahedron at integer positions: edge lengths √8, not binary64 numbers.
//! let s = Surface::from_embedded("tetrahedron", builders::tetrahedron()).unwrap();
//! let t = Targets::from_multiples_of_pi(vec![Rational::from(1); 4]); // cone angles π
//! let out = uniformize_closed(&s, &t, &Options::default(), &mut |_| {}).unwrap();
//! assert!(out.certified());
//! assert_eq!(out.metric, Some(CertifiedMetric::Input));
//! assert!(out.claim().unwrap()["euclidean_flips"].is_array());
//! ```

use super::{exact, rescaled, rescaled_owned, CertifiedMetric, Options, PipelineError, Precision};
use crate::io::json::edge_order;
use crate::io::Surface;
use crate::mesh::Edge;
use crate::scalar::{Dd, Interval, Mpfr, Precision as Bits, Real};
use crate::uniformization::certificate::{certify_near, prove, prove_on_owned, CertificateError};
use crate::uniformization::certificate::{CertificateOutcome, Proof, T0Metric};
use crate::uniformization::claim_form::ClaimJson;
use crate::uniformization::input_metric::{
    clearly_not_delaunay, euclidean_sequence, negative_on_enclosures, replay_enclosed,
    replay_values, t0_delaunay_on_input,
};
use crate::uniformization::newton::{uniformize_with_progress, StepReport, Uniformization};
use crate::uniformization::refine::{refine, refine_on};
use crate::uniformization::{Targets, UniformizeOptions};
use serde_json::Value;

/// The outcome of [`uniformize_closed`].
#[derive(Clone, Debug)]
pub struct ClosedOutcome {
    /// The surface solved: the input divided by `2^shift` exactly when its lengths are far
    /// from 1 (uniformization is scale invariant; `u` does not change).
    pub surface: Surface,
    /// The exact power of two the lengths were divided by (0: none).
    pub shift: i64,
    /// The `f64` solve (T₀, the Ptolemy flips, `u`, the residual, the stop reason).
    pub solution: Uniformization,
    /// The refinement and certificate, when the solve converged and a certificate was
    /// asked for.
    pub proof: Option<Proof>,
    /// The metric the certificate is about (with `proof`).
    pub metric: Option<CertifiedMetric>,
    /// The certificate's interval bits.
    pub bits: u32,
    /// The Euclidean flips to `T₀` of the input-metric replay, kept for the claim.
    euclidean: Option<Vec<Edge>>,
}

impl ClosedOutcome {
    /// Whether an exact solution was proved to exist near the refined `u`.
    pub fn certified(&self) -> bool {
        matches!(
            self.proof.as_ref().map(|p| &p.outcome),
            Some(CertificateOutcome::Holds { .. })
        )
    }

    /// The `uniformization` claim of a certified outcome, ready to write: about the input
    /// surface as given with its Euclidean flips (`euclidean_flips`) for
    /// [`CertifiedMetric::Input`], about `T₀` with binary64 lengths otherwise.
    pub fn claim(&self) -> Option<Value> {
        self.claim_json().map(|c| c.value())
    }

    /// The claim of [`Self::claim`] as a view to serialize straight into a file
    /// ([`ClaimJson`]: the same text, without building the value).
    pub fn claim_json(&self) -> Option<ClaimJson<'_>> {
        claim_json(
            self.proof.as_ref()?,
            self.metric.as_ref()?,
            self.euclidean.as_deref(),
            &self.surface,
            self.bits,
        )
    }
}

/// Uniformize the closed `surface` to the cone angles `targets` (module documentation):
/// the solve (calling `progress` after every Newton step), then, when it converged and
/// `options.certify`, the refinement and the certificate, for the input's exact metric
/// where possible.
pub fn uniformize_closed(
    surface: &Surface,
    targets: &Targets,
    options: &Options,
    progress: &mut dyn FnMut(&StepReport),
) -> Result<ClosedOutcome, PipelineError> {
    let (surface, shift, lengths) = rescaled(surface);
    solve_and_certify(surface, shift, &lengths, targets, options, progress)
}

/// [`uniformize_closed`] for an owned surface, which the outcome keeps as its
/// [`ClosedOutcome::surface`] (not a copy) when it needs no rescaling.
pub fn uniformize_closed_owned(
    surface: Surface,
    targets: &Targets,
    options: &Options,
    progress: &mut dyn FnMut(&StepReport),
) -> Result<ClosedOutcome, PipelineError> {
    let (surface, shift, lengths) = rescaled_owned(surface);
    solve_and_certify(surface, shift, &lengths, targets, options, progress)
}

/// [`uniformize_closed`] on `surface`, already divided by `2^shift`, with its binary64
/// lengths `lengths`.
fn solve_and_certify(
    surface: Surface,
    shift: i64,
    lengths: &[f64],
    targets: &Targets,
    options: &Options,
    progress: &mut dyn FnMut(&StepReport),
) -> Result<ClosedOutcome, PipelineError> {
    let solution = uniformize_with_progress(
        &surface.mesh,
        lengths,
        targets,
        &UniformizeOptions::default(),
        progress,
    )?;
    let (bits, _) = options.precision.bits_and_tolerance();
    let mut out = ClosedOutcome {
        surface,
        shift,
        solution,
        proof: None,
        metric: None,
        bits,
        euclidean: None,
    };
    if !out.solution.converged() || !options.certify {
        return Ok(out);
    }
    let c = certify_solution(&out.surface, lengths, &out.solution, options.precision)?;
    out.proof = Some(c.proof);
    out.metric = Some(c.metric);
    out.euclidean = c.euclidean;
    Ok(out)
}

/// A proof attempt by [`certify_solution`], the metric it is about, and (for the input
/// metric) the replay to `T₀` that the claim records.
#[derive(Clone, Debug)]
pub struct Certification {
    /// The refinement and certificate outcome.
    pub proof: Proof,
    /// The metric the proof is about.
    pub metric: CertifiedMetric,
    /// The Euclidean flips to `T₀` (for the input metric).
    euclidean: Option<Vec<Edge>>,
}

impl Certification {
    /// The `uniformization` claim when the proof holds: about `surface` (the closed
    /// surface given to [`certify_solution`]) with its Euclidean flips for the input
    /// metric, about `T₀` with binary64 lengths otherwise.
    pub fn claim(&self, surface: &Surface, bits: u32) -> Option<Value> {
        self.claim_json(surface, bits).map(|c| c.value())
    }

    /// The claim of [`Self::claim`] as a view to serialize straight into a file.
    pub fn claim_json<'a>(&'a self, surface: &'a Surface, bits: u32) -> Option<ClaimJson<'a>> {
        claim_json(
            &self.proof,
            &self.metric,
            self.euclidean.as_deref(),
            surface,
            bits,
        )
    }
}

/// The `uniformization` claim of `proof` when it holds (B71): about `surface` with its
/// Euclidean flips to `T₀` for the input metric, about `T₀` with binary64 lengths
/// otherwise; the final triangulation is that of the proof's own flips (the refinement may
/// flip near ties differently from the f64 solve, B69), which is what the re-check replays.
fn claim_json<'a>(
    proof: &'a Proof,
    metric: &CertifiedMetric,
    euclidean: Option<&'a [Edge]>,
    surface: &'a Surface,
    bits: u32,
) -> Option<ClaimJson<'a>> {
    let CertificateOutcome::Holds { residual, .. } = &proof.outcome else {
        return None;
    };
    let mut last = proof.data.t0.clone();
    for &e in &proof.data.flip_sequence {
        last.flip(e).ok()?;
    }
    let final_faces = last.face_list();
    Some(match (metric, euclidean) {
        (CertifiedMetric::Input, Some(euclidean)) => ClaimJson::on_input(
            &proof.data,
            surface,
            euclidean,
            final_faces,
            *residual,
            bits,
        ),
        _ => ClaimJson::rounded(&proof.data, final_faces, *residual, bits),
    })
}

/// Refine and certify a converged closed-surface solve `sol` of `surface` (whose binary64
/// lengths `lengths` the solve was given, on `surface.mesh`) at `precision`: for the
/// input's exact metric when its Euclidean flips to `T₀` replay on enclosures and `T₀` is
/// certified Delaunay for it and the box holds, otherwise for the binary64-rounded metric,
/// with the reason (module documentation).
pub fn certify_solution(
    surface: &Surface,
    lengths: &[f64],
    sol: &Uniformization,
    precision: Precision,
) -> Result<Certification, PipelineError> {
    let (bits, tolerance) = precision.bits_and_tolerance();
    let prec = Bits::new(u64::from(bits)).map_err(|_| CertificateError::Bits(bits.into()))?;
    let replay = input_metric_on_t0(surface, lengths, sol, prec);
    let reason = match replay {
        Ok(m) => {
            let (proof, euclidean) = if precision == Precision::Dd {
                let l0 = m
                    .values
                    .iter()
                    .map(|x| Dd::from_rational(&x.to_rational().unwrap_or_default(), ()))
                    .collect();
                let r =
                    refine_on::<Dd>(sol, l0, (), tolerance, 30).map_err(CertificateError::from)?;
                let proof = certify_near(sol, Some(&m), &exact(&r.u), r.residual_max(), bits)?;
                (proof, m.euclidean)
            } else {
                // The metric's values and enclosures are consumed by the refinement and
                // the certificate; only its Euclidean flips are kept.
                let T0Metric {
                    values,
                    enclosures,
                    euclidean,
                } = m;
                let proof = prove_on_owned(sol, values, enclosures, bits, tolerance)?;
                (proof, euclidean)
            };
            match proof.outcome {
                CertificateOutcome::Holds { .. } => {
                    return Ok(Certification {
                        proof,
                        metric: CertifiedMetric::Input,
                        euclidean: Some(euclidean),
                    })
                }
                CertificateOutcome::Undecided { reason } => reason,
            }
        }
        Err(reason) => reason,
    };
    let proof = match precision {
        Precision::Dd => {
            let r = refine::<Dd>(sol, (), tolerance, 30).map_err(CertificateError::from)?;
            certify_near(sol, None, &exact(&r.u), r.residual_max(), bits)?
        }
        _ => prove(sol, bits, tolerance)?,
    };
    Ok(Certification {
        proof,
        metric: CertifiedMetric::Rounded { reason },
        euclidean: None,
    })
}

/// The input's exact metric on `T₀` ([`input_on_t0`](crate::uniformization::input_metric::input_on_t0))
/// when `T₀` is certified intrinsic Delaunay for it ([`t0_delaunay_for_input`]), else the
/// reason. The rounded lengths of `T₀` come first (cheap): when they make an edge of `T₀`
/// clearly not Delaunay ([`clearly_not_delaunay`]), that edge is decided on the enclosures
/// carried through the flips it depends on only ([`negative_on_enclosures`]); certified
/// negative, the input's metric cannot be certified (not by the enclosures, not by the
/// exact replay) and the answer is the one of the full replay, without carrying every
/// enclosure to `T₀` nor replaying on the exact metric.
fn input_metric_on_t0(
    surface: &Surface,
    lengths: &[f64],
    sol: &Uniformization,
    prec: Bits,
) -> Result<T0Metric, String> {
    let euclidean = euclidean_sequence(sol, &surface.mesh, lengths)?;
    let mut values = surface.lengths::<Mpfr>(prec);
    let carried = replay_values(&surface.mesh, &mut values, &euclidean);
    let mut enclosures = surface.lengths::<Interval<Mpfr>>(prec);
    let candidate = carried
        .is_ok()
        .then(|| clearly_not_delaunay(&sol.initial_mesh, &values, &euclidean))
        .flatten();
    if let Some(e) = candidate {
        if negative_on_enclosures(&surface.mesh, &mut enclosures, &euclidean, e) {
            return Err(not_delaunay_reason(surface, e));
        }
    }
    let (_, enclosures) = replay_enclosed(&surface.mesh, enclosures, &euclidean)?;
    carried?;
    t0_delaunay_for_input(
        surface,
        sol,
        T0Metric {
            values,
            enclosures,
            euclidean,
        },
    )
}

/// Why the input's exact metric is not certified: edge `e` of `T₀` (of `surface.mesh`).
fn not_delaunay_reason(surface: &Surface, e: Edge) -> String {
    let k = edge_order(&surface.mesh)
        .iter()
        .position(|&x| x == e.idx())
        .unwrap_or(e.idx());
    format!("edge {k} of T₀ is not certified intrinsic Delaunay for the input's exact metric")
}

/// `m`, when `T₀` is certified intrinsic Delaunay for the input's exact metric (exactly
/// where its squared lengths are known, [`exact_squared_on_t0`]; on the enclosures
/// elsewhere): the decorated metric of the certificate is then the input's (B73 (a)).
fn t0_delaunay_for_input(
    surface: &Surface,
    sol: &Uniformization,
    m: T0Metric,
) -> Result<T0Metric, String> {
    match t0_delaunay_on_input(surface, &sol.initial_mesh, &m.enclosures, &m.euclidean) {
        Ok(()) => Ok(m),
        Err(e) => Err(not_delaunay_reason(surface, e)),
    }
}
