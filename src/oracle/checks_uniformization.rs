//! Registry entries of the uniformization checks T24 (a solution exists, certified for the
//! case's own metric), T25 (two certified solutions from different starts agree up to a
//! constant per component) and T26 (the solve's Ptolemy flips commute with scaling,
//! exactly), and the fixed data they use: the targets of [`uniform_targets`] and the
//! second start of [`second_start`].
//!
//! T24 and T25 solve in `f64` on the case's lengths rounded to binary64, then refine and
//! certify on the case's *exact* metric flipped to `T₀` in MPFR and in intervals
//! ([`input_on_t0`], B71, B73), at the check's precision: 53 bits at `f64`, 106 at `dd`,
//! `p` at MPFR-`p`. They have no `exact` row. T26 has only the `exact` row: exact in ℚ
//! for rational input lengths on `T₀`, on 256-bit enclosures otherwise (numerical `holds`,
//! certified `fails` only for disjoint enclosures).

use super::check_entry::Check;
use super::precision::Prec;
use crate::io::{Metric, Surface};
use crate::scalar::{Interval, Mpfr, Precision};
use crate::theorems::t24_uniformization_exists::{check_existence_on, Existence};
use crate::theorems::t25_uniformization_unique::{check_uniqueness_on, Certified2};
use crate::theorems::t26_flips_keep_metric::{check_flip_path_enclosed, check_flip_path_exact};
use crate::theorems::{Settings, Verdict, Witness};
use crate::uniformization::certificate::T0Metric;
use crate::uniformization::components::Components;
use crate::uniformization::input_metric::input_on_t0;
use crate::uniformization::{
    uniformize, Targets, Uniformization, UniformizeError, UniformizeOptions,
};
use rug::Rational;

/// Faces above which T24–T26 answer `NotApplicable`: each runs the Newton solve, T24 and
/// T25 an MPFR refinement and an interval certificate (two of each for T25), T26 an exact
/// replay whose bit sizes grow with the flips.
pub const MAX_FACES: usize = 5_000;

/// Bits above which T24 and T25 answer `NotApplicable` (the refinement's residuals and
/// the certificate's enclosures are computed at the check's precision).
pub const MAX_BITS: u32 = 1024;

/// The targets of the registry checks: on each component `C` with `n_C` vertices
/// `v_0 < … < v_{m−1}`, the curvature `2πχ(C)` spread evenly plus a fixed irregular
/// redistribution, `Θ_{v_i}/π = 2 − 2χ(C)/n_C + r_{v_i} − r_{v_{i+1 mod m}}` with
/// `r_v = ((5v + 1) mod 7)/(50·n_C)` (exact; Gauss–Bonnet holds on every component since the
/// differences telescope). The redistribution breaks the symmetry of the corpus solids,
/// whose solutions for even targets have Delaunay ties (cocircular squares: no box lies in
/// one Penner cell, B71). `None` when a target would not be positive.
pub fn uniform_targets(case: &Surface) -> Option<Targets> {
    let comps = Components::of(&case.mesh);
    let mut q = vec![Rational::new(); case.mesh.n_vertices()];
    for c in 0..comps.roots.len() {
        let vs: Vec<usize> = comps.vertices_of(c).collect();
        let n = vs.len() as i64;
        let chi = comps.euler_characteristic(&case.mesh, c);
        let base = Rational::from(2) - Rational::from((2 * chi, n));
        let r = |v: usize| Rational::from((((5 * v + 1) % 7) as i64, 50 * n));
        for (i, &v) in vs.iter().enumerate() {
            let t = Rational::from(&base + &r(v)) - r(vs[(i + 1) % vs.len()]);
            if t <= 0 {
                return None;
            }
            q[v] = t;
        }
    }
    Some(Targets::from_multiples_of_pi(q))
}

/// The second start of T25: `u_v = ((7v + 3) mod 11 − 5)/10 ∈ [−½, ½]`.
pub fn second_start(n: usize) -> Vec<f64> {
    (0..n)
        .map(|v| (((7 * v + 3) % 11) as f64 - 5.0) / 10.0)
        .collect()
}

/// Everything T24 and T25 need from a case, or the verdict that ends the check.
pub struct Prepared {
    /// The case's lengths rounded to binary64 (what the solve sees).
    pub lengths: Vec<f64>,
    /// The targets ([`uniform_targets`]).
    pub targets: Targets,
    /// MPFR precision of the refinement and the certificate.
    pub prec: Precision,
}

