//! T21 over random surfaces of genus 0–3, closed and with boundary, with random and
//! near-degenerate metrics, flipped at f64, Dd, MPFR and exactly (Ptolemy over ℚ). Every
//! result is re-checked edge by edge with the malachite D-form oracle; the negative
//! controls run the same oracle and the T21 check on the unflipped inputs.

use crate::delaunay::{exact_values, oracle_non_delaunay, to_m};
use crate::delaunay_undecided::encloses;
use crate::support::{case_seeds, cases};
use malachite::rational::Rational as MRational;
use penner::algorithms::flip_to_delaunay::{
    flip_to_delaunay, flip_to_delaunay_exact, ExactLengths, FlipKind, FlipOptions, FlipReport,
};
use penner::mesh::{builders, Edge, Face, Mesh};
use penner::predicates::delaunay::QuadEdges;
use penner::scalar::{Dd, Mpfr, Precision, Real};
use penner::theorems::t21_delaunay_flipping::check_all_edges_delaunay;
use penner::theorems::{Settings, Verdict};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rug::Rational;
use std::str::FromStr;

/// How the edge lengths of a test surface are drawn.
#[derive(Clone, Copy, Debug)]
enum MetricKind {
    /// `1 + k/1024`, `k ∈ 0..1024`: any three satisfy the strict triangle inequality.
    Random,
    /// `1` or `2 − 2⁻ᵏ` (`k ∈ 20..=50`, exact in binary64): a triangle with sides
    /// `(1, 1, 2 − 2⁻ᵏ)` is within `2⁻ᵏ` of degenerate (a cap with an angle near π);
    /// every other combination is a valid, fat triangle.
    NearDegenerate,
}

pub(crate) struct Case {
    pub(crate) name: String,
    pub(crate) mesh: Mesh,
    /// Exact lengths (every value is a binary64 number).
    pub(crate) lengths: Vec<Rational>,
}

/// A random closed surface of genus `g`, or the same surface with a hole cut in it
/// (two face splits, then the removal of a face with three distinct corners).
fn surface(g: u32, n_vertices: u32, boundary: bool, seed: u64) -> Mesh {
    let min = if g == 0 { 3 } else { 1 };
    let mut m = builders::random_surface(g, n_vertices.max(min), seed).unwrap();
    if boundary {
        m.split_face(Face(0)).unwrap();
        let f = Face(m.n_faces() as u32 - 2);
        m.split_face(f).unwrap();
        m = builders::remove_face(&m, Face(m.n_faces() as u32 - 2)).unwrap();
        assert!(m.n_boundary_loops() >= 1);
    }
    m
}

fn lengths(n: usize, kind: MetricKind, rng: &mut ChaCha8Rng) -> Vec<Rational> {
    let k: u32 = rng.gen_range(20..=50);
    (0..n)
        .map(|_| match kind {
            MetricKind::Random => Rational::from((1024 + rng.gen_range(0u32..1024), 1024)),
            MetricKind::NearDegenerate => {
                if rng.gen_bool(0.5) {
                    Rational::from(1)
                } else {
                    Rational::from(2) - Rational::from((1, rug::Integer::from(1) << k))
                }
            }
        })
        .collect()
}

