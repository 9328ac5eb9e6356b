//! The replay's first rung on widened `f64` enclosures (B83) and the lazy replay on exact
//! positions that uses it (`algorithms::replay::replay_lazy` with
//! `replay_input::PositionMetric`), against independent oracles: the integer incircle
//! determinant of planar points, and the replay on the exact rational metric of the same
//! file (built by the exact reader, not from the decimal integers).

use crate::meshgen::{icosphere, planar_grid, Embedded};
use crate::support::{case_seeds, cases, in_shard};
use penner::algorithms::flip_to_delaunay::{flip_to_delaunay, FlipKind, FlipOptions};
use penner::algorithms::replay::{replay_lazy, replay_on_input, BrokenStep, Len};
use penner::algorithms::replay_input::PositionMetric;
use penner::io::off;
use penner::predicates::delaunay::QuadEdges;
use penner::predicates::delaunay_widened::{length_from_square, sign_p};
use penner::scalar::Sign;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rug::Rational;

/// Lattice points on the circle `x² + y² = r²`, `r² = 5⁴·13²·17²` (many representations).
fn circle_points() -> Vec<[i128; 2]> {
    let r2: i128 = 625 * 169 * 289;
    let mut pts = Vec::new();
    let mut x: i128 = 0;
    while x * x <= r2 {
        let y2 = r2 - x * x;
        let y = (y2 as f64).sqrt().round() as i128;
        if y * y == y2 {
            for (sx, sy) in [(1, 1), (-1, 1), (1, -1), (-1, -1)] {
                let p = [sx * x, sy * y];
                if !pts.contains(&p) {
                    pts.push(p);
                }
            }
        }
        x += 1;
    }
    pts.sort_by(|a, b| {
        let ang = |p: &[i128; 2]| (p[1] as f64).atan2(p[0] as f64);
        ang(a).total_cmp(&ang(b))
    });
    pts
}

fn d2(p: [i128; 2], q: [i128; 2]) -> i128 {
    (p[0] - q[0]).pow(2) + (p[1] - q[1]).pow(2)
}

/// `−sign(orient(i, j, k) · incircle(i, j, k, l))`: the sign of `P` of the edge `ij` of the
/// convex quadrilateral `i, k, j, l` (positive: `l` outside the circle through `i, j, k`).
fn incircle_sign(i: [i128; 2], j: [i128; 2], k: [i128; 2], l: [i128; 2]) -> Sign {
    use rug::Integer;
    let z = |p: [i128; 2]| [Integer::from(p[0] - l[0]), Integer::from(p[1] - l[1])];
    let (a, b, c) = (z(i), z(j), z(k));
    let w = |p: &[Integer; 2]| Integer::from(&p[0] * &p[0]) + Integer::from(&p[1] * &p[1]);
    let det2 = |p: &[Integer; 2], q: &[Integer; 2]| {
        Integer::from(&p[0] * &q[1]) - Integer::from(&p[1] * &q[0])
    };
    let inc = w(&a) * det2(&b, &c) - w(&b) * det2(&a, &c) + w(&c) * det2(&a, &b);
    let o = (j[0] - i[0]) * (k[1] - i[1]) - (j[1] - i[1]) * (k[0] - i[0]);
    let s = inc.cmp0() as i32 * o.signum() as i32;
    Sign::of_ordering(0.cmp(&s))
}

