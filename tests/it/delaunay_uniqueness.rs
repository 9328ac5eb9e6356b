//! T22 on random surfaces of genus 0–3: different flip orders reach the same triangulation
//! up to renumbering of edges and faces (a vertex-fixing isomorphism of the gluing).

use crate::support::{case_seeds, cases};
use penner::algorithms::flip_to_delaunay::{flip_to_delaunay, FlipKind, FlipOptions};
use penner::mesh::Mesh;
use penner::strategies::ArbSurface;
use penner::theorems::t22_delaunay_uniqueness::{check_delaunay_uniqueness, same_triangulation};
use penner::theorems::Settings;

/// The Delaunay triangulation of `(mesh, l)` reached with visit order `seed`.
fn delaunay(mesh: &Mesh, l: &[f64], kind: FlipKind, seed: u64) -> (Mesh, usize) {
    let (mut m, mut l) = (mesh.clone(), l.to_vec());
    let opts = FlipOptions {
        order_seed: Some(seed),
        ..FlipOptions::default()
    };
    let report = flip_to_delaunay(&mut m, &mut l, kind, &opts).expect("valid surface");
    (m, report.flips)
}

#[test]
fn t22_flip_orders_reach_the_same_triangulation_on_random_surfaces_of_genus_0_to_3() {
    let mut flipped = 0;
    let mut controls = 0;
    for seed in case_seeds(60, 2000) {
        let genus = (seed % 4) as u32;
        let s = ArbSurface::new(genus, 4 + (seed % 9) as u32, seed).surface;
        let l: Vec<f64> = s.lengths(());
        for kind in [FlipKind::Euclidean, FlipKind::Ptolemy] {
            let v = check_delaunay_uniqueness(&s.mesh, &l, kind, &[1, 2, 3], &Settings::default());
            assert!(v.holds(), "{} (genus {genus}) {kind:?}: {v:?}", s.name);
            // Negative controls for the comparison itself: the start (when any flip was
            // needed) and the result with one more flip are other triangulations.
            let (d, flips) = delaunay(&s.mesh, &l, kind, 1);
            if flips > 0 {
                flipped += 1;
                assert!(!same_triangulation(&s.mesh, &d), "{}", s.name);
            }
            // Flipping an edge ij whose new diagonal kl joins another vertex pair changes
            // the multiset of edge endpoints, which every vertex-fixing isomorphism keeps.
            let pair = |m: &Mesh, e: penner::mesh::Edge| {
                let h = e.halfedge();
                let (a, b) = (m.tail(h).0, m.tip(h).0);
                (a.min(b), a.max(b))
            };
            for e in d.edges() {
                let mut x = d.clone();
                if x.flip(e).is_ok() && pair(&x, e) != pair(&d, e) {
                    assert!(!same_triangulation(&d, &x), "{} {e}", s.name);
                    controls += 1;
                    break;
                }
            }
        }
    }
    assert!(flipped > 0 && controls > 0, "{flipped} {controls}");
}

/// The f64 filter reads 53-bit values through `approx_f64`; for an enclosure that is a
/// midpoint, not the value. A wide `Interval<f64>` length must therefore not be decided by
/// the filter (here it is refused as a length that is not one number), while point
/// intervals — exact numbers — are decided as their `f64` values are.
#[test]
fn b61_filter_never_reads_an_enclosure_midpoint_as_a_length() {
    use penner::predicates::delaunay::{edge_delaunay_sign, EdgeDelaunay};
    use penner::predicates::ladder::Ladder;
    use penner::scalar::{Certified, Interval, Sign};
    let m = Mesh::from_faces(4, &[[0, 1, 2], [0, 2, 3]]).expect("two triangles");
    let diag = m
        .edges()
        .find(|&e| !m.is_boundary_edge(e))
        .expect("one interior edge");
    let side = m
        .edges()
        .find(|&e| m.is_boundary_edge(e))
        .expect("a boundary edge");
    // A thin rhombus: the diagonal 1.9 is far from Delaunay (D < 0) at sides 1.
    let lengths = |wide: bool| -> Vec<Interval<f64>> {
        m.edges()
            .map(|e| {
                if e == diag {
                    Interval::point(1.9)
                } else if wide && e == side {
                    Interval::new(0.5, 1.5)
                } else {
                    Interval::point(1.0)
                }
            })
            .collect()
    };
    let exact = edge_delaunay_sign(&m, &lengths(false), diag, &Ladder::default());
    assert!(
        matches!(
            exact,
            Ok(EdgeDelaunay::Interior(Certified::Known {
                value: Sign::Negative,
                ..
            }))
        ),
        "{exact:?}"
    );
    let wide = edge_delaunay_sign(&m, &lengths(true), diag, &Ladder::default());
    assert!(
        wide.is_err(),
        "a wide enclosure was read as a number: {wide:?}"
    );
}

