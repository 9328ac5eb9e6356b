//! Repairs a user asks for by name, each reported: polygon faces triangulated, face
//! orientations made consistent, unreferenced vertices dropped. Without a request nothing
//! is changed and the reader refuses the file (a verification tool must not change a
//! surface silently); the refusal names the repair that would fix it.
//!
//! - **Triangulate.** A planar polygon (its corners coplanar, decided exactly) is split in
//!   its plane: among the triangulations whose diagonals are inside the polygon (exact
//!   orientation and intersection tests on the exact coordinates projected to the
//!   coordinate plane most nearly parallel to it), the one maximising the smallest angle,
//!   by dynamic programming over the polygon's chains — the constrained Delaunay
//!   triangulation when that is unique. A non-planar polygon gets the fan, from the corner
//!   that maximises the smallest angle, whose triangles' normals pairwise make an acute
//!   angle (decided exactly), so no triangle folds over another. A quadrilateral bent so
//!   far that neither diagonal has that (a crease of more than 90°, as at the corners of
//!   modelled eyes and lips) is split along the diagonal whose two normals make the
//!   smallest angle, provided they are not opposite (decided exactly: two triangles on one
//!   edge cannot overlap otherwise), and reported apart. Every triangle is
//!   non-degenerate (exact cross product ≠ 0), and no diagonal joins two vertices already
//!   joined by a side of any face or by a diagonal chosen before (a second edge between
//!   them would make an edge of more than two faces: two quadrilaterals sharing two
//!   opposite corners, as in modelled eyelids, must not both be split between those two).
//!   Angles only rank valid candidates (binary64);
//!   validity is decided exactly. Polygons with more than [`DP_CORNERS`] corners get the fan.
//! - **Orient.** A breadth-first search over the dual graph (faces sharing an edge with
//!   exactly one other face) assigns each face a side so that every shared edge is used in
//!   opposite directions; in each component the faces fewer in number are reversed. A
//!   conflict proves the surface non-orientable: the error names a cycle of faces (by
//!   line) along which the orientation reverses. Edges with more than two faces are left
//!   to the surface builder, which refuses them (non-manifold).
//! - **Drop unreferenced.** Vertices in no face are removed and the others renumbered.

use super::decimal::Coordinate;
use super::soup::PolygonSoup;
use super::ReadError;
use rug::Rational;
use std::collections::{HashMap, VecDeque};
use std::fmt;

/// Polygons with at most this many corners are triangulated by the dynamic program
/// (`O(k⁴)` exact tests); larger ones get the best valid fan (`O(k³)`).
pub const DP_CORNERS: usize = 48;

/// Elements a report lists by line before it only counts the rest.
const LISTED: usize = 20;

/// Which repairs to apply.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Repairs {
    /// Split faces with more than three corners into triangles.
    pub triangulate: bool,
    /// Reverse faces so that the orientation is consistent.
    pub orient: bool,
    /// Remove vertices that belong to no face.
    pub drop_unreferenced: bool,
}

impl Repairs {
    /// Every repair (`--repair`).
    pub const ALL: Repairs = Repairs {
        triangulate: true,
        orient: true,
        drop_unreferenced: true,
    };

    /// Whether any repair is asked for.
    pub fn any(&self) -> bool {
        self.triangulate || self.orient || self.drop_unreferenced
    }
}

/// What the repairs changed, by input line.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct RepairLog {
    /// Polygon faces split in their plane: (line, corners).
    pub planar: Vec<(usize, usize)>,
    /// Non-planar polygon faces split as a fan: (line, corners).
    pub fans: Vec<(usize, usize)>,
    /// Quadrilaterals bent by more than 90° along both diagonals, split along the diagonal
    /// bending least: (line, corners).
    pub creased: Vec<(usize, usize)>,
    /// Faces whose orientation was reversed, by line.
    pub reversed: Vec<usize>,
    /// Vertices dropped, by line.
    pub dropped: Vec<usize>,
}

impl RepairLog {
    /// Whether nothing was changed.
    pub fn is_empty(&self) -> bool {
        self.planar.is_empty()
            && self.fans.is_empty()
            && self.creased.is_empty()
            && self.reversed.is_empty()
            && self.dropped.is_empty()
    }
}

