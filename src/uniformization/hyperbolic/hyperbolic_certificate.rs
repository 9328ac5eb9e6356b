//! Refinement and certificate of a hyperbolic uniformization (proofs/B39, B87, B89).
//!
//! All of it runs on the solver's final triangulation `T_k`, whose base lengths are the
//! Ptolemy flips of `T₀`'s replayed in the working precision or on enclosures
//! ([`super::hyperbolic_flips::replay_ptolemy`], B89); the certificate also checks that
//! `T₀` is hyperbolic Delaunay for its lengths and `T_k` on the whole box (B87, B89).
//!
//! - [`refine_hyperbolic`]: residuals `Θ − θ_hyp(u)` in `Dd` or MPFR with `u` kept in that
//!   precision, corrections from the binary64 Hessian factored once (as [`super::refine`]);
//! - [`certify_hyperbolic`]: the residual enclosed in `Interval<Mpfr>` at the given `u`
//!   (certified: directed rounding), and an existence radius: on the box `|v − u|_∞ ≤ r`
//!   every face is certified a strict triangle and the Hessian (B38) enclosed; Gershgorin
//!   gives `λ_min(H(v)) ≥ μ > 0` for every `v` in the box, and then (the argument of B71)
//!   an exact solution lies within `‖Θ − θ(u)‖₂/μ` of `u` when that is `≤ r`.
//! - [`total_area_lhuilier`]: the total hyperbolic area by the hyperbolic L'Huilier
//!   formula, an oracle independent of the angles (Gauss–Bonnet: `4π(g − 1)` at `Θ ≡ 2π`).

use super::certificate_outcome::to_f64_up;
use super::hyperbolic::{HyperbolicError, HyperbolicUniformization};
use super::hyperbolic_flips::{delaunay_on_box, replay_ptolemy};
use super::hyperbolic_kernel::face_terms_generic;
use super::newton_driver::{refine_loop, Over};
use super::refine::Refinement;
use super::targets::Targets;
use crate::mesh::Mesh;
use crate::scalar::{Dd, Interval, Mpfr, Precision, Real, Sign};
use crate::variational::hyperbolic::{cone_angles, hyperbolic_log_length, length_from_log};
use rug::Rational;

type I = Interval<Mpfr>;

/// `Θ_i = q_i·π` in `T`.
fn targets_in<T: Real>(sol: &HyperbolicUniformization, ctx: T::Ctx) -> Vec<T> {
    let pi = T::pi(ctx);
    sol.targets
        .over_pi()
        .iter()
        .map(|q| T::from_rational(q, ctx) * &pi)
        .collect()
}

/// Refine `sol.u` in precision `ctx` (residuals in `T`, the binary64 Hessian at `sol.u`
/// factored once) until `max |Θ − θ| ≤ tolerance`, `max_iterations`, or two iterations in
/// a row that fail to halve the residual. `Err` when the Hessian cannot be factored.
pub fn refine_hyperbolic<T: Real>(
    sol: &HyperbolicUniformization,
    ctx: T::Ctx,
    tolerance: f64,
    max_iterations: usize,
) -> Result<Refinement<T>, HyperbolicError> {
    let base0: Vec<T> = sol
        .lengths
        .iter()
        .map(|&x| hyperbolic_log_length(&T::from_f64(x, ctx)))
        .collect();
    refine_hyperbolic_on(sol, &base0, ctx, tolerance, max_iterations)
}

/// [`refine_hyperbolic`] for the logarithmic lengths `base0` of `sol.t0` (e.g. the input's
/// exact metric replayed to `T₀`, [`super::hyperbolic_flips::replay_geometric_enclosed`]):
/// the same binary64 factor, residuals in `T` for that metric.
pub fn refine_hyperbolic_on<T: Real>(
    sol: &HyperbolicUniformization,
    base0: &[T],
    ctx: T::Ctx,
    tolerance: f64,
    max_iterations: usize,
) -> Result<Refinement<T>, HyperbolicError> {
    let mesh = &sol.mesh;
    let factor =
        super::hyperbolic::hessian_factor_log(mesh, &sol.base_log, &sol.u).ok_or_else(|| {
            HyperbolicError::NotATriangle {
                face: first_bad_face(mesh, &sol.base_log, &sol.u),
            }
        })?;
    let (_, base) = replay_ptolemy(&sol.t0, base0, &sol.flips)?;
    let theta_target = targets_in::<T>(sol, ctx);
    let u: Vec<T> = sol.u.iter().map(|&x| T::from_f64(x, ctx)).collect();
    let residual = |u: &[T]| -> Result<Vec<T>, std::convert::Infallible> {
        let theta = cone_angles(mesh, &scaled_from_base(mesh, &base, u), false);
        Ok(theta_target
            .iter()
            .zip(&theta)
            .map(|(t, th)| t.clone() - th)
            .collect())
    };
    // H d = −∇E = −(Θ − θ).
    let correction = |_: &[T], r: &[f64]| {
        let d = factor.solve(&r.iter().map(|x| -x).collect::<Vec<_>>());
        d.into_iter().map(Dd::from_f64).collect::<Vec<_>>()
    };
    // A residual that stops being finite ends the refinement unreached (history `+∞`).
    let limits = (tolerance, max_iterations);
    let Ok((refinement, _)) = refine_loop(u, ctx, limits, Over::ALL, residual, correction);
    Ok(refinement)
}

