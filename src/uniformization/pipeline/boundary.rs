//! Uniformization of a surface with boundary (B79): interior cone angles and boundary angle
//! sums, solved on the double with `Θ = 2φ` at boundary vertices and certified there for
//! the input's exact metric pulled back to both copies, the pipeline behind `penner
//! uniformize` on a surface with boundary.
//!
//! ```
//! use penner::io::Surface;
//! use penner::mesh::builders;
//! use penner::uniformization::pipeline::{uniformize_boundary, Options};
//! // A 2×2 grid of squares, each split by a diagonal: flat inside, the boundary curvature
//! // spread evenly (`targets: None`).
//! let s = Surface::from_embedded("grid", builders::grid_disk(2, 2).unwrap()).unwrap();
//! let out = uniformize_boundary(&s, None, &Options::default()).unwrap();
//! assert!(out.certified());
//! assert!(out.claim().is_some());
//! ```

use super::closed::{certify_solution, Certification};
use super::{rescaled, CertifiedMetric, Options, PipelineError};
use crate::io::{Metric, Surface};
use crate::mesh::double::{Double, Sheet};
use crate::mesh::Face;
use crate::scalar::{Certified, Sign};
use crate::uniformization::boundary::{
    flat_with_even_boundary, uniformize_with_boundary, BoundaryUniformization,
};
use crate::uniformization::claim_form::ClaimJson;
use crate::uniformization::layout::{face_orientations, unfold, unfold_within, Layout};
use crate::uniformization::svg::scaled_lengths_f64;
use crate::uniformization::{Targets, UniformizeOptions};
use serde_json::Value;

/// The outcome of [`uniformize_boundary`].
#[derive(Clone, Debug)]
pub struct BoundaryOutcome {
    /// The surface solved (the input divided by `2^shift` exactly when its lengths are far
    /// from 1).
    pub surface: Surface,
    /// The exact power of two the lengths were divided by (0: none).
    pub shift: i64,
    /// The solve on the double (its `solution` holds `u`, the final triangulation, the
    /// flips and the residual).
    pub boundary: BoundaryUniformization,
    /// The double with the input's exact metric on both copies (with a certificate).
    pub double: Option<Surface>,
    /// The refinement and certificate on the double, when the solve converged and a
    /// certificate was asked for.
    pub certification: Option<Certification>,
    /// The certificate's interval bits.
    pub bits: u32,
}

/// The layout drawn for a surface with boundary: copy 1 of the final triangulation when
/// the seam is intact, else the whole double.
#[derive(Clone, Debug)]
pub struct SvgLayout {
    /// Per-corner planar coordinates.
    pub layout: Layout,
    /// What is drawn.
    pub what: &'static str,
    /// Faces drawn whose orientation is not certified counterclockwise (exact predicates
    /// on the binary64 coordinates).
    pub folds: usize,
}

impl BoundaryOutcome {
    /// Whether an exact solution of the double's problem was proved to exist near `u`.
    pub fn certified(&self) -> bool {
        self.certification.as_ref().is_some_and(|c| {
            matches!(
                c.proof.outcome,
                crate::uniformization::certificate::CertificateOutcome::Holds { .. }
            )
        })
    }

    /// The metric the certificate is about (with a certificate).
    pub fn metric(&self) -> Option<&CertifiedMetric> {
        self.certification.as_ref().map(|c| &c.metric)
    }

    /// The double's `uniformization` claim of a certified outcome, ready to write.
    pub fn claim(&self) -> Option<Value> {
        self.claim_json().map(|c| c.value())
    }