/// Lines, the first [`LISTED`] of them and a count of the rest.
fn lines_of(lines: impl ExactSizeIterator<Item = usize>) -> String {
    let n = lines.len();
    let shown: Vec<String> = lines.take(LISTED).map(|l| l.to_string()).collect();
    let more = if n > LISTED {
        format!(" and {} more", n - LISTED)
    } else {
        String::new()
    };
    format!("{}{more}", shown.join(", "))
}

impl fmt::Display for RepairLog {
    /// One line per repair that changed something.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let mut parts = Vec::new();
        if !self.planar.is_empty() {
            parts.push(format!(
                "triangulated {} planar polygon face(s) in their plane, largest smallest angle (lines {})",
                self.planar.len(),
                lines_of(self.planar.iter().map(|p| p.0))
            ));
        }
        if !self.fans.is_empty() {
            parts.push(format!(
                "triangulated {} non-planar polygon face(s) as the fan with the largest smallest angle (lines {})",
                self.fans.len(),
                lines_of(self.fans.iter().map(|p| p.0))
            ));
        }
        if !self.creased.is_empty() {
            parts.push(format!(
                "triangulated {} quadrilateral(s) bent by more than 90° along both diagonals, along the diagonal bending least (lines {})",
                self.creased.len(),
                lines_of(self.creased.iter().map(|p| p.0))
            ));
        }
        if !self.reversed.is_empty() {
            parts.push(format!(
                "reversed the orientation of {} face(s) (lines {})",
                self.reversed.len(),
                lines_of(self.reversed.iter().copied())
            ));
        }
        if !self.dropped.is_empty() {
            parts.push(format!(
                "dropped {} unreferenced vertex(es) (lines {})",
                self.dropped.len(),
                lines_of(self.dropped.iter().copied())
            ));
        }
        write!(f, "{}", parts.join("\n"))
    }
}

/// Apply `repairs` to `soup` (unreferenced vertices, then polygons, then orientation) and
/// say what changed.
pub fn repair(
    mut soup: PolygonSoup,
    repairs: &Repairs,
) -> Result<(PolygonSoup, RepairLog), ReadError> {
    let mut log = RepairLog::default();
    if repairs.drop_unreferenced {
        drop_unreferenced(&mut soup, &mut log);
    }
    if repairs.triangulate {
        triangulate(&mut soup, &mut log)?;
    }
    if repairs.orient {
        orient(&mut soup, &mut log)?;
    }
    Ok((soup, log))
}

fn drop_unreferenced(soup: &mut PolygonSoup, log: &mut RepairLog) {
    let n = soup.positions.len();
    let mut used = vec![false; n];
    for &v in &soup.corners {
        if let Some(u) = used.get_mut(v as usize) {
            *u = true;
        }
    }
    if used.iter().all(|&u| u) {
        return;
    }
    let mut new_id = vec![u32::MAX; n];
    let mut positions = Vec::with_capacity(n);
    let mut lines = Vec::with_capacity(n);
    for (v, p) in std::mem::take(&mut soup.positions).into_iter().enumerate() {
        if used[v] {
            new_id[v] = positions.len() as u32;
            positions.push(p);
            lines.push(soup.vertex_lines[v]);
        } else {
            log.dropped.push(soup.vertex_lines[v]);
        }
    }
    soup.positions = positions;
    soup.vertex_lines = lines;
    for v in &mut soup.corners {
        *v = new_id[*v as usize];
    }
}

/// An exact point.
type P3 = [Rational; 3];

fn exact(c: &[Coordinate; 3]) -> P3 {
    [c[0].to_rational(), c[1].to_rational(), c[2].to_rational()]
}

fn sub(a: &P3, b: &P3) -> P3 {
    [
        Rational::from(&a[0] - &b[0]),
        Rational::from(&a[1] - &b[1]),
        Rational::from(&a[2] - &b[2]),
    ]
}

fn cross(a: &P3, b: &P3) -> P3 {
    [
        Rational::from(&a[1] * &b[2]) - Rational::from(&a[2] * &b[1]),
        Rational::from(&a[2] * &b[0]) - Rational::from(&a[0] * &b[2]),
        Rational::from(&a[0] * &b[1]) - Rational::from(&a[1] * &b[0]),
    ]
}

fn dot(a: &P3, b: &P3) -> Rational {
    Rational::from(&a[0] * &b[0]) + Rational::from(&a[1] * &b[1]) + Rational::from(&a[2] * &b[2])
}

fn is_zero(a: &P3) -> bool {
    a.iter().all(|x| *x == 0)
}

