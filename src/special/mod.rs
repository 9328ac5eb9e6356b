//! Special functions generic over [`Real`](crate::scalar::Real): Lobachevsky's function `Л`
//! and Clausen's `Cl₂` (docs/catalogue.md §7, notes §1.6.3), the base of the hyperbolic volumes and
//! of the discrete-uniformization energy. Accuracy and enclosure bounds: proofs/B52, B53.

mod coefficients;
mod dual_fast;
mod elementary_table;
mod enclosure;
mod eval;
mod fast_dd;
mod fast_f64;
pub mod lobachevsky;
mod reduce;
pub mod reference;
mod series;

pub use enclosure::lobachevsky_enclosure;
pub(crate) use lobachevsky::MpfrLobachevsky;
pub use lobachevsky::{clausen2, ideal_tetrahedron_volume, lobachevsky};
pub use reference::lobachevsky_tangent_series;
