//! Hyperbolic uniformization with flips (notes Thm 11; B87, B89, B104) on a random
//! multi-vertex genus-2 surface: geometric flips of the input, Newton steps and Ptolemy
//! flips of the `f64` solve, and the wall time of the solve, of the double-double
//! refinement and of the certificate (B39 on the final triangulation, the flips replayed
//! on enclosures, Delaunay on the box), with their ratios to the `f64` solve.
//!
//! ```sh
//! cargo run --release --example uniformize_hyperbolic -- 1000 1       # ≥ 1000 faces, seed 1
//! cargo run --release --example uniformize_hyperbolic -- 10000 1 256  # MPFR-256 refinement
//! ```
//!
//! `BITS` (default 128): the interval precision of the certificate; up to 128 the
//! refinement is double-double, beyond it MPFR at `BITS`.
//!
//! The surface: `mesh::builders::random_surface(2, n, seed)` with `2n + 4 ≥ FACES` faces
//! (vertices inserted in random faces, then `3E` random flips), every length uniform in
//! `[1, 1.9]` (so every face is a strict triangle), all targets `2π`.

use penner::mesh::builders;
use penner::scalar::{Dd, Mpfr, Precision, Real};
use penner::uniformization::hyperbolic::{
    gershgorin_estimate_log, uniformize_hyperbolic, HyperbolicOptions,
};
use penner::uniformization::hyperbolic_certificate::{certify_hyperbolic, refine_hyperbolic};
use penner::uniformization::hyperbolic_flips::leibon_sum;
use penner::uniformization::Targets;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rug::Rational;
use std::process::ExitCode;
use std::time::Instant;

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let faces: u32 = args.first().and_then(|s| s.parse().ok()).unwrap_or(1000);
    let seed: u64 = args.get(1).and_then(|s| s.parse().ok()).unwrap_or(1);
    let bits: u32 = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(128);
    let n = faces.saturating_sub(4).div_ceil(2).max(1);
    let Ok(m) = builders::random_surface(2, n, seed) else {
        eprintln!("could not build the surface");
        return ExitCode::FAILURE;
    };
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let l: Vec<f64> = (0..m.n_edges()).map(|_| rng.gen_range(1.0..1.9)).collect();
    let targets = Targets::flat(m.n_vertices());
    println!(
        "genus 2, {} vertices, {} edges, {} faces, lengths in [1, 1.9], seed {seed}",
        m.n_vertices(),
        m.n_edges(),
        m.n_faces()
    );
    let t = Instant::now();
    let sol = match uniformize_hyperbolic(&m, &l, &targets, &HyperbolicOptions::default()) {
        Ok(s) => s,
        Err(e) => {
            eprintln!("{e}");
            return ExitCode::FAILURE;
        }
    };
    let t_solve = t.elapsed().as_secs_f64();
    println!(
        "f64 solve: {} geometric flips, {} Newton steps, {} Ptolemy flips, stop {:?}, max |Θ − θ| = {:e}, {t_solve:.3} s",
        sol.input_flips.len(),
        sol.steps.len(),
        sol.flips.len(),
        sol.stop,
        sol.residual_max
    );
    let scaled = |e: penner::mesh::Edge| {
        let h = e.halfedge();
        sol.base_log[e.idx()] + sol.u[sol.mesh.tail(h).idx()] + sol.u[sol.mesh.tip(h).idx()]
    };
    let min_leibon = sol
        .mesh
        .edges()
        .filter_map(|e| leibon_sum(&sol.mesh, e, &scaled).ok())
        .fold(f64::INFINITY, f64::min);
    println!(
        "at u: least Leibon sum {min_leibon:e}, Gershgorin estimate {:?} (f64)",
        gershgorin_estimate_log(&sol.mesh, &sol.base_log, &sol.u)
    );
    let t = Instant::now();
    // Double-double up to 128 bits, MPFR at `bits` beyond (residual to 2⁻⁽ᵇⁱᵗˢ⁻⁵⁶⁾).
    let refined = if bits <= 128 {
        refine_hyperbolic::<Dd>(&sol, (), 1e-28, 30).map(|r| {
            (
                r.residual_max(),
                r.u.iter().filter_map(Real::to_rational).collect(),
            )
        })
    } else {
        let Ok(prec) = Precision::new(u64::from(bits)) else {
            eprintln!("{bits} bits out of range");
            return ExitCode::FAILURE;
        };
        refine_hyperbolic::<Mpfr>(&sol, prec, 2f64.powi(56 - bits as i32), 60).map(|r| {
            (
                r.residual_max(),
                r.u.iter().filter_map(Real::to_rational).collect(),
            )
        })
    };
    let Ok((residual, u)): Result<(f64, Vec<Rational>), _> = refined else {
        eprintln!("refinement failed");
        return ExitCode::FAILURE;
    };
    let t_refine = t.elapsed().as_secs_f64();
    println!(
        "refinement ({}): max |Θ − θ| = {residual:e}, {t_refine:.3} s ({:.1}× the solve)",
        if bits <= 128 {
            "Dd".to_string()
        } else {
            format!("MPFR {bits}")
        },
        t_refine / t_solve
    );
    let t = Instant::now();
    let Ok(cert) = certify_hyperbolic(&sol, &u, bits) else {
        eprintln!("certificate refused its input");
        return ExitCode::FAILURE;
    };
    let t_cert = t.elapsed().as_secs_f64();
    println!(
        "certificate ({bits}-bit intervals): {:?}, {t_cert:.3} s ({:.1}× the solve)",
        cert.existence,
        t_cert / t_solve
    );
    ExitCode::SUCCESS
}
