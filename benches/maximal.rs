//! Maximal packings (T11) of random disk triangulations (`random_planar`, Delaunay of random
//! points): the `f64` Newton solve (faer sparse Cholesky) and the whole computation laid out for
//! tangency within `10⁻³⁰` at 128 bits (B99 stopping rule) (its own `f64` solve, mixed-precision refinement, MPFR
//! layout), on 10⁴ vertices; with `PENNER_BENCH_1E5=1` also on 10⁵.
//!
//! `cargo bench --bench maximal`; single runs with peak memory:
//! `/usr/bin/time -v target/release/examples/maximal_packing 10000 100000`.

#![allow(missing_docs)] // criterion_group! generates an undocumented function

use criterion::{criterion_group, criterion_main, Criterion};
use penner::circles::maximal::{maximal_disk, Options};
use penner::mesh::builders::random_planar;
use penner::scalar::{Mpfr, Precision};
use std::time::Duration;

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("maximal");
    g.sample_size(10).measurement_time(Duration::from_secs(30));
    let mut sizes = vec![10_000u32];
    if std::env::var("PENNER_BENCH_1E5").is_ok_and(|v| v == "1") {
        sizes.push(100_000);
    }
    let prec = Precision::new(128).expect("128 bits");
    let refined = Options {
        epsilon: Some(1e-30),
        ..Options::default()
    };
    for n in sizes {
        let mesh = random_planar(n, 1).expect("a disk").mesh;
        g.bench_function(format!("f64-{n}"), |b| {
            b.iter(|| maximal_disk::<f64>(&mesh, (), &Options::default()).expect("packs"));
        });
        g.bench_function(format!("mpfr128-1e-30-{n}"), |b| {
            b.iter(|| maximal_disk::<Mpfr>(&mesh, prec, &refined).expect("packs"));
        });
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
