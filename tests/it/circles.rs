//! Circle patterns (T08, T09; metrics and the Jacobian of `penner::circles`): fixed and
//! seeded random instances at f64, double-double, MPFR and exactly, each property with a
//! negative control that the same check rejects.

use crate::support::cases;
use penner::circles::jacobian::angle_jacobian;
use penner::circles::metric::{
    cone_angles, cos_pi, euclidean_length, hyperbolic_length, inversive_distance,
    lengths_from_radii,
};
use penner::circles::CirclePattern;
use penner::mesh::builders::{icosahedron, octahedron, random_surface, tetrahedron};
use penner::mesh::Mesh;
use penner::scalar::{Dd, Dual, Mpfr, Precision, Real};
use penner::theorems::t08_circle_pattern_lengths::{
    check_circle_pattern_lengths, face_triangle_signs, verify_faces,
};
use penner::theorems::t09_circle_pattern_rigidity::{fixed_starts, runs, verify_rigidity};
use penner::theorems::Settings;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rug::Rational;

fn rat(a: i64, b: i64) -> Rational {
    Rational::from((a, b))
}

fn p256() -> Precision {
    Precision::new(256).unwrap()
}

/// Random rational radii in [1/8, 8] and angles Φ/π from `choices`.
fn random_pattern(
    mesh: &Mesh,
    rng: &mut ChaCha8Rng,
    choices: &[Rational],
) -> (Vec<Rational>, Vec<Rational>) {
    let r = (0..mesh.n_vertices())
        .map(|_| Rational::from((rng.gen_range(1..=64), 8)))
        .collect();
    let phi = (0..mesh.n_edges())
        .map(|_| choices[rng.gen_range(0..choices.len())].clone())
        .collect();
    (r, phi)
}

#[test]
fn t08_pattern_lengths_are_strict_triangles_for_angles_up_to_a_right_angle() {
    let s = Settings::default();
    let exact = [rat(0, 1), rat(1, 3), rat(1, 2)];
    let irrational = [rat(0, 1), rat(1, 7), rat(1, 4), rat(5, 12), rat(1, 2)];
    let mut rng = ChaCha8Rng::seed_from_u64(8);
    for case in 0..cases(12, 200) {
        let mesh = random_surface((case % 3) as u32, 10 + case as u32 % 7, case as u64).unwrap();
        for choices in [&exact[..], &irrational[..]] {
            let (r, phi) = random_pattern(&mesh, &mut rng, choices);
            let v = check_circle_pattern_lengths(&mesh, &r, &phi, 128, &s);
            assert!(
                matches!(
                    v,
                    penner::theorems::Verdict::Holds {
                        certified: true,
                        ..
                    }
                ),
                "{v:?}"
            );
        }
    }
    // Negative control: the same faces with Φ = 2π/3 on two sides of a face and tangency on
    // the third, radii (1, 1, 1/2), are refused (the fixed instance below).
    let mesh = tetrahedron().mesh;
    let (r, phi) = obtuse_instance(&mesh);
    let v = verify_faces(&mesh, &face_triangle_signs(&mesh, &r, &phi, 128, &s), 128);
    assert!(v.fails(), "{v:?}");
}

/// Face 0 = ijk of `mesh`: radii r_i = r_j = 1, r_k = 1/2; Φ_ij = 0, Φ_jk = Φ_ki = 2π/3.
/// Then ℓ_ij² = 4 and ℓ_jk² = ℓ_ki² = 1 + 1/4 − 1/2 = 3/4: ℓ_jk + ℓ_ki = √3 < 2 = ℓ_ij.
fn obtuse_instance(mesh: &Mesh) -> (Vec<Rational>, Vec<Rational>) {
    let f = mesh.faces().next().unwrap();
    let [hij, hjk, hki] = mesh.face_halfedges(f);
    let k = mesh.tail(hki).idx();
    let mut r = vec![rat(1, 1); mesh.n_vertices()];
    r[k] = rat(1, 2);
    let mut phi = vec![rat(0, 1); mesh.n_edges()];
    phi[hij.edge().idx()] = rat(0, 1);
    phi[hjk.edge().idx()] = rat(2, 3);
    phi[hki.edge().idx()] = rat(2, 3);
    (r, phi)
}

