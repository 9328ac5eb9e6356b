//! The uniformization checks in the registry (T24–T26, `oracle::checks_uniformization`),
//! and the certificate on the exact input metric and the box exclusion behind them (B73).

use crate::meshgen::icosphere;
use penner::io::surface::squared_lengths_from_positions;
use penner::io::{Metric, Surface};
use penner::oracle::checks_uniformization::{input_metric, uniform_targets, MAX_FACES};
use penner::oracle::controls::uniformization::moved_targets;
use penner::oracle::corpus;
use penner::oracle::precision::Prec;
use penner::oracle::registry::{by_id, run_one, Outcome};
use penner::scalar::{Interval, Mpfr, Precision, Real};
use penner::theorems::{Settings, Verdict};
use penner::uniformization::certificate::{
    check_certificate_on, prove_on, CertificateOutcome, T0Metric,
};
use penner::uniformization::exclusion::excluded_vertices;
use penner::uniformization::{uniformize, UniformizeOptions};
use rug::Rational;

fn verdict(id: &str, case: &Surface, prec: Prec) -> Option<Verdict> {
    let row = run_one(&by_id(id).unwrap(), case, prec, &Settings::default())?;
    match row.outcome {
        Outcome::Verdict(v) => Some(v),
        Outcome::Crashed(m) => panic!("{id} crashed on {}: {m}", case.name),
    }
}

fn mpfr(bits: u64) -> Prec {
    Prec::Mpfr(Precision::new(bits).unwrap())
}

/// A noisy icosphere with `20k²` faces given by rational vertex positions (the binary64
/// coordinates, exactly): its lengths are square roots of rationals, not binary64 numbers.
pub(crate) fn irrational_sphere(k: u32, seed: u64) -> Surface {
    let mut s = icosphere(k);
    let amount = 0.2 * s.mean_edge();
    s.jitter(amount, seed);
    exact_positions("irrational sphere", &s)
}

/// The surface of `s` with its binary64 positions taken exactly (squared lengths rational).
pub(crate) fn exact_positions(name: &str, s: &crate::meshgen::Embedded) -> Surface {
    let mesh = s.mesh();
    let pos: Vec<[Rational; 3]> = s
        .pos
        .iter()
        .map(|p| p.map(|x| Rational::from_f64(x).unwrap()))
        .collect();
    let sq = squared_lengths_from_positions(&mesh, &pos);
    Surface::new(name, mesh, Metric::SquaredLengths(sq), None).unwrap()
}

#[test]
fn t24_registry_certifies_on_closed_corpus_surfaces() {
    let mut certified = 0;
    let mut undecided = Vec::new();
    for case in corpus::standard() {
        assert!(
            verdict("T24", &case, Prec::Exact).is_none(),
            "{}",
            case.name
        );
        for p in [Prec::F64, Prec::Dd, mpfr(256)] {
            let v = verdict("T24", &case, p).unwrap();
            if case.mesh.is_closed() {
                if matches!(
                    v,
                    Verdict::Holds {
                        certified: true,
                        ..
                    }
                ) {
                    certified += 1;
                } else {
                    undecided.push(format!("{} at {p}: {v:?}", case.name));
                }
            } else {
                assert!(
                    matches!(v, Verdict::NotApplicable { .. }),
                    "{}: {v:?}",
                    case.name
                );
            }
        }
    }
    assert!(
        undecided.is_empty(),
        "{certified} certified; {}",
        undecided.join("\n")
    );
    // An irrational metric that needs Euclidean flips first (a torus of long thin
    // triangles): certified for the input itself.
    let case = exact_positions("sheared torus", &crate::meshgen::sheared_torus(12, 8, 3));
    let sol = uniformize(
        &case.mesh,
        &case.lengths::<f64>(()),
        &uniform_targets(&case).unwrap(),
        &UniformizeOptions::default(),
    )
    .unwrap();
    assert!(sol.euclidean_flips > 0, "the test wants Euclidean flips");
    let v = verdict("T24", &case, mpfr(128)).unwrap();
    assert!(
        matches!(
            v,
            Verdict::Holds {
                certified: true,
                ..
            }
        ),
        "{v:?}"
    );
}

#[test]
fn t24_t25_t26_registry_size_and_precision_limits_are_named() {
    let big = {
        let s = icosphere(16); // 5120 faces
        let m = s.mesh();
        let l = s.lengths(&m);
        assert!(m.n_faces() > MAX_FACES);
        Surface::new(
            "big",
            m,
            Metric::Lengths(l.iter().map(|&x| Rational::from_f64(x).unwrap()).collect()),
            None,
        )
        .unwrap()
    };
    for (id, p) in [("T24", Prec::F64), ("T25", Prec::F64), ("T26", Prec::Exact)] {
        match verdict(id, &big, p).unwrap() {
            Verdict::NotApplicable { reason } => {
                assert!(reason.contains(&MAX_FACES.to_string()), "{id}: {reason}");
            }
            v => panic!("{id}: {v:?}"),
        }
    }
    let tet = &corpus::standard()[0];
    match verdict("T24", tet, mpfr(2048)).unwrap() {
        Verdict::NotApplicable { reason } => assert!(reason.contains("1024"), "{reason}"),
        v => panic!("{v:?}"),
    }
}

