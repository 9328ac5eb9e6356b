//! The hyperbolic target (notes Thm 11; B38, B39, B68): the Hessian against finite
//! differences in double-double and against dual numbers, the one-vertex genus-2 and
//! genus-3 surfaces whose solution is known in closed form, hyperbolic Gauss–Bonnet by the
//! L'Huilier area as an independent oracle, refinement and the certificate, typed errors.

use penner::mesh::{builders, Mesh};
use penner::scalar::{Dd, Dual, Real};
use penner::uniformization::hyperbolic::{
    hessian_dense, uniformize_hyperbolic, HyperbolicError, HyperbolicOptions,
    HyperbolicUniformization,
};
use penner::uniformization::hyperbolic_certificate::{
    certify_hyperbolic, refine_hyperbolic, total_area_lhuilier, Existence,
};
use penner::uniformization::{Targets, UniformizeError};
use penner::variational::hyperbolic::{cone_angles, gradient};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rug::float::Constant;
use rug::{Float, Rational};
use std::f64::consts::PI;

/// Lengths in `[lo, hi]` with `hi < 2 lo`: every face a strict triangle.
pub(crate) fn random_lengths(m: &Mesh, lo: f64, hi: f64, seed: u64) -> Vec<f64> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    (0..m.n_edges()).map(|_| rng.gen_range(lo..hi)).collect()
}

fn flat(m: &Mesh) -> Targets {
    Targets::flat(m.n_vertices())
}

/// `max_ij |A_ij − B_ij| / max(1, |B_ij|)`.
fn gap(a: &[Vec<f64>], b: &[Vec<f64>]) -> f64 {
    let mut worst: f64 = 0.0;
    for (ra, rb) in a.iter().zip(b) {
        for (x, y) in ra.iter().zip(rb) {
            worst = worst.max((x - y).abs() / y.abs().max(1.0));
        }
    }
    worst
}

/// `∂(Θ − θ)_i/∂u_j` by central differences of the generic gradient in double-double,
/// step `h = 10⁻⁶`: truncation `h²/6·max|θ'''|`, rounding `2⁻¹⁰⁴/h` (B38, "Checks").
#[allow(clippy::needless_range_loop)] // (i, j) index the matrix
fn hessian_fd_dd(m: &Mesh, l: &[f64], u: &[f64]) -> Vec<Vec<f64>> {
    let n = m.n_vertices();
    let ld: Vec<Dd> = l.iter().map(|&x| Dd::from_f64(x)).collect();
    let zero = vec![Dd::from_f64(0.0); n];
    let h = 1e-6;
    let mut out = vec![vec![0.0; n]; n];
    for j in 0..n {
        let at = |s: f64| {
            let uu: Vec<Dd> = (0..n)
                .map(|k| Dd::from_f64(u[k]) + Dd::from_f64(if k == j { s } else { 0.0 }))
                .collect();
            gradient(m, &ld, &uu, &zero)
        };
        let (p, q) = (at(h), at(-h));
        for i in 0..n {
            out[i][j] = ((p[i] - q[i]) / Dd::from_f64(2.0 * h)).approx_f64();
        }
    }
    out
}

/// The same derivative by forward-mode dual numbers over binary64.
#[allow(clippy::needless_range_loop)] // (i, j) index the matrix
fn hessian_dual(m: &Mesh, l: &[f64], u: &[f64]) -> Vec<Vec<f64>> {
    let n = m.n_vertices();
    let ld: Vec<Dual<f64>> = l.iter().map(|&x| Dual::constant(x)).collect();
    let zero = vec![Dual::constant(0.0); n];
    let mut out = vec![vec![0.0; n]; n];
    for j in 0..n {
        let uu: Vec<Dual<f64>> = (0..n)
            .map(|k| {
                if k == j {
                    Dual::variable(u[k])
                } else {
                    Dual::constant(u[k])
                }
            })
            .collect();
        let g = gradient(m, &ld, &uu, &zero);
        for i in 0..n {
            out[i][j] = g[i].d;
        }
    }
    out
}

