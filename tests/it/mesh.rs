//! The half-edge Δ-complex: builders, invariants, circulators, flips (T02).

use crate::support::cases;
use penner::mesh::builders::{self, CubeDiagonals};
use penner::mesh::{Edge, Face, FlipError, InvariantError, Mesh, RawMesh, Vertex};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// (name, mesh, expected (V, E, F), boundary loops).
type Entry = (String, Mesh, (usize, usize, usize), usize);
/// A corruption of raw mesh arrays, with a name.
type Corruption = (&'static str, Box<dyn Fn(&mut RawMesh)>);

/// Every builder at small sizes.
fn zoo() -> Vec<Entry> {
    let mut z: Vec<Entry> = vec![
        (
            "tetrahedron".into(),
            builders::tetrahedron().mesh,
            (4, 6, 4),
            0,
        ),
        (
            "octahedron".into(),
            builders::octahedron().mesh,
            (6, 12, 8),
            0,
        ),
        (
            "icosahedron".into(),
            builders::icosahedron().mesh,
            (12, 30, 20),
            0,
        ),
        (
            "cube-even".into(),
            builders::cube(CubeDiagonals::Even).mesh,
            (8, 18, 12),
            0,
        ),
        (
            "cube-odd".into(),
            builders::cube(CubeDiagonals::Odd).mesh,
            (8, 18, 12),
            0,
        ),
        (
            "triakis-tet".into(),
            builders::triakis_tetrahedron().mesh,
            (8, 18, 12),
            0,
        ),
        (
            "triakis-oct".into(),
            builders::triakis_octahedron().mesh,
            (14, 36, 24),
            0,
        ),
        (
            "two-triangle-sphere".into(),
            builders::two_triangle_sphere(),
            (3, 3, 2),
            0,
        ),
        (
            "one-vertex-torus".into(),
            builders::one_vertex_torus(),
            (1, 3, 2),
            0,
        ),
    ];
    for g in 1..=4u32 {
        let g_ = g as usize;
        z.push((
            format!("genus-{g}"),
            builders::genus(g).unwrap(),
            (1, 6 * g_ - 3, 4 * g_ - 2),
            0,
        ));
    }
    for (m, n) in [(1, 1), (1, 3), (2, 2), (3, 2)] {
        let (mu, nu) = (m as usize, n as usize);
        z.push((
            format!("grid-{m}x{n}"),
            builders::grid_disk(m, n).unwrap().mesh,
            ((mu + 1) * (nu + 1), 3 * mu * nu + mu + nu, 2 * mu * nu),
            1,
        ));
        z.push((
            format!("flat-torus-{m}x{n}"),
            builders::flat_torus(m, n).unwrap().mesh,
            (mu * nu, 3 * mu * nu, 2 * mu * nu),
            0,
        ));
    }
    for (m, n) in [(3, 1), (4, 2)] {
        let (mu, nu) = (m as usize, n as usize);
        z.push((
            format!("annulus-{m}x{n}"),
            builders::annulus(m, n).unwrap().mesh,
            (mu * (nu + 1), mu * (3 * nu + 1), 2 * mu * nu),
            2,
        ));
    }
    for g in 0..=2u32 {
        let m = builders::random_surface(g, 5, u64::from(g)).unwrap();
        z.push((format!("random-g{g}"), m, (0, 0, 0), 0));
    }
    z
}

#[test]
fn builders_have_expected_counts_and_invariants() {
    for (name, m, (v, e, f), loops) in zoo() {
        m.check_invariants()
            .unwrap_or_else(|err| panic!("{name}: {err}"));
        if !name.starts_with("random") {
            assert_eq!(
                (m.n_vertices(), m.n_edges(), m.n_faces()),
                (v, e, f),
                "{name}"
            );
        }
        assert_eq!(m.n_boundary_loops(), loops, "{name}");
        let deg_sum: usize = m.vertices().map(|x| m.degree(x)).sum();
        assert_eq!(deg_sum, 2 * m.n_edges(), "{name}: degrees sum to 2E");
    }
}

#[test]
fn random_surfaces_have_requested_genus_and_size() {
    for g in 0..=3u32 {
        for nv in [3u32, 4, 9] {
            let m = builders::random_surface(g, nv, 7).unwrap();
            m.check_invariants().unwrap();
            assert!(m.is_closed());
            assert_eq!(m.n_vertices(), nv as usize);
            assert_eq!(m.euler_characteristic(), 2 - 2 * i64::from(g));
        }
    }
    assert!(builders::random_surface(0, 2, 0).is_err());
}

#[test]
fn platonic_degrees() {
    let deg = |m: &Mesh| -> Vec<usize> { m.vertices().map(|v| m.degree(v)).collect() };
    assert!(deg(&builders::tetrahedron().mesh).iter().all(|&d| d == 3));
    assert!(deg(&builders::icosahedron().mesh).iter().all(|&d| d == 5));
    // Cube split by the even family: vertices with even bit count have degree 6.
    let c = builders::cube(CubeDiagonals::Even).mesh;
    for v in c.vertices() {
        let even = v.0.count_ones() % 2 == 0;
        assert_eq!(c.degree(v), if even { 6 } else { 3 }, "{v}");
    }
    let c = builders::cube(CubeDiagonals::Odd).mesh;
    for v in c.vertices() {
        let even = v.0.count_ones() % 2 == 0;
        assert_eq!(c.degree(v), if even { 3 } else { 6 }, "{v}");
    }
    let t = builders::flat_torus(4, 3).unwrap().mesh;
    assert!(deg(&t).iter().all(|&d| d == 6));
    let g = builders::genus(3).unwrap();
    assert_eq!(g.degree(Vertex(0)), 2 * g.n_edges());
}

/// Exact outward orientation: for an embedded closed surface around the origin, every
/// face (a, b, c) has det[a, b, c] > 0 (computed in ℚ, independent of the builder code).
#[test]
fn embedded_solids_are_outward_oriented() {
    for (name, e) in [
        ("tet", builders::tetrahedron()),
        ("oct", builders::octahedron()),
        ("ico", builders::icosahedron()),
        ("cube-even", builders::cube(CubeDiagonals::Even)),
        ("cube-odd", builders::cube(CubeDiagonals::Odd)),
        ("triakis-tet", builders::triakis_tetrahedron()),
        ("triakis-oct", builders::triakis_octahedron()),
    ] {
        for f in e.mesh.faces() {
            let [a, b, c] = e
                .mesh
                .face_vertices(f)
                .map(|v| e.positions[v.idx()].clone());
            let cross = [
                b[1].clone() * &c[2] - b[2].clone() * &c[1],
                b[2].clone() * &c[0] - b[0].clone() * &c[2],
                b[0].clone() * &c[1] - b[1].clone() * &c[0],
            ];
            let det =
                a[0].clone() * &cross[0] + a[1].clone() * &cross[1] + a[2].clone() * &cross[2];
            assert!(det > 0, "{name} {f}");
        }
    }
    // Planar builders: every face counter-clockwise in the xy-plane.
    for (name, e) in [
        ("grid", builders::grid_disk(3, 2).unwrap()),
        ("annulus", builders::annulus(5, 2).unwrap()),
        ("planar", builders::random_planar(30, 1).unwrap()),
    ] {
        for f in e.mesh.faces() {
            let [a, b, c] = e
                .mesh
                .face_vertices(f)
                .map(|v| e.positions[v.idx()].clone());
            let area2 = (b[0].clone() - &a[0]) * (c[1].clone() - &a[1])
                - (b[1].clone() - &a[1]) * (c[0].clone() - &a[0]);
            assert!(area2 > 0, "{name} {f}");
        }
    }
}

#[test]
fn planar_points_refuses_bad_input() {
    use builders::BuildError;
    let ok = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [1.0, 1.0]];
    let e = builders::planar_points(&ok).unwrap();
    assert_eq!((e.mesh.n_vertices(), e.mesh.n_faces()), (4, 2));
    assert_eq!(
        builders::planar_points(&[[0.0, 0.0], [1.0, 0.0], [0.0, 0.0]]),
        Err(BuildError::DuplicatePoint { index: 2 })
    );
    assert_eq!(
        builders::planar_points(&[[0.0, 0.0], [f64::NAN, 0.0]]),
        Err(BuildError::BadPoint { index: 1 })
    );
    assert_eq!(
        builders::planar_points(&[[0.0, 0.0], [1.0, 1.0], [2.0, 2.0]]),
        Err(BuildError::Degenerate)
    );
    assert!(builders::grid_disk(0, 3).is_err());
    assert!(builders::annulus(2, 3).is_err());
    assert!(builders::genus(0).is_err());
    assert!(matches!(
        builders::flat_torus(1 << 16, 1 << 16),
        Err(BuildError::TooLarge { .. })
    ));
}

