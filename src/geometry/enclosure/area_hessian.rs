//! The Hessian of `−2A` of one triangle in its squared side lengths `q = (ℓ₀², ℓ₁², ℓ₂²)`,
//! enclosed. proof: B102
//!
//! With `A = ¼√Q`, `Q(q) = qᵀMq = 2(q₀q₁ + q₁q₂ + q₂q₀) − q₀² − q₁² − q₂²` (`M` has `−1` on
//! the diagonal and `1` off it) and `cot α_i = (Mq)_i/√Q` (the corner opposite side `i`,
//! B34), differentiating `∇A = Mq/(4√Q)` once more gives
//!
//! `−2 ∂²A/∂q_i∂q_j = (cot α_i cot α_j − M_ij) / (8A)`,
//!
//! i.e. `(1 + cot² α_i)/(8A) = 1/(8A sin² α_i)` on the diagonal and
//! `(cot α_i cot α_j − 1)/(8A)` off it. Every bound is one directed-rounding MPFR operation
//! (B20), then rounded outward to binary64.

use super::{Bounds, FaceHeron};
use crate::scalar::{Interval, Mpfr};
use rug::float::Round;

type I = Interval<Mpfr>;

/// Outward binary64 bounds `(lo, hi)` of the nine entries `−2 ∂²A/∂q_i∂q_j` of one face
/// (`i`, `j` its sides in the order given).
pub type FaceHessianBounds = [[(f64, f64); 3]; 3];

/// Scratch space for [`AreaHessianKernel::face`] at one MPFR precision: no allocation per
/// face.
pub struct AreaHessianKernel {
    face: FaceHeron,
    sq: [Bounds; 3],
    cot: [Bounds; 3],
    area8: Bounds,
    t: Bounds,
    num: Bounds,
    entry: Bounds,
    one: Bounds,
}

impl AreaHessianKernel {
    /// A kernel whose bounds carry `bits` bits.
    pub fn new(bits: u32) -> AreaHessianKernel {
        let z = Bounds::zero(bits);
        let mut one = z.clone();
        one.set_int(1);
        AreaHessianKernel {
            face: FaceHeron::new(bits),
            sq: [z.clone(), z.clone(), z.clone()],
            cot: [z.clone(), z.clone(), z.clone()],
            area8: z.clone(),
            t: z.clone(),
            num: z.clone(),
            entry: z,
            one,
        }
    }

    /// Whether every triangle with sides in `l` is certified strict (every side and every
    /// Heron factor `ℓ_j + ℓ_k − ℓ_i` enclosed as positive): then `16A² = qᵀMq > 0`, the
    /// squared lengths lie in the open forward cone of `M`, and `−2∇²A` is positive
    /// semidefinite with kernel `span(q)` (proof: B103).
    pub fn strict(&mut self, l: [&I; 3]) -> bool {
        self.face.load(l)
    }

    /// Outward binary64 bounds of `−2 ∂²A/∂q_i∂q_j` (module formula) for every triangle
    /// whose sides lie in the enclosures `l` (side `i` opposite corner `i`), or `None` when
    /// the face is not certified a strict triangle (a side or a Heron factor not enclosed
    /// as positive: the squared lengths are then not proven interior to the cone where
    /// `A` is smooth, B102) or a bound is not finite in binary64. proof: B102
    ///
    /// ```
    /// use penner::geometry::enclosure::area_hessian::AreaHessianKernel;
    /// use penner::scalar::{Interval, Mpfr, Precision, Real};
    /// let p = Precision::new(128).unwrap();
    /// let one = Interval::point(Mpfr::from_f64(1.0, p));
    /// let h = AreaHessianKernel::new(128).face([&one, &one, &one]).unwrap();
    /// // Equilateral, side 1: 8A = 2√3, cot = 1/√3: diagonal 2/(3√3), off-diagonal −1/(3√3).
    /// let (d, o) = (2.0 / (3.0 * 3f64.sqrt()), -1.0 / (3.0 * 3f64.sqrt()));
    /// assert!(h[0][0].0 <= d && d <= h[0][0].1 && h[0][0].1 - h[0][0].0 < 1e-15);
    /// assert!(h[1][2].0 <= o && o <= h[1][2].1);
    /// ```
    pub fn face(&mut self, l: [&I; 3]) -> Option<FaceHessianBounds> {
        if !self.face.load(l) {
            return None;
        }
        for (q, x) in self.sq.iter_mut().zip(&self.face.l) {
            q.mul(x, x);
        }
        // 8A = 2√(16A²).
        self.area8.sqrt_of(&self.face.area16_sq);
        self.area8.scale_pow2(1);
        self.t.sqrt_of(&self.face.area16_sq);
        for i in 0..3 {
            self.num.add(&self.sq[(i + 1) % 3], &self.sq[(i + 2) % 3]);
            self.entry.sub(&self.num, &self.sq[i]);
            self.cot[i].div_positive(&self.entry, &self.t);
        }
        let mut out = [[(0.0, 0.0); 3]; 3];
        #[allow(clippy::needless_range_loop)] // (i, j) and (j, i) are filled together
        for i in 0..3 {
            for j in i..3 {
                self.t.mul(&self.cot[i], &self.cot[j]);
                if i == j {
                    self.num.add(&self.t, &self.one);
                } else {
                    self.num.sub(&self.t, &self.one);
                }
                self.entry.div_positive(&self.num, &self.area8);
                let lo = self.entry.lo.to_f64_round(Round::Down);
                let hi = self.entry.hi.to_f64_round(Round::Up);
                if !(lo.is_finite() && hi.is_finite() && lo <= hi) {
                    return None;
                }
                out[i][j] = (lo, hi);
                out[j][i] = (lo, hi);
            }
        }
        Some(out)
    }
}
