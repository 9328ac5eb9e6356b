//! `uniformization::pipeline::uniformize_closed` certifies the **input's exact metric**
//! (issue: real meshes, item 1; B73 (a), B71): on surfaces given by exact decimal
//! positions (irrational lengths), the exact solution is computed here by a different
//! method — plain Newton at 320 bits on the fixed triangulation, angles by the law of
//! cosines and a finite-difference Jacobian — and must lie in the certified box. Control:
//! the box certified for the binary64-rounded lengths alone excludes that solution, and
//! the certificate run on the exact lengths refuses it.

use penner::io::{Metric, Surface};
use penner::mesh::Mesh;
use penner::oracle::certify::{certify, ClaimVerdict};
use penner::oracle::claim::parse_value;
use penner::scalar::{Interval, Mpfr, Precision};
use penner::uniformization::certificate::{check_certificate_on, prove, CertificateOutcome};
use penner::uniformization::input_metric::input_on_t0;
use penner::uniformization::pipeline::{
    uniformize_closed, CertifiedMetric, Options, Precision as P,
};
use penner::uniformization::Targets;
use rug::{Float, Rational};
use serde_json::Value;
use std::fmt::Write as _;

const BITS: u32 = 320;

/// The octahedron of `builders` (vertices `±e_i`) moved by the decimal offsets `d`,
/// and cone angles `4π/3` at every vertex (Gauss–Bonnet: `6·(2π − 4π/3) = 4π`).
fn octahedron(d: &[[&str; 3]; 6]) -> (Surface, Targets) {
    let penner::mesh::builders::Embedded {
        mesh, positions, ..
    } = penner::mesh::builders::octahedron();
    let positions: Vec<[Rational; 3]> = positions
        .iter()
        .zip(d)
        .map(|(b, o)| [0, 1, 2].map(|i| decimal(o[i]) + &b[i]))
        .collect();
    let sq = penner::io::surface::squared_lengths_from_positions(&mesh, &positions);
    let s = Surface::new(
        "octahedron",
        mesh,
        Metric::SquaredLengths(sq),
        Some(positions),
    )
    .expect("valid");
    let t = Targets::from_multiples_of_pi(vec![Rational::from((4, 3)); 6]);
    (s, t)
}

/// An exact decimal string as a rational.
fn decimal(s: &str) -> Rational {
    let (neg, digits) = s.strip_prefix('-').map_or((false, s), |r| (true, r));
    let (int, frac) = digits.split_once('.').unwrap_or((digits, ""));
    let n: Rational = format!("{int}{frac}")
        .parse::<rug::Integer>()
        .unwrap()
        .into();
    let q = n / Rational::from(rug::Integer::from(rug::Integer::u_pow_u(
        10,
        frac.len() as u32,
    )));
    if neg {
        -q
    } else {
        q
    }
}

fn f<T>(x: T) -> Float
where
    Float: rug::Assign<T>,
{
    Float::with_val(BITS, x)
}

/// The cone angles at `u` on the fixed triangulation: corner angles by the law of cosines
/// `acos((b² + c² − a²)/(2bc))` of the scaled lengths `e^{(u_i+u_j)/2}ℓ_ij`.
fn angles(mesh: &Mesh, sq: &[Rational], u: &[Float]) -> Vec<Float> {
    let mut theta = vec![f(0); mesh.n_vertices()];
    for face in mesh.faces() {
        let hs = mesh.face_halfedges(face);
        let len: Vec<Float> = hs
            .iter()
            .map(|&h| {
                let (a, b) = (mesh.tail(h).idx(), mesh.tip(h).idx());
                let l = f(Float::with_val(BITS, &sq[h.edge().idx()]).sqrt());
                l * f(Float::with_val(BITS, &u[a] + &u[b]) / 2u32).exp()
            })
            .collect();
        for i in 0..3 {
            // The corner opposite hs[i] is at the tail of hs[(i + 2) % 3].
            let (a, b, c) = (&len[i], &len[(i + 1) % 3], &len[(i + 2) % 3]);
            let cos = (f(b * b) + f(c * c) - f(a * a)) / f(2u32 * f(b * c));
            theta[mesh.tail(hs[(i + 2) % 3]).idx()] += f(cos).acos();
        }
    }
    theta
}

