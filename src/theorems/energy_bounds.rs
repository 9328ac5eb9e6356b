//! Error bounds of the variational checks T31–T33 (proofs/B56–B58), evaluated in `f64`
//! from the `f64` approximations of the data, in the model of proofs/B40 (every operation
//! within `ε = 16u`, [`super::bounds::eps`], scaled by `2ˢ` past 400 bits), first order
//! times [`SAFETY`], `+∞` when the first-order relative error exceeds 1/8.

use super::bounds::{corner_angle_error, SAFETY};
use std::f64::consts::PI;

/// The number of series terms [`crate::special::lobachevsky`] sums at `bits` of
/// precision, plus 8 for the reduction, the logarithm and the final products: the
/// rounding count `N` of proofs/B56.
// proof: B56
pub fn lobachevsky_ops(bits: u32) -> f64 {
    f64::from(bits / 2 + 4 + 8)
}

/// `|ln(2 r)| + |ln(2 sin α)| + 4` with `r = min(α, π − α)` (floored at `2⁻¹⁰⁰⁰`): the size
/// of `Л′(α)` and of the logarithm inside its series (proofs/B56).
// proof: B56
pub fn lobachevsky_slope_size(alpha: f64) -> f64 {
    let r = alpha.min(PI - alpha).max(f64::MIN_POSITIVE);
    (2.0 * r).ln().abs() + (2.0 * r.sin().max(f64::MIN_POSITIVE)).ln().abs() + 4.0
}

/// The largest [`slack_condition`] where the bounds of B56–B58 are used: beyond it the
/// first-order expansion of the dual angle derivatives is not controlled (measured
/// failures of the first-order bound at `ρ ≈ 10¹⁰`, needles of width 10⁻⁹), and the
/// bounds are `+∞` (undecided).
// proof: B56
pub const MAX_SLACK_CONDITION: f64 = 65_536.0;

/// The relative condition `ρ = 4(ℓ₁+ℓ₂+ℓ₃)/min slack` of the half-angle form on sides `l`
/// (proofs/B40's `Σρᵢ/ε` for the four differences), `+∞` for a degenerate triangle or
/// past [`MAX_SLACK_CONDITION`].
// proof: B56
pub fn slack_condition(l: [f64; 3]) -> f64 {
    let s = l[0] + l[1] + l[2];
    let slack = (0..3)
        .map(|m| l[(m + 1) % 3] + l[(m + 2) % 3] - l[m])
        .fold(f64::INFINITY, f64::min);
    let rho = if slack > 0.0 {
        4.0 * s / slack
    } else {
        f64::INFINITY
    };
    if rho <= MAX_SLACK_CONDITION {
        rho
    } else {
        f64::INFINITY
    }
}

/// `SAFETY·first`, or `+∞` when `rel` (the first-order relative error) exceeds 1/8 or
/// anything is not finite (proofs/B40 "Evaluation").
fn finish(first: f64, rel: f64) -> f64 {
    if first.is_finite() && rel.is_finite() && rel <= 0.125 {
        SAFETY * first
    } else {
        f64::INFINITY
    }
}

/// B56: bound on `|D_ẋ f − ½ Σ α_m ẋ_m|`, the dual-number derivative of one triangle's `f`
/// ([`crate::variational::triangle::triangle_energy`]) along `ẋ` against the closed-form
/// half-angles, for a proper triangle with logarithmic lengths `x`, shifted sides `l`,
/// angles `α` and angle derivatives `α̇` (the dual parts of the angles along `ẋ`):
/// `N ε (1 + ρ) Σ_m [ |α_m ẋ_m| + |α̇_m| (|x_m| + S(α_m)) ]`, times [`SAFETY`], with
/// `N` = [`lobachevsky_ops`], `S` = [`lobachevsky_slope_size`], `ρ` = [`slack_condition`].
// proof: B56
pub fn schlafli_error(
    x: [f64; 3],
    xdot: [f64; 3],
    l: [f64; 3],
    alpha: [f64; 3],
    alpha_dot: [f64; 3],
    bits: u32,
    eps: f64,
) -> f64 {
    let n = lobachevsky_ops(bits);
    let rho = slack_condition(l);
    let first: f64 = (0..3)
        .map(|m| {
            (alpha[m] * xdot[m]).abs()
                + alpha_dot[m].abs() * (x[m].abs() + lobachevsky_slope_size(alpha[m]))
        })
        .sum::<f64>()
        * n
        * eps
        * (1.0 + rho);
    finish(first, n * eps * (1.0 + rho))
}

