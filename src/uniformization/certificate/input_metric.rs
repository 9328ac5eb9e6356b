//! The exact input metric on `T₀`: the `f64` solve flips the binary64 rounding of the input
//! lengths to the intrinsic Delaunay triangulation `T₀`; a certificate about the *input*
//! (rational lengths, or square roots of rational squared lengths) needs the input's own
//! lengths on `T₀`. They are obtained by replaying the same Euclidean flips in MPFR (for
//! the refinement) and in `Interval<Mpfr>` (for the certificate). proof: B73
//!
//! A Euclidean flip keeps the cone metric (T23) when the flipped edge's quadrilateral is
//! strictly convex; each replayed flip is therefore admitted only when, on the enclosed
//! input metric, the two corner angles at each end of the edge are certified to sum to
//! less than `π` ([`strictly_convex`]).

use super::certificate::{T0Metric, I};
use super::newton::Uniformization;
use crate::algorithms::flip_to_delaunay::{flip_to_delaunay, FlipKind, FlipOptions};
use crate::algorithms::flips::flip_euclidean;
use crate::geometry::exact3d::{opposite_in_plane, squared_distance};
use crate::io::Surface;
use crate::mesh::{Edge, Mesh};
use crate::predicates::delaunay::{delaunay_sign_squared, enclose_p, Quad, QuadEdges};
use crate::scalar::{Interval, Mpfr, Real, Sign};
use rug::Rational;

/// The input metric on `sol`'s `T₀`: `mesh` and `lengths` are what [`super::uniformize`]
/// was given (binary64), `values` the input lengths in MPFR and `enclosures` enclosures of
/// the exact input lengths, all on `mesh`. `Err(reason)` when the Euclidean flips to `T₀`
/// cannot be replayed on the enclosed input metric with certified convex quadrilaterals.
pub fn input_on_t0(
    sol: &Uniformization,
    mesh: &Mesh,
    lengths: &[f64],
    mut values: Vec<Mpfr>,
    enclosures: Vec<Interval<Mpfr>>,
) -> Result<T0Metric, String> {
    if values.len() != mesh.n_edges() || enclosures.len() != mesh.n_edges() {
        return Err("one input length per edge is required".into());
    }
    // The Euclidean flips of the solve, recorded: the same deterministic run.
    let mut m = mesh.clone();
    let mut l = lengths.to_vec();
    let opts = FlipOptions {
        record: true,
        ..FlipOptions::default()
    };
    let rep =
        flip_to_delaunay(&mut m, &mut l, FlipKind::Euclidean, &opts).map_err(|e| e.to_string())?;
    if m.face_list() != sol.initial_mesh.face_list() {
        return Err("the Euclidean flips do not reproduce the solve's T₀".into());
    }
    let (_, enclosures) = replay_enclosed(mesh, enclosures, &rep.sequence)?;
    let mut mv = mesh.clone();
    for &e in &rep.sequence {
        flip_euclidean(&mut mv, &mut values, e).map_err(|err| err.to_string())?;
    }
    Ok(T0Metric {
        values,
        enclosures,
        euclidean: rep.sequence,
    })
}

/// Replay the Euclidean flips `sequence` on `mesh` with the enclosed lengths
/// `enclosures`, admitting each flip only when its quadrilateral is [`strictly_convex`]
/// on the enclosures (B73 (a)): the result encloses the exact lengths, on the flipped
/// triangulation, of every metric in `enclosures`. `Err(reason)` names the first flip
/// not admitted. proof: B73
pub fn replay_enclosed(
    mesh: &Mesh,
    mut enclosures: Vec<Interval<Mpfr>>,
    sequence: &[Edge],
) -> Result<(Mesh, Vec<Interval<Mpfr>>), String> {
    let mut mi = mesh.clone();
    for (k, &e) in sequence.iter().enumerate() {
        let Some(q) = (e.idx() < mi.n_edges())
            .then(|| QuadEdges::of(&mi, e))
            .flatten()
        else {
            return Err(format!(
                "Euclidean flip {k} (e{}) has no quadrilateral",
                e.0
            ));
        };
        if !strictly_convex(&q.lengths(&enclosures).map(Clone::clone)) {
            return Err(format!(
                "Euclidean flip {k} (e{}): its quadrilateral is not certified strictly convex for the exact input lengths",
                e.0
            ));
        }
        flip_euclidean(&mut mi, &mut enclosures, e).map_err(|err| err.to_string())?;
    }
    Ok((mi, enclosures))
}