/// Cone angles on enclosures are rigorous in their multiple of 2π: at an interior vertex of
/// a flat grid (cone angle exactly 2π) with every length widened into an interval, the
/// enclosure contains 2π at every width. Negative control: the same enclosure does not
/// contain 2π ± 10⁻³.
#[test]
fn b15_cone_angle_enclosures_contain_the_flat_angle_at_every_width() {
    use penner::geometry::cone_angles::cone_angles;
    use penner::mesh::builders;
    use penner::scalar::{Interval, Mpfr, Precision, Real};
    use rug::Rational;
    let p = Precision::new(128).expect("valid precision");
    let grid = builders::grid_disk(4, 4).expect("a 4 × 4 grid");
    let sq = penner::io::surface::squared_lengths_from_positions(&grid.mesh, &grid.positions);
    let interior: Vec<usize> = grid
        .mesh
        .vertices()
        .filter(|&v| !grid.mesh.is_boundary_vertex(v))
        .map(penner::mesh::Vertex::idx)
        .collect();
    assert!(!interior.is_empty());
    let two_pi = Interval::<Mpfr>::point(Mpfr::from_f64(2.0, p)) * &Interval::<Mpfr>::pi(p);
    for k in [0, 3, 6, 9, 12] {
        let w = Rational::from((1, 10_i64.pow(k)));
        let l: Vec<Interval<Mpfr>> = sq
            .iter()
            .map(|q| {
                let x = Interval::<Mpfr>::from_rational(q, p).sqrt();
                if k == 0 {
                    x
                } else {
                    let lo = Interval::<Mpfr>::from_rational(&(Rational::from(1) - &w), p);
                    let hi = Interval::<Mpfr>::from_rational(&(Rational::from(1) + &w), p);
                    let span = Interval::new(lo.lo().clone(), hi.hi().clone());
                    x * &span
                }
            })
            .collect();
        let theta = cone_angles(&grid.mesh, &l);
        for &v in &interior {
            let d = theta[v].clone() - &two_pi;
            assert!(d.contains_zero(), "vertex {v} at width 1e-{k}: {d:?}");
            for off in [1e-3, -1e-3] {
                let shifted = d.clone() + &Interval::<Mpfr>::point(Mpfr::from_f64(off, p));
                assert!(
                    !shifted.contains_zero() || k <= 3,
                    "vertex {v} width 1e-{k}"
                );
            }
        }
    }
}

/// Whether `(ma, la)` and `(mb, lb)` are the same triangulation with the same lengths:
/// some vertex-fixing relabeling of `ma` onto `mb` (B81) maps every edge to one of exactly
/// the same rational length. (Several relabelings can exist on symmetric Δ-complexes; the
/// lengths must agree under one of them.)
fn same_triangulation_and_lengths(
    ma: &Mesh,
    la: &[rug::Rational],
    mb: &Mesh,
    lb: &[rug::Rational],
) -> bool {
    use penner::mesh::relabel::isomorphisms;
    isomorphisms(ma, mb, 1 << 12)
        .iter()
        .any(|r| ma.edges().all(|e| la[e.idx()] == lb[r.edge(e).idx()]))
}

/// Exact Ptolemy flipping to Delaunay over ℚ with a guard no run here reaches.
fn exact_delaunay(mesh: &Mesh, l: &[rug::Rational], seed: u64) -> (Mesh, Vec<rug::Rational>) {
    use penner::algorithms::flip_to_delaunay::{flip_to_delaunay_exact, ExactLengths};
    let mut m = mesh.clone();
    let opts = FlipOptions {
        order_seed: Some(seed),
        ..FlipOptions::default()
    };
    let (r, out) = flip_to_delaunay_exact(&mut m, l.to_vec(), 1 << 24, &opts).expect("valid");
    assert!(
        r.all_certified_delaunay() && r.fell_back_after.is_none(),
        "{r:?}"
    );
    let ExactLengths::Exact(l) = out else {
        panic!("guard passed: {r:?}")
    };
    (m, l)
}

