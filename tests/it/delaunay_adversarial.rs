//! The adversarial suite for certified Delaunay flipping (T21, B65, B66) on whole meshes.
//!
//! Families: regular `n`-gon fans and random triangulations of them, cyclic polygons with
//! rational chords, square grids, grids of 3-4-5 rectangles, honeycombs (the triangular
//! lattice without every third point) — every quadrilateral inside a polygon, a grid cell
//! or a hexagon is cocircular, `P = 0` — those families with every length perturbed by a
//! relative 10⁻²⁰ … 10⁻⁴⁰, lengths scaled by 10^±150, and marching-tetrahedra surfaces
//! (sphere, torus) whose vertices cluster 10⁻¹² cells from grid points (needles, caps,
//! rounded lengths that break the triangle inequality). Flipping runs at f64, Dd, MPFR
//! (256 bits) and exactly (Ptolemy over ℚ), with Euclidean and Ptolemy flips.
//!
//! Every certified run must stop without the cap, and the malachite D-form oracle
//! (`crate::delaunay::oracle`), evaluated on the exact values of the *returned* lengths,
//! must find Delaunay every edge the report does not list as undecided or refused, and
//! non-Delaunay every refused edge. Negative controls: the same check, on the result with
//! one certified edge made longer than its four neighbours together, reports that edge;
//! the inputs are not Delaunay for the oracle; perturbations that f64 rounding erases are
//! shown erased.
//!
//! Equilateral triangle grids are not ties: with all lengths 1 every interior edge has
//! `P = 2` (opposite angles 60° + 60°), so the triangular-lattice tie family is the
//! honeycomb, and the equilateral grid is checked separately (unique Delaunay
//! triangulation recovered from a scrambled start).

use crate::delaunay::{
    exact_values, exactly_strict, exactly_strict_face, oracle, oracle_non_delaunay, to_m,
};
use crate::meshgen::{
    honeycomb, lattice_incircle, lattice_orient, marching_tetrahedra, polygon_mesh,
    rational_cyclic_lengths, rect_lattice_grid, triangular_lattice_grid, LatticeMesh,
};
use crate::planar_gen::pow10;
use crate::support::{case_seeds, cases};
use malachite::rational::Rational as MRational;
use penner::algorithms::flip_to_delaunay::{
    flip_to_delaunay, flip_to_delaunay_exact, ExactLengths, FlipKind, FlipOptions, FlipReport,
    FlipToDelaunayError,
};
use penner::algorithms::naive::flip_to_delaunay_naive;
use penner::mesh::{Edge, Face, Mesh};
use penner::predicates::delaunay::{
    delaunay_sign_squared, exact_p, DelaunayError, Quad, QuadEdges,
};
use penner::scalar::{Dd, Mpfr, Precision, Real, Sign};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rug::float::Constant;
use rug::{Float, Rational};
use std::collections::BTreeMap;
use std::f64::consts::TAU;

const KINDS: [FlipKind; 2] = [FlipKind::Euclidean, FlipKind::Ptolemy];

/// Bits of the rounded tie metric of irrational families: its error (< 2⁻⁵¹² relative) is
/// far below every perturbation used.
const TIE_BITS: u32 = 512;

/// One adversarial input.
struct Family {
    /// Family class, for the tallies (`fan`, `rational fan`, `square`, `3-4-5`,
    /// `honeycomb`).
    class: &'static str,
    name: String,
    mesh: Mesh,
    /// The tie metric as rationals: exact for rational families, else rounded to
    /// [`TIE_BITS`] bits.
    exact: Vec<Rational>,
    /// Lengths a mesher computes in f64: distances of rotated f64 coordinates.
    coords_f64: Option<Vec<f64>>,
    /// Interior edges that are exact ties of the tie metric.
    ties: usize,
}

/// `√s` as a rational: exact when `s` is a perfect square, else rounded to [`TIE_BITS`].
fn sqrt_q(s: i64) -> Rational {
    let r = s.isqrt();
    if r * r == s {
        Rational::from(r)
    } else {
        Float::with_val(TIE_BITS, s).sqrt().to_rational().unwrap()
    }
}

/// The nearest f64 of a rational.
fn nearest(q: &Rational) -> f64 {
    Float::with_val(53, q).to_f64()
}

fn interior_edges(m: &Mesh) -> usize {
    m.edges().filter(|&e| QuadEdges::of(m, e).is_some()).count()
}

/// Vertex indices of the ends of `e`.
fn ends(m: &Mesh, e: Edge) -> (usize, usize) {
    let h = e.halfedge();
    (m.tail(h).idx(), m.tip(h).idx())
}

/// A family on lattice points: exact lengths from the integer squared lengths, f64
/// lengths from coordinates rotated by a random angle.
fn lattice_family(
    class: &'static str,
    name: String,
    lm: &LatticeMesh,
    rng: &mut ChaCha8Rng,
) -> Family {
    let mesh = lm.mesh();
    let exact = lm.squared_lengths(&mesh).into_iter().map(sqrt_q).collect();
    let pos = lm.positions(
        rng.gen_range(0.0..TAU),
        [rng.gen_range(-1.0..1.0), rng.gen_range(-1.0..1.0)],
    );
    let coords = mesh
        .edges()
        .map(|e| {
            let (a, b) = ends(&mesh, e);
            (pos[a][0] - pos[b][0]).hypot(pos[a][1] - pos[b][1])
        })
        .collect();
    let ties = lattice_ties(lm, &mesh);
    Family {
        class,
        name,
        mesh,
        exact,
        coords_f64: Some(coords),
        ties,
    }
}

/// Interior edges of a lattice mesh whose four points are cocircular (integer incircle
/// determinant zero).
fn lattice_ties(lm: &LatticeMesh, m: &Mesh) -> usize {
    m.edges()
        .filter(|&e| QuadEdges::of(m, e).is_some() && incircle_of(lm, m, e) == 0)
        .count()
}

