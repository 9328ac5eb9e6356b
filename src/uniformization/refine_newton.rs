//! The Newton correction of the refinement ([`super::refine`]) with the Hessian at the
//! current iterate in double-double.
//!
//! The refinement factors the grounded Hessian `H̃` once, in `f64`, at the `f64` solution
//! `u₀`. A correction `−H̃⁻¹(Θ − θ(u_k))` contracts the error by `‖I − H̃⁻¹H(u_k)‖`, about
//! `|u_k − u₀|` relative, so each step gains the `f64` solve's accuracy (about twelve
//! digits on the benchmark meshes) and `10⁻⁶⁰` takes five steps. Here the correction
//! solves `H(u_k) δ = −(Θ − θ(u_k))` instead, with `H(u_k) = −L` the cotan Laplacian of the
//! scaled lengths at `u_k` in double-double, by iterative refinement preconditioned with
//! `H̃` (`δ ← δ + H̃⁻¹(−r − H(u_k)δ)`, each sweep again contracting by `‖I − H̃⁻¹H(u_k)‖`):
//! a Newton step at `u_k` up to double-double rounding, so the residual falls as
//! `max(C·r², 2⁻¹⁰⁰·r)` — about `10⁻¹²`, `10⁻²⁴`, `10⁻⁴⁸`, `10⁻⁷²` — and `10⁻⁶⁰` takes
//! three steps. Nothing here is certified: the certificate (B71) judges the `u` it gets.

use super::hessian::{newton_direction, Factor};
use crate::geometry::triangle::cot_opposite;
use crate::mesh::{HalfEdge, Mesh};
use crate::scalar::{Dd, Real};

/// Inner sweeps at most (each gains about twelve digits; three reach double-double).
const MAX_SWEEPS: usize = 4;
/// The sweeps stop when the linear residual is below this fraction of `max |r|`: double-double's
/// unit roundoff `2⁻¹⁰⁴` ([`Real::unit_roundoff`]), about the rounding of the residual's
/// own evaluation, past which a sweep cannot gain.
fn sweep_tolerance() -> f64 {
    <Dd as Real>::unit_roundoff(())
}

/// The double-double nearest `x` up to two roundings (`hi = x` rounded, `lo = x − hi`
/// rounded): within a few units of `2⁻¹⁰⁶` relative for `T` of 128 bits or more.
pub(crate) fn to_dd<T: Real>(x: &T, ctx: T::Ctx) -> Dd {
    let hi = x.approx_f64();
    if !hi.is_finite() {
        return Dd::from_f64(hi);
    }
    let lo = (x.clone() - &T::from_f64(hi, ctx)).approx_f64();
    Dd::from_parts(hi, lo)
}

/// The cotan Laplacian `L` of a triangulation at one iterate, in double-double, as its
/// weighted half-edges: `(L x)_i = Σ_h w_h (x_j − x_i)` over the face half-edges `h = i→j`
/// touching `i`, `w_h = ½ cot α(h)` (docs/catalogue.md §3, the assembly of
/// [`cotan_laplacian`](crate::geometry::laplacian::cotan_laplacian) without the matrix).
pub(crate) struct IterateLaplacian {
    /// `(i, j, w_h)` per face half-edge `h = i→j` with `i ≠ j`.
    sides: Vec<(u32, u32, Dd)>,
}

impl IterateLaplacian {
    /// The Laplacian of `mesh` with the scaled lengths `lengths` (in `T`), from the lengths
    /// divided by a power of two near the longest (angles are scale-invariant, and the
    /// squares stay in range). `None` when a length or a weight is not finite (a
    /// degenerate face: the caller keeps the `f64` correction).
    pub(crate) fn at<T: Real>(mesh: &Mesh, lengths: &[T], ctx: T::Ctx) -> Option<Self> {
        let top = lengths.iter().map(Real::approx_f64).fold(0.0, f64::max);
        if !top.is_normal() || mesh.n_vertices() > u32::MAX as usize {
            return None;
        }
        let k = top.log2().floor() as i32;
        let l: Vec<Dd> = lengths.iter().map(|x| to_dd(x, ctx).ldexp(-k)).collect();
        let len = |h: HalfEdge| &l[h.edge().idx()];
        let mut sides = Vec::with_capacity(mesh.n_halfedges());
        for h in mesh.halfedges() {
            let (i, j) = (mesh.tail(h).idx(), mesh.tip(h).idx());
            if i == j || mesh.is_boundary_halfedge(h) {
                continue;
            }
            let w = cot_opposite(len(h), len(mesh.next(h)), len(mesh.prev(h))).mul_f64(0.5);
            if !w.hi.is_finite() {
                return None;
            }
            sides.push((i as u32, j as u32, w));
        }
        Some(IterateLaplacian { sides })
    }

    /// `L x` (one entry per vertex).
    pub(crate) fn apply(&self, x: &[Dd]) -> Vec<Dd> {
        let mut y = vec![Dd::default(); x.len()];
        for &(i, j, w) in &self.sides {
            let (i, j) = (i as usize, j as usize);
            let t = w * (x[j] - x[i]);
            y[i] += &t;
            y[j] -= &t;
        }
        y
    }
}

