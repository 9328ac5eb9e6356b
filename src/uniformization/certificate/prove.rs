//! Proof attempts for a computed solution (B71): the refinement at the certificate's
//! precision, then boxes of three radii around the refined `u`, for the binary64 lengths
//! of the solve or for a metric of `T₀` given at that precision and enclosed (B73 (a)).
//! The data of a box are checked by [`super::certificate`]. proof: B71

use super::certificate::{
    carry, check_carried, validate, Carried, CertificateData, CertificateError, CertificateOutcome,
    I,
};
use super::refine::{carry_lengths, carry_lengths_from, flip_to_delaunay_at, scaled};
use crate::mesh::Edge;
use crate::scalar::{Interval, Mpfr, Precision, Real};
use rug::Rational;
use std::borrow::Cow;

/// A proof attempt for a solution: the `u` and radius submitted and the outcome.
#[derive(Clone, Debug)]
pub struct Proof {
    /// The certificate data (exact `u` and radius).
    pub data: CertificateData,
    /// The outcome of [`check_certificate`] on it.
    pub outcome: CertificateOutcome,
    /// `max |Θ − θ|` at the submitted `u` (as computed by the refinement, `f64`).
    pub residual_max: f64,
}

/// The lengths of `T₀` of a metric the `f64` solve saw rounded: at one MPFR precision,
/// as MPFR numbers (for the refinement) and as enclosures (for the certificate).
#[derive(Clone, Debug)]
pub struct T0Metric {
    /// The lengths of `T₀`, rounded to the precision.
    pub values: Vec<Mpfr>,
    /// Enclosures of the exact lengths of `T₀`.
    pub enclosures: Vec<Interval<Mpfr>>,
    /// The Euclidean flips from the input triangulation to `T₀`, in order (an edge keeps
    /// its index when flipped).
    pub euclidean: Vec<Edge>,
}

/// Refine `sol` at `bits` of MPFR precision (to `tolerance`), then try to certify boxes of
/// radius `10⁶`, `10³` and `10¹⁰` times the residual's 2-norm estimate around the refined `u`
/// (exact rationals of the MPFR values); the first that holds, or the last outcome.
pub fn prove(
    sol: &super::newton::Uniformization,
    bits: u32,
    tolerance: f64,
) -> Result<Proof, CertificateError> {
    prove_on(sol, None, bits, tolerance)
}

/// [`prove`] for the metric `metric` on `T₀` instead of the binary64 lengths of the
/// solve: the refinement runs on `metric.values` and the certificate on
/// `metric.enclosures` ([`check_certificate_on`]), so a `Holds` is about that metric.
/// The certificate's flip sequence is the solve's followed by the refinement's (the
/// triangulation Delaunay at the refined `u`, B69).
pub fn prove_on(
    sol: &super::newton::Uniformization,
    metric: Option<&T0Metric>,
    bits: u32,
    tolerance: f64,
) -> Result<Proof, CertificateError> {
    let prec =
        Precision::new(u64::from(bits)).map_err(|_| CertificateError::Bits(u64::from(bits)))?;
    let l0 = match metric {
        None => sol
            .initial_lengths
            .iter()
            .map(|&x| Mpfr::from_f64(x, prec))
            .collect(),
        Some(m) => m.values.clone(),
    };
    let base0 = metric.map(|m| Cow::Borrowed(&m.enclosures[..]));
    refine_and_certify(sol, l0, base0, prec, bits, tolerance)
}

/// [`prove_on`] for the metric of `T₀` given by `values` (rounded to the precision of
/// `bits`) and `enclosures` (of its exact lengths), both consumed: the refinement takes
/// the values and the certificate carries the enclosures in place, so neither is copied
/// nor held through the certificate once it is no longer needed.
pub(crate) fn prove_on_owned(
    sol: &super::newton::Uniformization,
    values: Vec<Mpfr>,
    enclosures: Vec<I>,
    bits: u32,
    tolerance: f64,
) -> Result<Proof, CertificateError> {
    let prec =
        Precision::new(u64::from(bits)).map_err(|_| CertificateError::Bits(u64::from(bits)))?;
    refine_and_certify(
        sol,
        values,
        Some(Cow::Owned(enclosures)),
        prec,
        bits,
        tolerance,
    )
}

