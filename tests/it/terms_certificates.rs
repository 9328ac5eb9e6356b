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
