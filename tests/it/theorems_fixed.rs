//! Theorem checks T01, T03–T05, T07, T15–T20 on fixed and seeded random surfaces, at f64,
//! double-double, MPFR-128/256 and (where the statement is algebraic) exactly in ℚ. Every
//! theorem has a negative control that the same check rejects.

use crate::support::{case_seeds, cases};
use penner::geometry::curvature::curvature;
use penner::geometry::laplacian::cotan_laplacian;
use penner::geometry::scaling::conformal_scaling;
use penner::mesh::Mesh;
use penner::scalar::{Dd, Mpfr, Precision, Real};
use penner::theorems::t01_gauss_bonnet::{
    check_gauss_bonnet, gauss_bonnet_error_bound, verify_gauss_bonnet,
};
use penner::theorems::t03_angle_rigidity::check_equal_angles_imply_scale;
use penner::theorems::t04_angle_integrability::{
    check_angle_integrability, check_angle_integrability_from_lengths,
};
use penner::theorems::t05_cotan_laplacian::{
    check_cotan_laplacian, check_linear_precision, verify_laplacian,
};
use penner::theorems::t07_conformal_energy::{
    check_conformal_energy, verify_conformal_energy, EnergyTerms,
};
use penner::theorems::t15_lemma1::{
    check_lemma1, check_lemma1_exact, verify_lemma1, verify_lemma1_exact,
};
use penner::theorems::t16_scaling_cross_ratios::{
    check_scaling_preserves_cross_ratios, check_scaling_preserves_cross_ratios_exact,
    verify_equal_cross_ratios, verify_equal_cross_ratios_exact,
};
use penner::theorems::t17_cross_ratio_equivalence::{
    check_conformal_equivalence, check_conformal_equivalence_exact,
};
use penner::theorems::t18_two_triangle_sphere::{
    check_all_metrics_equivalent, check_all_metrics_equivalent_exact,
};
use penner::theorems::t19_one_vertex_torus::{
    check_equivalent_iff_uniform_scale, check_equivalent_iff_uniform_scale_exact,
};
use penner::theorems::t20_mobius_cross_ratios::{
    check_mobius_preserves_cross_ratios, check_mobius_preserves_cross_ratios_exact,
    verify_map_preserves_cross_ratios_exact,
};
use penner::theorems::{Settings, Verdict};
use proptest::prelude::*;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rug::Rational;

// ---------------------------------------------------------------- surfaces

fn tetrahedron() -> Mesh {
    Mesh::from_faces(4, &[[0, 1, 2], [0, 2, 3], [0, 3, 1], [1, 3, 2]]).unwrap()
}

/// Octahedron with vertices ±x (0, 1), ±y (2, 3), ±z (4, 5), faces outward.
fn octahedron() -> Mesh {
    Mesh::from_faces(
        6,
        &[
            [0, 2, 4],
            [2, 1, 4],
            [1, 3, 4],
            [3, 0, 4],
            [2, 0, 5],
            [1, 2, 5],
            [3, 1, 5],
            [0, 3, 5],
        ],
    )
    .unwrap()
}

fn two_triangle_sphere() -> Mesh {
    Mesh::from_faces(3, &[[0, 1, 2], [0, 2, 1]]).unwrap()
}

fn one_vertex_torus() -> Mesh {
    Mesh::from_gluing(
        1,
        &[[0, 0, 0], [0, 0, 0]],
        &[((0, 0), (1, 0)), ((0, 1), (1, 1)), ((0, 2), (1, 2))],
    )
    .unwrap()
}

/// `n × n` vertex grid in the plane, interior vertices jittered by ≤ 0.2 (fixed seed),
/// squares split along the main diagonal.
fn grid(n: u32, seed: u64) -> (Mesh, Vec<[f64; 3]>) {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let v = |i: u32, j: u32| j * n + i;
    let mut faces = Vec::new();
    for j in 0..n - 1 {
        for i in 0..n - 1 {
            faces.push([v(i, j), v(i + 1, j), v(i + 1, j + 1)]);
            faces.push([v(i, j), v(i + 1, j + 1), v(i, j + 1)]);
        }
    }
    let mut p = Vec::new();
    for j in 0..n {
        for i in 0..n {
            let interior = i > 0 && j > 0 && i < n - 1 && j < n - 1;
            let (dx, dy) = if interior {
                (rng.gen_range(-0.2..0.2), rng.gen_range(-0.2..0.2))
            } else {
                (0.0, 0.0)
            };
            p.push([f64::from(i) + dx, f64::from(j) + dy, 0.0]);
        }
    }
    (Mesh::from_faces(n * n, &faces).unwrap(), p)
}

