//! Registry entries of the variational checks T06 (cotan weights determine the metric),
//! T31 (Schläfli), T32 (the uniformization
//! energy on the case's triangulation) and T33 (its hyperbolic analogue, reading the case's
//! lengths as hyperbolic lengths), and the fixed data they use: log scale factors
//! `u_v = 2 log s_v` from [`scale_factors`], targets `Θ_v = 2π`, and the directions of
//! [`directions`].

// The `at_precision!` bodies are generic code that is also instantiated at `f64`.
#![allow(clippy::clone_on_copy, clippy::op_ref, clippy::let_unit_value)]

use super::check_entry::scale_factors;
use super::check_entry::Check;
use super::precision::Prec;
use crate::io::Surface;
use crate::scalar::Real;
use crate::theorems::t32_energy::{check_energy, EnergyInput};
use crate::theorems::{t06_cotan_weights_metric, t31_schlafli, t33_hyperbolic, Settings, Verdict};

/// `u_v = 2 log s_v` for the exact scale factors `s_v ∈ [9/10, 11/10]` of
/// [`scale_factors`] (so `e^{u_v/2} = s_v`), in the context of `like`.
pub fn log_scale_factors<T: Real>(n: usize, like: &T) -> Vec<T> {
    scale_factors(n)
        .iter()
        .map(|s| T::from_rational(s, like.ctx()).ln() * &like.lit(2.0))
        .collect()
}

/// Targets `Θ_v = 2π` (any targets do: the identities of T32 and T33 hold for all).
pub fn flat_targets<T: Real>(n: usize, like: &T) -> Vec<T> {
    vec![T::pi(like.ctx()) * &like.lit(2.0); n]
}

/// The probe of T32, T33 and their controls on `n` vertices, in the context of `like`:
/// the log scale factors `u` ([`log_scale_factors`]), flat targets `Θ`
/// ([`flat_targets`]) and the directions `d` ([`directions`]).
#[allow(clippy::type_complexity)]
pub fn energy_probe<T: Real>(n: usize, like: &T) -> (Vec<T>, Vec<T>, Vec<Vec<T>>) {
    (
        log_scale_factors(n, like),
        flat_targets(n, like),
        directions(n, like),
    )
}

/// Three fixed directions in `ℝⁿ`: `e_0` (so a perturbed `∂E/∂u_0` is seen) and two
/// irregular patterns `((7v + 5k) mod 11 − 5)/5`, `k = 1, 2`.
pub fn directions<T: Real>(n: usize, like: &T) -> Vec<Vec<T>> {
    let mut out = vec![(0..n)
        .map(|v| like.lit(if v == 0 { 1.0 } else { 0.0 }))
        .collect::<Vec<T>>()];
    for k in 1..=2 {
        out.push(
            (0..n)
                .map(|v| like.lit((((7 * v + 5 * k) % 11) as f64 - 5.0) / 5.0))
                .collect(),
        );
    }
    out
}

/// The most vertices each pattern direction of [`bounded_directions`] moves.
pub const T32_SUPPORT: usize = 64;

/// T32's directions: those of [`directions`] with each pattern kept on at most
/// [`T32_SUPPORT`] vertices spread over the index range (`v ≡ 0 mod ⌈n/64⌉`) and 0
/// elsewhere, so that T32's costly parts run on the faces touching the support
/// (proofs/B32); up to 64 vertices they are [`directions`].
pub fn bounded_directions<T: Real>(n: usize, like: &T) -> Vec<Vec<T>> {
    let stride = n.div_ceil(T32_SUPPORT).max(1);
    let mut out = directions(n, like);
    for d in out.iter_mut().skip(1) {
        for (v, x) in d.iter_mut().enumerate() {
            if v % stride != 0 {
                *x = like.zero_like();
            }
        }
    }
    out
}

/// Faces up to which a check runs, per backend (proofs/B32): `Л` and its derivative run
/// without MPFR at `f64` and `Dd` (B30, B53, B55), each MPFR row evaluates its series at
/// `p/2 + 4` terms per call.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FaceCaps {
    /// At `f64`.
    pub f64: usize,
    /// At `Dd`.
    pub dd: usize,
    /// At MPFR (and exact, where a check has that form).
    pub mpfr: usize,
    /// What costs the time, for the `NotApplicable` reason.
    pub why: &'static str,
}

impl FaceCaps {
    /// The cap at precision `prec`.
    pub fn at(&self, prec: Prec) -> usize {
        match prec {
            Prec::F64 => self.f64,
            Prec::Dd => self.dd,
            _ => self.mpfr,
        }
    }
}

/// T31: nine dual `Л` per face (costs measured in proofs/B32).
pub const T31_CAPS: FaceCaps = FaceCaps {
    f64: 1_000_000,
    dd: 200_000,
    mpfr: 20_000,
    why: "nine dual Lobachevsky series per face",
};