/// Plain Newton on `θ(u) = Θ` at 320 bits with `u_0 = 0` (the grounded vertex), a
/// central-difference Jacobian (step `2⁻¹²⁰`) and dense Gaussian elimination.
fn exact_solution(mesh: &Mesh, sq: &[Rational], target: &[Float]) -> Vec<Float> {
    let n = mesh.n_vertices();
    let mut u = vec![f(0); n];
    let h = f(Float::with_val(BITS, 1) >> 120);
    for _ in 0..60 {
        let th = angles(mesh, sq, &u);
        let r: Vec<Float> = (1..n).map(|i| f(&target[i] - &th[i])).collect();
        let norm = r
            .iter()
            .map(|x| x.clone().abs())
            .fold(f(0), |a, b| a.max(&b));
        if norm < f(Float::with_val(BITS, 1) >> 290) {
            break;
        }
        let mut jac = vec![vec![f(0); n - 1]; n - 1];
        for j in 1..n {
            let (mut up, mut dn) = (u.clone(), u.clone());
            up[j] += &h;
            dn[j] -= &h;
            let (tp, tm) = (angles(mesh, sq, &up), angles(mesh, sq, &dn));
            for i in 1..n {
                jac[i - 1][j - 1] = f(&tp[i] - &tm[i]) / f(2u32 * h.clone());
            }
        }
        let du = solve(jac, r);
        for i in 1..n {
            u[i] += &du[i - 1];
        }
    }
    u
}

/// `A x = b` by Gaussian elimination with partial pivoting.
fn solve(mut a: Vec<Vec<Float>>, mut b: Vec<Float>) -> Vec<Float> {
    let n = b.len();
    for k in 0..n {
        let p = (k..n)
            .max_by(|&i, &j| {
                a[i][k]
                    .clone()
                    .abs()
                    .partial_cmp(&a[j][k].clone().abs())
                    .unwrap()
            })
            .unwrap();
        a.swap(k, p);
        b.swap(k, p);
        let (top, rest) = a.split_at_mut(k + 1);
        let pivot = &top[k];
        for (r, row) in rest.iter_mut().enumerate() {
            let i = k + 1 + r;
            let m = f(&row[k] / &pivot[k]);
            for (x, p) in row[k..].iter_mut().zip(&pivot[k..]) {
                *x -= f(&m * p);
            }
            let t = f(&m * &b[k]);
            b[i] -= t;
        }
    }
    let mut x = vec![f(0); n];
    for k in (0..n).rev() {
        let mut s = b[k].clone();
        for j in k + 1..n {
            s -= f(&a[k][j] * &x[j]);
        }
        x[k] = f(s / &a[k][k]);
    }
    x
}

/// `‖u* − u‖₂` at 320 bits.
fn distance(exact: &[Float], u: &[Rational]) -> Float {
    exact
        .iter()
        .zip(u)
        .map(|(x, q)| {
            let d = f(x - Float::with_val(BITS, q));
            f(&d * &d)
        })
        .fold(f(0), |a, b| a + b)
        .sqrt()
}

