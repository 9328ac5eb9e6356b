//! The binary64 rung of the certificate's step 1 and of its Hessian over the box (B71,
//! steps 1–2): strict triangles, Delaunay edges and the cotan Laplacian over the box
//! `B = {u' : |u'_i − u_i| ≤ r}` on `f64` interval enclosures (`Interval<f64>`, bounds
//! moved outward after each correctly rounded operation, B21), with MPFR only for the
//! edges and faces binary64 leaves open. proof: B36
//!
//! The box lengths come from the lengths at the centre, already enclosed in MPFR for the
//! residual: `ℓ_ij(u') = ℓ_ij(u)·e^{(δ_i+δ_j)/2}` with `|δ_k| ≤ r` (`δ = 0` at grounded
//! vertices), so `ℓ_ij(u') ∈ [ℓ_ij(u)]·[e^{−r}, e^{r}]`, rounded outward to binary64: no
//! exponential per edge. The Laplacian enters the ball argument only through binary64
//! midpoints and radii (B71 step 2), and the verified Cholesky factorization bounds its
//! eigenvalues with a binary64 rounding term of relative size `≥ 2⁻⁵³` (B70), so an
//! enclosure of relative width a few ulps costs the bound nothing it can see.

use super::certificate_outcome::I;
use crate::geometry::cotan::halfedge_cotans;
use crate::geometry::laplacian::{laplacian_from_halfedge_cotans, SparseMatrix};
use crate::mesh::{Edge, HalfEdge, Mesh};
use crate::predicates::delaunay::{enclose_p, QuadEdges};
use crate::scalar::{Interval, IntervalBound, Sign};
use rug::float::Round;
use rug::{Float, Rational};

/// A binary64 interval.
pub(crate) type F = Interval<f64>;

/// `[e^{−r}, e^{r}]` rounded outward to binary64 (MPFR at 64 bits, directed rounding,
/// then directed conversion). proof: B36
fn exp_pm_radius(radius: &Rational) -> Option<(f64, f64)> {
    let r = Float::with_val_round(64, radius, Round::Up).0;
    let up = Float::with_val_round(64, r.exp_ref(), Round::Up).0;
    let down = Float::with_val_round(64, (-r).exp_ref(), Round::Down).0;
    let (lo, hi) = (down.to_f64_round(Round::Down), up.to_f64_round(Round::Up));
    (lo > 0.0 && hi.is_finite()).then_some((lo, hi))
}

/// Binary64 enclosures of the lengths of `T` over the box of radius `radius` around `u`,
/// from enclosures `at_centre` of the lengths at `u`: `[ℓ(u)]·[e^{−r}, e^{r}]`, every bound
/// rounded outward. `None` when a length is not enclosed as a positive finite binary64
/// interval. proof: B36
pub(crate) fn box_lengths(at_centre: &[I], radius: &Rational) -> Option<Vec<F>> {
    let (lo_factor, hi_factor) = exp_pm_radius(radius)?;
    let mut out = Vec::with_capacity(at_centre.len());
    for l in at_centre {
        let c = l.to_f64_outward();
        let x = F::new(c.lo().mul_down(&lo_factor), c.hi().mul_up(&hi_factor));
        if x.sign() != Some(Sign::Positive) || !x.hi().is_finite() {
            return None;
        }
        out.push(x);
    }
    Some(out)
}

/// Whether `x` is certified `≥ 0`.
fn nonnegative(x: &F) -> bool {
    x.is_valid() && *x.lo() >= 0.0
}

/// Whether the face of `h` is a strict triangle for every length in `len`'s enclosures:
/// `y + z − x > 0` certified for each side `x`.
#[allow(clippy::let_and_return)] // the borrows of `a, b, c` must end before they drop
fn strict<B: IntervalBound>(mesh: &Mesh, h: HalfEdge, len: impl Fn(Edge) -> Interval<B>) -> bool {
    let n = mesh.next(h);
    let [a, b, c] = [h, n, mesh.next(n)].map(|x| len(x.edge()));
    let strict = [(&a, &b, &c), (&b, &c, &a), (&c, &a, &b)]
        .into_iter()
        .all(|(x, y, z)| (y.clone() + z - x).sign() == Some(Sign::Positive));
    strict
}

