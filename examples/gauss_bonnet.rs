//! Discrete Gauss–Bonnet (T01): Σ K + Σ k = 2πχ on a closed surface and on a disk, checked
//! numerically at f64, double-double and MPFR-256 with tolerances derived from the
//! precision (proofs/B40–B45), and certified on MPFR interval enclosures (proofs/B50).
//! A negative control shifts one curvature and must be rejected.
//!
//! Run: `cargo run --release --example gauss_bonnet`

use penner::io::{Metric, Surface};
use penner::mesh::builders;
use penner::scalar::{Dd, Mpfr, Precision, Real};
use penner::theorems::t01_gauss_bonnet::{
    check_gauss_bonnet, check_gauss_bonnet_certified, verify_gauss_bonnet,
};
use penner::theorems::{Settings, Verdict};

fn show(what: &str, v: &Verdict) {
    match v {
        Verdict::Holds {
            certified,
            max_error,
        } => println!(
            "  {what:<34} holds  ({}; largest error {max_error:.2e})",
            if *certified { "certified" } else { "numerical" }
        ),
        Verdict::Fails { witnesses, .. } => println!(
            "  {what:<34} FAILS ({} witness(es), first: {} {})",
            witnesses.len(),
            witnesses[0].element,
            witnesses[0].detail
        ),
        other => println!("  {what:<34} {other:?}"),
    }
}

fn main() {
    let settings = Settings::default();
    let p256 = Precision::new(256).expect("valid precision");
    let mut ok = true;
    for (name, emb) in [
        ("octahedron (χ = 2)", builders::octahedron()),
        (
            "4×3 grid disk (χ = 1)",
            builders::grid_disk(4, 3).expect("small grid"),
        ),
    ] {
        let surface = Surface::from_embedded(name, emb).expect("valid embedded surface");
        let mesh = &surface.mesh;
        println!(
            "{name}: V = {}, E = {}, F = {}",
            mesh.n_vertices(),
            mesh.n_edges(),
            mesh.n_faces()
        );
        let l64: Vec<f64> = surface.lengths::<f64>(());
        let ldd: Vec<Dd> = surface.lengths::<Dd>(());
        let lmp: Vec<Mpfr> = surface.lengths::<Mpfr>(p256);
        let v = [
            check_gauss_bonnet(mesh, &l64, &settings),
            check_gauss_bonnet(mesh, &ldd, &settings),
            check_gauss_bonnet(mesh, &lmp, &settings),
        ];
        show("f64", &v[0]);
        show("double-double", &v[1]);
        show("mpfr-256", &v[2]);
        ok &= v.iter().all(Verdict::holds);
        if let Metric::SquaredLengths(sq) = &surface.metric {
            let c = check_gauss_bonnet_certified::<Mpfr>(mesh, sq, p256);
            show("mpfr-256 interval enclosure", &c);
            ok &= c.holds();
        }
        // Negative control: shift one curvature by 1e-30; MPFR-256 must reject it.
        let mut k = penner::geometry::curvature::curvature(mesh, &lmp);
        k[0] += &lmp[0].lit(1e-30);
        let neg = verify_gauss_bonnet(mesh, &lmp, &k, &settings);
        show("control: K(v0) + 1e-30 at mpfr-256", &neg);
        ok &= neg.fails();
    }
    if !ok {
        std::process::exit(1);
    }
}
