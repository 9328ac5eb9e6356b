//! SVG pictures of circle patterns laid out in the plane ([`super::layout`]): one circle per
//! placed vertex corner (repeated placements of a vertex drawn once) and the edges of the
//! layout as thin lines.

use super::layout::layout_faces;
use crate::mesh::Mesh;
use std::fmt::Write as _;

/// A circle of the picture: a vertex, its centre and radius.
#[derive(Clone, Debug, PartialEq)]
pub struct PlacedCircle {
    /// The vertex.
    pub vertex: usize,
    /// Centre.
    pub centre: [f64; 2],
    /// Radius.
    pub radius: f64,
}

/// The circles of a layout: for every face corner, the circle of radius `r[v]` at the
/// corner's position; placements of one vertex closer than `10⁻⁹·scale` are one circle.
pub fn placed_circles(mesh: &Mesh, lengths: &[f64], r: &[f64]) -> Vec<PlacedCircle> {
    let pos = layout_faces(mesh, lengths);
    let scale = lengths
        .iter()
        .copied()
        .fold(0.0, f64::max)
        .max(f64::MIN_POSITIVE);
    let mut out: Vec<PlacedCircle> = Vec::new();
    for h in mesh.halfedges() {
        let Some(c) = pos[h.idx()] else { continue };
        let v = mesh.tail(h).idx();
        let dup = out.iter().any(|o| {
            o.vertex == v && (o.centre[0] - c[0]).hypot(o.centre[1] - c[1]) < 1e-9 * scale
        });
        if !dup {
            out.push(PlacedCircle {
                vertex: v,
                centre: c,
                radius: r[v],
            });
        }
    }
    out
}

/// An SVG document (as text) of the layout of `mesh` with `lengths`, with the circles of
/// radii `r` (one per vertex) and the edges of every laid-out face.
pub fn render_svg(mesh: &Mesh, lengths: &[f64], r: &[f64]) -> String {
    let pos = layout_faces(mesh, lengths);
    let circles = placed_circles(mesh, lengths, r);
    let (mut x0, mut y0, mut x1, mut y1) = (f64::MAX, f64::MAX, f64::MIN, f64::MIN);
    for c in &circles {
        x0 = x0.min(c.centre[0] - c.radius);
        y0 = y0.min(c.centre[1] - c.radius);
        x1 = x1.max(c.centre[0] + c.radius);
        y1 = y1.max(c.centre[1] + c.radius);
    }
    if circles.is_empty() {
        (x0, y0, x1, y1) = (0.0, 0.0, 1.0, 1.0);
    }
    let w = (x1 - x0).max(f64::MIN_POSITIVE);
    let h = (y1 - y0).max(f64::MIN_POSITIVE);
    let pad = 0.02 * w.max(h);
    let stroke = 0.002 * w.max(h);
    let mut s = String::new();
    // SVG's y axis points down: flip y so the picture keeps the layout's orientation.
    let _ = writeln!(
        s,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"{} {} {} {}\" width=\"800\" height=\"{}\">",
        x0 - pad,
        -y1 - pad,
        w + 2.0 * pad,
        h + 2.0 * pad,
        (800.0 * (h + 2.0 * pad) / (w + 2.0 * pad)).round().max(1.0)
    );
    let _ = writeln!(
        s,
        "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"white\"/>",
        x0 - pad,
        -y1 - pad,
        w + 2.0 * pad,
        h + 2.0 * pad
    );
    let _ = writeln!(
        s,
        "<g fill=\"none\" stroke=\"#999\" stroke-width=\"{stroke}\">"
    );
    for f in mesh.faces() {
        let hs = mesh.face_halfedges(f);
        let pts: Vec<[f64; 2]> = hs.iter().filter_map(|h| pos[h.idx()]).collect();
        if pts.len() == 3 {
            let _ = writeln!(
                s,
                "<polygon points=\"{},{} {},{} {},{}\"/>",
                pts[0][0], -pts[0][1], pts[1][0], -pts[1][1], pts[2][0], -pts[2][1]
            );
        }
    }
    let _ = writeln!(s, "</g>");
    let _ = writeln!(
        s,
        "<g fill=\"#4a90d9\" fill-opacity=\"0.25\" stroke=\"#1f4e8c\" stroke-width=\"{stroke}\">"
    );
    for c in &circles {
        let _ = writeln!(
            s,
            "<circle cx=\"{}\" cy=\"{}\" r=\"{}\"><title>v{}</title></circle>",
            c.centre[0], -c.centre[1], c.radius, c.vertex
        );
    }
    let _ = writeln!(s, "</g>\n</svg>");
    s
}
