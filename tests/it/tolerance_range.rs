//! Tolerances at every precision and every scale (proofs/B40 "Range" and "Evaluation"), and
//! the semidefiniteness of `−L` on caps and needles (B51): valid input never fails, while a
//! perturbation just above the bound still does.

use penner::geometry::curvature::curvature;
use penner::geometry::laplacian::cotan_laplacian;
use penner::io::{Metric, Surface};
use penner::mesh::Mesh;
use penner::oracle::catalogue;
use penner::oracle::precision::Prec;
use penner::oracle::registry::{run_case, Outcome};
use penner::scalar::{Mpfr, Precision, Real};
use penner::theorems::t01_gauss_bonnet::{check_gauss_bonnet, verify_gauss_bonnet};
use penner::theorems::t05_cotan_laplacian::{check_cotan_laplacian, verify_laplacian};
use penner::theorems::{Settings, Verdict};
use rug::ops::Pow;
use rug::Rational;

const TET: [[u32; 3]; 4] = [[0, 1, 2], [0, 2, 3], [0, 3, 1], [1, 3, 2]];

fn mpfr(bits: u64) -> Prec {
    Prec::Mpfr(Precision::new(bits).unwrap())
}

fn all_precisions() -> Vec<Prec> {
    let mut p = vec![Prec::F64, Prec::Dd, Prec::Exact];
    p.extend([128, 256, 1080, 2048, 4096].map(mpfr));
    p
}

fn tetrahedron(l: &Rational) -> Surface {
    let mesh = Mesh::from_faces(4, &TET).unwrap();
    let n = mesh.n_edges();
    Surface::new("tet", mesh, Metric::Lengths(vec![l.clone(); n]), None).unwrap()
}

/// A closed surface: two triangles `(a, b, c)` glued along all three sides.
fn two_triangles(sq: &[Rational; 3]) -> Surface {
    let mesh = penner::mesh::builders::two_triangle_sphere();
    let mut v = Vec::new();
    for e in mesh.edges() {
        v.push(sq[e.idx() % 3].clone());
    }
    Surface::new("two-triangle sphere", mesh, Metric::SquaredLengths(v), None).unwrap()
}

/// `2^k` as a rational.
fn pow2(k: i32) -> Rational {
    if k >= 0 {
        Rational::from(1) << k as u32
    } else {
        Rational::from(1) >> (-k) as u32
    }
}

/// Every registered check at every precision: the rows that fail, as text.
fn failures(case: &Surface, precs: &[Prec]) -> Vec<String> {
    run_case(case, &catalogue(), precs, &Settings::default())
        .into_iter()
        .filter(|r| {
            matches!(
                r.outcome,
                Outcome::Verdict(Verdict::Fails { .. }) | Outcome::Crashed(_)
            )
        })
        .map(|r| format!("{} {} {}: {:?}", r.case, r.id, r.precision, r.outcome))
        .collect()
}

#[test]
fn b40_tolerances_at_high_precision_and_extreme_scales() {
    // MPFR 2048 and 4096 at the unit scale and 2^±1000 only, outside the long mode (1080
    // bits, past the f64 exponent range like both, runs at every scale;
    // never_fails::default_run_precisions).
    let deep = |k: i32| crate::support::long_mode() || matches!(k, 0 | 1000 | -1000);
    let mut scales: Vec<(Rational, bool)> = [0, 80, -80, 300, -300, 1000, -1000]
        .into_iter()
        .map(|k| (pow2(k), deep(k)))
        .collect();
    let ten = |k: u32| Rational::from(rug::Integer::from(10).pow(k));
    scales.extend(
        [ten(78), ten(80).recip(), ten(76).recip(), ten(400).recip()]
            .map(|s| (s, crate::support::long_mode())),
    );
    let mut bad = Vec::new();
    for (s, deep) in &scales {
        let precs: Vec<Prec> = all_precisions()
            .into_iter()
            .filter(|p| *deep || !matches!(p, Prec::Mpfr(b) if b.bits() > 1080))
            .collect();
        bad.extend(failures(&tetrahedron(s), &precs));
        // A cap and a needle pair, scaled.
        let s2 = Rational::from(s * s);
        let cap = [1, 1, 3].map(|x| Rational::from(x * &s2));
        bad.extend(failures(&two_triangles(&cap), &precs));
        let needle = [
            Rational::from(1),
            Rational::from(1),
            Rational::from((1, 1_000_000)),
        ]
        .map(|x| x * &s2);
        bad.extend(failures(&two_triangles(&needle), &precs));
    }
    assert!(bad.is_empty(), "false refutations:\n{}", bad.join("\n"));
}

