//! Flip-to-Delaunay (certified and naive f64) and the library's intrinsic-Delaunay cotan
//! Laplacian (`geometry::laplacian::cotan_laplacian`, compressed sparse rows) on
//! procedurally generated meshes: noisy subdivided icospheres (normal noise of standard
//! deviation 0.3 × mean edge length per coordinate) and a sheared torus of thin triangles.
//!
//! `cargo bench --bench delaunay` (set `PENNER_BENCH_LARGE=1` for the 10⁶-face mesh and
//! `PENNER_EXPORT_MESHES=<dir>` to write the meshes as OBJ for `benches/peers/`).

#![allow(missing_docs)] // criterion_group! generates an undocumented function

#[path = "../tests/it/meshgen.rs"]
mod meshgen;

use criterion::{criterion_group, criterion_main, BatchSize, Criterion};
use meshgen::{icosphere, sheared_torus, Embedded};
use penner::algorithms::flip_to_delaunay::{flip_to_delaunay, FlipKind, FlipOptions};
use penner::algorithms::naive::flip_to_delaunay_naive;
use penner::geometry::laplacian::cotan_laplacian;
use std::time::Duration;

/// Frequency-`k` icosphere with every vertex coordinate moved by normal noise of standard
/// deviation 0.3 × mean edge length (about 16k flips at 10⁵ faces).
fn noisy_icosphere(k: u32) -> Embedded {
    let mut e = icosphere(k);
    let sigma = 0.3 * e.mean_edge();
    e.jitter_normal(sigma, u64::from(k));
    e
}

fn meshes() -> Vec<(String, Embedded)> {
    let mut v = vec![
        ("icosphere-9680".to_string(), noisy_icosphere(22)),
        ("icosphere-100820".to_string(), noisy_icosphere(71)),
        ("torus-100000".to_string(), sheared_torus(500, 100, 8)),
    ];
    if std::env::var_os("PENNER_BENCH_LARGE").is_some() {
        v.push(("icosphere-1000000".to_string(), noisy_icosphere(224)));
        v.push(("torus-1000000".to_string(), sheared_torus(2000, 250, 16)));
    }
    v
}

fn bench(c: &mut Criterion) {
    let export = std::env::var_os("PENNER_EXPORT_MESHES");
    let mut g = c.benchmark_group("delaunay");
    g.sample_size(10)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(3));
    for (name, e) in meshes() {
        let m = e.mesh();
        let l = e.lengths(&m);
        if let Some(dir) = &export {
            let _ = std::fs::create_dir_all(dir);
            let _ = std::fs::write(
                std::path::Path::new(dir).join(format!("{name}.obj")),
                e.obj(),
            );
        }
        // One run outside the timer: flip counts and certification summary.
        let (mut m1, mut l1) = (m.clone(), l.clone());
        let r = flip_to_delaunay(
            &mut m1,
            &mut l1,
            FlipKind::Euclidean,
            &FlipOptions::default(),
        )
        .expect("valid lengths");
        let (mut m2, mut l2) = (m.clone(), l.clone());
        let nr = flip_to_delaunay_naive(&mut m2, &mut l2, FlipKind::Euclidean, usize::MAX);
        eprintln!(
            "{name}: F = {}, certified flips = {}, naive flips = {}, stages = {:?}, \
             refused = {}, undecided = {}, nudged = {}",
            m.n_faces(),
            r.flips,
            nr.flips,
            r.stages,
            r.refused.len(),
            r.undecided.len(),
            r.nudged
        );
        g.bench_function(format!("{name}/certified-flips"), |b| {
            b.iter_batched(
                || (m.clone(), l.clone()),
                |(mut mm, mut ll)| {
                    flip_to_delaunay(
                        &mut mm,
                        &mut ll,
                        FlipKind::Euclidean,
                        &FlipOptions::default(),
                    )
                    .map(|r| r.flips)
                },
                BatchSize::LargeInput,
            );
        });
        g.bench_function(format!("{name}/naive-flips"), |b| {
            b.iter_batched(
                || (m.clone(), l.clone()),
                |(mut mm, mut ll)| {
                    flip_to_delaunay_naive(&mut mm, &mut ll, FlipKind::Euclidean, usize::MAX).flips
                },
                BatchSize::LargeInput,
            );
        });
        g.bench_function(format!("{name}/certified-flips+laplacian"), |b| {
            b.iter_batched(
                || (m.clone(), l.clone()),
                |(mut mm, mut ll)| {
                    let _ = flip_to_delaunay(
                        &mut mm,
                        &mut ll,
                        FlipKind::Euclidean,
                        &FlipOptions::default(),
                    );
                    cotan_laplacian(&mm, &ll).dim()
                },
                BatchSize::LargeInput,
            );
        });
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
