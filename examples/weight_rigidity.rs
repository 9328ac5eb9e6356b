//! Times the two certificates of T06 (proofs/B102, B103) on a surface file, per precision:
//! the verified Cholesky factorization of the enclosed weight-energy Hessian and the
//! face-wise argument, each with its wall time.
//!
//! `cargo run --release --example weight_rigidity -- SURFACE.off`; without an argument, the
//! flat 64 × 64 torus of `mesh::builders::flat_torus` (8192 faces).

use penner::scalar::{Dd, Mpfr, Precision, Real};
use penner::theorems::t06_weight_rigidity::{certify_by_faces, certify_weight_rigidity};
use std::time::Instant;

fn run<T: Real>(name: &str, mesh: &penner::mesh::Mesh, l: &[T]) {
    let t = Instant::now();
    let chol = certify_weight_rigidity(mesh, l, 0);
    let t_chol = t.elapsed();
    let t = Instant::now();
    let faces = certify_by_faces(mesh, l);
    let t_faces = t.elapsed();
    match chol {
        Ok(c) => println!(
            "{name}: B102 certified in {t_chol:.2?} (λ_min ≥ {:.3e}, radius ≤ {:.3e}, {} free edges, {} bits)",
            c.lambda_min, c.radius_norm, c.free_edges, c.bits
        ),
        Err(e) => println!("{name}: B102 not certified in {t_chol:.2?}: {:?}", e.elements.first()),
    }
    println!(
        "{name}: B103 {} in {t_faces:.2?}",
        if faces.is_ok() {
            "certified"
        } else {
            "not certified"
        }
    );
}

/// The built-in surface: the flat 64 × 64 torus, its lengths from the exact squared ones.
fn flat_torus() {
    let t = penner::mesh::builders::flat_torus(64, 64).expect("64 × 64 is a valid grid");
    let lengths = |p: Precision| -> Vec<Mpfr> {
        t.squared_lengths
            .iter()
            .map(|q| Mpfr::from_rational(q, p).sqrt())
            .collect()
    };
    println!(
        "flat torus 64 × 64: {} faces, {} edges",
        t.mesh.n_faces(),
        t.mesh.n_edges()
    );
    let f64s: Vec<f64> = t
        .squared_lengths
        .iter()
        .map(|q| f64::from_rational(q, ()).sqrt())
        .collect();
    run("f64", &t.mesh, &f64s);
    let dds: Vec<Dd> = t
        .squared_lengths
        .iter()
        .map(|q| Dd::from_rational(q, ()).sqrt())
        .collect();
    run("dd", &t.mesh, &dds);
    run(
        "mpfr-256",
        &t.mesh,
        &lengths(Precision::new(256).expect("256 bits")),
    );
}

fn main() {
    let Some(path) = std::env::args().nth(1) else {
        flat_torus();
        return;
    };
    let s = match penner::io::read_path(std::path::Path::new(&path)) {
        Ok(s) => s,
        Err(e) => {
            eprintln!("{path}: {e}");
            std::process::exit(3);
        }
    };
    println!("{} faces, {} edges", s.mesh.n_faces(), s.mesh.n_edges());
    run("f64", &s.mesh, &s.lengths::<f64>(()));
    run("dd", &s.mesh, &s.lengths::<Dd>(()));
    let p = Precision::new(256).expect("256 bits");
    run("mpfr-256", &s.mesh, &s.lengths::<Mpfr>(p));
}