/// The incircle determinant of the quadrilateral of interior edge `e`: `i, j, k` (face
/// `ijk`, counter-clockwise) and `l`; positive iff `l` is inside (`e` not Delaunay).
fn incircle_of(lm: &LatticeMesh, m: &Mesh, e: Edge) -> i128 {
    let [i, j, k, l] = m.quad_vertices(e).map(|v| v.0);
    lattice_incircle(lm, i, j, k, l)
}

/// The regular `n`-gon (circumradius 1) triangulated as a fan or at random.
fn regular_polygon(n: u32, fan: bool, seed: u64, rng: &mut ChaCha8Rng) -> Family {
    let mesh = polygon_mesh(n, fan, seed);
    let exact = mesh
        .edges()
        .map(|e| {
            let (a, b) = ends(&mesh, e);
            let k = a.abs_diff(b) as u32;
            let x = Float::with_val(TIE_BITS, Constant::Pi) * k / n;
            (x.sin() * 2u32).to_rational().unwrap()
        })
        .collect();
    let theta = rng.gen_range(0.0..TAU);
    let p: Vec<[f64; 2]> = (0..n)
        .map(|i| {
            let t = theta + TAU * f64::from(i) / f64::from(n);
            [t.cos(), t.sin()]
        })
        .collect();
    let coords = mesh
        .edges()
        .map(|e| {
            let (a, b) = ends(&mesh, e);
            (p[a][0] - p[b][0]).hypot(p[a][1] - p[b][1])
        })
        .collect();
    Family {
        class: "fan",
        name: format!("regular {n}-gon {}", if fan { "fan" } else { "random" }),
        ties: interior_edges(&mesh),
        mesh,
        exact,
        coords_f64: Some(coords),
    }
}

/// Every tie family at one seed.
fn tie_families(seed: u64) -> Vec<Family> {
    let mut rng = ChaCha8Rng::seed_from_u64(0xad00 + seed);
    let mut out = Vec::new();
    for n in [5u32, 6, 8, 12, 17, 31] {
        for fan in [true, false] {
            out.push(regular_polygon(n, fan, seed, &mut rng));
        }
    }
    for n in [7u32, 12] {
        for fan in [true, false] {
            let mesh = polygon_mesh(n, fan, seed);
            out.push(Family {
                class: "rational fan",
                name: format!(
                    "rational cyclic {n}-gon {}",
                    if fan { "fan" } else { "random" }
                ),
                exact: rational_cyclic_lengths(&mesh, n),
                ties: interior_edges(&mesh),
                mesh,
                coords_f64: None,
            });
        }
    }
    let sq = rect_lattice_grid(6, 1, 1, seed);
    out.push(lattice_family(
        "square",
        "unit square grid 6×6".into(),
        &sq,
        &mut rng,
    ));
    let r345 = rect_lattice_grid(5, 3, 4, seed);
    out.push(lattice_family(
        "3-4-5",
        "3×4 rectangle grid 5×5".into(),
        &r345,
        &mut rng,
    ));
    let hc = honeycomb(10, seed);
    out.push(lattice_family(
        "honeycomb",
        "honeycomb 10".into(),
        &hc,
        &mut rng,
    ));
    out
}

/// Counts over certified runs of one family class and backend.
#[derive(Clone, Copy, Debug, Default)]
struct Tally {
    runs: usize,
    flips: usize,
    nudged: usize,
    refused: usize,
    undecided: usize,
    /// Inputs the oracle finds not Delaunay.
    inputs_not_delaunay: usize,
    /// Runs whose check was shown to reject a corrupted result.
    controls: usize,
    /// Euclidean runs refused because a face is not a strict triangle (checked exactly).
    not_a_triangle: usize,
}

impl Tally {
    fn add(&mut self, r: &FlipReport) {
        self.runs += 1;
        self.flips += r.flips;
        self.nudged += r.nudged;
        self.refused += r.refused.len();
        self.undecided += r.undecided.len();
    }
}

/// What is wrong with a certified run.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Problem {
    HitCap,
    /// Not Delaunay for the oracle, yet not listed as undecided or refused.
    Unlisted(Edge),
    /// Refused (so certified non-Delaunay), yet Delaunay for the oracle.
    RefusedDelaunay(Edge),
}

/// Everything wrong with the run `r` that returned `(mesh, ex)`, `ex` the exact values of
/// the returned lengths.
fn problems(mesh: &Mesh, ex: &[MRational], r: &FlipReport) -> Vec<Problem> {
    let mut out = Vec::new();
    if r.hit_cap {
        out.push(Problem::HitCap);
    }
    let bad = oracle_non_delaunay(mesh, ex);
    for &e in &bad {
        if !r.undecided.contains(&e) && !r.refused.contains(&e) {
            out.push(Problem::Unlisted(e));
        }
    }
    for &e in &r.refused {
        if !bad.contains(&e) {
            out.push(Problem::RefusedDelaunay(e));
        }
    }
    out
}

/// Negative control of [`problems`]: the first interior edge the run certified, made
/// longer than its four neighbours together (then `P < 0`: `a² > (b+c)² > b² + c²` and
/// likewise for `d, e`), is reported.
fn control(what: &str, mesh: &Mesh, mut ex: Vec<MRational>, r: &FlipReport, t: &mut Tally) {
    let listed = |e: &Edge| r.undecided.contains(e) || r.refused.contains(e);
    let Some(q) = mesh
        .edges()
        .filter(|e| !listed(e))
        .find_map(|e| QuadEdges::of(mesh, e))
    else {
        return;
    };
    let [_, b, c, d, e] = q.lengths(&ex).to_array().map(Clone::clone);
    ex[q.edge.idx()] = b + c + d + e;
    let p = problems(mesh, &ex, r);
    assert!(
        p.contains(&Problem::Unlisted(q.edge)),
        "{what}: corrupted {} not reported: {p:?}",
        q.edge
    );
    t.controls += 1;
}

