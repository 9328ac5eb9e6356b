//! T12 (notes §1.4.1, Thm 5; Rodin–Sullivan 1987): the discrete Riemann maps of hexagonal
//! circle packings converge to the Riemann map under refinement (proofs/T12, measured).
//!
//! Domain: the upper half-disk `Ω = {|z| < 1, Im z > 0}`, whose Riemann map is explicit:
//! `g(z) = ((1 + z)/(1 − z))²` maps `Ω` onto the upper half-plane (`(1 + z)/(1 − z)` maps
//! it onto the first quadrant), and `f(z) = e^{iθ}(g(z) − g(z₀))/(g(z) − conj g(z₀))`
//! onto the unit disk with `f(z₀) = 0`, `θ = −arg(g'(z₀)/(g(z₀) − conj g(z₀)))` making
//! `f'(z₀) > 0`, `g'(z) = 4(1 + z)/(1 − z)³` ([`half_disk_map`]).
//!
//! Discrete map: the hexagonal complex of spacing `ε` based at `z₀`
//! ([`hex_complex`]) is packed maximally in the unit disk (T11, [`maximal_disk`], `f64`),
//! normalised with the circle of `z₀` centred at 0 and the circle of `z₀ + ε` on the
//! positive real axis (the discrete `f'(z₀) > 0`). `f_ε` is the piecewise-linear map taking
//! each lattice triangle to the triangle of the packed centres. The error is
//! `max |f_ε(z) − f(z)|` over a fixed grid of the compact set
//! `K = {|z| ≤ 3/4, Im z ≥ 1/4}` ([`compact_samples`]), inside the carrier for every
//! `ε ≤ 1/4` (a point at distance ≥ ε from `∂Ω` lies in a lattice triangle with corners in
//! `Ω`).
//!
//! [`check_refinement`] holds (numerically) when the error decreases at every halving of
//! `ε` at a local rate `log₂(e(ε)/e(ε/2)) ≥` [`MIN_LOCAL_RATE`]. Rodin–Sullivan prove
//! convergence without a rate; the rate is measured, not a theorem.

use super::{Verdict, Witness};
use crate::circles::hexagonal::{hex_complex, locate, HexError};
use crate::circles::maximal::{maximal_disk, MaximalError, Options};

/// A complex number `[re, im]`.
pub type C = [f64; 2];

fn mul(a: C, b: C) -> C {
    [a[0] * b[0] - a[1] * b[1], a[0] * b[1] + a[1] * b[0]]
}

fn div(a: C, b: C) -> C {
    let d = b[0] * b[0] + b[1] * b[1];
    [
        (a[0] * b[0] + a[1] * b[1]) / d,
        (a[1] * b[0] - a[0] * b[1]) / d,
    ]
}

fn sub(a: C, b: C) -> C {
    [a[0] - b[0], a[1] - b[1]]
}

/// The base point `z₀ = i√3/4` of the lattice and of the normalisation: a lattice row lies
/// on the diameter `Im z = 0` at every spacing `ε = 2⁻ᵏ/8` (`√3/4 = 4·(√3/2)/8`), so the
/// carrier's gap to that side of `∂Ω` does not jump between levels.
pub const BASE: C = [0.0, 0.433_012_701_892_219_3];

/// The smallest accepted local rate `log₂(e(ε)/e(ε/2))`: any error of order `ε^p` with
/// `p ≥ 1/3` passes, an error that levels off at a nonzero value does not (the measured
/// rates are near 1, `examples/rodin_sullivan.rs`).
pub const MIN_LOCAL_RATE: f64 = 1.0 / 3.0;

/// The largest accepted ratio of a level's layout defect (the largest tangency defect of the
/// laid-out packing, [`crate::circles::maximal::stopping::layout_defect`]) to its measured
/// error: `2⁻⁸`. A level above it measures its layout, not the discrete Riemann map
/// (proofs/T12 "Limits", B92).
pub const MAX_LAYOUT_DEFECT_RATIO: f64 = 1.0 / 256.0;

/// Lattice points are computed with rounding: a point of a row meant to lie on the
/// diameter may come out at `|y| ≈ 10⁻¹⁷`. Points within this slack of the closed
/// half-disk count as inside (the carrier then exceeds `Ω` by at most `10⁻¹²`, far below the
/// measured errors).
pub const MEMBERSHIP_SLACK: f64 = 1e-12;

/// Whether `z` lies in the closed upper half-disk, up to [`MEMBERSHIP_SLACK`].
pub fn in_half_disk(z: C) -> bool {
    z[1] >= -MEMBERSHIP_SLACK && z[0] * z[0] + z[1] * z[1] <= 1.0 + MEMBERSHIP_SLACK
}

fn g(z: C) -> C {
    let s = div([1.0 + z[0], z[1]], [1.0 - z[0], -z[1]]);
    mul(s, s)
}

/// The Riemann map of the upper half-disk onto the unit disk with `f(z₀) = 0`,
/// `f'(z₀) > 0` (module docs), at `z`.
pub fn half_disk_map(z0: C, z: C) -> C {
    let w0 = g(z0);
    let conj = [w0[0], -w0[1]];
    let one_minus = [1.0 - z0[0], -z0[1]];
    let cube = mul(mul(one_minus, one_minus), one_minus);
    let dg = div(mul([4.0, 0.0], [1.0 + z0[0], z0[1]]), cube);
    let q = div(dg, sub(w0, conj));
    let theta = -q[1].atan2(q[0]);
    let rot = [theta.cos(), theta.sin()];
    let w = g(z);
    mul(rot, div(sub(w, w0), sub(w, conj)))
}

