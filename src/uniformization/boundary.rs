//! Surfaces with boundary by the double cover (notes §1.5.3; Campen et al. 2021): prescribed
//! interior cone angles `Θ_v` and boundary angle sums `φ_v`, solved as the closed problem
//! on the double `D` ([`crate::mesh::double`]) with `Θ_D = 2φ_v` at boundary vertices and
//! `Θ_v` on both copies of an interior vertex. proof: B79
//!
//! The targets are one `q_v` per vertex of `M`: `Θ_v = q_v·π` at an interior vertex and
//! `φ_v = q_v·π` at a boundary vertex, exact rationals, with Gauss–Bonnet with boundary
//! `Σ_int (2π − Θ_v) + Σ_∂ (π − φ_v) = 2πχ(C)` decided exactly per component `C` — which is
//! Gauss–Bonnet `Σ (2π − Θ_D) = 2πχ(D_C) = 4πχ(C)` on the double.
//!
//! The solve is the closed-surface solver on `D` (one grounded vertex per component of
//! `D`); `u` on `M` is `u` on copy 1. The solution with a fixed grounded value is unique
//! (T25) and `u* ∘ ι` is a solution too, so `u* ∘ ι = u*`: the symmetry is *checked*
//! ([`BoundaryUniformization::mirror_asymmetry`]), not enforced.

use super::components::Components;
use super::error::UniformizeError;
use super::newton::{uniformize_with_progress, StepReport, Uniformization, UniformizeOptions};
use super::targets::Targets;
use crate::algorithms::flip_to_delaunay::{flip_to_delaunay, FlipKind, FlipOptions};
use crate::geometry::corners::halfedge_angles;
use crate::mesh::double::{Double, DoubleError, Sheet};
use crate::mesh::{Edge, Face, Mesh};
use rug::Rational;
use std::collections::VecDeque;

/// Why a problem with boundary was refused (bad input, named by element).
#[derive(Debug, thiserror::Error)]
pub enum BoundaryError {
    /// The double could not be built.
    #[error(transparent)]
    Double(#[from] DoubleError),
    /// A component of the surface has no boundary (use the closed-surface solver).
    #[error("the component of v{root} has no boundary; prescribed boundary angles need every component to have boundary")]
    ClosedComponent {
        /// The smallest vertex of the component.
        root: u32,
    },
    /// Wrong number of targets.
    #[error(
        "{expected} targets expected (Θ_v/π at interior, φ_v/π at boundary vertices), got {got}"
    )]
    TargetCount {
        /// Vertices.
        expected: usize,
        /// Targets given.
        got: usize,
    },
    /// A target is `≤ 0`.
    #[error("target of {kind} vertex v{vertex} is {over_pi}·π: angles must be > 0")]
    NonPositiveTarget {
        /// The vertex.
        vertex: u32,
        /// "interior" or "boundary".
        kind: &'static str,
        /// `q_v` as an exact rational.
        over_pi: String,
    },
    /// Gauss–Bonnet with boundary is violated on a component.
    #[error(
        "Gauss–Bonnet with boundary: on the component of v{root}, Σ_int(2π − Θ_v) + Σ_∂(π − φ_v) = {sum_over_pi}·π but 2πχ = {}·π (χ = {chi})",
        2 * chi
    )]
    GaussBonnet {
        /// The smallest vertex of the component.
        root: u32,
        /// `Σ_int (2 − q_v) + Σ_∂ (1 − q_v)` exactly.
        sum_over_pi: String,
        /// The Euler characteristic of the component.
        chi: i64,
    },
    /// Wrong number of lengths.
    #[error("{expected} edge lengths expected, got {got}")]
    LengthCount {
        /// Edges.
        expected: usize,
        /// Lengths given.
        got: usize,
    },
    /// The closed-surface solver refused the double.
    #[error("on the double: {0}")]
    Solve(#[from] UniformizeError),
}