/// The first face of `mesh` whose exact side lengths `ex` are not a strict triangle
/// (malachite).
fn first_non_triangle(mesh: &Mesh, ex: &[MRational]) -> Option<Face> {
    mesh.faces().find(|&f| !exactly_strict_face(mesh, ex, f))
}

/// Certified flipping of `(mesh, l)` at backend `T`, checked by [`problems`] (and its
/// negative control); χ and the boundary are unchanged. Euclidean flipping refuses a
/// metric with a face that is not a strict triangle: `None` then, after checking that the
/// refused face is the first one exact arithmetic finds broken (and that no face is broken
/// when it does not refuse).
fn certified_or_refused<T: Real>(
    what: &str,
    mesh: &Mesh,
    l: &[T],
    kind: FlipKind,
    t: &mut Tally,
) -> Option<(Mesh, FlipReport)> {
    let ex_in = exact_values(l);
    let broken = first_non_triangle(mesh, &ex_in);
    let (mut m, mut out) = (mesh.clone(), l.to_vec());
    let r = match flip_to_delaunay(&mut m, &mut out, kind, &FlipOptions::default()) {
        Err(FlipToDelaunayError::Lengths(DelaunayError::NotATriangle { face })) => {
            assert_eq!(kind, FlipKind::Euclidean, "{what}");
            assert_eq!(Some(face), broken, "{what}: refused face");
            t.not_a_triangle += 1;
            return None;
        }
        other => other.unwrap(),
    };
    if kind == FlipKind::Euclidean {
        assert_eq!(broken, None, "{what}: a broken face was not refused");
    }
    t.inputs_not_delaunay += usize::from(!oracle_non_delaunay(mesh, &ex_in).is_empty());
    let ex = exact_values(&out);
    let p = problems(&m, &ex, &r);
    assert!(p.is_empty(), "{what} {kind:?}: {p:?}; {r:?}");
    assert_eq!(m.euler_characteristic(), mesh.euler_characteristic());
    assert_eq!(m.n_boundary_loops(), mesh.n_boundary_loops());
    control(what, &m, ex, &r, t);
    t.add(&r);
    Some((m, r))
}

/// [`certified_or_refused`] on a metric whose faces are all strict triangles.
fn certified<T: Real>(
    what: &str,
    mesh: &Mesh,
    l: &[T],
    kind: FlipKind,
    t: &mut Tally,
) -> (Mesh, FlipReport) {
    certified_or_refused(what, mesh, l, kind, t)
        .unwrap_or_else(|| panic!("{what} {kind:?}: refused as not a triangle"))
}

/// Exact Ptolemy flipping over ℚ (no fall-back), checked like [`certified`].
fn certified_exact(what: &str, mesh: &Mesh, l: &[Rational], t: &mut Tally) -> (Mesh, FlipReport) {
    let ex_in: Vec<MRational> = l.iter().map(to_m).collect();
    t.inputs_not_delaunay += usize::from(!oracle_non_delaunay(mesh, &ex_in).is_empty());
    let mut m = mesh.clone();
    let (r, out) =
        flip_to_delaunay_exact(&mut m, l.to_vec(), 1 << 16, &FlipOptions::default()).unwrap();
    assert_eq!(r.fell_back_after, None, "{what}: {r:?}");
    let ExactLengths::Exact(out) = out else {
        panic!("{what}: no fall-back, yet enclosures")
    };
    let ex: Vec<MRational> = out.iter().map(to_m).collect();
    let p = problems(&m, &ex, &r);
    assert!(p.is_empty(), "{what} exact: {p:?}; {r:?}");
    control(what, &m, ex, &r, t);
    t.add(&r);
    (m, r)
}

/// The f64 inputs of a tie family: the tie metric rounded to nearest, scaled by 10^±150
/// and rounded, and the distances of f64 coordinates.
fn f64_variants(f: &Family) -> Vec<(&'static str, Vec<f64>)> {
    let scaled = |k: i32| -> Vec<f64> {
        let s = pow10(k);
        f.exact
            .iter()
            .map(|q| nearest(&Rational::from(q * &s)))
            .collect()
    };
    let mut v = vec![
        ("rounded", f.exact.iter().map(nearest).collect()),
        ("1e-150", scaled(-150)),
        ("1e150", scaled(150)),
    ];
    if let Some(c) = &f.coords_f64 {
        v.push(("coords", c.clone()));
    }
    v
}

fn print_tallies(test: &str, tallies: &BTreeMap<String, Tally>) {
    for (k, t) in tallies {
        eprintln!("{test}: {k}: {t:?}");
    }
}

