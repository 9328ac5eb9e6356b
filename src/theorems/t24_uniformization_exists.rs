//! T24 — discrete uniformization with prescribed cone angles exists (notes §1.5.3 Thm 12,
//! with flips; Thm 10 for flat tori): the solver converges and an a-posteriori certificate
//! (B70, B71) proves an exact solution within a stated distance of the computed `u`.

use super::verdict::{Verdict, Witness};
use crate::mesh::Mesh;
use crate::uniformization::certificate::{prove_on, CertificateOutcome, Proof, T0Metric};
use crate::uniformization::{
    uniformize, Targets, Uniformization, UniformizeError, UniformizeOptions,
};

/// The outcome of [`check_existence`]: the verdict and, when the solve converged, the
/// proof attempt.
#[derive(Clone, Debug)]
pub struct Existence {
    /// `Holds` (certified) when the certificate holds; `Undecided` otherwise. Never
    /// `Fails`: a solver that does not converge proves nothing.
    pub verdict: Verdict,
    /// The certificate data and outcome, when the `f64` solve converged.
    pub proof: Option<Proof>,
}

/// T24 on one surface: solve in `f64`, refine at `bits` of MPFR to `tolerance`, certify.
/// Bad input (including targets violating Gauss–Bonnet) is a typed error.
pub fn check_existence(
    mesh: &Mesh,
    lengths: &[f64],
    targets: &Targets,
    bits: u32,
    tolerance: f64,
) -> Result<Existence, UniformizeError> {
    check_existence_on(mesh, lengths, targets, bits, tolerance, None)
}

/// The input metric on `T₀` at the certificate's precision, from the `f64` solution (see
/// [`crate::uniformization::input_metric::input_on_t0`]); `Err(reason)` when unavailable.
pub type InputOnT0<'a> = &'a dyn Fn(&Uniformization) -> Result<T0Metric, String>;

/// [`check_existence`] about an input metric that `lengths` only round: the solve runs on
/// `lengths`, the refinement and the certificate on `input`'s lengths of `T₀` (B71, B73),
/// so `Holds` (certified) is a proof for the input itself.
pub fn check_existence_on(
    mesh: &Mesh,
    lengths: &[f64],
    targets: &Targets,
    bits: u32,
    tolerance: f64,
    input: Option<InputOnT0<'_>>,
) -> Result<Existence, UniformizeError> {
    let sol = uniformize(mesh, lengths, targets, &UniformizeOptions::default())?;
    let undecided = |detail: String| Verdict::Undecided {
        bits_tried: bits,
        witnesses: vec![Witness {
            element: "surface".into(),
            detail,
            value: f64::NAN,
        }],
    };
    if !sol.converged() {
        return Ok(Existence {
            verdict: undecided(format!("the f64 solve stopped: {:?}", sol.stop)),
            proof: None,
        });
    }
    let metric = match input.map(|f| f(&sol)).transpose() {
        Ok(m) => m,
        Err(reason) => {
            return Ok(Existence {
                verdict: undecided(reason),
                proof: None,
            })
        }
    };
    let proof = match prove_on(&sol, metric.as_ref(), bits, tolerance) {
        Ok(p) => p,
        Err(e) => {
            return Ok(Existence {
                verdict: undecided(e.to_string()),
                proof: None,
            })
        }
    };
    let verdict = match &proof.outcome {
        CertificateOutcome::Holds { distance, .. } => Verdict::Holds {
            certified: true,
            max_error: *distance,
        },
        CertificateOutcome::Undecided { reason } => undecided(reason.clone()),
    };
    Ok(Existence {
        verdict,
        proof: Some(proof),
    })
}
