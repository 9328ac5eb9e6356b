//! Tangency packings of surfaces (`penner pack`) and their pictures: the layout closes up
//! around every vertex (one placement per vertex of a disk), neighbours touch, and no two
//! circles overlap.

use penner::circles::pack::{pack, puncture};
use penner::circles::svg::{placed_circles, render_svg};
use penner::mesh::builders::{grid_disk, icosahedron, random_planar};
use penner::mesh::Mesh;

/// Largest relative tangency error over the edges and largest relative overlap over all
/// pairs of circles, for a layout with one placement per vertex.
fn tangency_and_overlap(mesh: &Mesh, circles: &[penner::circles::svg::PlacedCircle]) -> (f64, f64) {
    let mut at = vec![None; mesh.n_vertices()];
    for c in circles {
        assert!(
            at[c.vertex].is_none(),
            "v{} placed twice: the layout does not close",
            c.vertex
        );
        at[c.vertex] = Some(c.clone());
    }
    let mut tangency = 0.0_f64;
    for e in mesh.edges() {
        let h = e.halfedge();
        let (a, b) = (
            at[mesh.tail(h).idx()].as_ref().unwrap(),
            at[mesh.tip(h).idx()].as_ref().unwrap(),
        );
        let d = (a.centre[0] - b.centre[0]).hypot(a.centre[1] - b.centre[1]);
        tangency = tangency.max((d - a.radius - b.radius).abs() / (a.radius + b.radius));
    }
    let mut overlap = 0.0_f64;
    for (i, a) in circles.iter().enumerate() {
        for b in &circles[i + 1..] {
            let d = (a.centre[0] - b.centre[0]).hypot(a.centre[1] - b.centre[1]);
            overlap = overlap.max((a.radius + b.radius - d) / (a.radius + b.radius));
        }
    }
    (tangency, overlap)
}

#[test]
fn disk_packings_close_up_touch_and_do_not_overlap() {
    let meshes = vec![
        grid_disk(6, 5).unwrap().mesh,
        random_planar(40, 7).unwrap().mesh,
        puncture(&icosahedron().mesh, 0).unwrap(),
    ];
    for mesh in meshes {
        let p = pack(&mesh).unwrap();
        assert!(p.certificate.is_ok(), "{:?}", p.certificate);
        let circles = placed_circles(&p.pattern.mesh, &p.lengths(), &p.radii());
        let (tangency, overlap) = tangency_and_overlap(&p.pattern.mesh, &circles);
        // Newton stops at 64·n·u radians (≈ 10⁻¹² here); the layout accumulates that error
        // along the breadth-first tree: 10⁻⁸ relative is far above it and far below the
        // 10⁻³ control below.
        assert!(tangency < 1e-8, "tangency error {tangency}");
        assert!(overlap < 1e-8, "overlap {overlap}");
        // Negative control: one radius changed by 1% (the layout is redone with the wrong
        // lengths) no longer closes up or no longer touches.
        let mut r = p.radii();
        let v = p.pattern.free()[0];
        r[v] *= 1.01;
        let cos = vec![1.0; p.pattern.mesh.n_edges()];
        let l = penner::circles::metric::lengths_from_radii(&p.pattern.mesh, &r, &cos);
        let bad = placed_circles(&p.pattern.mesh, &l, &r);
        assert!(
            bad.len() > p.pattern.mesh.n_vertices(),
            "a wrong radius still closes up"
        );
        let svg = render_svg(&p.pattern.mesh, &p.lengths(), &p.radii());
        assert_eq!(svg.matches("<circle").count(), p.pattern.mesh.n_vertices());
    }
    // A sphere is punctured before packing.
    let p = pack(&icosahedron().mesh).unwrap();
    assert_eq!(p.kind, "punctured sphere");
    assert_eq!(p.pattern.mesh.n_vertices(), 11);
}

/// A 3×3 grid disk with one diagonal flipped per row, as OBJ.
fn grid_obj() -> String {
    use std::fmt::Write as _;
    let mut s = String::new();
    for j in 0..4 {
        for i in 0..4 {
            let _ = writeln!(s, "v {i} {j} 0");
        }
    }
    for j in 0..3 {
        for i in 0..3 {
            let a = i + 4 * j + 1;
            let (b, c, d) = (a + 1, a + 5, a + 4);
            if (i + j) % 2 == 0 {
                let _ = writeln!(s, "f {a} {b} {c}\nf {a} {c} {d}");
            } else {
                let _ = writeln!(s, "f {a} {b} {d}\nf {b} {c} {d}");
            }
        }
    }
    s
}

#[test]
fn cli_pack_writes_a_new_svg_and_never_overwrites() {
    use crate::support::{assert_refused, penner, scratch, text, write};
    let dir = scratch("pack");
    let input = write(&dir, "grid.obj", grid_obj().as_bytes());
    let svg = dir.join("grid.svg");
    let out = penner(&[
        "pack",
        input.to_str().unwrap(),
        "--svg",
        svg.to_str().unwrap(),
    ]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert!(text(&out.stdout).contains("certified (B94)"));
    let doc = std::fs::read_to_string(&svg).unwrap();
    assert_eq!(doc.matches("<circle").count(), 16);
    // A second run refuses to overwrite (exit 4) and leaves the file as it was.
    let again = penner(&[
        "pack",
        input.to_str().unwrap(),
        "--svg",
        svg.to_str().unwrap(),
    ]);
    assert_refused(&again, 4, &["exists"]);
    assert_eq!(std::fs::read_to_string(&svg).unwrap(), doc);
    // An unwritable place is exit 4 as well; without --svg nothing is written.
    let bad = dir.join("no-such-dir").join("x.svg");
    assert_refused(
        &penner(&[
            "pack",
            input.to_str().unwrap(),
            "--svg",
            bad.to_str().unwrap(),
        ]),
        4,
        &["cannot write"],
    );
    let plain = penner(&["pack", input.to_str().unwrap()]);
    assert_eq!(plain.status.code(), Some(0));
    // Bad input: a missing file, and a one-vertex torus (every face meets its vertex
    // thrice) named by face.
    assert_refused(
        &penner(&["pack", dir.join("none.obj").to_str().unwrap()]),
        3,
        &["none.obj"],
    );
    let torus = write(
        &dir,
        "torus.json",
        br#"{"vertices": 1, "faces": [[0,0,0],[0,0,0]], "gluing": [[[0,0],[1,1]],[[0,1],[1,2]],[[0,2],[1,0]]], "lengths": [1,1,1]}"#,
    );
    assert_refused(&penner(&["pack", torus.to_str().unwrap()]), 3, &["face f0"]);
}