/// Tie families at f64 (rounded, scaled by 10^±150, from f64 coordinates) and Dd, both flip
/// kinds: terminates, the oracle agrees with every certified edge, and the check rejects a
/// corrupted result. Negative control: rounding breaks the ties, so inputs of every class
/// but the 3-4-5 grid (integers, exact in f64) are not Delaunay for the oracle.
#[test]
fn t21_adversarial_tie_families_f64_dd_and_scaled() {
    let mut tallies: BTreeMap<String, Tally> = BTreeMap::new();
    for seed in case_seeds(1, 6) {
        for f in tie_families(seed) {
            let variants = f64_variants(&f);
            let dd: Vec<Dd> = f
                .exact
                .iter()
                .map(|q| <Dd as Real>::from_rational(q, ()))
                .collect();
            for kind in KINDS {
                for (v, l) in &variants {
                    let t = tallies.entry(format!("{} f64 {v}", f.class)).or_default();
                    certified(&format!("{} {v}", f.name), &f.mesh, l, kind, t);
                }
                let t = tallies.entry(format!("{} dd", f.class)).or_default();
                certified(&format!("{} dd", f.name), &f.mesh, &dd, kind, t);
            }
        }
    }
    print_tallies("tie families", &tallies);
    for (k, t) in &tallies {
        assert!(t.runs > 0 && t.controls == t.runs, "{k}: {t:?}");
    }
    // The nudge of B65 ran (rounded new diagonals on the wrong side of a tie), and the
    // oracle accepted its results.
    assert!(tallies.values().map(|t| t.nudged).sum::<usize>() > 0);
    // Integer lengths: the 3-4-5 ties stay exact at f64 and Dd; nothing to flip.
    for k in ["3-4-5 f64 rounded", "3-4-5 dd"] {
        let t = tallies[k];
        assert_eq!((t.flips, t.inputs_not_delaunay), (0, 0), "{k}: {t:?}");
    }
    // Over its f64 inputs every class has ties broken to the wrong side (a lattice rounded
    // uniformly, every cell alike, may have none in one variant).
    for class in ["fan", "rational fan", "square", "3-4-5", "honeycomb"] {
        let prefix = format!("{class} f64 ");
        let (bad, flips) = tallies
            .iter()
            .filter(|(k, _)| k.starts_with(&prefix))
            .fold((0, 0), |(b, f), (_, t)| {
                (b + t.inputs_not_delaunay, f + t.flips)
            });
        assert!(
            bad > 0 && flips > 0,
            "{class}: {bad} inputs not Delaunay, {flips} flips"
        );
    }
}

/// The signs the oracle gives the interior edges (`None` elsewhere).
fn oracle_signs(mesh: &Mesh, ex: &[MRational]) -> Vec<Option<Sign>> {
    mesh.edges()
        .map(|e| QuadEdges::of(mesh, e).map(|q| oracle(q.lengths(ex).to_array())))
        .collect()
}

/// The exact ties themselves. Rational families (cyclic polygons with rational chords,
/// 3-4-5 grids): the oracle finds every expected tie `P = 0` and exact Ptolemy flipping in
/// ℚ flips nothing; lattice families with irrational lengths (square grid, honeycomb):
/// the squared-length sign (B63) is the sign of the integer incircle determinant of the
/// lattice points on every interior edge, zero exactly on the ties. Negative controls: a
/// tie perturbed by ±10⁻³⁰ relative is decided and flipped (resp. kept) as the oracle
/// says; the squared-length sign of a tie's diagonal stretched (shrunk) by 10⁻³⁰ is
/// negative (positive).
#[test]
fn t21_adversarial_exact_ties_in_rationals_and_squared_lengths() {
    let opts = FlipOptions::default();
    let (mut rational, mut lattice, mut controls) = (0, 0, 0);
    for seed in case_seeds(1, 6) {
        for f in tie_families(seed) {
            if f.class == "fan" {
                continue; // irrational chords (squared forms rational only for n = 4, 6)
            }
            let ex: Vec<MRational> = f.exact.iter().map(to_m).collect();
            let signs = oracle_signs(&f.mesh, &ex);
            let zeros = signs.iter().filter(|s| **s == Some(Sign::Zero)).count();
            if f.class == "rational fan" || f.class == "3-4-5" {
                rational += 1;
                assert_eq!(zeros, f.ties, "{}", f.name);
                assert!(!signs.contains(&Some(Sign::Negative)), "{}", f.name);
                let mut m = f.mesh.clone();
                let (r, _) =
                    flip_to_delaunay_exact(&mut m, f.exact.clone(), 1 << 16, &opts).unwrap();
                assert!(r.all_certified_delaunay(), "{}: {r:?}", f.name);
                assert_eq!(r.flips, 0, "{}", f.name);
                // Negative control: one tie stretched or shrunk by 10⁻³⁰ relative.
                let tie = f
                    .mesh
                    .edges()
                    .find(|e| signs[e.idx()] == Some(Sign::Zero))
                    .unwrap();
                for sgn in [1, -1] {
                    let mut l = f.exact.clone();
                    l[tie.idx()] *= Rational::from(1) + Rational::from(sgn) * pow10(-30);
                    let s = oracle_signs(&f.mesh, &l.iter().map(to_m).collect::<Vec<_>>());
                    let want = if sgn > 0 {
                        Sign::Negative
                    } else {
                        Sign::Positive
                    };
                    assert_eq!(s[tie.idx()], Some(want), "{}", f.name);
                    // The changed length is also a side of its neighbours' quadrilaterals
                    // (in a polygon), which then may flip too: flips happen iff the oracle
                    // finds an edge not Delaunay, and the result is checked as usual.
                    let (_, r) = certified_exact(&f.name, &f.mesh, &l, &mut Tally::default());
                    assert_eq!(r.flips > 0, s.contains(&Some(Sign::Negative)), "{}", f.name);
                    if sgn > 0 {
                        assert!(r.flips > 0, "{}: {r:?}", f.name);
                    }
                    controls += 1;
                }
            }
        }
        let lattices = [
            ("square", rect_lattice_grid(6, 1, 1, seed)),
            ("3-4-5", rect_lattice_grid(5, 3, 4, seed)),
            ("honeycomb", honeycomb(10, seed)),
            ("equilateral", triangular_lattice_grid(6)),
        ];
        for (name, lm) in &lattices {
            let m = lm.mesh();
            let sq: Vec<Rational> = lm
                .squared_lengths(&m)
                .into_iter()
                .map(Rational::from)
                .collect();
            let mut zeros = 0;
            for q in m.edges().filter_map(|e| QuadEdges::of(&m, e)) {
                let s = delaunay_sign_squared(q.lengths(&sq));
                let inc = incircle_of(lm, &m, q.edge);
                assert_eq!(s, Sign::of_ordering(0.cmp(&inc)), "{name} {}", q.edge);
                if s == Sign::Zero {
                    zeros += 1;
                    // Negative control: the tie's diagonal stretched / shrunk.
                    for (sgn, want) in [(1, Sign::Negative), (-1, Sign::Positive)] {
                        let a = q.lengths(&sq).ij.clone() * (1 + Rational::from(sgn) * pow10(-30));
                        let mut p = q.lengths(&sq);
                        p.ij = &a;
                        assert_eq!(delaunay_sign_squared(p), want, "{name}");
                        controls += 1;
                    }
                }
            }
            let expected = match *name {
                "square" => 36,
                "3-4-5" => 25,
                "honeycomb" => 3 * m.n_faces() / 4,
                _ => 0,
            };
            assert_eq!(zeros, expected, "{name}");
            lattice += 1;
        }
    }
    assert!(rational > 0 && lattice > 0 && controls > 0);
}

