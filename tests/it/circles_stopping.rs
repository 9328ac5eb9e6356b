//! The refinement of maximal packings tied to the tangency tolerance ε (B99): a layout
//! computed for ε is certified within ε with margin (B95); the same computation stopped at
//! a residual not tied to ε is refuted by the same certificate.

use penner::circles::maximal::stopping::{bits_for, first_tolerance, next_tolerance, MARGIN};
use penner::circles::maximal::tangency::{check_packing, exact_circles, PackingVerdict};
use penner::circles::maximal::{maximal_disk, Options};
use penner::mesh::builders::random_planar;
use penner::scalar::{Mpfr, Precision};
use rug::Rational;

fn certify(mesh: &penner::mesh::Mesh, opts: &Options, bits: u32, eps: &Rational) -> PackingVerdict {
    let p = maximal_disk::<Mpfr>(mesh, Precision::new(u64::from(bits)).unwrap(), opts).unwrap();
    let marks: Vec<bool> = p.interior.iter().map(|b| !b).collect();
    check_packing(
        mesh,
        &exact_circles(&p.circles).unwrap(),
        eps,
        2 * bits,
        Some(&marks),
    )
}

#[test]
fn b99_layout_refined_for_epsilon_certifies_with_margin_and_a_loose_residual_is_refuted() {
    let mesh = random_planar(600, 3).unwrap().mesh;
    let eps = 1e-40;
    let bits = bits_for(eps, mesh.n_vertices());
    let exact_eps = Rational::from_f64(eps).unwrap();
    let tied = Options {
        epsilon: Some(eps),
        ..Options::default()
    };
    match certify(&mesh, &tied, bits, &exact_eps) {
        // The aim is ε/2⁴ as measured in the working precision; the certificate's bound on
        // the exact circles may exceed it by rounding of the layout only, far below 2×.
        PackingVerdict::Holds { max_defect } => {
            assert!(max_defect <= 2.0 * eps / MARGIN, "{max_defect:e}");
        }
        v => panic!("{v:?}"),
    }
    // Negative control: the residual stopped at 10⁻²⁰ (not tied to ε) leaves defects far
    // above ε, which the certificate proves.
    let loose = Options {
        tolerance: Some(1e-20),
        ..Options::default()
    };
    let v = certify(&mesh, &loose, bits, &exact_eps);
    assert!(matches!(v, PackingVerdict::Fails(_)), "{v:?}");
}

#[test]
fn b99_stopping_rule_tightens_until_the_aim_and_respects_the_floor() {
    let (eps, floor) = (1e-30, 1e-45);
    assert_eq!(first_tolerance(eps, 1000, floor), eps / (MARGIN * 1000.0));
    assert_eq!(first_tolerance(eps, 1000, 1e-20), 1e-20);
    // Within the aim: stop. Above it: at least 4× tighter, in proportion to the excess.
    assert_eq!(next_tolerance(1e-35, eps / MARGIN, eps, floor), None);
    let next = next_tolerance(1e-35, 1e-25, eps, floor).unwrap();
    assert!(
        next <= 1e-35 * (eps / MARGIN) / 4e-25 * (1.0 + 1e-12),
        "{next:e}"
    );
    assert_eq!(
        next_tolerance(1e-35, f64::INFINITY, eps, floor),
        Some(1e-35 / 4.0)
    );
    // Below the floor the precision cannot go: stop (the certificate then decides).
    assert_eq!(next_tolerance(1e-44, 1e-20, eps, floor), None);
    // Precision: 2¹⁶·n²·2⁻ᵖ ≤ ε, at least 128 bits.
    assert_eq!(bits_for(1e-3, 10), 128);
    for (e, n) in [(1e-30, 10_000usize), (1e-30, 100_000), (1e-60, 500)] {
        let p = bits_for(e, n);
        let lhs = 2f64.powi(16) * (n as f64).powi(2) * 2f64.powi(-(p as i32));
        assert!(lhs <= e && 2.0 * lhs > e, "ε {e:e}, n {n}: {p} bits");
    }
}