/// Interior edges with exactly `P = 0` (malachite D-form oracle), and with `P < 0`.
fn oracle_ties_and_bad(m: &Mesh, l: &[rug::Rational]) -> (usize, usize) {
    use crate::delaunay::{oracle, to_m};
    use penner::predicates::delaunay::QuadEdges;
    use penner::scalar::Sign;
    let ml: Vec<_> = l.iter().map(to_m).collect();
    let signs: Vec<Sign> = m
        .edges()
        .filter_map(|e| QuadEdges::of(m, e).map(|q| oracle(q.lengths(&ml).to_array())))
        .collect();
    let count = |s: Sign| signs.iter().filter(|&&x| x == s).count();
    (count(Sign::Zero), count(Sign::Negative))
}

/// The strictly Delaunay edges (`P > 0` for the malachite oracle, or boundary) of
/// `(m, l)` as a sorted list of (vertex pair, exact length).
fn strict_edges(m: &Mesh, l: &[rug::Rational]) -> Vec<((u32, u32), rug::Rational)> {
    use crate::delaunay::{oracle, to_m};
    use penner::predicates::delaunay::QuadEdges;
    use penner::scalar::Sign;
    let ml: Vec<_> = l.iter().map(to_m).collect();
    let mut out: Vec<_> = m
        .edges()
        .filter(|&e| {
            QuadEdges::of(m, e).is_none_or(|q| oracle(q.lengths(&ml).to_array()) == Sign::Positive)
        })
        .map(|e| {
            let h = e.halfedge();
            let (a, b) = (m.tail(h).0, m.tip(h).0);
            ((a.min(b), a.max(b)), l[e.idx()].clone())
        })
        .collect();
    out.sort();
    out
}

/// What one start-pair comparison of
/// [`t22_ptolemy_delaunay_from_different_start_triangulations_has_equal_lengths`] saw.
#[derive(Default, Debug)]
struct StartPairs {
    compared: usize,
    tied: usize,
    starts_differ: usize,
    perturbed_rejected: usize,
    unflipped_rejected: usize,
}

/// Start A = `(mesh, la)`, start B = A after `k ∈ 1..=12` random exact Ptolemy flips; flip
/// both to Delaunay in ℚ and compare (see the test), with the negative controls.
fn compare_starts(name: &str, mesh: &Mesh, la: &[rug::Rational], seed: u64, st: &mut StartPairs) {
    use penner::algorithms::flips::flip_ptolemy_exact;
    use penner::mesh::Edge;
    use rand::{Rng, SeedableRng};
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed ^ 0x7222);
    let k = rng.gen_range(1..=12);
    let (mut mb, mut lb) = (mesh.clone(), la.to_vec());
    let mut done = 0;
    for _ in 0..1000 {
        if done == k {
            break;
        }
        let e = Edge(rng.gen_range(0..mb.n_edges() as u32));
        done += usize::from(flip_ptolemy_exact(&mut mb, &mut lb, e).is_ok());
    }
    assert_eq!(done, k, "{name}");
    st.starts_differ += usize::from(!same_triangulation(mesh, &mb));
    let (da, dla) = exact_delaunay(mesh, la, seed);
    let (db, dlb) = exact_delaunay(&mb, &lb, seed + 1);
    let (ties_a, bad_a) = oracle_ties_and_bad(&da, &dla);
    let (ties_b, bad_b) = oracle_ties_and_bad(&db, &dlb);
    assert_eq!((bad_a, bad_b), (0, 0), "{name}");
    // A non-triangular Epstein–Penner cell shows as a tie in every triangulation of it;
    // the cells' edges, strictly Delaunay, are the same with the same lengths.
    assert_eq!(ties_a > 0, ties_b > 0, "{name}");
    if ties_a > 0 {
        assert_eq!(strict_edges(&da, &dla), strict_edges(&db, &dlb), "{name}");
        st.tied += 1;
        // Negative control: with one length of start B times 65/64 the strictly Delaunay
        // edges or their lengths differ.
        let mut lp = lb.clone();
        let e0 = rng.gen_range(0..lp.len());
        lp[e0] *= rug::Rational::from((65, 64));
        let (dp, dlp) = exact_delaunay(&mb, &lp, seed + 1);
        assert_ne!(strict_edges(&da, &dla), strict_edges(&dp, &dlp), "{name}");
        st.perturbed_rejected += 1;
        return;
    }
    assert!(
        same_triangulation_and_lengths(&da, &dla, &db, &dlb),
        "{name}: {k} Ptolemy flips apart, different Delaunay results"
    );
    st.compared += 1;
    // Negative control 1: one length of start B times 65/64 is another decorated metric;
    // its Delaunay result is rejected by the same comparison.
    let e0 = Edge(rng.gen_range(0..mb.n_edges() as u32));
    let mut lp = lb.clone();
    lp[e0.idx()] *= rug::Rational::from((65, 64));
    let (dp, dlp) = exact_delaunay(&mb, &lp, seed + 1);
    if oracle_ties_and_bad(&dp, &dlp).0 == 0 {
        assert!(
            !same_triangulation_and_lengths(&da, &dla, &dp, &dlp),
            "{name}: perturbed edge {e0} accepted"
        );
        st.perturbed_rejected += 1;
    }
    // Negative control 2: start B itself, when not Delaunay, is rejected too.
    if oracle_ties_and_bad(&mb, &lb).1 > 0 {
        assert!(
            !same_triangulation_and_lengths(&da, &dla, &mb, &lb),
            "{name}"
        );
        st.unflipped_rejected += 1;
    }
}

