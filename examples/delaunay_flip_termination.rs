//! Delaunay flip termination (T21): flipping any metric to intrinsic Delaunay terminates,
//! and afterwards every edge is certified Delaunay. Shown on random surfaces of genus 0–2
//! with a conformally scaled metric, at f64, double-double and MPFR-256.
//!
//! Run: `cargo run --release --example delaunay_flip_termination`

use penner::algorithms::flip_to_delaunay::{flip_to_delaunay, FlipKind, FlipOptions};
use penner::oracle::registry::{by_id, run_one, Outcome};
use penner::oracle::{precision::parse_list, report, Metric, MetricOps, Prec, Surface};
use penner::scalar::{Dd, Mpfr, Real};
use penner::theorems::Settings;
use rug::Rational;

/// Flips needed to reach Delaunay in backend `T`.
fn flips<T: Real>(s: &Surface, ctx: T::Ctx) -> usize {
    let mut m = s.mesh.clone();
    let mut l: Vec<T> = s.lengths(ctx);
    flip_to_delaunay(&mut m, &mut l, FlipKind::Euclidean, &FlipOptions::default())
        .map_or(0, |r| r.flips)
}

fn main() {
    let check = by_id("T21").expect("T21 is in the registry");
    let mut bad = 0;
    for (g, n) in [(0u32, 40u32), (1, 30), (2, 30)] {
        let mesh =
            penner::mesh::builders::random_surface(g, n, 7 + u64::from(g)).expect("random surface");
        // Unit lengths scaled by s_v = 1 + (v mod 4)/4: a valid metric far from Delaunay.
        let s: Vec<Rational> = (0..mesh.n_vertices() as i64)
            .map(|v| Rational::from((4 + v % 4, 4)))
            .collect();
        let metric = Metric::Lengths(vec![Rational::from(1); mesh.n_edges()]).scaled(&mesh, &s);
        let name = format!("random genus-{g} surface, {n} vertices");
        let surface = Surface::new(name, mesh, metric, None).expect("a valid metric");
        for p in parse_list("f64,dd,256").expect("precision list") {
            let k = match p {
                Prec::F64 => flips::<f64>(&surface, ()),
                Prec::Dd => flips::<Dd>(&surface, ()),
                Prec::Mpfr(bits) => flips::<Mpfr>(&surface, bits),
                Prec::Exact => continue,
            };
            let Some(row) = run_one(&check, &surface, p, &Settings::default()) else {
                continue;
            };
            let word = report::verdict_word(&row.outcome);
            println!(
                "{:<36} {:<9} {k:>4} flips: T21 {word}",
                surface.name,
                p.to_string()
            );
            bad += usize::from(!matches!(row.outcome, Outcome::Verdict(ref v) if v.holds()));
        }
    }
    if bad > 0 {
        eprintln!("{bad} verdict(s) other than `holds`");
        std::process::exit(1);
    }
}
