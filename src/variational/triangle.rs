//! One Euclidean triangle in logarithmic lengths: its angles with the degenerate extension,
//! and Eq. 17's function `f` (docs/catalogue.md §7; SSP08; BPS15 §4).
//!
//! **Convention.** The variables are Penner's logarithmic lengths `x_m = λ_m = 2 log ℓ_m`
//! (not `log ℓ_m`): with this choice `∂f/∂x_m = α_m/2` exactly. Proof: with
//! `f = ½ Σ α_m x_m + Σ Л(α_m)` and `Л′(α) = −log(2 sin α)`,
//! `df = ½ Σ α_m dx_m + Σ (x_m/2 − log(2 sin α_m)) dα_m`, and by the law of sines
//! `x_m/2 − log(2 sin α_m) = log(ℓ_m / (2 sin α_m)) = log R` is the same for the three
//! sides, while `Σ dα_m = 0`. With `x_m = log ℓ_m` the bracket would not be constant.
//!
//! **Degenerate triangles.** When the triangle inequality fails or is tight,
//! `ℓ_m ≥ ℓ_{m+1} + ℓ_{m+2}`, the angles are extended by `α_m = π`, the others `0` (BPS15
//! §4): the extension is continuous (the half-angle formula tends to these values), so `f`
//! is C¹ on all of ℝ³ (its gradient `α/2` is continuous), and convex. Inside the degenerate
//! region the angles are constant: their derivatives, and the second derivatives of `f`,
//! are zero there.
//!
//! ```
//! use penner::variational::triangle::{angles_from_log_lengths, triangle_energy};
//! // An equilateral triangle: angles π/3 whatever the scale.
//! let a = angles_from_log_lengths(&[5.0_f64, 5.0, 5.0]);
//! assert!((a[0] - std::f64::consts::FRAC_PI_3).abs() < 1e-15);
//! // Degenerate (1, 1, 3): the angle opposite 3 is π, f = ½·π·x.
//! let x = [0.0_f64, 0.0, 2.0 * 3.0_f64.ln()];
//! let d = angles_from_log_lengths(&x);
//! assert_eq!(d[2], std::f64::consts::PI);
//! assert!((triangle_energy(&x) - 0.5 * std::f64::consts::PI * x[2]).abs() < 1e-15);
//! ```

use crate::geometry::triangle::{corner_angle, cot_opposite, kahan_area};
use crate::predicates::tolerance::sign_exact;
use crate::scalar::{Dd, Mpfr, Real, Sign};
use crate::special::lobachevsky;
use std::any::Any;

/// The shape of a triangle given by three lengths, as decided on the computed slacks
/// `ℓ_{m+1} + ℓ_{m+2} − ℓ_m`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Shape {
    /// Every slack is positive: a non-degenerate triangle.
    Proper,
    /// Slack `m` is `≤ 0`: side `m` is at least the sum of the others (angle `π` opposite).
    Degenerate(usize),
    /// An enclosure straddles 0: neither could be decided.
    Undecided,
}

/// The sign of a computed value: exactly on the stored number for point backends
/// ([`sign_exact`]; for `f64` and `Dd` read from the leading word, for `Mpfr` from the
/// float, the same answer without forming the rational); for enclosures ([`Real::is_point`] false) from the validity of the
/// enclosure's square roots, which is decided on its bounds (`√x` is a valid enclosure iff
/// its lower bound is `≥ 0`): positive when `√x` is valid and `√(−x)` is not, negative in
/// the mirror case, `None` otherwise.
fn sign_of<T: Real>(x: &T) -> Option<Sign> {
    let any = x as &dyn Any;
    if let Some(v) = any.downcast_ref::<f64>() {
        return sign_of_word(*v);
    }
    if let Some(v) = any.downcast_ref::<Dd>() {
        // Normalized: `hi = RN(hi + lo)` has the sign of the value, and is 0 only for 0.
        return sign_of_word(v.hi);
    }
    if let Some(v) = any.downcast_ref::<Mpfr>() {
        // The stored float's own sign: exact, without forming the rational (`None` for
        // NaN and ±∞, as `sign_exact`).
        return if v.0.is_finite() {
            v.0.cmp0().map(Sign::of_ordering)
        } else {
            None
        };
    }
    if T::is_point() {
        return sign_exact(x);
    }
    let up = x.sqrt().approx_f64().is_nan();
    let down = (-x.clone()).sqrt().approx_f64().is_nan();
    match (up, down) {
        (false, true) => Some(Sign::Positive),
        (true, false) => Some(Sign::Negative),
        _ => None,
    }
}

