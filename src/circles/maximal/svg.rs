//! SVG pictures of maximal packings: the circles in the unit disk, the unit circle (the
//! boundary of the disk, or the punctured vertex's circle of a sphere) and the edges of the
//! triangulation between the centres; packings of the sphere as caps seen orthographically
//! ([`render_sphere_svg`]).

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

/// The direction the sphere is seen from in [`render_sphere_svg`]: `d = (0, −sin 40°,
/// cos 40°)`, above the northern hemisphere (where the caps of the punctured sphere lie)
/// and tilted so that the southern cap's rim (the equator) shows.
pub const VIEW_ELEVATION_DEG: f64 = 40.0;

/// The view frame of [`render_sphere_svg`]: screen axes `a = (1, 0, 0)`, `b = (0, cos φ,
/// sin φ)` and the view direction `d = (0, −sin φ, cos φ)` (`a × b = d`), `φ` =
/// [`VIEW_ELEVATION_DEG`]. Returns `(a·P, b·P, d·P)`.
pub fn view_coordinates(p: &[f64; 3]) -> [f64; 3] {
    let (s, c) = VIEW_ELEVATION_DEG.to_radians().sin_cos();
    [p[0], c * p[1] + s * p[2], -s * p[1] + c * p[2]]
}

/// A cap in the orthographic view: its rim, the circle of centre `h·n` and radius
/// `√(1 − h²)` in the plane `n·P = h`, projects to the ellipse of centre `h·(n'_x, n'_y)`,
/// semi-axes `√(1 − h²)` (perpendicular to `(n'_x, n'_y)`) and `√(1 − h²)·|n'_z|` (along
/// it), `n'` the normal in view coordinates. `front` when the cap's centre faces the viewer
/// (`n'_z > 0`).
#[derive(Clone, Debug, PartialEq)]
pub struct CapEllipse {
    /// Centre on the screen (y up).
    pub centre: [f64; 2],
    /// Semi-major axis.
    pub major: f64,
    /// Semi-minor axis.
    pub minor: f64,
    /// Angle of the major axis from the screen's x axis, radians (counterclockwise).
    pub angle: f64,
    /// Whether the cap's centre faces the viewer.
    pub front: bool,
}

/// The projected rim of a cap (unit normal `n`, height `h = cos` of its angular radius).
pub fn cap_ellipse(cap: &super::sphere::Cap<f64>) -> CapEllipse {
    let n = view_coordinates(&cap.normal);
    let h = cap.height;
    let rho = (1.0 - h * h).max(0.0).sqrt();
    CapEllipse {
        centre: [h * n[0], h * n[1]],
        major: rho,
        minor: rho * n[2].abs(),
        angle: n[1].atan2(n[0]) + std::f64::consts::FRAC_PI_2,
        front: n[2] > 0.0,
    }
}

/// An SVG document of the caps on the unit sphere seen orthographically from
/// [`VIEW_ELEVATION_DEG`] (module docs of [`super::sphere`]): the sphere's outline, every
/// front-facing cap as a filled ellipse (`class="front"`, [`cap_ellipse`]) and every
/// back-facing cap as a faint dashed outline (`class="back"`). A front cap that reaches over
/// the limb is drawn whole, its hidden arc included; the visible band of a large back-facing
/// cap (the southern hemisphere of a punctured packing, between the dashed equator and the
/// limb) is left unfilled.
pub fn render_sphere_svg(caps: &[super::sphere::Cap<f64>]) -> String {
    let stroke = 0.003;
    let mut s = String::new();
    let _ = writeln!(
        s,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"-1.05 -1.05 2.1 2.1\" width=\"800\" height=\"800\">"
    );
    let _ = writeln!(
        s,
        "<rect x=\"-1.05\" y=\"-1.05\" width=\"2.1\" height=\"2.1\" fill=\"white\"/>"
    );
    let ellipses: Vec<(usize, CapEllipse)> = caps.iter().map(cap_ellipse).enumerate().collect();
    let draw = |s: &mut String, v: usize, e: &CapEllipse, class: &str| {
        // SVG's y axis points down: y and the angle are negated to keep the orientation.
        let _ = writeln!(
            s,
            "<ellipse class=\"{class}\" cx=\"0\" cy=\"0\" rx=\"{}\" ry=\"{}\" transform=\"translate({} {}) rotate({})\"><title>v{v}</title></ellipse>",
            e.major,
            e.minor,
            e.centre[0],
            -e.centre[1],
            -e.angle.to_degrees()
        );
    };
    let _ = writeln!(
        s,
        "<g fill=\"none\" stroke=\"#bbb\" stroke-width=\"{}\" stroke-dasharray=\"0.01 0.01\">",
        stroke / 2.0
    );
    for (v, e) in ellipses.iter().filter(|(_, e)| !e.front) {
        draw(&mut s, *v, e, "back");
    }
    let _ = writeln!(s, "</g>");
    let _ = writeln!(
        s,
        "<circle cx=\"0\" cy=\"0\" r=\"1\" fill=\"#f4f4f4\" fill-opacity=\"0.5\" stroke=\"black\" stroke-width=\"{stroke}\"/>"
    );
    let _ = writeln!(
        s,
        "<g fill=\"#4a90d9\" fill-opacity=\"0.25\" stroke=\"#1f4e8c\" stroke-width=\"{stroke}\">"
    );
    for (v, e) in ellipses.iter().filter(|(_, e)| e.front) {
        draw(&mut s, *v, e, "front");
    }
    let _ = writeln!(s, "</g>\n</svg>");
    s
}