/// Step 1 of B71 inside one Penner cell and the cotan Laplacian over the box, from the
/// binary64 box lengths `lb` (see [`box_lengths`]). A face or an edge that binary64 does
/// not certify is decided again on MPFR enclosures of its lengths over the box,
/// `exact(e)`; `None` when a face is still not a strict triangle, an edge not Delaunay, or
/// a cotangent not enclosed (the caller then takes the MPFR path, which also handles
/// boxes across cell boundaries, B35). The Laplacian's entries are binary64 bounds (read
/// as MPFR enclosures by [`super::box_values::BoxLaplacian`]). proof: B36, B71
pub(crate) fn cell_over_box(
    mesh: &Mesh,
    lb: &[F],
    exact: impl Fn(Edge) -> I,
) -> Option<SparseMatrix<F>> {
    let len = |e: Edge| lb[e.idx()].clone();
    for f in mesh.faces() {
        let h = mesh.face_halfedge(f);
        if !strict(mesh, h, len) && !strict(mesh, h, &exact) {
            return None;
        }
    }
    for e in mesh.edges() {
        let Some(q) = QuadEdges::of(mesh, e) else {
            continue;
        };
        if nonnegative(&enclose_p(&q.lengths(lb).map(Clone::clone).to_array())) {
            continue;
        }
        let p = enclose_p(&q.edges.map(&exact).to_array());
        if !super::ball_argument::certified_nonnegative(&p) {
            return None;
        }
    }
    let cot = halfedge_cotans(mesh, lb);
    if !cot
        .iter()
        .all(|c| c.is_valid() && c.lo().is_finite() && c.hi().is_finite())
    {
        return None;
    }
    Some(laplacian_from_halfedge_cotans(mesh, &cot))
}

#[cfg(test)]
mod tests {
    use super::{box_lengths, cell_over_box, F, I};
    use crate::geometry::cotan::halfedge_cotans;
    use crate::geometry::laplacian::laplacian_from_halfedge_cotans;
    use crate::mesh::builders::icosahedron;
    use crate::mesh::{Edge, Mesh};
    use crate::scalar::{Mpfr, Precision, Real};
    use crate::uniformization::cell_boundary::scale;
    use crate::uniformization::refine::scaled;
    use rug::Rational;

    const BITS: u64 = 256;

    /// The irregular icosahedron (binary64 positions), its lengths enclosed at 256 bits,
    /// and `u_v = (v mod 5)/50` as rationals.
    pub(super) fn case() -> (Mesh, Vec<I>, Vec<Rational>) {
        let s = icosahedron();
        let p = Precision::new(BITS).unwrap();
        let base: Vec<I> = s
            .mesh
            .edges()
            .map(|e| {
                let h = e.halfedge();
                let (a, b) = (
                    &s.positions[s.mesh.tail(h).idx()],
                    &s.positions[s.mesh.tip(h).idx()],
                );
                let sq: Rational = (0..3).map(|k| Rational::from(&a[k] - &b[k]).square()).sum();
                I::from_rational(&sq, p).sqrt()
            })
            .collect();
        let u = (0..s.mesh.n_vertices())
            .map(|v| Rational::from(((v % 5) as i64, 50)))
            .collect();
        (s.mesh, base, u)
    }

    pub(super) fn points(u: &[Rational]) -> Vec<I> {
        let p = Precision::new(BITS).unwrap();
        u.iter().map(|q| I::from_rational(q, p)).collect()
    }

    pub(super) fn boxed(u: &[Rational], r: &Rational) -> Vec<I> {
        let p = Precision::new(BITS).unwrap();
        u.iter()
            .map(|q| {
                let lo = I::from_rational(&Rational::from(q - r), p);
                let hi = I::from_rational(&Rational::from(q + r), p);
                I::new(lo.lo().clone(), hi.hi().clone())
            })
            .collect()
    }

    fn contains(outer: &F, inner: &I) -> bool {
        let (lo, hi) = (
            Mpfr::from_f64(*outer.lo(), inner.lo().precision()),
            Mpfr::from_f64(*outer.hi(), inner.lo().precision()),
        );
        lo.as_float() <= inner.lo().as_float() && inner.hi().as_float() <= hi.as_float()
    }

    fn contains_point(outer: &F, x: &Mpfr) -> bool {
        *outer.lo() <= x.approx_f64()
            && x.approx_f64() <= *outer.hi()
            && Mpfr::from_f64(*outer.lo(), x.precision()).as_float() <= x.as_float()
            && x.as_float() <= Mpfr::from_f64(*outer.hi(), x.precision()).as_float()
    }

