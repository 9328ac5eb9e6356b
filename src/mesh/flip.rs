//! The combinatorial edge flip: index surgery only.

use super::{Edge, Mesh};

/// Why an edge cannot be flipped.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum FlipError {
    /// The edge lies on the boundary.
    #[error("edge {0} is a boundary edge")]
    Boundary(Edge),
    /// Both sides of the edge belong to one face (a self-folded triangle around a
    /// degree-1 vertex).
    #[error("edge {0} has the same face on both sides")]
    SameFace(Edge),
    /// No such edge.
    #[error("edge {0} does not exist")]
    OutOfRange(Edge),
}

impl Mesh {
    /// Flip edge `e` = ij between faces `ijk` and `jil` into edge `kl`, between faces
    /// `lki` and `klj` (docs/catalogue.md §5). Half-edge `2e` becomes `l→k`, `2e+1` becomes `k→l`.
    ///
    /// ```text
    ///        k                 k
    ///       / \               /|\
    ///      i---j     →       i | j
    ///       \ /               \|/
    ///        l                 l
    /// ```
    ///
    /// V, E and F are unchanged, hence χ (T02, `proofs/T02-flips-keep-euler-characteristic.md`).
    /// Flipping the same edge twice gives back the original complex up to one relabeling:
    /// the two half-edges of `e` swap (`2e` ↔ `2e+1`), the two faces swap ids, and each
    /// face may start at a different half-edge. Four flips restore `next`, `tail` and
    /// `face` exactly.
    pub fn flip(&mut self, e: Edge) -> Result<(), FlipError> {
        if e.idx() >= self.n_edges() {
            return Err(FlipError::OutOfRange(e));
        }
        let h = e.side(0);
        let t = e.side(1);
        let (Some(fa), Some(fb)) = (self.face(h), self.face(t)) else {
            return Err(FlipError::Boundary(e));
        };
        if fa == fb {
            return Err(FlipError::SameFace(e));
        }
        let h_jk = self.next(h);
        let h_ki = self.next(h_jk);
        let t_il = self.next(t);
        let t_lj = self.next(t_il);
        let k = self.tail(h_ki);
        let l = self.tail(t_lj);
        // face A = (h: l→k, h_ki: k→i, t_il: i→l); face B = (t: k→l, t_lj: l→j, h_jk: j→k)
        self.next[h.idx()] = h_ki;
        self.next[h_ki.idx()] = t_il;
        self.next[t_il.idx()] = h;
        self.next[t.idx()] = t_lj;
        self.next[t_lj.idx()] = h_jk;
        self.next[h_jk.idx()] = t;
        self.tail[h.idx()] = l;
        self.tail[t.idx()] = k;
        self.face[t_il.idx()] = fa.0;
        self.face[h_jk.idx()] = fb.0;
        self.face_halfedge[fa.idx()] = h;
        self.face_halfedge[fb.idx()] = t;
        // i and j lose the outgoing half-edges h and t; i keeps i→l, j keeps j→k.
        let (i, j) = (self.tail(t_il), self.tail(h_jk));
        if self.out[i.idx()] == h {
            self.out[i.idx()] = t_il;
        }
        if self.out[j.idx()] == t {
            self.out[j.idx()] = h_jk;
        }
        Ok(())
    }
}
