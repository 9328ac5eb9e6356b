//! No false verdicts from the flip checks (T21, T21P, T22) on adversarial ties and
//! near-ties, the flip cap on every route of the driver, and the MPFR rung of the ladder at
//! its configured precision.
//!
//! Families (all generated here): polygons whose vertices are rational points of a circle
//! with every chord rational (Pythagorean parametrisation: exact cocircular ties), as fans
//! and zigzags; needles and caps on such circles (arcs of 10⁻³ … 10⁻²⁴); the regular hexagon
//! (squared lengths 1, 3, 4); regular polygons rounded to integer points; nearly collinear
//! integer triangles (points on the parabola `(kN, k²)`); exact scalings by `2^±300` and
//! `2^±1000`. Through the registry (`penner check`), at f64, dd, MPFR-128/256/1080, none of
//! T21, T21P, T22 may answer `fails`; the `undecided` rates are counted. Negative controls:
//! T21-NC and T22-NC still fail on the same families.

use crate::meshgen::polygon_mesh;
use penner::algorithms::flip_to_delaunay::{
    flip_to_delaunay, flip_to_delaunay_exact, FlipKind, FlipOptions,
};
use penner::io::{Metric, Surface};
use penner::mesh::Mesh;
use penner::oracle::controls;
use penner::oracle::precision::Prec;
use penner::oracle::registry::{by_id, run_one, Outcome};
use penner::predicates::delaunay::{Quad, RealQuad};
use penner::predicates::ladder::{decide, Ladder};
use penner::scalar::{Certified, Dd, Mpfr, Precision, Sign, Stage};
use penner::theorems::{Settings, Verdict};
use rug::ops::Pow;
use rug::{Float, Rational};
use std::collections::BTreeMap;

/// `(cos φ, sin φ)` for `t = tan(φ/2)`: a rational point of the unit circle.
fn half_angle(t: &Rational) -> (Rational, Rational) {
    let t2 = Rational::from(t * t);
    let den = Rational::from(1 + &t2);
    (Rational::from(1 - &t2) / &den, Rational::from(2 * t) / den)
}

/// Chord lengths `2R|sin(φ_a − φ_b)|` between points at angles `2φ` (rational for rational
/// `cos φ, sin φ`), one per edge of `mesh`.
fn chords(mesh: &Mesh, cs: &[(Rational, Rational)], r: &Rational) -> Vec<Rational> {
    mesh.edges()
        .map(|e| {
            let h = e.halfedge();
            let ((ca, sa), (cb, sb)) = (&cs[mesh.tail(h).idx()], &cs[mesh.tip(h).idx()]);
            let s = Rational::from(sa * cb) - Rational::from(ca * sb);
            Rational::from(r * 2) * s.abs()
        })
        .collect()
}

/// The zigzag triangulation of the convex polygon `0..n` (counter-clockwise).
fn zigzag(n: u32) -> Mesh {
    let (mut a, mut b, mut left) = (0, n - 1, true);
    let mut faces = Vec::new();
    while b - a >= 2 {
        if left {
            faces.push([a, a + 1, b]);
            a += 1;
        } else {
            faces.push([a, b - 1, b]);
            b -= 1;
        }
        left = !left;
    }
    Mesh::from_faces(n, &faces).unwrap()
}

fn surface(name: String, mesh: Mesh, metric: Metric) -> Surface {
    Surface {
        name,
        mesh,
        metric,
        positions: None,
    }
}

/// Both triangulations (fan, zigzag) of the polygon with rational circle parameters `t`
/// (increasing, in `(0, ∞)`), circumradius `r`.
fn circle_polygons(name: &str, t: &[Rational], r: &Rational) -> Vec<Surface> {
    let cs: Vec<_> = t.iter().map(half_angle).collect();
    let n = t.len() as u32;
    [("fan", polygon_mesh(n, true, 0)), ("zigzag", zigzag(n))]
        .into_iter()
        .map(|(how, m)| {
            let l = chords(&m, &cs, r);
            surface(format!("{name} {how}"), m, Metric::Lengths(l))
        })
        .collect()
}

