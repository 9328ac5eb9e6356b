//! Flips in the star of the pole (notes Thm 9; B93): rough genus-0 surfaces whose disk
//! problem, with the star of the pole kept, has a reflex link vertex are made convex by
//! Ptolemy flips of edges at the pole, certified for their exact metric (B76, B90), and
//! checked by two independent oracles: the length cross ratios of the output chords against
//! the input's carried by the same flips (T16, T17, T28; numerical, B75), and the
//! convexity of the output polyhedron by exact `orient3d` on its binary64 vertices
//! (certified for those rounded coordinates). Negative controls: the result without flips
//! at the pole, the claim with its flip at the pole removed, a moved `u`.

use crate::meshgen::{icosphere, Embedded};
use crate::registry_uniformization::exact_positions;
use crate::support::{cases, certify_expecting, penner, scratch, text};
use penner::io::json::edge_order;
use penner::io::Surface;
use penner::mesh::{Edge, Mesh, Vertex};
use penner::scalar::{Interval, Mpfr, Precision};
use penner::uniformization::certificate::CertificateOutcome;
use penner::uniformization::dirichlet_certificate::{certify_disk, certify_disk_near};
use penner::uniformization::sphere::{
    check_pole, uniformize_sphere, SphereOptions, SphereUniformization,
};
use penner::uniformization::sphere_checks::cross_ratio_deviation;
use penner::uniformization::sphere_claim::{claim_of, recheck, to_json, SphereClaim};
use penner::uniformization::sphere_refine::input_disk_metric;
use rug::Rational;
use serde_json::Value;
use std::cmp::Ordering;

/// B75: tolerance of the numerical comparison of cross ratios (at most 10³ vertices,
/// solved to max |Θ − θ| ≤ 10⁻¹²).
const B75_TOLERANCE: f64 = 1e-8;

/// An icosphere with 320 faces, its vertices moved by up to `0.45` of the mean edge.
fn rough_embedded(seed: u64) -> Embedded {
    let mut e = icosphere(2);
    let amount = 0.45 * e.mean_edge();
    e.jitter(amount, seed);
    e
}

/// [`rough_embedded`] with its binary64 positions taken exactly.
fn rough_sphere(seed: u64) -> Surface {
    exact_positions("rough sphere", &rough_embedded(seed))
}

/// The method before B93: the star of the pole kept.
fn kept_star() -> SphereOptions {
    SphereOptions {
        star_flips: false,
        ..SphereOptions::default()
    }
}

/// The first pole of `T₀` by decreasing degree (the default before the graph centre came
/// first) whose solution needs a flip at the pole: the star flips are what these tests are
/// about, and which pole needs them is a property of the pole, not of the default order.
fn solved_with_a_star_flip(s: &Surface, l: &[f64]) -> SphereUniformization {
    let t0 = uniformize_sphere(&s.mesh, l, &kept_star())
        .unwrap()
        .initial_mesh;
    let mut poles: Vec<Vertex> = t0
        .vertices()
        .filter(|&v| check_pole(&t0, v).is_ok())
        .collect();
    poles.sort_by_key(|&v| (std::cmp::Reverse(t0.degree(v)), v.0));
    poles
        .into_iter()
        .find_map(|v| {
            let opts = SphereOptions {
                pole: Some(v.0),
                ..SphereOptions::default()
            };
            uniformize_sphere(&s.mesh, l, &opts)
                .ok()
                .filter(|sol| !sol.star_flips.is_empty())
        })
        .expect("a pole whose star needs a flip")
}

