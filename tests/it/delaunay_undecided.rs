//! The `Undecided` end of the Delaunay ladder: at an exact tie `P = 0` a predicate with no
//! exact rung (enclosed lengths, `EnclosureQuad`; non-uniformly scaled lengths,
//! `ScaledQuad`) must answer `Undecided`, never a sign, and the flip driver must list such
//! an edge in `FlipReport::undecided`. Oracles: the D-form of GSC21 in malachite rationals
//! (`crate::delaunay::oracle`), and for transcendental lengths a polynomial identity
//! checked on a grid of rational scale factors plus the D-form at 3000 bits. Negative
//! controls: perturbed ties, which exact arithmetic finds nonzero, are decided with the
//! exact sign.

use crate::delaunay::{oracle, to_m};
use crate::meshgen::planar_grid;
use crate::support::{case_seeds, cases};
use malachite::rational::Rational as MRational;
use penner::algorithms::flip_to_delaunay::{flip_to_delaunay_exact, ExactLengths, FlipOptions};
use penner::mesh::{Edge, Mesh, Vertex};
use penner::predicates::delaunay::{
    edge_delaunay_sign_scaled, EdgeDelaunay, EnclosureQuad, Quad, QuadEdges, RationalQuad,
    ScaledQuad,
};
use penner::predicates::ladder::{decide, Ladder};
use penner::scalar::{Certified, Interval, Mpfr, Precision, Real, Sign, Stage};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rug::Rational;

/// `[ij, jk, ki, il, lj]` as a quadrilateral.
fn quad<T>(v: [T; 5]) -> Quad<T> {
    let [ij, jk, ki, il, lj] = v;
    Quad { ij, jk, ki, il, lj }
}

/// The malachite D-form oracle on five rug rationals.
fn exact_sign(l: &[Rational; 5]) -> Sign {
    let m = l.each_ref().map(to_m);
    oracle(m.each_ref())
}

/// The 3-4-5 rectangle `i k j l` cut along its diagonal `ij`, scaled by `s`:
/// `[ij, jk, ki, il, lj] = s·[5, 3, 4, 3, 4]`. Cocircular, so `P = 0` exactly.
fn rectangle(s: &Rational) -> [Rational; 5] {
    [5, 3, 4, 3, 4].map(|x| s * Rational::from(x))
}

/// The default ladder's answer when no rung decides.
const UNDECIDED: Certified<Sign> = Certified::Undecided { bits_tried: 1024 };

#[test]
fn b62_enclosure_quad_at_an_exact_tie_is_undecided() {
    let p = Precision::new(128).unwrap();
    let ladder = Ladder::default();
    let (mut ties, mut decided, mut beyond) = (0, 0, 0);
    for (n, d) in [(1, 3), (2, 7), (5, 11), (10, 3), (1, 10), (7, 9)] {
        let l = rectangle(&Rational::from((n, d)));
        // Oracle: exactly zero (malachite, D-form); the library's exact rung agrees.
        assert_eq!(exact_sign(&l), Sign::Zero, "scale {n}/{d}");
        assert_eq!(
            decide(&RationalQuad(quad(l.each_ref())), &ladder),
            Certified::Known {
                value: Sign::Zero,
                stage: Stage::Exact
            },
            "scale {n}/{d}"
        );
        // Enclosures of non-dyadic lengths are not points, so the enclosure of P contains
        // zero without being [0, 0]: no rung can decide it.
        let enc = l.each_ref().map(|x| Interval::<Mpfr>::from_rational(x, p));
        assert!(enc.iter().any(|x| x.width_f64() > 0.0), "scale {n}/{d}");
        for (x, q) in enc.iter().zip(&l) {
            assert!(encloses(x, &to_m(q)), "scale {n}/{d}");
        }
        assert_eq!(
            decide(&EnclosureQuad(quad(enc.each_ref())), &ladder),
            UNDECIDED,
            "scale {n}/{d}"
        );
        ties += 1;
        // Negative control: the diagonal stretched (P < 0) or shrunk (P > 0) by 10⁻ᵏ
        // relative. Exact arithmetic says nonzero, and the enclosures decide it with that
        // sign at their own precision.
        for k in [3u32, 10, 20, 30, 60] {
            for sgn in [-1i32, 1] {
                let mut lp = l.clone();
                let eps = Rational::from((sgn, 1)) / Rational::from(rug::Integer::u_pow_u(10, k));
                lp[0] *= Rational::from(1) + eps;
                let exact = exact_sign(&lp);
                let want = if sgn > 0 {
                    Sign::Negative
                } else {
                    Sign::Positive
                };
                assert_eq!(exact, want, "scale {n}/{d}, 10^-{k}");
                let encp = lp.each_ref().map(|x| Interval::<Mpfr>::from_rational(x, p));
                let got = decide(&EnclosureQuad(quad(encp.each_ref())), &ladder);
                if k <= 30 {
                    // 10⁻³⁰ ≈ 2⁻¹⁰⁰ relative, far above the 128-bit widths.
                    assert_eq!(
                        got,
                        Certified::Known {
                            value: exact,
                            stage: Stage::Interval { bits: 128 }
                        },
                        "scale {n}/{d}, 10^-{k}"
                    );
                    decided += 1;
                } else {
                    // 10⁻⁶⁰ ≈ 2⁻¹⁹⁹ is below the 128-bit widths: honest, not wrong.
                    assert_eq!(got, UNDECIDED, "scale {n}/{d}, 10^-{k}");
                    beyond += 1;
                }
            }
        }
    }
    assert_eq!((ties, decided, beyond), (6, 6 * 8, 6 * 2));
}

