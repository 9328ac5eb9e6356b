//! Step 1 of the uniformization certificate (B71) on a box that may cross Penner-cell
//! boundaries. proof: B35
//!
//! Let `T` be the final triangulation and `U` the edges of `T` not certified Delaunay
//! (`P ≥ 0`, B60) on the whole box `B`. When `U` is empty, `B` lies in one Penner cell and
//! the Hessian of `E` on `B` is the cotan Laplacian of `T` over the box (B71). Otherwise,
//! when no face touches two edges of `U`, the quadrilaterals of the `U`-edges are disjoint
//! and their Ptolemy flips commute; for `S ⊆ U` let `T_S` be `T` with the edges of `S`
//! flipped. If
//!
//! 1. every face of `T` and of `T_U` is a strict triangle on `B`, and
//! 2. every edge `f ∉ U` is Delaunay on `B` in each of the (at most four) configurations of
//!    the `U`-edges of its two faces,
//!
//! then for every `u' ∈ B` the triangulation `T_S` with `S = {e ∈ U : P_e(u') < 0}` is
//! Delaunay at `u'` (a flipped edge has `P' = −(ℓ_il ℓ_jk + ℓ_ki ℓ_lj)·P/ℓ_ij² > 0`, B35),
//! so `E` is `C²` on `B` (T32) with Hessian the cotan Laplacian of `T_S` at `u'`. That
//! Laplacian is enclosed by the Laplacian of `T` over the box with the two faces of each
//! `U`-edge replaced by the entrywise hull of the two configurations' local blocks
//! ([`CellOverBox::laplacian`]). The angle sums at a point or over the box take, per
//! `U`-edge, the configuration certified Delaunay there, or the hull of both
//! ([`Boundary::correct_angle_sums`]).

use super::ball_argument::certified_nonnegative as nonnegative;
use super::certificate_outcome::I;
use crate::algorithms::flips::ptolemy_length_enclosure;
use crate::geometry::enclosure::cotans::enclose_halfedge_cotans;
use crate::geometry::laplacian::{laplacian_from_halfedge_cotans, SparseMatrix};
use crate::geometry::triangle::{corner_angle, cot_opposite};
use crate::mesh::{Edge, HalfEdge, Mesh};
use crate::predicates::delaunay::{enclose_p, QuadEdges};
use crate::scalar::{Real, Sign};

/// No index (an edge not in `U`, a half-edge in no `U`-quadrilateral).
const NONE: u32 = u32::MAX;

/// The result of step 1 over the box: the enclosed Hessian (as `L`) and, when the box
/// crosses cell boundaries, what the angle sums need to know about them.
pub(crate) struct CellOverBox {
    /// `L` over the box: an entrywise enclosure of the cotan Laplacian of the Delaunay
    /// triangulation `T_S` at every `u'` of the box.
    pub laplacian: SparseMatrix<I>,
    /// The cell boundaries met (`None`: the box lies in one Penner cell).
    pub boundary: Option<Boundary>,
}

/// The edges `U` not certified Delaunay on the box and their flips (B35).
pub(crate) struct Boundary {
    /// `U`, in edge order.
    pub edges: Vec<Edge>,
    /// `T_U`: `T` with every edge of `U` Ptolemy-flipped.
    flipped: Mesh,
    /// The base (unscaled) Ptolemy lengths of the flipped `U`-edges, in the order of `edges`.
    flipped_base: Vec<I>,
}

/// The smallest interval holding `a` and `b` (both valid).
fn hull(a: &I, b: &I) -> I {
    let lo = if a.lo().as_float() <= b.lo().as_float() {
        a.lo()
    } else {
        b.lo()
    };
    let hi = if a.hi().as_float() >= b.hi().as_float() {
        a.hi()
    } else {
        b.hi()
    };
    I::new(lo.clone(), hi.clone())
}

/// The three half-edges of the face of `h` in `mesh`.
fn face_of(mesh: &Mesh, h: HalfEdge) -> [HalfEdge; 3] {
    let n = mesh.next(h);
    [h, n, mesh.next(n)]
}

/// `e^{(u_a+u_b)/2}·ℓ` for the ends `a, b` of `h`.
pub(crate) fn scale(mesh: &Mesh, h: HalfEdge, base: &I, u: &[I]) -> I {
    let s = (u[mesh.tail(h).idx()].clone() + &u[mesh.tip(h).idx()]) * &base.lit(0.5);
    s.exp() * base
}