/// The normal `(b − a) × (c − a)` of a triangle, exactly.
fn normal(a: &P3, b: &P3, c: &P3) -> P3 {
    cross(&sub(b, a), &sub(c, a))
}

/// The smallest angle of a triangle, in binary64 (only to rank valid candidates).
fn smallest_angle(a: &P3, b: &P3, c: &P3) -> f64 {
    let f = |p: &P3| [p[0].to_f64(), p[1].to_f64(), p[2].to_f64()];
    let (a, b, c) = (f(a), f(b), f(c));
    let d = |p: [f64; 3], q: [f64; 3]| {
        ((p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2) + (p[2] - q[2]).powi(2)).sqrt()
    };
    let (x, y, z) = (d(b, c), d(c, a), d(a, b));
    let angle = |o: f64, s: f64, t: f64| {
        ((s * s + t * t - o * o) / (2.0 * s * t))
            .clamp(-1.0, 1.0)
            .acos()
    };
    let m = angle(x, y, z).min(angle(y, z, x)).min(angle(z, x, y));
    if m.is_nan() {
        0.0
    } else {
        m
    }
}

fn triangulate(soup: &mut PolygonSoup, log: &mut RepairLog) -> Result<(), ReadError> {
    if soup.corners.len() == 3 * soup.n_faces() {
        return Ok(());
    }
    // Undirected pairs of vertices joined by a face's side, then by the diagonals chosen.
    let key = |a: u32, b: u32| (a.min(b), a.max(b));
    let mut joined: std::collections::HashSet<(u32, u32)> = (0..soup.n_faces())
        .flat_map(|f| {
            let c = soup.face(f);
            (0..c.len()).map(move |s| key(c[s], c[(s + 1) % c.len()]))
        })
        .collect();
    let mut out = PolygonSoup::default();
    for f in 0..soup.n_faces() {
        let (corners, line) = (soup.face(f), soup.face_lines[f]);
        if corners.len() == 3 {
            out.push_face(corners, line);
            continue;
        }
        let pts: Vec<P3> = corners
            .iter()
            .map(|&v| exact(&soup.positions[v as usize]))
            .collect();
        let taken = |i: usize, j: usize| joined.contains(&key(corners[i], corners[j]));
        let (triangles, kind) = split_polygon(&pts, &taken).ok_or_else(|| ReadError::CannotRepair {
            element: format!("line {line}"),
            message: format!(
                "the face with {} corners has no triangulation without a degenerate or folded triangle or a diagonal that is already an edge",
                corners.len()
            ),
        })?;
        let k = corners.len();
        for t in &triangles {
            for s in 0..3 {
                let (i, j) = (t[s], t[(s + 1) % 3]);
                if (i + 1) % k != j && (j + 1) % k != i {
                    joined.insert(key(corners[i], corners[j]));
                }
            }
        }
        match kind {
            Split::Planar => log.planar.push((line, corners.len())),
            Split::Fan => log.fans.push((line, corners.len())),
            Split::Creased => log.creased.push((line, corners.len())),
        }
        for [a, b, c] in triangles {
            out.push_face(&[corners[a], corners[b], corners[c]], line);
        }
    }
    soup.corners = out.corners;
    soup.ends = out.ends;
    soup.face_lines = out.face_lines;
    Ok(())
}

/// How [`split_polygon`] split a polygon.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Split {
    /// In its plane (the polygon is planar).
    Planar,
    /// A fan whose normals pairwise make an acute angle.
    Fan,
    /// A quadrilateral bent by more than 90° along both diagonals, split along the one
    /// bending least.
    Creased,
}

/// Triangles (corner indices) splitting the polygon `pts`, and how, with no diagonal `ij`
/// for which `taken(i, j)` (its ends already joined by an edge of the surface).
pub(crate) fn split_polygon(
    pts: &[P3],
    taken: &dyn Fn(usize, usize) -> bool,
) -> Option<(Vec<[usize; 3]>, Split)> {
    let k = pts.len();
    // Newell's normal: twice the vector area, exact.
    let mut n: P3 = [Rational::new(), Rational::new(), Rational::new()];
    for i in 0..k {
        let c = cross(&pts[i], &pts[(i + 1) % k]);
        for a in 0..3 {
            n[a] += &c[a];
        }
    }
    let planar = !is_zero(&n) && (1..k).all(|i| dot(&sub(&pts[i], &pts[0]), &n) == 0);
    if planar && k <= DP_CORNERS {
        if let Some(t) = planar_max_min_angle(pts, &n, taken) {
            return Some((t, Split::Planar));
        }
    }
    let kind = if planar { Split::Planar } else { Split::Fan };
    best_fan(pts, taken).map(|t| (t, kind)).or_else(|| {
        (k == 4)
            .then(|| least_bent_diagonal(pts, taken))
            .flatten()
            .map(|t| (t, Split::Creased))
    })
}