/// Squared distances of integer points, one per edge.
fn squared(mesh: &Mesh, p: &[(i128, i128)]) -> Vec<Rational> {
    mesh.edges()
        .map(|e| {
            let h = e.halfedge();
            let (a, b) = (p[mesh.tail(h).idx()], p[mesh.tip(h).idx()]);
            let (dx, dy) = (a.0 - b.0, a.1 - b.1);
            Rational::from(dx * dx + dy * dy)
        })
        .collect()
}

fn integer_polygons(name: &str, p: &[(i128, i128)]) -> Vec<Surface> {
    let n = p.len() as u32;
    [("fan", polygon_mesh(n, true, 0)), ("zigzag", zigzag(n))]
        .into_iter()
        .map(|(how, m)| {
            let s = squared(&m, p);
            surface(format!("{name} {how}"), m, Metric::SquaredLengths(s))
        })
        .collect()
}

fn q(n: i64, d: i64) -> Rational {
    Rational::from((n, d))
}

/// `10^-m` as a rational.
fn tenth_pow(m: u32) -> Rational {
    Rational::from((1, rug::Integer::from(10).pow(m)))
}

/// Every adversarial family (module docs).
fn families() -> Vec<Surface> {
    let one = Rational::from(1);
    let mut out = Vec::new();
    // Rational circles: evenly spread parameters (every quadrilateral an exact tie).
    for n in [6i64, 8, 12] {
        let t: Vec<Rational> = (0..n)
            .map(|k| {
                let x = (std::f64::consts::PI * (k as f64 + 0.5) / (2.0 * n as f64)).tan();
                q((x * 1000.0).round() as i64, 1000)
            })
            .collect();
        out.extend(circle_polygons(
            &format!("rational circle {n}-gon"),
            &t,
            &one,
        ));
    }
    // Needles (two clusters of close points) and caps (every point in one tiny arc).
    for m in [3u32, 8, 16, 24] {
        let d = tenth_pow(m);
        let needle: Vec<Rational> = [q(1, 2), q(1, 2) + &d, q(1, 1), q(2, 1), q(2, 1) + &d]
            .into_iter()
            .collect();
        out.extend(circle_polygons(&format!("needles 1e-{m}"), &needle, &one));
        let cap: Vec<Rational> = (0..6).map(|k| q(1, 1) + Rational::from(&d * k)).collect();
        out.extend(circle_polygons(&format!("cap 1e-{m}"), &cap, &one));
    }
    // The regular hexagon with unit sides: squared chords 1, 3, 4.
    for how in ["fan", "zigzag"] {
        let m = if how == "fan" {
            polygon_mesh(6, true, 0)
        } else {
            zigzag(6)
        };
        let s: Vec<Rational> = m
            .edges()
            .map(|e| {
                let h = e.halfedge();
                let k = m
                    .tail(h)
                    .0
                    .abs_diff(m.tip(h).0)
                    .min(6 - m.tail(h).0.abs_diff(m.tip(h).0));
                Rational::from([0, 1, 3, 4][k as usize])
            })
            .collect();
        out.push(surface(
            format!("regular hexagon {how}"),
            m,
            Metric::SquaredLengths(s),
        ));
    }
    // Regular polygons rounded to integer points.
    for (n, r) in [(7u32, 1e3), (12, 1e6), (16, 1e9)] {
        let p: Vec<(i128, i128)> = (0..n)
            .map(|k| {
                let a = std::f64::consts::TAU * f64::from(k) / f64::from(n);
                ((r * a.cos()).round() as i128, (r * a.sin()).round() as i128)
            })
            .collect();
        out.extend(integer_polygons(
            &format!("rounded regular {n}-gon R={r:e}"),
            &p,
        ));
    }
    // Nearly collinear integer triangles: the parabola (kN, k²), convex.
    for big in [1_000i128, 1_000_000, 1_000_000_000] {
        let p: Vec<(i128, i128)> = (0..6).map(|k| (k * big, k * k)).collect();
        out.extend(integer_polygons(&format!("parabola N={big}"), &p));
    }
    // Exact scalings by 2^±300 and 2^±1000 of a rational circle and of a needle family.
    let base: Vec<Surface> = out
        .iter()
        .filter(|s| {
            s.name.starts_with("rational circle 8-gon") || s.name.starts_with("needles 1e-8")
        })
        .cloned()
        .collect();
    for k in [300i32, -300, 1000, -1000] {
        let f: Rational = (Float::with_val(64, 1) << k).to_rational().unwrap();
        for s in &base {
            let Metric::Lengths(l) = &s.metric else {
                continue;
            };
            let l = l.iter().map(|x| Rational::from(x * &f)).collect();
            out.push(surface(
                format!("{} ×2^{k}", s.name),
                s.mesh.clone(),
                Metric::Lengths(l),
            ));
        }
    }
    out
}

