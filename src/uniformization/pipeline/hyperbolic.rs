//! The hyperbolic target (notes Thm 11; B38, B39, B87, B89, B104), the pipeline behind
//! `penner uniformize --hyperbolic`: the input lengths, rounded to binary64, are read as
//! hyperbolic lengths; geometric flips to hyperbolic Delaunay, Newton over Penner cells
//! with Ptolemy flips, refinement (double-double or MPFR), the residual enclosed in MPFR
//! intervals and an existence radius (B39). The certificate is first attempted for the
//! input's **exact** metric: the geometric flips replayed on enclosures of its lengths
//! (each admitted only on a certified convex quadrilateral, B104), the refinement and the
//! certificate on those enclosures. When that replay or box does not hold, the binary64
//! lengths are certified and [`CertifiedMetric::Rounded`] says why. The claim form speaks of
//! binary64 lengths (see [`HyperbolicOutcome::claim`]). The Gauss–Bonnet area by L'Huilier
//! is numerical.
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
use crate::scalar::{Dd, Interval, Mpfr, Precision as Bits, Real};
use crate::uniformization::hyperbolic::{
    uniformize_hyperbolic as solve, HyperbolicOptions, HyperbolicUniformization,
};
use crate::uniformization::hyperbolic_certificate::{
    base_log_i, certify_hyperbolic, certify_hyperbolic_on, refine_hyperbolic, refine_hyperbolic_on,
    total_area_lhuilier, Existence, HyperbolicCertificate,
};
use crate::uniformization::hyperbolic_claim::{to_claim, ClaimData};
use crate::uniformization::hyperbolic_flips::replay_geometric_enclosed;
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
    /// The claim ready to write.
    claim_doc: Option<Value>,
    /// The metric the claim is about.
    claim_about: CertifiedMetric,
}

impl HyperbolicOutcome {
    /// Whether an exact solution was proved to exist near the refined `u`.
    pub fn certified(&self) -> bool {
        self.certificate
            .as_ref()
            .is_some_and(|c| matches!(c.existence, Existence::Holds { .. }))
    }

    /// The `hyperbolic_uniformization` claim of a certified outcome, ready to write. The
    /// claim form speaks of `T₀` with binary64 lengths: when the certificate is about an
    /// exact metric that is not binary64, the claim is the certificate of its binary64
    /// rounding (computed for it), and [`Self::claim_metric`] says so.
    pub fn claim(&self) -> Option<Value> {
        self.claim_doc.clone()
    }

    /// The metric the claim of [`Self::claim`] is about.
    pub fn claim_metric(&self) -> &CertifiedMetric {
        &self.claim_about
    }
}

