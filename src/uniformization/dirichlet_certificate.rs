//! An a-posteriori proof for the disk problem of the sphere target ([`super::sphere`],
//! B74): the argument of B71 with the Dirichlet vertices in place of the grounded one, and
//! one more test that makes the polyhedron convex. proof: B76
//!
//! On the box `B` (free vertices `|u'_i − u_i| ≤ r`; at each link vertex `a` an enclosure of
//! the exact Dirichlet value `w_a = −2 log ℓ_{a v∞}`) the check establishes in
//! `Interval<Mpfr>`:
//!
//! 1. every face of the final disk triangulation is a strict triangle and every interior
//!    edge Delaunay on `B` (one Penner cell);
//! 2. at every link vertex the disk's angle sum is `≤ π` on `B` (the boundary polygon is
//!    convex: the edges from the pole are Delaunay, B74 "Convexity");
//! 3. `H(u') ⪰ μI` on `B` for the Hessian on the free vertices (`μ = λ_min(H_mid) −
//!    ‖H_rad‖_∞`, verified Cholesky, B70), and `‖Θ − θ(u)‖₂ ≤ γ` on the free vertices.
//!
//! If `γ < μ·r`, the exact disk problem has a solution `u*` with `‖u* − u‖₂ ≤ γ/μ` whose
//! flat disk is a Delaunay triangulation of a convex polygon, i.e. the inscribed polyhedron
//! of `u*` is convex and discretely conformally equivalent to the input (B74, B76).

use super::certificate::{to_f64_up, CertificateOutcome, I};
use super::dirichlet::free_index;
use super::hessian::{grounded_hessian, CholeskyCache};
use super::refine::{carry_lengths, scaled};
use super::sphere::SphereUniformization;
use super::verified_cholesky::{lambda_min_lower_bound, up, SymmetricLower};
use crate::geometry::cone_angles::cone_angles;
use crate::geometry::laplacian::cotan_laplacian;
use crate::mesh::{Edge, Mesh};
use crate::predicates::delaunay::{enclose_p, QuadEdges};
use crate::scalar::{IntervalBound, Mpfr, Precision, Real, Sign};
use rug::Rational;

/// The data of a disk certificate, all exact: the disk `D = T₀ − star(v∞)` with its
/// binary64 lengths, the pole lengths `ℓ_{a v∞}` of the link vertices (which fix
/// `w_a = −2 log ℓ_{a v∞}`), the targets `Θ_i/π` of the free vertices, the Ptolemy flips of
/// `D`, the free scale factors and the radius.
#[derive(Clone, Debug)]
pub struct DiskCertificateData {
    /// The disk before the flips.
    pub disk: Mesh,
    /// Its lengths `ℓ⁰`.
    pub lengths: Vec<f64>,
    /// `ℓ⁰_{a v∞}` at link vertices, `None` at free vertices.
    pub pole_length: Vec<Option<f64>>,
    /// `Θ_i/π` per vertex (read at free vertices).
    pub over_pi: Vec<Rational>,
    /// Ptolemy flips of the disk, in order.
    pub flip_sequence: Vec<Edge>,
    /// The scale factors (read at free vertices).
    pub u: Vec<Rational>,
    /// The radius of the box.
    pub radius: Rational,
}

fn lower_nonnegative(x: &I) -> bool {
    let lo = x.lo().as_float();
    x.is_valid() && (lo.is_zero() || lo.is_sign_positive())
}

