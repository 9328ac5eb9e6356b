//! Reading and writing large surfaces: an OFF noisy icosphere (radial noise, 17
//! significant digits, as `examples/noisy_sphere` writes it) read into the compact form
//! with its `f64` lengths (what `penner delaunay --precision f64` does), read into the
//! exact surface (what `penner check` does, 10⁴ faces), and written as compact JSON.
//!
//! `cargo bench --bench io` (set `PENNER_BENCH_LARGE=1` for the 10⁶-face sphere).

#![allow(missing_docs)] // criterion_group! generates an undocumented function

#[path = "../tests/it/meshgen.rs"]
mod meshgen;

use criterion::{criterion_group, criterion_main, Criterion};
use penner::io::write::{self, MetricKind, Values};
use penner::io::{off, DecimalSurface};
use std::time::Duration;

/// The OFF text of a noisy icosphere of frequency `k` (20k² faces).
fn sphere_off(k: u32) -> String {
    let mut e = meshgen::icosphere(k);
    let a = e.mean_edge();
    e.jitter_radial(a, 1);
    let mut out = Vec::new();
    e.write_off(&mut out).expect("write to memory");
    String::from_utf8(out).expect("ASCII")
}

fn read_f64(text: &str) -> (DecimalSurface, Vec<f64>) {
    let s = off::read_decimal(text).expect("valid OFF");
    let l = s.lengths_f64();
    (s, l)
}

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("io");
    g.sample_size(10)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(3));
    let mut sizes = vec![("icosphere-100820", 71)];
    if std::env::var_os("PENNER_BENCH_LARGE").is_some() {
        sizes.push(("icosphere-1003520", 224));
    }
    let small = sphere_off(22);
    g.bench_function("icosphere-9680/read-off-exact", |b| {
        b.iter(|| off::read(&small).expect("valid OFF").mesh.n_edges());
    });
    for (name, k) in sizes {
        let text = sphere_off(k);
        eprintln!("{name}: {} bytes of OFF", text.len());
        g.bench_function(format!("{name}/read-off-f64-lengths"), |b| {
            b.iter(|| read_f64(&text).1.len());
        });
        let (s, l) = read_f64(&text);
        g.bench_function(format!("{name}/write-json-f64"), |b| {
            b.iter(|| {
                let mut out = Vec::with_capacity(64 << 20);
                write::json::<String>(
                    &mut out,
                    "s",
                    &s.mesh,
                    MetricKind::Lengths,
                    Values::Binary64(&l),
                    None,
                )
                .expect("write to memory");
                out.len()
            });
        });
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
