//! Flipping conformally scaled metrics `e^{(u_i+u_j)/2}·ℓ_ij` with `|u|` up to 800 and
//! beyond (B67): lengths with the exponent kept apart, checked against the malachite
//! D-form oracle on their exact values and against MPFR at 53 bits (its own exponent
//! range, the generic driver), with binary64 overflow as the negative control.

use crate::delaunay::{exactly_strict_face, exactly_strict_faces, oracle_non_delaunay, to_m};
use crate::delaunay_genus::case;
use crate::support::case_seeds;
use malachite::rational::Rational as MRational;
use penner::algorithms::flip_scaled::{flip_to_delaunay_scaled, scaled_lengths};
use penner::algorithms::flip_to_delaunay::{
    flip_to_delaunay, FlipKind, FlipOptions, FlipToDelaunayError,
};
use penner::mesh::Mesh;
use penner::predicates::delaunay::DelaunayError;
use penner::scalar::exp_length::ExpLength;
use penner::scalar::{Mpfr, Real};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// Log scale factors for the vertices of `m`: independent in `[−800, 800]`, or a smooth
/// field `800·sin(v)` (neighbours close), or one constant.
fn factors(m: &Mesh, rng: &mut ChaCha8Rng) -> Vec<f64> {
    let n = m.n_vertices();
    match rng.gen_range(0..3) {
        0 => (0..n).map(|_| rng.gen_range(-800.0..=800.0)).collect(),
        1 => (0..n).map(|v| 800.0 * (v as f64 * 0.7).sin()).collect(),
        _ => vec![rng.gen_range(-800.0..=800.0); n],
    }
}

fn exact_of(l: &[ExpLength]) -> Vec<MRational> {
    l.iter().map(|x| to_m(&x.to_rational())).collect()
}

#[test]
fn b67_scaled_flipping_up_to_800_is_certified_and_matches_mpfr_53() {
    let (mut flips, mut wide, mut compared, mut refused_metrics) = (0, 0, 0, 0);
    for i in case_seeds(24, 2_000) {
        let c = case(i);
        let mut rng = ChaCha8Rng::seed_from_u64(0x67 + i);
        let base: Vec<f64> = c.lengths.iter().map(rug::Rational::to_f64).collect();
        let u = factors(&c.mesh, &mut rng);
        // Negative control: the same metric in binary64 overflows or underflows somewhere
        // (e^{800} = ∞) and is refused as bad input.
        let naive: Vec<f64> = c
            .mesh
            .edges()
            .map(|e| {
                let h = e.halfedge();
                let (a, b) = (c.mesh.tail(h).idx(), c.mesh.tip(h).idx());
                f64::midpoint(u[a], u[b]).exp() * base[e.idx()]
            })
            .collect();
        let overflows = naive.iter().any(|x| !x.is_normal());
        if overflows {
            let mut m = c.mesh.clone();
            let mut l = naive.clone();
            let r = flip_to_delaunay(&mut m, &mut l, FlipKind::Euclidean, &FlipOptions::default());
            assert!(
                matches!(r, Err(FlipToDelaunayError::Lengths(_))),
                "{}",
                c.name
            );
            wide += 1;
        }
        for kind in [FlipKind::Euclidean, FlipKind::Ptolemy] {
            let mut m = c.mesh.clone();
            let opts = FlipOptions {
                record: true,
                ..FlipOptions::default()
            };
            let start = scaled_lengths(&c.mesh, &base, &u).unwrap();
            let (r, l) = match flip_to_delaunay_scaled(&mut m, &base, &u, kind, &opts) {
                Ok(x) => x,
                Err(FlipToDelaunayError::Lengths(DelaunayError::NotATriangle { face })) => {
                    // Unequal factors broke the triangle inequality: Euclidean flips refuse
                    // the metric, and the face named is exactly not a strict triangle.
                    assert_eq!(kind, FlipKind::Euclidean);
                    let ex = exact_of(&start);
                    assert!(
                        !exactly_strict_face(&c.mesh, &ex, face),
                        "{}: {face}",
                        c.name
                    );
                    refused_metrics += 1;
                    continue;
                }
                Err(e) => panic!("{}: {e}", c.name),
            };
            assert!(!r.hit_cap, "{}", c.name);
            let exact = exact_of(&l);
            let mut bad = oracle_non_delaunay(&m, &exact);
            bad.retain(|e| !r.undecided.contains(e) && !r.refused.contains(e));
            assert!(bad.is_empty(), "{} {kind:?}: {bad:?}", c.name);
            if kind == FlipKind::Euclidean {
                assert!(
                    exactly_strict_faces(&m, &exact),
                    "{}: a degenerate face",
                    c.name
                );
            }
            flips += r.flips;
            // Oracle: the generic driver on MPFR values at 53 bits (its own exponent range,
            // its own ladder) makes the same flips and returns the same lengths bit for bit.
            let mut mm = c.mesh.clone();
            let mut lm: Vec<Mpfr> = start.iter().map(|x| Mpfr(x.to_float())).collect();
            let rm = flip_to_delaunay(&mut mm, &mut lm, kind, &opts).unwrap();
            if r.undecided.is_empty() && rm.undecided.is_empty() {
                assert_eq!(rm.sequence, r.sequence, "{} {kind:?}", c.name);
                let same = lm
                    .iter()
                    .zip(&l)
                    .all(|(a, b)| a.to_rational() == Some(b.to_rational()));
                assert!(same, "{} {kind:?}: lengths differ from MPFR-53", c.name);
                compared += 1;
            }
        }
    }
    assert!(
        flips > 0 && wide > 0 && compared > 0 && refused_metrics > 0,
        "{flips} {wide} {compared} {refused_metrics}"
    );
}

