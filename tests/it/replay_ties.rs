//! Ties that no enclosure decides, decided exactly in the replay on the input metric:
//! B107 (the separation bound of algebraic lengths) and B106 (chordal flips on planar
//! hinges of positions).
//!
//! The surface is a fan of four triangles symmetric under the mirror `x ↦ −x`, bent out of
//! any plane (a patch of a mirror-symmetric scan, with coordinates of our own). Intrinsic
//! Delaunay flipping takes five Euclidean flips; the fifth is of a quadrilateral whose
//! corners are two mirror pairs and whose sides are earlier flips' geodesics: an isosceles
//! trapezoid, so cyclic, `P = 0` exactly — by the symmetry, an argument independent of
//! any arithmetic. Its lengths are nested square roots, so every enclosure contains 0:
//! before B107 the replay stopped there, undecided at 1024 bits.

use penner::algorithms::delaunay_pipeline::{
    intrinsic_delaunay, DelaunayCertificate, DelaunayOptions,
};
use penner::algorithms::flip_to_delaunay::FlipKind;
use penner::algorithms::replay::replay_lazy;
use penner::algorithms::replay_chord::planar_chord;
use penner::algorithms::replay_input::PositionMetric;
use penner::io::{obj::read_decimal, DecimalSurface, FlipCase};
use penner::scalar::prec::Prec;
use penner::scalar::Precision;
use rug::Rational;

/// The mirror-symmetric patch, with the `x` of vertex 1 (and minus it for vertex 2)
/// written as `x1`.
fn patch(x1: &str) -> DecimalSurface {
    let text = format!(
        "v {x1} 0.15 -0.17\nv -0.81 0.15 -0.17\nv 0.3 0.64 0.37\nv -0.3 0.64 0.37\n\
         v 0 -1.88 -1.04\nv 0 0.73 0.49\nf 5 3 1\nf 5 2 4\nf 5 6 3\nf 6 5 4\n"
    );
    read_decimal(&text).expect("a valid patch")
}

/// The exact value of a decimal literal such as `-0.81`.
fn rational(s: &str) -> Rational {
    let (int, frac) = s.split_once('.').unwrap_or((s, ""));
    let n = rug::Integer::from(rug::Integer::parse(format!("{int}{frac}")).expect("digits"));
    let places = u32::try_from(frac.len()).expect("a short literal");
    Rational::from((n, rug::Integer::from(rug::Integer::u_pow_u(10, places))))
}

/// The replay's input metric on the patch's positions.
fn metric(s: &DecimalSurface) -> PositionMetric<'_> {
    PositionMetric {
        mesh: &s.mesh,
        surface: s,
        squares: None,
    }
}

/// The independent oracle of the tie: `x ↦ −x` maps the patch's vertices onto its
/// vertices and its faces onto its faces (orientation reversed), so it is an isometry of
/// the input metric, and every flip sequence has a mirror image.
fn assert_mirror_symmetric(x1: &str) {
    let p: Vec<[Rational; 3]> = [
        [x1, "0.15", "-0.17"],
        ["-0.81", "0.15", "-0.17"],
        ["0.3", "0.64", "0.37"],
        ["-0.3", "0.64", "0.37"],
        ["0", "-1.88", "-1.04"],
        ["0", "0.73", "0.49"],
    ]
    .iter()
    .map(|v| v.map(rational))
    .collect();
    let mirror = |v: &[Rational; 3]| [Rational::from(-&v[0]), v[1].clone(), v[2].clone()];
    let sigma: Vec<usize> = p
        .iter()
        .map(|v| {
            p.iter()
                .position(|w| *w == mirror(v))
                .expect("a mirror vertex")
        })
        .collect();
    let faces = [[4, 2, 0], [4, 1, 3], [4, 5, 2], [5, 4, 3]];
    for f in faces {
        let [a, b, c] = f.map(|v| sigma[v]);
        assert!(
            faces
                .iter()
                .any(|g| [[c, b, a], [b, a, c], [a, c, b]].contains(g)),
            "face {f:?} has no mirror face"
        );
    }
}