/// Every face of `faces` a strict triangle for the lengths `len`.
fn strict<'a>(
    mesh: &Mesh,
    faces: impl Iterator<Item = HalfEdge>,
    len: impl Fn(Edge) -> &'a I,
    what: &str,
) -> Result<(), String> {
    for h in faces {
        let [a, b, c] = face_of(mesh, h).map(|x| len(x.edge()));
        for (x, y, z) in [(a, b, c), (b, c, a), (c, a, b)] {
            let slack = y.clone() + z - x;
            if slack.sign() != Some(Sign::Positive) {
                return Err(format!(
                    "face {what} not certified a strict triangle on the whole box"
                ));
            }
        }
    }
    Ok(())
}

/// Step 1 of B71 over the box, across cell boundaries (B35): `lb` are the lengths of `T`
/// over the box `boxed` (`base` unscaled). `Err(reason)` when a hypothesis is not certified.
#[allow(clippy::too_many_lines)] // B35's steps in order: strict faces, U, hypotheses, configurations, hull
pub(crate) fn cell_over_box(
    mesh: &Mesh,
    base: &[I],
    boxed: &[I],
    lb: &[I],
) -> Result<CellOverBox, String> {
    for f in mesh.faces() {
        strict(
            mesh,
            std::iter::once(mesh.face_halfedge(f)),
            |e| &lb[e.idx()],
            &format!("f{}", f.0),
        )?;
    }
    let edges: Vec<Edge> = mesh
        .edges()
        .filter(|&e| {
            QuadEdges::of(mesh, e).is_some_and(|q| {
                !nonnegative(&enclose_p(&q.lengths(lb).map(Clone::clone).to_array()))
            })
        })
        .collect();
    if edges.is_empty() {
        return Ok(CellOverBox {
            laplacian: laplacian_from_halfedge_cotans(mesh, &enclose_halfedge_cotans(mesh, lb)),
            boundary: None,
        });
    }
    // Hypothesis: the quadrilaterals of U are face-disjoint.
    let mut quad_of = vec![NONE; mesh.n_halfedges()];
    for (k, &e) in edges.iter().enumerate() {
        for h in face_of(mesh, e.side(0))
            .into_iter()
            .chain(face_of(mesh, e.side(1)))
        {
            let other = quad_of[h.idx()];
            if other != NONE {
                return Err(format!(
                    "edge e{} not certified Delaunay on the whole box, and it shares a face \
                     with e{}, also not certified (B35 needs the two faces of each such edge \
                     apart from the others')",
                    e.0, edges[other as usize].0
                ));
            }
            quad_of[h.idx()] = k as u32;
        }
    }
    // T_U and the Ptolemy lengths of the flipped edges (the quadrilaterals are disjoint:
    // each flip sees the lengths of T).
    let mut flipped = mesh.clone();
    let mut flipped_base = Vec::with_capacity(edges.len());
    for &e in &edges {
        let Some(q) = QuadEdges::of(mesh, e) else {
            return Err(format!("edge e{e} has no quadrilateral", e = e.0));
        };
        let Some(l) = ptolemy_length_enclosure(q.lengths(base)) else {
            return Err(format!("Ptolemy length of e{} not enclosed", e.0));
        };
        if flipped.flip(e).is_err() {
            return Err(format!("edge e{} does not flip", e.0));
        }
        flipped_base.push(l);
    }
    let mut u_index = vec![NONE; mesh.n_edges()];
    for (k, e) in edges.iter().enumerate() {
        u_index[e.idx()] = k as u32;
    }
    let flipped_box: Vec<I> = edges
        .iter()
        .zip(&flipped_base)
        .map(|(&e, l)| scale(&flipped, e.side(0), l, boxed))
        .collect();
    let lengths = Lengths {
        lb,
        u_index: &u_index,
        flipped_box: &flipped_box,
    };
    let len_u = |e: Edge| lengths.get(e, true);
    // 1. Strict triangles in the flipped configuration too.
    for &e in &edges {
        strict(
            &flipped,
            [e.side(0), e.side(1)].into_iter(),
            len_u,
            &format!("beside the flipped e{}", e.0),
        )?;
    }
    // 2. Every other edge with a face in a U-quadrilateral: Delaunay in every configuration.
    for f in mesh.edges() {
        if u_index[f.idx()] != NONE || QuadEdges::of(mesh, f).is_none() {
            continue;
        }
        let sides = [f.side(0), f.side(1)];
        let marked = sides.map(|h| quad_of[h.idx()] != NONE);
        if !marked[0] && !marked[1] {
            continue;
        }
        for combo in 0..4u8 {
            let cfg = [combo & 1 == 1, combo & 2 == 2];
            if (cfg[0] && !marked[0]) || (cfg[1] && !marked[1]) {
                continue;
            }
            let mut l = vec![lb[f.idx()].clone()];
            for (s, &h) in sides.iter().enumerate() {
                let m = if cfg[s] { &flipped } else { mesh };
                let n1 = m.next(h);
                l.push(lengths.get(n1.edge(), cfg[s]).clone());
                l.push(lengths.get(m.next(n1).edge(), cfg[s]).clone());
            }
            let l: [I; 5] = l.try_into().map_err(|_| "five lengths".to_string())?;
            if !nonnegative(&enclose_p(&l)) {
                let near: Vec<String> = sides
                    .iter()
                    .filter(|h| quad_of[h.idx()] != NONE)
                    .map(|h| format!("e{}", edges[quad_of[h.idx()] as usize].0))
                    .collect();
                return Err(format!(
                    "edge e{} not certified Delaunay on the whole box once {} flip",
                    f.0,
                    near.join(" and ")
                ));
            }
        }
    }
    // The Laplacian: T's, with each U-quadrilateral's block replaced by the hull of the two.
    let mut laplacian = laplacian_from_halfedge_cotans(mesh, &enclose_halfedge_cotans(mesh, lb));
    let mut extra = Vec::new();
    for &e in &edges {
        let mut block: LocalBlock = Vec::new();
        for (c, m) in [mesh, &flipped].into_iter().enumerate() {
            let len = |x: Edge| lengths.get(x, c == 1);
            for h in face_of(m, e.side(0))
                .into_iter()
                .chain(face_of(m, e.side(1)))
            {
                let (i, j) = (m.tail(h).idx(), m.tip(h).idx());
                if i == j {
                    continue;
                }
                let (a, b, d) = (len(h.edge()), len(m.next(h).edge()), len(m.prev(h).edge()));
                let w = cot_opposite(a, b, d) * &a.lit(0.5);
                for (pos, v) in [((i, j), &w), ((j, i), &w)] {
                    add(&mut block, pos, c, v.clone());
                }
                for pos in [(i, i), (j, j)] {
                    add(&mut block, pos, c, -w.clone());
                }
            }
        }
        for ((i, j), [a, b]) in block {
            let zero = || lb[0].zero_like();
            let a = a.unwrap_or_else(zero);
            let b = b.unwrap_or_else(zero);
            let delta = hull(&a, &b) - &a;
            match laplacian.get_mut(i, j) {
                Some(x) => *x += &delta,
                None => extra.push((i, j, delta)),
            }
        }
    }
    if !extra.is_empty() {
        let mut triplets: Vec<(usize, usize, I)> = laplacian
            .entries()
            .map(|(i, j, w)| (i, j, w.clone()))
            .collect();
        triplets.append(&mut extra);
        laplacian = SparseMatrix::from_triplets(mesh.n_vertices(), &triplets);
    }
    Ok(CellOverBox {
        laplacian,
        boundary: Some(Boundary {
            edges,
            flipped,
            flipped_base,
        }),
    })
}

