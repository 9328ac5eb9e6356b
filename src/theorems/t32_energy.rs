//! T32 — the discrete-uniformization energy (notes §1.6.4, Eq. 16; docs/catalogue.md §7; SSP08,
//! Springborn 2020): `∇E = Θ − θ(u)`, Hessian = the cotan Laplacian, `E` convex, and on
//! the variable triangulation C² across Penner cells (at a cocircular tie, `E`, `∇E` and
//! the Hessian agree on both triangulations).
//!
//! API:
//! - `pub fn check_energy<T: Real>(input: &EnergyInput<'_, T>, directions: &[Vec<T>], settings: &Settings) -> Verdict`
//! - `pub fn verify_gradient<T: Real>(input: &EnergyInput<'_, T>, gradient: &[T], directions: &[Vec<T>], settings: &Settings) -> Verdict`
//! - `pub fn verify_hessian<T: Real>(input: &EnergyInput<'_, T>, hessian: &SparseMatrix<T>, directions: &[Vec<T>], settings: &Settings) -> Verdict`
//! - `pub fn check_convexity<T: Real>(input: &EnergyInput<'_, T>, directions: &[Vec<T>], settings: &Settings) -> Verdict`
//! - `pub fn verify_convexity<T: Real>(input: &EnergyInput<'_, T>, directions: &[Vec<T>], hessian: &dyn Fn(&Mesh, &[T]) -> SparseMatrix<T>, settings: &Settings) -> Verdict`
//! - `pub fn verify_one_pass<T: Real>(input: &EnergyInput<'_, T>, one_pass: &EnergyParts<T>, settings: &Settings) -> Verdict`
//! - `pub trait OnePass: Real` (the one-pass kernel of a backend: `f64`, MPFR; none for `Dd`)
//! - `pub fn check_tie<T: Real>(a: &EnergyInput<'_, T>, b: &EnergyInput<'_, T>, settings: &Settings) -> Verdict`

use super::bounds::{cot_error, eps, eps_shift, sum_error, SAFETY};
use super::energy_bounds::{
    face_angle_error, face_energy_error, one_pass_face_bound, schlafli_error, slack_condition,
};
use super::report::{check_lengths, lengths_out_of_range, Tally};
use super::t32_difference::{derivative_enclosure, distance_outside, support, touched_faces};
use super::verdict::{Settings, Verdict, Witness};
use crate::geometry::laplacian::SparseMatrix;
use crate::mesh::{Face, HalfEdge, Mesh};
use crate::predicates::tolerance::sign_beyond;
use crate::scalar::{Dd, Dual, Mpfr, Real, Sign};
use crate::variational::energy::{
    energy_gradient_hessian_with, face_energy_sum, gradient, hessian, hessian_at, log_lengths,
    scaled_log_lengths, EnergyParts,
};
use crate::variational::fast_f64::energy_gradient_hessian_f64;
use crate::variational::fast_mpfr::energy_gradient_hessian_mpfr;
use crate::variational::pattern::HessianPattern;
use crate::variational::triangle::{angles_from_log_lengths, shape, shifted_lengths, Shape};
use std::collections::HashMap;

/// The data of `E` on a fixed triangulation: the mesh, its lengths `ℓ` (`λ = 2 log ℓ`),
/// the log scale factors `u` and the target angles `Θ`.
#[derive(Clone, Copy, Debug)]
pub struct EnergyInput<'a, T> {
    /// The triangulation.
    pub mesh: &'a Mesh,
    /// One length per edge.
    pub lengths: &'a [T],
    /// One log scale factor per vertex.
    pub u: &'a [T],
    /// One target cone angle per vertex.
    pub targets: &'a [T],
}

impl<T: Real> EnergyInput<'_, T> {
    /// `NotApplicable` on malformed input, `Undecided` on lengths outside B40's range.
    fn validate(&self) -> Option<Verdict> {
        let n = self.mesh.n_vertices();
        check_lengths(self.mesh, self.lengths)
            .or_else(|| lengths_out_of_range(self.lengths))
            .or_else(|| {
                (self.u.len() != n || self.targets.len() != n).then(|| Verdict::NotApplicable {
                    reason: format!(
                        "{} scale factors and {} targets for {n} vertices",
                        self.u.len(),
                        self.targets.len()
                    ),
                })
            })
    }

    fn lambda(&self) -> Vec<T> {
        log_lengths(self.lengths)
    }
}

