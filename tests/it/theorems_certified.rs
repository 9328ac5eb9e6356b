//! Certified T01 on interval enclosures, the certified cotan-weight sign, and the error
//! bounds B40/B44 against a high-precision reference.

use penner::geometry::curvature::curvature;
use penner::geometry::triangle::{corner_angle, cot_opposite};
use penner::mesh::builders::{self, Embedded};
use penner::mesh::Mesh;
use penner::predicates::cotan::CotanWeightSign;
use penner::scalar::{Interval, Mpfr, Precision, Real, Sign};
use penner::theorems::bounds::{corner_angle_error, cot_error, eps};
use penner::theorems::t01_gauss_bonnet::{
    check_gauss_bonnet_certified, verify_gauss_bonnet_certified,
};
use penner::theorems::Verdict;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rug::Rational;

fn prec(bits: u64) -> Precision {
    Precision::new(bits).unwrap()
}

fn squared_lengths(e: &Embedded) -> Vec<Rational> {
    let m = &e.mesh;
    m.edges()
        .map(|edge| {
            let h = edge.halfedge();
            let (a, b) = (&e.positions[m.tail(h).idx()], &e.positions[m.tip(h).idx()]);
            (0..3).fold(Rational::new(), |acc, k| {
                let d = Rational::from(&b[k] - &a[k]);
                acc + Rational::from(&d * &d)
            })
        })
        .collect()
}

fn surfaces() -> Vec<(&'static str, Mesh, Vec<Rational>)> {
    let mut out = Vec::new();
    for (name, e) in [
        ("tetrahedron", builders::tetrahedron()),
        ("octahedron", builders::octahedron()),
        ("icosahedron", builders::icosahedron()),
        ("triakis tetrahedron", builders::triakis_tetrahedron()),
        ("grid disk", builders::grid_disk(4, 3).unwrap()),
        ("annulus", builders::annulus(6, 2).unwrap()),
    ] {
        let sq = squared_lengths(&e);
        out.push((name, e.mesh, sq));
    }
    let t = builders::flat_torus(3, 4).unwrap();
    out.push(("flat torus", t.mesh, t.squared_lengths));
    let q = |a: i64, b: i64| Rational::from((a, b));
    out.push((
        "one-vertex torus",
        builders::one_vertex_torus(),
        vec![q(9, 1), q(16, 1), q(121, 4)],
    ));
    out.push((
        "two-triangle sphere",
        builders::two_triangle_sphere(),
        vec![q(4, 1), q(9, 1), q(16, 1)],
    ));
    out
}

#[test]
fn t01_certified_enclosure_contains_two_pi_chi_with_width_bound() {
    for bits in [128, 256] {
        for (name, m, sq) in surfaces() {
            let v = check_gauss_bonnet_certified::<Mpfr>(&m, &sq, prec(bits));
            match v {
                Verdict::Holds {
                    certified: true,
                    max_error,
                } => {
                    eprintln!(
                        "t01 certified {name} at {bits} bits: width {max_error:.3e} = 2^{:.1}",
                        max_error.log2()
                    );
                }
                other => panic!("{name} at {bits} bits: {other:?}"),
            }
        }
    }
}

#[test]
fn t01_certified_rejects_shifted_curvature_enclosure() {
    for (bits, shift) in [(128_u64, 1e-30), (256, 1e-60), (256, 1e-12)] {
        for (name, m, sq) in surfaces() {
            let p = prec(bits);
            let l: Vec<Interval<Mpfr>> = sq
                .iter()
                .map(|q| Interval::<Mpfr>::from_rational(q, p).sqrt())
                .collect();
            let mut k = curvature(&m, &l);
            k[0] += &Interval::<Mpfr>::from_f64(shift, p);
            let v = verify_gauss_bonnet_certified(&m, &k);
            assert!(
                matches!(
                    v,
                    Verdict::Fails {
                        certified: true,
                        ..
                    }
                ),
                "{name} at {bits} bits, shift {shift:e}: {v:?}"
            );
        }
    }
}

#[test]
fn t01_certified_refuses_to_certify_a_broken_triangle() {
    // Sides 1, 1, 3 violate the triangle inequality: angles undefined, enclosure invalid.
    let m = builders::two_triangle_sphere();
    let sq = [1, 1, 9].map(Rational::from);
    let v = check_gauss_bonnet_certified::<Mpfr>(&m, &sq, prec(128));
    assert!(matches!(v, Verdict::Undecided { .. }), "{v:?}");
}

