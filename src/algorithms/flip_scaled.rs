//! Flip to an intrinsic Delaunay triangulation of a conformally scaled metric
//! `ℓ̃_ij = e^{(u_i+u_j)/2}·ℓ_ij` (docs/catalogue.md §4) without overflow or underflow: lengths are
//! kept as [`ExpLength`] (`m·2ᵏ`, exponent apart), every decision is made on the
//! quadrilateral shifted by its largest exponent ([`ExpQuad`], proof: B67), and new
//! diagonals are computed on the shifted binary64 images (MPFR at 53 bits when one
//! quadrilateral spans more than 2⁹⁹).
//!
//! The driver, its certificate and its report are those of
//! [`crate::algorithms::flip_to_delaunay`] (T21, B61, B65, B66): for the lengths returned,
//! every edge not listed as undecided or refused is certified Delaunay, and after
//! Euclidean flips every new face is a certified non-degenerate triangle.
//!
//! ```
//! use penner::algorithms::flip_scaled::flip_to_delaunay_scaled;
//! use penner::algorithms::flip_to_delaunay::{FlipKind, FlipOptions};
//! use penner::mesh::Mesh;
//! // A unit square with diagonal 0-2; scale factors ±800 put the lengths near e^{±800}.
//! let mut m = Mesh::from_faces(4, &[[0, 1, 2], [0, 2, 3]]).unwrap();
//! let base: Vec<f64> = m.edges().map(|e| {
//!     let h = e.halfedge();
//!     if (m.tail(h).0 + m.tip(h).0) % 2 == 0 { 2f64.sqrt() } else { 1.0 }
//! }).collect();
//! let u = [800.0, -800.0, 790.0, -800.0];
//! let (r, l) = flip_to_delaunay_scaled(&mut m, &base, &u, FlipKind::Ptolemy,
//!     &FlipOptions::default()).unwrap();
//! assert!(r.all_certified_delaunay());
//! assert!(l.iter().all(|x| x.log2().abs() < 1300.0));
//! ```

use super::flip_to_delaunay::{
    check_faces, new_faces, run, FlipOptions, FlipReport, FlipToDelaunayError, Metric,
};
use super::flips::{euclidean_length, moderate_f64, ptolemy_length, FlipKind};
use crate::mesh::{Edge, Mesh};
use crate::predicates::delaunay::{DelaunayError, Quad, QuadEdges};
use crate::predicates::delaunay_exp::{strict_triangle_exp, ExpQuad};
use crate::predicates::ladder::{decide, Ladder, SignPredicate};
use crate::scalar::exp_length::{ExpLength, MAX_LOG_SCALE};
use crate::scalar::{Certified, Mpfr, Precision, Real, Sign};

struct ExpMetric {
    lengths: Vec<ExpLength>,
    kind: FlipKind,
}

impl ExpMetric {
    fn quad(&self, q: Quad<Edge>) -> ExpQuad<'_> {
        ExpQuad(q.map(|e| &self.lengths[e.idx()]))
    }
}

/// The flip length of `kind` on five exponent-apart lengths: the formula on the images
/// shifted by the largest exponent `E` (exact shift, and the formulas are homogeneous of
/// degree 1, proof: B67), then shifted back; on MPFR at 53 bits when an image leaves the
/// range where the binary64 formula needs no rescaling.
fn flip_length_exp(q: Quad<&ExpLength>, kind: FlipKind) -> Option<ExpLength> {
    let e = q.to_array().iter().map(|l| l.exponent()).max()?;
    let s = q.map(|l| l.shifted(e));
    let formula = |x: Quad<&f64>| match kind {
        FlipKind::Euclidean => euclidean_length(x),
        FlipKind::Ptolemy => ptolemy_length(x),
    };
    if s.to_array().into_iter().all(moderate_f64) {
        return ExpLength::new(formula(s.as_refs()), i64::from(e));
    }
    // A wide quadrilateral: the same formula in MPFR's exponent range, 53 bits.
    let prec = Precision::new(53).ok()?;
    let m = q.map(|l| Mpfr::from_rational(&l.shifted_rational(e), prec));
    let r = match kind {
        FlipKind::Euclidean => euclidean_length(m.as_refs()),
        FlipKind::Ptolemy => ptolemy_length(m.as_refs()),
    };
    let x = ExpLength::from_float(r.as_float())?;
    ExpLength::new(x.mantissa(), i64::from(x.exponent()) + i64::from(e))
}

