//! Circle packings and patterns (notes §1.4): the tangency packing of a Delaunay disk of random points and of a
//! punctured icosahedron, certified (B94) and drawn as SVG files in a fresh temporary
//! directory; the degenerating torus of T10 (Thurston's condition fails, the flow pushes one
//! radius to 0) next to its converging twin (T13).
//!
//! Run: `cargo run --release --example circles` (writes only under the system temp dir).

use penner::circles::pack::pack;
use penner::circles::solve::{convergence_rate, ricci_flow};
use penner::circles::svg::render_svg;
use penner::circles::thurston::check_thurston;
use penner::circles::CirclePattern;
use penner::mesh::builders::{flat_torus, icosahedron, random_planar};
use penner::mesh::Face;
use rug::Rational;
use std::io::Write;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let dir = std::env::temp_dir().join(format!("penner-circles-{}", std::process::id()));
    std::fs::create_dir_all(&dir)?;
    for (name, mesh) in [
        ("planar-disk", random_planar(40, 1)?.mesh),
        ("icosahedron", icosahedron().mesh),
    ] {
        let p = pack(&mesh)?;
        let status = match &p.certificate {
            Ok(c) => format!("certified within {:.1e} in log r", c.radius),
            Err(why) => format!("not certified: {why}"),
        };
        let path = dir.join(format!("{name}.svg"));
        let mut f = std::fs::OpenOptions::new()
            .write(true)
            .create_new(true)
            .open(&path)?;
        f.write_all(render_svg(&p.pattern.mesh, &p.lengths(), &p.radii()).as_bytes())?;
        println!(
            "{name:<12} {} ({} circles, {} Newton iterations): {status}; picture {}",
            p.kind,
            p.pattern.mesh.n_vertices(),
            p.iterations,
            path.display()
        );
    }

    // T10: a flat torus with one face split; Φ = π/2 on the link of the new vertex.
    for (q, what) in [((1, 2), "Φ = π/2 on the link"), ((0, 1), "tangency")] {
        let mut mesh = flat_torus(4, 4)?.mesh;
        let link = mesh.face_halfedges(Face(0)).map(|h| h.edge().idx());
        let v = mesh.split_face(Face(0))?.idx();
        let mut phi = vec![Rational::new(); mesh.n_edges()];
        for e in link {
            phi[e] = Rational::from(q);
        }
        let n = mesh.n_vertices();
        let p = CirclePattern::new(mesh, phi, vec![Some(Rational::from(2)); n])?;
        let thurston = check_thurston(&p.mesh, &p.phi)?;
        let flow = ricci_flow::<f64>(&p, &vec![0.0; n], 1e-12, 2000, false);
        let outcome = if let Ok(s) = flow {
            format!(
                "flow converges in {} steps (rate {:.3})",
                s.iterations,
                convergence_rate(&s.history, &s.times).unwrap_or(f64::NAN)
            )
        } else {
            let s = ricci_flow::<f64>(&p, &vec![0.0; n], 0.0, 2000, true)?;
            let mean = s.u.iter().sum::<f64>() / n as f64;
            format!(
                "flow does not converge: log(r_v/r̄) = {:.1} at t = {:.1}",
                s.u[v] - mean,
                s.times.last().copied().unwrap_or(0.0)
            )
        };
        println!(
            "torus, {what:<20} Thurston violations: {}; {outcome}",
            thurston.violations.len()
        );
    }
    Ok(())
}