/// The hyperbolic lengths `ℓ̃ = 2 arsinh(e^{(x + u_i + u_j)/2})` of `mesh` from base
/// logarithmic lengths `x` and scale factors `u`.
pub fn scaled_from_base<T: Real>(mesh: &Mesh, base: &[T], u: &[T]) -> Vec<T> {
    mesh.edges()
        .map(|e| {
            let h = e.halfedge();
            length_from_log(
                &(base[e.idx()].clone() + &u[mesh.tail(h).idx()] + &u[mesh.tip(h).idx()]),
            )
        })
        .collect()
}

/// The base logarithmic lengths `2 log sinh(ℓ/2)` of enclosed hyperbolic lengths.
pub fn base_log_i(lengths: &[I]) -> Vec<I> {
    lengths.iter().map(hyperbolic_log_length).collect()
}

/// The first face that is not a strict triangle at `u` (`u32::MAX` if none).
fn first_bad_face(mesh: &Mesh, base: &[f64], u: &[f64]) -> u32 {
    mesh.faces()
        .find(|&f| {
            let lam = mesh
                .face_halfedges(f)
                .map(|h| base[h.edge().idx()] + u[mesh.tail(h).idx()] + u[mesh.tip(h).idx()]);
            super::hyperbolic_kernel::face_terms(lam).is_none()
        })
        .map_or(u32::MAX, |f| f.0)
}

/// The existence part of [`certify_hyperbolic`].
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub enum Existence {
    /// An exact solution `u*` with `‖u* − u‖₂ ≤ distance` exists (B39).
    Holds {
        /// `‖Θ − θ(u)‖₂/μ`, rounded up.
        distance: f64,
        /// The Gershgorin lower bound of the Hessian on the box, rounded down.
        mu: f64,
        /// The box radius `r` (sup norm).
        radius: f64,
    },
    /// Not certified, with the reason.
    Undecided {
        /// Why.
        reason: String,
    },
}

/// The certified residual and the existence radius at one `u` (B39).
#[derive(Clone, Debug)]
pub struct HyperbolicCertificate {
    /// `Θ_i − θ_i(u)` enclosed (`Interval<Mpfr>`); empty when a face is not certified a
    /// strict triangle at `u`.
    pub residual: Vec<I>,
    /// An upper bound of `max_i |Θ_i − θ_i(u)|` (`+∞` when not enclosed).
    pub residual_max: f64,
    /// An upper bound of `‖Θ − θ(u)‖₂` (`+∞` when not enclosed).
    pub residual_norm2: f64,
    /// The existence radius.
    pub existence: Existence,
}

/// `λ̃_ij = x_ij + u_i + u_j` over enclosed base logarithmic lengths `x` and intervals
/// of `u`.
fn log_lengths_i(mesh: &Mesh, base: &[I], u: &[I]) -> Vec<I> {
    mesh.edges()
        .map(|e| {
            let h = e.halfedge();
            base[e.idx()].clone() + &u[mesh.tail(h).idx()] + &u[mesh.tip(h).idx()]
        })
        .collect()
}

/// Whether every face is certified a strict triangle for the lengths `l`.
fn strict_triangles(mesh: &Mesh, l: &[I]) -> Result<(), u32> {
    for f in mesh.faces() {
        let [a, b, c] = mesh.face_halfedges(f).map(|h| &l[h.edge().idx()]);
        for (x, y, z) in [(a, b, c), (b, c, a), (c, a, b)] {
            if (y.clone() + z - x).sign() != Some(Sign::Positive) {
                return Err(f.0);
            }
        }
    }
    Ok(())
}

fn abs_up(x: &I) -> f64 {
    to_f64_up(x.hi()).max(-to_f64_down(x.lo()))
}

fn to_f64_down(x: &Mpfr) -> f64 {
    x.as_float().to_f64_round(rug::float::Round::Down)
}

/// A lower bound of `min |x|` over the interval (0 when it contains 0).
fn mig_down(x: &I) -> f64 {
    match x.sign() {
        Some(Sign::Positive) => to_f64_down(x.lo()),
        Some(Sign::Negative) => -to_f64_up(x.hi()),
        _ => 0.0,
    }
}

/// The input lengths (binary64, taken exactly) as point intervals.
fn lengths_i(lengths: &[f64], prec: Precision) -> Vec<I> {
    lengths.iter().map(|&x| I::from_f64(x, prec)).collect()
}

