//! Planar inputs for the predicate tests and benchmarks: random points (f64, fractions,
//! a fine grid) and adversarial ones (collinear triples and cocircular quadruples, exact,
//! rounded to f64, scaled by 10^±k, or perturbed by 10^−k).
#![allow(dead_code)]

use penner::predicates::planar::Point;
use rand::Rng;
use rand_chacha::ChaCha8Rng;
use rug::{Integer, Rational};

/// The rational `n/d`.
pub fn q(n: i64, d: i64) -> Rational {
    Rational::from((n, d))
}

/// The rational value of a finite double.
pub fn qf(x: f64) -> Rational {
    Rational::from_f64(x).expect("finite")
}

/// `10^e` exactly.
pub fn pow10(e: i32) -> Rational {
    let p = Rational::from(Integer::from(Integer::u_pow_u(10, e.unsigned_abs())));
    if e >= 0 {
        p
    } else {
        p.recip()
    }
}

/// A random coordinate: f64 in [−1, 1], a random fraction, or a small grid value.
pub fn coord(rng: &mut ChaCha8Rng, kind: u32) -> Rational {
    match kind {
        0 => qf(rng.gen_range(-1.0..1.0)),
        1 => q(rng.gen_range(-1000..1000), rng.gen_range(1..1000)),
        _ => q(rng.gen_range(-3..=3), 1 << 30),
    }
}

/// A random point with both coordinates of [`coord`]'s `kind`.
pub fn pt(rng: &mut ChaCha8Rng, kind: u32) -> Point {
    [coord(rng, kind), coord(rng, kind)]
}

/// Scale a point by `s` exactly.
pub fn scale(p: &Point, s: &Rational) -> Point {
    [Rational::from(&p[0] * s), Rational::from(&p[1] * s)]
}

/// Round a point's coordinates to f64 (a nearly-degenerate image of a degenerate input).
pub fn round(p: &Point) -> Point {
    [qf(p[0].to_f64()), qf(p[1].to_f64())]
}

/// Adversarial triples: collinear (exact or rounded to f64), extreme scale, tiny grid.
pub fn adversarial_triple(rng: &mut ChaCha8Rng) -> [Point; 3] {
    let a = pt(rng, 1);
    let b = pt(rng, 1);
    let t = q(rng.gen_range(-5..5), rng.gen_range(1..7));
    let c = [
        (&a[0] + (&t * Rational::from(&b[0] - &a[0]))),
        (&a[1] + (&t * Rational::from(&b[1] - &a[1]))),
    ];
    distort(rng, [a, b, c], 150, |rng, tri| {
        // Perturb one coordinate by a tiny amount.
        let eps = q(rng.gen_range(-2..=2), 1) * pow10(-rng.gen_range(10..40));
        tri[2][1] += eps;
    })
}

/// Four points, three on a rational circle; `d` on, near or off it.
pub fn adversarial_quad(rng: &mut ChaCha8Rng) -> [Point; 4] {
    // Rational points on the circle of centre (cx, cy) and radius r: (1−t²)/(1+t²), 2t/(1+t²).
    let centre = pt(rng, 1);
    let r = q(rng.gen_range(1..100), rng.gen_range(1..100));
    let on = |t: Rational| -> Point {
        let den = 1 + Rational::from(&t * &t);
        let x = (1 - Rational::from(&t * &t)) / &den;
        let y = (2 * t) / den;
        [
            (&centre[0] + Rational::from(&r * &x)),
            (&centre[1] + Rational::from(&r * &y)),
        ]
    };
    let mut ts = || q(rng.gen_range(-50..50), rng.gen_range(1..20));
    let quad = [on(ts()), on(ts()), on(ts()), on(ts())];
    distort(rng, quad, 60, |rng, quad| {
        quad[3][0] += pow10(-rng.gen_range(10..40));
    })
}

/// One of four variants of a degenerate configuration `pts`, chosen at random: as is
/// (exactly degenerate); rounded to f64; scaled by `10^k` (`|k| ≤ max_exp`) and rounded;
/// or changed by `perturb` (a tiny exact change).
fn distort<const N: usize>(
    rng: &mut ChaCha8Rng,
    pts: [Point; N],
    max_exp: i32,
    perturb: impl FnOnce(&mut ChaCha8Rng, &mut [Point; N]),
) -> [Point; N] {
    match rng.gen_range(0..4) {
        0 => pts,
        1 => pts.map(|p| round(&p)),
        2 => {
            let s = pow10(rng.gen_range(-max_exp..=max_exp));
            pts.map(|p| round(&scale(&p, &s)))
        }
        _ => {
            let mut pts = pts;
            perturb(rng, &mut pts);
            pts
        }
    }
}
