//! Tests in which one term of a certificate's inequality decides the verdict (the
//! `proofs/` entries list every term under **Terms** with its deciding test): an input
//! where the certificate is right with the term and would claim more than is true without
//! it. Expected values are closed forms, independent of the code under test.

use penner::theorems::t06_weight_rigidity::{
    certify_weight_rigidity, enclosure_bits, grounded_area_hessian,
};
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

/// B102 term `D H D`, a congruence by powers of two `d_e` that bring each diagonal
/// midpoint into `[1, 4)`: the grounded Hessian `−2∇²𝒜` is homogeneous of degree `−1` in
/// the squared lengths, so doubling every length divides `H` by 4 and doubles every `d_e`,
/// and `D H D` is the same matrix (each step exact but for the outward ulp). A scaling
/// that is not a congruence (`d_i + d_j` or `d_i / d_j` in place of `d_i d_j`, which do not
/// keep definiteness in general) or another choice of the powers changes it.
#[test]
fn term_b102_hessian_is_scaled_by_a_congruence_of_powers_of_two() {
    let (m, l) = crate::meshgen::jittered_torus(4, 5, 1);
    let bits = enclosure_bits(53);
    let h = grounded_area_hessian(&m, &l, 0, bits).expect("strict faces");
    let l2: Vec<f64> = l.iter().map(|x| 2.0 * x).collect();
    let h2 = grounded_area_hessian(&m, &l2, 0, bits).expect("strict faces");
    assert_eq!((h.n, h.entries.len()), (h2.n, h2.entries.len()));
    for (a, b) in h.entries.iter().zip(&h2.entries) {
        assert_eq!((a.0, a.1), (b.0, b.1));
        if a.0 == a.1 {
            let mid = 0.5 * a.2 + 0.5 * a.3;
            assert!(
                (1.0..4.0).contains(&mid),
                "diagonal midpoint {mid} at {}",
                a.0
            );
        }
        for (x, y) in [(a.2, b.2), (a.3, b.3)] {
            assert!(
                (x - y).abs() <= 1e-12 * x.abs().max(y.abs()),
                "({}, {}): {x:e} against {y:e} at doubled lengths",
                a.0,
                a.1
            );
        }
    }
}

/// B102 term "each entry once" (`IntervalLower` and B70's `SymmetricLower` hold no
/// duplicates: B70's error term is for one entry per position, not for a sum of them):
/// the per-face contributions to an entry are summed outward into one enclosure, so the
/// grounded Hessian of a surface has one entry per free edge on the diagonal and one per
/// pair of distinct free edges sharing a face (counted independently from the faces), in
/// the lower triangle, no position twice.
#[test]
fn term_b102_face_contributions_are_merged_into_one_entry() {
    let (m, l) = crate::meshgen::jittered_torus(4, 5, 1);
    let gauge = 0;
    let h = grounded_area_hessian(&m, &l, gauge, enclosure_bits(53)).expect("strict faces");
    let free = |e: usize| (e != gauge).then(|| if e < gauge { e } else { e - 1 });
    let mut expected = std::collections::BTreeSet::new();
    for f in m.faces() {
        let edges = m.face_halfedges(f).map(|h| h.edge().idx());
        for a in edges {
            for b in edges {
                if let (Some(i), Some(j)) = (free(a), free(b)) {
                    expected.insert((i.max(j), i.min(j)));
                }
            }
        }
    }
    let got: Vec<(usize, usize)> = h.entries.iter().map(|e| (e.0, e.1)).collect();
    let distinct: std::collections::BTreeSet<_> = got.iter().copied().collect();
    assert_eq!(distinct.len(), got.len(), "an entry appears twice");
    assert_eq!(distinct, expected);
    // Every merged enclosure is finite with `lo ≤ hi`.
    assert!(h
        .entries
        .iter()
        .all(|e| e.2 <= e.3 && e.2.is_finite() && e.3.is_finite()));
}

/// B102 hypotheses "one length per edge, a gauge edge of the mesh": a surplus length or a
/// gauge out of range is refused, never read as a certificate of the first `m` lengths;
/// the same lengths with the right count and gauge certify (control).
#[test]
fn term_b102_lengths_and_gauge_match_the_mesh() {
    let (m, l) = crate::meshgen::jittered_torus(4, 5, 1);
    let n = m.n_edges();
    let bits = enclosure_bits(53);
    assert!(certify_weight_rigidity(&m, &l, 0).is_ok());
    assert!(grounded_area_hessian(&m, &l, n - 1, bits).is_ok());
    let mut longer = l.clone();
    longer.push(1.0);
    assert!(grounded_area_hessian(&m, &longer, 0, bits).is_err());
    assert!(certify_weight_rigidity(&m, &longer, 0).is_err());
    assert!(grounded_area_hessian(&m, &l[..n - 1], 0, bits).is_err());
    assert!(grounded_area_hessian(&m, &l, n, bits).is_err());
}

