//! Smoke tests of the half-edge core (builders and flips).

use penner::mesh::{FlipError, Mesh, MeshError};

fn one_vertex_torus() -> Mesh {
    Mesh::from_gluing(
        1,
        &[[0, 0, 0], [0, 0, 0]],
        &[((0, 0), (1, 0)), ((0, 1), (1, 1)), ((0, 2), (1, 2))],
    )
    .unwrap()
}

#[test]
fn t02_flip_keeps_euler_characteristic_on_one_vertex_torus() {
    let mut m = one_vertex_torus();
    for e in 0..3 {
        m.flip(penner::mesh::Edge(e)).unwrap();
        assert_eq!(m.euler_characteristic(), 0);
    }
}

#[test]
fn flip_twice_is_identity_on_tetrahedron_up_to_relabel() {
    let tet = Mesh::from_faces(4, &[[0, 1, 2], [0, 2, 3], [0, 3, 1], [1, 3, 2]]).unwrap();
    let mut m = tet.clone();
    let e = penner::mesh::Edge(0);
    m.flip(e).unwrap();
    assert_ne!(m, tet);
    m.flip(e).unwrap();
    // The edge returns to its original endpoints.
    let h = e.side(0);
    let ends = |m: &Mesh| {
        let mut v = [m.tail(h).0, m.tip(h).0];
        v.sort_unstable();
        v
    };
    assert_eq!(ends(&m), ends(&tet));
}

#[test]
fn boundary_edge_refuses_flip() {
    let disk = Mesh::from_faces(3, &[[0, 1, 2]]).unwrap();
    assert!(matches!(
        disk.clone().flip(penner::mesh::Edge(0)),
        Err(FlipError::Boundary(_))
    ));
    assert_eq!(disk.euler_characteristic(), 1);
}

#[test]
fn nonmanifold_vertex_rejected() {
    // Two triangles sharing only vertex 0.
    let r = Mesh::from_faces(5, &[[0, 1, 2], [0, 3, 4]]);
    assert_eq!(r, Err(MeshError::NonManifoldVertex { vertex: 0 }));
}