/// Per face: half-edges, scaled log lengths, shifted sides and angles (f64 approximations).
struct FaceData {
    hs: [HalfEdge; 3],
    x: [f64; 3],
    l: [f64; 3],
    alpha: [f64; 3],
    /// Whether the face is a proper triangle (else degenerate or undecided: its angles
    /// are the constants `(π, 0, 0)` of the extension, or invalid enclosures).
    proper: bool,
}

fn face_data<T: Real>(mesh: &Mesh, f: Face, lt: &[T]) -> FaceData {
    let hs = mesh.face_halfedges(f);
    let x = hs.map(|h| lt[h.edge().idx()].clone());
    let a = angles_from_log_lengths(&x);
    let sl = shifted_lengths(&x);
    FaceData {
        hs,
        x: x.clone().map(|v| v.approx_f64()),
        proper: shape(&sl) == Shape::Proper,
        l: sl.map(|v| v.approx_f64()),
        alpha: a.map(|v| v.approx_f64()),
    }
}

fn dual_u<T: Real>(u: &[T], d: &[T]) -> Vec<Dual<T>> {
    u.iter()
        .zip(d)
        .map(|(a, b)| Dual::new(a.clone(), b.clone()))
        .collect()
}

fn constants<T: Real>(v: &[T]) -> Vec<Dual<T>> {
    v.iter().cloned().map(Dual::constant).collect()
}

/// The verdict of several parts: any failure fails (listing every witness), else any
/// undecided part is undecided, else any not-applicable part, else holds.
fn combine(parts: Vec<Verdict>) -> Verdict {
    let mut fails: Vec<Witness> = Vec::new();
    let mut open: Vec<Witness> = Vec::new();
    let (mut certified, mut max_error, mut bits) = (true, 0.0_f64, 0);
    let mut na: Option<String> = None;
    for v in parts {
        match v {
            Verdict::Holds {
                certified: c,
                max_error: m,
            } => {
                certified &= c;
                max_error = max_error.max(m);
            }
            Verdict::Fails {
                certified: c,
                witnesses,
            } => {
                certified &= c;
                fails.extend(witnesses);
            }
            Verdict::Undecided {
                bits_tried,
                witnesses,
            } => {
                bits = bits.max(bits_tried);
                open.extend(witnesses);
            }
            Verdict::NotApplicable { reason } => na = Some(reason),
        }
    }
    if !fails.is_empty() {
        fails.extend(open);
        Verdict::Fails {
            certified,
            witnesses: fails,
        }
    } else if !open.is_empty() {
        Verdict::Undecided {
            bits_tried: bits,
            witnesses: open,
        }
    } else if let Some(reason) = na {
        Verdict::NotApplicable { reason }
    } else {
        Verdict::Holds {
            certified,
            max_error,
        }
    }
}

/// T32 on one input: [`verify_gradient`] against `Θ − θ`, [`verify_hessian`] against the
/// assembled cotan Laplacian, [`check_convexity`] along every direction, and, where the
/// backend has a one-pass kernel ([`OnePass`]: `f64` and MPFR, not `Dd`),
/// [`verify_one_pass`]: `E`, `∇E` and the Hessian by that second formula against the
/// generic evaluation.
pub fn check_energy<T: OnePass>(
    input: &EnergyInput<'_, T>,
    directions: &[Vec<T>],
    settings: &Settings,
) -> Verdict {
    if let Some(v) = input.validate() {
        return v;
    }
    let lambda = input.lambda();
    let g = gradient(input.mesh, &lambda, input.u, input.targets);
    let h = hessian(input.mesh, &lambda, input.u);
    let mut parts = vec![
        verify_gradient(input, &g, directions, settings),
        verify_hessian(input, &h, directions, settings),
        check_convexity(input, directions, settings),
    ];
    let lt = scaled_log_lengths(input.mesh, &lambda, input.u);
    let pattern = HessianPattern::new(input.mesh);
    if let Some(p) = T::one_pass(&pattern, input.mesh, &lt, input.u, input.targets) {
        parts.push(verify_one_pass(input, &p, settings));
    }
    combine(parts)
}

/// A backend's one-pass evaluation of `E`, `∇E` and the Hessian (half-angle `atan`, the
/// face term rewritten about the longest side, cotangents from Heron's `r`; proofs/B88),
/// a second formula beside the generic one of `variational::energy`.
pub trait OnePass: Real {
    /// `E`, `∇E = Θ − θ` and the Hessian at the scaled logarithmic lengths `lt`, `u` and
    /// the targets, by the backend's one-pass kernel; `None` where the backend has none.
    fn one_pass(
        pattern: &HessianPattern,
        mesh: &Mesh,
        lt: &[Self],
        u: &[Self],
        targets: &[Self],
    ) -> Option<EnergyParts<Self>>;
}