/// `Θ − θ_hyp` enclosed over `u` (points or a box) for the enclosed base logarithmic
/// lengths `base` of `mesh` (`2 log sinh(ℓ/2)` at `u = 0`), by the inclusion property (B20): every value of the residual at a
/// point of the box lies in the returned intervals. `Err` with the reason when a face is not
/// certified a strict triangle on all of `u` or an angle sum is not enclosed. proof: B39
pub fn enclosed_residual(
    mesh: &Mesh,
    base: &[I],
    targets: &Targets,
    u: &[I],
    prec: Precision,
) -> Result<Vec<I>, String> {
    let l: Vec<I> = log_lengths_i(mesh, base, u)
        .iter()
        .map(length_from_log)
        .collect();
    strict_triangles(mesh, &l).map_err(|f| format!("face f{f} not certified a strict triangle"))?;
    let pi = I::pi(prec);
    let theta = cone_angles(mesh, &l, false);
    let mut residual = Vec::with_capacity(theta.len());
    for (v, th) in theta.iter().enumerate() {
        let g = I::from_rational(&targets.over_pi()[v], prec) * &pi - th;
        if !g.is_valid() {
            return Err(format!("angle sum at v{v} not enclosed"));
        }
        residual.push(g);
    }
    Ok(residual)
}

/// Bounds `(lower, upper)` of `‖g‖₂` over the enclosures `g` (directed rounding; the
/// lower bound from `min |g_i|`, 0 where `g_i` contains 0).
pub fn norm2_bounds(g: &[I], prec: Precision) -> (f64, f64) {
    let mut lo = I::from_f64(0.0, prec);
    let mut hi = I::from_f64(0.0, prec);
    for x in g {
        let a = I::from_f64(mig_down(x), prec);
        lo += &(a.clone() * &a);
        let b = I::from_f64(abs_up(x), prec);
        hi += &(b.clone() * &b);
    }
    (to_f64_down(lo.sqrt().lo()), to_f64_up(hi.sqrt().hi()))
}

/// The box `{v : |v_i − u_i| ≤ r}` (outward rounded).
pub fn box_around(u: &[Rational], r: &Rational, prec: Precision) -> Vec<I> {
    u.iter()
        .map(|q| {
            let lo = I::from_rational(&Rational::from(q - r), prec);
            let hi = I::from_rational(&Rational::from(q + r), prec);
            I::new(lo.lo().clone(), hi.hi().clone())
        })
        .collect()
}

/// Enclose `Θ − θ_hyp(u)` at the exact `u` (`bits` of MPFR intervals) on the final
/// triangulation and try an existence radius (module doc; B39 with the flips of B87/B89:
/// `T₀` certified hyperbolic Delaunay for its lengths, the Ptolemy flips replayed on
/// enclosures, `T_k` certified Delaunay on the whole box). Bad input is a typed error;
/// anything not certified is reported in the result, never as a failure.
pub fn certify_hyperbolic(
    sol: &HyperbolicUniformization,
    u: &[Rational],
    bits: u32,
) -> Result<HyperbolicCertificate, HyperbolicError> {
    super::hyperbolic::validate_hyperbolic(&sol.t0, &sol.lengths, &sol.targets)?;
    let n = sol.t0.n_vertices();
    if u.len() != n {
        return Err(super::error::UniformizeError::TargetCount {
            expected: n,
            got: u.len(),
        }
        .into());
    }
    let prec = Precision::new(u64::from(bits)).map_err(|_| HyperbolicError::Bits(bits))?;
    let base0 = base_log_i(&lengths_i(&sol.lengths, prec));
    certify_hyperbolic_on(sol, &base0, u, prec)
}

/// [`certify_hyperbolic`] for enclosures `base0` of the logarithmic lengths of `sol.t0`
/// at `prec` (e.g. the input's exact metric replayed to `T₀`): `T₀` certified hyperbolic
/// Delaunay for them, the residual and the existence radius on their Ptolemy replay.
/// proof: B39, B89
pub fn certify_hyperbolic_on(
    sol: &HyperbolicUniformization,
    base0: &[I],
    u: &[Rational],
    prec: Precision,
) -> Result<HyperbolicCertificate, HyperbolicError> {
    let n = sol.t0.n_vertices();
    if u.len() != n || base0.len() != sol.t0.n_edges() {
        return Err(super::error::UniformizeError::TargetCount {
            expected: n,
            got: u.len(),
        }
        .into());
    }
    let (mesh, base) = replay_ptolemy(&sol.t0, base0, &sol.flips)?;
    let point: Vec<I> = u.iter().map(|q| I::from_rational(q, prec)).collect();
    let residual = match enclosed_residual(&mesh, &base, &sol.targets, &point, prec) {
        Ok(r) => r,
        Err(reason) => {
            return Ok(HyperbolicCertificate {
                residual: Vec::new(),
                residual_max: f64::INFINITY,
                residual_norm2: f64::INFINITY,
                existence: Existence::Undecided {
                    reason: format!("{reason} at u"),
                },
            })
        }
    };
    let (_, residual_norm2) = norm2_bounds(&residual, prec);
    let residual_max = residual.iter().map(abs_up).fold(0.0, f64::max);
    let zero = vec![I::from_f64(0.0, prec); n];
    let existence = match delaunay_on_box(&sol.t0, base0, &zero) {
        Err(reason) => Existence::Undecided {
            reason: format!("T₀: {reason} (at u = 0)"),
        },
        Ok(()) => existence(sol, &mesh, &base, u, prec, residual_norm2),
    };
    Ok(HyperbolicCertificate {
        residual,
        residual_max,
        residual_norm2,
        existence,
    })
}

