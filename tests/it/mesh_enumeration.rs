//! T02 on every small Δ-complex: all orientable gluings of up to four triangles (closed)
//! and up to three triangles (with boundary), enumerated from side pairings rather than
//! taken from the builders. Complexes are labeled (one per side pairing, not up to
//! isomorphism): 9720 closed connected complexes of four triangles, 1900 with boundary of
//! up to three triangles (95 860 of up to four in the long mode, `PENNER_LONG=1`).

use crate::mesh::check_flip_involution;
use crate::support::cases;
use penner::mesh::{FaceSide, FlipError, Mesh};

/// A face side `(face, side)`; side `s` of face `f` runs from corner `s` to corner `s+1`.
type Side = FaceSide;

/// Every partial matching of `sides` (perfect ones only when `perfect`), as lists of pairs.
fn matchings(sides: &[Side], perfect: bool) -> Vec<Vec<(Side, Side)>> {
    let Some((&first, rest)) = sides.split_first() else {
        return vec![Vec::new()];
    };
    let mut out = Vec::new();
    if !perfect {
        // `first` stays a boundary side.
        out.extend(matchings(rest, perfect));
    }
    for (k, &partner) in rest.iter().enumerate() {
        let mut remaining = rest.to_vec();
        remaining.remove(k);
        for mut m in matchings(&remaining, perfect) {
            m.push((first, partner));
            out.push(m);
        }
    }
    out
}

/// Union–find root with path halving.
fn root(parent: &mut [usize], mut x: usize) -> usize {
    while parent[x] != x {
        parent[x] = parent[parent[x]];
        x = parent[x];
    }
    x
}

/// The complex of `n_faces` triangles glued by `pairs` (each glued pair reversed, so the
/// result is orientable), with vertices the classes of corners identified by the gluing,
/// and `V − E + F` counted from the pairing alone (an oracle for the mesh's own count).
/// `None` when the complex is disconnected.
fn complex(n_faces: u32, pairs: &[(Side, Side)]) -> Option<(Mesh, i64)> {
    let corner = |f: u32, c: u8| 3 * f as usize + c as usize % 3;
    let n = 3 * n_faces as usize;
    let mut parent: Vec<usize> = (0..n).collect();
    let mut face_parent: Vec<usize> = (0..n_faces as usize).collect();
    for &((f, s), (g, t)) in pairs {
        // Side s of f runs c_s → c_{s+1}; glued reversed to side t of g (c_t → c_{t+1}).
        for (a, b) in [
            (corner(f, s), corner(g, t + 1)),
            (corner(f, s + 1), corner(g, t)),
        ] {
            let (ra, rb) = (root(&mut parent, a), root(&mut parent, b));
            parent[ra] = rb;
        }
        let (ra, rb) = (
            root(&mut face_parent, f as usize),
            root(&mut face_parent, g as usize),
        );
        face_parent[ra] = rb;
    }
    let r0 = root(&mut face_parent, 0);
    if (0..n_faces as usize).any(|f| root(&mut face_parent, f) != r0) {
        return None;
    }
    let mut id = vec![u32::MAX; n];
    let mut n_vertices = 0u32;
    for c in 0..n {
        let r = root(&mut parent, c);
        if id[r] == u32::MAX {
            id[r] = n_vertices;
            n_vertices += 1;
        }
    }
    let faces: Vec<[u32; 3]> = (0..n_faces)
        .map(|f| [0, 1, 2].map(|c| id[root(&mut parent, corner(f, c))]))
        .collect();
    let n_edges = pairs.len() + (n - 2 * pairs.len());
    let chi = i64::from(n_vertices) - n_edges as i64 + i64::from(n_faces);
    let mesh = Mesh::from_gluing(n_vertices, &faces, pairs)
        .unwrap_or_else(|e| panic!("gluing {pairs:?}: {e}"));
    Some((mesh, chi))
}

/// Flip every edge of every connected complex from `sides` matchings: a flip succeeds
/// exactly when the edge is interior with two distinct faces, and then is an involution up
/// to the documented relabeling with invariants and χ kept. Returns (complexes, flips).
fn flip_all(n_faces: u32, perfect: bool) -> (usize, usize) {
    let sides: Vec<Side> = (0..n_faces)
        .flat_map(|f| (0..3).map(move |s| (f, s)))
        .collect();
    let (mut complexes, mut flips) = (0, 0);
    for pairs in matchings(&sides, perfect) {
        let Some((m, chi)) = complex(n_faces, &pairs) else {
            continue;
        };
        complexes += 1;
        m.check_invariants()
            .unwrap_or_else(|e| panic!("{pairs:?}: {e}"));
        assert_eq!(m.euler_characteristic(), chi, "{pairs:?}");
        let name = format!("{pairs:?}");
        for e in m.edges() {
            let mut x = m.clone();
            match x.flip(e) {
                Ok(()) => {
                    check_flip_involution(&name, &m, e);
                    flips += 1;
                }
                Err(FlipError::Boundary(_)) => assert!(m.is_boundary_edge(e), "{name} {e}"),
                Err(FlipError::SameFace(_)) => {
                    assert_eq!(m.face(e.side(0)), m.face(e.side(1)), "{name} {e}");
                }
                Err(err) => panic!("{name} {e}: {err}"),
            }
        }
    }
    (complexes, flips)
}

#[test]
fn t02_enumeration_counts_match_the_matching_numbers() {
    // Negative control for the enumerator: the numbers of perfect matchings of 6 and 12
    // sides are 5!! = 15 and 11!! = 10395; of all matchings of 3 sides, 1 + 3 = 4.
    let sides =
        |f: u32| -> Vec<Side> { (0..f).flat_map(|f| (0..3).map(move |s| (f, s))).collect() };
    assert_eq!(matchings(&sides(2), true).len(), 15);
    assert_eq!(matchings(&sides(4), true).len(), 10_395);
    assert_eq!(matchings(&sides(1), false).len(), 4);
    // Two triangles glued along one side only: a disk with χ = 1; a disconnected pair is
    // skipped.
    let (m, chi) = complex(2, &[((0, 0), (1, 0))]).unwrap();
    assert_eq!(
        (chi, m.euler_characteristic(), m.n_boundary_loops()),
        (1, 1, 1)
    );
    assert!(complex(2, &[]).is_none());
}

#[test]
fn t02_every_edge_of_every_closed_complex_of_two_and_four_triangles() {
    let (c2, f2) = flip_all(2, true);
    let (c4, f4) = flip_all(4, true);
    // Every pairing of two triangles is connected; at least the one-vertex torus and the
    // sphere of two triangles have flippable edges.
    eprintln!("closed: 2 faces {c2} complexes {f2} flips; 4 faces {c4} complexes {f4} flips");
    assert_eq!(c2, 15);
    assert!(f2 > 0 && c4 > 1000 && f4 > 1000, "{c2} {f2} {c4} {f4}");
}

#[test]
fn t02_every_edge_of_every_complex_with_boundary_up_to_three_triangles() {
    let mut total = (0, 0);
    for n in 1..=cases(3, 4) as u32 {
        let (c, f) = flip_all(n, false);
        total = (total.0 + c, total.1 + f);
    }
    eprintln!("with boundary: {} complexes, {} flips", total.0, total.1);
    assert!(total.0 > 1000 && total.1 > 1000, "{total:?}");
}