#[test]
fn t08_obtuse_angles_break_the_triangle_inequality_fixed_instance() {
    let s = Settings::default();
    let mesh = tetrahedron().mesh;
    let (r, phi) = obtuse_instance(&mesh);
    let signs = face_triangle_signs(&mesh, &r, &phi, 128, &s);
    // Face 0 is proved degenerate (exactly: cos 2π/3 = −1/2 is rational).
    assert_eq!(signs[0].value(), Some(false));
    // Independent arithmetic: √3 < 2 ⇔ 3 < 4.
    assert!(3.0_f64.sqrt() < 2.0);
    // The theorem's hypothesis excludes it: the check says so instead of failing.
    let v = check_circle_pattern_lengths(&mesh, &r, &phi, 128, &s);
    assert!(
        matches!(v, penner::theorems::Verdict::NotApplicable { .. }),
        "{v:?}"
    );
    // Control: with Φ_jk = Φ_ki = π/2 instead the face is a triangle.
    let mut ok = phi.clone();
    for q in &mut ok {
        if *q == rat(2, 3) {
            *q = rat(1, 2);
        }
    }
    assert_eq!(
        face_triangle_signs(&mesh, &r, &ok, 128, &s)[0].value(),
        Some(true)
    );
}

#[test]
fn circle_lengths_agree_with_closed_forms() {
    // Tangent: r_i + r_j; orthogonal: Pythagoras; Φ = π/3: r² + r'² + r r'.
    let p = p256();
    let m = |x: f64| Mpfr::from_f64(x, p);
    let l = euclidean_length(&m(1.25), &m(2.5), &cos_pi::<Mpfr>(&rat(0, 1), p));
    assert_eq!(l.approx_f64(), 3.75);
    let l = euclidean_length(&m(0.6), &m(0.8), &cos_pi::<Mpfr>(&rat(1, 2), p));
    assert_eq!(l.approx_f64(), 1.0);
    let l = euclidean_length(&m(3.0), &m(5.0), &cos_pi::<Mpfr>(&rat(1, 3), p));
    assert_eq!(l.approx_f64(), 7.0); // 9 + 25 + 15 = 49
                                     // Inversive distance inverts the length formula (Dd against MPFR).
    let (ri, rj, c) = (0.7_f64, 1.9, 0.3);
    let ld = euclidean_length(&Dd::from_f64(ri), &Dd::from_f64(rj), &Dd::from_f64(c));
    let back = inversive_distance(&ld, &Dd::from_f64(ri), &Dd::from_f64(rj));
    assert!((back.approx_f64() - c).abs() < 1e-28);
    // Hyperbolic: tangent circles are r_i + r_j apart; orthogonal ones satisfy the
    // hyperbolic Pythagoras cosh ℓ = cosh r_i cosh r_j.
    let h = hyperbolic_length(&m(0.3), &m(1.1), &m(1.0));
    assert!((h.approx_f64() - 1.4).abs() < 1e-15);
    let h = hyperbolic_length(&0.3_f64, &1.1, &0.0).approx_f64();
    assert!((h.cosh() - 0.3_f64.cosh() * 1.1_f64.cosh()).abs() < 1e-14);
    // Control: a wrong angle is seen.
    let h = hyperbolic_length(&m(0.3), &m(1.1), &m(0.99));
    assert!((h.approx_f64() - 1.4).abs() > 1e-4);
}

fn dual_derivatives(mesh: &Mesh, r: &[f64], cos_phi: &[f64], j: usize) -> Vec<f64> {
    // θ(u) with u_j the variable, at u = ln r (radii r_j e^{ε}).
    let u: Vec<Dual<f64>> = r
        .iter()
        .enumerate()
        .map(|(v, &x)| {
            if v == j {
                Dual::variable(x.ln())
            } else {
                Dual::constant(x.ln())
            }
        })
        .collect();
    let rd: Vec<Dual<f64>> = u.iter().map(Real::exp).collect();
    let cd: Vec<Dual<f64>> = cos_phi.iter().map(|&c| Dual::constant(c)).collect();
    let l = lengths_from_radii(mesh, &rd, &cd);
    cone_angles(mesh, &l).into_iter().map(|t| t.d).collect()
}

