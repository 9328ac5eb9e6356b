//! `penner check` without reading or printing: every registered check of the catalogue
//! (`oracle::registry::run_case`, in parallel over (check, precision) pairs) on noisy
//! subdivided icospheres, at f64 and at the default precisions `f64,dd,256`.
//!
//! `cargo bench --bench check` (set `PENNER_BENCH_LARGE=1` for the 10⁵-face mesh at the
//! default precisions). The whole command on large files (reading, checking, printing, peak
//! memory) is measured with `/usr/bin/time -v penner check sphere.off --precision f64`; see
//! docs/benchmarks.md, "Large meshes".

#![allow(missing_docs)] // criterion_group! generates an undocumented function

#[path = "../tests/it/meshgen.rs"]
mod meshgen;

use criterion::{criterion_group, criterion_main, Criterion};
use meshgen::icosphere;
use penner::io::{Metric, Surface};
use penner::oracle::catalogue;
use penner::oracle::precision::{parse_list, Prec};
use penner::oracle::registry::run_case;
use penner::theorems::Settings;
use rug::Rational;
use std::time::Duration;

/// A frequency-`k` icosphere with normal noise of 0.3 × the mean edge length, as a surface
/// whose exact lengths are its binary64 lengths.
fn noisy_sphere(k: u32) -> Surface {
    let mut e = icosphere(k);
    let sigma = 0.3 * e.mean_edge();
    e.jitter_normal(sigma, u64::from(k));
    let mesh = e.mesh();
    let lengths = e
        .lengths(&mesh)
        .into_iter()
        .map(|x| Rational::from_f64(x).expect("finite length"))
        .collect();
    Surface::new("noisy icosphere", mesh, Metric::Lengths(lengths), None).expect("valid")
}

fn bench_check(c: &mut Criterion) {
    let mut g = c.benchmark_group("check");
    g.sample_size(10);
    g.measurement_time(Duration::from_secs(20));
    let checks = catalogue();
    let settings = Settings::default();
    let default = parse_list("f64,dd,256").expect("valid list");
    let mut cases = vec![(22, false), (71, false)];
    if std::env::var_os("PENNER_BENCH_LARGE").is_some() {
        cases.push((71, true));
    }
    for (k, all) in cases {
        let s = noisy_sphere(k);
        let precs = if all {
            default.clone()
        } else {
            vec![Prec::F64]
        };
        let name = format!(
            "{}-faces/{}",
            s.mesh.n_faces(),
            if all { "f64,dd,256" } else { "f64" }
        );
        g.bench_function(name, |b| {
            b.iter(|| run_case(&s, &checks, &precs, &settings));
        });
    }
    let small = noisy_sphere(22);
    g.bench_function(format!("{}-faces/f64,dd,256", small.mesh.n_faces()), |b| {
        b.iter(|| run_case(&small, &checks, &default, &settings));
    });
    g.finish();
}

criterion_group!(benches, bench_check);
criterion_main!(benches);