/// The split of a quadrilateral along the diagonal whose two triangles' normals make the
/// smallest angle (ranked in binary64), among the splits with non-degenerate triangles whose
/// normals are not opposite (exact: `n₁ × n₂ ≠ 0` or `n₁·n₂ > 0`), so the two triangles on
/// the diagonal do not overlap; `None` when neither diagonal qualifies.
fn least_bent_diagonal(
    pts: &[P3],
    taken: &dyn Fn(usize, usize) -> bool,
) -> Option<Vec<[usize; 3]>> {
    let mut best: Option<(f64, Vec<[usize; 3]>)> = None;
    for apex in 0..2 {
        if taken(apex, apex + 2) {
            continue;
        }
        let tris = vec![
            [apex, apex + 1, (apex + 2) % 4],
            [apex, (apex + 2) % 4, (apex + 3) % 4],
        ];
        let [n1, n2] = [0, 1].map(|t| normal(&pts[tris[t][0]], &pts[tris[t][1]], &pts[tris[t][2]]));
        if is_zero(&n1) || is_zero(&n2) {
            continue;
        }
        let d = dot(&n1, &n2);
        if is_zero(&cross(&n1, &n2)) && d <= 0 {
            continue;
        }
        let norm = |n: &P3| n.iter().map(|x| x.to_f64().powi(2)).sum::<f64>().sqrt();
        let cosine = d.to_f64() / (norm(&n1) * norm(&n2));
        if best.as_ref().is_none_or(|b| cosine > b.0) {
            best = Some((cosine, tris));
        }
    }
    best.map(|b| b.1)
}

/// Project to the coordinate plane along the largest component of `n`, keeping the
/// polygon counter-clockwise: dropping x gives (y, z), y gives (z, x), z gives (x, y).
fn project(pts: &[P3], n: &P3) -> Vec<[Rational; 2]> {
    let abs = |x: &Rational| x.clone().abs();
    let axis = if abs(&n[0]) >= abs(&n[1]) && abs(&n[0]) >= abs(&n[2]) {
        0
    } else if abs(&n[1]) >= abs(&n[2]) {
        1
    } else {
        2
    };
    let (u, v) = ((axis + 1) % 3, (axis + 2) % 3);
    let flip = n[axis] < 0;
    pts.iter()
        .map(|p| {
            if flip {
                [p[v].clone(), p[u].clone()]
            } else {
                [p[u].clone(), p[v].clone()]
            }
        })
        .collect()
}

fn orient2d(a: &[Rational; 2], b: &[Rational; 2], c: &[Rational; 2]) -> std::cmp::Ordering {
    let l = Rational::from(&b[0] - &a[0]) * Rational::from(&c[1] - &a[1]);
    let r = Rational::from(&b[1] - &a[1]) * Rational::from(&c[0] - &a[0]);
    l.cmp(&r)
}

/// Whether the closed segments ab and cd meet.
fn segments_meet(
    a: &[Rational; 2],
    b: &[Rational; 2],
    c: &[Rational; 2],
    d: &[Rational; 2],
) -> bool {
    use std::cmp::Ordering::Equal;
    let (o1, o2) = (orient2d(a, b, c), orient2d(a, b, d));
    let (o3, o4) = (orient2d(c, d, a), orient2d(c, d, b));
    if o1 != Equal && o2 != Equal && o3 != Equal && o4 != Equal {
        return o1 != o2 && o3 != o4;
    }
    let between = |r: &Rational, p: &Rational, q: &Rational| {
        let (lo, hi) = if p <= q { (p, q) } else { (q, p) };
        r >= lo && r <= hi
    };
    let on = |p: &[Rational; 2], q: &[Rational; 2], r: &[Rational; 2]| {
        orient2d(p, q, r) == Equal && between(&r[0], &p[0], &q[0]) && between(&r[1], &p[1], &q[1])
    };
    (o1 != o2 && o3 != o4) || on(a, b, c) || on(a, b, d) || on(c, d, a) || on(c, d, b)
}

