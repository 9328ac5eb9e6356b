//! Cone angles θ_v: the sum of corner angles at each vertex.
//!
//! Kernel (proofs B15, B16): instead of one arctangent per corner, each corner contributes
//! the direction `e^{iα} = cos α + i sin α`, formed without any transcendental function
//! from the half-angle quantities of its triangle (shared by the three corners of a face),
//! and the vertex multiplies them: `Π e^{iα_k} = e^{iθ_v}`. Along the way the vertex counts
//! the quarter turns of the running product exactly, from the signs of its two components
//! (B15); one `atan2` per vertex, taken a quarter turn away from any branch cut, gives the
//! remainder. No per-corner arctangent, no estimate, no fallback.

use crate::mesh::{HalfEdge, Mesh};
use crate::scalar::Real;

/// The quadrant `q ∈ {0, 1, 2, 3}` of the nonzero point `re + i·im`: the index of the
/// half-open arc `[qπ/2, (q+1)π/2)` of `[0, 2π)` holding its argument. So 0 for
/// `re > 0, im ≥ 0`; 1 for `re ≤ 0, im > 0`; 2 for `re < 0, im ≤ 0`; 3 for `re ≥ 0, im < 0`
/// (`−0.0` counts as 0). proof: B15
///
/// ```
/// use penner::geometry::cone_angles::quadrant;
/// // The arguments 0, π/2, π, 3π/2 open the four arcs.
/// assert_eq!([quadrant(1.0, 0.0), quadrant(0.0, 1.0), quadrant(-1.0, 0.0), quadrant(0.0, -1.0)], [0, 1, 2, 3]);
/// assert_eq!(quadrant(1.0, -1e-300), 3);
/// ```
#[inline]
pub fn quadrant(re: f64, im: f64) -> i64 {
    // Argument in [π, 2π); then the second half of its half turn. Bitwise operators on
    // integers keep this free of branches (the quadrants of a running product are unpredictable).
    let bit = u8::from;
    let lower = bit(im < 0.0) | (bit(im == 0.0) & bit(re < 0.0));
    let second = (lower & bit(re >= 0.0)) | ((1 ^ lower) & bit(re <= 0.0));
    2 * i64::from(lower) + i64::from(second)
}

/// The quarter-turn index `Q' = ⌊Φ'/(π/2)⌋` of a path point after one step, given the
/// index `Q = ⌊Φ/(π/2)⌋` before it, the components of the new point (only their signs are
/// read) and whether the step's direction is obtuse (`cos < 0`, step in `(π/2 − η, π + η]`)
/// or not (step in `[−η, π/2 + η]`), for a per-step argument error `η < π/2`.
///
/// The change `Q' − Q` is the representative of `quadrant(re, im) − Q (mod 4)` in
/// `{−1, 0, 1, 2}` for a non-obtuse step and in `{0, 1, 2, 3}` for an obtuse one. proof: B15
///
/// ```
/// use penner::geometry::cone_angles::quarter_step;
/// // From Q = 3 (argument just below 2π) a small step forward lands in quadrant 0: Q = 4.
/// assert_eq!(quarter_step(3, 1.0, 1e-3, false), 4);
/// // A small step backwards from Q = 4 (argument just above 2π): Q = 3.
/// assert_eq!(quarter_step(4, 1.0, -1e-3, false), 3);
/// // An obtuse step of almost π from quadrant 0 lands in quadrant 2: Q = 2, not −2.
/// assert_eq!(quarter_step(0, -1.0, -1e-3, true), 2);
/// ```
#[inline]
pub fn quarter_step(quarter: i64, re: f64, im: f64, obtuse: bool) -> i64 {
    let shift = i64::from(!obtuse);
    quarter + ((quadrant(re, im) - quarter + shift) & 3) - shift
}

