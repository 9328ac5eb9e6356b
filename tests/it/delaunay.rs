//! The certified Delaunay predicate against independent oracles (malachite rationals with
//! the D-form of GSC21, integer incircle determinants), and the adversarial suite.

use crate::support::cases;
use malachite::base::num::arithmetic::traits::Sign as _;
use malachite::rational::Rational as MRational;
use penner::algorithms::naive::naive_p;
use penner::mesh::{Edge, Mesh};
use penner::predicates::delaunay::{
    delaunay_sign_squared, edge_delaunay_sign_scaled, enclose_p, filter_f64, EdgeDelaunay, Quad,
    QuadEdges, RationalQuad, RealQuad,
};
use penner::predicates::directed::enclose_f64;
use penner::predicates::ladder::{decide, Ladder, SignPredicate};
use penner::scalar::{Certified, Dd, Mpfr, Precision, Real, Sign, Stage};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rug::Rational;
use std::cmp::Ordering;
use std::str::FromStr;

/// Convert through the decimal string: a different code path from rug's arithmetic.
pub fn to_m(q: &Rational) -> MRational {
    MRational::from_str(&q.to_string()).unwrap()
}

/// The oracle: sign of GSC21's `D = ℓ_kl(ℓ_il ℓ_ki + ℓ_jk ℓ_lj) − ℓ_ij(ℓ_jk ℓ_ki + ℓ_il ℓ_lj)`
/// with the Ptolemy diagonal `ℓ_kl = (ℓ_ki ℓ_lj + ℓ_il ℓ_jk)/ℓ_ij`, in malachite.
pub fn oracle(q: [&MRational; 5]) -> Sign {
    let [ij, jk, ki, il, lj] = q;
    let kl = (ki * lj + il * jk) / ij;
    let d = &kl * (il * ki + jk * lj) - ij * (jk * ki + il * lj);
    match d.sign() {
        Ordering::Less => Sign::Negative,
        Ordering::Equal => Sign::Zero,
        Ordering::Greater => Sign::Positive,
    }
}

pub fn oracle_f64(q: [f64; 5]) -> Sign {
    oracle_of(&q.map(|x| MRational::try_from(x).unwrap()))
}

fn quad(q: [f64; 5]) -> Quad<f64> {
    Quad {
        ij: q[0],
        jk: q[1],
        ki: q[2],
        il: q[3],
        lj: q[4],
    }
}

/// The five lengths `[ij, jk, ki, il, lj]` of `s` (at least five) as a quadrilateral.
fn quad_of<T>(s: &[T]) -> Quad<&T> {
    Quad {
        ij: &s[0],
        jk: &s[1],
        ki: &s[2],
        il: &s[3],
        lj: &s[4],
    }
}

/// The exact values of point-valued lengths, in malachite.
pub fn exact_values<T: Real>(xs: &[T]) -> Vec<MRational> {
    xs.iter().map(|x| to_m(&x.to_rational().unwrap())).collect()
}

/// The triangle oracle: the three slacks `b + c − a` positive, in malachite (exact).
pub fn exactly_strict(s: [&MRational; 3]) -> bool {
    let [a, b, c] = s;
    let zero = MRational::from(0);
    (b + c - a) > zero && (c + a - b) > zero && (a + b - c) > zero
}

/// Whether face `f` of `mesh` is exactly a strict triangle for the lengths `l`.
pub fn exactly_strict_face(mesh: &Mesh, l: &[MRational], f: penner::mesh::Face) -> bool {
    exactly_strict(mesh.face_halfedges(f).map(|h| &l[h.edge().idx()]))
}

/// Whether every face of `mesh` is exactly a strict triangle for the lengths `l`.
pub fn exactly_strict_faces(mesh: &Mesh, l: &[MRational]) -> bool {
    mesh.faces().all(|f| exactly_strict_face(mesh, l, f))
}

/// Interior edges the malachite oracle finds not Delaunay (D < 0): an independent
/// re-check of a flip result.
pub fn oracle_non_delaunay(mesh: &Mesh, lengths: &[MRational]) -> Vec<Edge> {
    mesh.edges()
        .filter(|&e| {
            QuadEdges::of(mesh, e)
                .is_some_and(|q| oracle(q.lengths(lengths).to_array()) == Sign::Negative)
        })
        .collect()
}

/// [`oracle`] on five malachite lengths `[ij, jk, ki, il, lj]`.
fn oracle_of(m: &[MRational]) -> Sign {
    oracle([&m[0], &m[1], &m[2], &m[3], &m[4]])
}

/// The sign the default ladder certifies for `p` (`None` if undecided).
fn ladder_sign<P: SignPredicate>(p: &P) -> Option<Sign> {
    decide(p, &Ladder::default()).value()
}

/// The default ladder on f64 lengths `[ij, jk, ki, il, lj]`.
fn ladder_f64(q: [f64; 5]) -> Certified<Sign> {
    let qq = quad(q);
    decide(&RealQuad(qq.as_refs()), &Ladder::default())
}

