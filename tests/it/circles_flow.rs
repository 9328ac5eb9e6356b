//! Circle-pattern existence and flows: Thurston's conditions (T10) with a degenerating
//! instance kept fixed, and the Chow–Luo flow (T13) against certified Newton solutions.

use crate::support::cases;
use penner::circles::solve::{default_tolerance, ricci_flow};
use penner::circles::thurston::check_thurston;
use penner::circles::CirclePattern;
use penner::mesh::builders::{flat_torus, icosahedron};
use penner::mesh::{Face, Mesh};
use penner::scalar::{Dd, Real};
use penner::theorems::t10_thurston_existence::{check_thurston_existence, vertex_obstructions};
use penner::theorems::t13_chow_luo_flow::{check_flow_converges, verify_flow_end};
use penner::theorems::Verdict;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rug::Rational;

fn rat(a: i64, b: i64) -> Rational {
    Rational::from((a, b))
}

/// The 4×4 flat torus with face 0 split: the new vertex `v` (the last) has degree 3 and its
/// link is the boundary of the old face 0, a null-homotopic 3-cycle bounding three faces.
/// Returns the mesh, `v` and the link's edges.
fn split_torus() -> (Mesh, usize, [usize; 3]) {
    let mut mesh = flat_torus(4, 4).unwrap().mesh;
    let link = mesh.face_halfedges(Face(0)).map(|h| h.edge().idx());
    let v = mesh.split_face(Face(0)).unwrap().idx();
    (mesh, v, link)
}

/// Every target 2π; `Φ = q·π` on the link edges, 0 elsewhere.
fn torus_problem(q: &Rational) -> (CirclePattern, usize) {
    let (mesh, v, link) = split_torus();
    let mut phi = vec![rat(0, 1); mesh.n_edges()];
    for e in link {
        phi[e].clone_from(q);
    }
    let n = mesh.n_vertices();
    (
        CirclePattern::new(mesh, phi, vec![Some(rat(2, 1)); n]).unwrap(),
        v,
    )
}

/// Simple 3-cycles counted independently: vertex triples a < b < c times the number of
/// edges joining each pair.
fn count_three_cycles(mesh: &Mesh) -> usize {
    let n = mesh.n_vertices();
    let mut m = vec![vec![0usize; n]; n];
    for e in mesh.edges() {
        let h = e.halfedge();
        let (a, b) = (mesh.tail(h).idx(), mesh.tip(h).idx());
        if a != b {
            m[a][b] += 1;
            m[b][a] += 1;
        }
    }
    let mut count = 0;
    for a in 0..n {
        for b in a + 1..n {
            for c in b + 1..n {
                count += m[a][b] * m[b][c] * m[c][a];
            }
        }
    }
    count
}

#[test]
fn t10_thurston_violation_and_the_flow_degenerates_fixed_instance() {
    // Φ = π/2 on the link: ΣΦ = 3π/2 ≥ π on a null-homotopic 3-cycle bounding no face.
    let (p, v) = torus_problem(&rat(1, 2));
    let report = check_thurston(&p.mesh, &p.phi).unwrap();
    assert_eq!(report.three_cycles, count_three_cycles(&p.mesh));
    assert_eq!(report.violations.len(), 1, "{report:?}");
    assert_eq!(report.violations[0].angle_sum, rat(3, 2));
    // No radii reach 2π at v: sup θ_v = 3(π − π/2) = 3π/2 (proofs/T10).
    assert_eq!(vertex_obstructions(&p), vec![v]);
    let verdict = check_thurston_existence(&p);
    assert!(
        matches!(
            verdict,
            Verdict::Holds {
                certified: true,
                ..
            }
        ),
        "{verdict:?}"
    );
    // The flow degenerates: d(u_v − ū)/dt = θ_v − 2π < −π/2, so over time T the normalised
    // log radius of v drops by more than πT/2.
    let n = p.mesh.n_vertices();
    let flow = ricci_flow::<f64>(&p, &vec![0.0; n], 0.0, 400, true).unwrap();
    let time = *flow.times.last().unwrap();
    let mean = flow.u.iter().sum::<f64>() / n as f64;
    let drop = flow.u[v] - mean;
    assert!(time > 5.0, "flow time {time}");
    assert!(
        drop < -std::f64::consts::FRAC_PI_2 * time * (1.0 - 1e-9),
        "{drop} over {time}"
    );
    // The residual at v never goes below π/2 (it cannot converge); it tends to π/2 as
    // r_v → 0, so the f64 comparison allows the error of a three-corner angle sum (B40:
    // each corner within 16u·(small multiple) of π, far below 1e-13).
    assert!(flow
        .history
        .iter()
        .all(|&r| r > std::f64::consts::FRAC_PI_2 - 1e-13));
    // Control: the converging problem's residual does go below π/2.
    let (q, _) = torus_problem(&rat(0, 1));
    let ok = ricci_flow::<f64>(&q, &vec![0.0; n], 0.0, 400, true).unwrap();
    assert!(ok.history.last().unwrap() < &1e-6);
}