#[test]
fn remove_face_makes_a_hole_or_refuses() {
    let oct = builders::octahedron().mesh;
    let d = builders::remove_face(&oct, Face(3)).unwrap();
    d.check_invariants().unwrap();
    assert_eq!(
        (d.n_faces(), d.n_boundary_loops(), d.euler_characteristic()),
        (7, 1, 1)
    );
    // One-vertex torus: both corners of every face sit at the one vertex: refused.
    assert!(builders::remove_face(&builders::one_vertex_torus(), Face(0)).is_err());
}

/// Relabel a raw mesh by a half-edge permutation `ph` and a face permutation `pf`.
fn relabel(r: &RawMesh, ph: &[u32], pf: &[u32]) -> RawMesh {
    let nh = r.next.len();
    let mut out = r.clone();
    for h in 0..nh {
        let n = ph[h] as usize;
        out.next[n] = ph[r.next[h] as usize];
        out.tail[n] = r.tail[h];
        out.face[n] = r.face[h].map(|f| pf[f as usize]);
    }
    out
}

/// Flipping `e` twice equals the original up to the documented relabeling: swap `2e` ↔
/// `2e+1` and the two faces (face_halfedge/out may differ); four flips restore
/// next/tail/face exactly.
pub(crate) fn check_flip_involution(name: &str, m: &Mesh, e: Edge) {
    let before = m.to_raw();
    let mut x = m.clone();
    let (fa, fb) = (m.face(e.side(0)), m.face(e.side(1)));
    x.flip(e).unwrap();
    x.check_invariants()
        .unwrap_or_else(|err| panic!("{name} {e}: {err}"));
    assert_eq!(
        x.euler_characteristic(),
        m.euler_characteristic(),
        "{name} {e}"
    );
    assert_eq!(x.n_boundary_loops(), m.n_boundary_loops());
    x.flip(e).unwrap();
    x.check_invariants().unwrap();
    let mut ph: Vec<u32> = (0..m.n_halfedges() as u32).collect();
    ph.swap(e.side(0).idx(), e.side(1).idx());
    let mut pf: Vec<u32> = (0..m.n_faces() as u32).collect();
    let (fa, fb) = (fa.unwrap().idx(), fb.unwrap().idx());
    pf.swap(fa, fb);
    let want = relabel(&before, &ph, &pf);
    let got = x.to_raw();
    assert_eq!(
        (&got.next, &got.tail, &got.face),
        (&want.next, &want.tail, &want.face),
        "{name} {e}"
    );
    x.flip(e).unwrap();
    x.flip(e).unwrap();
    let got = x.to_raw();
    assert_eq!(
        (&got.next, &got.tail, &got.face),
        (&before.next, &before.tail, &before.face)
    );
}

