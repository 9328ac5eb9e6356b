//! B66: strict triangle inequalities of binary64 sides decided by one rounded sum and one
//! rounded difference (monotone rounding), checked against malachite rationals; and the
//! Euclidean flips that rely on it: no returned face is degenerate.

use crate::delaunay::{exactly_strict, exactly_strict_faces};
use crate::support::cases;
use malachite::rational::Rational as MRational;
use penner::algorithms::flip_to_delaunay::{flip_to_delaunay, FlipKind, FlipOptions};
use penner::algorithms::flips::flip_euclidean;
use penner::algorithms::naive::naive_p;
use penner::mesh::Mesh;
use penner::predicates::delaunay::QuadEdges;
use penner::predicates::ladder::Ladder;
use penner::predicates::triangle::{strict_triangle, strict_triangle_f64, strict_triangle_real};
use penner::scalar::{Dd, Real};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rug::Rational;

fn m(x: f64) -> MRational {
    MRational::try_from(x).unwrap()
}

/// `x` moved by `k` units in the last place.
fn ulps(x: f64, k: i64) -> f64 {
    f64::from_bits((x.to_bits() as i64 + k) as u64)
}

/// Triples at and around degeneracy: `a` within a few ulps of `fl(b + c)` or `|b − c|`,
/// at scales from 2⁻¹⁰⁰ to 2¹⁰⁰.
fn near_degenerate_triple(rng: &mut ChaCha8Rng) -> [f64; 3] {
    let s = 2f64.powi(rng.gen_range(-100..=100));
    let b = s * rng.gen_range(0.5..2.0);
    let c = if rng.gen_bool(0.3) {
        b * (1.0 + rng.gen_range(-1e-12..1e-12))
    } else {
        s * rng.gen_range(0.01..2.0)
    };
    let k = rng.gen_range(-3..=3);
    let a = if rng.gen_bool(0.5) {
        ulps(b + c, k)
    } else {
        ulps((b - c).abs(), k).abs()
    };
    let mut t = [a, b, c];
    t.rotate_left(rng.gen_range(0..3));
    t
}

#[test]
fn b66_monotone_triangle_test_never_contradicts_exact_sides() {
    let mut rng = ChaCha8Rng::seed_from_u64(660);
    let ladder = Ladder::default();
    let (mut proved, mut declined_strict, mut not_strict) = (0, 0, 0);
    for case in 0..cases(20_000, 1_000_000) {
        let [a, b, c] = near_degenerate_triple(&mut rng);
        if !crate::support::in_shard(case) {
            continue; // generated, then left to another shard
        }
        if !(a.is_normal() && b.is_normal() && c.is_normal()) || a <= 0.0 {
            continue;
        }
        let exact = exactly_strict([&m(a), &m(b), &m(c)]);
        if strict_triangle_f64(a, b, c) {
            assert!(
                exact,
                "f64 test proved a non-strict triangle {a:e} {b:e} {c:e}"
            );
            proved += 1;
        } else if exact {
            declined_strict += 1;
        } else {
            not_strict += 1;
        }
        // The backend-generic form answers exactly, at f64 and on Dd values.
        let r = strict_triangle_real([&a, &b, &c], &ladder).value();
        assert_eq!(r, Some(exact), "{a:e} {b:e} {c:e}");
        let dd = [a, b, c].map(|x| <Dd as Real>::from_f64(x, ()));
        let r = strict_triangle_real([&dd[0], &dd[1], &dd[2]], &ladder).value();
        assert_eq!(r, Some(exact));
    }
    // Both sides of the test were exercised, and degenerate or violated triples occurred.
    assert!(proved > 1000 && not_strict > 1000, "{proved} {not_strict}");
    eprintln!(
        "b66: proved {proved}, declined but strict {declined_strict}, not strict {not_strict}"
    );
}