#[test]
fn t25_registry_two_starts_agree_on_closed_corpus_surfaces() {
    for case in corpus::standard() {
        assert!(verdict("T25", &case, Prec::Exact).is_none());
        let v = verdict("T25", &case, mpfr(128)).unwrap();
        if case.mesh.is_closed() {
            assert!(
                matches!(
                    v,
                    Verdict::Holds {
                        certified: true,
                        ..
                    }
                ),
                "{}: {v:?}",
                case.name
            );
        } else {
            assert!(
                matches!(v, Verdict::NotApplicable { .. }),
                "{}: {v:?}",
                case.name
            );
        }
    }
}

#[test]
fn t26_registry_replays_flip_paths_exactly() {
    for case in corpus::standard() {
        assert!(verdict("T26", &case, Prec::F64).is_none());
        let v = verdict("T26", &case, Prec::Exact).unwrap();
        if case.mesh.is_closed() {
            // Certified in ℚ for rational lengths; on enclosures of irrational ones a
            // numerical holds (equal enclosures overlap, equality is not decided).
            let rational = matches!(case.metric, Metric::Lengths(_));
            assert!(
                matches!(v, Verdict::Holds { certified, .. } if certified == rational),
                "{}: {v:?}",
                case.name
            );
        } else {
            assert!(
                matches!(v, Verdict::NotApplicable { .. }),
                "{}: {v:?}",
                case.name
            );
        }
    }
}

/// The certificate data of a solve of `case` at `bits`, on its exact input metric.
fn proved(case: &Surface, bits: u32) -> (penner::uniformization::certificate::Proof, T0Metric) {
    let lengths = case.lengths::<f64>(());
    let targets = uniform_targets(case).unwrap();
    let sol = uniformize(
        &case.mesh,
        &lengths,
        &targets,
        &UniformizeOptions::default(),
    )
    .unwrap();
    let prec = Precision::new(u64::from(bits)).unwrap();
    let metric = input_metric(case, &lengths, prec, &sol).unwrap();
    let proof = prove_on(&sol, Some(&metric), bits, 1e-70).unwrap();
    (proof, metric)
}

#[test]
fn b73_certificate_for_irrational_input_metric() {
    let case = irrational_sphere(2, 7);
    let (proof, metric) = proved(&case, 256);
    let CertificateOutcome::Holds { distance, .. } = proof.outcome else {
        panic!("{:?}", proof.outcome);
    };
    assert!(distance < 1e-50, "{distance:e}");
    // The binary64 lengths of the solve are a different metric: the same u is not a
    // solution for them to 1e-50 (the rounding moves u by about 1e-16).
    let on_rounded = check_certificate_on(&proof.data, None, 256).unwrap();
    assert!(
        matches!(on_rounded, CertificateOutcome::Undecided { .. }),
        "{on_rounded:?}"
    );
    // Negative control: one input length enclosed 1% longer.
    let mut wrong = metric.enclosures.clone();
    let prec = Precision::new(256).unwrap();
    let f = Interval::<Mpfr>::from_rational(&Rational::from((101, 100)), prec);
    wrong[3] = wrong[3].clone() * &f;
    let out = check_certificate_on(&proof.data, Some(&wrong), 256).unwrap();
    assert!(
        matches!(out, CertificateOutcome::Undecided { .. }),
        "{out:?}"
    );
}

#[test]
fn b73_box_excludes_moved_targets() {
    let case = irrational_sphere(2, 9);
    let (proof, metric) = proved(&case, 128);
    assert!(
        matches!(proof.outcome, CertificateOutcome::Holds { .. }),
        "{:?}",
        proof.outcome
    );
    // The solved targets: nothing excluded (the box holds a solution).
    let none = excluded_vertices(&proof.data, Some(&metric.enclosures), 128)
        .unwrap()
        .unwrap();
    assert!(none.is_empty(), "{none:?}");
    // π/100 moved from v2 to v5: both excluded, nothing else.
    let mut data = proof.data.clone();
    data.targets = moved_targets(&data.targets, 2, 5);
    let ex = excluded_vertices(&data, Some(&metric.enclosures), 128)
        .unwrap()
        .unwrap();
    let vs: Vec<usize> = ex.iter().map(|x| x.vertex).collect();
    assert_eq!(vs, vec![2, 5]);
}

