//! Every command of `penner` as the library call behind it, on built-in surfaces: the
//! verdict each prints is the one the command would report, with negative controls (an
//! altered claim, impossible targets); the example exits non-zero when a verdict is not the
//! expected one.
//!
//! ```sh
//! cargo run --release --example pipelines
//! ```

use penner::algorithms::delaunay_pipeline::{intrinsic_delaunay, DelaunayOptions};
use penner::circles::maximal::pipeline::{pack_maximal, PackOptions};
use penner::circles::maximal::tangency::PackingVerdict;
use penner::io::{FlipCase, Metric, Surface};
use penner::mesh::builders;
use penner::oracle::certify::{certify, ClaimVerdict};
use penner::oracle::check_surface::{check_surface, CheckOptions};
use penner::oracle::claim::parse_value;
use penner::oracle::report::{status, Status};
use penner::scalar::parse_rational;
use penner::scalar::prec::Prec;
use penner::uniformization::pipeline::{
    uniformize_boundary, uniformize_closed, uniformize_hyperbolic, uniformize_sphere, Options,
};
use penner::uniformization::Targets;
use rug::Rational;
use std::process::ExitCode;

/// `penner certify` on a claim written by a pipeline.
fn rechecks(claim: Option<serde_json::Value>) -> bool {
    claim
        .and_then(|c| parse_value(&c).ok())
        .is_some_and(|c| certify(&c).is_ok_and(|a| a.verdict == ClaimVerdict::Holds))
}

fn main() -> ExitCode {
    let mut ok = true;
    let mut report = |what: &str, good: bool| {
        println!(
            "{what}: {}",
            if good { "as expected" } else { "UNEXPECTED" }
        );
        ok &= good;
    };
    let options = Options::default();
    let tet = Surface::from_embedded("tetrahedron", builders::tetrahedron()).expect("valid");
    let oct = Surface::from_embedded("octahedron", builders::octahedron()).expect("valid");

    // penner check tetrahedron.json --only T01,T03
    let check = CheckOptions {
        only: vec!["T01".into(), "T03".into()],
        ..CheckOptions::default()
    };
    let out = check_surface(&tet, "tetrahedron", &check, &|_| {});
    report(
        "check (T01, T03 on the tetrahedron): holds",
        out.is_ok_and(|o| status(&o.rows) == Status::Holds),
    );

    // penner delaunay octahedron.json --precision f64
    let mut case = FlipCase::Exact(oct.clone());
    let out = intrinsic_delaunay(&mut case, &DelaunayOptions::at(Prec::F64));
    report(
        "delaunay (octahedron): certified for the input metric",
        out.is_ok_and(|o| o.holds()),
    );

    // penner uniformize tetrahedron.json --targets [1, 1, 1, 1] -o claim.json
    let cones = Targets::from_multiples_of_pi(vec![Rational::from(1); 4]);
    let out = uniformize_closed(&tet, &cones, &options, &mut |_| {});
    let claim = out
        .as_ref()
        .ok()
        .and_then(penner::uniformization::pipeline::ClosedOutcome::claim);
    report(
        "uniformize (tetrahedron, cones π): certified, the claim re-checks",
        out.is_ok_and(|o| o.certified()) && rechecks(claim.clone()),
    );
    // Negative controls: the claim with its radius shrunk to 10⁻²⁰⁰ does not re-check;
    // targets that miss Gauss–Bonnet are refused as input.
    let shrunk = claim.map(|mut c| {
        c["radius"] = serde_json::Value::String("1e-200".into());
        c
    });
    report(
        "uniformize claim with a shrunk radius: not holds",
        !rechecks(shrunk),
    );
    let wrong = Targets::from_multiples_of_pi(vec![Rational::from(2); 4]);
    report(
        "uniformize (tetrahedron, flat targets on a sphere): bad input",
        uniformize_closed(&tet, &wrong, &options, &mut |_| {}).is_err_and(|e| e.is_bad_input()),
    );

    // penner uniformize grid.json --flat (a surface with boundary)
    let grid =
        Surface::from_embedded("grid", builders::grid_disk(3, 3).expect("3×3")).expect("valid");
    let out = uniformize_boundary(&grid, None, &options);
    report(
        "uniformize (3×3 grid disk, flat): certified on the double, the claim re-checks",
        out.is_ok_and(|o| o.certified() && rechecks(o.claim())),
    );

    // penner uniformize octahedron.json --sphere -o claim.json
    let out = uniformize_sphere(&oct, None, &options);
    report(
        "uniformize --sphere (octahedron): certified, the claim re-checks",
        out.is_ok_and(|o| o.certified() && rechecks(o.claim)),
    );

    // penner uniformize genus2.json --hyperbolic -o claim.json
    let g2 = builders::genus(2).expect("genus 2");
    let lengths = Metric::Lengths(vec![Rational::from((3, 2)); g2.n_edges()]);
    let g2 = Surface::new("genus 2", g2, lengths, None).expect("valid");
    let out = uniformize_hyperbolic(&g2, None, &options);
    report(
        "uniformize --hyperbolic (genus 2, lengths 3/2): certified, the claim re-checks",
        out.is_ok_and(|o| o.certified() && rechecks(o.claim())),
    );

    // penner pack octahedron.json --sphere --epsilon 1e-20
    let pack = PackOptions {
        sphere: true,
        puncture: 0,
        bits: 128,
        epsilon: parse_rational("1e-20").expect("a decimal"),
    };
    let out = pack_maximal(&oct.mesh, "octahedron", &pack);
    report(
        "pack --sphere (octahedron): tangency certified within 1e-20",
        out.is_ok_and(|o| matches!(o.verdict, PackingVerdict::Holds { .. })),
    );

    if ok {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    }
}
