//! Integer normal coordinates of the edges of the input triangulation `T_in` relative to
//! the current triangulation `T` (Sharp, Soliman & Crane, *Navigating intrinsic
//! triangulations*, ACM TOG 38(4), 2019, §4; proof: B105).
//!
//! For each edge `e` of `T`, `n_e ≥ 0` is the number of times the edges of `T_in` (arcs
//! between vertices, in minimal position) cross the interior of `e`, and `n_e = −1` marks
//! an edge of `T` that *is* an edge of `T_in`. Initially `T = T_in` and every coordinate
//! is `−1`. Inside a face with sides `a = p₀p₁`, `b = p₁p₂`, `c = p₂p₀` and crossing counts
//! `n̂ = max(n, 0)`, the arcs are `x_r` corner arcs around corner `p_r` and `ε_r` arcs from
//! corner `p_r` to the opposite side, with (B105)
//!
//! ```text
//! ε₀ = max(0, n̂_b − n̂_a − n̂_c)   (and cyclically),   m_s = n̂_s − ε_(opposite corner),
//! x₀ = (m_a + m_c − m_b)/2        (and cyclically),   m_a + m_b + m_c even.
//! ```
//!
//! Flipping `ij` (faces `ijk`, `jil`) to `kl` gives (B105)
//!
//! ```text
//! n_kl = x_k + y_l + ε_i + ε_j + φ_i + φ_j + [n_ij = −1]
//!        + max(0, x_i − y_i − φ_l) + max(0, y_i − x_i − ε_k),
//! ```
//!
//! where `x, ε` are the arcs of `ijk` and `y, φ` those of `jil`; `n_kl = −1` instead when
//! an arc from `k` and an arc from `l` meet at one crossing of `ij` (the overlap of the
//! ranges `(x_i, x_i + ε_k]` and `(y_i, y_i + φ_l]` along `ij` from `i`).

use crate::mesh::{Edge, FlipError, HalfEdge, Mesh};

/// Why normal coordinates could not be kept or are not consistent.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum NormalError {
    /// The flip itself is refused by the mesh (boundary edge, self-folded face, no such
    /// edge).
    #[error(transparent)]
    Flip(#[from] FlipError),
    /// Not one coordinate per edge.
    #[error("{got} normal coordinates for {edges} edges")]
    Count {
        /// Values given.
        got: usize,
        /// Edges of the mesh.
        edges: usize,
    },
    /// A coordinate below −1.
    #[error("edge {0}: normal coordinate {1} is below -1")]
    Negative(Edge, i64),
    /// The three coordinates of a face admit no arc decomposition (odd sum of the
    /// reduced counts).
    #[error("face f{face}: coordinates {coords:?} have no arc decomposition (odd parity)")]
    Parity {
        /// The face.
        face: u32,
        /// Its coordinates in side order.
        coords: [i64; 3],
    },
    /// An edge of `T` that is an edge of `T_in` would be crossed, or two arcs of
    /// `T_in` from `k` to `l` would be parallel: not the coordinates of a triangulation.
    #[error("flip of edge {edge}: {reason}")]
    Inconsistent {
        /// The flipped edge.
        edge: Edge,
        /// What went wrong.
        reason: &'static str,
    },
    /// A count exceeds the `i64` range.
    #[error("edge {0}: the normal coordinate overflows")]
    Overflow(Edge),
}

/// The arcs of `T_in` inside one face with sides `[a, b, c]` = `[p₀p₁, p₁p₂, p₂p₀]`:
/// `corner[r]` arcs around corner `p_r`, `emanating[r]` arcs from corner `p_r` to the
/// opposite side (proof: B105).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FaceArcs {
    /// Corner arcs `x_r` around `p_r` (joining the two sides at `p_r`).
    pub corner: [i64; 3],
    /// Arcs `ε_r` from the vertex at `p_r` to the opposite side.
    pub emanating: [i64; 3],
}

