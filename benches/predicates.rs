//! Criterion benchmarks of the certified planar predicates (`orient2d`, `incircle`) rung by
//! rung of the escalation ladder: the f64 filter alone, one MPFR enclosure at 53 and 128
//! bits, the exact rational sign, and the whole ladder (`decide`, construction included),
//! on random inputs (f64 coordinates, which the filter decides) and on adversarial ones
//! (collinear or cocircular points, rounded, scaled or perturbed, which climb the ladder).
//! Each iteration evaluates a batch of inputs; throughput is per predicate call.
//!
//! Run: `cargo bench --bench predicates` (add a filter such as `incircle` to run one group).
//! Before measuring, one line per input set says which rung decides how many inputs.

#![allow(missing_docs)] // criterion_group! generates an undocumented function

#[path = "../tests/it/planar_gen.rs"]
mod planar_gen;

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use penner::predicates::ladder::{decide, Ladder, SignPredicate};
use penner::predicates::planar::{InCircle, Orient2d, Point};
use penner::scalar::{Certified, Precision, Stage};
use planar_gen::{adversarial_quad, adversarial_triple, pt};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use std::hint::black_box;
use std::time::Duration;

/// Inputs per iteration.
const BATCH: usize = 1_000;

/// Enclosure precisions measured on their own (the ladder starts at 128 bits).
const BITS: [u64; 2] = [53, 128];

/// How many of `preds` each rung of the default ladder decides, as one line.
fn stage_line<P: SignPredicate>(preds: &[P]) -> String {
    let (mut filter, mut interval, mut exact, mut undecided) = (0, 0, 0, 0);
    for p in preds {
        match decide(p, &Ladder::default()) {
            Certified::Known {
                stage: Stage::Filter,
                ..
            } => filter += 1,
            Certified::Known {
                stage: Stage::Interval { .. },
                ..
            } => interval += 1,
            Certified::Known {
                stage: Stage::Exact,
                ..
            } => exact += 1,
            Certified::Undecided { .. } => undecided += 1,
        }
    }
    format!("filter {filter}, interval {interval}, exact {exact}, undecided {undecided}")
}

/// Benchmark every rung on `points` (one predicate per entry, built by `build`).
fn bench_rungs<const N: usize, P: SignPredicate>(
    c: &mut Criterion,
    group: &str,
    input: &str,
    points: &[[Point; N]],
    build: impl Fn(&[Point; N]) -> P,
) {
    let preds: Vec<P> = points.iter().map(&build).collect();
    eprintln!("{group}/{input}: {}", stage_line(&preds));
    let mut g = c.benchmark_group(group);
    g.throughput(Throughput::Elements(points.len() as u64))
        .sample_size(10)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(2));
    g.bench_function(BenchmarkId::new("filter", input), |b| {
        b.iter(|| preds.iter().filter_map(SignPredicate::filter).count());
    });
    for bits in BITS {
        let prec = Precision::new(bits).expect("valid precision");
        g.bench_function(BenchmarkId::new(format!("interval-{bits}"), input), |b| {
            b.iter(|| {
                preds
                    .iter()
                    .filter_map(|p| p.enclosure_sign(black_box(prec)))
                    .count()
            });
        });
    }
    g.bench_function(BenchmarkId::new("exact", input), |b| {
        b.iter(|| preds.iter().filter_map(SignPredicate::exact_sign).count());
    });
    let ladder = Ladder::default();
    g.bench_function(BenchmarkId::new("ladder", input), |b| {
        b.iter(|| {
            points
                .iter()
                .filter(|p| decide(&build(black_box(p)), &ladder).value().is_some())
                .count()
        });
    });
    g.finish();
}

fn bench(c: &mut Criterion) {
    let mut rng = ChaCha8Rng::seed_from_u64(106);
    let random: Vec<[Point; 4]> = (0..BATCH)
        .map(|_| std::array::from_fn(|_| pt(&mut rng, 0)))
        .collect();
    let triples: Vec<[Point; 3]> = (0..BATCH).map(|_| adversarial_triple(&mut rng)).collect();
    let quads: Vec<[Point; 4]> = (0..BATCH).map(|_| adversarial_quad(&mut rng)).collect();
    let orient = |p: &[Point; 3]| Orient2d::new(&p[0], &p[1], &p[2]);
    let random3: Vec<[Point; 3]> = random
        .iter()
        .map(|p| [p[0].clone(), p[1].clone(), p[2].clone()])
        .collect();
    bench_rungs(c, "orient2d", "random", &random3, orient);
    bench_rungs(c, "orient2d", "adversarial", &triples, orient);
    let incircle = |p: &[Point; 4]| InCircle::new(&p[0], &p[1], &p[2], &p[3]);
    bench_rungs(c, "incircle", "random", &random, incircle);
    bench_rungs(c, "incircle", "adversarial", &quads, incircle);
}

criterion_group!(benches, bench);
criterion_main!(benches);