/// The disk certificate of `sol` for the exact metric of `s` at 128 bits near its `f64`
/// solution, and when it holds the claim and its re-check (B90).
fn certify_exact(s: &Surface, sol: &SphereUniformization) -> (CertificateOutcome, SphereClaim) {
    let prec = Precision::new(128).unwrap();
    let metric = input_disk_metric(sol, &s.mesh, s.lengths::<Interval<Mpfr>>(prec)).unwrap();
    let u: Vec<Rational> = sol
        .solution
        .u
        .iter()
        .map(|&x| Rational::from_f64(x).unwrap())
        .collect();
    let (data, outcome) = certify_disk_near(sol, Some(&metric), &u, sol.solution.residual_max, 128);
    let residual = match outcome {
        CertificateOutcome::Holds { residual, .. } => residual,
        CertificateOutcome::Undecided { .. } => 1.0,
    };
    let claim = claim_of(s, sol, &data, residual);
    if !matches!(outcome, CertificateOutcome::Holds { .. }) {
        return (outcome, claim);
    }
    (recheck(s, &claim, 128).unwrap(), claim)
}

/// `orient3d(X_i, X_j, X_k, X_l)` for every edge `ij` of `mesh` with faces `(i, j, k)` and
/// `(j, i, l)`, exactly on the rationals of the binary64 `positions`.
fn edge_orientations(mesh: &Mesh, positions: &[[f64; 3]]) -> Vec<Ordering> {
    let q = |v: Vertex| positions[v.idx()].map(|x| Rational::from_f64(x).unwrap());
    mesh.edges()
        .map(|e| {
            let h = e.halfedge();
            let (a, b) = (q(mesh.tail(h)), q(mesh.tip(h)));
            let (c, d) = (
                q(mesh.opposite_vertex(h)),
                q(mesh.opposite_vertex(h.twin())),
            );
            let sub = |x: &[Rational; 3]| -> [Rational; 3] {
                [0, 1, 2].map(|k| Rational::from(&x[k] - &a[k]))
            };
            let (u, v, w) = (sub(&b), sub(&c), sub(&d));
            let cross = [
                Rational::from(&v[1] * &w[2]) - Rational::from(&v[2] * &w[1]),
                Rational::from(&v[2] * &w[0]) - Rational::from(&v[0] * &w[2]),
                Rational::from(&v[0] * &w[1]) - Rational::from(&v[1] * &w[0]),
            ];
            let det = Rational::from(&u[0] * &cross[0])
                + Rational::from(&u[1] * &cross[1])
                + Rational::from(&u[2] * &cross[2]);
            det.cmp0()
        })
        .collect()
}

/// The edge of `mesh` joining `a` and `b`.
fn edge_between(mesh: &Mesh, a: u32, b: u32) -> Edge {
    mesh.outgoing(Vertex(a))
        .find(|&h| mesh.tip(h) == Vertex(b))
        .unwrap()
        .edge()
}

