//! T22 on random surfaces of genus 0–3: different flip orders reach the same triangulation
//! up to renumbering of edges and faces (a vertex-fixing isomorphism of the gluing).

use crate::support::cases;
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
    for seed in 0..cases(60, 2000) as u64 {
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
