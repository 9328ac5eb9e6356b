//! What the certificate of B71 concludes, and the interval type and upward rounding shared
//! by [`super::certificate`] and the parts it runs ([`super::ball_argument`],
//! [`super::box_f64`], [`super::cell_boundary`]).

use crate::scalar::{Interval, Mpfr};
use rug::float::Round;

/// The outcome of [`check_certificate`](super::certificate::check_certificate).
#[derive(Clone, Debug, PartialEq)]
pub enum CertificateOutcome {
    /// An exact solution `u*` exists with `‖u* − u‖₂ ≤ distance` (so also in sup norm).
    Holds {
        /// The proved bound on `‖u* − u‖₂`.
        distance: f64,
        /// The proved lower bound `μ` on the grounded Hessian over the box.
        mu: f64,
        /// The enclosed `‖Θ − θ(u)‖₂` on the free vertices (upper bound).
        residual: f64,
    },
    /// No conclusion, with the reason (never a claim that no solution exists).
    Undecided {
        /// Why.
        reason: String,
    },
}

pub(crate) type I = Interval<Mpfr>;

pub(crate) fn to_f64_up(x: &Mpfr) -> f64 {
    x.as_float().to_f64_round(Round::Up)
}