#[test]
#[allow(clippy::needless_range_loop)] // matrix indices (i, j) of the Jacobian
fn circles_jacobian_matches_dual_derivatives() {
    let mut rng = ChaCha8Rng::seed_from_u64(9);
    for case in 0..cases(6, 60) {
        let mesh = random_surface((case % 2) as u32, 8 + case as u32, case as u64).unwrap();
        let r: Vec<f64> = (0..mesh.n_vertices())
            .map(|_| rng.gen_range(0.3..3.0))
            .collect();
        let cos_phi: Vec<f64> = (0..mesh.n_edges())
            .map(|_| (rng.gen_range(0.0..0.5) * std::f64::consts::PI).cos())
            .collect();
        let l = lengths_from_radii(&mesh, &r, &cos_phi);
        let jac = angle_jacobian(&mesh, &r, &cos_phi, &l);
        let n = mesh.n_vertices();
        for j in 0..n {
            let d = dual_derivatives(&mesh, &r, &cos_phi, j);
            for i in 0..n {
                // Both are f64 evaluations of O(degree) terms of size O(1): 1e-12 absolute
                // is far above their rounding (B27, B40) and far below the 1e-3 control.
                assert!(
                    (jac[i][j] - d[i]).abs() < 1e-12,
                    "({i},{j}): {} vs {}",
                    jac[i][j],
                    d[i]
                );
                assert_eq!(jac[i][j], jac[j][i]);
                if i != j {
                    assert!(jac[i][j] >= 0.0, "Chow–Luo: off-diagonal entries are ≥ 0");
                }
            }
            let row: f64 = jac[j].iter().sum();
            assert!(row.abs() < 1e-12);
        }
        // Negative control: one weight changed by 1e-3 is seen by the comparison.
        let mut bad = jac.clone();
        bad[0][1] += 1e-3;
        let d = dual_derivatives(&mesh, &r, &cos_phi, 1);
        assert!((bad[0][1] - d[0]).abs() > 1e-12);
    }
}

fn pattern(mesh: Mesh, phi: &Rational, targets: Vec<Rational>) -> CirclePattern {
    CirclePattern::uniform(mesh, phi, targets).unwrap()
}

/// Targets with curvature proportional to degree: K_v = 2πχ·d_v/(2E).
fn degree_targets(mesh: &Mesh) -> Vec<Rational> {
    let e = mesh.n_edges() as i64;
    let chi = mesh.euler_characteristic();
    mesh.vertices()
        .map(|v| rat(2, 1) - rat(chi * mesh.degree(v) as i64, e))
        .collect()
}

#[test]
fn t09_rigidity_two_starts_three_precisions() {
    for (mesh, phi) in [
        (tetrahedron().mesh, rat(0, 1)),
        (octahedron().mesh, rat(1, 3)),
        (icosahedron().mesh, rat(1, 2)),
        (icosahedron().mesh, rat(1, 5)),
    ] {
        let p = pattern(mesh.clone(), &phi, degree_targets(&mesh));
        let starts = fixed_starts(mesh.n_vertices());
        let mut all = runs::<f64>(&p, &starts, ());
        all.extend(runs::<Dd>(&p, &starts, ()));
        all.extend(runs::<Mpfr>(&p, &starts, p256()));
        let v = verify_rigidity(&p, &all);
        assert!(
            matches!(
                v,
                penner::theorems::Verdict::Holds {
                    certified: true,
                    ..
                }
            ),
            "{v:?}"
        );
        // Regular solids with degree targets: by symmetry all radii are equal (u = 0),
        // an independent expectation.
        for run in &all {
            assert!(run.u.iter().all(|x| x.abs() < 1e-12), "{:?}", run.u);
        }
        // Negative control: a solution of a different problem (one target moved by π/10 at
        // two vertices, keeping Gauss–Bonnet) is certified in a disjoint box.
        let mut t = degree_targets(&mesh);
        t[1] += rat(1, 10);
        t[2] -= rat(1, 10);
        let q = pattern(mesh.clone(), &phi, t);
        let mut mixed = runs::<f64>(&p, &starts[..1], ());
        mixed.extend(runs::<f64>(&q, &starts[..1], ()));
        assert!(verify_rigidity(&p, &mixed).fails());
    }
}

