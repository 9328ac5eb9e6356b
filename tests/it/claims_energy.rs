//! The `energy` claim of `penner certify`: E(u) and ∇E(u) of the uniformization energy,
//! decided by MPFR interval enclosures (holds, refuted, undecided, bad input).

use crate::cli::tetrahedron_json;
use crate::support::{certify_expecting, counterexample, scratch};
use serde_json::{json, Value};

/// `E(0) = 8·Cl₂(π/3)` on the regular unit tetrahedron (every face contributes
/// `2·3·Л(π/3) = 2·Cl₂(π/3)`, and Л(π/3) = ⅓Cl₂(π/3)): the Gieseking-type constant
/// `Cl₂(π/3) = 1.01494160640965362502120255427452028594168930753029979…` times 8, from the
/// literature (not computed by penner).
const E_TETRA: &str = "8.11953285127722900016962043419616228753351446024239832";
/// π to 60 digits: with targets 2π the gradient is 2π − π = π at every vertex.
const PI: &str = "3.14159265358979323846264338327950288419716939937510582097494459";

fn claim(energy: &str, gradient: [&str; 4], eps: &str) -> Value {
    json!({"penner_claim": 1, "id": "e", "kind": "energy", "surface": tetrahedron_json(),
           "u": ["0", "0", "0", "0"], "energy": energy, "gradient": gradient, "epsilon": eps})
}

#[test]
fn t32_certify_energy_holds_refuted_undecided() {
    let d = scratch("claims-energy");
    let (a, _) = certify_expecting(
        &d,
        "holds.json",
        &claim(E_TETRA, [PI; 4], "1e-45"),
        0,
        "holds",
    );
    assert_eq!(a["certified"], true, "{a}");
    // Negative controls: E off by 10⁻³, one gradient entry off by 10⁻³.
    let (a, _) = certify_expecting(
        &d,
        "e.json",
        &claim(
            "8.1205328512772290001696204341961622875335",
            [PI; 4],
            "1e-6",
        ),
        1,
        "refuted",
    );
    assert_eq!(counterexample(&a), "energy", "{a}");
    let (a, _) = certify_expecting(
        &d,
        "g.json",
        &claim(E_TETRA, [PI, PI, "3.1425926535897932384626", PI], "1e-6"),
        1,
        "refuted",
    );
    assert_eq!(counterexample(&a), "v2 (∂E/∂u)", "{a}");
    // ε = 10⁻⁴⁵ below what 128 bits (≈ 38 digits) can separate: undecided at that cap.
    let mut capped = claim(E_TETRA, [PI; 4], "1e-45");
    capped["max_bits"] = json!(128);
    let (a, _) = certify_expecting(&d, "u.json", &capped, 2, "undecided");
    assert_eq!(a["certified"], false);
    // ε = 0 with truncated decimals of irrational values: refuted (they differ).
    certify_expecting(&d, "z.json", &claim(E_TETRA, [PI; 4], "0"), 1, "refuted");
}

#[test]
fn t32_certify_energy_with_targets_and_scale_factors() {
    let d = scratch("claims-energy-targets");
    // Targets 3: gradient 3 − π. A uniform u = c adds c(ΣΘ − π|F|) = c(12 − 4π) to E.
    let mut c = claim(E_TETRA, [PI; 4], "1e-30");
    let g = "-0.141592653589793238462643383279502884197169399375105820974945";
    c["targets"] = json!(["3", "3", "3", "3"]);
    c["gradient"] = json!([g, g, g, g]);
    certify_expecting(&d, "t.json", &c, 0, "holds");
    // u = 1/2 everywhere: E = 8·Cl₂(π/3) + ½(12 − 4π) = E_TETRA + 6 − 2π.
    c["u"] = json!(["1/2", "1/2", "1/2", "1/2"]);
    c["energy"] = json!("7.83634754409764252324433366763715651913917566149218667805011");
    certify_expecting(&d, "tu.json", &c, 0, "holds");
    // Control: the same claim with the 2π default targets is refuted.
    c.as_object_mut().unwrap().remove("targets");
    certify_expecting(&d, "tu2.json", &c, 1, "refuted");
}

#[test]
fn t32_certify_energy_refuses_malformed_claims() {
    let d = scratch("claims-energy-bad");
    let mut no_gradient = claim(E_TETRA, [PI; 4], "1e-9");
    no_gradient.as_object_mut().unwrap().remove("gradient");
    let mut short_u = claim(E_TETRA, [PI; 4], "1e-9");
    short_u["u"] = json!(["0", "0"]);
    let mut bad_targets = claim(E_TETRA, [PI; 4], "1e-9");
    bad_targets["targets"] = json!(["x", "1", "1", "1"]);
    let mut no_energy = claim(E_TETRA, [PI; 4], "1e-9");
    no_energy.as_object_mut().unwrap().remove("energy");
    let mut stray = claim(E_TETRA, [PI; 4], "1e-9");
    stray["weights"] = json!([]);
    for (name, c, mention) in [
        ("g.json", no_gradient, "gradient"),
        ("u.json", short_u, "u:"),
        ("t.json", bad_targets, "targets[0]"),
        ("e.json", no_energy, "energy"),
        ("w.json", stray, "weights"),
    ] {
        let (_, err) = certify_expecting(&d, name, &c, 3, "bad_input");
        assert!(err.contains(mention), "{name}: {err}");
    }
}

/// Every field of an `energy` claim is used by the re-check: the closed-form claim that
/// holds is never `holds` with `u` moved at one vertex (energy and gradient kept), targets
/// of 3 (gradient kept), the energy or one gradient entry off by `10⁻²²`, or `ε = 0`.
#[test]
fn t32_energy_claim_fields_u_targets_energy_gradient_epsilon_are_each_used() {
    use penner::oracle::certify::{certify, ClaimVerdict};
    use penner::oracle::claim::parse_value;
    let verdict = |c: &Value| certify(&parse_value(c).unwrap()).unwrap().verdict;
    let base = claim(E_TETRA, [PI; 4], "1e-30");
    assert_eq!(verdict(&base), ClaimVerdict::Holds);
    let with = |f: &dyn Fn(&mut Value)| {
        let mut c = base.clone();
        f(&mut c);
        c
    };
    let off = "8.11953285127722900016972043419616228753351446024239832";
    let g_off = "3.14159265358979323846274338327950288419716939937510582097494459";
    let altered = [
        ("u moved at v0", with(&|c| c["u"][0] = json!("1/1000"))),
        (
            "targets 3",
            with(&|c| c["targets"] = json!(["3", "3", "3", "3"])),
        ),
        ("energy 1e-22 off", with(&|c| c["energy"] = json!(off))),
        (
            "gradient 1e-20 off",
            with(&|c| c["gradient"][1] = json!(g_off)),
        ),
        ("ε = 0", with(&|c| c["epsilon"] = json!("0"))),
    ];
    for (what, c) in altered {
        assert_ne!(verdict(&c), ClaimVerdict::Holds, "{what}");
    }
}