/// The arc decomposition of a face with coordinates `n = [n_a, n_b, n_c]` (B105), `None`
/// on odd parity.
pub fn face_arcs(n: [i64; 3]) -> Option<FaceArcs> {
    let [a, b, c] = n.map(|v| v.max(0));
    // ε_r from p_r to the opposite side: p₀ ↔ b, p₁ ↔ c, p₂ ↔ a.
    let emanating = [(b - a - c).max(0), (c - a - b).max(0), (a - b - c).max(0)];
    let (ma, mb, mc) = (a - emanating[2], b - emanating[0], c - emanating[1]);
    if (ma + mb + mc) % 2 != 0 {
        return None;
    }
    // x₀ between c and a, x₁ between a and b, x₂ between b and c.
    let corner = [(ma + mc - mb) / 2, (ma + mb - mc) / 2, (mb + mc - ma) / 2];
    Some(FaceArcs { corner, emanating })
}

/// Normal coordinates of `T_in`'s edges relative to the current triangulation, indexed
/// by `Edge.idx()` of the current mesh (module documentation; proof: B105).
///
/// ```
/// use penner::mesh::{Edge, Mesh};
/// use penner::overlay::NormalCoordinates;
/// // Two triangles; flipping the diagonal crosses the old diagonal once.
/// let mut m = Mesh::from_faces(4, &[[0, 1, 2], [0, 2, 3]]).unwrap();
/// let mut n = NormalCoordinates::of_input(&m);
/// let d = m.edges().find(|&e| !m.is_boundary_edge(e)).unwrap();
/// n.flip(&mut m, d).unwrap();
/// assert_eq!(n.get(d), 1);
/// n.flip(&mut m, d).unwrap();
/// assert_eq!(n.get(d), -1); // the input diagonal is back
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct NormalCoordinates {
    n: Vec<i64>,
}

impl NormalCoordinates {
    /// `T = T_in`: every edge is an edge of the input (`−1`).
    pub fn of_input(mesh: &Mesh) -> NormalCoordinates {
        NormalCoordinates {
            n: vec![-1; mesh.n_edges()],
        }
    }

    /// Coordinates given by value, validated on `mesh` ([`NormalCoordinates::check`]).
    pub fn from_values(mesh: &Mesh, n: Vec<i64>) -> Result<NormalCoordinates, NormalError> {
        let c = NormalCoordinates { n };
        c.check(mesh)?;
        Ok(c)
    }

    /// The coordinate of `e`: crossings, or `−1` for an edge of `T_in`.
    pub fn get(&self, e: Edge) -> i64 {
        self.n[e.idx()]
    }

    /// All coordinates, indexed by `Edge.idx()`.
    pub fn values(&self) -> &[i64] {
        &self.n
    }

    /// The coordinates of the three sides of the face of `h`, from `h` on.
    fn face_coords(&self, mesh: &Mesh, h: HalfEdge) -> [i64; 3] {
        let b = mesh.next(h);
        [h, b, mesh.next(b)].map(|g| self.n[g.edge().idx()])
    }

    /// Necessary conditions for coordinates of a triangulation: one per edge, each `≥ −1`,
    /// boundary edges `−1` (they are never flipped), and every face decomposes into arcs
    /// (even parity, B105).
    pub fn check(&self, mesh: &Mesh) -> Result<(), NormalError> {
        if self.n.len() != mesh.n_edges() {
            return Err(NormalError::Count {
                got: self.n.len(),
                edges: mesh.n_edges(),
            });
        }
        for e in mesh.edges() {
            let v = self.get(e);
            if v < -1 || (mesh.is_boundary_edge(e) && v != -1) {
                return Err(NormalError::Negative(e, v));
            }
        }
        for f in mesh.faces() {
            let coords = self.face_coords(mesh, mesh.face_halfedge(f));
            if face_arcs(coords).is_none() {
                return Err(NormalError::Parity { face: f.0, coords });
            }
        }
        Ok(())
    }

