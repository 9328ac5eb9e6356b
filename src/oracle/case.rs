//! The subject of every check: an [`io::Surface`](crate::io::Surface) (a named Δ-complex
//! with an exact metric), and the exact operations on its metric the oracle needs.

use crate::io::{Metric, Surface};
use crate::mesh::Mesh;
use rug::Rational;

/// Exact operations on a [`Metric`].
pub trait MetricOps {
    /// The conformal scaling ℓ̃_ij = s_i s_j ℓ_ij with rational s_i = e^{u_i/2} (docs/catalogue.md
    /// §4, Eq. 10), exact; squared lengths scale by s_i² s_j².
    fn scaled(&self, mesh: &Mesh, s: &[Rational]) -> Metric;
    /// Entry `i` of the result is entry `map[i]` of `self` (maps come from the mesh, so
    /// indices are in range).
    fn reindex(&self, map: &[usize]) -> Metric;
}

impl MetricOps for Metric {
    fn scaled(&self, mesh: &Mesh, s: &[Rational]) -> Metric {
        let squared = matches!(self, Metric::SquaredLengths(_));
        let v = self.values();
        let out = mesh
            .edges()
            .map(|e| {
                let h = e.halfedge();
                let f = Rational::from(&s[mesh.tail(h).idx()] * &s[mesh.tip(h).idx()]);
                let f = if squared { Rational::from(&f * &f) } else { f };
                f * &v[e.idx()]
            })
            .collect();
        if squared {
            Metric::SquaredLengths(out)
        } else {
            Metric::Lengths(out)
        }
    }

    fn reindex(&self, map: &[usize]) -> Metric {
        let v = self.values();
        let pick: Vec<Rational> = map.iter().map(|&i| v[i].clone()).collect();
        match self {
            Metric::Lengths(_) => Metric::Lengths(pick),
            Metric::SquaredLengths(_) => Metric::SquaredLengths(pick),
        }
    }
}

/// The same surface under another name.
pub fn renamed(s: &Surface, name: impl Into<String>) -> Surface {
    Surface {
        name: name.into(),
        ..s.clone()
    }
}