#[test]
fn b107_a_mirror_tie_of_algebraic_lengths_is_proved_and_certified_for_the_input_metric() {
    assert_mirror_symmetric("0.81");
    let bits = Precision::new(256).expect("bits");
    for prec in [Prec::F64, Prec::Dd, Prec::Mpfr(bits)] {
        let mut case = FlipCase::Decimal(patch("0.81"));
        let out = intrinsic_delaunay(&mut case, &DelaunayOptions::at(prec)).expect("runs");
        assert!(out.report.flips >= 4, "{prec:?}");
        assert_eq!(
            out.certificate,
            DelaunayCertificate::InputMetric,
            "{prec:?}"
        );
        let (replay, _) = out.replay.as_ref().expect("a replay");
        assert!(replay.broken.is_none(), "{prec:?}: {:?}", replay.broken);
        // The tie flip's new diagonal is again a tie: both diagonals are Delaunay.
        assert!(!replay.ties.is_empty(), "{prec:?}: the tie is proved");
        // No enclosure decides it: the quadrilateral's lengths come from non-planar
        // hinges, so the chordal rule (B106) does not apply anywhere on this patch.
        let s = patch("0.81");
        let pos = |v: penner::mesh::Vertex| {
            let c = &s.positions[v.idx()];
            [c[0].to_rational(), c[1].to_rational(), c[2].to_rational()]
        };
        let first = out.report.sequence[0];
        let [i, j, k, l] = s.mesh.quad_vertices(first).map(pos);
        assert_eq!(planar_chord([&i, &j, &k, &l]), None);
    }
    // The same on the exact metric without positions (squared lengths).
    let mut case = FlipCase::Exact(patch("0.81").into_surface());
    let out = intrinsic_delaunay(&mut case, &DelaunayOptions::at(Prec::F64)).expect("runs");
    assert_eq!(out.certificate, DelaunayCertificate::InputMetric);
}

/// Control: moving vertex 1 by 10⁻⁴⁰⁰ breaks the mirror. The rounded run is the same
/// (its `f64` positions are), no enclosure below about 1 330 bits separates the fifth
/// flip's `P` from 0, and the replay must not call it a tie: at 128 bits the separation
/// bound decides its sign, and the replay's verdicts equal those of a replay at 4 096
/// bits, where the enclosures decide it alone.
#[test]
fn b107_a_mirror_broken_by_ten_to_the_minus_400_is_no_tie_and_agrees_with_4096_bits() {
    let tiny = format!("0.81{}1", "0".repeat(398));
    let symmetric = patch("0.81");
    let broken = patch(&tiny);
    let mut case = FlipCase::Decimal(symmetric.clone());
    let out = intrinsic_delaunay(&mut case, &DelaunayOptions::at(Prec::F64)).expect("runs");
    let seq = out.report.sequence.clone();
    for s in [&symmetric, &broken] {
        let low = replay_lazy(&s.mesh, &metric(s), &seq, FlipKind::Euclidean, 128);
        let high = replay_lazy(&s.mesh, &metric(s), &seq, FlipKind::Euclidean, 4096);
        assert_eq!(low.broken, high.broken);
        assert_eq!(low.ties, high.ties);
        assert_eq!(low.negative, high.negative);
        assert!(low.undecided.is_empty() && high.undecided.is_empty());
    }
    let low = replay_lazy(
        &broken.mesh,
        &metric(&broken),
        &seq,
        FlipKind::Euclidean,
        128,
    );
    assert!(low.ties.is_empty(), "a broken mirror has no tie");
    let sym = replay_lazy(
        &symmetric.mesh,
        &metric(&symmetric),
        &seq,
        FlipKind::Euclidean,
        128,
    );
    assert!(!sym.ties.is_empty() && sym.broken.is_none());
}
