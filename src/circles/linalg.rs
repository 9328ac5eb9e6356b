//! Dense symmetric positive definite systems for small meshes: Cholesky `A = L Lᵀ` generic
//! over [`Real`], and its interval form, which proves every symmetric matrix of an interval
//! hull positive definite.

use crate::scalar::{Interval, IntervalBound, Real, Sign};

/// The Cholesky factor `L` (lower triangular, row-major) of a symmetric matrix, reading only
/// its lower triangle; `None` when a pivot is not positive **as seen through
/// `approx_f64`** — a numerical routine for the solvers, never a proof (see
/// [`interval_cholesky_positive`]).
#[allow(clippy::needless_range_loop)] // row-by-row indices of the factorisation
pub fn cholesky<T: Real>(a: &[Vec<T>]) -> Option<Vec<Vec<T>>> {
    let n = a.len();
    let mut l: Vec<Vec<T>> = Vec::with_capacity(n);
    for i in 0..n {
        let mut row: Vec<T> = Vec::with_capacity(i + 1);
        for j in 0..=i {
            let lj: &[T] = if j == i { &row } else { &l[j] };
            let mut s = a[i][j].clone();
            for k in 0..j {
                s -= &(row[k].clone() * &lj[k]);
            }
            if i == j {
                if s.approx_f64() <= 0.0 || s.approx_f64().is_nan() {
                    return None;
                }
                row.push(s.sqrt());
            } else {
                row.push(s / &l[j][j]);
            }
        }
        l.push(row);
    }
    Some(l)
}

/// Solve `A x = b` for symmetric positive definite `A` by [`cholesky`]; `None` when the
/// factorisation fails.
#[allow(clippy::needless_range_loop)] // triangular solves by index
pub fn solve_spd<T: Real>(a: &[Vec<T>], b: &[T]) -> Option<Vec<T>> {
    let l = cholesky(a)?;
    let n = b.len();
    let mut y: Vec<T> = Vec::with_capacity(n);
    for i in 0..n {
        let mut s = b[i].clone();
        for k in 0..i {
            s -= &(l[i][k].clone() * &y[k]);
        }
        y.push(s / &l[i][i]);
    }
    let mut x = y;
    for i in (0..n).rev() {
        let mut s = x[i].clone();
        for k in i + 1..n {
            s -= &(l[k][i].clone() * &x[k]);
        }
        x[i] = s / &l[i][i];
    }
    Some(x)
}

/// Whether every symmetric matrix whose lower-triangle entries lie in the given intervals
/// is positive definite, proved by an interval Cholesky factorisation: each computed entry
/// of `L` encloses the exact entry of every member of the hull (inclusion property,
/// proofs/B20), so certified-positive pivots `a_ii − Σ_k l_ik²` prove each member positive
/// definite (proofs/B94). `false` proves nothing (a pivot enclosure reached 0: the hull may
/// be too wide).
#[allow(clippy::needless_range_loop)] // row-by-row indices of the factorisation
pub fn interval_cholesky_positive<B: IntervalBound>(a: &[Vec<Interval<B>>]) -> bool {
    let n = a.len();
    let mut l: Vec<Vec<Interval<B>>> = Vec::with_capacity(n);
    for i in 0..n {
        let mut row: Vec<Interval<B>> = Vec::with_capacity(i + 1);
        for j in 0..=i {
            let lj: &[Interval<B>] = if j == i { &row } else { &l[j] };
            let mut s = a[i][j].clone();
            for k in 0..j {
                s -= &(row[k].clone() * &lj[k]);
            }
            if i == j {
                if s.sign() != Some(Sign::Positive) {
                    return false;
                }
                row.push(s.sqrt());
            } else {
                row.push(s / &l[j][j]);
            }
        }
        l.push(row);
    }
    true
}
