//! The hyperbolic target (notes Thm 11; BPS15 §6; docs/catalogue.md §7; T33, proofs/B38): log scale
//! factors `u` with `sinh(ℓ̃_ij/2) = e^{(u_i+u_j)/2} sinh(ℓ_ij/2)` whose hyperbolic cone
//! angles are the targets `Θ` (all `2π` for [`Targets::flat`] on genus ≥ 2).
//!
//! **Convention.** The input lengths `ℓ` are read as *hyperbolic* lengths of the same
//! triangulation (any lengths with strict triangle inequalities are: the hyperbolic and
//! Euclidean triangle inequalities are the same inequality). Unlike the Euclidean target
//! the problem is not scale invariant: `2ℓ` is a different hyperbolic metric.
//!
//! **Solver (B87).** The input is first made hyperbolic Delaunay by geometric flips
//! ([`geometric_to_delaunay`], B104), giving `T₀` with binary64 lengths. Newton on `E_hyp`
//! (T33) over Penner cells: at every evaluated `u` the current triangulation is flipped to
//! hyperbolic Delaunay by Ptolemy flips of the base λ-lengths ([`ptolemy_to_delaunay`];
//! flips commute with scaling, B87 step 1), then the gradient `Θ − θ_hyp(u)` and the
//! Hessian from [`face_terms`] (B38: per side `½ cot β[(du_i − du_j)² +
//! tanh²(ℓ̃/2)(du_i + du_j)²]`) are taken on that triangulation. `E_hyp` is strictly convex
//! with no gauge (the `(du_i + du_j)²` terms), so no vertex is grounded. Sparse `LLᵀ` by
//! faer, the symbolic factorization kept while the pattern stays ([`CholeskyCache`]); the
//! line search of [`super::newton_driver`]. The flips from `T₀` are recorded in order
//! ([`HyperbolicUniformization::flips`]) for the certificate (B89). A face that is not a
//! triangle even after flipping makes the line search halve; a solve that cannot get around
//! it stops with [`HyperbolicStop::Degenerate`], never a wrong `u`.
//!
//! **Gauss–Bonnet.** `Σ_i (2π − Θ_i) − Area = 2πχ` with `Area > 0`: the targets must have
//! `Σ_i (2π − Θ_i) > 2πχ` on every component (decided exactly, `Θ_i/π` rational); for
//! `Θ ≡ 2π` this is `χ < 0`, genus ≥ 2.

use super::components::Components;
use super::error::UniformizeError;
use super::hessian::{CholeskyCache, GroundedHessian};
use super::hyperbolic_flips::{geometric_to_delaunay, ptolemy_to_delaunay, FlipFault};
use super::hyperbolic_kernel::{face_terms, log_length};
use super::newton::StepReport;
use super::newton_driver::{drive, DriverStop, Limits, NewtonSystem, Over};
use super::targets::Targets;
use crate::mesh::{Edge, Mesh};
use faer::sparse::{SparseColMat, Triplet};
use rug::Rational;
use std::collections::HashMap;

/// Why a hyperbolic uniformization problem was refused.
#[derive(Debug, thiserror::Error)]
pub enum HyperbolicError {
    /// Input shared with the Euclidean solver (closed, counts, lengths, targets > 0).
    #[error(transparent)]
    Input(#[from] UniformizeError),
    /// Gauss–Bonnet leaves no positive area: `Σ(2π − Θ_i) ≤ 2πχ` on a component.
    #[error(
        "hyperbolic Gauss–Bonnet: on the component of v{root}, Σ(2π − Θ_i) = {sum_over_pi}·π must exceed 2πχ = {}·π (χ = {chi}; with Θ = 2π everywhere: genus ≥ 2)",
        2 * chi
    )]
    NoArea {
        /// The smallest vertex of the component.
        root: u32,
        /// `Σ(2 − Θ_i/π)` exactly.
        sum_over_pi: String,
        /// The Euler characteristic of the component.
        chi: i64,
    },
    /// A face of the input (or of the starting `u`) is not a strict triangle.
    #[error("face f{face} is not a strict hyperbolic triangle at the starting u")]
    NotATriangle {
        /// The face.
        face: u32,
    },
    /// The precision is out of range.
    #[error("precision of {0} bits out of range")]
    Bits(u32),
    /// The geometric flips to hyperbolic Delaunay (B104) or the Ptolemy flips at the
    /// starting `u` stopped short.
    #[error("flipping to hyperbolic Delaunay: {0}")]
    Flips(FlipFault),
    /// A flip sequence does not replay on the triangulation (B89).
    #[error(transparent)]
    Replay(#[from] super::hyperbolic_flips::ReplayError),
}