/// Whether the enclosure `x` contains `q`, compared in malachite (independent of
/// `Interval::contains_rational`).
pub fn encloses(x: &Interval<Mpfr>, q: &MRational) -> bool {
    let lo = to_m(&x.lo().to_rational().expect("finite lower end"));
    let hi = to_m(&x.hi().to_rational().expect("finite upper end"));
    lo <= *q && *q <= hi
}

/// An `n × n` grid of congruent rectangles with sides `w` (x) and `h` (y) and diagonal
/// `d`, on the triangulation of [`planar_grid`] (one random diagonal per cell); the
/// diagonal edges in edge order.
pub fn rectangle_grid(
    n: u32,
    [w, h, d]: [&Rational; 3],
    seed: u64,
) -> (Mesh, Vec<Rational>, Vec<Edge>) {
    let e = planar_grid(n, 0.0, seed);
    let m = e.mesh();
    let cell = |v: Vertex| {
        let p = e.pos[v.idx()];
        [p[0], p[1]].map(|x| (x * f64::from(n)).round() as i64)
    };
    let mut diagonals = Vec::new();
    let l = m
        .edges()
        .map(|x| {
            let h_ = x.halfedge();
            let (a, b) = (cell(m.tail(h_)), cell(m.tip(h_)));
            match ((a[0] - b[0]).abs(), (a[1] - b[1]).abs()) {
                (1, 0) => w.clone(),
                (0, 1) => h.clone(),
                (1, 1) => {
                    diagonals.push(x);
                    d.clone()
                }
                other => panic!("edge {x} spans {other:?} cells"),
            }
        })
        .collect();
    (m, l, diagonals)
}

/// Interior edges of `(m, l)` where the malachite oracle finds `P = 0`.
fn oracle_ties(m: &Mesh, l: &[Rational]) -> Vec<Edge> {
    let ml: Vec<MRational> = l.iter().map(to_m).collect();
    m.edges()
        .filter(|&e| {
            QuadEdges::of(m, e).is_some_and(|q| oracle(q.lengths(&ml).to_array()) == Sign::Zero)
        })
        .collect()
}