/// The existence radius of B39 (module doc): the box radius from the binary64 Gershgorin
/// estimate at `u`, then [`existence_on_box`] and [`delaunay_on_box`] on `T_k`.
fn existence(
    sol: &HyperbolicUniformization,
    mesh: &Mesh,
    base: &[I],
    u: &[Rational],
    prec: Precision,
    norm2: f64,
) -> Existence {
    let uf: Vec<f64> = u.iter().map(Rational::to_f64).collect();
    let Some(mu_estimate) =
        super::hyperbolic::gershgorin_estimate_log(&sol.mesh, &sol.base_log, &uf)
    else {
        return Existence::Undecided {
            reason: "a face is not a triangle at u".into(),
        };
    };
    if mu_estimate.is_nan() || mu_estimate <= 0.0 || !norm2.is_finite() {
        return Existence::Undecided {
            reason: format!(
                "the Hessian is not diagonally dominant at u (Gershgorin bound {mu_estimate:e})"
            ),
        };
    }
    // The box radius: twice the distance the estimate predicts, at least 2⁻⁽ᵇⁱᵗˢ⁻⁸⁾.
    let floor = 2f64.powi(-(prec.bits() as i32 - 8));
    let radius = (2.0 * norm2 / mu_estimate).max(floor);
    let Some(r) = Rational::from_f64(radius) else {
        return Existence::Undecided {
            reason: format!("box radius {radius:e} not finite"),
        };
    };
    existence_with_flips(mesh, base, u, &r, norm2, prec)
}

/// [`existence_on_box`] on the final triangulation `mesh` of a flip sequence, and every
/// edge of it certified hyperbolic Delaunay on the same box ([`delaunay_on_box`]): then the
/// solution is the metric of Thm 11 with flips (B87). proof: B87, B89
pub fn existence_with_flips(
    mesh: &Mesh,
    base: &[I],
    u: &[Rational],
    radius: &Rational,
    norm2: f64,
    prec: Precision,
) -> Existence {
    match delaunay_on_box(mesh, base, &box_around(u, radius, prec)) {
        Ok(()) => existence_on_box(mesh, base, u, radius, norm2, prec),
        Err(reason) => Existence::Undecided {
            reason: format!("{reason} of radius {:e}", radius.to_f64()),
        },
    }
}

/// B39 on the box of sup-norm radius `radius` around the exact `u`, with `norm2 ≥
/// ‖Θ − θ_hyp(u)‖₂`: every face certified a strict triangle on the box, the interval
/// Hessian's Gershgorin bound `μ > 0` on the box, and `norm2/μ ≤ radius` (compared
/// exactly). Then an exact solution lies within `norm2/μ` (2-norm, so also sup norm) of
/// `u`. `base` are the enclosed base logarithmic lengths of `mesh`. Anything not certified
/// is [`Existence::Undecided`] with the reason. proof: B39
pub fn existence_on_box(
    mesh: &Mesh,
    base: &[I],
    u: &[Rational],
    radius: &Rational,
    norm2: f64,
    prec: Precision,
) -> Existence {
    let und = |reason: String| Existence::Undecided { reason };
    let radius_f = radius.to_f64();
    let boxed = box_around(u, radius, prec);
    let lam = log_lengths_i(mesh, base, &boxed);
    let lb: Vec<I> = lam.iter().map(length_from_log).collect();
    if let Err(f) = strict_triangles(mesh, &lb) {
        return und(format!(
            "face f{f} not certified a strict triangle on the box of radius {radius_f:e}"
        ));
    }
    let n = mesh.n_vertices();
    let zero = I::from_f64(0.0, prec);
    let mut diag = vec![zero.clone(); n];
    let mut off: std::collections::HashMap<(usize, usize), I> = std::collections::HashMap::new();
    for f in mesh.faces() {
        let hs = mesh.face_halfedges(f);
        let x = hs.map(|h| lam[h.edge().idx()].clone());
        let (_, w, t2) = face_terms_generic(&x);
        for m in 0..3 {
            let (i, j) = (mesh.tail(hs[m]).idx(), mesh.tip(hs[m]).idx());
            let one = zero.one_like();
            if i == j {
                diag[i] += &(w[m].clone() * &t2[m] * &zero.lit(4.0));
            } else {
                let d = w[m].clone() * &(one.clone() + &t2[m]);
                diag[i] += &d;
                diag[j] += &d;
                let o = off
                    .entry((i.max(j), i.min(j)))
                    .or_insert_with(|| zero.clone());
                *o += &(w[m].clone() * &(t2[m].clone() - &one));
            }
        }
    }
    let mut row: Vec<I> = diag;
    for (&(i, j), o) in &off {
        if !o.is_valid() {
            return und(format!("Hessian entry ({i}, {j}) not enclosed on the box"));
        }
        let a = I::from_f64(abs_up(o), prec);
        row[i] -= &a;
        row[j] -= &a;
    }
    let mut mu = f64::INFINITY;
    for (i, r) in row.iter().enumerate() {
        if !r.is_valid() {
            return und(format!("Hessian row {i} not enclosed on the box"));
        }
        mu = mu.min(to_f64_down(r.lo()));
    }
    if mu.is_nan() || mu <= 0.0 {
        return und(format!(
            "Gershgorin bound of the Hessian on the box not positive ({mu:e})"
        ));
    }
    let distance = {
        let q = I::from_f64(norm2, prec) / &I::from_f64(mu, prec);
        to_f64_up(q.hi())
    };
    let within = Rational::from_f64(distance).is_some_and(|d| d <= *radius);
    if within {
        Existence::Holds {
            distance,
            mu,
            radius: radius_f,
        }
    } else {
        und(format!(
            "‖Θ − θ(u)‖₂/μ = {distance:e} exceeds the box radius {radius_f:e}"
        ))
    }
}