#[test]
fn b94_interval_cholesky_rejects_an_indefinite_hull() {
    use penner::scalar::dense::interval_cholesky_positive;
    use penner::scalar::Interval;
    let p = Precision::new(128).unwrap();
    let iv = |lo: f64, hi: f64| Interval::new(Mpfr::from_f64(lo, p), Mpfr::from_f64(hi, p));
    // [[1, b], [b, 1]] has eigenvalues 1 ± b: positive definite for every |b| < 1 (the
    // independent closed form), indefinite as soon as the hull reaches |b| ≥ 1.
    for (lo, hi, pd) in [
        (-0.5, 0.5, true),
        (0.9, 0.999, true),
        (0.9, 1.1, false),
        (-1.0, 0.0, false),
        (2.0, 2.0, false),
    ] {
        let m = vec![
            vec![iv(1.0, 1.0), iv(lo, hi)],
            vec![iv(lo, hi), iv(1.0, 1.0)],
        ];
        let closed_form = 1.0 - lo.abs().max(hi.abs()) > 0.0;
        assert_eq!(closed_form, pd);
        assert_eq!(interval_cholesky_positive(&m), pd, "b ∈ [{lo}, {hi}]");
    }
    // A 3×3 grounded Laplacian of a triangle (positive definite) and the same matrix with one
    // diagonal entry lowered so that the determinant is negative.
    let l = |d: f64| {
        vec![
            vec![iv(2.0, 2.0), iv(-1.0, -1.0), iv(-1.0, -1.0)],
            vec![iv(-1.0, -1.0), iv(2.0, 2.0), iv(-1.0, -1.0)],
            vec![iv(-1.0, -1.0), iv(-1.0, -1.0), iv(d, d)],
        ]
    };
    assert!(interval_cholesky_positive(&l(2.5)));
    assert!(!interval_cholesky_positive(&l(1.5)));
}

/// A certificate of T09's comparison (B94) with the given exact centre and half-width; the
/// other fields do not enter `contains` or `disjoint_from`.
fn b94_box(center: &[Rational], radius: f64) -> penner::circles::certify::Certificate {
    penner::circles::certify::Certificate {
        center: center.to_vec(),
        radius,
        lambda: 1.0,
        gradient_norm: 0.0,
        bits: 128,
    }
}

/// B94 term "a box nested in another holds the same critical point": `|c − c'|∞ + ρ' ≤ ρ`,
/// compared exactly. Centres `(3, 3)` and `(3, 3 + δ)`, `ρ = 1`, `ρ' = ½`: nested exactly
/// when `δ + ½ ≤ 1` (closed form), so `δ = ½` (touching the wall from inside) nests and
/// `δ = ½ + 2⁻⁴⁰` does not; the coordinate that moves is the second, the first is the same
/// nonzero value in both boxes (a sum `c + c'` would be 6).
#[test]
fn term_b94_nested_boxes_compared_exactly() {
    let big = b94_box(&[rat(3, 1), rat(3, 1)], 1.0);
    let tiny = Rational::from((1, 1u64 << 40));
    for (delta, nested) in [
        (rat(1, 2), true),
        (rat(1, 2) + &tiny, false),
        (-rat(1, 2), true),
        (-rat(1, 2) - &tiny, false),
        (rat(0, 1), true),
    ] {
        let small = b94_box(&[rat(3, 1), rat(3, 1) + &delta], 0.5);
        let closed_form = Rational::from(delta.abs_ref()) + rat(1, 2) <= 1;
        assert_eq!(closed_form, nested);
        assert_eq!(big.contains(&small), nested, "δ = {delta}");
    }
    // Negative control: the larger box is never nested in the smaller one.
    let small = b94_box(&[rat(3, 1), rat(3, 1)], 0.5);
    assert!(!small.contains(&big));
    assert!(big.contains(&small));
}

