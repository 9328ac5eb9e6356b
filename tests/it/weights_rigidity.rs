//! T06 certified by the positive definiteness of the weight energy's Hessian (proofs/B102):
//! the per-face enclosure against second differences of the area at high precision, the
//! certificate on the corpus, random surfaces, needles and caps and surfaces beyond the
//! dense recovery's size, and inputs where the argument must not certify.

use crate::meshgen::{icosphere, jittered_torus, random_tetrahedron};
use penner::geometry::enclosure::area_hessian::AreaHessianKernel;
use penner::geometry::triangle::kahan_area;
use penner::mesh::Mesh;
use penner::oracle::precision::Prec;
use penner::scalar::{Dd, Interval, Mpfr, Precision, Real};
use penner::theorems::t06_cotan_weights_metric::{
    check_weights_determine_metric, verify_weight_boxes, weight_enclosures,
};
use penner::theorems::t06_weight_rigidity::{
    certify_by_faces, certify_positive_definite, certify_weight_rigidity, enclosure_bits,
    grounded_area_hessian,
};
use penner::theorems::{Settings, Verdict};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rug::Rational;

fn prec(bits: u64) -> Precision {
    Precision::new(bits).unwrap()
}

/// `−2A` of the triangle with squared sides `q`, by Kahan's formula on the sides `√q`
/// (a different formula from the kernel's cotangents), at the precision of `q`.
fn minus_two_area(q: &[Mpfr; 3]) -> Mpfr {
    let l = q.clone().map(|x| x.sqrt());
    kahan_area(&l[0], &l[1], &l[2]) * &q[0].lit(-2.0)
}

/// Second differences of `−2A` in `q` with step `h = 2⁻²⁰⁰·min q` at 1200 bits: the
/// truncation error is `O(h²)` relative (about `2⁻⁴⁰⁰`), the cancellation costs about 400
/// bits of the 1200.
fn second_differences(l: [f64; 3]) -> [[f64; 3]; 3] {
    let p = prec(1200);
    let q: [Mpfr; 3] = l.map(|x| {
        let x = Mpfr::from_f64(x, p);
        x.clone() * &x
    });
    let qmin = l.iter().fold(f64::INFINITY, |a, &x| a.min(x * x));
    let h = Mpfr::from_f64(qmin, p) * &Mpfr::from_f64(2f64.powi(-200), p);
    let at = |di: usize, si: f64, dj: usize, sj: f64| {
        let mut x = q.clone();
        x[di] += &(h.clone() * &h.lit(si));
        x[dj] += &(h.clone() * &h.lit(sj));
        minus_two_area(&x)
    };
    let mut out = [[0.0; 3]; 3];
    #[allow(clippy::needless_range_loop)] // (i, j) index the difference directions
    for i in 0..3 {
        for j in 0..3 {
            let d = if i == j {
                let mut c = q.clone();
                let f0 = minus_two_area(&c);
                c[i] += &h;
                let fp = minus_two_area(&c);
                c[i] -= &(h.clone() * &h.lit(2.0));
                let fm = minus_two_area(&c);
                (fp - &(f0 * &h.lit(2.0)) + &fm) / &(h.clone() * &h)
            } else {
                (at(i, 1.0, j, 1.0) - &at(i, 1.0, j, -1.0) - &at(i, -1.0, j, 1.0)
                    + &at(i, -1.0, j, -1.0))
                    / &(h.clone() * &h * &h.lit(4.0))
            };
            out[i][j] = d.approx_f64();
        }
    }
    out
}

fn kernel_bounds(l: [f64; 3], bits: u32) -> Option<[[(f64, f64); 3]; 3]> {
    let p = prec(u64::from(bits));
    let li = l.map(|x| Interval::point(Mpfr::from_f64(x, p)));
    AreaHessianKernel::new(bits).face([&li[0], &li[1], &li[2]])
}

/// Random strict triangles: generic, obtuse, and needles down to sides `10⁻⁸` apart.
fn random_triangle(rng: &mut ChaCha8Rng) -> [f64; 3] {
    loop {
        let a = 0.1 + rng.r#gen::<f64>();
        let b = 0.1 + rng.r#gen::<f64>();
        let c = match rng.gen_range(0..3) {
            0 => (a - b).abs() + (a + b - (a - b).abs()) * rng.r#gen::<f64>(),
            1 => (a + b) * (1.0 - 10f64.powi(-rng.gen_range(2..8))),
            _ => (a - b).abs() + 10f64.powi(-rng.gen_range(2..8)),
        };
        if c > (a - b).abs() && c < a + b && c > 0.0 {
            return [a, b, c];
        }
    }
}