/// The total area `Σ_t Area(t)` of the hyperbolic metric `lengths` on `mesh` by the
/// hyperbolic L'Huilier formula `tan(A/4) = √(tanh(s/2) Π_m tanh((s − ℓ_m)/2))` (a second
/// formula, independent of the corner angles; Gauss–Bonnet: `Σ_i(2π − θ_i) − A = 2πχ`).
/// `None` when a face is not a strict triangle.
pub fn total_area_lhuilier<T: Real>(mesh: &Mesh, lengths: &[T]) -> Option<T> {
    let z = lengths.first()?;
    let (half, four) = (z.lit(0.5), z.lit(4.0));
    let mut total = z.zero_like();
    for f in mesh.faces() {
        let l = mesh
            .face_halfedges(f)
            .map(|h| lengths[h.edge().idx()].clone());
        let s = (l[0].clone() + &l[1] + &l[2]) * &half;
        let mut p = tanh(&(s.clone() * &half));
        for m in &l {
            let d = s.clone() - m;
            let slack = d.approx_f64();
            if slack.is_nan() || slack <= 0.0 {
                return None;
            }
            p *= &tanh(&(d * &half));
        }
        total += &(p.sqrt().atan() * &four);
    }
    Some(total)
}

/// `tanh x = (1 − e^{−2x})/(1 + e^{−2x})` for `x ≥ 0`.
fn tanh<T: Real>(x: &T) -> T {
    let e = (x.clone() * &x.lit(-2.0)).exp();
    (x.one_like() - &e) / &(x.one_like() + &e)
}

/// Inputs in which one term of B39 (and B87's Delaunay condition) decides the verdict
/// (proofs/B39, **Terms**). The subject is the tetrahedron with hyperbolic edge lengths:
/// with all six equal to `ℓ` its Hessian has closed-form entries (`cos α = cosh ℓ/(cosh ℓ +
/// 1)`, `w = ½ cot((π − α)/2)`, `t² = tanh²(ℓ/2)`), so the Gershgorin bound is
/// `μ = 12·w·t²` and the diagonal alone would be `6·w·(1 + t²)`, independent of the code.
#[cfg(test)]
mod terms {
    use super::*;
    use crate::mesh::builders;
    use crate::mesh::Edge;

    const BITS: u64 = 128;

    fn prec() -> Precision {
        Precision::new(BITS).expect("precision")
    }

    /// The tetrahedron with edge 0 of hyperbolic length `long` and the others `1`, its
    /// enclosed base logarithmic lengths.
    fn tetrahedron(long: f64) -> (Mesh, Vec<I>) {
        let mesh = builders::tetrahedron().mesh;
        let lengths: Vec<f64> = (0..mesh.n_edges())
            .map(|e| if e == 0 { long } else { 1.0 })
            .collect();
        let base = base_log_i(&lengths_i(&lengths, prec()));
        (mesh, base)
    }

    /// `(μ, diagonal)` in closed form for six edges of length 1.
    fn closed_form() -> (f64, f64) {
        let (c, t) = (1f64.cosh(), 0.5f64.tanh());
        let alpha = (c / (c + 1.0)).acos();
        let w = 0.5 / ((std::f64::consts::PI - alpha) / 2.0).tan();
        (12.0 * w * t * t, 6.0 * w * (1.0 + t * t))
    }

    fn r() -> Rational {
        Rational::from(1) >> 30u32
    }

    fn zeros() -> Vec<Rational> {
        vec![Rational::new(); 4]
    }

    /// B39 term "each row's lower end minus the upper ends of `|H_ij|`" (Gershgorin): a
    /// residual whose distance `γ/μ` exceeds the radius while `γ/diag` would not. The
    /// control halves the residual and reports `μ` within `10⁻⁶` of the closed form (the
    /// box of radius `2⁻³⁰` moves it by `O(2⁻³⁰)`).
    #[test]
    fn term_b39_gershgorin_subtracts_the_off_diagonal() {
        let (mesh, base) = tetrahedron(1.0);
        let (mu, diagonal) = closed_form();
        assert!(
            diagonal > 2.0 * mu,
            "the test needs a wide gap: {mu} {diagonal}"
        );
        let rf = r().to_f64();
        let between = rf * (mu + diagonal) / 2.0;
        let outcome = existence_on_box(&mesh, &base, &zeros(), &r(), between, prec());
        assert!(
            matches!(&outcome, Existence::Undecided { reason } if reason.contains("exceeds")),
            "{outcome:?}"
        );
        let below = rf * mu / 2.0;
        let outcome = existence_on_box(&mesh, &base, &zeros(), &r(), below, prec());
        let Existence::Holds { mu: got, .. } = outcome else {
            panic!("{outcome:?}")
        };
        assert!(
            (got - mu).abs() <= 1e-6 * mu && got <= mu * (1.0 + 1e-12),
            "{got} {mu}"
        );
    }