/// B94 term "two disjoint boxes hold two different critical points": some `|c_k − c'_k| >
/// ρ + ρ'`, compared exactly. Centres `(3, 3)` and `(3, 3 + δ)`, `ρ = 1`, `ρ' = ½`: disjoint
/// exactly when `|δ| > 3/2` (closed form); at `δ = 3/2` the boxes share a side (not disjoint,
/// the solution could lie on it), at `3/2 + 2⁻⁴⁰` they are apart.
#[test]
fn term_b94_disjoint_boxes_compared_exactly() {
    let a = b94_box(&[rat(3, 1), rat(3, 1)], 1.0);
    let tiny = Rational::from((1, 1u64 << 40));
    for (delta, disjoint) in [
        (rat(3, 2), false),
        (rat(3, 2) + &tiny, true),
        (-rat(3, 2), false),
        (-rat(3, 2) - &tiny, true),
        (rat(1, 2), false),
        (rat(0, 1), false),
    ] {
        let b = b94_box(&[rat(3, 1), rat(3, 1) + &delta], 0.5);
        let closed_form = Rational::from(delta.abs_ref()) > rat(3, 2);
        assert_eq!(closed_form, disjoint);
        assert_eq!(a.disjoint_from(&b), disjoint, "δ = {delta}");
        assert_eq!(b.disjoint_from(&a), disjoint, "δ = {delta}, swapped");
    }
}

/// `θ_v(u)` of the tangency pattern (`Φ = 0`) of the tetrahedron, independently of
/// `penner::circles`: at each vertex the three angles of the triangles of sides `r_i + r_j`
/// (`r = e^u`), by the law of cosines in `bits`-bit MPFR.
fn tetrahedron_tangency_angles(u: &[rug::Float; 4], bits: u32) -> [rug::Float; 4] {
    use rug::Float;
    let r: Vec<Float> = u
        .iter()
        .map(|x| Float::with_val(bits, x.exp_ref()))
        .collect();
    let angle = |v: usize, x: usize, y: usize| {
        let b = Float::with_val(bits, &r[v] + &r[x]);
        let c = Float::with_val(bits, &r[v] + &r[y]);
        let a = Float::with_val(bits, &r[x] + &r[y]);
        let num = Float::with_val(bits, &b * &b) + Float::with_val(bits, &c * &c)
            - Float::with_val(bits, &a * &a);
        let den = Float::with_val(bits, &b * &c) * 2u32;
        Float::with_val(bits, num / den).acos()
    };
    std::array::from_fn(|v| {
        let o: Vec<usize> = (0..4).filter(|&w| w != v).collect();
        angle(v, o[0], o[1]) + angle(v, o[1], o[2]) + angle(v, o[0], o[2])
    })
}

/// Whether `H(u) − λI` is positive definite at `u` for the grounded Hessian `H = −∂θ/∂u`
/// on the free vertices `1, 2, 3` of [`tetrahedron_tangency_angles`]: central differences
/// of step `2⁻⁸⁰` at 512 bits (error far below `2⁻¹⁰⁰`), symmetrised, and Sylvester's
/// criterion on the three leading minors.
fn tetrahedron_hessian_above(u: [f64; 4], lambda: f64) -> bool {
    use rug::Float;
    let bits = 512;
    let h = Float::with_val(bits, Float::i_exp(1, -80));
    let mut m: [[Float; 3]; 3] = std::array::from_fn(|_| std::array::from_fn(|_| Float::new(bits)));
    for b in 1..4 {
        let at = |s: i32| {
            let x: [Float; 4] = std::array::from_fn(|k| {
                let mut x = Float::with_val(bits, u[k]);
                if k == b {
                    x += Float::with_val(bits, &h * s);
                }
                x
            });
            tetrahedron_tangency_angles(&x, bits)
        };
        let (plus, minus) = (at(1), at(-1));
        for a in 1..4 {
            let d = Float::with_val(bits, &minus[a] - &plus[a]) / Float::with_val(bits, &h * 2u32);
            m[a - 1][b - 1] = d;
        }
    }
    let s = |i: usize, j: usize| {
        let mut x = Float::with_val(bits, &m[i][j] + &m[j][i]) / 2u32;
        if i == j {
            x -= lambda;
        }
        x
    };
    let d1 = s(0, 0);
    let d2 = Float::with_val(bits, s(0, 0) * s(1, 1)) - Float::with_val(bits, s(0, 1) * s(0, 1));
    let d3 = Float::with_val(
        bits,
        s(0, 0)
            * (Float::with_val(bits, s(1, 1) * s(2, 2)) - Float::with_val(bits, s(1, 2) * s(1, 2))),
    ) - Float::with_val(
        bits,
        s(0, 1)
            * (Float::with_val(bits, s(0, 1) * s(2, 2)) - Float::with_val(bits, s(1, 2) * s(0, 2))),
    ) + Float::with_val(
        bits,
        s(0, 2)
            * (Float::with_val(bits, s(0, 1) * s(1, 2)) - Float::with_val(bits, s(1, 1) * s(0, 2))),
    );
    d1 > 0 && d2 > 0 && d3 > 0
}