/// A relative perturbation `1 + r·10⁻ᵏ` per edge, `r` uniform in (−1, 1) (53 random bits).
fn perturbed(l: &[Rational], k: i32, rng: &mut ChaCha8Rng) -> Vec<Rational> {
    let eps = pow10(-k);
    l.iter()
        .map(|q| {
            let r = Rational::from_f64(rng.gen_range(-1.0..1.0)).unwrap();
            q * (1 + r * &eps)
        })
        .collect()
}

/// Whole tie meshes with every length perturbed by a relative 10⁻ᵏ, `k` = 20, 30, 40
/// (every 5 from 20 to 40 under `PENNER_LONG`), as exact rationals (irrational ties first
/// rounded to 512 bits, 10⁻¹⁵⁴, far below the perturbation): exact Ptolemy flipping over
/// ℚ, MPFR at 256 bits and Dd (`k ≤ 30`) with both flip kinds, every run checked against
/// the oracle. The perturbation is really represented: every tie is broken, and the oracle
/// signs of the input at 256 bits (and at Dd for `k ≤ 25`; counted for `k = 30`) are those
/// of the exact perturbed lengths on every edge; Ptolemy flipping at 256 bits reaches the
/// triangulation exact flipping in ℚ reaches (counted at Dd). Negative controls: inputs
/// not Delaunay for the oracle in every class; rounded to f64, the perturbation of the
/// integer 3-4-5 lengths vanishes (every length rounds back to its integer).
#[test]
fn t21_adversarial_meshes_perturbed_1e20_to_1e40_exact_mpfr_dd() {
    let p256 = Precision::new(256).unwrap();
    let mut tallies: BTreeMap<String, Tally> = BTreeMap::new();
    let (mut dd_agree, mut dd_edges, mut erased) = (0, 0, 0);
    let (mut dd_runs, mut dd_same) = (0, 0);
    for seed in case_seeds(1, 4) {
        for (fi, f) in tie_families(seed).into_iter().enumerate() {
            for k in (20..=40).step_by(cases(10, 5)) {
                let mut rng =
                    ChaCha8Rng::seed_from_u64((seed << 16) | ((fi as u64) << 8) | k as u64);
                let l = perturbed(&f.exact, k, &mut rng);
                let what = format!("{} 1e-{k}", f.name);
                let ex_in: Vec<MRational> = l.iter().map(to_m).collect();
                let signs = oracle_signs(&f.mesh, &ex_in);
                // Every tie is broken: no interior edge has P = 0.
                assert!(!signs.contains(&Some(Sign::Zero)), "{what}: a tie survived");
                if f.class == "3-4-5" {
                    assert!(l
                        .iter()
                        .zip(&f.exact)
                        .all(|(p, q)| nearest(p) == nearest(q)));
                    erased += 1;
                }
                let (m_exact, _) = certified_exact(
                    &what,
                    &f.mesh,
                    &l,
                    tallies.entry(format!("{} exact", f.class)).or_default(),
                );
                let mp: Vec<Mpfr> = l
                    .iter()
                    .map(|q| <Mpfr as Real>::from_rational(q, p256))
                    .collect();
                assert_eq!(
                    oracle_signs(&f.mesh, &exact_values(&mp)),
                    signs,
                    "{what}: 256 bits"
                );
                for kind in KINDS {
                    let t = tallies.entry(format!("{} mpfr-256", f.class)).or_default();
                    let (m, _) = certified(&what, &f.mesh, &mp, kind, t);
                    // Every decision certified, 2⁻²⁵⁶ rounding far below the perturbation:
                    // Ptolemy flips at 256 bits reach the triangulation of ℚ.
                    if kind == FlipKind::Ptolemy {
                        assert_eq!(m, m_exact, "{what}: 256 bits vs ℚ");
                    }
                }
                if k <= 30 {
                    let dd: Vec<Dd> = l
                        .iter()
                        .map(|q| <Dd as Real>::from_rational(q, ()))
                        .collect();
                    let sd = oracle_signs(&f.mesh, &exact_values(&dd));
                    for (a, b) in sd.iter().zip(&signs) {
                        if a.is_some() {
                            dd_edges += 1;
                            dd_agree += usize::from(a == b);
                        }
                    }
                    if k <= 25 {
                        assert_eq!(sd, signs, "{what}: dd");
                    }
                    for kind in KINDS {
                        let t = tallies.entry(format!("{} dd", f.class)).or_default();
                        let (m, _) = certified(&what, &f.mesh, &dd, kind, t);
                        if kind == FlipKind::Ptolemy {
                            dd_runs += 1;
                            dd_same += usize::from(m == m_exact);
                        }
                    }
                }
            }
        }
    }
    print_tallies("perturbed", &tallies);
    eprintln!("perturbed: dd signs agree with exact on {dd_agree} of {dd_edges} edges");
    eprintln!(
        "perturbed: dd Ptolemy reaches the triangulation of ℚ in {dd_same} of {dd_runs} runs"
    );
    for (k, t) in &tallies {
        assert!(t.runs > 0 && t.controls == t.runs, "{k}: {t:?}");
        assert!(t.inputs_not_delaunay > 0 && t.flips > 0, "{k}: {t:?}");
    }
    assert!(erased > 0);
}