/// The lengths of `T` (`lb`) or of `T_U` (`lb` with the flipped `U`-edges' lengths).
struct Lengths<'a> {
    lb: &'a [I],
    u_index: &'a [u32],
    flipped_box: &'a [I],
}

impl<'a> Lengths<'a> {
    /// The length of `e` in `T_U` (`flipped`) or in `T`.
    fn get(&self, e: Edge, flipped: bool) -> &'a I {
        match self.u_index[e.idx()] {
            k if flipped && k != NONE => &self.flipped_box[k as usize],
            _ => &self.lb[e.idx()],
        }
    }
}

/// A quadrilateral's local Laplacian block: per matrix position, the entry in `T` (0) and
/// in the flipped triangulation (1), absent where the configuration has none (B35).
type LocalBlock = Vec<((usize, usize), [Option<I>; 2])>;

/// Add `v` to the configuration `c` of position `pos` of a local block.
fn add(block: &mut LocalBlock, pos: (usize, usize), c: usize, v: I) {
    let k = if let Some(k) = block.iter().position(|(p, _)| *p == pos) {
        k
    } else {
        block.push((pos, [None, None]));
        block.len() - 1
    };
    let slot = &mut block[k].1[c];
    *slot = Some(match slot.take() {
        None => v,
        Some(x) => x + &v,
    });
}

