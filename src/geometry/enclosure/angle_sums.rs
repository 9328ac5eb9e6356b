//! Enclosed cone angles `θ_v = Σ α` by one argument per vertex: the product of the corner
//! directions `w = 4bc·e^{iα}` in complex interval arithmetic, its quarter turns counted
//! exactly from the signs of the enclosed running products, and one enclosed arctangent
//! per vertex. proof: B33
//!
//! A vertex whose running product is not certified inside an open quadrant (an enclosure
//! touching an axis: a partial angle sum at a multiple of π/2, or wide input) is not
//! guessed: it falls back to the sum of enclosed corner angles
//! ([`corner_angle`](crate::geometry::triangle::corner_angle), two arctangents per corner).

use super::{Bounds, FaceHeron};
use crate::geometry::triangle::corner_angle;
use crate::mesh::Mesh;
use crate::scalar::{Interval, Mpfr, Real};
use rug::float::{Constant, Round};
use rug::ops::AssignRound;
use rug::Float;

type I = Interval<Mpfr>;

/// The enclosed cone angles of [`enclose_cone_angles`] and the vertices that took the
/// per-corner fallback.
#[derive(Clone, Debug)]
pub struct EnclosedConeAngles {
    /// `θ_v` enclosed, one per vertex (invalid where a corner of `v` is not enclosed).
    pub theta: Vec<I>,
    /// The vertices whose enclosure is the sum of enclosed corner angles (B33, "Fallback").
    pub fallback: Vec<usize>,
}

/// Per-vertex state: the enclosed running product `x + iy` of the corner directions met so
/// far, the quarter-turn index `Q` of its continuous argument (exact while `quadrant_known`),
/// and `Q` before the last corner.
struct Winding {
    x: Bounds,
    y: Bounds,
    quarter: i64,
    quarter_before_last: i64,
    quadrant_known: bool,
    corners: u32,
    failed: bool,
}

/// Scratch of one face: the Heron quantities, the cosine parts `C_i = D_i − N_i` and the
/// common sine part `S = 2√(D₀N₀) = 8·Area`, and the products of one complex step.
struct Scratch {
    face: FaceHeron,
    c: [Bounds; 3],
    sine: Bounds,
    d: Bounds,
    n: Bounds,
    p: [Bounds; 4],
}

impl Scratch {
    fn new(bits: u32) -> Scratch {
        let z = Bounds::zero(bits);
        Scratch {
            face: FaceHeron::new(bits),
            c: [z.clone(), z.clone(), z.clone()],
            sine: z.clone(),
            d: z.clone(),
            n: z.clone(),
            p: [z.clone(), z.clone(), z.clone(), z],
        }
    }

    /// The corner directions `C_i + iS` of the face with sides `l` (corner `i` opposite
    /// `l_i`): `C_i = s·e_i − e_{i+1}e_{i+2} = 4 l_{i+1}l_{i+2} cos α_i` and
    /// `S = 2√(16·Area²) = 4 l_{i+1}l_{i+2} sin α_i` (docs/catalogue.md §1; B16's kernel). Returns
    /// whether the face is a certified strict triangle with `S > 0`. proof: B33
    fn load(&mut self, l: [&I; 3]) -> bool {
        if !self.face.load(l) {
            return false;
        }
        let f = &self.face;
        for i in 0..3 {
            self.d.mul(&f.s, &f.e[i]);
            self.n.mul(&f.e[(i + 1) % 3], &f.e[(i + 2) % 3]);
            self.c[i].sub(&self.d, &self.n);
        }
        self.sine.sqrt_of(&f.area16_sq);
        self.sine.scale_pow2(1);
        self.sine.positive()
    }