/// The lengths `e^{(x_m − x_s)/2}` of the triangle rescaled so that its longest side (by the
/// `f64` approximations; any choice gives the same angles) is 1: finite for any magnitude of
/// the `x_m`.
pub fn shifted_lengths<T: Real>(x: &[T; 3]) -> [T; 3] {
    let s = (0..3)
        .max_by(|&a, &b| x[a].approx_f64().total_cmp(&x[b].approx_f64()))
        .unwrap_or(0);
    let half = x[0].lit(0.5);
    [0, 1, 2].map(|m| ((x[m].clone() - &x[s]) * &half).exp())
}

/// The exact sign of a finite binary64 number (`None` for NaN and `±∞`, as
/// [`sign_exact`]).
fn sign_of_word(v: f64) -> Option<Sign> {
    if !v.is_finite() {
        None
    } else if v > 0.0 {
        Some(Sign::Positive)
    } else if v < 0.0 {
        Some(Sign::Negative)
    } else {
        Some(Sign::Zero)
    }
}

/// The [`Shape`] of the triangle with sides `l`.
pub fn shape<T: Real>(l: &[T; 3]) -> Shape {
    let mut undecided = false;
    for m in 0..3 {
        let slack = l[(m + 1) % 3].clone() + &l[(m + 2) % 3] - &l[m];
        match sign_of(&slack) {
            Some(Sign::Positive) => {}
            Some(_) => return Shape::Degenerate(m),
            None => undecided = true,
        }
    }
    if undecided {
        Shape::Undecided
    } else {
        Shape::Proper
    }
}

/// The angles `α_m` opposite the sides of logarithmic lengths `x_m = 2 log ℓ_m`, by the
/// half-angle form ([`corner_angle`], proofs/B40) on [`shifted_lengths`]; for a degenerate
/// triangle `(π, 0, 0)` with `π` opposite the side that is too long (module doc). An
/// undecided enclosure gives the half-angle form, whose square root is then an invalid
/// enclosure (the caller's verdict is undecided).
pub fn angles_from_log_lengths<T: Real>(x: &[T; 3]) -> [T; 3] {
    let l = shifted_lengths(x);
    angles_of_lengths(&l)
}

/// The angles opposite the sides `l` with the degenerate extension (see
/// [`angles_from_log_lengths`]).
pub fn angles_of_lengths<T: Real>(l: &[T; 3]) -> [T; 3] {
    match shape(l) {
        Shape::Degenerate(m) => {
            let zero = l[0].zero_like();
            let mut a = [zero.clone(), zero.clone(), zero];
            a[m] = T::pi(l[0].ctx());
            a
        }
        _ => [0, 1, 2].map(|m| corner_angle(&l[m], &l[(m + 1) % 3], &l[(m + 2) % 3])),
    }
}

