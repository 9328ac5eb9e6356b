//! The one dense solver (`scalar::dense`): Gaussian elimination with partial pivoting and
//! the Cholesky factorisation, against exact integer solutions enclosed by the same
//! elimination run on `Interval<Mpfr>` (inclusion property, proofs/B20: whichever pivots
//! the approximations pick, every computed interval encloses the exact value of the exact
//! elimination, and in exact arithmetic any pivot order gives the unique solution).

use penner::scalar::dense::{lu_solve, solve_spd};
use penner::scalar::{Interval, Mpfr, Precision, Real};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

type I = Interval<Mpfr>;

fn ctx() -> Precision {
    Precision::new(256).expect("valid precision")
}

/// A random integer system `A x = b` with `|a_ij| ≤ 20`, `|x_i| ≤ 50`, `b = A x` exact in
/// `i64` and in `f64` (every value below 2⁵³).
fn integer_system(rng: &mut ChaCha8Rng, n: usize) -> (Vec<Vec<i64>>, Vec<i64>, Vec<i64>) {
    let a: Vec<Vec<i64>> = (0..n)
        .map(|_| (0..n).map(|_| rng.gen_range(-20..=20)).collect())
        .collect();
    let x: Vec<i64> = (0..n).map(|_| rng.gen_range(-50..=50)).collect();
    let b = a
        .iter()
        .map(|row| row.iter().zip(&x).map(|(p, q)| p * q).sum())
        .collect();
    (a, x, b)
}

fn intervals(v: &[i64]) -> Vec<I> {
    v.iter().map(|&k| I::from_f64(k as f64, ctx())).collect()
}

#[test]
fn lu_solve_encloses_the_exact_integer_solution_and_not_a_perturbed_one() {
    let mut rng = ChaCha8Rng::seed_from_u64(0xD5E);
    let mut solved = 0;
    for n in 1..=9 {
        for _ in 0..12 {
            let (a, x, b) = integer_system(&mut rng, n);
            let ai: Vec<Vec<I>> = a.iter().map(|r| intervals(r)).collect();
            let mut shifted = b.clone();
            shifted[0] += 1;
            let Some(sol) = lu_solve(ai, vec![intervals(&b), intervals(&shifted)], 0.0) else {
                continue; // a singular draw (or an enclosure of a pivot reaching 0)
            };
            solved += 1;
            for (xi, enc) in x.iter().zip(&sol[0]) {
                assert!(
                    enc.contains_rational(&rug::Rational::from(*xi)),
                    "x = {x:?}"
                );
            }
            // Control: the solution of the shifted right-hand side differs from x (A is
            // nonsingular, so A⁻¹e₀ ≠ 0) and some enclosure at 256 bits excludes it.
            assert!(x
                .iter()
                .zip(&sol[1])
                .any(|(xi, enc)| !enc.contains_rational(&rug::Rational::from(*xi))));
            // The binary64 run is backward stable (Higham 2002, Thm 9.4): (A + ΔA) x̃ = b
            // with |ΔA| ≤ γ_{3n}|L̃||Ũ|, where partial pivoting gives |l| ≤ 1 and
            // |u| ≤ 2ⁿ⁻¹ max|a|, so |A x̃ − b|_i ≤ γ_{3n} n 2ⁿ⁻¹ max|a| Σ|x̃_j|; the residual
            // itself, summed in binary64, adds γ_{n+1}(Σ_j |a_ij x̃_j| + |b_i|).
            let af: Vec<Vec<f64>> = a
                .iter()
                .map(|r| r.iter().map(|&v| v as f64).collect())
                .collect();
            let bf: Vec<f64> = b.iter().map(|&v| v as f64).collect();
            let xf = lu_solve(af.clone(), vec![bf.clone()], 0.0).expect("nonsingular");
            let xf = &xf[0];
            let within = |y: &[f64]| {
                let gamma = |k: f64| k * f64::EPSILON / 2.0 / (1.0 - k * f64::EPSILON / 2.0);
                let nf = n as f64;
                let max_a = af.iter().flatten().fold(0.0f64, |m, v| m.max(v.abs()));
                let sum_y: f64 = y.iter().copied().map(f64::abs).sum();
                af.iter().zip(&bf).all(|(row, bi)| {
                    let r: f64 = row.iter().zip(y).map(|(p, q)| p * q).sum::<f64>() - bi;
                    let abs: f64 = row.iter().zip(y).map(|(p, q)| (p * q).abs()).sum::<f64>();
                    let bound = gamma(3.0 * nf) * nf * 2f64.powi(n as i32 - 1) * max_a * sum_y
                        + gamma(nf + 1.0) * (abs + bi.abs());
                    r.abs() <= bound
                })
            };
            assert!(within(xf), "binary64 solution {xf:?} of {a:?} x = {b:?}");
            // Control: x̃ + e₀/2 has the residual A e₀/2, half a nonzero integer column,
            // far above the bound.
            let mut moved = xf.clone();
            moved[0] += 0.5;
            assert!(!within(&moved), "a moved solution passes");
        }
    }
    assert!(solved >= 90, "only {solved} nonsingular systems");
}