#[test]
fn b40_library_calls_at_extreme_scales_are_undecided_not_refuted() {
    // Without the registry's rescaling, the numerical checks refuse to judge lengths outside
    // [2^-100, 2^100] (B40 "Range") rather than compare against an underflowed bound.
    let mesh = Mesh::from_faces(4, &TET).unwrap();
    for l in [1e-80_f64, 1e-200, 1e78, 1e200] {
        let v = check_gauss_bonnet(&mesh, &[l; 6], &Settings::default());
        assert!(matches!(v, Verdict::Undecided { .. }), "{l}: {v:?}");
        let v = check_cotan_laplacian(&mesh, &[l; 6], &Settings::default());
        assert!(matches!(v, Verdict::Undecided { .. }), "{l}: {v:?}");
    }
    // Inside the range the same calls hold.
    let v = check_gauss_bonnet(&mesh, &[1e-25_f64; 6], &Settings::default());
    assert!(v.holds(), "{v:?}");
}

#[test]
fn b40_tolerance_at_4096_bits_is_not_vacuous() {
    // Gauss–Bonnet at 4096 bits: the tolerance is about 2^-4080 (carried as tol·2^-s); the
    // exact curvatures pass, a perturbation of 2^-3900 — invisible to any f64 tolerance,
    // which underflows to 0 — is rejected, and so is one of 2^-4000.
    let p = Precision::new(4096).unwrap();
    let mesh = Mesh::from_faces(4, &TET).unwrap();
    let l: Vec<Mpfr> = (0..6).map(|_| Mpfr::from_f64(1.0, p)).collect();
    let k = curvature(&mesh, &l);
    assert!(verify_gauss_bonnet(&mesh, &l, &k, &Settings::default()).holds());
    for shift in [3900u32, 4000] {
        let mut kk = k.clone();
        kk[0] += &Mpfr::from_rational(&(Rational::from(1) >> shift), p);
        let v = verify_gauss_bonnet(&mesh, &l, &kk, &Settings::default());
        assert!(v.fails(), "2^-{shift}: {v:?}");
    }
}

/// A planar hinge of two triangles on `(0,0), (2,0), (1, h), (1, −1)`: for small `h` the upper
/// triangle is a cap (angle near π at `(1, h)`), its weight on the shared edge negative.
fn cap_hinge(h: &Rational) -> Surface {
    let mesh = Mesh::from_faces(4, &[[0, 1, 2], [1, 0, 3]]).unwrap();
    let z = Rational::new();
    let pos = vec![
        [z.clone(), z.clone(), z.clone()],
        [Rational::from(2), z.clone(), z.clone()],
        [Rational::from(1), h.clone(), z.clone()],
        [Rational::from(1), Rational::from(-1), z.clone()],
    ];
    let sq = penner::io::surface::squared_lengths_from_positions(&mesh, &pos);
    Surface::new("cap hinge", mesh, Metric::SquaredLengths(sq), Some(pos)).unwrap()
}

#[test]
fn b51_caps_and_needles_are_semidefinite_at_every_precision() {
    let precs = [Prec::F64, Prec::Dd, mpfr(256), mpfr(1080)];
    let mut bad = Vec::new();
    for k in [3u32, 6, 12, 24] {
        let h = Rational::from((1, rug::Integer::from(10).pow(k)));
        bad.extend(failures(&cap_hinge(&h), &precs));
        // Closed: two caps (1, 1, 2 − h) glued.
        let c = Rational::from(2) - &h;
        bad.extend(failures(
            &two_triangles(&[
                Rational::from(1),
                Rational::from(1),
                Rational::from(&c * &c),
            ]),
            &precs,
        ));
    }
    assert!(bad.is_empty(), "false refutations:\n{}", bad.join("\n"));

    // Negative control: a claimed Laplacian of the unit tetrahedron with weight −10 on one
    // edge (row sums kept zero, so only semidefiniteness breaks) is refuted by the exact
    // witness of B51.
    let mesh = Mesh::from_faces(4, &TET).unwrap();
    let mut lap = cotan_laplacian(&mesh, &[1.0_f64; 6]);
    let w = *lap.get(0, 1).unwrap();
    for (i, j) in [(0, 1), (1, 0)] {
        *lap.get_mut(i, j).unwrap() = -10.0;
    }
    for i in [0, 1] {
        *lap.get_mut(i, i).unwrap() += w + 10.0;
    }
    let v = verify_laplacian(&mesh, &lap, &Settings::default());
    assert!(v.fails(), "{v:?}");
    assert!(format!("{v:?}").contains("pivot"), "{v:?}");
}

#[test]
fn b65_corpus_past_the_f64_exponent_range_has_no_false_refutation() {
    // Past 1074 bits 2^-p underflows in f64: tolerances (B40 "Range") and the nudge of the
    // flip driver (B65) must not. The cube with split square faces has exact cocircular ties
    // whose rounded diagonals need the nudge.
    // 4096 bits in the long mode: never_fails::never_fails_high_precision_* run every check
    // on this corpus at 1080 and 4096 bits in the default run.
    let mut precs = vec![mpfr(1080)];
    if crate::support::long_mode() {
        precs.push(mpfr(4096));
    }
    let mut bad = Vec::new();
    for case in penner::oracle::corpus::standard() {
        bad.extend(failures(&case, &precs));
    }
    assert!(bad.is_empty(), "false refutations:\n{}", bad.join("\n"));
}
