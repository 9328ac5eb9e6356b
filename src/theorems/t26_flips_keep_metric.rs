//! T26 — the flips along uniformization are finitely many and keep the metric: the
//! recorded Ptolemy flip sequence of a solve, replayed exactly in ℚ, commutes with the
//! conformal scaling `ℓ ↦ s_i s_j ℓ` (T28 (b) along the whole path), so the final
//! triangulation carries the same decorated metric as the input at every `u`.

use super::verdict::{Verdict, Witness};
use crate::algorithms::flip_to_delaunay::rational_bits;
use crate::algorithms::flips::{flip_ptolemy, flip_ptolemy_exact};
use crate::mesh::{Edge, Mesh};
use crate::scalar::{nearest_f64, Interval, Mpfr, Real};
use rug::Rational;

/// The largest bit size of a carried length before the exact replay gives up (`Undecided`).
pub const MAX_REPLAY_BITS: u64 = 1 << 20;

fn scale(mesh: &Mesh, l: &[Rational], s: &[Rational]) -> Vec<Rational> {
    mesh.edges()
        .map(|e| {
            let h = e.halfedge();
            Rational::from(&s[mesh.tail(h).idx()] * &s[mesh.tip(h).idx()]) * &l[e.idx()]
        })
        .collect()
}

/// Replay `sequence` on `(t0, l0)` twice, exactly: flip the scaled lengths `s_i s_j ℓ`, and
/// flip `ℓ` then scale by `t`. The theorem is `t = s` (equal lengths on every edge of the
/// final triangulation); `t ≠ s` is the negative control. Also `final_mesh` must be the
/// triangulation the sequence reaches.
pub fn check_flip_path(
    t0: &Mesh,
    l0: &[f64],
    sequence: &[Edge],
    final_mesh: &Mesh,
    s: &[Rational],
    t: &[Rational],
) -> Verdict {
    // The counts are checked once, by `check_flip_path_exact` (a conversion keeps them).
    let Some(l): Option<Vec<Rational>> = l0.iter().map(|&x| Rational::from_f64(x)).collect() else {
        return Verdict::certified(vec![surface("a length is not finite".into())], vec![], 0);
    };
    check_flip_path_exact(t0, l, sequence, final_mesh, s, t)
}

/// A witness about the whole surface (no element of it).
fn surface(detail: String) -> Witness {
    Witness {
        element: "surface".into(),
        detail,
        value: f64::NAN,
    }
}

/// The certified refusal when the counts of lengths (`n_lengths`) or factors (`s`, `t`) do
/// not match `t0`'s edges and vertices.
fn count_mismatch(t0: &Mesh, n_lengths: usize, s: &[Rational], t: &[Rational]) -> Option<Verdict> {
    (n_lengths != t0.n_edges() || s.len() != t0.n_vertices() || t.len() != t0.n_vertices()).then(
        || {
            Verdict::certified(
                vec![surface(
                    "one length per edge and one factor per vertex are required".into(),
                )],
                vec![],
                0,
            )
        },
    )
}

/// [`check_flip_path`] on rational lengths `l0` of `T₀` (e.g. an input given by rational
/// lengths, exactly).
pub fn check_flip_path_exact(
    t0: &Mesh,
    l: Vec<Rational>,
    sequence: &[Edge],
    final_mesh: &Mesh,
    s: &[Rational],
    t: &[Rational],
) -> Verdict {
    if let Some(refused) = count_mismatch(t0, l.len(), s, t) {
        return refused;
    }
    let (mut m1, mut a) = (t0.clone(), scale(t0, &l, s));
    let (mut m2, mut b) = (t0.clone(), l);
    for (k, &e) in sequence.iter().enumerate() {
        if e.idx() >= m1.n_edges()
            || flip_ptolemy_exact(&mut m1, &mut a, e).is_err()
            || flip_ptolemy_exact(&mut m2, &mut b, e).is_err()
        {
            return Verdict::certified(
                vec![surface(format!("flip {k} (e{}) cannot be performed", e.0))],
                vec![],
                0,
            );
        }
        let bits = rational_bits(&a[e.idx()]).max(rational_bits(&b[e.idx()]));
        if bits > MAX_REPLAY_BITS {
            return Verdict::Undecided {
                bits_tried: 0,
                witnesses: vec![surface(format!(
                    "exact lengths past {MAX_REPLAY_BITS} bits at flip {k}"
                ))],
            };
        }
    }
    if m1.face_list() != final_mesh.face_list() {
        return Verdict::certified(
            vec![surface(
                "the sequence does not reach the final triangulation".into(),
            )],
            vec![],
            0,
        );
    }
    let b = scale(&m2, &b, t);
    let failures: Vec<Witness> = a
        .iter()
        .zip(&b)
        .enumerate()
        .filter(|(_, (x, y))| x != y)
        .map(|(e, (x, y))| Witness {
            element: format!("e{e}"),
            detail: format!(
                "scale then flip gives {:e}, flip then scale gives {:e}",
                nearest_f64(x),
                nearest_f64(y)
            ),
            value: nearest_f64(x) - nearest_f64(y),
        })
        .collect();
    Verdict::certified(failures, vec![], 0)
}