/// B57: bound on the error of the three computed angles of one proper face (B40 each, on
/// the shifted sides `l`), `Σ_m Δα_m`.
// proof: B57
pub fn face_angle_error(l: [f64; 3], eps: f64) -> [f64; 3] {
    [0, 1, 2].map(|m| corner_angle_error(l[m], l[(m + 1) % 3], l[(m + 2) % 3], eps))
}

/// B57: bound on the error of one face's term `2f(x) − (π/2)Σx` of `E`: the angle errors
/// times `|x_m|/2 + S(α_m)` (their first-order effect on `f`), plus `N ε` times the sizes
/// `Σ(|α_m x_m| + |Л(α_m)| + 1) + π Σ|x_m|`, plus the error of the `x_m` themselves
/// (`ε(|x_m| + 2)` each, weighted by `α_m + π`), times [`SAFETY`].
// proof: B57
pub fn face_energy_error(x: [f64; 3], l: [f64; 3], alpha: [f64; 3], bits: u32, eps: f64) -> f64 {
    let da = face_angle_error(l, eps);
    let n = lobachevsky_ops(bits);
    let mut first = 0.0;
    for m in 0..3 {
        first += 2.0 * da[m] * (0.5 * x[m].abs() + lobachevsky_slope_size(alpha[m]));
        first += n * eps * ((alpha[m] * x[m]).abs() + 1.0 + PI * x[m].abs());
        first += eps * (x[m].abs() + 2.0) * (alpha[m] + PI);
    }
    let rel = n * eps * (1.0 + slack_condition(l));
    finish(first, rel)
}

/// `coth|x|` (`+∞` at 0): the relative condition of `sinh x = (eˣ − e⁻ˣ)/2`.
fn coth_abs(x: f64) -> f64 {
    let a = x.abs();
    if a == 0.0 {
        f64::INFINITY
    } else {
        1.0 / a.tanh()
    }
}

/// B58: bound on `|α_half − α_cos|`, the two hyperbolic angle formulas of
/// [`crate::variational::hyperbolic`] on sides `l` for the angle opposite `l[i]`:
/// half-angle `½ sin α · Σ_{4 sinh factors}(ε coth|d|(Σℓ/2 + 1) + 3ε) + 2εα` plus law of
/// cosines `(ΔN/|D| + |c| ΔD/|D| + ε|c|)/sin α + 2εα` with
/// `ΔN = ε(4 cosh_j cosh_k + 2 cosh_i)(1 + max ℓ)` and
/// `ΔD/|D| = ε(coth ℓ_j + coth ℓ_k)(1 + max ℓ) + 3ε`, times [`SAFETY`]; `+∞` when the
/// relative error of `t²` or the first-order bound relative to `α` exceeds 1/8.
// proof: B58
pub fn hyperbolic_angle_gap(l: [f64; 3], i: usize, eps: f64) -> f64 {
    let (j, k) = ((i + 1) % 3, (i + 2) % 3);
    let s = l[0] + l[1] + l[2];
    let d = [0, 1, 2].map(|m| 0.5 * (l[(m + 1) % 3] + l[(m + 2) % 3] - l[m]));
    let factors = [0.5 * s, d[i], d[j], d[k]];
    let rel_t2: f64 = factors
        .iter()
        .map(|&x| eps * coth_abs(x) * (0.5 * s + 1.0) + 3.0 * eps)
        .sum::<f64>()
        + 3.0 * eps;
    let (ci, cj, ck) = (l[i].cosh(), l[j].cosh(), l[k].cosh());
    let den = l[j].sinh() * l[k].sinh();
    let c = (cj * ck - ci) / den;
    let alpha = c.clamp(-1.0, 1.0).acos();
    let sin = alpha.sin();
    let lmax = l[0].max(l[1]).max(l[2]);
    let dn = eps * (4.0 * cj * ck + 2.0 * ci) * (1.0 + lmax);
    let dd = eps * (coth_abs(l[j]) + coth_abs(l[k])) * (1.0 + lmax) + 3.0 * eps;
    let dc = dn / den.abs() + c.abs() * dd + eps * c.abs();
    let half = 0.5 * sin * rel_t2 + 2.0 * eps * alpha;
    let cos = dc / sin + 2.0 * eps * alpha;
    // Both first-order terms must be small against the angle itself (acos and atan are
    // far from linear once the error reaches α).
    let rel = rel_t2
        .max((half + cos) / alpha.max(f64::MIN_POSITIVE))
        .max(slack_condition(l) * eps);
    finish(half + cos, rel)
}