/// Check a disk certificate at `bits` of interval precision (steps 1–3 of the module
/// documentation). Malformed data (counts, a flip that does not replay, bits out of range)
/// is `Undecided` with the reason: this check never claims that no solution exists.
/// proof: B76
#[allow(clippy::too_many_lines)] // the three steps of B76, read top to bottom
pub fn check_disk_certificate(data: &DiskCertificateData, bits: u32) -> CertificateOutcome {
    let undecided = |reason: String| CertificateOutcome::Undecided { reason };
    let n = data.disk.n_vertices();
    if data.pole_length.len() != n || data.over_pi.len() != n || data.u.len() != n {
        return undecided("one pole length, target and scale factor per vertex expected".into());
    }
    if data.lengths.len() != data.disk.n_edges() {
        return undecided("one length per edge expected".into());
    }
    if data.radius <= 0 {
        return undecided("the radius is not positive".into());
    }
    let Ok(prec) = Precision::new(u64::from(bits)) else {
        return undecided(format!("precision of {bits} bits out of range"));
    };
    let Ok((mesh, base)) = carry_lengths::<I>(&data.disk, &data.lengths, &data.flip_sequence, prec)
    else {
        return undecided("the flip sequence does not replay on the disk".into());
    };
    let markers: Vec<Option<f64>> = data.pole_length.iter().map(|l| l.map(|_| 0.0)).collect();
    let (free, free_idx) = free_index(&markers);
    let mut point = Vec::with_capacity(n);
    let mut boxed = Vec::with_capacity(n);
    for v in 0..n {
        if let Some(l) = data.pole_length[v] {
            if !(l.is_finite() && l > 0.0) {
                return undecided(format!("pole length of v{v} is not positive"));
            }
            let w = I::from_f64(l, prec).ln() * &I::from_f64(-2.0, prec);
            point.push(w.clone());
            boxed.push(w);
        } else {
            let q = &data.u[v];
            let lo = I::from_rational(&Rational::from(q - &data.radius), prec);
            let hi = I::from_rational(&Rational::from(q + &data.radius), prec);
            point.push(I::from_rational(q, prec));
            boxed.push(I::new(lo.lo().clone(), hi.hi().clone()));
        }
    }
    // 1. One Penner cell on the box.
    let lb = scaled(&mesh, &base, &boxed);
    for f in mesh.faces() {
        let [a, b, c] = mesh.face_halfedges(f).map(|h| &lb[h.edge().idx()]);
        for (x, y, z) in [(a, b, c), (b, c, a), (c, a, b)] {
            if (y.clone() + z - x).sign() != Some(Sign::Positive) {
                return undecided(format!(
                    "face f{} not certified a strict triangle on the whole box",
                    f.0
                ));
            }
        }
    }
    for e in mesh.edges() {
        let Some(q) = QuadEdges::of(&mesh, e) else {
            continue;
        };
        if !lower_nonnegative(&enclose_p(&q.lengths(&lb).map(Clone::clone).to_array())) {
            return undecided(format!(
                "edge e{} not certified Delaunay on the whole box",
                e.0
            ));
        }
    }
    // 2. A convex boundary: θ_a ≤ π at every link vertex on the box.
    let pi = I::pi(prec);
    let theta_box = cone_angles(&mesh, &lb);
    for (v, theta_v) in theta_box.iter().enumerate() {
        if data.pole_length[v].is_some() && !lower_nonnegative(&(pi.clone() - theta_v)) {
            return undecided(format!(
                "the disk's angle at link vertex v{v} is not certified ≤ π on the whole box"
            ));
        }
    }
    if free.is_empty() {
        // No unknowns: the box is the exact metric itself, already checked.
        return CertificateOutcome::Holds {
            distance: 0.0,
            mu: f64::INFINITY,
            residual: 0.0,
        };
    }
    // 3. The Hessian over the box and the residual at u.
    let laplacian = cotan_laplacian(&mesh, &lb);
    let mut entries = Vec::new();
    let mut rad_row = vec![0.0f64; free.len()];
    for (i, j, w) in laplacian.entries() {
        let (Some(a), Some(b)) = (free_idx[i], free_idx[j]) else {
            continue;
        };
        if !w.is_valid() {
            return undecided(format!("cotan Laplacian entry ({i}, {j}) not enclosed"));
        }
        let h = -w.clone();
        let mid = ((h.lo().clone() + h.hi()) * &h.lo().lit(0.5)).approx_f64();
        let m = Mpfr::from_f64(mid, prec);
        let rad = to_f64_up(&h.hi().sub_up(&m)).max(to_f64_up(&m.sub_up(h.lo())));
        rad_row[a] = up(rad_row[a] + rad);
        if a >= b {
            entries.push((a, b, mid));
        }
    }
    let rad_norm = rad_row.iter().copied().fold(0.0, f64::max);
    let mid = SymmetricLower {
        n: free.len(),
        entries,
    };
    let estimate = smallest_eigenvalue_estimate(&mesh, &lb, &free_idx);
    let bound = [0.5, 0.25, 0.0625]
        .into_iter()
        .filter_map(|frac| lambda_min_lower_bound(&mid, estimate * frac))
        .find(|b| b.lambda_min > 0.0);
    let Some(bound) = bound else {
        return undecided("no verified positive lower bound on the Hessian's eigenvalues".into());
    };
    let mu = -up(rad_norm - bound.lambda_min);
    if mu.is_nan() || mu <= 0.0 {
        return undecided(format!(
            "the Hessian's variation over the box ({rad_norm:e}) exceeds its eigenvalue bound ({:e})",
            bound.lambda_min
        ));
    }
    let lp = scaled(&mesh, &base, &point);
    let theta = cone_angles(&mesh, &lp);
    let mut sum = Mpfr::from_f64(0.0, prec);
    for &v in &free {
        let g = I::from_rational(&data.over_pi[v], prec) * &pi - &theta[v];
        if !g.is_valid() {
            return undecided(format!("angle sum at v{v} not enclosed"));
        }
        let (lo, hi) = (g.lo().abs(), g.hi().abs());
        let mag = if lo.as_float() > hi.as_float() {
            lo
        } else {
            hi
        };
        sum = sum.add_up(&mag.mul_up(&mag));
    }
    let gamma = sum.sqrt_up();
    let distance = gamma.div_up(&Mpfr::from_f64(mu, prec));
    let r = Mpfr::from_rational(&data.radius, prec);
    if distance.as_float() >= r.as_float() {
        return undecided(format!(
            "residual bound {:e} / μ {mu:e} = {:e} is not below the radius {:e}",
            to_f64_up(&gamma),
            to_f64_up(&distance),
            r.approx_f64()
        ));
    }
    CertificateOutcome::Holds {
        distance: to_f64_up(&distance),
        mu,
        residual: to_f64_up(&gamma),
    }
}

