//! T26 — the flips along uniformization are finitely many and keep the metric: the
//! recorded Ptolemy flip sequence of a solve, replayed exactly in ℚ, commutes with the
//! conformal scaling `ℓ ↦ s_i s_j ℓ` (T28 (b) along the whole path), so the final
//! triangulation carries the same decorated metric as the input at every `u`.

use super::verdict::{Verdict, Witness};
use crate::algorithms::flip_to_delaunay::rational_bits;
use crate::algorithms::flips::flip_ptolemy_exact;
use crate::mesh::{Edge, Mesh};
use crate::scalar::nearest_f64;
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
    let surface = |detail: String| Witness {
        element: "surface".into(),
        detail,
        value: f64::NAN,
    };
    if l0.len() != t0.n_edges() || s.len() != t0.n_vertices() || t.len() != t0.n_vertices() {
        return Verdict::certified(
            vec![surface(
                "one length per edge and one factor per vertex are required".into(),
            )],
            vec![],
            0,
        );
    }
    let Some(l): Option<Vec<Rational>> = l0.iter().map(|&x| Rational::from_f64(x)).collect() else {
        return Verdict::certified(vec![surface("a length is not finite".into())], vec![], 0);
    };
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
