//! The uniformization certificate on boxes crossing Penner-cell boundaries (B35): exact
//! cocircular ties at the solution, certified by both certifiers, with negative controls.

use penner::mesh::builders::flat_torus;
use penner::scalar::{Interval, Mpfr, Precision, Real};
use penner::uniformization::certificate::{
    check_certificate, check_certificate_on, CertificateData, CertificateOutcome,
};
use penner::uniformization::exclusion::excluded_vertices;
use penner::uniformization::krawczyk::{krawczyk, KrawczykOutcome};
use penner::uniformization::Targets;
use rug::Rational;

const BITS: u32 = 256;

fn ratio(p: i64, q: i64) -> Rational {
    Rational::from((p, q))
}

/// The 4×4 flat torus of unit squares, `u = 0`, flat targets: `u = 0` solves the exact
/// metric, where every diagonal is an exact cocircular tie (`P = 0`). Returns the data
/// (binary64 lengths, √2 rounded) and the enclosures of the exact lengths (1 and √2).
fn flat_torus_at_zero(radius: Rational) -> (CertificateData, Vec<Interval<Mpfr>>) {
    let flat = flat_torus(4, 4).unwrap();
    let prec = Precision::new(u64::from(BITS)).unwrap();
    let exact: Vec<Interval<Mpfr>> = flat
        .squared_lengths
        .iter()
        .map(|q| Interval::<Mpfr>::from_rational(q, prec).sqrt())
        .collect();
    let l0: Vec<f64> = flat
        .squared_lengths
        .iter()
        .map(|q| q.to_f64().sqrt())
        .collect();
    let n = flat.mesh.n_vertices();
    let data = CertificateData {
        t0: flat.mesh,
        l0,
        targets: Targets::flat(n),
        flip_sequence: Vec::new(),
        u: vec![Rational::new(); n],
        radius,
    };
    (data, exact)
}

fn holds(o: &CertificateOutcome) -> bool {
    matches!(o, CertificateOutcome::Holds { .. })
}

#[test]
fn b35_flat_torus_ties_at_the_solution_are_certified() {
    let (data, exact) = flat_torus_at_zero(ratio(1, 1_000_000));
    // On the exact metric u = 0 is the solution and every diagonal a tie at it: the box
    // crosses 16 cell boundaries, and the certificate holds (before B35: undecided, "edge …
    // not certified Delaunay on the whole box").
    let on_exact = check_certificate_on(&data, Some(&exact), BITS).unwrap();
    let CertificateOutcome::Holds { distance, mu, .. } = on_exact else {
        panic!("{on_exact:?}");
    };
    // The residual at u = 0 is an enclosure of 0 (width of 256-bit rounding), μ > 0.
    assert!(distance < 1e-60 && mu > 0.0, "{distance} {mu}");
    // A box holding a solution holds no excluded vertex (B73 across the boundaries).
    assert_eq!(
        excluded_vertices(&data, Some(&exact), BITS).unwrap(),
        Ok(Vec::new())
    );
    // The binary64 metric (√2 rounded, near-ties): both certifiers hold on the same box.
    let sparse = check_certificate(&data, BITS).unwrap();
    assert!(holds(&sparse), "{sparse:?}");
    let dense = krawczyk(&data, BITS).unwrap();
    assert!(matches!(dense, KrawczykOutcome::Holds { .. }), "{dense:?}");

    // Negative control 1: u moved by 1/100 (10⁴ radii) at one vertex: undecided, never a
    // refutation; both certifiers.
    let mut moved = data.clone();
    moved.u[5] = ratio(1, 100);
    let o = check_certificate_on(&moved, Some(&exact), BITS).unwrap();
    assert!(!holds(&o), "{o:?}");
    let k = krawczyk(&moved, BITS).unwrap();
    assert!(matches!(k, KrawczykOutcome::Undecided { .. }), "{k:?}");

    // Negative control 2: a wrong target (π/100 moved between two vertices, Gauss–Bonnet
    // kept): undecided, and the box is proved to hold no solution (B73) at those vertices.
    let mut wrong = data.clone();
    let mut q: Vec<Rational> = wrong.targets.over_pi().to_vec();
    q[0] += ratio(1, 100);
    q[5] -= ratio(1, 100);
    wrong.targets = Targets::from_multiples_of_pi(q);
    let o = check_certificate_on(&wrong, Some(&exact), BITS).unwrap();
    assert!(!holds(&o), "{o:?}");
    let k = krawczyk(&wrong, BITS).unwrap();
    assert!(matches!(k, KrawczykOutcome::Undecided { .. }), "{k:?}");
    let ex = excluded_vertices(&wrong, Some(&exact), BITS)
        .unwrap()
        .unwrap();
    let vs: Vec<usize> = ex.iter().map(|x| x.vertex).collect();
    assert!(vs.contains(&0) && vs.contains(&5), "{ex:?}");

    // Negative control 3: the box of radius 1 is not a proof either (no face a certified
    // strict triangle on it): undecided, never a refutation.
    let (big, exact) = flat_torus_at_zero(ratio(1, 1));
    let o = check_certificate_on(&big, Some(&exact), BITS).unwrap();
    assert!(!holds(&o), "{o:?}");
}

