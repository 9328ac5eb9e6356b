//! The scale factors `e^{u_v/2}` of the refinement ([`super::refine`]), carried from one
//! iterate to the next by the exponential of the step.
//!
//! The refinement's steps are small (about `10⁻¹²`, then `10⁻²⁴`, `10⁻⁴⁸` per vertex), and
//! `e^{(u + δ)/2} = e^{u/2}·e^{δ/2}` with `e^{δ/2}` from a few terms of its Taylor series —
//! seven at `|δ| ≈ 10⁻¹²` and 256 bits, two at `10⁻⁴⁸` — in place of a full exponential per
//! vertex at every iterate. Each update rounds a few times more than a fresh exponential
//! (relative error a few units of the precision per step); nothing here is certified: the
//! certificate recomputes its lengths in interval arithmetic.

use crate::mesh::Mesh;
use crate::scalar::Real;

/// Steps above this are exponentiated afresh.
const SMALL_STEP: f64 = 1.0 / 1_048_576.0;

/// The terms `N` of `Σ_{n<N} xⁿ/n!` that bring the truncation `|x|^N/N!` (times the
/// geometric tail, below 2 for `|x| ≤ 1/2`) below `2^{−bits−8}` for `|x| ≤ x_abs`.
pub(crate) fn taylor_terms(x_abs: f64, bits: u32) -> usize {
    let target = 2f64.powi(-(bits.min(1000) as i32) - 8);
    let mut term = 1.0;
    let mut n = 0;
    while term * 2.0 > target && n < 200 {
        n += 1;
        term *= x_abs / n as f64;
        if term == 0.0 {
            break;
        }
    }
    n.max(1)
}

/// `e^x` for `|x| ≤ 2⁻²⁰` by Horner on the first [`taylor_terms`] terms of its series.
pub(crate) fn exp_small<T: Real>(x: &T, terms: usize) -> T {
    let one = x.one_like();
    let mut s = one.clone();
    for n in (1..terms).rev() {
        s = one.clone() + &(s * x / &x.lit(n as f64));
    }
    s
}

/// `e^{u_v/2}` per vertex at the last `u` seen.
pub(crate) struct HalfExp<T> {
    u: Vec<T>,
    factor: Vec<T>,
}

impl<T: Real> HalfExp<T> {
    /// The factors at `u`, one exponential each.
    pub(crate) fn new(u: &[T]) -> Self {
        let factor = u.iter().map(half_exp).collect();
        HalfExp {
            u: u.to_vec(),
            factor,
        }
    }

    /// Move to `u`: each factor times `e^{δ/2}`, `δ = u_v − u_v^{old}` (by its series when
    /// `|δ| ≤ 2⁻²⁰`, else a fresh exponential of `u_v/2`).
    pub(crate) fn update(&mut self, u: &[T], ctx: T::Ctx) {
        let bits = T::precision_bits(ctx);
        for ((old, f), new) in self.u.iter_mut().zip(&mut self.factor).zip(u) {
            let d = new.clone() - &*old;
            let d_abs = d.approx_f64().abs();
            if d_abs == 0.0 {
                continue;
            }
            if d_abs <= SMALL_STEP {
                let half = d * &new.lit(0.5);
                *f *= &exp_small(&half, taylor_terms(0.5 * d_abs, bits));
            } else {
                *f = half_exp(new);
            }
            *old = new.clone();
        }
    }

    /// The scaled lengths `e^{u_i/2}·e^{u_j/2}·ℓ_ij` of `mesh` from `base`.
    pub(crate) fn lengths(&self, mesh: &Mesh, base: &[T]) -> Vec<T> {
        mesh.edges()
            .map(|e| {
                let h = e.halfedge();
                self.factor[mesh.tail(h).idx()].clone()
                    * &self.factor[mesh.tip(h).idx()]
                    * &base[e.idx()]
            })
            .collect()
    }
}

fn half_exp<T: Real>(x: &T) -> T {
    (x.clone() * &x.lit(0.5)).exp()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scalar::{Mpfr, Precision};

    /// [`exp_small`] with [`taylor_terms`] for 256 bits against MPFR's own `exp`: at 256
    /// bits within `2⁻²⁵⁰` relative (truncation below `2⁻²⁶⁴` plus a few roundings per
    /// term); evaluated at 512 bits, where rounding is negligible, the truncation itself is
    /// below `2⁻²⁶³` (the bound `2^{−bits−8}` with the tail's factor 2), and the control —
    /// one term fewer — is above `2⁻²⁶⁷`: the count is the least that meets the bound, at
    /// steps from `2⁻²⁰` down to `10⁻⁴⁸`.
    #[test]
    fn the_series_matches_the_exponential_at_256_bits() {
        let rel = |a: &Mpfr, b: &Mpfr| ((a.clone() - b) / b).approx_f64().abs();
        for x in [SMALL_STEP, -3e-7, 1e-12, -7e-13, 1e-24, 1e-48] {
            let n = taylor_terms(x.abs(), 256);
            assert!(n >= 2, "x {x:e}: {n} terms");
            let p = Precision::new(256).expect("bits");
            let xm = Mpfr::from_f64(x, p);
            let err = rel(&exp_small(&xm, n), &xm.exp());
            assert!(err <= 2f64.powi(-250), "x {x:e}: {n} terms, {err:e}");
            let wide = Precision::new(512).expect("bits");
            let xw = Mpfr::from_f64(x, wide);
            let exact = xw.exp();
            let truncation = rel(&exp_small(&xw, n), &exact);
            assert!(truncation <= 2f64.powi(-263), "x {x:e}: {truncation:e}");
            let short = rel(&exp_small(&xw, n - 1), &exact);
            assert!(
                short > 2f64.powi(-267),
                "x {x:e}: {} terms already {short:e}",
                n - 1
            );
        }
    }

    /// [`HalfExp::update`] tracks `e^{u/2}` along small and large steps, within `2⁻²⁴⁵`
    /// relative of a fresh 256-bit exponential; the control: factors left at the start
    /// (never updated) differ from the fresh ones by more than that after every step.
    #[test]
    fn carried_factors_match_fresh_exponentials() {
        let p = Precision::new(256).expect("bits");
        let u0: Vec<Mpfr> = [0.3, -1.2, 2.5]
            .iter()
            .map(|&x| Mpfr::from_f64(x, p))
            .collect();
        let mut h = HalfExp::new(&u0);
        let stale = HalfExp::new(&u0);
        let mut u = u0;
        for step in [1e-12, -3e-25, 0.25, 1e-48] {
            u = u
                .iter()
                .map(|x| x.clone() + &Mpfr::from_f64(step, p))
                .collect();
            h.update(&u, p);
            for ((f, old), x) in h.factor.iter().zip(&stale.factor).zip(&u) {
                let fresh = (x.clone() * &x.lit(0.5)).exp();
                let rel = |y: &Mpfr| ((y.clone() - &fresh) / &fresh).approx_f64().abs();
                assert!(rel(f) <= 2f64.powi(-245), "step {step:e}: {:e}", rel(f));
                // Control.
                assert!(
                    rel(old) > 2f64.powi(-245),
                    "step {step:e}: stale {:e}",
                    rel(old)
                );
            }
        }
    }
}
