//! Validation of explicit gluings (`Mesh::from_gluing`), exhaustively on small complexes:
//! one and two triangles, every vertex labeling up to renaming, every partial pairing of
//! their sides, each pair listed both ways round. The oracle is the definition, written
//! here from the vertex labels alone: side `s` of face `f` runs `F[f][s] → F[f][s+1]`, and
//! an orientable gluing joins `a→b` to `b→a` — both ends must match. End to end, `penner
//! check` refuses such a surface file before printing any theorem row.

use crate::support::{assert_refused, penner, scratch, text, write};
use penner::mesh::{Face, FaceSide, Mesh, MeshError};

/// Every partial matching of `sides`, as lists of pairs.
fn matchings(sides: &[FaceSide]) -> Vec<Vec<(FaceSide, FaceSide)>> {
    let Some((&first, rest)) = sides.split_first() else {
        return vec![Vec::new()];
    };
    let mut out = matchings(rest);
    for (k, &partner) in rest.iter().enumerate() {
        let mut remaining = rest.to_vec();
        remaining.remove(k);
        for mut m in matchings(&remaining) {
            m.insert(0, (first, partner));
            out.push(m);
        }
    }
    out
}

/// Every labeling of `n` corners up to renaming of the labels (restricted growth strings:
/// each label is at most one more than the largest before it), so every label is used.
fn labelings(n: usize) -> Vec<Vec<u32>> {
    let mut out = vec![Vec::new()];
    for _ in 0..n {
        out = out
            .into_iter()
            .flat_map(|l: Vec<u32>| {
                let next = l.iter().max().map_or(0, |m| m + 1);
                (0..=next).map(move |v| {
                    let mut l = l.clone();
                    l.push(v);
                    l
                })
            })
            .collect();
    }
    out
}

/// The side `(f, s)` as the vertex pair (tail, tip) it runs along.
fn ends(faces: &[[u32; 3]], (f, s): FaceSide) -> (u32, u32) {
    let t = faces[f as usize];
    (t[s as usize], t[(s as usize + 1) % 3])
}

/// Which ends of a glued pair match the definition: (tail of p = tip of q, tip of p = tail of q).
fn matching_ends(faces: &[[u32; 3]], (p, q): (FaceSide, FaceSide)) -> (bool, bool) {
    let ((a0, a1), (b0, b1)) = (ends(faces, p), ends(faces, q));
    (a0 == b1, a1 == b0)
}

/// An accepted mesh realizes the input: each face's sides in order run along the labels
/// given, glued sides are twins running the opposite way, and every other side is on the
/// boundary.
fn assert_realizes(mesh: &Mesh, faces: &[[u32; 3]], pairs: &[(FaceSide, FaceSide)]) {
    let he = |(f, s): FaceSide| mesh.face_halfedges(Face(f))[s as usize];
    for (f, t) in faces.iter().enumerate() {
        for s in 0..3u8 {
            let h = he((f as u32, s));
            let (a, b) = ends(faces, (f as u32, s));
            assert_eq!(
                (mesh.tail(h).0, mesh.tip(h).0, mesh.tail(mesh.next(h)).0),
                (a, b, b),
                "face {f} {t:?} side {s}"
            );
            let glued = pairs
                .iter()
                .any(|&(p, q)| p == (f as u32, s) || q == (f as u32, s));
            assert_eq!(
                !glued,
                mesh.is_boundary_halfedge(h.twin()),
                "face {f} side {s}"
            );
        }
    }
    for &(p, q) in pairs {
        assert_eq!(he(p).twin(), he(q), "{p:?} and {q:?} are not twins");
    }
    mesh.check_invariants().expect("invariants");
}

/// Check `from_gluing` on one complex against the definition; returns whether some pair
/// is wrong at exactly one end, and whether the complex was accepted.
fn check_complex(faces: &[[u32; 3]], pairs: &[(FaceSide, FaceSide)]) -> (bool, bool) {
    let n_vertices = faces.iter().flatten().max().map_or(0, |m| m + 1);
    let got = Mesh::from_gluing(n_vertices, faces, pairs);
    let first_wrong = pairs
        .iter()
        .position(|&pair| matching_ends(faces, pair) != (true, true));
    match first_wrong {
        Some(index) => {
            let (p, q) = pairs[index];
            let ((a0, a1), (b0, b1)) = (ends(faces, p), ends(faces, q));
            assert_eq!(
                got.as_ref().err(),
                Some(&MeshError::InconsistentGluing {
                    index,
                    a0,
                    a1,
                    b0,
                    b1
                }),
                "faces {faces:?}, gluing {pairs:?}"
            );
        }
        None => match &got {
            Ok(mesh) => assert_realizes(mesh, faces, pairs),
            // A consistent gluing may still pinch a vertex (two fans); nothing else fails.
            Err(e) => assert!(
                matches!(e, MeshError::NonManifoldVertex { .. }),
                "faces {faces:?}, gluing {pairs:?}: {e}"
            ),
        },
    }
    let one_end = pairs
        .iter()
        .any(|&pair| matches!(matching_ends(faces, pair), (true, false) | (false, true)));
    (one_end, got.is_ok())
}