impl From<FlipFault> for HyperbolicError {
    fn from(f: FlipFault) -> HyperbolicError {
        match f {
            FlipFault::NotATriangle(face) => HyperbolicError::NotATriangle { face },
            other => HyperbolicError::Flips(other),
        }
    }
}

/// Solver options (as [`super::UniformizeOptions`]).
#[derive(Clone, Debug)]
pub struct HyperbolicOptions {
    /// Stop when `max_i |Θ_i − θ_i| ≤ tolerance` (radians).
    pub tolerance: f64,
    /// At most this many Newton steps.
    pub max_iterations: usize,
    /// At most this many halvings of the step in one line search.
    pub max_halvings: usize,
    /// A starting `u` (default 0).
    pub start: Option<Vec<f64>>,
}

impl Default for HyperbolicOptions {
    fn default() -> Self {
        HyperbolicOptions {
            tolerance: 1e-10,
            max_iterations: 100,
            max_halvings: 40,
            start: None,
        }
    }
}

/// Why the hyperbolic solver stopped.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub enum HyperbolicStop {
    /// `max |Θ − θ| ≤ tolerance`.
    Converged,
    /// The iteration cap was reached first.
    IterationCap,
    /// The line search found no acceptable step and met a degenerate configuration even
    /// after flipping to Delaunay (a face not a triangle, an unflippable or non-convex
    /// edge, the flip cap), with the reason.
    Degenerate(String),
    /// No acceptable step for another reason (Hessian not factored, no decrease).
    DegenerateStep(String),
}

/// The result of [`uniformize_hyperbolic`]; `u` is a solution only when
/// [`HyperbolicUniformization::converged`].
#[derive(Clone, Debug)]
pub struct HyperbolicUniformization {
    /// The final triangulation `T_k` (hyperbolic Delaunay at `u`).
    pub mesh: Mesh,
    /// `T₀`: the input made hyperbolic Delaunay by geometric flips (B104).
    pub t0: Mesh,
    /// The binary64 hyperbolic lengths `ℓ` of `T₀` (the input's where no geometric flip
    /// touched the edge).
    pub lengths: Vec<f64>,
    /// The geometric flips from the input to `T₀`, in order (B104).
    pub input_flips: Vec<Edge>,
    /// The Ptolemy flips from `T₀` to `T_k`, in order (B87; replayed by the certificate).
    pub flips: Vec<Edge>,
    /// The base logarithmic lengths `2 log sinh(ℓ/2)` of `T_k` at `u = 0` (binary64).
    pub base_log: Vec<f64>,
    /// The log scale factors.
    pub u: Vec<f64>,
    /// The targets.
    pub targets: Targets,
    /// Accepted steps (with their Ptolemy flip counts).
    pub steps: Vec<StepReport>,
    /// Why the solver stopped.
    pub stop: HyperbolicStop,
    /// `max_i |Θ_i − θ_i(u)|` at the returned `u` (`f64`).
    pub residual_max: f64,
    /// Symbolic and numeric factorizations computed.
    pub factorizations: (usize, usize),
}

impl HyperbolicUniformization {
    /// Whether the residual reached the tolerance.
    pub fn converged(&self) -> bool {
        self.stop == HyperbolicStop::Converged
    }

    /// The scaled hyperbolic lengths `ℓ̃` of `T_k` at `u` (binary64).
    pub fn scaled_lengths(&self) -> Vec<f64> {
        scaled_base_log(&self.mesh, &self.base_log, &self.u)
            .into_iter()
            .map(super::hyperbolic_kernel::length_from_log)
            .collect()
    }
}

/// `λ̃_ij = 2 log sinh(ℓ_ij/2) + u_i + u_j` (binary64).
pub fn scaled_log_lengths(mesh: &Mesh, lengths: &[f64], u: &[f64]) -> Vec<f64> {
    let base: Vec<f64> = lengths.iter().map(|&l| log_length(l)).collect();
    scaled_base_log(mesh, &base, u)
}

