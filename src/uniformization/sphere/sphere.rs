//! The sphere target (notes §1.5.3 Thm 9): a closed genus-0 surface with a discrete metric
//! is discretely conformally equivalent (with Ptolemy flips) to a convex polyhedron
//! inscribed in the unit sphere. proof: B74
//!
//! Method (B74): choose a pole `v∞` (given, or [`pole_candidates`]: a graph centre, then the
//! vertices of largest degree with a simple link, tried in turn). The inversion centred at `v∞` is a
//! Möbius map; it turns the inscribed polyhedron into a planar Delaunay triangulation of
//! the disk `D = M − star(v∞)` whose lengths are `e^{(w_i+w_j)/2}·ℓ_ij` with
//! `w_a = −2 log ℓ_{a v∞}` on the link of `v∞`. So:
//!
//! 1. `T₀`: the input made intrinsic Delaunay by Euclidean flips (as in [`super::newton`]);
//! 2. the Dirichlet problem on `D` ([`super::dirichlet`]): `u_a = w_a` on the link,
//!    `θ_i(u) = 2π` at the other vertices, Ptolemy flips of the interior edges of `D`;
//! 3. `D` laid out in the plane ([`super::layout`]), scaled and translated so that its
//!    vertices have centroid `0` and mean squared distance `1` from it;
//! 4. inverse stereographic projection `p ↦ (2p, |p|² − 1)/(|p|² + 1)` to `S²`, `v∞` at
//!    the north pole `(0, 0, 1)`;
//! 5. optionally ([`SphereOptions::normalize`]) the Möbius normalisation that puts the
//!    centroid of the vertices at the origin (the conformal barycentre, unique up to
//!    rotation), by iterating the ball automorphism `φ_c` with `c` half the centroid.
//!
//! When the solved disk is not convex at a link vertex `a` (its angle `θ_a > π`, so the
//! inscribed polyhedron would fold along the edge `v∞a`), the edge `v∞a` is Ptolemy-flipped
//! in the whole surface (B93): `a` leaves the link and becomes a free interior vertex of the
//! new disk, whose new boundary edge `bc` has disk length `ℓ̃_ab + ℓ̃_ac` (a degenerate
//! triangle at `u_a = w_a`); the disk is rebuilt from the new star and re-solved from the
//! previous `u` with `u_a = w_a +` [`STAR_FLIP_START_OFFSET`], until the link is convex
//! ([`SphereOptions::star_flips`]).
//!
//! The final triangulation is `T₀` with all Ptolemy flips in order: the disk's and those of
//! edges at the pole.

use super::dirichlet::{solve_dirichlet, DirichletError, DirichletSolution};
use super::error::UniformizeError;
use super::layout::{unfold, Layout};
use super::newton::{validate_input, Stop, UniformizeOptions};
pub use super::pole::{check_pole, pole_candidates, POLE_ATTEMPTS};
use super::targets::Targets;
use crate::algorithms::flip_to_delaunay::{flip_to_delaunay, FlipKind, FlipOptions};
use crate::algorithms::flips::flip_ptolemy;
use crate::mesh::{Edge, Face, HalfEdge, Mesh, Vertex};

/// Options of [`uniformize_sphere`].
#[derive(Clone, Debug)]
pub struct SphereOptions {
    /// The pole `v∞` (a vertex of the input); default: [`pole_candidates`] of `T₀` in turn.
    pub pole: Option<u32>,
    /// Möbius-normalise: centroid of the output vertices at the origin.
    pub normalize: bool,
    /// Newton options of the disk problem.
    pub newton: UniformizeOptions,
    /// Flip the edge `v∞a` and re-solve while a link vertex `a` has disk angle `θ_a > π`
    /// (B93); when `false`, the star of `v∞` is kept and such a result is returned as it is
    /// (never certified, B74 "Limits").
    pub star_flips: bool,
}