/// The tangency pattern (`Φ = 0`) of the tetrahedron with every `Θ_v = π`: its solution
/// is `u = 0` (by symmetry), grounded at `v0`.
fn tetrahedron_tangency_pattern() -> CirclePattern {
    let p = pattern(tetrahedron().mesh, &rat(0, 1), vec![rat(1, 1); 4]);
    assert_eq!(p.free(), vec![1, 2, 3]);
    p
}

/// Whether the claim of `c` about the Hessian, `H(u) − λI` positive definite on the box
/// `ũ ± ρ`, holds at the box's eight corners ([`tetrahedron_hessian_above`]).
fn b94_lambda_holds_at_the_corners(c: &penner::circles::certify::Certificate) -> bool {
    let u: Vec<f64> = c.center.iter().map(Rational::to_f64).collect();
    (0..8).all(|k| {
        let mut x = [u[0], u[1], u[2], u[3]];
        for b in 0..3 {
            x[b + 1] += if k >> b & 1 == 1 { c.radius } else { -c.radius };
        }
        tetrahedron_hessian_above(x, c.lambda)
    })
}

/// B94 term `γ ≥ ‖Θ − θ(ũ)‖₂`: at `ũ = (0, δ, 0, 0)` near the solution `u = 0` of
/// [`tetrahedron_tangency_pattern`], the certificate's `γ` must bound the gradient on the
/// free vertices, recomputed independently at 256 bits ([`tetrahedron_tangency_angles`]),
/// and be tight (an enclosure's upper end); the box must hold the solution `0`, and its `λ`
/// hold at the corners. The squares are `|g|·|g|` summed: a product of them (`γ = 0`), a
/// sum of `|g|` or of ones gives another `γ`.
#[test]
fn term_b94_gradient_norm_bounds_the_independent_gradient() {
    use rug::Float;
    let bits = 256;
    let p = tetrahedron_tangency_pattern();
    let pi = Float::with_val(bits, rug::float::Constant::Pi);
    for delta in [1.0 / 1048576.0, -1.0 / 4194304.0, 1.0 / 67108864.0] {
        let u = [0.0, delta, 0.0, 0.0];
        let theta = tetrahedron_tangency_angles(&u.map(|x| Float::with_val(bits, x)), bits);
        let mut sq = Float::with_val(bits, 0);
        for t in &theta[1..] {
            let g = Float::with_val(bits, &pi - t);
            sq += Float::with_val(bits, &g * &g);
        }
        let gamma = sq.sqrt().to_f64();
        assert!(
            gamma > 1e-9,
            "δ = {delta}: the gradient is not small ({gamma})"
        );
        let c = penner::circles::certify::certify_solution(&p, &u, 128, 0.0)
            .unwrap_or_else(|e| panic!("δ = {delta}: {e}"));
        assert!(
            c.gradient_norm >= gamma && c.gradient_norm <= gamma * (1.0 + 1e-12),
            "δ = {delta}: γ = {} for ‖g‖₂ = {gamma}",
            c.gradient_norm
        );
        let reach = Rational::from_f64(c.radius).unwrap();
        for v in p.free() {
            assert!(
                Rational::from(c.center[v].abs_ref()) <= reach,
                "δ = {delta}: v{v}"
            );
        }
        assert!(b94_lambda_holds_at_the_corners(&c), "δ = {delta}");
    }
}

