//! `penner certify` claims of kinds `circle_packing` (plane circles, sphere caps) and
//! `circle_pattern` (B98): exact configurations, maximal packings computed by
//! `circles::maximal`, cone angles against an independent law-of-cosines evaluation at 400
//! bits; negative controls (a perturbed radius, a mirrored layout, a shifted angle) and bad
//! input.

use crate::support::{certify, certify_expecting, counterexample, scratch};
use penner::circles::maximal::sphere::exact_caps;
use penner::circles::maximal::tangency::exact_circles;
use penner::circles::maximal::{maximal_disk, maximal_sphere, Options};
use penner::mesh::builders::{icosahedron, random_planar};
use penner::mesh::Mesh;
use penner::oracle::certify::{certify as answer, ClaimVerdict};
use penner::oracle::claim::parse_value;
use penner::scalar::{Mpfr, Precision};
use rug::{Float, Rational};
use serde_json::{json, Value};

fn prec(bits: u64) -> Precision {
    Precision::new(bits).unwrap()
}

fn q(x: &Rational) -> Value {
    Value::String(x.to_string())
}

/// The triangulation of `mesh` as a claim surface without a metric.
fn faces(mesh: &Mesh) -> Value {
    json!({"vertices": mesh.n_vertices(), "faces": mesh.face_list()})
}

fn verdict(claim: &Value) -> (ClaimVerdict, String) {
    let c = parse_value(claim).unwrap_or_else(|e| panic!("{e}: {claim}"));
    let a = answer(&c).unwrap();
    let first = a
        .counterexample
        .as_ref()
        .map(|w| format!("{}: {}", w.element, w.detail))
        .unwrap_or_default();
    (a.verdict, first)
}

/// Circles of radii 1, 2, 3 centred at (0, 0), (3, 0), (0, 4): the 3-4-5 triangle, tangent
/// exactly (3 = 1 + 2, 4 = 1 + 3, 5 = 2 + 3).
fn three_four_five(eps: &str) -> Value {
    json!({"penner_claim": 1, "id": "345", "kind": "circle_packing",
           "surface": {"vertices": 3, "faces": [[0, 1, 2]]},
           "centres": [["0", "0"], ["3", "0"], ["0", "4"]], "radii": ["1", "2", "3"],
           "epsilon": eps})
}

#[test]
fn b98_plane_packing_claims_hold_refute_and_stay_undecided_honestly() {
    let dir = scratch("circle-packing-claims");
    let (a, _) = certify_expecting(&dir, "345.json", &three_four_five("1e-30"), 0, "holds");
    assert_eq!(a["certified"], json!(true));
    // The exact tie |0| = ε = 0 cannot be separated by enclosures: undecided, not refuted.
    certify_expecting(&dir, "345-0.json", &three_four_five("0"), 2, "undecided");
    // Negative controls: radius 3 → 3 + 10⁻²⁰ puts two tangencies 10⁻²⁰ off (ε = 10⁻³⁰).
    let mut off = three_four_five("1e-30");
    off["radii"][2] = json!("3.00000000000000000001");
    let (a, _) = certify_expecting(&dir, "off.json", &off, 1, "refuted");
    assert!(counterexample(&a).starts_with("edge "), "{a}");
    assert_eq!(a["witnesses"].as_array().unwrap().len(), 2, "{a}");
    // The mirror image (y → −y) keeps every tangency but turns the face clockwise.
    let mut mirror = three_four_five("1e-30");
    mirror["centres"][2] = json!(["0", "-4"]);
    let (a, _) = certify_expecting(&dir, "mirror.json", &mirror, 1, "refuted");
    assert_eq!(counterexample(&a), "face f0 (v0, v1, v2)", "{a}");
    // The two-triangle sphere on the same circles: no closed surface packs in the plane;
    // its second face is proved clockwise.
    let mut sphere = three_four_five("1e-30");
    sphere["surface"] = json!({"vertices": 3, "faces": [[0, 1, 2], [0, 2, 1]]});
    let (a, _) = certify_expecting(&dir, "sphere.json", &sphere, 1, "refuted");
    assert_eq!(counterexample(&a), "face f1 (v0, v2, v1)", "{a}");
    // A metric, when given, is not read: the triangulation alone matters.
    let mut with_metric = three_four_five("1e-30");
    with_metric["surface"]["lengths"] = json!(["1", "1", "1"]);
    certify_expecting(&dir, "metric.json", &with_metric, 0, "holds");
}

