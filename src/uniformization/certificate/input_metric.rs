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
use crate::predicates::delaunay::{delaunay_p, delaunay_sign_squared, enclose_p, Quad, QuadEdges};
use crate::scalar::{Interval, IntervalBound, Mpfr, Real, Sign};
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
    let euclidean = euclidean_sequence(sol, mesh, lengths)?;
    let (_, enclosures) = replay_enclosed(mesh, enclosures, &euclidean)?;
    replay_values(mesh, &mut values, &euclidean)?;
    Ok(T0Metric {
        values,
        enclosures,
        euclidean,
    })
}

/// The Euclidean flips from `mesh` (binary64 `lengths`, what [`super::uniformize`] was
/// given) to `sol`'s `T₀`, recorded by rerunning the solve's deterministic flips.
pub fn euclidean_sequence(
    sol: &Uniformization,
    mesh: &Mesh,
    lengths: &[f64],
) -> Result<Vec<Edge>, String> {
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
    Ok(rep.sequence)
}

/// The MPFR lengths `values` of `mesh` carried through the Euclidean flips `sequence` (in
/// place): the input lengths on `T₀` rounded, for the refinement (not an enclosure).
pub fn replay_values(mesh: &Mesh, values: &mut [Mpfr], sequence: &[Edge]) -> Result<(), String> {
    let mut mv = mesh.clone();
    for &e in sequence {
        flip_euclidean(&mut mv, values, e).map_err(|err| err.to_string())?;
    }
    Ok(())
}

/// The first edge of `t0` whose quadrilateral has an edge flipped by `sequence` and whose
/// `P` (B60) at the rounded MPFR lengths `values` of `t0` (precision `p`) is below
/// `−2^(24−p)·M`, `M = de(b² + c² + a²) + bc(d² + e² + a²)` its magnitude: clearly
/// negative, far beyond the rounding of the carried lengths, so an edge presumably not
/// Delaunay for the exact metric (edges of unflipped quadrilaterals keep the input's
/// lengths, decided exactly by [`t0_delaunay`]). A heuristic choice of the edge that
/// [`negative_on_enclosures`] then decides; `P` in binary64 first, to pass over the edges
/// clearly Delaunay.
pub(crate) fn clearly_not_delaunay(t0: &Mesh, values: &[Mpfr], sequence: &[Edge]) -> Option<Edge> {
    let first = values.first()?;
    let margin = first.lit(2f64.powi(24 - Mpfr::precision_bits(first.ctx()).min(1000) as i32));
    let mut flipped = vec![false; t0.n_edges()];
    for e in sequence {
        if let Some(f) = flipped.get_mut(e.idx()) {
            *f = true;
        }
    }
    let magnitude = |[a, b, c, d, e]: &[Mpfr; 5]| {
        d.clone() * e * &(b.clone() * b + &(c.clone() * c) + &(a.clone() * a))
            + &(b.clone() * c * &(d.clone() * d + &(e.clone() * e) + &(a.clone() * a)))
    };
    t0.edges().find(|&e| {
        let Some(q) = QuadEdges::of(t0, e) else {
            return false;
        };
        if !q.edges.to_array().iter().any(|x| flipped[x.idx()]) {
            return false;
        }
        let l = q.lengths(values).to_array().map(Clone::clone);
        let [a, b, c, d, e] = l.each_ref().map(Real::approx_f64);
        let m = d * e * (b * b + c * c + a * a) + b * c * (d * d + e * e + a * a);
        if delaunay_p(&[a, b, c, d, e]) > 1e-8 * m {
            return false;
        }
        (delaunay_p(&l) + &(magnitude(&l) * &margin)).approx_f64() < 0.0
    })
}