/// The angle `m·π/2 + atan2(i^{−m}(re + i·im))`, with `half_pi` = π/2 in the context of
/// `re`: the argument of `re + i·im` unwrapped around the quarter turn `m`.
///
/// The rotation by `i^{−m}` is exact (swaps and sign changes). When `m` is the quarter-turn
/// index of the continuous argument Φ (Φ ∈ [mπ/2, (m+1)π/2)), the rotated point has its
/// argument in `[0, π/2)`, a quarter turn away from the branch cut of `atan2`, and the
/// result is Φ up to the error of `atan2` and one rounding of `m·π/2`. proof: B15
pub fn unwrap_quarter<T: Real>(re: &T, im: &T, m: i64, half_pi: &T) -> T {
    let (x, y) = match m.rem_euclid(4) {
        0 => (re.clone(), im.clone()),
        1 => (im.clone(), -re.clone()),
        2 => (-re.clone(), -im.clone()),
        _ => (-im.clone(), re.clone()),
    };
    let turn = half_pi.clone() * &half_pi.lit(m as f64);
    y.atan2(&x) + &turn
}

/// The angle `θ` with `e^{iθ} ∝ re + i·im` that lies within 3π/4 of `estimate`, for an
/// `estimate` within `3π/4 − ε` of the true angle (ε: the error of the computed argument):
/// [`unwrap_quarter`] with `m = round(estimate / (π/2))`. proof: B15
///
/// ```
/// use penner::geometry::cone_angles::unwrap_angle;
/// // The point e^{i·0.3}, unwrapped near 2π + 0.3.
/// let (re, im) = (0.3_f64.cos(), 0.3_f64.sin());
/// let t = unwrap_angle(&re, &im, 6.0);
/// assert!((t - (2.0 * std::f64::consts::PI + 0.3)).abs() < 1e-14);
/// ```
pub fn unwrap_angle<T: Real>(re: &T, im: &T, estimate: f64) -> T {
    let m = (estimate / std::f64::consts::FRAC_PI_2).round() as i64;
    let half_pi = T::pi(re.ctx()) * &re.lit(0.5);
    unwrap_quarter(re, im, m, &half_pi)
}

/// Per-vertex state: the running product `re + i·im` of corner directions and the
/// quarter-turn index of its continuous argument.
#[derive(Clone)]
struct Winding<T> {
    re: T,
    im: T,
    quarter: i64,
}

/// Scratch values of one face, reused for every face (no allocation per face for MPFR).
struct FaceScratch<T> {
    /// Partial sums.
    t: T,
    /// `a + b + c`.
    s: T,
    /// `e_i = l_{i+1} + l_{i+2} − l_i`.
    e: [T; 3],
    /// `D_i = s·e_i`, then `D_i − N_i` (the unnormalized cosine part), then `cos α_i`.
    c: [T; 3],
    /// `N_i = e_{i+1}·e_{i+2}`.
    n: T,
    /// `2√(D_i N_i) = 2√(s e_0 e_1 e_2)` (the same for all three corners: 8·area).
    r: T,
    /// Products of the complex multiplication.
    p: T,
    q: T,
}

impl<T: Real> FaceScratch<T> {
    fn new(like: &T) -> Self {
        let z = like.zero_like();
        FaceScratch {
            t: z.clone(),
            s: z.clone(),
            e: [z.clone(), z.clone(), z.clone()],
            c: [z.clone(), z.clone(), z.clone()],
            n: z.clone(),
            r: z.clone(),
            p: z.clone(),
            q: z,
        }
    }

    /// The unnormalized cosine parts `D_i − N_i` of the three corners of the triangle with
    /// sides `l = [l_0, l_1, l_2]` (corner `i` opposite `l_i`) into `c`, and the common sine
    /// part `2√(D_i N_i)` into `r` (docs/catalogue.md §1: `tan²(α_i/2) = N_i/D_i`, so
    /// `(√D_i + i√N_i)² = (D_i − N_i) + 2i√(D_i N_i) ∝ e^{iα_i}`, of modulus
    /// `D_i + N_i = 4 l_{i+1} l_{i+2}`). proof: B16
    fn load(&mut self, l: [&T; 3]) {
        let [a, b, c] = l;
        self.t.clone_from(b);
        self.t += c;
        self.e[0].clone_from(&self.t);
        self.e[0] -= a;
        self.s.clone_from(&self.t);
        self.s += a;
        self.t.clone_from(a);
        self.t -= b;
        self.e[1].clone_from(&self.t);
        self.e[1] += c;
        self.t.clone_from(a);
        self.t += b;
        self.e[2].clone_from(&self.t);
        self.e[2] -= c;
        for i in 0..3 {
            self.c[i].clone_from(&self.s);
            self.c[i] *= &self.e[i];
        }
        // N_0, then 16·area² = D_0·N_0.
        self.n.clone_from(&self.e[1]);
        self.n *= &self.e[2];
        self.t.clone_from(&self.c[0]);
        self.t *= &self.n;
        self.c[0] -= &self.n;
        self.r = self.t.sqrt();
        self.r.ldexp_assign(1);
        self.n.clone_from(&self.e[2]);
        self.n *= &self.e[0];
        self.c[1] -= &self.n;
        self.n.clone_from(&self.e[0]);
        self.n *= &self.e[1];
        self.c[2] -= &self.n;
    }