#[test]
fn b98_maximal_disk_packings_certify_as_claims_and_a_moved_circle_is_refuted() {
    let mesh = random_planar(60, 5).unwrap().mesh;
    let p = maximal_disk::<Mpfr>(&mesh, prec(128), &Options::default()).unwrap();
    let circles = exact_circles(&p.circles).unwrap();
    let claim = json!({"penner_claim": 1, "kind": "circle_packing", "surface": faces(&mesh),
        "centres": circles.iter().map(|c| json!([q(&c.centre[0]), q(&c.centre[1])])).collect::<Vec<_>>(),
        "radii": circles.iter().map(|c| q(&c.radius)).collect::<Vec<_>>(),
        "epsilon": "1e-30"});
    assert_eq!(verdict(&claim).0, ClaimVerdict::Holds);
    // Negative control: an interior circle moved by 10⁻²⁰ along x.
    let w = p.interior.iter().position(|&b| b).unwrap();
    let mut moved = claim.clone();
    let x: Rational = &circles[w].centre[0] + Rational::from((1, 10u128.pow(20)));
    moved["centres"][w][0] = q(&x);
    let (v, first) = verdict(&moved);
    assert_eq!(v, ClaimVerdict::Refuted);
    assert!(
        first.contains(&format!("v{w}–")) || first.contains(&format!("–v{w})")),
        "{first}"
    );
    // Two neighbouring circles swapped: orientations flip, proved exactly.
    let h = mesh.vertex_halfedge(penner::mesh::Vertex(w as u32));
    let n = mesh.tip(h).idx();
    let mut swapped = claim.clone();
    let (cw, cn) = (claim["centres"][w].clone(), claim["centres"][n].clone());
    swapped["centres"][w] = cn;
    swapped["centres"][n] = cw;
    let (rw, rn) = (claim["radii"][w].clone(), claim["radii"][n].clone());
    swapped["radii"][w] = rn;
    swapped["radii"][n] = rw;
    let (v, first) = verdict(&swapped);
    assert_eq!(v, ClaimVerdict::Refuted);
    assert!(first.contains("not positively oriented"), "{first}");
}

fn cap_json(c: &penner::circles::maximal::sphere::ExactCap) -> Value {
    json!({"normal": c.normal.iter().map(q).collect::<Vec<_>>(), "height": q(&c.height)})
}

#[test]
fn b98_sphere_cap_packings_certify_and_a_mirrored_or_shrunk_cap_is_refuted() {
    let mesh = icosahedron().mesh;
    let s = maximal_sphere::<Mpfr>(&mesh, 0, prec(128), &Options::default()).unwrap();
    let caps = exact_caps(&s.caps).unwrap();
    let claim = json!({"penner_claim": 1, "kind": "circle_packing", "surface": faces(&mesh),
        "caps": caps.iter().map(cap_json).collect::<Vec<_>>(), "epsilon": "1e-30"});
    assert_eq!(verdict(&claim).0, ClaimVerdict::Holds);
    // Negative control: cap 5's height raised by 10⁻²⁰ (a smaller cap) leaves its tangencies.
    let mut shrunk = caps.clone();
    shrunk[5].height += Rational::from((1, 10u128.pow(20)));
    let mut c = claim.clone();
    c["caps"] = shrunk.iter().map(cap_json).collect();
    let (v, first) = verdict(&c);
    assert_eq!(v, ClaimVerdict::Refuted);
    assert!(first.contains("v5"), "{first}");
    // The mirror image x → −x keeps every inversive distance and reverses every face.
    let mut mirrored = caps.clone();
    for cap in &mut mirrored {
        cap.normal[0] = -cap.normal[0].clone();
    }
    c["caps"] = mirrored.iter().map(cap_json).collect();
    let (v, first) = verdict(&c);
    assert_eq!(v, ClaimVerdict::Refuted);
    assert!(first.contains("not positively oriented"), "{first}");
}

