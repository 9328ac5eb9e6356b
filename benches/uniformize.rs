//! Discrete uniformization (T24): the `f64` Newton solve with Ptolemy flips on noisy
//! icospheres of about 10⁴ and 10⁵ faces with random admissible targets, one refinement of
//! the 10⁴-face solution to MPFR-256 (max |Θ − θ| ≤ 1e-60), and the certificate alone
//! (B71: `check_certificate` at 256 bits on the refined `u`, the box of the proof that
//! holds, as `penner certify` re-checks a claim's box).
//!
//! `cargo bench --bench uniformize`.

#![allow(missing_docs)] // criterion_group! generates an undocumented function

#[path = "../tests/it/meshgen.rs"]
mod meshgen;

use criterion::{criterion_group, criterion_main, Criterion};
use meshgen::icosphere;
use penner::mesh::Mesh;
use penner::scalar::{Mpfr, Precision};
use penner::uniformization::certificate::{check_certificate, prove, CertificateOutcome};
use penner::uniformization::refine::refine;
use penner::uniformization::{uniformize, Targets, UniformizeOptions};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rug::Rational;
use std::time::Duration;

/// A frequency-`k` icosphere (20k² faces) with every vertex moved by up to 0.2 × the mean
/// edge length, and its lengths.
fn noisy_sphere(k: u32) -> (Mesh, Vec<f64>) {
    let mut s = icosphere(k);
    let amount = 0.2 * s.mean_edge();
    s.jitter(amount, u64::from(k));
    let m = s.mesh();
    let l = s.lengths(&m);
    (m, l)
}

/// Random admissible targets on a sphere: `q_i = 2 − 4/V + r_i − r_{i+1}`, `|r_i| ≤ 0.5/V`.
fn targets(n: usize) -> Targets {
    let mut rng = ChaCha8Rng::seed_from_u64(1);
    let base = Rational::from(2) - Rational::from((4, n as i64));
    let r: Vec<Rational> = (0..n)
        .map(|_| Rational::from((rng.gen_range(-50..=50), 100 * n as i64)))
        .collect();
    Targets::from_multiples_of_pi(
        (0..n)
            .map(|i| Rational::from(&base + &r[i]) - &r[(i + 1) % n])
            .collect(),
    )
}

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("uniformize");
    g.sample_size(10).measurement_time(Duration::from_secs(20));
    for k in [22u32, 71] {
        let (m, l) = noisy_sphere(k);
        let t = targets(m.n_vertices());
        let opts = UniformizeOptions::default();
        let sol = uniformize(&m, &l, &t, &opts).expect("valid input");
        eprintln!(
            "icosphere {} faces: converged {}, {} steps, {} Ptolemy flips, max |Θ − θ| {:e}",
            m.n_faces(),
            sol.converged(),
            sol.steps.len(),
            sol.flip_sequence.len(),
            sol.residual_max
        );
        g.bench_function(format!("f64-solve-{}", m.n_faces()), |b| {
            b.iter(|| uniformize(&m, &l, &t, &opts).expect("valid input"));
        });
        if k == 22 {
            let p = Precision::new(256).expect("256 bits");
            g.bench_function(format!("refine-mpfr256-{}", m.n_faces()), |b| {
                b.iter(|| {
                    let r = refine::<Mpfr>(&sol, p, 1e-60, 12).expect("replays");
                    assert!(r.reached);
                    r
                });
            });
            let proof = prove(&sol, 256, 1e-60).expect("a proof attempt");
            assert!(matches!(proof.outcome, CertificateOutcome::Holds { .. }));
            g.bench_function(format!("certificate-mpfr256-{}", m.n_faces()), |b| {
                b.iter(|| {
                    let o = check_certificate(&proof.data, 256).expect("well formed");
                    assert!(matches!(o, CertificateOutcome::Holds { .. }));
                    o
                });
            });
        }
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
