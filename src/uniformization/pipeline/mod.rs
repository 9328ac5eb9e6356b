//! Discrete uniformization as one library call per target, the pipelines behind `penner
//! uniformize` (the CLI parses, calls one of these, prints and writes):
//!
//! | target | call | certificate | claim kind |
//! |---|---|---|---|
//! | flat or cone angles, closed (T24) | [`uniformize_closed`] | B71 on the input's exact metric (B73 (a)), else the rounded one | `uniformization` |
//! | with boundary (B79) | [`uniformize_boundary`] | B71 on the double, for the input's exact metric pulled back | `uniformization` (the double) |
//! | the sphere (B74–B76) | [`uniformize_sphere`] | B76 on the disk, for the input's exact metric | `sphere_uniformization` |
//! | hyperbolic (B38, B39, B87) | [`uniformize_hyperbolic`] | B39 on the binary64 lengths | `hyperbolic_uniformization` |
//! | UVs on the input mesh (flat or cones; B108, B109, B111) | [`uv_closed`] after [`uniformize_closed`], [`uv_boundary`] (copy 1 of the double) after [`uniformize_boundary`] | exact fold and tiling checks of the written files | — |
//!
//! Each takes a [`Surface`](crate::io::Surface) and typed options (a [`Precision`], whether
//! to certify) and returns an outcome holding the solve (`u`, the final triangulation and
//! lengths, the flips, the residual), the certificate or the reason it is undecided, and
//! the claim ready to write, which `penner certify` re-checks. Not converging and not
//! certifying are outcomes; [`PipelineError`] is for input refused and for a computation
//! of penner's own that did not go through ([`PipelineError::is_bad_input`] tells which).

mod boundary;
mod closed;
mod hyperbolic;
mod sphere;
mod uv;

pub use boundary::{double_surface, uniformize_boundary, BoundaryOutcome, SvgLayout};
pub use closed::{
    certify_solution, uniformize_closed, uniformize_closed_owned, Certification, ClosedOutcome,
};
pub use hyperbolic::{uniformize_hyperbolic, HyperbolicOutcome};
pub use sphere::{uniformize_sphere, SphereOutcome};
pub use uv::{check_written_uv, uv_boundary, uv_closed, UvCones, WrittenUvChecks};

use crate::io::Surface;
use crate::scalar::Real;
use crate::uniformization::boundary::BoundaryError;
use crate::uniformization::certificate::CertificateError;
use crate::uniformization::hyperbolic::HyperbolicError;
use crate::uniformization::sphere::SphereError;
use crate::uniformization::UniformizeError;
use rug::Rational;

/// The working precision of a pipeline: where the solution is refined before the
/// certificate, which always runs in MPFR interval arithmetic (directed rounding).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Precision {
    /// Refined to `10⁻¹⁰` in binary64's neighbourhood, certified at 128 bits.
    F64,
    /// Refined in double-double to `10⁻²⁸`, certified at 128 bits.
    Dd,
    /// Refined at `N` MPFR bits (`128 ≤ N ≤ 4096`) to `2^{−(N−56)}`, certified at `N`.
    Mpfr(u32),
}

impl Default for Precision {
    /// 256 MPFR bits.
    fn default() -> Precision {
        Precision::Mpfr(256)
    }
}

impl std::str::FromStr for Precision {
    type Err = String;

    /// `f64`, `dd` or MPFR bits `128..=4096`.
    fn from_str(word: &str) -> Result<Precision, String> {
        match word {
            "f64" => Ok(Precision::F64),
            "dd" => Ok(Precision::Dd),
            other => match other.parse::<u32>() {
                Ok(b) if (128..=4096).contains(&b) => Ok(Precision::Mpfr(b)),
                _ => Err(format!(
                    "expected f64, dd or MPFR bits 128..=4096, got {other:?}"
                )),
            },
        }
    }
}

impl std::fmt::Display for Precision {
    /// The word [`FromStr`](std::str::FromStr) reads: `f64`, `dd` or the MPFR bits.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Precision::F64 => f.write_str("f64"),
            Precision::Dd => f.write_str("dd"),
            Precision::Mpfr(b) => write!(f, "{b}"),
        }
    }
}

impl Precision {
    /// The certificate's interval bits and the refinement's tolerance on `max |Θ − θ|`.
    pub fn bits_and_tolerance(self) -> (u32, f64) {
        match self {
            Precision::F64 => (128, 1e-10),
            Precision::Dd => (128, 1e-28),
            Precision::Mpfr(b) => (b, 2f64.powi(-(b as i32 - 56))),
        }
    }
}

/// Options of the pipelines.
#[derive(Clone, Debug, PartialEq)]
pub struct Options {
    /// The working precision.
    pub precision: Precision,
    /// Attempt a certificate (otherwise the result is numerical: the `f64` solve alone).
    pub certify: bool,
}

impl Default for Options {
    /// 256 bits, certified.
    fn default() -> Options {
        Options {
            precision: Precision::default(),
            certify: true,
        }
    }
}

/// Which metric a certificate is about.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum CertifiedMetric {
    /// The input's own exact metric (after the exact rescaling by `2^{−shift}`).
    Input,
    /// The binary64 rounding of the input lengths only; `reason` says why the input's
    /// exact metric was not certified.
    Rounded {
        /// Why the exact-metric certificate was not obtained.
        reason: String,
    },
}