/// `λ̃_ij = x_ij + u_i + u_j` from base logarithmic lengths `x` (binary64).
pub fn scaled_base_log(mesh: &Mesh, base: &[f64], u: &[f64]) -> Vec<f64> {
    mesh.edges()
        .map(|e| {
            let h = e.halfedge();
            base[e.idx()] + u[mesh.tail(h).idx()] + u[mesh.tip(h).idx()]
        })
        .collect()
}

/// Check the input: a closed surface with one positive finite length per edge, one positive
/// target per vertex, and `Σ(2π − Θ_i) > 2πχ` on every component (exact).
pub fn validate_hyperbolic(
    mesh: &Mesh,
    lengths: &[f64],
    targets: &Targets,
) -> Result<(), HyperbolicError> {
    if mesh.n_faces() == 0 {
        return Err(UniformizeError::Empty.into());
    }
    if !mesh.is_closed() {
        return Err(UniformizeError::NotClosed {
            edges: mesh.n_boundary_edges(),
        }
        .into());
    }
    if lengths.len() != mesh.n_edges() {
        return Err(UniformizeError::LengthCount {
            expected: mesh.n_edges(),
            got: lengths.len(),
        }
        .into());
    }
    if let Some(e) = lengths.iter().position(|x| !(x.is_finite() && *x > 0.0)) {
        return Err(UniformizeError::BadLength {
            edge: e as u32,
            value: lengths[e],
        }
        .into());
    }
    validate_hyperbolic_targets(mesh, targets)?;
    hyperbolic_gauss_bonnet(mesh, targets)
}

/// One target per vertex of `mesh`, each `Θ_i > 0` (bad input otherwise).
pub fn validate_hyperbolic_targets(mesh: &Mesh, targets: &Targets) -> Result<(), HyperbolicError> {
    if targets.len() != mesh.n_vertices() {
        return Err(UniformizeError::TargetCount {
            expected: mesh.n_vertices(),
            got: targets.len(),
        }
        .into());
    }
    for (v, q) in targets.over_pi().iter().enumerate() {
        if *q <= 0 {
            return Err(UniformizeError::NonPositiveTarget {
                vertex: v as u32,
                over_pi: q.to_string(),
            }
            .into());
        }
    }
    Ok(())
}

/// Hyperbolic Gauss–Bonnet leaves a positive area: `Σ_{i∈C}(2π − Θ_i) > 2πχ(C)` on every
/// component `C`, decided exactly on `Θ_i/π` (B38). When it fails no hyperbolic cone metric
/// on `mesh` has the angles `Θ` ([`HyperbolicError::NoArea`]): the area `Σ_t(π − Σα)` of
/// strict hyperbolic triangles is positive. `targets` must have one entry per vertex.
pub fn hyperbolic_gauss_bonnet(mesh: &Mesh, targets: &Targets) -> Result<(), HyperbolicError> {
    let comps = Components::of(mesh);
    for (c, &root) in comps.roots.iter().enumerate() {
        let mut sum = Rational::new();
        for v in comps.vertices_of(c) {
            sum += Rational::from(2) - &targets.over_pi()[v];
        }
        let chi = comps.euler_characteristic(mesh, c);
        if sum <= 2 * chi {
            return Err(HyperbolicError::NoArea {
                root: root as u32,
                sum_over_pi: sum.to_string(),
                chi,
            });
        }
    }
    Ok(())
}

/// The Hessian's lower-triangle pattern on a fixed triangulation: per half-edge the
/// positions of its `H_ii`, `H_jj`, `H_ij` entries (a loop: `H_ii` only).
struct Assembly {
    n: usize,
    pairs: Vec<(usize, usize)>,
    slots: Vec<Slot>,
}

#[derive(Clone, Copy)]
enum Slot {
    Loop(usize),
    Side { ii: usize, jj: usize, ij: usize },
}

