//! SVG pictures of planar layouts ([`super::layout`]): every laid-out face as a filled
//! triangle, faces not certified counterclockwise in red, edges cut open by the layout
//! where its two sides land apart (the boundary of a fundamental domain) and boundary
//! edges in blue.

use super::layout::{unproved_faces, Layout};
use crate::io::svg::SvgFrame;
use crate::mesh::Mesh;
use std::fmt::Write as _;

/// The lengths `e^{(u_i+u_j)/2}·ℓ_ij` divided by their maximum, computed from logarithms
/// (no overflow for any finite `u`): the lengths a flattened result is laid out with.
pub fn scaled_lengths_f64(mesh: &Mesh, base: &[f64], u: &[f64]) -> Vec<f64> {
    let logs: Vec<f64> = mesh
        .edges()
        .map(|e| {
            let h = e.halfedge();
            base[e.idx()].ln() + 0.5 * (u[mesh.tail(h).idx()] + u[mesh.tip(h).idx()])
        })
        .collect();
    let top = logs.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    logs.iter().map(|x| (x - top).exp()).collect()
}

/// An SVG document (as text) of `layout` of `mesh`, 800 px wide, `y` pointing up.
pub fn render_layout_svg(mesh: &Mesh, layout: &Layout) -> String {
    let folded: std::collections::HashSet<u32> =
        unproved_faces(mesh, layout).iter().map(|f| f.0).collect();
    let frame = SvgFrame::of(layout.corner.iter().flatten());
    let span = frame.span;
    let tx = |p: [f64; 2]| frame.px(p);
    let stroke = (0.5f64).min(200.0 / (mesh.n_faces().max(1) as f64).sqrt());
    let mut out = frame.header();
    for f in mesh.faces() {
        let Some(c) = layout.face_corners(mesh, f) else {
            continue;
        };
        let fill = if folded.contains(&f.0) {
            "#e04040"
        } else {
            "#dde8f4"
        };
        let [a, b, d] = c.map(tx);
        let _ = writeln!(
            out,
            r##"<polygon points="{:.3},{:.3} {:.3},{:.3} {:.3},{:.3}" fill="{fill}" stroke="#335577" stroke-width="{stroke:.3}"/>"##,
            a.0, a.1, b.0, b.1, d.0, d.1
        );
    }
    for h in mesh.halfedges() {
        if mesh.face(h).is_none() || !(layout.is_cut(mesh, h) || mesh.face(h.twin()).is_none()) {
            continue;
        }
        let (Some(p), Some(q)) = (layout.corner[h.idx()], layout.corner[mesh.next(h).idx()]) else {
            continue;
        };
        // A cut whose two sides were laid out at the same place (a disk) is not drawn.
        let t = h.twin();
        let same = |a: Option<[f64; 2]>, b: [f64; 2]| {
            a.is_some_and(|a| (a[0] - b[0]).hypot(a[1] - b[1]) <= 1e-9 * span)
        };
        if mesh.face(t).is_some()
            && same(layout.corner[t.idx()], q)
            && same(layout.corner[mesh.next(t).idx()], p)
        {
            continue;
        }
        let (p, q) = (tx(p), tx(q));
        let _ = writeln!(
            out,
            r##"<line x1="{:.3}" y1="{:.3}" x2="{:.3}" y2="{:.3}" stroke="#1f4fd0" stroke-width="{:.3}"/>"##,
            p.0,
            p.1,
            q.0,
            q.1,
            2.0 * stroke
        );
    }
    out.push_str("</svg>\n");
    out
}
