//! Criterion benchmarks: the cone angles (angle sums) of a closed mesh with 10⁶ faces,
//! from its edge lengths, in f64, double-double and MPFR at 128 and 256 bits (issue 2,
//! item 9). The mesh is a 1000 × 500 torus grid (two triangles per quad) embedded with
//! jittered vertices; lengths are Euclidean distances, so every triangle is valid.
//!
//! Run: `cargo bench --bench kernels -- --measurement-time 5 --warm-up-time 1`.
//!
//! On a shared machine, `PENNER_BENCH_CPU=1` measures the CPU time of the benchmark thread
//! (Linux `/proc/thread-self/schedstat`, nanoseconds) instead of wall time, so that other
//! processes competing for the cores do not inflate the figures.

// criterion's macros generate undocumented public functions.
#![allow(missing_docs)]

#[path = "../tests/it/meshgen.rs"]
mod meshgen;

use criterion::measurement::{Measurement, ValueFormatter, WallTime};
use criterion::{criterion_main, BenchmarkId, Criterion, Throughput};
use meshgen::jittered_torus;
use penner::geometry::cone_angles::{cone_angles, cone_angles_per_corner};
use penner::scalar::{Dd, Mpfr, Precision, Real};
use std::hint::black_box;

/// CPU time of the calling thread in nanoseconds (first field of
/// `/proc/thread-self/schedstat`); 0 where it cannot be read.
fn thread_cpu_ns() -> u64 {
    std::fs::read_to_string("/proc/thread-self/schedstat")
        .ok()
        .and_then(|s| s.split_whitespace().next()?.parse().ok())
        .unwrap_or(0)
}

/// Thread CPU time as a criterion measurement.
struct ThreadCpu;

/// Formats nanoseconds of CPU time.
struct CpuFormatter;

impl ValueFormatter for CpuFormatter {
    fn scale_values(&self, typical: f64, values: &mut [f64]) -> &'static str {
        let (factor, unit) = if typical < 1e3 {
            (1.0, "ns cpu")
        } else if typical < 1e6 {
            (1e-3, "µs cpu")
        } else if typical < 1e9 {
            (1e-6, "ms cpu")
        } else {
            (1e-9, "s cpu")
        };
        for v in values.iter_mut() {
            *v *= factor;
        }
        unit
    }
    fn scale_throughputs(&self, _: f64, _: &Throughput, values: &mut [f64]) -> &'static str {
        for v in values.iter_mut() {
            *v = 1e9 / *v;
        }
        "iter/s cpu"
    }
    fn scale_for_machines(&self, _: &mut [f64]) -> &'static str {
        "ns"
    }
}

impl Measurement for ThreadCpu {
    type Intermediate = u64;
    type Value = u64;
    fn start(&self) -> u64 {
        thread_cpu_ns()
    }
    fn end(&self, start: u64) -> u64 {
        thread_cpu_ns().saturating_sub(start)
    }
    fn add(&self, a: &u64, b: &u64) -> u64 {
        a + b
    }
    fn zero(&self) -> u64 {
        0
    }
    fn to_f64(&self, v: &u64) -> f64 {
        *v as f64
    }
    fn formatter(&self) -> &dyn ValueFormatter {
        &CpuFormatter
    }
}

fn bench_cone_angles<M: Measurement>(c: &mut Criterion<M>) {
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

fn benches() {
    if std::env::var_os("PENNER_BENCH_CPU").is_some() {
        let mut c = Criterion::default()
            .with_measurement(ThreadCpu)
            .configure_from_args();
        bench_cone_angles(&mut c);
    } else {
        let mut c: Criterion<WallTime> = Criterion::default().configure_from_args();
        bench_cone_angles(&mut c);
    }
}

criterion_main!(benches);
