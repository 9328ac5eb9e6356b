//! The crossings of the input edges with the current triangulation `T`, tracked through
//! Euclidean flips in the **input metric** (proof: B108) and through Ptolemy flips in the
//! **hyperbolic (Klein) picture** of the base metric (proof: B111).
//!
//! **Euclidean flips.** Every edge `g` of `T_in` is a geodesic of the input's flat cone
//! metric. A flip of `ij` (faces `ijk`, `jil`) whose quadrilateral is strictly convex in the
//! input metric replaces `ij` by the straight diagonal `kl`, again a geodesic. Inside the
//! quadrilateral laid out in the plane (`i = (0, 0)`, `j = (ℓ_ij, 0)`, `k` above, `l` below)
//! each piece of `g` is the straight segment `AB` between its ends (corners or points of the
//! four sides), so the new crossing with `kl` is
//!
//! ```text
//! μ = (K − A) × (L − K) / ((B − A) × (L − K)),   τ = (K − A) × (B − A) / ((B − A) × (L − K)),
//! Y = A + μ (B − A) = K + τ (L − K),             s_Y = s_A + μ (s_B − s_A),
//! ```
//!
//! with `s` the parameter along `g` (affine along a straight segment). *Which* pieces cross
//! `kl` is combinatorial (their ends lie on opposite sides of `kl`: `{ki, i, il}` against
//! `{lj, j, jk}`, B105), never decided by rounding; `μ, τ ∈ (0, 1)` is then checked, and a
//! value outside says the quadrilateral is not convex in the input metric: the typed error
//! [`TrackError::NotStraight`].
//!
//! **Ptolemy flips** ([`TrackedOverlay::flip_ptolemy`]). The lengths are then the base
//! metric `λ` (Penner coordinates), carried by `λ_kl = (λ_ki λ_lj + λ_jk λ_il)/λ_ij`, and a
//! crossing is stored at its Euclidean parameter in the base metric of its edge. Each
//! Euclidean triangle, seen in its circumdisk as a Klein model, is an ideal hyperbolic
//! triangle; the quadrilateral is laid out on the unit circle (`i = (−1, 0)`, `j = (1, 0)`,
//! `k = (0, 1)`, `l = (cos φ, −sin φ)`, `tan(φ/2) = e^σ`, `σ = log(λ_ki λ_lj/(λ_jk λ_il))`),
//! where it is always strictly convex and the Ptolemy flip is the chord `kl`. A point of
//! barycentric coordinates `β` in a triangle of the base metric goes to the point of
//! barycentric coordinates `∝ w_a β_a`, `w_a = (μ_a/λ_a)²` (`μ_a, λ_a` the Klein and base
//! lengths of the side opposite corner `a`): the projective map of the triangle onto its
//! Klein picture, which matches the symmedian feet (the feet of the hyperbolic
//! perpendiculars). A run of pieces is a polyline `A, [Y on ij], B` there, straight in each
//! old triangle; its crossing with `kl` is mapped back to the base metric of the new
//! triangles the same way. Which runs cross `kl` stays combinatorial (B105). The position
//! `s` along the input edge is affine in the base metric of the old triangle holding the
//! crossed piece: the input's flat arc length while that piece is still a piece of the
//! input edge in the input metric (every piece at `T₀`), a **parametrization choice**
//! afterwards, since each new piece is the straight chord between its ends (isotopic to
//! the bent polyline with its ends fixed). [`TrackedOverlay::rescale`] finally moves every
//! crossing to the conformally scaled metric `e^{(u_i+u_j)/2} λ_ij` (same hyperbolic point:
//! `t/(1 − t)` times `e^{u_tail − u_tip}`).
//!
//! Positions are binary64; the written output is checked exactly afterwards (B109, B110).

use crate::algorithms::flips::FlipKind;
use crate::geometry::unfold::third_corner;
use crate::mesh::{Edge, Face, FlipError, HalfEdge, Mesh};