/// `variational::fast_f64` (proofs/B88).
impl OnePass for f64 {
    fn one_pass(
        pattern: &HessianPattern,
        mesh: &Mesh,
        lt: &[f64],
        u: &[f64],
        targets: &[f64],
    ) -> Option<EnergyParts<f64>> {
        Some(energy_gradient_hessian_f64(pattern, mesh, lt, u, targets))
    }
}

/// `variational::fast_mpfr` (proofs/B29, B100, B101).
impl OnePass for Mpfr {
    fn one_pass(
        pattern: &HessianPattern,
        mesh: &Mesh,
        lt: &[Mpfr],
        u: &[Mpfr],
        targets: &[Mpfr],
    ) -> Option<EnergyParts<Mpfr>> {
        Some(energy_gradient_hessian_mpfr(pattern, mesh, lt, u, targets))
    }
}

/// Double-double has no one-pass kernel: T32 at `Dd` runs without that component.
impl OnePass for Dd {
    fn one_pass(
        _: &HessianPattern,
        _: &Mesh,
        _: &[Dd],
        _: &[Dd],
        _: &[Dd],
    ) -> Option<EnergyParts<Dd>> {
        None
    }
}

/// The smallest slack `e_m = ℓ_{m+1} + ℓ_{m+2} − ℓ_m` relative to the perimeter, from the
/// `f64` shifted sides, below which a face the generic path calls degenerate is not
/// compared: the one-pass kernel decides the shape on its own computed slacks, which may
/// disagree there (proofs/B88, Limits).
const SHAPE_MARGIN: f64 = 1e-9;

/// `E`, `∇E` and the Hessian of a one-pass kernel (`one_pass`, as [`OnePass`] gives it)
/// against the generic evaluation at the same precision
/// ([`energy_gradient_hessian_with`]): each difference must lie within the one-pass
/// kernel's bound (proofs/B88 items 1–5, read with `u = 2⁻ᵖ` at MPFR by B29, `Л` by B100,
/// the table `atan` by B101; times B88's safety factor 2) plus the generic evaluation's own
/// bound (proofs/B57: B40 per angle, B44 per cotangent, B57 per face term, B41 for the
/// sums, as [`check_tie`] uses them). Witnesses `one-pass:E`, `one-pass:v{i}` and
/// `one-pass:H[{i},{j}]`. Numerical: a first-order bound. A face the generic path calls
/// degenerate with a slack within `10⁻⁹` of 0 leaves its vertices and entries undecided.
pub fn verify_one_pass<T: Real>(
    input: &EnergyInput<'_, T>,
    one_pass: &EnergyParts<T>,
    settings: &Settings,
) -> Verdict {
    if let Some(v) = input.validate() {
        return v;
    }
    let mesh = input.mesh;
    let n = mesh.n_vertices();
    if one_pass.gradient.len() != n || one_pass.hessian.dim() != n {
        return Verdict::NotApplicable {
            reason: format!("one-pass gradient and Hessian need dimension {n}"),
        };
    }
    let ctx = input.lengths[0].ctx();
    let (e, bits) = (eps::<T>(ctx), T::precision_bits(ctx));
    // The unit roundoff scaled as ε (bounds linear in it, proofs/B40 "Range").
    let unit = e / 16.0;
    let lambda = input.lambda();
    let lt = scaled_log_lengths(mesh, &lambda, input.u);
    let generic = energy_gradient_hessian_with(
        &HessianPattern::new(mesh),
        mesh,
        &lt,
        input.u,
        input.targets,
    );
    let OnePassBounds {
        e_fast,
        e_gen,
        e_size,
        th,
        hb,
    } = one_pass_bounds(mesh, &lt, unit, e, bits);
    let mut tally = Tally::new(false, bits);
    if let (Some(a), Some(g)) = (&one_pass.energy, &generic.energy) {
        // Σ_faces + Σ Θ_i u_i, recursive summation on both sides (B88 item 5, B41).
        let tu: Vec<f64> = input
            .targets
            .iter()
            .zip(input.u)
            .map(|(t, x)| t.approx_f64() * x.approx_f64())
            .collect();
        let tu_abs: f64 = tu.iter().copied().map(f64::abs).sum();
        let terms = (mesh.n_faces() + n) as f64;
        let fast = e_fast + terms * unit * (e_size + tu_abs) + unit * tu_abs;
        let generic_b = e_gen + SAFETY * terms * e * (e_size + tu_abs);
        let tol = settings.slack * (SAFETY * fast + generic_b);
        tally.within("one-pass:E", "E one-pass − generic", &(a.clone() - g), tol);
    }
    for (i, (a, g)) in one_pass.gradient.iter().zip(&generic.gradient).enumerate() {
        let (fast, generic_b, theta, c) = th[i];
        let gi = g.approx_f64().abs();
        let fast = fast + c * unit * theta + unit * gi;
        let generic_b = generic_b + SAFETY * c * e * theta + e * gi;
        let tol = settings.slack * (SAFETY * fast + generic_b);
        tally.within(
            format!("one-pass:v{i}"),
            "∇E one-pass − generic",
            &(a.clone() - g),
            tol,
        );
    }
    let zero = input.lengths[0].zero_like();
    let entry = |i: usize, j: usize, a: &T, g: &T, tally: &mut Tally| {
        let (fast, generic_b, abs, c) = hb.get(&(i, j)).copied().unwrap_or_default();
        let tol =
            settings.slack * (SAFETY * (fast + c * unit * abs) + generic_b + SAFETY * c * e * abs);
        tally.within(
            format!("one-pass:H[{i},{j}]"),
            "Hessian entry one-pass − generic",
            &(a.clone() - g),
            tol,
        );
    };
    for i in 0..n {
        for (j, a) in one_pass.hessian.row(i) {
            let g = generic.hessian.get(i, j).unwrap_or(&zero);
            entry(i, j, a, g, &mut tally);
        }
        // Entries the generic evaluation stores and the one-pass result does not.
        for (j, g) in generic.hessian.row(i) {
            if one_pass.hessian.get(i, j).is_none() {
                entry(i, j, &zero, g, &mut tally);
            }
        }
    }
    tally.verdict()
}