/// Whether `P` (B60) of edge `e` of `T₀` (reached from `mesh` by the Euclidean flips
/// `sequence`) is certified negative on the enclosures `enclosures` of `mesh`'s lengths
/// carried to `T₀` by [`replay_enclosed`] — computed on the flips that the five lengths of
/// `e`'s quadrilateral depend on only, each admitted as there (strictly convex), all others
/// done on the connectivity alone. These five enclosures are the ones [`replay_enclosed`]
/// gives (the same operations on the same operands), so `true` means that the full replay
/// would admit these flips and that [`t0_delaunay`] cannot certify `e` Delaunay, nor can
/// any replay on the exact metric (its lengths lie in the enclosures, where `P < 0`): `T₀`
/// is not intrinsic Delaunay for any metric in `enclosures`. The lengths it overwrites are
/// restored: `enclosures` comes back as given, and nothing of its size is copied.
/// proof: B73, B62
pub(crate) fn negative_on_enclosures(
    mesh: &Mesh,
    enclosures: &mut [I],
    sequence: &[Edge],
    e: Edge,
) -> bool {
    let mut undo = Vec::new();
    let negative = negative_with_undo(mesh, enclosures, sequence, e, &mut undo);
    for (x, old) in undo.into_iter().rev() {
        enclosures[x] = old;
    }
    negative
}

/// [`negative_on_enclosures`], recording in `undo` the value of every length it
/// overwrites, in order.
fn negative_with_undo(
    mesh: &Mesh,
    enclosures: &mut [I],
    sequence: &[Edge],
    e: Edge,
    undo: &mut Vec<(usize, I)>,
) -> bool {
    // The flips on the connectivity: each one's five input edges' last writers.
    const NONE: u32 = u32::MAX;
    let Ok(count) = u32::try_from(sequence.len()) else {
        return false;
    };
    let mut m = mesh.clone();
    let mut writer = vec![NONE; mesh.n_edges()];
    let mut inputs: Vec<[u32; 5]> = Vec::with_capacity(sequence.len());
    for (k, &f) in (0..count).zip(sequence) {
        let Some(q) = (f.idx() < m.n_edges())
            .then(|| QuadEdges::of(&m, f))
            .flatten()
        else {
            return false;
        };
        inputs.push(q.edges.to_array().map(|x| writer[x.idx()]));
        if m.flip(f).is_err() {
            return false;
        }
        writer[f.idx()] = k;
    }
    let Some(q) = (e.idx() < m.n_edges())
        .then(|| QuadEdges::of(&m, e))
        .flatten()
    else {
        return false;
    };
    // The flips the quadrilateral of e depends on (each input written before its reader).
    let mut needed = vec![false; sequence.len()];
    let mut stack: Vec<u32> = q.edges.to_array().map(|x| writer[x.idx()]).to_vec();
    while let Some(k) = stack.pop() {
        if k == NONE || needed[k as usize] {
            continue;
        }
        needed[k as usize] = true;
        stack.extend(inputs[k as usize]);
    }
    let mut m = mesh.clone();
    for (k, &f) in sequence.iter().enumerate() {
        if !needed[k] {
            if m.flip(f).is_err() {
                return false;
            }
            continue;
        }
        let Some(q) = QuadEdges::of(&m, f) else {
            return false;
        };
        if !strictly_convex_enclosed(&q.lengths(enclosures).map(Clone::clone)) {
            return false;
        }
        undo.push((f.idx(), enclosures[f.idx()].clone()));
        if flip_euclidean(&mut m, enclosures, f).is_err() {
            return false;
        }
    }
    let p = enclose_p(&q.lengths(enclosures).map(Clone::clone).to_array());
    p.is_valid() && p.sign() == Some(Sign::Negative)
}

/// Whether replaying `sequence` on `surface`'s exact metric certifies every flip a legal
/// step and reaches `t0` certified intrinsic Delaunay (B80: escalating from 128 to 1024
/// bits, exact signs where the squared lengths are rational, B83). proof: B80
pub(crate) fn t0_delaunay_by_exact_replay(surface: &Surface, t0: &Mesh, sequence: &[Edge]) -> bool {
    use crate::algorithms::replay::replay_escalating_lazy;
    let (r, _) = replay_escalating_lazy(
        &surface.mesh,
        &surface.metric,
        sequence,
        FlipKind::Euclidean,
        128,
        1024,
    );
    r.certified_delaunay() && r.mesh.face_list() == t0.face_list()
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
        if !strictly_convex_enclosed(&q.lengths(&enclosures).map(Clone::clone)) {
            return Err(format!(
                "Euclidean flip {k} (e{}): its quadrilateral is not certified strictly convex for the exact input lengths",
                e.0
            ));
        }
        flip_euclidean(&mut mi, &mut enclosures, e).map_err(|err| err.to_string())?;
    }
    Ok((mi, enclosures))
}

