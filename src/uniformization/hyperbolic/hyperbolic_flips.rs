//! Flips for the hyperbolic target (notes Thm 11; Gu–Guo–Luo–Sun–Wu 2018; proofs/B87,
//! B89, B104).
//!
//! **λ-lengths.** With `λ = 2 sinh(ℓ/2)` the scaling of Thm 11 is `λ̃_ij = e^{(u_i+u_j)/2}λ_ij`
//! and a flip of edge `e = ij` between faces `ijk`, `jil` (quadrilateral `j k i l`, opposite
//! side pairs `jk, il` and `ki, lj`) is the hyperbolic Ptolemy relation
//! `λ_e λ_f = λ_jk λ_il + λ_ki λ_lj`. The code carries the logarithmic lengths
//! `x = 2 log sinh(ℓ/2) = 2 log(λ/2)` (T33's convention), in which the relation reads
//! `x_f = 2 log(e^{(x_jk + x_il)/2} + e^{(x_ki + x_lj)/2}) − x_e` ([`ptolemy_log`]) and the
//! scaling `x̃_ij = x_ij + u_i + u_j`: flips commute with scaling (B87 step 1), so the solver
//! and the certificate carry *base* lengths (at `u = 0`) through the flips.
//!
//! **Hyperbolic Delaunay (Leibon).** Edge `e` with angles `α, α′` opposite it in its two
//! faces and `β, γ`, `β′, γ′` the other corners is Delaunay when the Leibon sum
//! `(β + γ − α) + (β′ + γ′ − α′) ≥ 0` ([`leibon_sum`]). The solver decides it in binary64
//! (a heuristic, never a verdict); the certificate encloses it over a box
//! ([`delaunay_on_box`], B89).
//!
//! **Geometric flips of the input** ([`geometric_to_delaunay`], B104): the other diagonal
//! of the developed quadrilateral by the hyperbolic law of cosines at `i` in the stable form
//! `sinh²(ℓ_kl/2) = sinh²((a − b)/2) + sinh a sinh b sin²(θ_i/2)` (`a = ℓ_ki`, `b = ℓ_il`,
//! `θ_i` the angle of the quadrilateral at `i`), admitted only where the quadrilateral is
//! convex at `i` and `j` (binary64, numerical: the result is a new binary64 metric whose
//! claims are about it, as the Euclidean `uniformization` claim).

use super::hyperbolic_kernel::{face_terms, length_from_log as length_from_log_f64, log_length};
use crate::mesh::{Edge, FlipError, HalfEdge, Mesh};
use crate::scalar::{Interval, Mpfr, Real};
use crate::variational::hyperbolic::{angles_half_angle, length_from_log};
use std::collections::VecDeque;
use std::f64::consts::PI;

/// The binary64 solver flips an edge when its Leibon sum is below `−FLIP_SLACK` (a
/// heuristic threshold that keeps near-ties from cycling under rounding; the certificate
/// decides Delaunay on enclosures, B89). proof: B87
pub const FLIP_SLACK: f64 = 1e-12;

/// At most `FLIP_CAP_PER_EDGE · E` flips in one flip-to-Delaunay pass (a safety stop; the
/// passes terminate, B104). proof: B104
pub const FLIP_CAP_PER_EDGE: usize = 200;

/// The quadrilateral around edge `e = ij` (`h = 2e: i→j` in face `ijk`, `t = 2e+1: j→i` in
/// face `jil`): the half-edges `[jk, ki, il, lj]`; `None` for a boundary edge or one with
/// the same face on both sides.
pub fn quad(mesh: &Mesh, e: Edge) -> Option<[HalfEdge; 4]> {
    let (h, t) = (e.side(0), e.side(1));
    let (fa, fb) = (mesh.face(h)?, mesh.face(t)?);
    if fa == fb {
        return None;
    }
    let h_jk = mesh.next(h);
    let h_ki = mesh.next(h_jk);
    let t_il = mesh.next(t);
    let t_lj = mesh.next(t_il);
    Some([h_jk, h_ki, t_il, t_lj])
}

