//! Times the two certificates of T06 (proofs/B102, B103) on a surface file, per precision:
//! the verified Cholesky factorization of the enclosed weight-energy Hessian and the
//! face-wise argument, each with its wall time.
//!
//! `cargo run --release --example weight_rigidity -- SURFACE.off`

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

fn main() {
    let Some(path) = std::env::args().nth(1) else {
        eprintln!("usage: weight_rigidity SURFACE");
        std::process::exit(3);
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
