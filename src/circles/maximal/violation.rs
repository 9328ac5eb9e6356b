//! A proved violation of an exact condition of a packing (a face's orientation, a vertex's
//! winding number): reported by [`super::tangency`] and [`super::sphere`], and by
//! [`crate::circles::realize`] for the circle claims.

/// A proved violation of an exact condition (an orientation or a winding number).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Violation {
    /// The element: `face fK (vA, vB, vC)` or `vK`.
    pub element: String,
    /// What is wrong with it.
    pub detail: String,
}
