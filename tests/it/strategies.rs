//! The user-facing strategies: everything they produce is valid, and shrinking reaches
//! small surfaces.

use penner::io::Surface;
use penner::strategies::{self, ArbSurface};
use proptest::prelude::*;
use proptest::test_runner::{Config, TestError, TestRunner};
use quickcheck::{Arbitrary, Gen};

fn assert_valid(s: &Surface) -> Result<(), TestCaseError> {
    prop_assert!(s.mesh.check_invariants().is_ok(), "{}", s.name);
    prop_assert!(s.validate().is_ok(), "{}: {:?}", s.name, s.validate());
    Ok(())
}

fn config() -> ProptestConfig {
    crate::support::proptest_config(64, 10_000)
}

proptest! {
    #![proptest_config(config())]

    #[test]
    fn closed_surfaces_are_valid_with_requested_genus(s in strategies::closed_surface(0..=3, 1..=20)) {
        assert_valid(&s)?;
        prop_assert!(s.mesh.is_closed());
        let chi = s.mesh.euler_characteristic();
        prop_assert!((-4..=2).contains(&chi) && chi % 2 == 0, "χ = {}", chi);
    }

    #[test]
    fn surfaces_with_boundary_are_valid(s in strategies::surface_with_boundary(5)) {
        assert_valid(&s)?;
        prop_assert!(!s.mesh.is_closed());
        prop_assert!(s.mesh.n_boundary_loops() >= 1);
    }

    #[test]
    fn embedded_surfaces_are_valid(s in strategies::embedded_surface(40)) {
        assert_valid(&s)?;
        prop_assert!(s.positions.is_some());
    }

    #[test]
    fn conformal_scalings_are_valid_and_exact(
        (s, f) in strategies::closed_surface(0..=2, 3..=10).prop_flat_map(strategies::conformally_scaled),
    ) {
        assert_valid(&s)?;
        prop_assert_eq!(f.len(), s.mesh.n_vertices());
    }

    #[test]
    fn near_degenerate_surfaces_are_valid_but_close(s in strategies::near_degenerate_surface()) {
        assert_valid(&s)?;
        // Independent check of nearness: some face has 16·area² below 10⁻³ relative to
        // its largest squared side squared (Heron's form evaluated here directly).
        let sq = s.metric.squared();
        let near = s.mesh.faces().any(|f| {
            let [a, b, c] = s.mesh.face_halfedges(f).map(|h| sq[h.edge().idx()].clone());
            let (a2, b2, c2) = (a.clone() * &a, b.clone() * &b, c.clone() * &c);
            let h16 = (a.clone() * &b + b.clone() * &c + c.clone() * &a) * 2u32 - a2.clone() - &b2 - &c2;
            let m = a2.max(b2).max(c2);
            h16 * 1000u32 < m
        });
        prop_assert!(near, "{}", s.name);
    }
}

/// Negative control: a perturbed near-degenerate metric (ε → −ε) is refused.
#[test]
fn near_degenerate_negative_control() {
    use penner::io::Metric;
    use rug::Rational;
    let m = penner::mesh::builders::two_triangle_sphere();
    let bad = vec![
        Rational::from(1),
        Rational::from(1),
        Rational::from(2) + Rational::from((1, 1u64 << 60)),
    ];
    assert!(Surface::new("x", m, Metric::Lengths(bad), None).is_err());
}

/// A deliberately broken property shrinks to a small counterexample (proptest).
#[test]
fn proptest_shrinks_to_small_surfaces() {
    let mut runner = TestRunner::new(Config {
        cases: 256,
        ..Config::default()
    });
    // Broken: "every surface has at most 4 vertices".
    let r = runner.run(&strategies::closed_surface(0..=3, 1..=60), |s| {
        prop_assert!(s.mesh.n_vertices() <= 4);
        Ok(())
    });
    let Err(TestError::Fail(_, s)) = r else {
        panic!("the broken check was not refuted: {r:?}")
    };
    assert!(
        s.mesh.n_faces() <= 10,
        "shrunk to {} faces",
        s.mesh.n_faces()
    );
    // Broken: "χ = 2" on surfaces with boundary.
    let r = runner.run(&strategies::surface_with_boundary(8), |s| {
        prop_assert_eq!(s.mesh.euler_characteristic(), 2);
        Ok(())
    });
    let Err(TestError::Fail(_, s)) = r else {
        panic!("not refuted")
    };
    assert!(
        s.mesh.n_faces() <= 10,
        "shrunk to {} faces",
        s.mesh.n_faces()
    );
    // Negative control: a true property is not refuted.
    let r = runner.run(&strategies::closed_surface(0..=3, 1..=60), |s| {
        prop_assert!(s.mesh.euler_characteristic() <= 2);
        Ok(())
    });
    assert!(r.is_ok());
}

/// A deliberately broken property shrinks to a small counterexample (quickcheck's
/// `shrink`, followed greedily as quickcheck does).
#[test]
fn quickcheck_shrinks_to_small_surfaces() {
    let broken = |a: &ArbSurface| a.surface.mesh.euler_characteristic() == 2; // fails for g ≥ 1
    let mut g = Gen::new(100);
    let mut x = (0..1000)
        .map(|_| ArbSurface::arbitrary(&mut g))
        .find(|a| !broken(a) && a.vertices > 20)
        .expect("a counterexample");
    while let Some(smaller) = x.shrink().find(|a| !broken(a)) {
        x = smaller;
    }
    assert!(
        x.surface.mesh.n_faces() <= 10,
        "shrunk to {} faces",
        x.surface.mesh.n_faces()
    );
    assert!(x.surface.validate().is_ok());
}
