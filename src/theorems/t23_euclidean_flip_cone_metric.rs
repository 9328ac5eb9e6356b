//! T23 (notes §1.5.2): Euclidean flips preserve the cone metric — every cone angle is
//! unchanged and discrete Gauss–Bonnet still holds.
//!
//! Certified: the flip sequence chosen by [`flip_to_delaunay`] is replayed on outward-
//! rounded MPFR enclosures of the *exact* flipped lengths ([`euclidean_length_enclosure`]),
//! cone angles are enclosed with the half-angle form (MATH.md §1) before and after, and the
//! two enclosures of each cone angle must intersect (the exact values are equal). With the
//! Ptolemy update instead, cone angles change and the enclosures separate (the negative
//! control of the tests).

use super::{Settings, Verdict, Witness};
use crate::algorithms::flip_to_delaunay::{flip_to_delaunay, FlipKind, FlipOptions};
use crate::algorithms::flips::{euclidean_length_enclosure, ptolemy_length_enclosure};
use crate::mesh::Mesh;
use crate::predicates::delaunay::QuadEdges;
use crate::predicates::directed::{div_positive, enclose_f64, overlaps, valid};
use crate::scalar::{Interval, Mpfr, Precision, Real};

/// Enclosures of the corner angle opposite `a` in a triangle `a, b, c`:
/// `2·atan √((a−b+c)(a+b−c) / ((a+b+c)(−a+b+c)))`; `None` if the triangle may be invalid.
pub fn corner_angle_enclosure(
    a: &Interval<Mpfr>,
    b: &Interval<Mpfr>,
    c: &Interval<Mpfr>,
) -> Option<Interval<Mpfr>> {
    let num = (a.clone() - b + c) * &(a.clone() + b - c);
    let den = (a.clone() + b + c) * &(b.clone() + c - a);
    let half = valid(div_positive(&num, &den)?.sqrt())?.atan();
    valid(half * &enclose_f64(2.0, a.ctx()))
}

/// Enclosures of all cone angles, or the first face whose angles cannot be enclosed.
pub fn cone_angle_enclosures(
    mesh: &Mesh,
    l: &[Interval<Mpfr>],
    prec: Precision,
) -> Result<Vec<Interval<Mpfr>>, u32> {
    let mut theta = vec![enclose_f64(0.0, prec); mesh.n_vertices()];
    for f in mesh.faces() {
        let hs = mesh.face_halfedges(f);
        for i in 0..3 {
            let a = &l[hs[i].edge().idx()];
            let b = &l[hs[(i + 1) % 3].edge().idx()];
            let c = &l[hs[(i + 2) % 3].edge().idx()];
            let v = mesh.tail(hs[(i + 2) % 3]).idx();
            theta[v] += &corner_angle_enclosure(a, b, c).ok_or(f.0)?;
        }
    }
    Ok(theta)
}

/// Flip a copy of `(mesh, lengths)` to Delaunay with Euclidean flips, replay the flips on
/// enclosures with the `replay` update (Euclidean for the theorem), and compare cone
/// angles and the Gauss–Bonnet sum at `prec` bits.
#[allow(clippy::too_many_lines)]
pub fn check_euclidean_flips_preserve_cone_metric<T: Real>(
    mesh: &Mesh,
    lengths: &[T],
    replay: FlipKind,
    prec: u32,
    settings: &Settings,
) -> Verdict {
    let bits = prec;
    let prec = match Precision::new(u64::from(bits)) {
        Ok(p) => p,
        Err(err) => {
            return Verdict::NotApplicable {
                reason: err.to_string(),
            }
        }
    };
    let mut enc = Vec::with_capacity(lengths.len());
    for l in lengths {
        let Some(q) = l.to_rational() else {
            return Verdict::NotApplicable {
                reason: "a length is not finite".into(),
            };
        };
        enc.push(Interval::from_rational(&q, prec));
    }
    let (mut m, mut l) = (mesh.clone(), lengths.to_vec());
    let opts = FlipOptions {
        ladder: settings.ladder,
        record: true,
        ..FlipOptions::default()
    };
    let report = match flip_to_delaunay(&mut m, &mut l, FlipKind::Euclidean, &opts) {
        Ok(r) => r,
        Err(err) => {
            return Verdict::NotApplicable {
                reason: err.to_string(),
            }
        }
    };
    let before = match cone_angle_enclosures(mesh, &enc, prec) {
        Ok(t) => t,
        Err(f) => {
            return Verdict::NotApplicable {
                reason: format!("face f{f} violates the triangle inequality"),
            }
        }
    };
    let mut replayed = mesh.clone();
    let mut undecided = Vec::new();
    for &e in &report.sequence {
        let Some(q) = QuadEdges::of(&replayed, e) else {
            undecided.push(Witness {
                element: e.to_string(),
                detail: "recorded flip not replayable".into(),
                value: 0.0,
            });
            break;
        };
        let new = match replay {
            FlipKind::Euclidean => euclidean_length_enclosure(q.lengths(&enc)),
            FlipKind::Ptolemy => ptolemy_length_enclosure(q.lengths(&enc)),
        };
        let Some(new) = new else {
            undecided.push(Witness {
                element: e.to_string(),
                detail: "new length could not be enclosed".into(),
                value: 0.0,
            });
            break;
        };
        enc[e.idx()] = new;
        let _ = replayed.flip(e);
    }
    let after = if undecided.is_empty() {
        cone_angle_enclosures(&replayed, &enc, prec).ok()
    } else {
        None
    };
    let Some(after) = after else {
        if undecided.is_empty() {
            undecided.push(Witness {
                element: "surface".into(),
                detail: "cone angles after flipping could not be enclosed".into(),
                value: 0.0,
            });
        }
        return Verdict::Undecided {
            bits_tried: bits,
            witnesses: undecided,
        };
    };
    let mut witnesses = Vec::new();
    let mut max_width: f64 = 0.0;
    for v in mesh.vertices() {
        let (b, a) = (&before[v.idx()], &after[v.idx()]);
        max_width = max_width.max(a.width_f64()).max(b.width_f64());
        if !overlaps(a, b) {
            witnesses.push(Witness {
                element: v.to_string(),
                detail: format!(
                    "cone angle changed: [{:.17e}, …] before, [{:.17e}, …] after",
                    b.lo().approx_f64(),
                    a.lo().approx_f64()
                ),
                value: (a.lo().approx_f64() - b.lo().approx_f64()).abs(),
            });
        }
    }
    // Gauss–Bonnet on the flipped metric: Σ_int (2π − θ) + Σ_∂ (π − θ) = 2πχ.
    let pi = Interval::<Mpfr>::pi(prec);
    let two_pi = pi.clone() * &enclose_f64(2.0, prec);
    let on_boundary = replayed.boundary_vertices();
    let mut total = enclose_f64(0.0, prec);
    for v in replayed.vertices() {
        let k = if on_boundary[v.idx()] {
            pi.clone()
        } else {
            two_pi.clone()
        };
        total += &(k - &after[v.idx()]);
    }
    let chi = enclose_f64(replayed.euler_characteristic() as f64, prec);
    if !overlaps(&total, &(two_pi * &chi)) {
        witnesses.push(Witness {
            element: "surface".into(),
            detail: "Gauss–Bonnet fails after flipping".into(),
            value: total.lo().approx_f64(),
        });
    }
    if witnesses.is_empty() {
        Verdict::Holds {
            certified: true,
            max_error: max_width,
        }
    } else {
        Verdict::Fails {
            certified: true,
            witnesses,
        }
    }
}