/// A crossing of an input edge `g` with an edge of `T`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Crossing {
    /// The half-edge of the crossed edge of `T` whose face holds the piece of `g` after the
    /// crossing (in the direction of `g`'s half-edge `2g`).
    pub h: HalfEdge,
    /// The position along `h`, from `tail(h)`, in `(0, 1)`.
    pub t: f64,
    /// The position along `g`, from the tail of `2g`, in `(0, 1)`.
    pub s: f64,
}

/// An input edge `g` relative to `T`: its crossings in order from the tail of `2g`, or the
/// edge of `T` it coincides with.
#[derive(Clone, Debug, PartialEq)]
pub struct InputEdgePath {
    /// The crossings, ordered along `g`.
    pub crossings: Vec<Crossing>,
    /// With no crossings: the half-edge of `T` that is `2g` (same ends, same direction).
    pub along: Option<HalfEdge>,
    /// The corner of `T` (the half-edge out of `g`'s tail in that face) holding the first
    /// piece; meaningful when `along` is `None`.
    pub start: HalfEdge,
    /// The corner of `T` at `g`'s tip holding the last piece; meaningful when `along` is
    /// `None`.
    pub end: HalfEdge,
}

/// Why the crossings could not be tracked.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum TrackError {
    /// The flip itself is refused by the mesh.
    #[error(transparent)]
    Flip(#[from] FlipError),
    /// The lengths are not one positive finite number per edge.
    #[error("the input metric needs one positive finite length per edge")]
    Lengths,
    /// The log scale factors are not one finite number per vertex.
    #[error("the log scale factors need one finite number per vertex")]
    ScaleFactors,
    /// A Euclidean flip whose new diagonal is not a straight segment of the input metric
    /// across its quadrilateral (the quadrilateral is not strictly convex in the input
    /// metric, or rounding at a near-degenerate one): positions are not computed (B108).
    /// Ptolemy flips never give it: their quadrilateral is convex in the Klein picture
    /// (B111).
    #[error("flip {flip} (edge {edge}): the new diagonal is not a geodesic of the input metric (its quadrilateral is not convex there)")]
    NotStraight {
        /// The flip's index in the sequence.
        flip: usize,
        /// The flipped edge.
        edge: Edge,
    },
    /// The pieces are not in minimal position or not the pieces of a triangulation.
    #[error("flip {flip} (edge {edge}): {reason}")]
    Inconsistent {
        /// The flip's index in the sequence.
        flip: usize,
        /// The flipped edge.
        edge: Edge,
        /// What went wrong.
        reason: &'static str,
    },
}

/// The input edges tracked through flips of `T` (module documentation; proof: B108).
#[derive(Clone, Debug)]
pub struct TrackedOverlay {
    /// The current triangulation `T`.
    pub mesh: Mesh,
    /// The lengths of `T`'s edges in the metric the crossings' parameters `t` refer to: the
    /// input metric through Euclidean flips, the base metric `λ` carried by Ptolemy flips
    /// after them, the scaled metric after [`TrackedOverlay::rescale`].
    pub lengths: Vec<f64>,
    /// Per input edge, its path through `T`.
    pub paths: Vec<InputEdgePath>,
    /// Per edge of `T`, the input edges crossing it (with repetition).
    users: Vec<Vec<u32>>,
    /// Per edge of `T`, the input edge it coincides with.
    along_of: Vec<Option<u32>>,
    flips: usize,
}

/// A place on the boundary of the flipped quadrilateral.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Place {
    /// A corner `i, j, k, l` (0..4).
    Corner(usize),
    /// A point of a side `jk, ki, il, lj` (0..4) at a parameter along it.
    Side(usize, f64),
}

const I: usize = 0;
const J: usize = 1;
const K: usize = 2;
const L: usize = 3;
/// The sides `jk, ki, il, lj` as (tail, tip) corners.
const SIDES: [(usize, usize); 4] = [(J, K), (K, I), (I, L), (L, J)];