#[test]
fn t02_every_flippable_edge_of_every_builder() {
    let mut flipped = 0;
    for (name, m, _, _) in zoo() {
        for e in m.edges() {
            let mut x = m.clone();
            match x.flip(e) {
                Ok(()) => {
                    check_flip_involution(&name, &m, e);
                    flipped += 1;
                }
                Err(FlipError::Boundary(_)) => assert!(m.is_boundary_edge(e)),
                Err(FlipError::SameFace(_)) => assert_eq!(m.face(e.side(0)), m.face(e.side(1))),
                Err(err) => panic!("{name} {e}: {err}"),
            }
            assert_eq!(x.euler_characteristic(), m.euler_characteristic());
        }
    }
    assert!(flipped > 200, "{flipped}");
}

#[test]
fn t02_random_flip_sequences_keep_invariants_and_euler_characteristic() {
    let mut rng = ChaCha8Rng::seed_from_u64(2);
    let bases = zoo();
    let mut flips = 0usize;
    for round in 0..cases(40, 4000) {
        let (name, base, _, _) = &bases[round % bases.len()];
        let mut m = base.clone();
        let chi = m.euler_characteristic();
        for _ in 0..30 {
            let e = Edge(rng.gen_range(0..m.n_edges() as u32));
            let deg_before: usize = m.vertices().map(|v| m.degree(v)).sum();
            if m.flip(e).is_ok() {
                flips += 1;
                m.check_invariants()
                    .unwrap_or_else(|err| panic!("{name}: {err}"));
                assert_eq!(m.euler_characteristic(), chi);
                let deg_after: usize = m.vertices().map(|v| m.degree(v)).sum();
                assert_eq!(deg_before, deg_after);
                if rng.gen_bool(0.2) {
                    check_flip_involution(name, &m, e);
                }
            }
        }
        // Face splits keep χ too.
        let v = m
            .split_face(Face(rng.gen_range(0..m.n_faces() as u32)))
            .unwrap();
        m.check_invariants().unwrap();
        assert_eq!((m.euler_characteristic(), m.degree(v)), (chi, 3));
    }
    assert!(flips > 500, "{flips}");
}