/// The first rung decides only what the incircle determinant says: convex quadrilaterals
/// of lattice points on one circle, scaled by an odd factor near 2²⁴ so that squared lengths
/// exceed 2⁵³ and round, are exact ties and never decided; the same with the fourth point
/// moved off the circle by one unit (relative size about 10⁻¹¹) decide only with the
/// oracle's sign; moved by 30 units (relative 5·10⁻³) they are always decided (the rung has
/// power).
#[test]
fn b83_widened_sign_agrees_with_the_incircle_sign() {
    let pts = circle_points();
    assert!(pts.len() >= 32, "{} lattice points", pts.len());
    let mut rng = ChaCha8Rng::seed_from_u64(83);
    let (mut ties, mut decided_near, mut far) = (0, 0, 0);
    for case in 0..cases(3_000, 300_000) {
        let mut idx: Vec<usize> = (0..4).map(|_| rng.gen_range(0..pts.len())).collect();
        let s: i128 = (1 << 24) + 2 * rng.gen_range(0..1000) + 1;
        let dx: i128 = rng.gen_range(-1..=1);
        if !in_shard(case) {
            continue; // generated, then left to another shard
        }
        idx.sort_unstable();
        idx.dedup();
        if idx.len() < 4 {
            continue;
        }
        let p = idx
            .iter()
            .map(|&k| pts[k].map(|c| c * s))
            .collect::<Vec<_>>();
        // Around the circle: i = p0, k = p1, j = p2, l = p3 (convex, ij a diagonal).
        let (i, k, j, l0) = (p[0], p[1], p[2], p[3]);
        for (dx, dy, kind) in [
            (0i128, 0i128, 0),
            (dx, 1, 1),
            (0, s * 30, 2),
            (0, -s * 30, 2),
        ] {
            let l = [l0[0] + dx, l0[1] + dy];
            // k and l on opposite sides of ij (a moved l may cross it): otherwise the
            // planar incircle test is not the intrinsic Delaunay condition.
            let side = |p: [i128; 2]| {
                ((j[0] - i[0]) * (p[1] - i[1]) - (j[1] - i[1]) * (p[0] - i[0])).signum()
            };
            if side(k) * side(l) != -1 {
                continue;
            }
            let sq = [d2(i, j), d2(j, k), d2(k, i), d2(i, l), d2(l, j)];
            let q = sq.map(|x| length_from_square(x as f64).unwrap());
            let oracle = incircle_sign(i, j, k, l);
            let got = sign_p(q);
            if let Some(g) = got {
                assert_eq!(g, oracle, "points {i:?} {j:?} {k:?} {l:?}");
            }
            match kind {
                0 => {
                    assert_eq!(
                        oracle,
                        Sign::Zero,
                        "not cocircular: {i:?} {j:?} {k:?} {l:?}"
                    );
                    assert_eq!(got, None, "a tie decided: {i:?} {j:?} {k:?} {l:?}");
                    ties += 1;
                }
                1 => decided_near += usize::from(got.is_some()),
                _ => {
                    assert!(got.is_some(), "not decided: {i:?} {j:?} {k:?} {l:?}");
                    far += 1;
                }
            }
        }
    }
    eprintln!("ties {ties}, decided one unit off {decided_near}, far {far}");
    assert!(ties > 100 && far > 200);
}

/// The OFF text of `e` (17 significant digits).
fn off_text(e: &Embedded) -> String {
    let mut out = Vec::new();
    e.write_off(&mut out).unwrap();
    String::from_utf8(out).unwrap()
}

/// A flip sequence from an `f64` run, the replay on positions (with and without the kept
/// squares) and the replay on the exact metric of the same OFF file agree on every
/// outcome and length; all certify the result. Negative control: a flip of an edge that is
/// strictly Delaunay appended to the sequence breaks all three at that step.
#[test]
fn b83_lazy_replay_on_positions_equals_the_replay_on_the_exact_metric() {
    let mut inputs: Vec<(String, Embedded)> = Vec::new();
    for seed in case_seeds(3, 30) {
        let mut s = icosphere(6 + seed as u32 % 3);
        s.jitter_radial(0.05 + 0.05 * (seed % 3) as f64, seed);
        inputs.push((format!("sphere {seed}"), s));
        inputs.push((format!("grid {seed}"), planar_grid(12, 0.45, seed)));
    }
    let (mut flipped, mut chords) = (0, 0);
    for (name, e) in &inputs {
        let text = off_text(e);
        let dec = off::read_decimal(&text).unwrap();
        let exact = off::read(&text).unwrap();
        let mut mesh = dec.mesh.clone();
        let squares = dec.squared_lengths_f64();
        let mut l = dec.lengths_f64();
        let opts = FlipOptions {
            record: true,
            ..FlipOptions::default()
        };
        let report = flip_to_delaunay(&mut mesh, &mut l, FlipKind::Euclidean, &opts).unwrap();
        assert!(report.all_certified_delaunay(), "{name}");
        flipped += report.flips;
        let delaunay_edge = mesh
            .edges()
            .find(|&x| QuadEdges::of(&mesh, x).is_some() && !report.sequence.contains(&x))
            .unwrap();
        let mut bad = report.sequence.clone();
        bad.push(delaunay_edge);
        for (seq, broken) in [(&report.sequence, false), (&bad, true)] {
            let reference =
                replay_on_input(&dec.mesh, &exact.metric, seq, FlipKind::Euclidean, 128);
            for kept in [Some(&squares[..]), None] {
                let input = PositionMetric {
                    mesh: &dec.mesh,
                    surface: &dec,
                    squares: kept,
                };
                let r = replay_lazy(&dec.mesh, &input, seq, FlipKind::Euclidean, 128)
                    .materialized(&input);
                assert_eq!(r.broken, reference.broken, "{name}");
                assert_eq!(
                    (&r.ties, &r.negative, &r.undecided),
                    (&reference.ties, &reference.negative, &reference.undecided),
                    "{name}"
                );
                assert_eq!(r.mesh, reference.mesh, "{name}");
                assert_eq!(r.lens.len(), reference.lens.len());
                for (a, b) in r.lens.iter().zip(&reference.lens) {
                    if let (Len::Root(sq), Len::Enclosed(x)) = (a, b) {
                        // B106: a flip of a planar hinge of chords keeps the chord on
                        // positions; the metric's replay encloses the unfolded distance,
                        // which must contain it (compared exactly).
                        assert!(encloses_root(x, sq), "{name}: chord {sq} outside {x:?}");
                        chords += 1;
                    } else {
                        assert_eq!(format!("{a:?}"), format!("{b:?}"), "{name}");
                    }
                }
                if broken {
                    assert!(
                        matches!(r.broken, Some((n, _, BrokenStep::StrictlyDelaunay)) if n == seq.len() - 1),
                        "{name}: {:?}",
                        r.broken
                    );
                } else {
                    assert!(r.certified_delaunay(), "{name}");
                }
            }
        }
    }
    assert!(flipped > 0);
    assert!(chords > 0, "the grids' flips are chordal (B106)");
}

