//! `E`, `∇E = Θ − θ` and the cotan Hessian at MPFR precision `p` from one pass over the
//! faces: the formulas of [`super::fast_f64`] (proofs/B88) with every operation of `rug`
//! rounded to nearest at `p` bits, each corner angle computed once (the largest as
//! `π − α_a − α_b`), the cotangents from the squared sides over `r = 4·Area` (no
//! transcendental function), each half angle `atan τ` with `τ < 1` (the two smaller
//! corners) from a table arctangent at `p + 16 ≤ 1040` bits (proofs/B101), any other from a
//! binary64 seed and one `sin_cos` at `p + 8` bits (proofs/B29), and `Л` at `p + 16` bits
//! with a table logarithm (proofs/B100).
//!
//! Half angle: with `φ₀ = atan(fl₆₄(τ))` (a binary64 number, exact in MPFR), `s = sin φ₀`,
//! `c = cos φ₀`, the identity `atan τ = φ₀ + atan ρ`, `ρ = (τc − s)/(c + τs) = tan(atan τ − φ₀)`
//! holds for every `τ > 0`; `|ρ| < 2⁻⁴⁰` for the seed, so `atan ρ = ρ − ρ³/3 + ρ⁵/5 − …` needs
//! a handful of terms, chosen from the exponents of `ρ` and `φ₀`. Outside the binary64 range
//! of the seed (`τ` below `2⁻¹⁰⁰⁰` or above `2¹⁰⁰⁰`), past 2048 bits, or with a seed off by
//! more than `2⁻²⁰`, MPFR's `atan` is used instead. Either way, and by the table, the half
//! angle is within `1.02·2⁻ᵖ` relative (B29, B101), inside B88's allowance of 2 ulps for
//! `atan`.
//!
//! The result is numerical, not certified: it differs from the generic
//! [`energy_gradient_hessian_with`](super::energy::energy_gradient_hessian_with) at MPFR-p by
//! rounding, within B88's first-order bound read with `u = 2⁻ᵖ` (B29).
//!
//! Consumer: T32 (`theorems::t32_energy::verify_one_pass`, through the `OnePass` impl for
//! [`Mpfr`]) checks this pass against the generic evaluation within that bound, as a second
//! formula inside `penner check`.
//!
//! ```
//! use penner::mesh::Mesh;
//! use penner::scalar::{Mpfr, Precision, Real};
//! use penner::variational::fast_mpfr::energy_gradient_hessian_mpfr;
//! use penner::variational::pattern::HessianPattern;
//! // Two equilateral triangles glued into a sphere: cone angles 2π/3, gradient 0.
//! let m = Mesh::from_faces(3, &[[0, 1, 2], [0, 2, 1]]).unwrap();
//! let p = Precision::new(256).unwrap();
//! let zero = vec![Mpfr::from_f64(0.0, p); 3];
//! let t = vec![Mpfr::pi(p) * &Mpfr::from_f64(2.0, p) / Mpfr::from_f64(3.0, p); 3];
//! let parts = energy_gradient_hessian_mpfr(&HessianPattern::new(&m), &m, &zero, &zero, &t);
//! assert!(parts.gradient.iter().all(|g| g.approx_f64().abs() < 1e-70));
//! ```

use super::energy::{close_parts, EnergyParts};
use super::pattern::HessianPattern;
use crate::geometry::laplacian::SparseMatrix;
use crate::mesh::Mesh;
use crate::scalar::Mpfr;
use crate::special::MpfrLobachevsky;
use rug::float::Constant;
use rug::Float;
use std::cmp::Ordering;

/// One face's share of `E`, `∇E` and the Hessian at MPFR precision (module doc).
#[derive(Clone, Debug, PartialEq)]
pub struct FaceMpfr {
    /// The angles `α_m` opposite the sides `m` (NaN when a side is NaN).
    pub angles: [Mpfr; 3],
    /// `cot α_m` for a proper face, `None` for a degenerate or undecided one.
    pub cot: Option<[Mpfr; 3]>,
    /// The face's term `2f(x) − (π/2)(x₀ + x₁ + x₂)` of `E`.
    pub energy: Mpfr,
    /// `Л(α_m)` (0 for a degenerate face).
    pub lobachevsky: [Mpfr; 3],
}

/// Largest precision for the seeded half angle; beyond it the `atan ρ` series would need
/// more terms than MPFR's `atan` costs.
const SEEDED_MAX_BITS: u32 = 2048;

/// Extra bits of the seeded half angle's intermediate values (proof: B29).
const SEEDED_GUARD_BITS: u32 = 8;