/// `∇E = g` against claimed `g` (one per vertex), along each direction `d`:
/// (1) the dual-number derivative `D_d E` equals `g·d` within proofs/B57 (B56 per face plus
/// the angle errors of `Θ − θ`, B40, and the sums, B41); (2) `g·d` lies in the enclosure
/// of `E′(u)·d` made of the central difference `(E(u+hd) − E(u−hd))/2h` on
/// `Interval<Mpfr>` at twice the working precision (`h = 2^{−⌈p/2⌉}`) widened by the
/// rigorous truncation bound `(h²/6) max|E‴|` over the segment (proofs/B57), up to the
/// angle part of B57 and the sums (the error of the claimed `g·d` itself). Witnesses
/// `d{k}`, `fd{k}`; a face not certified proper near `u` makes `fd{k}` undecided.
pub fn verify_gradient<T: Real>(
    input: &EnergyInput<'_, T>,
    claimed: &[T],
    directions: &[Vec<T>],
    settings: &Settings,
) -> Verdict {
    if let Some(v) = input.validate() {
        return v;
    }
    let mesh = input.mesh;
    let n = mesh.n_vertices();
    if claimed.len() != n || directions.iter().any(|d| d.len() != n) {
        return Verdict::NotApplicable {
            reason: format!("gradient and directions need {n} entries (one per vertex)"),
        };
    }
    let ctx = input.lengths[0].ctx();
    let (e, bits) = (eps::<T>(ctx), T::precision_bits(ctx));
    let lambda = input.lambda();
    let lt = scaled_log_lengths(mesh, &lambda, input.u);
    let lam_d = constants(&lambda);
    let mut tally = Tally::new(false, bits);
    for (k, d) in directions.iter().enumerate() {
        let df: Vec<f64> = d.iter().map(Real::approx_f64).collect();
        // Only the faces touching the support of d move (proofs/B32): the others add
        // exactly 0 to D_d E and to every sum of the bound below.
        let moving = support(d);
        let touched = touched_faces(mesh, &moving);
        let ud = dual_u(input.u, d);
        let ltd = scaled_log_lengths(mesh, &lam_d, &ud);
        // D_d E = Σ_touched D_d F_f + Σ_{d_i ≠ 0} Θ_i d_i.
        let mut ed = face_energy_sum(mesh, touched.iter().copied(), &ltd, &ud[0]);
        for ((t, ui), &m) in input.targets.iter().zip(&ud).zip(&moving) {
            if m {
                ed += &(Dual::constant(t.clone()) * ui);
            }
        }
        let gd = claimed
            .iter()
            .zip(d)
            .fold(d[0].zero_like(), |s, (g, x)| s + &(g.clone() * x));
        // Angle part of the bound: Σ_f Σ_m Δα_m Σ_{v∈f} |d_v|, plus π's rounding.
        let mut angle_part = 0.0;
        let mut schlafli_part = 0.0;
        let mut terms: Vec<f64> = Vec::new();
        for fd in touched.iter().map(|&f| face_data(mesh, f, &lt)) {
            let vs = fd.hs.map(|h| mesh.tail(h).idx());
            let dsum: f64 = vs.iter().map(|&v| df[v].abs()).sum();
            let xd = fd.hs.map(|h| ltd[h.edge().idx()].clone());
            if !fd.proper {
                // Degenerate: f = ½πx_m exactly, angles the constants (π, 0, 0).
                angle_part += 3.0 * e * std::f64::consts::PI * dsum;
                schlafli_part += SAFETY * 2.0 * e * std::f64::consts::PI * 2.0 * dsum;
                continue;
            }
            let da = face_angle_error(fd.l, e);
            angle_part += (da.iter().sum::<f64>() + 3.0 * e * std::f64::consts::PI) * dsum;
            let a = angles_from_log_lengths(&xd);
            let ad = [0, 1, 2].map(|m| a[m].d.approx_f64());
            let xdot = [0, 1, 2].map(|m| xd[m].d.approx_f64());
            schlafli_part += 2.0 * schlafli_error(fd.x, xdot, fd.l, fd.alpha, ad, bits, e);
            terms.extend((0..3).map(|m| fd.alpha[m] * xdot[m]));
        }
        terms.extend(claimed.iter().zip(&df).map(|(g, x)| g.approx_f64() * x));
        let sums = sum_error(terms.iter().copied(), e);
        let tol = settings.slack * (angle_part + schlafli_part + 2.0 * sums);
        tally.within(format!("d{k}"), "D_d E − (Θ−θ)·d", &(ed.d - &gd), tol);
        // (2) The enclosure of E′(u)·d by central differences at twice the precision with
        // a rigorous truncation bound (B57): only the claimed g·d carries a tolerance.
        match derivative_enclosure(mesh, &lambda, input.u, input.targets, d, bits) {
            Some(enc) => match gd.to_rational() {
                Some(q) => {
                    let out = distance_outside(&q, &enc);
                    let tol = settings.slack * (angle_part + sums);
                    tally.within(
                        format!("fd{k}"),
                        "(Θ−θ)·d outside the difference enclosure of E′·d",
                        &out,
                        tol,
                    );
                }
                None => tally.undecided(format!("fd{k}"), "g·d not finite", f64::NAN),
            },
            None => tally.undecided(
                format!("fd{k}"),
                "difference enclosure not formed (a face not certified proper near u)",
                f64::NAN,
            ),
        }
    }
    tally.verdict()
}

