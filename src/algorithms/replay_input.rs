//! The exact input metric of a replay ([`super::replay`]), asked for edge by edge: an
//! exact [`Metric`], or the squared distances of exact vertex positions on the input
//! triangulation ([`PositionMetric`], what `penner delaunay` replays OBJ and OFF input on).
//! The first rung of every sign takes a cheap `f64` enclosure of each length (proof: B83);
//! the exact value of an edge is built only when a sign or a new length needs it.

use super::replay_chord::Point;
use super::replay_len::{f64_enclosure, Len};
use crate::io::{DecimalSurface, Metric};
use crate::mesh::{Edge, Mesh, Vertex};
use crate::predicates::delaunay_widened::{in_range, length_from_square, Bounds};

/// An exact metric on the input triangulation of a replay.
pub trait InputMetric {
    /// The number of edges it has lengths for.
    fn n_edges(&self) -> usize;
    /// The exact length of edge `e` of the input triangulation.
    fn exact(&self, e: Edge) -> Len;
    /// An enclosure of that length for the first rung (proof: B83), `None` when `f64`
    /// cannot hold one in the rung's range.
    fn first_rung(&self, e: Edge) -> Option<Bounds>;
    /// The exact position of vertex `v` when every input length is the chord `|p_u − p_v|`
    /// of its ends (the chordal flips of B106 need them); `None` by default.
    fn position(&self, _v: Vertex) -> Option<Point> {
        None
    }
}

impl InputMetric for Metric {
    fn n_edges(&self) -> usize {
        self.len()
    }
    fn exact(&self, e: Edge) -> Len {
        match self {
            Metric::Lengths(l) => Len::Exact(l[e.idx()].clone()),
            Metric::SquaredLengths(s) => Len::Root(s[e.idx()].clone()),
        }
    }
    fn first_rung(&self, e: Edge) -> Option<Bounds> {
        let x = f64_enclosure(&self.exact(e))?;
        in_range([*x.lo(), *x.hi()])
    }
}

/// The metric `ℓ_uv² = |p_v − p_u|²` of exact positions on the input triangulation (which
/// the surface's own mesh may no longer be, once flipped).
#[derive(Clone, Copy, Debug)]
pub struct PositionMetric<'a> {
    /// The input triangulation.
    pub mesh: &'a Mesh,
    /// The positions (its mesh is not used).
    pub surface: &'a DecimalSurface,
    /// The squared lengths of the input edges as
    /// [`DecimalSurface::squared_lengths_f64`] computed them before flipping, if kept.
    pub squares: Option<&'a [f64]>,
}

impl PositionMetric<'_> {
    fn ends(&self, e: Edge) -> (crate::mesh::Vertex, crate::mesh::Vertex) {
        let h = e.halfedge();
        (self.mesh.tail(h), self.mesh.tip(h))
    }
}

impl InputMetric for PositionMetric<'_> {
    fn n_edges(&self) -> usize {
        self.mesh.n_edges()
    }
    fn exact(&self, e: Edge) -> Len {
        let (u, v) = self.ends(e);
        Len::Root(self.surface.squared_distance(u, v))
    }
    fn first_rung(&self, e: Edge) -> Option<Bounds> {
        // proof: B83 — the nearest binary64 value of the exact square where it is normal
        // (B19); `length_from_square` refuses values below 2⁻²⁰⁰, subnormals among them.
        let nearest = if let Some(s) = self.squares {
            *s.get(e.idx())?
        } else {
            let (u, v) = self.ends(e);
            self.surface.squared_distance_f64(u, v)?
        };
        length_from_square(nearest)
    }
    fn position(&self, v: Vertex) -> Option<Point> {
        // proof: B106 — `exact` above is `Root(|p_u − p_v|²)` of these positions.
        let p = self.surface.positions.get(v.idx())?;
        Some([p[0].to_rational(), p[1].to_rational(), p[2].to_rational()])
    }
}
