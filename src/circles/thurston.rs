//! Thurston's conditions for circle patterns with intersection angles `Φ ∈ [0, π/2]`
//! (notes Thm 7; Marden–Rodin 1990; docs/catalogue.md §8): on a closed surface,
//! 1. a null-homotopic cycle of three edges with `ΣΦ ≥ π` bounds a face, and
//! 2. a null-homotopic cycle of four edges with `ΣΦ = 2π` bounds two adjacent faces.
//!
//! The checker enumerates every simple 3- and 4-cycle (distinct vertices; every choice of
//! edge between two vertices of a Δ-complex). A simple closed curve of the surface is
//! null-homologous mod 2 exactly when it separates (the faces fall into two parts across
//! it), and on the sphere and the torus a simple closed curve is null-homotopic exactly
//! when it separates (on the torus a non-separating simple curve has a primitive, hence
//! non-zero mod 2, class). On higher genus a separating cycle may be essential: such a
//! cycle is reported as undecided, never as a violation.

use crate::mesh::Mesh;
use rug::Rational;

/// A simple cycle of edges through distinct vertices.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Cycle {
    /// The vertices in order.
    pub vertices: Vec<usize>,
    /// The edges in order (`edges[k]` joins `vertices[k]` and `vertices[k + 1]`).
    pub edges: Vec<usize>,
    /// `ΣΦ / π` over the edges.
    pub angle_sum: Rational,
}

/// The outcome of the check.
#[derive(Clone, Debug, Default)]
pub struct ThurstonReport {
    /// Cycles that violate a condition (null-homotopic, angle sum at the threshold, not
    /// bounding a face or two adjacent faces).
    pub violations: Vec<Cycle>,
    /// Cycles at the threshold that separate a surface of genus ≥ 2 (null-homotopy not
    /// decided).
    pub undecided: Vec<Cycle>,
    /// 3-cycles examined.
    pub three_cycles: usize,
    /// 4-cycles examined.
    pub four_cycles: usize,
}

impl ThurstonReport {
    /// Whether both conditions are proved to hold.
    pub fn holds(&self) -> bool {
        self.violations.is_empty() && self.undecided.is_empty()
    }
}

/// Why the check does not apply.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum ThurstonError {
    /// Thurston's conditions are stated for closed surfaces.
    #[error("the surface has boundary: Thurston's conditions are stated for closed surfaces")]
    Boundary,
    /// One angle per edge is needed.
    #[error("expected {expected} intersection angles, got {got}")]
    Count {
        /// Edges.
        expected: usize,
        /// Given.
        got: usize,
    },
}

fn neighbours(mesh: &Mesh) -> Vec<Vec<(usize, usize)>> {
    let mut adj = vec![Vec::new(); mesh.n_vertices()];
    for e in mesh.edges() {
        let h = e.halfedge();
        let (a, b) = (mesh.tail(h).idx(), mesh.tip(h).idx());
        if a != b {
            adj[a].push((b, e.idx()));
            adj[b].push((a, e.idx()));
        }
    }
    adj
}

fn sorted(mut v: Vec<usize>) -> Vec<usize> {
    v.sort_unstable();
    v
}

fn find(p: &mut [usize], mut x: usize) -> usize {
    while p[x] != x {
        p[x] = p[p[x]];
        x = p[x];
    }
    x
}

/// Whether the faces fall into more than one part when glued only across edges not in
/// `cut`.
fn separates(mesh: &Mesh, cut: &[usize]) -> bool {
    let nf = mesh.n_faces();
    let mut parent: Vec<usize> = (0..nf).collect();
    for e in mesh.edges() {
        if cut.contains(&e.idx()) {
            continue;
        }
        let (f0, f1) = (mesh.face(e.side(0)), mesh.face(e.side(1)));
        if let (Some(a), Some(b)) = (f0, f1) {
            let (ra, rb) = (find(&mut parent, a.idx()), find(&mut parent, b.idx()));
            parent[ra] = rb;
        }
    }
    let root = find(&mut parent, 0);
    (1..nf).any(|f| find(&mut parent, f) != root)
}

fn face_edge_sets(mesh: &Mesh) -> Vec<Vec<usize>> {
    mesh.faces()
        .map(|f| {
            sorted(
                mesh.face_halfedges(f)
                    .iter()
                    .map(|h| h.edge().idx())
                    .collect(),
            )
        })
        .collect()
}

/// The four outer edges of the two faces of every interior edge with distinct faces.
fn face_pair_edge_sets(mesh: &Mesh) -> Vec<Vec<usize>> {
    let mut out = Vec::new();
    for e in mesh.edges() {
        let (Some(f0), Some(f1)) = (mesh.face(e.side(0)), mesh.face(e.side(1))) else {
            continue;
        };
        if f0 == f1 {
            continue;
        }
        let mut s: Vec<usize> = [f0, f1]
            .iter()
            .flat_map(|&f| mesh.face_halfedges(f))
            .map(|h| h.edge().idx())
            .filter(|&x| x != e.idx())
            .collect();
        s.sort_unstable();
        out.push(s);
    }
    out
}

/// Check Thurston's two conditions for `phi[e] = Φ_e/π` on a closed surface.
pub fn check_thurston(mesh: &Mesh, phi: &[Rational]) -> Result<ThurstonReport, ThurstonError> {
    if !mesh.is_closed() {
        return Err(ThurstonError::Boundary);
    }
    if phi.len() != mesh.n_edges() {
        return Err(ThurstonError::Count {
            expected: mesh.n_edges(),
            got: phi.len(),
        });
    }
    let genus = (2 - mesh.euler_characteristic()) / 2;
    let adj = neighbours(mesh);
    let faces = face_edge_sets(mesh);
    let pairs = face_pair_edge_sets(mesh);
    let mut report = ThurstonReport::default();
    let judge = |report: &mut ThurstonReport,
                 vertices: Vec<usize>,
                 edges: Vec<usize>,
                 bounds: bool,
                 threshold: i32| {
        let angle_sum: Rational = edges.iter().map(|&e| phi[e].clone()).sum();
        if angle_sum < threshold || bounds {
            return;
        }
        let cycle = Cycle {
            vertices,
            edges: edges.clone(),
            angle_sum,
        };
        if !separates(mesh, &edges) {
            return;
        }
        if genus <= 1 {
            report.violations.push(cycle);
        } else {
            report.undecided.push(cycle);
        }
    };
    let n = mesh.n_vertices();
    for a in 0..n {
        for &(b, eab) in &adj[a] {
            if b <= a {
                continue;
            }
            for &(c, ebc) in &adj[b] {
                if c <= b {
                    continue;
                }
                for &(a2, eca) in &adj[c] {
                    if a2 != a {
                        continue;
                    }
                    report.three_cycles += 1;
                    let edges = vec![eab, ebc, eca];
                    let bounds = faces.contains(&sorted(edges.clone()));
                    judge(&mut report, vec![a, b, c], edges, bounds, 1);
                }
            }
            // 4-cycles a-b-c-d-a with a the smallest vertex and b < d.
            for &(c, ebc) in &adj[b] {
                if c <= a || c == b {
                    continue;
                }
                for &(d, ecd) in &adj[c] {
                    if d <= b || d == c {
                        continue;
                    }
                    for &(a2, eda) in &adj[d] {
                        if a2 != a {
                            continue;
                        }
                        report.four_cycles += 1;
                        let edges = vec![eab, ebc, ecd, eda];
                        let bounds = pairs.contains(&sorted(edges.clone()));
                        judge(&mut report, vec![a, b, c, d], edges, bounds, 2);
                    }
                }
            }
        }
    }
    Ok(report)
}