/// Octahedron vertices ±e_k moved by ≤ 0.3 (a convex embedding for every seed).
fn octahedron_points(seed: u64) -> Vec<[f64; 3]> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut p = Vec::new();
    for k in 0..3 {
        for s in [1.0, -1.0] {
            let mut x = [0.0; 3];
            x[k] = s;
            for c in &mut x {
                *c += rng.gen_range(-0.3..0.3);
            }
            p.push(x);
        }
    }
    p
}

fn tetrahedron_points(seed: u64) -> Vec<[f64; 3]> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let base = [
        [1.0, 1.0, 1.0],
        [1.0, -1.0, -1.0],
        [-1.0, 1.0, -1.0],
        [-1.0, -1.0, 1.0],
    ];
    base.iter()
        .map(|b| b.map(|x| x + rng.gen_range(-0.3..0.3)))
        .collect()
}

/// Edge lengths `|p_j − p_i|` computed in `T`.
fn lengths_in<T: Real>(mesh: &Mesh, p: &[[f64; 3]], ctx: T::Ctx) -> Vec<T> {
    mesh.edges()
        .map(|e| {
            let h = e.halfedge();
            let (a, b) = (p[mesh.tail(h).idx()], p[mesh.tip(h).idx()]);
            let mut s = T::from_f64(0.0, ctx);
            for k in 0..3 {
                let d = T::from_f64(b[k], ctx) - &T::from_f64(a[k], ctx);
                s += &(d.clone() * &d);
            }
            s.sqrt()
        })
        .collect()
}

fn to_t<T: Real>(x: &[f64], ctx: T::Ctx) -> Vec<T> {
    x.iter().map(|&v| T::from_f64(v, ctx)).collect()
}

fn p128() -> Precision {
    Precision::new(128).unwrap()
}
fn p256() -> Precision {
    Precision::new(256).unwrap()
}

/// Run a generic body at f64, double-double, MPFR-128 and MPFR-256.
macro_rules! at_all_precisions {
    ($body:ident) => {
        $body::<f64>(());
        if dd_enabled() {
            $body::<Dd>(());
        }
        $body::<Mpfr>(p128());
        $body::<Mpfr>(p256());
    };
}

/// Double-double runs need double-double arithmetic and functions accurate to the
/// hypothesis of proofs/B40 (relative error ≤ 16·2⁻¹⁰⁶). A probe against MPFR-256 checks
/// it and fails the test when it does not hold (a broken backend must not turn the
/// double-double runs off silently); `PENNER_SKIP_DD` skips them explicitly, reported on
/// stderr.
fn dd_enabled() -> bool {
    if std::env::var_os("PENNER_SKIP_DD").is_some() {
        eprintln!("double-double runs skipped: PENNER_SKIP_DD is set");
        return false;
    }
    let p = p256();
    let close = |x: Dd, y: Mpfr| {
        let (Some(a), Some(b)) = (x.to_rational(), y.to_rational()) else {
            return false;
        };
        let tol = Rational::from_f64(16.0 * Dd::unit_roundoff(())).unwrap() * b.clone().abs();
        (a - b).abs() <= tol
    };
    let d = |x: f64| <Dd as Real>::from_f64(x, ());
    let m = |x: f64| Mpfr::from_f64(x, p);
    let ok = close(d(1.0) / d(3.0), m(1.0) / m(3.0))
        && close(d(0.7).atan(), m(0.7).atan())
        && close(d(0.7).exp(), m(0.7).exp())
        && close(d(0.7).sin(), m(0.7).sin())
        && close(d(2.0).sqrt(), m(2.0).sqrt());
    assert!(
        ok,
        "the double-double probe is not accurate to 16·2^-106 (proofs/B40): set PENNER_SKIP_DD to skip the double-double runs knowingly"
    );
    true
}

fn settings() -> Settings {
    Settings::default()
}

fn assert_holds(v: &Verdict, what: &str) {
    assert!(v.holds(), "{what}: expected Holds, got {v:?}");
}

fn witnesses(v: &Verdict) -> Vec<String> {
    match v {
        Verdict::Fails { witnesses, .. } => witnesses.iter().map(|w| w.element.clone()).collect(),
        other => panic!("expected Fails, got {other:?}"),
    }
}

fn q(x: i64) -> Rational {
    Rational::from(x)
}

fn random_rational(rng: &mut ChaCha8Rng, lo: i64, hi: i64) -> Rational {
    Rational::from((rng.gen_range(lo..hi), rng.gen_range(1..17_i64)))
}

// ---------------------------------------------------------------- T01

