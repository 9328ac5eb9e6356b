//! The double of a surface with boundary (B78): closed, χ(D) = 2χ(M) − χ(∂M) = 2χ(M),
//! every mesh invariant, the mirror an orientation-reversing involution fixing exactly the
//! seam; tampered mirrors are the negative controls.

use penner::mesh::double::{Double, Sheet};
use penner::mesh::{builders, Face, Mesh, Vertex};

/// Surfaces with boundary: disks, an annulus (two boundary loops), a planar Delaunay disk,
/// one face, and a Δ-complex cone whose boundary is one loop edge.
fn family() -> Vec<(&'static str, Mesh)> {
    let mut out = vec![
        ("grid 1x1", builders::grid_disk(1, 1).unwrap().mesh),
        ("grid 3x2", builders::grid_disk(3, 2).unwrap().mesh),
        ("annulus 4x2", builders::annulus(4, 2).unwrap().mesh),
        ("planar 20", builders::random_planar(20, 3).unwrap().mesh),
        ("triangle", Mesh::from_faces(3, &[[0, 1, 2]]).unwrap()),
    ];
    // Face [b, b, c]: side 0 is the loop b→b (the boundary), sides 1 and 2 glued.
    out.push((
        "loop cone",
        Mesh::from_gluing(2, &[[0, 0, 1]], &[((0, 1), (0, 2))]).unwrap(),
    ));
    out
}

#[test]
fn b78_double_is_closed_with_twice_the_euler_characteristic() {
    for (name, m) in family() {
        let d = Double::of(&m).unwrap();
        let dm = &d.mesh;
        assert!(dm.check_invariants().is_ok(), "{name}");
        assert!(dm.is_closed(), "{name}");
        // χ(∂M) = V_∂ − E_∂ = 0: the boundary is a union of circles.
        let vb = m.boundary_vertices().iter().filter(|b| **b).count();
        let eb = m.n_boundary_edges();
        assert_eq!(vb, eb, "{name}");
        assert_eq!(
            dm.euler_characteristic(),
            2 * m.euler_characteristic() - (vb as i64 - eb as i64),
            "{name}"
        );
        assert_eq!(
            (dm.n_vertices(), dm.n_edges(), dm.n_faces()),
            (
                2 * m.n_vertices() - vb,
                2 * m.n_edges() - eb,
                2 * m.n_faces()
            ),
            "{name}"
        );
        // Copy 1 is M itself: same faces, same ids.
        for f in m.faces() {
            assert_eq!(dm.face_vertices(f), m.face_vertices(f), "{name} {f}");
        }
        // Negative control: M alone is not closed (unless it has no boundary).
        assert!(!m.is_closed(), "{name}");
    }
}

#[test]
fn b78_mirror_is_an_orientation_reversing_involution_fixing_the_seam() {
    for (name, m) in family() {
        let d = Double::of(&m).unwrap();
        assert_eq!(d.check_mirror(), Ok(()), "{name}");
        let seam = d.vertex_sheet.iter().filter(|s| **s == Sheet::Seam).count();
        assert_eq!(seam, m.boundary_vertices().iter().filter(|b| **b).count());
        let lengths: Vec<usize> = (0..m.n_edges()).collect();
        let pulled = d.pull_back_edges(&lengths).unwrap();
        for e in d.mesh.edges() {
            assert_eq!(
                pulled[e.idx()],
                pulled[d.edge_mirror[e.idx()].idx()],
                "{name}"
            );
        }
        assert!(d.pull_back_edges(&lengths[1..]).is_none(), "{name}");

        // Negative controls: the identity (it fixes every face); a mirror sending a face
        // to a face other than its reversed copy; two swapped vertex images.
        let mut identity = d.clone();
        identity.vertex_mirror = d.mesh.vertices().collect();
        identity.edge_mirror = d.mesh.edges().collect();
        identity.face_mirror = d.mesh.faces().collect();
        assert!(identity.check_mirror().is_err(), "{name}: identity");
        if m.n_faces() > 1 {
            let mut shifted = d.clone();
            let nf = m.n_faces();
            shifted.face_mirror = (0..2 * nf)
                .map(|f| Face(((f + nf + 1) % (2 * nf)) as u32))
                .collect();
            assert!(shifted.check_mirror().is_err(), "{name}: shifted faces");
        }
        let interior: Vec<usize> = (0..m.n_vertices())
            .filter(|&v| d.vertex_sheet[v] == Sheet::Original)
            .collect();
        if interior.len() >= 2 {
            let mut swapped = d.clone();
            let (a, b) = (interior[0], interior[1]);
            let (ma, mb) = (d.vertex_mirror[a], d.vertex_mirror[b]);
            swapped.vertex_mirror[a] = mb;
            swapped.vertex_mirror[b] = ma;
            swapped.vertex_mirror[mb.idx()] = Vertex(a as u32);
            swapped.vertex_mirror[ma.idx()] = Vertex(b as u32);
            assert!(swapped.check_mirror().is_err(), "{name}: swapped vertices");
        }
    }
}

#[test]
fn b78_double_of_a_closed_surface_is_two_copies() {
    let m = builders::one_vertex_torus();
    let d = Double::of(&m).unwrap();
    assert_eq!(d.check_mirror(), Ok(()));
    assert_eq!(
        (d.mesh.n_vertices(), d.mesh.n_edges(), d.mesh.n_faces()),
        (2, 6, 4)
    );
    assert_eq!(d.mesh.euler_characteristic(), 0);
}
