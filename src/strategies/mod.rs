//! Random surfaces, metrics and conformal factors for property tests (feature
//! `strategies`): proptest [`Strategy`]s and quickcheck [`Arbitrary`] impls that a
//! downstream crate can use to property-test its own code.
//!
//! Every strategy is built from a few integer parameters (genus, vertex count, grid size,
//! a seed) through deterministic builders, so proptest shrinks toward small surfaces:
//! a failing property on a big random surface shrinks to one with a handful of faces.
//! Every surface produced satisfies [`Mesh::check_invariants`] and
//! [`Surface::validate`] (checked in `tests/it/strategies.rs`).
//!
//! ```
//! use proptest::prelude::*;
//! use penner::strategies;
//! proptest!(|(s in strategies::closed_surface(0..=2, 3..=12))| {
//!     let g = (2 - s.mesh.euler_characteristic()) / 2;
//!     prop_assert!((0..=2).contains(&g));
//! });
//! ```

use crate::io::surface::{squared_lengths_from_positions, validate_metric};
use crate::io::{Metric, Surface};
use crate::mesh::builders::{self, CubeDiagonals, Embedded};
use crate::mesh::{Face, Mesh};
use proptest::prelude::*;
use quickcheck::{Arbitrary, Gen};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rug::{Integer, Rational};
use std::ops::RangeInclusive;

/// A closed oriented surface (usually a Δ-complex) of genus in `genus` (0..=3 is
/// supported) with a vertex count in `vertices` (at least 3 for genus 0, at least 1
/// otherwise; smaller requests are raised to the minimum): [`builders::random_surface`].
pub fn closed_mesh(
    genus: RangeInclusive<u32>,
    vertices: RangeInclusive<u32>,
) -> impl Strategy<Value = Mesh> {
    (genus, vertices, any::<u64>()).prop_map(|(g, v, seed)| closed_mesh_of(g, v, seed))
}

fn closed_mesh_of(g: u32, v: u32, seed: u64) -> Mesh {
    let v = if g == 0 { v.max(3) } else { v.max(1) };
    builders::random_surface(g.min(3), v.min(4000), seed)
        .unwrap_or_else(|_| builders::two_triangle_sphere())
}

/// A closed surface with one boundary loop cut in it: [`closed_mesh`], two face splits,
/// and the removal of a face with three distinct vertices (always a valid surface).
pub fn punctured_mesh(
    genus: RangeInclusive<u32>,
    vertices: RangeInclusive<u32>,
) -> impl Strategy<Value = Mesh> {
    (genus, vertices, any::<u64>()).prop_map(|(g, v, seed)| punctured_of(g, v, seed))
}

fn punctured_of(g: u32, v: u32, seed: u64) -> Mesh {
    let mut m = closed_mesh_of(g, v, seed);
    // Split f0 = abc (new v), then f1 = bcv (new w): face n-2 = cvw has distinct corners.
    let _ = m.split_face(Face(0));
    let _ = m.split_face(Face(m.n_faces() as u32 - 2));
    let f = Face(m.n_faces() as u32 - 2);
    builders::remove_face(&m, f).unwrap_or(m)
}

/// A surface with boundary: a grid disk, an annulus, a Delaunay-triangulated planar
/// point set, or a punctured closed surface of genus 0..=2; sizes up to about `max_size`
/// along each parameter.
pub fn mesh_with_boundary(max_size: u32) -> impl Strategy<Value = Mesh> {
    let m = max_size.max(1);
    prop_oneof![
        (1..=m, 1..=m).prop_map(|(a, b)| builders::grid_disk(a, b).map(|e| e.mesh)),
        (3..=m + 2, 1..=m).prop_map(|(a, b)| builders::annulus(a, b).map(|e| e.mesh)),
        (3..=m + 3, any::<u64>()).prop_map(|(n, s)| builders::random_planar(n, s).map(|e| e.mesh)),
        (0..=2u32, 1..=m + 3, any::<u64>()).prop_map(|(g, v, s)| Ok(punctured_of(g, v, s))),
    ]
    .prop_map(|r| r.unwrap_or_else(|_| builders::tetrahedron().mesh))
}

/// Random exact lengths `1 + k/1024`, `k ∈ 0..1024`, on every edge of `mesh`: any three
/// values in [1, 2) satisfy the strict triangle inequality, so the metric is valid on
/// every Δ-complex (self-folded faces included).
pub fn metric_on(mesh: Mesh) -> impl Strategy<Value = Surface> {
    let n = mesh.n_edges();
    proptest::collection::vec(0u32..1024, n).prop_map(move |ks| {
        let l = ks
            .iter()
            .map(|&k| Rational::from((1024 + k, 1024)))
            .collect();
        Surface {
            mesh: mesh.clone(),
            metric: Metric::Lengths(l),
            positions: None,
            name: "random metric".into(),
        }
    })
}

