//! A second, independent certifier for small meshes: the interval Krawczyk operator on the
//! free scale factors (dense, at most [`KRAWCZYK_LIMIT`] free vertices). proof: B72
//!
//! With `y = u' − u` on the box `Y = [−r, r]ⁿ`, `F(y) = Θ − θ(u + y)` (free vertices) and an
//! interval enclosure `J ⊇ {F'(u + y) : y ∈ Y}` (the interval `−L` over the box), and any
//! real matrix `R` (here `fl(H_mid⁻¹)` by dense Gauss–Jordan), the Krawczyk image
//! `K = −R·F(u) + (I − R·J)·Y` satisfies: if `K ⊂ int Y`, `F` has exactly one zero in
//! `u + Y`. Interval arithmetic in `f64` with outward rounding (B21); the enclosures of
//! `F(u)` and `J` come from the shared MPFR interval computation (B71 step 1 checks the
//! Penner cell on the same box).

use super::certificate::{prepare, CertificateData, CertificateError, I};
use crate::scalar::Interval;
use rug::float::Round;

/// The largest number of free vertices the dense certifier accepts.
pub const KRAWCZYK_LIMIT: usize = 2000;

/// The outcome of [`krawczyk`].
#[derive(Clone, Debug, PartialEq)]
pub enum KrawczykOutcome {
    /// A unique zero lies in the box; `width` is the largest half-width of `K` (a bound on
    /// `|u* − u|_∞`).
    Holds {
        /// `max_i |K_i|`, rounded up.
        width: f64,
    },
    /// No conclusion.
    Undecided {
        /// Why.
        reason: String,
    },
}

type F = Interval<f64>;

fn outward(x: &I) -> F {
    let lo = x.lo().as_float().to_f64_round(Round::Down);
    let hi = x.hi().as_float().to_f64_round(Round::Up);
    F::new(lo, hi)
}

/// Dense inverse by Gauss–Jordan with partial pivoting (plain `f64`: `R` needs no rigor).
fn inverse(mut a: Vec<Vec<f64>>) -> Option<Vec<Vec<f64>>> {
    let n = a.len();
    let mut inv: Vec<Vec<f64>> = (0..n)
        .map(|i| (0..n).map(|j| f64::from(u8::from(i == j))).collect())
        .collect();
    for c in 0..n {
        let p = (c..n).max_by(|&x, &y| a[x][c].abs().total_cmp(&a[y][c].abs()))?;
        if a[p][c] == 0.0 {
            return None;
        }
        a.swap(c, p);
        inv.swap(c, p);
        let d = a[c][c];
        for j in 0..n {
            a[c][j] /= d;
            inv[c][j] /= d;
        }
        for r in 0..n {
            if r != c && a[r][c] != 0.0 {
                let f = a[r][c];
                for j in 0..n {
                    a[r][j] -= f * a[c][j];
                    inv[r][j] -= f * inv[c][j];
                }
            }
        }
    }
    Some(inv)
}

/// Run the Krawczyk test on the box of `data` at `bits` of MPFR precision for the
/// enclosures. proof: B72
pub fn krawczyk(data: &CertificateData, bits: u32) -> Result<KrawczykOutcome, CertificateError> {
    let p = match prepare(data, None, bits, super::certificate::Rung::Mpfr)? {
        Ok(p) => p,
        Err(reason) => return Ok(KrawczykOutcome::Undecided { reason }),
    };
    let n = p.free.len();
    if n > KRAWCZYK_LIMIT {
        return Ok(KrawczykOutcome::Undecided {
            reason: format!("{n} free vertices: more than the dense limit {KRAWCZYK_LIMIT}"),
        });
    }
    // J = −L over the box (free rows and columns), sparse by rows; H_mid dense.
    let mut jac: Vec<Vec<(usize, F)>> = vec![Vec::new(); n];
    let mut mid = vec![vec![0.0; n]; n];
    for (i, j, w) in p.laplacian.entries() {
        if let (Some(a), Some(b)) = (p.free_idx[i], p.free_idx[j]) {
            let h = outward(&(-w.clone()));
            mid[a][b] = 0.5 * (h.lo() + h.hi());
            jac[a].push((b, h));
        }
    }
    let Some(r) = inverse(mid) else {
        return Ok(KrawczykOutcome::Undecided {
            reason: "the midpoint Hessian is singular in f64".into(),
        });
    };
    // An f64 radius not above the certificate's (the box checked by `prepare`).
    let rad = rug::Float::with_val_round(53, &data.radius, Round::Down)
        .0
        .to_f64();
    if rad.is_nan() || rad <= 0.0 {
        return Ok(KrawczykOutcome::Undecided {
            reason: "radius underflows binary64".into(),
        });
    }
    let y = F::new(-rad, rad);
    let g: Vec<F> = p.residual.iter().map(outward).collect();
    let zero = F::new(0.0, 0.0);
    let mut width: f64 = 0.0;
    for (i, ri) in r.iter().enumerate() {
        // c_i = e_i − (R J)_i, as a dense interval row.
        let mut c: Vec<F> = (0..n)
            .map(|j| {
                if i == j {
                    F::new(1.0, 1.0)
                } else {
                    zero.clone()
                }
            })
            .collect();
        let mut k = zero.clone();
        for (m, &rim) in ri.iter().enumerate() {
            if rim == 0.0 {
                continue;
            }
            let rim_i = F::new(rim, rim);
            k -= &(rim_i.clone() * &g[m]);
            for (j, jmj) in &jac[m] {
                c[*j] = c[*j].clone() - &(rim_i.clone() * jmj);
            }
        }
        for cj in &c {
            k += &(cj.clone() * &y);
        }
        if !(k.is_valid() && *k.lo() > -rad && *k.hi() < rad) {
            return Ok(KrawczykOutcome::Undecided {
                reason: format!(
                    "Krawczyk image of v{} is [{:e}, {:e}], not inside the box of radius {rad:e}",
                    p.free[i],
                    k.lo(),
                    k.hi()
                ),
            });
        }
        width = width.max(k.lo().abs()).max(k.hi().abs());
    }
    Ok(KrawczykOutcome::Holds { width })
}