/// The Hessian of `E` is `hessian` (the cotan Laplacian): along each direction `d`, the
/// dual-number derivative of `∇E = Θ − θ` equals `H d` per vertex, within the error of
/// the dual angle derivatives (relative `(ρ + 10)ε` each, B27 and B40's `ρ`) plus B44's
/// cotangent errors times `|d_i − d_j|` and B41 for the sums (proofs/B57). Witnesses
/// `d{k}:v{i}`.
pub fn verify_hessian<T: Real>(
    input: &EnergyInput<'_, T>,
    claimed: &SparseMatrix<T>,
    directions: &[Vec<T>],
    settings: &Settings,
) -> Verdict {
    if let Some(v) = input.validate() {
        return v;
    }
    let mesh = input.mesh;
    let n = mesh.n_vertices();
    if claimed.dim() != n || directions.iter().any(|d| d.len() != n) {
        return Verdict::NotApplicable {
            reason: format!("Hessian and directions need dimension {n}"),
        };
    }
    let ctx = input.lengths[0].ctx();
    let (e, bits) = (eps::<T>(ctx), T::precision_bits(ctx));
    let lambda = input.lambda();
    let lt = scaled_log_lengths(mesh, &lambda, input.u);
    let mut tally = Tally::new(false, bits);
    for (k, d) in directions.iter().enumerate() {
        let df: Vec<f64> = d.iter().map(Real::approx_f64).collect();
        let ud = dual_u(input.u, d);
        let Some(hd) = claimed.mul_vec(d) else {
            continue;
        };
        let ltd = scaled_log_lengths(mesh, &constants(&lambda), &ud);
        // D_d θ from the faces touching the support of d: elsewhere the angles do not
        // move (proofs/B32), and (Hd)_i of the claimed H is compared at every vertex.
        let zero = d[0].zero_like();
        let mut theta_d = vec![zero.clone(); n];
        let mut tol = vec![0.0; n];
        let mut sizes = vec![0.0; n];
        for f in touched_faces(mesh, &support(d)) {
            let fd = face_data(mesh, f, &lt);
            let xd = fd.hs.map(|h| ltd[h.edge().idx()].clone());
            let a = angles_from_log_lengths(&xd);
            for (m, am) in a.iter().enumerate() {
                theta_d[mesh.tail(fd.hs[(m + 2) % 3]).idx()] += &am.d;
            }
            if !fd.proper {
                // Constant angles, no Hessian contribution.
                continue;
            }
            let rho = slack_condition(fd.l);
            for (m, am) in a.iter().enumerate() {
                let corner = mesh.tail(fd.hs[(m + 2) % 3]).idx();
                tol[corner] += (rho + 10.0) * e * am.d.approx_f64().abs();
                let (i, j) = (mesh.tail(fd.hs[m]).idx(), mesh.tip(fd.hs[m]).idx());
                let (p, q) = ((m + 1) % 3, (m + 2) % 3);
                let ce = cot_error(fd.l[m], fd.l[p], fd.l[q], e);
                let cot = (fd.alpha[m]).tan().recip();
                let diff = (df[i] - df[j]).abs();
                let t = (0.5 * ce + 2.0 * e * cot.abs()) * diff;
                tol[i] += t;
                tol[j] += t;
                sizes[i] += (0.5 * cot * diff).abs() + am.d.approx_f64().abs();
                sizes[j] += (0.5 * cot * diff).abs();
            }
        }
        for i in 0..n {
            let sum = sum_error([sizes[i], sizes[i]], e) * (mesh.n_halfedges() as f64).sqrt();
            let t = settings.slack * (SAFETY * tol[i] + sum);
            // D_d(Θ − θ)_i = −D_d θ_i.
            let err = zero.clone() - &theta_d[i] - &hd[i];
            tally.within(format!("d{k}:v{i}"), "D_d(Θ−θ) − H d", &err, t);
        }
    }
    tally.verdict()
}

