//! Criterion benchmarks: the cone angles (angle sums) of a closed mesh with 10⁶ faces,
//! from its edge lengths, in f64, double-double and MPFR at 128 and 256 bits (issue 2,
//! item 9). The mesh is a 1000 × 500 torus grid (two triangles per quad) embedded with
//! jittered vertices; lengths are Euclidean distances, so every triangle is valid.
//!
//! Run: `cargo bench --bench kernels -- --measurement-time 5 --warm-up-time 1`.

// criterion's macros generate undocumented public functions.
#![allow(missing_docs)]

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use penner::geometry::cone_angles::{cone_angles, cone_angles_per_corner};
use penner::mesh::Mesh;
use penner::scalar::{Dd, Mpfr, Precision, Real};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::f64::consts::PI;
use std::hint::black_box;

/// A jittered torus grid with `2·nu·nv` faces and its f64 edge lengths.
fn torus(nu: u32, nv: u32) -> (Mesh, Vec<f64>) {
    let mut rng = ChaCha8Rng::seed_from_u64(2026);
    let id = |i: u32, j: u32| (i % nu) * nv + (j % nv);
    let mut faces = Vec::with_capacity(2 * (nu * nv) as usize);
    for i in 0..nu {
        for j in 0..nv {
            faces.push([id(i, j), id(i + 1, j), id(i + 1, j + 1)]);
            faces.push([id(i, j), id(i + 1, j + 1), id(i, j + 1)]);
        }
    }
    let mesh = Mesh::from_faces(nu * nv, &faces).expect("the torus grid is a valid mesh");
    let pos: Vec<[f64; 3]> = (0..nu * nv)
        .map(|k| {
            let (i, j) = (k / nv, k % nv);
            let u = 2.0 * PI * (f64::from(i) + rng.gen_range(-0.2..0.2)) / f64::from(nu);
            let v = 2.0 * PI * (f64::from(j) + rng.gen_range(-0.2..0.2)) / f64::from(nv);
            let r = 1.0 + 0.4 * v.cos();
            [r * u.cos(), r * u.sin(), 0.4 * v.sin()]
        })
        .collect();
    let len = mesh
        .edges()
        .map(|e| {
            let h = e.halfedge();
            let (p, q) = (pos[mesh.tail(h).idx()], pos[mesh.tip(h).idx()]);
            ((p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2) + (p[2] - q[2]).powi(2)).sqrt()
        })
        .collect();
    (mesh, len)
}

fn bench_cone_angles(c: &mut Criterion) {
    let (mesh, len) = torus(1000, 500);
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