/// B93 on rough spheres: of `N` solved with the star kept, those with a reflex link vertex
/// are certified after flips at the pole (exact input metric, claim re-checked), their
/// output polyhedra are certified convex by exact `orient3d` on the output coordinates
/// and their chords have the input's cross ratios. Negative controls: the result with the
/// star kept is not certified and its polyhedron is certified reflex at the edge from the
/// pole to the reflex vertex; one input length 0.1 % longer changes the cross ratios.
#[test]
fn b93_star_flips_make_rough_spheres_convex_and_certified() {
    let (mut solved, mut before, mut after, mut certified) = (0, 0, 0, 0);
    let mut not_certified = Vec::new();
    for seed in 0..cases(30, 100) as u64 {
        let s = rough_sphere(seed);
        let l = s.lengths::<f64>(());
        let Ok(old) = uniformize_sphere(&s.mesh, &l, &kept_star()) else {
            continue;
        };
        solved += 1;
        let new = uniformize_sphere(&s.mesh, &l, &SphereOptions::default()).unwrap();
        if old.reflex.is_empty() {
            assert!(new.star_flips.is_empty(), "seed {seed}");
            continue;
        }
        before += 1;
        assert!(!new.star_flips.is_empty(), "seed {seed}");
        if !new.reflex.is_empty() {
            after += 1;
            continue;
        }
        match certify_exact(&s, &new).0 {
            CertificateOutcome::Holds { distance, .. } if distance < 1e-9 => certified += 1,
            other => not_certified.push((seed, format!("{other:?}"))),
        }
        // Negative control: with the star kept the certificate does not hold.
        let (kept, _) = certify_exact(&s, &old);
        assert!(
            matches!(kept, CertificateOutcome::Undecided { .. }),
            "seed {seed}: {kept:?}"
        );
        // Oracle 1: exact orientations of the output polyhedron, one sign on every edge
        // (locally convex everywhere, B74 "Convexity").
        let signs = edge_orientations(&new.mesh, &new.positions);
        let convex = signs[0];
        assert!(
            convex != Ordering::Equal && signs.iter().all(|&x| x == convex),
            "seed {seed}: {signs:?}"
        );
        // Negative control (B93 (a)): with the star kept, the edge from the pole to the
        // reflex link vertex has the other sign.
        let star = edge_between(&old.mesh, old.pole, old.reflex[0]);
        let old_signs = edge_orientations(&old.mesh, &old.positions);
        assert_eq!(old_signs[star.idx()], convex.reverse(), "seed {seed}");
        // Oracle 2: cross ratios of the chords equal the input's carried by the same flips.
        let dev = cross_ratio_deviation(&new, &new.initial_lengths).unwrap();
        assert!(dev <= B75_TOLERANCE, "seed {seed}: {dev:e}");
        let mut wrong = new.initial_lengths.clone();
        wrong[7] *= 1.001;
        let dev = cross_ratio_deviation(&new, &wrong).unwrap();
        assert!(dev > 1e4 * B75_TOLERANCE, "seed {seed}: control {dev:e}");
    }
    println!(
        "B93: {solved} rough spheres solved; {before} with a reflex link vertex when the star is kept, {after} after flips at the pole; {certified} of those certified"
    );
    assert!(before >= 3, "{before} of {solved}");
    assert_eq!(after, 0);
    assert!(not_certified.is_empty(), "{not_certified:?}");
}

/// B93, the disk certificate's own metric (`certify_disk`, no metric given): with flips at
/// the pole it is `T₀`'s binary64 lengths carried through them in intervals, not the
/// disk's binary64 lengths (rounded in the flips), so one of those moved by 10⁻³ changes
/// nothing. Negative control: on the unjittered icosphere, which needs no flip at the pole
/// and whose disk lengths are `T₀`'s, it holds and the same move is refused.
#[test]
fn b93_disk_certificate_reads_t0_through_the_flips_at_the_pole() {
    let holds = |sol: &SphereUniformization| {
        matches!(certify_disk(sol, 128).1, CertificateOutcome::Holds { .. })
    };
    let s = rough_sphere(1);
    let mut sol = solved_with_a_star_flip(&s, &s.lengths::<f64>(()));
    assert!(sol.star_prefix > 0 && holds(&sol));
    sol.disk.lengths[0] *= 1.001;
    assert!(holds(&sol), "the disk's binary64 lengths were read");
    let smooth = exact_positions("icosphere", &icosphere(2));
    let mut sol = uniformize_sphere(
        &smooth.mesh,
        &smooth.lengths::<f64>(()),
        &SphereOptions::default(),
    )
    .unwrap();
    assert!(sol.star_prefix == 0 && holds(&sol));
    sol.disk.lengths[0] *= 1.001;
    assert!(!holds(&sol), "control: a moved length is refused");
}