/// Convexity along lines: [`verify_convexity`] with the assembled Hessian
/// ([`hessian_at`]).
pub fn check_convexity<T: Real>(
    input: &EnergyInput<'_, T>,
    directions: &[Vec<T>],
    settings: &Settings,
) -> Verdict {
    verify_convexity(input, directions, &|m, lt| hessian_at(m, lt), settings)
}

/// The points `t` of the lines `u + t d` where convexity is checked.
pub const LINE_POINTS: [f64; 5] = [-0.25, -0.125, 0.0, 0.125, 0.25];

/// Convexity along lines: for each direction `d` and `t ∈` [`LINE_POINTS`], the second
/// directional derivative `dᵀ H(u + t d) d` is `≥ −tol`, `H` given by `hessian(mesh, λ̃)`
/// (the energy's Hessian is `Σ_faces Σ_sides ½ cot α (d_i − d_j)²`); tol from B44 per
/// term and B41 for the sums (proofs/B57). A value below `−tol` is a failure, witness
/// `d{k}@t`.
pub fn verify_convexity<T: Real>(
    input: &EnergyInput<'_, T>,
    directions: &[Vec<T>],
    hessian: &dyn Fn(&Mesh, &[T]) -> SparseMatrix<T>,
    settings: &Settings,
) -> Verdict {
    if let Some(v) = input.validate() {
        return v;
    }
    let mesh = input.mesh;
    let ctx = input.lengths[0].ctx();
    let (e, bits) = (eps::<T>(ctx), T::precision_bits(ctx));
    let lambda = input.lambda();
    let mut tally = Tally::new(false, bits);
    for (k, d) in directions.iter().enumerate() {
        if d.len() != mesh.n_vertices() {
            return Verdict::NotApplicable {
                reason: "a direction of the wrong length".into(),
            };
        }
        let touched = touched_faces(mesh, &support(d));
        for t in LINE_POINTS {
            let ut: Vec<T> = input
                .u
                .iter()
                .zip(d)
                .map(|(a, b)| a.clone() + &(b.clone() * &b.lit(t)))
                .collect();
            let lt = scaled_log_lengths(mesh, &lambda, &ut);
            let h = hessian(mesh, &lt);
            let Some(hd) = h.mul_vec(d) else {
                continue;
            };
            let q = hd
                .iter()
                .zip(d)
                .fold(d[0].zero_like(), |s, (a, b)| s + &(a.clone() * b));
            let mut tol = 0.0;
            let mut terms = Vec::new();
            // Faces away from the support of d have (d_i − d_j)² = 0 on every side.
            for &f in &touched {
                let fd = face_data(mesh, f, &lt);
                if !fd.proper {
                    // A degenerate face adds nothing to H (its angles are constant).
                    continue;
                }
                for m in 0..3 {
                    let (i, j) = (mesh.tail(fd.hs[m]).idx(), mesh.tip(fd.hs[m]).idx());
                    let (p, r) = ((m + 1) % 3, (m + 2) % 3);
                    let sq = (d[i].approx_f64() - d[j].approx_f64()).powi(2);
                    let term = 0.5 * fd.alpha[m].tan().recip() * sq;
                    tol +=
                        0.5 * cot_error(fd.l[m], fd.l[p], fd.l[r], e) * sq + 4.0 * e * term.abs();
                    terms.push(term);
                }
            }
            let n = mesh.n_vertices() as f64;
            let tol = settings.slack * (tol + (n + 4.0) * sum_error(terms, e));
            let elem = format!("d{k}@{t}");
            match sign_beyond(&q, tol, eps_shift(bits)) {
                Some(Sign::Negative) => {
                    tally.fail(elem, "dᵀHd < 0 beyond its error bound", q.approx_f64());
                }
                Some(_) => {}
                None => tally.undecided(elem, "dᵀHd: no error bound or not finite", q.approx_f64()),
            }
        }
    }
    tally.verdict()
}