impl Assembly {
    fn new(mesh: &Mesh) -> Assembly {
        let mut index: HashMap<(usize, usize), usize> = HashMap::new();
        let mut pairs = Vec::new();
        let mut at = |r: usize, c: usize| -> usize {
            let key = (r.max(c), r.min(c));
            *index.entry(key).or_insert_with(|| {
                pairs.push(key);
                pairs.len() - 1
            })
        };
        let slots = mesh
            .halfedges()
            .map(|h| {
                let (i, j) = (mesh.tail(h).idx(), mesh.tip(h).idx());
                if i == j {
                    Slot::Loop(at(i, i))
                } else {
                    Slot::Side {
                        ii: at(i, i),
                        jj: at(j, j),
                        ij: at(i, j),
                    }
                }
            })
            .collect();
        Assembly {
            n: mesh.n_vertices(),
            pairs,
            slots,
        }
    }

    /// The Hessian's values (order of `pairs`) from `½ cot β` and `t²` per half-edge (B38).
    fn values(&self, weight: &[f64], t2: &[f64]) -> Vec<f64> {
        let mut val = vec![0.0; self.pairs.len()];
        for ((s, &w), &t) in self.slots.iter().zip(weight).zip(t2) {
            match *s {
                Slot::Loop(ii) => val[ii] += 4.0 * w * t,
                Slot::Side { ii, jj, ij } => {
                    val[ii] += w * (1.0 + t);
                    val[jj] += w * (1.0 + t);
                    val[ij] += w * (t - 1.0);
                }
            }
        }
        val
    }

    /// The Hessian from `½ cot β` and `t²` per half-edge (B38), lower triangle.
    fn matrix(&self, weight: &[f64], t2: &[f64]) -> Option<GroundedHessian> {
        let val = self.values(weight, t2);
        let trip: Vec<Triplet<usize, usize, f64>> = self
            .pairs
            .iter()
            .zip(&val)
            .map(|(&(r, c), &v)| Triplet::new(r, c, v))
            .collect();
        let matrix = SparseColMat::try_new_from_triplets(self.n, self.n, &trip).ok()?;
        Some(GroundedHessian { matrix })
    }
}

/// The hyperbolic angle sums and Hessian terms at one `u`, on the triangulation
/// flipped to Delaunay there.
struct Evaluation {
    /// The triangulation at this `u`.
    mesh: Mesh,
    /// Its base logarithmic lengths.
    base: Vec<f64>,
    /// The Ptolemy flips from `T₀`.
    flips: Vec<Edge>,
    /// The flips made for this evaluation.
    new_flips: usize,
    grad: Vec<f64>,
    /// `½ cot β` of the side of each half-edge in its face.
    weight: Vec<f64>,
    /// `tanh²(ℓ̃/2)` of the edge of each half-edge.
    t2: Vec<f64>,
}

/// The angle sums and Hessian terms at `u` on a fixed triangulation.
struct Terms {
    grad: Vec<f64>,
    weight: Vec<f64>,
    t2: Vec<f64>,
}

/// Evaluate at `u`; `Err(face)` when a face is not a strict triangle (or a term overflows).
fn evaluate(mesh: &Mesh, lambda0: &[f64], u: &[f64], theta: &[f64]) -> Result<Terms, u32> {
    let mut sum = vec![0.0; mesh.n_vertices()];
    let mut weight = vec![0.0; mesh.n_halfedges()];
    let mut t2 = vec![0.0; mesh.n_halfedges()];
    for f in mesh.faces() {
        let hs = mesh.face_halfedges(f);
        let lam =
            hs.map(|h| lambda0[h.edge().idx()] + u[mesh.tail(h).idx()] + u[mesh.tip(h).idx()]);
        let terms = face_terms(lam).ok_or(f.0)?;
        for m in 0..3 {
            sum[mesh.tail(hs[(m + 2) % 3]).idx()] += terms.angles[m];
            weight[hs[m].idx()] = terms.weight[m];
            t2[hs[m].idx()] = terms.t2[m];
        }
    }
    let grad = theta.iter().zip(&sum).map(|(t, s)| t - s).collect();
    Ok(Terms { grad, weight, t2 })
}

/// Flip `(mesh, base, flips)` to Delaunay at `u` (Ptolemy, B87) and evaluate there.
fn evaluate_flipped(
    mut mesh: Mesh,
    mut base: Vec<f64>,
    mut flips: Vec<Edge>,
    u: &[f64],
    theta: &[f64],
) -> Result<Evaluation, FlipFault> {
    let new_flips = ptolemy_to_delaunay(&mut mesh, &mut base, u, &mut flips)?;
    let t = evaluate(&mesh, &base, u, theta).map_err(FlipFault::NotATriangle)?;
    Ok(Evaluation {
        mesh,
        base,
        flips,
        new_flips,
        grad: t.grad,
        weight: t.weight,
        t2: t.t2,
    })
}

