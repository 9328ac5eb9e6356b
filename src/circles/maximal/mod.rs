//! Koebe–Andreev–Thurston maximal packings (notes §1.4, proofs/T11).
//!
//! - Disk: a simplicial triangulated disk with at least one interior vertex gets
//!   horocycles at its boundary vertices and hyperbolic radii at its interior vertices
//!   with angle sum `2π` ([`hyperbolic`], [`solve`]), laid out in the unit disk
//!   ([`layout`]) — the maximal packing, unique up to disk automorphisms, which the
//!   normalisation fixes.
//! - Sphere: a simplicial triangulated sphere is punctured at one vertex, the rest packed
//!   maximally, and the unit circle taken as the punctured vertex's circle; the inverse
//!   stereographic projection gives caps on the sphere ([`sphere`]).
//! - [`tangency`] and [`sphere::check_sphere_packing`] certify the result on its circles.
//!
//! The radii depend only on the combinatorics: no length of the input is read.

pub mod hyperbolic;
pub mod layout;
pub mod pipeline;
pub mod solve;
pub mod sphere;
pub mod stopping;
pub mod svg;
pub mod tangency;
pub mod violation;

use crate::mesh::{Mesh, MeshError, Vertex};
use crate::scalar::Real;
use layout::{layout_disk, Circle, LayoutError};
use solve::{newton_f64, refine, refine_from, MaximalSolveError};
use sphere::{cap_of_disk, outer_cap, Cap};
use std::collections::HashSet;