#[test]
fn t10_flow_converges_once_thurston_holds() {
    // Φ = π/4 on the link (ΣΦ = 3π/4 < π) and tangency (Φ = 0): the conditions hold, a
    // flat pattern is certified, and no vertex obstruction exists.
    for q in [rat(1, 4), rat(0, 1)] {
        let (p, _) = torus_problem(&q);
        let report = check_thurston(&p.mesh, &p.phi).unwrap();
        assert!(report.holds(), "{report:?}");
        assert!(vertex_obstructions(&p).is_empty());
        let v = check_thurston_existence(&p);
        assert!(
            matches!(
                v,
                Verdict::Holds {
                    certified: true,
                    ..
                }
            ),
            "{v:?}"
        );
        let n = p.mesh.n_vertices();
        let r = check_flow_converges::<f64>(&p, &vec![0.0; n], (), 1e-12, 20_000);
        assert!(r.verdict.holds(), "{:?}", r.verdict);
        assert!(r.rate.unwrap() > 0.0);
    }
    // Negative control: at q = 1/3 the link sums to exactly π — still a violation.
    let (p, v) = torus_problem(&rat(1, 3));
    assert_eq!(check_thurston(&p.mesh, &p.phi).unwrap().violations.len(), 1);
    assert_eq!(vertex_obstructions(&p), vec![v]);
}

#[test]
fn t13_chow_luo_flow_reaches_the_certified_solution() {
    let mut rng = ChaCha8Rng::seed_from_u64(13);
    for case in 0..cases(3, 30) {
        let mut mesh = icosahedron().mesh;
        for _ in 0..rng.gen_range(0..=3) {
            let f = Face(rng.gen_range(0..mesh.n_faces() as u32));
            mesh.split_face(f).unwrap();
        }
        let choices = [rat(0, 1), rat(1, 6), rat(1, 3)];
        let phi: Vec<Rational> = (0..mesh.n_edges())
            .map(|_| choices[rng.gen_range(0..3)].clone())
            .collect();
        let e = mesh.n_edges() as i64;
        let targets = mesh
            .vertices()
            .map(|v| Some(rat(2, 1) - rat(2 * mesh.degree(v) as i64, e)))
            .collect();
        let p = CirclePattern::new(mesh.clone(), phi, targets).unwrap();
        let n = mesh.n_vertices();
        let start: Vec<f64> = (0..n).map(|_| rng.gen_range(-1.0..1.0)).collect();
        let r = check_flow_converges::<f64>(&p, &start, (), 1e-12, 50_000);
        assert!(r.verdict.holds(), "case {case}: {:?}", r.verdict);
        let rate = r.rate.unwrap();
        assert!(rate > 0.0, "rate {rate}");
        // Double-double: the same limit, closer.
        let tol = default_tolerance::<Dd>(n, ());
        let rd = check_flow_converges::<Dd>(&p, &start, (), tol.max(1e-25), 100_000);
        assert!(rd.verdict.holds(), "case {case} dd: {:?}", rd.verdict);
        // Negative control: the end of the flow of another problem (targets moved by π/20
        // at two vertices) is not in this problem's certified box.
        let mut t: Vec<Option<Rational>> = p.targets.clone();
        t[1] = t[1].take().map(|x| x + rat(1, 20));
        t[2] = t[2].take().map(|x| x - rat(1, 20));
        let q = CirclePattern::new(mesh.clone(), p.phi.clone(), t).unwrap();
        let other = ricci_flow::<f64>(&q, &start, 1e-12, 50_000, false).unwrap();
        assert!(!verify_flow_end(&p, &other.u).holds());
        let _ = other.u.iter().map(Real::approx_f64).sum::<f64>();
    }
}

#[test]
fn t10_essential_cycles_are_not_violations() {
    // On the 3×4 flat torus the three edges of a row close up around the torus: essential
    // (non-separating) 3-cycles. With Φ = π/2 everywhere they sum to 3π/2 ≥ π but are not
    // null-homotopic, so Thurston's conditions hold; faces are the only other 3-cycles.
    let mesh = flat_torus(3, 4).unwrap().mesh;
    let cycles = count_three_cycles(&mesh);
    assert!(
        cycles > mesh.n_faces(),
        "{cycles} 3-cycles, {} faces",
        mesh.n_faces()
    );
    let n = mesh.n_vertices();
    let p = CirclePattern::new(
        mesh.clone(),
        vec![rat(1, 2); mesh.n_edges()],
        vec![Some(rat(2, 1)); n],
    )
    .unwrap();
    let report = check_thurston(&p.mesh, &p.phi).unwrap();
    assert_eq!(report.three_cycles, cycles);
    assert!(report.holds(), "{:?}", report.violations);
    // Control: the split torus (a separating 3-cycle) at the same angles is a violation.
    let (q, _) = torus_problem(&rat(1, 2));
    assert!(!check_thurston(&q.mesh, &q.phi).unwrap().holds());
}