#[test]
fn b67_negative_control_the_oracle_flags_unflipped_scaled_inputs() {
    // The same oracle on the scaled inputs before flipping finds non-Delaunay edges: the
    // check above can fail.
    let mut flagged = 0;
    for i in case_seeds(24, 400) {
        let c = case(i);
        let mut rng = ChaCha8Rng::seed_from_u64(0x67 + i);
        let base: Vec<f64> = c.lengths.iter().map(rug::Rational::to_f64).collect();
        let u = factors(&c.mesh, &mut rng);
        let start = scaled_lengths(&c.mesh, &base, &u).unwrap();
        flagged += oracle_non_delaunay(&c.mesh, &exact_of(&start)).len();
    }
    assert!(flagged > 0);
}

#[test]
fn b67_uniform_scaling_keeps_the_flips_of_the_base_metric() {
    // One common u scales every length by e^u: the Delaunay condition and both flip
    // formulas are homogeneous, so the flips are those of the base metric in f64.
    let mut compared = 0;
    for i in case_seeds(16, 400) {
        let c = case(i);
        let base: Vec<f64> = c.lengths.iter().map(rug::Rational::to_f64).collect();
        for u0 in [-790.0, 700.0] {
            let u = vec![u0; c.mesh.n_vertices()];
            let opts = FlipOptions {
                record: true,
                ..FlipOptions::default()
            };
            let mut m = c.mesh.clone();
            let (r, _) =
                flip_to_delaunay_scaled(&mut m, &base, &u, FlipKind::Ptolemy, &opts).unwrap();
            let (mut m0, mut l0) = (c.mesh.clone(), base.clone());
            let r0 = flip_to_delaunay(&mut m0, &mut l0, FlipKind::Ptolemy, &opts).unwrap();
            if r.all_certified_delaunay() && r0.all_certified_delaunay() && r0.nudged == 0 {
                assert_eq!(r.sequence, r0.sequence, "{} u = {u0}", c.name);
                compared += 1;
            }
        }
    }
    assert!(compared > 0);
}

#[test]
fn b67_scale_factors_to_the_supported_limit() {
    // |u| up to 2^20: lengths near e^{±10⁶}; adjacent vertices 2·10⁶ apart make one
    // quadrilateral span about 1.4·10⁶ binary orders (the filter declines, the exact
    // shifted rationals decide).
    let m0 = Mesh::from_faces(4, &[[0, 1, 2], [0, 2, 3]]).unwrap();
    let base = vec![1.0; m0.n_edges()];
    for u in [
        [1_048_576.0, -1_048_576.0, 1_048_576.0, -1_048_576.0],
        [1_048_576.0; 4],
        [-1_048_576.0, 0.0, 5.0, 1e-300],
    ] {
        // Unequal factors this far apart break the triangle inequality: Ptolemy flips only.
        let kinds: &[FlipKind] = if u.iter().all(|&x| x == u[0]) {
            &[FlipKind::Euclidean, FlipKind::Ptolemy]
        } else {
            &[FlipKind::Ptolemy]
        };
        for &kind in kinds {
            let mut m = m0.clone();
            let (r, l) =
                flip_to_delaunay_scaled(&mut m, &base, &u, kind, &FlipOptions::default()).unwrap();
            assert!(
                !r.hit_cap && r.undecided.is_empty(),
                "{u:?} {kind:?}: {r:?}"
            );
            let bad = oracle_non_delaunay(&m, &exact_of(&l));
            assert!(bad.iter().all(|e| r.refused.contains(e)), "{u:?} {kind:?}");
        }
    }
}