/// B94 term "`H − λI` positive definite for every `u` in `U`": the Hessian is enclosed over
/// the whole box `ũ ± ρ` (not at its centre or one corner) and shifted by `−λ`. Asked for a
/// box of half-width `ρ ≥ 2` around `ũ = (0, 2⁻²⁰, 0, 0)`, where the independent Hessian
/// ([`tetrahedron_hessian_above`]) has `λ_min < ¼` at a corner while the centre's is about
/// `0.58` (the certifier's `λ` is half of it), a certificate is refused or its `λ` holds at
/// every corner; a box of half-width `2⁻²⁰` is certified.
#[test]
fn term_b94_hessian_bound_holds_on_the_whole_box() {
    let p = tetrahedron_tangency_pattern();
    let u = [0.0, 1.0 / 1048576.0, 0.0, 0.0];
    let small = penner::circles::certify::certify_solution(&p, &u, 128, 1.0 / 1048576.0)
        .expect("a small box is certified");
    assert!(b94_lambda_holds_at_the_corners(&small));
    assert!(small.lambda > 0.25, "{}", small.lambda);
    for rho in [2.0, 4.0] {
        // The premise, from the oracle alone: some corner has λ_min(H) < ¼ < λ.
        let low_corner = (0..8).any(|k| {
            let mut x = u;
            for b in 0..3 {
                x[b + 1] += if k >> b & 1 == 1 { rho } else { -rho };
            }
            !tetrahedron_hessian_above(x, 0.25)
        });
        assert!(low_corner, "ρ = {rho}");
        if let Ok(c) = penner::circles::certify::certify_solution(&p, &u, 128, rho) {
            assert!(
                b94_lambda_holds_at_the_corners(&c),
                "ρ = {rho}: λ = {}",
                c.lambda
            );
        }
    }
}

/// B94 term "`H − λI` positive definite", the shift `−λ` on the diagonal: the hull of
/// `[[1, b], [b, 1]]`, `b ∈ [0.4, 0.5]`, has eigenvalues `1 ± b` (closed form), smallest
/// `½`. With `λ = 0.4` every `H − λI` is positive definite; with `λ = ½` one member is
/// singular and with `λ = 0.6` indefinite, both refused (`H + λI` would be positive
/// definite in all three).
#[test]
fn term_b94_lambda_is_subtracted_from_the_hessian() {
    use penner::circles::certify::shifted_positive_definite;
    use penner::scalar::Interval;
    let p = Precision::new(128).unwrap();
    let iv = |lo: f64, hi: f64| Interval::new(Mpfr::from_f64(lo, p), Mpfr::from_f64(hi, p));
    let hull = || {
        vec![
            vec![iv(1.0, 1.0), iv(0.4, 0.5)],
            vec![iv(0.4, 0.5), iv(1.0, 1.0)],
        ]
    };
    for (lambda, pd) in [(0.4, true), (0.5, false), (0.6, false), (0.0, true)] {
        let closed_form = 1.0 - 0.5 - lambda > 0.0;
        assert_eq!(closed_form, pd);
        assert_eq!(
            shifted_positive_definite(hull(), &iv(lambda, lambda)),
            pd,
            "λ = {lambda}"
        );
    }
}

/// A simplicial sphere (icosahedron) or torus (3×4 or 4×4 grid) with 1–3 random faces split
/// (vertex insertion keeps it simplicial).
fn simplicial_surface(case: usize, rng: &mut ChaCha8Rng) -> Mesh {
    let mut mesh = if case % 2 == 0 {
        icosahedron().mesh
    } else {
        penner::mesh::builders::flat_torus(3 + (case / 2 % 2) as u32, 4)
            .unwrap()
            .mesh
    };
    for _ in 0..rng.gen_range(1..=3) {
        let f = penner::mesh::Face(rng.gen_range(0..mesh.n_faces() as u32));
        mesh.split_face(f).unwrap();
    }
    mesh
}

