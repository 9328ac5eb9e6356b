//! T32's finite-difference comparison as an enclosure (proofs/B57): the directional
//! derivative `E′(u)·d` lies in
//! `[(E(u+hd) − E(u−hd))/2h] ± (h²/6)·max_{|s|≤h} |E‴(u+sd)|`,
//! the difference quotient enclosed by evaluating `E` on `Interval<Mpfr>` at twice the
//! working precision, and `E‴` along `d` enclosed on the whole segment by dual numbers over
//! intervals of `dᵀH(u+sd)d` (the derivative of each proper face's
//! `½ Σ cot α_m (d_i − d_j)²`). No estimate is involved: the comparison's only other
//! tolerance is the error of the claimed `g·d` itself.
//!
//! Only the faces touching the support of `d` ([`touched_faces`]) enter: on a fixed
//! triangulation a face none of whose vertices moves keeps its lengths along `u + sd`, so
//! its term of `E` cancels exactly in `E(u+hd) − E(u−hd)` and adds nothing to `E‴`; so do
//! the terms `Θ_i u_i` with `d_i = 0` (proofs/B32). Leaving them out is exact and narrows
//! the enclosure (an interval minus itself is not 0).

use crate::geometry::triangle::cot_opposite;
use crate::mesh::{Face, Mesh};
use crate::scalar::{Dual, Interval, Mpfr, Precision, Real};
use crate::variational::energy::{face_energy_sum, scaled_log_lengths};
use crate::variational::triangle::{shape, shifted_lengths, Shape};
use rug::float::Round;
use rug::Float;

/// An enclosure of `E′(u)·d` and the two parts it is made of.
#[derive(Clone, Debug)]
pub struct DerivativeEnclosure {
    /// Lower bound of `E′(u)·d`.
    pub lo: Float,
    /// Upper bound of `E′(u)·d`.
    pub hi: Float,
    /// The truncation bound `(h²/6)·max|E‴|` included in `[lo, hi]` (rounded up).
    pub truncation: Float,
}

/// Whether each vertex moves along `d` (`d_v ≠ 0`; a value without a rational, NaN or
/// infinite, counts as moving).
pub fn support<T: Real>(d: &[T]) -> Vec<bool> {
    d.iter()
        .map(|x| x.to_rational().is_none_or(|q| q != 0))
        .collect()
}

/// The faces with a vertex in the support of `d` (see [`support`]), in face order: on a
/// fixed triangulation the only faces whose term of `E(u + sd)` depends on `s`
/// (proofs/B32).
pub fn touched_faces(mesh: &Mesh, moving: &[bool]) -> Vec<Face> {
    mesh.faces()
        .filter(|&f| {
            mesh.face_halfedges(f)
                .iter()
                .any(|&h| moving[mesh.tail(h).idx()])
        })
        .collect()
}

/// The step `h = 2^{−⌈p/2⌉}` for working precision `p` bits.
pub fn step_exponent(bits: u32) -> u32 {
    bits.div_ceil(2)
}

fn enclose<T: Real>(v: &[T], p: Precision) -> Option<Vec<Interval<Mpfr>>> {
    v.iter()
        .map(|x| Some(Interval::<Mpfr>::from_rational(&x.to_rational()?, p)))
        .collect()
}

/// `|x|`'s upper bound for an enclosure.
fn mag_up(x: &Interval<Mpfr>) -> Float {
    let a = Float::with_val(x.lo().0.prec(), x.lo().0.abs_ref());
    let b = Float::with_val(x.hi().0.prec(), x.hi().0.abs_ref());
    if a > b {
        a
    } else {
        b
    }
}

/// An enclosure of `max_{|s|≤h} |d/ds dᵀH(u+sd)d|` (`= |E‴|` along `d`): per face of the
/// scaled metric on the box `u + [−h, h]d`, the dual derivative of
/// `½ Σ_m cot α_m (d_i − d_j)²`, summed over `faces` (those touching the support of `d`;
/// the others add exactly 0); a face certified strictly degenerate on the whole box adds
/// nothing. `None` when some face of `faces` is neither certified proper nor strictly
/// degenerate on the whole box (`E` need not be three times differentiable there).
fn third_derivative_bound(
    mesh: &Mesh,
    faces: &[Face],
    lambda: &[Interval<Mpfr>],
    u: &[Interval<Mpfr>],
    d: &[Interval<Mpfr>],
    h: &Interval<Mpfr>,
) -> Option<Float> {
    let hull = |a: &Interval<Mpfr>, b: &Interval<Mpfr>| {
        let lo = if a.lo().0 < b.lo().0 { a.lo() } else { b.lo() };
        let hi = if a.hi().0 > b.hi().0 { a.hi() } else { b.hi() };
        Interval::new(lo.clone(), hi.clone())
    };
    let ud: Vec<Dual<Interval<Mpfr>>> = u
        .iter()
        .zip(d)
        .map(|(ui, di)| {
            let step = di.clone() * h;
            let a = ui.clone() - &step;
            let b = ui.clone() + &step;
            Dual::new(hull(&a, &b), di.clone())
        })
        .collect();
    let lam: Vec<Dual<Interval<Mpfr>>> = lambda.iter().cloned().map(Dual::constant).collect();
    let lt = scaled_log_lengths(mesh, &lam, &ud);
    let z = lambda.first()?.zero_like();
    let mut total = z.clone();
    for &f in faces {
        let hs = mesh.face_halfedges(f);
        let x = hs.map(|he| lt[he.edge().idx()].clone());
        // The shape is decided on the value enclosures (over the whole box); `Dual` is a
        // point type for `shape`, so its own test would not see the intervals.
        let xv = x.clone().map(|v| v.v);
        let lv = shifted_lengths(&xv);
        match shape(&lv) {
            Shape::Proper => {}
            // Strictly degenerate on the whole box: `f = ½πx_m` is linear there
            // (proofs/B57), no third derivative.
            Shape::Degenerate(m) => {
                let slack = lv[(m + 1) % 3].clone() + &lv[(m + 2) % 3] - &lv[m];
                if slack.is_valid() && slack.hi().0.is_sign_negative() && !slack.hi().0.is_zero() {
                    continue;
                }
                return None;
            }
            Shape::Undecided => return None,
        }
        let l = shifted_lengths(&x);
        let c = [0, 1, 2].map(|m| cot_opposite(&l[m], &l[(m + 1) % 3], &l[(m + 2) % 3]));
        for m in 0..3 {
            let (i, j) = (mesh.tail(hs[m]).idx(), mesh.tip(hs[m]).idx());
            let diff = d[i].clone() - &d[j];
            let sq = diff.clone() * &diff;
            let term = c[m].clone() * &Dual::constant(sq * &z.lit(0.5));
            total += &term.d;
        }
    }
    total.is_valid().then(|| mag_up(&total))
}

