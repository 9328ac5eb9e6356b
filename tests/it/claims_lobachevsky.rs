//! `penner certify` claims of kind `lobachevsky` (B52 enclosure): holds, refuted,
//! undecided and malformed, end to end through the binary.

use crate::support::{certify, certify_expecting, scratch};
use serde_json::json;

/// Л(1/2) = ½ Cl₂(1) to 30 digits (independent: the tangent-number series at 300 bits).
fn half_value() -> rug::Float {
    let x = rug::Float::with_val(53, 0.5);
    penner::special::lobachevsky_tangent_series(&x, 300).unwrap()
}

#[test]
fn b52_lobachevsky_claims_hold_refute_and_stay_undecided_honestly() {
    let dir = scratch("lobachevsky-claims");
    let v = half_value();
    let y = format!("{v:.40}");
    let claim = |x: &str, y: &str, eps: &str| json!({"penner_claim": 1, "id": "l", "kind": "lobachevsky", "x": x, "y": y, "epsilon": eps});
    let (a, _) = certify_expecting(&dir, "holds.json", &claim("0.5", &y, "1e-30"), 0, "holds");
    assert_eq!(a["certified"], json!(true));
    // Negative control: the same value shifted by 1e-25 with ε = 1e-30 is refuted.
    let shifted = format!("{:.40}", rug::Float::with_val(300, &v + 1e-25));
    let (a, _) = certify_expecting(
        &dir,
        "off.json",
        &claim("0.5", &shifted, "1e-30"),
        1,
        "refuted",
    );
    assert_eq!(a["certified"], json!(true));
    // Π-periodicity through the claim: Л(1/2 + 10⁶π) is not Л(1/2) for a rational x, but
    // Л(π/2) = 0 within 1e-30 at x = 3.14159…/2 to 40 digits holds.
    certify_expecting(
        &dir,
        "halfpi.json",
        &claim("1.570796326794896619231321691639751442098", "0", "1e-30"),
        0,
        "holds",
    );
    // A tolerance at the exact distance cannot be separated: undecided, never refuted.
    certify_expecting(&dir, "zero.json", &claim("0", "0", "0"), 2, "undecided");
    // x beyond what max_bits resolves modulo π: undecided.
    let mut c = claim("1e400", "0", "1e-3");
    c["max_bits"] = json!(256);
    certify_expecting(&dir, "huge.json", &c, 2, "undecided");
    // Malformed: a surface, a missing y, a negative epsilon.
    for (name, mut bad, word) in [
        ("surf.json", claim("0.5", &y, "0"), "surface"),
        (
            "noy.json",
            json!({"penner_claim": 1, "kind": "lobachevsky", "x": "0.5", "epsilon": "0"}),
            "y",
        ),
        ("neg.json", claim("0.5", &y, "-1"), "epsilon"),
    ] {
        if name == "surf.json" {
            bad["surface"] =
                json!({"vertices": 3, "faces": [[0, 1, 2]], "lengths": ["1", "1", "1"]});
        }
        let (code, a, err) = certify(&dir, name, &bad);
        assert_eq!(
            (code, a["verdict"].as_str()),
            (Some(3), Some("bad_input")),
            "{name}"
        );
        assert!(err.contains(word), "{name}: {err}");
    }
}