fn precisions() -> Vec<Prec> {
    let mut p = vec![Prec::F64, Prec::Dd];
    for b in [128, 256, 1080] {
        p.push(Prec::Mpfr(Precision::new(b).unwrap()));
    }
    p.push(Prec::Exact);
    p
}

#[test]
fn t21_t22_adversarial_ties_never_fail_through_the_registry() {
    let settings = Settings::default();
    let fams = families();
    assert!(fams.len() >= 40, "{}", fams.len());
    // (check, precision) → [holds, undecided, n/a]
    let mut tally: BTreeMap<(String, String), [usize; 3]> = BTreeMap::new();
    let mut bad = Vec::new();
    for case in &fams {
        for id in ["T21", "T21P", "T22"] {
            let check = by_id(id).unwrap();
            for p in precisions() {
                let Some(row) = run_one(&check, case, p, &settings) else {
                    continue;
                };
                let slot = match &row.outcome {
                    Outcome::Verdict(Verdict::Holds { .. }) => 0,
                    Outcome::Verdict(Verdict::Undecided { .. }) => 1,
                    Outcome::Verdict(Verdict::NotApplicable { .. }) => 2,
                    other => {
                        bad.push(format!("{} {id} {p}: {other:?}", case.name));
                        continue;
                    }
                };
                tally.entry((id.to_string(), p.to_string())).or_default()[slot] += 1;
            }
        }
    }
    for ((id, p), [h, u, na]) in &tally {
        eprintln!("{id} at {p}: {h} holds, {u} undecided, {na} n/a");
    }
    assert!(
        bad.is_empty(),
        "false or broken verdicts:\n{}",
        bad.join("\n")
    );
    // The checks are not vacuous here: each holds on some family at every precision.
    for ((id, p), [h, ..]) in &tally {
        assert!(*h > 0, "{id} at {p} never holds");
    }
}

#[test]
fn t21_t22_negative_controls_still_fail_on_the_adversarial_families() {
    let settings = Settings::default();
    let mut failed = BTreeMap::<&str, usize>::new();
    let fams = families();
    for case in &fams {
        for id in ["T21-NC", "T22-NC"] {
            let c = controls::by_id(id).unwrap();
            for p in [Prec::F64, Prec::Mpfr(Precision::new(256).unwrap())] {
                let Some(row) = run_one(&c, case, p, &settings) else {
                    continue;
                };
                match &row.outcome {
                    Outcome::Verdict(Verdict::Fails { .. }) => *failed.entry(id).or_default() += 1,
                    Outcome::Verdict(Verdict::NotApplicable { .. }) => {}
                    other => panic!("{} {id} {p}: control did not fail: {other:?}", case.name),
                }
            }
        }
    }
    // T21-NC needs an edge non-Delaunay by a margin: not applicable on the all-tie
    // polygons, applicable (and failing) on the others.
    assert!(
        failed.get("T21-NC").copied().unwrap_or(0) >= 2,
        "{failed:?}"
    );
    assert!(failed.get("T22-NC").copied().unwrap_or(0) > 5, "{failed:?}");
}

/// A named run with an optional flip cap, returning the flips and whether the cap was hit.
type CappedRun<'a> = (&'a str, &'a dyn Fn(Option<usize>) -> (usize, bool));

/// Flip a copy of `(m, l)` with the flip cap `cap`.
fn capped<T: penner::scalar::Real>(
    m: &Mesh,
    l: &[T],
    cap: Option<usize>,
) -> penner::algorithms::flip_to_delaunay::FlipReport {
    let (mut m, mut l) = (m.clone(), l.to_vec());
    let opts = FlipOptions {
        max_flips: cap,
        ..FlipOptions::default()
    };
    flip_to_delaunay(&mut m, &mut l, FlipKind::Euclidean, &opts).unwrap()
}