/// The hyperbolic Ptolemy relation in logarithmic lengths (module doc, B87):
/// `x_f = 2 log(e^{(x_jk + x_il)/2} + e^{(x_ki + x_lj)/2}) − x_e`, over any [`Real`]
/// (on enclosures: an enclosure of the exact value, B20).
pub fn ptolemy_log<T: Real>(x_e: &T, [jk, ki, il, lj]: [&T; 4]) -> T {
    let half = x_e.lit(0.5);
    let p = ((jk.clone() + il) * &half).exp();
    let q = ((ki.clone() + lj) * &half).exp();
    (p + &q).ln() * &x_e.lit(2.0) - x_e
}

/// [`ptolemy_log`] in binary64 without overflow (`log(eᵃ + eᵇ) = max + log1p(e^{−|a−b|})`).
pub fn ptolemy_log_f64(x_e: f64, [jk, ki, il, lj]: [f64; 4]) -> f64 {
    let (a, b) = (0.5 * (jk + il), 0.5 * (ki + lj));
    let (hi, lo) = if a >= b { (a, b) } else { (b, a) };
    2.0 * (hi + (lo - hi).exp().ln_1p()) - x_e
}

/// Why a flip sequence could not be replayed: the position in the sequence and the reason.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("flips[{position}]: {reason}")]
pub struct ReplayError {
    /// Position in the sequence.
    pub position: usize,
    /// The combinatorial refusal.
    pub reason: FlipError,
}

/// Replay Ptolemy flips on base logarithmic lengths `base` of `t0` (module doc): the final
/// triangulation and its base lengths, over any [`Real`] (enclosures replay to enclosures of
/// the exact formal lengths, B89). proof: B87, B89
pub fn replay_ptolemy<T: Real>(
    t0: &Mesh,
    base: &[T],
    flips: &[Edge],
) -> Result<(Mesh, Vec<T>), ReplayError> {
    let mut mesh = t0.clone();
    let mut x = base.to_vec();
    for (position, &e) in flips.iter().enumerate() {
        let Some(q) = quad(&mesh, e) else {
            let reason = match mesh.flip(e) {
                Err(r) => r,
                Ok(()) => FlipError::SameFace(e),
            };
            return Err(ReplayError { position, reason });
        };
        let s = q.map(|h| &x[h.edge().idx()]);
        let new = ptolemy_log(&x[e.idx()], s);
        mesh.flip(e)
            .map_err(|reason| ReplayError { position, reason })?;
        x[e.idx()] = new;
    }
    Ok((mesh, x))
}

/// The index of half-edge `h` in its face's [`Mesh::face_halfedges`].
fn slot(mesh: &Mesh, h: HalfEdge) -> Option<usize> {
    let f = mesh.face(h)?;
    mesh.face_halfedges(f).iter().position(|&g| g == h)
}

/// The binary64 corner angles of the face of `h` (opposite its sides in
/// [`Mesh::face_halfedges`] order) from logarithmic lengths `x(edge)`; `Err(face)` when it
/// is not a strict triangle.
fn face_angles(mesh: &Mesh, h: HalfEdge, x: &dyn Fn(Edge) -> f64) -> Result<[f64; 3], u32> {
    let f = mesh.face(h).ok_or(u32::MAX)?;
    let lam = mesh.face_halfedges(f).map(|g| x(g.edge()));
    face_terms(lam).map(|t| t.angles).ok_or(f.0)
}

/// The Leibon sum `(β + γ − α) + (β′ + γ′ − α′)` of edge `e` (module doc) in binary64 from
/// logarithmic lengths; `Err(face)` when an adjacent face is not a strict triangle.
pub fn leibon_sum(mesh: &Mesh, e: Edge, x: &dyn Fn(Edge) -> f64) -> Result<f64, u32> {
    let mut sum = 0.0;
    for h in [e.side(0), e.side(1)] {
        let a = face_angles(mesh, h, x)?;
        let m = slot(mesh, h).ok_or(u32::MAX)?;
        sum += a[(m + 1) % 3] + a[(m + 2) % 3] - a[m];
    }
    Ok(sum)
}

