//! A rigorous lower bound on the smallest eigenvalue of a symmetric sparse matrix by a
//! floating-point Cholesky factorization of `A − σI` and its rounding-error bound
//! (Demmel; Higham, *Accuracy and Stability of Numerical Algorithms*, Thm 10.3; the
//! verification style of Rump). proof: B70
//!
//! If the up-looking Cholesky below, run in binary64 on `C = fl(PAPᵀ − σI)` with a
//! fill-reducing permutation `P` (approximate minimum degree, faer), completes with positive
//! pivots, then `L̃L̃ᵀ = C + ΔC` with `|ΔC| ≤ γ_{m+1}|L̃||L̃ᵀ|`, `m` the largest number of
//! off-diagonal entries in a row of `L̃`, and so
//! `λ_min(A) ≥ σ − γ_{m+1}‖|L̃||L̃ᵀ|‖_∞ − u·max_k |C_kk|` (B70). No inverse is formed: the
//! cost is that of one sparse factorization.

use faer::sparse::linalg::amd;
use faer::sparse::SymbolicSparseColMatRef;

/// A symmetric matrix given by its lower triangle: `(row, column, value)` with `row ≥ column`.
#[derive(Clone, Debug)]
pub struct SymmetricLower {
    /// Dimension.
    pub n: usize,
    /// Entries with `row ≥ column`, no duplicates.
    pub entries: Vec<(usize, usize, f64)>,
}

/// The next binary64 above `x` (`f64::next_up`: IEEE 754 nextUp; `∞` and NaN unchanged).
pub(crate) fn up(x: f64) -> f64 {
    x.next_up()
}

/// The next binary64 below `x` (`f64::next_down`: IEEE 754 nextDown).
pub(crate) fn down(x: f64) -> f64 {
    x.next_down()
}

/// A fill-reducing ordering (faer's approximate minimum degree): `perm[new] = old`.
fn ordering(a: &SymmetricLower) -> Vec<usize> {
    let n = a.n;
    let mut cols: Vec<Vec<usize>> = vec![Vec::new(); n];
    for &(r, c, _) in &a.entries {
        cols[c].push(r);
    }
    let mut col_ptr = vec![0usize; n + 1];
    let mut row_idx = Vec::new();
    for (c, rows) in cols.iter_mut().enumerate() {
        rows.sort_unstable();
        rows.dedup();
        row_idx.extend_from_slice(rows);
        col_ptr[c + 1] = row_idx.len();
    }
    let identity = || (0..n).collect::<Vec<_>>();
    let sym = SymbolicSparseColMatRef::new_checked(n, n, &col_ptr, None, &row_idx);
    let mut perm = vec![0usize; n];
    let mut perm_inv = vec![0usize; n];
    let mut buf = faer::dyn_stack::MemBuffer::new(amd::order_scratch::<usize>(n, row_idx.len()));
    let stack = faer::dyn_stack::MemStack::new(&mut buf);
    match amd::order(
        &mut perm,
        &mut perm_inv,
        sym,
        amd::Control::default(),
        stack,
    ) {
        Ok(_) => perm,
        Err(_) => identity(),
    }
}

/// B70's error term `γ_{m+1}·S + u·D`, rounded up, from computed inputs: `s` the binary64
/// value of `S = ‖|L̃||L̃ᵀ|‖_∞` as summed (each row sum `Σ_k |l_ik|·c_k` has at most `m + 1`
/// products, each column sum `c_k` at most `c` terms, all nonnegative, so the computed `s`
/// is at least `(1 − (m + c)u)·S`), `D = max_k |C_kk|`, `γ_k = ku/(1 − ku)`, `u = 2⁻⁵³`.
/// The result is at least `γ_{m+1}·s/(1 − (m + c)u) + u·D` (exactly, in ℝ): `s` is
/// inflated twice by `1 + 2(m + c + 4)u` (`(m + c + 4)u ≤ ¼` for any `m + c < 2⁵⁰`), and
/// every product and sum is rounded upward (`up`) and multiplied by `1 + 4u`. proof: B70
pub(crate) fn rounding_error_bound(m: usize, c: usize, s: f64, diag_max: f64) -> f64 {
    let u = f64::EPSILON / 2.0;
    let terms = (m + c + 4) as f64;
    let inflate = 1.0 + 2.0 * terms * u;
    let s_up = up(up(s * inflate) * inflate);
    let k = m as f64 + 1.0;
    let gamma = up(k * u / (1.0 - k * u) * (1.0 + 4.0 * u));
    up(up(up(gamma * s_up) * (1.0 + 4.0 * u)) + up(up(u * diag_max) * (1.0 + 4.0 * u)))
}

/// The outcome of a verified factorization.
#[derive(Clone, Debug, PartialEq)]
pub struct EigenLowerBound {
    /// A rigorous lower bound on `λ_min(A)`.
    pub lambda_min: f64,
    /// The shift used.
    pub sigma: f64,
    /// The rounding-error term subtracted from `σ`.
    pub error: f64,
}