/// `mesh` with exact lengths `1 + k/1024` drawn from `seed` (valid on every Δ-complex, as
/// in [`metric_on`]). Deterministic, so shrinking acts on the seed only.
pub fn with_random_metric(mesh: Mesh, seed: u64, name: String) -> Surface {
    let mut rng = ChaCha8Rng::seed_from_u64(seed ^ 0x9e37_79b9_7f4a_7c15);
    let l = (0..mesh.n_edges())
        .map(|_| Rational::from((1024 + rng.gen_range(0u32..1024), 1024)))
        .collect();
    Surface {
        mesh,
        metric: Metric::Lengths(l),
        positions: None,
        name,
    }
}

/// A closed surface ([`closed_mesh`]) with a random valid metric
/// ([`with_random_metric`]). Shrinks toward low genus and few vertices.
pub fn closed_surface(
    genus: RangeInclusive<u32>,
    vertices: RangeInclusive<u32>,
) -> impl Strategy<Value = Surface> {
    (genus, vertices, any::<u64>()).prop_map(|(g, v, seed)| ArbSurface::new(g, v, seed).surface)
}

/// A surface with boundary ([`mesh_with_boundary`]) with a random valid metric.
pub fn surface_with_boundary(max_size: u32) -> impl Strategy<Value = Surface> {
    (mesh_with_boundary(max_size), any::<u64>())
        .prop_map(|(m, seed)| with_random_metric(m, seed, "surface with boundary".into()))
}

fn from_embedding(name: &str, e: Embedded) -> Surface {
    let metric = Metric::SquaredLengths(squared_lengths_from_positions(&e.mesh, &e.positions));
    Surface {
        mesh: e.mesh,
        metric,
        positions: Some(e.positions),
        name: name.into(),
    }
}

/// A surface whose metric comes from an embedding (exact squared lengths of rational
/// positions): a platonic or triakis solid, a split cube, a grid disk, or Delaunay
/// triangulated random planar points (up to `max_points`).
pub fn embedded_surface(max_points: u32) -> impl Strategy<Value = Surface> {
    let solids = (0usize..8).prop_map(|i| {
        let (name, e) = match i {
            0 => ("tetrahedron", builders::tetrahedron()),
            1 => ("octahedron", builders::octahedron()),
            2 => ("icosahedron", builders::icosahedron()),
            3 => ("cube-even", builders::cube(CubeDiagonals::Even)),
            4 => ("cube-odd", builders::cube(CubeDiagonals::Odd)),
            5 => ("triakis-tetrahedron", builders::triakis_tetrahedron()),
            _ => ("triakis-octahedron", builders::triakis_octahedron()),
        };
        from_embedding(name, e)
    });
    let m = max_points.max(3);
    let planar = (3..=m, any::<u64>()).prop_map(|(n, s)| {
        builders::random_planar(n, s).map_or_else(
            |_| from_embedding("tetrahedron", builders::tetrahedron()),
            |e| from_embedding("planar points", e),
        )
    });
    let grid = (1..=4u32, 1..=4u32).prop_map(|(a, b)| {
        builders::grid_disk(a, b).map_or_else(
            |_| from_embedding("tetrahedron", builders::tetrahedron()),
            |e| from_embedding("grid", e),
        )
    });
    prop_oneof![solids, planar, grid]
}

/// `n` rational conformal factors `s_i = e^{u_i/2} = k/32`, `k ∈ 16..=64` (so s_i ∈
/// [1/2, 2]).
pub fn conformal_factors(n: usize) -> impl Strategy<Value = Vec<Rational>> {
    proptest::collection::vec(16u32..=64, n)
        .prop_map(|ks| ks.into_iter().map(|k| Rational::from((k, 32))).collect())
}

/// `n` logarithmic conformal factors `u_i ∈ [−1, 1]` (binary64).
pub fn log_factors(n: usize) -> impl Strategy<Value = Vec<f64>> {
    proptest::collection::vec(-1.0f64..=1.0, n)
}

/// Conformal scaling ℓ̃_ij = s_i s_j ℓ_ij (docs/catalogue.md §4, Eq. 10; squared lengths scale by
/// s_i² s_j²), exact. The result may violate the triangle inequality; see
/// [`conformally_scaled`].
pub fn scale_metric(s: &Surface, factors: &[Rational]) -> Metric {
    let scale = |e: crate::mesh::Edge| {
        let h = e.halfedge();
        Rational::from(&factors[s.mesh.tail(h).idx()] * &factors[s.mesh.tip(h).idx()])
    };
    match &s.metric {
        Metric::Lengths(v) => Metric::Lengths(
            s.mesh
                .edges()
                .map(|e| Rational::from(&v[e.idx()] * &scale(e)))
                .collect(),
        ),
        Metric::SquaredLengths(v) => Metric::SquaredLengths(
            s.mesh
                .edges()
                .map(|e| {
                    let f = scale(e);
                    Rational::from(&v[e.idx()] * &Rational::from(&f * &f))
                })
                .collect(),
        ),
    }
}