/// Why a flip-to-Delaunay pass stopped short.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum FlipFault {
    /// A face met is not a strict hyperbolic triangle.
    #[error("face f{0} is not a strict hyperbolic triangle")]
    NotATriangle(u32),
    /// A non-Delaunay edge cannot be flipped (same face on both sides).
    #[error("edge e{0} is not Delaunay and has the same face on both sides")]
    Unflippable(u32),
    /// A quadrilateral to flip geometrically is not convex.
    #[error("edge e{0} is not Delaunay but its quadrilateral is not convex")]
    NotConvex(u32),
    /// More than `FLIP_CAP_PER_EDGE · E` flips.
    #[error("more than {0} flips")]
    Cap(usize),
}

/// Flip `mesh` to hyperbolic Delaunay at the scale factors `u` by Ptolemy flips of the base
/// logarithmic lengths `base` (module doc; an edge flips when its Leibon sum at `u` is below
/// `−FLIP_SLACK`), appending each flipped edge to `flips`. Returns the number of flips.
/// proof: B87
pub fn ptolemy_to_delaunay(
    mesh: &mut Mesh,
    base: &mut [f64],
    u: &[f64],
    flips: &mut Vec<Edge>,
) -> Result<usize, FlipFault> {
    run_flips(
        mesh,
        base,
        flips,
        |mesh, x, e| {
            let q = quad(mesh, e).ok_or(FlipFault::Unflippable(e.0))?;
            let s = q.map(|h| x[h.edge().idx()]);
            Ok(ptolemy_log_f64(x[e.idx()], s))
        },
        |mesh, x, e| {
            let scaled = |g: Edge| {
                let h = g.halfedge();
                x[g.idx()] + u[mesh.tail(h).idx()] + u[mesh.tip(h).idx()]
            };
            leibon_sum(mesh, e, &scaled).map_err(FlipFault::NotATriangle)
        },
    )
}

/// The flip loop shared by the Ptolemy and the geometric passes: a queue of edges, each
/// checked by `leibon` and, below `−FLIP_SLACK`, replaced by `new_x` and flipped.
fn run_flips(
    mesh: &mut Mesh,
    x: &mut [f64],
    flips: &mut Vec<Edge>,
    new_x: impl Fn(&Mesh, &[f64], Edge) -> Result<f64, FlipFault>,
    leibon: impl Fn(&Mesh, &[f64], Edge) -> Result<f64, FlipFault>,
) -> Result<usize, FlipFault> {
    let cap = FLIP_CAP_PER_EDGE * mesh.n_edges();
    let mut queue: VecDeque<Edge> = mesh.edges().collect();
    let mut queued = vec![true; mesh.n_edges()];
    let mut count = 0;
    while let Some(e) = queue.pop_front() {
        queued[e.idx()] = false;
        if leibon(mesh, x, e)? >= -FLIP_SLACK {
            continue;
        }
        if count >= cap {
            return Err(FlipFault::Cap(cap));
        }
        let q = quad(mesh, e).ok_or(FlipFault::Unflippable(e.0))?;
        let v = new_x(mesh, x, e)?;
        if !v.is_finite() {
            return Err(FlipFault::NotATriangle(
                mesh.face(e.side(0)).map_or(u32::MAX, |f| f.0),
            ));
        }
        mesh.flip(e).map_err(|_| FlipFault::Unflippable(e.0))?;
        x[e.idx()] = v;
        flips.push(e);
        count += 1;
        for h in q {
            let g = h.edge();
            if !queued[g.idx()] {
                queued[g.idx()] = true;
                queue.push_back(g);
            }
        }
    }
    Ok(count)
}

