//! The `hyperbolic_uniformization` claim of `penner certify` (B39): the certificate of
//! `uniformize_hyperbolic` round-trips to `holds`; a `u` computed outside penner (a closed
//! form in MPFR) holds too; a perturbed `u`, a wrong target, a claimed residual bound below
//! the residual and targets without hyperbolic area are refuted, each with its proof; too
//! few bits leave the claim undecided; malformed fields are errors naming the field.

use crate::uniformization_hyperbolic::{closed_form_u, random_lengths};
use penner::mesh::{builders, Mesh};
use penner::oracle::certify::{certify, Answer, ClaimVerdict};
use penner::oracle::claim::{parse_value, ClaimError};
use penner::scalar::{Mpfr, Precision, Real};
use penner::uniformization::hyperbolic::{uniformize_hyperbolic, HyperbolicOptions};
use penner::uniformization::hyperbolic_certificate::{
    certify_hyperbolic, refine_hyperbolic, Existence,
};
use penner::uniformization::hyperbolic_claim::{to_claim, ClaimData};
use penner::uniformization::Targets;
use rug::float::Constant;
use rug::{Float, Rational};
use serde_json::{json, Value};

/// The certified claim of a flat-target (`Θ ≡ 2π`) hyperbolic uniformization of `(m, l)`
/// refined and certified at `bits`, and the certified box radius.
fn certified_claim(m: &Mesh, l: &[f64], bits: u32) -> (Value, f64) {
    let targets = Targets::flat(m.n_vertices());
    let sol = uniformize_hyperbolic(m, l, &targets, &HyperbolicOptions::default()).unwrap();
    assert!(sol.converged(), "{:?}", sol.stop);
    let prec = Precision::new(u64::from(bits)).unwrap();
    let tolerance = 2f64.powi(-(bits as i32 - 56));
    let r = refine_hyperbolic::<Mpfr>(&sol, prec, tolerance, 60).unwrap();
    let u: Vec<Rational> = r.u.iter().map(|x| x.to_rational().unwrap()).collect();
    let cert = certify_hyperbolic(&sol, &u, bits).unwrap();
    let Existence::Holds { radius, .. } = cert.existence else {
        panic!("not certified: {:?}", cert.existence);
    };
    let data = ClaimData {
        mesh: &sol.t0,
        lengths: &sol.lengths,
        flips: &sol.flips,
        targets: &targets,
        u: &u,
    };
    let claim = to_claim(&data, radius, cert.residual_norm2, bits);
    (claim, radius)
}

fn answer(v: &Value) -> Answer {
    let c = parse_value(v).unwrap_or_else(|e| panic!("{e}: {v}"));
    certify(&c).unwrap()
}

fn refuted_at(a: &Answer) -> String {
    assert_eq!(a.verdict, ClaimVerdict::Refuted, "{:?}", a.witnesses);
    assert!(a.certified);
    a.counterexample.as_ref().unwrap().element.clone()
}

fn exact(v: &Value) -> Rational {
    penner::io::json::exact_number(v, "test").unwrap()
}

/// `u` shifted by `delta` at every vertex, as exact strings.
fn shifted(claim: &Value, delta: &Rational) -> Value {
    let u: Vec<String> = claim["u"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| Rational::from(&exact(x) + delta).to_string())
        .collect();
    json!(u)
}

