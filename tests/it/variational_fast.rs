//! The binary64 one-pass `E`, `∇E` and Hessian (`variational::fast_f64`, proofs/B88)
//! against the generic formulas at MPFR-128 (angles by the half-angle form per corner,
//! cotangents from Kahan's area, `Л` by the MPFR series): per face and assembled, within
//! twice the first-order bound of B88 computed from the binary64 values.

use crate::meshgen::{icosphere, jittered_torus, random_tetrahedron};
use crate::support::cases;
use penner::mesh::Mesh;
use penner::scalar::{Mpfr, Precision, Real};
use penner::variational::energy::{energy_gradient_hessian_at, log_lengths};
use penner::variational::fast_f64::{energy_gradient_hessian_f64, face_f64, FaceF64};
use penner::variational::fast_mpfr::{
    energy_gradient_hessian_mpfr, face_mpfr, half_angle_atan, FaceMpfr,
};
use penner::variational::pattern::HessianPattern;
use penner::variational::triangle::face_terms;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rug::Float;
use std::collections::HashMap;
use std::f64::consts::{FRAC_PI_2, PI};

/// The unit roundoff `2⁻⁵³`.
const U: f64 = 1.0 / 9007199254740992.0;

/// B88's safety factor over the first-order bound (second-order terms, rounding of the
/// bound and the MPFR-128 reference's own error).
const SAFETY: f64 = 2.0;

/// `|fast − reference|`, the difference taken exactly (at the sum of both precisions plus
/// room for the exponent gap, capped at 4096 bits: far below every bound compared).
fn err(fast: &Float, r: &Mpfr) -> f64 {
    let bits = (fast.prec() + r.0.prec() + 64).min(4096);
    Float::with_val(bits, &r.0 - fast).abs().to_f64()
}

/// One face of a one-pass kernel, at its own precision.
struct FastFace {
    angles: [Float; 3],
    cot: Option<[Float; 3]>,
    energy: Float,
    lobachevsky: [Float; 3],
}

impl FastFace {
    fn of_f64(t: &FaceF64) -> FastFace {
        let f = |v: f64| Float::with_val(53, v);
        FastFace {
            angles: t.angles.map(f),
            cot: t.cot.map(|c| c.map(f)),
            energy: f(t.energy),
            lobachevsky: t.lobachevsky.map(f),
        }
    }
    fn of_mpfr(t: &FaceMpfr) -> FastFace {
        let f = |v: &Mpfr| v.0.clone();
        FastFace {
            angles: [0, 1, 2].map(|k| f(&t.angles[k])),
            cot: t.cot.as_ref().map(|c| [0, 1, 2].map(|k| f(&c[k]))),
            energy: f(&t.energy),
            lobachevsky: [0, 1, 2].map(|k| f(&t.lobachevsky[k])),
        }
    }
    fn approx(v: &Float) -> f64 {
        v.to_f64()
    }
}

/// `E`, `∇E` and the Hessian's rows of a one-pass kernel, at its own precision.
type Assembled = (Float, Vec<Float>, Vec<Vec<(usize, Float)>>);

/// A whole pass: mesh, logarithmic lengths, `u` and targets in; `E`, `∇E`, Hessian rows out.
type Pass<'a> = dyn Fn(&Mesh, &[f64], &[f64], &[f64]) -> Assembled + 'a;

/// A one-pass kernel under test: its unit roundoff, the precision of the generic reference,
/// one face from its logarithmic lengths, and `E`, `∇E` and the Hessian's rows assembled.
struct Kernel<'a> {
    unit: f64,
    reference_bits: u32,
    face: &'a dyn Fn(&[f64; 3]) -> FastFace,
    all: &'a Pass<'a>,
}

/// B88 items 1–4 for one face with logarithmic lengths `x` and binary64 terms `t`: the
/// bound on each angle, on each cotangent and on the face's energy term.
struct FaceBound {
    angle: f64,
    cot: [f64; 3],
    energy: f64,
}