/// `atan τ` for `τ > 0` at `p` bits, to nearest within `1.02·2⁻ᵖ` relative (module doc,
/// proofs/B29): binary64 seed, one `sin_cos` and a short series in `ρ`; MPFR's `atan`
/// outside the seed's range.
pub fn half_angle_atan(tau: &Float, p: u32) -> Float {
    let fallback = || Float::with_val(p, tau.atan_ref());
    let tf = tau.to_f64();
    if p > SEEDED_MAX_BITS || !(tf > 1e-300 && tf < 1e300) {
        return fallback();
    }
    let w = p + SEEDED_GUARD_BITS;
    let phi0 = tf.atan();
    let (s, c) = Float::with_val(w, phi0).sin_cos(Float::new(w));
    // ρ = (τc − s)/(c + τs) = tan(atan τ − φ₀).
    let mut num = Float::with_val(w, tau * &c);
    num -= &s;
    let mut den = Float::with_val(w, tau * &s);
    den += &c;
    let rho = Float::with_val(w, &num / &den);
    let (Some(e_rho), Some(e_phi)) = (rho.get_exp(), Float::with_val(53, phi0).get_exp()) else {
        // ρ = 0: the seed is the half angle to w bits.
        return Float::with_val(p, phi0);
    };
    // The seed must be within 2⁻¹⁹ of atan τ, relatively (B29); libm's atan is far better.
    if e_rho > e_phi - 20 {
        return fallback();
    }
    // Terms ρ^(2j+1)/(2j+1), j < J: the first omitted one is below 2^(e_ρ(2J+1)), which is
    // at most 2^(e_φ − w − 4) ≤ 2^(−w−2)·|atan τ| (|atan τ| > 2^(e_φ − 2)).
    let need = i64::from(w) + 4 - i64::from(e_phi);
    let per = -i64::from(e_rho);
    let odd = (need + per - 1) / per; // ⌈need / per⌉ ≥ 2J + 1
    let terms = ((odd.max(1) - 1) / 2 + 1) as u32;
    let rho2 = Float::with_val(w, rho.square_ref());
    let mut pow = rho.clone();
    let mut series = rho.clone();
    for j in 1..terms {
        pow *= &rho2;
        let term = Float::with_val(w, &pow / (2 * j + 1));
        if j % 2 == 1 {
            series -= &term;
        } else {
            series += &term;
        }
    }
    Float::with_val(p, &series + phi0)
}

/// The half angle `atan τ` at `p` bits in the pass: from the table arctangent at `p + 16`
/// bits rounded once when `τ < 1` (proof: B101), else by [`half_angle_atan`] (B29); both
/// within `1.02·2⁻ᵖ` relative.
fn half_angle_in_pass(tau: &Float, p: u32, lob: &MpfrLobachevsky) -> Float {
    match lob.elementary().and_then(|t| t.atan(tau)) {
        Some(a) => Float::with_val(p, &a),
        None => half_angle_atan(tau, p),
    }
}

/// The index of the largest `x_m` (the last one among equal maxima), or `None` when one is
/// NaN.
fn longest(x: &[&Float; 3]) -> Option<usize> {
    let mut s = 0;
    for m in 1..3 {
        match x[m].partial_cmp(x[s])? {
            Ordering::Less => {}
            _ => s = m,
        }
    }
    Some(s)
}

/// [`FaceMpfr`] of the face with logarithmic lengths `x` (all at the same precision),
/// with `π` and `π/2` at that precision (module doc).
pub fn face_mpfr(x: &[Mpfr; 3], pi: &Float, half_pi: &Float) -> FaceMpfr {
    let lob = MpfrLobachevsky::for_energy_pass(x[0].0.prec());
    face_with(&x.each_ref().map(|v| &v.0), pi, half_pi, &lob)
}

