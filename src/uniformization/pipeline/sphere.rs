//! Uniformization to the sphere (notes Thm 9; B74–B76, B93): the conformally equivalent
//! convex polyhedron inscribed in the unit sphere, the pipeline behind `penner uniformize
//! --sphere`. The disk problem (the surface punctured at a pole, its star flattened) is
//! certified for the surface's **exact** metric: the Euclidean flips replayed on
//! enclosures (B73), B76 on the disk, and the `sphere_uniformization` claim re-checked
//! from scratch before it is returned (B90). The planar layout is checked Delaunay and
//! convex by exact predicates on its binary64 coordinates; the 3-D positions and the
//! cross-ratio comparison are numerical.
//!
//! ```
//! use penner::io::Surface;
//! use penner::mesh::builders;
//! use penner::uniformization::pipeline::{uniformize_sphere, Options};
//! let s = Surface::from_embedded("octahedron", builders::octahedron()).unwrap();
//! let out = uniformize_sphere(&s, None, &Options::default()).unwrap();
//! assert!(out.certified());
//! assert_eq!(out.claim.as_ref().unwrap()["kind"], "sphere_uniformization");
//! ```

use super::{rescaled, Options, PipelineError, Precision};
use crate::io::Surface;
use crate::scalar::{Interval, Mpfr, Precision as Bits};
use crate::uniformization::certificate::CertificateOutcome;
use crate::uniformization::dirichlet_certificate::{certify_disk_near, DiskCertificateData};
use crate::uniformization::sphere::SphereUniformization;
use crate::uniformization::sphere::{uniformize_sphere as solve, SphereOptions};
use crate::uniformization::sphere_checks::PlanarDelaunay;
use crate::uniformization::sphere_checks::{cross_ratio_deviation, planar_delaunay};
use crate::uniformization::sphere_claim::{claim_of, recheck, to_json};
use crate::uniformization::sphere_refine::{input_disk_metric, prove_disk};
use serde_json::Value;

/// The outcome of [`uniformize_sphere`].
#[derive(Clone, Debug)]
pub struct SphereOutcome {
    /// The surface solved (the input divided by `2^shift` exactly when its lengths are far
    /// from 1).
    pub surface: Surface,
    /// The exact power of two the lengths were divided by (0: none).
    pub shift: i64,
    /// The solve: `T₀`, the pole, the disk problem's `u`, flips and residual, the layout
    /// and the inscribed positions.
    pub solution: SphereUniformization,
    /// `max |2π − θ|` after the MPFR refinement and its steps (when refined).
    pub refinement: Option<(f64, usize)>,
    /// The disk certificate, re-checked as the claim (when asked for).
    pub certificate: Option<CertificateOutcome>,
    /// The `sphere_uniformization` claim when the certificate holds, ready to write.
    pub claim: Option<Value>,
    /// The planar layout checked by exact predicates on its binary64 coordinates.
    pub planar: PlanarDelaunay,
    /// Numerical: `max |log c(chords) − log c(input)|` over the final edges.
    pub deviation: Option<f64>,
    /// The certificate's interval bits.
    pub bits: u32,
}

impl SphereOutcome {
    /// Whether the disk problem is certified for the exact metric and the planar layout is
    /// Delaunay and convex.
    pub fn certified(&self) -> bool {
        matches!(self.certificate, Some(CertificateOutcome::Holds { .. })) && self.planar.holds()
    }
}

/// Uniformize the closed genus-0 `surface` to the sphere, with the pole `pole` (default:
/// the candidates of `T₀` in turn), then certify the disk problem for the exact metric
/// (module documentation). `Precision::F64` certifies the solve's `u` at 128 bits;
/// MPFR bits refine first; double-double is [`PipelineError::Unsupported`].
pub fn uniformize_sphere(
    surface: &Surface,
    pole: Option<u32>,
    options: &Options,
) -> Result<SphereOutcome, PipelineError> {
    if options.precision == Precision::Dd {
        return Err(PipelineError::Unsupported(
            "--precision dd is not implemented for --sphere; use f64 or MPFR bits (128..=4096)"
                .into(),
        ));
    }
    let (surface, shift, lengths) = rescaled(surface);
    let opts = SphereOptions {
        pole,
        ..SphereOptions::default()
    };
    let solution = solve(&surface.mesh, &lengths, &opts)?;
    let (bits, _) = options.precision.bits_and_tolerance();
    let planar = planar_delaunay(&solution.solution.mesh, &solution.planar);
    let deviation = cross_ratio_deviation(&solution, &solution.initial_lengths);
    let mut out = SphereOutcome {
        surface,
        shift,
        solution,
        refinement: None,
        certificate: None,
        claim: None,
        planar,
        deviation,
        bits,
    };
    if options.certify {
        let (certificate, claim) = certify(&mut out, options.precision);
        out.certificate = Some(certificate);
        out.claim = claim;
    }
    Ok(out)
}

/// The disk certificate of `out`'s solve for the exact metric, re-checked as the claim.
fn certify(out: &mut SphereOutcome, precision: Precision) -> (CertificateOutcome, Option<Value>) {
    let bits = out.bits;
    let attempt = disk_certificate(out, precision);
    let undecided = |reason: String| (CertificateOutcome::Undecided { reason }, None);
    match attempt {
        Ok((data, CertificateOutcome::Holds { residual, .. })) => {
            let claim = claim_of(&out.surface, &out.solution, &data, residual);
            match recheck(&out.surface, &claim, bits) {
                Ok(outcome @ CertificateOutcome::Holds { .. }) => {
                    let doc = to_json(&out.surface, &claim, bits);
                    (outcome, Some(doc))
                }
                Ok(other) => (other, None),
                Err(e) => undecided(format!("the certificate does not re-check: {e}")),
            }
        }
        Ok((_, undecided_outcome)) => (undecided_outcome, None),
        Err(reason) => undecided(reason),
    }
}

/// The disk certificate data and outcome near the `f64` solution (at `F64`) or its MPFR
/// refinement (recorded in `out.refinement`); `Err(reason)` when the exact metric cannot
/// be replayed to `T₀` or the refinement fails.
fn disk_certificate(
    out: &mut SphereOutcome,
    precision: Precision,
) -> Result<(DiskCertificateData, CertificateOutcome), String> {
    let (bits, tolerance) = precision.bits_and_tolerance();
    let prec = Bits::new(u64::from(bits)).map_err(|e| e.to_string())?;
    let sol = &out.solution;
    let enclosures = out.surface.lengths::<Interval<Mpfr>>(prec);
    let metric = input_disk_metric(sol, &out.surface.mesh, enclosures)?;
    if precision == Precision::F64 {
        let Some(u) = sol
            .solution
            .u
            .iter()
            .map(|&x| rug::Rational::from_f64(x))
            .collect::<Option<Vec<rug::Rational>>>()
        else {
            return Err("a value of the computed u is not finite".into());
        };
        let residual = sol.solution.residual_max.max(4.0 * f64::EPSILON);
        return Ok(certify_disk_near(sol, Some(&metric), &u, residual, bits));
    }
    let proof = prove_disk(sol, Some(&metric), prec, tolerance).map_err(|e| e.to_string())?;
    out.refinement = Some((
        proof.history.last().copied().unwrap_or(f64::NAN),
        proof.history.len().saturating_sub(1),
    ));
    Ok((proof.data, proof.outcome))
}
