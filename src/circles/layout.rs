//! Planar layout of a triangulated surface with a metric, face by face along a spanning
//! tree of the dual graph (closed surfaces are cut open along the other edges): every face
//! keeps its shape, and a vertex gets one position per face corner. For pictures (`f64`).

use crate::geometry::unfold::unfold_faces;
use crate::mesh::Mesh;

pub use crate::geometry::unfold::third_corner;

/// The position of the tail of every face half-edge (`None` for boundary half-edges and
/// faces of other components), laying out face 0 with its first half-edge on the positive
/// x-axis and its neighbours breadth first ([`unfold_faces`]).
pub fn layout_faces(mesh: &Mesh, lengths: &[f64]) -> Vec<Option<[f64; 2]>> {
    match mesh.faces().next() {
        Some(f0) => unfold_faces(mesh, lengths, f0, |_| true).corner,
        None => vec![None; mesh.n_halfedges()],
    }
}