/// A marching-tetrahedra surface with lengths: the distances of its f64 vertices, exactly
/// computed and rounded to f64 (nearest) and to Dd.
struct Sliver {
    /// `marching-tets 1e-12` or `marching-tets 1e-7` (the snapped distance).
    class: String,
    name: String,
    mesh: Mesh,
    f64s: Vec<f64>,
    dds: Vec<Dd>,
    /// Mean edge length, for the sliver statistics.
    mean: f64,
}

fn sliver_surfaces(seed: u64) -> Vec<Sliver> {
    let mut rng = ChaCha8Rng::seed_from_u64(0x5117 + seed);
    let c: [f64; 3] = std::array::from_fn(|_| rng.gen_range(-0.05..0.05));
    let r = rng.gen_range(0.8..0.95);
    let sphere = move |p: [f64; 3]| {
        (p[0] - c[0]).powi(2) + (p[1] - c[1]).powi(2) + (p[2] - c[2]).powi(2) - r * r
    };
    let torus = move |p: [f64; 3]| {
        let (x, y, z) = (p[0] - c[0], p[1] - c[1], p[2] - c[2]);
        (x.hypot(y) - 0.75).powi(2) + z * z - 0.32f64.powi(2)
    };
    let (n_s, n_t) = (8u32, 10u32);
    let mut surfaces = Vec::new();
    for tiny in [1e-12, 1e-7] {
        let (hs, ht) = (2.4 / f64::from(n_s), 2.4 / f64::from(n_t));
        let s = marching_tetrahedra(n_s, 1.2, &sphere, 0.35 * hs, tiny);
        surfaces.push((tiny, "sphere", s));
        let t = marching_tetrahedra(n_t, 1.2, &torus, 0.12 * ht, tiny);
        surfaces.push((tiny, "torus", t));
    }
    surfaces
        .into_iter()
        .map(|(tiny, name, e)| {
            let mesh = e.mesh();
            let exact: Vec<Float> = mesh
                .edges()
                .map(|x| {
                    let (a, b) = ends(&mesh, x);
                    let mut s = Rational::new();
                    for d in 0..3 {
                        let dx = Rational::from_f64(e.pos[a][d]).unwrap()
                            - Rational::from_f64(e.pos[b][d]).unwrap();
                        s += dx.clone() * dx;
                    }
                    Float::with_val(256, &s).sqrt()
                })
                .collect();
            let f64s: Vec<f64> = exact.iter().map(Float::to_f64).collect();
            let dds = exact
                .iter()
                .map(|x| <Dd as Real>::from_rational(&x.to_rational().unwrap(), ()))
                .collect();
            let mean = f64s.iter().sum::<f64>() / f64s.len() as f64;
            Sliver {
                class: format!("marching-tets {tiny:e}"),
                name: format!("{name} {tiny:e} seed {seed}"),
                mesh,
                f64s,
                dds,
                mean,
            }
        })
        .collect()
}

/// Faces of `s` that are needles (shortest side below 10⁻⁹ of the longest) and faces whose
/// f64 lengths are not a strict triangle (exact comparison).
fn sliver_stats(s: &Sliver) -> (usize, usize) {
    let (mut needles, mut broken) = (0, 0);
    for f in s.mesh.faces() {
        let l = s.mesh.face_halfedges(f).map(|h| s.f64s[h.edge().idx()]);
        let (lo, hi) = (l[0].min(l[1]).min(l[2]), l[0].max(l[1]).max(l[2]));
        needles += usize::from(lo < 1e-9 * hi);
        let q = l.map(|x| MRational::try_from(x).unwrap());
        broken += usize::from(!exactly_strict(q.each_ref()));
    }
    (needles, broken)
}

/// Marching-tetrahedra surfaces (sphere, torus) with vertices snapped to 10⁻¹² (and 10⁻⁷)
/// cells from grid points: edges 10⁻¹² of the mean, needles, caps, and at 10⁻¹² f64
/// lengths that break the triangle inequality. Certified flipping at f64 and Dd, both flip
/// kinds: terminates, the oracle agrees with every certified edge, every other edge is
/// listed; Euclidean flipping refuses exactly the metrics with a broken face, naming the
/// first (checked in malachite) — all 10⁻¹² surfaces at f64, none at Dd or 10⁻⁷. Negative
/// controls: the inputs are not Delaunay; corrupted results are rejected.
#[test]
fn t21_adversarial_marching_tetrahedra_slivers_f64_and_dd() {
    let mut tallies: BTreeMap<String, Tally> = BTreeMap::new();
    let (mut tiny, mut needles, mut broken) = (0, 0, 0);
    for seed in case_seeds(1, 8) {
        for s in sliver_surfaces(seed) {
            tiny += s.f64s.iter().filter(|&&x| x < 1e-10 * s.mean).count();
            let (n, b) = sliver_stats(&s);
            eprintln!(
                "{}: {} faces, {n} needles, {b} broken at f64",
                s.name,
                s.mesh.n_faces()
            );
            needles += n;
            broken += b;
            for kind in KINDS {
                let t = tallies
                    .entry(format!("{} {kind:?} f64", s.class))
                    .or_default();
                certified_or_refused(&s.name, &s.mesh, &s.f64s, kind, t);
                let t = tallies
                    .entry(format!("{} {kind:?} dd", s.class))
                    .or_default();
                certified_or_refused(&s.name, &s.mesh, &s.dds, kind, t);
            }
        }
    }
    print_tallies("slivers", &tallies);
    eprintln!("slivers: {tiny} edges below 1e-10 of the mean, {needles} needles, {broken} faces not strict at f64");
    assert!(
        tiny > 0 && needles > 0 && broken > 0,
        "the surfaces have no slivers"
    );
    let refused = "marching-tets 1e-12 Euclidean f64";
    assert!(tallies[refused].not_a_triangle > 0 && tallies[refused].runs == 0);
    for (k, t) in tallies.iter().filter(|(k, _)| *k != refused) {
        assert!(t.runs > 0 && t.controls == t.runs, "{k}: {t:?}");
        assert_eq!(t.not_a_triangle, 0, "{k}: {t:?}");
        assert_eq!(t.inputs_not_delaunay, t.runs, "{k}: {t:?}");
        assert!(t.flips > 0, "{k}: {t:?}");
    }
}