/// [`face_mpfr`] on borrowed lengths with `Л` at hand (the pass's inner step).
fn face_with(x: &[&Float; 3], pi: &Float, half_pi: &Float, lob: &MpfrLobachevsky) -> FaceMpfr {
    let p = x[0].prec();
    let nan = || Mpfr(Float::with_val(p, f64::NAN));
    let zero = || Mpfr(Float::new(p));
    let Some(s) = longest(x) else {
        return FaceMpfr {
            angles: [nan(), nan(), nan()],
            cot: None,
            energy: nan(),
            lobachevsky: [nan(), nan(), nan()],
        };
    };
    let d = [0, 1, 2].map(|m| Float::with_val(p, x[m] - x[s]));
    // The same side lengths as the generic path (`exp((x_m − x_s)·½)`, `ℓ_s = 1`).
    let l = [0, 1, 2].map(|m| {
        if m == s {
            Float::with_val(p, 1)
        } else {
            let mut v = Float::with_val(p, &d[m] >> 1u32);
            v.exp_mut();
            v
        }
    });
    let e = [0, 1, 2].map(|m| {
        let mut v = Float::with_val(p, &l[(m + 1) % 3] + &l[(m + 2) % 3]);
        v -= &l[m];
        v
    });
    // 2f − (π/2)Σx = Σ(α − π/2)d − (π/2)x_s + 2ΣЛ (d_s = 0: the term k = s vanishes).
    let energy_of = |angles: &[Float; 3], lob_sum: &Float| -> Float {
        let mut en = Float::with_val(p, half_pi * x[s]);
        en = -en;
        for k in 0..3 {
            if k != s {
                let mut a = Float::with_val(p, &angles[k] - half_pi);
                a *= &d[k];
                en += &a;
            }
        }
        let mut twice = lob_sum.clone();
        twice <<= 1u32;
        en + &twice
    };
    if let Some(m) = (0..3).find(|&m| e[m].cmp0() != Some(Ordering::Greater) && !e[m].is_nan()) {
        let mut angles = [Float::new(p), Float::new(p), Float::new(p)];
        angles[m].clone_from(pi);
        // Л(0) = Л(π) = 0.
        let en = energy_of(&angles, &Float::new(p));
        return FaceMpfr {
            angles: angles.map(Mpfr),
            cot: None,
            energy: Mpfr(en),
            lobachevsky: [zero(), zero(), zero()],
        };
    }
    if e.iter().any(Float::is_nan) {
        return FaceMpfr {
            angles: [nan(), nan(), nan()],
            cot: None,
            energy: nan(),
            lobachevsky: [nan(), nan(), nan()],
        };
    }
    let mut sigma = Float::with_val(p, &l[0] + &l[1]);
    sigma += &l[2];
    let mut r = Float::with_val(p, &sigma * &e[0]);
    r *= &e[1];
    r *= &e[2];
    r.sqrt_mut();
    let (a, b) = ((s + 1) % 3, (s + 2) % 3);
    let half = |m: usize| -> Float {
        let mut den = Float::with_val(p, &sigma * &e[m]);
        den.recip_mut();
        den *= &r;
        let mut ang = half_angle_in_pass(&den, p, lob);
        ang <<= 1u32;
        ang
    };
    let mut angles = [Float::new(p), Float::new(p), Float::new(p)];
    angles[a] = half(a);
    angles[b] = half(b);
    let mut big = Float::with_val(p, pi - &angles[a]);
    big -= &angles[b];
    angles[s] = big;
    let lob = [0, 1, 2].map(|m| lob.eval(&angles[m]));
    let mut lob_sum = Float::with_val(p, &lob[0] + &lob[1]);
    lob_sum += &lob[2];
    let sq = l.clone().map(|mut v| {
        v.square_mut();
        v
    });
    let cot = [0, 1, 2].map(|m| {
        let mut v = Float::with_val(p, &sq[(m + 1) % 3] + &sq[(m + 2) % 3]);
        v -= &sq[m];
        v /= &r;
        Mpfr(v)
    });
    let energy = energy_of(&angles, &lob_sum);
    FaceMpfr {
        angles: angles.map(Mpfr),
        cot: Some(cot),
        energy: Mpfr(energy),
        lobachevsky: lob.map(Mpfr),
    }
}

/// `E`, `∇E = Θ − θ` and the Hessian `−L` at the precision of `lt` from the scaled
/// logarithmic lengths `λ̃`, `u` and the targets `Θ` (all at one precision), on a pattern
/// built once for `mesh`: faces in face order, each by [`face_mpfr`]; `θ` accumulated per
/// corner, `½ cot α_m` added in place. Numerical (proofs/B29), the MPFR counterpart of
/// [`energy_gradient_hessian_f64`](super::fast_f64::energy_gradient_hessian_f64).
///
/// A pattern of another mesh, or values of different precisions, are programming errors:
/// they panic ([`HessianPattern::fits`], [`Mpfr`]'s precision check).
pub fn energy_gradient_hessian_mpfr(
    pattern: &HessianPattern,
    mesh: &Mesh,
    lt: &[Mpfr],
    u: &[Mpfr],
    targets: &[Mpfr],
) -> EnergyParts<Mpfr> {
    assert!(pattern.fits(mesh), "Hessian pattern of another mesh");
    let Some(z) = lt.first().or(u.first()) else {
        return EnergyParts {
            energy: None,
            gradient: targets.to_vec(),
            hessian: SparseMatrix::from_triplets(mesh.n_vertices(), &[]),
        };
    };
    let p = z.0.prec();
    let pi = Float::with_val(p, Constant::Pi);
    let half_pi = Float::with_val(p, &pi >> 1u32);
    let zero = Mpfr(Float::new(p));
    let mut energy = zero.clone();
    let mut theta = vec![zero.clone(); mesh.n_vertices()];
    let mut val = pattern.zeros(&zero);
    let mut w = zero.clone();
    let lob = MpfrLobachevsky::for_energy_pass(p);
    for f in mesh.faces() {
        let hs = mesh.face_halfedges(f);
        let x = hs.map(|h| &lt[h.edge().idx()].0);
        let t = face_with(&x, &pi, &half_pi, &lob);
        energy += &t.energy;
        for m in 0..3 {
            // The corner opposite side m is at the tail of side m + 2.
            theta[mesh.tail(hs[(m + 2) % 3]).idx()] += &t.angles[m];
        }
        if let Some(c) = &t.cot {
            for m in 0..3 {
                // ½ cot α_m, exact.
                rug::Assign::assign(&mut w.0, &c[m].0);
                w.0 >>= 1u32;
                pattern.add_side(mesh, &mut val, hs[m], &w);
            }
        }
    }
    close_parts(
        energy,
        theta,
        !lt.is_empty(),
        u,
        targets,
        pattern.matrix(val),
    )
}
