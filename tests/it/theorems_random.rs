//! Catalogue checks on random surfaces from the user-facing strategies (genus 0–3, with
//! and without boundary), each case with its own negative control.

use penner::geometry::cross_ratio::cross_ratio_halfedges;
use penner::geometry::curvature::curvature;
use penner::io::surface::validate_metric;
use penner::io::{Metric, Surface};
use penner::scalar::{Dd, Mpfr, Precision, Real};
use penner::strategies;
use penner::theorems::t01_gauss_bonnet::{
    check_gauss_bonnet, gauss_bonnet_error_bound, verify_gauss_bonnet,
};
use penner::theorems::t17_cross_ratio_equivalence::check_conformal_equivalence_exact;
use penner::theorems::{Settings, Verdict};
use proptest::prelude::*;
use proptest::test_runner::TestRunner;
use rug::Rational;
use std::cell::Cell;

fn exact_lengths(s: &Surface) -> &[Rational] {
    match &s.metric {
        Metric::Lengths(l) => l,
        Metric::SquaredLengths(_) => panic!("{}: the strategies produce lengths", s.name),
    }
}

/// T01 holds within B42's bound at `ctx`, and the same comparison rejects one vertex
/// curvature moved by four times that bound.
fn gauss_bonnet_case<T: Real>(s: &Surface, ctx: T::Ctx) -> Result<(), TestCaseError> {
    let l: Vec<T> = s.lengths(ctx);
    let settings = Settings::default();
    let v = check_gauss_bonnet(&s.mesh, &l, &settings);
    prop_assert!(
        v.holds(),
        "{} at {} bits: {v:?}",
        s.name,
        T::precision_bits(ctx)
    );
    let bound = gauss_bonnet_error_bound(&s.mesh, &l);
    let mut k = curvature(&s.mesh, &l);
    k[0] += &T::from_f64(4.0 * bound, ctx);
    let v = verify_gauss_bonnet(&s.mesh, &l, &k, &settings);
    prop_assert!(v.fails(), "{}: perturbed curvature accepted: {v:?}", s.name);
    Ok(())
}

fn gauss_bonnet_all_precisions(s: &Surface) -> Result<(), TestCaseError> {
    gauss_bonnet_case::<f64>(s, ())?;
    gauss_bonnet_case::<Dd>(s, ())?;
    gauss_bonnet_case::<Mpfr>(s, Precision::new(256).expect("valid precision"))
}

proptest! {
    #![proptest_config(crate::support::proptest_config(24, 2000))]

    #[test]
    fn t01_gauss_bonnet_on_random_closed_surfaces(s in strategies::closed_surface(0..=3, 1..=30)) {
        gauss_bonnet_all_precisions(&s)?;
    }

    #[test]
    fn t01_gauss_bonnet_on_random_surfaces_with_boundary(s in strategies::surface_with_boundary(6)) {
        gauss_bonnet_all_precisions(&s)?;
    }
}

/// An interior edge whose cross ratio `ℓ_il ℓ_jk / (ℓ_ki ℓ_lj)` involves four distinct
/// edges, and the edge `jk` of its numerator: scaling `ℓ_jk` alone changes that cross
/// ratio by the same factor, so the two metrics are not conformally equivalent (T17).
fn numerator_edge(s: &Surface) -> Option<usize> {
    s.mesh.edges().find_map(|e| {
        let hs = cross_ratio_halfedges(&s.mesh, e)?;
        let ids: Vec<usize> = hs.iter().map(|h| h.edge().idx()).collect();
        let distinct = (0..4).all(|a| (0..a).all(|b| ids[a] != ids[b]));
        (distinct && !ids.contains(&e.idx())).then_some(ids[1])
    })
}

#[test]
fn t17_scaled_random_surfaces_are_equivalent_and_a_one_edge_change_is_not() {
    let mut runner = TestRunner::new(crate::support::proptest_config(24, 2000));
    let strategy = prop_oneof![
        strategies::closed_surface(0..=3, 1..=30),
        strategies::surface_with_boundary(6),
    ]
    .prop_flat_map(|s| {
        // Mild rational factors s_v ∈ [1, 1 + 1/64]: scaled triangles stay valid.
        let n = s.mesh.n_vertices();
        (Just(s), proptest::collection::vec(0u32..=256, n))
    });
    let (controls, total) = (Cell::new(0usize), Cell::new(0usize));
    runner
        .run(&strategy, |(s, ks)| {
            let factors: Vec<Rational> = ks
                .iter()
                .map(|&k| Rational::from((16384 + k, 16384)))
                .collect();
            let metric = strategies::scale_metric(&s, &factors);
            prop_assume!(validate_metric(&s.mesh, &metric).is_ok());
            let scaled = Surface {
                metric,
                ..s.clone()
            };
            total.set(total.get() + 1);
            let (l, lt) = (exact_lengths(&s), exact_lengths(&scaled));
            let v = check_conformal_equivalence_exact(&s.mesh, l, lt);
            prop_assert!(v.holds(), "{}: {v:?}", scaled.name);
            if let Some(jk) = numerator_edge(&scaled) {
                let mut bent = lt.to_vec();
                bent[jk] = Rational::from(&bent[jk] * 4095) / 4096;
                if validate_metric(&s.mesh, &Metric::Lengths(bent.clone())).is_ok() {
                    let v = check_conformal_equivalence_exact(&s.mesh, l, &bent);
                    prop_assert!(
                        matches!(
                            v,
                            Verdict::Fails {
                                certified: true,
                                ..
                            }
                        ),
                        "{}: one-edge change accepted: {v:?}",
                        scaled.name
                    );
                    controls.set(controls.get() + 1);
                }
            }
            Ok(())
        })
        .unwrap_or_else(|e| panic!("{e}"));
    let (controls, total) = (controls.get(), total.get());
    assert!(
        controls * 2 >= total,
        "negative control ran in {controls} of {total} cases"
    );
}