/// The per-element bounds of [`verify_one_pass`], accumulated over the faces.
struct OnePassBounds {
    /// `E`: Σ of the one-pass face bounds (B88 item 3), of the generic ones (B57), of the
    /// face terms' sizes `S_F`.
    e_fast: f64,
    e_gen: f64,
    e_size: f64,
    /// Per vertex: one-pass bound, generic bound, Σ angles, corners.
    th: Vec<(f64, f64, f64, f64)>,
    /// Per Hessian entry: one-pass bound, generic bound, Σ|½ cot|, contributions.
    hb: HashMap<(usize, usize), (f64, f64, f64, f64)>,
}

/// [`OnePassBounds`] on the scaled logarithmic lengths `lt`, with the unit roundoff `unit`
/// and `ε` both scaled as [`eps`] (proofs/B88, B57).
fn one_pass_bounds(mesh: &Mesh, lt: &[impl Real], unit: f64, e: f64, bits: u32) -> OnePassBounds {
    let n = mesh.n_vertices();
    let mut th = vec![(0.0, 0.0, 0.0, 0.0); n];
    let mut hb: HashMap<(usize, usize), (f64, f64, f64, f64)> = HashMap::new();
    let (mut e_fast, mut e_gen, mut e_size) = (0.0, 0.0, 0.0);
    for f in mesh.faces() {
        let fd = face_data(mesh, f, lt);
        let b = one_pass_face_bound(fd.x, fd.alpha, fd.proper, unit);
        e_fast += b.energy;
        e_size += b.size;
        let near = !fd.proper && {
            let sigma: f64 = fd.l.iter().sum();
            (0..3).any(|m| {
                let slack = fd.l[(m + 1) % 3] + fd.l[(m + 2) % 3] - fd.l[m];
                slack.abs().partial_cmp(&(SHAPE_MARGIN * sigma))
                    != Some(std::cmp::Ordering::Greater)
            })
        };
        let corners = fd.hs.map(|h| mesh.tail(h).idx());
        if near {
            e_fast = f64::INFINITY;
            for m in 0..3 {
                th[corners[m]].0 = f64::INFINITY;
                let (i, j) = (corners[m], mesh.tip(fd.hs[m]).idx());
                for key in [(i, i), (j, j), (i, j), (j, i)] {
                    hb.entry(key).or_default().0 = f64::INFINITY;
                }
            }
            continue;
        }
        if !fd.proper {
            // f = ½πx_m exactly, angles the constants (π, 0, 0): π's rounding.
            e_gen += SAFETY
                * 4.0
                * e
                * std::f64::consts::PI
                * fd.x.iter().copied().map(f64::abs).sum::<f64>();
            for m in 0..3 {
                let v = mesh.tail(fd.hs[(m + 2) % 3]).idx();
                th[v].0 += b.angle;
                th[v].1 += e * std::f64::consts::PI;
                th[v].2 += fd.alpha[m];
                th[v].3 += 1.0;
            }
            continue;
        }
        e_gen += 2.0 * face_energy_error(fd.x, fd.l, fd.alpha, bits, e);
        let da = face_angle_error(fd.l, e);
        for (m, dam) in da.iter().enumerate() {
            let v = mesh.tail(fd.hs[(m + 2) % 3]).idx();
            th[v].0 += b.angle;
            th[v].1 += dam + 4.0 * e;
            th[v].2 += fd.alpha[m];
            th[v].3 += 1.0;
            let (i, j) = (mesh.tail(fd.hs[m]).idx(), mesh.tip(fd.hs[m]).idx());
            let (p, r) = ((m + 1) % 3, (m + 2) % 3);
            let generic_b = SAFETY * (0.5 * cot_error(fd.l[m], fd.l[p], fd.l[r], e) + e);
            let half_cot = 0.5 * fd.alpha[m].tan().recip().abs();
            for key in [(i, i), (j, j), (i, j), (j, i)] {
                let x = hb.entry(key).or_default();
                x.0 += 0.5 * b.cot[m];
                x.1 += generic_b;
                x.2 += half_cot;
                x.3 += 1.0;
            }
        }
    }
    OnePassBounds {
        e_fast,
        e_gen,
        e_size,
        th,
        hb,
    }
}

