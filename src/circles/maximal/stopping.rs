//! The stopping rule of the refinement tied to the tangency tolerance `ε` of the layout
//! (proofs/B99). The layout turns an angle residual `δ = max |2π − θ|` into tangency
//! defects up to `K·δ`, with `K` growing with the size of the triangulation and the
//! smallness of its circles (a rotation error about a circle near the unit circle moves far
//! circles by about `δ/(1 − |z|²)`), so no residual fixed in advance suits every `n`: the
//! refinement starts at `δ₀ = ε/(2⁴·n)`, lays out, measures the largest defect `D` in the
//! working precision, and while `D > ε/2⁴` refines again to `δ·(ε/2⁴)/(4D)`, no lower than
//! the floor `2⁶·n·u` the working precision supports. Rounding in the layout is amplified
//! alike (about `0.7·n²·u` at `n = 10⁴`, measured), so the working precision itself must
//! grow with `n` and `1/ε`: [`bits_for`]. The measurement reads `approx_f64`: it steers the
//! computation only; the verdict on the circles is B95's certificate.

use super::layout::Circle;
use crate::mesh::Mesh;
use crate::scalar::Real;

/// The margin `2⁴`: the refinement aims at defects below `ε/2⁴`.
pub const MARGIN: f64 = 16.0;

/// Rounds of refine-and-lay-out after the first (each at least 4× tighter).
pub const MAX_ROUNDS: usize = 6;

/// The largest tangency defect of the laid-out circles, evaluated in `T` and read as `f64`
/// (a heuristic, proofs/B99): `|‖c_i − c_j‖ − (ρ_i + ρ_j)|` over the edges and
/// `|1 − ‖c_v‖ − ρ_v|` over the boundary vertices (`interior[v] = false`). `+∞` when a
/// value is not finite.
pub fn layout_defect<T: Real>(mesh: &Mesh, circles: &[Circle<T>], interior: &[bool]) -> f64 {
    let norm = |x: &T, y: &T| (x.clone() * x + &(y.clone() * y)).sqrt();
    let mut worst = 0.0_f64;
    let mut see = |d: T| {
        let d = d.approx_f64().abs();
        worst = if d.is_finite() {
            worst.max(d)
        } else {
            f64::INFINITY
        };
    };
    for e in mesh.edges() {
        let h = e.halfedge();
        let (a, b) = (&circles[mesh.tail(h).idx()], &circles[mesh.tip(h).idx()]);
        let dx = a.centre[0].clone() - &b.centre[0];
        let dy = a.centre[1].clone() - &b.centre[1];
        see(norm(&dx, &dy) - &(a.radius.clone() + &b.radius));
    }
    for (c, _) in circles.iter().zip(interior).filter(|&(_, &i)| !i) {
        see(c.radius.one_like() - &norm(&c.centre[0], &c.centre[1]) - &c.radius);
    }
    worst
}

/// The first residual to refine to for tolerance `eps` on `n` vertices: `ε/(2⁴·n)`, no
/// lower than `floor`.
pub fn first_tolerance(eps: f64, n: usize, floor: f64) -> f64 {
    (eps / (MARGIN * n.max(1) as f64)).max(floor)
}

/// The next residual after a layout with largest defect `defect` refined to `tol`:
/// `tol·(ε/2⁴)/(4·defect)`, at least 4× below `tol`; `None` when the layout is within
/// `ε/2⁴` already or the next residual would be below `floor`.
pub fn next_tolerance(tol: f64, defect: f64, eps: f64, floor: f64) -> Option<f64> {
    let aim = eps / MARGIN;
    if defect <= aim {
        return None;
    }
    let next = if defect.is_finite() {
        (tol * aim / (4.0 * defect)).min(tol / 4.0)
    } else {
        tol / 4.0
    };
    (next >= floor).then_some(next)
}

/// The working precision for a layout within `eps` on `n` vertices: the bits `p` with
/// `2¹⁶·n²·2⁻ᵖ ≤ ε` (the measured rounding amplification `n²·u` with a margin `2¹⁶`), at
/// least 128 (proofs/B99). `eps` is clamped to `[2⁻¹⁰⁰⁰, 1]`.
pub fn bits_for(eps: f64, n: usize) -> u32 {
    let e = eps.clamp(2f64.powi(-1000), 1.0);
    let n = n.max(1) as f64;
    let p = (16.0 + 2.0 * n.log2() - e.log2()).ceil();
    (p as u32).max(128)
}

/// The precision for a second run after a layout at `bits` whose measured defect `defect`
/// stayed above `ε/2⁴`: `bits + ⌈log₂(defect·2⁴/ε)⌉ + 8` (the defect of a precision-limited
/// layout scales with `2⁻ᵖ`); `None` when the defect is within the aim or not finite, or
/// the result would exceed 2¹⁶ bits.
pub fn bits_after(bits: u32, defect: f64, eps: f64) -> Option<u32> {
    let aim = eps / MARGIN;
    let wanted = defect > aim && defect.is_finite() && aim > 0.0;
    if !wanted {
        return None;
    }
    let extra = (defect / aim).log2().ceil() as u32 + 8;
    let b = bits.saturating_add(extra);
    (b <= 1 << 16).then_some(b)
}
