//! Laying out a maximal packing in the Poincaré disk, generic over [`Real`] (proofs/T11).
//!
//! Interior circles are placed by their hyperbolic centres `z` (`|z| < 1`), horocycles by
//! their ideal points `ζ` (`|ζ| = 1`). The disk automorphism
//! `M_a(z) = (z − z_a)/(1 − z̄_a z)` moves the centre of a placed interior circle `a` to 0;
//! there a neighbour `c` tangent to `a` lies in direction `e^{iφ}` at Euclidean distance
//! `tanh((r_a + r_c)/2) = (t_a + t_c)/(1 + t_a t_c)` (1 for a horocycle), and the direction
//! of `c` in a face `a → b → c` is that of `b` turned by the face's angle at `a`
//! ([`super::hyperbolic::corner_rotation`]). `M_a⁻¹(w) = (w + z_a)/(1 + z̄_a w)` maps back.
//!
//! Normalisation (a Möbius normalisation of the disk): the circle of `centre` has its
//! hyperbolic centre at 0, and the centre (or ideal point) of its neighbour `direction` is
//! on the positive real axis.
//!
//! Euclidean circles: a hyperbolic circle of centre `z` and `t = tanh(r/2)` is the
//! Euclidean circle of centre `z(1 − t²)/(1 − t²|z|²)` and radius
//! `t(1 − |z|²)/(1 − t²|z|²)`; the horocycle at `ζ` through the tangency point `p` with a
//! placed neighbour has radius `ρ = |ζ − p|²/(2(1 − Re(p ζ̄)))` and centre `(1 − ρ)ζ`.

use super::hyperbolic::corner_rotation;
use crate::geometry::unfold::dual_breadth_first;
use crate::mesh::{Mesh, Vertex};
use crate::scalar::Real;

/// A complex number over `T`.
#[derive(Clone, Debug)]
pub struct Complex<T> {
    /// Real part.
    pub re: T,
    /// Imaginary part.
    pub im: T,
}

impl<T: Real> Complex<T> {
    fn add(&self, o: &Self) -> Self {
        Complex {
            re: self.re.clone() + &o.re,
            im: self.im.clone() + &o.im,
        }
    }
    fn sub(&self, o: &Self) -> Self {
        Complex {
            re: self.re.clone() - &o.re,
            im: self.im.clone() - &o.im,
        }
    }
    fn mul(&self, o: &Self) -> Self {
        Complex {
            re: self.re.clone() * &o.re - &(self.im.clone() * &o.im),
            im: self.re.clone() * &o.im + &(self.im.clone() * &o.re),
        }
    }
    fn conj(&self) -> Self {
        Complex {
            re: self.re.clone(),
            im: -self.im.clone(),
        }
    }
    fn norm_sq(&self) -> T {
        self.re.clone() * &self.re + &(self.im.clone() * &self.im)
    }
    fn div(&self, o: &Self) -> Self {
        let d = o.norm_sq();
        let n = self.mul(&o.conj());
        Complex {
            re: n.re / &d,
            im: n.im / &d,
        }
    }
    fn scale(&self, s: &T) -> Self {
        Complex {
            re: self.re.clone() * s,
            im: self.im.clone() * s,
        }
    }
    fn unit(&self) -> Self {
        let n = self.norm_sq().sqrt();
        Complex {
            re: self.re.clone() / &n,
            im: self.im.clone() / &n,
        }
    }
    fn one(x: &T) -> Self {
        Complex {
            re: x.one_like(),
            im: x.zero_like(),
        }
    }
}

/// `M_a(z) = (z − a)/(1 − ā z)`.
fn to_frame<T: Real>(a: &Complex<T>, z: &Complex<T>) -> Complex<T> {
    let one = Complex::one(&a.re);
    z.sub(a).div(&one.sub(&a.conj().mul(z)))
}

/// `M_a⁻¹(w) = (w + a)/(1 + ā w)`.
fn from_frame<T: Real>(a: &Complex<T>, w: &Complex<T>) -> Complex<T> {
    let one = Complex::one(&a.re);
    w.add(a).div(&one.add(&a.conj().mul(w)))
}

/// A Euclidean circle in the plane.
#[derive(Clone, Debug)]
pub struct Circle<T> {
    /// Centre `(x, y)`.
    pub centre: [T; 2],
    /// Radius.
    pub radius: T,
}

/// Why the layout could not place every circle.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum LayoutError {
    /// The normalising vertex is not an interior vertex.
    #[error("v{0} is not an interior vertex: the normalising circle must be interior")]
    CentreNotInterior(usize),
    /// The direction vertex is not a neighbour of the centre.
    #[error("v{direction} is not a neighbour of v{centre}")]
    NotANeighbour {
        /// Centre vertex.
        centre: usize,
        /// Direction vertex.
        direction: usize,
    },
    /// Some vertex is not reached from the centre through faces with an interior vertex.
    #[error("v{0} is not reached through faces with a placed interior vertex")]
    Unreached(usize),
}