impl Place {
    /// `−1` on the side of `i`, `+1` on the side of `j`, `0` on `kl`.
    fn side_of_kl(self) -> i32 {
        match self {
            Place::Corner(I) | Place::Side(1 | 2, _) => -1,
            Place::Corner(J) | Place::Side(0 | 3, _) => 1,
            _ => 0,
        }
    }
}

fn lerp(a: [f64; 2], b: [f64; 2], t: f64) -> [f64; 2] {
    [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]
}

fn cross(a: [f64; 2], b: [f64; 2]) -> f64 {
    a[0] * b[1] - a[1] * b[0]
}

fn sub(a: [f64; 2], b: [f64; 2]) -> [f64; 2] {
    [a[0] - b[0], a[1] - b[1]]
}

impl TrackedOverlay {
    /// `T = T_in` with its input-metric `lengths` (per edge): every input edge lies along
    /// itself.
    pub fn of_input(mesh: &Mesh, lengths: &[f64]) -> Result<TrackedOverlay, TrackError> {
        if lengths.len() != mesh.n_edges() || lengths.iter().any(|&x| !(x.is_finite() && x > 0.0)) {
            return Err(TrackError::Lengths);
        }
        let paths = mesh
            .edges()
            .map(|e| InputEdgePath {
                crossings: Vec::new(),
                along: Some(e.side(0)),
                start: e.side(0),
                end: e.side(1),
            })
            .collect();
        Ok(TrackedOverlay {
            mesh: mesh.clone(),
            lengths: lengths.to_vec(),
            paths,
            users: vec![Vec::new(); mesh.n_edges()],
            along_of: (0..mesh.n_edges() as u32).map(Some).collect(),
            flips: 0,
        })
    }

    /// The input edge that edge `e` of `T` coincides with.
    pub fn along_of(&self, e: Edge) -> Option<u32> {
        self.along_of.get(e.idx()).copied().flatten()
    }

    /// The number of crossings on each edge of `T`, `−1` for an edge that is an input edge:
    /// the normal coordinates, counted from the tracked geometry (B105 gives them
    /// independently).
    pub fn crossing_counts(&self) -> Vec<i64> {
        let mut n = vec![0i64; self.mesh.n_edges()];
        for p in &self.paths {
            for c in &p.crossings {
                n[c.h.edge().idx()] += 1;
            }
        }
        for (e, a) in self.along_of.iter().enumerate() {
            if a.is_some() {
                n[e] = -1;
            }
        }
        n
    }

    /// The face of `T` holding piece `m` of input edge `g` (between its nodes `m` and
    /// `m + 1`, node 0 the tail, the crossings, the tip last); `None` along an edge.
    pub fn piece_face(&self, g: usize, m: usize) -> Option<Face> {
        let c = &self.paths[g].crossings;
        if let Some(x) = c.get(m) {
            self.mesh.face(x.h.twin())
        } else {
            self.mesh.face(c.get(m.checked_sub(1)?)?.h)
        }
    }

    /// Flip `e` of `T` by a Euclidean flip, keeping every input edge's crossings (module
    /// documentation; B108). On error nothing changes.
    pub fn flip(&mut self, e: Edge) -> Result<(), TrackError> {
        self.flip_of_kind(e, FlipKind::Euclidean)
    }

    /// Flip `e` of `T` by a Ptolemy flip of the base metric, keeping every input edge's
    /// crossings through the Klein picture (module documentation; B111). On error nothing
    /// changes.
    pub fn flip_ptolemy(&mut self, e: Edge) -> Result<(), TrackError> {
        self.flip_of_kind(e, FlipKind::Ptolemy)
    }