/// B38: the Hessian of the binary64 kernel equals the Jacobian of `Θ − θ_hyp` by
/// finite differences at double-double and by dual numbers, on one-vertex surfaces (every
/// edge a loop) and random multi-vertex genus-2 surfaces; a Hessian with its diagonal
/// halved is rejected by the same comparison.
#[test]
fn b38_hyperbolic_hessian_matches_finite_differences_and_dual_numbers() {
    let mut surfaces = vec![builders::genus(2).unwrap(), builders::genus(3).unwrap()];
    for seed in 0..3 {
        surfaces.push(builders::random_surface(2, 7, seed).unwrap());
    }
    let mut checked = 0;
    for (k, m) in surfaces.iter().enumerate() {
        let l = random_lengths(m, 1.2, 1.6, k as u64);
        let mut rng = ChaCha8Rng::seed_from_u64(100 + k as u64);
        let u: Vec<f64> = (0..m.n_vertices())
            .map(|_| rng.gen_range(-0.03..0.03))
            .collect();
        let Some(h) = hessian_dense(m, &l, &u) else {
            continue;
        };
        let fd = hessian_fd_dd(m, &l, &u);
        let du = hessian_dual(m, &l, &u);
        // B38 "Checks": 10⁻⁸ covers the kernel's relative error (≤ 10³u) and the
        // difference quotient's truncation (≤ 10⁻¹²·max|θ'''|).
        assert!(
            gap(&h, &fd) < 1e-8,
            "surface {k}: FD gap {:e}",
            gap(&h, &fd)
        );
        assert!(
            gap(&h, &du) < 1e-8,
            "surface {k}: dual gap {:e}",
            gap(&h, &du)
        );
        // Symmetric.
        for i in 0..h.len() {
            for j in 0..h.len() {
                assert!((h[i][j] - h[j][i]).abs() <= 1e-12 * h[i][i].abs().max(1.0));
            }
        }
        // Negative control: the diagonal halved.
        let mut wrong = h.clone();
        for (i, row) in wrong.iter_mut().enumerate() {
            row[i] *= 0.5;
        }
        assert!(gap(&wrong, &fd) > 1e-3, "surface {k}: control accepted");
        checked += 1;
    }
    assert!(checked >= 4, "only {checked} surfaces had strict triangles");
}

/// The equilateral one-vertex genus-`g` surface: every side `L`, so by symmetry (one
/// vertex) the solution makes `6(2g − 1)·… ` equal corners `α = 2π/(3(4g − 2))`, and
/// `cosh ℓ̃ = cos α/(1 − cos α)` (law of cosines of an equilateral triangle), so
/// `u* = ½ ln((2c − 1)/(2(1 − c))) − ln sinh(L/2)`, `c = cos α` (B68), in MPFR.
pub(crate) fn closed_form_u(g: u32, side: f64, bits: u32) -> Float {
    let alpha = Float::with_val(bits, Constant::Pi) * 2u32 / (3 * (4 * g - 2));
    let c = alpha.cos();
    let num = Float::with_val(bits, 2 * c.clone() - 1u32);
    let den = Float::with_val(bits, 2 * (1u32 - c));
    let half_log = Float::with_val(bits, num / den).ln() / 2u32;
    let s = Float::with_val(bits, side / 2.0).sinh().ln();
    half_log - s
}

fn solve_flat(m: &Mesh, l: &[f64]) -> HyperbolicUniformization {
    uniformize_hyperbolic(m, l, &flat(m), &HyperbolicOptions::default()).unwrap()
}