/// Cone angles of the Eq. 9 metric by the law of cosines (`acos`) on 400-bit floats: an
/// evaluation independent of the half-angle formula the oracle encloses.
fn cosine_law_angles(mesh: &Mesh, r: &[Rational], phi: &[Rational]) -> Vec<Float> {
    let f = |x: &Rational| Float::with_val(400, x);
    let pi = Float::with_val(400, rug::float::Constant::Pi);
    let mut theta = vec![Float::with_val(400, 0); mesh.n_vertices()];
    let order = penner::io::json::edge_order(mesh);
    let mut phi_mesh = vec![Rational::new(); mesh.n_edges()];
    for (k, &e) in order.iter().enumerate() {
        phi_mesh[e].clone_from(&phi[k]);
    }
    let len = |h: penner::mesh::HalfEdge| {
        let (i, j) = (mesh.tail(h).idx(), mesh.tip(h).idx());
        let c = (Float::with_val(400, &pi * f(&phi_mesh[h.edge().idx()]))).cos();
        let l2: Float = f(&r[i]) * f(&r[i]) + f(&r[j]) * f(&r[j]) + 2 * f(&r[i]) * f(&r[j]) * c;
        l2.sqrt()
    };
    for h in mesh.halfedges() {
        if mesh.is_boundary_halfedge(h) {
            continue;
        }
        // The corner opposite h, at the tip of next(h).
        let (a, b, c) = (len(h), len(mesh.next(h)), len(mesh.prev(h)));
        let num = Float::with_val(400, &b * &b) + Float::with_val(400, &c * &c)
            - Float::with_val(400, &a * &a);
        let cos: Float = num / Float::with_val(400, 2 * Float::with_val(400, &b * &c));
        theta[mesh.opposite_vertex(h).idx()] += cos.acos();
    }
    theta
}

fn pattern_claim(
    mesh: &Mesh,
    r: &[Rational],
    phi: &[Rational],
    angles: &[Float],
    eps: &str,
) -> Value {
    json!({"penner_claim": 1, "kind": "circle_pattern", "surface": faces(mesh),
        "radii": r.iter().map(q).collect::<Vec<_>>(),
        "phi_over_pi": phi.iter().map(q).collect::<Vec<_>>(),
        "angles": angles.iter().map(|a| format!("{a:.60}")).collect::<Vec<_>>(),
        "epsilon": eps})
}

#[test]
fn b98_circle_pattern_claims_match_the_law_of_cosines_and_a_shifted_angle_is_refuted() {
    let dir = scratch("circle-pattern-claims");
    for (mesh, seed) in [
        (icosahedron().mesh, 3u64),
        (random_planar(30, 9).unwrap().mesh, 4),
    ] {
        let r: Vec<Rational> = (0..mesh.n_vertices())
            .map(|v| Rational::from(((v as u64 * 7 + seed) % 5 + 1, 3)))
            .collect();
        // Φ/π ∈ {0, 1/12, 1/3, 2/5, 1/2}: exact and irrational cosines.
        let choices = [(0, 1), (1, 12), (1, 3), (2, 5), (1, 2)];
        let phi: Vec<Rational> = (0..mesh.n_edges())
            .map(|e| Rational::from(choices[(e * 3 + seed as usize) % 5]))
            .collect();
        let angles = cosine_law_angles(&mesh, &r, &phi);
        let claim = pattern_claim(&mesh, &r, &phi, &angles, "1e-40");
        assert_eq!(verdict(&claim), (ClaimVerdict::Holds, String::new()));
        // Negative control: vertex 2's angle shifted by 10⁻³⁰ (ε = 10⁻⁴⁰).
        let mut shifted = angles.clone();
        shifted[2] += Float::with_val(400, 1e-30);
        let c = pattern_claim(&mesh, &r, &phi, &shifted, "1e-40");
        let (a, _) = certify_expecting(&dir, "shifted.json", &c, 1, "refuted");
        assert_eq!(counterexample(&a), "v2", "{a}");
        assert_eq!(a["witnesses"].as_array().unwrap().len(), 1, "{a}");
    }
}