/// B39: the written claim re-checks to `holds` (certified, the distance within the box);
/// on the equilateral genus-2 surface the claimed `u` is within `radius` of the closed form
/// (B68, an independent oracle); `u + 10⁻⁶` is refuted at a vertex (no solution in the
/// box), a wrong target at the vertex, a residual bound of `10⁻³⁰` at `u + 10⁻²⁰` as the
/// residual bound; at 128 bits the 256-bit claim is undecided, never refuted.
#[test]
fn b39_hyperbolic_claim_round_trip_holds_and_is_refuted_only_with_a_proof() {
    // The first random genus-2 surface that converges (with flips every one does, B87),
    // else genus 3 with one vertex and random lengths.
    let candidates = (0..24u64).map(|k| {
        let (seed, nv) = (k % 8, 4 - (k / 8) as u32);
        let m = builders::random_surface(2, nv, seed).unwrap();
        let l = random_lengths(&m, 1.0, 1.5, seed);
        (m, l)
    });
    let genus3 = builders::genus(3).unwrap();
    let random = candidates
        .chain(std::iter::once((
            genus3.clone(),
            random_lengths(&genus3, 1.0, 1.5, 1),
        )))
        .find(|(m, l)| {
            let t = Targets::flat(m.n_vertices());
            uniformize_hyperbolic(m, l, &t, &HyperbolicOptions::default())
                .is_ok_and(|s| s.converged())
        })
        .expect("a random genus-2 surface solved");
    let cases = [(builders::genus(2).unwrap(), vec![1.0; 9]), random];
    for (k, (m, l)) in cases.iter().enumerate() {
        let (claim, radius) = certified_claim(m, l, 256);
        let a = answer(&claim);
        assert_eq!(
            a.verdict,
            ClaimVerdict::Holds,
            "case {k}: {:?}",
            a.witnesses
        );
        assert!(a.certified && a.kind == "hyperbolic_uniformization");
        let distance = a.max_discrepancy.unwrap();
        assert!(distance <= radius, "case {k}: {distance:e} > {radius:e}");
        if k == 0 {
            // B68: |u − u*| ≤ radius against the closed form at 512 bits.
            let u0 = Float::with_val(512, &exact(&claim["u"][0]));
            let gap = (u0 - closed_form_u(2, 1.0, 512)).abs().to_f64();
            assert!(gap <= radius, "closed form gap {gap:e} > radius {radius:e}");
        }
        // Negative control: u + 10⁻⁶ at every vertex.
        let mut bad = claim.clone();
        bad["u"] = shifted(&claim, &Rational::from((1, 1_000_000)));
        assert!(
            refuted_at(&answer(&bad)).starts_with('v'),
            "case {k}: perturbed u"
        );
        // A wrong target at v0 (still with hyperbolic area).
        let mut bad = claim.clone();
        bad["targets"][0] = json!("3/2");
        assert_eq!(refuted_at(&answer(&bad)), "v0", "case {k}: wrong target");
        // A residual bound below the residual: u + 10⁻²⁰ in a box of radius 10⁻¹⁰.
        let mut bad = claim.clone();
        bad["u"] = shifted(&claim, &Rational::from((1, 10u128.pow(20))));
        bad["radius"] = json!("1e-10");
        bad["residual_bound"] = json!("1e-30");
        assert_eq!(refuted_at(&answer(&bad)), "residual_bound", "case {k}");
        // Too few bits for the claimed residual bound: undecided, not refuted.
        let mut low = claim.clone();
        low["max_bits"] = json!(128);
        let a = answer(&low);
        assert_eq!(a.verdict, ClaimVerdict::Undecided, "case {k}: {a:?}");
        assert!(!a.certified);
    }
}

/// A `u` computed outside penner: the unit tetrahedron read as a hyperbolic metric with
/// cone angles `π/2` (corners `π/6`, `cosh ℓ̃ = 3 + 2√3`, `sinh²(ℓ̃/2) = 1 + √3`) has
/// `u* = ½ ln((1 + √3)/sinh²(½))` at every vertex, here in MPFR at 300 bits, stated as that
/// binary fraction: `holds`; the closed form of the wrong corner `π/5` is refuted.
#[test]
fn b39_hyperbolic_claim_of_a_closed_form_holds() {
    let u_star = |corner_over_pi: u32| -> String {
        let p = 300;
        let c = Float::with_val(p, Float::with_val(p, Constant::Pi) / corner_over_pi).cos();
        // cosh ℓ̃ = c/(1 − c) for an equilateral triangle of angle α, c = cos α.
        let cosh = Float::with_val(p, &c / Float::with_val(p, 1 - &c));
        let s2 = Float::with_val(p, (cosh - 1u32) / 2u32);
        let sh = Float::with_val(p, 0.5).sinh();
        let u = Float::with_val(p, s2 / Float::with_val(p, &sh * &sh)).ln() / 2u32;
        u.to_rational().unwrap().to_string()
    };
    let claim = |u: String| {
        json!({"penner_claim": 1, "kind": "hyperbolic_uniformization", "max_bits": 256,
               "surface": crate::cli::tetrahedron_json(), "targets": vec!["1/2"; 4], "u": vec![u; 4],
               "radius": "1e-40", "residual_bound": "1e-40"})
    };
    let a = answer(&claim(u_star(6)));
    assert_eq!(a.verdict, ClaimVerdict::Holds, "{:?}", a.witnesses);
    assert!(a.certified);
    assert_eq!(refuted_at(&answer(&claim(u_star(5)))), "v0");
}