impl Boundary {
    /// Correct angle sums `theta` computed on `T` with the lengths `lengths` of `T` at `u`
    /// (a point or the box) to enclose the angle sums of the Delaunay triangulation: per
    /// `U`-edge, `T`'s two faces where `P ≥ 0` is certified, the flipped faces where `P < 0`
    /// is, else the hull of both (B35). `Err(reason)` when an angle is not enclosed.
    pub(crate) fn correct_angle_sums(
        &self,
        mesh: &Mesh,
        u: &[I],
        lengths: &[I],
        theta: &mut [I],
    ) -> Result<(), String> {
        for (&e, fb) in self.edges.iter().zip(&self.flipped_base) {
            let Some(q) = QuadEdges::of(mesh, e) else {
                continue;
            };
            let p = enclose_p(&q.lengths(lengths).map(Clone::clone).to_array());
            if nonnegative(&p) {
                continue;
            }
            let new = scale(&self.flipped, e.side(0), fb, u);
            let len_u = |x: Edge| if x == e { &new } else { &lengths[x.idx()] };
            let len_t = |x: Edge| &lengths[x.idx()];
            let a = corner_sums(mesh, e, &len_t);
            let b = corner_sums(&self.flipped, e, &len_u);
            let flip = p.sign() == Some(Sign::Negative);
            let mut verts: Vec<usize> = a.iter().chain(&b).map(|(v, _)| *v).collect();
            verts.sort_unstable();
            verts.dedup();
            for v in verts {
                let get = |s: &[(usize, I)]| {
                    s.iter()
                        .find(|(w, _)| *w == v)
                        .map_or_else(|| lengths[0].zero_like(), |(_, x)| x.clone())
                };
                let (av, bv) = (get(&a), get(&b));
                if !(av.is_valid() && bv.is_valid()) {
                    return Err(format!("angles beside e{} not enclosed", e.0));
                }
                let delta = if flip { bv - &av } else { hull(&av, &bv) - &av };
                theta[v] += &delta;
            }
        }
        Ok(())
    }
}

/// The angles of the two faces of `e` in `m`, summed per vertex.
fn corner_sums<'a>(m: &Mesh, e: Edge, len: &dyn Fn(Edge) -> &'a I) -> Vec<(usize, I)> {
    let mut out: Vec<(usize, I)> = Vec::new();
    for h in face_of(m, e.side(0))
        .into_iter()
        .chain(face_of(m, e.side(1)))
    {
        // The corner opposite h is at the tip of next(h).
        let v = m.tip(m.next(h)).idx();
        let angle = corner_angle(len(h.edge()), len(m.next(h).edge()), len(m.prev(h).edge()));
        match out.iter_mut().find(|(w, _)| *w == v) {
            Some((_, s)) => *s += &angle,
            None => out.push((v, angle)),
        }
    }
    out
}

/// B35's terms (proofs/B35, **Terms**): the hull of a `U`-edge's block must hold the values
/// of both configurations, whichever has the lower or the upper end; the flipped faces must
/// be strict on the box.
#[cfg(test)]
mod terms {
    use super::{cell_over_box, hull, I};
    use crate::mesh::Mesh;
    use crate::scalar::{Mpfr, Precision, Real};
    use crate::uniformization::refine::scaled;

    fn iv(lo: f64, hi: f64) -> I {
        let p = Precision::new(64).expect("precision");
        I::new(Mpfr::from_f64(lo, p), Mpfr::from_f64(hi, p))
    }

    fn ends(x: &I) -> (f64, f64) {
        (x.lo().as_float().to_f64(), x.hi().as_float().to_f64())
    }

    /// B35 term "the entrywise hull of the two configurations": disjoint, overlapping and
    /// nested pairs, in both orders, give the smallest interval holding both.
    #[test]
    fn term_b35_hull_holds_both_configurations() {
        for (a, b, want) in [
            ((0.0, 1.0), (2.0, 3.0), (0.0, 3.0)),
            ((0.0, 2.0), (1.0, 3.0), (0.0, 3.0)),
            ((0.0, 3.0), (1.0, 2.0), (0.0, 3.0)),
            ((-1.0, -0.5), (-2.0, 4.0), (-2.0, 4.0)),
        ] {
            let (x, y) = (iv(a.0, a.1), iv(b.0, b.1));
            assert_eq!(ends(&hull(&x, &y)), want, "{a:?} ∪ {b:?}");
            assert_eq!(ends(&hull(&y, &x)), want, "{b:?} ∪ {a:?}");
        }
    }