fn t01_body<T: Real>(ctx: T::Ctx) {
    let name = T::backend_name(ctx);
    let mut surfaces: Vec<(&str, Mesh, Vec<T>)> = vec![
        (
            "tetrahedron",
            tetrahedron(),
            lengths_in(&tetrahedron(), &tetrahedron_points(1), ctx),
        ),
        (
            "octahedron",
            octahedron(),
            lengths_in(&octahedron(), &octahedron_points(2), ctx),
        ),
        ("torus", one_vertex_torus(), to_t(&[3.0, 4.0, 5.5], ctx)),
        (
            "sphere2",
            two_triangle_sphere(),
            to_t(&[2.0, 3.0, 4.0], ctx),
        ),
    ];
    let (g, p) = grid(5, 3);
    surfaces.push(("grid", g.clone(), lengths_in(&g, &p, ctx)));
    // A non-flat disk: the grid with its interior lifted.
    let lifted: Vec<[f64; 3]> = p
        .iter()
        .map(|x| [x[0], x[1], (x[0] * x[1]).sin()])
        .collect();
    surfaces.push(("bumpy grid", g.clone(), lengths_in(&g, &lifted, ctx)));
    for (what, m, l) in &surfaces {
        assert_holds(
            &check_gauss_bonnet(m, l, &settings()),
            &format!("{what} at {name}"),
        );
        // Negative control: one curvature moved by 4× the bound (and by 1e-12 at high
        // precision) is rejected by the same comparison.
        let bound = gauss_bonnet_error_bound(m, l);
        for delta in [4.0 * bound, 1e-12] {
            if T::precision_bits(ctx) <= 53 && delta == 1e-12 {
                continue;
            }
            let mut k = curvature(m, l);
            k[0] += &T::from_f64(delta, ctx);
            let v = verify_gauss_bonnet(m, l, &k, &settings());
            assert_eq!(
                witnesses(&v),
                vec!["surface".to_string()],
                "{what} at {name}, δ = {delta:e}"
            );
        }
    }
}

#[test]
fn t01_gauss_bonnet_holds_with_derived_tolerance_and_rejects_perturbed_curvature() {
    at_all_precisions!(t01_body);
}

#[test]
fn t01_tolerance_scales_with_precision() {
    let m = octahedron();
    let p = octahedron_points(5);
    let b53 = gauss_bonnet_error_bound(&m, &lengths_in::<f64>(&m, &p, ()));
    let b256 = gauss_bonnet_error_bound(&m, &lengths_in::<Mpfr>(&m, &p, p256()));
    assert!(b53 < 1e-10, "f64 bound {b53:e}");
    assert!(b256 < 1e-70, "mpfr-256 bound {b256:e}");
}

#[test]
fn t01_random_octahedra_f64() {
    for seed in case_seeds(50, 100_000) {
        let m = octahedron();
        let l = lengths_in::<f64>(&m, &octahedron_points(seed), ());
        assert_holds(
            &check_gauss_bonnet(&m, &l, &settings()),
            &format!("seed {seed}"),
        );
    }
}

// ---------------------------------------------------------------- T03

fn t03_body<T: Real>(ctx: T::Ctx) {
    let m = octahedron();
    let l: Vec<T> = lengths_in(&m, &octahedron_points(7), ctx);
    let three = T::from_f64(3.0, ctx);
    let lt: Vec<T> = l.iter().map(|x| x.clone() * &three).collect();
    assert_holds(
        &check_equal_angles_imply_scale(&m, &l, &lt, &settings()),
        "uniform scale",
    );
    // A non-uniform conformal scaling changes the angles: hypothesis refused.
    let u = to_t::<T>(&[0.0, 0.1, 0.0, 0.0, 0.0, 0.0], ctx);
    let ls = conformal_scaling(&m, &l, &u);
    assert!(matches!(
        check_equal_angles_imply_scale(&m, &l, &ls, &settings()),
        Verdict::NotApplicable { .. }
    ));
    // Negative control: two components scaled by 2 and 3 keep every angle.
    let two = Mesh::from_faces(6, &[[0, 1, 2], [3, 4, 5]]).unwrap();
    let l2 = to_t::<T>(&[3.0, 4.0, 5.0, 3.0, 4.0, 5.0], ctx);
    let mut lt2 = l2.clone();
    for e in two.edges() {
        let s = if two.tail(e.halfedge()).0 < 3 {
            2.0
        } else {
            3.0
        };
        lt2[e.idx()] = l2[e.idx()].clone() * &T::from_f64(s, ctx);
    }
    let w = witnesses(&check_equal_angles_imply_scale(
        &two,
        &l2,
        &lt2,
        &settings(),
    ));
    assert_eq!(w.len(), 3, "{w:?}");
}