/// B93 (b): the Ptolemy length of the new boundary edge `bc` in the disk's coordinates is
/// `ℓ̃_ab + ℓ̃_ac` at `u_a = w_a`, exactly: `ℓ_bc/(ℓ_{∞b}ℓ_{∞c}) = ℓ_ab/(ℓ_{∞a}ℓ_{∞b}) +
/// ℓ_ac/(ℓ_{∞a}ℓ_{∞c})` for the exact Ptolemy flip of `∞a` on rational lengths. Negative
/// control: the pole lengths paired the other way round.
#[test]
fn b93_new_boundary_edge_is_the_sum_of_the_two_it_replaces() {
    use penner::algorithms::flips::flip_ptolemy_exact;
    let s = rough_sphere(1);
    let l = s.lengths::<f64>(());
    let sol = solved_with_a_star_flip(&s, &l);
    let star = *sol.star_flips.first().expect("a flip at the pole");
    // The triangulation just before the first flip at the pole, lengths exact rationals of
    // T₀'s binary64 lengths carried exactly.
    let mut t = sol.initial_mesh.clone();
    let mut q: Vec<Rational> = sol
        .initial_lengths
        .iter()
        .map(|&x| Rational::from_f64(x).unwrap())
        .collect();
    for &e in sol.flip_sequence.iter().take_while(|&&e| e != star) {
        flip_ptolemy_exact(&mut t, &mut q, e).unwrap();
    }
    let h = star.halfedge();
    let (p, a) = if t.tail(h).0 == sol.pole {
        (t.tail(h), t.tip(h))
    } else {
        (t.tip(h), t.tail(h))
    };
    assert_eq!(p.0, sol.pole);
    let (b, c) = (t.opposite_vertex(h), t.opposite_vertex(h.twin()));
    let len = |t: &Mesh, q: &[Rational], x: Vertex, y: Vertex| -> Rational {
        q[edge_between(t, x.0, y.0).idx()].clone()
    };
    let (pa, pb, pc) = (len(&t, &q, p, a), len(&t, &q, p, b), len(&t, &q, p, c));
    let (ab, ac) = (len(&t, &q, a, b), len(&t, &q, a, c));
    flip_ptolemy_exact(&mut t, &mut q, star).unwrap();
    let bc = q[star.idx()].clone();
    assert_eq!(len(&t, &q, b, c), bc);
    let lhs = Rational::from(&bc / &pb) / &pc;
    let sum = Rational::from(&ab / &pa) / &pb + Rational::from(&ac / &pa) / &pc;
    assert_eq!(lhs, sum);
    let swapped = Rational::from(&ab / &pa) / &pc + Rational::from(&ac / &pa) / &pb;
    assert_ne!(lhs, swapped);
}

/// B90 with B93: the claim of a result with a flip at the pole re-checks for the exact
/// input metric and survives the parser; the same claim with that flip removed (and `u`,
/// `final_faces` made consistent with the kept star) and with `u` moved by `10⁻⁴` is not
/// certified.
#[test]
fn b93_claim_with_a_flip_at_the_pole_rechecks() {
    let s = rough_sphere(1);
    let l = s.lengths::<f64>(());
    let sol = solved_with_a_star_flip(&s, &l);
    assert!(!sol.star_flips.is_empty());
    let (outcome, claim) = certify_exact(&s, &sol);
    assert!(
        matches!(outcome, CertificateOutcome::Holds { .. }),
        "{outcome:?}"
    );
    let doc = to_json(&s, &claim, 128);
    let parsed = penner::oracle::claim::parse_value(&doc).unwrap();
    assert_eq!(
        parsed.assertion,
        penner::oracle::claim::Assertion::SphereUniformization(claim.clone())
    );
    // Negative control: the flip at the pole removed; `a` back on the link (no value) and
    // the final faces those of the remaining flips.
    let order = edge_order(&s.mesh);
    let user = |e: Edge| order.iter().position(|&x| x == e.idx()).unwrap();
    let star = sol.star_flips[0];
    let mut removed = claim.clone();
    removed.flips.retain(|&k| k != user(star));
    let h = star.halfedge();
    let a = if sol.initial_mesh.tail(h).0 == sol.pole {
        sol.initial_mesh.tip(h)
    } else {
        sol.initial_mesh.tail(h)
    };
    removed.u[a.idx()] = None;
    let mut m = sol.initial_mesh.clone();
    let replays = removed
        .flips
        .iter()
        .all(|&k| m.flip(Edge(order[k] as u32)).is_ok());
    removed.final_faces = m.face_list();
    let out = recheck(&s, &removed, 128);
    assert!(
        !matches!(out, Ok(CertificateOutcome::Holds { .. })),
        "replays: {replays}; {out:?}"
    );
    // Negative control: u moved by 10⁻⁴ at a free vertex.
    let mut moved = claim;
    let free = moved.u.iter().position(Option::is_some).unwrap();
    if let Some(x) = &mut moved.u[free] {
        *x += Rational::from((1, 10_000));
    }
    let out = recheck(&s, &moved, 128).unwrap();
    assert!(
        matches!(out, CertificateOutcome::Undecided { .. }),
        "{out:?}"
    );
}

