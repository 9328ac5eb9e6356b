//! Criterion benchmarks: the cone angles (angle sums) of a closed mesh with 10⁶ faces,
//! from its edge lengths, in f64, double-double and MPFR at 128 and 256 bits (issue 2,
//! item 9). The mesh is a 1000 × 500 torus grid (two triangles per quad) embedded with
//! jittered vertices; lengths are Euclidean distances, so every triangle is valid.
//!
//! Run: `cargo bench --bench kernels -- --measurement-time 5 --warm-up-time 1`.

// criterion's macros generate undocumented public functions.
#![allow(missing_docs)]

#[path = "../tests/it/meshgen.rs"]
mod meshgen;

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use meshgen::jittered_torus;
use penner::geometry::cone_angles::{cone_angles, cone_angles_per_corner};
use penner::scalar::{Dd, Mpfr, Precision, Real};
use std::hint::black_box;

fn bench_cone_angles(c: &mut Criterion) {
    let (mesh, len) = jittered_torus(1000, 500, 2026);
    let mut g = c.benchmark_group(format!("cone_angles_{}_faces", mesh.n_faces()));
    g.sample_size(10);

    g.bench_function(BenchmarkId::new("fast", "f64"), |b| {
        b.iter(|| black_box(cone_angles(&mesh, black_box(&len))));
    });
    g.bench_function(BenchmarkId::new("per_corner", "f64"), |b| {
        b.iter(|| black_box(cone_angles_per_corner(&mesh, black_box(&len))));
    });

    let dd: Vec<Dd> = len.iter().map(|&x| Dd::from_f64(x)).collect();
    g.bench_function(BenchmarkId::new("fast", "dd"), |b| {
        b.iter(|| black_box(cone_angles(&mesh, black_box(&dd))));
    });
    g.bench_function(BenchmarkId::new("per_corner", "dd"), |b| {
        b.iter(|| black_box(cone_angles_per_corner(&mesh, black_box(&dd))));
    });

    for bits in [128, 256] {
        let p = Precision::new(bits).expect("valid precision");
        let m: Vec<Mpfr> = len.iter().map(|&x| Mpfr::from_f64(x, p)).collect();
        g.bench_function(BenchmarkId::new("fast", format!("mpfr-{bits}")), |b| {
            b.iter(|| black_box(cone_angles(&mesh, black_box(&m))));
        });
    }
    g.finish();
}

criterion_group!(benches, bench_cone_angles);
criterion_main!(benches);