/// T22 for decorated metrics (Epstein–Penner): exact Ptolemy flips keep the decorated
/// hyperbolic structure, so two starts related by random Ptolemy flips flip to the same
/// Ptolemy-Delaunay triangulation with the same rational lengths, edge for edge, unless a
/// cell of the Epstein–Penner decomposition is not a triangle (a tie, `P = 0`): then the
/// strictly Delaunay edges agree with their lengths. Random closed surfaces of genus 0–3
/// (no ties in practice), and grids of 3-4-5 rectangles (every cell a tie).
#[test]
fn t22_ptolemy_delaunay_from_different_start_triangulations_has_equal_lengths() {
    let n = cases(200, 10_000);
    let mut st = StartPairs::default();
    for seed in 0..n as u64 {
        let genus = (seed % 4) as u32;
        let s = ArbSurface::new(genus, 3 + (seed % 10) as u32, seed).surface;
        compare_starts(&s.name, &s.mesh, s.metric.values(), seed, &mut st);
    }
    assert!(st.compared * 2 > n, "{st:?}");
    assert!(st.starts_differ * 2 > n, "{st:?}");
    assert!(st.perturbed_rejected * 2 > st.compared, "{st:?}");
    assert!(st.unflipped_rejected * 2 > st.compared, "{st:?}");
    let (untied, controls) = (st.compared, st.perturbed_rejected);
    let (w, h, d) = (3.into(), 4.into(), 5.into());
    for seed in case_seeds(4, 100) {
        let (m, l, _) = crate::delaunay_undecided::rectangle_grid(4, [&w, &h, &d], seed);
        compare_starts(&format!("rectangles {seed}"), &m, &l, seed, &mut st);
    }
    assert_eq!(st.compared, untied, "{st:?}");
    assert_eq!(st.tied, cases(4, 100), "{st:?}");
    assert!(st.perturbed_rejected >= controls + st.tied, "{st:?}");
}

/// Exact orientation of `a, b, c` (rational coordinates): the sign of the cross product.
fn orient(
    a: &[rug::Rational; 2],
    b: &[rug::Rational; 2],
    c: &[rug::Rational; 2],
) -> std::cmp::Ordering {
    use rug::Rational;
    let x = Rational::from(&b[0] - &a[0]) * Rational::from(&c[1] - &a[1]);
    let y = Rational::from(&b[1] - &a[1]) * Rational::from(&c[0] - &a[0]);
    x.cmp(&y)
}

