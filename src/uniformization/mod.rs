//! Discrete uniformization with Ptolemy flips (notes §1.5.3 Thms 9–12; docs/catalogue.md §7;
//! T24–T26): find log scale factors `u` with prescribed cone angles `θ_i(u) = Θ_i` on a
//! closed surface, the scaled metric `e^{(u_i+u_j)/2}·ℓ_ij` kept intrinsic Delaunay by
//! Ptolemy flips.
//!
//! - [`newton`]: the `f64` Newton solver ([`uniformize`]), sparse Cholesky by faer;
//! - [`refine`]: mixed-precision refinement (residuals in `Dd` or MPFR, `f64` factor);
//! - [`certificate`]: an a-posteriori existence proof near a computed `u` (B70, B71);
//! - [`targets`]: prescribed angles as exact multiples of π and Gauss–Bonnet.
//! - [`boundary`]: surfaces with boundary (cone and boundary angles) by the double (B79).
//! - [`pipeline`]: the closed-surface pipeline as one call (solve, refine, certify for the
//!   input's exact metric, the claim).

pub(crate) mod ball_argument;
pub mod boundary;
pub(crate) mod box_f64;
pub(crate) mod cell_boundary;
pub mod certificate;
pub mod claim_form;
pub mod components;
pub mod dirichlet;
pub mod dirichlet_certificate;
pub mod error;
pub mod exclusion;
pub mod hessian;
pub mod hyperbolic;
pub mod hyperbolic_certificate;
pub mod hyperbolic_claim;
pub mod hyperbolic_flips;
pub mod hyperbolic_kernel;
pub mod input_metric;
pub mod krawczyk;
pub mod layout;
pub mod newton;
pub(crate) mod newton_driver;
pub mod pipeline;
pub mod refine;
pub mod scaling;
pub mod sphere;
pub mod sphere_checks;
pub mod sphere_claim;
pub mod sphere_refine;
pub mod svg;
pub mod targets;
pub mod verified_cholesky;

pub use error::UniformizeError;
pub use newton::{
    uniformize, uniformize_with_progress, StepReport, Stop, Uniformization, UniformizeOptions,
};
pub use targets::Targets;