/// What naive f64 flipping did to one input.
#[derive(Clone, Copy, Debug, Default)]
struct NaiveTally {
    runs: usize,
    /// Runs with at least one error below.
    erring_runs: usize,
    /// Edges the oracle finds not Delaunay in the result.
    bad_edges: usize,
    /// Non-finite lengths in the result (NaN from a Euclidean flip of a broken triangle).
    non_finite: usize,
    /// Runs stopped by the cap (a flip loop).
    cap_hits: usize,
}

fn naive_run(mesh: &Mesh, l: &[f64], kind: FlipKind, t: &mut NaiveTally) {
    let (mut m, mut out) = (mesh.clone(), l.to_vec());
    let cap = 64 * m.n_edges() + 1024;
    let r = flip_to_delaunay_naive(&mut m, &mut out, kind, cap);
    let ex: Vec<Option<MRational>> = out
        .iter()
        .map(|&x| (x.is_finite() && x > 0.0).then(|| MRational::try_from(x).unwrap()))
        .collect();
    let non_finite = ex.iter().filter(|x| x.is_none()).count();
    let bad = m
        .edges()
        .filter_map(|e| QuadEdges::of(&m, e))
        .filter(|q| {
            let Quad { ij, jk, ki, il, lj } = q.lengths(&ex);
            match (ij, jk, ki, il, lj) {
                (Some(a), Some(b), Some(c), Some(d), Some(e)) => {
                    oracle([a, b, c, d, e]) == Sign::Negative
                }
                _ => false,
            }
        })
        .count();
    t.runs += 1;
    t.bad_edges += bad;
    t.non_finite += non_finite;
    t.cap_hits += usize::from(r.hit_cap);
    t.erring_runs += usize::from(bad > 0 || non_finite > 0 || r.hit_cap);
}

/// Naive f64 flipping (raw sign of `P`, `algorithms::naive`) on the f64 inputs of the
/// suite, beside certified flipping on the same inputs (checked as in the other tests).
/// The naive result is judged by the same oracle: edges left non-Delaunay, non-finite
/// lengths, cap hits (a flip loop). Where it errs is asserted from these counts, not
/// assumed.
///
/// On the default inputs it errs, with both flip kinds, on regular and rational fans
/// (correctly rounded chords, f64 coordinates, 10⁻¹⁵ perturbations), honeycombs and square
/// grids from f64 coordinates, the 3-4-5 grid perturbed by 10⁻¹⁵ (near-tie signs wrong);
/// on fans, rational fans and honeycombs scaled by 10⁻¹⁵⁰ (`P` underflows to 0: nothing is
/// flipped) or 10¹⁵⁰ (`P` overflows: wrong flips, and on fans flip loops stopped by the
/// cap) and the 3-4-5 grid at 10¹⁵⁰; and with Euclidean flips on the 10⁻¹²
/// marching-tetrahedra surfaces (NaN lengths from broken triangles, flip loops).
///
/// It does not err on: square grids and honeycombs with correctly rounded lengths (every
/// cell rounds alike, and the flips it makes are right), square grids scaled by 10^±150,
/// the 3-4-5 grid with exact integer lengths (`P = 0` exactly in f64; asserted) or at
/// 10⁻¹⁵⁰, either flip kind on the 10⁻⁷ marching-tetrahedra surfaces, the equilateral grid
/// (`t21_equilateral_grids_are_strictly_delaunay_not_ties`, asserted). On the default
/// inputs it also made no error on square grids perturbed by 10⁻¹⁵, the 3-4-5 grid from
/// coordinates, and with Ptolemy flips on the 10⁻¹² surfaces, but does under
/// `PENNER_LONG` (2–3 of 6, 4–5 of 6, 2 of 12 runs). Counts are printed.
#[test]
fn t21_negative_control_naive_f64_flipping_errs_on_adversarial_families() {
    let mut naive: BTreeMap<String, NaiveTally> = BTreeMap::new();
    let mut cert: BTreeMap<String, Tally> = BTreeMap::new();
    let mut run = |class: &str, v: &str, name: &str, mesh: &Mesh, l: &[f64]| {
        for kind in KINDS {
            let key = format!("{class} {v} {kind:?}");
            naive_run(mesh, l, kind, naive.entry(key.clone()).or_default());
            certified_or_refused(name, mesh, l, kind, cert.entry(key).or_default());
        }
    };
    for seed in case_seeds(1, 6) {
        for f in tie_families(seed) {
            let mut variants = f64_variants(&f);
            let mut rng = ChaCha8Rng::seed_from_u64(0x15 + seed);
            let p15 = perturbed(&f.exact, 15, &mut rng);
            variants.push(("1e-15", p15.iter().map(nearest).collect()));
            for (v, l) in &variants {
                run(f.class, v, &f.name, &f.mesh, l);
            }
        }
        for s in sliver_surfaces(seed) {
            run(&s.class, "f64", &s.name, &s.mesh, &s.f64s);
        }
    }
    for (k, t) in &naive {
        eprintln!("naive: {k}: {t:?}");
    }
    print_tallies("certified", &cert);
    // Certified flipping on the same inputs: checked in `certified_or_refused`; it made
    // no error anywhere, and ran on every input but the broken-triangle ones.
    assert!(cert.values().all(|t| t.runs + t.not_a_triangle > 0));
    let errors = |prefix: &str, kind: FlipKind| {
        let suffix = format!(" {kind:?}");
        naive
            .iter()
            .filter(|(k, _)| k.starts_with(prefix) && k.ends_with(&suffix))
            .map(|(_, t)| t.bad_edges + t.non_finite + t.cap_hits)
            .sum::<usize>()
    };
    for kind in KINDS {
        // Wrong signs at near-ties (no overflow involved).
        for prefix in [
            "fan rounded",
            "fan coords",
            "fan 1e-15",
            "rational fan rounded",
            "rational fan 1e-15",
            "honeycomb coords",
            "square coords",
        ] {
            assert!(
                errors(prefix, kind) > 0,
                "naive {prefix} {kind:?} did not err"
            );
        }
        // Underflow and overflow of the raw P.
        for class in ["fan", "rational fan", "honeycomb"] {
            for v in ["1e-150", "1e150"] {
                let prefix = format!("{class} {v}");
                assert!(
                    errors(&prefix, kind) > 0,
                    "naive {prefix} {kind:?} did not err"
                );
            }
        }
        assert!(errors("3-4-5 1e150", kind) > 0 && errors("3-4-5 1e-15", kind) > 0);
        assert!(
            errors("fan 1e150", kind) > 0 && naive[&format!("fan 1e150 {kind:?}")].cap_hits > 0
        );
        // Exact integer ties: the raw P is exactly 0, and naive flipping is right.
        assert_eq!(errors("3-4-5 rounded", kind), 0);
    }
    let mt = naive["marching-tets 1e-12 f64 Euclidean"];
    assert!(mt.non_finite > 0 && mt.cap_hits > 0, "{mt:?}");
}