/// Solve `θ_hyp(u) = Θ` for the hyperbolic metric `lengths` on `mesh` with flips (module
/// doc: convention, geometric flips of the input, Newton over Penner cells with Ptolemy
/// flips, line search). Bad input is a typed error; a solve that does not reach
/// `opts.tolerance` returns `Ok` with the reason ([`HyperbolicStop`]), never a panic.
/// proof: B38, B87, B104
pub fn uniformize_hyperbolic(
    mesh: &Mesh,
    lengths: &[f64],
    targets: &Targets,
    opts: &HyperbolicOptions,
) -> Result<HyperbolicUniformization, HyperbolicError> {
    validate_hyperbolic(mesh, lengths, targets)?;
    let u = match &opts.start {
        None => vec![0.0; mesh.n_vertices()],
        Some(s) if s.len() != mesh.n_vertices() => {
            return Err(UniformizeError::TargetCount {
                expected: mesh.n_vertices(),
                got: s.len(),
            }
            .into())
        }
        Some(s) => {
            if let Some(v) = s.iter().position(|x| !x.is_finite()) {
                return Err(UniformizeError::BadStart {
                    vertex: v as u32,
                    value: s[v],
                }
                .into());
            }
            s.clone()
        }
    };
    let (t0, l0, input_flips) = geometric_to_delaunay(mesh, lengths)?;
    let lambda0: Vec<f64> = l0.iter().map(|&l| log_length(l)).collect();
    let theta = targets.radians_f64();
    let ev = evaluate_flipped(t0.clone(), lambda0, Vec::new(), &u, &theta)?;
    let mut sys = Hyperbolic {
        theta: &theta,
        assembly: Assembly::new(&ev.mesh),
        cache: CholeskyCache::default(),
    };
    let limits = Limits {
        tolerance: opts.tolerance,
        max_iterations: opts.max_iterations,
        max_halvings: opts.max_halvings,
        stall_window: None,
    };
    let run = drive(&mut sys, Over::ALL, u, ev, limits, &mut |_| {});
    let residual_max = Over::ALL.max_abs(&run.eval.grad);
    let stop = match run.stop {
        DriverStop::Converged => HyperbolicStop::Converged,
        DriverStop::IterationCap => HyperbolicStop::IterationCap,
        DriverStop::Factor(reason) => HyperbolicStop::DegenerateStep(reason),
        DriverStop::LineSearch(Some(fault)) => HyperbolicStop::Degenerate(fault.to_string()),
        DriverStop::LineSearch(None) => HyperbolicStop::DegenerateStep(format!(
            "line search: no decrease of |∇E| after {} halvings at max residual {residual_max:e}",
            opts.max_halvings,
        )),
        DriverStop::Stalled(window) => HyperbolicStop::DegenerateStep(format!(
            "line search stalled over {window} steps at max residual {residual_max:e}"
        )),
    };
    Ok(HyperbolicUniformization {
        mesh: run.eval.mesh,
        t0,
        lengths: l0,
        input_flips,
        flips: run.eval.flips,
        base_log: run.eval.base,
        u: run.u,
        targets: targets.clone(),
        steps: run.steps,
        stop,
        residual_max,
        factorizations: (sys.cache.symbolic_count, sys.cache.numeric_count),
    })
}

/// The hyperbolic Newton system for [`drive`]: each evaluation flips to Delaunay at its
/// `u` (B87), the Hessian of B38 is assembled on the current triangulation's pattern and
/// factored (symbolic factorization kept while the pattern stays); an evaluation fault is
/// a degenerate configuration ([`FlipFault`]).
struct Hyperbolic<'a> {
    theta: &'a [f64],
    assembly: Assembly,
    cache: CholeskyCache,
}