/// [`check_flip_path_exact`] on enclosures `l` of irrational lengths of `T₀` (e.g. square
/// roots of an input's rational squared lengths, flipped to `T₀` in intervals): both
/// orders are replayed in interval arithmetic (B20) with the exact factors `s` and `t`
/// enclosed. An edge whose two enclosures are disjoint is a certified failure for the
/// lengths enclosed; overlapping enclosures on every edge are `Holds`, numerical (equality
/// of irrational numbers is not decided), with the widest overlap as the error.
pub fn check_flip_path_enclosed(
    t0: &Mesh,
    l: Vec<Interval<Mpfr>>,
    sequence: &[Edge],
    final_mesh: &Mesh,
    s: &[Rational],
    t: &[Rational],
) -> Verdict {
    let Some(first) = l.first() else {
        return Verdict::certified(vec![surface("no edges".into())], vec![], 0);
    };
    let prec = first.lo().ctx();
    if let Some(refused) = count_mismatch(t0, l.len(), s, t) {
        return refused;
    }
    let enclose = |q: &[Rational]| -> Vec<Interval<Mpfr>> {
        q.iter().map(|x| Interval::from_rational(x, prec)).collect()
    };
    let (si, ti) = (enclose(s), enclose(t));
    let scale_i = |mesh: &Mesh, l: &[Interval<Mpfr>], f: &[Interval<Mpfr>]| -> Vec<_> {
        mesh.edges()
            .map(|e| {
                let h = e.halfedge();
                f[mesh.tail(h).idx()].clone() * &f[mesh.tip(h).idx()] * &l[e.idx()]
            })
            .collect::<Vec<Interval<Mpfr>>>()
    };
    let (mut m1, mut a) = (t0.clone(), scale_i(t0, &l, &si));
    let (mut m2, mut b) = (t0.clone(), l);
    for (k, &e) in sequence.iter().enumerate() {
        if e.idx() >= m1.n_edges()
            || flip_ptolemy(&mut m1, &mut a, e).is_err()
            || flip_ptolemy(&mut m2, &mut b, e).is_err()
        {
            return Verdict::certified(
                vec![surface(format!("flip {k} (e{}) cannot be performed", e.0))],
                vec![],
                0,
            );
        }
    }
    if m1.face_list() != final_mesh.face_list() {
        return Verdict::certified(
            vec![surface(
                "the sequence does not reach the final triangulation".into(),
            )],
            vec![],
            0,
        );
    }
    let b = scale_i(&m2, &b, &ti);
    let mut failures = Vec::new();
    let mut undecided = Vec::new();
    let mut widest: f64 = 0.0;
    for (e, (x, y)) in a.iter().zip(&b).enumerate() {
        if !(x.is_valid() && y.is_valid()) {
            undecided.push(surface(format!("e{e}: a length is not enclosed")));
            continue;
        }
        let disjoint =
            x.hi().as_float() < y.lo().as_float() || y.hi().as_float() < x.lo().as_float();
        if disjoint {
            failures.push(Witness {
                element: format!("e{e}"),
                detail: format!(
                    "scale then flip gives {:e}, flip then scale gives {:e} (disjoint enclosures)",
                    x.approx_f64(),
                    y.approx_f64()
                ),
                value: x.approx_f64() - y.approx_f64(),
            });
        } else {
            widest = widest.max(x.width_f64()).max(y.width_f64());
        }
    }
    if !failures.is_empty() || !undecided.is_empty() {
        return Verdict::certified(failures, undecided, prec.bits());
    }
    Verdict::Holds {
        certified: false,
        max_error: widest,
    }
}
