//! The hyperbolic target with flips (notes Thm 11 with flips; B87, B89, B104): random
//! multi-vertex genus-2 metrics whose solution leaves the input's Penner cell solve and
//! certify; the claim with `flips` round-trips and its controls (a wrong flip, a moved `u`,
//! a box crossing a cell boundary, no flips) are never certified; the angle sums after the
//! flips agree with an independent MPFR replay of the λ-Ptolemy flips; geometric flips of
//! the input keep its cone angles and area.

use crate::uniformization_hyperbolic::random_lengths;
use penner::mesh::{builders, Edge, Mesh};
use penner::oracle::certify::{certify, Answer, ClaimVerdict};
use penner::oracle::claim::parse_value;
use penner::scalar::{Interval, Mpfr, Precision, Real};
use penner::uniformization::hyperbolic::{
    uniformize_hyperbolic, HyperbolicOptions, HyperbolicUniformization,
};
use penner::uniformization::hyperbolic_certificate::{
    base_log_i, box_around, certify_hyperbolic, refine_hyperbolic, total_area_lhuilier, Existence,
};
use penner::uniformization::hyperbolic_claim::{to_claim, ClaimData};
use penner::uniformization::hyperbolic_flips::{delaunay_on_box, replay_ptolemy};
use penner::uniformization::Targets;
use penner::variational::hyperbolic::cone_angles;
use rug::float::Constant;
use rug::{Float, Rational};
use serde_json::{json, Value};

/// Random genus-2 surfaces with `nv` vertices and lengths in `[lo, hi]`.
fn random_case(nv: u32, seed: u64, lo: f64, hi: f64) -> (Mesh, Vec<f64>) {
    let m = builders::random_surface(2, nv, seed).unwrap();
    let l = random_lengths(&m, lo, hi, seed);
    (m, l)
}

fn solve(m: &Mesh, l: &[f64]) -> HyperbolicUniformization {
    let t = Targets::flat(m.n_vertices());
    let sol = uniformize_hyperbolic(m, l, &t, &HyperbolicOptions::default()).unwrap();
    assert!(sol.converged(), "{:?}", sol.stop);
    sol
}

/// The 256-bit refinement of `sol`, certified: `(u, claim, radius)`.
fn certified(sol: &HyperbolicUniformization) -> (Vec<Rational>, Value, f64) {
    let bits = 256;
    let prec = Precision::new(bits).unwrap();
    let r = refine_hyperbolic::<Mpfr>(sol, prec, 2f64.powi(-200), 60).unwrap();
    let u: Vec<Rational> = r.u.iter().map(|x| x.to_rational().unwrap()).collect();
    let cert = certify_hyperbolic(sol, &u, bits as u32).unwrap();
    let Existence::Holds { radius, .. } = cert.existence else {
        panic!("not certified: {:?}", cert.existence);
    };
    let data = ClaimData {
        mesh: &sol.t0,
        lengths: &sol.lengths,
        flips: &sol.flips,
        targets: &sol.targets,
        u: &u,
    };
    let claim = to_claim(&data, radius, cert.residual_norm2, bits as u32);
    (u, claim, radius)
}

fn answer(v: &Value) -> Answer {
    let c = parse_value(v).unwrap_or_else(|e| panic!("{e}: {v}"));
    certify(&c).unwrap()
}

/// Not certified: `undecided`, or `refuted` only with a proof at a vertex (the residual
/// enclosed away from 0 on the whole box) or at the residual bound.
fn not_certified(a: &Answer, what: &str) {
    assert_ne!(a.verdict, ClaimVerdict::Holds, "{what}: {:?}", a.witnesses);
    if a.verdict == ClaimVerdict::Refuted {
        let el = &a.counterexample.as_ref().unwrap().element;
        assert!(
            el.starts_with('v') || el == "residual_bound",
            "{what}: refuted at {el}"
        );
    }
}

