//! B36's terms, one deciding test each (proofs/B36, **Terms**): the outward roundings, each
//! on a value whose nearest binary64 number lies on the wrong side, checked against 256-bit
//! MPFR enclosures; the strict-triangle test on the enclosures, decided exactly; binary64
//! deciding a well-shaped box alone; and the MPFR look deciding a face binary64 leaves open.

use super::tests::{boxed, case, points};
use super::{box_lengths, cell_over_box, exp_pm_radius, strict, F, I};
use crate::geometry::cotan::halfedge_cotans;
use crate::geometry::laplacian::laplacian_from_halfedge_cotans;
use crate::mesh::{Edge, HalfEdge, Mesh};
use crate::predicates::delaunay::{enclose_p, QuadEdges};
use crate::scalar::{Mpfr, Precision, Real};
use crate::uniformization::ball_argument::certified_nonnegative;
use crate::uniformization::cell_boundary::scale;
use crate::uniformization::refine::scaled;
use rug::float::Round;
use rug::{Float, Rational};

/// `[e^{x}]` at 256 bits, rounded down and up.
fn exp256(x: &Rational) -> (Float, Float) {
    let lo = Float::with_val_round(256, x, Round::Down).0;
    let hi = Float::with_val_round(256, x, Round::Up).0;
    (
        Float::with_val_round(256, lo.exp_ref(), Round::Down).0,
        Float::with_val_round(256, hi.exp_ref(), Round::Up).0,
    )
}

/// B36 terms `c⁻ ≤ e^{−r}` and `c⁺ ≥ e^{r}`: radii `k/1000` for which the nearest
/// binary64 number of `e^{r}` lies below it and that of `e^{−r}` above it.
#[test]
fn term_b36_exponential_factors_rounded_outward() {
    let (mut up_tested, mut down_tested) = (false, false);
    for k in 1..200 {
        let r = Rational::from((k, 1000));
        let (lo, hi) = exp_pm_radius(&r).expect("finite factors");
        let (_, e_up) = exp256(&r);
        let (e_down, _) = exp256(&Rational::from(-&r));
        assert!(
            Float::with_val(256, hi) >= e_up,
            "r = {r}: e^r rounded inward"
        );
        assert!(
            Float::with_val(256, lo) <= e_down,
            "r = {r}: e^-r rounded inward"
        );
        up_tested |= Float::with_val(53, &e_up) < e_up;
        down_tested |= Float::with_val(53, &e_down) > e_down;
    }
    assert!(
        up_tested && down_tested,
        "no radius had its nearest on the wrong side"
    );
}

/// B36 term "every bound of `[ℓ(u)]·[e^{−r}, e^{r}]` rounded outward": exact binary64
/// centre lengths `c` (point enclosures) on boxes of radius `k/1000`, among which some
/// have the nearest binary64 number of `c·c⁺` below `c·e^{r}` (and of `c·c⁻` above
/// `c·e^{−r}`); a product rounded to nearest would leave the box there.
#[test]
fn term_b36_box_lengths_rounded_outward() {
    let p = Precision::new(64).expect("precision");
    let (mut up_tested, mut down_tested) = (false, false);
    for k in [1, 7, 50, 199] {
        let r = Rational::from((k, 1000));
        let (lo_factor, hi_factor) = exp_pm_radius(&r).expect("finite factors");
        let (_, e_up) = exp256(&r);
        let (e_down, _) = exp256(&Rational::from(-&r));
        for j in 0..400 {
            let c = 1.0 + f64::from(j) / 997.0;
            let l = box_lengths(&[I::from_f64(c, p)], &r).expect("a positive length");
            let high = Float::with_val_round(256, c * &e_up, Round::Up).0;
            let low = Float::with_val_round(256, c * &e_down, Round::Down).0;
            assert!(Float::with_val(256, *l[0].hi()) >= high, "c = {c}, r = {r}");
            assert!(Float::with_val(256, *l[0].lo()) <= low, "c = {c}, r = {r}");
            up_tested |= Float::with_val(256, c * hi_factor) < high;
            down_tested |= Float::with_val(256, c * lo_factor) > low;
        }
    }
    assert!(
        up_tested && down_tested,
        "no product had its nearest on the wrong side"
    );
}