#[test]
fn b73_convexity_admits_flips_of_convex_quadrilaterals_only() {
    use penner::predicates::delaunay::Quad;
    use penner::uniformization::input_metric::strictly_convex;
    use rand::{Rng, SeedableRng};
    let prec = Precision::new(128).unwrap();
    let q = |x: Rational| Interval::<Mpfr>::from_rational(&x, prec);
    let sqrt = |x: i64| Interval::<Mpfr>::from_rational(&Rational::from(x), prec).sqrt();
    // Unit square i=(0,0), k=(1,0)… with diagonal ij from (0,0) to (1,1): cocircular,
    // convex (angle sums π/2 at both ends).
    let square = Quad {
        ij: sqrt(2),
        jk: q(Rational::from(1)),
        ki: q(Rational::from(1)),
        il: q(Rational::from(1)),
        lj: q(Rational::from(1)),
    };
    assert!(strictly_convex(&square));
    // Negative control, a dart: i=(0,0), j=(4,0), k=(−1,1), l=(−1,−1):
    // ∠kij = ∠jil = 135°, sum 270° > 180°.
    let dart = Quad {
        ij: q(Rational::from(4)),
        jk: sqrt(26), // j=(4,0) to k=(−1,1)
        ki: sqrt(2),
        il: sqrt(2),
        lj: sqrt(26),
    };
    assert!(!strictly_convex(&dart));
    // Exactly π at i: i=(0,0), j=(2,0), k=(1,1), l=(−1,−1) (∠kij = 45°, ∠jil = 135°):
    // not strictly convex, refused.
    let flat = Quad {
        ij: q(Rational::from(2)),
        jk: sqrt(2),
        ki: sqrt(2),
        il: sqrt(2),
        lj: sqrt(10),
    };
    assert!(!strictly_convex(&flat));
    // Independent oracle: planar quadrilaterals i=(0,0), j=(1,0), k above, l below, their
    // angle sums at i and j by atan2 in f64; away from π by 10⁻⁶ the verdicts agree.
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(73);
    let (mut yes, mut no) = (0, 0);
    for _ in 0..400 {
        let k = [rng.gen_range(-1.5..2.5), rng.gen_range(0.05..1.5)];
        let l = [rng.gen_range(-1.5..2.5), -rng.gen_range(0.05..1.5)];
        let (i, j) = ([0.0f64, 0.0], [1.0f64, 0.0]);
        let ang = |p: [f64; 2], a: [f64; 2], b: [f64; 2]| {
            let (v, w) = ([a[0] - p[0], a[1] - p[1]], [b[0] - p[0], b[1] - p[1]]);
            (v[0] * w[1] - v[1] * w[0])
                .atan2(v[0] * w[0] + v[1] * w[1])
                .abs()
        };
        let sum_i = ang(i, k, j) + ang(i, j, l);
        let sum_j = ang(j, i, k) + ang(j, l, i);
        let pi = std::f64::consts::PI;
        if (sum_i - pi).abs() < 1e-6 || (sum_j - pi).abs() < 1e-6 {
            continue;
        }
        let d = |a: [f64; 2], b: [f64; 2]| {
            let r = |x: f64| Rational::from_f64(x).unwrap();
            let s = r(a[0] - b[0]) * r(a[0] - b[0]) + r(a[1] - b[1]) * r(a[1] - b[1]);
            Interval::<Mpfr>::from_rational(&s, prec).sqrt()
        };
        let quad = Quad {
            ij: d(i, j),
            jk: d(j, k),
            ki: d(k, i),
            il: d(i, l),
            lj: d(l, j),
        };
        let convex = sum_i < pi && sum_j < pi;
        assert_eq!(strictly_convex(&quad), convex, "k {k:?} l {l:?}");
        if convex {
            yes += 1;
        } else {
            no += 1;
        }
    }
    assert!(yes > 50 && no > 50, "{yes} convex, {no} not");
}

#[test]
fn b35_cube_ties_at_the_solution_are_certified() {
    use penner::theorems::t24_uniformization_exists::check_existence_on;
    use penner::uniformization::Targets;
    // The cube with even targets 3π/2: u = 0 solves it and every square's diagonal is a
    // Delaunay tie there, so no box lies in one Penner cell; the six tied diagonals have
    // face-disjoint quadrilaterals and the cube's edges stay Delaunay whichever flip
    // (B35): certified on the exact input metric (before B35: undecided, "edge … not
    // certified Delaunay on the whole box").
    let cube = corpus::standard()
        .into_iter()
        .find(|c| c.name == "cube, diagonals one way")
        .unwrap();
    let n = cube.mesh.n_vertices();
    let even = Targets::from_multiples_of_pi(vec![Rational::from((3, 2)); n]);
    let lengths = cube.lengths::<f64>(());
    let prec = Precision::new(128).unwrap();
    let input =
        |sol: &penner::uniformization::Uniformization| input_metric(&cube, &lengths, prec, sol);
    let ex = check_existence_on(&cube.mesh, &lengths, &even, 128, 1e-30, Some(&input)).unwrap();
    assert!(
        matches!(
            ex.verdict,
            Verdict::Holds {
                certified: true,
                ..
            }
        ),
        "{:?}",
        ex.verdict
    );
    // The registry's redistributed targets break the symmetry: certified.
    let v = verdict("T24", &cube, mpfr(128)).unwrap();
    assert!(
        matches!(
            v,
            Verdict::Holds {
                certified: true,
                ..
            }
        ),
        "{v:?}"
    );
}