/// The surface under random rational conformal factors ([`conformal_factors`]), with
/// the factors; scalings that break the triangle inequality are rejected (filtered).
pub fn conformally_scaled(s: Surface) -> impl Strategy<Value = (Surface, Vec<Rational>)> {
    let n = s.mesh.n_vertices();
    conformal_factors(n).prop_filter_map("scaling breaks a triangle", move |f| {
        let metric = scale_metric(&s, &f);
        validate_metric(&s.mesh, &metric).ok()?;
        let mut t = s.clone();
        t.metric = metric;
        t.positions = None;
        t.name = format!("{} (conformally scaled)", s.name);
        Some((t, f))
    })
}

/// A valid surface with a triangle within `10⁻ᵏ` (k = 3..=60) of violating the triangle
/// inequality: the two-triangle sphere with lengths (a, b, a + b − ε),
/// `ε = 10⁻ᵏ·min(a, b)/16` (near also relative to its size), the one-vertex
/// torus with the same lengths (both faces near-degenerate), or a planar quadrilateral
/// with a vertex at height 2⁻⁽ᵏ⁺¹⁰⁾ above a diagonal.
pub fn near_degenerate_surface() -> impl Strategy<Value = Surface> {
    (0usize..3, 1u32..=1000, 1u32..=1000, 3u32..=60).prop_map(|(kind, a, b, k)| {
        let (a, b) = (Rational::from((a, 100)), Rational::from((b, 100)));
        // ε = 10⁻ᵏ·min(a, b)/16: near-degenerate relative to the triangle's size too, so
        // 16·Area² ≈ 8ab(a + b)ε < 10⁻ᵏ·(a + b)⁴/16 (ab·min(a, b) ≤ (a + b)³/8).
        let eps = Rational::from((1, Integer::from(Integer::u_pow_u(10, k)) * 16u32))
            * a.clone().min(b.clone());
        let c = Rational::from(&a + &b) - eps;
        // a + b − c = ε > 0, and a + c − b = 2a − ε > 0 since ε < a.
        let lengths = vec![a, b, c];
        match kind {
            0 => Surface {
                mesh: builders::two_triangle_sphere(),
                metric: Metric::Lengths(lengths),
                positions: None,
                name: "near-degenerate sphere".into(),
            },
            1 => Surface {
                mesh: builders::one_vertex_torus(),
                metric: Metric::Lengths(lengths),
                positions: None,
                name: "near-degenerate torus".into(),
            },
            _ => {
                let h = Rational::from((1, Integer::from(Integer::u_pow_u(2, k + 10))));
                let p = |x: i32, y: Rational| [Rational::from(x), y, Rational::new()];
                let positions = vec![
                    p(0, Rational::new()),
                    p(2, Rational::new()),
                    p(1, h),
                    p(1, Rational::from(-1)),
                ];
                let mesh = Mesh::from_faces(4, &[[0, 1, 2], [0, 3, 1]])
                    .unwrap_or_else(|_| builders::two_triangle_sphere());
                from_embedding(
                    "near-degenerate quad",
                    Embedded {
                        mesh,
                        positions,
                        exact: true,
                    },
                )
            }
        }
    })
}

/// A closed surface for quickcheck: genus 0..=3 and up to `g.size()` vertices, with a
/// random valid metric; shrinks toward lower genus and fewer vertices.
#[derive(Clone, Debug)]
pub struct ArbSurface {
    /// The surface.
    pub surface: Surface,
    /// Its genus.
    pub genus: u32,
    /// Its vertex count.
    pub vertices: u32,
    /// The seed of its triangulation and metric.
    pub seed: u64,
}

impl ArbSurface {
    /// The surface of genus `genus` with `vertices` vertices from `seed` (raised to the
    /// minimum vertex count of the genus).
    pub fn new(genus: u32, vertices: u32, seed: u64) -> ArbSurface {
        let mesh = closed_mesh_of(genus, vertices, seed);
        let n = mesh.n_vertices() as u32;
        let name = format!("genus {genus}, {n} vertices, seed {seed}");
        ArbSurface {
            genus: genus.min(3),
            vertices: n,
            seed,
            surface: with_random_metric(mesh, seed, name),
        }
    }
}

impl Arbitrary for ArbSurface {
    fn arbitrary(g: &mut Gen) -> ArbSurface {
        let genus = u32::arbitrary(g) % 4;
        let max = (g.size() as u32).clamp(3, 200);
        let vertices = 1 + u32::arbitrary(g) % max;
        ArbSurface::new(genus, vertices, u64::arbitrary(g))
    }

    fn shrink(&self) -> Box<dyn Iterator<Item = ArbSurface>> {
        let (g, v, s) = (self.genus, self.vertices, self.seed);
        let min_v = if g == 0 { 3 } else { 1 };
        let mut out = Vec::new();
        if g > 0 {
            out.push(ArbSurface::new(g - 1, v, s));
        }
        if v > min_v {
            out.push(ArbSurface::new(g, min_v.max(v / 2), s));
            out.push(ArbSurface::new(g, v - 1, s));
        }
        if s != 0 {
            out.push(ArbSurface::new(g, v, 0));
        }
        Box::new(out.into_iter())
    }
}