/// B36 `None` when a bound leaves binary64: `e^{720}` overflows while `e^{−720}` is a
/// positive subnormal; a centre length `10³⁰⁸` times `e` overflows.
#[test]
fn term_b36_bounds_outside_binary64_are_refused() {
    assert!(exp_pm_radius(&Rational::from(720)).is_none());
    assert!(exp_pm_radius(&Rational::from(700)).is_some());
    let p = Precision::new(64).expect("precision");
    assert!(box_lengths(&[I::from_f64(1e308, p)], &Rational::from(1)).is_none());
    assert!(box_lengths(&[I::from_f64(1e300, p)], &Rational::from(1)).is_some());
}

/// The doubled triangle (faces `[0, 1, 2]`, `[0, 2, 1]`), one of its half-edges, and the
/// side index of an edge: the vertex it is opposite.
fn doubled() -> (Mesh, HalfEdge) {
    let mesh = Mesh::from_faces(3, &[[0, 1, 2], [0, 2, 1]]).expect("the doubled triangle");
    let h = mesh.face_halfedge(mesh.faces().next().expect("a face"));
    (mesh, h)
}

fn side(mesh: &Mesh, e: Edge) -> usize {
    let h = e.halfedge();
    3 - mesh.tail(h).idx() - mesh.tip(h).idx()
}

/// The binary64 interval `[lo, hi]` taken exactly at 256 bits.
fn mpfr(x: &F) -> I {
    let p = Precision::new(256).expect("precision");
    I::new(Mpfr::from_f64(*x.lo(), p), Mpfr::from_f64(*x.hi(), p))
}

/// The oracle: `lo(y) + lo(z) − hi(x) > 0` for every side `x`, in exact rationals — every
/// point of the three enclosures is a strict triangle.
fn strict_exactly(s: &[F; 3]) -> bool {
    let q = |x: f64| Rational::from_f64(x).expect("finite");
    (0..3).all(|k| q(*s[(k + 1) % 3].lo()) + q(*s[(k + 2) % 3].lo()) - q(*s[k].hi()) > 0)
}

/// B36 term "strict faces on the enclosures": `strict` accepts a face only when every point
/// of its enclosures is a strict triangle (the exact rational oracle), and accepts the
/// clear ones; at 256 bits the sums of binary64 endpoints are exact, so there it is the
/// oracle itself. Negative controls: a degenerate face `1, 1, 2`, a non-triangle
/// `1, 1, 2.5`, a side straddling the sum of the others. A needle whose binary64 sum
/// `lo(y) + lo(z)` rounds down onto `hi(x)` is a strict triangle that binary64 leaves open.
#[test]
fn term_b36_strict_faces_decided_on_the_enclosures() {
    let (mesh, h) = doubled();
    let e = f64::EPSILON;
    let unit = F::new(1.0 - e / 2.0, 1.0 + e);
    let needle = F::new(1.9 * e * (1.0 - e / 2.0), 1.9 * e * (1.0 + e));
    let pt = |x: f64| F::new(x, x);
    // (sides opposite vertices 0, 1, 2; whether binary64 certifies).
    let cases: [([F; 3], bool); 7] = [
        ([unit.clone(), unit.clone(), unit.clone()], true),
        ([pt(3.0), pt(4.0), pt(5.0)], true),
        ([pt(2.0), pt(1.0), pt(1.0)], false),
        ([pt(1.0), pt(2.5), pt(1.0)], false),
        ([F::new(1.5, 2.5), pt(1.0), pt(1.0)], false),
        ([F::new(1.5, 1.9), pt(1.0), pt(1.0)], true),
        ([needle, unit.clone(), unit], false),
    ];
    for (sides, certified) in &cases {
        let f64_len = |e: Edge| sides[side(&mesh, e)].clone();
        let mp_len = |e: Edge| mpfr(&sides[side(&mesh, e)]);
        let exact = strict_exactly(sides);
        let got = strict(&mesh, h, f64_len);
        assert!(
            !got || exact,
            "{sides:?}: accepted, but not a strict triangle"
        );
        assert_eq!(got, *certified, "{sides:?}");
        assert_eq!(strict(&mesh, h, mp_len), exact, "{sides:?} at 256 bits");
    }
    // The needle is the case binary64 leaves open although it is a strict triangle.
    assert!(strict_exactly(&cases[6].0) && !cases[6].1);
}