/// Whether the quadrilateral `[ij, jk, ki, il, lj]` (faces `ijk`, `jil`) is certified
/// strictly convex at both ends of its diagonal: `∠kij + ∠jil < π` and `∠ijk + ∠lji < π`.
/// For corner angles `α, β ∈ (0, π)`, `α + β < π ⟺ cot α + cot β > 0` (`cot` decreases on
/// `(0, π)` and `cot(π − β) = −cot β`); with `cot α = (b² + c² − a²)/(4A)` this is
/// `x₁·4A₂ + x₂·4A₁ > 0` for `x` the numerators and `4A = √(16A²)` from the squared
/// sides, both areas certified positive (each face a strict triangle). No arc tangent:
/// the test costs a few products and two square roots per quadrilateral. proof: B73
pub fn strictly_convex(q: &Quad<Interval<Mpfr>>) -> bool {
    let sq = |x: &Interval<Mpfr>| x.clone() * x;
    let [ij, jk, ki, il, lj] = [&q.ij, &q.jk, &q.ki, &q.il, &q.lj].map(sq);
    let four_area = |a: &Interval<Mpfr>, b: &Interval<Mpfr>, c: &Interval<Mpfr>| {
        // 16A² = 2a²b² + 2b²c² + 2c²a² − a⁴ − b⁴ − c⁴ (a, b, c squared sides).
        let two = a.lit(2.0);
        let p = (a.clone() * b + &(b.clone() * c) + &(c.clone() * a)) * &two
            - &(a.clone() * a)
            - &(b.clone() * b)
            - &(c.clone() * c);
        (p.is_valid() && p.sign() == Some(Sign::Positive)).then(|| p.sqrt())
    };
    let (Some(a1), Some(a2)) = (four_area(&ij, &jk, &ki), four_area(&ij, &il, &lj)) else {
        return false;
    };
    // At i: ∠kij opposite jk in ijk, ∠jil opposite lj in jil; at j: ∠ijk opposite ki,
    // ∠lji opposite il.
    let at_i = (ki.clone() + &ij - &jk) * &a2 + &((il.clone() + &ij - &lj) * &a1);
    let at_j = (jk.clone() + &ij - &ki) * &a2 + &((lj.clone() + &ij - &il) * &a1);
    [at_i, at_j]
        .iter()
        .all(|x| x.is_valid() && x.sign() == Some(Sign::Positive))
}

/// The exact squared lengths of `T₀` where they are known, one entry per edge: the input's
/// own (`ℓ²` of its lengths, or of its positions) on edges no flip of `sequence` changed,
/// and, for inputs with positions, `|p_k − p_l|²` on an edge flipped across a flat hinge:
/// `k`, `l` coplanar with `ij` and on opposite sides of it (decided exactly,
/// [`opposite_in_plane`]), and both triangles straight (all five edges still have their
/// 3-D lengths). The flip's quadrilateral is strictly convex (admitted by
/// [`replay_enclosed`]), so the new diagonal is the straight segment `kl` of that plane. `None` on other flipped edges (their lengths are only enclosed).
pub(crate) fn exact_squared_on_t0(surface: &Surface, sequence: &[Edge]) -> Vec<Option<Rational>> {
    let mut mesh = surface.mesh.clone();
    let mut sq: Vec<Option<Rational>> = surface.metric.squared().into_iter().map(Some).collect();
    for &e in sequence {
        let Some(q) = QuadEdges::of(&mesh, e) else {
            return vec![None; sq.len()];
        };
        let h = e.side(0);
        let t = e.side(1);
        let (i, j) = (mesh.tail(h).idx(), mesh.tip(h).idx());
        let (k, l) = (mesh.tip(mesh.next(h)).idx(), mesh.tip(mesh.next(t)).idx());
        let straight = q.edges.to_array().iter().all(|x| sq[x.idx()].is_some());
        let new = match &surface.positions {
            Some(p) if straight && opposite_in_plane(&p[i], &p[j], &p[k], &p[l]) => {
                Some(squared_distance(&p[k], &p[l]))
            }
            _ => None,
        };
        if mesh.flip(e).is_err() {
            return vec![None; sq.len()];
        }
        sq[e.idx()] = new;
    }
    sq
}

