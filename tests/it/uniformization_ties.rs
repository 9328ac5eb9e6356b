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
