//! SVG pictures of maximal packings: the circles in the unit disk, the unit circle (the
//! boundary of the disk, or the punctured vertex's circle of a sphere) and the edges of the
//! triangulation between the centres.

use super::layout::Circle;
use crate::mesh::Mesh;
use std::fmt::Write as _;

/// An SVG document of `circles` (one per vertex of `mesh`, `f64`) inside the unit circle.
pub fn render_disk_svg(mesh: &Mesh, circles: &[Circle<f64>]) -> String {
    let stroke = 0.002;
    let mut s = String::new();
    let _ = writeln!(
        s,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"-1.05 -1.05 2.1 2.1\" width=\"800\" height=\"800\">"
    );
    let _ = writeln!(
        s,
        "<rect x=\"-1.05\" y=\"-1.05\" width=\"2.1\" height=\"2.1\" fill=\"white\"/>"
    );
    let _ = writeln!(
        s,
        "<circle cx=\"0\" cy=\"0\" r=\"1\" fill=\"none\" stroke=\"black\" stroke-width=\"{stroke}\"/>"
    );
    let _ = writeln!(s, "<g stroke=\"#999\" stroke-width=\"{}\">", stroke / 2.0);
    for e in mesh.edges() {
        let h = e.halfedge();
        let (a, b) = (&circles[mesh.tail(h).idx()], &circles[mesh.tip(h).idx()]);
        // SVG's y axis points down: y is negated to keep the orientation.
        let _ = writeln!(
            s,
            "<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\"/>",
            a.centre[0], -a.centre[1], b.centre[0], -b.centre[1]
        );
    }
    let _ = writeln!(s, "</g>");
    let _ = writeln!(
        s,
        "<g fill=\"#4a90d9\" fill-opacity=\"0.25\" stroke=\"#1f4e8c\" stroke-width=\"{stroke}\">"
    );
    for (v, c) in circles.iter().enumerate() {
        let _ = writeln!(
            s,
            "<circle cx=\"{}\" cy=\"{}\" r=\"{}\"><title>v{v}</title></circle>",
            c.centre[0], -c.centre[1], c.radius
        );
    }
    let _ = writeln!(s, "</g>\n</svg>");
    s
}