/// `λ_min` of the Hessian on the free vertices at the midpoint lengths, by inverse
/// iteration (a heuristic that only picks the shift; the bound itself is verified).
fn smallest_eigenvalue_estimate(mesh: &Mesh, lengths: &[I], free_idx: &[Option<usize>]) -> f64 {
    let top = lengths.iter().map(Real::approx_f64).fold(0.0, f64::max);
    let lf: Vec<f64> = lengths.iter().map(|x| x.approx_f64() / top).collect();
    let h = grounded_hessian(mesh, &lf, free_idx);
    let Some(f) = CholeskyCache::default().factor(&h) else {
        return 0.0;
    };
    let m = free_idx.iter().flatten().count();
    let mut x: Vec<f64> = (0..m).map(|k| 1.0 + (k % 7) as f64 / 7.0).collect();
    let mut lambda = 0.0;
    for _ in 0..30 {
        let y = f.solve(&x);
        let ny = y.iter().map(|a| a * a).sum::<f64>().sqrt();
        let nx = x.iter().map(|a| a * a).sum::<f64>().sqrt();
        if ny.is_nan() || ny <= 0.0 {
            return 0.0;
        }
        lambda = nx / ny;
        x = y.iter().map(|a| a / ny).collect();
    }
    lambda
}

/// The certificate data of a solved sphere uniformization at the scale factors `u` (one
/// per disk vertex, exact) and radius `radius`.
pub fn disk_data(
    sol: &SphereUniformization,
    u: Vec<Rational>,
    radius: Rational,
) -> DiskCertificateData {
    DiskCertificateData {
        disk: sol.disk.mesh.clone(),
        lengths: sol.disk.lengths.clone(),
        pole_length: sol.disk.pole_length.clone(),
        over_pi: vec![Rational::from(2); sol.disk.mesh.n_vertices()],
        flip_sequence: sol.solution.flip_sequence.clone(),
        u,
        radius,
    }
}

/// Certify the disk problem near the `f64` solution of `sol`: boxes of radius `10⁶`, `10³`
/// and `10¹⁰` times `max(max |Θ − θ|, 4ε)·√n` (at least `2^(10 − bits)` times those factors) around
/// `u` taken exactly; the first outcome that holds, or the last, with its data.
pub fn certify_disk(
    sol: &SphereUniformization,
    bits: u32,
) -> (DiskCertificateData, CertificateOutcome) {
    let u: Vec<Rational> = sol
        .solution
        .u
        .iter()
        .map(|&x| Rational::from_f64(x).unwrap_or_default())
        .collect();
    let n = u.len().max(1) as f64;
    let floor = 2f64.powi(-(bits.min(1000) as i32) + 10);
    let estimate = (sol.solution.residual_max.max(4.0 * f64::EPSILON) * n.sqrt()).max(floor);
    let mut last = None;
    for factor in [1e6, 1e3, 1e10] {
        let radius = Rational::from_f64(estimate * factor).unwrap_or_else(|| Rational::from(1));
        let data = disk_data(sol, u.clone(), radius);
        let outcome = check_disk_certificate(&data, bits);
        let done = matches!(outcome, CertificateOutcome::Holds { .. });
        last = Some((data, outcome));
        if done {
            break;
        }
    }
    last.expect("three attempts")
}