    /// The coordinate the new diagonal `kl` gets when `e = ij` is flipped (B105), computed
    /// on the mesh before the flip.
    pub fn flipped_coordinate(&self, mesh: &Mesh, e: Edge) -> Result<i64, NormalError> {
        if e.idx() >= mesh.n_edges() {
            return Err(FlipError::OutOfRange(e).into());
        }
        let (h, t) = (e.side(0), e.side(1));
        match (mesh.face(h), mesh.face(t)) {
            (Some(a), Some(b)) if a != b => {}
            (Some(_), Some(_)) => return Err(FlipError::SameFace(e).into()),
            _ => return Err(FlipError::Boundary(e).into()),
        }
        let parity = |h: HalfEdge| {
            let coords = self.face_coords(mesh, h);
            let face = mesh.face(h).map_or(u32::MAX, |f| f.0);
            face_arcs(coords).ok_or(NormalError::Parity { face, coords })
        };
        // ijk from h = i→j: p₀ = i, p₁ = j, p₂ = k. jil from t = j→i: p₀ = j, p₁ = i, p₂ = l.
        let a = parity(h)?;
        let b = parity(t)?;
        let (x_i, x_k, e_i, e_j, e_k) = (
            a.corner[0],
            a.corner[2],
            a.emanating[0],
            a.emanating[1],
            a.emanating[2],
        );
        let (y_i, y_l, f_j, f_i, f_l) = (
            b.corner[1],
            b.corner[2],
            b.emanating[0],
            b.emanating[1],
            b.emanating[2],
        );
        let overlap = ((x_i + e_k).min(y_i + f_l) - x_i.max(y_i)).max(0);
        let diagonal = i64::from(self.get(e) == -1);
        let crossings = [
            x_k,
            y_l,
            e_i,
            e_j,
            f_i,
            f_j,
            diagonal,
            (x_i - y_i - f_l).max(0),
            (y_i - x_i - e_k).max(0),
        ]
        .iter()
        .try_fold(0i64, |s, &v| s.checked_add(v))
        .ok_or(NormalError::Overflow(e))?;
        match overlap {
            0 => Ok(crossings),
            1 if crossings == 0 => Ok(-1),
            1 => Err(NormalError::Inconsistent {
                edge: e,
                reason: "the new diagonal is an input edge but would be crossed",
            }),
            _ => Err(NormalError::Inconsistent {
                edge: e,
                reason: "two parallel input arcs would join k and l",
            }),
        }
    }

    /// Flip `e` in `mesh` and update the coordinates (B105). On error nothing changes.
    pub fn flip(&mut self, mesh: &mut Mesh, e: Edge) -> Result<(), NormalError> {
        let n = self.flipped_coordinate(mesh, e)?;
        mesh.flip(e)?;
        self.n[e.idx()] = n;
        Ok(())
    }
}