    /// Move every crossing from the base metric `λ` to the conformally equivalent metric
    /// `e^{(u_i+u_j)/2} λ_ij` (the same point of the hyperbolic surface, B111 part 2): on a
    /// half-edge `a → b`, `t/(1 − t)` is multiplied by `e^{u_a − u_b}`; the lengths are
    /// scaled. `u` must have one finite entry per vertex of `T`, else
    /// [`TrackError::ScaleFactors`] and nothing changes.
    pub fn rescale(&mut self, u: &[f64]) -> Result<(), TrackError> {
        let m = &self.mesh;
        if u.len() != m.n_vertices() || u.iter().any(|x| !x.is_finite()) {
            return Err(TrackError::ScaleFactors);
        }
        for p in &mut self.paths {
            for c in &mut p.crossings {
                c.t = rescaled_parameter(c.t, u[m.tail(c.h).idx()] - u[m.tip(c.h).idx()]);
            }
        }
        for e in m.edges() {
            let h = e.side(0);
            self.lengths[e.idx()] *= (0.5 * (u[m.tail(h).idx()] + u[m.tip(h).idx()])).exp();
        }
        Ok(())
    }

    /// Flip `e` of `T` by a flip of `kind`, keeping every input edge's crossings.
    fn flip_of_kind(&mut self, e: Edge, kind: FlipKind) -> Result<(), TrackError> {
        let q = self.quad(e, kind)?;
        let sides = q.side_he.map(HalfEdge::edge);
        let mut touched: Vec<u32> = std::iter::once(e)
            .chain(sides)
            .flat_map(|x| self.users[x.idx()].iter().copied())
            .chain(self.along_of[e.idx()])
            .collect();
        touched.sort_unstable();
        touched.dedup();
        let mut rebuilt = Vec::with_capacity(touched.len());
        let (mut new_users, mut new_along) = (Vec::new(), None);
        for g in touched {
            let Some(r) = self.rebuild(&q, g)? else {
                continue;
            };
            if r.crosses_kl {
                new_users.push(g);
            }
            if r.along_kl {
                new_along = Some(g);
            }
            rebuilt.push((g, r.path));
        }
        self.mesh.flip(e)?;
        self.lengths[e.idx()] = match kind {
            FlipKind::Euclidean => {
                let (pk, pl) = (q.pos[K], q.pos[L]);
                (pk[0] - pl[0]).hypot(pk[1] - pl[1])
            }
            FlipKind::Ptolemy => {
                let [ij, jk, ki, il, lj] = q.lam;
                ki * (lj / ij) + il * (jk / ij)
            }
        };
        for (g, path) in rebuilt {
            self.paths[g as usize] = path;
        }
        self.users[e.idx()] = new_users;
        self.along_of[e.idx()] = new_along;
        self.flips += 1;
        Ok(())
    }

    /// The quadrilateral of `e`, laid out with the current lengths, and for a Ptolemy flip
    /// its Klein picture.
    fn quad(&self, e: Edge, kind: FlipKind) -> Result<Quad, TrackError> {
        let m = &self.mesh;
        if e.idx() >= m.n_edges() {
            return Err(FlipError::OutOfRange(e).into());
        }
        let (h0, h1) = (e.side(0), e.side(1));
        let (f0, f1) = match (m.face(h0), m.face(h1)) {
            (Some(a), Some(b)) if a != b => (a, b),
            (Some(_), Some(_)) => return Err(FlipError::SameFace(e).into()),
            _ => return Err(FlipError::Boundary(e).into()),
        };
        let (h_jk, t_il) = (m.next(h0), m.next(h1));
        let (h_ki, t_lj) = (m.next(h_jk), m.next(t_il));
        let len = |h: HalfEdge| self.lengths[h.edge().idx()];
        let pi = [0.0, 0.0];
        let pj = [len(h0), 0.0];
        let pk = third_corner(pi, pj, len(h_ki), len(h_jk));
        let pl = third_corner(pj, pi, len(t_lj), len(t_il));
        let lam = [h0, h_jk, h_ki, t_il, t_lj].map(len);
        Ok(Quad {
            e,
            flip: self.flips,
            faces: [f0, f1],
            side_he: [h_jk, h_ki, t_il, t_lj],
            pos: [pi, pj, pk, pl],
            lam,
            klein: (kind == FlipKind::Ptolemy).then(|| Klein::of(lam)),
        })
    }