impl NewtonSystem for Hyperbolic<'_> {
    type Eval = Evaluation;
    type Fault = FlipFault;

    fn gradient(ev: &Evaluation) -> &[f64] {
        &ev.grad
    }

    fn evaluate(&mut self, at: &Evaluation, u: &[f64]) -> Result<Evaluation, FlipFault> {
        evaluate_flipped(
            at.mesh.clone(),
            at.base.clone(),
            at.flips.clone(),
            u,
            self.theta,
        )
    }

    fn direction(&mut self, ev: &Evaluation) -> Result<Vec<f64>, String> {
        let factor = self
            .assembly
            .matrix(&ev.weight, &ev.t2)
            .and_then(|h| self.cache.factor(&h))
            .ok_or("the hyperbolic Hessian is not numerically positive definite")?;
        let minus_g: Vec<f64> = ev.grad.iter().map(|g| -g).collect();
        Ok(factor.solve(&minus_g))
    }

    fn accept(&mut self, new: &Evaluation) -> usize {
        if new.new_flips > 0 {
            self.assembly = Assembly::new(&new.mesh);
        }
        new.new_flips
    }
}

/// The binary64 Hessian of `E_hyp` at `u` as a dense matrix (B38; for tests and small
/// surfaces); `None` when a face is not a strict triangle.
pub fn hessian_dense(mesh: &Mesh, lengths: &[f64], u: &[f64]) -> Option<Vec<Vec<f64>>> {
    let lambda0: Vec<f64> = lengths.iter().map(|&l| log_length(l)).collect();
    let zero = vec![0.0; mesh.n_vertices()];
    let ev = evaluate(mesh, &lambda0, u, &zero).ok()?;
    let n = mesh.n_vertices();
    let mut h = vec![vec![0.0; n]; n];
    for (hh, (&w, &t)) in mesh.halfedges().zip(ev.weight.iter().zip(&ev.t2)) {
        let (i, j) = (mesh.tail(hh).idx(), mesh.tip(hh).idx());
        if i == j {
            h[i][i] += 4.0 * w * t;
        } else {
            h[i][i] += w * (1.0 + t);
            h[j][j] += w * (1.0 + t);
            h[i][j] += w * (t - 1.0);
            h[j][i] += w * (t - 1.0);
        }
    }
    Some(h)
}

/// The binary64 Hessian of `E_hyp` at `u`, factored (sparse `LLᵀ`); `None` when a face
/// is not a strict triangle or the matrix is not numerically positive definite. proof: B38
pub fn hessian_factor(mesh: &Mesh, lengths: &[f64], u: &[f64]) -> Option<super::hessian::Factor> {
    let lambda0: Vec<f64> = lengths.iter().map(|&l| log_length(l)).collect();
    hessian_factor_log(mesh, &lambda0, u)
}

/// [`hessian_factor`] from the base logarithmic lengths `2 log sinh(ℓ/2)` of `mesh`.
pub fn hessian_factor_log(
    mesh: &Mesh,
    lambda0: &[f64],
    u: &[f64],
) -> Option<super::hessian::Factor> {
    let zero = vec![0.0; mesh.n_vertices()];
    let ev = evaluate(mesh, lambda0, u, &zero).ok()?;
    let h = Assembly::new(mesh).matrix(&ev.weight, &ev.t2)?;
    CholeskyCache::default().factor(&h)
}

/// Gershgorin's bound `min_i (H_ii − Σ_{j≠i} |H_ij|)` of the binary64 Hessian at `u`
/// (an estimate, rounded to nearest); `None` when a face is not a strict triangle.
pub fn gershgorin_estimate(mesh: &Mesh, lengths: &[f64], u: &[f64]) -> Option<f64> {
    let lambda0: Vec<f64> = lengths.iter().map(|&l| log_length(l)).collect();
    gershgorin_estimate_log(mesh, &lambda0, u)
}

/// [`gershgorin_estimate`] from the base logarithmic lengths of `mesh`.
pub fn gershgorin_estimate_log(mesh: &Mesh, lambda0: &[f64], u: &[f64]) -> Option<f64> {
    let zero = vec![0.0; mesh.n_vertices()];
    let ev = evaluate(mesh, lambda0, u, &zero).ok()?;
    let a = Assembly::new(mesh);
    let mut row = vec![0.0; a.n];
    for (&(r, c), v) in a.pairs.iter().zip(a.values(&ev.weight, &ev.t2)) {
        if r == c {
            row[r] += v;
        } else {
            row[r] -= v.abs();
            row[c] -= v.abs();
        }
    }
    Some(row.into_iter().fold(f64::INFINITY, f64::min))
}