/// B102 enclosure precision `2·max(p, 53) + 64` bits (B102 "Hypotheses"): the squares of
/// `p`-bit lengths are exact with 64 bits to spare (`≥ 2p + 64`), at the documented value.
#[test]
fn b102_enclosure_bits_hold_the_squared_lengths_exactly() {
    for (p, bits) in [
        (1, 170),
        (24, 170),
        (53, 170),
        (106, 276),
        (107, 278),
        (256, 576),
    ] {
        assert_eq!(enclosure_bits(p), bits, "{p}");
        assert!(enclosure_bits(p) >= 2 * p + 64);
    }
}

/// B62 term `(u_i + u_j)/2` in `ℓ̃ = e^{(u_i+u_j)/2}·ℓ` (`directed::scaled_length`, the
/// lengths of `ScaledQuad`): the enclosure at 128 bits contains the value bracketed at 1024
/// bits with directed rounding (exponent and product rounded down, then up), and is tight
/// (relative width below `2⁻¹⁰⁰`). The mean `½(u_i + u_j)` read as `u_i + u_j + ½` or
/// `2(u_i + u_j)` encloses another length, which would then decide the sign of `P`.
#[test]
fn term_b62_scaled_length_encloses_the_mean_scale_factor() {
    use penner::predicates::directed::scaled_length;
    use penner::scalar::Precision;
    use rug::float::Round;
    use rug::ops::MulAssignRound;
    use rug::Float;
    let p = Precision::new(128).unwrap();
    for (l, ui, uj) in [
        (3.0, 1.0, 1.0),
        (1.0, 0.0, 0.0),
        (0.75, -2.5, 0.5),
        (2.0, 400.0, -399.0),
        (1.5, 0.1, 0.2),
    ] {
        let bracket = |round: Round| {
            let mut x: Float = Float::with_val(1024, ui) + uj; // exact: both binary64
            x /= 2; // exact
            x.exp_round(round);
            x.mul_assign_round(l, round);
            x
        };
        let (below, above) = (bracket(Round::Down), bracket(Round::Up));
        let e = scaled_length(l, ui, uj, p);
        let (lo, hi) = (e.lo().as_float(), e.hi().as_float());
        assert!(
            *lo <= below && above <= *hi,
            "ℓ = {l}, u = ({ui}, {uj}): [{lo}, {hi}] misses e^((u_i+u_j)/2)·ℓ = {below}"
        );
        let width = Float::with_val(1024, hi - lo);
        assert!(
            width <= below * Float::with_val(64, Float::i_exp(1, -100)),
            "ℓ = {l}"
        );
    }
}

/// B98 term "refuted only when `D − ε > 0` or `−D − ε > 0` is proved", on either side of the
/// claimed value (`predicates::within::within_all`): with `c = 1`, `ε = ¼` and point
/// enclosures, `x = 1 ± ¼` are exact ties `|x − c| = ε` (true claims), undecided at every
/// precision, never refuted; `ε + D` or `ε − D` in place of `D − ε` or `−D − ε` would refute
/// them. Controls: `x = 1.5` refuted, `x = 0.875` and `x = 1` within.
#[test]
fn term_b98_a_tie_on_either_side_of_the_claim_is_never_refuted() {
    use penner::predicates::directed::enclose_f64;
    use penner::predicates::within::{within_all, Within};
    use penner::scalar::Certified;
    use rug::Rational;
    let xs = [1.25, 0.75, 1.5, 0.875, 1.0];
    let claimed = vec![Rational::from(1); xs.len()];
    let eps = Rational::from((1, 4));
    let mut enclose = |p| xs.iter().map(|&x| enclose_f64(x, p)).collect::<Vec<_>>();
    let b = within_all(&mut enclose, &claimed, &eps, 128, 512);
    let got: Vec<Option<Within>> = b.answers.iter().map(Certified::value).collect();
    assert_eq!(
        got,
        [
            None,
            None,
            Some(Within::Outside),
            Some(Within::Inside),
            Some(Within::Inside)
        ],
        "{:?}",
        b.answers
    );
}