/// B87: random multi-vertex genus-2 metrics (lengths in `[1, 1.9]` and `[2, 3.8]`) whose
/// solution needs Ptolemy flips (and often geometric flips of the input) converge, refine
/// to 256 bits and certify (B39 on `T_k`, `T_k` Delaunay on the box, `T₀` Delaunay at 0),
/// and the written claim re-checks to `holds` from scratch.
#[test]
fn b87_random_genus2_metrics_needing_flips_solve_and_certify() {
    let mut with_input_flips = 0;
    for (nv, seed, lo, hi) in [
        (4, 0, 1.0, 1.9),
        (4, 1, 2.0, 3.8),
        (8, 2, 1.0, 1.9),
        (8, 3, 2.0, 3.8),
        (16, 1, 1.0, 1.9),
    ] {
        let (m, l) = random_case(nv, seed, lo, hi);
        let sol = solve(&m, &l);
        assert!(
            !sol.flips.is_empty(),
            "nv {nv} seed {seed}: no flips needed"
        );
        with_input_flips += usize::from(!sol.input_flips.is_empty());
        let (_, claim, radius) = certified(&sol);
        assert_eq!(claim["flips"].as_array().unwrap().len(), sol.flips.len());
        let a = answer(&claim);
        assert_eq!(
            a.verdict,
            ClaimVerdict::Holds,
            "nv {nv} seed {seed}: {:?}",
            a.witnesses
        );
        assert!(a.certified && a.max_discrepancy.unwrap() <= radius);
    }
    assert!(
        with_input_flips >= 3,
        "only {with_input_flips} inputs were flipped"
    );
}

/// B89 controls on one certified claim with flips: one flip replaced by another edge, the
/// last flip dropped, no flips at all (`[]`), `u + 10⁻⁶`, are not certified (refuted only
/// with a proof); a box of growing radius around the certified `u` is never refuted and
/// becomes undecided because an edge of `T_k` is not certified Delaunay on it; a claim
/// without the `flips` field keeps the fixed-triangulation meaning (parsed, answered).
#[test]
fn b89_flip_claim_controls_are_not_certified() {
    let (m, l) = random_case(8, 2, 1.0, 1.9);
    let sol = solve(&m, &l);
    let (_, claim, _) = certified(&sol);
    assert_eq!(answer(&claim).verdict, ClaimVerdict::Holds);
    let flips: Vec<u64> = claim["flips"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_u64().unwrap())
        .collect();
    let edges = m.n_edges() as u64;
    // A wrong flip: the first flip replaced by the next edge index.
    let mut bad = claim.clone();
    bad["flips"][0] = json!((flips[0] + 1) % edges);
    match parse_value(&bad).map(|c| certify(&c).unwrap()) {
        Ok(a) => not_certified(&a, "wrong flip"),
        Err(e) => assert!(e.to_string().contains("flips["), "{e}"),
    }
    // The last flip dropped.
    let mut bad = claim.clone();
    bad["flips"] = json!(flips[..flips.len() - 1]);
    not_certified(&answer(&bad), "last flip dropped");
    // No flips: T₀ itself, which is not Delaunay at the solution.
    let mut bad = claim.clone();
    bad["flips"] = json!([]);
    not_certified(&answer(&bad), "no flips");
    // u moved by 10⁻⁶ at every vertex.
    let mut bad = claim.clone();
    let moved: Vec<String> = claim["u"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| {
            let q = penner::io::json::exact_number(x, "u").unwrap();
            (q + Rational::from((1, 1_000_000))).to_string()
        })
        .collect();
    bad["u"] = json!(moved);
    not_certified(&answer(&bad), "u + 1e-6");
    // Growing boxes: never refuted; some radius is undecided for want of Delaunay.
    let mut delaunay_reason = false;
    for r in ["0.001", "0.01", "0.03", "0.1", "0.3"] {
        let mut wide = claim.clone();
        wide["radius"] = json!(r);
        let a = answer(&wide);
        assert_ne!(
            a.verdict,
            ClaimVerdict::Refuted,
            "radius {r}: {:?}",
            a.witnesses
        );
        if a.verdict == ClaimVerdict::Undecided {
            delaunay_reason |= a
                .witnesses
                .iter()
                .any(|w| w.detail.contains("not certified hyperbolic Delaunay"));
        }
    }
    assert!(
        delaunay_reason,
        "no box was refused for a non-Delaunay edge"
    );
    // Without the `flips` field: the fixed-triangulation claim on T₀ (B39), answered.
    let mut old = claim.clone();
    old.as_object_mut().unwrap().remove("flips");
    not_certified(&answer(&old), "fixed T₀");
}