    /// The path of input edge `g` after the flip of `q.e`, and whether it crosses or is the
    /// new diagonal; `None` when `g` lies along a side of the quadrilateral.
    fn rebuild(&self, q: &Quad, g: u32) -> Result<Option<Rebuilt>, TrackError> {
        let path = &self.paths[g as usize];
        let mut out = path.clone();
        let (h0, h1) = (q.e.side(0), q.e.side(1));
        if let Some(a) = path.along {
            if a != h0 && a != h1 {
                return Ok(None);
            }
            // g is the diagonal ij itself: one run from corner to corner.
            let (ca, cb) = if a == h0 { (I, J) } else { (J, I) };
            let (ya, y) =
                q.cross_kl((Place::Corner(ca), 0.0), None, (Place::Corner(cb), 1.0), 0)?;
            out.crossings = vec![y];
            out.along = None;
            out.start = q.corner_in(ca, ya);
            out.end = q.corner_in(cb, -ya);
            return Ok(Some(Rebuilt {
                path: out,
                crosses_kl: true,
                along_kl: false,
            }));
        }
        let n = path.crossings.len();
        let in_quad = |p: usize| {
            self.piece_face(g as usize, p)
                .is_some_and(|f| q.faces.contains(&f))
        };
        let mut r = Rebuilt {
            path: out,
            crosses_kl: false,
            along_kl: false,
        };
        let mut crossings = Vec::with_capacity(n + 1);
        let mut p = 0;
        while p <= n {
            if !in_quad(p) {
                if p < n {
                    crossings.push(path.crossings[p]);
                }
                p += 1;
                continue;
            }
            // A run of pieces in the quadrilateral, joined at crossings of e: from node
            // `p` to node `end + 1`.
            let mut end = p;
            while end < n && path.crossings[end].h.edge() == q.e {
                end += 1;
            }
            if end - p > 1 {
                return Err(q.bad("an input edge crosses the flipped edge twice in a row (not in minimal position)"));
            }
            let a = if p == 0 {
                (Place::Corner(q.corner_of(path.start)?), 0.0)
            } else {
                let x = path.crossings[p - 1];
                (Place::Side(q.side_of(x.h)?, x.t), x.s)
            };
            let b = if end == n {
                (Place::Corner(q.corner_of(path.end)?), 1.0)
            } else {
                let x = path.crossings[end];
                (Place::Side(q.side_of(x.h.twin())?, 1.0 - x.t), x.s)
            };
            let (sa, sb) = (a.0.side_of_kl(), b.0.side_of_kl());
            let (ta, tb) = if sa * sb < 0 {
                // The crossing of ij inside the run (parameter from i, s), and the old face
                // holding the run's first piece.
                let y = (end > p).then(|| {
                    let x = path.crossings[p];
                    let t = if x.h == h0 { x.t } else { 1.0 - x.t };
                    (t, x.s)
                });
                let first = usize::from(self.piece_face(g as usize, p) != Some(q.faces[0]));
                let (ya, y) = q.cross_kl(a, y, b, first)?;
                crossings.push(y);
                r.crosses_kl = true;
                (ya, -ya)
            } else if sa == 0 && sb == 0 {
                if p != 0 || end != n || a.0 == b.0 {
                    return Err(q.bad("an input arc from k to l is not a whole input edge"));
                }
                r.path.along = Some(if a.0 == Place::Corner(K) { h1 } else { h0 });
                r.along_kl = true;
                (0, 0)
            } else {
                (sa + sb, sa + sb)
            };
            if let (0, Place::Corner(c)) = (p, a.0) {
                r.path.start = q.corner_in(c, ta);
            }
            if let (true, Place::Corner(c)) = (end == n, b.0) {
                r.path.end = q.corner_in(c, tb);
            }
            if end < n {
                crossings.push(path.crossings[end]);
            }
            p = end + 1;
        }
        r.path.crossings = crossings;
        Ok(Some(r))
    }
}