/// C² across Penner cells: `a` and `b` are the same metric on two triangulations of one
/// surface that differ by flips at cocircular ties (same vertices, same `u` and `Θ`); `E`,
/// every `∂E/∂u_i` and every Hessian entry must agree within the sum of both sides' bounds
/// (proofs/B57: B56/B40 per face for `E`, B40 per corner for `θ`, B44 per cotangent).
pub fn check_tie<T: Real>(
    a: &EnergyInput<'_, T>,
    b: &EnergyInput<'_, T>,
    settings: &Settings,
) -> Verdict {
    if let Some(v) = a.validate().or_else(|| b.validate()) {
        return v;
    }
    let n = a.mesh.n_vertices();
    if b.mesh.n_vertices() != n {
        return Verdict::NotApplicable {
            reason: "the two triangulations have different vertex counts".into(),
        };
    }
    let ctx = a.lengths[0].ctx();
    let (e, bits) = (eps::<T>(ctx), T::precision_bits(ctx));
    let mut tally = Tally::new(false, bits);
    let sides = [a, b].map(|s| {
        let lambda = s.lambda();
        let lt = scaled_log_lengths(s.mesh, &lambda, s.u);
        let mut e_tol = 0.0;
        let mut th_tol = vec![0.0; n];
        let mut h_tol = vec![vec![0.0; n]; n];
        for f in s.mesh.faces() {
            let fd = face_data(s.mesh, f, &lt);
            if !fd.proper {
                // f = ½πx_m: one product and π's rounding.
                e_tol += SAFETY
                    * 4.0
                    * e
                    * std::f64::consts::PI
                    * fd.x.iter().copied().map(f64::abs).sum::<f64>();
                continue;
            }
            e_tol += 2.0 * face_energy_error(fd.x, fd.l, fd.alpha, bits, e);
            let da = face_angle_error(fd.l, e);
            for m in 0..3 {
                th_tol[s.mesh.tail(fd.hs[(m + 2) % 3]).idx()] += da[m] + e * 4.0;
                let (i, j) = (s.mesh.tail(fd.hs[m]).idx(), s.mesh.tip(fd.hs[m]).idx());
                let (p, r) = ((m + 1) % 3, (m + 2) % 3);
                let ce = 0.5 * cot_error(fd.l[m], fd.l[p], fd.l[r], e) + e;
                for (x, y) in [(i, i), (j, j), (i, j), (j, i)] {
                    h_tol[x][y] += ce;
                }
            }
        }
        let en = crate::variational::energy::energy_at(s.mesh, &lt, s.u, s.targets);
        let g = crate::variational::energy::gradient_at(s.mesh, &lt, s.targets);
        let h = hessian_at(s.mesh, &lt);
        (en, g, h, e_tol, th_tol, h_tol)
    });
    let [(ea, ga, ha, eta, tta, hta), (eb, gb, hb, etb, ttb, htb)] = sides;
    if let (Some(x), Some(y)) = (ea, eb) {
        tally.within(
            "E",
            "E on the two triangulations",
            &(x - &y),
            settings.slack * (eta + etb),
        );
    }
    for i in 0..n {
        let t = settings.slack * (tta[i] + ttb[i]);
        tally.within(
            format!("v{i}"),
            "∂E/∂u on the two triangulations",
            &(ga[i].clone() - &gb[i]),
            t,
        );
    }
    let zero = a.lengths[0].zero_like();
    for i in 0..n {
        for j in 0..n {
            let x = ha.get(i, j).unwrap_or(&zero).clone();
            let y = hb.get(i, j).unwrap_or(&zero).clone();
            let t = settings.slack * SAFETY * (hta[i][j] + htb[i][j] + e);
            tally.within(
                format!("H[{i},{j}]"),
                "Hessian entry on the two triangulations",
                &(x - &y),
                t,
            );
        }
    }
    tally.verdict()
}