/// Whether every edge of `mesh` is certified intrinsic Delaunay for every metric in
/// `lengths` (`P ≥ 0`, B60, B62); where the five squared lengths of an edge's
/// quadrilateral are known exactly (`exact`, [`exact_squared_on_t0`]) the sign is decided
/// exactly (B63: a tie `P = 0` is Delaunay). `Err` names the first edge not certified.
pub(crate) fn t0_delaunay(
    mesh: &Mesh,
    lengths: &[I],
    exact: &[Option<Rational>],
) -> Result<(), Edge> {
    for e in mesh.edges() {
        let Some(q) = QuadEdges::of(mesh, e) else {
            continue;
        };
        let sq = q
            .edges
            .to_array()
            .map(|x| exact.get(x.idx()).cloned().flatten());
        let ok = match sq {
            [Some(ij), Some(jk), Some(ki), Some(il), Some(lj)] => {
                let quad = Quad { ij, jk, ki, il, lj };
                delaunay_sign_squared(quad.as_refs()) != Sign::Negative
            }
            _ => super::ball_argument::certified_nonnegative(&enclose_p(
                &q.lengths(lengths).map(Clone::clone).to_array(),
            )),
        };
        if !ok {
            return Err(e);
        }
    }
    Ok(())
}

/// `T₀` (`t0`, reached from `surface` by the Euclidean flips `sequence`, with enclosures
/// `lengths` of its exact lengths) certified intrinsic Delaunay for `surface`'s exact
/// metric: first by [`t0_delaunay`]; an edge it leaves open (a tie or a near-tie of
/// irrational lengths) is then decided by replaying `sequence` on the exact metric (B80:
/// every flip certified a legal step, escalating from 128 to 1024 bits, exact signs where
/// the squared lengths are rational, B83), which must reach `t0` and certify it Delaunay.
/// `Err` names the edge [`t0_delaunay`] left open. proof: B73, B80
pub(crate) fn t0_delaunay_on_input(
    surface: &Surface,
    t0: &Mesh,
    lengths: &[I],
    sequence: &[Edge],
) -> Result<(), Edge> {
    use crate::algorithms::replay::replay_escalating_lazy;
    let exact = exact_squared_on_t0(surface, sequence);
    let Err(e) = t0_delaunay(t0, lengths, &exact) else {
        return Ok(());
    };
    let (r, _) = replay_escalating_lazy(
        &surface.mesh,
        &surface.metric,
        sequence,
        FlipKind::Euclidean,
        128,
        1024,
    );
    if r.certified_delaunay() && r.mesh.face_list() == t0.face_list() {
        Ok(())
    } else {
        Err(e)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::builders::Embedded;
    use crate::scalar::Precision;

    /// [`t0_delaunay_on_input`] refuses a `T₀` that is not Delaunay for the exact metric:
    /// a flat kite `(0, 0), (4, 0), (2, 1), (2, −1)` split by its long diagonal (both
    /// opposite angles obtuse) with no flip is refused, naming that edge; after the flip of
    /// that edge it is certified.
    #[test]
    fn t0_delaunay_on_input_refuses_a_non_delaunay_t0() {
        let q = |x: i32, y: i32| [Rational::from(x), Rational::from(y), Rational::from(0)];
        let e = Embedded {
            mesh: Mesh::from_faces(4, &[[0, 1, 2], [1, 0, 3]]).expect("a kite"),
            positions: vec![q(0, 0), q(4, 0), q(2, 1), q(2, -1)],
            exact: true,
        };
        let s = Surface::from_embedded("kite", e).expect("valid");
        let prec = Precision::new(128).expect("bits");
        let long = s
            .mesh
            .edges()
            .find(|&e| QuadEdges::of(&s.mesh, e).is_some())
            .expect("the diagonal");
        let l = s.lengths::<I>(prec);
        assert_eq!(t0_delaunay_on_input(&s, &s.mesh, &l, &[]), Err(long));
        let (t0, l0) = replay_enclosed(&s.mesh, l, &[long]).expect("a convex kite flips");
        assert_eq!(t0_delaunay_on_input(&s, &t0, &l0, &[long]), Ok(()));
    }
}