    /// Multiplies the running product of `acc` by the (unnormalized) direction
    /// `c_i + i·r` of corner `i`, advances its quarter-turn index, and rescales it by the
    /// power of two that brings its larger component into `[1, 2)` (exact: only the
    /// modulus changes, and it stays in `[1, 2√2)` for any number of corners).
    /// proof: B15, B16
    fn step(&mut self, i: usize, acc: &mut Winding<T>) {
        let wr = &self.c[i];
        let obtuse = wr.approx_f64() < 0.0;
        // (re + i·im)(wr + i·r) = (re·wr − im·r) + i(im·wr + re·r)
        self.p.clone_from(&acc.re);
        self.p *= &self.r;
        self.q.clone_from(&acc.im);
        self.q *= &self.r;
        acc.re *= wr;
        acc.re -= &self.q;
        acc.im *= wr;
        acc.im += &self.p;
        let (x, y) = (acc.re.approx_f64(), acc.im.approx_f64());
        acc.quarter = quarter_step(acc.quarter, x, y, obtuse);
        let k = -exponent(x.abs().max(y.abs()));
        acc.re.ldexp_assign(k);
        acc.im.ldexp_assign(k);
    }
}

/// The binary exponent `⌊log₂ x⌋` of a positive normal `f64`, clamped to `[−1000, 1000]`
/// (0 for zero, subnormal or non-finite input: the rescaling is then skipped in effect).
#[inline]
fn exponent(x: f64) -> i32 {
    let e = ((x.to_bits() >> 52) & 0x7ff) as i32;
    if e == 0 || e == 0x7ff {
        0
    } else {
        (e - 1023).clamp(-1000, 1000)
    }
}

/// Cone angle `θ_v = Σ α_v` over all corners at `v` (docs/catalogue.md §2), from per-edge lengths
/// `lengths[e]` (indexed by `Edge::idx`). Corners are counted with multiplicity (a face may
/// have a vertex twice); a vertex without corners gets 0.
///
/// Cost per face: seven additions, seven multiplications and one square root for the three
/// corner directions; per corner a complex multiplication, three sign reads and an exact
/// rescaling by a power of two; per vertex one `atan2` ([`unwrap_quarter`]). No
/// transcendental function per corner. The quarter-turn count is exact for the computed product (proof: B15), so
/// the error is that of a product of unit complex numbers, comparable to the per-corner
/// sum (proof: B16).
///
/// For enclosure types ([`Real::is_point`] false, e.g. `Interval<Mpfr>`) the result is
/// [`cone_angles_per_corner`]: the quarter count reads signs through `approx_f64`, which
/// for an enclosure is a midpoint, while a sum of enclosed corner angles is rigorous.
///
/// Lengths violating the triangle inequality give NaN (f64) — callers validate lengths
/// first (see `predicates`). Lengths must lie within about 2^±250, so that the
/// unnormalized directions (modulus `4bc`) and their products with the running product
/// stay in the normal range of every backend.
///
/// ```
/// use penner::geometry::cone_angles::cone_angles;
/// use penner::mesh::Mesh;
/// // A regular tetrahedron: three equilateral corners (π/3 each) at every vertex.
/// let m = Mesh::from_faces(4, &[[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]]).unwrap();
/// let theta = cone_angles(&m, &vec![1.0_f64; m.n_edges()]);
/// assert!(theta.iter().all(|t| (t - std::f64::consts::PI).abs() < 1e-14));
/// ```
pub fn cone_angles<T: Real>(mesh: &Mesh, lengths: &[T]) -> Vec<T> {
    assert_eq!(
        lengths.len(),
        mesh.n_edges(),
        "cone_angles: one length per edge is required"
    );
    if !T::is_point() {
        // Enclosures: the quarter count would follow midpoints (B15, Limits); the sum of
        // enclosed corner angles in (0, π) is rigorous and needs no count.
        return cone_angles_per_corner(mesh, lengths);
    }
    winding_cone_angles(mesh, lengths, |_, _, _| {})
}