/// The grid `x + iy`, `x = −0.75 + k/20`, `y = 0.25 + l/20`, kept where `|z| ≤ 3/4`
/// (the compact set `K` of the module docs).
pub fn compact_samples() -> Vec<C> {
    let mut out = Vec::new();
    for l in 0..=10 {
        for k in 0..=30 {
            let z = [-0.75 + f64::from(k) / 20.0, 0.25 + f64::from(l) / 20.0];
            if z[0] * z[0] + z[1] * z[1] <= 0.5625 {
                out.push(z);
            }
        }
    }
    out
}

/// Why no discrete map was measured.
#[derive(Debug, thiserror::Error)]
pub enum RodinSullivanError {
    /// The hexagonal complex failed.
    #[error(transparent)]
    Hex(#[from] HexError),
    /// The maximal packing failed.
    #[error(transparent)]
    Packing(#[from] MaximalError),
    /// The normalising neighbour `z₀ + ε` is not in the complex.
    #[error("the lattice neighbour z₀ + ε is not in the complex")]
    NoDirection,
    /// A sample point is not in the carrier.
    #[error("sample point {0:?} is outside the complex")]
    Outside(C),
}

/// One level of refinement.
#[derive(Clone, Debug)]
pub struct Level {
    /// Spacing `ε`.
    pub spacing: f64,
    /// Vertices of the complex.
    pub vertices: usize,
    /// `max_K |f_ε − f|`.
    pub error: f64,
    /// Where the maximum is attained.
    pub worst: C,
    /// The largest tangency defect of the laid-out packing (proofs/B92).
    pub layout_defect: f64,
}

/// The discrete map of spacing `eps` and its largest distance from `map` on
/// [`compact_samples`] (module docs).
pub fn measure_level(eps: f64, map: &dyn Fn(C) -> C) -> Result<Level, RodinSullivanError> {
    let hex = hex_complex(&in_half_disk, BASE, eps, 1.2)?;
    let direction = hex.direction.ok_or(RodinSullivanError::NoDirection)?;
    let opts = Options {
        centre: Some(hex.centre),
        direction: Some(direction),
        ..Options::default()
    };
    let packing = maximal_disk::<f64>(&hex.mesh, (), &opts)?;
    let index: std::collections::HashMap<(i64, i64), usize> = hex
        .lattice
        .iter()
        .enumerate()
        .map(|(v, &p)| (p, v))
        .collect();
    let (mut error, mut worst) = (0.0_f64, BASE);
    for z in compact_samples() {
        let (corners, weights) = locate(BASE, eps, z);
        let mut image = [0.0, 0.0];
        for (p, w) in corners.iter().zip(weights) {
            let v = *index.get(p).ok_or(RodinSullivanError::Outside(z))?;
            let c = packing.circles[v].centre;
            image[0] += w * c[0];
            image[1] += w * c[1];
        }
        let d = sub(image, map(z));
        let e = d[0].hypot(d[1]);
        if e > error || e.is_nan() {
            error = e;
            worst = z;
        }
    }
    Ok(Level {
        spacing: eps,
        vertices: hex.mesh.n_vertices(),
        error,
        worst,
        layout_defect: packing.layout_defect,
    })
}

/// The local rates `log₂(e_k / e_{k+1})` of levels whose spacings halve.
pub fn local_rates(levels: &[Level]) -> Vec<f64> {
    levels
        .windows(2)
        .map(|w| (w[0].error / w[1].error).log2())
        .collect()
}

/// T12 on the levels of a refinement (spacings halving): `Holds` (numerical) when every
/// local rate is at least [`MIN_LOCAL_RATE`] and every level's layout defect is at most
/// [`MAX_LAYOUT_DEFECT_RATIO`] times its error, `Undecided` otherwise (a slow decrease on
/// finitely many levels disproves no limit, and a level whose layout is not consistent
/// far below its error measures nothing).
pub fn check_refinement(levels: &[Level]) -> Verdict {
    if levels.len() < 2 {
        return Verdict::NotApplicable {
            reason: "fewer than two levels".into(),
        };
    }
    let witnesses: Vec<Witness> = levels
        .windows(2)
        .zip(local_rates(levels))
        .filter(|(_, r)| r.is_nan() || *r < MIN_LOCAL_RATE)
        .map(|(w, r)| Witness {
            element: format!("ε = {}", w[1].spacing),
            detail: format!(
                "error {:.3e} → {:.3e}: local rate {r:.3} below {MIN_LOCAL_RATE:.3}",
                w[0].error, w[1].error
            ),
            value: r,
        })
        .chain(
            levels
                .iter()
                .filter(|l| {
                    let bound = MAX_LAYOUT_DEFECT_RATIO * l.error;
                    l.layout_defect.is_nan() || bound.is_nan() || l.layout_defect > bound
                })
                .map(|l| Witness {
                    element: format!("ε = {}", l.spacing),
                    detail: format!(
                        "layout defect {:.3e} not below 2⁻⁸ of the error {:.3e}",
                        l.layout_defect, l.error
                    ),
                    value: l.layout_defect,
                }),
        )
        .collect();
    if witnesses.is_empty() {
        Verdict::Holds {
            certified: false,
            max_error: levels.last().map_or(f64::NAN, |l| l.error),
        }
    } else {
        Verdict::Undecided {
            bits_tried: 0,
            witnesses,
        }
    }
}