/// Why no maximal packing was computed.
#[derive(Debug, thiserror::Error)]
pub enum MaximalError {
    /// A face meets one vertex twice.
    #[error("face f{0} meets one vertex twice: a packing needs a simplicial triangulation")]
    RepeatedVertex(usize),
    /// Two edges join the same two vertices.
    #[error("edges e{0} and e{1} join the same two vertices: a packing needs a simplicial triangulation")]
    MultiEdge(usize, usize),
    /// The surface is not a disk (disk packings) or not a sphere (sphere packings).
    #[error("not a {expected}: Euler characteristic {chi}, {loops} boundary loop(s)")]
    Topology {
        /// What was expected.
        expected: &'static str,
        /// Euler characteristic.
        chi: i64,
        /// Boundary loops.
        loops: usize,
    },
    /// A disk without interior vertices (or a sphere punctured to one).
    #[error("no interior vertex: the maximal packing is normalised at an interior circle")]
    NoInteriorVertex,
    /// The puncture vertex does not exist.
    #[error("v{0} is not a vertex")]
    NoSuchVertex(usize),
    /// Removing the star of the puncture failed.
    #[error("puncturing at v{0}: {1}")]
    Puncture(usize, MeshError),
    /// The solver failed.
    #[error(transparent)]
    Solve(#[from] MaximalSolveError),
    /// The layout failed.
    #[error(transparent)]
    Layout(#[from] LayoutError),
}

/// How to compute a maximal packing.
#[derive(Clone, Debug, Default)]
pub struct Options {
    /// The interior vertex whose circle is centred at 0 (default: one farthest from the
    /// boundary in edges, the lowest index among them).
    pub centre: Option<usize>,
    /// A neighbour of `centre` placed on the positive real axis (default: the tip of the
    /// first outgoing half-edge of `centre`).
    pub direction: Option<usize>,
    /// `u = ln tanh(r/2)` per vertex to start Newton from (default `ln tanh(1/2)`).
    pub start: Option<Vec<f64>>,
    /// Stopping residual `max |2π − θ|` of the refinement (default `2⁶·n·u` of the
    /// backend).
    pub tolerance: Option<f64>,
    /// The tangency tolerance `ε` the layout should meet with margin: the refinement starts
    /// at `ε/(2⁴·n)` and is tightened until the largest defect of the layout, measured in
    /// the backend, is below `ε/2⁴` (proofs/B99; [`stopping`]). Ignored in `f64` and when
    /// `tolerance` is given.
    pub epsilon: Option<f64>,
}

/// A maximal packing of a disk, laid out in the unit disk.
#[derive(Clone, Debug)]
pub struct DiskPacking<T> {
    /// The disk.
    pub mesh: Mesh,
    /// Interior vertices (boundary ones carry horocycles).
    pub interior: Vec<bool>,
    /// `t = tanh(r/2)` per vertex (1 on horocycles).
    pub t: Vec<T>,
    /// The Euclidean circles in the unit disk.
    pub circles: Vec<Circle<T>>,
    /// The normalisation: centred circle and the neighbour on the positive real axis.
    pub centre: usize,
    /// See `centre`.
    pub direction: usize,
    /// Newton iterations in `f64`.
    pub newton_iterations: usize,
    /// Refinement steps in `T`.
    pub refinement_steps: usize,
    /// `max |2π − θ|` of the `f64` solution.
    pub f64_residual: f64,
    /// Layouts computed (more than one when [`Options::epsilon`] tightened the refinement).
    pub layouts: usize,
    /// The largest tangency defect of the final layout measured in the backend
    /// ([`stopping::layout_defect`]; a heuristic, not a bound).
    pub layout_defect: f64,
}

/// A packing of a sphere by caps, from a maximal packing of the sphere punctured at `puncture`.
#[derive(Clone, Debug)]
pub struct SpherePacking<T> {
    /// The punctured vertex (its cap is the southern hemisphere).
    pub puncture: usize,
    /// The maximal packing of the punctured sphere (vertices `w > puncture` renumbered `w − 1`).
    pub disk: DiskPacking<T>,
    /// One cap per vertex of the sphere.
    pub caps: Vec<Cap<T>>,
}

/// Refuse faces with a repeated vertex and multi-edges.
pub fn check_simplicial(mesh: &Mesh) -> Result<(), MaximalError> {
    for f in mesh.faces() {
        let [a, b, c] = mesh.face_vertices(f);
        if a == b || b == c || c == a {
            return Err(MaximalError::RepeatedVertex(f.idx()));
        }
    }
    let mut seen = std::collections::HashMap::new();
    for e in mesh.edges() {
        let h = e.halfedge();
        let (a, b) = (mesh.tail(h).idx(), mesh.tip(h).idx());
        let key = (a.min(b), a.max(b));
        if let Some(&first) = seen.get(&key) {
            return Err(MaximalError::MultiEdge(first, e.idx()));
        }
        seen.insert(key, e.idx());
    }
    Ok(())
}

/// The maximal packing of the triangulated disk `mesh` in the backend of `ctx` (module docs).
pub fn maximal_disk<T: Real>(
    mesh: &Mesh,
    ctx: T::Ctx,
    opts: &Options,
) -> Result<DiskPacking<T>, MaximalError> {
    check_simplicial(mesh)?;
    let chi = mesh.euler_characteristic();
    let loops = mesh.n_boundary_loops();
    if chi != 1 || loops != 1 {
        return Err(MaximalError::Topology {
            expected: "disk",
            chi,
            loops,
        });
    }
    let interior: Vec<bool> = mesh.boundary_vertices().iter().map(|b| !b).collect();
    if !interior.iter().any(|&b| b) {
        return Err(MaximalError::NoInteriorVertex);
    }
    let centre = opts
        .centre
        .unwrap_or_else(|| deepest_vertex(mesh, &interior));
    if !interior.get(centre).copied().unwrap_or(false) {
        return Err(LayoutError::CentreNotInterior(centre).into());
    }
    let direction = match opts.direction {
        Some(d) => d,
        None => mesh.tip(mesh.vertex_halfedge(Vertex(centre as u32))).idx(),
    };
    let n = mesh.n_vertices();
    let default_u = 0.5_f64.tanh().ln();
    let start = opts
        .start
        .clone()
        .unwrap_or_else(|| vec![solve::common_scale_start(mesh, &interior, default_u); n]);
    let tol64 = 64.0 * n as f64 * f64::EPSILON / 2.0;
    let sol = newton_f64(mesh, &interior, &start, tol64.max(1e-13), 100)?;
    let floor = 64.0 * n as f64 * T::unit_roundoff(ctx);
    let mut tol = match (opts.tolerance, opts.epsilon) {
        (Some(t), _) => t,
        (None, Some(eps)) => stopping::first_tolerance(eps, n, floor),
        (None, None) => floor,
    };
    let (mut u, mut steps) = if T::precision_bits(ctx) <= 53 {
        (sol.u.iter().map(|&x| T::from_f64(x, ctx)).collect(), 0)
    } else {
        refine::<T>(mesh, &interior, &sol, ctx, tol, 40)?
    };
    let mut t = hyperbolic::radii_from_u(&u, &interior);
    let mut circles = layout_disk(mesh, &t, &interior, centre, direction)?;
    let mut layouts = 1;
    // proof: B99 — tighten the residual until the layout's defects are below ε/2⁴.
    if let (None, Some(eps), true) = (opts.tolerance, opts.epsilon, T::precision_bits(ctx) > 53) {
        while layouts <= stopping::MAX_ROUNDS {
            let defect = stopping::layout_defect(mesh, &circles, &interior);
            let Some(next) = stopping::next_tolerance(tol, defect, eps, floor) else {
                break;
            };
            tol = next;
            let (v, s) = refine_from::<T>(mesh, &interior, &sol, u, ctx, tol, 40)?;
            u = v;
            steps += s;
            t = hyperbolic::radii_from_u(&u, &interior);
            circles = layout_disk(mesh, &t, &interior, centre, direction)?;
            layouts += 1;
        }
    }
    let layout_defect = stopping::layout_defect(mesh, &circles, &interior);
    Ok(DiskPacking {
        mesh: mesh.clone(),
        interior,
        t,
        circles,
        centre,
        direction,
        newton_iterations: sol.iterations,
        refinement_steps: steps,
        f64_residual: sol.residual,
        layouts,
        layout_defect,
    })
}

/// The maximal packing of the disk `mesh` in MPFR laid out within `eps` with margin
/// (proofs/B99): at `bits` (raised to [`stopping::bits_for`]) with [`Options::epsilon`], and
/// when the refinement reached the floor of that precision with a measured defect still
/// above `ε/2⁴` (rounding in the layout, amplified near the unit circle), once more at
/// [`stopping::bits_after`] bits. Returns the packing and the bits used.
pub fn maximal_disk_within(
    mesh: &Mesh,
    eps: f64,
    bits: u32,
    opts: &Options,
) -> Result<(DiskPacking<crate::scalar::Mpfr>, u32), MaximalError> {
    let bits = bits.max(stopping::bits_for(eps, mesh.n_vertices()));
    let o = Options {
        epsilon: Some(eps),
        ..opts.clone()
    };
    let run = |bits: u32| {
        let prec = crate::scalar::Precision::new(u64::from(bits))
            .map_err(|_| MaximalError::Solve(MaximalSolveError::Precision(bits)))?;
        maximal_disk::<crate::scalar::Mpfr>(mesh, prec, &o)
    };
    let first = run(bits)?;
    match stopping::bits_after(bits, first.layout_defect, eps) {
        Some(more) => Ok((run(more)?, more)),
        None => Ok((first, bits)),
    }
}

/// An interior vertex at the largest edge distance from the boundary (lowest index on ties).
fn deepest_vertex(mesh: &Mesh, interior: &[bool]) -> usize {
    let mut dist: Vec<usize> = interior
        .iter()
        .map(|&i| if i { usize::MAX } else { 0 })
        .collect();
    let mut queue: std::collections::VecDeque<usize> =
        (0..interior.len()).filter(|&v| !interior[v]).collect();
    while let Some(v) = queue.pop_front() {
        for h in mesh.outgoing(Vertex(v as u32)) {
            let w = mesh.tip(h).idx();
            if dist[w] == usize::MAX {
                dist[w] = dist[v] + 1;
                queue.push_back(w);
            }
        }
    }
    let best = dist
        .iter()
        .filter(|&&d| d != usize::MAX)
        .max()
        .copied()
        .unwrap_or(0);
    dist.iter().position(|&d| d == best).unwrap_or(0)
}

/// The mesh without the star of `v` (vertices `w > v` renumbered `w − 1`).
pub fn puncture(mesh: &Mesh, v: usize) -> Result<Mesh, MeshError> {
    let keep: Vec<[u32; 3]> = mesh
        .face_list()
        .into_iter()
        .filter(|t| !t.contains(&(v as u32)))
        .map(|t| t.map(|w| if w as usize > v { w - 1 } else { w }))
        .collect();
    Mesh::from_faces(mesh.n_vertices() as u32 - 1, &keep)
}

/// The cap packing of the triangulated sphere `mesh` from the maximal packing of the sphere
/// punctured at `puncture` (module docs). `opts.centre`/`direction` name vertices of the
/// sphere (default: the vertex of the punctured sphere farthest from its boundary).
pub fn maximal_sphere<T: Real>(
    mesh: &Mesh,
    puncture_at: usize,
    ctx: T::Ctx,
    opts: &Options,
) -> Result<SpherePacking<T>, MaximalError> {
    check_simplicial(mesh)?;
    let chi = mesh.euler_characteristic();
    if !mesh.is_closed() || chi != 2 {
        return Err(MaximalError::Topology {
            expected: "sphere",
            chi,
            loops: mesh.n_boundary_loops(),
        });
    }
    if puncture_at >= mesh.n_vertices() {
        return Err(MaximalError::NoSuchVertex(puncture_at));
    }
    let disk = puncture(mesh, puncture_at).map_err(|e| MaximalError::Puncture(puncture_at, e))?;
    let down = |w: usize| if w > puncture_at { w - 1 } else { w };
    let links: HashSet<usize> = mesh
        .outgoing(Vertex(puncture_at as u32))
        .map(|h| mesh.tip(h).idx())
        .collect();
    let mut o = opts.clone();
    o.centre = match opts.centre {
        Some(c) if c == puncture_at || links.contains(&c) || c >= mesh.n_vertices() => {
            return Err(LayoutError::CentreNotInterior(c).into())
        }
        Some(c) => Some(down(c)),
        None => None,
    };
    o.direction = opts.direction.map(|d| {
        if d == puncture_at {
            usize::MAX
        } else {
            down(d)
        }
    });
    if let Some(s) = &opts.start {
        o.start = Some(
            (0..mesh.n_vertices())
                .filter(|&w| w != puncture_at)
                .map(|w| s.get(w).copied().unwrap_or(0.5_f64.tanh().ln()))
                .collect(),
        );
    }
    let packing = maximal_disk::<T>(&disk, ctx, &o)?;
    let like = packing.t[0].clone();
    let caps = (0..mesh.n_vertices())
        .map(|w| {
            if w == puncture_at {
                outer_cap(&like)
            } else {
                let c = &packing.circles[down(w)];
                cap_of_disk(&c.centre, &c.radius)
            }
        })
        .collect();
    Ok(SpherePacking {
        puncture: puncture_at,
        disk: packing,
        caps,
    })
}