    /// The lengths of `mesh`'s edges between the planar `points`, enclosed.
    fn planar_lengths(mesh: &Mesh, points: &[[f64; 2]], prec: Precision) -> Vec<I> {
        mesh.edges()
            .map(|e| {
                let h = e.halfedge();
                let [a, b] = [mesh.tail(h), mesh.tip(h)].map(|v| points[v.idx()]);
                I::from_f64((a[0] - b[0]).hypot(a[1] - b[1]), prec)
            })
            .collect()
    }

    /// [`cell_over_box`] on the box `u ∈ [−r, r]ⱽ` around the lengths `base`.
    fn cell_on(
        mesh: &Mesh,
        base: &[I],
        r: f64,
        prec: Precision,
    ) -> Result<super::CellOverBox, String> {
        let interval = I::new(Mpfr::from_f64(-r, prec), Mpfr::from_f64(r, prec));
        let boxed = vec![interval; mesh.n_vertices()];
        let lb = scaled(mesh, base, &boxed);
        cell_over_box(mesh, base, &boxed, &lb)
    }

    /// B35 condition 2, the flipped faces strict on the box: four points of the unit circle
    /// `i = (−1, 0)`, `k = e^{−iε}`, `j = (1, 0)`, `l = e^{iε}` (`ε = 10⁻²`), the faces `ijk`
    /// and `jil` of `T`. Cocircular, so `P_ij = 0` and `ij ∈ U` on every box. `T`'s faces
    /// have triangle slacks of order `ε`, but the flipped face `klj` is a cap: its slack is
    /// `4 sin(ε/2)(1 − cos(ε/2)) ≈ ε³/8 ≈ 1.25·10⁻⁷` (closed form). On the box `u ∈ [−r, r]⁴`
    /// with `r = 10⁻³` the lengths vary by about `10⁻⁵`, so `klj` is not certified strict:
    /// refused, naming the flipped edge, while every condition on `T` holds; with
    /// `r = 10⁻⁹` it is certified, with `U = {ij}`.
    #[test]
    fn term_b35_flipped_faces_strict_on_the_box() {
        let prec = Precision::new(128).expect("precision");
        let eps = 1e-2f64;
        let points = [
            [-1.0, 0.0],
            [eps.cos(), -eps.sin()],
            [1.0, 0.0],
            [eps.cos(), eps.sin()],
        ];
        let mesh = Mesh::from_faces(4, &[[0, 2, 1], [2, 0, 3]]).expect("two triangles");
        let base = planar_lengths(&mesh, &points, prec);
        let cell = |r: f64| cell_on(&mesh, &base, r, prec);
        let Err(why) = cell(1e-3) else {
            panic!("the cap klj is certified strict on a box of radius 1e-3")
        };
        assert!(why.contains("beside the flipped"), "{why}");
        let Ok(fine) = cell(1e-9) else {
            panic!("radius 1e-9 not certified")
        };
        let boundary = fine.boundary.expect("ij is a tie on every box");
        assert_eq!(boundary.edges.len(), 1);
        // On the box `u ∈ [−10⁻⁹, 10⁻⁹]⁴`, `P_ij` straddles 0: the correction takes the hull
        // of both configurations, which for cocircular points carry the same angle sums
        // (the Ptolemy flip is the Euclidean one), so the corrected sums stay `T`'s.
        let tiny = I::new(Mpfr::from_f64(-1e-9, prec), Mpfr::from_f64(1e-9, prec));
        let zero = vec![tiny; 4];
        let lengths = scaled(&mesh, &base, &zero);
        let theta = crate::geometry::cone_angles::cone_angles(&mesh, &lengths);
        let mut corrected = theta.clone();
        boundary
            .correct_angle_sums(&mesh, &zero, &lengths, &mut corrected)
            .expect("enclosed");
        for (t, c) in theta.iter().zip(&corrected) {
            let ((a, b), (x, y)) = (ends(t), ends(c));
            assert!(
                x <= a + 1e-12 && b - 1e-12 <= y && y - x < 1e-4,
                "{a} {b} → {x} {y}"
            );
        }
    }

