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
//! - [`pipeline`]: one call per target (solve, refine, certify for the input's exact
//!   metric, the claim).
//!
//! The files: the core (Newton, refinement, Hessian, scaling, targets, layout) at the top;
//! `certificate/` the a-posteriori proof shared by the targets (box, cell boundaries, ball
//! argument, verified Cholesky, exclusion, Krawczyk, the input metric and the claim form);
//! `sphere/` the sphere target (the disk's Dirichlet problem, its certificate, checks and
//! claim); `hyperbolic/` the hyperbolic target (kernel, flips, certificate, claim);
//! `pipeline/` the pipelines. Module paths stay flat (`uniformization::sphere_claim`).

#[path = "certificate/ball_argument.rs"]
pub(crate) mod ball_argument;
pub mod boundary;
#[path = "certificate/box_f64.rs"]
pub(crate) mod box_f64;
#[path = "certificate/box_values.rs"]
pub(crate) mod box_values;
#[path = "certificate/cell_boundary.rs"]
pub(crate) mod cell_boundary;
#[path = "certificate/certificate.rs"]
pub mod certificate;
#[path = "certificate/outcome.rs"]
pub(crate) mod certificate_outcome;
#[path = "certificate/prove.rs"]
pub(crate) mod certificate_prove;
#[path = "certificate/claim_form.rs"]
pub mod claim_form;
pub mod components;
#[path = "sphere/dirichlet.rs"]
pub mod dirichlet;
#[path = "sphere/dirichlet_certificate.rs"]
pub mod dirichlet_certificate;
pub mod error;
#[path = "certificate/exclusion.rs"]
pub mod exclusion;
pub mod hessian;
#[path = "hyperbolic/hyperbolic.rs"]
pub mod hyperbolic;
#[path = "hyperbolic/hyperbolic_certificate.rs"]
pub mod hyperbolic_certificate;
#[path = "hyperbolic/hyperbolic_claim.rs"]
pub mod hyperbolic_claim;
#[path = "hyperbolic/hyperbolic_flips.rs"]
pub mod hyperbolic_flips;
#[path = "hyperbolic/hyperbolic_kernel.rs"]
pub mod hyperbolic_kernel;
#[path = "certificate/input_metric.rs"]
pub mod input_metric;
#[path = "certificate/krawczyk.rs"]
pub mod krawczyk;
pub mod layout;
pub mod newton;
pub(crate) mod newton_driver;
pub mod pipeline;
#[path = "sphere/pole.rs"]
pub mod pole;
pub mod refine;
pub(crate) mod refine_newton;
pub(crate) mod refine_scaling;
pub mod scaling;
#[path = "sphere/sphere.rs"]
pub mod sphere;
#[path = "sphere/sphere_checks.rs"]
pub mod sphere_checks;
#[path = "sphere/sphere_claim.rs"]
pub mod sphere_claim;
#[path = "sphere/sphere_refine.rs"]
pub mod sphere_refine;
pub mod svg;
pub mod targets;
#[path = "certificate/verified_cholesky.rs"]
pub mod verified_cholesky;

pub use error::UniformizeError;
pub use newton::{
    uniformize, uniformize_with_progress, StepReport, Stop, Uniformization, UniformizeOptions,
};
pub use targets::Targets;