    /// Multiplies the running product of `w` by the direction of corner `i` and advances
    /// its quarter count (B33, "Count").
    fn step(&mut self, i: usize, w: &mut Winding) {
        w.corners += 1;
        if w.failed {
            return;
        }
        if !w.quadrant_known && w.corners > 1 {
            // The previous product touched an axis: its quarter is not certified.
            w.failed = true;
            return;
        }
        w.quarter_before_last = w.quarter;
        let (c, s) = (&self.c[i], &self.sine);
        // (x + iy)(C + iS) = (xC − yS) + i(xS + yC)
        let [p0, p1, p2, p3] = &mut self.p;
        p0.mul(&w.x, c);
        p1.mul(&w.y, s);
        p2.mul(&w.x, s);
        p3.mul(&w.y, c);
        w.x.sub(p0, p1);
        w.y.add(p2, p3);
        // An exact power-of-two rescaling keeps the bounds' exponents near 0.
        let e = [&w.x.lo, &w.x.hi, &w.y.lo, &w.y.hi]
            .iter()
            .filter_map(|f| f.get_exp())
            .max()
            .unwrap_or(0);
        w.x.scale_pow2(-e);
        w.y.scale_pow2(-e);
        match quadrant_of(&w.x, &w.y) {
            Some(q) => {
                let d = (q - w.quarter).rem_euclid(4);
                if d == 3 {
                    // Impossible for a step in (0, π) (B33): never guess.
                    w.failed = true;
                } else {
                    w.quarter += d;
                    w.quadrant_known = true;
                }
            }
            None => w.quadrant_known = false,
        }
    }
}

/// The quadrant `q` with every point of the box `x × y` in the open quarter
/// `(qπ/2, (q+1)π/2)`, or `None` when the box meets an axis.
fn quadrant_of(x: &Bounds, y: &Bounds) -> Option<i64> {
    match (x.strict_sign()?, y.strict_sign()?) {
        (1, 1) => Some(0),
        (-1, 1) => Some(1),
        (-1, -1) => Some(2),
        _ => Some(3),
    }
}

/// Bounds of `π` at `bits`: MPFR's constant rounded toward −∞ and toward +∞.
fn pi_bounds(bits: u32) -> Bounds {
    Bounds {
        lo: Float::with_val_round(bits, Constant::Pi, Round::Down).0,
        hi: Float::with_val_round(bits, Constant::Pi, Round::Up).0,
    }
}

/// `θ = mπ/2 + atan(y'/x')` for the box `x × y` rotated by `i^{−m}`, where `m` is
/// `Q_{n−1} + 1` or `Q_{n−1} + 2` (whichever leaves the rotated box in the open right
/// half-plane); `None` when neither does. proof: B33 ("Last corner")
fn unwrap_final(w: &Winding, pi: &Bounds, bits: u32) -> Option<I> {
    let mut rx = Bounds::zero(bits);
    let mut ry = Bounds::zero(bits);
    for m in [w.quarter_before_last + 1, w.quarter_before_last + 2] {
        // i^{−m}(x + iy): m ≡ 1 → (y, −x); 2 → (−x, −y); 3 → (−y, x); 0 → (x, y). Exact.
        match m.rem_euclid(4) {
            0 => {
                rx.clone_from(&w.x);
                ry.clone_from(&w.y);
            }
            1 => {
                rx.clone_from(&w.y);
                ry.neg_of(&w.x);
            }
            2 => {
                rx.neg_of(&w.x);
                ry.neg_of(&w.y);
            }
            _ => {
                rx.neg_of(&w.y);
                ry.clone_from(&w.x);
            }
        }
        if !rx.positive() {
            continue;
        }
        let mut ratio = Bounds::zero(bits);
        ratio.div_positive(&ry, &rx);
        if ratio.lo.is_nan() || ratio.hi.is_nan() {
            return None;
        }
        let mut psi = Bounds::zero(bits);
        psi.lo.assign_round(ratio.lo.atan_ref(), Round::Down);
        psi.hi.assign_round(ratio.hi.atan_ref(), Round::Up);
        // m ≥ 1, so m·[π_lo, π_hi]/2 is increasing in π: bounds from the bounds of π.
        let mut turn = Bounds::zero(bits);
        let mi = i32::try_from(m).ok()?;
        turn.lo.assign_round(&pi.lo * mi, Round::Down);
        turn.hi.assign_round(&pi.hi * mi, Round::Up);
        turn.scale_pow2(-1);
        let mut theta = Bounds::zero(bits);
        theta.add(&turn, &psi);
        return Some(theta.to_interval());
    }
    None
}