#[test]
fn t03_equal_angles_imply_one_scale() {
    at_all_precisions!(t03_body);
}

// ---------------------------------------------------------------- T04

fn t04_body<T: Real>(ctx: T::Ctx) {
    let (g, p) = grid(5, 11);
    let l: Vec<T> = lengths_in(&g, &p, ctx);
    assert_holds(
        &check_angle_integrability_from_lengths(&g, &l, &settings()),
        "planar grid",
    );
    // Fig. 5 shape: a flower of three triangles around vertex 0 with angle 2π/3 at the
    // center and π/6 ± δ at the petals: all sums Euclidean, sine closure violated.
    let flower = Mesh::from_faces(4, &[[0, 1, 2], [0, 2, 3], [0, 3, 1]]).unwrap();
    let pi = T::pi(ctx);
    let lit = |x: f64| T::from_f64(x, ctx);
    let mut a = vec![lit(0.0); flower.n_halfedges()];
    for h in flower.halfedges() {
        if !flower.is_boundary_halfedge(h) && flower.tail(h).0 == 0 {
            let delta = lit(0.1);
            a[flower.next(h).idx()] = pi.clone() * &lit(2.0) / &lit(3.0);
            a[h.idx()] = pi.clone() / &lit(6.0) + &delta;
            a[flower.prev(h).idx()] = pi.clone() / &lit(6.0) - &delta;
        }
    }
    let err = vec![16.0 * 4.0 * T::unit_roundoff(ctx) * 4.0; flower.n_halfedges()];
    let v = check_angle_integrability(&flower, &a, &err, &settings());
    let w = match &v {
        Verdict::Fails { witnesses, .. } => witnesses.clone(),
        other => panic!("Fig. 5 shape accepted: {other:?}"),
    };
    assert_eq!(w.len(), 1, "{w:?}");
    assert_eq!(w[0].element, "v0");
    assert!(w[0].detail.starts_with("sine closure"), "{w:?}");
    // Negative control for the sums: one angle of the planar grid moved by 1e-9 relative.
    let mut errs = vec![0.0; g.n_halfedges()];
    let mut ang = penner::geometry::corners::halfedge_angles(&g, &l);
    let eps = 16.0 * T::unit_roundoff(ctx);
    for (k, x) in ang.iter().enumerate() {
        errs[k] = 40.0 * eps * x.approx_f64().abs() + 0.0;
    }
    let h = g
        .halfedges()
        .find(|&h| !g.is_boundary_halfedge(h) && !g.boundary_vertices()[g.tail(g.prev(h)).idx()])
        .unwrap();
    ang[h.idx()] += &lit(1e-9);
    let w = witnesses(&check_angle_integrability(&g, &ang, &errs, &settings()));
    assert!(w.iter().any(|x| x.starts_with('f')), "{w:?}");
}

#[test]
fn t04_planar_angles_integrable_and_fig5_sine_condition_rejected() {
    at_all_precisions!(t04_body);
}

// ---------------------------------------------------------------- T05

fn t05_body<T: Real>(ctx: T::Ctx) {
    let (g, p) = grid(5, 13);
    let lg: Vec<T> = lengths_in(&g, &p, ctx);
    let bumpy: Vec<[f64; 3]> = p
        .iter()
        .map(|x| [x[0], x[1], 0.3 * (x[0] + 2.0 * x[1]).sin()])
        .collect();
    for (what, m, l) in [
        (
            "tetrahedron",
            tetrahedron(),
            lengths_in::<T>(&tetrahedron(), &tetrahedron_points(3), ctx),
        ),
        (
            "octahedron",
            octahedron(),
            lengths_in::<T>(&octahedron(), &octahedron_points(4), ctx),
        ),
        (
            "torus",
            one_vertex_torus(),
            to_t::<T>(&[3.0, 4.0, 5.5], ctx),
        ),
        ("grid", g.clone(), lg.clone()),
        ("bumpy grid", g.clone(), lengths_in::<T>(&g, &bumpy, ctx)),
    ] {
        assert_holds(&check_cotan_laplacian(&m, &l, &settings()), what);
    }
    let pos: Vec<[T; 2]> = p
        .iter()
        .map(|x| [T::from_f64(x[0], ctx), T::from_f64(x[1], ctx)])
        .collect();
    assert_holds(
        &check_linear_precision(&g, &pos, &lg, &settings()),
        "flat grid",
    );
    // Negative control (linear precision): lift interior vertex 6 out of the plane.
    let mut lifted = p.clone();
    lifted[6][2] = 0.3;
    let lw = lengths_in::<T>(&g, &lifted, ctx);
    let w = witnesses(&check_linear_precision(&g, &pos, &lw, &settings()));
    assert!(w.contains(&"v6".to_string()), "{w:?}");
    // Negative controls (matrix): break symmetry; make −L indefinite keeping symmetry and
    // zero rows.
    let m = octahedron();
    let l = lengths_in::<T>(&m, &octahedron_points(4), ctx);
    let mut lap = cotan_laplacian(&m, &l);
    let tiny = if T::precision_bits(ctx) <= 53 {
        1e-12
    } else {
        1e-20
    };
    *lap.get_mut(0, 2).unwrap() += &T::from_f64(tiny, ctx);
    let w = witnesses(&verify_laplacian(&m, &lap, &settings()));
    assert!(
        w.contains(&"L[0,2]".to_string()) && w.contains(&"row 0".to_string()),
        "{w:?}"
    );
    let mut lap = cotan_laplacian(&m, &l);
    let big = T::from_f64(-10.0, ctx);
    let old = lap.get(0, 2).unwrap().clone();
    let shift = big.clone() - &old;
    *lap.get_mut(0, 2).unwrap() = big.clone();
    *lap.get_mut(2, 0).unwrap() = big;
    *lap.get_mut(0, 0).unwrap() -= &shift;
    *lap.get_mut(2, 2).unwrap() -= &shift;
    let w = witnesses(&verify_laplacian(&m, &lap, &settings()));
    assert!(w.len() == 1 && w[0].starts_with("pivot"), "{w:?}");
}

