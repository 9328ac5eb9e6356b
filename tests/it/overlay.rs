//! B105: normal coordinates of the input triangulation relative to the intrinsic
//! Delaunay triangulation, against an independent exact oracle on planar meshes (every
//! edge of a flat disk with convex boundary is the straight segment between its ends, so
//! crossings are counted by exact rational orientation tests).

use penner::algorithms::flip_to_delaunay::{flip_to_delaunay, FlipKind, FlipOptions};
use penner::io::surface::squared_lengths_from_positions;
use penner::mesh::{builders, Edge, Mesh};
use penner::overlay::replay_normal_coordinates;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rug::Rational;

type P = [Rational; 3];

/// Sign of the exact orientation of `a, b, c` in the plane.
fn orient(a: &P, b: &P, c: &P) -> i32 {
    let d = Rational::from(&b[0] - &a[0]) * Rational::from(&c[1] - &a[1])
        - Rational::from(&b[1] - &a[1]) * Rational::from(&c[0] - &a[0]);
    d.cmp0() as i32
}

/// Ends of `e` as vertex indices.
fn ends(m: &Mesh, e: Edge) -> (usize, usize) {
    let h = e.halfedge();
    (m.tail(h).idx(), m.tip(h).idx())
}

/// The exact oracle: for every edge of `t`, `−1` if it is an edge of `t_in`, else the
/// number of proper crossings of its segment with the segments of `t_in`.
fn oracle(t_in: &Mesh, t: &Mesh, pos: &[P]) -> Vec<i64> {
    t.edges()
        .map(|e| {
            let (p, q) = ends(t, e);
            let mut count = 0;
            for g in t_in.edges() {
                let (a, b) = ends(t_in, g);
                if (a, b) == (p, q) || (a, b) == (q, p) {
                    return -1;
                }
                let s1 = orient(&pos[p], &pos[q], &pos[a]) * orient(&pos[p], &pos[q], &pos[b]);
                let s2 = orient(&pos[a], &pos[b], &pos[p]) * orient(&pos[a], &pos[b], &pos[q]);
                if s1 < 0 && s2 < 0 {
                    count += 1;
                }
            }
            count
        })
        .collect()
}

/// A planar Delaunay triangulation spoiled by random flips of strictly convex quads.
fn spoiled(n: u32, seed: u64) -> (Mesh, Vec<P>) {
    let e = builders::random_planar(n, seed).unwrap();
    let (mut m, pos) = (e.mesh, e.positions);
    let mut rng = ChaCha8Rng::seed_from_u64(seed ^ 0x5eed);
    for _ in 0..4 * m.n_edges() {
        let e = Edge(rng.gen_range(0..m.n_edges() as u32));
        if m.is_boundary_edge(e) {
            continue;
        }
        let [i, j, k, l] = m.quad_vertices(e).map(|v| &pos[v.idx()]);
        if orient(k, l, i) * orient(k, l, j) < 0 {
            m.flip(e).unwrap();
        }
    }
    (m, pos)
}

#[test]
fn b105_normal_coordinates_match_exact_planar_crossings() {
    let mut crossed = 0;
    for seed in 0..12u64 {
        let (t_in, pos) = spoiled(12 + 3 * seed as u32, seed);
        let mut t = t_in.clone();
        let mut l: Vec<f64> = squared_lengths_from_positions(&t_in, &pos)
            .iter()
            .map(|s| s.to_f64().sqrt())
            .collect();
        let opts = FlipOptions {
            record: true,
            ..FlipOptions::default()
        };
        let r = flip_to_delaunay(&mut t, &mut l, FlipKind::Euclidean, &opts).unwrap();
        assert!(r.all_certified_delaunay());
        let (replayed, n) = replay_normal_coordinates(&t_in, &r.sequence).unwrap();
        assert_eq!(replayed, t);
        n.check(&t).unwrap();
        let exact = oracle(&t_in, &t, &pos);
        assert_eq!(n.values(), &exact[..], "seed {seed}");
        crossed += exact.iter().filter(|&&v| v > 0).count();
        // Negative control: one coordinate altered is caught by the oracle comparison.
        let mut bad = n.values().to_vec();
        bad[r.sequence[0].idx()] += 2;
        assert_ne!(bad, exact);
    }
    assert!(
        crossed > 20,
        "the spoiled meshes were hardly flipped: {crossed}"
    );
}

#[test]
fn b105_replay_refuses_a_boundary_flip() {
    let (t_in, _) = spoiled(10, 3);
    let b = t_in.edges().find(|&e| t_in.is_boundary_edge(e)).unwrap();
    assert!(replay_normal_coordinates(&t_in, &[b]).is_err());
}