/// B58: bound on `|D_d F_h − Σ β_m λ̇_m|` for one hyperbolic face (the B56 argument with
/// the seven Л terms of `F_h`): `N ε (1 + ρ) [Σ_m |β_m λ̇_m| + (Σ_m |α̇_m|)(3·max|λ| + 7 S)]`
/// with `S` the largest [`lobachevsky_slope_size`] over `α_m`, `β_m`, `α′` and `ρ` the
/// largest relative condition `coth|d|(Σℓ/2 + 1)` of the half-angle factors, plus the
/// rounding of `β` and of the side sums `4επ Σ|λ̇_m|`, times [`SAFETY`].
// proof: B58
pub fn hyperbolic_face_error(
    lambda: [f64; 3],
    lambda_dot: [f64; 3],
    l: [f64; 3],
    alpha: [f64; 3],
    alpha_dot: [f64; 3],
    bits: u32,
    eps: f64,
) -> f64 {
    let n = lobachevsky_ops(bits);
    let s = l[0] + l[1] + l[2];
    let d = [0, 1, 2].map(|m| 0.5 * (l[(m + 1) % 3] + l[(m + 2) % 3] - l[m]));
    let rho = [0.5 * s, d[0], d[1], d[2]]
        .iter()
        .map(|&x| coth_abs(x) * (0.5 * s + 1.0))
        .fold(0.0, f64::max);
    let area_half = 0.5 * (PI - alpha[0] - alpha[1] - alpha[2]);
    let mut slope = lobachevsky_slope_size(area_half);
    let mut first = 0.0;
    for m in 0..3 {
        let beta = 0.5 * (PI + alpha[m] - alpha[(m + 1) % 3] - alpha[(m + 2) % 3]);
        slope = slope
            .max(lobachevsky_slope_size(alpha[m]))
            .max(lobachevsky_slope_size(beta));
        first += (beta * lambda_dot[m]).abs();
    }
    let lmax = lambda.iter().fold(0.0_f64, |a, x| a.max(x.abs()));
    let adot: f64 = alpha_dot.iter().map(|x| x.abs()).sum();
    let sum_dot: f64 = lambda_dot.iter().map(|x| x.abs()).sum();
    let first = n * eps * (1.0 + rho) * (first + adot * (3.0 * lmax + 7.0 * slope))
        + 4.0 * eps * PI * sum_dot;
    finish(first, n * eps * (1.0 + rho.max(slack_condition(l))))
}