/// Check targets with boundary on `mesh`: one per vertex, each `> 0`, every component has
/// boundary, and `Σ_int (2 − q_v) + Σ_∂ (1 − q_v) = 2χ(C)` exactly on every component `C`.
/// proof: B79
pub fn validate_boundary_targets(mesh: &Mesh, targets: &Targets) -> Result<(), BoundaryError> {
    let q = targets.over_pi();
    if q.len() != mesh.n_vertices() {
        return Err(BoundaryError::TargetCount {
            expected: mesh.n_vertices(),
            got: q.len(),
        });
    }
    let on_boundary = mesh.boundary_vertices();
    for (v, x) in q.iter().enumerate() {
        if *x <= 0 {
            return Err(BoundaryError::NonPositiveTarget {
                vertex: v as u32,
                kind: if on_boundary[v] {
                    "boundary"
                } else {
                    "interior"
                },
                over_pi: x.to_string(),
            });
        }
    }
    let comps = Components::of(mesh);
    for (c, &root) in comps.roots.iter().enumerate() {
        if !comps.vertices_of(c).any(|v| on_boundary[v]) {
            return Err(BoundaryError::ClosedComponent { root: root as u32 });
        }
        let mut sum = Rational::new();
        for v in comps.vertices_of(c) {
            let full = if on_boundary[v] { 1 } else { 2 };
            sum += Rational::from(full) - &q[v];
        }
        let chi = comps.euler_characteristic(mesh, c);
        if sum != 2 * chi {
            return Err(BoundaryError::GaussBonnet {
                root: root as u32,
                sum_over_pi: sum.to_string(),
                chi,
            });
        }
    }
    Ok(())
}

/// The default targets of `--flat` on a surface with boundary: `Θ_v = 2π` inside, and the
/// boundary curvature `2πχ(C)` spread evenly over the `n_∂(C)` boundary vertices of each
/// component, `φ_v = π − 2πχ(C)/n_∂(C)` (a disk becomes a flat polygon with equal corner
/// angles `π(1 − 2/n_∂)`, the discrete analogue of the round disk). Closed components keep
/// `2π` (and are refused by [`validate_boundary_targets`]).
pub fn flat_with_even_boundary(mesh: &Mesh) -> Targets {
    let on_boundary = mesh.boundary_vertices();
    let comps = Components::of(mesh);
    let mut q = vec![Rational::from(2); mesh.n_vertices()];
    for c in 0..comps.roots.len() {
        let n_b = comps.vertices_of(c).filter(|&v| on_boundary[v]).count();
        if n_b == 0 {
            continue;
        }
        let chi = comps.euler_characteristic(mesh, c);
        let phi = Rational::from(1) - Rational::from((2 * chi, n_b as i64));
        for v in comps.vertices_of(c) {
            if on_boundary[v] {
                q[v].clone_from(&phi);
            }
        }
    }
    Targets::from_multiples_of_pi(q)
}

/// The targets on the double: `Θ_D(v) = 2φ_v` at a seam vertex, `Θ_v` on both copies of
/// an interior vertex. proof: B79
pub fn double_targets(double: &Double, targets: &Targets) -> Targets {
    let q = targets.over_pi();
    Targets::from_multiples_of_pi(
        double
            .vertex_origin
            .iter()
            .zip(&double.vertex_sheet)
            .map(|(v, s)| match s {
                Sheet::Seam => Rational::from(2 * &q[v.idx()]),
                _ => q[v.idx()].clone(),
            })
            .collect(),
    )
}

/// The result of [`uniformize_with_boundary`].
#[derive(Clone, Debug)]
pub struct BoundaryUniformization {
    /// The double of the input (before any flip).
    pub double: Double,
    /// The closed-surface solve on the double: its final triangulation is of `D`.
    pub solution: Uniformization,
    /// `u` on `M`: the double's `u` on copy 1 (same vertex ids).
    pub u: Vec<f64>,
    /// `max_v |u(v) − u(ι v)|` over the vertices of `D`: the measured asymmetry of the
    /// computed solution (the exact one is symmetric, B79).
    pub mirror_asymmetry: f64,
    /// Seam edges flipped, by the Euclidean flips to the Delaunay `T₀` or by the Ptolemy
    /// flips of the solve (then the final triangulation does not contain the seam).
    pub seam_flips: Vec<Edge>,
}