/// A flip that only relabels the connectivity cannot change the vertex degrees' multiset
/// except at the four quad corners: i, j lose one, k, l gain one.
#[test]
fn t02_flip_changes_degrees_at_quad_corners_only() {
    let m = builders::icosahedron().mesh;
    let e = Edge(0);
    let h = e.side(0);
    let (i, j, k, l) = (
        m.tail(h),
        m.tip(h),
        m.opposite_vertex(h),
        m.opposite_vertex(h.twin()),
    );
    let mut x = m.clone();
    x.flip(e).unwrap();
    for v in m.vertices() {
        let d = m.degree(v) as i64;
        let want = if v == i || v == j {
            d - 1
        } else if v == k || v == l {
            d + 1
        } else {
            d
        };
        assert_eq!(x.degree(v) as i64, want, "{v}");
    }
    let h = e.side(0);
    assert_eq!((x.tail(h), x.tip(h)), (l, k));
}

#[test]
fn outgoing_visits_each_half_edge_once() {
    for (name, m, _, _) in zoo() {
        let mut seen = vec![0u32; m.n_halfedges()];
        for v in m.vertices() {
            let hs: Vec<_> = m.outgoing(v).collect();
            assert_eq!(hs.first(), Some(&m.vertex_halfedge(v)));
            if m.is_boundary_vertex(v) {
                assert!(m.is_boundary_halfedge(hs[0]), "{name}");
                assert!(m.is_boundary_halfedge(hs[hs.len() - 1].twin()), "{name}");
            }
            for h in hs {
                assert_eq!(m.tail(h), v);
                seen[h.idx()] += 1;
            }
        }
        assert!(seen.iter().all(|&c| c == 1), "{name}");
    }
}

