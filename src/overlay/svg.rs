//! An SVG picture of the UV layout of the common refinement: every refined triangle at its
//! texture coordinates, the pieces of the input edges in one colour and of the edges of the
//! final triangulation `T_F` in another (a piece on both — an input edge that is also an
//! edge of `T_F` — in the second, drawn over the first), and the cones marked at every
//! place the layout puts them (a cone lies on the cut, so it appears more than once).
//!
//! A side of a refined triangle lies on an edge of its input face when its two corners do:
//! a corner at `(1 − σ) e_r + σ e_{r+1}` lies on side `r`, and also on side `r − 1` when
//! `σ = 0` (it is corner `r`) or on side `r + 1` when `σ = 1`. The same rule on the places
//! in the face of `T_F` (corner `r` on sides `r` and `r − 1`, a point of side `r` on it)
//! finds the pieces of `T_F`'s edges. Sides on neither are the diagonals that split a cell
//! into triangles and are drawn only as the triangles' fill.

use super::refinement::FacePlace;
use super::uv::UvMesh;
use crate::io::svg::SvgFrame;
use std::collections::HashSet;
use std::fmt::Write as _;

/// The sides (0..3) of a triangle that a point lies on, given as "side `r` at `σ`".
fn sides_at(r: usize, sigma: f64) -> [Option<usize>; 2] {
    if sigma == 0.0 {
        [Some(r), Some((r + 2) % 3)]
    } else if sigma == 1.0 {
        [Some(r), Some((r + 1) % 3)]
    } else {
        [Some(r), None]
    }
}

/// Whether two points given by their sides share one.
fn share(a: [Option<usize>; 2], b: [Option<usize>; 2]) -> bool {
    a.iter()
        .flatten()
        .any(|x| b.iter().flatten().any(|y| x == y))
}

/// The sides of the face of `T_F` that a place lies on.
fn final_sides(p: FacePlace) -> [Option<usize>; 2] {
    match p {
        FacePlace::Corner(r) => sides_at(r, 0.0),
        FacePlace::Side(r, _) => [Some(r), None],
    }
}

/// The line groups (input pieces orange, final pieces blue over them, cones red) and the
/// end of the document.
fn close(out: &mut String, input_pieces: &str, final_pieces: &str, marks: &str, stroke: f64) {
    for (colour, lines) in [("#d07020", input_pieces), ("#2050a0", final_pieces)] {
        let _ = writeln!(out, r#"<g stroke="{colour}" stroke-width="{stroke:.3}">"#);
        out.push_str(lines);
        out.push_str("</g>\n");
    }
    out.push_str("<g fill=\"#d02020\">\n");
    out.push_str(marks);
    out.push_str("</g>\n</svg>\n");
}

/// The SVG document (text) of the UV layout of `uv` (module documentation), 800 px wide,
/// `y` up; `cones[v]` marks input vertex `v` as a cone (an input vertex is refinement
/// vertex `v`, the input vertices coming first).
pub fn render_uv_svg(uv: &UvMesh, cones: &[bool]) -> String {
    let frame = SvgFrame::of(uv.uv.iter().flatten());
    let tx = |p: [f64; 2]| frame.px(p);
    let n = uv.refinement.triangles.len().max(1) as f64;
    let stroke = 0.6f64.min(150.0 / n.sqrt());
    let mut out = frame.header();
    let mut input_pieces = String::new();
    let mut final_pieces = String::new();
    let mut marks = String::new();
    let mut seen: HashSet<(u64, u64, u64, u64)> = HashSet::new();
    let mut marked: HashSet<(u64, u64)> = HashSet::new();
    for ((tri, corners), bary) in uv
        .refinement
        .triangles
        .iter()
        .zip(&uv.uv)
        .zip(&uv.barycentric)
    {
        let p = corners.map(tx);
        let _ = writeln!(
            out,
            r##"<polygon points="{:.3},{:.3} {:.3},{:.3} {:.3},{:.3}" fill="#eef2f6"/>"##,
            p[0].0, p[0].1, p[1].0, p[1].1, p[2].0, p[2].1
        );
        for k in 0..3 {
            let l = (k + 1) % 3;
            let (a, b) = (corners[k], corners[l]);
            let key = {
                let (a, b) = if (a[0], a[1]) <= (b[0], b[1]) {
                    (a, b)
                } else {
                    (b, a)
                };
                (
                    a[0].to_bits(),
                    a[1].to_bits(),
                    b[0].to_bits(),
                    b[1].to_bits(),
                )
            };
            if !seen.insert(key) {
                continue;
            }
            let on_final = share(final_sides(tri.places[k]), final_sides(tri.places[l]));
            let on_input = share(
                sides_at(bary[k].0, bary[k].1),
                sides_at(bary[l].0, bary[l].1),
            );
            let target = if on_final {
                &mut final_pieces
            } else if on_input {
                &mut input_pieces
            } else {
                continue;
            };
            let _ = writeln!(
                target,
                r#"<line x1="{:.3}" y1="{:.3}" x2="{:.3}" y2="{:.3}"/>"#,
                p[k].0, p[k].1, p[l].0, p[l].1
            );
        }
        for (k, &v) in tri.vertices.iter().enumerate() {
            let is_cone = cones.get(v as usize).copied().unwrap_or(false);
            if is_cone && marked.insert((corners[k][0].to_bits(), corners[k][1].to_bits())) {
                let _ = writeln!(
                    marks,
                    r#"<circle cx="{:.3}" cy="{:.3}" r="4"/>"#,
                    p[k].0, p[k].1
                );
            }
        }
    }
    close(&mut out, &input_pieces, &final_pieces, &marks, stroke);
    out
}

#[cfg(test)]
mod tests {
    use super::{final_sides, share, sides_at};
    use crate::overlay::refinement::FacePlace;

    /// Corner `r` lies on sides `r` and `r − 1`; corner `r + 1`, written as side `r` at
    /// `σ = 1`, on sides `r` and `r + 1`; an inner point of side `r` on it alone. Controls:
    /// inner points of two different sides share none, and corner 0 is not on side 1.
    #[test]
    fn sides_of_corners_and_side_points() {
        assert!(share(sides_at(0, 0.0), sides_at(2, 0.5)));
        assert!(share(sides_at(0, 1.0), sides_at(1, 0.3)));
        assert!(share(sides_at(0, 1.0), sides_at(1, 0.0)));
        assert!(share(sides_at(1, 0.25), sides_at(1, 0.75)));
        assert!(!share(sides_at(0, 0.5), sides_at(1, 0.5)));
        assert!(!share(sides_at(0, 0.0), sides_at(1, 0.5)));
        assert!(share(
            final_sides(FacePlace::Corner(2)),
            final_sides(FacePlace::Side(1, 0.5))
        ));
        assert!(!share(
            final_sides(FacePlace::Corner(0)),
            final_sides(FacePlace::Side(1, 0.5))
        ));
    }
}