/// B89 (`delaunay_on_box`): the input with geometric flips pending is not certified
/// Delaunay at `u = 0` and `T₀` is; at the certified `u`, `T_k` is certified Delaunay on
/// the certified box while `T₀` with its formal lengths is not (the solution left `T₀`'s
/// Penner cell).
#[test]
fn b89_delaunay_on_the_box_separates_the_cells() {
    let (m, l) = random_case(8, 2, 1.0, 1.9);
    let sol = solve(&m, &l);
    assert!(!sol.input_flips.is_empty() && !sol.flips.is_empty());
    let prec = Precision::new(256).unwrap();
    let zero = vec![Interval::<Mpfr>::from_f64(0.0, prec); m.n_vertices()];
    let lengths = |x: &[f64]| -> Vec<Interval<Mpfr>> {
        base_log_i(
            &x.iter()
                .map(|&v| Interval::from_f64(v, prec))
                .collect::<Vec<_>>(),
        )
    };
    assert!(delaunay_on_box(&m, &lengths(&l), &zero).is_err());
    let base0 = lengths(&sol.lengths);
    assert!(delaunay_on_box(&sol.t0, &base0, &zero).is_ok());
    let (u, _, radius) = certified(&sol);
    let (tk, base) = replay_ptolemy(&sol.t0, &base0, &sol.flips).unwrap();
    let boxed = box_around(&u, &Rational::from_f64(radius).unwrap(), prec);
    assert!(delaunay_on_box(&tk, &base, &boxed).is_ok());
    let point = box_around(&u, &Rational::from((1, 1u128 << 100)), prec);
    assert!(delaunay_on_box(&sol.t0, &base0, &point).is_err());
}

/// The λ-Ptolemy replay of the test: `λ = 2 sinh(ℓ/2)`, `λ_f = (λ_jk λ_il + λ_ki λ_lj)/λ_e`
/// in 256-bit MPFR (not the library's logarithmic form).
fn replay_lambda(t0: &Mesh, l: &[f64], flips: &[Edge]) -> (Mesh, Vec<Float>) {
    let mut m = t0.clone();
    let mut lam: Vec<Float> = l
        .iter()
        .map(|&x| Float::with_val(256, x / 2.0).sinh() * 2u32)
        .collect();
    for &e in flips {
        let (h, t) = (e.side(0), e.side(1));
        let jk = m.next(h);
        let ki = m.next(jk);
        let il = m.next(t);
        let lj = m.next(il);
        let g = |x: penner::mesh::HalfEdge| lam[x.edge().idx()].clone();
        let new = (g(jk) * g(il) + g(ki) * g(lj)) / &lam[e.idx()];
        m.flip(e).unwrap();
        lam[e.idx()] = new;
    }
    (m, lam)
}

/// `max_i |2π − θ_i|` of the scaled λ-lengths `e^{(u_i+u_j)/2}λ` on `m`, angles by the
/// hyperbolic law of cosines at 256 bits (the solver uses the half-angle form in binary64).
fn residual_by_law_of_cosines(m: &Mesh, lam: &[Float], u: &[f64]) -> f64 {
    let lengths: Vec<Mpfr> = m
        .edges()
        .map(|e| {
            let h = e.halfedge();
            let sum = Float::with_val(256, u[m.tail(h).idx()]) + u[m.tip(h).idx()];
            let s = Float::with_val(256, sum / 2u32).exp();
            let half = Float::with_val(256, &lam[e.idx()] * s) / 2u32;
            let l = Float::with_val(256, half.asinh() * 2u32);
            Mpfr::from_rational(&l.to_rational().unwrap(), Precision::new(256).unwrap())
        })
        .collect();
    let theta = cone_angles(m, &lengths, true);
    let two_pi = Float::with_val(256, Constant::Pi) * 2u32;
    theta
        .iter()
        .map(|t| (two_pi.clone() - t.as_float()).abs().to_f64())
        .fold(0.0, f64::max)
}