/// The quadrilateral of a flip: the flipped edge, the flip's index, its two faces, the
/// half-edges of its sides `jk, ki, il, lj` facing inward, the layout of `i, j, k, l` in
/// the current metric, the current lengths of `ij, jk, ki, il, lj`, and for a Ptolemy flip
/// the Klein picture.
struct Quad {
    e: Edge,
    flip: usize,
    faces: [Face; 2],
    side_he: [HalfEdge; 4],
    pos: [[f64; 2]; 4],
    lam: [f64; 5],
    klein: Option<Klein>,
}

/// The Klein picture of a quadrilateral (B111): the corners `i, j, k, l` on the unit
/// circle, and per old face (`ijk`, `jil`) the weights `w_a = (μ_a/λ_a)²` of its corners
/// (`μ_a`, `λ_a`: the Klein and base lengths of the side opposite `a`; `0` for the corner
/// not in the face), and the same ratio for the new diagonal's ends in face `kil`:
/// `w_k/w_l = (μ_il/λ_il)²/(μ_ki/λ_ki)²`.
struct Klein {
    pos: [[f64; 2]; 4],
    w: [[f64; 4]; 2],
    w_kl: f64,
}

impl Klein {
    /// The Klein picture of a quadrilateral with base lengths `ij, jk, ki, il, lj`:
    /// `tan(φ/2) = ρ = e^σ = λ_ki λ_lj / (λ_jk λ_il)`, so `cos φ = (1 − ρ²)/(1 + ρ²)`,
    /// `sin φ = 2ρ/(1 + ρ²)`, and the chords `μ_ij = 2`, `μ_jk = μ_ki = √2`,
    /// `μ_il² = 4/(1 + ρ²)`, `μ_lj² = 4ρ²/(1 + ρ²)`.
    fn of([ij, jk, ki, il, lj]: [f64; 5]) -> Klein {
        let rho = (ki / jk) * (lj / il);
        let d = 1.0 + rho * rho;
        let pos = [
            [-1.0, 0.0],
            [1.0, 0.0],
            [0.0, 1.0],
            [(1.0 - rho * rho) / d, -2.0 * rho / d],
        ];
        let (m_ij, m_side) = (4.0, 2.0);
        let (m_il, m_lj) = (4.0 / d, 4.0 * rho * rho / d);
        let sq = |x: f64| x * x;
        let w = [
            [m_side / sq(jk), m_side / sq(ki), m_ij / sq(ij), 0.0],
            [m_lj / sq(lj), m_il / sq(il), 0.0, m_ij / sq(ij)],
        ];
        let w_kl = (m_il / sq(il)) / (m_side / sq(ki));
        Klein { pos, w, w_kl }
    }

    /// The Klein point and the normalizer `W = Σ w_a β_a` of the point of barycentric
    /// coordinates `β` (pairs of corner and coordinate) in old face `face`.
    fn point(&self, face: usize, beta: [(usize, f64); 2]) -> ([f64; 2], f64) {
        let w = &self.w[face];
        let big_w: f64 = beta.iter().map(|&(c, b)| w[c] * b).sum();
        let mut p = [0.0; 2];
        for &(c, b) in &beta {
            p[0] += w[c] * b * self.pos[c][0];
            p[1] += w[c] * b * self.pos[c][1];
        }
        ([p[0] / big_w, p[1] / big_w], big_w)
    }
}

/// `t` on a half-edge `a → b` moved to the metric scaled by `e^{(u_a+u_b)/2}` on every
/// edge: `t/(1 − t)` times `e^{d}`, `d = u_a − u_b` (B111 part 2).
pub fn rescaled_parameter(t: f64, d: f64) -> f64 {
    let x = d.exp();
    t * x / ((1.0 - t) + t * x)
}

/// The barycentric coordinates of a place of the quadrilateral (pairs of corner and
/// coordinate).
fn barycentric(p: Place) -> [(usize, f64); 2] {
    match p {
        Place::Corner(c) => [(c, 1.0), (c, 0.0)],
        Place::Side(s, t) => [(SIDES[s].0, 1.0 - t), (SIDES[s].1, t)],
    }
}