    /// B35 condition 3, every edge outside `U` Delaunay in each configuration: `i = (−1, 0)`,
    /// `k = (0, −1)`, `j = (1, 0)` on the unit circle, `l = (0, ¾)` inside it, so the edge
    /// `ij` (faces `ijk`, `jil`) is not Delaunay and in `U`; a third face `kjm` with
    /// `m = s·e^{−iπ/4}` just outside the circle. The edge `kj` sees `i` (angle `π/4`) in
    /// `T` but `l` (a larger angle) once `ij` is flipped. At `s = 1.02` the opposite angles
    /// of `kj` sum to `π − 0.048` in `T` and `π + 0.094` after the flip (values checked
    /// below by `atan2`): refused, naming `kj` and `ij`, although every condition on `T`
    /// holds; at `s = 1.2` (`π − 0.29` after the flip) certified.
    #[test]
    fn term_b35_other_edges_delaunay_in_each_configuration() {
        let prec = Precision::new(128).expect("precision");
        // Both orientations, so that the U-quadrilateral is on either side of `kj`.
        for faces in [
            [[0, 2, 1], [2, 0, 3], [1, 2, 4]],
            [[0, 1, 2], [3, 0, 2], [4, 2, 1]],
        ] {
            let mesh = Mesh::from_faces(5, &faces).expect("three faces");
            other_edges_case(&mesh, prec);
        }
    }

    fn other_edges_case(mesh: &Mesh, prec: Precision) {
        let angle = |p: [f64; 2], a: [f64; 2], b: [f64; 2]| {
            let (v, w) = ([a[0] - p[0], a[1] - p[1]], [b[0] - p[0], b[1] - p[1]]);
            (v[0] * w[1] - v[1] * w[0])
                .atan2(v[0] * w[0] + v[1] * w[1])
                .abs()
        };
        let [i, k, j, l] = [[-1.0, 0.0], [0.0, -1.0], [1.0, 0.0], [0.0, 0.75]];
        let pi = std::f64::consts::PI;
        for (s, refused) in [(1.02, true), (1.2, false)] {
            let m = [s * (pi / 4.0).cos(), -s * (pi / 4.0).sin()];
            let in_t = angle(i, k, j) + angle(m, k, j) - pi;
            let flipped = angle(l, k, j) + angle(m, k, j) - pi;
            assert!(
                in_t < -0.04 && (flipped > 0.09) == refused,
                "{in_t} {flipped}"
            );
            let base = planar_lengths(mesh, &[i, k, j, l, m], prec);
            match cell_on(mesh, &base, 1e-6, prec) {
                Err(why) if refused => assert!(why.contains("once"), "{why}"),
                Ok(cell) if !refused => {
                    assert_eq!(cell.boundary.expect("ij in U").edges.len(), 1);
                }
                Err(why) => panic!("s = {s}: {why}"),
                Ok(_) => panic!("s = {s}: kj not Delaunay after the flip, certified"),
            }
        }
    }

