//! Criterion benchmarks: Lobachevsky's function `Л` per call at f64, double-double, MPFR at
//! 128 and 256 bits, and the rigorous enclosure on `Interval<Mpfr>` at 256 bits, over 64
//! arguments spread over (−10, 10) (coefficient tables are built before timing).
//!
//! Run: `cargo bench --bench special -- --measurement-time 3 --warm-up-time 1`.

// criterion's macros generate undocumented public functions.
#![allow(missing_docs)]

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use penner::scalar::{Dd, Interval, Mpfr, Precision, Real};
use penner::special::{lobachevsky, lobachevsky_enclosure};
use std::hint::black_box;

fn arguments() -> Vec<f64> {
    (0..64)
        .map(|i| -10.0 + 20.0 * (f64::from(i) + 0.37) / 64.0)
        .collect()
}

fn bench(c: &mut Criterion) {
    let xs = arguments();
    let mut g = c.benchmark_group("lobachevsky");
    g.throughput(Throughput::Elements(xs.len() as u64));
    g.bench_function("f64", |b| {
        b.iter(|| xs.iter().map(|x| lobachevsky(black_box(x))).sum::<f64>());
    });
    // Triangle angles in (0, π): the native double-double range of B55.
    let angles: Vec<Dd> = (0..64)
        .map(|i| Dd::from_f64(std::f64::consts::PI * (f64::from(i) + 0.37) / 64.0))
        .collect();
    g.bench_function("dd-angles", |b| {
        b.iter(|| {
            angles
                .iter()
                .map(|x| lobachevsky(black_box(x)).approx_f64())
                .sum::<f64>()
        });
    });
    let dd: Vec<Dd> = xs.iter().map(|&x| Dd::from_f64(x)).collect();
    g.bench_function("dd", |b| {
        b.iter(|| {
            dd.iter()
                .map(|x| lobachevsky(black_box(x)).approx_f64())
                .sum::<f64>()
        });
    });
    for bits in [128u64, 256] {
        let p = Precision::new(bits).unwrap();
        let mp: Vec<Mpfr> = xs.iter().map(|&x| Mpfr::from_f64(x, p)).collect();
        let _ = lobachevsky(&mp[0]);
        g.bench_function(format!("mpfr-{bits}"), |b| {
            b.iter(|| {
                mp.iter()
                    .map(|x| lobachevsky(black_box(x)).approx_f64())
                    .sum::<f64>()
            });
        });
    }
    let p = Precision::new(256).unwrap();
    let iv: Vec<Interval<Mpfr>> = xs
        .iter()
        .map(|&x| Interval::point(Mpfr::from_f64(x, p)))
        .collect();
    g.bench_function("interval-mpfr-256", |b| {
        b.iter(|| {
            iv.iter()
                .map(|x| lobachevsky_enclosure(black_box(x)).width_f64())
                .sum::<f64>()
        });
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