/// B88 items 1–4 for one face of the one-pass kernels (`variational::fast_f64`, and
/// `fast_mpfr` by B29 with `u = 2⁻ᵖ`): first-order bounds on each computed angle, each
/// cotangent and the face's term `2f − (π/2)Σx`, from the `f64` approximations of the
/// logarithmic lengths `x` and angles `α` and the unit roundoff `unit` (every term is linear
/// in `unit`, so `ε·2ˢ/16` in place of `2⁻ᵖ` gives the bound times `2ˢ`). Also the size
/// `S_F` of the face's energy term (it bounds `|F|`). Without [`SAFETY`]: B88's factor 2
/// is applied by the caller.
// proof: B88
pub fn one_pass_face_bound(x: [f64; 3], alpha: [f64; 3], proper: bool, unit: f64) -> OnePassBound {
    let s = (0..3).max_by(|&a, &b| x[a].total_cmp(&x[b])).unwrap_or(0);
    let d = x.map(|v| v - x[s]);
    let xs = x[s].abs();
    if !proper {
        // Degenerate: the angles 0 and the rounded π; F = Σ(α − π/2)d − (π/2)x_s.
        let size = d.iter().map(|v| 0.5 * PI * v.abs()).sum::<f64>() + 0.5 * PI * xs;
        let energy = d.iter().map(|v| v.abs() * 12.0 * unit).sum::<f64>()
            + 7.0 * unit * size
            + PI * unit * xs;
        return OnePassBound {
            angle: 4.0 * unit,
            cot: [0.0; 3],
            energy,
            size,
        };
    }
    let l = d.map(|v| (0.5 * v).exp());
    let sigma = l[0] + l[1] + l[2];
    let kappa = [0, 1, 2].map(|m| sigma / (l[(m + 1) % 3] + l[(m + 2) % 3] - l[m]));
    let k_sum: f64 = kappa.iter().sum();
    let k_max = kappa.iter().copied().fold(0.0, f64::max);
    let cot = alpha.map(|a| a.tan().recip());
    let c_sum: f64 = cot.iter().copied().map(f64::abs).sum();
    let rho = d
        .iter()
        .map(|v| unit * v.abs() / 2.0 + 4.0 * unit)
        .fold(0.0, f64::max);
    let small = unit * (k_sum / 2.0 + k_max + 17.0) + 2.0 * rho * c_sum;
    let angle = 2.0 * small + 10.0 * unit;
    let lob = alpha.map(|a| crate::special::lobachevsky(&a));
    let dl = alpha.map(|a| (2.0 * a.sin()).ln().abs() * angle + 4.1 * unit);
    let size: f64 = (0..3)
        .map(|m| ((alpha[m] - 0.5 * PI) * d[m]).abs() + 2.0 * lob[m].abs())
        .sum::<f64>()
        + 0.5 * PI * xs;
    let energy = d
        .iter()
        .map(|v| v.abs() * (angle + 8.0 * unit))
        .sum::<f64>()
        + 2.0 * dl.iter().sum::<f64>()
        + 7.0 * unit * size
        + PI * unit * xs;
    let cot = cot.map(|c| {
        2.0 * unit * c_sum
            + c.abs() * unit * (k_sum / 2.0 + 7.0)
            + (1.0 + c * c) * 2.0 * rho * c_sum
    });
    let bad = |v: f64| if v.is_finite() { v } else { f64::INFINITY };
    OnePassBound {
        angle: bad(angle),
        cot: cot.map(bad),
        energy: bad(energy),
        size,
    }
}

/// [`one_pass_face_bound`]'s answer (proofs/B88 items 1, 3, 4).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OnePassBound {
    /// Bound on each computed angle.
    pub angle: f64,
    /// Bound on each computed `cot α_m` (0 for a degenerate face: it has none).
    pub cot: [f64; 3],
    /// Bound on the face's term `2f − (π/2)Σx`.
    pub energy: f64,
    /// `S_F = Σ(|(α_m − π/2)d_m| + 2|Л(α_m)|) + (π/2)|x_s|`, at least `|F|`.
    pub size: f64,
}