/// Random triangles, including needles and nearly flat caps.
fn triangles(seed: u64, n: usize) -> Vec<[f64; 3]> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    (0..n)
        .map(|k| {
            let a: f64 = rng.gen_range(0.5..2.0);
            let b: f64 = rng.gen_range(0.5..2.0);
            match k % 3 {
                // needle: c tiny
                0 => {
                    let c = 10f64.powi(-rng.gen_range(3..12));
                    [a, a + c * rng.gen_range(-0.45..0.45), c]
                }
                // cap: c close to a + b
                1 => [a, b, (a + b) * (1.0 - 10f64.powi(-rng.gen_range(3..12)))],
                _ => {
                    let lo = (a - b).abs();
                    [a, b, rng.gen_range(lo + 0.01 * (a + b)..(a + b) * 0.99)]
                }
            }
        })
        .collect()
}

fn reference_angle(t: [f64; 3]) -> Mpfr {
    let p = prec(1024);
    let [a, b, c] = t.map(|x| Mpfr::from_f64(x, p));
    corner_angle(&a, &b, &c)
}

#[test]
fn b40_corner_angle_error_bound_holds_against_mpfr_1024() {
    for t in triangles(71, crate::support::cases(300, 100_000)) {
        for (k, s) in [[t[0], t[1], t[2]], [t[1], t[2], t[0]], [t[2], t[0], t[1]]]
            .into_iter()
            .enumerate()
        {
            let exact = reference_angle(s);
            // f64
            let got = corner_angle(&s[0], &s[1], &s[2]);
            let bound = corner_angle_error(s[0], s[1], s[2], eps::<f64>(()));
            let err = (Mpfr::from_f64(got, prec(1024)) - &exact)
                .abs()
                .approx_f64();
            assert!(
                err <= bound,
                "f64 {s:?} corner {k}: error {err:e} > bound {bound:e}"
            );
            // MPFR-128
            let p = prec(128);
            let got = corner_angle(
                &Mpfr::from_f64(s[0], p),
                &Mpfr::from_f64(s[1], p),
                &Mpfr::from_f64(s[2], p),
            );
            let bound = corner_angle_error(s[0], s[1], s[2], eps::<Mpfr>(p));
            let err = (Mpfr(rug::Float::with_val(1024, got.as_float())) - &exact)
                .abs()
                .approx_f64();
            assert!(
                err <= bound,
                "mpfr-128 {s:?} corner {k}: error {err:e} > bound {bound:e}"
            );
        }
    }
}

#[test]
fn b40_bound_is_not_vacuous() {
    // Negative control: the bound must be tight enough to reject a result off by 1e-12
    // relative on an ordinary triangle.
    let bound = corner_angle_error(3.0, 4.0, 5.0, eps::<f64>(()));
    assert!(bound < 1e-13, "{bound:e}");
}

#[test]
fn b44_cotangent_error_bound_holds_against_mpfr_1024() {
    for t in triangles(73, crate::support::cases(300, 100_000)) {
        if t[2] > 1e-6 {
            let p = prec(1024);
            let exact = cot_opposite(
                &Mpfr::from_f64(t[0], p),
                &Mpfr::from_f64(t[1], p),
                &Mpfr::from_f64(t[2], p),
            );
            let got = cot_opposite(&t[0], &t[1], &t[2]);
            let bound = cot_error(t[0], t[1], t[2], eps::<f64>(()));
            let err = (Mpfr::from_f64(got, p) - &exact).abs().approx_f64();
            assert!(err <= bound, "{t:?}: error {err:e} > bound {bound:e}");
        }
    }
}

/// Two triangles on a common edge from rational planar points with denominator `den`:
/// `i, j` on the x-axis, `k` above, `l` below (a convex or non-convex quadrilateral).
fn planar_quad(rng: &mut ChaCha8Rng, den: i64) -> [[Rational; 2]; 4] {
    let mut q = |lo: i64, hi: i64| Rational::from((rng.gen_range(lo..hi), den));
    let i = [q(-20, 0), Rational::new()];
    let j = [q(1, 20), Rational::new()];
    let k = [q(-30, 30), q(1, 30)];
    let l = [q(-30, 30), q(-30, -1)];
    [i, j, k, l]
}

/// The squared distance of two rational points.
fn d2(a: &[Rational; 2], b: &[Rational; 2]) -> Rational {
    let dx = Rational::from(&a[0] - &b[0]);
    let dy = Rational::from(&a[1] - &b[1]);
    Rational::from(&dx * &dx) + Rational::from(&dy * &dy)
}