/// An input edge's path rebuilt by a flip.
struct Rebuilt {
    path: InputEdgePath,
    crosses_kl: bool,
    along_kl: bool,
}

impl Quad {
    fn bad(&self, reason: &'static str) -> TrackError {
        TrackError::Inconsistent {
            flip: self.flip,
            edge: self.e,
            reason,
        }
    }

    /// The corner `i, j, k, l` of a corner half-edge of the faces before the flip.
    fn corner_of(&self, h: HalfEdge) -> Result<usize, TrackError> {
        let [h_jk, h_ki, t_il, t_lj] = self.side_he;
        match h {
            _ if h == self.e.side(0) || h == t_il => Ok(I),
            _ if h == self.e.side(1) || h == h_jk => Ok(J),
            _ if h == h_ki => Ok(K),
            _ if h == t_lj => Ok(L),
            _ => Err(self.bad("a piece's corner is not in the quadrilateral")),
        }
    }

    /// The side `jk, ki, il, lj` of an inward half-edge.
    fn side_of(&self, h: HalfEdge) -> Result<usize, TrackError> {
        self.side_he
            .iter()
            .position(|&x| x == h)
            .ok_or_else(|| self.bad("a piece crosses the flipped edge at its end"))
    }

    /// The corner half-edge of corner `c` in the new face on the side `toward` of `kl`
    /// (`< 0`: face A = (l→k, k→i, i→l); else face B = (k→l, l→j, j→k)).
    fn corner_in(&self, c: usize, toward: i32) -> HalfEdge {
        let [h_jk, h_ki, t_il, t_lj] = self.side_he;
        match (c, toward < 0) {
            (I, _) => t_il,
            (J, _) => h_jk,
            (K, true) => h_ki,
            (K, false) => self.e.side(1),
            (_, true) => self.e.side(0),
            (_, false) => t_lj,
        }
    }

    /// The crossing with `kl` of the run from `a` to `b` (places with their parameters along
    /// the input edge) through `y` (its crossing of `ij`: parameter from `i` and along the
    /// input edge), whose first piece lies in old face `first` (`0`: `ijk`), and which side
    /// of `kl` `a` lies on (`−1`: the side of `i`, face A after the flip). A Euclidean flip
    /// takes the straight segment `ab` of the input metric (B108), a Ptolemy flip the
    /// polyline in the Klein picture (B111).
    fn cross_kl(
        &self,
        a: (Place, f64),
        y: Option<(f64, f64)>,
        b: (Place, f64),
        first: usize,
    ) -> Result<(i32, Crossing), TrackError> {
        let (tau, s) = match &self.klein {
            None => self.cross_kl_flat(a, b)?,
            Some(k) => self.cross_kl_klein(k, a, y, b, first)?,
        };
        let side = a.0.side_of_kl();
        // The piece after the crossing lies towards b: face B (k→l) when a is on i's side,
        // face A (l→k) otherwise.
        let y = if side < 0 {
            Crossing {
                h: self.e.side(1),
                t: tau,
                s,
            }
        } else {
            Crossing {
                h: self.e.side(0),
                t: 1.0 - tau,
                s,
            }
        };
        Ok((side, y))
    }