fn not_applicable(reason: String) -> Verdict {
    Verdict::NotApplicable { reason }
}

fn undecided(bits: u32, detail: String) -> Verdict {
    Verdict::Undecided {
        bits_tried: bits,
        witnesses: vec![Witness {
            element: "surface".into(),
            detail,
            value: f64::NAN,
        }],
    }
}

/// The common prologue: closed surface, size and precision limits, targets. `None` at
/// `exact` (no row); `Some(Err(verdict))` when the check does not apply.
pub fn prepare(case: &Surface, prec: Prec) -> Option<Result<Prepared, Verdict>> {
    let bits = match prec {
        Prec::Exact => return None,
        p => p.bits().max(53),
    };
    Some(prepare_at(case, bits))
}

fn prepare_at(case: &Surface, bits: u32) -> Result<Prepared, Verdict> {
    if !case.mesh.is_closed() {
        return Err(not_applicable(
            "uniformization with prescribed cone angles is stated for closed surfaces".into(),
        ));
    }
    if case.mesh.n_faces() > MAX_FACES {
        return Err(not_applicable(format!(
            "{} faces: this check runs on surfaces up to {MAX_FACES} faces",
            case.mesh.n_faces()
        )));
    }
    if bits > MAX_BITS {
        return Err(not_applicable(format!(
            "{bits} bits: this check runs up to {MAX_BITS} bits"
        )));
    }
    let Some(targets) = uniform_targets(case) else {
        return Err(not_applicable(
            "a component has too few vertices for positive even targets".into(),
        ));
    };
    let prec =
        Precision::new(u64::from(bits)).map_err(|e| not_applicable(format!("precision: {e}")))?;
    Ok(Prepared {
        lengths: case.lengths::<f64>(()),
        targets,
        prec,
    })
}

/// The case's exact metric on the `T₀` of `sol`, at `prec` ([`input_on_t0`]).
pub fn input_metric(
    case: &Surface,
    lengths: &[f64],
    prec: Precision,
    sol: &Uniformization,
) -> Result<T0Metric, String> {
    input_on_t0(
        sol,
        &case.mesh,
        lengths,
        case.lengths::<Mpfr>(prec),
        case.lengths::<Interval<Mpfr>>(prec),
    )
}

/// The refinement's stopping tolerance at `bits`: `2^(8 − bits)` (the refinement also
/// stops at its precision's floor).
pub fn tolerance(bits: u32) -> f64 {
    2f64.powi(8 - bits as i32)
}

/// A solver error as the check's verdict: targets the case does not admit are not
/// applicable; anything else (e.g. an input not certified Delaunay after flipping) is
/// undecided.
fn from_error(e: &UniformizeError, bits: u32) -> Verdict {
    match e {
        UniformizeError::GaussBonnet { .. }
        | UniformizeError::NonPositiveTarget { .. }
        | UniformizeError::TargetCount { .. } => not_applicable(e.to_string()),
        _ => undecided(bits, e.to_string()),
    }
}

/// T24 on `case` at `prec`: the existence outcome, or the verdict that ends the check.
pub fn t24_existence(case: &Surface, prec: Prec) -> Option<Result<Existence, Verdict>> {
    let p = match prepare(case, prec)? {
        Ok(p) => p,
        Err(v) => return Some(Err(v)),
    };
    let bits = p.prec.bits();
    let input = |sol: &Uniformization| input_metric(case, &p.lengths, p.prec, sol);
    Some(
        check_existence_on(
            &case.mesh,
            &p.lengths,
            &p.targets,
            bits,
            tolerance(bits),
            Some(&input),
        )
        .map_err(|e| from_error(&e, bits)),
    )
}

fn t24(case: &Surface, prec: Prec, _: &Settings) -> Option<Verdict> {
    Some(match t24_existence(case, prec)? {
        Ok(ex) => ex.verdict,
        Err(v) => v,
    })
}

/// T25 on `case` at `prec`: the verdict and the two certified solutions, or the verdict
/// that ends the check.
pub fn t25_pair(case: &Surface, prec: Prec) -> Option<Result<(Verdict, Certified2), Verdict>> {
    let p = match prepare(case, prec)? {
        Ok(p) => p,
        Err(v) => return Some(Err(v)),
    };
    let bits = p.prec.bits();
    let input = |sol: &Uniformization| input_metric(case, &p.lengths, p.prec, sol);
    Some(
        check_uniqueness_on(
            &case.mesh,
            &p.lengths,
            &p.targets,
            second_start(case.mesh.n_vertices()),
            bits,
            tolerance(bits),
            Some(&input),
        )
        .map_err(|e| from_error(&e, bits)),
    )
}

