//! The cotan Laplacian's direct CSR assembly against an independent assembly from
//! triplets (`SparseMatrix::from_triplets`: each half-edge `h = i→j` adds `½ cot α(h)` to
//! `L_ij`, `L_ji` and subtracts it from `L_ii`, `L_jj`), entry for entry and bit for bit, on
//! Δ-complexes with loops, multi-edges, self-folded faces and boundary.

use penner::geometry::cotan::halfedge_cotans;
use penner::geometry::laplacian::{cotan_laplacian, SparseMatrix};
use penner::mesh::{builders, Mesh};
use penner::scalar::{Dd, Real};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// The Laplacian from triplets, in half-edge order.
fn by_triplets<T: Real>(mesh: &Mesh, lengths: &[T]) -> SparseMatrix<T> {
    let cots = halfedge_cotans(mesh, lengths);
    let mut trip = Vec::new();
    for h in mesh.halfedges() {
        let (i, j) = (mesh.tail(h).idx(), mesh.tip(h).idx());
        if mesh.is_boundary_halfedge(h) || i == j {
            continue;
        }
        let c = cots[h.idx()].clone() * &cots[h.idx()].lit(0.5);
        trip.push((i, j, c.clone()));
        trip.push((j, i, c.clone()));
        trip.push((i, i, -c.clone()));
        trip.push((j, j, -c));
    }
    SparseMatrix::from_triplets(mesh.n_vertices(), &trip)
}

/// Lengths `1 + k/1024` (`k < 1024`): every triangle is strict.
fn lengths(mesh: &Mesh, rng: &mut ChaCha8Rng) -> Vec<f64> {
    (0..mesh.n_edges())
        .map(|_| 1.0 + f64::from(rng.gen_range(0u32..1024)) / 1024.0)
        .collect()
}

fn surfaces() -> Vec<(String, Mesh)> {
    let mut v = vec![
        (
            "two-triangle sphere".to_string(),
            builders::two_triangle_sphere(),
        ),
        ("one-vertex torus".to_string(), builders::one_vertex_torus()),
        ("genus 2".to_string(), builders::genus(2).unwrap()),
        ("annulus".to_string(), builders::annulus(3, 5).unwrap().mesh),
    ];
    for s in 0..12u64 {
        let g = (s % 4) as u32;
        let m = builders::random_surface(g, 3 + (s as u32 % 9), s).unwrap();
        v.push((format!("random genus {g} seed {s}"), m));
        // Random flips make loops, multi-edges and self-folded faces.
        v.push((
            format!("flipped genus {g} seed {s}"),
            builders::random_flips(&v.last().unwrap().1, 40, s),
        ));
    }
    v
}

#[test]
fn t05_direct_assembly_equals_triplet_assembly() {
    let mut rng = ChaCha8Rng::seed_from_u64(505);
    let mut compared = 0;
    for (name, m) in surfaces() {
        let l = lengths(&m, &mut rng);
        assert_eq!(cotan_laplacian(&m, &l), by_triplets(&m, &l), "{name} f64");
        let d: Vec<Dd> = l.iter().map(|&x| <Dd as Real>::from_f64(x, ())).collect();
        let (a, b) = (cotan_laplacian(&m, &d), by_triplets(&m, &d));
        let same = a
            .entries()
            .zip(b.entries())
            .all(|(x, y)| x.0 == y.0 && x.1 == y.1 && x.2.to_rational() == y.2.to_rational())
            && a.entries().count() == b.entries().count();
        assert!(same, "{name} dd");
        compared += 1;
    }
    assert!(compared >= 20);
}

#[test]
fn t05_negative_control_one_changed_length_changes_the_laplacian() {
    // The comparison above can fail: the same comparison rejects the Laplacian of a metric
    // with one length changed by one part in 1024.
    let mut rng = ChaCha8Rng::seed_from_u64(506);
    let mut rejected = 0;
    for (name, m) in surfaces() {
        let l = lengths(&m, &mut rng);
        // An interior edge with two distinct ends: its length enters some cotangent.
        let Some(e) = m.edges().find(|&e| {
            let h = e.halfedge();
            !m.is_boundary_edge(e) && m.tail(h) != m.tip(h)
        }) else {
            continue;
        };
        let mut l2 = l.clone();
        l2[e.idx()] *= 1.0 + 1.0 / 1024.0;
        assert_ne!(cotan_laplacian(&m, &l), by_triplets(&m, &l2), "{name}");
        rejected += 1;
    }
    assert!(rejected > 10);
}