    /// B35's hull and angle-sum correction, against an independent binary64 computation:
    /// on the configuration of [`term_b35_other_edges_delaunay_in_each_configuration`] at
    /// `s = 1.2` (`l` inside the circle of `ijk`, so `ij ∈ U` with `P_ij < 0` at `u = 0`),
    /// the cotan Laplacian of `T` and of `T` with `ij` Ptolemy-flipped (`ℓ_kl =
    /// (ℓ_ki ℓ_lj + ℓ_jk ℓ_il)/ℓ_ij`) are computed in `f64` from the side lengths (law of
    /// cosines). Every entry of both lies in the enclosed Laplacian over the box of radius
    /// `10⁻⁶` (within `10⁻¹²` for the `f64` rounding), and the entries of the two differ
    /// by more than `10⁻³`, so a hull that kept one configuration only would miss the other;
    /// no entry is wider than `1.01` times the two configurations' difference plus `10⁻⁴`.
    /// The angle sums of `T` at `u = 0`, corrected, enclose the flipped configuration's
    /// (`P < 0` is certified there), which differ from `T`'s by more than `10⁻³`.
    #[test]
    #[allow(clippy::too_many_lines)] // two configurations computed independently, then compared
    fn term_b35_hull_and_corrected_angle_sums_hold_both_configurations() {
        let prec = Precision::new(128).expect("precision");
        let mesh = Mesh::from_faces(5, &[[0, 2, 1], [2, 0, 3], [1, 2, 4]]).expect("three faces");
        let s = 1.2f64;
        let pi = std::f64::consts::PI;
        let m = [s * (pi / 4.0).cos(), -s * (pi / 4.0).sin()];
        let points = [[-1.0, 0.0], [0.0, -1.0], [1.0, 0.0], [0.0, 0.75], m];
        let base = planar_lengths(&mesh, &points, prec);
        let cell = cell_on(&mesh, &base, 1e-6, prec).expect("certified");
        let boundary = cell.boundary.as_ref().expect("ij in U");
        let d = |a: usize, b: usize| {
            let (p, q) = (points[a], points[b]);
            (p[0] - q[0]).hypot(p[1] - q[1])
        };
        // i = 0, k = 1, j = 2, l = 3, m = 4.
        let kl = (d(1, 0) * d(3, 2) + d(2, 1) * d(0, 3)) / d(0, 2);
        let len = |a: usize, b: usize| {
            if (a, b) == (1, 3) || (a, b) == (3, 1) {
                kl
            } else {
                d(a, b)
            }
        };
        // Faces of T and of T with ij flipped (to kl), counterclockwise as the mesh's.
        let t_faces = [[0, 2, 1], [2, 0, 3], [1, 2, 4]];
        let f_faces = [[1, 3, 2], [3, 1, 0], [1, 2, 4]];
        let laplacian = |faces: &[[usize; 3]]| {
            let mut l = [[0.0f64; 5]; 5];
            for f in faces {
                for c in 0..3 {
                    // The corner at f[c], opposite the side f[c+1] f[c+2].
                    let (o, a, b) = (f[c], f[(c + 1) % 3], f[(c + 2) % 3]);
                    let (x, y, z) = (len(a, b), len(o, a), len(o, b));
                    let area4 = ((x + y + z) * (-x + y + z) * (x - y + z) * (x + y - z)).sqrt();
                    let w = 0.5 * (y * y + z * z - x * x) / area4;
                    l[a][b] += w;
                    l[b][a] += w;
                    l[a][a] -= w;
                    l[b][b] -= w;
                }
            }
            l
        };
        let (lt, lf) = (laplacian(&t_faces), laplacian(&f_faces));
        let mut spread = 0.0f64;
        for i in 0..5 {
            for j in 0..5 {
                let enclosed = cell.laplacian.get(i, j);
                for (which, want) in [("T", lt[i][j]), ("flipped", lf[i][j])] {
                    let ok = match enclosed {
                        Some(e) => {
                            let (lo, hi) = ends(e);
                            lo - 1e-12 <= want && want <= hi + 1e-12
                        }
                        None => want.abs() < 1e-12,
                    };
                    assert!(
                        ok,
                        "L[{i}][{j}] of {which} = {want} not in {:?}",
                        enclosed.map(ends)
                    );
                }
                // And not much wider than the two configurations need (the box of radius 10⁻⁶ adds
                // about 10⁻⁴ here): a block assembled with the wrong weight scale would be.
                if let Some(e) = enclosed {
                    let (lo, hi) = ends(e);
                    let need = 1.01 * (lt[i][j] - lf[i][j]).abs() + 1e-4;
                    assert!(
                        hi - lo <= need,
                        "L[{i}][{j}] enclosed in [{lo}, {hi}], T {} flipped {}",
                        lt[i][j],
                        lf[i][j]
                    );
                }
                spread = spread.max((lt[i][j] - lf[i][j]).abs());
            }
        }
        assert!(
            spread > 1e-3,
            "the configurations' Laplacians agree ({spread:e})"
        );
        // Angle sums at u = 0: T's, corrected to the flipped configuration's.
        let zero = vec![I::new(Mpfr::from_f64(0.0, prec), Mpfr::from_f64(0.0, prec)); 5];
        let lengths = scaled(&mesh, &base, &zero);
        let mut theta = crate::geometry::cone_angles::cone_angles(&mesh, &lengths);
        let before: Vec<f64> = theta
            .iter()
            .map(|t| 0.5 * (ends(t).0 + ends(t).1))
            .collect();
        boundary
            .correct_angle_sums(&mesh, &zero, &lengths, &mut theta)
            .expect("enclosed");
        let sums = |faces: &[[usize; 3]]| {
            let mut out = [0.0f64; 5];
            for f in faces {
                for c in 0..3 {
                    let (o, a, b) = (f[c], f[(c + 1) % 3], f[(c + 2) % 3]);
                    let (x, y, z) = (len(a, b), len(o, a), len(o, b));
                    out[o] += ((y * y + z * z - x * x) / (2.0 * y * z)).acos();
                }
            }
            out
        };
        let want = sums(&f_faces);
        let mut moved = 0.0f64;
        for v in 0..5 {
            let (lo, hi) = ends(&theta[v]);
            assert!(
                lo - 1e-12 <= want[v] && want[v] <= hi + 1e-12,
                "θ[{v}] = {want:?}"
            );
            // `P < 0` is certified at this point: the flipped sums alone, not a hull.
            assert!(hi - lo < 1e-9, "θ[{v}] enclosed in [{lo}, {hi}]");
            moved = moved.max((want[v] - before[v]).abs());
        }
        assert!(moved > 1e-3, "the correction moved nothing ({moved:e})");
    }