fn offsets() -> Vec<[[&'static str; 3]; 6]> {
    vec![
        [
            ["0.031", "-0.017", "0.002"],
            ["-0.05", "0.013", "0.021"],
            ["0.007", "0.043", "-0.011"],
            ["0.019", "-0.029", "0.037"],
            ["-0.023", "0.011", "0.047"],
            ["0.013", "0.003", "-0.041"],
        ],
        [
            ["0.1", "0.1", "0"],
            ["0", "-0.1", "0.1"],
            ["-0.1", "0", "0.1"],
            ["0.1", "0", "-0.1"],
            ["0", "0.1", "0.1"],
            ["0.1", "-0.1", "0"],
        ],
    ]
}

#[test]
fn t24_pipeline_certifies_the_exact_metric_of_decimal_positions_against_an_independent_newton() {
    for d in offsets() {
        let (s, t) = octahedron(&d);
        let out = uniformize_closed(&s, &t, &Options::default(), &mut |_| {}).expect("solves");
        let sol = &out.solution;
        assert_eq!(
            (sol.euclidean_flips, sol.flip_sequence.len()),
            (0, 0),
            "the oracle below works on the fixed input triangulation"
        );
        assert_eq!(out.metric, Some(CertifiedMetric::Input));
        let proof = out.proof.as_ref().expect("a proof");
        let CertificateOutcome::Holds { distance: r, .. } = proof.outcome else {
            panic!("not certified: {:?}", proof.outcome);
        };
        let pi = Float::with_val(BITS, rug::float::Constant::Pi);
        let target: Vec<Float> = t.over_pi().iter().map(|q| f(&pi * q)).collect();
        let exact = exact_solution(&s.mesh, &s.metric.squared(), &target);
        let err = distance(&exact, &proof.data.u);
        assert!(
            err <= r,
            "the exact solution is {err} from u, beyond the proved {r:e}"
        );

        // Control: the binary64-rounded metric's certificate is about another surface.
        let rounded = prove(sol, 256, 2f64.powi(-200)).expect("refines");
        let CertificateOutcome::Holds { distance: rr, .. } = rounded.outcome else {
            panic!("the rounded metric certifies too");
        };
        let off = distance(&exact, &rounded.data.u);
        assert!(
            off > rr * 1e6,
            "the rounded box must exclude the exact solution: {off} vs {rr:e}"
        );
        let prec = Precision::new(256).unwrap();
        let m = input_on_t0(
            sol,
            &s.mesh,
            &s.lengths::<f64>(()),
            s.lengths::<Mpfr>(prec),
            s.lengths::<Interval<Mpfr>>(prec),
        )
        .expect("no flips to replay");
        let on_exact = check_certificate_on(&rounded.data, Some(&m.enclosures), 256).unwrap();
        assert!(
            !matches!(on_exact, CertificateOutcome::Holds { .. }),
            "the rounded box must not hold for the exact lengths"
        );
    }
}

/// The certificate at `--precision dd` (refined in double-double on the exact lengths) is
/// also about the exact metric, and holds in its own, larger box.
#[test]
fn t24_pipeline_dd_certifies_the_exact_metric() {
    let (s, t) = octahedron(&offsets()[0]);
    let o = Options {
        precision: P::Dd,
        certify: true,
    };
    let out = uniformize_closed(&s, &t, &o, &mut |_| {}).expect("solves");
    assert_eq!(out.metric, Some(CertifiedMetric::Input));
    assert!(out.certified());
}

fn answer(claim: &Value) -> ClaimVerdict {
    let c = parse_value(claim).expect("a well-formed claim");
    certify(&c).expect("supported").verdict
}

/// The claim of the input-metric form holds under `penner certify`; with the surface's
/// positions moved by 10⁻⁶ (another metric), a Euclidean flip index added, or the radius
/// shrunk it is not `holds`.
#[test]
fn t24_input_metric_claim_rechecks_and_its_fields_are_used() {
    let (s, t) = octahedron(&offsets()[1]);
    let out = uniformize_closed(&s, &t, &Options::default(), &mut |_| {}).expect("solves");
    let claim = out.claim().expect("certified");
    assert_eq!(answer(&claim), ClaimVerdict::Holds);
    let mut moved = claim.clone();
    let q: Rational = moved["surface"]["squared_lengths"][0]
        .as_str()
        .expect("exact string")
        .parse()
        .unwrap();
    let q = q * Rational::from((1_000_001, 1_000_000));
    moved["surface"]["squared_lengths"][0] = Value::String(q.to_string());
    moved["surface"]
        .as_object_mut()
        .unwrap()
        .remove("positions");
    assert_ne!(answer(&moved), ClaimVerdict::Holds, "another metric");
    let mut radius = claim.clone();
    radius["radius"] = Value::String("1e-200".into());
    assert_ne!(answer(&radius), ClaimVerdict::Holds, "radius");
    let mut flips = claim.clone();
    flips["euclidean_flips"] = serde_json::json!([0]);
    assert_ne!(
        answer(&flips),
        ClaimVerdict::Holds,
        "a Euclidean flip that was not made"
    );
}

/// MeshLab's cube (`tests/data/real/cube.obj`, integer positions): the solve flips face
/// diagonals, exact ties of the input metric. Each is across a flat hinge, so the new
/// diagonal's squared length is the 3-D one and `T₀` is decided Delaunay exactly: the
/// exact metric certifies, with the Euclidean flips in the claim, and the claim holds.
/// The same metric by its squared lengths alone (no positions) leaves the flipped
/// diagonals only enclosed, so the enclosures cannot decide the ties; the replay of the
/// flips on the exact metric (B80, B83) decides them, and that certificate and its claim
/// hold too. (`t0_delaunay_on_input`'s negative control, a kite split by its long
/// diagonal, is in the library's tests.)
#[test]
fn t24_ties_across_flat_hinges_are_decided_exactly_with_positions() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/real/cube.obj");
    let cube = penner::io::read_path(&path).expect("reads");
    let t = Targets::from_multiples_of_pi(vec![Rational::from((3, 2)); 8]);
    let bare = Surface::new("cube", cube.mesh.clone(), cube.metric.clone(), None).unwrap();
    for s in [&cube, &bare] {
        let out = uniformize_closed(s, &t, &Options::default(), &mut |_| {}).expect("solves");
        assert!(
            out.solution.euclidean_flips > 0,
            "the cube's ties are flipped"
        );
        assert_eq!(
            out.metric,
            Some(CertifiedMetric::Input),
            "{:?}",
            s.positions.is_some()
        );
        let claim = out.claim().expect("certified");
        assert!(!claim["euclidean_flips"].as_array().unwrap().is_empty());
        assert_eq!(answer(&claim), ClaimVerdict::Holds);
    }
}