/// B68: genus 2 and 3, several side lengths: the `f64` solve, the double-double and the
/// 256-bit refinements agree with the closed form to the stated bounds; the closed form of
/// the wrong angle (`2π/(3(4g−2)+1)`) is rejected by the same comparison.
#[test]
fn b68_equilateral_one_vertex_surfaces_match_the_closed_form() {
    for g in [2u32, 3] {
        let m = builders::genus(g).unwrap();
        for side in [0.3, 1.0, 2.5, 6.0] {
            let l = vec![side; m.n_edges()];
            let sol = solve_flat(&m, &l);
            assert!(sol.converged(), "g={g} L={side}: {:?}", sol.stop);
            let exact = closed_form_u(g, side, 256);
            let e = exact.to_f64();
            // B68: |u − u*| ≤ residual/μ, μ = 36 tan(α/2)(2c − 1)·(2g−1)/3 ≥ 0.5 here,
            // residual ≤ 10⁻¹⁰ (the solver's tolerance): 10⁻⁹ with rounding margin.
            assert!(
                (sol.u[0] - e).abs() < 1e-9,
                "g={g} L={side}: {} vs {e}",
                sol.u[0]
            );
            let dd = refine_hyperbolic::<Dd>(&sol, (), 1e-28, 20).unwrap();
            assert!(dd.reached, "dd history {:?}", dd.history);
            let ud = dd.u[0].to_rational().unwrap();
            let gap_dd = (Float::with_val(256, &ud) - &exact).abs().to_f64();
            assert!(gap_dd < 1e-26, "g={g} L={side}: Dd gap {gap_dd:e}");
            let prec = penner::scalar::Precision::new(256).unwrap();
            let mp = refine_hyperbolic::<penner::scalar::Mpfr>(&sol, prec, 1e-70, 30).unwrap();
            assert!(mp.reached, "mpfr history {:?}", mp.history);
            let um = mp.u[0].to_rational().unwrap();
            let gap_mp = (Float::with_val(256, &um) - &exact).abs().to_f64();
            assert!(gap_mp < 1e-68, "g={g} L={side}: MPFR gap {gap_mp:e}");
            // Negative control: the closed form for a wrong corner angle.
            let alpha_wrong = 2.0 * PI / f64::from(3 * (4 * g - 2) + 1);
            let c = alpha_wrong.cos();
            let wrong = 0.5 * ((2.0 * c - 1.0) / (2.0 * (1.0 - c))).ln() - (side / 2.0).sinh().ln();
            assert!((sol.u[0] - wrong).abs() > 1e-3, "control accepted");
        }
    }
}

/// B68 (oracle): hyperbolic Gauss–Bonnet. At the solution of `Θ ≡ 2π` the total area by
/// the L'Huilier formula (no corner angles) is `−2πχ = 4π(g − 1)` within
/// `V·residual + F·10⁻¹³`; the L'Huilier area of a triangle equals `π − Σα` (a second
/// formula) on random triangles; the input metric and a perturbed `u` are rejected.
#[test]
fn b68_gauss_bonnet_area_by_lhuilier_at_the_solution() {
    // The two area formulas agree on random triangles (and so L'Huilier is an oracle).
    let tri = Mesh::from_faces(3, &[[0, 1, 2], [0, 2, 1]]).unwrap();
    let mut rng = ChaCha8Rng::seed_from_u64(7);
    for _ in 0..200 {
        let l: Vec<f64> = (0..3).map(|_| rng.gen_range(0.1..3.0)).collect();
        let (a, b, c) = (l[0], l[1], l[2]);
        if !(a < b + c && b < a + c && c < a + b) {
            continue;
        }
        let by_angles: f64 = 2.0 * PI - cone_angles(&tri, &l, true).iter().sum::<f64>();
        let by_lhuilier = total_area_lhuilier(&tri, &l).unwrap();
        assert!((by_angles - by_lhuilier).abs() < 1e-9 * (1.0 + by_lhuilier.recip()));
    }
    let mut solved = 0;
    for seed in 0..8u64 {
        let g = 2 + (seed % 2) as u32;
        let m = if seed < 4 {
            builders::genus(g).unwrap()
        } else {
            builders::random_surface(g, 2 + seed as u32, seed).unwrap()
        };
        let l = random_lengths(&m, 1.0, 1.5, seed);
        // With flips (B87) every one of these converges.
        let sol = solve_flat(&m, &l);
        assert!(sol.converged(), "seed {seed}: {:?}", sol.stop);
        solved += 1;
        let area = total_area_lhuilier(&sol.mesh, &sol.scaled_lengths()).unwrap();
        let expected = 4.0 * PI * f64::from(g - 1);
        let tol = m.n_vertices() as f64 * sol.residual_max + m.n_faces() as f64 * 1e-13;
        assert!(
            (area - expected).abs() <= tol,
            "seed {seed}: {area} vs {expected}"
        );
        // Negative controls: the input metric, and a perturbed u.
        let a0 = total_area_lhuilier(&m, &l).unwrap();
        assert!(
            (a0 - expected).abs() > 1e3 * tol,
            "seed {seed}: input area {a0}"
        );
        let mut bad = sol.clone();
        bad.u[0] += 1e-4;
        let a1 = total_area_lhuilier(&bad.mesh, &bad.scaled_lengths()).unwrap();
        assert!(
            (a1 - expected).abs() > tol,
            "seed {seed}: perturbed area {a1}"
        );
    }
    assert_eq!(solved, 8);
}