#[test]
fn b102_face_hessian_encloses_the_second_differences_of_the_area() {
    let mut rng = ChaCha8Rng::seed_from_u64(102);
    let mut excluded = 0;
    let n = 40;
    for k in 0..n {
        let l = random_triangle(&mut rng);
        let fd = second_differences(l);
        for bits in [128, 170, 576] {
            let h = kernel_bounds(l, bits).unwrap_or_else(|| panic!("{l:?} at {bits} bits"));
            for i in 0..3 {
                for j in 0..3 {
                    let (lo, hi) = h[i][j];
                    // The differences are within 2⁻³⁰⁰ relative of the exact entry; the f64
                    // bounds are outward-rounded, so a margin of 2⁻²⁰⁰ of the magnitude is
                    // far below their width.
                    let m = 2f64.powi(-200) * (lo.abs() + hi.abs());
                    assert!(
                        lo - m <= fd[i][j] && fd[i][j] <= hi + m,
                        "{l:?} ({i},{j}) at {bits}: {} not in [{lo}, {hi}]",
                        fd[i][j]
                    );
                }
            }
            // Homogeneity: −2∇²A q = 0 (the scaling direction is in the kernel).
            for row in &h {
                let (mut lo, mut hi) = (0.0, 0.0);
                for (e, x) in row.iter().zip(l) {
                    lo += e.0 * x * x;
                    hi += e.1 * x * x;
                }
                let s = row
                    .iter()
                    .zip(l)
                    .map(|(e, x)| e.1.abs() * x * x)
                    .sum::<f64>();
                assert!(lo - 1e-12 * s <= 0.0 && 0.0 <= hi + 1e-12 * s, "{l:?}");
            }
        }
        // Negative control: the enclosure at a triangle with one side longer by 10⁻⁶
        // relative excludes some second difference of the original one.
        let mut moved = l;
        moved[k % 3] *= 1.0 + 1e-6;
        if let Some(h) = kernel_bounds(moved, 170) {
            let out = (0..9).any(|t| {
                let (i, j) = (t / 3, t % 3);
                fd[i][j] < h[i][j].0 || fd[i][j] > h[i][j].1
            });
            excluded += usize::from(out);
        }
    }
    assert!(
        excluded >= n - 2,
        "{excluded} of {n} moved triangles excluded"
    );
}