impl Default for SphereOptions {
    fn default() -> Self {
        SphereOptions {
            pole: None,
            normalize: true,
            newton: UniformizeOptions {
                tolerance: 1e-12,
                // A pole whose disk problem stalls is given up after 5 such steps (the
                // next pole or continuation stage is tried), not after the iteration cap.
                stall_window: Some(5),
                ..UniformizeOptions::default()
            },
            star_flips: true,
        }
    }
}

/// Why the sphere target was refused or not reached.
#[derive(Debug, thiserror::Error)]
pub enum SphereError {
    /// The surface or its lengths are refused.
    #[error(transparent)]
    Input(#[from] UniformizeError),
    /// Not a connected genus-0 surface.
    #[error("the sphere target needs a connected closed surface of genus 0 (χ = 2); this one has χ = {chi} and {components} component(s)")]
    NotASphere {
        /// Euler characteristic.
        chi: i64,
        /// Connected components.
        components: usize,
    },
    /// The pole is out of range or its star in `T₀` is not a disk with a simple link.
    #[error("pole v{vertex}: {reason}")]
    Pole {
        /// The vertex.
        vertex: u32,
        /// Why.
        reason: String,
    },
    /// No vertex of `T₀` has a simple link that leaves faces outside its star.
    #[error("no vertex of the intrinsic Delaunay triangulation has a simple link leaving faces outside its star; give --pole")]
    NoPole,
    /// The disk problem was refused.
    #[error("the disk problem: {0}")]
    Dirichlet(#[from] DirichletError),
    /// The disk problem did not converge.
    #[error("the disk problem did not converge ({stop:?}); max |Θ − θ| = {residual:e}")]
    NotConverged {
        /// Why Newton stopped.
        stop: Stop,
        /// The last residual.
        residual: f64,
    },
    /// The layout of the flat disk failed (a vertex not reached or not finite).
    #[error("laying out the flat disk: {0}")]
    Layout(String),
}

/// The disk `D = T − star(v∞)` of a triangulation `T` of the sphere (`T₀`, or `T₀` after
/// Ptolemy flips) with its maps back to `T`.
#[derive(Clone, Debug)]
pub struct Disk {
    /// The disk (vertices renumbered: `T`'s without `v∞`).
    pub mesh: Mesh,
    /// The lengths of `T` restricted to the disk.
    pub lengths: Vec<f64>,
    /// Per disk vertex, the vertex of `T` (and of `T₀`: flips keep vertices).
    pub vertex: Vec<u32>,
    /// Per disk edge, the edge of `T` (edge indices survive flips, so this map holds for
    /// the flipped disk and the flipped `T` alike).
    pub edge: Vec<Edge>,
    /// Per disk vertex on the link of `v∞` in `T`: the length `ℓ_{a v∞}`; `None` inside.
    pub pole_length: Vec<Option<f64>>,
}

/// The result of [`uniformize_sphere`].
#[derive(Clone, Debug)]
pub struct SphereUniformization {
    /// `T₀`: the input made intrinsic Delaunay by Euclidean flips.
    pub initial_mesh: Mesh,
    /// `ℓ⁰`: the lengths of `T₀`.
    pub initial_lengths: Vec<f64>,
    /// Euclidean flips from the input to `T₀`.
    pub euclidean_flips: usize,
    /// Those flips, in order (edges of the input; an edge keeps its index when flipped).
    pub euclidean_sequence: Vec<Edge>,
    /// The pole `v∞` (a vertex of `T₀`).
    pub pole: u32,
    /// The disk `T − star(v∞)` of the last disk problem, `T` being `T₀` with the flips
    /// `flip_sequence[..star_prefix]` (`T₀` itself when no edge at the pole flipped).
    pub disk: Disk,
    /// The Dirichlet values `w_a = −2 log ℓ_{a v∞}` per vertex of `disk` (`None` inside).
    pub fixed: Vec<Option<f64>>,
    /// The solved disk problem on `disk` (its flips are edges of `disk`).
    pub solution: DirichletSolution,
    /// The flips of edges at the pole (B93), as edges of `T₀`, in order; each is also in
    /// `flip_sequence`.
    pub star_flips: Vec<Edge>,
    /// `flip_sequence[..star_prefix]` ends with the last flip at the pole (`0`: none).
    pub star_prefix: usize,
    /// Link vertices (of `T₀`) where the returned disk's angle exceeds `π` by more than
    /// [`STAR_FLIP_MARGIN`] in `f64`: empty when the boundary is numerically convex (a
    /// heuristic; only the certificate, B76, proves convexity).
    pub reflex: Vec<u32>,
    /// The layout of the final disk triangulation.
    pub layout: Layout,
    /// Per disk vertex, its planar position (centroid 0, mean squared radius 1, over the
    /// placed vertices), the stereographic preimage of its output position before the
    /// Möbius normalisation; NaN for a vertex not placed (`layout_failure`).
    pub planar: Vec<[f64; 2]>,
    /// The final triangulation of the sphere: `T₀` with `flip_sequence`.
    pub mesh: Mesh,
    /// All Ptolemy flips from `T₀` to `mesh` as edges of `T₀`, in order: the disk flips of
    /// each disk problem, and between them the flips at the pole (B93).
    pub flip_sequence: Vec<Edge>,
    /// Per vertex of `T₀`, its position on the unit sphere (NaN where not placed).
    pub positions: Vec<[f64; 3]>,
    /// `|centroid|` of `positions` (after the normalisation, when asked for).
    pub centroid_norm: f64,
    /// Why the binary64 layout is incomplete, when it is: the disk vertices it could not
    /// place have NaN in `planar` and `positions`, and no Möbius normalisation is applied.
    /// The disk problem's solution (and its certificate) does not depend on the layout.
    pub layout_failure: Option<String>,
}

/// A link vertex counts as reflex when its disk angle exceeds `π` by more than this (in
/// radians, `f64`): far above the solver's residual `10⁻¹²`, so that a rounding error at a
/// tie `θ_a = π` does not flip an edge whose new triangle would stay degenerate. A
/// heuristic steering the solve; the certificate (B76) decides. proof: B93
pub const STAR_FLIP_MARGIN: f64 = 1e-9;

/// The start of `u_a` after the flip of `v∞a` is `w_a` plus this: the new triangle `abc`
/// is degenerate at `u_a = w_a` (angle `π` at `a`, B93), its angles at `b` and `c` grow
/// like `√(u_a − w_a)` (about `0.04` rad here for equal sides), so the cotangent
/// Hessian is finite and no `NaN` appears; the angle sum at `a` still exceeds `2π`, and
/// Newton increases `u_a`. proof: B93
pub const STAR_FLIP_START_OFFSET: f64 = 1.0 / 512.0;

/// One pole's outcome: the disk problems and the flips at the pole.
struct PoleSolve {
    disk: Disk,
    fixed: Vec<Option<f64>>,
    solution: DirichletSolution,
    /// Flips (edges of `T₀`) before the last disk problem.
    sequence: Vec<Edge>,
    star_flips: Vec<Edge>,
    /// Disk vertices with `θ > π + STAR_FLIP_MARGIN`, most reflex first.
    reflex: Vec<usize>,
}

/// The Dirichlet values `w_a = −2 log ℓ_{a v∞}` per disk vertex.
fn dirichlet_values(disk: &Disk) -> Vec<Option<f64>> {
    disk.pole_length
        .iter()
        .map(|l| l.map(|l| -2.0 * l.ln()))
        .collect()
}

/// Link vertices of `disk` whose angle sum in `solution` exceeds `π + STAR_FLIP_MARGIN`,
/// most reflex first.
fn reflex_link(fixed: &[Option<f64>], solution: &DirichletSolution) -> Vec<usize> {
    let theta = crate::geometry::cone_angles::cone_angles::<f64>(&solution.mesh, &solution.lengths);
    let mut out: Vec<(usize, f64)> = theta
        .iter()
        .enumerate()
        .filter(|&(v, t)| fixed[v].is_some() && *t > std::f64::consts::PI + STAR_FLIP_MARGIN)
        .map(|(v, &t)| (v, t))
        .collect();
    out.sort_by(|x, y| y.1.total_cmp(&x.1));
    out.into_iter().map(|(v, _)| v).collect()
}

/// Solve the disk problem of `pole` and, while a link vertex is reflex (and `star_flips`),
/// flip its edge to the pole in the whole surface and re-solve (B93). `Err` when the first
/// disk problem fails; a later failure keeps the last solved (reflex) state.
fn solve_for_pole(
    t0: &Mesh,
    l0: &[f64],
    pole: Vertex,
    opts: &SphereOptions,
) -> Result<PoleSolve, SphereError> {
    let pole_err = |reason| SphereError::Pole {
        vertex: pole.0,
        reason,
    };
    let disk = disk_of(t0, l0, pole).map_err(pole_err)?;
    let fixed = dirichlet_values(&disk);
    let theta = vec![2.0 * std::f64::consts::PI; disk.mesh.n_vertices()];
    let solution = solve_by_continuation(&disk, &fixed, &theta, &opts.newton)?;
    let reflex = reflex_link(&fixed, &solution);
    let mut state = PoleSolve {
        disk,
        fixed,
        solution,
        sequence: Vec::new(),
        star_flips: Vec::new(),
        reflex,
    };
    // The triangulation T of the current disk, with its f64 lengths (T₀'s carried by the
    // Ptolemy flips, T28).
    let (mut t, mut l) = (t0.clone(), l0.to_vec());
    if opts.star_flips {
        while let Some(next) = star_flip_step(&t, &l, pole, &state, &theta, &opts.newton) {
            (t, l) = (next.0, next.1);
            state = next.2;
        }
    }
    Ok(state)
}

/// One round of B93 on `state` (solved on the disk of `(t, l)`): the disk's flips and the
/// flip of `v∞a` (`a` the most reflex link vertex) applied to `t`, the new disk, and its
/// problem solved from the previous `u` with `u_a = w_a + STAR_FLIP_START_OFFSET` (by
/// continuation when that fails). `None` when nothing is reflex, the link has three
/// vertices, or a step fails.
fn star_flip_step(
    t: &Mesh,
    l: &[f64],
    pole: Vertex,
    state: &PoleSolve,
    theta: &[f64],
    newton: &UniformizeOptions,
) -> Option<(Mesh, Vec<f64>, PoleSolve)> {
    let &a = state.reflex.first()?;
    if state.fixed.iter().flatten().count() <= 3 {
        return None;
    }
    let (mut t, mut l) = (t.clone(), l.to_vec());
    let mut sequence = state.sequence.clone();
    for e in &state.solution.flip_sequence {
        let e = state.disk.edge[e.idx()];
        flip_ptolemy(&mut t, &mut l, e).ok()?;
        sequence.push(e);
    }
    let target = Vertex(state.disk.vertex[a]);
    let star = t.outgoing(pole).find(|&h| t.tip(h) == target)?.edge();
    flip_ptolemy(&mut t, &mut l, star).ok()?;
    sequence.push(star);
    check_pole(&t, pole).ok()?;
    let disk = disk_of(&t, &l, pole).ok()?;
    let fixed = dirichlet_values(&disk);
    let start: Vec<f64> = state
        .solution
        .u
        .iter()
        .enumerate()
        .map(|(v, &x)| {
            if v == a {
                x + STAR_FLIP_START_OFFSET
            } else {
                x
            }
        })
        .collect();
    let warm = solve_dirichlet(&disk.mesh, &disk.lengths, &fixed, theta, &start, newton).ok();
    let solution = match warm {
        Some(s) if s.stop == Stop::Converged => s,
        _ => solve_by_continuation(&disk, &fixed, theta, newton).ok()?,
    };
    let reflex = reflex_link(&fixed, &solution);
    let mut star_flips = state.star_flips.clone();
    star_flips.push(star);
    Some((
        t,
        l,
        PoleSolve {
            disk,
            fixed,
            solution,
            sequence,
            star_flips,
            reflex,
        },
    ))
}

/// The disk `mesh − star(pole)` (the pole already checked by [`check_pole`]).
pub fn disk_of(mesh: &Mesh, lengths: &[f64], pole: Vertex) -> Result<Disk, String> {
    let renumber = |w: Vertex| if w.0 < pole.0 { w.0 } else { w.0 - 1 };
    let in_star = |f: Face| mesh.face_vertices(f).contains(&pole);
    let kept: Vec<Face> = mesh.faces().filter(|&f| !in_star(f)).collect();
    let mut slot = vec![u32::MAX; mesh.n_faces()];
    for (k, f) in kept.iter().enumerate() {
        slot[f.idx()] = k as u32;
    }
    let faces: Vec<[u32; 3]> = kept
        .iter()
        .map(|&f| mesh.face_vertices(f).map(renumber))
        .collect();
    let side = |h: HalfEdge| -> Option<(u32, u8)> {
        let f = mesh.face(h)?;
        let s = mesh.face_halfedges(f).iter().position(|&x| x == h)?;
        (slot[f.idx()] != u32::MAX).then_some((slot[f.idx()], s as u8))
    };
    let gluing: Vec<_> = mesh
        .edges()
        .filter_map(|e| Some((side(e.side(0))?, side(e.side(1))?)))
        .collect();
    let disk = Mesh::from_gluing(mesh.n_vertices() as u32 - 1, &faces, &gluing)
        .map_err(|e| format!("the disk does not build: {e}"))?;
    let mut edge = vec![Edge(u32::MAX); disk.n_edges()];
    for (k, &f) in kept.iter().enumerate() {
        let ours = disk.face_halfedges(Face(k as u32));
        for (hd, hs) in ours.into_iter().zip(mesh.face_halfedges(f)) {
            if disk.tail(hd).0 != renumber(mesh.tail(hs)) {
                return Err("the disk's faces do not match the surface's".into());
            }
            edge[hd.edge().idx()] = hs.edge();
        }
    }
    let chi = disk.euler_characteristic();
    if chi != 1 || disk.n_boundary_loops() != 1 {
        return Err(format!(
            "the complement of the star is not a disk (χ = {chi}, {} boundary loop(s))",
            disk.n_boundary_loops()
        ));
    }
    let vertex: Vec<u32> = (0..mesh.n_vertices() as u32)
        .filter(|&w| w != pole.0)
        .collect();
    let mut pole_length = vec![None; disk.n_vertices()];
    for h in mesh.outgoing(pole) {
        pole_length[renumber(mesh.tip(h)) as usize] = Some(lengths[h.edge().idx()]);
    }
    let disk_lengths = edge.iter().map(|e| lengths[e.idx()]).collect();
    Ok(Disk {
        mesh: disk,
        lengths: disk_lengths,
        vertex,
        edge,
        pole_length,
    })
}

/// The disk problem by continuation in the Dirichlet values: with `w̄` their mean and
/// `δ_a = w_a − w̄`, solve with the values `w̄ + t·δ` for `t` from `0` (a constant, i.e. a
/// global scale of the input: `u ≡ w̄` is a valid start) to `1`, each stage started at the
/// previous solution — first extrapolated along the secant of the last two stages' solutions
/// (a predictor: the free values follow the boundary's), then as it is if that start does
/// not converge — the step in `t` doubled after a success and halved after a failure (at
/// least `2⁻²⁰`). Intermediate stages stop at `max |Θ − θ| ≤ 10⁻⁶`.
fn solve_by_continuation(
    disk: &Disk,
    fixed: &[Option<f64>],
    theta: &[f64],
    newton: &UniformizeOptions,
) -> Result<DirichletSolution, SphereError> {
    let values: Vec<f64> = fixed.iter().flatten().copied().collect();
    let mean = values.iter().sum::<f64>() / values.len().max(1) as f64;
    let at = |t: f64| -> Vec<Option<f64>> {
        fixed
            .iter()
            .map(|w| w.map(|w| if t >= 1.0 { w } else { mean + t * (w - mean) }))
            .collect()
    };
    let loose = UniformizeOptions {
        tolerance: newton.tolerance.max(1e-6),
        ..newton.clone()
    };
    let mut u = vec![mean; fixed.len()];
    let first = solve_dirichlet(&disk.mesh, &disk.lengths, &at(0.0), theta, &u, &loose)?;
    if first.stop != Stop::Converged {
        return Err(SphereError::NotConverged {
            stop: first.stop,
            residual: first.residual_max,
        });
    }
    u.clone_from(&first.u);
    let (mut t, mut dt) = (0.0f64, 1.0f64);
    // The last two stages' solutions: the next stage starts from their secant extrapolation
    // (the free values follow the boundary's), then, if that start fails, from `u` itself.
    let mut previous: Option<(f64, Vec<f64>)> = None;
    loop {
        let next = (t + dt).min(1.0);
        let o = if next >= 1.0 { newton } else { &loose };
        let fixed_next = at(next);
        let predicted = previous.as_ref().map(|(tp, up)| {
            let s = (next - t) / (t - tp);
            u.iter()
                .zip(up)
                .map(|(a, b)| a + s * (a - b))
                .collect::<Vec<f64>>()
        });
        let mut sol = None;
        for start in predicted.iter().chain(std::iter::once(&u)) {
            let trial = solve_dirichlet(&disk.mesh, &disk.lengths, &fixed_next, theta, start, o)?;
            let converged = trial.stop == Stop::Converged;
            sol = Some(trial);
            if converged {
                break;
            }
        }
        let sol = sol.expect("at least the plain start is tried");
        if sol.stop == Stop::Converged {
            if next >= 1.0 {
                return Ok(sol);
            }
            previous = Some((t, std::mem::replace(&mut u, sol.u)));
            t = next;
            dt *= 2.0;
        } else {
            dt *= 0.5;
            if dt < 2f64.powi(-20) {
                return Err(SphereError::NotConverged {
                    stop: sol.stop,
                    residual: sol.residual_max,
                });
            }
        }
    }
}

/// Inverse stereographic projection from the north pole: `p ↦ (2p, |p|² − 1)/(|p|² + 1)`.
pub fn inverse_stereographic(p: [f64; 2]) -> [f64; 3] {
    let r2 = p[0] * p[0] + p[1] * p[1];
    let d = r2 + 1.0;
    unit([2.0 * p[0] / d, 2.0 * p[1] / d, (r2 - 1.0) / d])
}

fn unit(x: [f64; 3]) -> [f64; 3] {
    let n = (x[0] * x[0] + x[1] * x[1] + x[2] * x[2]).sqrt();
    [x[0] / n, x[1] / n, x[2] / n]
}

fn centroid(points: &[[f64; 3]]) -> [f64; 3] {
    let n = points.len().max(1) as f64;
    let mut c = [0.0; 3];
    for p in points {
        for k in 0..3 {
            c[k] += p[k] / n;
        }
    }
    c
}

fn norm(x: [f64; 3]) -> f64 {
    (x[0] * x[0] + x[1] * x[1] + x[2] * x[2]).sqrt()
}

/// The automorphism of the unit ball taking `c` (`|c| < 1`) to the origin, on `|x| = 1`:
/// `φ_c(x) = ((1 − |c|²)(x − c) − |x − c|²c)/|x − c|²` (a Möbius map of `S²`).
pub fn ball_automorphism(c: [f64; 3], x: [f64; 3]) -> [f64; 3] {
    let c2 = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
    let d = [x[0] - c[0], x[1] - c[1], x[2] - c[2]];
    let d2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    unit([
        ((1.0 - c2) * d[0] - d2 * c[0]) / d2,
        ((1.0 - c2) * d[1] - d2 * c[1]) / d2,
        ((1.0 - c2) * d[2] - d2 * c[2]) / d2,
    ])
}

/// Möbius-normalise `points` on `S²`: `x ↦ φ_c(x)` with `c` half the centroid, repeated
/// until `|centroid| ≤ 10⁻¹³` or 1000 rounds (the linearisation of one round is the
/// second-moment matrix, of norm below 1 unless all points lie on a line). Returns the
/// final `|centroid|`.
pub fn mobius_center(points: &mut [[f64; 3]]) -> f64 {
    for _ in 0..1000 {
        let m = centroid(points);
        if norm(m) <= 1e-13 {
            break;
        }
        let c = [0.5 * m[0], 0.5 * m[1], 0.5 * m[2]];
        for p in points.iter_mut() {
            *p = ball_automorphism(c, *p);
        }
    }
    norm(centroid(points))
}

/// Uniformize a closed genus-0 surface to a convex polyhedron inscribed in the unit sphere
/// (notes Thm 9) by the method of the module documentation. The result is numerical
/// (`f64`); [`super::sphere_checks`] certifies its planar layout and
/// [`super::dirichlet_certificate`] the disk problem.
#[allow(clippy::too_many_lines)] // the five steps of the method, in order
pub fn uniformize_sphere(
    mesh: &Mesh,
    lengths: &[f64],
    opts: &SphereOptions,
) -> Result<SphereUniformization, SphereError> {
    validate_input(mesh, lengths, &Targets::flat(mesh.n_vertices())).or_else(|e| match e {
        UniformizeError::GaussBonnet { .. } => Ok(()),
        other => Err(other),
    })?;
    let comps = super::components::Components::of(mesh);
    let chi = mesh.euler_characteristic();
    if chi != 2 || comps.roots.len() != 1 {
        return Err(SphereError::NotASphere {
            chi,
            components: comps.roots.len(),
        });
    }
    if let Some(p) = opts.pole {
        if p as usize >= mesh.n_vertices() {
            return Err(SphereError::Pole {
                vertex: p,
                reason: format!(
                    "out of range (the surface has {} vertices)",
                    mesh.n_vertices()
                ),
            });
        }
    }
    // 1. T₀ (T21, T23).
    let mut t0 = mesh.clone();
    let mut l0 = lengths.to_vec();
    let record = FlipOptions {
        record: true,
        ..FlipOptions::default()
    };
    let rep = flip_to_delaunay(&mut t0, &mut l0, FlipKind::Euclidean, &record)
        .map_err(UniformizeError::from)?;
    if !rep.all_certified_delaunay() {
        return Err(UniformizeError::InitialNotDelaunay {
            undecided: rep.undecided.len() + rep.refused.len(),
        }
        .into());
    }
    let candidates: Vec<Vertex> = match opts.pole {
        Some(p) => {
            check_pole(&t0, Vertex(p)).map_err(|reason| SphereError::Pole { vertex: p, reason })?;
            vec![Vertex(p)]
        }
        None => pole_candidates(&t0),
    };
    // 2. The Dirichlet problem on the disk, for the first candidate pole that converges
    //    with a convex link (after flips at the pole, B93); failing that, the first pole
    //    that converged (its reflex link vertices are reported, never certified).
    let mut first_error = None;
    let mut found = None;
    let mut reflex_fallback = None;
    for &pole in &candidates {
        match solve_for_pole(&t0, &l0, pole, opts) {
            Ok(x) if x.reflex.is_empty() || !opts.star_flips => {
                found = Some((pole, x));
                break;
            }
            Ok(x) => {
                reflex_fallback.get_or_insert((pole, x));
            }
            Err(e) => {
                first_error.get_or_insert(e);
            }
        }
    }
    let Some((pole, solved)) = found.or(reflex_fallback) else {
        return Err(first_error.unwrap_or(SphereError::NoPole));
    };
    let PoleSolve {
        disk,
        fixed,
        solution,
        sequence,
        star_flips,
        reflex,
    } = solved;
    let reflex: Vec<u32> = reflex.iter().map(|&v| disk.vertex[v]).collect();
    // 3. Layout, centroid 0 and mean squared radius 1. A layout binary64 cannot hold (a
    //    vertex the unfolding gives no finite position, where the conformal map crowds a
    //    thin part of the surface below binary64's resolution) is not an error of the
    //    solve: the disk problem is still solved and can be certified; the unplaced
    //    vertices get NaN coordinates and the reason is kept (`layout_failure`).
    let layout = unfold(&solution.mesh, &solution.lengths, Face(0));
    let placed = layout.vertex_positions(&solution.mesh);
    let unplaced = placed
        .iter()
        .filter(|p| !p.is_some_and(|p| p[0].is_finite() && p[1].is_finite()))
        .count();
    let mut planar: Vec<[f64; 2]> = placed
        .iter()
        .map(|p| match p {
            Some(p) if p[0].is_finite() && p[1].is_finite() => *p,
            _ => [f64::NAN; 2],
        })
        .collect();
    let mut layout_failure = (unplaced > 0).then(|| {
        let first = planar.iter().position(|p| p[0].is_nan()).unwrap_or(0);
        let at: Vec<f64> = u32::try_from(first)
            .map(|w| {
                solution
                    .mesh
                    .outgoing(crate::mesh::Vertex(w))
                    .map(|h| solution.lengths[h.edge().idx()])
                    .collect()
            })
            .unwrap_or_default();
        let lo = at.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = at.iter().copied().fold(0.0, f64::max);
        format!(
            "{unplaced} disk vertices (first: {first}, its edges' scaled lengths {lo:e} … {hi:e}) got no finite binary64 position in the unfolding (the conformal map crowds that part of the surface)"
        )
    });
    let kept: Vec<&[f64; 2]> = planar.iter().filter(|p| !p[0].is_nan()).collect();
    let n = kept.len() as f64;
    let (cx, cy) = kept
        .iter()
        .fold((0.0, 0.0), |(x, y), p| (x + p[0] / n, y + p[1] / n));
    let spread = (kept
        .iter()
        .map(|p| (p[0] - cx).powi(2) + (p[1] - cy).powi(2))
        .sum::<f64>()
        / n)
        .sqrt();
    if !(spread.is_normal()) {
        layout_failure.get_or_insert_with(|| "the laid-out vertices coincide".into());
    }
    let scale = if spread.is_normal() { spread } else { 1.0 };
    for p in &mut planar {
        *p = [(p[0] - cx) / scale, (p[1] - cy) / scale];
    }
    // 4. Inverse stereographic projection, v∞ at the north pole, composed with the
    // reflection y ↦ −y: the projection alone reverses orientation (a counterclockwise
    // planar face is seen clockwise from outside the sphere), the reflection restores it so
    // that the faces of the inscribed polyhedron are oriented outward, as the input's are.
    // Both are isometries of the chords' cross ratios (B74).
    let mut positions = vec![[0.0, 0.0, 1.0]; t0.n_vertices()];
    for (k, &v) in disk.vertex.iter().enumerate() {
        let [x, y, z] = inverse_stereographic(planar[k]);
        positions[v as usize] = [x, -y, z];
    }
    // 5. Möbius normalisation (of a complete layout only).
    let centroid_norm = if opts.normalize && layout_failure.is_none() {
        mobius_center(&mut positions)
    } else {
        norm(centroid(&positions))
    };
    // The final triangulation: all flips on T₀.
    let star_prefix = sequence.len();
    let mut flip_sequence = sequence;
    flip_sequence.extend(solution.flip_sequence.iter().map(|e| disk.edge[e.idx()]));
    let mut final_mesh = t0.clone();
    for &e in &flip_sequence {
        final_mesh
            .flip(e)
            .map_err(|err| SphereError::Layout(format!("replaying flip of e{}: {err}", e.0)))?;
    }
    Ok(SphereUniformization {
        initial_mesh: t0,
        initial_lengths: l0,
        euclidean_flips: rep.flips,
        euclidean_sequence: rep.sequence,
        pole: pole.0,
        disk,
        fixed,
        solution,
        layout,
        planar,
        star_flips,
        star_prefix,
        reflex,
        mesh: final_mesh,
        flip_sequence,
        positions,
        centroid_norm,
        layout_failure,
    })
}