/// Solve for `u` with interior cone angles and boundary angle sums `targets` (see the
/// module documentation) on a surface with boundary, by the closed-surface solver on the
/// double. The double is first flipped to an intrinsic Delaunay `T₀` by Euclidean flips
/// (recorded, so that flips of seam edges are reported), then handed to
/// [`uniformize_with_progress`], which finds it Delaunay already. proof: B79
pub fn uniformize_with_boundary(
    mesh: &Mesh,
    lengths: &[f64],
    targets: &Targets,
    opts: &UniformizeOptions,
    progress: &mut dyn FnMut(&StepReport),
) -> Result<BoundaryUniformization, BoundaryError> {
    if mesh.n_faces() == 0 {
        return Err(UniformizeError::Empty.into());
    }
    if lengths.len() != mesh.n_edges() {
        return Err(BoundaryError::LengthCount {
            expected: mesh.n_edges(),
            got: lengths.len(),
        });
    }
    validate_boundary_targets(mesh, targets)?;
    let double = Double::of(mesh)?;
    let dl = double
        .pull_back_edges(lengths)
        .ok_or(BoundaryError::LengthCount {
            expected: mesh.n_edges(),
            got: lengths.len(),
        })?;
    let dt = double_targets(&double, targets);
    let start = match &opts.start {
        None => None,
        Some(s) if s.len() == mesh.n_vertices() => {
            Some(double.vertex_origin.iter().map(|v| s[v.idx()]).collect())
        }
        Some(s) => {
            return Err(BoundaryError::TargetCount {
                expected: mesh.n_vertices(),
                got: s.len(),
            })
        }
    };
    let opts = UniformizeOptions {
        start,
        ..opts.clone()
    };
    // T₀ with the Euclidean flips recorded; on any trouble the solver meets it again and
    // reports it with its own typed error.
    let (mut t0, mut l0) = (double.mesh.clone(), dl.clone());
    let record = FlipOptions {
        record: true,
        ..FlipOptions::default()
    };
    let euclidean = match flip_to_delaunay(&mut t0, &mut l0, FlipKind::Euclidean, &record) {
        Ok(rep) if rep.all_certified_delaunay() => rep.sequence,
        _ => {
            t0 = double.mesh.clone();
            l0 = dl;
            Vec::new()
        }
    };
    let solution = uniformize_with_progress(&t0, &l0, &dt, &opts, progress)?;
    let mut seam_flips: Vec<Edge> = euclidean
        .iter()
        .chain(&solution.flip_sequence)
        .copied()
        .filter(|e| double.edge_sheet[e.idx()] == Sheet::Seam)
        .collect();
    seam_flips.sort_unstable();
    seam_flips.dedup();
    let u = solution.u[..mesh.n_vertices()].to_vec();
    let mirror_asymmetry = double
        .vertex_mirror
        .iter()
        .enumerate()
        .map(|(v, w)| (solution.u[v] - solution.u[w.idx()]).abs())
        .fold(0.0, f64::max);
    Ok(BoundaryUniformization {
        double,
        solution,
        u,
        mirror_asymmetry,
        seam_flips,
    })
}