/// Targets without hyperbolic area (Gauss–Bonnet: `Σ(2π − Θ_i) ≤ 2πχ`) are refuted, exactly:
/// `Θ ≡ 2π` on the torus and on the sphere; the control `Θ = π` on the torus has area
/// and is not refuted by Gauss–Bonnet.
#[test]
fn b39_hyperbolic_claim_without_area_is_refuted_by_gauss_bonnet() {
    use penner::io::{json::to_value, Metric, Surface};
    let lengths = Metric::Lengths(vec![1.into(), 1.into(), Rational::from((3, 2))]);
    let torus =
        to_value(&Surface::new("torus", builders::one_vertex_torus(), lengths, None).unwrap());
    let claim = |surface: &Value, targets: Value, u: Value| {
        json!({"penner_claim": 1, "kind": "hyperbolic_uniformization", "surface": surface,
               "targets": targets, "u": u, "radius": "1", "residual_bound": "10"})
    };
    let t = claim(&torus, json!(["2"]), json!(["0"]));
    assert_eq!(refuted_at(&answer(&t)), "targets (component of v0)");
    let s = claim(
        &crate::cli::tetrahedron_json(),
        json!(vec!["2"; 4]),
        json!(vec!["0"; 4]),
    );
    assert_eq!(refuted_at(&answer(&s)), "targets (component of v0)");
    // Control: a cone of angle π on the torus leaves area π.
    let c = answer(&claim(&torus, json!(["1"]), json!(["0"])));
    let by_gb = c
        .counterexample
        .as_ref()
        .is_some_and(|w| w.element.starts_with("targets"));
    assert!(!by_gb, "{c:?}");
}

/// Malformed fields are errors naming the field; the unmodified claim parses.
#[test]
fn b39_malformed_hyperbolic_claims_are_typed_errors() {
    let good = json!({"penner_claim": 1, "kind": "hyperbolic_uniformization",
                      "surface": crate::cli::tetrahedron_json(), "targets": vec!["1/2"; 4],
                      "u": vec!["1.15"; 4], "radius": "1e-3", "residual_bound": "1"});
    assert!(parse_value(&good).is_ok());
    let refused = |edit: &dyn Fn(&mut Value), field: &str| {
        let mut v = good.clone();
        edit(&mut v);
        let e: ClaimError = parse_value(&v).expect_err(field);
        assert!(e.0.contains(field), "{field}: {e}");
    };
    refused(&|v| v["radius"] = json!("0"), "radius: must be positive");
    refused(
        &|v| v["residual_bound"] = json!("-1"),
        "residual_bound: must be ≥ 0",
    );
    refused(&|v| v["u"] = json!(vec!["0"; 3]), "u: 3 entries");
    refused(&|v| v["targets"][2] = json!("-1"), "targets: ");
    refused(&|v| v["targets"][1] = json!("one"), "targets[1]");
    refused(&|v| v["epsilon"] = json!("0"), "epsilon");
    refused(
        &|v| {
            v.as_object_mut().unwrap().remove("radius");
        },
        "radius: required",
    );
    refused(
        &|v| {
            v["surface"] = json!({"vertices": 3, "faces": [[0, 1, 2]], "lengths": ["1", "1", "1"]});
            v["targets"] = json!(vec!["1"; 3]);
            v["u"] = json!(vec!["0"; 3]);
        },
        "surface: ",
    );
}

/// The re-check uses every field of a `hyperbolic_uniformization` claim: the certified
/// claim of a random genus-2 surface holds, and with its radius shrunk, its residual bound
/// set to 0, a target moved by π/100 between two vertices, or (when it has flips) its last
/// flip dropped, it is never `holds`.
#[test]
fn hyperbolic_claim_fields_radius_residual_targets_flips_are_each_used() {
    let (claim, _) = (0..8u64)
        .find_map(|seed| {
            let m = builders::random_surface(2, 4, seed).ok()?;
            let l = random_lengths(&m, 1.0, 1.5, seed);
            let t = Targets::flat(m.n_vertices());
            let sol = uniformize_hyperbolic(&m, &l, &t, &HyperbolicOptions::default()).ok()?;
            sol.converged().then(|| certified_claim(&m, &l, 256))
        })
        .expect("a random genus-2 surface converges");
    assert_eq!(answer(&claim).verdict, ClaimVerdict::Holds);
    for field in ["radius", "residual_bound", "targets", "u"] {
        assert!(claim.get(field).is_some(), "the claim has no `{field}`");
    }
    let with = |f: &dyn Fn(&mut Value)| {
        let mut c = claim.clone();
        f(&mut c);
        c
    };
    let mut altered = vec![
        ("radius 1e-200", with(&|c| c["radius"] = json!("1e-200"))),
        (
            "residual bound 0",
            with(&|c| c["residual_bound"] = json!("0")),
        ),
        (
            "targets moved by π/100",
            with(&|c| {
                c["targets"][0] = json!("201/100");
                c["targets"][1] = json!("199/100");
            }),
        ),
    ];
    if claim["flips"].as_array().is_some_and(|f| !f.is_empty()) {
        altered.push((
            "last flip dropped",
            with(&|c| {
                c["flips"].as_array_mut().expect("flips").pop();
            }),
        ));
    }
    for (what, c) in altered {
        let verdict = parse_value(&c)
            .ok()
            .and_then(|c| certify(&c).ok())
            .map(|a| a.verdict);
        assert_ne!(verdict, Some(ClaimVerdict::Holds), "{what}: still holds");
    }
}