/// Where one circle sits in one face: the hyperbolic centre of an interior circle, or the
/// ideal point `ζ` of a horocycle with its Euclidean radius.
#[derive(Clone, Debug)]
struct Spot<T> {
    /// Hyperbolic centre or ideal point.
    z: Complex<T>,
    /// The Euclidean horocycle radius (`None` for an interior circle).
    horo: Option<T>,
}

/// Place every circle: `t` per vertex (`1` on horocycles), `interior` flags, and the
/// normalisation `(centre, direction)` (module docs). Returns the Euclidean circles.
///
/// Faces are placed breadth first along a spanning tree of the dual graph
/// ([`dual_breadth_first`]), each from the two corners it shares with its parent face *as
/// placed in that face*, and a circle keeps its position in the first face that places it.
/// Every face is then a rigid (Möbius) image of its parent, so an angle-sum residual `δ`
/// at a vertex only turns the faces beyond it about that vertex: the errors add up along a
/// path of the tree. Placing a circle from two neighbours positioned through different
/// faces instead mixes two such motions, and the mixture, carried on from face to face, is
/// a Cauchy problem for the layout that amplifies errors exponentially with the number of
/// rows (proofs/B92).
pub fn layout_disk<T: Real>(
    mesh: &Mesh,
    t: &[T],
    interior: &[bool],
    centre: usize,
    direction: usize,
) -> Result<Vec<Circle<T>>, LayoutError> {
    if !interior.get(centre).copied().unwrap_or(false) {
        return Err(LayoutError::CentreNotInterior(centre));
    }
    let Some(h0) = mesh
        .outgoing(Vertex(centre as u32))
        .find(|&h| mesh.tip(h).idx() == direction)
    else {
        return Err(LayoutError::NotANeighbour { centre, direction });
    };
    // An interior vertex has a face on every outgoing half-edge.
    let Some(root) = mesh.face(h0) else {
        return Err(LayoutError::CentreNotInterior(centre));
    };
    let n = mesh.n_vertices();
    let zero = t[centre].zero_like();
    let one = t[centre].one_like();
    // corner[h]: the spot of tail(h) in the face of h.
    let mut corner: Vec<Option<Spot<T>>> = vec![None; mesh.n_halfedges()];
    let mut pos: Vec<Option<Spot<T>>> = vec![None; n];
    let origin = Spot {
        z: Complex {
            re: zero.clone(),
            im: zero.clone(),
        },
        horo: None,
    };
    let first = place(
        t,
        interior,
        centre,
        &origin.z,
        direction,
        &Complex::one(&zero),
    );
    let (h1, h2) = (mesh.next(h0), mesh.prev(h0));
    let third = place_third(
        t,
        interior,
        [centre, direction, mesh.tail(h2).idx()],
        &origin,
        &first,
    );
    for (h, spot) in [(h0, origin), (h1, first), (h2, third)] {
        pos[mesh.tail(h).idx()].get_or_insert_with(|| spot.clone());
        corner[h.idx()] = Some(spot);
    }
    dual_breadth_first(
        mesh,
        root,
        |_| true,
        |h| {
            // h runs from tip(g) to tail(g), g = twin(h) in the parent face.
            let g = h.twin();
            let (Some(sx), Some(sy)) =
                (corner[mesh.next(g).idx()].clone(), corner[g.idx()].clone())
            else {
                return;
            };
            let (hn, hp) = (mesh.next(h), mesh.prev(h));
            let (x, y, r) = (mesh.tail(h).idx(), mesh.tip(h).idx(), mesh.tail(hp).idx());
            let sr = place_third(t, interior, [x, y, r], &sx, &sy);
            pos[r].get_or_insert_with(|| sr.clone());
            corner[h.idx()] = Some(sx);
            corner[hn.idx()] = Some(sy);
            corner[hp.idx()] = Some(sr);
        },
    );
    let mut out = Vec::with_capacity(n);
    for (v, spot) in pos.iter().enumerate() {
        let Some(Spot { z, horo }) = spot else {
            return Err(LayoutError::Unreached(v));
        };
        if interior[v] {
            let t2 = t[v].clone() * &t[v];
            let zz = z.norm_sq();
            let den = one.clone() - &(t2.clone() * &zz);
            let c = z.scale(&((one.clone() - &t2) / &den));
            let rho = t[v].clone() * &(one.clone() - &zz) / &den;
            out.push(Circle {
                centre: [c.re, c.im],
                radius: rho,
            });
        } else {
            let rho = horo.clone().unwrap_or_else(|| zero.clone());
            let c = z.scale(&(one.clone() - &rho));
            out.push(Circle {
                centre: [c.re, c.im],
                radius: rho,
            });
        }
    }
    Ok(out)
}