#[test]
fn t21_fell_back_exact_flipping_lists_exact_ties_as_undecided() {
    // A 4 × 4 grid of 3-4-5 rectangles scaled by 1/3: sides 1 and 4/3, diagonals 5/3.
    let third = |x: i32| Rational::from((x, 3));
    let (w, h, d) = (third(3), third(4), third(5));
    let opts = FlipOptions::default();
    let mut perturbed_runs = 0;
    for seed in case_seeds(8, 40) {
        let (m, l, diagonals) = rectangle_grid(4, [&w, &h, &d], seed);
        assert_eq!(diagonals.len(), 16);
        // Oracle: every diagonal, and nothing else, is an exact tie.
        assert_eq!(oracle_ties(&m, &l), diagonals, "seed {seed}");
        // In ℚ all the way: the ties are decided (Zero), nothing is flipped.
        let mut me = m.clone();
        let (re, _) = flip_to_delaunay_exact(&mut me, l.clone(), 1 << 20, &opts).unwrap();
        assert!(re.all_certified_delaunay(), "seed {seed}: {re:?}");
        assert_eq!((re.flips, re.fell_back_after), (0, None), "seed {seed}");
        assert_eq!(re.stages.undecided, 0, "seed {seed}");
        // A one-bit guard: the whole run on 128-bit enclosures of 1, 4/3, 5/3. Every tie
        // is undecided and listed; every other edge is certified.
        let mut mf = m.clone();
        let (rf, out) = flip_to_delaunay_exact(&mut mf, l.clone(), 1, &opts).unwrap();
        assert_eq!(rf.fell_back_after, Some(0), "seed {seed}");
        assert!(matches!(out, ExactLengths::Enclosed(_)));
        assert_eq!(rf.flips, 0, "seed {seed}");
        assert_eq!(rf.undecided, diagonals, "seed {seed}");
        assert_eq!(rf.stages.undecided, 16, "seed {seed}");
        assert!(rf.refused.is_empty() && !rf.hit_cap, "seed {seed}");
        assert!(!rf.all_certified_delaunay());
        // Negative control: one diagonal stretched (exactly non-Delaunay) or shrunk
        // (exactly strictly Delaunay) by 10⁻²⁰ relative is no tie; the enclosures decide it
        // as exact arithmetic does (flipped, resp. kept) and it leaves the undecided list.
        let d0 = diagonals[seed as usize % 16];
        for sgn in [1i32, -1] {
            let mut lp = l.clone();
            lp[d0.idx()] *= Rational::from(1)
                + Rational::from((sgn, 1)) / Rational::from(rug::Integer::u_pow_u(10, 20));
            let ties: Vec<Edge> = diagonals.iter().copied().filter(|&x| x != d0).collect();
            assert_eq!(oracle_ties(&m, &lp), ties, "seed {seed} {sgn}");
            let mut me = m.clone();
            let (re, _) = flip_to_delaunay_exact(&mut me, lp.clone(), 1 << 20, &opts).unwrap();
            let mut mf = m.clone();
            let (rf, _) = flip_to_delaunay_exact(&mut mf, lp, 1, &opts).unwrap();
            assert_eq!(rf.fell_back_after, Some(0));
            assert_eq!(re.flips, usize::from(sgn > 0), "seed {seed} {sgn}");
            assert_eq!(rf.flips, re.flips, "seed {seed} {sgn}");
            assert_eq!(mf, me, "seed {seed} {sgn}");
            assert_eq!(rf.undecided, ties, "seed {seed} {sgn}");
            assert_eq!(rf.stages.undecided, 15, "seed {seed} {sgn}");
            perturbed_runs += 1;
        }
    }
    assert_eq!(perturbed_runs, 2 * cases(8, 40));
}

/// The D-form of `ℓ̃ = e^{(u_a+u_b)/2}·ℓ` on `q` at 3000 bits (a different formula, code
/// path and precision from the predicate).
fn scaled_d_3000(m: &Mesh, q: &QuadEdges, base: &[f64], u: &[f64]) -> Mpfr {
    let prec = Precision::new(3000).unwrap();
    let len = |e: Edge| {
        let h = e.halfedge();
        let (a, b) = (m.tail(h).idx(), m.tip(h).idx());
        let half = Mpfr::from_f64(u[a], prec) + &Mpfr::from_f64(u[b], prec);
        (half / &Mpfr::from_f64(2.0, prec)).exp() * &Mpfr::from_f64(base[e.idx()], prec)
    };
    let [ij, jk, ki, il, lj] = q.edges.to_array().map(len);
    let kl = (ki.clone() * &lj + &(il.clone() * &jk)) / &ij;
    kl * &(il.clone() * &ki + &(jk.clone() * &lj)) - &(ij * &(jk * &ki + &(il * &lj)))
}

/// Whether `P` of the 3-4-5 rectangle with vertex scales `σ_i = σ_k = x`, `σ_j = σ_l = y`
/// (lengths `σ_a σ_b ℓ_ab`, all rational) is zero for the malachite oracle; with `z` for
/// `σ_k` instead when given.
fn rectangle_tie_at(x: &Rational, y: &Rational, z: Option<&Rational>) -> bool {
    let k = z.unwrap_or(x);
    let base = rectangle(&Rational::from(1));
    let scales = [(x, y), (y, k), (k, x), (x, y), (y, y)];
    let l: [Rational; 5] = std::array::from_fn(|n| {
        let (a, b) = scales[n];
        Rational::from(a * b) * &base[n]
    });
    exact_sign(&l) == Sign::Zero
}

/// The oracle of [`b62_scaled_quad_at_an_exact_transcendental_tie_is_undecided`]. With
/// `σ_v = e^{u_v/2}`, `u_i = u_k = s` and `u_j = u_l = t` the scaled 3-4-5 rectangle is an
/// isosceles trapezoid (parallel sides `4σ_i²`, `4σ_j²`, legs `3σ_iσ_j`, diagonal `5σ_iσ_j`):
/// cocircular. In the roles `ij = 5, jk = 3, ki = 4, il = 3, lj = 4`, `P` is a polynomial of
/// degree ≤ 5 in each of `σ_i`, `σ_j`; it vanishes on a 9 × 9 grid of rational values
/// (exact, malachite), hence identically, hence at `σ = e^{s/2}, e^{t/2}`.
fn assert_trapezoid_family_is_an_exact_tie() {
    let grid: Vec<Rational> = [
        (1, 2),
        (2, 3),
        (1, 1),
        (3, 2),
        (2, 1),
        (5, 2),
        (3, 1),
        (7, 2),
        (4, 1),
    ]
    .map(Rational::from)
    .to_vec();
    let mut distinct = 0;
    for x in &grid {
        for y in &grid {
            assert!(rectangle_tie_at(x, y, None), "σ = {x}, {y}");
            distinct += usize::from(x != y);
        }
    }
    assert_eq!(distinct, 72);
    // Negative control of the oracle: a third scale at k breaks the tie (e.g. one vertex
    // scaled alone): D = 0 is not invariant under general conformal scaling.
    let third = Rational::from((5, 4));
    let broken = grid
        .iter()
        .filter(|y| !rectangle_tie_at(&grid[2], y, Some(&third)))
        .count();
    assert_eq!(broken, grid.len());
}