/// Flip the input `(mesh, lengths)` (hyperbolic lengths) to hyperbolic Delaunay by
/// geometric flips (module doc, B104): the new triangulation, its binary64 hyperbolic
/// lengths (an edge never flipped keeps its input length bit for bit) and the flips made.
pub fn geometric_to_delaunay(
    mesh: &Mesh,
    lengths: &[f64],
) -> Result<(Mesh, Vec<f64>, Vec<Edge>), FlipFault> {
    let mut m = mesh.clone();
    let mut x: Vec<f64> = lengths.iter().map(|&l| log_length(l)).collect();
    let mut flips = Vec::new();
    run_flips(
        &mut m,
        &mut x,
        &mut flips,
        other_diagonal_log,
        |mesh, x, e| leibon_sum(mesh, e, &|g| x[g.idx()]).map_err(FlipFault::NotATriangle),
    )?;
    let mut flipped = vec![false; m.n_edges()];
    for e in &flips {
        flipped[e.idx()] = true;
    }
    let out = lengths
        .iter()
        .zip(&x)
        .zip(&flipped)
        .map(|((&l, &xe), &f)| if f { length_from_log_f64(xe) } else { l })
        .collect();
    Ok((m, out, flips))
}

/// The logarithmic length of the other diagonal `kl` of edge `e`'s quadrilateral in the
/// metric (module doc, B104); `NotConvex` unless the angles at `i` and `j` are below `π`.
fn other_diagonal_log(mesh: &Mesh, x: &[f64], e: Edge) -> Result<f64, FlipFault> {
    let [h_jk, h_ki, t_il, t_lj] = quad(mesh, e).ok_or(FlipFault::Unflippable(e.0))?;
    let xf = |g: Edge| x[g.idx()];
    let (h, t) = (e.side(0), e.side(1));
    let a_face = face_angles(mesh, h, &xf).map_err(FlipFault::NotATriangle)?;
    let b_face = face_angles(mesh, t, &xf).map_err(FlipFault::NotATriangle)?;
    let at = |h: HalfEdge, a: &[f64; 3]| slot(mesh, h).map_or(f64::NAN, |m| a[m]);
    // The corner at i is opposite jk (face A) and lj (face B); at j opposite ki and il.
    let theta_i = at(h_jk, &a_face) + at(t_lj, &b_face);
    let theta_j = at(h_ki, &a_face) + at(t_il, &b_face);
    if !(theta_i < PI && theta_j < PI) {
        return Err(FlipFault::NotConvex(e.0));
    }
    let a = length_from_log_f64(x[h_ki.edge().idx()]);
    let b = length_from_log_f64(x[t_il.edge().idx()]);
    let s = (0.5 * (a - b)).sinh();
    let w = (0.5 * theta_i).sin();
    let sinh2 = s * s + a.sinh() * b.sinh() * w * w;
    Ok(sinh2.ln())
}

type I = Interval<Mpfr>;

/// Every edge of `mesh` hyperbolic Delaunay for every scale factor in the box `boxed`:
/// the Leibon sum (module doc) enclosed over the box from the base logarithmic lengths
/// `base` (enclosures) has a lower end `≥ 0` (inclusion property, B20). `Err` names the
/// first edge not certified. proof: B89
pub fn delaunay_on_box(mesh: &Mesh, base: &[I], boxed: &[I]) -> Result<(), String> {
    let l: Vec<I> = mesh
        .edges()
        .map(|e| {
            let h = e.halfedge();
            length_from_log(
                &(base[e.idx()].clone() + &boxed[mesh.tail(h).idx()] + &boxed[mesh.tip(h).idx()]),
            )
        })
        .collect();
    let angles: Vec<[I; 3]> = mesh
        .faces()
        .map(|f| angles_half_angle(&mesh.face_halfedges(f).map(|h| l[h.edge().idx()].clone())))
        .collect();
    for e in mesh.edges() {
        let mut sum: Option<I> = None;
        for h in [e.side(0), e.side(1)] {
            let (Some(f), Some(m)) = (mesh.face(h), slot(mesh, h)) else {
                return Err(format!("edge e{} is a boundary edge", e.0));
            };
            let a = &angles[f.idx()];
            let term = a[(m + 1) % 3].clone() + &a[(m + 2) % 3] - &a[m];
            sum = Some(match sum {
                None => term,
                Some(s) => s + &term,
            });
        }
        let ok = sum.is_some_and(|s| s.is_valid() && *s.lo().as_float() >= 0);
        if !ok {
            return Err(format!(
                "edge e{} not certified hyperbolic Delaunay on the box",
                e.0
            ));
        }
    }
    Ok(())
}