/// Whether the chord `ij` of the counter-clockwise simple polygon `q` is a diagonal: it
/// leaves `i` into the interior and meets no edge it does not end on.
fn is_diagonal(q: &[[Rational; 2]], i: usize, j: usize) -> bool {
    use std::cmp::Ordering::{Greater, Less};
    let k = q.len();
    let (prev, next) = ((i + k - 1) % k, (i + 1) % k);
    // In the cone at i: convex corner → strictly left of (prev, i) and of (i, next).
    let convex = orient2d(&q[prev], &q[i], &q[next]) != Less;
    let in_cone = if convex {
        orient2d(&q[i], &q[j], &q[prev]) == Greater && orient2d(&q[j], &q[i], &q[next]) == Greater
    } else {
        !(orient2d(&q[i], &q[j], &q[next]) != Less && orient2d(&q[j], &q[i], &q[prev]) != Less)
    };
    if !in_cone {
        return false;
    }
    (0..k).all(|a| {
        let b = (a + 1) % k;
        a == i || b == i || a == j || b == j || !segments_meet(&q[i], &q[j], &q[a], &q[b])
    })
}

/// The triangulation of a planar polygon (normal `n`) by diagonals (none `taken`)
/// maximising the smallest angle, or `None` when the polygon is not simple in its plane.
fn planar_max_min_angle(
    pts: &[P3],
    n: &P3,
    taken: &dyn Fn(usize, usize) -> bool,
) -> Option<Vec<[usize; 3]>> {
    use std::cmp::Ordering::Greater;
    let k = pts.len();
    let q = project(pts, n);
    let diag: Vec<Vec<bool>> = (0..k)
        .map(|i| {
            (0..k)
                .map(|j| {
                    let side = j == i + 1 || (i == 0 && j == k - 1);
                    j > i
                        && (side
                            || (!taken(i, j) && is_diagonal(&q, i, j) && is_diagonal(&q, j, i)))
                })
                .collect()
        })
        .collect();
    // best[i][j]: the largest smallest angle over triangulations of the chain i..j.
    let mut best = vec![vec![None::<(f64, usize)>; k]; k];
    for len in 2..k {
        for i in 0..k - len {
            let j = i + len;
            if !diag[i][j] {
                continue;
            }
            for m in i + 1..j {
                if !diag[i][m] || !diag[m][j] || orient2d(&q[i], &q[m], &q[j]) != Greater {
                    continue;
                }
                let left = if m == i + 1 {
                    Some(f64::INFINITY)
                } else {
                    best[i][m].map(|b| b.0)
                };
                let right = if j == m + 1 {
                    Some(f64::INFINITY)
                } else {
                    best[m][j].map(|b| b.0)
                };
                let (Some(l), Some(r)) = (left, right) else {
                    continue;
                };
                let v = smallest_angle(&pts[i], &pts[m], &pts[j]).min(l).min(r);
                if best[i][j].is_none_or(|b| v > b.0) {
                    best[i][j] = Some((v, m));
                }
            }
        }
    }
    best[0][k - 1]?;
    let mut out = Vec::with_capacity(k - 2);
    let mut stack = vec![(0, k - 1)];
    while let Some((i, j)) = stack.pop() {
        if j <= i + 1 {
            continue;
        }
        let (_, m) = best[i][j]?;
        out.push([i, m, j]);
        stack.push((i, m));
        stack.push((m, j));
    }
    Some(out)
}

/// The fan with the largest smallest angle, with no diagonal `taken`, whose triangles are non-degenerate and whose
/// normals pairwise have a positive dot product.
fn best_fan(pts: &[P3], taken: &dyn Fn(usize, usize) -> bool) -> Option<Vec<[usize; 3]>> {
    let k = pts.len();
    let mut best: Option<(f64, Vec<[usize; 3]>)> = None;
    for apex in 0..k {
        if (2..k - 1).any(|t| taken(apex, (apex + t) % k)) {
            continue;
        }
        let tris: Vec<[usize; 3]> = (1..k - 1)
            .map(|t| [apex, (apex + t) % k, (apex + t + 1) % k])
            .collect();
        let normals: Vec<P3> = tris
            .iter()
            .map(|t| normal(&pts[t[0]], &pts[t[1]], &pts[t[2]]))
            .collect();
        if normals.iter().any(is_zero) {
            continue;
        }
        let folded = (0..normals.len())
            .any(|a| (a + 1..normals.len()).any(|b| dot(&normals[a], &normals[b]) <= 0));
        if folded {
            continue;
        }
        let v = tris
            .iter()
            .map(|t| smallest_angle(&pts[t[0]], &pts[t[1]], &pts[t[2]]))
            .fold(f64::INFINITY, f64::min);
        if best.as_ref().is_none_or(|b| v > b.0) {
            best = Some((v, tris));
        }
    }
    best.map(|b| b.1)
}

