//! Steps 2–3 of the certificate, shared by the closed surfaces ([`super::certificate`],
//! B71) and the disk problem of the sphere target ([`super::dirichlet_certificate`], B76):
//! from the interval cotan Laplacian over the box and the enclosed residual at its centre,
//! the strong-convexity ball argument. proof: B71
//!
//! With `H_mid ± H_rad` enclosing `H = −L` on the free vertices over the box,
//! `μ = λ_min(H_mid) − ‖H_rad‖_∞` (the eigenvalue bound by a verified Cholesky
//! factorization, B70; Weyl for the radius) and `γ ≥ ‖Θ − θ(u)‖₂`: if `γ/μ < r` (rounded
//! up), a zero `u*` of the free gradient exists with `‖u* − u‖₂ ≤ γ/μ`.

use super::certificate_outcome::{to_f64_up, CertificateOutcome, I};
use super::hessian::{grounded_hessian, CholeskyCache};
use super::verified_cholesky::{lambda_min_lower_bound, up, SymmetricLower};
use crate::mesh::Mesh;
use crate::scalar::{IntervalBound, Mpfr, Precision, Real};
use rug::Rational;
use std::borrow::Borrow;

/// Whether `x` is a valid enclosure certified `≥ 0`.
pub(crate) fn certified_nonnegative(x: &I) -> bool {
    let lo = x.lo().as_float();
    x.is_valid() && (lo.is_zero() || lo.is_sign_positive())
}

/// The Hessian `H = −L` over the box on the free vertices, as B71 step 2 uses it: the
/// binary64 midpoint matrix `H_mid` (lower triangle) and `‖H_rad‖_∞` rounded up.
pub(crate) struct BoxHessian {
    mid: SymmetricLower,
    rad_norm: f64,
}

/// The ball argument (module documentation) for the interval Laplacian over the box of
/// radius `radius`, given by its stored entries `laplacian` (as [`box_hessian`] takes
/// them), the free vertices `free_idx` (`None` at fixed vertices) and the enclosed
/// residuals `residual` at the centre (one per free vertex). `mesh` and `box_lengths`
/// (binary64 approximations of the lengths over the box, [`Real::approx_f64`]) only pick
/// the verified shift (an estimate of `λ_min(H_mid)`); the entries of the Laplacian must
/// be valid enclosures. proof: B71, B76
pub(crate) fn ball_outcome<W: Borrow<I>>(
    mesh: &Mesh,
    box_lengths: &[f64],
    laplacian: impl IntoIterator<Item = (usize, usize, W)>,
    free_idx: &[Option<usize>],
    residual: &[I],
    radius: &Rational,
    prec: Precision,
) -> CertificateOutcome {
    let hessian = box_hessian(laplacian, free_idx, residual.len(), prec);
    ball_outcome_of(
        mesh,
        box_lengths,
        &hessian,
        free_idx,
        residual,
        radius,
        prec,
    )
}

/// The Hessian over the box from the stored entries `laplacian` of the interval Laplacian
/// (`(row, column, value)`, as
/// [`SparseMatrix::entries`](crate::geometry::laplacian::SparseMatrix::entries)) on the
/// `n_free` free vertices `free_idx`: per entry the binary64 midpoint of `−L` and the
/// radius about it, rounded up (B71 step 2). proof: B71
pub(crate) fn box_hessian<W: Borrow<I>>(
    laplacian: impl IntoIterator<Item = (usize, usize, W)>,
    free_idx: &[Option<usize>],
    n_free: usize,
    prec: Precision,
) -> BoxHessian {
    // The Hessian over the box: midpoint and radius matrices of −L.
    let mut entries = Vec::new();
    let mut rad_row = vec![0.0f64; n_free];
    for (i, j, w) in laplacian {
        let (Some(a), Some(b)) = (free_idx[i], free_idx[j]) else {
            continue;
        };
        let h = -w.borrow().clone();
        let mid = ((h.lo().clone() + h.hi()) * &h.lo().lit(0.5)).approx_f64();
        let m = Mpfr::from_f64(mid, prec);
        let rad = to_f64_up(&h.hi().sub_up(&m)).max(to_f64_up(&m.sub_up(h.lo())));
        rad_row[a] = up(rad_row[a] + rad);
        if a >= b {
            entries.push((a, b, mid));
        }
    }
    BoxHessian {
        mid: SymmetricLower { n: n_free, entries },
        rad_norm: rad_row.iter().copied().fold(0.0, f64::max),
    }
}

