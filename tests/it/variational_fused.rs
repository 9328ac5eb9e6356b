//! The one-pass evaluation of `E`, `∇E` and the Hessian
//! (`variational::energy::energy_gradient_hessian_at`) and the precomputed Hessian pattern
//! (`variational::pattern`), against the separate functions and an independent triplet
//! assembly, on simplicial surfaces and on Δ-complexes with loops and multiple edges.

use crate::meshgen::{icosphere, jittered_torus, random_tetrahedron};
use crate::support::cases;
use penner::geometry::laplacian::SparseMatrix;
use penner::mesh::builders::{genus, one_vertex_torus, two_triangle_sphere};
use penner::mesh::Mesh;
use penner::scalar::{Dd, Mpfr, Precision, Real};
use penner::variational::energy::{
    energy_at, energy_gradient_hessian_at, energy_gradient_hessian_with, gradient_at,
};
use penner::variational::pattern::HessianPattern;
use penner::variational::triangle::cotangents;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// Surfaces by `seed`: simplicial (tetrahedron, icosphere, torus) and Δ-complexes (the
/// two-triangle sphere, the one-vertex torus, a one-vertex genus-2 surface), with random
/// logarithmic lengths `λ̃ ∈ [−0.3, 0.3]` (every face a proper triangle on the simplicial
/// ones; the Δ-complexes may have degenerate faces, exercising the skipped faces).
fn case(seed: u64) -> (Mesh, Vec<f64>) {
    let m = match seed % 6 {
        0 => random_tetrahedron(seed).mesh(),
        1 => icosphere(1).mesh(),
        2 => jittered_torus(4, 5, seed).0,
        3 => two_triangle_sphere(),
        4 => one_vertex_torus(),
        _ => genus(2).unwrap(),
    };
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let lt = (0..m.n_edges())
        .map(|_| 0.6 * (rng.r#gen::<f64>() - 0.5))
        .collect();
    (m, lt)
}

/// The Hessian assembled independently: per face, `½ cot α_m` of
/// [`cotangents`] as `(i,i), (j,j), (i,j), (j,i)` triplets summed by
/// [`SparseMatrix::from_triplets`] (no pattern).
fn triplet_hessian<T: Real>(m: &Mesh, lt: &[T]) -> SparseMatrix<T> {
    let mut trip = Vec::new();
    for f in m.faces() {
        let hs = m.face_halfedges(f);
        let x = hs.map(|h| lt[h.edge().idx()].clone());
        let Some(c) = cotangents(&x) else { continue };
        for k in 0..3 {
            let w = c[k].clone() * &c[k].lit(0.5);
            let (i, j) = (m.tail(hs[k]).idx(), m.tip(hs[k]).idx());
            trip.push((i, i, w.clone()));
            trip.push((j, j, w.clone()));
            trip.push((i, j, -w.clone()));
            trip.push((j, i, -w));
        }
    }
    SparseMatrix::from_triplets(m.n_vertices(), &trip)
}

/// Entries where `a` and `b` differ (a missing entry counts as 0), compared exactly.
fn differing<T: Real>(a: &SparseMatrix<T>, b: &SparseMatrix<T>) -> usize {
    let same = |x: Option<&T>, y: Option<&T>| {
        let q = |v: Option<&T>| v.and_then(Real::to_rational).unwrap_or_default();
        q(x) == q(y)
    };
    let n = a.dim();
    let mut bad = 0;
    for i in 0..n {
        for j in 0..n {
            if !same(a.get(i, j), b.get(i, j)) {
                bad += 1;
            }
        }
    }
    bad
}

/// The one-pass values equal the separate functions and the triplet assembly exactly:
/// the same operations in the same order (the triangle's sides are distinct, so the
/// Kahan sort is the same). Returns the number of differences against a reference taken
/// at `lt_ref` (the identity check when `lt_ref == lt`).
fn mismatches<T: Real>(m: &Mesh, lt: &[f64], lt_ref: &[f64], ctx: T::Ctx) -> usize {
    let to = |v: &[f64]| -> Vec<T> { v.iter().map(|&x| T::from_f64(x, ctx)).collect() };
    let (x, xr) = (to(lt), to(lt_ref));
    let mut rng = ChaCha8Rng::seed_from_u64(lt.len() as u64);
    let n = m.n_vertices();
    let u = to(&(0..n).map(|_| rng.r#gen::<f64>() - 0.5).collect::<Vec<_>>());
    let t = to(&(0..n).map(|_| 6.0 * rng.r#gen::<f64>()).collect::<Vec<_>>());
    let parts = energy_gradient_hessian_at(m, &x, &u, &t);
    let q = |v: &T| v.to_rational();
    let mut bad = 0;
    let e_ref = energy_at(m, &xr, &u, &t).unwrap();
    bad += usize::from(parts.energy.as_ref().and_then(q) != q(&e_ref));
    let g_ref = gradient_at(m, &xr, &t);
    bad += parts
        .gradient
        .iter()
        .zip(&g_ref)
        .filter(|(a, b)| q(a) != q(b))
        .count();
    bad += differing(&parts.hessian, &triplet_hessian(m, &xr));
    // The same on a pattern built once and reused.
    let pattern = HessianPattern::new(m);
    let again = energy_gradient_hessian_with(&pattern, m, &x, &u, &t);
    bad += differing(&again.hessian, &parts.hessian);
    bad
}

fn all_backends(m: &Mesh, lt: &[f64], lt_ref: &[f64]) -> [usize; 3] {
    let p = Precision::new(128).unwrap();
    [
        mismatches::<f64>(m, lt, lt_ref, ()),
        mismatches::<Dd>(m, lt, lt_ref, ()),
        mismatches::<Mpfr>(m, lt, lt_ref, p),
    ]
}

#[test]
fn t32_one_pass_energy_gradient_hessian_equal_the_separate_assemblies() {
    for seed in 0..cases(12, 60) as u64 {
        let (m, lt) = case(seed);
        assert_eq!(all_backends(&m, &lt, &lt), [0, 0, 0], "seed {seed}");
        // Negative control: against the references at λ̃ with one edge lengthened by
        // 10⁻³ (on the edges of a proper face every angle moves), the comparison fails.
        let mut moved = lt.clone();
        moved[0] += 1e-3;
        let r = all_backends(&m, &lt, &moved);
        assert!(r.iter().all(|&k| k > 0), "seed {seed}: control {r:?}");
    }
}

#[test]
fn t32_hessian_pattern_of_loops_and_multiple_edges() {
    // The one-vertex torus: every side is a loop, H is the 1×1 zero (loops cancel).
    let m = one_vertex_torus();
    let p = HessianPattern::new(&m);
    assert_eq!(p.dim(), 1);
    let lt = [0.1, -0.05, 0.2];
    let parts = energy_gradient_hessian_with(&p, &m, &lt, &[0.0], &[std::f64::consts::TAU]);
    assert_eq!(parts.hessian.get(0, 0).copied(), Some(0.0));
    // ∇E = 2π − (sum of all six angles) = 0 on a torus.
    assert!(parts.gradient[0].abs() < 1e-14, "{:?}", parts.gradient);
    // The two-triangle sphere: each vertex pair is joined by one edge of both faces.
    let m = two_triangle_sphere();
    let p = HessianPattern::new(&m);
    assert!(p.fits(&m) && !p.fits(&one_vertex_torus()));
    let lt = [0.0, 0.1, -0.1];
    let h = energy_gradient_hessian_with(&p, &m, &lt, &[0.0; 3], &[1.0; 3]).hessian;
    let r = triplet_hessian(&m, &lt);
    assert_eq!(differing(&h, &r), 0);
    // Row sums of the cotan Laplacian vanish; the control (a doubled diagonal) does not.
    for i in 0..3 {
        let s: f64 = h.row(i).map(|(_, v)| *v).sum();
        assert!(s.abs() < 1e-15, "row {i}: {s}");
        assert!((s + h.get(i, i).unwrap()).abs() > 1e-3);
    }
}

/// B57: the difference enclosure of `E′(u)·d` (53-bit data, 106-bit intervals) contains
/// `(Θ − θ(u))·d` evaluated independently from the angles at 320 bits, is narrow, and
/// excludes the same value moved by 10⁻⁹.
#[test]
fn b57_difference_enclosure_contains_the_gradient_and_excludes_a_moved_one() {
    use penner::theorems::t32_difference::derivative_enclosure;
    use penner::variational::energy::{gradient, log_lengths};
    use rug::{Float, Rational};
    let p = Precision::new(320).unwrap();
    for seed in 0..cases(3, 12) as u64 {
        let (m, l) = match seed % 3 {
            0 => {
                let e = random_tetrahedron(seed);
                let m = e.mesh();
                let l = e.lengths(&m);
                (m, l)
            }
            1 => {
                let e = icosphere(1);
                let m = e.mesh();
                let l = e.lengths(&m);
                (m, l)
            }
            // A finer torus: the 4 × 5 one has faces next to degenerate, where E‴ and so
            // the enclosure's truncation part are large (still an enclosure, not narrow).
            _ => jittered_torus(10, 12, seed),
        };
        let n = m.n_vertices();
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let u: Vec<f64> = (0..n).map(|_| 0.2 * (rng.r#gen::<f64>() - 0.5)).collect();
        let t: Vec<f64> = (0..n).map(|_| 6.0 * rng.r#gen::<f64>()).collect();
        let d: Vec<f64> = (0..n).map(|_| rng.r#gen::<f64>() - 0.5).collect();
        let lambda = log_lengths(&l);
        let enc = derivative_enclosure(&m, &lambda, &u, &t, &d, 53).expect("enclosure");
        // Independent: Θ − θ from the angles at 320 bits on the same exact data.
        let hi = |v: &[f64]| -> Vec<Mpfr> { v.iter().map(|&x| Mpfr::from_f64(x, p)).collect() };
        let g = gradient(&m, &hi(&lambda), &hi(&u), &hi(&t));
        let gd = g.iter().zip(&d).fold(Float::with_val(320, 0), |s, (a, b)| {
            s + Float::with_val(640, &a.0 * *b)
        });
        let q = Rational::from_f64(0.0).unwrap() + gd.to_rational().unwrap();
        assert!(
            enc.lo <= q && q <= enc.hi,
            "seed {seed}: {q} not in [{}, {}]",
            enc.lo,
            enc.hi
        );
        let width = Float::with_val(320, &enc.hi - &enc.lo).to_f64();
        assert!(
            width < 1e-12,
            "seed {seed}: width {width}, truncation {}",
            enc.truncation
        );
        // Negative control: moved by 10⁻⁹ it lies outside.
        let moved = q + Rational::from_f64(1e-9).unwrap();
        assert!(moved > enc.hi, "seed {seed}: control inside");
    }
}

/// B32: with `d` supported on two vertices of a 240-face torus, the enclosure summed over
/// the faces touching the support contains `(Θ − θ(u))·d` evaluated independently (angles
/// at 320 bits, every face) and is no wider than the enclosure summed over every face,
/// which contains it too. Negative control: the same enclosure with one touched face left
/// out (that face's term moves along `d`) excludes it.
#[test]
fn b32_difference_on_touched_faces_encloses_the_gradient_and_a_missed_face_does_not() {
    use penner::theorems::t32_difference::{
        derivative_enclosure, derivative_enclosure_on, support, touched_faces,
    };
    use penner::variational::energy::{gradient, log_lengths};
    use rug::{Float, Rational};
    let p = Precision::new(320).unwrap();
    for seed in 0..cases(2, 8) as u64 {
        let (m, l) = jittered_torus(10, 12, seed);
        let n = m.n_vertices();
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let u: Vec<f64> = (0..n).map(|_| 0.2 * (rng.r#gen::<f64>() - 0.5)).collect();
        let t: Vec<f64> = (0..n).map(|_| 6.0 * rng.r#gen::<f64>()).collect();
        let mut d = vec![0.0; n];
        d[(seed as usize * 7) % n] = 0.75;
        d[(seed as usize * 7 + n / 2) % n] = -0.5;
        let lambda = log_lengths(&l);
        let faces = touched_faces(&m, &support(&d));
        assert!(faces.len() < m.n_faces() / 4, "{} touched", faces.len());
        let enc = derivative_enclosure(&m, &lambda, &u, &t, &d, 53).expect("enclosure");
        let all: Vec<_> = m.faces().collect();
        let full = derivative_enclosure_on(&m, &all, &lambda, &u, &t, &d, 53).expect("full");
        let hi = |v: &[f64]| -> Vec<Mpfr> { v.iter().map(|&x| Mpfr::from_f64(x, p)).collect() };
        let g = gradient(&m, &hi(&lambda), &hi(&u), &hi(&t));
        let gd = g.iter().zip(&d).fold(Float::with_val(320, 0), |s, (a, b)| {
            s + Float::with_val(640, &a.0 * *b)
        });
        let q = Rational::from_f64(0.0).unwrap() + gd.to_rational().unwrap();
        for (name, e) in [("touched", &enc), ("all", &full)] {
            assert!(
                e.lo <= q && q <= e.hi,
                "seed {seed}, {name}: {q} not in [{}, {}]",
                e.lo,
                e.hi
            );
        }
        let width = |e: &penner::theorems::t32_difference::DerivativeEnclosure| {
            Float::with_val(640, &e.hi - &e.lo)
        };
        assert!(width(&enc) <= width(&full), "seed {seed}: restricted wider");
        assert!(width(&enc).to_f64() < 1e-12, "seed {seed}: {}", width(&enc));
        // Negative control: leave out one touched face.
        let missed = &faces[1..];
        let off = derivative_enclosure_on(&m, missed, &lambda, &u, &t, &d, 53).expect("missed");
        assert!(
            q < off.lo || q > off.hi,
            "seed {seed}: a missed face went unnoticed"
        );
    }
}