#[test]
fn t09_rigidity_random_surfaces() {
    let mut rng = ChaCha8Rng::seed_from_u64(90);
    let choices = [rat(0, 1), rat(1, 6), rat(1, 4)];
    for case in 0..cases(4, 40) {
        let mesh = simplicial_surface(case, &mut rng);
        let phi: Vec<Rational> = (0..mesh.n_edges())
            .map(|_| choices[rng.gen_range(0..choices.len())].clone())
            .collect();
        let targets = degree_targets(&mesh).into_iter().map(Some).collect();
        let p = CirclePattern::new(mesh.clone(), phi, targets).unwrap();
        let starts = fixed_starts(mesh.n_vertices());
        let mut all = runs::<f64>(&p, &starts, ());
        all.extend(runs::<Dd>(&p, &starts, ()));
        all.extend(runs::<Mpfr>(&p, &starts[1..], p256()));
        let v = verify_rigidity(&p, &all);
        assert!(
            matches!(
                v,
                penner::theorems::Verdict::Holds {
                    certified: true,
                    ..
                }
            ),
            "case {case}: {v:?}"
        );
        // Independent of the solver: the radii reproduce the targets when the cone angles are
        // recomputed at MPFR from the f64 solution (to f64 accuracy).
        let u: Vec<Mpfr> = all[0]
            .u
            .iter()
            .map(|&x| Mpfr::from_f64(x, p256()))
            .collect();
        let c = p.cos_phi::<Mpfr>(p256());
        let rr: Vec<Mpfr> = u.iter().map(Real::exp).collect();
        let theta = cone_angles(&mesh, &lengths_from_radii(&mesh, &rr, &c));
        for (t, want) in theta.iter().zip(p.target_angles::<Mpfr>(p256())) {
            assert!((t.clone() - &want).approx_f64().abs() < 1e-12);
        }
        // The starts really differ from the solution.
        assert!(all[0].iterations > 0 && all[1].iterations > 0);
    }
}

#[test]
fn t34_stellated_solids_admit_no_rivin_weights() {
    use penner::circles::rivin::{
        are_rivin_weights, certificate_strings, steiner_certificate, verify_certificate_num,
        verify_certificate_rug,
    };
    use penner::mesh::builders::{triakis_octahedron, triakis_tetrahedron};
    use penner::theorems::t34_steiner_rivin::check_no_rivin_weights;
    for mesh in [triakis_tetrahedron().mesh, triakis_octahedron().mesh] {
        let v = check_no_rivin_weights(&mesh);
        assert!(
            matches!(
                v,
                penner::theorems::Verdict::Holds {
                    certified: true,
                    ..
                }
            ),
            "{v:?}"
        );
        let y = steiner_certificate(&mesh).unwrap();
        assert!(verify_certificate_rug(&mesh, &y));
        assert!(verify_certificate_num(&mesh, &certificate_strings(&y)));
        // Negative control: the certificate with one entry raised by 1 is refused by both
        // verifications (an edge coefficient becomes positive).
        let mut bad = y.clone();
        bad[0] += 1;
        assert!(!verify_certificate_rug(&mesh, &bad));
        assert!(!verify_certificate_num(&mesh, &certificate_strings(&bad)));
    }
    // The regular solids are inscribed: uniform weights 1/degree are Rivin weights (checked
    // exactly), no certificate exists (the verdict stays undecided, never a false proof),
    // and the stellated certificate does not transfer.
    for (mesh, deg) in [(octahedron().mesh, 4), (icosahedron().mesh, 5)] {
        let w = vec![rat(1, deg); mesh.n_edges()];
        assert!(are_rivin_weights(&mesh, &w));
        assert!(steiner_certificate(&mesh).is_none());
        let v = penner::theorems::t34_steiner_rivin::check_no_rivin_weights(&mesh);
        assert!(!v.holds(), "{v:?}");
        let y = vec![rat(1, 2); mesh.n_vertices()];
        assert!(!verify_certificate_rug(&mesh, &y));
        assert!(!verify_certificate_num(&mesh, &certificate_strings(&y)));
    }
    // Control of the weight checker: weights 1/4 on the icosahedron sum to 5/4.
    let ico = icosahedron().mesh;
    assert!(!are_rivin_weights(&ico, &vec![rat(1, 4); ico.n_edges()]));
}