fn t25(case: &Surface, prec: Prec, _: &Settings) -> Option<Verdict> {
    Some(match t25_pair(case, prec)? {
        Ok((v, _)) | Err(v) => v,
    })
}

/// The case's lengths on `T₀` for T26.
pub enum T0Lengths {
    /// Exact: rational lengths and no Euclidean flip.
    Exact(Vec<Rational>),
    /// Enclosed at [`T26_BITS`] (irrational lengths, or Euclidean flips, B73).
    Enclosed(Vec<Interval<Mpfr>>),
    /// Not available, with the reason.
    Unavailable(String),
}

/// Interval precision of T26 on irrational input lengths.
pub const T26_BITS: u32 = 256;

/// The data of T26 on a case: the `f64` solve, the exact scale factors
/// `s_v = e^{u_v/2}` (binary64, taken exactly), and the case's lengths of `T₀`.
pub struct FlipPath {
    /// The solve.
    pub sol: Uniformization,
    /// The scale factors.
    pub s: Vec<Rational>,
    /// The case's lengths on `T₀`.
    pub t0: T0Lengths,
}

/// T26's data, or the verdict that ends the check; `None` except at `exact`.
pub fn t26_path(case: &Surface, prec: Prec) -> Option<Result<FlipPath, Verdict>> {
    if prec != Prec::Exact {
        return None;
    }
    let p = match prepare_at(case, 53) {
        Ok(p) => p,
        Err(v) => return Some(Err(v)),
    };
    let sol = match uniformize(
        &case.mesh,
        &p.lengths,
        &p.targets,
        &UniformizeOptions::default(),
    ) {
        Ok(s) => s,
        Err(e) => return Some(Err(from_error(&e, 0))),
    };
    let Some(s) = sol
        .u
        .iter()
        .map(|&x| Rational::from_f64((0.5 * x).exp()))
        .collect::<Option<Vec<_>>>()
    else {
        return Some(Err(undecided(0, "a scale factor is not finite".into())));
    };
    let t0 = match &case.metric {
        Metric::Lengths(l) if sol.euclidean_flips == 0 => T0Lengths::Exact(l.clone()),
        _ => {
            let prec = Precision::new(u64::from(T26_BITS)).expect("in range");
            match input_metric(case, &p.lengths, prec, &sol) {
                Ok(m) => T0Lengths::Enclosed(m.enclosures),
                Err(reason) => T0Lengths::Unavailable(reason),
            }
        }
    };
    Some(Ok(FlipPath { sol, s, t0 }))
}

/// The replay of T26 with scale factors `s` before and `t` after the flips, on the case's
/// lengths of `T₀`: exactly when they are rational, on enclosures otherwise
/// ([`check_flip_path_enclosed`]: a failure only for disjoint enclosures).
pub fn t26_replay(path: &FlipPath, t: &[Rational]) -> Verdict {
    let sol = &path.sol;
    match &path.t0 {
        T0Lengths::Exact(l) => check_flip_path_exact(
            &sol.initial_mesh,
            l.clone(),
            &sol.flip_sequence,
            &sol.mesh,
            &path.s,
            t,
        ),
        T0Lengths::Enclosed(l) => check_flip_path_enclosed(
            &sol.initial_mesh,
            l.clone(),
            &sol.flip_sequence,
            &sol.mesh,
            &path.s,
            t,
        ),
        T0Lengths::Unavailable(reason) => undecided(0, reason.clone()),
    }
}

fn t26(case: &Surface, prec: Prec, _: &Settings) -> Option<Verdict> {
    Some(match t26_path(case, prec)? {
        Ok(path) => t26_replay(&path, &path.s),
        Err(v) => v,
    })
}

/// The entries, in catalogue order.
pub fn entries() -> Vec<Check> {
    vec![
        Check {
            id: "T24",
            title: "uniformization exists (certified)",
            run: t24,
        },
        Check {
            id: "T25",
            title: "uniformization unique up to scale",
            run: t25,
        },
        Check {
            id: "T26",
            title: "flips along uniformization keep metric",
            run: t26,
        },
    ]
}
