//! Dense linear systems for small meshes, generic over [`Real`]: the one dense solver of the
//! library.
//!
//! - [`cholesky`] / [`solve_spd`]: `A = L Lᵀ` for symmetric positive definite `A` (the
//!   circle-pattern and Rivin Hessians);
//! - [`lu_solve`]: Gaussian elimination with partial pivoting for a general square `A`
//!   and several right-hand sides (the weight-rigidity Jacobian, harmonic maps whose
//!   weights may be negative);
//! - [`interval_cholesky_positive`]: the interval form, which proves every symmetric
//!   matrix of an interval hull positive definite.
//!
//! The first three are numerical routines (pivots judged through `approx_f64`); only the
//! last proves anything. Large sparse systems go to faer's sparse Cholesky
//! (`uniformization::hessian`).

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

/// Solve `A X = B` for a square `A` (rows `a`) and the right-hand sides `rhs` (one vector of
/// length `n` each) by Gaussian elimination with partial pivoting: at column `c` the row of
/// largest `|approx_f64|` (the last among equal ones) becomes the pivot. `None` when a
/// pivot's magnitude is at most `min_pivot` or not finite (a singular or ill-posed system;
/// `min_pivot = 0` refuses exact zeros only).
///
/// ```
/// use penner::scalar::dense::lu_solve;
/// // [[0, 2], [1, 1]] x = [2, 3] needs the row swap: x = (2, 1).
/// let a = vec![vec![0.0, 2.0], vec![1.0, 1.0]];
/// let x = lu_solve(a, vec![vec![2.0, 3.0]], 0.0).unwrap();
/// assert_eq!(x, vec![vec![2.0, 1.0]]);
/// ```
#[allow(clippy::needless_range_loop)] // elimination and back substitution by index
pub fn lu_solve<T: Real>(
    mut a: Vec<Vec<T>>,
    mut rhs: Vec<Vec<T>>,
    min_pivot: f64,
) -> Option<Vec<Vec<T>>> {
    let n = a.len();
    if a.iter().any(|row| row.len() != n) || rhs.iter().any(|b| b.len() != n) {
        return None;
    }
    for c in 0..n {
        let p = (c..n).max_by(|&i, &j| {
            a[i][c]
                .approx_f64()
                .abs()
                .total_cmp(&a[j][c].approx_f64().abs())
        })?;
        let pivot = a[p][c].approx_f64().abs();
        if pivot <= min_pivot || !pivot.is_finite() {
            return None;
        }
        a.swap(c, p);
        for b in &mut rhs {
            b.swap(c, p);
        }
        let (top, rest) = a.split_at_mut(c + 1);
        let pivot_row = &top[c];
        for (k, row) in rest.iter_mut().enumerate() {
            let f = row[c].clone() / &pivot_row[c];
            for (x, y) in row[c..].iter_mut().zip(&pivot_row[c..]) {
                let t = f.clone() * y;
                *x -= &t;
            }
            for b in &mut rhs {
                let t = f.clone() * &b[c];
                b[c + 1 + k] -= &t;
            }
        }
    }
    for b in &mut rhs {
        for r in (0..n).rev() {
            let mut s = b[r].clone();
            for k in r + 1..n {
                s -= &(a[r][k].clone() * &b[k]);
            }
            b[r] = s / &a[r][r];
        }
    }
    Some(rhs)
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
