//! Cross-ratio invariance (T16): a conformal scaling ℓ̃_ij = s_i s_j ℓ_ij leaves every length
//! cross ratio c_ij = (ℓ_il ℓ_jk)/(ℓ_ki ℓ_lj) unchanged — exactly in ℚ with rational
//! s_i = e^{u_i/2}, and numerically at f64 and MPFR-256 with real u. A negative control
//! perturbs one scaled length and must be rejected.
//!
//! Run: `cargo run --release --example cross_ratio_invariance`

use penner::mesh::builders;
use penner::scalar::{Mpfr, Precision, Real};
use penner::theorems::t16_scaling_cross_ratios::{
    check_scaling_preserves_cross_ratios, check_scaling_preserves_cross_ratios_exact,
    verify_equal_cross_ratios_exact,
};
use penner::theorems::{Settings, Verdict};
use rug::Rational;

fn line(what: &str, v: &Verdict) {
    let word = match v {
        Verdict::Holds {
            certified: true, ..
        } => "holds (exact)".to_string(),
        Verdict::Holds { max_error, .. } => {
            format!("holds (numerical, largest error {max_error:.2e})")
        }
        Verdict::Fails { witnesses, .. } => format!(
            "FAILS at {} element(s), first {}",
            witnesses.len(),
            witnesses[0].element
        ),
        other => format!("{other:?}"),
    };
    println!("  {what:<40} {word}");
}

fn main() {
    let mesh = builders::icosahedron().mesh;
    let settings = Settings::default();
    println!(
        "icosahedron: {} edges, cross ratios on every edge",
        mesh.n_edges()
    );
    // Rational lengths near 1 (every triangle valid) and rational scale factors.
    let l: Vec<Rational> = (0..mesh.n_edges() as i64)
        .map(|e| Rational::from((20 + e % 7, 20)))
        .collect();
    let s: Vec<Rational> = (0..mesh.n_vertices() as i64)
        .map(|v| Rational::from((5 + v, 6)))
        .collect();
    let exact = check_scaling_preserves_cross_ratios_exact(&mesh, &l, &s);
    line("exact in ℚ, s_i = (5+i)/6", &exact);

    let u64s: Vec<f64> = (0..mesh.n_vertices())
        .map(|v| (v as f64 * 0.7).sin())
        .collect();
    let l64: Vec<f64> = l.iter().map(|q| f64::from_rational(q, ())).collect();
    let v64 = check_scaling_preserves_cross_ratios(&mesh, &l64, &u64s, &settings);
    line("f64, u_i = sin(0.7 i)", &v64);

    let p = Precision::new(256).expect("valid precision");
    let lmp: Vec<Mpfr> = l.iter().map(|q| Mpfr::from_rational(q, p)).collect();
    let ump: Vec<Mpfr> = u64s.iter().map(|&x| Mpfr::from_f64(x, p)).collect();
    let vmp = check_scaling_preserves_cross_ratios(&mesh, &lmp, &ump, &settings);
    line("mpfr-256, u_i = sin(0.7 i)", &vmp);

    // Negative control: scale, then lengthen edge 0 by 1/1000: cross ratios must differ.
    let mut lt: Vec<Rational> = mesh
        .edges()
        .map(|e| {
            let h = e.halfedge();
            Rational::from(&s[mesh.tail(h).idx()] * &s[mesh.tip(h).idx()]) * &l[e.idx()]
        })
        .collect();
    lt[0] += Rational::from((1, 1000));
    let neg = verify_equal_cross_ratios_exact(&mesh, &l, &lt);
    line("control: scaled, then ℓ̃(e0) + 1/1000", &neg);

    if !(exact.holds() && v64.holds() && vmp.holds() && neg.fails()) {
        std::process::exit(1);
    }
}