/// `penner uniformize --sphere` on a rough sphere that needs a flip at the pole: exit 0,
/// the flip reported, the claim written and re-checked by `penner certify` (holds);
/// negative controls through `penner certify`: the flips at the pole removed from `flips`,
/// and a `u` moved by `10⁻⁴`, are `undecided` (exit 2); with `--pole` at a vertex whose
/// star needs no flip the exit code is that of its own certificate.
#[test]
fn b93_cli_sphere_flips_at_the_pole_and_certifies() {
    let d = scratch("uniformize-sphere-star");
    let e = rough_embedded(1);
    let mut off = Vec::new();
    e.write_off(&mut off).unwrap();
    let surf = d.join("rough.off");
    std::fs::write(&surf, off).unwrap();
    let res = d.join("claim.json");
    let lib = exact_positions("rough", &e);
    let l = lib.lengths::<f64>(());
    let sol = solved_with_a_star_flip(&lib, &l);
    let pole = sol.pole.to_string();
    let out = penner(&[
        "uniformize",
        surf.to_str().unwrap(),
        "--sphere",
        "--pole",
        &pole,
        "-o",
        res.to_str().unwrap(),
    ]);
    let s = text(&out.stdout);
    assert_eq!(out.status.code(), Some(0), "{s}{}", text(&out.stderr));
    assert!(
        s.contains("disk problem certified") && !s.contains("(0 of edges at the pole"),
        "{s}"
    );
    let doc: Value = serde_json::from_str(&std::fs::read_to_string(&res).unwrap()).unwrap();
    certify_expecting(&d, "same.json", &doc, 0, "holds");
    // The flips at the pole: flips of edges at the pole in T₀ (no disk flip creates one).
    assert_eq!(doc["pole"].as_u64(), Some(u64::from(sol.pole)));
    let order = edge_order(&lib.mesh);
    let star: Vec<usize> = sol
        .initial_mesh
        .outgoing(Vertex(sol.pole))
        .map(|h| order.iter().position(|&x| x == h.edge().idx()).unwrap())
        .collect();
    let flips: Vec<u64> = doc["flips"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_u64().unwrap())
        .collect();
    let kept: Vec<u64> = flips
        .iter()
        .copied()
        .filter(|&k| !star.contains(&(k as usize)))
        .collect();
    assert!(kept.len() < flips.len());
    let mut removed = doc.clone();
    removed["flips"] = serde_json::json!(kept);
    certify_expecting(&d, "removed.json", &removed, 2, "undecided");
    let free = doc["u"]
        .as_array()
        .unwrap()
        .iter()
        .position(|x| !x.is_null())
        .unwrap();
    let x = penner::io::json::exact_number(&doc["u"][free], "u")
        .unwrap()
        .to_f64();
    let mut moved = doc.clone();
    moved["u"][free] = Value::String(format!("{}", x + 1e-4));
    certify_expecting(&d, "moved.json", &moved, 2, "undecided");
}