/// B39: at the 256-bit refinement the residual is enclosed below `10⁻⁶⁰` and an exact
/// solution certified within `10⁻⁵⁵`; at `u + 10⁻⁶` the enclosure excludes 0 (the
/// perturbed `u` is certified *not* a solution) and the distance is at least `10⁻⁷`.
#[test]
fn b39_certificate_holds_at_the_refined_u_and_rejects_a_perturbed_one() {
    for (m, l) in [(builders::genus(2).unwrap(), vec![1.0; 9]), {
        let m = builders::random_surface(2, 8, 3).unwrap();
        let l = random_lengths(&m, 1.0, 1.5, 3);
        (m, l)
    }] {
        let sol = solve_flat(&m, &l);
        if !sol.converged() {
            continue;
        }
        let prec = penner::scalar::Precision::new(256).unwrap();
        let r = refine_hyperbolic::<penner::scalar::Mpfr>(&sol, prec, 1e-65, 30).unwrap();
        let u: Vec<Rational> = r.u.iter().map(|x| x.to_rational().unwrap()).collect();
        let cert = certify_hyperbolic(&sol, &u, 256).unwrap();
        assert!(
            cert.residual_max < 1e-60,
            "residual {:e}",
            cert.residual_max
        );
        match cert.existence {
            Existence::Holds { distance, .. } => assert!(distance < 1e-55),
            Existence::Undecided { reason } => panic!("not certified: {reason}"),
        }
        let mut up = u.clone();
        up[0] += Rational::from((1, 1_000_000));
        let bad = certify_hyperbolic(&sol, &up, 256).unwrap();
        assert!(
            bad.residual
                .iter()
                .any(|g| g.sign().is_some_and(|s| s != penner::scalar::Sign::Zero)),
            "perturbed u not excluded"
        );
        if let Existence::Holds { distance, .. } = bad.existence {
            assert!(distance > 1e-7, "perturbed distance {distance:e}");
        }
    }
}

/// Typed errors: genus 0 and 1 with `Θ ≡ 2π` (no area), a length that is not a
/// triangle, a wrong length count; cone targets with positive area are accepted.
#[test]
fn b38_hyperbolic_input_errors_are_typed() {
    let torus = builders::one_vertex_torus();
    let e = uniformize_hyperbolic(
        &torus,
        &[1.0; 3],
        &flat(&torus),
        &HyperbolicOptions::default(),
    );
    assert!(
        matches!(e, Err(HyperbolicError::NoArea { chi: 0, .. })),
        "{e:?}"
    );
    let sphere = builders::two_triangle_sphere();
    let e = uniformize_hyperbolic(
        &sphere,
        &[1.0; 3],
        &flat(&sphere),
        &HyperbolicOptions::default(),
    );
    assert!(matches!(e, Err(HyperbolicError::NoArea { chi: 2, .. })));
    let m = builders::genus(2).unwrap();
    let mut l = vec![1.0; 9];
    l[0] = 5.0;
    let e = uniformize_hyperbolic(&m, &l, &flat(&m), &HyperbolicOptions::default());
    assert!(
        matches!(e, Err(HyperbolicError::NotATriangle { .. })),
        "{e:?}"
    );
    let e = uniformize_hyperbolic(&m, &[1.0; 8], &flat(&m), &HyperbolicOptions::default());
    assert!(matches!(
        e,
        Err(HyperbolicError::Input(UniformizeError::LengthCount { .. }))
    ));
    // A cone of angle π at the one vertex: Σ(2π − Θ) = π > 2πχ = −4π.
    let cone = Targets::from_multiples_of_pi(vec![Rational::from(1)]);
    let sol = uniformize_hyperbolic(&m, &[1.0; 9], &cone, &HyperbolicOptions::default()).unwrap();
    assert!(sol.converged(), "{:?}", sol.stop);
    // Negative control of the exact Gauss–Bonnet test: Θ = 6π on genus 2 gives
    // Σ(2π − Θ) = −4π = 2πχ, zero area: refused.
    let none = Targets::from_multiples_of_pi(vec![Rational::from(6)]);
    let e = uniformize_hyperbolic(&m, &[1.0; 9], &none, &HyperbolicOptions::default());
    assert!(matches!(e, Err(HyperbolicError::NoArea { .. })), "{e:?}");
}