/// Two regular hexagons (circumradius 1) glued along their boundary, each fanned from a
/// different vertex: a sphere whose six interior diagonals are exact cocircular ties at
/// `u = 0`, the solution for targets `4π/3` (twice the hexagon's 2π/3 angle).
fn hexagon_pillow(radius: Rational) -> (CertificateData, Vec<Interval<Mpfr>>) {
    let faces = [
        [0, 1, 2],
        [0, 2, 3],
        [0, 3, 4],
        [0, 4, 5],
        [1, 3, 2],
        [1, 4, 3],
        [1, 5, 4],
        [1, 0, 5],
    ];
    let mesh = penner::mesh::Mesh::from_faces(6, &faces).unwrap();
    // |v_i − v_j|² = 1, 3, 4 for index distance 1, 2, 3.
    let squared: Vec<Rational> = mesh
        .edges()
        .map(|e| {
            let h = e.halfedge();
            let d = (mesh.tail(h).idx() as i64 - mesh.tip(h).idx() as i64).rem_euclid(6);
            Rational::from([0, 1, 3, 4, 3, 1][d as usize])
        })
        .collect();
    let prec = Precision::new(u64::from(BITS)).unwrap();
    let exact = squared
        .iter()
        .map(|q| Interval::<Mpfr>::from_rational(q, prec).sqrt())
        .collect();
    let l0 = squared.iter().map(|q| q.to_f64().sqrt()).collect();
    let data = CertificateData {
        t0: mesh,
        l0,
        targets: Targets::from_multiples_of_pi(vec![ratio(4, 3); 6]),
        flip_sequence: Vec::new(),
        u: vec![Rational::new(); 6],
        radius,
    };
    (data, exact)
}

#[test]
fn b35_adjacent_ties_are_undecided_not_refuted() {
    // Faces 0-2-3 and 1-4-3 each have two tied edges: B35's hypothesis fails, so even a
    // tiny box around the exact solution is undecided, naming both edges — never refuted.
    let (data, exact) = hexagon_pillow(ratio(1, 1_000_000));
    match check_certificate_on(&data, Some(&exact), BITS).unwrap() {
        CertificateOutcome::Undecided { reason } => {
            assert!(reason.contains("shares a face"), "{reason}");
        }
        h @ CertificateOutcome::Holds { .. } => panic!("{h:?}"),
    }
    let k = krawczyk(&data, BITS).unwrap();
    assert!(matches!(k, KrawczykOutcome::Undecided { .. }), "{k:?}");
    // The exclusion does not conclude either (nothing is claimed off a failed step 1).
    assert!(excluded_vertices(&data, Some(&exact), BITS)
        .unwrap()
        .is_err());
    // Control: the targets are right (u = 0 has zero residual on the exact metric), so
    // the undecided comes from the hypothesis alone: the angle sums of the two fans at
    // u = 0, enclosed, contain the targets 4π/3.
    let pi = Interval::<Mpfr>::pi(Precision::new(u64::from(BITS)).unwrap());
    let theta = penner::geometry::cone_angles::cone_angles(&data.t0, &exact);
    for (v, t) in theta.iter().enumerate() {
        let target = Interval::<Mpfr>::from_rational(&ratio(4, 3), t.lo().ctx()) * &pi;
        let d = t.clone() - &target;
        assert!(d.contains_zero(), "v{v}: {d:?}");
    }
}

/// The flat torus `ℝ²/(mℤ × nℤ)` of the lattice `(i + t·j, j)`, cells split along the long
/// diagonals `(i, j)–(i+1, j+1)` (vector `(1 + t, 1)`, not Delaunay: the short diagonal
/// `(1 − t, 1)` is), binary64 lengths.
fn parallelogram_torus(m: u32, n: u32, t: f64) -> (penner::mesh::Mesh, Vec<f64>) {
    let v = |i: u32, j: u32| (j % n) * m + (i % m);
    let mut faces = Vec::new();
    for j in 0..n {
        for i in 0..m {
            let (p, q, r, s) = (v(i, j), v(i + 1, j), v(i + 1, j + 1), v(i, j + 1));
            faces.push([p, q, r]);
            faces.push([p, r, s]);
        }
    }
    let mesh = penner::mesh::Mesh::from_faces(m * n, &faces).unwrap();
    // The edge vector from the grid steps (each in {−1, 0, 1}, m, n ≥ 3).
    let step = |a: u32, b: u32, k: u32| {
        let d = (i64::from(b) - i64::from(a)).rem_euclid(i64::from(k));
        if d > i64::from(k) / 2 {
            d - i64::from(k)
        } else {
            d
        }
    };
    let lengths = mesh
        .edges()
        .map(|e| {
            let h = e.halfedge();
            let (a, b) = (mesh.tail(h).0, mesh.tip(h).0);
            let di = step(a % m, b % m, m) as f64;
            let dj = step(a / m, b / m, n) as f64;
            (di + t * dj).hypot(dj)
        })
        .collect();
    (mesh, lengths)
}

