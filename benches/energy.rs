//! Criterion benchmarks: the discrete-uniformization energy `E`, its gradient `Θ − θ` and
//! the sparse Hessian assembly (`penner::variational::energy`) on a closed mesh (a
//! jittered torus grid, 4000 faces by default so that the run stays short; 10⁵ faces with
//! `PENNER_BENCH_FACES_GRID=250,200`), in f64, double-double and MPFR-256, and the
//! cone-angle kernel alone (`geometry::cone_angles`, f64) on the same mesh for the ratio
//! (E + ∇E + H at f64) / (cone angles at f64). The input of `E` is the scaled logarithmic
//! lengths `λ̃` (computed once, outside the timing, as a Newton step would keep them);
//! `pattern_reused` times the same with the Hessian's sparsity pattern built once, and
//! `gradient_hessian` without `E` (no Lobachevsky function), `fast_f64` the binary64 pass
//! of `variational::fast_f64` (each corner angle once, proofs/B88), `fast_mpfr` its MPFR
//! counterpart `variational::fast_mpfr` (proofs/B29) at 128 and 256 bits.
//!
//! After the group, the ratios Dd/f64 and MPFR-256/f64 of `energy_gradient_hessian` (and
//! of the one-pass kernels) are printed from criterion's estimates of this run (the mean
//! of each id, read from `target/criterion`; an id filtered out is skipped).
//!
//! Run: `cargo bench --bench energy -- --measurement-time 5 --warm-up-time 1`.
//! `PENNER_BENCH_FACES_GRID=NU,NV` picks another grid (2·NU·NV faces).

// criterion's macros generate undocumented public functions.
#![allow(missing_docs)]

#[path = "../tests/it/meshgen.rs"]
mod meshgen;

use criterion::{criterion_main, BenchmarkId, Criterion};
use meshgen::jittered_torus;
use penner::geometry::cone_angles::cone_angles;
use penner::mesh::Mesh;
use penner::scalar::{Dd, Mpfr, Precision, Real};
use penner::special::lobachevsky;
use penner::variational::energy::{
    energy_gradient_hessian_at, energy_gradient_hessian_with, gradient_at, hessian_at, log_lengths,
};
use penner::variational::fast_f64::energy_gradient_hessian_f64;
use penner::variational::fast_mpfr::energy_gradient_hessian_mpfr;
use penner::variational::pattern::HessianPattern;
use penner::variational::triangle::angles_from_log_lengths;
use std::hint::black_box;

/// `E`, `∇E` and the Hessian from the log lengths `λ̃` (`u = 0`, targets 2π).
fn energy_all<T: Real>(mesh: &Mesh, lt: &[T], u: &[T], t: &[T]) -> usize {
    let parts = energy_gradient_hessian_at(mesh, lt, u, t);
    black_box((parts.energy, parts.gradient));
    parts.hessian.dim()
}

fn run<T: Real + 'static>(
    g: &mut criterion::BenchmarkGroup<'_, criterion::measurement::WallTime>,
    name: &str,
    mesh: &Mesh,
    len: &[f64],
    ctx: T::Ctx,
) {
    let l: Vec<T> = len.iter().map(|&x| T::from_f64(x, ctx)).collect();
    let lt = log_lengths(&l);
    let n = mesh.n_vertices();
    let u = vec![T::from_f64(0.0, ctx); n];
    let t = vec![T::pi(ctx) * &T::from_f64(2.0, ctx); n];
    g.bench_function(BenchmarkId::new("energy_gradient_hessian", name), |b| {
        b.iter(|| black_box(energy_all(mesh, black_box(&lt), &u, &t)));
    });
    let pattern = HessianPattern::new(mesh);
    g.bench_function(BenchmarkId::new("pattern_reused", name), |b| {
        b.iter(|| {
            let p = energy_gradient_hessian_with(&pattern, mesh, black_box(&lt), &u, &t);
            black_box(p.energy)
        });
    });
    if let Some(lt64) = (&lt as &dyn std::any::Any).downcast_ref::<Vec<f64>>() {
        let (u64, t64) = (vec![0.0; n], vec![std::f64::consts::TAU; n]);
        g.bench_function(BenchmarkId::new("fast_f64", name), |b| {
            b.iter(|| {
                let p = energy_gradient_hessian_f64(&pattern, mesh, black_box(lt64), &u64, &t64);
                black_box(p.energy)
            });
        });
    }
    if let (Some(ltm), Some(um), Some(tm)) = (
        (&lt as &dyn std::any::Any).downcast_ref::<Vec<Mpfr>>(),
        (&u as &dyn std::any::Any).downcast_ref::<Vec<Mpfr>>(),
        (&t as &dyn std::any::Any).downcast_ref::<Vec<Mpfr>>(),
    ) {
        g.bench_function(BenchmarkId::new("fast_mpfr", name), |b| {
            b.iter(|| {
                let p = energy_gradient_hessian_mpfr(&pattern, mesh, black_box(ltm), um, tm);
                black_box(p.energy)
            });
        });
    }
    g.bench_function(BenchmarkId::new("gradient_hessian", name), |b| {
        b.iter(|| {
            let gr = gradient_at(mesh, black_box(&lt), &t);
            black_box((gr, hessian_at(mesh, &lt).dim()))
        });
    });
}

