//! The sphere target of discrete uniformization (notes Thm 9; B74–B76): a noisy icosphere
//! (every vertex moved by up to 0.2 × the mean edge length, so not inscribed) mapped to a
//! conformally equivalent convex polyhedron inscribed in the unit sphere; the disk problem
//! certified, the planar layout certified Delaunay and convex, the length cross ratios of
//! the output's 3-D chords compared with the input's.
//!
//! ```sh
//! cargo run --release --example uniformize_sphere -- 8    # frequency 8: 1280 faces
//! cargo run --release --example uniformize_sphere -- 71 256  # 100 820 faces, MPFR-256
//! ```
//!
//! With a second argument `BITS`, the disk problem is also refined in MPFR at `BITS` bits
//! (`f64` factor, MPFR residuals; tolerance `2^(56 − BITS)`) and certified at `BITS` bits
//! (B91, B76), and the wall times are reported as ratios to the `f64` solve.

#[path = "../tests/it/meshgen.rs"]
mod meshgen;

use penner::scalar::Precision;
use penner::uniformization::certificate::CertificateOutcome;
use penner::uniformization::dirichlet_certificate::certify_disk;
use penner::uniformization::sphere::{uniformize_sphere, SphereOptions};
use penner::uniformization::sphere_checks::{cross_ratio_deviation, planar_delaunay};
use penner::uniformization::sphere_refine::prove_disk;
use std::process::ExitCode;
use std::time::Instant;

fn main() -> ExitCode {
    let k: u32 = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(4);
    let mut s = meshgen::icosphere(k.max(1));
    let amount = 0.2 * s.mean_edge();
    s.jitter(amount, u64::from(k));
    let m = s.mesh();
    let l = s.lengths(&m);
    let t = Instant::now();
    let sol = match uniformize_sphere(&m, &l, &SphereOptions::default()) {
        Ok(sol) => sol,
        Err(e) => {
            eprintln!("{e}");
            return ExitCode::FAILURE;
        }
    };
    let solve = t.elapsed();
    println!(
        "{} faces: pole v{}, {} Newton steps, {} Ptolemy flips, max |Θ − θ| = {:e}, {:.3} s",
        m.n_faces(),
        sol.pole,
        sol.solution.steps.len(),
        sol.flip_sequence.len(),
        sol.solution.residual_max,
        solve.as_secs_f64()
    );
    let t = Instant::now();
    let (_, outcome) = certify_disk(&sol, 128);
    match outcome {
        CertificateOutcome::Holds { distance, .. } => println!(
            "disk problem certified: exact solution within {distance:e} ({:.3} s)",
            t.elapsed().as_secs_f64()
        ),
        CertificateOutcome::Undecided { reason } => println!("not certified: {reason}"),
    }
    let bits: Option<u32> = std::env::args().nth(2).and_then(|a| a.parse().ok());
    if let Some(prec) = bits.and_then(|b| Precision::new(u64::from(b)).ok()) {
        let b = prec.bits();
        let t = Instant::now();
        match prove_disk(&sol, None, prec, 2f64.powi(56 - b as i32)) {
            Ok(p) => {
                let total = t.elapsed().as_secs_f64();
                let verdict = match &p.outcome {
                    CertificateOutcome::Holds {
                        distance, residual, ..
                    } => format!("certified: within {distance:e}, ‖Θ − θ‖₂ ≤ {residual:e}"),
                    CertificateOutcome::Undecided { reason } => format!("not certified: {reason}"),
                };
                println!(
                    "MPFR-{b}: max |Θ − θ| per step {:?}; {verdict}; refine + certify {total:.3} s = {:.1}× the f64 solve",
                    p.history,
                    total / solve.as_secs_f64()
                );
            }
            Err(e) => println!("MPFR-{b}: refinement failed: {e}"),
        }
    }
    let planar = planar_delaunay(&sol.solution.mesh, &sol.planar);
    println!(
        "planar layout certified Delaunay with a convex boundary: {}",
        planar.holds()
    );
    if let Some(d) = cross_ratio_deviation(&sol, &sol.initial_lengths) {
        println!("numerical: max |log c(chords) − log c(input)| = {d:e}");
    }
    ExitCode::SUCCESS
}
