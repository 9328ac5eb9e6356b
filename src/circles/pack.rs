//! The tangency packing `penner pack` computes for a surface (`Φ = 0` on every edge):
//!
//! - a surface with boundary: every interior vertex gets cone angle `2π`, boundary circles
//!   keep radius 1 (Dirichlet data) — a flat packing of a disk-like layout;
//! - a sphere: the star of vertex 0 is removed (a puncture) and the remaining disk packed as
//!   above;
//! - another closed surface: curvature in proportion to the degree (`2π` everywhere on a
//!   torus), one radius fixed.
//!
//! The solution is computed by Newton's method in `f64` and certified by B94.

use super::certify::{certify_solution, Certificate};
use super::metric::lengths_from_radii;
use super::pattern::{CirclePattern, PatternError};
use super::solve::{default_tolerance, newton, SolveError};
use crate::mesh::{Mesh, MeshError};
use rug::Rational;

/// Why no packing was computed.
#[derive(Debug, thiserror::Error)]
pub enum PackError {
    /// A face meets one vertex twice (a Δ-complex): no tangency packing.
    #[error("face f{0} meets one vertex twice: a tangency packing needs three distinct circles per face")]
    RepeatedVertex(usize),
    /// The surface is too large for the dense solver.
    #[error("{0} vertices: the dense solver is limited to {MAX_PACK_VERTICES}")]
    TooLarge(usize),
    /// Removing the star of vertex 0 of a sphere did not leave a surface.
    #[error("puncturing the sphere at v0: {0}")]
    Puncture(MeshError),
    /// The problem was refused.
    #[error(transparent)]
    Pattern(#[from] PatternError),
    /// Newton's method failed.
    #[error("Newton: {0}")]
    Solve(#[from] SolveError),
}

/// Largest vertex count `penner pack` solves (dense linear algebra).
pub const MAX_PACK_VERTICES: usize = 2000;

/// A computed packing.
#[derive(Clone, Debug)]
pub struct Packing {
    /// What was done to the surface (`disk`, `punctured sphere`, `closed`).
    pub kind: &'static str,
    /// The problem solved (its mesh is the punctured one for spheres).
    pub pattern: CirclePattern,
    /// `log r` per vertex.
    pub u: Vec<f64>,
    /// Newton iterations.
    pub iterations: usize,
    /// `max |Θ − θ|` at the end.
    pub residual: f64,
    /// The B94 certificate, or why there is none.
    pub certificate: Result<Certificate, String>,
}

impl Packing {
    /// The radii `e^u`.
    pub fn radii(&self) -> Vec<f64> {
        self.u.iter().map(|x| x.exp()).collect()
    }
    /// The tangency lengths `r_i + r_j` of every edge.
    pub fn lengths(&self) -> Vec<f64> {
        let cos = vec![1.0; self.pattern.mesh.n_edges()];
        lengths_from_radii(&self.pattern.mesh, &self.radii(), &cos)
    }
}

/// The mesh without the star of vertex `v` (vertices renumbered, `v` dropped).
pub fn puncture(mesh: &Mesh, v: usize) -> Result<Mesh, MeshError> {
    let keep: Vec<[u32; 3]> = mesh
        .face_list()
        .into_iter()
        .filter(|t| !t.contains(&(v as u32)))
        .map(|t| t.map(|w| if w as usize > v { w - 1 } else { w }))
        .collect();
    Mesh::from_faces(mesh.n_vertices() as u32 - 1, &keep)
}

/// Compute and certify the tangency packing of `mesh` (see the module docs).
pub fn pack(mesh: &Mesh) -> Result<Packing, PackError> {
    if let Some(f) = mesh.faces().find(|&f| {
        let [a, b, c] = mesh.face_vertices(f);
        a == b || b == c || c == a
    }) {
        return Err(PackError::RepeatedVertex(f.idx()));
    }
    if mesh.n_vertices() > MAX_PACK_VERTICES {
        return Err(PackError::TooLarge(mesh.n_vertices()));
    }
    let (kind, work) = if mesh.is_closed() && mesh.euler_characteristic() == 2 {
        (
            "punctured sphere",
            puncture(mesh, 0).map_err(PackError::Puncture)?,
        )
    } else if mesh.is_closed() {
        ("closed", mesh.clone())
    } else {
        ("disk", mesh.clone())
    };
    let n = work.n_vertices();
    let targets: Vec<Option<Rational>> = if work.is_closed() {
        let e = work.n_edges() as i64;
        let chi = work.euler_characteristic();
        work.vertices()
            .map(|v| Some(Rational::from(2) - Rational::from((chi * work.degree(v) as i64, e))))
            .collect()
    } else {
        let boundary = work.boundary_vertices();
        boundary
            .iter()
            .map(|&b| (!b).then(|| Rational::from(2)))
            .collect()
    };
    let pattern = CirclePattern::new(work.clone(), vec![Rational::new(); work.n_edges()], targets)?;
    let sol = newton(
        &pattern,
        &vec![0.0; n],
        default_tolerance::<f64>(n, ()),
        200,
    )?;
    let certificate = certify_solution(&pattern, &sol.u, 128, 0.0);
    Ok(Packing {
        kind,
        pattern,
        u: sol.u,
        iterations: sol.iterations,
        residual: sol.residual,
        certificate,
    })
}