#[test]
fn b67_bad_scale_factors_are_typed_errors() {
    let m0 = Mesh::from_faces(4, &[[0, 1, 2], [0, 2, 3]]).unwrap();
    let base = vec![1.0; m0.n_edges()];
    let run = |u: &[f64], base: &[f64]| {
        let mut m = m0.clone();
        flip_to_delaunay_scaled(&mut m, base, u, FlipKind::Ptolemy, &FlipOptions::default())
    };
    let err = |r: Result<_, FlipToDelaunayError>| match r {
        Err(FlipToDelaunayError::Lengths(e)) => e,
        Ok(_) => panic!("accepted"),
    };
    assert!(matches!(
        err(run(&[0.0, f64::NAN, 0.0, 0.0], &base)),
        DelaunayError::BadScale { vertex: 1, .. }
    ));
    assert!(matches!(
        err(run(&[0.0, 0.0, 2e6, 0.0], &base)),
        DelaunayError::ScaleOutOfRange { vertex: 2, .. }
    ));
    assert!(matches!(
        err(run(&[0.0; 3], &base)),
        DelaunayError::ScaleCount { .. }
    ));
    let mut bad_base = base.clone();
    bad_base[1] = -1.0;
    assert!(matches!(
        err(run(&[0.0; 4], &bad_base)),
        DelaunayError::BadLength { .. }
    ));
    assert!(matches!(
        err(run(&[0.0; 4], &base[1..])),
        DelaunayError::LengthCount { .. }
    ));
}

/// B67, rung by rung: on exponent-apart lengths (`e^{±700}` and `e^{1.5}` at every vertex,
/// shapes well away from a tie), the `f64` filter on the shifted images, the MPFR-256
/// enclosure and the exact rung each decide, and each gives malachite's sign of `P` on
/// the exact lengths (a second exact backend). A rung that answered `None` would let the
/// ladder fall through unnoticed; a shift by a wrong exponent would leave the filter's
/// range at `e^{±700}`. The control: the oracle tells the thin rhombus (negative) from the
/// fat one (positive), so the three answers are not one constant.
#[test]
fn b67_each_rung_of_the_exponent_apart_predicate_agrees_with_malachite() {
    use crate::delaunay::oracle;
    use penner::predicates::delaunay::Quad;
    use penner::predicates::delaunay_exp::ExpQuad;
    use penner::predicates::ladder::SignPredicate;
    use penner::scalar::{Precision, Sign};
    let shapes: [[f64; 5]; 3] = [
        [1.9, 1.0, 1.0, 1.0, 1.0],
        [1.0, 1.0, 1.0, 1.0, 1.0],
        [1.2, 1.0, 0.9, 1.1, 0.8],
    ];
    let mut seen = Vec::new();
    for x in shapes {
        for (ui, uj) in [(700.0, 700.0), (-700.0, -650.0), (0.0, 3.0)] {
            let l: Vec<ExpLength> = x
                .iter()
                .map(|&v| ExpLength::scaled(v, ui, uj).unwrap())
                .collect();
            let q = Quad {
                ij: l[0],
                jk: l[1],
                ki: l[2],
                il: l[3],
                lj: l[4],
            };
            let m = exact_of(&l);
            let want = oracle([&m[0], &m[1], &m[2], &m[3], &m[4]]);
            let p = ExpQuad(q.as_refs());
            let what = format!("{x:?} scaled by ({ui}, {uj})");
            assert_eq!(p.exact_sign(), Some(want), "exact rung, {what}");
            let prec = Precision::new(256).unwrap();
            assert_eq!(p.enclosure_sign(prec), Some(want), "enclosure rung, {what}");
            assert_eq!(p.filter(), Some(want), "filter rung, {what}");
            seen.push(want);
        }
    }
    assert!(
        seen.contains(&Sign::Negative) && seen.contains(&Sign::Positive),
        "{seen:?}"
    );
}