    /// B35 condition 3 with both faces of an edge in `U`-quadrilaterals: faces `ijk`, `jil`,
    /// `kjm`, `kmn` (`U = {ij, km}`, both certified non-Delaunay), the edge `kj` between
    /// them. Its opposite angles sum (in `f64` from the side lengths, the flipped diagonals
    /// by Ptolemy) to less than `π` in `T`, with `ij` flipped and with `km` flipped, and to
    /// more than `π` with both flipped: refused, naming both `U`-edges; a configuration
    /// where all four are Delaunay is certified.
    #[test]
    fn term_b35_edge_between_two_u_quadrilaterals_in_every_configuration() {
        let prec = Precision::new(128).expect("precision");
        // i = 0, k = 1, j = 2, l = 3, m = 4, n = 5.
        let mesh =
            Mesh::from_faces(6, &[[0, 2, 1], [2, 0, 3], [1, 2, 4], [1, 4, 5]]).expect("four faces");
        let margins = |p: &[[f64; 2]; 6]| {
            let d = |a: usize, b: usize| (p[a][0] - p[b][0]).hypot(p[a][1] - p[b][1]);
            let ang = |a: f64, b: f64, c: f64| ((b * b + c * c - a * a) / (2.0 * b * c)).acos();
            let kl = (d(1, 0) * d(3, 2) + d(2, 1) * d(0, 3)) / d(0, 2);
            let jn = (d(1, 2) * d(4, 5) + d(2, 4) * d(5, 1)) / d(1, 4);
            let kj = d(1, 2);
            let a_i = ang(kj, d(1, 0), d(0, 2));
            let a_m = ang(kj, d(1, 4), d(2, 4));
            let a_l = ang(kj, kl, d(3, 2));
            let a_n = ang(kj, jn, d(5, 1));
            let pi = std::f64::consts::PI;
            [
                pi - a_i - a_m,
                pi - a_l - a_m,
                pi - a_i - a_n,
                pi - a_l - a_n,
            ]
        };
        let refused = [
            [-0.531_456_216_594_192_1, 0.980_545_145_760_812_5],
            [-1.0, 0.0],
            [1.0, 0.0],
            [0.301_113_849_539_826, 0.490_856_420_835_652_4],
            [0.796_570_003_362_112_4, -1.179_466_778_087_866],
            [0.091_477_002_218_052_66, -1.137_808_384_824_202],
        ];
        let certified = [
            [0.009_440_934_857_726_68, 1.366_835_246_901_015_2],
            [-1.0, 0.0],
            [1.0, 0.0],
            [0.427_159_858_179_822_8, 0.930_587_005_643_571_7],
            [0.076_957_591_475_688_59, -1.671_676_796_154_511_4],
            [-0.550_190_140_869_097_5, -1.199_552_320_239_338_6],
        ];
        let c = margins(&refused);
        assert!(c[..3].iter().all(|&x| x > 0.05) && c[3] < -0.05, "{c:?}");
        assert!(margins(&certified).iter().all(|&x| x > 0.05));
        let base = planar_lengths(&mesh, &refused, prec);
        match cell_on(&mesh, &base, 1e-6, prec) {
            Err(why) => assert!(why.contains("once") && why.contains(" and "), "{why}"),
            Ok(_) => panic!("kj is not Delaunay once both ij and km flip"),
        }
        let base = planar_lengths(&mesh, &certified, prec);
        let cell = cell_on(&mesh, &base, 1e-6, prec).expect("every configuration Delaunay");
        assert_eq!(cell.boundary.expect("U = {ij, km}").edges.len(), 2);
    }
}
