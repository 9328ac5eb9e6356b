//! The hyperbolic target (notes Thm 11; B38, B39, B87, B89, B104), the pipeline behind
//! `penner uniformize --hyperbolic`: the input lengths, rounded to binary64, are read as
//! hyperbolic lengths; geometric flips to hyperbolic Delaunay, Newton over Penner cells
//! with Ptolemy flips, refinement (double-double or MPFR), the residual enclosed in MPFR
//! intervals and an existence radius (B39). The certificate is about the binary64 lengths:
//! the input's exact metric when every length is a binary64 number (JSON numbers, or
//! decimals that happen to be), else [`CertifiedMetric::Rounded`] with the first edge that
//! is not. The Gauss–Bonnet area by L'Huilier is numerical.
//!
//! ```
//! use penner::io::{Metric, Surface};
//! use penner::mesh::builders;
//! use penner::uniformization::pipeline::{uniformize_hyperbolic, Options};
//! use rug::Rational;
//! // The genus-2 surface with every length 3/2 (a binary64 number): flat targets 2π.
//! let m = builders::genus(2).unwrap();
//! let l = Metric::Lengths(vec![Rational::from((3, 2)); m.n_edges()]);
//! let s = Surface::new("genus 2", m, l, None).unwrap();
//! let out = uniformize_hyperbolic(&s, None, &Options::default()).unwrap();
//! assert!(out.certified());
//! assert!(out.claim().is_some());
//! ```

use super::{finite_u, CertifiedMetric, Options, PipelineError, Precision};
use crate::io::json::edge_order;
use crate::io::{Metric, Surface};
use crate::scalar::{Dd, Mpfr, Precision as Bits, Real};
use crate::uniformization::hyperbolic::{
    uniformize_hyperbolic as solve, HyperbolicOptions, HyperbolicUniformization,
};
use crate::uniformization::hyperbolic_certificate::{
    certify_hyperbolic, refine_hyperbolic, total_area_lhuilier, Existence, HyperbolicCertificate,
};
use crate::uniformization::hyperbolic_claim::{to_claim, ClaimData};
use crate::uniformization::Targets;
use rug::Rational;
use serde_json::Value;

/// The outcome of [`uniformize_hyperbolic`].
#[derive(Clone, Debug)]
pub struct HyperbolicOutcome {
    /// The solve: `T₀` after the geometric flips, the Ptolemy flips, `u`, the residual.
    pub solution: HyperbolicUniformization,
    /// The refined `u` (exact values of the working precision's numbers) and its
    /// `max |Θ − θ|`, when converged and a certificate was asked for.
    pub refined: Option<(Vec<Rational>, f64)>,
    /// The residual enclosure and the existence radius (B39).
    pub certificate: Option<HyperbolicCertificate>,
    /// The metric the certificate is about.
    pub metric: CertifiedMetric,
    /// Numerical: the total area by L'Huilier's formula (`None` when a face is not a
    /// triangle at the solution).
    pub area: Option<f64>,
    /// Numerical: `Σ(2π − Θ_i) − 2πχ`, the area Gauss–Bonnet asks for.
    pub gauss_bonnet: f64,
    /// The certificate's interval bits.
    pub bits: u32,
}

impl HyperbolicOutcome {
    /// Whether an exact solution was proved to exist near the refined `u`.
    pub fn certified(&self) -> bool {
        self.certificate
            .as_ref()
            .is_some_and(|c| matches!(c.existence, Existence::Holds { .. }))
    }

    /// The `hyperbolic_uniformization` claim of a certified outcome, ready to write.
    pub fn claim(&self) -> Option<Value> {
        let cert = self.certificate.as_ref()?;
        let Existence::Holds { radius, .. } = &cert.existence else {
            return None;
        };
        let (u, _) = self.refined.as_ref()?;
        let sol = &self.solution;
        let data = ClaimData {
            mesh: &sol.t0,
            lengths: &sol.lengths,
            flips: &sol.flips,
            targets: &sol.targets,
            u,
        };
        Some(to_claim(&data, *radius, cert.residual_norm2, self.bits))
    }
}

/// Uniformize the closed `surface` (its lengths read as hyperbolic lengths) to the cone
/// angles `targets` (default: `2π` everywhere), then refine at `options.precision` and
/// certify (module documentation).
pub fn uniformize_hyperbolic(
    surface: &Surface,
    targets: Option<&Targets>,
    options: &Options,
) -> Result<HyperbolicOutcome, PipelineError> {
    let mesh = &surface.mesh;
    let lengths: Vec<f64> = surface.lengths::<f64>(());
    let targets = targets.map_or_else(|| Targets::flat(mesh.n_vertices()), Clone::clone);
    let solution = solve(mesh, &lengths, &targets, &HyperbolicOptions::default())?;
    let (bits, tolerance) = options.precision.bits_and_tolerance();
    let area = total_area_lhuilier(&solution.mesh, &solution.scaled_lengths());
    let k: f64 = targets
        .over_pi()
        .iter()
        .map(|q| (2.0 - q.to_f64()) * std::f64::consts::PI)
        .sum();
    let gauss_bonnet = k - 2.0 * std::f64::consts::PI * mesh.euler_characteristic() as f64;
    let mut out = HyperbolicOutcome {
        metric: binary64_metric(surface),
        solution,
        refined: None,
        certificate: None,
        area,
        gauss_bonnet,
        bits,
    };
    if !out.solution.converged() || !options.certify {
        return Ok(out);
    }
    let sol = &out.solution;
    let not_computed = |e: crate::uniformization::hyperbolic::HyperbolicError| {
        PipelineError::NotComputed(format!("not certified: the refinement failed: {e}"))
    };
    let refined = match options.precision {
        Precision::F64 => (
            finite_u(sol.u.iter().map(|&x| Rational::from_f64(x)))?,
            sol.residual_max,
        ),
        Precision::Dd => {
            let r = refine_hyperbolic::<Dd>(sol, (), tolerance, 30).map_err(not_computed)?;
            (
                finite_u(r.u.iter().map(Real::to_rational))?,
                r.residual_max(),
            )
        }
        Precision::Mpfr(b) => {
            let prec = Bits::new(u64::from(b))
                .map_err(|_| PipelineError::Unsupported(format!("{b} bits out of range")))?;
            let r = refine_hyperbolic::<Mpfr>(sol, prec, tolerance, 60).map_err(not_computed)?;
            (
                finite_u(r.u.iter().map(Real::to_rational))?,
                r.residual_max(),
            )
        }
    };
    out.certificate = Some(certify_hyperbolic(sol, &refined.0, bits)?);
    out.refined = Some(refined);
    Ok(out)
}

/// [`CertifiedMetric::Input`] when every length of `surface` is a binary64 number (the
/// solve and the certificate see it exactly), else `Rounded`, naming the first edge (in
/// the input's edge order) that is not.
fn binary64_metric(surface: &Surface) -> CertifiedMetric {
    let rounded = surface.lengths::<f64>(());
    let exact = |e: usize| {
        let Some(r) = Rational::from_f64(rounded[e]) else {
            return false;
        };
        match &surface.metric {
            Metric::Lengths(v) => v[e] == r,
            Metric::SquaredLengths(v) => v[e] == r.clone() * &r,
        }
    };
    let order = edge_order(&surface.mesh);
    match order.iter().position(|&e| !exact(e)) {
        None => CertifiedMetric::Input,
        Some(k) => CertifiedMetric::Rounded {
            reason: format!(
                "edge {k}'s length is not a binary64 number; the hyperbolic certificate is about the binary64-rounded lengths"
            ),
        },
    }
}