/// The geometric flips `flips` of the input (B104) replayed on enclosures `x` of its
/// logarithmic lengths `2 log sinh(ℓ/2)` (the input's exact metric): each flip admitted
/// only when both faces are certified strict triangles and the quadrilateral certified
/// convex at both ends of the diagonal (`θ_i, θ_j < π`, half-angle form on intervals), the
/// new diagonal's `x_kl = log(sinh²((a − b)/2) + sinh a sinh b sin²(θ_i/2))` enclosed
/// (B20). The triangulation reached and its enclosures, or the first flip refused.
/// proof: B104, B73
pub fn replay_geometric_enclosed(
    mesh: &Mesh,
    mut x: Vec<I>,
    flips: &[Edge],
) -> Result<(Mesh, Vec<I>), String> {
    use crate::scalar::Sign;
    use crate::variational::hyperbolic::sinh;
    let positive = |v: &I| v.is_valid() && v.sign() == Some(Sign::Positive);
    let mut m = mesh.clone();
    for (n, &e) in flips.iter().enumerate() {
        let refused = |why: &str| format!("flip {n} of the input (edge e{}): {why}", e.0);
        let [h_jk, h_ki, t_il, t_lj] = quad(&m, e).ok_or_else(|| refused("no quadrilateral"))?;
        let mut angles = Vec::with_capacity(2);
        for h in [e.side(0), e.side(1)] {
            let f = m.face(h).ok_or_else(|| refused("a boundary edge"))?;
            let l = m
                .face_halfedges(f)
                .map(|g| length_from_log(&x[g.edge().idx()]));
            let half = l[0].lit(0.5);
            for k in 0..3 {
                let slack = (l[(k + 1) % 3].clone() + &l[(k + 2) % 3] - &l[k]) * &half;
                if !positive(&slack) {
                    return Err(refused("a face not certified a strict triangle"));
                }
            }
            angles.push(angles_half_angle(&l));
        }
        let at = |h: HalfEdge, a: &[I; 3]| slot(&m, h).map(|k| a[k].clone());
        let (Some(i_a), Some(i_b), Some(j_a), Some(j_b)) = (
            at(h_jk, &angles[0]),
            at(t_lj, &angles[1]),
            at(h_ki, &angles[0]),
            at(t_il, &angles[1]),
        ) else {
            return Err(refused("a corner outside its face"));
        };
        let pi = I::pi(x[0].ctx());
        let theta_i = i_a + &i_b;
        let theta_j = j_a + &j_b;
        if !positive(&(pi.clone() - &theta_i)) || !positive(&(pi - &theta_j)) {
            return Err(refused("not certified convex at both ends of the diagonal"));
        }
        let a = length_from_log(&x[h_ki.edge().idx()]);
        let b = length_from_log(&x[t_il.edge().idx()]);
        let half = a.lit(0.5);
        let s = sinh(&((a.clone() - &b) * &half));
        let w = (theta_i * &half).sin();
        let sinh2 = s.clone() * &s + &(sinh(&a) * &sinh(&b) * &w * &w);
        if !positive(&sinh2) {
            return Err(refused("the new diagonal's length not enclosed"));
        }
        m.flip(e).map_err(|err| refused(&err.to_string()))?;
        x[e.idx()] = sinh2.ln();
    }
    Ok((m, x))
}
