//! A surface loaded for flipping: exact (surface JSON) or by its decimal positions (OBJ,
//! OFF) in the compact form, whose lengths are computed per edge without building the
//! exact metric ([`DecimalSurface`]).

use super::{DecimalSurface, Metric, Surface};
use crate::mesh::Mesh;
use crate::scalar::Real;
use rug::Rational;

/// A surface loaded for flipping: exact (JSON) or with compact decimal positions (OBJ,
/// OFF), whose lengths are computed per edge without building the exact metric.
#[derive(Clone, Debug)]
pub enum FlipCase {
    /// A surface with an exact metric.
    Exact(Surface),
    /// A surface from positions (OBJ, OFF).
    Decimal(DecimalSurface),
}

impl FlipCase {
    /// The triangulation.
    pub fn mesh(&self) -> &Mesh {
        match self {
            FlipCase::Exact(s) => &s.mesh,
            FlipCase::Decimal(s) => &s.mesh,
        }
    }
    /// The triangulation, to be flipped.
    pub fn mesh_mut(&mut self) -> &mut Mesh {
        match self {
            FlipCase::Exact(s) => &mut s.mesh,
            FlipCase::Decimal(s) => &mut s.mesh,
        }
    }
    /// The name for messages.
    pub fn name(&self) -> &str {
        match self {
            FlipCase::Exact(s) => &s.name,
            FlipCase::Decimal(s) => &s.name,
        }
    }
    /// The lengths in backend `T` (`Surface::lengths`).
    pub fn lengths<T: Real + 'static>(&self, ctx: T::Ctx) -> Vec<T> {
        match self {
            FlipCase::Exact(s) => s.lengths(ctx),
            FlipCase::Decimal(s) => s.lengths(ctx),
        }
    }
    /// The exact lengths, when the metric is given by lengths (not squared lengths).
    pub fn exact_lengths(&self) -> Option<&Vec<Rational>> {
        match self {
            FlipCase::Exact(Surface {
                metric: Metric::Lengths(l),
                ..
            }) => Some(l),
            _ => None,
        }
    }
}