    /// The binary64 box lengths (from the centre, `[e^{−r}, e^{r}]`) contain the MPFR box
    /// lengths computed edge by edge from the box of `u` (another evaluation), and their
    /// relative width is at most `e^{2r} − 1` plus eight units of binary64 rounding (B36). Negative
    /// control: the lengths at `u` moved by `3r` at one vertex leave the enclosure.
    #[test]
    fn b36_binary64_box_lengths_contain_the_mpfr_box_lengths() {
        let (mesh, base, u) = case();
        let r = Rational::from((1, 1_000_000));
        let lp = scaled(&mesh, &base, &points(&u));
        let lb = box_lengths(&lp, &r).unwrap();
        let bx = boxed(&u, &r);
        for e in mesh.edges() {
            let m = scale(&mesh, e.halfedge(), &base[e.idx()], &bx);
            let f = &lb[e.idx()];
            assert!(contains(f, &m), "e{}: {f:?} ∌ {m:?}", e.0);
            let rel = (f.hi() - f.lo()) / f.lo();
            // e^{2r} − 1, with a margin for its own evaluation, plus the rounding.
            let bound = 2e-6f64.exp_m1() * (1.0 + 1e-12) + 8.0 * f64::EPSILON;
            assert!(rel <= bound, "e{}: {rel:e}", e.0);
        }
        // Negative control: u + 3r at vertex 0.
        let mut moved = u.clone();
        moved[0] += Rational::from(3) * &r;
        let lm = scaled(&mesh, &base, &points(&moved));
        let outside = mesh.edges().filter(|&e| {
            let h = e.halfedge();
            let at0 = mesh.tail(h).idx() == 0 || mesh.tip(h).idx() == 0;
            at0 && !contains_point(&lb[e.idx()], lm[e.idx()].lo())
        });
        assert_eq!(
            outside.count(),
            5,
            "all five edges at vertex 0 leave the box"
        );
    }

    /// The binary64 Laplacian over the box contains the cotan Laplacian at the box's
    /// corners `u ± r` (alternating signs), evaluated in 256-bit MPFR at points (B36, B71
    /// step 2). Negative control: at `u` moved by `100r` at one vertex, some entry of the
    /// Laplacian leaves the enclosure.
    #[test]
    fn b36_binary64_laplacian_contains_the_laplacian_at_points_of_the_box() {
        let (mesh, base, u) = case();
        let r = Rational::from((1, 1_000_000));
        let lp = scaled(&mesh, &base, &points(&u));
        let lb = box_lengths(&lp, &r).unwrap();
        let bx = boxed(&u, &r);
        let exact = |e: Edge| scale(&mesh, e.halfedge(), &base[e.idx()], &bx);
        let lap = cell_over_box(&mesh, &lb, exact).expect("the icosahedron is Delaunay");
        let at = |u: &[Rational]| {
            let mid: Vec<Mpfr> = scaled(&mesh, &base, &points(u))
                .iter()
                .map(|x| x.lo().clone())
                .collect();
            laplacian_from_halfedge_cotans(&mesh, &halfedge_cotans(&mesh, &mid))
        };
        let inside = |l: &crate::geometry::laplacian::SparseMatrix<Mpfr>| {
            l.entries()
                .all(|(i, j, w)| contains_point(lap.get(i, j).unwrap(), w))
        };
        for sign in [1i64, -1] {
            let corner: Vec<Rational> = u
                .iter()
                .enumerate()
                .map(|(v, q)| {
                    let s = if v % 2 == 0 { sign } else { -sign };
                    q + Rational::from(s) * &r
                })
                .collect();
            assert!(inside(&at(&corner)), "corner {sign}");
        }
        let mut moved = u.clone();
        moved[0] += Rational::from(100) * &r;
        assert!(
            !inside(&at(&moved)),
            "u + 100r at v0 must leave the enclosure"
        );
    }

    /// Step 1 refuses what is not Delaunay: two copies of an obtuse triangle glued along
    /// their sides (the side opposite the obtuse angle has `α + β > π`) give `None`, two
    /// equilateral ones give the Laplacian (B36).
    #[test]
    fn b36_binary64_rung_refuses_a_non_delaunay_edge() {
        let mesh = Mesh::from_faces(3, &[[0, 1, 2], [0, 2, 1]]).unwrap();
        let p = Precision::new(BITS).unwrap();
        let r = Rational::from((1, 1_000_000));
        let u = vec![Rational::from(0); 3];
        let run = |sides: [f64; 3]| {
            let mut base = vec![I::point(Mpfr::from_f64(1.0, p)); 3];
            for e in mesh.edges() {
                let h = e.halfedge();
                let (a, b) = (mesh.tail(h).idx(), mesh.tip(h).idx());
                base[e.idx()] = I::point(Mpfr::from_f64(sides[3 - a - b], p));
            }
            let lp = scaled(&mesh, &base, &points(&u));
            let lb = box_lengths(&lp, &r).unwrap();
            let bx = boxed(&u, &r);
            cell_over_box(&mesh, &lb, |e| {
                scale(&mesh, e.halfedge(), &base[e.idx()], &bx)
            })
        };
        assert!(run([1.0, 1.0, 1.0]).is_some());
        assert!(run([1.0, 1.0, 1.9]).is_none());
    }
}

#[cfg(test)]
#[path = "box_f64_terms.rs"]
mod terms;
