//! Maximal packings of large random disk triangulations (T11): time of the `f64` solve and of
//! the computation (`maximal_disk_within`: at `stopping::bits_for(ε, n)` bits, once more at
//! more bits when the layout is precision-limited) whose layout aims at tangency within `ε = 10⁻³⁰` (the refinement
//! tightened until the measured defect is below `ε/2⁴`, B99), and the certificate of tangency
//! within 10⁻³⁰ (B95) at 256 bits.
//!
//! ```sh
//! cargo run --release --example maximal_packing -- 10000 100000
//! /usr/bin/time -v target/release/examples/maximal_packing 100000   # peak memory
//! ```

use penner::circles::maximal::tangency::{check_packing, exact_circles, PackingVerdict};
use penner::circles::maximal::{maximal_disk, maximal_disk_within, Options};
use penner::mesh::builders::random_planar;
use rug::Rational;
use std::time::Instant;

fn main() {
    let sizes: Vec<u32> = std::env::args()
        .skip(1)
        .filter_map(|a| a.parse().ok())
        .collect();
    let sizes = if sizes.is_empty() {
        vec![10_000]
    } else {
        sizes
    };
    for n in sizes {
        let Ok(embedded) = random_planar(n, 1) else {
            eprintln!("cannot build a disk of {n} vertices");
            continue;
        };
        let mesh = embedded.mesh;
        let t0 = Instant::now();
        let p = match maximal_disk::<f64>(&mesh, (), &Options::default()) {
            Ok(p) => p,
            Err(e) => {
                eprintln!("n = {n}: {e}");
                continue;
            }
        };
        let f64_time = t0.elapsed().as_secs_f64();
        let t1 = Instant::now();
        let q = match maximal_disk_within(&mesh, 1e-30, 128, &Options::default()) {
            Ok(q) => q,
            Err(e) => {
                eprintln!("n = {n}: {e}");
                continue;
            }
        };
        let mp_time = t1.elapsed().as_secs_f64();
        let (q, bits) = q;
        let t2 = Instant::now();
        let marks: Vec<bool> = q.interior.iter().map(|b| !b).collect();
        let verdict = exact_circles(&q.circles).map(|c| {
            check_packing(
                &mesh,
                &c,
                &Rational::from((1, 10u128.pow(30))),
                256,
                Some(&marks),
            )
        });
        let cert_time = t2.elapsed().as_secs_f64();
        let verdict = match verdict {
            Some(PackingVerdict::Holds { max_defect }) => {
                format!("certified, defect ≤ {max_defect:.1e}")
            }
            Some(PackingVerdict::Fails(w)) => format!("fails: {} ({})", w.len(), w[0]),
            Some(PackingVerdict::Undecided(w)) => format!("undecided: {}", w.len()),
            None => "no exact circles".into(),
        };
        println!(
            "n = {n}: f64 {f64_time:.2} s ({} Newton iterations, residual {:.1e}); ε = 1e-30 at {bits} bits {mp_time:.2} s ({} steps, {} layouts, ratio {:.1}); certificate at 256 bits {cert_time:.2} s: {verdict}",
            p.newton_iterations,
            p.f64_residual,
            q.refinement_steps,
            q.layouts,
            mp_time / f64_time
        );
    }
}
