//! The built-in corpus of the report (`penner` with no arguments): the standard surfaces
//! with metrics from their embeddings, unit lengths, an intrinsic flat metric, and exact
//! conformal scalings.

use super::case::MetricOps;
use crate::io::{Metric, MetricError, Surface};
use crate::mesh::builders::{self, CubeDiagonals};
use crate::mesh::Mesh;
use rug::Rational;

/// Corpus scale factors s_v = 1 + ((3v + 1) mod 5 − 2)/20 ∈ {9/10, …, 11/10}: exact,
/// irregular, with max/min < 1.23, which keeps every triangle of the near-equilateral
/// solids a triangle (the surfaces are validated exactly anyway).
fn corpus_factors(n: usize) -> Vec<Rational> {
    (0..n)
        .map(|v| {
            let k = ((3 * v + 1) % 5) as i64 - 2;
            Rational::from((20 + k, 20))
        })
        .collect()
}

fn scaled(name: &str, base: &Surface) -> Result<Surface, MetricError> {
    let s = corpus_factors(base.mesh.n_vertices());
    Surface::new(
        name,
        base.mesh.clone(),
        base.metric.scaled(&base.mesh, &s),
        None,
    )
}

/// Every edge of length 1 (the regular solid's intrinsic metric, exactly).
fn unit(name: &str, mesh: &Mesh) -> Result<Surface, MetricError> {
    Surface::new(
        name,
        mesh.clone(),
        Metric::Lengths(vec![Rational::from(1); mesh.n_edges()]),
        None,
    )
}

fn lengths(name: &str, mesh: Mesh, l: &[i64]) -> Result<Surface, MetricError> {
    Surface::new(
        name,
        mesh,
        Metric::Lengths(l.iter().map(|&x| Rational::from(x)).collect()),
        None,
    )
}

/// Every corpus surface, each validated exactly ([`Surface::new`]); an invalid one is a
/// defect and is returned as the error.
pub fn try_standard() -> Result<Vec<Surface>, MetricError> {
    let tet = Surface::from_embedded("tetrahedron", builders::tetrahedron())?;
    let oct = Surface::from_embedded("octahedron", builders::octahedron())?;
    let ico = Surface::from_embedded("icosahedron", builders::icosahedron())?;
    let unit_ico = unit("regular icosahedron (unit lengths)", &ico.mesh)?;
    Ok(vec![
        unit("regular tetrahedron (unit lengths)", &tet.mesh)?,
        scaled("tetrahedron, conformally scaled", &tet)?,
        scaled("octahedron, conformally scaled", &oct)?,
        scaled("icosahedron, conformally scaled", &ico)?,
        scaled("regular icosahedron, conformally scaled", &unit_ico)?,
        tet,
        oct,
        ico,
        unit_ico,
        Surface::from_embedded(
            "cube, diagonals one way",
            builders::cube(CubeDiagonals::Even),
        )?,
        Surface::from_embedded("triakis tetrahedron", builders::triakis_tetrahedron())?,
        Surface::from_embedded("triakis octahedron", builders::triakis_octahedron())?,
        lengths(
            "two-triangle sphere (4, 5, 6)",
            builders::two_triangle_sphere(),
            &[4, 5, 6],
        )?,
        lengths(
            "one-vertex torus (4, 5, 6)",
            builders::one_vertex_torus(),
            &[4, 5, 6],
        )?,
    ])
}

/// The corpus, in report order (see [`try_standard`]); small surfaces, so the whole report
/// runs in seconds. Intrinsic and boundary surfaces follow the solids.
pub fn standard() -> Vec<Surface> {
    let mut out = try_standard().unwrap_or_default();
    if let Ok(t) = builders::flat_torus(4, 3) {
        out.extend(Surface::from_intrinsic("flat torus 4×3", t));
    }
    if let Ok(d) = builders::grid_disk(3, 3) {
        out.extend(Surface::from_embedded("grid disk 3×3", d));
    }
    out
}