impl BoundaryUniformization {
    /// The faces of the final triangulation of `D` that lie on copy 1 (`M`), when no seam
    /// edge was flipped: flood fill from the side of every seam edge that faced into `M`,
    /// never crossing a seam edge. `None` when a seam edge was flipped (the final
    /// triangulation then crosses the boundary of `M`) or the fill reaches the mirror side
    /// of a seam edge.
    pub fn original_faces(&self) -> Option<Vec<bool>> {
        if !self.seam_flips.is_empty() {
            return None;
        }
        let m = &self.solution.mesh;
        let d = &self.double;
        let seam = |e: Edge| d.edge_sheet[e.idx()] == Sheet::Seam;
        let mut inside = vec![false; m.n_faces()];
        let mut queue = VecDeque::new();
        let n_m_faces = d
            .face_sheet
            .iter()
            .filter(|s| **s == Sheet::Original)
            .count();
        for e in m.edges().filter(|&e| seam(e)) {
            for h in [e.side(0), e.side(1)] {
                // In D, copy 1 keeps the face of the side that had one in M: face id < F.
                let original_side = d.mesh.face(h).is_some_and(|f| f.idx() < n_m_faces);
                if original_side {
                    if let Some(f) = m.face(h) {
                        if !inside[f.idx()] {
                            inside[f.idx()] = true;
                            queue.push_back(f);
                        }
                    }
                }
            }
        }
        while let Some(f) = queue.pop_front() {
            for h in m.face_halfedges(f) {
                if seam(h.edge()) {
                    continue;
                }
                let Some(g) = m.face(h.twin()) else { continue };
                if !inside[g.idx()] {
                    inside[g.idx()] = true;
                    queue.push_back(g);
                }
            }
        }
        // Copy 1 holds exactly half of the faces, and no mirror-side seam half-edge.
        let count = inside.iter().filter(|x| **x).count();
        let crossed = m.edges().filter(|&e| seam(e)).any(|e| {
            let sides = [e.side(0), e.side(1)];
            sides
                .iter()
                .all(|&h| m.face(h).is_some_and(|f| inside[f.idx()]))
        });
        (count == n_m_faces && !crossed).then_some(inside)
    }

    /// Whether the final triangulation of `D` is mirror symmetric: the faces on copy 1,
    /// mapped by `ι`, have the same vertex triples (as multisets) as the faces on copy 2.
    /// `None` when [`Self::original_faces`] is.
    pub fn triangulation_symmetric(&self) -> Option<bool> {
        let inside = self.original_faces()?;
        let m = &self.solution.mesh;
        let iota = &self.double.vertex_mirror;
        let key = |mut t: [u32; 3]| {
            t.sort_unstable();
            t
        };
        let mut a: Vec<[u32; 3]> = m
            .faces()
            .filter(|f| inside[f.idx()])
            .map(|f| key(m.face_vertices(f).map(|v| iota[v.idx()].0)))
            .collect();
        let mut b: Vec<[u32; 3]> = m
            .faces()
            .filter(|f| !inside[f.idx()])
            .map(|f| key(m.face_vertices(f).map(|v| v.0)))
            .collect();
        a.sort_unstable();
        b.sort_unstable();
        Some(a == b)
    }

    /// Per vertex of `M`: the sum of the corner angles of the copy-1 faces of the final
    /// triangulation at the computed `u` (`f64`, numerical): `Θ_v` inside and the boundary
    /// angle sum `φ_v` on the boundary. `None` when [`Self::original_faces`] is.
    pub fn angle_sums_on_original(&self) -> Option<Vec<f64>> {
        let inside = self.original_faces()?;
        let sol = &self.solution;
        let lengths = super::svg::scaled_lengths_f64(&sol.mesh, &sol.base_lengths, &sol.u);
        let angles = halfedge_angles(&sol.mesh, &lengths);
        let mut sums = vec![0.0; self.u.len()];
        for f in sol.mesh.faces().filter(|f| inside[f.idx()]) {
            for h in sol.mesh.face_halfedges(f) {
                let v = sol.mesh.opposite_vertex(h).idx();
                if v < sums.len() {
                    sums[v] += angles[h.idx()];
                }
            }
        }
        Some(sums)
    }

    /// A face of copy 1 in the final triangulation (the root of a layout of `M`).
    pub fn original_root(&self) -> Option<Face> {
        let inside = self.original_faces()?;
        inside.iter().position(|x| *x).map(|f| Face(f as u32))
    }
}