    /// B39 term "`γ/μ` rounded up": a radius `r` near `2⁻³⁰` and a residual `γ` with `γ/μ`
    /// (exact, in ℚ) just above `r` but nearer to `r` than to the next binary64 number.
    /// Rounded up, the distance exceeds `r`; rounded to nearest it would equal `r` and hold.
    /// (`r` is searched: for a power of two no binary64 `γ` lands in that half ulp.)
    #[test]
    fn term_b39_distance_rounded_up() {
        let (mesh, base) = tetrahedron(1.0);
        let subject = (1..400u32).find_map(|k| {
            let radius = Rational::from(2u64.pow(30) + 2 * u64::from(k) + 1) >> 60u32;
            let Existence::Holds { mu, .. } =
                existence_on_box(&mesh, &base, &zeros(), &radius, 0.0, prec())
            else {
                return None;
            };
            let mu_q = Rational::from_f64(mu)?;
            let start = rug::Float::with_val(53, &radius * mu_q.clone()).to_f64();
            let mut g = start;
            for _ in 0..4 {
                let ratio = Rational::from_f64(g)? / &mu_q;
                // `Rational::to_f64` truncates; the nearest binary64 number is MPFR's.
                let nearest = Rational::from_f64(rug::Float::with_val(53, &ratio).to_f64())?;
                if ratio > radius && nearest == radius {
                    return Some((radius, g));
                }
                g = f64::from_bits(g.to_bits() + 1);
            }
            None
        });
        let (radius, gamma) = subject.expect("a residual whose ratio rounds to nearest onto r");
        let outcome = existence_on_box(&mesh, &base, &zeros(), &radius, gamma, prec());
        assert!(
            matches!(&outcome, Existence::Undecided { reason } if reason.contains("exceeds")),
            "{outcome:?}"
        );
    }

    /// B39 term "`γ` the upper end of `‖g‖₂`": enclosures whose ends differ in magnitude
    /// by `10³` (upper bound from the larger, lower bound from `min |g_i|`, 0 across 0), and
    /// outward rounding of one third.
    #[test]
    fn term_b39_residual_norm_bounds_from_the_right_ends() {
        let p = prec();
        let g = |lo: f64, hi: f64| I::new(Mpfr::from_f64(lo, p), Mpfr::from_f64(hi, p));
        let (lo, hi) = norm2_bounds(&[g(1e-6, 1e-3)], p);
        assert!(hi >= 1e-3 && lo <= 1e-6 && lo > 0.0, "{lo} {hi}");
        let (lo, hi) = norm2_bounds(&[g(-1e-3, -1e-6)], p);
        assert!(hi >= 1e-3 && lo <= 1e-6 && lo > 0.0, "{lo} {hi}");
        let (lo, hi) = norm2_bounds(&[g(-1e-3, 1e-6)], p);
        assert!(hi >= 1e-3 && lo == 0.0, "{lo} {hi}");
        let third = I::from_rational(&Rational::from((1, 3)), Precision::new(200).unwrap());
        let q = Rational::from((1, 3));
        assert!(Rational::from_f64(abs_up(&third)).unwrap() > q);
        assert!(Rational::from_f64(mig_down(&third)).unwrap() < q);
        assert!(Rational::from_f64(to_f64_down(third.lo())).unwrap() < q);
    }

    /// B87/B89 term "`T_k` hyperbolic Delaunay on the box": a tetrahedron whose long edge
    /// has a negative Leibon sum (binary64, an independent evaluation) while Gershgorin
    /// still certifies the fixed-triangulation solution. Without the Delaunay check the
    /// claim would be the metric of Thm 11 with flips, which it is not. Control: all edges
    /// of length 1 hold.
    #[test]
    fn term_b87_final_triangulation_delaunay_on_the_box() {
        let subject = (100..199).map(|k| f64::from(k) / 100.0).find_map(|long| {
            let (mesh, base) = tetrahedron(long);
            let x: Vec<f64> = base.iter().map(Real::approx_f64).collect();
            let sum = leibon_sum_f64(&mesh, Edge(0), &x)?;
            let fixed = existence_on_box(&mesh, &base, &zeros(), &r(), 0.0, prec());
            (sum < -1e-3 && matches!(fixed, Existence::Holds { .. })).then_some((mesh, base))
        });
        let (mesh, base) = subject.expect("a non-Delaunay tetrahedron that Gershgorin certifies");
        let outcome = existence_with_flips(&mesh, &base, &zeros(), &r(), 0.0, prec());
        assert!(
            matches!(&outcome, Existence::Undecided { reason } if reason.contains("Delaunay")),
            "{outcome:?}"
        );
        let (mesh, base) = tetrahedron(1.0);
        let outcome = existence_with_flips(&mesh, &base, &zeros(), &r(), 0.0, prec());
        assert!(matches!(outcome, Existence::Holds { .. }), "{outcome:?}");
    }