fn face_bound(x: &[f64; 3], t: &FastFace, unit: f64) -> FaceBound {
    let s = (0..3).max_by(|&a, &b| x[a].total_cmp(&x[b])).unwrap_or(0);
    let d = x.map(|v| v - x[s]);
    let xs = x[s].abs();
    let Some(cot) = t.cot.as_ref().map(|c| c.each_ref().map(FastFace::approx)) else {
        // Degenerate: angles 0 and the rounded π; f = Σ(α − π/2)d − (π/2)x_s.
        let sf: f64 = d.iter().map(|v| FRAC_PI_2 * v.abs()).sum::<f64>() + FRAC_PI_2 * xs;
        let energy =
            d.iter().map(|v| v.abs() * 12.0 * unit).sum::<f64>() + 7.0 * unit * sf + PI * unit * xs;
        return FaceBound {
            angle: 4.0 * unit,
            cot: [0.0; 3],
            energy,
        };
    };
    let l = d.map(|v| (0.5 * v).exp());
    let sigma = l[0] + l[1] + l[2];
    let kappa = [0, 1, 2].map(|m| sigma / (l[(m + 1) % 3] + l[(m + 2) % 3] - l[m]));
    let k_sum: f64 = kappa.iter().sum();
    let k_max = kappa.iter().copied().fold(0.0, f64::max);
    let c_sum: f64 = cot.iter().copied().map(f64::abs).sum();
    let rho = d
        .iter()
        .map(|v| unit * v.abs() / 2.0 + 4.0 * unit)
        .fold(0.0, f64::max);
    let small = unit * (k_sum / 2.0 + k_max + 17.0) + 2.0 * rho * c_sum;
    let angle = 2.0 * small + 10.0 * unit;
    let angles = t.angles.each_ref().map(FastFace::approx);
    let lob = t.lobachevsky.each_ref().map(FastFace::approx);
    let dl = angles.map(|a| (2.0 * a.sin()).ln().abs() * angle + 4.1 * unit);
    let sf: f64 = (0..3)
        .map(|m| ((angles[m] - FRAC_PI_2) * d[m]).abs() + 2.0 * lob[m].abs())
        .sum::<f64>()
        + FRAC_PI_2 * xs;
    let energy = d
        .iter()
        .map(|v| v.abs() * (angle + 8.0 * unit))
        .sum::<f64>()
        + 2.0 * dl.iter().sum::<f64>()
        + 7.0 * unit * sf
        + PI * unit * xs;
    let cot_b = cot.map(|c| {
        2.0 * unit * c_sum
            + c.abs() * unit * (k_sum / 2.0 + 7.0)
            + (1.0 + c * c) * 2.0 * rho * c_sum
    });
    FaceBound {
        angle,
        cot: cot_b,
        energy,
    }
}