/// Errors of the pipelines: the input, targets or options refused, or a step of penner's
/// own computation that did not go through. Not converging and not certifying are
/// outcomes, not errors.
#[derive(Debug, thiserror::Error)]
pub enum PipelineError {
    /// The surface or targets are refused (e.g. Gauss–Bonnet, a non-closed surface).
    #[error(transparent)]
    Input(#[from] UniformizeError),
    /// The surface with boundary or its targets are refused.
    #[error(transparent)]
    Boundary(#[from] BoundaryError),
    /// The refinement or certificate could not be set up.
    #[error(transparent)]
    Certificate(#[from] CertificateError),
    /// The sphere target refused the surface, or its disk problem did not go through.
    #[error(transparent)]
    Sphere(#[from] SphereError),
    /// The hyperbolic target refused the surface or targets.
    #[error(transparent)]
    Hyperbolic(#[from] HyperbolicError),
    /// An option this target does not have (e.g. double-double for the sphere).
    #[error("{0}")]
    Unsupported(String),
    /// A step of penner's own computation did not go through (a refinement, a non-finite
    /// computed `u`, the double's metric): undecided, not the input's fault.
    #[error("{0}")]
    NotComputed(String),
}

impl PipelineError {
    /// Whether the error is the input's fault (a refused surface, targets or option);
    /// otherwise penner's own computation did not go through and the answer is undecided.
    pub fn is_bad_input(&self) -> bool {
        match self {
            PipelineError::Input(_)
            | PipelineError::Boundary(_)
            | PipelineError::Hyperbolic(_)
            | PipelineError::Unsupported(_) => true,
            PipelineError::Certificate(e) => !matches!(e, CertificateError::Replay(_)),
            PipelineError::Sphere(e) => !matches!(
                e,
                SphereError::NotConverged { .. } | SphereError::Layout(_) | SphereError::NoPole
            ),
            PipelineError::NotComputed(_) => false,
        }
    }
}

/// The exact values of a refined `u` (a non-finite entry becomes 0, which the certificate
/// then refuses: its residual is not small).
fn exact<T: Real>(u: &[T]) -> Vec<Rational> {
    u.iter()
        .map(|x| x.to_rational().unwrap_or_default())
        .collect()
}

/// The exact values of a computed `u`, or [`PipelineError::NotComputed`] naming the first
/// entry that is not finite (a failure of the computation, never of the input).
fn finite_u(
    values: impl IntoIterator<Item = Option<Rational>>,
) -> Result<Vec<Rational>, PipelineError> {
    values
        .into_iter()
        .enumerate()
        .map(|(i, q)| {
            q.ok_or_else(|| {
                PipelineError::NotComputed(format!(
                    "not certified: u[{i}] of the computed solution is not finite"
                ))
            })
        })
        .collect()
}

/// The surface divided by an exact power of two `2^shift` when its binary64 lengths are
/// not all in `[2⁻¹⁰⁰, 2¹⁰⁰]` (their squares then leave binary64's range;
/// [`Surface::normalized_scale`]), the shift, and the binary64 lengths of the returned
/// surface ([`Surface::lengths`], computed once).
pub fn rescaled(surface: &Surface) -> (Surface, i64, Vec<f64>) {
    match rescaled_if_needed(surface) {
        Ok(r) => r,
        Err(l) => (surface.clone(), 0, l),
    }
}

/// [`rescaled`] for an owned surface: returned as it is (not copied) when it needs no
/// rescaling.
pub fn rescaled_owned(surface: Surface) -> (Surface, i64, Vec<f64>) {
    match rescaled_if_needed(&surface) {
        Ok(r) => r,
        Err(l) => (surface, 0, l),
    }
}

/// The rescaled surface, shift and lengths of [`rescaled`] when the lengths of `surface`
/// need it, else `Err` with its binary64 lengths.
fn rescaled_if_needed(surface: &Surface) -> Result<(Surface, i64, Vec<f64>), Vec<f64>> {
    let l = surface.lengths::<f64>(());
    let in_range = l
        .iter()
        .all(|&x| x.is_finite() && (f64::powi(2.0, -100)..=f64::powi(2.0, 100)).contains(&x));
    match surface.normalized_scale().filter(|_| !in_range) {
        Some((s, k)) => {
            let l = s.lengths::<f64>(());
            Ok((s, k, l))
        }
        None => Err(l),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every precision word reads back from its display; out-of-range bits are refused.
    #[test]
    fn precision_words_round_trip() {
        for p in [
            Precision::F64,
            Precision::Dd,
            Precision::Mpfr(128),
            Precision::Mpfr(4096),
        ] {
            assert_eq!(p.to_string().parse::<Precision>(), Ok(p));
        }
        for bad in ["127", "4097", "mpfr", ""] {
            assert!(bad.parse::<Precision>().is_err(), "{bad:?}");
        }
    }

    /// The kind of each error: the input's fault (exit 3 in the CLI) or undecided.
    #[test]
    fn errors_say_whose_fault() {
        use crate::uniformization::refine::RefineError;
        assert!(
            !PipelineError::Certificate(CertificateError::Replay(RefineError::Hessian))
                .is_bad_input()
        );
        assert!(PipelineError::Certificate(CertificateError::Radius("-1".into())).is_bad_input());
        assert!(!PipelineError::Sphere(SphereError::NoPole).is_bad_input());
        assert!(PipelineError::Unsupported("dd".into()).is_bad_input());
        assert!(!PipelineError::NotComputed("u".into()).is_bad_input());
        let e = finite_u([Some(Rational::from(1)), None]).unwrap_err();
        assert!(!e.is_bad_input() && e.to_string().contains("u[1]"), "{e}");
    }
}