/// Eq. 17: `f(x) = ½ Σ α_m x_m + Σ Л(α_m)` with `x_m = 2 log ℓ_m` and `α_m` from
/// [`angles_from_log_lengths`]; `∂f/∂x_m = α_m/2` (module doc). On a degenerate triangle
/// `f = ½ π x_m` for the long side `m` (`Л(0) = Л(π) = 0`, used exactly).
///
/// `Л` is [`lobachevsky`], evaluated generically: on `Interval<Mpfr>` it is the rigorous
/// enclosure of proofs/B52.
pub fn triangle_energy<T: Real>(x: &[T; 3]) -> T {
    let l = shifted_lengths(x);
    let half = x[0].lit(0.5);
    if let Shape::Degenerate(m) = shape(&l) {
        return T::pi(x[0].ctx()) * &x[m] * &half;
    }
    let a = angles_of_lengths(&l);
    let mut f = x[0].zero_like();
    for m in 0..3 {
        f += &(a[m].clone() * &x[m] * &half);
        f += &lobachevsky(&a[m]);
    }
    f
}

/// `cot α_m` for the three angles of the triangle with logarithmic lengths `x`
/// ([`cot_opposite`] on [`shifted_lengths`], proofs/B44); `None` for a degenerate or
/// undecided triangle, where the second derivatives of `f` are 0 inside the degenerate
/// region and do not exist on its boundary.
pub fn cotangents<T: Real>(x: &[T; 3]) -> Option<[T; 3]> {
    let l = shifted_lengths(x);
    (shape(&l) == Shape::Proper)
        .then(|| [0, 1, 2].map(|m| cot_opposite(&l[m], &l[(m + 1) % 3], &l[(m + 2) % 3])))
}

/// What `E`, `∇E` and the Hessian need from one face, from one evaluation of its shifted
/// sides and shape ([`face_terms`]).
#[derive(Clone, Debug)]
pub struct FaceTerms<T> {
    /// The angles `α_m` of [`angles_from_log_lengths`].
    pub angles: [T; 3],
    /// `cot α_m` as in [`cotangents`] (`None` for a degenerate or undecided face, or when
    /// not asked for).
    pub cot: Option<[T; 3]>,
    /// `f(x)` of [`triangle_energy`] (`None` when not asked for).
    pub f: Option<T>,
}

/// The angles, and on request `f` and the cotangents, of the triangle with logarithmic
/// lengths `x`, from one computation of [`shifted_lengths`] and [`shape`]: the same
/// formulas as [`angles_from_log_lengths`], [`triangle_energy`] and [`cotangents`]
/// (the cotangents share one Kahan area, `cot α_m = (ℓ²_{m+1} + ℓ²_{m+2} − ℓ²_m)/(4A)`,
/// proofs/B44; `A` is symmetric in the sides since [`kahan_area`] sorts them).
pub fn face_terms<T: Real>(x: &[T; 3], with_f: bool, with_cot: bool) -> FaceTerms<T> {
    let l = shifted_lengths(x);
    let half = x[0].lit(0.5);
    let sh = shape(&l);
    if let Shape::Degenerate(m) = sh {
        let pi = T::pi(x[0].ctx());
        let zero = l[0].zero_like();
        let mut angles = [zero.clone(), zero.clone(), zero];
        angles[m] = pi.clone();
        let f = with_f.then(|| pi * &x[m] * &half);
        return FaceTerms {
            angles,
            cot: None,
            f,
        };
    }
    let angles = [0, 1, 2].map(|m| corner_angle(&l[m], &l[(m + 1) % 3], &l[(m + 2) % 3]));
    let f = with_f.then(|| {
        let mut f = x[0].zero_like();
        for m in 0..3 {
            f += &(angles[m].clone() * &x[m] * &half);
            f += &lobachevsky(&angles[m]);
        }
        f
    });
    let cot = (with_cot && sh == Shape::Proper).then(|| {
        let four_area = kahan_area(&l[0], &l[1], &l[2]) * &x[0].lit(4.0);
        let sq = [0, 1, 2].map(|m| l[m].clone() * &l[m]);
        [0, 1, 2].map(|m| (sq[(m + 1) % 3].clone() + &sq[(m + 2) % 3] - &sq[m]) / &four_area)
    });
    FaceTerms { angles, cot, f }
}
