//! The negative controls (`penner::oracle::controls`) on the built-in corpus: every control
//! that applies to a surface fails there (a control that holds is a check blind to its
//! perturbation) while the unperturbed check does not, each fails somewhere, and every check
//! of the registry has one.

use penner::oracle::precision::Prec;
use penner::oracle::registry::{by_id, run_one, Outcome};
use penner::oracle::{catalogue, controls, corpus};
use penner::scalar::Precision;
use penner::theorems::{Settings, Verdict};
use std::collections::BTreeMap;

#[test]
fn every_applicable_control_fails_on_the_corpus() {
    let precs = [
        Prec::F64,
        Prec::Mpfr(Precision::new(128).unwrap()),
        Prec::Exact,
    ];
    let settings = Settings::default();
    let mut failed = BTreeMap::<&str, usize>::new();
    let mut bad = Vec::new();
    for case in corpus::standard() {
        for c in controls::controls() {
            for &p in &precs {
                let Some(row) = run_one(&c, &case, p, &settings) else {
                    continue;
                };
                match &row.outcome {
                    Outcome::Verdict(Verdict::Fails { witnesses, .. }) => {
                        assert!(!witnesses.is_empty(), "{} {} {p}", case.name, c.id);
                        *failed.entry(c.id).or_default() += 1;
                        // The unperturbed check does not fail there: the failure is the
                        // perturbation's doing.
                        let check = by_id(c.id.trim_end_matches("-NC")).unwrap();
                        if let Some(r) = run_one(&check, &case, p, &settings) {
                            assert!(
                                !matches!(r.outcome, Outcome::Verdict(Verdict::Fails { .. })),
                                "{} fails unperturbed on {} at {p}",
                                check.id,
                                case.name
                            );
                        }
                    }
                    Outcome::Verdict(Verdict::NotApplicable { reason }) => {
                        assert!(!reason.is_empty(), "{} {} {p}", case.name, c.id);
                    }
                    other => bad.push(format!("{} {} {p}: {other:?}", case.name, c.id)),
                }
            }
        }
    }
    assert!(
        bad.is_empty(),
        "controls that did not fail:\n{}",
        bad.join("\n")
    );
    // Each control applies to, and fails on, some corpus surface.
    for c in controls::controls() {
        assert!(failed.contains_key(c.id), "{} never ran: {failed:?}", c.id);
    }
}

#[test]
fn every_registry_check_has_a_negative_control() {
    let ids: Vec<&str> = controls::controls().iter().map(|c| c.id).collect();
    for check in catalogue() {
        // T21P certifies its result with T21's `check_all_edges_delaunay`, which T21-NC
        // exercises.
        if check.id == "T21P" {
            continue;
        }
        let want = format!("{}-NC", check.id);
        assert!(ids.contains(&want.as_str()), "no {want} among {ids:?}");
    }
    // Control IDs are unique and each names a check of the registry.
    let mut sorted = ids.clone();
    sorted.dedup();
    assert_eq!(sorted.len(), ids.len(), "{ids:?}");
    for id in ids {
        let base = id.trim_end_matches("-NC");
        assert!(catalogue().iter().any(|c| c.id == base), "{id}");
    }
}

#[test]
fn controls_on_the_other_three_edge_surface_apply_only_to_their_own() {
    // T18-NC and T19-NC run on the two-triangle sphere and the one-vertex torus only.
    let settings = Settings::default();
    let corpus = corpus::standard();
    for (id, name) in [
        ("T18-NC", "two-triangle sphere"),
        ("T19-NC", "one-vertex torus"),
    ] {
        let c = controls::by_id(id).unwrap();
        for case in &corpus {
            let row = run_one(&c, case, Prec::Exact, &settings).unwrap();
            let fails = matches!(row.outcome, Outcome::Verdict(Verdict::Fails { .. }));
            assert_eq!(fails, case.name.starts_with(name), "{id} on {}", case.name);
        }
    }
}