fn grid() -> (u32, u32) {
    std::env::var("PENNER_BENCH_FACES_GRID")
        .ok()
        .and_then(|s| {
            let (a, b) = s.split_once(',')?;
            Some((a.trim().parse().ok()?, b.trim().parse().ok()?))
        })
        .unwrap_or((50, 40))
}

fn bench_energy(c: &mut Criterion) {
    let (nu, nv) = grid();
    let (mesh, len) = jittered_torus(nu, nv, 2026);
    let mut g = c.benchmark_group(format!("energy_{}_faces", mesh.n_faces()));
    g.sample_size(10);
    g.bench_function(BenchmarkId::new("cone_angles", "f64"), |b| {
        b.iter(|| black_box(cone_angles(&mesh, black_box(&len))));
    });
    g.bench_function(BenchmarkId::new("hessian_pattern", "f64"), |b| {
        b.iter(|| black_box(HessianPattern::new(black_box(&mesh)).dim()));
    });
    // Л alone on the mesh's corner angles, three per face (its share of E + ∇E + H at f64).
    let lt64 = log_lengths(&len);
    let angles: Vec<f64> = mesh
        .faces()
        .flat_map(|f| {
            let x = mesh.face_halfedges(f).map(|h| lt64[h.edge().idx()]);
            angles_from_log_lengths(&x)
        })
        .collect();
    g.bench_function(BenchmarkId::new("lobachevsky_of_angles", "f64"), |b| {
        b.iter(|| {
            let s: f64 = black_box(&angles).iter().map(lobachevsky).sum();
            black_box(s)
        });
    });
    g.bench_function(BenchmarkId::new("atan_of_angles", "f64"), |b| {
        b.iter(|| {
            let s: f64 = black_box(&angles).iter().copied().map(f64::atan).sum();
            black_box(s)
        });
    });
    run::<f64>(&mut g, "f64", &mesh, &len, ());
    run::<Dd>(&mut g, "dd", &mesh, &len, ());
    for bits in [128u64, 256] {
        let p = Precision::new(bits).expect("valid precision");
        run::<Mpfr>(&mut g, &format!("mpfr-{bits}"), &mesh, &len, p);
    }
    let group = format!("energy_{}_faces", mesh.n_faces());
    g.finish();
    print_ratios(&group);
}

/// The mean time of `group/function/value` in this run, from criterion's
/// `new/estimates.json` (nanoseconds), or `None` when it was not measured.
fn mean_ns(group: &str, function: &str, value: &str) -> Option<f64> {
    let target = std::env::var("CARGO_TARGET_DIR").unwrap_or_else(|_| "target".into());
    let path = std::path::Path::new(&target)
        .join("criterion")
        .join(group)
        .join(function)
        .join(value)
        .join("new/estimates.json");
    let text = std::fs::read_to_string(path).ok()?;
    let json: serde_json::Value = serde_json::from_str(&text).ok()?;
    json["mean"]["point_estimate"].as_f64()
}

/// Prints the ratios of issue 13: each backend's `E + ∇E + H` over `f64`'s.
fn print_ratios(group: &str) {
    let Some(base) = mean_ns(group, "energy_gradient_hessian", "f64") else {
        return;
    };
    println!(
        "ratios over energy_gradient_hessian/f64 ({:.3} ms):",
        base / 1e6
    );
    for (function, value) in [
        ("cone_angles", "f64"),
        ("fast_f64", "f64"),
        ("energy_gradient_hessian", "dd"),
        ("energy_gradient_hessian", "mpfr-128"),
        ("energy_gradient_hessian", "mpfr-256"),
        ("fast_mpfr", "mpfr-128"),
        ("fast_mpfr", "mpfr-256"),
    ] {
        if let Some(t) = mean_ns(group, function, value) {
            println!("  {function}/{value}: {:.3} ms, {:.1}×", t / 1e6, t / base);
        }
    }
}

fn benches() {
    let mut c = Criterion::default().configure_from_args();
    bench_energy(&mut c);
}

criterion_main!(benches);