/// The flip cap stops every route of the driver after exactly `cap` flips: the f64 fast
/// path, the general path (Dd, MPFR: no fast path) and the exact path (ℚ, Ptolemy); a cap
/// equal to the flips needed is not hit. Negative control: the uncapped runs need more
/// flips than each cap tested.
#[test]
fn t21_flip_cap_stops_every_route_after_exactly_cap_flips() {
    let e = crate::meshgen::planar_grid(7, 0.3, 11);
    let m = e.mesh();
    let l: Vec<f64> = m
        .edges()
        .map(|x| {
            let h = x.halfedge();
            let (a, b) = (e.pos[m.tail(h).idx()], e.pos[m.tip(h).idx()]);
            (a[0] - b[0]).hypot(a[1] - b[1])
        })
        .collect();
    let p = Precision::new(200).unwrap();
    let ld: Vec<Dd> = l.iter().map(|&x| Dd::from_f64(x)).collect();
    let lm: Vec<Mpfr> = l
        .iter()
        .map(|&x| <Mpfr as penner::scalar::Real>::from_f64(x, p))
        .collect();
    let lq: Vec<Rational> = l.iter().map(|&x| Rational::from_f64(x).unwrap()).collect();
    let runs: [CappedRun; 4] = [
        ("f64", &|c| {
            let r = capped(&m, &l, c);
            (r.flips, r.hit_cap)
        }),
        ("dd", &|c| {
            let r = capped(&m, &ld, c);
            (r.flips, r.hit_cap)
        }),
        ("mpfr-200", &|c| {
            let r = capped(&m, &lm, c);
            (r.flips, r.hit_cap)
        }),
        ("exact", &|c| {
            let mut m2 = m.clone();
            let opts = FlipOptions {
                max_flips: c,
                ..FlipOptions::default()
            };
            let (r, _) = flip_to_delaunay_exact(&mut m2, lq.clone(), 1 << 20, &opts).unwrap();
            (r.flips, r.hit_cap)
        }),
    ];
    for (name, run) in runs {
        let (total, hit) = run(None);
        assert!(!hit && total >= 6, "{name}: {total} flips");
        for cap in [0, 1, total / 2, total - 1] {
            assert_eq!(run(Some(cap)), (cap, true), "{name}: cap {cap} of {total}");
        }
        assert_eq!(
            run(Some(total)),
            (total, false),
            "{name}: cap = flips needed"
        );
    }
}

/// The rungs of the ladder evaluate at their own precision: with the exact rung off, a
/// quadrilateral `P` of relative size 2⁻³⁰⁰ (the 3-4-5 rectangle with its diagonal
/// 5(1 ∓ 2⁻³⁰⁰), exact in 1024-bit MPFR) is decided at the 512-bit rung and undecided by
/// a ladder that stops at 256 bits (the inputs round to the exact tie there). Negative
/// control: the other perturbation gives the other sign.
#[test]
fn b62_ladder_rungs_use_their_configured_mpfr_precision() {
    let p = Precision::new(1024).unwrap();
    let x = |r: Rational| <Mpfr as penner::scalar::Real>::from_rational(&r, p);
    let tiny: Rational = (Float::with_val(64, 1) >> 300i32).to_rational().unwrap();
    let no_exact = Ladder {
        start_bits: 128,
        max_bits: 1024,
        exact: false,
    };
    for (sign, value) in [(-1, Sign::Positive), (1, Sign::Negative)] {
        let diag = Rational::from(5) * (Rational::from(1) + Rational::from(&tiny * sign));
        let [a, b, c, d, e] = [x(diag), x(3.into()), x(4.into()), x(3.into()), x(4.into())];
        let quad = RealQuad(Quad {
            ij: &a,
            jk: &b,
            ki: &c,
            il: &d,
            lj: &e,
        });
        assert_eq!(
            decide(&quad, &no_exact),
            Certified::Known {
                value,
                stage: Stage::Interval { bits: 512 }
            }
        );
        let short = Ladder {
            max_bits: 256,
            ..no_exact
        };
        assert_eq!(
            decide(&quad, &short),
            Certified::Undecided { bits_tried: 256 }
        );
    }
}