/// T32: one pass per part over every face at the working precision (`∇E`, the Hessian,
/// the convexity Hessians); the dual derivatives and the difference enclosure on
/// `Interval<Mpfr>` at twice the precision run on the faces its bounded directions touch
/// (costs in proofs/B32).
pub const T32_CAPS: FaceCaps = FaceCaps {
    f64: 500_000,
    dd: 100_000,
    mpfr: 10_000,
    why: "one pass per part over every face, the convexity Hessians at five points",
};

/// T33: dual hyperbolic angles (`Dd` time goes to its `exp`) and `Л` per face (costs in
/// proofs/B32).
pub const T33_CAPS: FaceCaps = FaceCaps {
    f64: 1_000_000,
    dd: 50_000,
    mpfr: 2_000,
    why: "dual hyperbolic angles and Lobachevsky series per face",
};

/// Precision (bits) above which T06 and T31–T33 answer `NotApplicable`: the Lobachevsky
/// series has `p/2 + 4` terms and T32's central difference runs at `2p` bits.
pub const MAX_BITS: u32 = 512;

/// `NotApplicable` past the cap of `caps` at `prec` or past [`MAX_BITS`] bits, naming
/// the limit.
pub fn beyond_caps(case: &Surface, prec: Prec, caps: &FaceCaps) -> Option<Verdict> {
    let cap = caps.at(prec);
    if case.mesh.n_faces() > cap {
        return Some(Verdict::NotApplicable {
            reason: format!(
                "{} faces: at {prec} this check runs on surfaces up to {cap} faces ({})",
                case.mesh.n_faces(),
                caps.why
            ),
        });
    }
    beyond_limits(case, prec, usize::MAX)
}

/// `NotApplicable` past `max_faces` faces or [`MAX_BITS`] bits, naming the limit.
pub fn beyond_limits(case: &Surface, prec: Prec, max_faces: usize) -> Option<Verdict> {
    let bits = match prec {
        Prec::Mpfr(p) => p.bits(),
        _ => 0,
    };
    if case.mesh.n_faces() > max_faces {
        return Some(Verdict::NotApplicable {
            reason: format!(
                "{} faces: this check runs on surfaces up to {max_faces} faces",
                case.mesh.n_faces()
            ),
        });
    }
    (bits > MAX_BITS).then(|| Verdict::NotApplicable {
        reason: format!("{bits} bits: this check runs up to {MAX_BITS} bits"),
    })
}

/// T06: the per-face Hessian enclosure at `2p + 64` bits and one sparse verified Cholesky
/// factorization per shift (proofs/B102; costs measured there); its control T06-NC, the
/// weight enclosures at `4p + 64` bits (B31).
pub const T06_CAPS: FaceCaps = FaceCaps {
    f64: 200_000,
    dd: 200_000,
    mpfr: 200_000,
    why: "per-face Hessian enclosures and a sparse verified Cholesky factorization",
};

fn t06(case: &Surface, prec: Prec, s: &Settings) -> Option<Verdict> {
    if let Some(v) = beyond_caps(case, prec, &T06_CAPS) {
        return Some(v);
    }
    at_precision!(prec, case, |l: T| Some(
        t06_cotan_weights_metric::check_weights_determine_metric(&case.mesh, &l, s)
    ))
}

fn t31(case: &Surface, prec: Prec, s: &Settings) -> Option<Verdict> {
    if let Some(v) = beyond_caps(case, prec, &T31_CAPS) {
        return Some(v);
    }
    at_precision!(prec, case, |l: T| Some(t31_schlafli::check_schlafli(
        &case.mesh, &l, s
    )))
}

fn t32(case: &Surface, prec: Prec, s: &Settings) -> Option<Verdict> {
    if let Some(v) = beyond_caps(case, prec, &T32_CAPS) {
        return Some(v);
    }
    at_precision!(prec, case, |l: T| {
        let n = case.mesh.n_vertices();
        let z = l.first()?;
        let (u, t) = (log_scale_factors(n, z), flat_targets(n, z));
        let d = bounded_directions(n, z);
        let input = EnergyInput {
            mesh: &case.mesh,
            lengths: &l,
            u: &u,
            targets: &t,
        };
        Some(check_energy(&input, &d, s))
    })
}

fn t33(case: &Surface, prec: Prec, s: &Settings) -> Option<Verdict> {
    if let Some(v) = beyond_caps(case, prec, &T33_CAPS) {
        return Some(v);
    }
    at_precision!(prec, case, |l: T| {
        let n = case.mesh.n_vertices();
        let z = l.first()?;
        let (u, t, d) = energy_probe(n, z);
        Some(t33_hyperbolic::check_hyperbolic(
            &case.mesh, &l, &u, &t, &d, s,
        ))
    })
}

/// The entries, in catalogue order.
pub fn entries() -> Vec<Check> {
    vec![
        Check {
            id: "T06",
            title: "cotan weights ⇒ metric up to scale",
            run: t06,
        },
        Check {
            id: "T31",
            title: "Schläfli: ∂f/∂λ = α/2",
            run: t31,
        },
        Check {
            id: "T32",
            title: "energy: ∇E = Θ−θ, H = cotan L",
            run: t32,
        },
        Check {
            id: "T33",
            title: "hyperbolic energy gradient",
            run: t33,
        },
    ]
}