/// The refinement of `sol` at `prec` from the lengths `l0` of `T₀`, then the certificate
/// ([`certify_after_flips`]) for the metric enclosed by `base0` (`None`: the binary64
/// lengths of the solve). The refinement's state is dropped before the certificate.
fn refine_and_certify(
    sol: &super::newton::Uniformization,
    l0: Vec<Mpfr>,
    base0: Option<Cow<'_, [I]>>,
    prec: Precision,
    bits: u32,
    tolerance: f64,
) -> Result<Proof, CertificateError> {
    let (r, flips) = super::refine::refine_with_flips::<Mpfr>(sol, l0, prec, tolerance, 30)?;
    let u: Vec<Rational> =
        r.u.iter()
            .map(|x| x.to_rational().unwrap_or_default())
            .collect();
    let residual_max = r.residual_max();
    drop(r);
    certify_after_flips(sol, &flips, base0, u, residual_max, bits)
}

/// The certificate half of [`prove_on`] for a `u` refined elsewhere (e.g. in double-double,
/// which has no directed rounding: the proof is in `Interval<Mpfr>` at `bits`), whose
/// `max |Θ − θ|` was estimated as `residual_max`: boxes of radius `10⁶`, `10³` and `10¹⁰`
/// times `residual_max·√n` (at least `2^(10 − bits)`·those factors) around `u`; the first
/// that holds, or the last outcome. The triangulation is the solve's, Ptolemy-flipped to
/// the Delaunay triangulation at `u` (decided on MPFR values at `bits`; B69).
pub fn certify_near(
    sol: &super::newton::Uniformization,
    metric: Option<&T0Metric>,
    u: &[Rational],
    residual_max: f64,
    bits: u32,
) -> Result<Proof, CertificateError> {
    let prec =
        Precision::new(u64::from(bits)).map_err(|_| CertificateError::Bits(u64::from(bits)))?;
    if u.len() != sol.initial_mesh.n_vertices() {
        return Err(CertificateError::ScaleCount {
            expected: sol.initial_mesh.n_vertices(),
            got: u.len(),
        });
    }
    let (mut mesh, mut base) = match metric {
        None => carry_lengths::<Mpfr>(
            &sol.initial_mesh,
            &sol.initial_lengths,
            &sol.flip_sequence,
            prec,
        )?,
        Some(m) => carry_lengths_from(&sol.initial_mesh, m.values.clone(), &sol.flip_sequence)?,
    };
    let um: Vec<Mpfr> = u.iter().map(|q| Mpfr::from_rational(q, prec)).collect();
    let mut l = scaled(&mesh, &base, &um);
    let flips = flip_to_delaunay_at(&mut mesh, &mut base, &mut l, &um)?;
    drop((mesh, base, l, um));
    let base0 = metric.map(|m| Cow::Borrowed(&m.enclosures[..]));
    certify_after_flips(sol, &flips, base0, u.to_vec(), residual_max, bits)
}

/// [`certify_near`] on the solve's triangulation followed by the Ptolemy flips `flips`,
/// for the metric of `T₀` enclosed by `base0` (`None`: the solve's binary64 lengths). The
/// boxes differ in their radius only: the data are validated for each, the lengths carried
/// to the final triangulation once.
fn certify_after_flips(
    sol: &super::newton::Uniformization,
    flips: &[Edge],
    mut base0: Option<Cow<'_, [I]>>,
    u: Vec<Rational>,
    residual_max: f64,
    bits: u32,
) -> Result<Proof, CertificateError> {
    let n = sol.u.len().max(1) as f64;
    let floor = 2f64.powi(-(bits.min(1000) as i32) + 10);
    let estimate = (residual_max * n.sqrt()).max(floor);
    let mut flip_sequence = sol.flip_sequence.clone();
    flip_sequence.extend_from_slice(flips);
    let radius_of =
        |factor: f64| Rational::from_f64(estimate * factor).unwrap_or_else(|| Rational::from(1));
    let mut data = CertificateData {
        t0: sol.initial_mesh.clone(),
        l0: sol.initial_lengths.clone(),
        targets: sol.targets.clone(),
        flip_sequence,
        u,
        radius: radius_of(1e6),
    };
    let mut carried: Option<Carried> = None;
    let mut outcome = None;
    // 10⁶ first; then a smaller box (when the first left the Penner cell, e.g. near a
    // Delaunay tie) and a larger one (when the residual over μ exceeded the radius).
    for factor in [1e6, 1e3, 1e10] {
        data.radius = radius_of(factor);
        let prec = validate(&data, bits)?;
        let c = match carried.take() {
            Some(c) => c,
            None => carry(&data, base0.take(), prec)?,
        };
        let o = check_carried(&data, carried.insert(c));
        let done = matches!(o, CertificateOutcome::Holds { .. });
        outcome = Some(o);
        if done {
            break;
        }
    }
    Ok(Proof {
        data,
        outcome: outcome.expect("three attempts"),
        residual_max,
    })
}