fn dist(p: [f64; 2], q: [f64; 2]) -> f64 {
    (p[0] - q[0]).hypot(p[1] - q[1])
}

/// Lengths `[ij, jk, ki, il, lj]` of four points `i, j, k, l`.
fn lengths_of(p: [[f64; 2]; 4]) -> [f64; 5] {
    let [i, j, k, l] = p;
    [dist(i, j), dist(j, k), dist(k, i), dist(i, l), dist(l, j)]
}

/// A random quadrilateral of one of several adversarial families.
fn adversarial_quad(rng: &mut ChaCha8Rng, family: u32) -> [f64; 5] {
    match family % 6 {
        // Random valid triangles.
        0 => {
            let p: [[f64; 2]; 4] = std::array::from_fn(|_| [rng.r#gen(), rng.r#gen()]);
            lengths_of(p)
        }
        // Four points on a circle (f64 coordinates): nearly cocircular.
        1 => {
            let t: [f64; 4] = std::array::from_fn(|_| rng.gen_range(0.0..std::f64::consts::TAU));
            lengths_of(t.map(|a| [a.cos(), a.sin()]))
        }
        // Arbitrary positive lengths (triangle inequality may fail).
        2 => std::array::from_fn(|_| rng.gen_range(0.01..3.0)),
        // Needles and caps.
        3 => {
            let eps = 10f64.powi(-rng.gen_range(3..14));
            [
                1.0,
                1.0 + eps * rng.r#gen::<f64>(),
                eps,
                1.0,
                eps * rng.r#gen::<f64>() + 1e-300,
            ]
        }
        // Cocircular rectangle 3-4-5 with a relative perturbation 1e-15 … 1e-17.
        4 => {
            let eps = rng.gen_range(-1.0..1.0) * 10f64.powi(-rng.gen_range(15..18));
            [5.0 * (1.0 + eps), 4.0, 3.0, 4.0, 3.0]
        }
        // Random scale 1e-150 … 1e150 of a near-cocircular quad.
        _ => {
            let t: [f64; 4] = std::array::from_fn(|_| rng.gen_range(0.0..std::f64::consts::TAU));
            let s = 10f64.powi(rng.gen_range(-150..=150));
            lengths_of(t.map(|a| [a.cos(), a.sin()])).map(|x| x * s)
        }
    }
}

#[test]
fn b61_filter_never_contradicts_exact_oracle() {
    let mut rng = ChaCha8Rng::seed_from_u64(61);
    let n = cases(6_000, 200_000);
    let mut decided = 0;
    for i in 0..n {
        let q = adversarial_quad(&mut rng, i as u32);
        let exact = oracle_f64(q);
        if let Some(s) = filter_f64(q) {
            decided += 1;
            assert_eq!(s, exact, "filter contradicts exact arithmetic on {q:?}");
        }
        assert_eq!(ladder_f64(q).value(), Some(exact), "ladder on {q:?}");
    }
    // The filter decides most inputs (else it would be useless), not all (near ties).
    assert!(
        decided > n / 2 && decided < n,
        "filter decided {decided} of {n}"
    );
}

#[test]
fn b61_negative_control_naive_f64_sign_contradicts_exact() {
    // The same inputs decided by the raw f64 value of P (no error bound): wrong signs.
    let mut rng = ChaCha8Rng::seed_from_u64(62);
    let mut wrong = Vec::new();
    for _ in 0..4_000 {
        let q = adversarial_quad(&mut rng, 1);
        let exact = oracle_f64(q);
        let p = naive_p(q);
        let naive = if p > 0.0 {
            Sign::Positive
        } else if p < 0.0 {
            Sign::Negative
        } else {
            Sign::Zero
        };
        if naive != exact {
            wrong.push((q, naive, exact));
        }
    }
    assert!(
        !wrong.is_empty(),
        "expected naive f64 decisions to err on near-cocircular quads"
    );
    // ... while the certified predicate agrees on every one of them.
    for (q, _, exact) in &wrong {
        assert_eq!(ladder_f64(*q).value(), Some(*exact));
    }
}

#[test]
fn b62_enclosure_contains_exact_value() {
    let mut rng = ChaCha8Rng::seed_from_u64(63);
    let mut strict = 0;
    for i in 0..cases(1_500, 50_000) {
        let q = adversarial_quad(&mut rng, i as u32);
        if !crate::support::in_shard(i) {
            continue; // generated, then left to another shard
        }
        let m = q.map(|x| MRational::try_from(x).unwrap());
        // Oracle value ℓ_ij·D in malachite.
        let [ij, jk, ki, il, lj] = [&m[0], &m[1], &m[2], &m[3], &m[4]];
        let kl = (ki * lj + il * jk) / ij;
        let p_exact = ij * (&kl * (il * ki + jk * lj) - ij * (jk * ki + il * lj));
        for bits in [53u64, 64, 100] {
            let p = Precision::new(bits).unwrap();
            let e = enclose_p(&q.map(|x| enclose_f64(x, p)));
            let lo = to_m(&e.lo().to_rational().unwrap());
            let hi = to_m(&e.hi().to_rational().unwrap());
            assert!(lo <= p_exact && p_exact <= hi, "{q:?} at {bits} bits");
            // Negative control: the round-to-nearest midpoint is generally not the value.
            if lo < hi {
                strict += 1;
            }
        }
    }
    assert!(
        strict > 0,
        "every enclosure was a point: rounding never exercised"
    );
}

/// Integer incircle determinant (independent oracle): > 0 iff `d` lies inside the
/// circle through `a, b, c` (counter-clockwise).
fn incircle(a: [i64; 2], b: [i64; 2], c: [i64; 2], d: [i64; 2]) -> i128 {
    let r = |p: [i64; 2]| {
        let (x, y) = (i128::from(p[0] - d[0]), i128::from(p[1] - d[1]));
        (x, y, x * x + y * y)
    };
    let (ax, ay, a2) = r(a);
    let (bx, by, b2) = r(b);
    let (cx, cy, c2) = r(c);
    ax * (by * c2 - b2 * cy) - ay * (bx * c2 - b2 * cx) + a2 * (bx * cy - by * cx)
}

fn orient(a: [i64; 2], b: [i64; 2], c: [i64; 2]) -> i64 {
    (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
}

/// Four random lattice points `i, j, k, l` in `[−range, range]²`, kept (`Some`) when they
/// form a quadrilateral with `ijk` counter-clockwise and `l` on the other side of `ij`.
fn lattice_quad(rng: &mut ChaCha8Rng, range: i64) -> Option<[[i64; 2]; 4]> {
    let p: [[i64; 2]; 4] =
        std::array::from_fn(|_| [rng.gen_range(-range..=range), rng.gen_range(-range..=range)]);
    let [i, j, k, l] = p;
    (orient(i, j, k) > 0 && orient(i, j, l) < 0).then_some(p)
}

/// Squared distance of two lattice points.
fn sq(a: [i64; 2], b: [i64; 2]) -> Rational {
    Rational::from((a[0] - b[0]).pow(2) + (a[1] - b[1]).pow(2))
}

#[test]
fn b63_squared_length_sign_matches_integer_incircle() {
    let mut rng = ChaCha8Rng::seed_from_u64(64);
    let (mut zeros, mut n) = (0, 0);
    let target = cases(3_000, 100_000);
    while n < target {
        let range = if n % 3 == 0 { 3 } else { 1000 };
        let Some(p) = lattice_quad(&mut rng, range) else {
            continue;
        };
        let [i, j, k, l] = p;
        n += 1;
        let s = [sq(i, j), sq(j, k), sq(k, i), sq(i, l), sq(l, j)];
        let got = delaunay_sign_squared(quad_of(&s));
        let expected = Sign::of_ordering(0.cmp(&incircle(i, j, k, l)));
        assert_eq!(got, expected, "{p:?}");
        zeros += usize::from(got == Sign::Zero);
    }
    assert!(zeros > 0, "no cocircular lattice quadrilateral was tested");
}

#[test]
fn b63_negative_control_squared_sign_of_wrong_quad_differs() {
    // Swapping the roles of the two triangles' sides (jk ↔ lj) changes the quadrilateral;
    // the same incircle oracle then disagrees on some inputs.
    let mut rng = ChaCha8Rng::seed_from_u64(65);
    let mut disagreements = 0;
    for _ in 0..500 {
        let Some([i, j, k, l]) = lattice_quad(&mut rng, 50) else {
            continue;
        };
        let s = [sq(i, j), sq(l, j), sq(k, i), sq(i, l), sq(j, k)];
        let got = delaunay_sign_squared(quad_of(&s));
        disagreements += usize::from(got != Sign::of_ordering(0.cmp(&incircle(i, j, k, l))));
    }
    assert!(disagreements > 0);
}

#[test]
fn perturbations_1e15_to_1e40_decided_correctly_at_mpfr_and_exact() {
    // The 3-4-5 rectangle is cocircular (P = 0); perturb the diagonal by ±10⁻ᵏ relative.
    let p = Precision::new(256).unwrap();
    for k in 15..=40 {
        for sign in [-1i32, 1] {
            let eps = Rational::from((sign, 1))
                / Rational::from(rug::Integer::from(rug::Integer::u_pow_u(10, k as u32)));
            let diag = Rational::from(5) * (Rational::from(1) + &eps);
            // Exact rung on rationals.
            let l = [diag.clone(), 4.into(), 3.into(), 4.into(), 3.into()];
            let r = RationalQuad(quad_of(&l));
            let expected = oracle_of(&l.each_ref().map(to_m));
            assert_eq!(
                expected,
                if sign > 0 {
                    Sign::Negative
                } else {
                    Sign::Positive
                }
            );
            assert_eq!(ladder_sign(&r), Some(expected), "k={k}");
            // MPFR lengths at 256 bits (the rounded diagonal still carries the perturbation).
            let m: Vec<Mpfr> = l.iter().map(|x| Mpfr::from_rational(x, p)).collect();
            let rq = RealQuad(quad_of(&m));
            let exact_of_rounded = oracle_of(&exact_values(&m));
            assert_eq!(exact_of_rounded, expected);
            assert_eq!(ladder_sign(&rq), Some(expected), "k={k}");
        }
    }
    // Unperturbed: exactly zero, decided (a point enclosure or the exact rung).
    let l: [Rational; 5] = [5.into(), 4.into(), 3.into(), 4.into(), 3.into()];
    assert_eq!(ladder_sign(&RationalQuad(quad_of(&l))), Some(Sign::Zero));
}

#[test]
fn dd_lengths_decided_like_exact_oracle() {
    let mut rng = ChaCha8Rng::seed_from_u64(66);
    for i in 0..cases(300, 20_000) {
        let q = adversarial_quad(&mut rng, i as u32);
        let tiny = adversarial_quad(&mut rng, 2).map(|x| x * 1e-20);
        if !crate::support::in_shard(i) {
            continue; // generated, then left to another shard
        }
        let d: Vec<Dd> = (0..5)
            .map(|k| <Dd as Real>::from_f64(q[k], ()) + <Dd as Real>::from_f64(tiny[k] * q[k], ()))
            .collect();
        let expected = oracle_of(&exact_values(&d));
        assert_eq!(ladder_sign(&RealQuad(quad_of(&d))), Some(expected));
    }
}

/// The square 0-1-2-3 cut along the diagonal 0-2, and that (only interior) edge.
fn two_triangles() -> (Mesh, Edge) {
    let m = Mesh::from_faces(4, &[[0, 1, 2], [0, 2, 3]]).unwrap();
    let diag = m.edges().find(|&e| !m.is_boundary_edge(e)).unwrap();
    (m, diag)
}

#[test]
fn scale_factors_up_to_800_do_not_overflow() {
    // Square 0-1-2-3 with diagonal 0-2: unit sides, diagonal √2 as f64.
    let (m, diag) = two_triangles();
    let l: Vec<f64> = m
        .edges()
        .map(|e| if e == diag { 2f64.sqrt() } else { 1.0 })
        .collect();
    // Naive f64 lengths overflow: e^{(800+800)/2} = inf.
    assert!(800.0f64.exp().is_infinite());
    let mut rng = ChaCha8Rng::seed_from_u64(67);
    let prec = Precision::new(3000).unwrap();
    let mut decided = 0;
    for _ in 0..cases(40, 2_000) {
        let u: Vec<f64> = (0..4).map(|_| rng.gen_range(-800.0..800.0)).collect();
        let s = edge_delaunay_sign_scaled(&m, &l, &u, diag, &Ladder::default()).unwrap();
        // Oracle: the D-form in 3000-bit MPFR arithmetic (a different formula and code).
        let len = |e: Edge| {
            let h = e.halfedge();
            let (a, b) = (m.tail(h).idx(), m.tip(h).idx());
            let half = Mpfr::from_f64(u[a], prec) + &Mpfr::from_f64(u[b], prec);
            (half / &Mpfr::from_f64(2.0, prec)).exp() * &Mpfr::from_f64(l[e.idx()], prec)
        };
        let q = QuadEdges::of(&m, diag).unwrap();
        let [ij, jk, ki, il, lj] = q.edges.to_array().map(len);
        let kl = (ki.clone() * &lj + &(il.clone() * &jk)) / &ij;
        let d = kl * &(il.clone() * &ki + &(jk.clone() * &lj)) - &(ij * &(jk * &ki + &(il * &lj)));
        let v = d.as_float().clone();
        if let EdgeDelaunay::Interior(Certified::Known { value, .. }) = s {
            decided += 1;
            let expected = if v > 0 {
                Sign::Positive
            } else {
                Sign::Negative
            };
            assert!(!v.is_zero() && !v.is_nan());
            assert_eq!(value, expected, "u = {u:?}");
        }
    }
    assert!(decided > 0);
    // Uniform u: scaling does not change the sign; the exact rung decides on base lengths.
    let u = vec![800.0; 4];
    let s = edge_delaunay_sign_scaled(&m, &l, &u, diag, &Ladder::default()).unwrap();
    let q = QuadEdges::of(&m, diag).unwrap();
    let base = q.edges.to_array().map(|e| l[e.idx()]);
    assert_eq!(s.is_delaunay(), Some(oracle_f64(base) != Sign::Negative));
}

#[test]
fn lengths_from_1e_minus_150_to_1e150_keep_their_sign() {
    let mut rng = ChaCha8Rng::seed_from_u64(68);
    for i in 0..cases(400, 20_000) {
        let q = adversarial_quad(&mut rng, i as u32 % 2);
        if !crate::support::in_shard(i) {
            continue; // generated, then left to another shard
        }
        for k in (-150..=150).step_by(25) {
            let s = 2f64.powi(k * 10 / 3); // exact power of two: the sign is unchanged
            let c = ladder_f64(q.map(|x| x * s));
            assert_eq!(c.value(), Some(oracle_f64(q)), "scale 2^{}", k * 10 / 3);
        }
        // Decimal scales round the lengths; compare with the oracle of the rounded values.
        let qs = q.map(|x| x * 1e150);
        assert_eq!(ladder_f64(qs).value(), Some(oracle_f64(qs)));
    }
}

#[test]
fn filter_rescales_extreme_quads() {
    // All lengths near 1e300: without rescaling the products would overflow.
    let q = [1.5e300, 1e300, 1e300, 1e300, 1e300];
    assert_eq!(filter_f64(q), Some(oracle_f64(q)));
    let q = [1.5e-300, 1e-300, 1e-300, 1e-300, 1e-300];
    assert_eq!(filter_f64(q), Some(oracle_f64(q)));
    // Spanning more than 2^200 inside one quad: the filter declines, the ladder decides.
    let q = [1.0, 1.0, 1e-70, 1.0, 1.0];
    assert_eq!(filter_f64(q), None);
    assert_eq!(
        ladder_f64(q),
        Certified::Known {
            value: oracle_f64(q),
            stage: Stage::Interval { bits: 128 }
        }
    );
}

#[test]
fn bad_lengths_are_typed_errors() {
    let (m, diag) = two_triangles();
    for bad in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        let l: Vec<f64> = m
            .edges()
            .map(|e| if e == diag { bad } else { 1.0 })
            .collect();
        let r = penner::predicates::delaunay::edge_delaunay_sign(&m, &l, diag, &Ladder::default());
        assert!(
            matches!(r, Err(penner::predicates::delaunay::DelaunayError::BadLength { edge, .. }) if edge == diag),
            "{bad}: {r:?}"
        );
    }
    let r = penner::predicates::delaunay::edge_delaunay_sign(&m, &[1.0], diag, &Ladder::default());
    assert!(r.is_err());
}

/// B61's range guard. Three lengths near `2⁻⁵³⁰` (their squares and products are
/// subnormal, with a few bits of precision) and two near 1: the filter cannot rescale the
/// quadrilateral into `[2⁻²⁰⁰, 2²⁰⁰)`, so it declines, and the ladder decides the exact
/// sign. Found by a search over near-ties; each is also taken with the pairs `(b, c)` and
/// `(d, e)` swapped (`P` is symmetric under the swap), so the small lengths sit at
/// different positions. Control: B61's evaluation written out here without the range
/// guard reads the wrong sign on every witness.
#[test]
fn term_b61_range_guard_keeps_subnormal_products_out_of_the_filter() {
    const W: [[u64; 5]; 5] = [
        [
            0x1ede26803d38381e,
            0x1ecafbd67e6ee61e,
            0x1ecf8130c4d81faa,
            0x3ff0000000000000,
            0x3ffa542dcd504c34,
        ],
        [
            0x1f04e2d3da41913b,
            0x1ef6d14475e6419a,
            0x1ef0e5e18af652fa,
            0x3ff0000000000000,
            0x3ffe95964683a015,
        ],
        [
            0x1f2babf054c7053a,
            0x1f1fbbe93981aeca,
            0x1f172a9b8a2e5480,
            0x3ff7a5f3e5b91b08,
            0x3ffe93df76aea9d1,
        ],
        [
            0x1e76c1556406e80a,
            0x1e698910042f2062,
            0x1e63ebebe270b836,
            0x3ff0000000000000,
            0x3ff1a47f51378c2c,
        ],
        [
            0x1e7a071400522462,
            0x1e6ac15307d07675,
            0x1e68d8e3b1ae72a8,
            0x3ff0000000000000,
            0x3fe88d2abfcb26a2,
        ],
    ];
    // B61's K̂ and N̂ and its two tests, without the range guard.
    let unguarded = |[a, b, c, d, e]: [f64; 5]| {
        let rho = 1.0 - 2f64.powi(-49);
        let (de, bc) = (d * e, b * c);
        let k = de * (b * b + c * c) + bc * (d * d + e * e);
        let n = (a * a) * (de + bc);
        if n < k * rho {
            Some(Sign::Positive)
        } else if k < n * rho {
            Some(Sign::Negative)
        } else {
            None
        }
    };
    check_guard_witnesses(&W, unguarded, |q| {
        assert_eq!(filter_f64(q), None, "{q:?}");
        ladder_f64(q).value()
    });
}

/// For each witness `w` (binary64 bit patterns) and its copy with the pairs `(b, c)` and
/// `(d, e)` swapped (`P` is symmetric under the swap): `P ≠ 0`, the predicate under test
/// (`decided`, which asserts its own filter declines) gives the oracle's sign, and the
/// `unguarded` evaluation reads the wrong sign (the control).
fn check_guard_witnesses(
    witnesses: &[[u64; 5]],
    unguarded: impl Fn([f64; 5]) -> Option<Sign>,
    decided: impl Fn([f64; 5]) -> Option<Sign>,
) {
    for w in witnesses {
        let q = w.map(f64::from_bits);
        for q in [q, [q[0], q[3], q[4], q[1], q[2]]] {
            let exact = oracle_f64(q);
            assert_ne!(exact, Sign::Zero, "{q:?}");
            assert_eq!(decided(q), Some(exact), "{q:?}");
            let naive = unguarded(q);
            assert!(
                naive.is_some() && naive != Some(exact),
                "control: {q:?} {naive:?}"
            );
        }
    }
}

/// The f64 filter is the first rung for binary64 lengths, and only for them (B61's
/// hypothesis: the inputs are binary64 numbers exactly). A well-shaped quadrilateral
/// (`P` far from 0) in `f64` is decided by the filter; the same lengths as double-doubles
/// with a nonzero low part, and as 256-bit MPFR values, are decided by an enclosure or
/// the exact rung, with the sign of the malachite oracle.
#[test]
fn term_b61_the_filter_runs_on_binary64_lengths_only() {
    let q = [1.2, 1.0, 1.1, 0.9, 1.05];
    let c = ladder_f64(q);
    assert_eq!(
        c,
        Certified::Known {
            value: oracle_f64(q),
            stage: Stage::Filter
        }
    );
    let ladder = Ladder::default();
    // Double-doubles hi + 2⁻⁶⁰·hi: not binary64 numbers.
    let dd: Vec<Dd> = q
        .iter()
        .map(|&x| <Dd as Real>::from_f64(x, ()) + <Dd as Real>::from_f64(x * 2f64.powi(-60), ()))
        .collect();
    let mq = exact_values(&dd);
    // The oracle's sign, from a rung past the filter.
    let past_filter = |r: Certified<Sign>| {
        assert_eq!(r.value(), Some(oracle_of(&mq)));
        assert!(
            !matches!(
                r,
                Certified::Known {
                    stage: Stage::Filter,
                    ..
                }
            ),
            "{r:?}"
        );
    };
    past_filter(decide(&RealQuad(quad_of(&dd)), &ladder));
    let prec = Precision::new(256).unwrap();
    let mp: Vec<Mpfr> = dd
        .iter()
        .map(|x| Mpfr::from_rational(&x.to_rational().unwrap(), prec))
        .collect();
    assert_eq!(exact_values(&mp), mq);
    past_filter(decide(&RealQuad(quad_of(&mp)), &ladder));
}

/// `in_filter_range` is B61's range `[2⁻²⁰⁰, 2²⁰⁰)` exactly: both ends and their
/// neighbours, and the values no range holds (zero, negative, subnormal, infinite, NaN).
#[test]
fn b61_filter_range_is_two_to_the_minus_200_up_to_two_to_the_200() {
    use penner::predicates::delaunay::in_filter_range;
    let (lo, hi) = (2f64.powi(-200), 2f64.powi(200));
    for x in [lo, lo.next_up(), 1.0, hi.next_down()] {
        assert!(in_filter_range(x), "{x:e}");
    }
    let outside = [
        lo.next_down(),
        hi,
        hi.next_up(),
        0.0,
        -0.0,
        -1.0,
        f64::MIN_POSITIVE / 2.0,
        f64::INFINITY,
        f64::NAN,
    ];
    for x in outside {
        assert!(!in_filter_range(x), "{x:e}");
    }
}

/// B61's bound for rounded rational inputs, `|P̂| > 2⁻⁴⁷·M̂ + 2⁻¹⁰⁰⁰`. Exactly cocircular
/// rational quadrilaterals (rectangles with Pythagorean sides, `b² + c² = d² + e² = a²`,
/// so `P = 0`) scaled by factors that are not dyadic, from `2⁻¹⁸⁰` to `2¹⁸⁰`: their
/// truncated binary64 images are not ties, so the filter's own `P̂` is not 0, and only the
/// bound keeps the filter from answering. The ladder decides `Zero` exactly. Control: the
/// filter's `P̂` is nonzero on most of them (a sign read from `P̂` alone would be wrong).
#[test]
fn term_b61_rational_filter_declines_ties_its_rounded_inputs_break() {
    let triples: [[i64; 5]; 4] = [
        [5, 4, 3, 3, 4],
        [25, 7, 24, 15, 20],
        [65, 16, 63, 33, 56],
        [65, 25, 60, 39, 52],
    ];
    let mut scales: Vec<Rational> = Vec::new();
    for k in [-180i32, -100, -40, 0, 40, 100, 180] {
        for den in [3u32, 7, 10, 11] {
            let two_k = if k >= 0 {
                Rational::from(rug::Integer::from(1) << k as u32)
            } else {
                Rational::from((rug::Integer::from(1), rug::Integer::from(1) << (-k) as u32))
            };
            scales.push(two_k / den);
        }
    }
    let (mut cases, mut nonzero) = (0, 0);
    for t in triples {
        for s in &scales {
            let l: Vec<Rational> = t.iter().map(|&x| Rational::from(x) * s).collect();
            assert_eq!(oracle_of(&exact_values_q(&l)), Sign::Zero);
            let q = RationalQuad(quad_of(&l));
            assert_eq!(q.filter(), None, "{t:?} × {s}");
            assert_eq!(ladder_sign(&q), Some(Sign::Zero), "{t:?} × {s}");
            // The filter's own P̂ on the truncated inputs.
            let [a, b, c, d, e] = [0, 1, 2, 3, 4].map(|i| l[i].to_f64());
            let (de, bc) = (d * e, b * c);
            let p = de * (b * b + c * c - a * a) + bc * (d * d + e * e - a * a);
            cases += 1;
            nonzero += usize::from(p != 0.0);
        }
    }
    assert!(
        2 * nonzero > cases,
        "control: P̂ ≠ 0 on {nonzero} of {cases}"
    );
}

/// The rational filter answers where the bound allows: a well-shaped rational
/// quadrilateral (`P` far from 0) is decided by the filter rung, with the oracle's sign.
#[test]
fn term_b61_rational_filter_decides_well_shaped_quads() {
    for l in [
        ["6/5", "1", "11/10", "9/10", "21/20"],
        ["2", "1/3", "5/3", "3/7", "12/7"],
        ["1/10", "1/3", "1/3", "1/3", "1/3"],
    ] {
        let l: Vec<Rational> = l.iter().map(|x| Rational::from_str(x).unwrap()).collect();
        let q = RationalQuad(quad_of(&l));
        let expected = oracle_of(&exact_values_q(&l));
        assert_ne!(expected, Sign::Zero);
        assert_eq!(q.filter(), Some(expected), "{l:?}");
        assert_eq!(
            decide(&q, &Ladder::default()),
            Certified::Known {
                value: expected,
                stage: Stage::Filter
            }
        );
    }
}

/// Exact rationals in malachite, through their decimal strings.
fn exact_values_q(l: &[Rational]) -> Vec<MRational> {
    l.iter().map(to_m).collect()
}

/// B61's range test of the rational filter. Three lengths near `2⁻⁵³⁰` and two of `2¹⁵⁰`
/// or `2¹⁸⁰` (inside the range): the squares of the small ones are subnormal, and their
/// rounding, multiplied by `bc ≈ 2³⁰⁰`, exceeds the bound `2⁻⁴⁷M̂ + 2⁻¹⁰⁰⁰` that assumes no
/// underflow. Found by a search over near-ties `a ≈ d + e` (then `P ≈ b²((d+e)² − a²)`).
/// The filter declines them (the smallest length is below `2⁻²⁰⁰`), the ladder decides
/// the exact sign. Control: the same evaluation and bound without the range test read the
/// wrong sign on each.
#[test]
fn term_b61_rational_filter_range_test_keeps_subnormal_squares_out() {
    const W: [[u64; 5]; 4] = [
        [
            0x1ef1f36704062ca3,
            0x4950000000000000,
            0x4950000000000000,
            0x1eee6a16a2504ed1,
            0x1ec5f2dd96f029d1,
        ],
        [
            0x1ee484d2d9de8514,
            0x4950000000000000,
            0x4950000000000000,
            0x1ec359eeef8c1479,
            0x1edf5cae3bf6ffe6,
        ],
        [
            0x1ec4d23fc6341810,
            0x4950000000000000,
            0x4950000000000000,
            0x1ec4a0fe74a096e9,
            0x1e58a0a8c9c092a9,
        ],
        [
            0x1e771999c9d21ede,
            0x4b30000000000000,
            0x4b30000000000000,
            0x1e64d25deba2824b,
            0x1e6960d5a801bb6e,
        ],
    ];
    // RationalQuad::filter's evaluation and bound (B61), without the range test.
    let unguarded = |[a, b, c, d, e]: [f64; 5]| {
        let (a2, de, bc) = (a * a, d * e, b * c);
        let p = de * (b * b + c * c - a2) + bc * (d * d + e * e - a2);
        let m = de * (b * b + c * c + a2) + bc * (d * d + e * e + a2);
        let t = 2f64.powi(-47) * m + 2f64.powi(-1000);
        if p > t {
            Some(Sign::Positive)
        } else if p < -t {
            Some(Sign::Negative)
        } else {
            None
        }
    };
    check_guard_witnesses(&W, unguarded, |q| {
        let l: Vec<Rational> = q.iter().map(|&x| Rational::from_f64(x).unwrap()).collect();
        let rq = RationalQuad(quad_of(&l));
        assert_eq!(rq.filter(), None, "{q:?}");
        ladder_sign(&rq)
    });
}

/// The exact rung of the Delaunay predicate on `Real` lengths: double-double lengths of
/// the cyclic trapezoid with diagonal 7, bases 4 and 6 and legs 5 (`P = 30·(−8) + 20·12 =
/// 0`, a tie with `X, Y ≠ 0`) scaled by `s = 1 + 3·2⁻³⁰ + 2⁻⁹⁷` (each length `k·s` a
/// double-double exactly; `P`'s monomials need about 400 bits) are decided `Zero` by the
/// exact rung of a ladder that stops at 256 bits. Control: the same ladder without the
/// exact rung leaves them undecided.
#[test]
fn term_b63_exact_rung_decides_real_ties_past_the_intervals() {
    let l: Vec<Dd> = [7.0, 4.0, 5.0, 6.0, 5.0]
        .iter()
        .map(|&k: &f64| {
            let hi = k * (1.0 + 3.0 * 2f64.powi(-30));
            <Dd as Real>::from_f64(hi, ()) + <Dd as Real>::from_f64(k * 2f64.powi(-97), ())
        })
        .collect();
    assert_eq!(oracle_of(&exact_values(&l)), Sign::Zero);
    let short = Ladder {
        start_bits: 128,
        max_bits: 256,
        exact: true,
    };
    assert_eq!(
        decide(&RealQuad(quad_of(&l)), &short),
        Certified::Known {
            value: Sign::Zero,
            stage: Stage::Exact
        }
    );
    let no_exact = Ladder {
        exact: false,
        ..short
    };
    assert_eq!(decide(&RealQuad(quad_of(&l)), &no_exact).value(), None);
}

/// B61's bound for rational inputs, term by term: the filter's `t` against `2⁻⁴⁷·M` with
/// `M = de(b² + c² + a²) + bc(d² + e² + a²)` evaluated exactly (num-rational) on the same
/// truncated binary64 images. `M̂` sees at most six roundings per monomial and the product
/// with `2⁻⁴⁷` is exact, so `t` lies within `8u·2⁻⁴⁷M + 2⁻⁹⁹⁹` of `2⁻⁴⁷M`. Random
/// non-dyadic lengths (each within a factor 2⁸ of the others, at scales 2⁻¹⁵⁰ … 2¹⁵⁰, so
/// every monomial of `M` is comparable and far from 1): a bound missing or misreading any
/// term of `M` leaves that window.
#[test]
fn term_b61_rational_filter_bound_is_two_to_the_minus_47_times_the_majorant() {
    use num_rational::BigRational as NQ;
    let mut rng = ChaCha8Rng::seed_from_u64(6147);
    let exact = |x: f64| NQ::from_float(x).unwrap();
    let pow2 = |k: i32| {
        if k >= 0 {
            NQ::from_integer(num_bigint::BigInt::from(1) << k)
        } else {
            NQ::new(1.into(), num_bigint::BigInt::from(1) << -k)
        }
    };
    let slack = pow2(-53) * NQ::from_integer(8.into());
    for i in 0..400 {
        let scale = rng.gen_range(-150..150);
        let l: Vec<Rational> = (0..5)
            .map(|_| {
                let num: u64 = rng.gen_range(1 << 20..1 << 40);
                let den: u64 = 2 * rng.gen_range(1u64 << 20..1 << 30) + 1;
                let e = scale + rng.gen_range(0..8);
                let q = Rational::from((num, den)) * Rational::from(rug::Integer::from(1) << 200);
                q >> (200 - e + 20)
            })
            .collect();
        let (_, t) = RationalQuad(quad_of(&l))
            .filter_terms()
            .expect("inside the range");
        let [a, b, c, d, e] = [0, 1, 2, 3, 4].map(|k| exact(l[k].to_f64()));
        let m = &d * &e * (&b * &b + &c * &c + &a * &a) + &b * &c * (&d * &d + &e * &e + &a * &a);
        let target = pow2(-47) * m;
        let gap = num_traits::Signed::abs(&(exact(t) - &target));
        assert!(gap <= &slack * &target + pow2(-999), "case {i}: {l:?}");
    }
}

/// The enclosure rung of the rational predicate (B62): the 3-4-5 rectangle with its
/// diagonal moved by `±10⁻²⁰` relative is declined by the filter (`|P| ≈ 10⁻²⁰·M`, far
/// below `2⁻⁴⁷M`) and decided by the 128-bit enclosure, before the exact rung, with the
/// sign of the oracle.
#[test]
fn term_b62_rational_near_ties_are_decided_by_the_first_enclosure() {
    for sign in [-1i32, 1] {
        let eps = Rational::from((sign, 1)) / Rational::from(rug::Integer::u_pow_u(10, 20));
        let diag = Rational::from(5) * (Rational::from(1) + &eps);
        let l = [diag, 4.into(), 3.into(), 4.into(), 3.into()];
        let q = RationalQuad(quad_of(&l));
        assert_eq!(q.filter(), None);
        assert_eq!(
            decide(&q, &Ladder::default()),
            Certified::Known {
                value: oracle_of(&exact_values_q(&l)),
                stage: Stage::Interval { bits: 128 }
            }
        );
    }
}