    /// The crossing with `kl` (parameter from `k`, parameter along the input edge) in the
    /// Klein picture: the piece of the polyline `a, y, b` whose ends lie on both sides of
    /// `kl` (`y`'s side computed, `a`'s and `b`'s combinatorial), intersected with the
    /// chord `kl`, mapped back to the base metric of face `kil` (B111 part 4). `s` is affine
    /// along the piece in the base metric of its old face.
    fn cross_kl_klein(
        &self,
        kl: &Klein,
        a: (Place, f64),
        y: Option<(f64, f64)>,
        b: (Place, f64),
        first: usize,
    ) -> Result<(f64, f64), TrackError> {
        let (kk, ll) = (kl.pos[K], kl.pos[L]);
        let dir = sub(ll, kk);
        let ((pb, ps), (qb, qs), face) = match y {
            None => ((barycentric(a.0), a.1), (barycentric(b.0), b.1), first),
            Some((ty, sy)) => {
                let yb = [(I, 1.0 - ty), (J, ty)];
                let (yk, _) = kl.point(first, yb);
                let side_y = cross(dir, sub(yk, kk));
                let side_i = cross(dir, sub(kl.pos[I], kk));
                let a_side = f64::from(a.0.side_of_kl());
                // `y` strictly on `a`'s side of kl: the second piece crosses it.
                if side_y * side_i * -a_side > 0.0 {
                    ((yb, sy), (barycentric(b.0), b.1), 1 - first)
                } else {
                    ((barycentric(a.0), a.1), (yb, sy), first)
                }
            }
        };
        let (p, wp) = kl.point(face, pb);
        let (q, wq) = kl.point(face, qb);
        let d = sub(q, p);
        let den = cross(d, dir);
        let mu = (cross(sub(kk, p), dir) / den).clamp(0.0, 1.0);
        let tau = cross(sub(kk, p), d) / den;
        if !(tau > 0.0 && tau < 1.0) {
            return Err(self.bad("the crossing with the new diagonal fell outside it in the Klein picture (rounding)"));
        }
        // Back to the base metric: along the piece (old face), and along kl (face kil).
        let mu_base = mu * wp / ((1.0 - mu) * wq + mu * wp);
        let tau_base = tau * kl.w_kl / ((1.0 - tau) + tau * kl.w_kl);
        Ok((tau_base, ps + mu_base * (qs - ps)))
    }

    /// The crossing with `kl` (parameter from `k`, parameter along the input edge) of the
    /// straight segment from `a` to `b` in the input metric (B108).
    fn cross_kl_flat(&self, a: (Place, f64), b: (Place, f64)) -> Result<(f64, f64), TrackError> {
        let pos = self.pos;
        let at = |p: Place| match p {
            Place::Corner(c) => pos[c],
            Place::Side(s, t) => lerp(pos[SIDES[s].0], pos[SIDES[s].1], t),
        };
        let (pa, pb) = (at(a.0), at(b.0));
        let (d, kl) = (sub(pb, pa), sub(pos[L], pos[K]));
        let den = cross(d, kl);
        let mu = cross(sub(pos[K], pa), kl) / den;
        let tau = cross(sub(pos[K], pa), d) / den;
        if !(mu > 0.0 && mu < 1.0 && tau > 0.0 && tau < 1.0) {
            return Err(TrackError::NotStraight {
                flip: self.flip,
                edge: self.e,
            });
        }
        Ok((tau, a.1 + mu * (b.1 - a.1)))
    }
}

/// Track the input edges of `input` (input-metric `lengths`) through the Euclidean `flips`
/// ([`TrackedOverlay::flip`]).
pub fn track_flips(
    input: &Mesh,
    lengths: &[f64],
    flips: &[Edge],
) -> Result<TrackedOverlay, TrackError> {
    let mut o = TrackedOverlay::of_input(input, lengths)?;
    for &e in flips {
        o.flip(e)?;
    }
    Ok(o)
}

/// Track the input edges of `input` (input-metric `lengths`) through the Euclidean flips
/// `euclidean` (to `T₀`, B108), then the Ptolemy flips `ptolemy` of the base metric (B111),
/// and move the crossings to the metric scaled by `e^{(u_i+u_j)/2}` when `u` is given
/// ([`TrackedOverlay::rescale`]). Flip indices in errors count both phases.
pub fn track_euclidean_then_ptolemy(
    input: &Mesh,
    lengths: &[f64],
    euclidean: &[Edge],
    ptolemy: &[Edge],
    u: Option<&[f64]>,
) -> Result<TrackedOverlay, TrackError> {
    let mut o = track_flips(input, lengths, euclidean)?;
    for &e in ptolemy {
        o.flip_ptolemy(e)?;
    }
    if let Some(u) = u {
        o.rescale(u)?;
    }
    Ok(o)
}
