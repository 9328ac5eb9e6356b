//! A tour of penner: a surface, its metric at three precisions, certified decisions,
//! theorem checks with verdicts, and a claim answered by the oracle.
//!
//! Run: `cargo run --release --example tour`

use penner::geometry::cone_angles::cone_angles;
use penner::io::{json, Metric, Surface};
use penner::mesh::builders;
use penner::oracle::certify::{certify, ClaimVerdict};
use penner::oracle::registry::{catalogue, run_case};
use penner::oracle::{claim, precision::parse_list, report};
use penner::scalar::{Dd, Mpfr, Precision, Real};
use penner::theorems::Settings;
use rug::Rational;

fn main() {
    // 1. A Δ-complex: the one-vertex torus (1 vertex, 3 edges, 2 faces, every edge a loop),
    //    with exact lengths 4, 5, 6 (validated exactly: every face is a triangle).
    let torus = Surface::new(
        "one-vertex torus (4, 5, 6)",
        builders::one_vertex_torus(),
        Metric::Lengths([4, 5, 6].map(Rational::from).to_vec()),
        None,
    )
    .expect("a valid metric");
    let m = &torus.mesh;
    println!(
        "{}: V = {}, E = {}, F = {}, χ = {}",
        torus.name,
        m.n_vertices(),
        m.n_edges(),
        m.n_faces(),
        m.euler_characteristic()
    );

    // 2. Its single cone angle at three precisions: all six corners meet at the vertex,
    //    θ = 2π on a flat torus.
    let p256 = Precision::new(256).expect("256 bits");
    let t_f64 = cone_angles::<f64>(m, &torus.lengths(()))[0];
    let t_dd = cone_angles::<Dd>(m, &torus.lengths(()))[0].approx_f64();
    let t_mp = cone_angles::<Mpfr>(m, &torus.lengths(p256))[0].clone();
    let tau = std::f64::consts::TAU;
    println!(
        "θ − 2π: f64 {:.2e}, dd (shown in f64) {:.2e}",
        t_f64 - tau,
        t_dd - tau
    );
    println!("θ at MPFR-256: {:.45}", t_mp.0);

    // 3. Every catalogue check in this build, at f64, double-double, MPFR-256 and exact.
    let precs = parse_list("f64,dd,256,exact").expect("precision list");
    let rows = run_case(&torus, &catalogue(), &precs, &Settings::default());
    print!("\n{}", report::table(&rows));

    // 4. The oracle: another program claims the cone angle is 2π within 1e-40.
    let claim_json = serde_json::json!({
        "penner_claim": 1, "kind": "cone_angles",
        "surface": json::to_value(&torus),
        "angles": ["6.28318530717958647692528676655900576839433879875021"],
        "epsilon": "1e-40"
    });
    let c = claim::parse_value(&claim_json).expect("a valid claim");
    let answer = certify(&c).expect("cone_angles is supported");
    println!(
        "claim θ = 2π ± 1e-40: {} (certified: {}, {} bits)",
        answer.verdict.word(),
        answer.certified,
        answer.precision_bits
    );
    if answer.verdict != ClaimVerdict::Holds || report::status(&rows) != report::Status::Holds {
        std::process::exit(1);
    }
}
