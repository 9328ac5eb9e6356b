//! Registry entries that need more than a metric: T04 (planar layouts), T07 (a fixed map),
//! T20 (positions in ℝ³), T35 (a built-in second metric), each applicable or saying why not.

use penner::mesh::builders;
use penner::oracle::checks_extra::coplanar;
use penner::oracle::registry::by_id;
use penner::oracle::{Metric, Prec, Surface};
use penner::theorems::{Settings, Verdict};
use rug::Rational;

fn run(id: &str, case: &Surface, prec: Prec) -> Verdict {
    let check = by_id(id).unwrap_or_else(|| panic!("{id} is registered"));
    (check.run)(case, prec, &Settings::default()).unwrap_or_else(|| panic!("{id} runs at {prec}"))
}

fn grid() -> Surface {
    Surface::from_embedded("grid", builders::grid_disk(2, 2).unwrap()).unwrap()
}

fn tetrahedron() -> Surface {
    Surface::from_embedded("tet", builders::tetrahedron()).unwrap()
}

fn one_vertex_torus() -> Surface {
    let l = [4, 5, 6].map(Rational::from).to_vec();
    Surface::new(
        "torus",
        builders::one_vertex_torus(),
        Metric::Lengths(l),
        None,
    )
    .unwrap()
}

#[test]
fn coplanar_sees_planes_exactly() {
    assert!(coplanar(grid().positions.as_ref().unwrap()));
    // Negative control: the tetrahedron's vertices span ℝ³.
    assert!(!coplanar(tetrahedron().positions.as_ref().unwrap()));
}

#[test]
fn t04_entry_runs_on_planar_layouts_only() {
    for p in [Prec::F64, Prec::Dd] {
        assert!(run("T04", &grid(), p).holds(), "{p}");
    }
    // Negative control: the same grid with one interior length changed is not flat.
    let mut bent = grid();
    let Metric::SquaredLengths(sq) = &mut bent.metric else {
        panic!("embedded surfaces carry squared lengths")
    };
    let e = bent
        .mesh
        .edges()
        .find(|&e| !bent.mesh.is_boundary_edge(e))
        .unwrap();
    sq[e.idx()] *= Rational::from((101, 100));
    assert!(matches!(run("T04", &bent, Prec::Dd), Verdict::Fails { .. }));
    assert!(matches!(
        run("T04", &tetrahedron(), Prec::F64),
        Verdict::NotApplicable { .. }
    ));
    assert!(matches!(
        run("T04", &one_vertex_torus(), Prec::F64),
        Verdict::NotApplicable { .. }
    ));
}

#[test]
fn t07_t20_t35_entries_hold_on_standard_surfaces() {
    assert!(run("T07", &tetrahedron(), Prec::Dd).holds());
    assert!(run(
        "T07",
        &one_vertex_torus(),
        Prec::Mpfr(penner::scalar::Precision::new(128).unwrap())
    )
    .holds());
    assert!(run("T20", &tetrahedron(), Prec::Exact).holds());
    assert!(run("T20", &tetrahedron(), Prec::F64).holds());
    assert!(matches!(
        run("T20", &one_vertex_torus(), Prec::Exact),
        Verdict::NotApplicable { .. }
    ));
    assert!(run("T35", &one_vertex_torus(), Prec::Exact).holds());
    assert!(matches!(
        run("T35", &tetrahedron(), Prec::Exact),
        Verdict::NotApplicable { .. }
    ));
    assert!(
        (by_id("T35").unwrap().run)(&one_vertex_torus(), Prec::F64, &Settings::default()).is_none()
    );
}