/// The spot of `r` in the face `x → y → r` (counter-clockwise) from the spots of `x` and
/// `y` in that face: from an interior one of them (from `x`, `r` is counter-clockwise of
/// `y`; from `y`, clockwise of `x`), or from two horocycles.
fn place_third<T: Real>(
    t: &[T],
    interior: &[bool],
    [x, y, r]: [usize; 3],
    sx: &Spot<T>,
    sy: &Spot<T>,
) -> Spot<T> {
    let (p, sp, q, sq, ccw) = if interior[x] {
        (x, sx, y, sy, true)
    } else if interior[y] {
        (y, sy, x, sx, false)
    } else {
        return place_from_horocycles(t, interior, [x, y, r], sx, sy);
    };
    let wq = to_frame(&sp.z, &sq.z).unit();
    let (cos, sin) = corner_rotation(&t[p], &t[q], &t[r]);
    let rot = Complex {
        re: cos,
        im: if ccw { sin } else { -sin },
    };
    place(t, interior, p, &sp.z, r, &wq.mul(&rot))
}

/// The spot of `r` tangent to the interior circle `p` (hyperbolic centre `zp`) in direction
/// `w` (a unit complex number in `p`'s frame).
fn place<T: Real>(
    t: &[T],
    interior: &[bool],
    p: usize,
    zp: &Complex<T>,
    r: usize,
    w: &Complex<T>,
) -> Spot<T> {
    let one = t[p].one_like();
    if interior[r] {
        let d = (t[p].clone() + &t[r]) / &(one + &(t[p].clone() * &t[r]));
        Spot {
            z: from_frame(zp, &w.scale(&d)),
            horo: None,
        }
    } else {
        let zeta = from_frame(zp, w);
        let touch = from_frame(zp, &w.scale(&t[p]));
        let re = touch.re.clone() * &zeta.re + &(touch.im.clone() * &zeta.im);
        let rho = zeta.sub(&touch).norm_sq() / &((one - &re) * &re.lit(2.0));
        Spot {
            z: zeta,
            horo: Some(rho),
        }
    }
}

/// The spot of `r` in the face `a → b → r` (counter-clockwise) whose `a` and `b` are
/// horocycles (`[a, b, r]`, spots `sa`, `sb`): the map `φ(z) = i(ζ_a + z)/(ζ_a − z)` to the
/// upper half-plane sends `a`'s horocycle to the line `y = H`, `b`'s to the circle of
/// diameter `H` on `x_b`; a circle tangent to both with `s = e^{−r} = (1 − t)/(1 + t)` has
/// its hyperbolic centre at `x_b + H√(1 − s²) + iHs` (`√(1 − s²) = 2√t/(1 + t)`; a
/// horocycle: the point `x_b + H`, touching the line at `x_b + H + iH`).
/// `φ⁻¹(w) = ζ_a(w − i)/(w + i)`.
fn place_from_horocycles<T: Real>(
    t: &[T],
    interior: &[bool],
    [_, _, r]: [usize; 3],
    sa: &Spot<T>,
    sb: &Spot<T>,
) -> Spot<T> {
    let (za, zb) = (&sa.z, &sb.z);
    let rho_a = sa.horo.clone().unwrap_or_else(|| t[r].zero_like());
    let zero = rho_a.zero_like();
    let one = rho_a.one_like();
    let i = Complex {
        re: zero.clone(),
        im: one.clone(),
    };
    let phi = |z: &Complex<T>| i.mul(&za.add(z)).div(&za.sub(z));
    let phi_inv = |w: &Complex<T>| za.mul(&w.sub(&i)).div(&w.add(&i));
    let far = za.scale(&(one.clone() - &(rho_a.clone() * &one.lit(2.0))));
    let h = phi(&far).im;
    let xb = phi(zb).re;
    let tr = &t[r];
    let two = one.lit(2.0);
    let sq = tr.sqrt() * &two / &(one.clone() + tr);
    let x = xb + &(h.clone() * &sq);
    if interior[r] {
        let s = (one.clone() - tr) / &(one.clone() + tr);
        Spot {
            z: phi_inv(&Complex { re: x, im: h * &s }),
            horo: None,
        }
    } else {
        let zeta = phi_inv(&Complex {
            re: x.clone(),
            im: zero,
        });
        let touch = phi_inv(&Complex { re: x, im: h });
        let re = touch.re.clone() * &zeta.re + &(touch.im.clone() * &zeta.im);
        let rho = zeta.sub(&touch).norm_sq() / &((one - &re) * &two);
        Spot {
            z: zeta,
            horo: Some(rho),
        }
    }
}