#[test]
fn lu_solve_refuses_singular_ragged_and_tiny_pivots() {
    let singular = vec![vec![1.0, 2.0], vec![2.0, 4.0]];
    assert!(lu_solve(singular, vec![vec![1.0, 2.0]], 0.0).is_none());
    let ragged = vec![vec![1.0, 2.0], vec![2.0]];
    assert!(lu_solve(ragged, vec![vec![1.0, 2.0]], 0.0).is_none());
    let short_rhs = vec![vec![1.0, 0.0], vec![0.0, 1.0]];
    assert!(lu_solve(short_rhs, vec![vec![1.0]], 0.0).is_none());
    let tiny = vec![vec![1e-301, 0.0], vec![0.0, 1.0]];
    assert!(lu_solve(tiny.clone(), vec![vec![1.0, 1.0]], 1e-300).is_none());
    // Control: the same tiny pivot passes when only exact zeros are refused.
    let x = lu_solve(tiny, vec![vec![1e-301, 1.0]], 0.0).expect("nonzero pivots");
    assert_eq!(x[0], vec![1.0, 1.0]);
    let nan = vec![vec![f64::NAN, 0.0], vec![0.0, 1.0]];
    assert!(lu_solve(nan, vec![vec![1.0, 1.0]], 0.0).is_none());
}

#[test]
fn solve_spd_agrees_with_lu_on_gram_matrices_and_refuses_an_indefinite_one() {
    let mut rng = ChaCha8Rng::seed_from_u64(0x5D);
    for n in 1..=8 {
        // G = MᵀM + I: symmetric positive definite, integer entries.
        let m: Vec<Vec<i64>> = (0..n)
            .map(|_| (0..n).map(|_| rng.gen_range(-5..=5)).collect())
            .collect();
        let g: Vec<Vec<i64>> = (0..n)
            .map(|i| {
                (0..n)
                    .map(|j| (0..n).map(|k| m[k][i] * m[k][j]).sum::<i64>() + i64::from(i == j))
                    .collect()
            })
            .collect();
        let x: Vec<i64> = (0..n).map(|_| rng.gen_range(-30..=30)).collect();
        let b: Vec<i64> = g
            .iter()
            .map(|r| r.iter().zip(&x).map(|(p, q)| p * q).sum())
            .collect();
        let gi: Vec<Vec<I>> = g.iter().map(|r| intervals(r)).collect();
        let sol = solve_spd(&gi, &intervals(&b)).expect("positive definite");
        for (xi, enc) in x.iter().zip(&sol) {
            assert!(enc.contains_rational(&rug::Rational::from(*xi)));
        }
    }
    // Control: an indefinite symmetric matrix has no Cholesky factor.
    let indefinite = vec![vec![1.0, 2.0], vec![2.0, 1.0]];
    assert!(solve_spd(&indefinite, &[1.0, 1.0]).is_none());
}