#[test]
fn b66_negative_control_rounded_rational_sides_fool_the_f64_test() {
    // a = b + c exactly in ℚ (a flat triangle); rounding the three sides to binary64 first
    // breaks the hypothesis of B66, and the f64 test then "proves" a strict triangle.
    let ladder = Ladder::default();
    let mut fooled = 0;
    for p in 1..200u32 {
        for q in [3u32, 7, 10, 11, 13] {
            let b = Rational::from((p, q));
            let c = Rational::from((q + p % 5 + 1, 3 * q + 1));
            let a = Rational::from(&b + &c);
            let [af, bf, cf] = [&a, &b, &c].map(Rational::to_f64);
            if strict_triangle_f64(af, bf, cf) {
                fooled += 1;
                // The exact route is not fooled.
                assert_eq!(strict_triangle(&a, &b, &c, &ladder).value(), Some(false));
            }
        }
    }
    assert!(fooled > 0, "rounded inputs never fooled the test");
}

/// A flat quadrilateral `i = (0,0)`, `j = (1,0)`, `k` just above and `l` just below the
/// segment (heights 10⁻⁹ … 10⁻⁶): edge `ij` is far from Delaunay and the new triangles
/// `lki`, `klj` are slivers. Vertices `0 = i, 1 = k, 2 = j, 3 = l`; `None` if the input
/// triangles are not exactly strict after rounding the lengths.
fn flat_quad(rng: &mut ChaCha8Rng) -> Option<(Mesh, Vec<f64>)> {
    let p: [(f64, f64); 4] = [
        (0.0, 0.0),
        (
            rng.gen_range(0.0..1.0),
            10f64.powf(rng.gen_range(-9.0..-6.0)),
        ),
        (1.0, 0.0),
        (
            rng.gen_range(0.0..1.0),
            -10f64.powf(rng.gen_range(-9.0..-6.0)),
        ),
    ];
    let mesh = Mesh::from_faces(4, &[[0, 1, 2], [0, 2, 3]]).unwrap();
    let l: Vec<f64> = mesh
        .edges()
        .map(|e| {
            let h = e.halfedge();
            let (a, b) = (p[mesh.tail(h).idx()], p[mesh.tip(h).idx()]);
            (f64::powi(a.0 - b.0, 2) + f64::powi(a.1 - b.1, 2)).sqrt()
        })
        .collect();
    faces_strict(&mesh, &l).then_some((mesh, l))
}

/// Whether every face of `mesh` is exactly a strict triangle for binary64 lengths `l`.
fn faces_strict(mesh: &Mesh, l: &[f64]) -> bool {
    exactly_strict_faces(mesh, &l.iter().map(|&x| m(x)).collect::<Vec<_>>())
}

#[test]
fn b66_euclidean_flips_never_return_a_degenerate_triangle() {
    let mut rng = ChaCha8Rng::seed_from_u64(661);
    let (mut flipped, mut refused, mut unchecked_bad) = (0, 0, 0);
    for _ in 0..cases(20_000, 500_000) {
        let Some((mesh, l)) = flat_quad(&mut rng) else {
            continue;
        };
        let diag = mesh.edges().find(|&e| !mesh.is_boundary_edge(e)).unwrap();
        let q = QuadEdges::of(&mesh, diag).unwrap();
        if naive_p(q.lengths(&l).map(|x| *x).to_array()) >= 0.0 {
            continue;
        }
        let (mut m1, mut l1) = (mesh.clone(), l.clone());
        let r = flip_to_delaunay(
            &mut m1,
            &mut l1,
            FlipKind::Euclidean,
            &FlipOptions::default(),
        )
        .unwrap();
        assert!(
            faces_strict(&m1, &l1),
            "a returned face is degenerate: {l1:?}"
        );
        flipped += r.flips;
        refused += r.refused.len();
        // Negative control: the same face check rejects the unchecked rounded flip.
        let (mut m2, mut l2) = (mesh.clone(), l.clone());
        flip_euclidean(&mut m2, &mut l2, diag).unwrap();
        unchecked_bad += usize::from(!faces_strict(&m2, &l2));
    }
    assert!(flipped > 1000, "{flipped}");
    assert!(
        unchecked_bad > 0 && refused > 0,
        "{unchecked_bad} {refused}"
    );
    eprintln!(
        "b66 flips: {flipped} flipped, {refused} refused, {unchecked_bad} unchecked degenerate"
    );
}