#[test]
fn t05_cotan_laplacian_symmetric_zero_rows_semidefinite_linear_precision() {
    at_all_precisions!(t05_body);
}

// ---------------------------------------------------------------- T07

fn t07_body<T: Real>(ctx: T::Ctx) {
    let mut rng = ChaCha8Rng::seed_from_u64(17);
    let (g, p) = grid(4, 19);
    let bumpy: Vec<[f64; 3]> = p
        .iter()
        .map(|x| [x[0], x[1], 0.3 * (x[0] * x[1]).cos()])
        .collect();
    for (what, m, l) in [
        ("grid", g.clone(), lengths_in::<T>(&g, &p, ctx)),
        ("bumpy grid", g.clone(), lengths_in::<T>(&g, &bumpy, ctx)),
        (
            "octahedron",
            octahedron(),
            lengths_in::<T>(&octahedron(), &octahedron_points(8), ctx),
        ),
    ] {
        let f: Vec<[T; 2]> = (0..m.n_vertices())
            .map(|_| {
                [
                    T::from_f64(rng.gen_range(-2.0..2.0), ctx),
                    T::from_f64(rng.gen_range(-2.0..2.0), ctx),
                ]
            })
            .collect();
        assert_holds(&check_conformal_energy(&m, &l, &f, &settings()), what);
    }
    // Negative control: the identity with the area's sign flipped (E_D + A) is rejected.
    let l = lengths_in::<T>(&g, &p, ctx);
    let f: Vec<[T; 2]> = p
        .iter()
        .map(|x| [T::from_f64(x[0] * 1.5, ctx), T::from_f64(x[1] - x[0], ctx)])
        .collect();
    let w = penner::geometry::cotan::cotan_weights(&g, &l);
    let terms = EnergyTerms {
        dirichlet: penner::geometry::energy::dirichlet_energy(&g, &w, &f).unwrap(),
        area: -penner::geometry::energy::signed_area(&g, &f).unwrap(),
        cauchy_riemann: penner::geometry::energy::cauchy_riemann_energy(&g, &l, &f).unwrap(),
        error_bound: penner::theorems::t07_conformal_energy::energy_error_bound(&g, &l, &f),
    };
    assert_eq!(
        witnesses(&verify_conformal_energy(&terms, &settings())),
        vec!["surface".to_string()]
    );
}

#[test]
fn t07_conformal_energy_is_dirichlet_minus_area() {
    at_all_precisions!(t07_body);
}

#[test]
fn t07_holomorphic_map_has_zero_conformal_energy() {
    // f(z) = z² restricted to vertices is not holomorphic on triangles, but f(z) = (2+i)z + 1
    // is affine-holomorphic: E_D = A exactly in exact arithmetic.
    let (g, p) = grid(4, 23);
    let l = lengths_in::<Mpfr>(&g, &p, p256());
    let f: Vec<[Mpfr; 2]> = p
        .iter()
        .map(|x| {
            let (a, b) = (Mpfr::from_f64(x[0], p256()), Mpfr::from_f64(x[1], p256()));
            let two = Mpfr::from_f64(2.0, p256());
            let re = two.clone() * &a - &b + &Mpfr::from_f64(1.0, p256());
            let im = a + &(two * &b);
            [re, im]
        })
        .collect();
    let w = penner::geometry::cotan::cotan_weights(&g, &l);
    let e = penner::geometry::energy::conformal_energy(&g, &w, &f).unwrap();
    assert!(e.approx_f64().abs() < 1e-60, "{}", e.approx_f64());
    assert_holds(
        &check_conformal_energy(&g, &l, &f, &settings()),
        "affine holomorphic",
    );
}