/// The surfaces of the comparison: a tetrahedron, an icosphere and jittered tori, with
/// `λ̃ = λ + u_i + u_j` for random `u ∈ [−½, ½]` plus a common shift of up to ±300 (the
/// scale enters `E` through `x_s`). Returns the mesh, `λ̃`, `u` and targets `Θ`.
fn case(seed: u64) -> (Mesh, Vec<f64>, Vec<f64>, Vec<f64>) {
    let (m, l) = match seed % 3 {
        0 => {
            let e = random_tetrahedron(seed);
            let m = e.mesh();
            let l = e.lengths(&m);
            (m, l)
        }
        1 => {
            let e = icosphere(2);
            let m = e.mesh();
            let l = e.lengths(&m);
            (m, l)
        }
        _ => jittered_torus(9, 7, seed),
    };
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let n = m.n_vertices();
    let shift = 600.0 * (rng.r#gen::<f64>() - 0.5);
    let u: Vec<f64> = (0..n)
        .map(|_| rng.r#gen::<f64>() - 0.5 + shift / 2.0)
        .collect();
    let lambda = log_lengths(&l);
    let lt = m
        .edges()
        .map(|e| {
            let h = e.halfedge();
            lambda[e.idx()] + u[m.tail(h).idx()] + u[m.tip(h).idx()]
        })
        .collect();
    let t = (0..n).map(|_| 6.0 * rng.r#gen::<f64>()).collect();
    (m, lt, u, t)
}

/// Elements of a one-pass kernel's result outside `SAFETY ×` their B88 bound (read with the
/// kernel's unit roundoff, B29 for MPFR) against the generic evaluation at the kernel's
/// reference precision at `lt_ref` (`lt_ref = lt` for the comparison itself): per-face
/// angles, cotangents and energy terms, then `E`, every `∇E_i` and every stored Hessian
/// entry.
fn violations_of(
    k: &Kernel<'_>,
    m: &Mesh,
    lt: &[f64],
    lt_ref: &[f64],
    u: &[f64],
    t: &[f64],
) -> usize {
    let unit = k.unit;
    let p = Precision::new(u64::from(k.reference_bits)).unwrap();
    let hi = |v: &[f64]| -> Vec<Mpfr> { v.iter().map(|&x| Mpfr::from_f64(x, p)).collect() };
    let (lr, ur, tr) = (hi(lt_ref), hi(u), hi(t));
    let mut bad = 0;
    let mut e_bound = 0.0;
    let mut e_abs = 0.0;
    let mut theta_bound = vec![0.0; m.n_vertices()];
    let mut corners = vec![0.0; m.n_vertices()];
    // (i, j) ↦ (Σ ½Δcot, Σ |½cot|, contributions).
    let mut h_bound: HashMap<(usize, usize), (f64, f64, f64)> = HashMap::new();
    for f in m.faces() {
        let hs = m.face_halfedges(f);
        let x = hs.map(|h| lt[h.edge().idx()]);
        let tf = (k.face)(&x);
        let b = face_bound(&x, &tf, unit);
        let xr = hs.map(|h| lr[h.edge().idx()].clone());
        let rf = face_terms(&xr, true, true);
        if rf.cot.is_some() != tf.cot.is_some() {
            bad += 1;
            continue;
        }
        for j in 0..3 {
            bad += usize::from(err(&tf.angles[j], &rf.angles[j]) > SAFETY * b.angle);
            let v = m.tail(hs[(j + 2) % 3]).idx();
            theta_bound[v] += b.angle;
            corners[v] += 1.0;
        }
        let sum = xr[0].clone() + &xr[1] + &xr[2];
        let half_pi = Mpfr::pi(p) * &Mpfr::from_f64(0.5, p);
        let fr = rf.f.clone().unwrap() * &Mpfr::from_f64(2.0, p) - &(half_pi * &sum);
        bad += usize::from(err(&tf.energy, &fr) > SAFETY * b.energy);
        e_bound += b.energy;
        e_abs += tf.energy.to_f64().abs();
        if let (Some(c), Some(cr)) = (&tf.cot, &rf.cot) {
            for j in 0..3 {
                bad += usize::from(err(&c[j], &cr[j]) > SAFETY * b.cot[j]);
                let (i, l) = (m.tail(hs[j]).idx(), m.tip(hs[j]).idx());
                for key in [(i, i), (l, l), (i, l), (l, i)] {
                    let e = h_bound.entry(key).or_insert((0.0, 0.0, 0.0));
                    e.0 += 0.5 * b.cot[j];
                    e.1 += 0.5 * c[j].to_f64().abs();
                    e.2 += 1.0;
                }
            }
        }
    }
    let (energy, gradient, rows) = (k.all)(m, lt, u, t);
    let reference = energy_gradient_hessian_at(m, &lr, &ur, &tr);
    // E: faces, then Σ Θ_i u_i, recursive summation (B41).
    let tu: f64 = t.iter().zip(u).map(|(a, b)| (a * b).abs()).sum();
    let n_terms = (m.n_faces() + m.n_vertices()) as f64;
    let eb = e_bound + n_terms * unit * (e_abs + tu) + unit * tu;
    bad += usize::from(err(&energy, reference.energy.as_ref().unwrap()) > SAFETY * eb);
    for (i, (g, gr)) in gradient.iter().zip(&reference.gradient).enumerate() {
        // Corner sums (B41: (corners − 1)·u·θ), then Θ − θ rounded once.
        let gf = g.to_f64();
        let gb = theta_bound[i] + corners[i] * unit * (t[i] - gf).abs() + unit * gf.abs();
        bad += usize::from(err(g, gr) > SAFETY * gb);
    }
    for (i, row) in rows.iter().enumerate() {
        for (j, v) in row {
            let r = reference
                .hessian
                .get(i, *j)
                .cloned()
                .unwrap_or(Mpfr::from_f64(0.0, p));
            let (b, abs, cnt) = h_bound.get(&(i, *j)).copied().unwrap_or_default();
            bad += usize::from(err(v, &r) > SAFETY * (b + cnt * unit * abs));
        }
    }
    bad
}

/// The binary64 kernel against MPFR-128 (B88).
fn violations(m: &Mesh, lt: &[f64], lt_ref: &[f64], u: &[f64], t: &[f64]) -> usize {
    let face = |x: &[f64; 3]| FastFace::of_f64(&face_f64(x));
    let all = |m: &Mesh, lt: &[f64], u: &[f64], t: &[f64]| -> Assembled {
        let parts = energy_gradient_hessian_f64(&HessianPattern::new(m), m, lt, u, t);
        let f = |v: f64| Float::with_val(53, v);
        let rows = (0..m.n_vertices())
            .map(|i| parts.hessian.row(i).map(|(j, v)| (j, f(*v))).collect())
            .collect();
        (
            f(parts.energy.unwrap()),
            parts.gradient.into_iter().map(f).collect(),
            rows,
        )
    };
    let k = Kernel {
        unit: U,
        reference_bits: 128,
        face: &face,
        all: &all,
    };
    violations_of(&k, m, lt, lt_ref, u, t)
}

/// The MPFR-`bits` kernel (B29) against the generic formulas at `2·bits`.
fn violations_mpfr(bits: u32, m: &Mesh, lt: &[f64], lt_ref: &[f64], u: &[f64], t: &[f64]) -> usize {
    let p = Precision::new(u64::from(bits)).unwrap();
    let mp = |v: &[f64]| -> Vec<Mpfr> { v.iter().map(|&x| Mpfr::from_f64(x, p)).collect() };
    let pi = Float::with_val(bits, rug::float::Constant::Pi);
    let half_pi = Float::with_val(bits, &pi >> 1u32);
    let face = |x: &[f64; 3]| {
        let xm = x.map(|v| Mpfr::from_f64(v, p));
        FastFace::of_mpfr(&face_mpfr(&xm, &pi, &half_pi))
    };
    let all = |m: &Mesh, lt: &[f64], u: &[f64], t: &[f64]| -> Assembled {
        let parts =
            energy_gradient_hessian_mpfr(&HessianPattern::new(m), m, &mp(lt), &mp(u), &mp(t));
        let rows = (0..m.n_vertices())
            .map(|i| {
                parts
                    .hessian
                    .row(i)
                    .map(|(j, v)| (j, v.0.clone()))
                    .collect()
            })
            .collect();
        let energy = parts.energy.unwrap().0;
        (
            energy,
            parts.gradient.into_iter().map(|g| g.0).collect(),
            rows,
        )
    };
    let k = Kernel {
        unit: (-f64::from(bits)).exp2(),
        reference_bits: 2 * bits,
        face: &face,
        all: &all,
    };
    violations_of(&k, m, lt, lt_ref, u, t)
}

#[test]
fn b88_fast_energy_gradient_hessian_within_bound_of_mpfr_generic() {
    for seed in 0..cases(9, 60) as u64 {
        let (m, lt, u, t) = case(seed);
        assert_eq!(violations(&m, &lt, &lt, &u, &t), 0, "seed {seed}");
        // Negative control: against the reference at λ̃ with one edge lengthened by
        // 10⁻⁹ (its faces' angles move by about that), the same comparison fails.
        let mut moved = lt.clone();
        moved[0] += 1e-9;
        assert!(
            violations(&m, &lt, &moved, &u, &t) > 0,
            "seed {seed}: control"
        );
    }
}

#[test]
fn b88_fast_path_degenerate_and_loops() {
    use penner::mesh::builders::{one_vertex_torus, two_triangle_sphere};
    // A degenerate face (1, 1, 3): α = (0, 0, π), f = ½πx₂, no Hessian term.
    let x = [0.0, 0.0, 2.0 * 3.0_f64.ln()];
    let t = face_f64(&x);
    assert_eq!(t.angles, [0.0, 0.0, PI]);
    assert!(t.cot.is_none());
    let want = PI * x[2] - FRAC_PI_2 * (x[0] + x[1] + x[2]);
    assert!(
        (t.energy - want).abs() < 8.0 * U * want.abs(),
        "{} {want}",
        t.energy
    );
    // Control: the proper triangle (1, 1, 1.9) has cotangents.
    assert!(face_f64(&[0.0, 0.0, 2.0 * 1.9_f64.ln()]).cot.is_some());
    // Non-finite input: NaN angles, never a panic.
    assert!(face_f64(&[f64::NAN, 0.0, 0.0])
        .angles
        .iter()
        .all(|a| a.is_nan()));
    // The one-vertex torus: all sides are loops, H = 0, ∇E = 2π − 2π.
    let m = one_vertex_torus();
    let p = HessianPattern::new(&m);
    let parts = energy_gradient_hessian_f64(&p, &m, &[0.1, -0.05, 0.2], &[0.0], &[PI * 2.0]);
    assert_eq!(parts.hessian.get(0, 0).copied(), Some(0.0));
    assert!(parts.gradient[0].abs() < 1e-14);
    // Two-triangle sphere with equal sides: cone angles 2π/3.
    let m = two_triangle_sphere();
    let p = HessianPattern::new(&m);
    let parts = energy_gradient_hessian_f64(&p, &m, &[0.0; 3], &[0.0; 3], &[0.0; 3]);
    for g in &parts.gradient {
        assert!((g + 2.0 * PI / 3.0).abs() < 1e-15, "{g}");
    }
}

#[test]
fn b29_fast_mpfr_within_b88_bound_of_generic_at_twice_the_precision() {
    for bits in [128u32, 256] {
        for seed in 0..cases(6, 30) as u64 {
            let (m, lt, u, t) = case(seed);
            assert_eq!(
                violations_mpfr(bits, &m, &lt, &lt, &u, &t),
                0,
                "{bits} bits, seed {seed}"
            );
            // Negative control: the reference at λ̃ with one edge moved by one binary64 ulp
            // (far above the bound at these precisions) is rejected.
            let mut moved = lt.clone();
            moved[0] = if lt[0].abs() > 1e-10 {
                f64::from_bits(lt[0].to_bits() + 1)
            } else {
                lt[0] + 1e-12
            };
            assert!(
                violations_mpfr(bits, &m, &lt, &moved, &u, &t) > 0,
                "{bits} bits, seed {seed}: control"
            );
        }
    }
}

#[test]
fn b29_seeded_half_angle_within_one_ulp_of_mpfr_atan() {
    // Against MPFR's correctly rounded atan at twice the precision: within 1.02·2⁻ᵖ
    // relative (B29), over half angles of every size, both fallbacks included.
    let mut rng = ChaCha8Rng::seed_from_u64(29);
    for p in [53u32, 64, 128, 256, 512, 1024, 4096] {
        let mut taus: Vec<f64> = (0..200).map(|_| rng.gen_range(1e-6..4.0)).collect();
        taus.extend([1e-310, 1e-200, 1e-30, 0.5, 1.0, 1.0 - 1e-16, 3e200, 1e305]);
        for tf in taus {
            let tau = Float::with_val(p, tf) + (Float::with_val(p, tf) >> (p - 5));
            let got = half_angle_atan(&tau, p);
            let exact = Float::with_val(2 * p + 64, tau.atan_ref());
            // Relative errors in units of 2⁻ᵖ (a Float: 2⁻⁴⁰⁹⁶ underflows binary64).
            let in_units =
                |v: &Float| ((Float::with_val(4 * p, v - &exact) / &exact).abs() << p).to_f64();
            let rel = in_units(&got);
            let bound = 1.02; // proof: B29
            assert!(rel <= bound, "p = {p}, τ = {tau}: {rel} units > {bound}");
            assert_eq!(got.prec(), p);
            // Negative control: the seed alone (binary64) is rejected beyond 53 bits.
            if p > 60 && tf > 1e-300 && tf < 1e300 {
                let seed = Float::with_val(p, tf.atan());
                assert!(
                    in_units(&seed) > bound,
                    "p = {p}, τ = {tf}: the seed passed"
                );
            }
        }
    }
}
