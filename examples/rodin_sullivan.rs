//! Rodin–Sullivan (T12): hexagonal packings of the upper half-disk of spacing ε, packed
//! maximally (`f64`), against the explicit Riemann map; prints `max_K |f_ε − f|` per level and
//! the local rates `log₂(e(ε)/e(ε/2))` (measured, not a theorem: Rodin–Sullivan prove
//! convergence without a rate).
//!
//! ```sh
//! cargo run --release --example rodin_sullivan -- 6    # ε = 1/4 … 1/128
//! cargo run --release --example rodin_sullivan -- 7    # and 1/256 (about 1.2·10⁵ vertices)
//! ```

use penner::theorems::t12_rodin_sullivan::{
    check_refinement, half_disk_map, local_rates, measure_level, BASE, C,
};
use std::time::Instant;

fn main() {
    let levels: u32 = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(6);
    let f = |z: C| half_disk_map(BASE, z);
    let mut out = Vec::new();
    println!(
        "{:>10} {:>9} {:>12} {:>8} {:>13} {:>9}",
        "ε", "vertices", "max_K error", "rate", "layout defect", "time s"
    );
    for k in 0..levels {
        let eps = 0.25 / f64::from(1u32 << k);
        let t = Instant::now();
        let level = match measure_level(eps, &f) {
            Ok(l) => l,
            Err(e) => {
                eprintln!("ε = {eps}: {e}");
                return;
            }
        };
        out.push(level);
        let rate = local_rates(&out).last().copied();
        let l = &out[out.len() - 1];
        println!(
            "{:>10.6} {:>9} {:>12.4e} {:>8} {:>13.3e} {:>9.2}",
            eps,
            l.vertices,
            l.error,
            rate.map_or("–".into(), |r| format!("{r:.3}")),
            l.layout_defect,
            t.elapsed().as_secs_f64()
        );
    }
    if out.len() >= 2 {
        let (a, b) = (&out[0], &out[out.len() - 1]);
        let overall = (a.error / b.error).log2() / (out.len() - 1) as f64;
        println!("overall rate {overall:.3} (error ≈ C·ε^rate)");
    }
    println!("{:?}", check_refinement(&out));
}