/// Replay `flips` from `input` (= `T_in`) and return the flipped mesh `T` with the normal
/// coordinates of `T_in` relative to it (B105). Purely combinatorial: valid for any flip
/// kind.
pub fn replay_normal_coordinates(
    input: &Mesh,
    flips: &[Edge],
) -> Result<(Mesh, NormalCoordinates), NormalError> {
    let mut mesh = input.clone();
    let mut n = NormalCoordinates::of_input(&mesh);
    for &e in flips {
        n.flip(&mut mesh, e)?;
    }
    Ok((mesh, n))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::builders;
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    #[test]
    fn b105_face_arcs_reconstruct_the_counts() {
        for a in 0..6i64 {
            for b in 0..6 {
                for c in 0..6 {
                    let Some(f) = face_arcs([a, b, c]) else {
                        assert_eq!((a + b + c) % 2, 1, "{a} {b} {c}");
                        continue;
                    };
                    let [x0, x1, x2] = f.corner;
                    let [e0, e1, e2] = f.emanating;
                    assert!(f.corner.iter().chain(&f.emanating).all(|&v| v >= 0));
                    assert!(f.emanating.iter().filter(|&&v| v > 0).count() <= 1);
                    assert_eq!((x0 + x1 + e2, x1 + x2 + e0, x2 + x0 + e1), (a, b, c));
                }
            }
        }
    }

    /// Random flips of a closed surface and back: every face stays decomposable and the
    /// flips undone in reverse order give back `T_in` (all `−1`).
    fn there_and_back(base: &Mesh, n_flips: usize, seed: u64) {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let mut m = base.clone();
        let mut n = NormalCoordinates::of_input(&m);
        let mut done = Vec::new();
        for _ in 0..n_flips {
            let e = Edge(rng.gen_range(0..m.n_edges() as u32));
            match n.flip(&mut m, e) {
                Ok(()) => done.push(e),
                Err(NormalError::Flip(_)) => continue,
                Err(err) => panic!("{err}"),
            }
            n.check(&m).unwrap();
            assert!(n.values().iter().all(|&v| v != 0), "{:?}", n.values());
        }
        assert!(!done.is_empty());
        for &e in done.iter().rev() {
            n.flip(&mut m, e).unwrap();
        }
        assert!(n.values().iter().all(|&v| v == -1), "{:?}", n.values());
    }

    #[test]
    fn b105_one_vertex_torus_there_and_back() {
        for seed in 0..20 {
            there_and_back(&builders::one_vertex_torus(), 12, seed);
        }
    }

    #[test]
    fn b105_genus_two_and_flat_torus_there_and_back() {
        let g2 = builders::genus(2).unwrap();
        let t = builders::flat_torus(3, 3).unwrap().mesh;
        for seed in 0..10 {
            there_and_back(&g2, 40, seed);
            there_and_back(&t, 60, seed);
        }
    }

    #[test]
    fn b105_one_flip_on_the_one_vertex_torus_crosses_once() {
        let mut m = builders::one_vertex_torus();
        let mut n = NormalCoordinates::of_input(&m);
        n.flip(&mut m, Edge(0)).unwrap();
        assert_eq!(n.values().iter().filter(|&&v| v == 1).count(), 1);
        assert_eq!(n.get(Edge(0)), 1);
    }

    #[test]
    fn b105_negative_controls() {
        let m = builders::flat_torus(3, 3).unwrap().mesh;
        let mut t = m.clone();
        let mut n = NormalCoordinates::of_input(&t);
        let e = t.edges().next().unwrap();
        n.flip(&mut t, e).unwrap();
        // One coordinate altered by one: locally consistent (two arcs from one corner),
        // but flipping back would join k and l by two parallel input arcs.
        let mut bad = n.values().to_vec();
        bad[e.idx()] += 1;
        let mut nb = NormalCoordinates::from_values(&t, bad).unwrap();
        assert!(matches!(
            nb.flip(&mut t.clone(), e),
            Err(NormalError::Inconsistent { .. })
        ));
        // The two other sides of a face of the flipped edge marked crossed once: the
        // face reads (1, 1, 1), odd parity.
        let mut bad = n.values().to_vec();
        let h = t.next(e.side(0));
        bad[h.edge().idx()] = 1;
        bad[t.next(h).edge().idx()] = 1;
        assert!(matches!(
            NormalCoordinates::from_values(&t, bad),
            Err(NormalError::Parity { .. })
        ));
        let mut bad = n.values().to_vec();
        bad[0] = -2;
        assert!(NormalCoordinates::from_values(&t, bad).is_err());
        assert!(matches!(
            NormalCoordinates::from_values(&t, vec![-1; 2]),
            Err(NormalError::Count { .. })
        ));
        // A boundary flip is refused and changes nothing.
        let mut d = Mesh::from_faces(4, &[[0, 1, 2], [0, 2, 3]]).unwrap();
        let mut nd = NormalCoordinates::of_input(&d);
        let b = d.edges().find(|&e| d.is_boundary_edge(e)).unwrap();
        let before = (d.clone(), nd.clone());
        assert!(matches!(
            nd.flip(&mut d, b),
            Err(NormalError::Flip(FlipError::Boundary(_)))
        ));
        assert_eq!((d, nd), before);
    }
}