#[test]
fn b49_cotan_weight_sign_exact_agrees_with_mpfr_1024() {
    let mut rng = ChaCha8Rng::seed_from_u64(79);
    let mut seen = [0usize; 3];
    for case in 0..crate::support::cases(500, 100_000) {
        let [i, j, k, l] = planar_quad(&mut rng, 8);
        if !crate::support::in_shard(case) {
            continue; // generated, then left to another shard
        }
        let p = CotanWeightSign {
            first: [d2(&i, &j), d2(&j, &k), d2(&k, &i)],
            second: [d2(&i, &j), d2(&i, &l), d2(&l, &j)],
        };
        let s = p.sign_exact().unwrap();
        // Reference: the cotangents in MPFR-1024 from the lengths.
        let pr = prec(1024);
        let len = |x: &Rational| Mpfr::from_rational(x, pr).sqrt();
        let c1 = cot_opposite(&len(&p.first[0]), &len(&p.first[1]), &len(&p.first[2]));
        let c2 = cot_opposite(&len(&p.second[0]), &len(&p.second[1]), &len(&p.second[2]));
        let w = (c1 + &c2).approx_f64();
        match s {
            Sign::Positive => assert!(w > 0.0, "{w:e}"),
            Sign::Negative => assert!(w < 0.0, "{w:e}"),
            Sign::Zero => assert!(w.abs() < 1e-250, "{w:e}"),
        }
        seen[s as usize] += 1;
    }
    assert!(
        seen[0] > 0 && seen[2] > 0,
        "both signs must occur: {seen:?}"
    );
}

#[test]
fn b49_cotan_weight_interval_rung_agrees_with_exact_and_decides_a_tie_only_at_a_point_zero() {
    use penner::predicates::ladder::SignPredicate;
    let mut rng = ChaCha8Rng::seed_from_u64(80);
    let n = crate::support::cases(500, 100_000);
    let mut decided = 0;
    for _ in 0..n {
        let [i, j, k, l] = planar_quad(&mut rng, 8);
        let p = CotanWeightSign {
            first: [d2(&i, &j), d2(&j, &k), d2(&k, &i)],
            second: [d2(&i, &j), d2(&i, &l), d2(&l, &j)],
        };
        let exact = p.sign_exact().unwrap();
        if let Some(s) = p.enclosure_sign(prec(128)) {
            assert_eq!(s, exact, "{p:?}");
            decided += 1;
        }
    }
    assert!(
        decided * 10 >= n * 9,
        "interval rung decided only {decided} of {n}"
    );
    // Control: at a tie (a square split by its diagonal, W = 0) the rung may only answer
    // Zero, and only when its enclosure is the point 0 (side 1: every value exact); with side
    // 1/3 the enclosures are proper and contain 0, so it must not decide.
    for side in [Rational::from(1), Rational::from((1, 3))] {
        let s2 = Rational::from(&side * &side);
        let d = Rational::from(&s2 * 2);
        let tie = CotanWeightSign {
            first: [d.clone(), s2.clone(), s2.clone()],
            second: [d, s2.clone(), s2],
        };
        assert_eq!(tie.sign_exact(), Some(Sign::Zero));
        for bits in [128, 1024] {
            let got = tie.enclosure_sign(prec(bits));
            if side == 1 {
                assert_eq!(got, Some(Sign::Zero));
            } else {
                assert_eq!(got, None, "side {side} at {bits} bits");
            }
        }
    }
}

#[test]
fn b49_cotan_weight_sign_cocircular_is_zero() {
    // Unit square split along a diagonal: the two opposite angles are right angles.
    let one = Rational::from(1);
    let p = CotanWeightSign {
        first: [Rational::from(2), one.clone(), one.clone()],
        second: [Rational::from(2), one.clone(), one],
    };
    assert_eq!(p.sign_exact(), Some(Sign::Zero));
    // Negative control: stretch one side, the weight becomes nonzero.
    let p = CotanWeightSign {
        first: [
            Rational::from(2),
            Rational::from((11, 10)),
            Rational::from(1),
        ],
        second: [Rational::from(2), Rational::from(1), Rational::from(1)],
    };
    assert_ne!(p.sign_exact(), Some(Sign::Zero));
}

#[test]
fn t05_cotan_weight_sign_matches_the_delaunay_predicate() {
    // Cot-form (Heron, this crate's cotan predicate) against the cos-form Delaunay
    // predicate on squared lengths: independent formulas, same sign (docs/catalogue.md §5).
    use penner::predicates::delaunay::{delaunay_sign_squared, Quad};
    let mut rng = ChaCha8Rng::seed_from_u64(83);
    let mut seen = [0usize; 3];
    for case in 0..crate::support::cases(500, 100_000) {
        let [i, j, k, l] = planar_quad(&mut rng, 4);
        if !crate::support::in_shard(case) {
            continue; // generated, then left to another shard
        }
        let (ij, jk, ki, il, lj) = (d2(&i, &j), d2(&j, &k), d2(&k, &i), d2(&i, &l), d2(&l, &j));
        let cot = CotanWeightSign {
            first: [ij.clone(), jk.clone(), ki.clone()],
            second: [ij.clone(), il.clone(), lj.clone()],
        }
        .sign_exact()
        .unwrap();
        let d = delaunay_sign_squared(Quad {
            ij: &ij,
            jk: &jk,
            ki: &ki,
            il: &il,
            lj: &lj,
        });
        assert_eq!(cot, d);
        seen[cot as usize] += 1;
    }
    assert!(
        seen[0] > 0 && seen[2] > 0,
        "both signs must occur: {seen:?}"
    );
}