/// Equilateral triangle grids are not ties: with all lengths 1, `P = 2` exactly on every
/// interior edge (oracle positive, the library's exact `P` is 2). Started from the lattice
/// scrambled by random planar flips (negative control: then not Delaunay for the oracle),
/// Euclidean flipping at f64 and Dd recovers exactly the equilateral triangulation (the
/// unique Delaunay triangulation, no ties); Ptolemy flipping is certified and checked by
/// the oracle.
#[test]
fn t21_equilateral_grids_are_strictly_delaunay_not_ties() {
    let lm = triangular_lattice_grid(8);
    let m0 = lm.mesh();
    let ones = vec![MRational::from(1); m0.n_edges()];
    let one = Rational::from(1);
    for q in m0.edges().filter_map(|e| QuadEdges::of(&m0, e)) {
        assert_eq!(oracle(q.lengths(&ones).to_array()), Sign::Positive);
        assert_eq!(exact_p([&one; 5]), 2);
    }
    let pairs = |m: &Mesh| {
        let mut v: Vec<(usize, usize)> = m
            .edges()
            .map(|e| {
                let (a, b) = ends(m, e);
                (a.min(b), a.max(b))
            })
            .collect();
        v.sort_unstable();
        v
    };
    let mut tallies: BTreeMap<String, Tally> = BTreeMap::new();
    let mut naive = NaiveTally::default();
    for seed in case_seeds(3, 30) {
        let mut rng = ChaCha8Rng::seed_from_u64(0xe9 + seed);
        let mut m = m0.clone();
        let mut flipped = 0;
        for _ in 0..200 {
            let e = Edge(rng.gen_range(0..m.n_edges() as u32));
            let Some(q) = QuadEdges::of(&m, e) else {
                continue;
            };
            let [i, j, k, l] = m.quad_vertices(e).map(|v| v.0);
            // A planar flip: i and j strictly on opposite sides of kl.
            if lattice_orient(&lm, k, l, i).signum() * lattice_orient(&lm, k, l, j).signum() < 0 {
                m.flip(q.edge).unwrap();
                flipped += 1;
            }
        }
        let sq = lm.squared_lengths(&m);
        let exact: Vec<Rational> = sq.into_iter().map(sqrt_q).collect();
        let f: Vec<f64> = exact.iter().map(nearest).collect();
        let dd: Vec<Dd> = exact
            .iter()
            .map(|q| <Dd as Real>::from_rational(q, ()))
            .collect();
        assert!(flipped > 0 && pairs(&m) != pairs(&m0));
        assert!(!oracle_non_delaunay(&m, &exact_values(&f)).is_empty());
        for kind in KINDS {
            let t = tallies.entry(format!("{kind:?} f64")).or_default();
            let (mf, _) = certified("scrambled equilateral", &m, &f, kind, t);
            let t = tallies.entry(format!("{kind:?} dd")).or_default();
            let (md, _) = certified("scrambled equilateral", &m, &dd, kind, t);
            if kind == FlipKind::Euclidean {
                assert_eq!(pairs(&mf), pairs(&m0), "seed {seed} f64");
                assert_eq!(pairs(&md), pairs(&m0), "seed {seed} dd");
            }
            naive_run(&m, &f, kind, &mut naive);
        }
    }
    print_tallies("equilateral", &tallies);
    eprintln!("equilateral: naive {naive:?}");
    // Control of the naive tally: on these well-separated signs naive f64 flipping is
    // right, and the tally counts no error.
    assert!(naive.runs > 0 && naive.erring_runs == 0, "{naive:?}");
    for (k, t) in &tallies {
        assert!(t.flips > 0 && t.controls == t.runs, "{k}: {t:?}");
    }
}