#[test]
fn b62_scaled_quad_at_an_exact_transcendental_tie_is_undecided() {
    assert_trapezoid_family_is_an_exact_tie();
    // The mesh: the square 0-1-2-3 cut along 0-2, with the rectangle in the roles of the
    // diagonal's quadrilateral.
    let m = Mesh::from_faces(4, &[[0, 1, 2], [0, 2, 3]]).unwrap();
    let diag = m.edges().find(|&e| !m.is_boundary_edge(e)).unwrap();
    let q = QuadEdges::of(&m, diag).unwrap();
    let [vi, vj, vk, vl] = m.quad_vertices(diag).map(Vertex::idx);
    let mut base = vec![0.0; m.n_edges()];
    for (e, x) in q
        .edges
        .to_array()
        .into_iter()
        .zip([5.0, 3.0, 4.0, 3.0, 4.0])
    {
        base[e.idx()] = x;
    }
    let ladder = Ladder::default();
    let mut rng = ChaCha8Rng::seed_from_u64(0xB62);
    let (mut undecided, mut decided) = (0, 0);
    for _ in 0..cases(200, 2_000) {
        let s: f64 = rng.gen_range(-3.0..3.0);
        let t: f64 = rng.gen_range(-3.0..3.0);
        if s == t {
            continue;
        }
        let mut u = vec![0.0; 4];
        (u[vi], u[vk], u[vj], u[vl]) = (s, s, t, t);
        // The tie is exact and transcendental: every enclosure contains 0 and none is a
        // point, and with non-uniform scales there is no exact rung.
        let got = edge_delaunay_sign_scaled(&m, &base, &u, diag, &ladder).unwrap();
        assert_eq!(got, EdgeDelaunay::Interior(UNDECIDED), "s = {s}, t = {t}");
        assert_eq!(got.is_delaunay(), None);
        let direct = ScaledQuad {
            base: q.edges.map(|e| base[e.idx()]),
            scale: q.edges.map(|e| {
                let h = e.halfedge();
                (u[m.tail(h).idx()], u[m.tip(h).idx()])
            }),
            uniform: false,
        };
        assert_eq!(decide(&direct, &ladder), UNDECIDED, "s = {s}, t = {t}");
        undecided += 1;
        // Control: one common scale is decided exactly on the base lengths (Zero).
        let same = vec![s; 4];
        assert_eq!(
            edge_delaunay_sign_scaled(&m, &base, &same, diag, &ladder).unwrap(),
            EdgeDelaunay::Interior(Certified::Known {
                value: Sign::Zero,
                stage: Stage::Exact
            }),
            "s = {s}"
        );
        // Negative control: u_k moved by one ulp or by up to 0.1 breaks the tie; the
        // ladder decides, with the sign of the 3000-bit D-form.
        let one_ulp = f64::from_bits(s.to_bits() + 1) - s;
        for delta in [one_ulp, -one_ulp, rng.gen_range(-0.1..0.1)] {
            let mut up = u.clone();
            up[vk] = s + delta;
            if up[vk] == s {
                continue;
            }
            let dv = scaled_d_3000(&m, &q, &base, &up);
            let v = dv.0.clone();
            assert!(
                !v.is_zero() && v.clone().abs() > 1e-60,
                "s = {s}, δ = {delta}: {v}"
            );
            let want = if v > 0 {
                Sign::Positive
            } else {
                Sign::Negative
            };
            let got = edge_delaunay_sign_scaled(&m, &base, &up, diag, &ladder).unwrap();
            match got {
                EdgeDelaunay::Interior(Certified::Known { value, .. }) => {
                    assert_eq!(value, want, "s = {s}, t = {t}, δ = {delta}");
                }
                other => panic!("s = {s}, t = {t}, δ = {delta}: {other:?}"),
            }
            decided += 1;
        }
    }
    assert!(
        undecided > 0 && decided >= 2 * undecided,
        "{undecided} {decided}"
    );
}