/// The claim of a certified `(u, certificate)` for `T₀` with the solve's binary64 lengths.
fn claim_of(
    sol: &HyperbolicUniformization,
    u: &[Rational],
    cert: &HyperbolicCertificate,
    bits: u32,
) -> Option<Value> {
    let Existence::Holds { radius, .. } = &cert.existence else {
        return None;
    };
    let data = ClaimData {
        mesh: &sol.t0,
        lengths: &sol.lengths,
        flips: &sol.flips,
        targets: &sol.targets,
        u,
    };
    Some(to_claim(&data, *radius, cert.residual_norm2, bits))
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
    let binary64 = binary64_metric(surface, &solution);
    let mut out = HyperbolicOutcome {
        claim_doc: None,
        claim_about: binary64.clone(),
        metric: binary64.clone(),
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
    let prec = Bits::new(u64::from(bits))
        .map_err(|_| PipelineError::Unsupported(format!("{bits} bits out of range")))?;
    // First for the input's exact metric: the geometric flips replayed on its enclosures.
    let reason = match input_on_t0(surface, &out.solution, prec) {
        Ok(x) => {
            let base: Vec<Mpfr> = x.iter().map(|v| v.lo().clone()).collect();
            let refined = refine(&out.solution, Some(base), options.precision, tolerance)?;
            let cert = certify_hyperbolic_on(&out.solution, &x, &refined.0, prec)?;
            match &cert.existence {
                Existence::Holds { .. } => {
                    out.metric = CertifiedMetric::Input;
                    out.claim_doc = if binary64 == CertifiedMetric::Input {
                        claim_of(&out.solution, &refined.0, &cert, bits)
                    } else {
                        // The claim form's binary64 lengths: their own certificate.
                        let r = refine(&out.solution, None, options.precision, tolerance)?;
                        let c = certify_hyperbolic(&out.solution, &r.0, bits)?;
                        claim_of(&out.solution, &r.0, &c, bits)
                    };
                    out.certificate = Some(cert);
                    out.refined = Some(refined);
                    return Ok(out);
                }
                Existence::Undecided { reason } => reason.clone(),
            }
        }
        Err(reason) => reason,
    };
    let refined = refine(&out.solution, None, options.precision, tolerance)?;
    let cert = certify_hyperbolic(&out.solution, &refined.0, bits)?;
    out.claim_doc = claim_of(&out.solution, &refined.0, &cert, bits);
    out.certificate = Some(cert);
    out.refined = Some(refined);
    if let CertifiedMetric::Rounded { reason: why } = &mut out.metric {
        *why = format!("{why}; for the exact metric: {reason}");
        out.claim_about = out.metric.clone();
    }
    Ok(out)
}

/// Enclosures of the logarithmic lengths of `sol.t0` for `surface`'s exact metric: its
/// geometric flips replayed on enclosures at `prec` (B104), reaching the solve's `T₀`.
fn input_on_t0(
    surface: &Surface,
    sol: &HyperbolicUniformization,
    prec: Bits,
) -> Result<Vec<Interval<Mpfr>>, String> {
    let x = base_log_i(&surface.lengths::<Interval<Mpfr>>(prec));
    let (t0, x) = replay_geometric_enclosed(&surface.mesh, x, &sol.input_flips)?;
    if t0.face_list() != sol.t0.face_list() {
        return Err("the geometric flips do not reproduce the solve's T₀".into());
    }
    Ok(x)
}

/// The refined `u` (exact values) and its `max |Θ − θ|`: the solve's own at `F64`, else
/// refined in double-double or MPFR, for the logarithmic lengths `base` of `T₀` (default:
/// the solve's binary64 lengths).
fn refine(
    sol: &HyperbolicUniformization,
    base: Option<Vec<Mpfr>>,
    precision: Precision,
    tolerance: f64,
) -> Result<(Vec<Rational>, f64), PipelineError> {
    let not_computed = |e: crate::uniformization::hyperbolic::HyperbolicError| {
        PipelineError::NotComputed(format!("not certified: the refinement failed: {e}"))
    };
    Ok(match precision {
        Precision::F64 => (
            finite_u(sol.u.iter().map(|&x| Rational::from_f64(x)))?,
            sol.residual_max,
        ),
        Precision::Dd => {
            let r = match base {
                Some(b) => {
                    let b: Vec<Dd> = b
                        .iter()
                        .map(|x| Dd::from_rational(&x.to_rational().unwrap_or_default(), ()))
                        .collect();
                    refine_hyperbolic_on::<Dd>(sol, &b, (), tolerance, 30)
                }
                None => refine_hyperbolic::<Dd>(sol, (), tolerance, 30),
            }
            .map_err(not_computed)?;
            (
                finite_u(r.u.iter().map(Real::to_rational))?,
                r.residual_max(),
            )
        }
        Precision::Mpfr(b) => {
            let prec = Bits::new(u64::from(b))
                .map_err(|_| PipelineError::Unsupported(format!("{b} bits out of range")))?;
            let r = match base {
                Some(x) => refine_hyperbolic_on::<Mpfr>(sol, &x, prec, tolerance, 60),
                None => refine_hyperbolic::<Mpfr>(sol, prec, tolerance, 60),
            }
            .map_err(not_computed)?;
            (
                finite_u(r.u.iter().map(Real::to_rational))?,
                r.residual_max(),
            )
        }
    })
}

/// The metric of a certificate on the solve's binary64 lengths of `T₀`:
/// [`CertifiedMetric::Input`] when no geometric flip changed the input and every length of
/// `surface` is a binary64 number (the solve sees it exactly), else `Rounded`, saying why
/// (the flips, or the first edge, in the input's edge order, that is not binary64).
fn binary64_metric(surface: &Surface, sol: &HyperbolicUniformization) -> CertifiedMetric {
    if !sol.input_flips.is_empty() {
        return CertifiedMetric::Rounded {
            reason: format!(
                "the lengths of T₀ are the binary64 results of {} geometric flips",
                sol.input_flips.len()
            ),
        };
    }
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
