//! The maximal packing's refinement residual from products of corner rotations (B112)
//! against the `atan2` angle sums at 600 bits (a second formula at higher precision), and
//! the common-scale starting point of the `f64` Newton solve.

use penner::circles::maximal::hyperbolic::{angle_sums, half_angle_sin_sq, residual_by_rotations};
use penner::circles::maximal::solve::{common_scale_start, newton_f64, residual, residual_f64};
use penner::mesh::builders::random_planar;
use penner::mesh::{Mesh, Vertex};
use penner::scalar::{Mpfr, Precision, Real};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

fn interior_of(mesh: &Mesh) -> Vec<bool> {
    mesh.boundary_vertices().iter().map(|b| !b).collect()
}

/// B112's first-order bound for vertex `v`, doubled for the `O(u²)` terms:
/// `2·(Σ_c (γ₁₁ tan(α_c/2) + 2γ₅ + 2√2γ₂) + 2πu + 4πu|m|)` with `γ_k ≈ ku`.
fn b112_bound(mesh: &Mesh, t: &[f64], v: usize, m: f64, u: f64) -> f64 {
    let mut sum = 0.0;
    for h in mesh.outgoing(Vertex(v as u32)) {
        let (y, z) = (mesh.tip(h).idx(), mesh.tip(mesh.next(h)).idx());
        let q = half_angle_sin_sq(&t[v], &t[y], &t[z]);
        sum += 11.0 * u * (q / (1.0 - q)).sqrt() + 10.0 * u + 4.0 * 2f64.sqrt() * u;
    }
    2.0 * (sum + std::f64::consts::TAU * u * (1.0 + 2.0 * m.abs()))
}

/// The residual at `bits` by rotations and at 600 bits by `atan2` sums, on the same radii
/// (binary64 values, exact at both precisions).
fn both(
    mesh: &Mesh,
    t: &[f64],
    interior: &[bool],
    bits: u64,
    guide: &[f64],
) -> (Vec<Mpfr>, Vec<Mpfr>) {
    let p = Precision::new(bits).unwrap();
    let tp: Vec<Mpfr> = t.iter().map(|&x| Mpfr::from_f64(x, p)).collect();
    let rot = residual_by_rotations(mesh, &tp, interior, guide);
    let r = Precision::new(600).unwrap();
    let tr: Vec<Mpfr> = t.iter().map(|&x| Mpfr::from_f64(x, r)).collect();
    let theta = angle_sums(mesh, &tr);
    let two_pi = Mpfr::pi(r) * &Mpfr::from_f64(2.0, r);
    let reference = theta
        .into_iter()
        .zip(interior)
        .filter(|&(_, &i)| i)
        .map(|(th, _)| two_pi.clone() - &th)
        .collect();
    (rot, reference)
}

/// `|a − b|` with `a` widened exactly to `b`'s 600 bits.
fn gap(a: &Mpfr, b: &Mpfr) -> f64 {
    (rug::Float::with_val(600, a.as_float()) - b.as_float())
        .abs()
        .to_f64()
}

/// `a − b` with `a` widened exactly to `b`'s 600 bits.
fn diff(a: &Mpfr, b: &Mpfr) -> f64 {
    (rug::Float::with_val(600, a.as_float()) - b.as_float()).to_f64()
}

fn radii(mesh: &Mesh, interior: &[bool], seed: u64) -> Vec<f64> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    (0..mesh.n_vertices())
        .map(|v| {
            if interior[v] {
                rng.gen_range(0.02..0.9)
            } else {
                1.0
            }
        })
        .collect()
}

/// proof: B112 — far from the packing (random radii, residuals of order 1, some `m ≠ 0`)
/// and at it (the `f64` solution), at 149 and 256 bits, every vertex's residual is within
/// the bound of the 600-bit `atan2` sum. Controls: a guide off by `2π` moves the result by
/// `2π`, and a radius moved by a relative `2⁻⁴⁰` at one vertex move its residual beyond the bound.
#[test]
fn b112_rotation_residual_matches_angle_sums_at_600_bits() {
    let mesh = random_planar(400, 5).unwrap().mesh;
    let interior = interior_of(&mesh);
    let n = mesh.n_vertices();
    let solved = {
        let start = vec![common_scale_start(&mesh, &interior, 0.5f64.tanh().ln()); n];
        let sol = newton_f64(&mesh, &interior, &start, 1e-13, 100).unwrap();
        sol.u
            .iter()
            .zip(&interior)
            .map(|(x, &i)| if i { x.exp() } else { 1.0 })
            .collect::<Vec<f64>>()
    };
    let verts: Vec<usize> = (0..n).filter(|&v| interior[v]).collect();
    for (name, t) in [("random", radii(&mesh, &interior, 9)), ("solved", solved)] {
        let u64s: Vec<f64> = t
            .iter()
            .zip(&interior)
            .map(|(x, &i)| if i { x.ln() } else { 0.0 })
            .collect();
        let guide = residual(&mesh, &u64s, &interior);
        for bits in [149u64, 256] {
            let u = 2f64.powi(-(bits as i32));
            let (rot, reference) = both(&mesh, &t, &interior, bits, &guide);
            let mut worst = 0.0f64;
            for ((&v, a), b) in verts.iter().zip(&rot).zip(&reference) {
                let m = (b.approx_f64() / std::f64::consts::TAU).round();
                let err = gap(a, b);
                let bound = b112_bound(&mesh, &t, v, m, u);
                assert!(
                    err <= bound,
                    "{name}, {bits} bits, vertex {v}: |error| {err:e} > {bound:e}"
                );
                worst = worst.max(err / bound);
            }
            assert!(worst > 0.0, "{name}: the comparison saw no rounding at all");
            // Control: a guide off by 2π changes every residual by 2π.
            let off: Vec<f64> = guide.iter().map(|g| g + std::f64::consts::TAU).collect();
            let (shifted, _) = both(&mesh, &t, &interior, bits, &off);
            for (a, b) in shifted.iter().zip(&reference) {
                let d = diff(a, b);
                assert!(
                    (d - std::f64::consts::TAU).abs() < 1e-9,
                    "{name}: a wrong guide went unnoticed"
                );
            }
        }
        // Control: a radius moved by a relative 2⁻⁴⁰ at one vertex moves its residual at 256
        // bits beyond the bound.
        let v = verts[verts.len() / 2];
        let mut moved = t.clone();
        moved[v] *= 1.0 + 2f64.powi(-40);
        let (rot, _) = both(&mesh, &moved, &interior, 256, &guide);
        let (_, reference) = both(&mesh, &t, &interior, 256, &guide);
        let k = verts.iter().position(|&w| w == v).unwrap();
        let err = gap(&rot[k], &reference[k]);
        assert!(
            err > b112_bound(&mesh, &t, v, 0.0, 2f64.powi(-256)),
            "{name}: a moved radius went unnoticed"
        );
    }
}