/// B36 term "binary64 decides": on the irregular icosahedron's box (radius 10⁻⁶) every face
/// and edge is decided by the binary64 enclosures alone, so an MPFR look given enclosures
/// that decide nothing (`[lo/2, 2·hi]` of the binary64 ones, still enclosures) changes
/// nothing: the same Laplacian as with the tight MPFR enclosures. Controls: those wide
/// enclosures certify no face strict and no edge's `P ≥ 0`.
#[test]
fn term_b36_binary64_decides_a_well_shaped_box_alone() {
    let (mesh, base, u) = case();
    let r = Rational::from((1, 1_000_000));
    let lb = box_lengths(&scaled(&mesh, &base, &points(&u)), &r).expect("box lengths");
    let bx = boxed(&u, &r);
    let tight = |e: Edge| scale(&mesh, e.halfedge(), &base[e.idx()], &bx);
    let wide = |e: Edge| mpfr(&F::new(lb[e.idx()].lo() / 2.0, lb[e.idx()].hi() * 2.0));
    for f in mesh.faces() {
        assert!(!strict(&mesh, mesh.face_halfedge(f), wide), "f{}", f.0);
    }
    for e in mesh.edges() {
        let q = QuadEdges::of(&mesh, e).expect("closed mesh");
        let pw = enclose_p(&q.edges.map(wide).to_array());
        assert!(!certified_nonnegative(&pw), "e{}", e.0);
    }
    let with_wide = cell_over_box(&mesh, &lb, wide).expect("decided by binary64 alone");
    let with_tight = cell_over_box(&mesh, &lb, tight).expect("the icosahedron is Delaunay");
    let bits = |x: &F| (*x.lo(), *x.hi());
    let a: Vec<_> = with_wide
        .entries()
        .map(|(i, j, w)| (i, j, bits(w)))
        .collect();
    let b: Vec<_> = with_tight
        .entries()
        .map(|(i, j, w)| (i, j, bits(w)))
        .collect();
    assert_eq!(a, b);
}

/// B36 term "MPFR where binary64 leaves a face open": the doubled needle triangle with sides
/// `1, 1, z = 1.9·2⁻⁵²` on a box of radius `2⁻¹²⁰`. Its binary64 box lengths are a strict
/// triangle (exact rational oracle on their endpoints) that binary64 cannot certify (the
/// sum `lo(1) + lo(z)` rounds down onto `hi(1)`); the MPFR enclosures certify it, and the
/// binary64 rung then gives a Laplacian that contains the cotan Laplacian at the centre
/// (256-bit MPFR). Control: with MPFR enclosures that decide nothing, it is refused.
#[test]
fn term_b36_mpfr_decides_a_face_binary64_leaves_open() {
    let (mesh, h) = doubled();
    let p = Precision::new(256).expect("precision");
    let r = Rational::from((1, 1u128 << 120));
    let sides = [1.9 * f64::EPSILON, 1.0, 1.0];
    let base: Vec<I> = mesh
        .edges()
        .map(|e| I::from_f64(sides[side(&mesh, e)], p))
        .collect();
    let u = vec![Rational::from(0); 3];
    let lb = box_lengths(&scaled(&mesh, &base, &points(&u)), &r).expect("box lengths");
    let bx = boxed(&u, &r);
    let exact = |e: Edge| scale(&mesh, e.halfedge(), &base[e.idx()], &bx);
    let by_side: [F; 3] = std::array::from_fn(|k| {
        let e = mesh
            .edges()
            .find(|&e| side(&mesh, e) == k)
            .expect("an edge");
        lb[e.idx()].clone()
    });
    assert!(strict_exactly(&by_side), "a strict triangle");
    assert!(
        !strict(&mesh, h, |e: Edge| lb[e.idx()].clone()),
        "open in binary64"
    );
    assert!(strict(&mesh, h, exact), "decided in MPFR");
    let lap = cell_over_box(&mesh, &lb, exact).expect("decided by the MPFR look");
    let centre: Vec<Mpfr> = base.iter().map(|x| x.lo().clone()).collect();
    let at_centre = laplacian_from_halfedge_cotans(&mesh, &halfedge_cotans(&mesh, &centre));
    for (i, j, w) in at_centre.entries() {
        let f = mpfr(lap.get(i, j).expect("the same pattern"));
        assert!(f.lo().as_float() <= w.as_float() && w.as_float() <= f.hi().as_float());
    }
    let wide = |e: Edge| mpfr(&F::new(lb[e.idx()].lo() / 2.0, lb[e.idx()].hi() * 2.0));
    assert!(cell_over_box(&mesh, &lb, wide).is_none());
}