fn surface_file(dir: &std::path::Path, name: &str, m: Mesh, l: &[f64]) -> String {
    use penner::io::{json, Metric, Surface};
    let metric = Metric::Lengths(l.iter().map(|&x| Rational::from_f64(x).unwrap()).collect());
    let s = Surface::new(name, m, metric, None).unwrap();
    let p = dir.join(format!("{name}.json"));
    std::fs::write(&p, json::write(&s)).unwrap();
    p.display().to_string()
}

/// `penner uniformize --hyperbolic` end to end: the equilateral genus-2 surface certifies
/// (exit 0) and writes a `hyperbolic_uniformization` claim whose `u` is the closed form
/// (B68); `penner certify` re-checks it from scratch (holds, exit 0) and refutes it with one
/// `u` moved by 10⁻⁶ (exit 1); the torus is refused with exit 3 naming Gauss–Bonnet; an
/// existing output file is never overwritten (exit 4, contents kept).
#[test]
fn b39_cli_uniformize_hyperbolic_certifies_and_refuses_bad_input() {
    use crate::support::{penner, scratch, text};
    let d = scratch("uniformize-hyperbolic");
    let surf = surface_file(&d, "genus2", builders::genus(2).unwrap(), &[1.0; 9]);
    let res = d.join("result.json").display().to_string();
    let out = penner(&[
        "uniformize",
        &surf,
        "--hyperbolic",
        "--precision",
        "128",
        "-o",
        &res,
    ]);
    let shown = format!("{}{}", text(&out.stdout), text(&out.stderr));
    assert_eq!(out.status.code(), Some(0), "{shown}");
    assert!(shown.contains("certified"), "{shown}");
    // B87: the flip counts are printed (the equilateral surface is Delaunay throughout).
    assert!(
        shown.contains("0 geometric flips") && shown.contains("0 Ptolemy flips"),
        "{shown}"
    );
    let written = std::fs::read_to_string(&res).unwrap();
    let mut doc: serde_json::Value = serde_json::from_str(&written).unwrap();
    assert_eq!(doc["kind"], "hyperbolic_uniformization");
    let u = penner::io::json::exact_number(&doc["u"][0], "u").unwrap();
    let exact = closed_form_u(2, 1.0, 256);
    let radius = penner::io::json::exact_number(&doc["radius"], "radius").unwrap();
    let gap = (Float::with_val(256, &u) - &exact).abs();
    assert!(gap <= radius, "{u} vs {exact}: gap {gap} > radius {radius}");
    let recheck = penner(&["certify", &res]);
    assert_eq!(recheck.status.code(), Some(0), "{}", text(&recheck.stdout));
    let answer: serde_json::Value = serde_json::from_str(&text(&recheck.stdout)).unwrap();
    assert_eq!(answer["verdict"], "holds");
    assert_eq!(answer["kind"], "hyperbolic_uniformization");
    // Negative control: u moved by 10⁻⁶ is refuted (certified), exit 1.
    doc["u"][0] = serde_json::json!((u + Rational::from((1, 1_000_000))).to_string());
    let bad = d.join("moved.json");
    std::fs::write(&bad, doc.to_string()).unwrap();
    let refuted = penner(&["certify", &bad.display().to_string()]);
    assert_eq!(refuted.status.code(), Some(1), "{}", text(&refuted.stdout));
    // Never overwrite.
    let again = penner(&["uniformize", &surf, "--hyperbolic", "-o", &res]);
    assert_eq!(again.status.code(), Some(4), "{}", text(&again.stderr));
    assert_eq!(std::fs::read_to_string(&res).unwrap(), written);
    // B87: a random 8-vertex genus-2 metric needing geometric and Ptolemy flips certifies
    // through the CLI, and its claim (with `flips`) re-checks to holds.
    let m = builders::random_surface(2, 8, 2).unwrap();
    let l = random_lengths(&m, 1.0, 1.9, 2);
    let flipped = surface_file(&d, "random8", m, &l);
    let res8 = d.join("random8-result.json").display().to_string();
    let out = penner(&["uniformize", &flipped, "--hyperbolic", "-o", &res8]);
    let shown = format!("{}{}", text(&out.stdout), text(&out.stderr));
    assert_eq!(out.status.code(), Some(0), "{shown}");
    assert!(
        !shown.contains("0 geometric flips") && !shown.contains(" 0 Ptolemy flips"),
        "{shown}"
    );
    let doc: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&res8).unwrap()).unwrap();
    assert!(!doc["flips"].as_array().unwrap().is_empty());
    let recheck = penner(&["certify", &res8]);
    assert_eq!(recheck.status.code(), Some(0), "{}", text(&recheck.stdout));
    // Genus 1: typed refusal.
    let torus = surface_file(&d, "torus", builders::one_vertex_torus(), &[1.0, 1.0, 1.5]);
    let out = penner(&["uniformize", &torus, "--hyperbolic"]);
    assert_eq!(out.status.code(), Some(3), "{}", text(&out.stdout));
    assert!(
        text(&out.stderr).contains("Gauss–Bonnet"),
        "{}",
        text(&out.stderr)
    );
}