/// [`strictly_convex`] on the enclosures `q`, decided first on their outward binary64
/// roundings (each `[RD(lo), RU(hi)]` contains the MPFR interval, so a quadrilateral
/// certified strictly convex there is so for every metric in `q`), then, where binary64
/// leaves it open (a near-degenerate corner or an angle sum near `π`), on `q` itself.
/// proof: B73
pub(crate) fn strictly_convex_enclosed(q: &Quad<Interval<Mpfr>>) -> bool {
    strictly_convex(&q.as_refs().map(Interval::to_f64_outward)) || strictly_convex(q)
}

/// Whether the quadrilateral `[ij, jk, ki, il, lj]` (faces `ijk`, `jil`) is certified
/// strictly convex at both ends of its diagonal: `∠kij + ∠jil < π` and `∠ijk + ∠lji < π`.
/// For corner angles `α, β ∈ (0, π)`, `α + β < π ⟺ cot α + cot β > 0` (`cot` decreases on
/// `(0, π)` and `cot(π − β) = −cot β`); with `cot α = (b² + c² − a²)/(4A)` this is
/// `x₁·4A₂ + x₂·4A₁ > 0` for `x` the numerators and `4A = √(16A²)` from the squared
/// sides, both areas certified positive (each face a strict triangle). No arc tangent:
/// the test costs a few products and two square roots per quadrilateral. proof: B73
pub fn strictly_convex<B: IntervalBound>(q: &Quad<Interval<B>>) -> bool {
    let sq = |x: &Interval<B>| x.clone() * x;
    let [ij, jk, ki, il, lj] = [&q.ij, &q.jk, &q.ki, &q.il, &q.lj].map(sq);
    let four_area = |a: &Interval<B>, b: &Interval<B>, c: &Interval<B>| {
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
/// `lengths` (`P ≥ 0`, B60, B62): first `P > 0` on the binary64 outward roundings of the
/// enclosures (which contain them); then, where the five squared lengths of an edge's
/// quadrilateral are known exactly (`exact`, [`exact_squared_on_t0`]), the sign decided
/// exactly (B63: a tie `P = 0` is Delaunay), else on the MPFR enclosures. `Err` names the
/// first edge not certified.
pub(crate) fn t0_delaunay(
    mesh: &Mesh,
    lengths: &[I],
    exact: &[Option<Rational>],
) -> Result<(), Edge> {
    for e in mesh.edges() {
        let Some(q) = QuadEdges::of(mesh, e) else {
            continue;
        };
        // P > 0 on the binary64 outward enclosures holds for every metric in `lengths`,
        // the exact one included: most edges are decided here, ties and near-ties below.
        let p64 = enclose_p(&q.lengths(lengths).to_array().map(Interval::to_f64_outward));
        if p64.is_valid() && p64.sign() == Some(Sign::Positive) {
            continue;
        }
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
    let exact = exact_squared_on_t0(surface, sequence);
    let Err(e) = t0_delaunay(t0, lengths, &exact) else {
        return Ok(());
    };
    if t0_delaunay_by_exact_replay(surface, t0, sequence) {
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

    /// [`negative_on_enclosures`] on the flips an edge depends on gives the answer of the
    /// full [`replay_enclosed`] at every edge: a random planar triangulation scrambled by
    /// random flips, flipped to Delaunay (many Euclidean flips), then three more flips of
    /// strictly convex Delaunay edges (each leaves an edge with `P < 0`). Every edge
    /// certified negative by the full replay is so on its flips alone, and no other;
    /// [`clearly_not_delaunay`] finds one of them from the rounded lengths, and none on the
    /// Delaunay `T₀`; the enclosures given come back unchanged.
    #[test]
    fn negative_on_the_flips_an_edge_depends_on_is_the_full_replays_answer() {
        let planar = crate::mesh::builders::random_planar(60, 7).expect("points");
        // Random flips may fold an edge onto a vertex pair twice (length 0): the first seed
        // whose scrambled mesh is a valid surface.
        let s = (11..)
            .find_map(|seed| {
                let scrambled = Embedded {
                    mesh: crate::mesh::builders::random_flips(&planar.mesh, 150, seed),
                    positions: planar.positions.clone(),
                    exact: true,
                };
                Surface::from_embedded("scrambled", scrambled).ok()
            })
            .expect("a valid scrambled surface");
        let prec = Precision::new(256).expect("bits");
        let mut m = s.mesh.clone();
        let mut l = s.lengths::<f64>(());
        let opts = FlipOptions {
            record: true,
            ..FlipOptions::default()
        };
        let mut seq = flip_to_delaunay(&mut m, &mut l, FlipKind::Euclidean, &opts)
            .expect("flips")
            .sequence;
        assert!(seq.len() > 20, "{} flips", seq.len());
        let enc0 = s.lengths::<I>(prec);
        let mut values = s.lengths::<Mpfr>(prec);
        replay_values(&s.mesh, &mut values, &seq).expect("replay");
        assert_eq!(clearly_not_delaunay(&m, &values, &seq), None);
        let mut extra = 0;
        while extra < 3 {
            let (t, enc) = replay_enclosed(&s.mesh, enc0.clone(), &seq).expect("convex");
            let next = t.edges().find(|&e| {
                !seq.contains(&e)
                    && QuadEdges::of(&t, e)
                        .is_some_and(|q| strictly_convex(&q.lengths(&enc).map(Clone::clone)))
            });
            seq.push(next.expect("a convex edge"));
            extra += 1;
        }
        let (t, enc) = replay_enclosed(&s.mesh, enc0.clone(), &seq).expect("convex");
        let mut negatives = Vec::new();
        for e in t.edges() {
            let Some(q) = QuadEdges::of(&t, e) else {
                continue;
            };
            let p = enclose_p(&q.lengths(&enc).map(Clone::clone).to_array());
            let full = p.is_valid() && p.sign() == Some(Sign::Negative);
            let mut given = enc0.clone();
            assert_eq!(
                negative_on_enclosures(&s.mesh, &mut given, &seq, e),
                full,
                "e{}",
                e.0
            );
            // The enclosures are left as given.
            assert!(given
                .iter()
                .zip(&enc0)
                .all(|(x, y)| x.lo().0 == y.lo().0 && x.hi().0 == y.hi().0));
            if full {
                negatives.push(e);
            }
        }
        assert!(!negatives.is_empty());
        let mut values = s.lengths::<Mpfr>(prec);
        replay_values(&s.mesh, &mut values, &seq).expect("replay");
        let found = clearly_not_delaunay(&t, &values, &seq).expect("a negative edge");
        assert!(negatives.contains(&found));
    }

    /// [`strictly_convex_enclosed`]: binary64 first, MPFR where binary64 leaves it open.
    /// `i = (0, 0)`, `j = (1, 0)`, `k = (−1, 1)`, `l = (1, −1 + δ)`: the angle sum at `i`
    /// is `π − δ/2 + O(δ²)`. At `δ = 2⁻⁶⁶` binary64 enclosures cannot certify it below `π`,
    /// MPFR-256 does; the unit square is certified by binary64 alone; and the control
    /// `δ = −2⁻⁶⁶` (a reflex corner at `i`) is refused by both.
    #[test]
    fn strictly_convex_enclosed_falls_back_to_mpfr_near_a_straight_corner() {
        let prec = Precision::new(256).expect("bits");
        let quad = |delta: Rational| {
            let one = Rational::from(1);
            let m = one.clone() - delta;
            let sq = [
                one.clone(),
                Rational::from(5),
                Rational::from(2),
                one + m.clone() * &m,
                m.clone() * &m,
            ];
            let [ij, jk, ki, il, lj] = sq.map(|q| I::from_rational(&q, prec).sqrt());
            Quad { ij, jk, ki, il, lj }
        };
        let outward = |q: &Quad<I>| q.as_refs().map(Interval::to_f64_outward);
        let tiny = Rational::from((1, 1u128 << 66));
        let near = quad(tiny.clone());
        assert!(!strictly_convex(&outward(&near)), "binary64 leaves it open");
        assert!(strictly_convex(&near) && strictly_convex_enclosed(&near));
        let s = I::point(Mpfr::from_f64(1.0, prec));
        let d = I::point(Mpfr::from_f64(2.0, prec)).sqrt();
        let square = Quad {
            ij: d,
            jk: s.clone(),
            ki: s.clone(),
            il: s.clone(),
            lj: s,
        };
        assert!(strictly_convex(&outward(&square)) && strictly_convex_enclosed(&square));
        // Control: the reflex corner.
        let reflex = quad(-tiny);
        assert!(!strictly_convex(&outward(&reflex)));
        assert!(!strictly_convex_enclosed(&reflex));
    }

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
