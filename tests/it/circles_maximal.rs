//! Koebe–Andreev–Thurston maximal packings (T11): disks in the unit disk, spheres by caps.

use penner::circles::maximal::tangency::{check_packing, exact_circles, PackingVerdict};
use penner::circles::maximal::{maximal_disk, Options};
use penner::mesh::builders::random_planar;
use penner::scalar::{Mpfr, Precision};
use rug::Rational;

#[test]
fn t11_smoke() {
    let mesh = random_planar(40, 7).unwrap().mesh;
    let p = maximal_disk::<f64>(&mesh, (), &Options::default()).unwrap();
    eprintln!("f64 it {} res {:e}", p.newton_iterations, p.f64_residual);
    let ex = exact_circles(&p.circles).unwrap();
    let marks: Vec<bool> = p.interior.iter().map(|b| !b).collect();
    let v = check_packing(
        &mesh,
        &ex,
        &Rational::from((1, 1_000_000_000)),
        128,
        Some(&marks),
    );
    eprintln!("{v:?}");
    let prec = Precision::new(128).unwrap();
    let q = maximal_disk::<Mpfr>(&mesh, prec, &Options::default()).unwrap();
    eprintln!("refine {}", q.refinement_steps);
    let ex = exact_circles(&q.circles).unwrap();
    let v = check_packing(
        &mesh,
        &ex,
        &Rational::from((1, 10u128.pow(30))),
        256,
        Some(&marks),
    );
    eprintln!("{v:?}");
}