/// B104 on enclosures (issue: certificates about the user's metric): genus 2 with every
/// length `11/10`, not a binary64 number. The pipeline certifies the exact metric
/// (`CertifiedMetric::Input`, distance below 10⁻⁵⁰); the claim it writes speaks of the
/// binary64 lengths (the claim form's) and holds under `penner certify`. Control: the two
/// certified solutions differ by about the rounding of `11/10` (`> 10⁻²⁰`), far beyond
/// either distance, so the box certified for the exact metric excludes the rounded
/// metric's solution and the other way round: they are certificates of different metrics.
#[test]
fn b104_hyperbolic_certificate_is_about_the_exact_input_metric() {
    use penner::io::{Metric, Surface};
    use penner::oracle::certify::{certify, ClaimVerdict};
    use penner::oracle::claim::parse_value;
    use penner::uniformization::hyperbolic_certificate::Existence;
    use penner::uniformization::pipeline::{uniformize_hyperbolic, CertifiedMetric, Options};
    let m = builders::genus(2).unwrap();
    let l = Metric::Lengths(vec![Rational::from((11, 10)); m.n_edges()]);
    let s = Surface::new("genus 2, lengths 11/10", m, l, None).unwrap();
    let out = uniformize_hyperbolic(&s, None, &Options::default()).expect("solves");
    assert_eq!(out.metric, CertifiedMetric::Input);
    let Some(Existence::Holds { distance, .. }) = out.certificate.as_ref().map(|c| &c.existence)
    else {
        panic!("not certified: {:?}", out.certificate.map(|c| c.existence));
    };
    assert!(*distance < 1e-50, "{distance:e}");
    assert!(matches!(
        out.claim_metric(),
        CertifiedMetric::Rounded { .. }
    ));
    let claim = out.claim().expect("a claim of the binary64 lengths");
    let answer = certify(&parse_value(&claim).unwrap()).unwrap();
    assert_eq!(answer.verdict, ClaimVerdict::Holds);
    let (u_exact, _) = out.refined.as_ref().unwrap();
    let gap = claim["u"]
        .as_array()
        .unwrap()
        .iter()
        .zip(u_exact)
        .map(|(c, e)| {
            let c = penner::scalar::parse_rational(c.as_str().unwrap()).unwrap();
            (c - e).abs().to_f64()
        })
        .fold(0.0, f64::max);
    assert!(
        gap > 1e-20,
        "the two metrics' solutions differ by {gap:e} only"
    );
}