#[test]
fn gluing_wrong_at_either_end_is_refused_on_every_small_complex() {
    let mut one_end = 0;
    let mut accepted = 0;
    let mut total = 0;
    for n_faces in 1..=2u32 {
        let sides: Vec<FaceSide> = (0..n_faces)
            .flat_map(|f| (0..3u8).map(move |s| (f, s)))
            .collect();
        let all_pairs = matchings(&sides);
        for labels in labelings(3 * n_faces as usize) {
            let faces: Vec<[u32; 3]> = labels.chunks(3).map(|c| [c[0], c[1], c[2]]).collect();
            for pairs in &all_pairs {
                let reversed: Vec<_> = pairs.iter().map(|&(p, q)| (q, p)).collect();
                for list in [pairs, &reversed] {
                    total += 1;
                    let (wrong_at_one_end, ok) = check_complex(&faces, list);
                    one_end += usize::from(wrong_at_one_end);
                    accepted += usize::from(ok);
                }
            }
        }
    }
    // 5·4 one-face and 203·76 two-face complexes, each pairing listed both ways round.
    assert_eq!(total, 2 * (5 * 4 + 203 * 76));
    // The enumeration reaches the case at stake, and valid gluings too.
    assert!(
        one_end > 1000,
        "only {one_end} gluings wrong at exactly one end"
    );
    assert!(accepted > 100, "only {accepted} accepted");
}

#[test]
fn gluing_a_side_to_itself_or_twice_is_refused() {
    // A loop side 0→0 glued to itself matches at both ends but is one side, not two.
    assert_eq!(
        Mesh::from_gluing(1, &[[0, 0, 0]], &[((0, 0), (0, 0))]).err(),
        Some(MeshError::SideGluedTwice { face: 0, side: 0 })
    );
    let faces = [[0, 0, 0], [0, 0, 0]];
    assert_eq!(
        Mesh::from_gluing(1, &faces, &[((0, 0), (1, 0)), ((0, 0), (1, 1))]).err(),
        Some(MeshError::SideGluedTwice { face: 0, side: 0 })
    );
    // Negative control: the same faces with each side glued once form the one-vertex torus.
    let torus = Mesh::from_gluing(
        1,
        &faces,
        &[((0, 0), (1, 0)), ((0, 1), (1, 1)), ((0, 2), (1, 2))],
    );
    assert_eq!(torus.map(|m| m.euler_characteristic()).ok(), Some(0));
}

#[test]
fn check_refuses_a_gluing_wrong_at_one_end_before_any_row() {
    let d = scratch("strict-gluing");
    // Side 1 of face 0 runs 0→1, side 0 of face 1 runs 1→2: the tips match the tails at
    // one end (1 = 1) but not at the other (0 ≠ 2).
    let bad = br#"{"vertices": 3, "faces": [[0,0,1],[1,2,2]],
        "gluing": [[[0,1],[1,0]], [[0,2],[1,2]]], "lengths": ["1","1","1","1"]}"#;
    let p = write(&d, "one-end.json", bad);
    let out = penner(&["check", &p.display().to_string()]);
    assert_refused(&out, 3, &["one-end.json", "gluing[0]", "0→1"]);
    assert!(text(&out.stdout).is_empty(), "{}", text(&out.stdout));
    // Negative control: an explicit gluing that is right at both ends is read and checked.
    let good = br#"{"vertices": 4, "faces": [[0,1,2],[1,0,3]],
        "gluing": [[[0,0],[1,0]]], "lengths": ["1","1","1","1","1"]}"#;
    let p = write(&d, "both-ends.json", good);
    let out = penner(&["check", &p.display().to_string(), "--precision", "f64"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert!(
        text(&out.stdout).contains("4 vertices, 5 edges, 2 faces"),
        "{}",
        text(&out.stdout)
    );
}