/// Small closed surfaces with Euclidean lengths (as in the variational tests).
fn small_surface(seed: u64) -> (Mesh, Vec<f64>) {
    match seed % 3 {
        0 => {
            let e = random_tetrahedron(seed);
            let m = e.mesh();
            let l = e.lengths(&m);
            (m, l)
        }
        1 => {
            let mut e = icosphere(1);
            let mut rng = ChaCha8Rng::seed_from_u64(seed);
            for p in &mut e.pos {
                let s = 1.0 + 0.1 * (rng.r#gen::<f64>() - 0.5);
                *p = p.map(|x| x * s);
            }
            let m = e.mesh();
            let l = e.lengths(&m);
            (m, l)
        }
        _ => jittered_torus(4, 5, seed),
    }
}

fn certified_holds(v: &Verdict) -> bool {
    matches!(
        v,
        Verdict::Holds {
            certified: true,
            ..
        }
    )
}

/// The certificate holds on the corpus (solids, the two-triangle sphere and one-vertex
/// torus whose faces repeat edges, the grid disk with boundary) at f64, Dd and MPFR-256,
/// and on random small surfaces, where the independent recovery (dense Newton on the
/// weights, B59) agrees: the metric's own weights give back `ℓ²/ℓ₀²`.
#[test]
fn b102_certifies_the_corpus_and_random_surfaces_and_the_recovery_agrees() {
    let s = Settings::default();
    let check = penner::oracle::catalogue()
        .into_iter()
        .find(|c| c.id == "T06")
        .unwrap();
    for case in penner::oracle::corpus::standard() {
        for p in [Prec::F64, Prec::Dd, Prec::Mpfr(prec(256))] {
            let v = (check.run)(&case, p, &s).unwrap();
            assert!(certified_holds(&v), "{} at {p:?}: {v:?}", case.name);
        }
    }
    for seed in 0..crate::support::cases(6, 30) as u64 {
        let (m, l) = small_surface(seed);
        let c = certify_weight_rigidity(&m, &l, 0);
        assert!(c.is_ok(), "seed {seed}: {c:?}");
        let ld: Vec<Dd> = l.iter().map(|&x| <Dd as Real>::from_f64(x, ())).collect();
        assert!(
            certify_weight_rigidity(&m, &ld, 0).is_ok(),
            "seed {seed} Dd"
        );
        // Another gauge edge certifies too (the kernel is span(q) whichever edge is fixed).
        assert!(certify_weight_rigidity(&m, &l, m.n_edges() - 1).is_ok());
        // The independent computation: the recovery from the metric's weights.
        let boxes = weight_enclosures(&m, &l).unwrap();
        let r = verify_weight_boxes(&m, &l, &boxes, &s);
        assert!(
            matches!(
                r,
                Verdict::Holds {
                    certified: false,
                    ..
                }
            ),
            "seed {seed}: {r:?}"
        );
        assert!(certified_holds(&check_weights_determine_metric(&m, &l, &s)));
    }
}

/// Needles and caps (sides to `10⁻²⁴`): the registry's T06 never `fails`, and is
/// certified wherever every face is a certified strict triangle — by the verified
/// factorization (B102) where binary64 resolves the conditioning, by faces (B103) elsewhere
/// (the needles of the hinges: the midpoint matrix is not numerically definite). Wherever
/// B102 certifies, B103 does too. Only the caps rounded to degenerate triangles at f64
/// (`½ + 10⁻²⁴ = ½`) stay undecided.
#[test]
fn b103_needles_and_caps_are_certified_by_faces_and_never_refuted() {
    let s = Settings::default();
    let check = penner::oracle::catalogue()
        .into_iter()
        .find(|c| c.id == "T06")
        .unwrap();
    let cases: Vec<_> = [3, 9, 16, 24]
        .into_iter()
        .flat_map(crate::adversarial_gen::needles_and_caps)
        .collect();
    let (mut by_cholesky, mut by_faces_only, mut undecided) = (0, 0, 0);
    for case in &cases {
        for p in [Prec::F64, Prec::Dd, Prec::Mpfr(prec(256))] {
            let v = (check.run)(case, p, &s).unwrap();
            assert!(!v.fails(), "{} at {p:?}: {v:?}", case.name);
            let (chol, faces) = match p {
                Prec::F64 => {
                    let l = case.lengths::<f64>(());
                    (
                        certify_weight_rigidity(&case.mesh, &l, 0).is_ok(),
                        certify_by_faces(&case.mesh, &l).is_ok(),
                    )
                }
                Prec::Dd => {
                    let l = case.lengths::<Dd>(());
                    (
                        certify_weight_rigidity(&case.mesh, &l, 0).is_ok(),
                        certify_by_faces(&case.mesh, &l).is_ok(),
                    )
                }
                _ => {
                    let l = case.lengths::<Mpfr>(prec(256));
                    (
                        certify_weight_rigidity(&case.mesh, &l, 0).is_ok(),
                        certify_by_faces(&case.mesh, &l).is_ok(),
                    )
                }
            };
            assert!(!chol || faces, "{} at {p:?}: B102 without B103", case.name);
            assert_eq!(certified_holds(&v), faces, "{} at {p:?}: {v:?}", case.name);
            if !faces {
                assert!(
                    matches!(p, Prec::F64) && case.name.contains("cap 1e-24"),
                    "{} at {p:?}: {v:?}",
                    case.name
                );
            }
            by_cholesky += usize::from(chol);
            by_faces_only += usize::from(faces && !chol);
            undecided += usize::from(!faces);
        }
    }
    // Measured: 39 by the factorization, 42 by faces only, 3 undecided (of 84).
    assert!(by_cholesky >= 30 && by_faces_only >= 30 && undecided <= 3);
}

/// Inputs where neither argument (B102's factorization, B103's faces) may certify. (1) Two disjoint tetrahedra: scaling one
/// of them keeps every weight, so T06 is false there and the grounded Hessian is singular
/// (the check says `NotApplicable`). (2) A face with sides `1, 1, 2`: the metric is on the
/// boundary of the cone, not an interior point; the certificate names that face and the
/// check never fails. (3) A certified matrix whose enclosure is widened at one diagonal
/// entry beyond the eigenvalue bound.
#[test]
fn b102_b103_singular_or_degenerate_input_is_never_certified() {
    let s = Settings::default();
    let (t, l) = small_surface(0);
    let one = random_tetrahedron(0);
    let mut pos = one.pos.clone();
    pos.extend(one.pos.iter().map(|p| p.map(|x| 2.0 * x + 5.0)));
    let mut faces = one.faces.clone();
    faces.extend(one.faces.iter().map(|f| f.map(|v| v + 4)));
    let both = crate::meshgen::Embedded { pos, faces };
    let two = both.mesh();
    let two_l = both.lengths(&two);
    let c = certify_weight_rigidity(&two, &two_l, 0);
    assert!(c.is_err(), "two components certified: {c:?}");
    assert!(certify_by_faces(&two, &two_l).is_err());
    assert!(matches!(
        check_weights_determine_metric(&two, &two_l, &s),
        Verdict::NotApplicable { .. }
    ));
    // The same surface's components one at a time certify (the control is not vacuous).
    assert!(certify_weight_rigidity(&t, &l, 0).is_ok());
    assert!(certify_by_faces(&t, &l).is_ok());

    // (2) A degenerate face: tetrahedron with face (0, 1, 2) of sides 1, 1, 2.
    let tet = Mesh::from_faces(4, &[[0, 1, 2], [0, 2, 3], [0, 3, 1], [1, 3, 2]]).unwrap();
    let len = |a: u32, b: u32| match (a.min(b), a.max(b)) {
        (0, 1) | (1, 2) => 1.0,
        _ => 2.0, // (0, 2), the degenerate face's long side, and the edges to 3
    };
    let tl: Vec<f64> = tet
        .edges()
        .map(|ed| {
            let h = ed.halfedge();
            len(tet.tail(h).idx() as u32, tet.tip(h).idx() as u32)
        })
        .collect();
    let c = certify_weight_rigidity(&tet, &tl, 0).unwrap_err();
    assert_eq!(c.elements.len(), 1, "{c:?}");
    assert_eq!(c.elements[0].0, "f0");
    let c = certify_by_faces(&tet, &tl).unwrap_err();
    assert_eq!(c.elements.len(), 1, "{c:?}");
    assert_eq!(c.elements[0].0, "f0");
    for bits in [53, 256] {
        let v = if bits == 53 {
            check_weights_determine_metric(&tet, &tl, &s)
        } else {
            let lm: Vec<Mpfr> = tl.iter().map(|&x| Mpfr::from_f64(x, prec(256))).collect();
            check_weights_determine_metric(&tet, &lm, &s)
        };
        assert!(!v.fails() && !certified_holds(&v), "{bits}: {v:?}");
    }

    // (3) The certified grounded Hessian of a tetrahedron, one diagonal entry widened
    // downward by twice the eigenvalue bound: no longer certified.
    let h = grounded_area_hessian(&t, &l, 0, enclosure_bits(53)).unwrap();
    let (lambda, _) = certify_positive_definite(&h).unwrap();
    let mut wide = h.clone();
    let k = wide.entries.iter().position(|e| e.0 == e.1).unwrap();
    wide.entries[k].2 -= 2.0 * lambda;
    assert!(certify_positive_definite(&wide).is_err());
    // … and the midpoint shifted down by λ_max bound (singular or indefinite).
    let mut shifted = h;
    let top = shifted
        .entries
        .iter()
        .map(|e| e.3.abs())
        .fold(0.0f64, f64::max);
    for e in shifted.entries.iter_mut().filter(|e| e.0 == e.1) {
        e.2 -= 4.0 * top;
        e.3 -= 4.0 * top;
    }
    assert!(certify_positive_definite(&shifted).is_err());
}

/// Beyond the dense recovery's former cap of 150 edges: a jittered 32×32 torus (3072 edges)
/// and a jittered icosphere (1920 edges) certify at f64, Dd and MPFR-256 in the registry,
/// and T06-NC (a raised weight, B31) fails, certified, on the same surfaces.
#[test]
fn t06_certified_beyond_the_dense_recovery_cap() {
    let s = Settings::default();
    let check = penner::oracle::catalogue()
        .into_iter()
        .find(|c| c.id == "T06")
        .unwrap();
    let control = penner::oracle::controls::by_id("T06-NC").unwrap();
    let (tm, tl) = jittered_torus(32, 32, 7);
    let mut e = icosphere(8);
    let mut rng = ChaCha8Rng::seed_from_u64(3);
    for p in &mut e.pos {
        let s = 1.0 + 0.05 * (rng.r#gen::<f64>() - 0.5);
        *p = p.map(|x| x * s);
    }
    let im = e.mesh();
    let il = e.lengths(&im);
    for (name, m, l) in [("torus", tm, tl), ("icosphere", im, il)] {
        assert!(m.n_edges() > 150);
        let q: Vec<Rational> = l.iter().map(|x| Rational::from_f64(*x).unwrap()).collect();
        let case = crate::adversarial_gen::from_lengths(name, m, q).unwrap();
        for p in [Prec::F64, Prec::Dd, Prec::Mpfr(prec(256))] {
            let v = (check.run)(&case, p, &s).unwrap();
            assert!(certified_holds(&v), "{name} at {p:?}: {v:?}");
        }
        let nc = (control.run)(&case, Prec::F64, &s).unwrap();
        assert!(
            matches!(
                &nc,
                Verdict::Fails {
                    certified: true,
                    ..
                }
            ),
            "{name}: {nc:?}"
        );
    }
}