fn orient(soup: &mut PolygonSoup, log: &mut RepairLog) -> Result<(), ReadError> {
    let nf = soup.n_faces();
    // Undirected edge → the faces using it, with whether they use it from lower to higher id.
    let mut uses: HashMap<(u32, u32), Vec<(usize, bool)>> = HashMap::new();
    for f in 0..nf {
        let corners = soup.face(f);
        for s in 0..corners.len() {
            let (a, b) = (corners[s], corners[(s + 1) % corners.len()]);
            uses.entry((a.min(b), a.max(b)))
                .or_default()
                .push((f, a < b));
        }
    }
    let mut flip: Vec<Option<bool>> = vec![None; nf];
    let mut parent = vec![usize::MAX; nf];
    for root in 0..nf {
        if flip[root].is_some() {
            continue;
        }
        flip[root] = Some(false);
        let mut component = vec![root];
        let mut queue = VecDeque::from([root]);
        while let Some(f) = queue.pop_front() {
            let corners = soup.face(f);
            for s in 0..corners.len() {
                let (a, b) = (corners[s], corners[(s + 1) % corners.len()]);
                let Some(faces) = uses.get(&(a.min(b), a.max(b))) else {
                    continue;
                };
                let [(f0, d0), (f1, d1)] = faces.as_slice() else {
                    continue; // boundary or non-manifold: the builder decides
                };
                let ((g, dg), df) = if *f0 == f {
                    ((*f1, *d1), *d0)
                } else {
                    ((*f0, *d0), *d1)
                };
                if g == f {
                    continue;
                }
                let x = df ^ flip[f].unwrap_or(false);
                let want = dg ^ x ^ true;
                match flip[g] {
                    None => {
                        flip[g] = Some(want);
                        parent[g] = f;
                        component.push(g);
                        queue.push_back(g);
                    }
                    Some(have) if have != want => {
                        return Err(non_orientable(soup, &parent, f, g));
                    }
                    Some(_) => {}
                }
            }
        }
        // Keep the orientation of the majority.
        let flipped = component.iter().filter(|&&f| flip[f] == Some(true)).count();
        if 2 * flipped > component.len() {
            for &f in &component {
                flip[f] = flip[f].map(|x| !x);
            }
        }
    }
    for (f, fl) in flip.iter().enumerate() {
        if *fl == Some(true) {
            let start = if f == 0 { 0 } else { soup.ends[f - 1] };
            soup.corners[start..soup.ends[f]].reverse();
            log.reversed.push(soup.face_lines[f]);
        }
    }
    Ok(())
}

/// The error for a conflict between `f` and its neighbour `g`: the cycle from `f` up the
/// search tree to the common ancestor and down to `g`.
fn non_orientable(soup: &PolygonSoup, parent: &[usize], f: usize, g: usize) -> ReadError {
    let path = |mut x: usize| {
        let mut p = vec![x];
        while parent[x] != usize::MAX {
            x = parent[x];
            p.push(x);
        }
        p
    };
    let (pf, pg) = (path(f), path(g));
    let common = pf.iter().find(|x| pg.contains(x)).copied();
    let mut cycle: Vec<usize> = pf
        .iter()
        .copied()
        .take_while(|&x| Some(x) != common)
        .collect();
    if let Some(c) = common {
        cycle.push(c);
    }
    let down: Vec<usize> = pg
        .iter()
        .copied()
        .take_while(|&x| Some(x) != common)
        .collect();
    cycle.extend(down.into_iter().rev());
    let lines: Vec<usize> = cycle.iter().map(|&x| soup.face_lines[x]).collect();
    ReadError::CannotRepair {
        element: format!("line {}", soup.face_lines[f]),
        message: format!(
            "the surface is not orientable: the faces of lines {} form a cycle along which the orientation reverses",
            lines_of(lines.into_iter())
        ),
    }
}