// ---------------------------------------------------------------- T15–T19

fn random_metric<T: Real>(rng: &mut ChaCha8Rng, n: usize, ctx: T::Ctx) -> Vec<T> {
    (0..n)
        .map(|_| T::from_f64(rng.gen_range(0.5..2.0), ctx))
        .collect()
}

fn t15_body<T: Real>(ctx: T::Ctx) {
    let mut rng = ChaCha8Rng::seed_from_u64(29);
    let m = octahedron();
    let l: Vec<T> = random_metric(&mut rng, m.n_edges(), ctx);
    let lt: Vec<T> = random_metric(&mut rng, m.n_edges(), ctx);
    assert_holds(&check_lemma1(&m, &l, &lt, &settings()), "lemma 1");
    let mut r = penner::geometry::scaling::reconstruct_scale_factors(&m, &l, &lt);
    let h = m.halfedges().find(|&h| !m.is_boundary_halfedge(h)).unwrap();
    if let Some(x) = r.corner_exp_u[h.idx()].as_mut() {
        *x *= &(T::from_f64(1.0, ctx) + &T::from_f64(1e-12, ctx));
    }
    let w = witnesses(&verify_lemma1(&m, &l, &lt, &r.corner_exp_u, &settings()));
    // The perturbed corner touches the two edges of its face at that corner.
    assert_eq!(w.len(), 2, "{w:?}");
}

#[test]
fn t15_lemma1_relates_any_two_metrics_on_a_triangle() {
    at_all_precisions!(t15_body);
}

#[test]
fn t15_lemma1_exact() {
    let mut rng = ChaCha8Rng::seed_from_u64(31);
    let m = octahedron();
    for _ in 0..cases(20, 2000) {
        let l: Vec<Rational> = (0..12).map(|_| random_rational(&mut rng, 1, 40)).collect();
        let lt: Vec<Rational> = (0..12).map(|_| random_rational(&mut rng, 1, 40)).collect();
        assert_eq!(
            check_lemma1_exact(&m, &l, &lt),
            Verdict::Holds {
                certified: true,
                max_error: 0.0
            }
        );
        let mut r = penner::geometry::scaling::reconstruct_scale_factors(&m, &l, &lt);
        if let Some(x) = r.corner_exp_u[0].as_mut() {
            *x += Rational::from((1, 1_000_000_007));
        }
        assert_eq!(
            witnesses(&verify_lemma1_exact(&m, &l, &lt, &r.corner_exp_u)).len(),
            2
        );
    }
}

fn t16_body<T: Real>(ctx: T::Ctx) {
    let mut rng = ChaCha8Rng::seed_from_u64(37);
    let m = octahedron();
    let l: Vec<T> = lengths_in(&m, &octahedron_points(9), ctx);
    let u: Vec<T> = (0..6)
        .map(|_| T::from_f64(rng.gen_range(-1.5..1.5), ctx))
        .collect();
    assert_holds(
        &check_scaling_preserves_cross_ratios(&m, &l, &u, &settings()),
        "scaling",
    );
    // Negative control: one scaled edge moved by 1e-12 relative.
    let mut lt = conformal_scaling(&m, &l, &u);
    lt[3] *= &(T::from_f64(1.0, ctx) + &T::from_f64(1e-12, ctx));
    let errs = vec![1e-30; m.n_edges()];
    let v = verify_equal_cross_ratios(&m, &l, &lt, &errs, &errs, &settings());
    // Edge 3 appears in the cross ratios of the four edges of its two faces.
    assert_eq!(witnesses(&v).len(), 4, "{v:?}");
}

#[test]
fn t16_scaling_preserves_cross_ratios() {
    // f64 cannot see a 1e-12 perturbation against its own tolerance: run the high precisions.
    if dd_enabled() {
        t16_body::<Dd>(());
    }
    t16_body::<Mpfr>(p128());
    t16_body::<Mpfr>(p256());
    let m = octahedron();
    let l: Vec<f64> = lengths_in(&m, &octahedron_points(9), ());
    assert_holds(
        &check_scaling_preserves_cross_ratios(
            &m,
            &l,
            &[0.3, -0.2, 1.0, 0.0, 0.5, -1.0],
            &settings(),
        ),
        "f64",
    );
}