impl Metric for ExpMetric {
    type Saved = ExpLength;
    fn filter(&self, q: Quad<Edge>) -> Option<Sign> {
        self.quad(q).filter()
    }
    fn sign(&self, q: Quad<Edge>, ladder: &Ladder) -> Certified<Sign> {
        decide(&self.quad(q), ladder)
    }
    fn flip_length(&mut self, q: &QuadEdges) -> Option<ExpLength> {
        let new = flip_length_exp(q.lengths(&self.lengths), self.kind)?;
        Some(std::mem::replace(&mut self.lengths[q.edge.idx()], new))
    }
    fn restore(&mut self, e: Edge, old: ExpLength) {
        self.lengths[e.idx()] = old;
    }
    fn nudge(&mut self, e: Edge) -> bool {
        // proof: B65 — m ← fl(m − fl(4u·m)) on the significand, the exponent unchanged.
        let l = self.lengths[e.idx()];
        let m = l.mantissa();
        let m = m - m * (4.0 * f64::EPSILON / 2.0);
        match ExpLength::new(m, i64::from(l.exponent())) {
            Some(x) => {
                self.lengths[e.idx()] = x;
                true
            }
            None => false,
        }
    }
    fn new_triangles_valid(&self, q: &QuadEdges, ladder: &Ladder) -> bool {
        if self.kind == FlipKind::Ptolemy {
            return true;
        }
        // proof: B66, B67
        new_faces(q, &self.lengths)
            .iter()
            .all(|&t| strict_triangle_exp(t, ladder).value() == Some(true))
    }
}

/// Flip `mesh` to an intrinsic Delaunay triangulation of the exponent-apart `lengths`
/// (one per edge) with Euclidean or Ptolemy flips (T21), returning the report and the
/// final lengths. Euclidean flips refuse a face that is not a certified non-degenerate
/// triangle ([`DelaunayError::NotATriangle`]; conformal scalings with unequal factors often
/// break the triangle inequality, Ptolemy flips do not need it). The certificate is that of
/// [`flip_to_delaunay`](crate::algorithms::flip_to_delaunay::flip_to_delaunay).
pub fn flip_to_delaunay_exp(
    mesh: &mut Mesh,
    lengths: Vec<ExpLength>,
    kind: FlipKind,
    opts: &FlipOptions,
) -> Result<(FlipReport, Vec<ExpLength>), FlipToDelaunayError> {
    if lengths.len() != mesh.n_edges() {
        return Err(DelaunayError::LengthCount {
            expected: mesh.n_edges(),
            got: lengths.len(),
        }
        .into());
    }
    if kind == FlipKind::Euclidean {
        check_faces(mesh, |f| {
            let [a, b, c] = mesh.face_halfedges(f).map(|h| &lengths[h.edge().idx()]);
            strict_triangle_exp([a, b, c], &opts.ladder)
        })?;
    }
    let mut m = ExpMetric { lengths, kind };
    let report = run(mesh, &mut m, opts);
    Ok((report, m.lengths))
}

/// The lengths `ℓ̃_ij = e^{(u_i+u_j)/2}·ℓ_ij` (docs/catalogue.md §4) as [`ExpLength`], each rounded
/// once to 53 bits ([`ExpLength::scaled`]), validated: one positive finite base length per
/// edge, one finite log scale factor per vertex with `|u| ≤` [`MAX_LOG_SCALE`].
pub fn scaled_lengths(
    mesh: &Mesh,
    base: &[f64],
    u: &[f64],
) -> Result<Vec<ExpLength>, DelaunayError> {
    if base.len() != mesh.n_edges() {
        return Err(DelaunayError::LengthCount {
            expected: mesh.n_edges(),
            got: base.len(),
        });
    }
    if u.len() != mesh.n_vertices() {
        return Err(DelaunayError::ScaleCount {
            expected: mesh.n_vertices(),
            got: u.len(),
        });
    }
    for (v, &x) in u.iter().enumerate() {
        if !x.is_finite() {
            return Err(DelaunayError::BadScale {
                vertex: v as u32,
                value: x,
            });
        }
        if x.abs() > MAX_LOG_SCALE {
            return Err(DelaunayError::ScaleOutOfRange {
                vertex: v as u32,
                value: x,
            });
        }
    }
    mesh.edges()
        .map(|e| {
            let h = e.halfedge();
            let (i, j) = (mesh.tail(h).idx(), mesh.tip(h).idx());
            ExpLength::scaled(base[e.idx()], u[i], u[j]).ok_or(DelaunayError::BadLength {
                edge: e,
                value: base[e.idx()],
            })
        })
        .collect()
}

/// Flip to an intrinsic Delaunay triangulation of the conformally scaled metric
/// `e^{(u_i+u_j)/2}·ℓ_ij` ([`scaled_lengths`], then [`flip_to_delaunay_exp`]). Safe for
/// every `|u| ≤` [`MAX_LOG_SCALE`]: nothing is formed outside binary64's range.
pub fn flip_to_delaunay_scaled(
    mesh: &mut Mesh,
    base: &[f64],
    u: &[f64],
    kind: FlipKind,
    opts: &FlipOptions,
) -> Result<(FlipReport, Vec<ExpLength>), FlipToDelaunayError> {
    let lengths = scaled_lengths(mesh, base, u)?;
    flip_to_delaunay_exp(mesh, lengths, kind, opts)
}
