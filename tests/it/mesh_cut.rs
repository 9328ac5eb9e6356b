//! B113: the cut graph through the cones opens a closed surface into a disk whose interior
//! holds no cone, with no dangling cut edge at a vertex that is not a cone. Checked on
//! random Δ-complexes of genus 0–3 (loops and multi-edges included) by counting: the cut
//! surface has `χ = 1` and its faces are connected across the edges not cut.

use penner::mesh::builders;
use penner::mesh::cut::cut_through_cones;
use penner::mesh::{Face, Mesh};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// Cut degree per vertex (a loop counts twice).
fn cut_degree(m: &Mesh, cut: &[bool]) -> Vec<usize> {
    let mut d = vec![0; m.n_vertices()];
    for e in m.edges().filter(|e| cut[e.idx()]) {
        let h = e.side(0);
        d[m.tail(h).idx()] += 1;
        d[m.tip(h).idx()] += 1;
    }
    d
}

/// `χ` of the surface cut open along `cut` (each vertex of cut degree `d ≥ 1` becomes `d`
/// vertices, each cut edge two), and whether its faces are connected across the edges
/// that are not cut.
fn cut_surface(m: &Mesh, cut: &[bool]) -> (i64, bool) {
    let deg = cut_degree(m, cut);
    let v: usize = deg.iter().map(|&d| d.max(1)).sum();
    let e = m.n_edges() + cut.iter().filter(|&&c| c).count();
    let chi = v as i64 - e as i64 + m.n_faces() as i64;
    let mut seen = vec![false; m.n_faces()];
    let mut stack = vec![Face(0)];
    seen[0] = true;
    while let Some(f) = stack.pop() {
        for h in m.face_halfedges(f) {
            if let Some(g) = m.face(h.twin()) {
                if !cut[h.edge().idx()] && !seen[g.idx()] {
                    seen[g.idx()] = true;
                    stack.push(g);
                }
            }
        }
    }
    (chi, seen.iter().all(|&s| s))
}

/// What is wrong with `cut` as a cut through the cones: a dangling cut edge at a vertex
/// that is not a cone, a cone the cut does not reach, a cut surface that is not a
/// connected disk.
fn defects(m: &Mesh, cut: &[bool], cone: &[bool]) -> Vec<String> {
    let deg = cut_degree(m, cut);
    let mut out = Vec::new();
    for v in m.vertices() {
        if !cone[v.idx()] && deg[v.idx()] == 1 {
            out.push(format!("a dangling cut edge at {v:?}"));
        }
        if cone[v.idx()] && deg[v.idx()] == 0 {
            out.push(format!("cone {v:?} not on the cut"));
        }
    }
    let (chi, connected) = cut_surface(m, cut);
    if (chi, connected) != (1, true) {
        out.push(format!("cut surface χ = {chi}, connected {connected}"));
    }
    out
}

#[test]
fn b113_cut_through_cones_opens_a_disk_with_no_dangling_edge() {
    let mut rng = ChaCha8Rng::seed_from_u64(113);
    let (mut tried, mut controls) = (0, 0);
    for g in 0..4u32 {
        for seed in 0..crate::support::cases(6, 60) as u64 {
            let n = rng.gen_range(4..40);
            let m = builders::random_surface(g, n, seed).unwrap();
            let k = if g == 0 {
                rng.gen_range(2..6)
            } else {
                rng.gen_range(0..4)
            };
            let mut cone = vec![false; m.n_vertices()];
            for _ in 0..k {
                cone[rng.gen_range(0..m.n_vertices())] = true;
            }
            if g == 0 && cone.iter().filter(|&&c| c).count() < 2 {
                continue;
            }
            let all = vec![true; m.n_faces()];
            let cut = cut_through_cones(&m, &all, Face(0), &cone);
            assert_eq!(
                defects(&m, &cut, &cone),
                Vec::<String>::new(),
                "g {g} seed {seed}"
            );
            tried += 1;
            // Control 1: the last edge to a cone at the end of a path un-cut leaves that cone
            // inside the disk.
            let deg = cut_degree(&m, &cut);
            let leaf = m.edges().find(|e| {
                let h = e.side(0);
                cut[e.idx()]
                    && [m.tail(h), m.tip(h)]
                        .iter()
                        .any(|v| cone[v.idx()] && deg[v.idx()] == 1)
            });
            if let Some(e) = leaf {
                let mut less = cut.clone();
                less[e.idx()] = false;
                assert!(!defects(&m, &less, &cone).is_empty(), "g {g} seed {seed}");
                controls += 1;
            }
            // Control 2: the cut with every vertex a cone (nothing pruned) dangles at the
            // vertices that are not cones, unless every vertex is one.
            let everything = cut_through_cones(&m, &all, Face(0), &vec![true; m.n_vertices()]);
            if cone.iter().any(|&c| !c) && everything != cut {
                assert!(
                    !defects(&m, &everything, &cone).is_empty(),
                    "g {g} seed {seed}"
                );
                controls += 1;
            }
        }
    }
    assert!(
        tried >= 12 && controls >= 12,
        "{tried} cases, {controls} controls"
    );
}