proptest! {
    #![proptest_config(crate::support::proptest_config(64, 100_000))]
    #[test]
    fn t16_scaling_preserves_cross_ratios_exact(
        l in prop::collection::vec((1i64..50, 1i64..9), 12),
        s in prop::collection::vec((1i64..30, 1i64..9), 6),
        bump in 0usize..12,
    ) {
        let m = octahedron();
        let l: Vec<Rational> = l.into_iter().map(Rational::from).collect();
        let s: Vec<Rational> = s.into_iter().map(Rational::from).collect();
        prop_assert_eq!(check_scaling_preserves_cross_ratios_exact(&m, &l, &s), Verdict::Holds { certified: true, max_error: 0.0 });
        let mut lt = penner::geometry::scaling::conformal_scaling_exact(&m, &l, &s);
        lt[bump] *= Rational::from((1_000_001, 1_000_000));
        prop_assert_eq!(witnesses(&verify_equal_cross_ratios_exact(&m, &l, &lt)).len(), 4);
    }
}

fn t17_body<T: Real>(ctx: T::Ctx) {
    let mut rng = ChaCha8Rng::seed_from_u64(41);
    for (m, l) in [
        (
            octahedron(),
            lengths_in::<T>(&octahedron(), &octahedron_points(10), ctx),
        ),
        (
            tetrahedron(),
            lengths_in::<T>(&tetrahedron(), &tetrahedron_points(11), ctx),
        ),
    ] {
        let u: Vec<T> = (0..m.n_vertices())
            .map(|_| T::from_f64(rng.gen_range(-1.0..1.0), ctx))
            .collect();
        let lt = conformal_scaling(&m, &l, &u);
        assert_holds(
            &check_conformal_equivalence(&m, &l, &lt, &settings()),
            "scaled metric",
        );
        // Negative control: a perturbed metric (relative 1e-6 at f64, 1e-24 above) is refused.
        let rel = if T::precision_bits(ctx) <= 53 {
            1e-6
        } else {
            1e-24
        };
        let mut bad = lt.clone();
        bad[0] *= &(T::from_f64(1.0, ctx) + &T::from_f64(rel, ctx));
        let v = check_conformal_equivalence(&m, &l, &bad, &settings());
        assert!(
            v.fails(),
            "{} vertices at {}: {v:?}",
            m.n_vertices(),
            T::backend_name(ctx)
        );
    }
}

#[test]
fn t17_equal_cross_ratios_reconstruct_scale_factors() {
    at_all_precisions!(t17_body);
}

#[test]
fn t17_exact_reconstruction_and_refusal() {
    let mut rng = ChaCha8Rng::seed_from_u64(43);
    let m = octahedron();
    for _ in 0..cases(20, 5000) {
        let l: Vec<Rational> = (0..12).map(|_| random_rational(&mut rng, 1, 40)).collect();
        let s: Vec<Rational> = (0..6).map(|_| random_rational(&mut rng, 1, 40)).collect();
        let lt = penner::geometry::scaling::conformal_scaling_exact(&m, &l, &s);
        assert_eq!(
            check_conformal_equivalence_exact(&m, &l, &lt),
            Verdict::Holds {
                certified: true,
                max_error: 0.0
            }
        );
        let mut bad = lt.clone();
        bad[5] += Rational::from((1, 1000));
        assert!(check_conformal_equivalence_exact(&m, &l, &bad).fails());
    }
}

fn t18_body<T: Real>(ctx: T::Ctx) {
    let mut rng = ChaCha8Rng::seed_from_u64(47);
    let s = two_triangle_sphere();
    let t = tetrahedron();
    for _ in 0..10 {
        let l: Vec<T> = random_metric(&mut rng, 3, ctx);
        let lt: Vec<T> = random_metric(&mut rng, 3, ctx);
        assert_holds(
            &check_all_metrics_equivalent(&s, &l, &lt, &settings()),
            "two-triangle sphere",
        );
        let l: Vec<T> = random_metric(&mut rng, 6, ctx);
        let lt: Vec<T> = random_metric(&mut rng, 6, ctx);
        assert!(
            check_all_metrics_equivalent(&t, &l, &lt, &settings()).fails(),
            "tetrahedron"
        );
    }
}