/// [`ball_outcome`] for the Hessian over the box formed by [`box_hessian`] (the Laplacian
/// itself no longer needed). proof: B71, B76
pub(crate) fn ball_outcome_of(
    mesh: &Mesh,
    box_lengths: &[f64],
    hessian: &BoxHessian,
    free_idx: &[Option<usize>],
    residual: &[I],
    radius: &Rational,
    prec: Precision,
) -> CertificateOutcome {
    let undecided = |reason: String| CertificateOutcome::Undecided { reason };
    let BoxHessian { mid, rad_norm } = hessian;
    let rad_norm = *rad_norm;
    // An estimate of λ_min(H_mid) by inverse iteration, then verified shifts below it.
    let estimate = smallest_eigenvalue_estimate(mesh, box_lengths, free_idx);
    let bound = [0.5, 0.25, 0.0625]
        .into_iter()
        .filter_map(|frac| lambda_min_lower_bound(mid, estimate * frac))
        .find(|b| b.lambda_min > 0.0);
    let Some(bound) = bound else {
        return undecided("no verified positive lower bound on the Hessian's eigenvalues".into());
    };
    let mu = -up(rad_norm - bound.lambda_min); // μ ≤ λ_min − ‖H_rad‖ (rounded down)
    if mu.is_nan() || mu <= 0.0 {
        return undecided(format!(
            "the Hessian's variation over the box ({rad_norm:e}) exceeds its eigenvalue bound ({:e})",
            bound.lambda_min
        ));
    }
    // ‖residual‖₂, rounded up.
    let mut sum = Mpfr::from_f64(0.0, prec);
    for g in residual {
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
    let r = Mpfr::from_rational(radius, prec);
    // Strict: γ/μ < r (rounded up) implies γ < μr.
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
fn smallest_eigenvalue_estimate(mesh: &Mesh, lengths: &[f64], free_idx: &[Option<usize>]) -> f64 {
    let top = lengths.iter().copied().fold(0.0, f64::max);
    let lf: Vec<f64> = lengths.iter().map(|x| x / top).collect();
    let h = grounded_hessian(mesh, &lf, free_idx);
    let Some(f) = CholeskyCache::default().factor(&h) else {
        return 0.0;
    };
    let m = free_idx.iter().flatten().count();
    let mut x: Vec<f64> = (0..m).map(|k| 1.0 + (k % 7) as f64 / 7.0).collect();
    let mut lambda = 0.0;
    // ‖x‖/‖H⁻¹x‖ decreases towards λ_min; stop once it moves by less than 10⁻³ of itself
    // (the shifts below are at most half of it, so a slightly high estimate still works).
    for k in 0..30 {
        let y = f.solve(&x);
        let ny = y.iter().map(|a| a * a).sum::<f64>().sqrt();
        let nx = x.iter().map(|a| a * a).sum::<f64>().sqrt();
        if ny.is_nan() || ny <= 0.0 {
            return 0.0;
        }
        let previous = lambda;
        lambda = nx / ny;
        x = y.iter().map(|a| a / ny).collect();
        if k >= 3 && (previous - lambda).abs() <= 1e-3 * lambda {
            break;
        }
    }
    lambda
}

/// Tests in which one term of the ball argument's inequality (proofs/B71, "Terms") decides
/// the verdict: the honest computation is `undecided` where the weakened one would hold.
/// The exact data are closed forms: on the regular unit tetrahedron every cotan weight is
/// `w = 1/√3` and the Hessian on the free vertices `{1, 2, 3}` is
/// `w·[[3, −1, −1], [−1, 3, −1], [−1, −1, 3]]` with eigenvalues `w, 4w, 4w`.
#[cfg(test)]
mod terms {
    use super::*;
    use crate::geometry::laplacian::cotan_laplacian;
    use crate::geometry::laplacian::SparseMatrix;
    use crate::mesh::builders;

    const BITS: u64 = 128;

    fn prec() -> Precision {
        Precision::new(BITS).expect("precision")
    }

    /// The regular tetrahedron's Laplacian, each entry widened by `delta` on both sides,
    /// with vertex 0 grounded.
    fn setup(delta: f64) -> (Mesh, Vec<f64>, SparseMatrix<I>, Vec<Option<usize>>) {
        let mesh = builders::tetrahedron().mesh;
        let p = prec();
        let lengths: Vec<I> = (0..mesh.n_edges())
            .map(|_| I::from_rational(&Rational::from(1), p))
            .collect();
        let l = cotan_laplacian(&mesh, &lengths);
        let widen = |x: &I| {
            let d = Mpfr::from_f64(delta, p);
            I::new(x.lo().sub_down(&d), x.hi().add_up(&d))
        };
        let wide = l.map_values(widen);
        let free = vec![None, Some(0), Some(1), Some(2)];
        let lengths = lengths.iter().map(Real::approx_f64).collect();
        (mesh, lengths, wide, free)
    }

    fn residual(values: &[(f64, f64)]) -> Vec<I> {
        let p = prec();
        values
            .iter()
            .map(|&(lo, hi)| I::new(Mpfr::from_f64(lo, p), Mpfr::from_f64(hi, p)))
            .collect()
    }

    const W: f64 = 0.577_350_269_189_625_8; // 1/√3, λ_min of the grounded Hessian

    /// B71 term `− ‖H_rad‖_∞`: entries widened by 0.25 give ‖H_rad‖_∞ = 0.75 > λ_min = w,
    /// while λ_min(H_mid) = w > 0. With a residual of 10⁻³⁰ and radius 1 the argument
    /// would hold if the Hessian's variation over the box were not subtracted.
    #[test]
    fn term_b71_hessian_variation_over_the_box_is_subtracted() {
        let (mesh, lengths, wide, free) = setup(0.25);
        let r = residual(&[(1e-30, 1e-30); 3]);
        let out = ball_outcome(
            &mesh,
            &lengths,
            wide.entries(),
            &free,
            &r,
            &Rational::from(1),
            prec(),
        );
        assert!(
            matches!(out, CertificateOutcome::Undecided { .. }),
            "{out:?}"
        );
        // Positive side: a narrow box (‖H_rad‖ = 3·10⁻³) certifies, with μ below w − 0.003.
        let (mesh, lengths, narrow, free) = setup(1e-3);
        match ball_outcome(
            &mesh,
            &lengths,
            narrow.entries(),
            &free,
            &r,
            &Rational::from(1),
            prec(),
        ) {
            CertificateOutcome::Holds { mu, .. } => assert!(mu > 0.0 && mu <= W - 3e-3, "{mu}"),
            other @ CertificateOutcome::Undecided { .. } => panic!("{other:?}"),
        }
    }

    /// B71 term "γ from the larger end": residual enclosures `[−10⁻³, 10⁻⁶]` have
    /// magnitudes up to 10⁻³ (γ = √3·10⁻³), their smaller ends 10⁻⁶. With μ ≈ w and the
    /// radius 10⁻⁴ between `γ_small/μ ≈ 3·10⁻⁶` and `γ/μ ≈ 3·10⁻³`, only the larger end
    /// keeps the ball from being claimed.
    #[test]
    fn term_b71_residual_norm_from_the_larger_end_of_each_enclosure() {
        let (mesh, lengths, narrow, free) = setup(1e-12);
        let radius = Rational::from((1, 10_000));
        let wide = residual(&[(-1e-3, 1e-6); 3]);
        let out = ball_outcome(
            &mesh,
            &lengths,
            narrow.entries(),
            &free,
            &wide,
            &radius,
            prec(),
        );
        assert!(
            matches!(out, CertificateOutcome::Undecided { .. }),
            "{out:?}"
        );
        // The mirror image: the larger end on the right.
        let right = residual(&[(-1e-6, 1e-3); 3]);
        let out = ball_outcome(
            &mesh,
            &lengths,
            narrow.entries(),
            &free,
            &right,
            &radius,
            prec(),
        );
        assert!(
            matches!(out, CertificateOutcome::Undecided { .. }),
            "{out:?}"
        );
        // Positive side: residuals of magnitude 10⁻⁶ certify within γ/μ ≥ √3·10⁻⁶/w.
        let small = residual(&[(-1e-6, 1e-6); 3]);
        match ball_outcome(
            &mesh,
            &lengths,
            narrow.entries(),
            &free,
            &small,
            &radius,
            prec(),
        ) {
            CertificateOutcome::Holds {
                distance, residual, ..
            } => {
                assert!(residual >= 3f64.sqrt() * 1e-6, "{residual}");
                assert!(distance >= 3f64.sqrt() * 1e-6 / W, "{distance}");
            }
            other @ CertificateOutcome::Undecided { .. } => panic!("{other:?}"),
        }
    }

    /// B71 term "γ/μ < r, strict and rounded up": with the radius equal to a ball the
    /// data only just fail to fit (γ/μ computed, then r set a hair below it), the verdict
    /// is undecided; a radius twice as large certifies.
    #[test]
    fn term_b71_ball_must_fit_strictly_inside_the_box() {
        let (mesh, lengths, narrow, free) = setup(1e-12);
        let r = residual(&[(1e-6, 1e-6); 3]);
        let big = Rational::from(1);
        let CertificateOutcome::Holds { distance, .. } =
            ball_outcome(&mesh, &lengths, narrow.entries(), &free, &r, &big, prec())
        else {
            panic!("the reference ball must certify");
        };
        // A radius strictly below the proved distance: the ball does not fit.
        let below = Rational::from_f64(distance * (1.0 - 1e-9)).expect("finite");
        let out = ball_outcome(&mesh, &lengths, narrow.entries(), &free, &r, &below, prec());
        assert!(
            matches!(out, CertificateOutcome::Undecided { .. }),
            "{out:?}"
        );
        let above = Rational::from_f64(distance * 2.0).expect("finite");
        let out = ball_outcome(&mesh, &lengths, narrow.entries(), &free, &r, &above, prec());
        assert!(matches!(out, CertificateOutcome::Holds { .. }), "{out:?}");
    }
}