/// Negative controls: each corruption is caught by `check_invariants` (via `from_raw`).
#[test]
fn corrupted_meshes_fail_invariants() {
    let good = builders::grid_disk(2, 2).unwrap().mesh.to_raw();
    assert!(Mesh::from_raw(good.clone()).is_ok());
    let first_boundary = good.face.iter().position(Option::is_none).unwrap();
    let first_interior = good.face.iter().position(Option::is_some).unwrap();
    let h0 = first_interior;
    let corruptions: Vec<Corruption> = vec![
        ("next out of range", Box::new(|r| r.next[0] = 999)),
        (
            "next not a permutation",
            Box::new(move |r| r.next[h0] = r.next[r.next[h0] as usize]),
        ),
        (
            "tail changed",
            Box::new(move |r| r.tail[h0] = (r.tail[h0] + 1) % r.n_vertices),
        ),
        (
            "face relabeled",
            Box::new(move |r| r.face[h0] = r.face[h0].map(|f| (f + 1) % 8)),
        ),
        (
            "interior made boundary",
            Box::new(move |r| r.face[h0] = None),
        ),
        (
            "boundary made interior",
            Box::new(move |r| r.face[first_boundary] = Some(0)),
        ),
        (
            "face_halfedge wrong",
            Box::new(move |r| r.face_halfedge[0] = r.face_halfedge[1]),
        ),
        ("out wrong vertex", Box::new(|r| r.out.swap(0, 1))),
        (
            "out interior at boundary vertex",
            Box::new(|r| {
                let h = (0..r.tail.len())
                    .find(|&h| r.tail[h] == 0 && r.face[h].is_some())
                    .unwrap();
                r.out[0] = h as u32;
            }),
        ),
        (
            "odd length",
            Box::new(|r| {
                r.next.push(0);
                r.tail.push(0);
                r.face.push(None);
            }),
        ),
        (
            "isolated vertex",
            Box::new(|r| {
                r.n_vertices += 1;
                r.out.push(0);
            }),
        ),
        ("swapped next", Box::new(|r| r.next.swap(0, 1))),
    ];
    for (what, corrupt) in corruptions {
        let mut r = good.clone();
        corrupt(&mut r);
        assert!(Mesh::from_raw(r).is_err(), "{what} not detected");
    }
    // A pinched vertex: two triangles sharing only vertex 0 (a bow tie).
    let two = Mesh::from_faces(6, &[[0, 1, 2], [3, 4, 5]])
        .unwrap()
        .to_raw();
    let mut pinched = two.clone();
    for t in &mut pinched.tail {
        *t = match *t {
            3 => 0,
            t if t > 3 => t - 1,
            t => t,
        };
    }
    pinched.out.remove(3);
    pinched.n_vertices = 5;
    let err = Mesh::from_raw(pinched).unwrap_err();
    assert!(
        matches!(err, InvariantError::NonManifoldVertex { vertex: 0, .. }),
        "{err}"
    );
    assert!(Mesh::from_raw(two).is_ok());
}

/// Negative control for the involution check: after two flips the mesh is *not* equal to
/// the original without the relabeling, and a wrong relabeling (faces not swapped) is
/// rejected too.
#[test]
fn t02_involution_check_rejects_wrong_relabeling() {
    let m = builders::octahedron().mesh;
    let e = Edge(0);
    let mut x = m.clone();
    x.flip(e).unwrap();
    x.flip(e).unwrap();
    let (got, before) = (x.to_raw(), m.to_raw());
    assert_ne!(got.next, before.next);
    let mut ph: Vec<u32> = (0..m.n_halfedges() as u32).collect();
    ph.swap(e.side(0).idx(), e.side(1).idx());
    let pf: Vec<u32> = (0..m.n_faces() as u32).collect();
    let wrong = relabel(&before, &ph, &pf);
    assert_ne!((&got.next, &got.face), (&wrong.next, &wrong.face));
    // A flip that skips the tail update breaks the invariants: tails are checked.
    let mut raw = m.clone().to_raw();
    let mut y = m.clone();
    y.flip(e).unwrap();
    let flipped = y.to_raw();
    raw.next.clone_from(&flipped.next);
    raw.face.clone_from(&flipped.face);
    raw.face_halfedge.clone_from(&flipped.face_halfedge);
    assert!(Mesh::from_raw(raw).is_err());
}
