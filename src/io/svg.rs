//! The frame of the project's SVG pictures of planar layouts: the bounding box of the
//! points fitted into 760 px with a 20 px margin (800 px wide at most), `y` pointing up, on a
//! white background.

use std::fmt::Write as _;

/// A bounding box mapped to SVG pixels: `(20 + s(x − x₀), h − 20 − s(y − y₀))`,
/// `s = 760/max(width, height)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SvgFrame {
    x0: f64,
    y0: f64,
    /// Pixels per unit.
    pub scale: f64,
    /// The picture's width in pixels.
    pub width: f64,
    /// The picture's height in pixels.
    pub height: f64,
    /// The larger side of the bounding box, in the points' units.
    pub span: f64,
}

impl SvgFrame {
    /// The frame of `points` (the unit square when there is none or the box is not finite).
    pub fn of<'a>(points: impl IntoIterator<Item = &'a [f64; 2]>) -> SvgFrame {
        let (mut x0, mut y0, mut x1, mut y1) = (f64::MAX, f64::MAX, f64::MIN, f64::MIN);
        for p in points {
            x0 = x0.min(p[0]);
            y0 = y0.min(p[1]);
            x1 = x1.max(p[0]);
            y1 = y1.max(p[1]);
        }
        if x0 > x1 || !(x1 - x0).is_finite() || !(y1 - y0).is_finite() {
            (x0, y0, x1, y1) = (0.0, 0.0, 1.0, 1.0);
        }
        let span = (x1 - x0).max(y1 - y0).max(f64::MIN_POSITIVE);
        let scale = 760.0 / span;
        SvgFrame {
            x0,
            y0,
            scale,
            width: scale * (x1 - x0) + 40.0,
            height: scale * (y1 - y0) + 40.0,
            span,
        }
    }

    /// The pixel position of `p`.
    pub fn px(&self, p: [f64; 2]) -> (f64, f64) {
        (
            20.0 + self.scale * (p[0] - self.x0),
            self.height - 20.0 - self.scale * (p[1] - self.y0),
        )
    }

    /// The opening `<svg …>` element and the white background.
    pub fn header(&self) -> String {
        let (w, h) = (self.width, self.height);
        let mut out = String::new();
        let _ = writeln!(
            out,
            r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w:.0}" height="{h:.0}" viewBox="0 0 {w:.2} {h:.2}">"#
        );
        let _ = writeln!(
            out,
            r##"<rect width="100%" height="100%" fill="#ffffff"/>"##
        );
        out
    }
}