/// The Newton correction `δ` with `H δ = −r` on the free vertices `free` (zero elsewhere),
/// `H = −lap` the Hessian at the iterate and `r = Θ − θ` its residual in double-double (one
/// entry per vertex), by iterative refinement preconditioned by `factor` (`H̃`, module
/// doc). The sweeps stop when the linear residual is below `2⁻¹⁰⁴·max |r|` (double-double's unit roundoff), after
/// [`MAX_SWEEPS`], or when a sweep fails to halve it (then the best `δ` so far is kept:
/// at worst the `f64` correction `−H̃⁻¹r`).
pub(crate) fn newton_correction(
    lap: &IterateLaplacian,
    factor: &Factor,
    r: &[Dd],
    free: &[usize],
) -> Vec<Dd> {
    let hi = |x: &[Dd]| x.iter().map(|d| d.hi).collect::<Vec<f64>>();
    let max_free = |x: &[Dd]| free.iter().map(|&v| x[v].hi.abs()).fold(0.0, f64::max);
    let mut delta: Vec<Dd> = newton_direction(factor, &hi(r), free)
        .into_iter()
        .map(Dd::from_f64)
        .collect();
    let r_max = max_free(r);
    // The best δ so far and its linear residual (δ₀'s is at most about `r` itself).
    let mut best = (delta.clone(), f64::INFINITY);
    for _ in 0..=MAX_SWEEPS {
        // The linear residual −r − Hδ = Lδ − r on the free vertices (δ is zero elsewhere).
        let ld = lap.apply(&delta);
        let mut res = vec![Dd::default(); r.len()];
        for &v in free {
            res[v] = ld[v] - r[v];
        }
        let res_max = max_free(&res);
        if res_max.is_nan() || res_max >= 0.5 * best.1 {
            break;
        }
        best = (delta.clone(), res_max);
        if res_max <= sweep_tolerance() * r_max {
            break;
        }
        // δ ← δ + H̃⁻¹(−r − Hδ) = δ − newton_direction(res).
        let step = newton_direction(factor, &hi(&res), free);
        for &v in free {
            delta[v] = delta[v].add_f64(-step[v]);
        }
    }
    best.0
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::laplacian::cotan_laplacian;
    use crate::mesh::builders::flat_torus;
    use crate::scalar::{Mpfr, Precision};
    use crate::uniformization::components::Components;
    use crate::uniformization::hessian::{grounded_hessian, CholeskyCache};

    /// [`newton_correction`] solves `H δ = −r` for the Hessian of the lengths it is given,
    /// not for the preconditioner's: on a jittered flat 5 × 6 torus (lengths at 256 bits)
    /// with the `f64` factor taken at lengths perturbed by about `10⁻⁶` relative, the
    /// linear residual `L δ − r`, evaluated by an independent computation (the assembled
    /// cotan Laplacian in MPFR-256 applied to `δ`), is below `10⁻²⁶·max |r|`:
    /// double-double's `2⁻¹⁰⁴ ≈ 5·10⁻³²` per operation, times the grounded Laplacian's
    /// condition number (below 10³ here) and the dozen terms of a row, with margin. The
    /// control: the `f64` correction `−H̃⁻¹r` alone leaves the mismatch of the two
    /// Hessians, above `10⁻⁹·max |r|`.
    #[test]
    fn the_correction_solves_with_the_hessian_of_the_iterate() {
        let t = flat_torus(5, 6).expect("a torus");
        let mesh = t.mesh;
        let p = Precision::new(256).expect("bits");
        let jitter = |e: usize, scale: f64| 1.0 + scale * (((e * 37 + 11) % 17) as f64 - 8.0);
        let l: Vec<f64> = t
            .squared_lengths
            .iter()
            .enumerate()
            .map(|(e, q)| q.to_f64().sqrt() * jitter(e, 1e-3))
            .collect();
        let lm: Vec<Mpfr> = l.iter().map(|&x| Mpfr::from_f64(x, p)).collect();
        let (free, free_idx) = Components::of(&mesh).free_index();
        let off: Vec<f64> = l
            .iter()
            .enumerate()
            .map(|(e, &x)| x * jitter(e + 5, 1e-7))
            .collect();
        let factor = CholeskyCache::default()
            .factor(&grounded_hessian(&mesh, &off, &free_idx))
            .expect("positive definite");
        let r: Vec<Dd> = (0..mesh.n_vertices())
            .map(|v| Dd::from_f64(1e-3 * (((v * 13 + 3) % 7) as f64 - 3.0)) / Dd::from_f64(3.0))
            .collect();
        let r_max = free.iter().map(|&v| r[v].hi.abs()).fold(0.0, f64::max);
        let lap = IterateLaplacian::at(&mesh, &lm, p).expect("finite");
        let lm_matrix = cotan_laplacian(&mesh, &lm);
        let linear_residual = |delta: &[Dd]| {
            let dm: Vec<Mpfr> = delta
                .iter()
                .map(|d| Mpfr::from_f64(d.hi, p) + &Mpfr::from_f64(d.lo, p))
                .collect();
            let ld = lm_matrix.mul_vec(&dm).expect("one entry per vertex");
            free.iter()
                .map(|&v| {
                    let rv = Mpfr::from_f64(r[v].hi, p) + &Mpfr::from_f64(r[v].lo, p);
                    (ld[v].clone() - &rv).approx_f64().abs()
                })
                .fold(0.0, f64::max)
        };
        let delta = newton_correction(&lap, &factor, &r, &free);
        let solved = linear_residual(&delta);
        assert!(solved <= 1e-26 * r_max, "{solved:e} against {r_max:e}");
        // Control: the preconditioner's own correction.
        let hi: Vec<f64> = r.iter().map(|d| d.hi).collect();
        let plain: Vec<Dd> = newton_direction(&factor, &hi, &free)
            .into_iter()
            .map(Dd::from_f64)
            .collect();
        let mismatch = linear_residual(&plain);
        assert!(mismatch > 1e-9 * r_max, "{mismatch:e} against {r_max:e}");
        // Grounded vertices keep their u.
        assert!((0..mesh.n_vertices())
            .filter(|v| free_idx[*v].is_none())
            .all(|v| delta[v] == Dd::default()));
    }
}