/// [`cone_angles`] and, from the same per-face quantities, the cotangent of the corner
/// opposite every half-edge of a face (`cot[h]`, indexed by `HalfEdge::idx`; boundary
/// half-edges keep the value they had): the direction of corner `i` is `c_i + i·r`
/// ([`cone_angles`]' kernel, B16), so `cot α_i = c_i / r` at the cost of one division per
/// corner. The cone angles are those of [`cone_angles`], bit for bit. Point types only:
/// for enclosures ([`Real::is_point`] false) the cotangents come from
/// [`halfedge_cotans`](super::cotan::halfedge_cotans) and the angles from
/// [`cone_angles_per_corner`]. A degenerate face (`r = 0`) gives infinite or NaN
/// cotangents, as the formula does.
pub fn cone_angles_and_cotans<T: Real>(mesh: &Mesh, lengths: &[T], cot: &mut [T]) -> Vec<T> {
    assert_eq!(
        lengths.len(),
        mesh.n_edges(),
        "cone_angles_and_cotans: one length per edge is required"
    );
    assert_eq!(
        cot.len(),
        mesh.n_halfedges(),
        "cone_angles_and_cotans: one cotangent slot per half-edge is required"
    );
    if !T::is_point() {
        for (slot, c) in cot
            .iter_mut()
            .zip(super::cotan::halfedge_cotans(mesh, lengths))
        {
            *slot = c;
        }
        return cone_angles_per_corner(mesh, lengths);
    }
    winding_cone_angles(mesh, lengths, |h, sc, i| {
        cot[h.idx()] = sc.c[i].clone() / &sc.r;
    })
}

/// The kernel of [`cone_angles`] (B16): every face's corner directions `c_i + i·r`
/// multiplied into one winding per vertex, `at_corner(h, scratch, i)` called for the corner
/// opposite half-edge `h = hs[i]` of each face before its direction is multiplied in.
fn winding_cone_angles<T: Real>(
    mesh: &Mesh,
    lengths: &[T],
    mut at_corner: impl FnMut(HalfEdge, &FaceScratch<T>, usize),
) -> Vec<T> {
    let Some(first) = lengths.first() else {
        return Vec::new();
    };
    let start = Winding {
        re: first.one_like(),
        im: first.zero_like(),
        quarter: 0,
    };
    let mut acc = vec![start; mesh.n_vertices()];
    let mut sc = FaceScratch::new(first);
    for f in mesh.faces() {
        let hs = mesh.face_halfedges(f);
        sc.load(hs.map(|h| &lengths[h.edge().idx()]));
        for i in 0..3 {
            at_corner(hs[i], &sc, i);
            // Corner opposite hs[i] is at the tail of hs[(i+2)%3].
            sc.step(i, &mut acc[mesh.tail(hs[(i + 2) % 3]).idx()]);
        }
    }
    let half_pi = T::pi(first.ctx()) * &first.lit(0.5);
    acc.iter()
        .map(|w| unwrap_quarter(&w.re, &w.im, w.quarter, &half_pi))
        .collect()
}

/// The straightforward cone angles: one [`corner_angle`](super::triangle::corner_angle)
/// (an arctangent) per corner, summed in `T`. Slower than [`cone_angles`]; kept as an
/// independent reference for tests and benchmarks.
pub fn cone_angles_per_corner<T: Real>(mesh: &Mesh, lengths: &[T]) -> Vec<T> {
    assert_eq!(
        lengths.len(),
        mesh.n_edges(),
        "cone_angles_per_corner: one length per edge is required"
    );
    let Some(first) = lengths.first() else {
        return Vec::new();
    };
    let mut theta = vec![first.zero_like(); mesh.n_vertices()];
    for f in mesh.faces() {
        let hs = mesh.face_halfedges(f);
        for i in 0..3 {
            let a = &lengths[hs[i].edge().idx()];
            let b = &lengths[hs[(i + 1) % 3].edge().idx()];
            let c = &lengths[hs[(i + 2) % 3].edge().idx()];
            let v = mesh.tail(hs[(i + 2) % 3]).idx();
            theta[v] += &super::triangle::corner_angle(a, b, c);
        }
    }
    theta
}