/// Claims refused as bad input, with the word the message must contain.
fn malformed_cases() -> Vec<(&'static str, Value, &'static str)> {
    let pattern = json!({"penner_claim": 1, "kind": "circle_pattern",
        "surface": {"vertices": 3, "faces": [[0, 1, 2]]},
        "radii": ["1", "1", "1"], "phi_over_pi": ["0", "0", "0"],
        "angles": ["1", "1", "1"], "epsilon": "1e-9"});
    let set = |base: &Value, key: &str, v: Value| {
        let mut c = base.clone();
        if v.is_null() {
            c.as_object_mut().unwrap().remove(key);
        } else {
            c[key] = v;
        }
        c
    };
    let base = three_four_five("1e-30");
    let loop_face = json!({"vertices": 2, "faces": [[0, 1, 1]]});
    vec![
        (
            "radii-count",
            set(&base, "radii", json!(["1", "2"])),
            "radii",
        ),
        (
            "radius-zero",
            set(&base, "radii", json!(["1", "0", "3"])),
            "radii[1]",
        ),
        (
            "radius-neg",
            set(&base, "radii", json!(["1", "2", -3.0])),
            "radii[2]",
        ),
        (
            "radius-nan",
            set(&base, "radii", json!(["1", "NaN", "3"])),
            "radii[1]",
        ),
        (
            "radius-inf",
            set(&base, "radii", json!(["1", "inf", "3"])),
            "radii[1]",
        ),
        (
            "centre-short",
            set(&base, "centres", json!([["0"], ["3", "0"], ["0", "4"]])),
            "centres[0]",
        ),
        ("eps-neg", set(&base, "epsilon", json!("-1e-3")), "epsilon"),
        ("eps-missing", set(&base, "epsilon", Value::Null), "epsilon"),
        ("no-radii", set(&base, "radii", Value::Null), "radii"),
        (
            "both",
            set(
                &base,
                "caps",
                Value::Array(vec![json!({"normal": ["0", "0", "1"], "height": "0"}); 3]),
            ),
            "caps",
        ),
        (
            "improper-cap",
            set(
                &set(&set(&base, "centres", Value::Null), "radii", Value::Null),
                "caps",
                json!([{"normal": ["0", "0", "1"], "height": "1"}, {"normal": ["0", "1", "0"], "height": "0"}, {"normal": ["1", "0", "0"], "height": "0"}]),
            ),
            "caps[0]",
        ),
        ("typo", set(&base, "radius", json!("1")), "radius"),
        ("loop", set(&base, "surface", loop_face), "surface"),
        (
            "phi-range",
            set(&pattern, "phi_over_pi", json!(["0", "3/5", "0"])),
            "phi_over_pi[1]",
        ),
        (
            "phi-count",
            set(&pattern, "phi_over_pi", json!(["0", "0"])),
            "phi_over_pi",
        ),
        (
            "pattern-radius",
            set(&pattern, "radii", json!(["1", "-1", "1"])),
            "radii[1]",
        ),
        (
            "pattern-angles",
            set(&pattern, "angles", json!(["1", "1"])),
            "angles",
        ),
        ("pattern-caps", set(&pattern, "caps", json!([])), "caps"),
    ]
}

#[test]
fn b98_malformed_circle_claims_are_bad_input_naming_the_field() {
    let dir = scratch("circle-claims-bad");
    for (name, claim, word) in malformed_cases() {
        let (code, a, err) = certify(&dir, &format!("{name}.json"), &claim);
        assert_eq!(
            (code, a["verdict"].as_str()),
            (Some(3), Some("bad_input")),
            "{name}: {a} {err}"
        );
        assert!(err.contains(word), "{name}: {err}");
        assert!(!err.contains("panicked"), "{name}: {err}");
    }
}

/// Every field of a `circle_pattern` claim is used by the re-check: the claim that holds
/// (law-of-cosines angles computed here at 400 bits) is never `holds` with one radius
/// `10⁻²⁰` larger, one intersection angle changed, one angle shifted by `10⁻³⁰`, or
/// `ε = 0` (the angles are truncated decimals of irrational values).
#[test]
fn b98_circle_pattern_claim_fields_radii_phi_angles_epsilon_are_each_used() {
    let mesh = icosahedron().mesh;
    let r: Vec<Rational> = (0..mesh.n_vertices())
        .map(|v| Rational::from((v as u64 * 7 % 5 + 1, 3)))
        .collect();
    let choices = [(0, 1), (1, 12), (1, 3), (2, 5), (1, 2)];
    let phi: Vec<Rational> = (0..mesh.n_edges())
        .map(|e| Rational::from(choices[(e * 3) % 5]))
        .collect();
    let angles = cosine_law_angles(&mesh, &r, &phi);
    let claim = pattern_claim(&mesh, &r, &phi, &angles, "1e-40");
    assert_eq!(verdict(&claim).0, ClaimVerdict::Holds);
    let mut radius = r.clone();
    radius[0] += Rational::from((1, 10u128.pow(20)));
    let mut angle = phi.clone();
    angle[0] = if angle[0] == Rational::from((1, 12)) {
        Rational::from((1, 3))
    } else {
        Rational::from((1, 12))
    };
    let mut shifted = angles.clone();
    shifted[2] += Float::with_val(400, 1e-30);
    let altered = [
        (
            "one radius 1e-20 larger",
            pattern_claim(&mesh, &radius, &phi, &angles, "1e-40"),
        ),
        (
            "one Φ changed",
            pattern_claim(&mesh, &r, &angle, &angles, "1e-40"),
        ),
        (
            "one angle shifted",
            pattern_claim(&mesh, &r, &phi, &shifted, "1e-40"),
        ),
        ("ε = 0", pattern_claim(&mesh, &r, &phi, &angles, "0")),
    ];
    for (what, c) in altered {
        assert_ne!(verdict(&c).0, ClaimVerdict::Holds, "{what}");
    }
}
