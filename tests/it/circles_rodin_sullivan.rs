//! Rodin–Sullivan (T12): hexagonal packings of the upper half-disk, packed maximally, approach
//! its explicit Riemann map as the spacing halves; a wrong closed form does not.

use penner::circles::hexagonal::{hex_complex, lattice_point, locate};
use penner::theorems::t12_rodin_sullivan::{
    check_refinement, compact_samples, half_disk_map, in_half_disk, measure_level, Level, BASE, C,
    MAX_LAYOUT_DEFECT_RATIO,
};
use penner::theorems::Verdict;

#[test]
fn t12_half_disk_map_is_the_normalised_riemann_map() {
    // Independent of the packing: f(z₀) = 0, f'(z₀) > 0 by a central difference, |f| = 1 on
    // the boundary (the segment and the arc), |f| < 1 inside.
    let f = |z: C| half_disk_map(BASE, z);
    let at = f(BASE);
    assert!(at[0].hypot(at[1]) < 1e-15);
    let h = 1e-6;
    let (a, b) = (f([BASE[0] + h, BASE[1]]), f([BASE[0] - h, BASE[1]]));
    let d = [(a[0] - b[0]) / (2.0 * h), (a[1] - b[1]) / (2.0 * h)];
    assert!(d[0] > 0.1 && d[1].abs() < 1e-8 * d[0], "{d:?}");
    for k in 1..40 {
        let x = -1.0 + f64::from(k) / 20.0;
        let t = std::f64::consts::PI * f64::from(k) / 40.0;
        for z in [[x, 0.0], [t.cos(), t.sin()]] {
            let w = f(z);
            assert!((w[0].hypot(w[1]) - 1.0).abs() < 1e-9, "{z:?} ↦ {w:?}");
        }
    }
    for z in compact_samples() {
        let w = f(z);
        assert!(w[0].hypot(w[1]) < 1.0);
    }
}

#[test]
fn t12_hex_complex_is_a_disk_containing_the_compact_set() {
    for eps in [0.25, 0.125, 0.0625] {
        let hex = hex_complex(&in_half_disk, BASE, eps, 1.2).unwrap();
        assert_eq!(hex.mesh.euler_characteristic(), 1);
        assert_eq!(hex.mesh.n_boundary_loops(), 1);
        assert!(hex.points.iter().all(|&p| in_half_disk(p)));
        let index: std::collections::HashSet<_> = hex.lattice.iter().copied().collect();
        for z in compact_samples() {
            let (corners, w) = locate(BASE, eps, z);
            assert!(
                corners.iter().all(|p| index.contains(p)),
                "ε = {eps}: {z:?}"
            );
            // Barycentric weights reproduce z.
            let mut back = [0.0, 0.0];
            for (p, wi) in corners.iter().zip(w) {
                let q = lattice_point(BASE, eps, *p);
                back[0] += wi * q[0];
                back[1] += wi * q[1];
            }
            assert!((back[0] - z[0]).hypot(back[1] - z[1]) < 1e-12);
            assert!(w.iter().all(|&x| x >= -1e-12));
        }
    }
}

#[test]
fn t12_discrete_riemann_maps_converge_under_refinement() {
    let f = |z: C| half_disk_map(BASE, z);
    let levels: Vec<_> = [0.125, 0.0625, 0.03125]
        .iter()
        .map(|&eps| measure_level(eps, &f).unwrap())
        .collect();
    let v = check_refinement(&levels);
    assert!(
        matches!(
            v,
            Verdict::Holds {
                certified: false,
                ..
            }
        ),
        "{v:?} {levels:?}"
    );
    // Negative control: the map rotated by 0.2 rad (still a Riemann map of Ω, with the
    // wrong normalisation) is approached by no refinement: the errors level off near
    // |1 − e^{0.2i}|·max_K |f| and the check rejects them.
    let rotated = |z: C| {
        let w = f(z);
        let (s, c) = 0.2_f64.sin_cos();
        [c * w[0] - s * w[1], s * w[0] + c * w[1]]
    };
    let wrong: Vec<_> = [0.125, 0.0625, 0.03125]
        .iter()
        .map(|&eps| measure_level(eps, &rotated).unwrap())
        .collect();
    assert!(!check_refinement(&wrong).holds(), "{wrong:?}");
}

#[test]
fn t12_a_level_whose_layout_is_not_consistent_far_below_its_error_is_not_counted() {
    // Errors halving (rate 1) with layout defects far below them hold; the same errors with
    // the second level's layout defect at 2⁻⁶ of its error (above 2⁻⁸, proofs/B92: what
    // the vertex-by-vertex layout gave at ε = 1/128) do not.
    let level = |spacing: f64, error: f64, layout_defect: f64| Level {
        spacing,
        vertices: 0,
        error,
        worst: BASE,
        layout_defect,
    };
    let good = [level(0.25, 0.1, 1e-12), level(0.125, 0.05, 1e-12)];
    assert!(check_refinement(&good).holds());
    let bad = [level(0.25, 0.1, 1e-12), level(0.125, 0.05, 0.05 / 64.0)];
    const { assert!(1.0 / 64.0 > MAX_LAYOUT_DEFECT_RATIO) };
    assert!(!check_refinement(&bad).holds());
    let nan = [level(0.25, 0.1, 1e-12), level(0.125, 0.05, f64::NAN)];
    assert!(!check_refinement(&nan).holds());
}