/// Factor `fl(PAPᵀ − σI)` and return the rigorous bound `λ_min(A) ≥ σ − error`, or `None`
/// when a pivot is not positive (no conclusion). proof: B70
#[allow(
    clippy::too_many_lines,
    clippy::needless_range_loop,
    clippy::items_after_statements
)] // the factorization reads as in CSparse
pub fn lambda_min_lower_bound(a: &SymmetricLower, sigma: f64) -> Option<EigenLowerBound> {
    let n = a.n;
    if n == 0 || u32::try_from(n).is_err() {
        return None;
    }
    let perm = ordering(a);
    let mut inv = vec![0usize; n];
    for (new, &old) in perm.iter().enumerate() {
        inv[old] = new;
    }
    // Upper triangle of C = PAPᵀ by columns: column k holds rows i ≤ k.
    let mut upper: Vec<Vec<(usize, f64)>> = vec![Vec::new(); n];
    let mut diag_max: f64 = 0.0;
    for &(r, c, v) in &a.entries {
        let (i, j) = (inv[r], inv[c]);
        let (i, j) = if i <= j { (i, j) } else { (j, i) };
        let v = if i == j {
            let d = v - sigma;
            diag_max = diag_max.max(d.abs());
            d
        } else {
            v
        };
        upper[j].push((i, v));
    }
    // Elimination tree of C.
    const NONE: usize = usize::MAX;
    let mut parent = vec![NONE; n];
    let mut ancestor = vec![NONE; n];
    for k in 0..n {
        for &(i0, _) in &upper[k] {
            let mut i = i0;
            while i != NONE && i < k {
                let next = ancestor[i];
                ancestor[i] = k;
                if next == NONE {
                    parent[i] = k;
                }
                i = next;
            }
        }
    }
    // The pattern of each row of L (its reach in the elimination tree), first to count
    // the entries of each column, then for the factorization itself.
    let mut mark = vec![NONE; n];
    let mut stack = vec![0usize; n];
    let mut pattern = vec![0usize; n];
    let mut reach = |k: usize, mark: &mut [usize], pattern: &mut [usize], x: Option<&mut [f64]>| {
        let mut top = n;
        mark[k] = k;
        let mut x = x;
        for &(i, v) in &upper[k] {
            if i == k {
                continue;
            }
            if let Some(x) = x.as_deref_mut() {
                x[i] += v;
            }
            let mut len = 0;
            let mut j = i;
            while mark[j] != k {
                stack[len] = j;
                len += 1;
                mark[j] = k;
                j = parent[j];
                if j == NONE {
                    break;
                }
            }
            while len > 0 {
                len -= 1;
                top -= 1;
                pattern[top] = stack[len];
            }
        }
        top
    };
    let mut col_ptr = vec![0usize; n + 1];
    for k in 0..n {
        let top = reach(k, &mut mark, &mut pattern, None);
        for &i in &pattern[top..n] {
            col_ptr[i + 1] += 1;
        }
        col_ptr[k + 1] += 1;
    }
    for k in 0..n {
        col_ptr[k + 1] += col_ptr[k];
    }
    // Up-looking Cholesky: row k of L from a sparse triangular solve. Column i of L is
    // stored at col_ptr[i]..next[i] (diagonal first, then rows in increasing order).
    let nnz = col_ptr[n];
    let mut row_idx = vec![0u32; nnz];
    let mut val = vec![0.0f64; nnz];
    let mut next: Vec<usize> = col_ptr[..n].to_vec();
    let mut row_count = vec![0usize; n];
    let mut x = vec![0.0f64; n];
    mark.fill(NONE);
    for k in 0..n {
        let top = reach(k, &mut mark, &mut pattern, Some(&mut x));
        let mut d = 0.0;
        for &(i, v) in &upper[k] {
            if i == k {
                d += v;
            }
        }
        for &i in &pattern[top..n] {
            let lii = val[col_ptr[i]];
            let lki = x[i] / lii;
            x[i] = 0.0;
            for p in col_ptr[i] + 1..next[i] {
                x[row_idx[p] as usize] -= val[p] * lki;
            }
            d -= lki * lki;
            row_idx[next[i]] = k as u32;
            val[next[i]] = lki;
            next[i] += 1;
            row_count[k] += 1;
        }
        if !(d > 0.0 && d.is_finite()) {
            return None;
        }
        row_idx[next[k]] = k as u32;
        val[next[k]] = d.sqrt();
        next[k] += 1;
    }
    // ‖|L||Lᵀ|‖_∞ = max_i Σ_k |l_ik| Σ_j |l_jk|, sums of nonnegative terms rounded to
    // nearest and then inflated (B70): `m` bounds the products of a row sum, the longest
    // column `c` the terms of a column sum.
    let m = row_count.iter().copied().max().unwrap_or(0);
    let c = (0..n).map(|k| next[k] - col_ptr[k]).max().unwrap_or(0);
    let colsum: Vec<f64> = (0..n)
        .map(|c| {
            val[col_ptr[c]..next[c]]
                .iter()
                .map(|v| v.abs())
                .sum::<f64>()
        })
        .collect();
    let mut rowsum = vec![0.0f64; n];
    for (k, &ck) in colsum.iter().enumerate() {
        for p in col_ptr[k]..next[k] {
            rowsum[row_idx[p] as usize] += val[p].abs() * ck;
        }
    }
    let s = rowsum.iter().copied().fold(0.0, f64::max);
    let error = rounding_error_bound(m, c, s, diag_max);
    let lambda_min = down(sigma - error);
    Some(EigenLowerBound {
        lambda_min,
        sigma,
        error,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use rug::Rational;

    /// `γ_{m+1}·s/(1 − (m + c)u) + u·D` exactly (the quantity B70 needs bounded above).
    fn required(m: usize, c: usize, s: f64, d: f64) -> Rational {
        let u = Rational::from((1, 1u64 << 53));
        let k = Rational::from(m + 1);
        let one = Rational::from(1);
        let gamma = Rational::from(&k * &u) / (one.clone() - Rational::from(&k * &u));
        let shrink = one - &u * Rational::from(m + c);
        gamma * Rational::from_f64(s).unwrap() / shrink + u * Rational::from_f64(d).unwrap()
    }

    /// B70's error term against its exact requirement on a grid of row and column counts
    /// (up to 10⁶), norms (10⁻²⁰⁰ … 10²⁰⁰) and diagonals: never below it (soundness), and
    /// within a relative `8(m + c + 4)u + 64u` above it (no slack beyond the stated
    /// inflation: the term is what B70 says, not merely an upper bound). Control: the same
    /// formula rounded to nearest without the inflation falls below the requirement.
    #[test]
    fn b70_rounding_error_bound_is_at_least_the_exact_term_and_tight() {
        let u = f64::EPSILON / 2.0;
        let mut naive_below = 0;
        for m in [0usize, 1, 2, 5, 11, 100, 10_000, 1_000_000] {
            for c in [0usize, 1, 7, 100_000] {
                for s in [1e-200, 3e-7, 1.0, 12.5, 7.3e9, 1e200] {
                    for d in [0.0, 1e-3, 1.0, 4.5e6] {
                        let e = rounding_error_bound(m, c, s, d);
                        let need = required(m, c, s, d);
                        let got = Rational::from_f64(e).unwrap();
                        assert!(got >= need, "m {m} c {c} s {s:e} d {d:e}: {e:e} below");
                        let slack = 8.0 * (m + c + 4) as f64 * u + 64.0 * u;
                        let cap = need.clone() * Rational::from_f64(1.0 + slack).unwrap();
                        assert!(got <= cap, "m {m} c {c} s {s:e} d {d:e}: {e:e} too loose");
                        let k = m as f64 + 1.0;
                        let naive = k * u / (1.0 - k * u) * s + u * d;
                        if Rational::from_f64(naive).unwrap() < need {
                            naive_below += 1;
                        }
                    }
                }
            }
        }
        assert!(
            naive_below > 100,
            "control: naive below in {naive_below} cases"
        );
    }

    /// A zero pivot gives no conclusion: `[[1, 1], [1, 1]]` at `σ = 0` has the exact pivot
    /// `1 − 1·1 = 0`. Control: at `σ = −1` (`A + I`, eigenvalues 1 and 3) it factors, and
    /// the bound `σ − error` lies just below `σ` and below `λ_min(A) = 0`.
    #[test]
    fn b70_a_zero_pivot_gives_no_bound() {
        let a = SymmetricLower {
            n: 2,
            entries: vec![(0, 0, 1.0), (1, 0, 1.0), (1, 1, 1.0)],
        };
        assert_eq!(lambda_min_lower_bound(&a, 0.0), None);
        let b = lambda_min_lower_bound(&a, -1.0).expect("A + I is positive definite");
        assert!(b.lambda_min < -1.0 && b.lambda_min > -1.0 - 1e-12, "{b:?}");
    }

    /// The empty matrix has no eigenvalue to bound: no conclusion (a bound would be
    /// vacuous, and `σ` itself would be returned as one). Control: the 1×1 matrix `[2]`
    /// at `σ = 1` gets a bound in `(0, 2]`.
    #[test]
    fn b70_the_empty_matrix_gets_no_bound() {
        let empty = SymmetricLower {
            n: 0,
            entries: Vec::new(),
        };
        assert_eq!(lambda_min_lower_bound(&empty, 1.0), None);
        let one = SymmetricLower {
            n: 1,
            entries: vec![(0, 0, 2.0)],
        };
        let b = lambda_min_lower_bound(&one, 1.0).expect("a positive pivot");
        assert!(b.lambda_min > 0.0 && b.lambda_min <= 2.0, "{b:?}");
    }
}
