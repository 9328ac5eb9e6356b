//! Tests in which one term of a certificate's inequality decides the verdict (the
//! `proofs/` entries list every term under **Terms** with its deciding test): an input
//! where the certificate is right with the term and would claim more than is true without
//! it. Expected values are closed forms, independent of the code under test.

use penner::uniformization::verified_cholesky::{lambda_min_lower_bound, SymmetricLower};

/// `[[1, 1 − t], [1 − t, 1]]`, eigenvalues `t` and `2 − t` (closed form).
fn near_singular(t: f64) -> SymmetricLower {
    SymmetricLower {
        n: 2,
        entries: vec![(0, 0, 1.0), (1, 0, 1.0 - t), (1, 1, 1.0)],
    }
}

/// B70 term `γ_{m+1}‖|L̃||L̃ᵀ|‖_∞` (with `u·max|C_kk|`): shifts `σ` just above the true
/// `λ_min = t` for which the binary64 factorization of `A − σI` still completes (rounding
/// hides the negative pivot `≈ 2(t − σ)`). The bound must stay below `t`; `σ` alone would
/// claim `λ_min ≥ σ > t`.
#[test]
fn term_b70_rounding_error_of_the_factorization_is_subtracted() {
    let t = 2f64.powi(-12);
    let a = near_singular(t);
    let mut hidden = 0;
    for k in 1..4096 {
        let sigma = t + f64::from(k) * 2f64.powi(-60);
        assert!(sigma > t);
        if let Some(b) = lambda_min_lower_bound(&a, sigma) {
            hidden += 1;
            assert!(
                b.lambda_min <= t,
                "σ = {sigma:e}: bound {:e} > λ_min = {t:e}",
                b.lambda_min
            );
            assert!(b.error >= sigma - t, "{b:?}");
        }
    }
    assert!(
        hidden > 0,
        "no shift above λ_min factored: the test lost its subject"
    );
    // Positive side: a shift of half λ_min factors and proves λ_min > 0.
    let b = lambda_min_lower_bound(&a, t / 2.0).expect("A − (t/2)I is positive definite");
    assert!(b.lambda_min > 0.0 && b.lambda_min <= t, "{b:?}");
}

/// B70 term `m` in `γ_{m+1}`, the largest number of off-diagonal entries in a row of the
/// factor, and the norm `‖|L̃||L̃ᵀ|‖_∞` it multiplies: on the dense `A = k((1 − c)I + cJ)`
/// (`n = 12`, `c = 1 − t`; eigenvalues `kt` (×11) and `k(1 + 11c)`, closed form; the
/// scale `k = 1` and `k = 2²⁰`, exact) the factor is dense, so `m = n − 1` and the error
/// term is at least `γ_n·‖|L||Lᵀ|‖_∞`, with `L` here from an independent dense Cholesky
/// (textbook column order, no permutation). At `k = 2²⁰` the entries of `L` are about
/// `2¹⁰`, so a norm summing `|l_ik| + Σ_j|l_jk|` instead of their products falls far short.
/// Control: with `m = 0` (`γ₁`) the term would be below half of that bound.
#[test]
fn term_b70_gamma_counts_the_longest_row_of_the_factor() {
    let (n, t) = (12usize, 0.25);
    let c = 1.0 - t;
    for k in [1.0, 2f64.powi(20)] {
        let sigma = k * t / 2.0;
        let mut entries = Vec::new();
        for i in 0..n {
            for j in 0..=i {
                entries.push((i, j, if i == j { k } else { k * c }));
            }
        }
        let a = SymmetricLower { n, entries };
        let b = lambda_min_lower_bound(&a, sigma).expect("A − (kt/2)I is positive definite");
        assert!(b.lambda_min > 0.0 && b.lambda_min <= k * t, "{b:?}");
        // Dense Cholesky of A − σI (permutation-invariant: AMD may reorder a dense matrix,
        // and every symmetric permutation of this A is A itself).
        let mut l = vec![vec![0.0f64; n]; n];
        for j in 0..n {
            let d = k - sigma - (0..j).map(|q| l[j][q] * l[j][q]).sum::<f64>();
            l[j][j] = d.sqrt();
            for i in j + 1..n {
                l[i][j] = (k * c - (0..j).map(|q| l[i][q] * l[j][q]).sum::<f64>()) / l[j][j];
            }
        }
        let s = (0..n)
            .map(|i| {
                (0..n)
                    .map(|j| (0..n).map(|q| l[i][q].abs() * l[j][q].abs()).sum::<f64>())
                    .sum::<f64>()
            })
            .fold(0.0, f64::max);
        let u = f64::EPSILON / 2.0;
        let gamma = |q: f64| q * u / (1.0 - q * u);
        let dense = gamma(n as f64) * s;
        assert!(
            b.error >= 0.99 * dense,
            "k {k}: error {:e} < γ_n·s = {dense:e}",
            b.error
        );
        assert!(gamma(1.0) * s + u * (k - sigma) < 0.5 * dense, "control");
    }
}