/// B49: the cotan weight is undefined when *either* triangle is degenerate (`P ≤ 0`): the
/// exact rung and the interval rung both refuse a pair whose first triangle is flat (sides
/// 1, 1, 2: `P = 0`) or whose second violates the triangle inequality (1, 1, 3), however
/// proper the other one is. Control: the same proper triangle paired with itself decides.
#[test]
fn term_b49_either_degenerate_triangle_leaves_the_weight_undefined() {
    use penner::predicates::ladder::SignPredicate;
    let q = |a: i64| Rational::from(a);
    let proper = [q(2), q(1), q(1)];
    let flat = [q(4), q(1), q(1)];
    let broken = [q(9), q(1), q(1)];
    for (first, second) in [
        (flat.clone(), proper.clone()),
        (proper.clone(), flat),
        (proper.clone(), broken.clone()),
        (broken, proper.clone()),
    ] {
        let p = CotanWeightSign { first, second };
        assert_eq!(p.sign_exact(), None, "{p:?}");
        for bits in [128, 1024] {
            assert_eq!(p.enclosure_sign(prec(bits)), None, "{p:?} at {bits} bits");
        }
    }
    let p = CotanWeightSign {
        first: proper.clone(),
        second: proper,
    };
    assert_eq!(p.sign_exact(), Some(Sign::Zero));
}

/// B49 through the mesh-level call: `cotan_weight_signs` gives one entry per edge, `None`
/// exactly on boundary edges, and on interior edges the sign of `cot α + cot β` computed
/// independently in MPFR-1024 from the lengths (random planar meshes). On a grid of squares
/// of side 1/3 split by diagonals, every diagonal is a tie (`w = 0`) that no interval
/// rung can decide (the enclosures of `1/9` are proper): the exact rung must, and answers
/// `Zero`; the grid's other interior edges are positive.
#[test]
fn term_b49_cotan_weight_signs_per_edge_and_ties_decided_exactly() {
    use penner::io::surface::squared_lengths_from_positions;
    use penner::predicates::cotan::cotan_weight_signs;
    use penner::predicates::ladder::Ladder;
    use penner::scalar::{Certified, Stage};
    let ladder = Ladder::default();
    let pr = prec(1024);
    for seed in 0..4 {
        let e: Embedded = builders::random_planar(30, seed).unwrap();
        let sq = squared_lengths_from_positions(&e.mesh, &e.positions);
        let signs = cotan_weight_signs(&e.mesh, &sq, &ladder);
        assert_eq!(signs.len(), e.mesh.n_edges());
        let mut seen = [0usize; 3];
        for edge in e.mesh.edges() {
            let got = &signs[edge.idx()];
            if e.mesh.is_boundary_edge(edge) {
                assert!(got.is_none());
                continue;
            }
            let mut w = Mpfr::from_f64(0.0, pr);
            for h in [edge.side(0), edge.side(1)] {
                let l =
                    |g: penner::mesh::HalfEdge| Mpfr::from_rational(&sq[g.edge().idx()], pr).sqrt();
                w += &cot_opposite(&l(h), &l(e.mesh.next(h)), &l(e.mesh.prev(h)));
            }
            let w = w.approx_f64();
            let s = got.as_ref().and_then(Certified::value).expect("decided");
            match s {
                Sign::Positive => assert!(w > 0.0, "{w:e}"),
                Sign::Negative => assert!(w < 0.0, "{w:e}"),
                Sign::Zero => assert!(w.abs() < 1e-250, "{w:e}"),
            }
            seen[s as usize] += 1;
        }
        assert!(seen[2] > 0, "seed {seed}: {seen:?}");
    }
    let mut g: Embedded = builders::grid_disk(3, 3).unwrap();
    let third = Rational::from((1, 3));
    for p in &mut g.positions {
        for x in p.iter_mut() {
            *x *= &third;
        }
    }
    let sq = squared_lengths_from_positions(&g.mesh, &g.positions);
    let signs = cotan_weight_signs(&g.mesh, &sq, &ladder);
    let two_ninths = Rational::from((2, 9));
    let mut ties = 0;
    for edge in g.mesh.edges().filter(|&e| !g.mesh.is_boundary_edge(e)) {
        let got = signs[edge.idx()].clone().expect("interior");
        if sq[edge.idx()] == two_ninths {
            assert_eq!(
                got,
                Certified::Known {
                    value: Sign::Zero,
                    stage: Stage::Exact
                }
            );
            ties += 1;
        } else {
            assert_eq!(got.value(), Some(Sign::Positive));
        }
    }
    assert_eq!(ties, 9);
}