/// A disk (a hexagonal cap with an inner ring, exact decimal positions: irrational
/// lengths) with `--flat`'s even boundary angles: the solve on the double is certified for
/// the input's exact metric pulled back to both copies (`double_surface`), its claim
/// holds, and with one pulled-back squared length moved by 10⁻⁶ it does not.
#[test]
fn b79_boundary_double_certifies_the_exact_metric_of_decimal_positions() {
    use penner::uniformization::boundary::{flat_with_even_boundary, uniformize_with_boundary};
    use penner::uniformization::pipeline::{certify_solution, double_surface};
    let ring = |r: &str, k: usize, z: &str| -> Vec<[Rational; 3]> {
        let r = decimal(r);
        (0..k)
            .map(|i| {
                let a = std::f64::consts::TAU * i as f64 / k as f64 + 0.1;
                let c = Rational::from_f64((a.cos() * 1000.0).round() / 1000.0).unwrap();
                let s = Rational::from_f64((a.sin() * 1000.0).round() / 1000.0).unwrap();
                [Rational::from(&r * &c), Rational::from(&r * &s), decimal(z)]
            })
            .collect()
    };
    let mut positions = vec![[decimal("0.013"), decimal("-0.021"), decimal("0.37")]];
    positions.extend(ring("0.5", 6, "0.29"));
    positions.extend(ring("1", 6, "0"));
    let mut faces = Vec::new();
    for i in 0..6u32 {
        let (a, b) = (1 + i, 1 + (i + 1) % 6);
        let (c, d) = (7 + i, 7 + (i + 1) % 6);
        faces.extend([[0, a, b], [a, c, d], [a, d, b]]);
    }
    let mesh = Mesh::from_faces(13, &faces).expect("disk");
    let sq = penner::io::surface::squared_lengths_from_positions(&mesh, &positions);
    let s = Surface::new("cap", mesh, Metric::SquaredLengths(sq), Some(positions)).unwrap();
    let t = flat_with_even_boundary(&s.mesh);
    let l = s.lengths::<f64>(());
    let opts = penner::uniformization::UniformizeOptions::default();
    let b = uniformize_with_boundary(&s.mesh, &l, &t, &opts, &mut |_| {}).expect("solves");
    assert!(b.solution.converged());
    let d = double_surface(&s, &b.double).expect("the double's metric");
    // Built without validating again (B78: each face of D carries a face's three values);
    // the independent check is the validation itself, which it passes.
    assert_eq!(d.validate(), Ok(()));
    // Control: a double that is not this surface's is refused.
    let other =
        penner::mesh::double::Double::of(&penner::mesh::builders::grid_disk(1, 1).unwrap().mesh)
            .unwrap();
    assert!(double_surface(&s, &other).is_none());
    let dl = b.double.pull_back_edges(&l).unwrap();
    let c = certify_solution(&d, &dl, &b.solution, P::default()).expect("certifies");
    assert_eq!(c.metric, CertifiedMetric::Input);
    let claim = c.claim(&d, 256).expect("holds");
    assert_eq!(answer(&claim), ClaimVerdict::Holds);
    let mut moved = claim.clone();
    let q: Rational = moved["surface"]["squared_lengths"][3]
        .as_str()
        .unwrap()
        .parse()
        .unwrap();
    moved["surface"]["squared_lengths"][3] =
        Value::String((q * Rational::from((1_000_001, 1_000_000))).to_string());
    assert_ne!(answer(&moved), ClaimVerdict::Holds, "another metric");
}