/// Whether the enclosure `x` contains `√sq`, decided exactly: `lo² ≤ sq ≤ hi²`, `lo ≥ 0`.
fn encloses_root(x: &penner::algorithms::replay::Enclosure, sq: &Rational) -> bool {
    let (Some(lo), Some(hi)) = (x.lo().0.to_rational(), x.hi().0.to_rational()) else {
        return false;
    };
    lo.cmp0() != std::cmp::Ordering::Less
        && Rational::from(&lo * &lo) <= *sq
        && *sq <= Rational::from(&hi * &hi)
}

/// B83's range condition: the widened evaluation is only claimed for bounds in
/// `[2⁻²⁰⁰, 2²⁰⁰)` (so that no product underflows or overflows), and an enclosure with
/// either end outside, or with `lo > hi`, is refused by `in_range` and so by `sign_p`, even
/// where the evaluation would give a sign. Controls: the same shapes with every end in
/// range are decided (a tiny diagonal: `P > 0`).
#[test]
fn term_b83_enclosures_outside_the_range_are_refused() {
    use penner::predicates::delaunay_widened::in_range;
    let one = length_from_square(1.0).unwrap();
    let (tiny, small, big) = (2f64.powi(-300), 2f64.powi(-299), 2f64.powi(250));
    for b in [
        [tiny, 0.5],
        [tiny, small],
        [0.5, big],
        [0.0, 1.0],
        [1.0, f64::INFINITY],
        [1.0, f64::NAN],
        [2.0, 1.0],
        [-1.0, 1.0],
    ] {
        assert_eq!(in_range(b), None, "{b:?}");
        assert_eq!(sign_p([b, one, one, one, one]), None, "{b:?}");
    }
    for b in [[2f64.powi(-200), 0.5], [2f64.powi(-150), 2f64.powi(-149)]] {
        assert_eq!(in_range(b), Some(b));
        assert_eq!(
            sign_p([b, one, one, one, one]),
            Some(Sign::Positive),
            "{b:?}"
        );
    }
    // A square's enclosure: in range from 2⁻²⁰⁰ up to below 2²⁰⁰ only.
    assert!(length_from_square(2f64.powi(-200)).is_some());
    assert!(length_from_square(2f64.powi(-201)).is_none());
    assert!(length_from_square(2f64.powi(199)).is_some());
    assert!(length_from_square(2f64.powi(200)).is_none());
}

/// B83's product `p·x` for a positive `p` and a negative `x`: the upper end is `p_lo·x_hi`,
/// not `p_hi·x_hi`. With `a² = 5`, `b = c = 1` (so `b² + c² − a² = −3`), `d = 2.5` and `e`
/// anywhere in `[0.1, 0.25]`, `P(e) = e² − 7.5e + 1.25` is `+0.51` at `e = 0.1` and
/// `−0.5625` at `e = 0.25` (rational arithmetic below), so no sign holds on the box and
/// `sign_p` must answer `None`; taking `p_hi·x_hi` would certify `Negative`. Control: with
/// `e` in `[0.2, 0.25]`, where `P < 0` throughout, it answers `Negative`.
#[test]
fn term_b83_upper_end_of_a_positive_times_a_negative_enclosure() {
    let point = |x: f64| [x, x];
    let p_at = |e: Rational| {
        let (a2, b, c, d) = (
            Rational::from(5),
            Rational::from(1),
            Rational::from(1),
            Rational::from((5, 2)),
        );
        let x = Rational::from(&b * &b) + Rational::from(&c * &c) - &a2;
        let y = Rational::from(&d * &d) + Rational::from(&e * &e) - &a2;
        Rational::from(&d * &e) * x + Rational::from(&b * &c) * y
    };
    assert!(p_at(Rational::from((1, 10))) > 0);
    assert!(p_at(Rational::from((1, 4))) < 0);
    let a = length_from_square(5.0).unwrap();
    let (one, d) = (point(1.0), point(2.5));
    assert_eq!(sign_p([a, one, one, d, [0.1, 0.25]]), None);
    assert!(p_at(Rational::from((1, 5))) < 0);
    assert_eq!(sign_p([a, one, one, d, [0.2, 0.25]]), Some(Sign::Negative));
}