/// B87 (independent oracle): the flips replayed on `λ = 2 sinh(ℓ/2)` by Ptolemy's relation
/// in MPFR reach the solver's triangulation, and there the angle sums at the solver's `u`
/// by the law of cosines are `2π` within `10⁻⁹` (solver tolerance `10⁻¹⁰` plus the binary64
/// rounding of the flips, `≲ 10⁻¹²` per flip); the same `u` on `T₀` (no flips) is off by
/// more than `10⁻⁴`.
#[test]
fn b87_angle_sums_after_flips_match_an_independent_mpfr_replay() {
    for (nv, seed, lo, hi) in [(4, 1, 2.0, 3.8), (16, 0, 1.0, 1.9), (30, 3, 0.3, 0.55)] {
        let (m, l) = random_case(nv, seed, lo, hi);
        let sol = solve(&m, &l);
        let (tk, lam) = replay_lambda(&sol.t0, &sol.lengths, &sol.flips);
        assert_eq!(tk.face_list(), sol.mesh.face_list());
        let r = residual_by_law_of_cosines(&tk, &lam, &sol.u);
        assert!(r < 1e-9, "nv {nv} seed {seed}: residual {r:e}");
        let (t0, lam0) = replay_lambda(&sol.t0, &sol.lengths, &[]);
        let r0 = residual_by_law_of_cosines(&t0, &lam0, &sol.u);
        assert!(r0 > 1e-4, "nv {nv} seed {seed}: T₀ residual {r0:e}");
    }
}

/// B104: geometric flips keep the metric: the cone angles (half-angle form, binary64) and
/// the L'Huilier area of the input and of `T₀` agree within `10⁻¹¹` (a few hundred
/// rounding errors); the same edges flipped by the formal Ptolemy relation instead (not an
/// isometry off the cell boundary) change an angle sum by more than `10⁻⁶`.
#[test]
fn b104_geometric_flips_keep_cone_angles_and_area() {
    let mut checked = 0;
    for (nv, seed) in [(8, 2), (16, 1), (30, 3)] {
        let (m, l) = random_case(nv, seed, 2.0, 3.8);
        let sol = solve(&m, &l);
        if sol.input_flips.is_empty() {
            continue;
        }
        let th_in = cone_angles(&m, &l, false);
        let th_0 = cone_angles(&sol.t0, &sol.lengths, false);
        let gap = th_in
            .iter()
            .zip(&th_0)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        assert!(gap < 1e-11, "nv {nv}: angle gap {gap:e}");
        let (a_in, a_0) = (
            total_area_lhuilier(&m, &l).unwrap(),
            total_area_lhuilier(&sol.t0, &sol.lengths).unwrap(),
        );
        assert!((a_in - a_0).abs() < 1e-11, "nv {nv}: area {a_in} vs {a_0}");
        // Control: the same flips by Ptolemy's relation.
        let (tp, lam) = replay_lambda(&m, &l, &sol.input_flips);
        assert_eq!(tp.face_list(), sol.t0.face_list());
        let lp: Vec<f64> = lam
            .iter()
            .map(|x| (Float::with_val(256, x / 2u32).asinh() * 2u32).to_f64())
            .collect();
        let th_p = cone_angles(&tp, &lp, false);
        let gap_p = th_in
            .iter()
            .zip(&th_p)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        assert!(gap_p > 1e-6, "nv {nv}: Ptolemy control gap {gap_p:e}");
        checked += 1;
    }
    assert!(checked >= 2, "only {checked} inputs needed geometric flips");
}