/// The claim's final triangulation is the one its own flips reach: on a 4×4 torus of
/// revolution (OBJ positions as shortest round-trip decimals, flat targets) the MPFR refinement flips
/// near-ties differently from the `f64` solve (B69), so the final faces of the solve are not
/// those of the certificate's flip sequence. The written claim holds under
/// `penner certify`; the faces of the `f64` solve in its place are refused.
#[test]
fn b69_claim_final_faces_follow_the_refined_flips() {
    let (n, m, big, small) = (4usize, 4usize, 2.0f64, 0.7f64);
    let mut obj = String::new();
    for i in 0..n {
        for j in 0..m {
            let (a, b) = (
                std::f64::consts::TAU * i as f64 / n as f64,
                std::f64::consts::TAU * j as f64 / m as f64,
            );
            let w = big + small * b.cos();
            let _ = writeln!(
                obj,
                "v {:e} {:e} {:e}",
                w * a.cos(),
                w * a.sin(),
                small * b.sin()
            );
        }
    }
    let id = |i: usize, j: usize| (i % n) * m + (j % m) + 1;
    for i in 0..n {
        for j in 0..m {
            let (a, b, c, d) = (id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
            let _ = writeln!(
                obj,
                "f {a} {b} {c}
f {a} {c} {d}"
            );
        }
    }
    let dir = crate::support::scratch("torus-final-faces");
    let path = dir.join("torus4.obj");
    std::fs::write(&path, obj).unwrap();
    let torus = penner::io::read_path(&path).expect("reads");
    let t = Targets::flat(torus.mesh.n_vertices());
    let out = uniformize_closed(&torus, &t, &Options::default(), &mut |_| {}).expect("solves");
    let proof = out.proof.as_ref().expect("converged");
    assert_ne!(
        proof.data.flip_sequence, out.solution.flip_sequence,
        "the test wants a refinement that flips differently"
    );
    let claim = out.claim().expect("certified");
    assert_eq!(answer(&claim), ClaimVerdict::Holds);
    let mut stale = claim.clone();
    stale["final_faces"] = serde_json::json!(out.solution.mesh.face_list());
    assert_ne!(answer(&stale), ClaimVerdict::Holds, "the solve's faces");
}