#[test]
fn t18_two_triangle_sphere_all_metrics_equivalent() {
    at_all_precisions!(t18_body);
    let mut rng = ChaCha8Rng::seed_from_u64(53);
    for _ in 0..cases(20, 5000) {
        let l: Vec<Rational> = (0..3).map(|_| random_rational(&mut rng, 1, 40)).collect();
        let lt: Vec<Rational> = (0..3).map(|_| random_rational(&mut rng, 1, 40)).collect();
        assert!(check_all_metrics_equivalent_exact(&two_triangle_sphere(), &l, &lt).holds());
        let l: Vec<Rational> = (0..6).map(|_| random_rational(&mut rng, 1, 40)).collect();
        let lt: Vec<Rational> = (0..6).map(|_| random_rational(&mut rng, 1, 40)).collect();
        assert!(check_all_metrics_equivalent_exact(&tetrahedron(), &l, &lt).fails());
    }
}

fn t19_body<T: Real>(ctx: T::Ctx) {
    let t = one_vertex_torus();
    let l = to_t::<T>(&[3.0, 4.0, 5.5], ctx);
    let uniform: Vec<T> = l
        .iter()
        .map(|x| x.clone() * &T::from_f64(1.75, ctx))
        .collect();
    let other = to_t::<T>(&[3.0, 4.5, 5.5], ctx);
    let s = settings();
    assert_holds(
        &check_equivalent_iff_uniform_scale(&t, &l, &uniform, &s),
        "uniform",
    );
    assert_holds(
        &check_equivalent_iff_uniform_scale(&t, &l, &other, &s),
        "non-uniform",
    );
    assert!(check_conformal_equivalence(&t, &l, &other, &s).fails());
    assert_holds(
        &check_conformal_equivalence(&t, &l, &uniform, &s),
        "uniform is equivalent",
    );
    // Negative control: on the two-triangle sphere a non-uniform metric is equivalent.
    let sp = two_triangle_sphere();
    let w = witnesses(&check_equivalent_iff_uniform_scale(&sp, &l, &other, &s));
    assert_eq!(w, vec!["surface".to_string()]);
}

#[test]
fn t19_one_vertex_torus_equivalent_iff_uniform() {
    at_all_precisions!(t19_body);
    let t = one_vertex_torus();
    let l = [q(3), q(4), Rational::from((11, 2))];
    let uniform: Vec<Rational> = l.iter().map(|x| x * Rational::from((7, 4))).collect();
    assert!(check_equivalent_iff_uniform_scale_exact(&t, &l, &uniform).holds());
    assert!(check_equivalent_iff_uniform_scale_exact(&t, &l, &[q(3), q(5), q(6)]).holds());
    assert!(check_equivalent_iff_uniform_scale_exact(
        &two_triangle_sphere(),
        &l,
        &[q(3), q(5), q(6)]
    )
    .fails());
}

// ---------------------------------------------------------------- T20

fn rational_points(rng: &mut ChaCha8Rng, n: usize) -> Vec<[Rational; 3]> {
    (0..n)
        .map(|_| std::array::from_fn(|_| random_rational(rng, -20, 20)))
        .collect()
}

#[test]
fn t20_inversion_preserves_cross_ratios_exact() {
    let mut rng = ChaCha8Rng::seed_from_u64(59);
    let m = octahedron();
    for _ in 0..cases(20, 5000) {
        let p = rational_points(&mut rng, 6);
        let c: [Rational; 3] = std::array::from_fn(|_| random_rational(&mut rng, -30, 30));
        let r2 = random_rational(&mut rng, 1, 50);
        match check_mobius_preserves_cross_ratios_exact(&m, &p, &c, &r2) {
            Verdict::NotApplicable { .. } => continue,
            v => assert_eq!(
                v,
                Verdict::Holds {
                    certified: true,
                    max_error: 0.0
                }
            ),
        }
        // Negative control: a non-uniform stretch (x, y, z) ↦ (x, 2y, z) is not Möbius.
        let stretched: Vec<[Rational; 3]> = p
            .iter()
            .map(|x| [x[0].clone(), Rational::from(&x[1] * 2), x[2].clone()])
            .collect();
        assert!(verify_map_preserves_cross_ratios_exact(&m, &p, &stretched).fails());
    }
}

fn t20_body<T: Real>(ctx: T::Ctx) {
    let m = octahedron();
    let p: Vec<[T; 3]> = octahedron_points(61)
        .iter()
        .map(|x| x.map(|c| T::from_f64(c, ctx)))
        .collect();
    let c = [0.5, 3.0, -1.0].map(|x| T::from_f64(x, ctx));
    let r2 = T::from_f64(2.5, ctx);
    assert_holds(
        &check_mobius_preserves_cross_ratios(&m, &p, &c, &r2, &settings()),
        "inversion",
    );
}

#[test]
fn t20_inversion_preserves_cross_ratios_numerical() {
    at_all_precisions!(t20_body);
}