/// Flip up to `n` random edges of the planar triangulation `m` of `pts`, each only when its
/// quadrilateral is strictly convex (exact orientations), so the result is again a
/// triangulation of the points; the number of flips made.
fn random_legal_flips(m: &mut Mesh, pts: &[[rug::Rational; 2]], n: usize, seed: u64) -> usize {
    use penner::mesh::Edge;
    use penner::predicates::delaunay::QuadEdges;
    use rand::{Rng, SeedableRng};
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    let mut flips = 0;
    for _ in 0..n {
        let e = Edge(rng.gen_range(0..m.n_edges() as u32));
        if QuadEdges::of(m, e).is_none() {
            continue; // boundary edge
        }
        let [i, j, k, l] = m.quad_vertices(e).map(|v| &pts[v.idx()]);
        // k and l lie on opposite sides of ij; convex iff i and j lie on opposite sides of kl.
        let (si, sj) = (orient(k, l, i), orient(k, l, j));
        if si != std::cmp::Ordering::Equal && sj == si.reverse() {
            m.flip(e).expect("an interior edge with two faces");
            flips += 1;
        }
    }
    flips
}

/// T22 in the plane from other start triangulations: spade's Delaunay triangulation of
/// random integer points, and jittered grids with random diagonals, each moved away by
/// random legal flips; lengths from the coordinates; Euclidean flipping to Delaunay must
/// give spade's edges. Negative control: the randomly flipped start, when the oracle finds
/// it non-Delaunay, disagrees with spade under the same comparison.
#[test]
fn t22_planar_flipping_from_randomly_flipped_starts_matches_spade() {
    use crate::delaunay::{exact_values, oracle_non_delaunay};
    use crate::meshgen::planar_grid;
    use penner::mesh::builders;
    use penner::theorems::t22_delaunay_uniqueness::{
        check_planar_delaunay_matches_spade, planar_edge_mismatches,
    };
    use rug::Rational;
    let settings = Settings::default();
    let (mut runs, mut flipped, mut rejected) = (0, 0, 0);
    for seed in case_seeds(16, 200) {
        let spade_start = builders::random_planar(20 + (seed % 30) as u32, seed).unwrap();
        let pts_spade: Vec<[Rational; 2]> = spade_start
            .positions
            .iter()
            .map(|p| [p[0].clone(), p[1].clone()])
            .collect();
        let grid = planar_grid(7, 0.35, seed);
        let pts_grid: Vec<[Rational; 2]> = grid
            .pos
            .iter()
            .map(|p| [p[0], p[1]].map(|x| Rational::from_f64(x).unwrap()))
            .collect();
        for (mut m, pts) in [(spade_start.mesh, pts_spade), (grid.mesh(), pts_grid)] {
            let tries = 4 * m.n_edges();
            let legal = random_legal_flips(&mut m, &pts, tries, seed ^ 0x22);
            assert!(legal > 0, "seed {seed}");
            let xy: Vec<[f64; 2]> = pts.iter().map(|p| [p[0].to_f64(), p[1].to_f64()]).collect();
            let lengths = |m: &Mesh| -> Vec<f64> {
                m.edges()
                    .map(|e| {
                        let h = e.halfedge();
                        let (a, b) = (xy[m.tail(h).idx()], xy[m.tip(h).idx()]);
                        (a[0] - b[0]).hypot(a[1] - b[1])
                    })
                    .collect()
            };
            let mut l = lengths(&m);
            // Negative control: the flipped start against spade.
            if !oracle_non_delaunay(&m, &exact_values(&l)).is_empty() {
                assert!(
                    !planar_edge_mismatches(&xy, &m, &l, &settings)
                        .unwrap()
                        .is_empty(),
                    "seed {seed}: a non-Delaunay start matches spade"
                );
                rejected += 1;
            }
            // The library's whole check from this start's faces.
            let v = check_planar_delaunay_matches_spade(&xy, &m.face_list(), &settings);
            assert!(v.holds(), "seed {seed}: {v:?}");
            let r = flip_to_delaunay(&mut m, &mut l, FlipKind::Euclidean, &FlipOptions::default())
                .unwrap();
            assert!(r.all_certified_delaunay(), "seed {seed}: {r:?}");
            flipped += usize::from(r.flips > 0);
            let w = planar_edge_mismatches(&xy, &m, &l, &settings).unwrap();
            assert!(w.is_empty(), "seed {seed}: {w:?}");
            runs += 1;
        }
    }
    assert_eq!(runs, 2 * cases(16, 200));
    assert!(
        flipped == runs && rejected == runs,
        "{runs} {flipped} {rejected}"
    );
}