/// B69: a recorded triangulation that the solution lies past a near-tie of (one short
/// diagonal of the nearly rectangular flat torus Ptolemy-flipped back to the long one,
/// `|P|/M ≈ t = 2⁻³⁰` at the solution). On that fixed triangulation the refinement would
/// converge to the zero of `∇E_T`, whose true residual `∇E = Θ − θ_Delaunay` is `O(P²)`
/// (≈ 10⁻¹⁸, undecided at 256 bits); kept Delaunay by Ptolemy flips it reaches the solution
/// and the enclosed residual stays within the stated factor of the computed one:
/// `γ ≤ √n·(max|Θ − θ| + 2^(40−bits))`, the `2^(40−bits)` covering the enclosure widths
/// (B33: a few hundred roundings of relative size `2^−bits` on angle sums ≤ 2π·deg).
#[test]
fn b69_refinement_across_a_near_tie_is_certified_tightly() {
    use penner::algorithms::flips::flip_ptolemy;
    use penner::predicates::delaunay::{enclose_p, QuadEdges};
    use penner::uniformization::certificate::prove;
    use penner::uniformization::{uniformize, UniformizeOptions};
    let t = 2f64.powi(-30);
    let (mesh, l) = parallelogram_torus(6, 6, t);
    let n = mesh.n_vertices();
    let mut sol = uniformize(&mesh, &l, &Targets::flat(n), &UniformizeOptions::default()).unwrap();
    assert!(sol.converged());
    // Flip one diagonal of the final triangulation back: a near-tie crossed (P < 0 there,
    // certified, so the recorded triangulation is not Delaunay at the solution).
    let e = sol
        .mesh
        .edges()
        .find(|&e| {
            let h = e.halfedge();
            let (a, b) = (sol.mesh.tail(h).0, sol.mesh.tip(h).0);
            // A diagonal: its ends differ in both grid coordinates.
            a % 6 != b % 6 && a / 6 != b / 6
        })
        .unwrap();
    flip_ptolemy(&mut sol.mesh, &mut sol.base_lengths, e).unwrap();
    sol.flip_sequence.push(e);
    let prec = Precision::new(u64::from(BITS)).unwrap();
    let q = QuadEdges::of(&sol.mesh, e).unwrap();
    let lq: Vec<Interval<Mpfr>> = sol
        .base_lengths
        .iter()
        .map(|&x| Interval::point(Mpfr::from_f64(x, prec)))
        .collect();
    let p = enclose_p(&q.lengths(&lq).map(Clone::clone).to_array());
    assert!(
        p.hi().approx_f64() < 0.0,
        "the flipped-back diagonal is not Delaunay"
    );

    let proof = prove(&sol, BITS, 1e-60).unwrap();
    // The refinement flipped the diagonal again (the certificate's triangulation).
    assert!(proof.data.flip_sequence.len() > sol.flip_sequence.len());
    let CertificateOutcome::Holds {
        residual, distance, ..
    } = proof.outcome
    else {
        panic!("{:?}", proof.outcome);
    };
    let factor = (n as f64).sqrt() * (proof.residual_max + 2f64.powi(40 - BITS as i32));
    assert!(residual <= factor, "{residual:e} > {factor:e}");
    assert!(distance < 1e-55, "{distance:e}");

    // Negative control 1: u moved by 10⁻⁶ at one vertex (far beyond the box): undecided.
    let mut moved = proof.data.clone();
    moved.u[7] += Rational::from_f64(1e-6).unwrap();
    let o = check_certificate(&moved, BITS).unwrap();
    assert!(!holds(&o), "{o:?}");
    // Negative control 2: a wrong target (π/100 moved between two vertices, Gauss–Bonnet
    // kept) at the same u and box: undecided.
    let mut wrong = proof.data.clone();
    let mut q: Vec<Rational> = wrong.targets.over_pi().to_vec();
    q[0] += ratio(1, 100);
    q[9] -= ratio(1, 100);
    wrong.targets = Targets::from_multiples_of_pi(q);
    let o = check_certificate(&wrong, BITS).unwrap();
    assert!(!holds(&o), "{o:?}");
}