    /// The claim of [`Self::claim`] as a view to serialize straight into a file
    /// ([`ClaimJson`]: the same text, without building the value).
    pub fn claim_json(&self) -> Option<ClaimJson<'_>> {
        let (c, d) = (self.certification.as_ref()?, self.double.as_ref()?);
        c.claim_json(d, self.bits)
    }

    /// `max |θ_v − target|` on copy 1 (`f64`, numerical: half the double's target at seam
    /// vertices), when the seam is intact.
    pub fn worst_angle_on_copy_1(&self) -> Option<f64> {
        let b = &self.boundary;
        let sums = b.angle_sums_on_original()?;
        Some(
            sums.iter()
                .zip(b.solution.targets.over_pi())
                .zip(&b.double.vertex_sheet)
                .map(|((s, q), sheet)| {
                    let full = q.to_f64() * std::f64::consts::PI;
                    let want = if *sheet == Sheet::Seam {
                        full / 2.0
                    } else {
                        full
                    };
                    (s - want).abs()
                })
                .fold(0.0, f64::max),
        )
    }

    /// The planar layout of copy 1 (the flattened surface) when the seam is intact, else
    /// of the whole double, with its folds counted by exact predicates.
    pub fn layout(&self) -> SvgLayout {
        let b = &self.boundary;
        let sol = &b.solution;
        let lengths = scaled_lengths_f64(&sol.mesh, &sol.base_lengths, &sol.u);
        let region = b.original_faces();
        let (layout, what) = match (&region, b.original_root()) {
            (Some(keep), Some(root)) => (
                unfold_within(&sol.mesh, &lengths, root, Some(keep)),
                "the surface (copy 1 of the double)",
            ),
            _ => (
                unfold(&sol.mesh, &lengths, Face(0)),
                "the whole double (a seam edge was flipped)",
            ),
        };
        let folds = face_orientations(&sol.mesh, &layout)
            .iter()
            .enumerate()
            .filter(|(f, _)| region.as_ref().is_none_or(|k| k[*f]))
            .filter(|(_, o)| o.as_ref().and_then(Certified::value) != Some(Sign::Positive))
            .count();
        SvgLayout {
            layout,
            what,
            folds,
        }
    }
}

/// Uniformize the surface with boundary `surface` to `targets` (`Θ_v/π` at interior
/// vertices, `φ_v/π` at boundary vertices; `None`: flat inside with the boundary curvature
/// spread evenly, [`flat_with_even_boundary`]) on its double (B79), then refine and
/// certify on the double for the input's exact metric where possible.
pub fn uniformize_boundary(
    surface: &Surface,
    targets: Option<&Targets>,
    options: &Options,
) -> Result<BoundaryOutcome, PipelineError> {
    let (surface, shift, lengths) = rescaled(surface);
    let targets = targets.map_or_else(|| flat_with_even_boundary(&surface.mesh), Clone::clone);
    let boundary = uniformize_with_boundary(
        &surface.mesh,
        &lengths,
        &targets,
        &UniformizeOptions::default(),
        &mut |_| {},
    )?;
    let (bits, _) = options.precision.bits_and_tolerance();
    let mut out = BoundaryOutcome {
        double: None,
        certification: None,
        surface,
        shift,
        boundary,
        bits,
    };
    if !out.boundary.solution.converged() || !options.certify {
        return Ok(out);
    }
    let (Some(double), Some(double_lengths)) = (
        double_surface(&out.surface, &out.boundary.double),
        out.boundary.double.pull_back_edges(&lengths),
    ) else {
        return Err(PipelineError::NotComputed(
            "not certified: the exact metric could not be pulled back to the double".into(),
        ));
    };
    let c = certify_solution(
        &double,
        &double_lengths,
        &out.boundary.solution,
        options.precision,
    )?;
    out.double = Some(double);
    out.certification = Some(c);
    Ok(out)
}

/// The double `D` of a surface with boundary (B79) as a closed [`Surface`] with `surface`'s
/// exact metric pulled back to both copies (no positions: copy 2 is the mirror image, not
/// an embedding). `None` when `double` is not the double of `surface.mesh`.
///
/// The metric is not validated again: every face of `D` is a face of `surface` or its
/// mirror image, with the same three edge values (B78), so the strict triangle
/// inequalities that [`Surface::new`] checked on `surface` hold on `D` face by face.
pub fn double_surface(surface: &Surface, double: &Double) -> Option<Surface> {
    if double.face_origin.len() != double.mesh.n_faces()
        || double.edge_origin.len() != double.mesh.n_edges()
        || double.mesh.n_faces() != 2 * surface.mesh.n_faces()
    {
        return None;
    }
    let metric = match &surface.metric {
        Metric::Lengths(v) => Metric::Lengths(double.pull_back_edges(v)?),
        Metric::SquaredLengths(v) => Metric::SquaredLengths(double.pull_back_edges(v)?),
    };
    Some(Surface {
        mesh: double.mesh.clone(),
        metric,
        positions: None,
        name: format!("double of {}", surface.name),
    })
}