    /// B39 (1), every face strict on the box: a long edge `1.999` beside two edges `1`
    /// on a box of radius `10⁻²` (the lengths move by about 1 %, past the degenerate
    /// `1 + 1`): refused naming the face. With step (1) removed the box is still refused,
    /// by the enclosures of (2) that are not valid.
    #[test]
    fn term_b39_faces_strict_on_the_box() {
        let (mesh, base) = tetrahedron(1.999);
        let radius = Rational::from((1, 100));
        let outcome = existence_on_box(&mesh, &base, &zeros(), &radius, 0.0, prec());
        assert!(
            matches!(&outcome, Existence::Undecided { reason } if reason.contains("strict triangle")),
            "{outcome:?}"
        );
        let small = Rational::from(1) >> 40u32;
        let outcome = existence_on_box(&mesh, &base, &zeros(), &small, 0.0, prec());
        assert!(
            !matches!(&outcome, Existence::Undecided { reason } if reason.contains("strict")),
            "{outcome:?}"
        );
    }

    /// B39 (2), the interval Hessian's Gershgorin bound on a box of radius `2⁻⁵⁰` agrees
    /// within `10⁻¹⁰` (relative; the box moves it by `O(2⁻⁵⁰)`, binary64 by a few ulps) with the binary64 Gershgorin bound of the solver's own
    /// assembly (an independent evaluation) on uneven tetrahedra (one edge of length 1.6,
    /// at each of the six positions, so that the smallest row is each vertex in turn) and
    /// on the one-vertex torus (loops: the diagonal term `4·w·t²` of an edge from a vertex
    /// to itself), and never exceeds it by more than that.
    #[test]
    fn term_b39_gershgorin_rows_match_the_binary64_assembly() {
        let mut cases: Vec<(Mesh, Vec<f64>)> = (0..6)
            .map(|e| {
                let mesh = builders::tetrahedron().mesh;
                let l = (0..6).map(|k| if k == e { 1.6 } else { 1.0 }).collect();
                (mesh, l)
            })
            .collect();
        cases.push((builders::one_vertex_torus(), vec![1.0, 1.2, 1.4]));
        for (mesh, lengths) in cases {
            let base = base_log_i(&lengths_i(&lengths, prec()));
            let x: Vec<f64> = base.iter().map(Real::approx_f64).collect();
            let zero = vec![0.0; mesh.n_vertices()];
            let estimate =
                super::super::hyperbolic::gershgorin_estimate_log(&mesh, &x, &zero).unwrap();
            let u = vec![Rational::new(); mesh.n_vertices()];
            let tiny = Rational::from(1) >> 50u32;
            let outcome = existence_on_box(&mesh, &base, &u, &tiny, 0.0, prec());
            let mu = match outcome {
                Existence::Holds { mu, .. } => mu,
                Existence::Undecided { reason } => {
                    assert!(
                        estimate <= 0.0,
                        "{lengths:?}: {reason}, estimate {estimate}"
                    );
                    continue;
                }
            };
            assert!(
                (mu - estimate).abs() <= 1e-10 * estimate.abs(),
                "{lengths:?}: μ = {mu}, binary64 {estimate}"
            );
        }
    }

    /// B39 (2), `μ > 0` required: a nearly degenerate tetrahedron (one edge close to the
    /// sum `1 + 1`, strict on the box) whose Gershgorin bound is negative is refused for
    /// that reason; without the test a negative `μ` would make `γ/μ ≤ r` hold.
    #[test]
    fn term_b39_gershgorin_bound_must_be_positive() {
        let refused = (90..100).map(|k| 1.0 + f64::from(k) / 100.0).any(|long| {
            let (mesh, base) = tetrahedron(long);
            let outcome = existence_on_box(&mesh, &base, &zeros(), &r(), 1e-3, prec());
            matches!(&outcome, Existence::Undecided { reason } if reason.contains("Gershgorin bound of the Hessian on the box not positive"))
        });
        assert!(refused, "no tetrahedron with a negative Gershgorin bound");
    }

    /// B39 (3), `γ` from squares: enclosures of magnitude 3 (where `2b` and `b/b` would be
    /// smaller than `b²`) give an upper bound `≥ √18` and a lower bound `≤ √18`.
    #[test]
    fn term_b39_residual_norm_squares_large_entries() {
        let p = prec();
        let three = I::from_f64(3.0, p);
        let (lo, hi) = norm2_bounds(&[three.clone(), three], p);
        assert!(
            hi >= 18f64.sqrt() && lo <= 18f64.sqrt() && lo >= 4.0,
            "{lo} {hi}"
        );
    }

