//! Connected components of a mesh (by edges), each with a grounded vertex: the smallest
//! vertex index of the component. Newton fixes `u` there (the energy is invariant under
//! adding a constant to `u` on one closed component, docs/catalogue.md §7).

use crate::mesh::Mesh;

/// The vertex components of a mesh.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Components {
    /// Component index per vertex.
    pub of_vertex: Vec<usize>,
    /// The smallest vertex of each component (its grounded vertex).
    pub roots: Vec<usize>,
}

/// The representative of `x` in the union–find forest `p` (with path halving).
fn find(p: &mut [usize], mut x: usize) -> usize {
    while p[x] != x {
        p[x] = p[p[x]];
        x = p[x];
    }
    x
}

impl Components {
    /// The components of `mesh`, numbered in the order of their smallest vertex.
    pub fn of(mesh: &Mesh) -> Components {
        let n = mesh.n_vertices();
        let mut parent: Vec<usize> = (0..n).collect();
        for e in mesh.edges() {
            let h = e.halfedge();
            let (a, b) = (mesh.tail(h).idx(), mesh.tip(h).idx());
            let (ra, rb) = (find(&mut parent, a), find(&mut parent, b));
            if ra != rb {
                // Keep the smaller index as the representative.
                let (lo, hi) = if ra < rb { (ra, rb) } else { (rb, ra) };
                parent[hi] = lo;
            }
        }
        let mut index = vec![usize::MAX; n];
        let mut roots = Vec::new();
        let mut of_vertex = vec![0; n];
        for (v, slot) in of_vertex.iter_mut().enumerate() {
            let r = find(&mut parent, v);
            if index[r] == usize::MAX {
                index[r] = roots.len();
                roots.push(r);
            }
            *slot = index[r];
        }
        Components { of_vertex, roots }
    }

    /// The vertices of component `c`.
    pub fn vertices_of(&self, c: usize) -> impl Iterator<Item = usize> + '_ {
        self.of_vertex
            .iter()
            .enumerate()
            .filter(move |&(_, &k)| k == c)
            .map(|(v, _)| v)
    }

    /// Whether `v` is a grounded vertex.
    pub fn is_root(&self, v: usize) -> bool {
        self.roots[self.of_vertex[v]] == v
    }

    /// `χ = V − E + F` of component `c`.
    pub fn euler_characteristic(&self, mesh: &Mesh, c: usize) -> i64 {
        let v = self.of_vertex.iter().filter(|&&k| k == c).count() as i64;
        let e = mesh
            .edges()
            .filter(|e| self.of_vertex[mesh.tail(e.halfedge()).idx()] == c)
            .count() as i64;
        let f = mesh
            .faces()
            .filter(|&f| self.of_vertex[mesh.face_vertices(f)[0].idx()] == c)
            .count() as i64;
        v - e + f
    }

    /// The free (non-grounded) vertices in order and, per vertex, its index among them.
    pub fn free_index(&self) -> (Vec<usize>, Vec<Option<usize>>) {
        let mut free = Vec::new();
        let mut idx = vec![None; self.of_vertex.len()];
        for (v, slot) in idx.iter_mut().enumerate() {
            if !self.is_root(v) {
                *slot = Some(free.len());
                free.push(v);
            }
        }
        (free, idx)
    }
}
