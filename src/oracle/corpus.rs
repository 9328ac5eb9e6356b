//! The built-in corpus of the report (`penner` with no arguments): the standard surfaces
//! with metrics from their embeddings, intrinsic flat metrics, and exact conformal
//! scalings of some of them.

use super::case::{Case, Lengths};
use crate::mesh::builders::{self, CubeDiagonals, Embedded};
use crate::mesh::Mesh;
use rug::Rational;

/// Squared edge lengths `|p_tip − p_tail|²` of an embedded surface, exact.
fn embedded_squared_lengths(e: &Embedded) -> Vec<Rational> {
    e.mesh
        .edges()
        .map(|edge| {
            let h = edge.halfedge();
            let (a, b) = (
                &e.positions[e.mesh.tail(h).idx()],
                &e.positions[e.mesh.tip(h).idx()],
            );
            let mut s = Rational::new();
            for k in 0..3 {
                let d = Rational::from(&b[k] - &a[k]);
                s += Rational::from(&d * &d);
            }
            s
        })
        .collect()
}

fn embedded(name: &str, e: &Embedded) -> Case {
    Case {
        name: name.to_string(),
        mesh: e.mesh.clone(),
        lengths: Lengths::Squared(embedded_squared_lengths(e)),
    }
}

/// Corpus scale factors s_v = 1 + ((3v + 1) mod 5 − 2)/20 ∈ {9/10, …, 11/10}: exact, irregular,
/// with max/min < 1.23, which keeps every triangle of the near-equilateral solids a
/// triangle.
fn corpus_factors(n: usize) -> Vec<Rational> {
    (0..n)
        .map(|v| {
            let k = ((3 * v + 1) % 5) as i64 - 2;
            Rational::from((20 + k, 20))
        })
        .collect()
}

fn scaled(name: &str, base: &Case) -> Case {
    let s = corpus_factors(base.mesh.n_vertices());
    Case {
        name: name.to_string(),
        mesh: base.mesh.clone(),
        lengths: base.lengths.scaled(&base.mesh, &s),
    }
}

/// A case with every edge of length 1 (the regular solid's intrinsic metric, exactly).
fn unit(name: &str, mesh: &Mesh) -> Case {
    Case {
        name: name.to_string(),
        mesh: mesh.clone(),
        lengths: Lengths::Exact(vec![Rational::from(1); mesh.n_edges()]),
    }
}

/// The corpus, in report order. Every surface is small, so the whole report runs in
/// seconds.
pub fn standard() -> Vec<Case> {
    let mut out = Vec::new();
    let tet = embedded("tetrahedron", &builders::tetrahedron());
    let oct = embedded("octahedron", &builders::octahedron());
    let ico = embedded("icosahedron", &builders::icosahedron());
    let unit_tet = unit("regular tetrahedron (unit lengths)", &tet.mesh);
    let unit_ico = unit("regular icosahedron (unit lengths)", &ico.mesh);
    out.push(scaled("tetrahedron, conformally scaled", &tet));
    out.push(scaled("octahedron, conformally scaled", &oct));
    out.push(scaled("icosahedron, conformally scaled", &ico));
    out.push(scaled("regular icosahedron, conformally scaled", &unit_ico));
    out.splice(0..0, [tet, oct, ico, unit_tet, unit_ico]);
    out.push(embedded(
        "cube, diagonals one way",
        &builders::cube(CubeDiagonals::Even),
    ));
    out.push(embedded(
        "triakis tetrahedron",
        &builders::triakis_tetrahedron(),
    ));
    out.push(embedded(
        "triakis octahedron",
        &builders::triakis_octahedron(),
    ));
    // Two-triangle sphere with sides 3, 4, 5 and one-vertex torus with sides 4, 5, 6.
    let sphere2 = builders::two_triangle_sphere();
    out.push(Case {
        name: "two-triangle sphere (3, 4, 5)".to_string(),
        lengths: Lengths::Exact([3, 4, 5].map(Rational::from).to_vec()),
        mesh: sphere2,
    });
    let torus1 = builders::one_vertex_torus();
    out.push(Case {
        name: "one-vertex torus (4, 5, 6)".to_string(),
        lengths: Lengths::Exact([4, 5, 6].map(Rational::from).to_vec()),
        mesh: torus1,
    });
    if let Ok(t) = builders::flat_torus(4, 3) {
        out.push(Case {
            name: "flat torus 4×3".to_string(),
            mesh: t.mesh,
            lengths: Lengths::Squared(t.squared_lengths),
        });
    }
    if let Ok(d) = builders::grid_disk(3, 3) {
        out.push(embedded("grid disk 3×3", &d));
    }
    out
}
