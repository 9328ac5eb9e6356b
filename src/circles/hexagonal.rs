//! Hexagonal circle packings of a planar domain (notes §1.4.1, Rodin–Sullivan; proofs/T12):
//! the triangular lattice `z₀ + ε(i + j·ω)`, `ω = e^{iπ/3}`, restricted to a domain `Ω`.
//! Every lattice point is the centre of a disk of radius `ε/2`, tangent to its six
//! neighbours; the complex keeps the lattice triangles with all three corners in `Ω`, the
//! edge-connected component of the triangles at `z₀`, and at a vertex where the kept
//! triangles form several fans (a pinch) only the largest fan, so that the carrier is a
//! triangulated disk.

use crate::mesh::{Mesh, MeshError};
use std::collections::{HashMap, HashSet, VecDeque};

/// Why no hexagonal complex was built.
#[derive(Debug, thiserror::Error)]
pub enum HexError {
    /// `ε` not positive and finite, or the extent too large for the lattice indices.
    #[error("spacing {0} is not a positive number giving fewer than 2³¹ lattice points per row")]
    Spacing(f64),
    /// No lattice triangle at `z₀` lies in the domain.
    #[error("no lattice triangle at the base point lies in the domain")]
    Empty,
    /// The kept triangles did not form a mesh.
    #[error(transparent)]
    Mesh(#[from] MeshError),
}

/// A hexagonal complex: the mesh, the lattice point of every vertex, and the lattice indices.
#[derive(Clone, Debug)]
pub struct HexComplex {
    /// The triangulated disk.
    pub mesh: Mesh,
    /// Position of every vertex.
    pub points: Vec<[f64; 2]>,
    /// Lattice indices `(i, j)` of every vertex.
    pub lattice: Vec<(i64, i64)>,
    /// The base point `z₀` (lattice `(0, 0)`) and spacing `ε`.
    pub base: [f64; 2],
    /// Spacing.
    pub spacing: f64,
    /// The vertex at `z₀`.
    pub centre: usize,
    /// The vertex at `z₀ + ε` (lattice `(1, 0)`), when kept.
    pub direction: Option<usize>,
}

/// `z₀ + ε(i + j/2, j√3/2)`.
pub fn lattice_point(base: [f64; 2], eps: f64, (i, j): (i64, i64)) -> [f64; 2] {
    let (i, j) = (i as f64, j as f64);
    [
        base[0] + eps * (i + 0.5 * j),
        base[1] + eps * j * 3.0_f64.sqrt() / 2.0,
    ]
}

/// Lattice coordinates `(s, t)` of `z` (`z = z₀ + ε(s + t/2, t√3/2)`).
pub fn lattice_coordinates(base: [f64; 2], eps: f64, z: [f64; 2]) -> (f64, f64) {
    let t = (z[1] - base[1]) / (eps * 3.0_f64.sqrt() / 2.0);
    let s = (z[0] - base[0]) / eps - 0.5 * t;
    (s, t)
}

/// The lattice triangle containing `z` and the barycentric weights of `z` in it: the "up"
/// triangle `(i, j), (i+1, j), (i, j+1)` when the fractional parts satisfy `a + b ≤ 1`,
/// else the "down" triangle `(i+1, j), (i+1, j+1), (i, j+1)` (both counterclockwise).
pub fn locate(base: [f64; 2], eps: f64, z: [f64; 2]) -> ([(i64, i64); 3], [f64; 3]) {
    let (s, t) = lattice_coordinates(base, eps, z);
    let (i, j) = (s.floor(), t.floor());
    let (a, b) = (s - i, t - j);
    let (i, j) = (i as i64, j as i64);
    if a + b <= 1.0 {
        ([(i, j), (i + 1, j), (i, j + 1)], [1.0 - a - b, a, b])
    } else {
        (
            [(i + 1, j), (i + 1, j + 1), (i, j + 1)],
            [1.0 - b, a + b - 1.0, 1.0 - a],
        )
    }
}

/// The hexagonal complex of spacing `eps` based at `base` of the domain `inside` contained
/// in the disk of radius `extent` around `base` (module docs).
pub fn hex_complex(
    inside: &dyn Fn([f64; 2]) -> bool,
    base: [f64; 2],
    eps: f64,
    extent: f64,
) -> Result<HexComplex, HexError> {
    let reach = (2.0 * extent / eps).ceil() + 2.0;
    if !(eps > 0.0 && reach.is_finite() && reach < 2e9) {
        return Err(HexError::Spacing(eps));
    }
    let reach = reach as i64;
    let mut tris: Vec<[(i64, i64); 3]> = Vec::new();
    let ok = |p: (i64, i64)| inside(lattice_point(base, eps, p));
    for j in -reach..=reach {
        for i in -reach..=reach {
            let up = [(i, j), (i + 1, j), (i, j + 1)];
            let down = [(i + 1, j), (i + 1, j + 1), (i, j + 1)];
            for t in [up, down] {
                if t.iter().all(|&p| ok(p)) {
                    tris.push(t);
                }
            }
        }
    }
    let tris = prune_to_disk(tris);
    if tris.is_empty() {
        return Err(HexError::Empty);
    }
    let mut index: HashMap<(i64, i64), u32> = HashMap::new();
    let mut lattice = Vec::new();
    let faces: Vec<[u32; 3]> = tris
        .iter()
        .map(|t| {
            t.map(|p| {
                *index.entry(p).or_insert_with(|| {
                    lattice.push(p);
                    (lattice.len() - 1) as u32
                })
            })
        })
        .collect();
    let mesh = Mesh::from_faces(lattice.len() as u32, &faces)?;
    let points = lattice
        .iter()
        .map(|&p| lattice_point(base, eps, p))
        .collect();
    Ok(HexComplex {
        mesh,
        points,
        centre: index.get(&(0, 0)).map_or(0, |&v| v as usize),
        direction: index.get(&(1, 0)).map(|&v| v as usize),
        lattice,
        base,
        spacing: eps,
    })
}

type Tri = [(i64, i64); 3];
type LatticeEdge = ((i64, i64), (i64, i64));

/// The edge-connected component of the triangles at `(0, 0)`, pinches removed (module
/// docs), repeated until stable.
fn prune_to_disk(mut tris: Vec<Tri>) -> Vec<Tri> {
    loop {
        tris = component_at_origin(&tris);
        let mut drop: HashSet<Tri> = HashSet::new();
        let mut at: HashMap<(i64, i64), Vec<Tri>> = HashMap::new();
        for t in &tris {
            for &p in t {
                at.entry(p).or_default().push(*t);
            }
        }
        let mut keys: Vec<_> = at.keys().copied().collect();
        keys.sort_unstable();
        for p in keys {
            let fans = fans(&at[&p]);
            if fans.len() > 1 {
                let largest = fans.iter().map(Vec::len).max().unwrap_or(0);
                let keep = fans.iter().position(|f| f.len() == largest).unwrap_or(0);
                for (k, f) in fans.iter().enumerate() {
                    if k != keep {
                        drop.extend(f.iter().copied());
                    }
                }
            }
        }
        if drop.is_empty() {
            return tris;
        }
        tris.retain(|t| !drop.contains(t));
    }
}

fn shares_edge(a: &Tri, b: &Tri) -> bool {
    a.iter().filter(|p| b.contains(p)).count() == 2
}

/// Groups of triangles around one vertex connected through shared edges.
fn fans(around: &[Tri]) -> Vec<Vec<Tri>> {
    let mut seen = vec![false; around.len()];
    let mut out = Vec::new();
    for s in 0..around.len() {
        if seen[s] {
            continue;
        }
        seen[s] = true;
        let mut fan = vec![around[s]];
        let mut queue = VecDeque::from([s]);
        while let Some(a) = queue.pop_front() {
            for b in 0..around.len() {
                if !seen[b] && shares_edge(&around[a], &around[b]) {
                    seen[b] = true;
                    fan.push(around[b]);
                    queue.push_back(b);
                }
            }
        }
        out.push(fan);
    }
    out
}

/// The triangles edge-connected to one with corner `(0, 0)`.
fn component_at_origin(tris: &[Tri]) -> Vec<Tri> {
    let mut by_edge: HashMap<LatticeEdge, Vec<usize>> = HashMap::new();
    for (k, t) in tris.iter().enumerate() {
        for e in 0..3 {
            let (a, b) = (t[e], t[(e + 1) % 3]);
            by_edge.entry((a.min(b), a.max(b))).or_default().push(k);
        }
    }
    let Some(start) = tris.iter().position(|t| t.contains(&(0, 0))) else {
        return Vec::new();
    };
    let mut seen = vec![false; tris.len()];
    seen[start] = true;
    let mut queue = VecDeque::from([start]);
    while let Some(k) = queue.pop_front() {
        let t = tris[k];
        for e in 0..3 {
            let (a, b) = (t[e], t[(e + 1) % 3]);
            for &m in &by_edge[&(a.min(b), a.max(b))] {
                if !seen[m] {
                    seen[m] = true;
                    queue.push_back(m);
                }
            }
        }
    }
    tris.iter()
        .zip(&seen)
        .filter(|&(_, &s)| s)
        .map(|(t, _)| *t)
        .collect()
}