/// Enclosed cone angles `θ_v = Σ α` (corners counted with multiplicity; 0 for a vertex
/// without corners) from enclosed edge lengths (one per edge, all at one precision), by
/// one enclosed argument per vertex of the product of its corner directions with an exact
/// quarter-turn count, falling back per vertex to the sum of enclosed corner angles where
/// the count is not certified. Every returned interval contains the exact cone angle of
/// every metric in the length enclosures (or is invalid). proof: B33
///
/// Cost: per face about forty directed-rounding MPFR operations and one square root; per
/// corner four interval products (two MPFR products each when the signs are known); per
/// vertex two arctangents (against two per corner for the per-corner sum).
///
/// ```
/// use penner::geometry::enclosure::angle_sums::enclose_cone_angles;
/// use penner::mesh::Mesh;
/// use penner::scalar::{Interval, Mpfr, Precision, Real};
/// let p = Precision::new(128).unwrap();
/// // A regular tetrahedron: three corners of π/3 at each vertex, θ = π.
/// let m = Mesh::from_faces(4, &[[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]]).unwrap();
/// let l = vec![Interval::point(Mpfr::from_f64(1.0, p)); m.n_edges()];
/// let a = enclose_cone_angles(&m, &l);
/// let pi = Interval::<Mpfr>::pi(p);
/// assert!(a.theta.iter().all(|t| t.lo().as_float() <= pi.lo().as_float()
///     && pi.hi().as_float() <= t.hi().as_float() && t.width_f64() < 1e-35));
/// ```
pub fn enclose_cone_angles(mesh: &Mesh, lengths: &[I]) -> EnclosedConeAngles {
    assert_eq!(
        lengths.len(),
        mesh.n_edges(),
        "enclose_cone_angles: one length per edge is required"
    );
    let Some(first) = lengths.first() else {
        return EnclosedConeAngles {
            theta: Vec::new(),
            fallback: Vec::new(),
        };
    };
    let bits = first.lo().as_float().prec();
    let mut one = Bounds::zero(bits);
    one.set_int(1);
    let start = Winding {
        x: one,
        y: Bounds::zero(bits),
        quarter: 0,
        quarter_before_last: 0,
        quadrant_known: true,
        corners: 0,
        failed: false,
    };
    let mut acc: Vec<Winding> = (0..mesh.n_vertices())
        .map(|_| Winding {
            x: start.x.clone(),
            y: start.y.clone(),
            ..start
        })
        .collect();
    let mut sc = Scratch::new(bits);
    for f in mesh.faces() {
        let hs = mesh.face_halfedges(f);
        let ok = sc.load(hs.map(|h| &lengths[h.edge().idx()]));
        for i in 0..3 {
            // Corner opposite hs[i] is at the tail of hs[(i+2)%3].
            let w = &mut acc[mesh.tail(hs[(i + 2) % 3]).idx()];
            if ok {
                sc.step(i, w);
            } else {
                w.corners += 1;
                w.failed = true;
            }
        }
    }
    let pi = pi_bounds(bits);
    let mut fallback = Vec::new();
    let mut theta: Vec<I> = acc
        .iter()
        .enumerate()
        .map(|(v, w)| {
            if w.corners == 0 {
                return first.zero_like();
            }
            let t = if w.failed {
                None
            } else {
                unwrap_final(w, &pi, bits)
            };
            t.unwrap_or_else(|| {
                fallback.push(v);
                first.zero_like()
            })
        })
        .collect();
    if !fallback.is_empty() {
        let mut is_fallback = vec![false; mesh.n_vertices()];
        for &v in &fallback {
            is_fallback[v] = true;
        }
        for f in mesh.faces() {
            let hs = mesh.face_halfedges(f);
            for i in 0..3 {
                let v = mesh.tail(hs[(i + 2) % 3]).idx();
                if is_fallback[v] {
                    let len = |k: usize| &lengths[hs[(i + k) % 3].edge().idx()];
                    theta[v] += &corner_angle(len(0), len(1), len(2));
                }
            }
        }
    }
    EnclosedConeAngles { theta, fallback }
}

#[cfg(test)]
#[path = "angle_sums_terms.rs"]
mod terms;