/// The `i`-th test case: genus `i mod 4`, boundary and metric kind from the seed.
pub(crate) fn case(i: u64) -> Case {
    let mut rng = ChaCha8Rng::seed_from_u64(0x7421 + i);
    let g = (i % 4) as u32;
    let boundary = rng.gen_bool(0.5);
    let kind = if rng.gen_bool(0.5) {
        MetricKind::Random
    } else {
        MetricKind::NearDegenerate
    };
    let nv = rng.gen_range(1..=18);
    let mesh = surface(g, nv, boundary, rng.r#gen());
    let lengths = lengths(mesh.n_edges(), kind, &mut rng);
    Case {
        name: format!(
            "case {i}: genus {g}, boundary {boundary}, {kind:?}, V = {}",
            mesh.n_vertices()
        ),
        mesh,
        lengths,
    }
}

/// Flip at backend `T`, then assert: terminated, every edge certified, the oracle agrees,
/// χ and the boundary are unchanged. Returns the flip count.
fn flip_and_check<T: Real>(c: &Case, l: &[T], kind: FlipKind, what: &str) -> usize {
    let (mut m, mut l) = (c.mesh.clone(), l.to_vec());
    let r: FlipReport = flip_to_delaunay(&mut m, &mut l, kind, &FlipOptions::default()).unwrap();
    assert!(
        r.all_certified_delaunay(),
        "{} {what} {kind:?}: {r:?}",
        c.name
    );
    assert_eq!(
        oracle_non_delaunay(&m, &exact_values(&l)),
        vec![],
        "{} {what} {kind:?}",
        c.name
    );
    assert_eq!(m.euler_characteristic(), c.mesh.euler_characteristic());
    assert_eq!(m.n_boundary_loops(), c.mesh.n_boundary_loops());
    r.flips
}

fn settings() -> Settings {
    Settings::default()
}

#[test]
fn t21_genus_0_to_3_with_and_without_boundary_all_backends() {
    let p = Precision::new(128).unwrap();
    let mut non_delaunay_inputs = 0;
    let mut flips = 0;
    let n = cases(48, 20_000) as u64;
    for i in 0..n {
        let c = case(i);
        let f: Vec<f64> = c.lengths.iter().map(Rational::to_f64).collect();
        // Every length is a binary64 number: the f64 metric is the exact metric.
        assert!(f
            .iter()
            .zip(&c.lengths)
            .all(|(x, q)| Rational::from_f64(*x).as_ref() == Some(q)));
        let dd: Vec<Dd> = f.iter().map(|&x| <Dd as Real>::from_f64(x, ())).collect();
        let mp: Vec<Mpfr> = f.iter().map(|&x| Mpfr::from_f64(x, p)).collect();
        for kind in [FlipKind::Euclidean, FlipKind::Ptolemy] {
            flips += flip_and_check(&c, &f, kind, "f64");
            flip_and_check(&c, &dd, kind, "dd");
            flip_and_check(&c, &mp, kind, "mpfr");
        }
        // Exact Ptolemy flipping over ℚ: no rounding at all below the guard.
        let mut m = c.mesh.clone();
        let (r, out) =
            flip_to_delaunay_exact(&mut m, c.lengths.clone(), 1 << 16, &FlipOptions::default())
                .unwrap();
        assert!(r.all_certified_delaunay(), "{} exact: {r:?}", c.name);
        let ExactLengths::Exact(ex) = out else {
            panic!("{}: guard of 2¹⁶ bits passed", c.name)
        };
        let ex: Vec<MRational> = ex.iter().map(to_m).collect();
        assert_eq!(oracle_non_delaunay(&m, &ex), vec![], "{} exact", c.name);
        // Negative control: the same oracle and the T21 check reject the unflipped input
        // whenever it is not Delaunay, naming every failing edge.
        let before = oracle_non_delaunay(&c.mesh, &exact_values(&f));
        let v = check_all_edges_delaunay(&c.mesh, &f, &settings(), false, 0);
        if before.is_empty() {
            assert!(v.holds(), "{}", c.name);
        } else {
            non_delaunay_inputs += 1;
            let Verdict::Fails { witnesses, .. } = v else {
                panic!("{}: unflipped input accepted: {v:?}", c.name)
            };
            assert_eq!(witnesses.len(), before.len(), "{}", c.name);
        }
    }
    assert!(
        non_delaunay_inputs * 2 > n as usize,
        "most inputs must need flips: {non_delaunay_inputs} of {n}"
    );
    assert!(flips > 0);
}

#[test]
fn t21_genus_cases_cover_every_genus_boundary_and_metric() {
    // The generator really produces genus 0–3, closed and bounded: χ = 2 − 2g − b.
    let mut seen = [[false; 2]; 4];
    for i in case_seeds(48, 20_000) {
        let c = case(i);
        let b = c.mesh.n_boundary_loops() as i64;
        let g = (2 - c.mesh.euler_characteristic() - b) / 2;
        assert!((0..=3).contains(&g), "{}", c.name);
        assert_eq!(g as u64, i % 4, "{}", c.name);
        seen[g as usize][usize::from(b > 0)] = true;
    }
    assert_eq!(seen, [[true; 2]; 4]);
}

/// Four points on the unit circle at increasing random angles, split along `0–2`: the
/// edge lengths of the disk `[0,1,2], [0,2,3]` rounded to f64, so `P` of the diagonal is a
/// rounding-sized number of either sign.
fn cocircular_quad(rng: &mut ChaCha8Rng) -> (Mesh, Vec<f64>) {
    let mut t: Vec<f64> = (0..4)
        .map(|_| rng.gen_range(0.0..std::f64::consts::TAU))
        .collect();
    t.sort_by(f64::total_cmp);
    let m = Mesh::from_faces(4, &[[0, 1, 2], [0, 2, 3]]).unwrap();
    let l = m
        .edges()
        .map(|e| {
            let h = e.halfedge();
            let (a, b) = (t[m.tail(h).idx()], t[m.tip(h).idx()]);
            (a.cos() - b.cos()).hypot(a.sin() - b.sin())
        })
        .collect();
    (m, l)
}

#[test]
fn b65_nudged_flips_are_certified_for_the_stored_lengths() {
    use penner::algorithms::flips::euclidean_length;
    let u = f64::EPSILON / 2.0;
    let mut rng = ChaCha8Rng::seed_from_u64(65);
    let (mut nudged, mut flipped) = (0, 0);
    for case in 0..cases(3000, 200_000) {
        let (m, l) = cocircular_quad(&mut rng);
        if !crate::support::in_shard(case) {
            continue; // generated, then left to another shard
        }
        let diag = m.edges().find(|&e| !m.is_boundary_edge(e)).unwrap();
        let q = QuadEdges::of(&m, diag).unwrap();
        let rounded = euclidean_length(q.lengths(&l));
        let (mut m2, mut l2) = (m.clone(), l.clone());
        let r = flip_to_delaunay(
            &mut m2,
            &mut l2,
            FlipKind::Euclidean,
            &FlipOptions::default(),
        )
        .unwrap();
        assert!(r.all_certified_delaunay(), "{l:?}: {r:?}");
        // The oracle agrees on the stored lengths, whatever happened.
        assert_eq!(
            oracle_non_delaunay(&m2, &exact_values(&l2)),
            vec![],
            "{l:?}"
        );
        if r.flips == 0 {
            continue;
        }
        flipped += 1;
        let stored = l2[diag.idx()];
        if r.nudged == 0 {
            assert_eq!(
                stored, rounded,
                "an unnudged flip stores the rounded length"
            );
            continue;
        }
        nudged += 1;
        // The stored length is the rounded one shrunk by at most 8 steps of
        // fl(ℓ − fl(4u·ℓ)), each a relative change below 5u + 4u² (proof: B65).
        assert!(stored < rounded, "{l:?}");
        assert!(
            stored >= rounded * (1.0 - 8.0 * (5.0 * u + 4.0 * u * u)),
            "{l:?}"
        );
        // Negative control: with the rounded length the new diagonal is not Delaunay for
        // the oracle, so the nudge was needed.
        let mut bare = l2.clone();
        bare[diag.idx()] = rounded;
        assert_eq!(
            oracle_non_delaunay(&m2, &exact_values(&bare)),
            vec![diag],
            "{l:?}"
        );
    }
    assert!(flipped > 100, "only {flipped} flips");
    assert!(
        nudged > 0,
        "no rounded flip landed on the wrong side of a tie"
    );
}

#[test]
fn b61_flipping_commutes_with_power_of_two_scaling() {
    // Scaling every length by 2ᵏ multiplies P by 2⁴ᵏ and every flip length by 2ᵏ exactly,
    // so certified flipping must make the same flips and return exactly 2ᵏ × the lengths,
    // whether the filter runs unscaled (|k| small), rescaled, or not at all (the lengths
    // span the 2^±200 range boundary, or leave it during the run).
    for i in case_seeds(12, 400) {
        let c = case(i);
        let f: Vec<f64> = c.lengths.iter().map(Rational::to_f64).collect();
        let opts = FlipOptions {
            record: true,
            ..FlipOptions::default()
        };
        let (mut m0, mut l0) = (c.mesh.clone(), f.clone());
        let r0 = flip_to_delaunay(&mut m0, &mut l0, FlipKind::Euclidean, &opts).unwrap();
        assert!(r0.all_certified_delaunay(), "{}", c.name);
        for k in [-600, -300, -199, -150, 150, 199, 300, 600] {
            let s = 2f64.powi(k);
            let mut ls: Vec<f64> = f.iter().map(|x| x * s).collect();
            let mut ms = c.mesh.clone();
            let rs = flip_to_delaunay(&mut ms, &mut ls, FlipKind::Euclidean, &opts).unwrap();
            assert!(rs.all_certified_delaunay(), "{} at 2^{k}", c.name);
            assert_eq!(rs.sequence, r0.sequence, "{} at 2^{k}", c.name);
            assert_eq!(ms, m0, "{} at 2^{k}", c.name);
            let back: Vec<f64> = ls.iter().map(|x| x / s).collect();
            assert_eq!(back, l0, "{} at 2^{k}", c.name);
        }
    }
    // Negative control: raw f64 decisions at 2^±300 overflow or underflow (P is ∞ − ∞ or
    // 0) and flip differently from the unscaled run on the same inputs.
    let mut differs = 0;
    for i in case_seeds(12, 400) {
        let c = case(i);
        let f: Vec<f64> = c.lengths.iter().map(Rational::to_f64).collect();
        let (mut m0, mut l0) = (c.mesh.clone(), f.clone());
        let n0 = penner::algorithms::naive::flip_to_delaunay_naive(
            &mut m0,
            &mut l0,
            FlipKind::Euclidean,
            10_000,
        );
        for k in [-300, 300] {
            let s = 2f64.powi(k);
            let mut ls: Vec<f64> = f.iter().map(|x| x * s).collect();
            let mut ms = c.mesh.clone();
            let ns = penner::algorithms::naive::flip_to_delaunay_naive(
                &mut ms,
                &mut ls,
                FlipKind::Euclidean,
                10_000,
            );
            differs += usize::from(ns.flips != n0.flips || ms != m0);
        }
    }
    assert!(differs > 0, "naive f64 flipping never noticed the scale");
}

/// Replay `sequence` on `(mesh, lengths)` with Ptolemy flips computed in malachite (the
/// combinatorial flip from the mesh, the length formula written out here): the exact
/// lengths of the triangulation that sequence reaches.
fn replay_exact(mesh: &Mesh, lengths: &[Rational], sequence: &[Edge]) -> (Mesh, Vec<MRational>) {
    let mut m = mesh.clone();
    let mut l: Vec<MRational> = lengths.iter().map(to_m).collect();
    for &e in sequence {
        let q = QuadEdges::of(&m, e).expect("a recorded flip is flippable");
        let [ij, jk, ki, il, lj] = q.lengths(&l).to_array();
        let kl = (ki * lj + il * jk) / ij;
        m.flip(e).expect("a recorded flip is flippable");
        l[e.idx()] = kl;
    }
    (m, l)
}

/// `q·(1 + 2⁻¹⁰⁰)`: a wrong length, far closer to the exact one than f64 rounding.
fn off_by_2_pow_minus_100(q: &MRational) -> MRational {
    let tiny = MRational::from_str("1/1267650600228229401496703205376").unwrap();
    q * (MRational::from(1) + tiny)
}

/// What [`t21_exact_flipping_after_fallback_agrees_with_exact_arithmetic`] saw.
#[derive(Debug, Default)]
struct FallbackTally {
    /// Guarded runs (each fell back).
    fell_back: usize,
    /// Of those, runs on enclosures from the start.
    whole_run: usize,
    /// Runs with every decision certified: the exact run, flip for flip.
    identical: usize,
    /// Runs with an undecided decision (a tie on enclosures).
    with_undecided: usize,
    /// Enclosures checked to contain the exact length.
    enclosed: usize,
    /// Of those, enclosures that reject the length off by 2⁻¹⁰⁰ relative.
    wrong_rejected: usize,
    /// Signs certified on the final enclosures, compared with the exact ones.
    signs: usize,
    /// Ties decided in ℚ before the fallback and not re-examined after it.
    ties_before: usize,
}

/// The exact run of a case: ℚ all the way, from the same start with the same options.
struct ExactRun {
    report: FlipReport,
    mesh: Mesh,
    lengths: Vec<MRational>,
}

/// Run case `c` with `guard`, which the exact run `ex` passed, and check the fallback
/// against exact arithmetic.
fn check_fell_back_run(
    c: &Case,
    guard: u64,
    opts: &FlipOptions,
    ex: &ExactRun,
    t: &mut FallbackTally,
) {
    use penner::predicates::delaunay::EnclosureQuad;
    use penner::predicates::ladder::{decide, Ladder};
    use penner::scalar::{Certified, Sign};
    let what = format!("{} guard {guard}", c.name);
    let mut mf = c.mesh.clone();
    let (rf, outf) = flip_to_delaunay_exact(&mut mf, c.lengths.clone(), guard, opts).unwrap();
    // The exact run passed this guard, so the guarded run must fall back.
    let after = rf
        .fell_back_after
        .unwrap_or_else(|| panic!("{what}: no fallback ({rf:?})"));
    t.fell_back += 1;
    t.whole_run += usize::from(after == 0);
    assert!(!rf.hit_cap, "{what}");
    let ExactLengths::Enclosed(enc) = outf else {
        panic!("{what}: fell back without enclosures")
    };
    // The exact lengths of the triangulation the guarded run reached.
    let (mr, lr) = replay_exact(&c.mesh, &c.lengths, &rf.sequence);
    assert_eq!(mr, mf, "{what}: the recorded flips");
    for e in mf.edges() {
        // Every returned enclosure contains the exact length ...
        assert!(encloses(&enc[e.idx()], &lr[e.idx()]), "{what} {e}");
        t.enclosed += 1;
        // ... and is tight enough to reject a length wrong by 2⁻¹⁰⁰ relative (negative
        // control of the containment check).
        let wrong = off_by_2_pow_minus_100(&lr[e.idx()]);
        assert!(!encloses(&enc[e.idx()], &wrong), "{what} {e}");
        t.wrong_rejected += 1;
    }
    // Every sign the enclosures certify is the exact sign, and every edge the run reports
    // certified is Delaunay in exact arithmetic.
    let flagged: Vec<Edge> = rf.undecided.iter().chain(&rf.refused).copied().collect();
    for e in mf.edges() {
        let Some(q) = QuadEdges::of(&mf, e) else {
            continue;
        };
        let exact = crate::delaunay::oracle(q.lengths(&lr).to_array());
        match decide(&EnclosureQuad(q.lengths(&enc)), &Ladder::default()) {
            Certified::Known { value, .. } => {
                assert_eq!(value, exact, "{what} {e}");
                t.signs += 1;
            }
            // Not decidable on the final enclosures: an exact tie (the enclosures are not
            // too wide). Unless listed, it was decided (Zero) in ℚ before the fallback and
            // its quadrilateral was not flipped since.
            Certified::Undecided { .. } => {
                assert_eq!(exact, Sign::Zero, "{what} {e}");
                if !flagged.contains(&e) {
                    assert!(after > 0 && rf.stages.exact > 0, "{what} {e}");
                    t.ties_before += 1;
                }
            }
        }
        if !flagged.contains(&e) {
            assert_ne!(exact, Sign::Negative, "{what} {e}");
        }
    }
    if rf.stages.undecided == 0 && rf.refused.is_empty() {
        // Every decision certified, so each equals the exact one: the same run.
        assert_eq!(rf.sequence, ex.report.sequence, "{what}");
        assert_eq!(rf.flips, ex.report.flips, "{what}");
        assert_eq!(mf, ex.mesh, "{what}");
        assert_eq!(lr, ex.lengths, "{what}");
        t.identical += 1;
    } else {
        t.with_undecided += 1;
    }
}

/// Exact Ptolemy flipping past its bit guard, against ℚ all the way: the fall-back happens
/// (counted), its enclosures contain the exact lengths, its certified signs are the exact
/// ones, and a run without undecided decisions is the exact run.
#[test]
fn t21_exact_flipping_after_fallback_agrees_with_exact_arithmetic() {
    use penner::algorithms::flip_to_delaunay::rational_bits;
    let mut t = FallbackTally::default();
    for i in case_seeds(160, 4_000) {
        let c = case(i);
        let opts = FlipOptions {
            record: true,
            order_seed: (i % 2 == 1).then_some(i),
            ..FlipOptions::default()
        };
        // The oracle run: ℚ all the way (no guard can be passed).
        let mut me = c.mesh.clone();
        let (re, oute) =
            flip_to_delaunay_exact(&mut me, c.lengths.clone(), u64::MAX, &opts).unwrap();
        assert!(re.all_certified_delaunay(), "{}", c.name);
        let ExactLengths::Exact(le) = oute else {
            panic!("{}: no fallback without a guard", c.name)
        };
        let start_bits = c.lengths.iter().map(rational_bits).max().unwrap();
        if re.max_bits <= start_bits {
            continue; // no flip grew a length: no guard falls between
        }
        let ex = ExactRun {
            report: re,
            mesh: me,
            lengths: le.iter().map(to_m).collect(),
        };
        // A guard below the inputs (the whole run on enclosures) and one halfway through
        // the growth (exact first, enclosures after some flip).
        for guard in [start_bits - 1, start_bits.midpoint(ex.report.max_bits)] {
            check_fell_back_run(&c, guard, &opts, &ex, &mut t);
        }
    }
    assert!(t.fell_back > t.whole_run && t.whole_run > 0, "{t:?}");
    assert!(t.identical > 0, "{t:?}");
    assert!(
        t.enclosed > 0 && t.wrong_rejected == t.enclosed && t.signs > 0,
        "{t:?}"
    );
    eprintln!("{t:?}");
}