/// The common-scale start brackets the root of `S(c) = Σ_v (2π − θ_v(c))` within `0.05`
/// (checked with the rotation residual in `f64`, a second formula for `S`); the control: a
/// start moved by `1` leaves the bracket. At `n = 2000` the `f64` Newton solve from it ends
/// below `10⁻³·64nu` (the rule that takes one more step in the quadratic phase).
#[test]
fn common_scale_start_brackets_the_root_of_the_summed_residual() {
    let mesh = random_planar(2000, 3).unwrap().mesh;
    let interior = interior_of(&mesh);
    let n = mesh.n_vertices();
    let hi = 0.5f64.tanh().ln();
    let c = common_scale_start(&mesh, &interior, hi);
    let s = |c: f64| -> f64 {
        let u: Vec<f64> = interior.iter().map(|&i| if i { c } else { 0.0 }).collect();
        let t: Vec<f64> = u.iter().map(|x: &f64| f64::exp(*x)).collect();
        let guide = residual(&mesh, &u, &interior);
        residual_by_rotations(&mesh, &t, &interior, &guide)
            .iter()
            .sum()
    };
    // The guide (the atan2 sums) only picks each vertex's multiple of 2π; the values are
    // the rotation products'.
    assert!(
        s(c - 0.05) < 0.0 && s(c + 0.05) > 0.0,
        "c = {c} does not bracket the root"
    );
    assert!(
        s(c + 1.0) > 0.0 && s(c + 1.0 - 0.05) > 0.0,
        "control: c + 1 is not a bracket"
    );
    assert!(
        c < hi - 1.0,
        "the start did not move from the default ({c})"
    );
    let tol = 64.0 * n as f64 * f64::EPSILON / 2.0;
    let sol = newton_f64(&mesh, &interior, &vec![c; n], tol, 100).unwrap();
    assert!(
        sol.residual <= 1e-3 * tol,
        "residual {:e} vs tol {tol:e}",
        sol.residual
    );
}

/// The per-vertex parallel `f64` residual sums the same corner angles as the per-face
/// [`residual`] in another order: B41 bounds the difference of two orders of a sum of `k`
/// terms by `2(k − 1)·u·Σ|terms|`, here `k = deg + 1` terms (the corners and `2π`) with
/// `Σ|terms| ≤ 4π`. The control: one interior `u` moved by `10⁻⁹` moves that vertex's
/// residual far beyond the bound.
#[test]
fn b41_parallel_f64_residual_sums_the_same_corner_angles() {
    let mesh = random_planar(3000, 8).unwrap().mesh;
    let interior = interior_of(&mesh);
    let t = radii(&mesh, &interior, 4);
    let u: Vec<f64> = t.iter().map(|x: &f64| f64::ln(*x)).collect();
    let (a, b) = (
        residual_f64(&mesh, &u, &interior),
        residual(&mesh, &u, &interior),
    );
    let verts: Vec<usize> = (0..mesh.n_vertices()).filter(|&v| interior[v]).collect();
    let unit = f64::EPSILON / 2.0;
    let bound = |v: usize| {
        let k = mesh.outgoing(Vertex(v as u32)).count() + 1;
        2.0 * (k - 1) as f64 * unit * 4.0 * std::f64::consts::PI
    };
    for ((&v, x), y) in verts.iter().zip(&a).zip(&b) {
        assert!((x - y).abs() <= bound(v), "vertex {v}: {x} vs {y}");
    }
    let v = verts[verts.len() / 3];
    let mut moved = u.clone();
    moved[v] += 1e-9;
    let c = residual_f64(&mesh, &moved, &interior);
    let k = verts.iter().position(|&w| w == v).unwrap();
    assert!(
        (c[k] - b[k]).abs() > 1e3 * bound(v),
        "a moved u went unnoticed"
    );
}