/// The enclosure of `E′(u)·d` for the energy with logarithmic lengths `lambda`, log scale
/// factors `u`, targets `Θ`, at `2·bits` bits with `h = 2^{−⌈bits/2⌉}` (proofs/B57), on
/// the faces touching the support of `d` ([`touched_faces`], proofs/B32).
/// `None` when an enclosure is invalid (a face not certified proper on the segment, an
/// argument not finite) or the precision is out of range.
pub fn derivative_enclosure<T: Real>(
    mesh: &Mesh,
    lambda: &[T],
    u: &[T],
    targets: &[T],
    d: &[T],
    bits: u32,
) -> Option<DerivativeEnclosure> {
    let moving = support(d);
    let faces = touched_faces(mesh, &moving);
    derivative_enclosure_on(mesh, &faces, lambda, u, targets, d, bits)
}

/// [`derivative_enclosure`] with the face part of `E` summed over `faces` only. It encloses
/// `E′(u)·d` when `faces` holds every face touching the support of `d` (proofs/B32); a
/// list that misses one encloses the derivative of another function.
pub fn derivative_enclosure_on<T: Real>(
    mesh: &Mesh,
    faces: &[Face],
    lambda: &[T],
    u: &[T],
    targets: &[T],
    d: &[T],
    bits: u32,
) -> Option<DerivativeEnclosure> {
    let p2 = Precision::new(u64::from(2 * bits)).ok()?;
    let (l2, u2, t2, d2) = (
        enclose(lambda, p2)?,
        enclose(u, p2)?,
        enclose(targets, p2)?,
        enclose(d, p2)?,
    );
    let moving = support(d);
    let k = step_exponent(bits);
    let h = Interval::point(Mpfr(Float::with_val(p2.bits(), 1) >> k));
    let shift = |s: f64| -> Vec<Interval<Mpfr>> {
        u2.iter()
            .zip(&d2)
            .map(|(a, b)| a.clone() + &(b.clone() * &h * &h.lit(s)))
            .collect()
    };
    let z = l2.first()?;
    // φ(s) up to terms constant in s: the faces given and Θ_i u_i for the moving i.
    let part = |us: &[Interval<Mpfr>]| -> Interval<Mpfr> {
        let lt = scaled_log_lengths(mesh, &l2, us);
        let mut e = face_energy_sum(mesh, faces.iter().copied(), &lt, z);
        for ((t, ui), &m) in t2.iter().zip(us).zip(&moving) {
            if m {
                e += &(t.clone() * ui);
            }
        }
        e
    };
    let ep = part(&shift(1.0));
    let em = part(&shift(-1.0));
    // (E₊ − E₋)/2h: the division by the power of two 2h is exact.
    let q = (ep - &em) / &(h.clone() * &h.lit(2.0));
    if !q.is_valid() {
        return None;
    }
    let m3 = third_derivative_bound(mesh, faces, &l2, &u2, &d2, &h)?;
    // (h²/6)·M, h² = 2^{−2k} exact, rounded up.
    let prec = p2.bits();
    let trunc = Float::with_val_round(prec, &m3 / 6u32, Round::Up).0 >> (2 * k);
    let lo = Float::with_val_round(prec, &q.lo().0 - &trunc, Round::Down).0;
    let hi = Float::with_val_round(prec, &q.hi().0 + &trunc, Round::Up).0;
    Some(DerivativeEnclosure {
        lo,
        hi,
        truncation: trunc,
    })
}

/// How far the exact rational `x` lies outside `[enc.lo, enc.hi]` (0 inside), rounded up,
/// as an `Mpfr` at the enclosure's precision.
pub fn distance_outside(x: &rug::Rational, enc: &DerivativeEnclosure) -> Mpfr {
    let prec = enc.hi.prec();
    if *x < enc.lo {
        Mpfr(Float::with_val_round(prec, &enc.lo - x.clone(), Round::Up).0)
    } else if *x > enc.hi {
        Mpfr(Float::with_val_round(prec, x.clone() - &enc.hi, Round::Up).0)
    } else {
        Mpfr(Float::new(prec))
    }
}