    /// The face `refine_hyperbolic` names when the binary64 Hessian cannot be factored:
    /// `first_bad_face` on tetrahedra with pseudo-random base logarithmic lengths and scale
    /// factors is the first face whose lengths `2 arsinh(e^{(x + u_i + u_j)/2})`, evaluated
    /// at 128 bits, violate a strict triangle inequality (`u32::MAX` when none does; cases
    /// within `10⁻⁶` of a tie skipped). Both outcomes and faces past `f1` occur.
    #[test]
    fn b39_first_bad_face_is_the_first_face_not_a_strict_triangle() {
        let mesh = builders::tetrahedron().mesh;
        let mut state = 0x9e37_79b9_7f4a_7c15_u64;
        let mut next = |lo: f64, hi: f64| {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            lo + (hi - lo) * (state >> 11) as f64 / (1u64 << 53) as f64
        };
        let length = |x: f64, a: f64, b: f64| {
            let lam = rug::Float::with_val(128, x) + a + b;
            let s: rug::Float = (lam / 2u32).exp().asinh();
            s * 2u32
        };
        let (mut none, mut late) = (0, 0);
        for _ in 0..400 {
            let base: Vec<f64> = (0..mesh.n_edges()).map(|_| next(-2.0, 2.0)).collect();
            let u: Vec<f64> = (0..mesh.n_vertices()).map(|_| next(-1.5, 1.5)).collect();
            let mut tie = false;
            let expected = mesh.faces().find(|&f| {
                let l = mesh.face_halfedges(f).map(|h| {
                    let (i, j) = (mesh.tail(h).idx(), mesh.tip(h).idx());
                    length(base[h.edge().idx()], u[i], u[j])
                });
                let slack = (0..3).map(|m| {
                    let s = l[(m + 1) % 3].clone() + &l[(m + 2) % 3] - &l[m];
                    s.to_f64()
                });
                let least = slack.fold(f64::INFINITY, f64::min);
                tie |= least.abs() < 1e-6;
                least <= 0.0
            });
            if tie {
                continue;
            }
            let expected = expected.map_or(u32::MAX, |f| f.0);
            assert_eq!(first_bad_face(&mesh, &base, &u), expected, "{base:?} {u:?}");
            none += usize::from(expected == u32::MAX);
            late += usize::from(expected != u32::MAX && expected >= 2);
        }
        assert!(none > 0 && late > 0, "{none} without, {late} past f1");
    }

    /// `certify_hyperbolic_on` refuses a `u` or enclosed lengths `base0` of the wrong
    /// length, either one alone, as a typed error (genus 2, one vertex, a cone of angle
    /// `π`). Control: the right lengths give a certificate.
    #[test]
    fn b39_certify_on_refuses_inputs_of_the_wrong_length() {
        use super::super::error::UniformizeError;
        use super::super::hyperbolic::{uniformize_hyperbolic, HyperbolicOptions};
        let mesh = builders::genus(2).expect("genus 2");
        let cone = Targets::from_multiples_of_pi(vec![Rational::from(1)]);
        let options = HyperbolicOptions::default();
        let sol = uniformize_hyperbolic(&mesh, &[1.0; 9], &cone, &options).expect("solved");
        let p = prec();
        let base0 = base_log_i(&lengths_i(&sol.lengths, p));
        let u: Vec<Rational> = sol
            .u
            .iter()
            .map(|&x| Rational::from_f64(x).unwrap())
            .collect();
        assert!(certify_hyperbolic_on(&sol, &base0, &u, p).is_ok());
        let wrong = |r: Result<HyperbolicCertificate, HyperbolicError>| {
            matches!(
                r,
                Err(HyperbolicError::Input(UniformizeError::TargetCount { .. }))
            )
        };
        assert!(wrong(certify_hyperbolic_on(&sol, &base0, &u[1..], p)));
        assert!(wrong(certify_hyperbolic_on(&sol, &base0[1..], &u, p)));
    }

    /// The L'Huilier area (B68's oracle) is `None` when a face is not a strict triangle:
    /// sides `1, 1, 2.5` (a negative factor, whose square root would be NaN) and `1, 1, 2`
    /// (a zero factor, area 0). Controls: the doubled equilateral triangle of side `a` has
    /// area `2(π − 3α)`, `cos α = cosh a/(cosh a + 1)` (hyperbolic law of cosines), at
    /// `a = 1` and at `a = 500`, nearly ideal (area `2π`), where `tanh` of the half
    /// perimeter `375` from `e^{+2x}` would overflow to NaN.
    #[test]
    fn b68_lhuilier_area_none_unless_every_face_is_strict() {
        let mesh = Mesh::from_faces(3, &[[0, 1, 2], [0, 2, 1]]).expect("doubled triangle");
        assert!(total_area_lhuilier(&mesh, &[1.0, 1.0, 2.5]).is_none());
        assert!(total_area_lhuilier(&mesh, &[1.0, 1.0, 2.0]).is_none());
        for a in [1f64, 500.0] {
            let alpha = (a.cosh() / (a.cosh() + 1.0)).acos();
            let area = total_area_lhuilier(&mesh, &[a; 3]).expect("a triangle");
            let expected = 2.0 * (std::f64::consts::PI - 3.0 * alpha);
            assert!(
                (area - expected).abs() < 1e-12,
                "a = {a}: {area} vs {expected}"
            );
        }
    }

    fn leibon_sum_f64(mesh: &Mesh, e: Edge, x: &[f64]) -> Option<f64> {
        super::super::hyperbolic_flips::leibon_sum(mesh, e, &|f: Edge| x[f.idx()]).ok()
    }
}
