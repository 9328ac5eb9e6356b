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
use crate::mesh::{Mesh, Vertex};
use crate::scalar::Real;
use std::collections::VecDeque;

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

/// Place every circle: `t` per vertex (`1` on horocycles), `interior` flags, and the
/// normalisation `(centre, direction)` (module docs). Returns the Euclidean circles.
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
    if !mesh
        .outgoing(Vertex(centre as u32))
        .any(|h| mesh.tip(h).idx() == direction)
    {
        return Err(LayoutError::NotANeighbour { centre, direction });
    }
    let n = mesh.n_vertices();
    let zero = t[centre].zero_like();
    let one = t[centre].one_like();
    // pos[v]: hyperbolic centre (interior) or ideal point (horocycle); horo[v]: the
    // Euclidean horocycle radius.
    let mut pos: Vec<Option<Complex<T>>> = vec![None; n];
    let mut horo: Vec<Option<T>> = vec![None; n];
    let origin = Complex {
        re: zero.clone(),
        im: zero.clone(),
    };
    pos[centre] = Some(origin.clone());
    let dir = Complex::one(&zero);
    place(
        t, interior, centre, &origin, direction, &dir, &mut pos, &mut horo,
    );
    let mut queue: VecDeque<usize> = VecDeque::from([centre, direction]);
    let mut queued = vec![false; n];
    queued[centre] = true;
    queued[direction] = true;
    while let Some(v) = queue.pop_front() {
        for h in mesh.outgoing(Vertex(v as u32)) {
            // Faces around v: v → b → c with v, b placed.
            if mesh.is_boundary_halfedge(h) {
                continue;
            }
            let (a, b, c) = (v, mesh.tip(h).idx(), mesh.opposite_vertex(h).idx());
            for (x, y, r) in [(a, b, c), (b, c, a), (c, a, b)] {
                // The face x → y → r (counter-clockwise) with x, y placed and r not: place
                // r from an interior one of x, y (from x, r is counter-clockwise of y; from
                // y, clockwise of x), or from two horocycles.
                if pos[r].is_some() || pos[x].is_none() || pos[y].is_none() {
                    continue;
                }
                let from = if interior[x] {
                    Some((x, y, true))
                } else if interior[y] {
                    Some((y, x, false))
                } else {
                    None
                };
                match from {
                    None => place_from_horocycles(t, interior, [x, y, r], &mut pos, &mut horo),
                    Some((p, q, ccw)) => {
                        let (Some(zp), Some(zq)) = (pos[p].clone(), pos[q].clone()) else {
                            continue;
                        };
                        let wq = to_frame(&zp, &zq).unit();
                        let (cos, sin) = corner_rotation(&t[p], &t[q], &t[r]);
                        let rot = Complex {
                            re: cos,
                            im: if ccw { sin } else { -sin },
                        };
                        let wr = wq.mul(&rot);
                        place(t, interior, p, &zp, r, &wr, &mut pos, &mut horo);
                    }
                }
                if pos[r].is_some() && !queued[r] {
                    queued[r] = true;
                    queue.push_back(r);
                }
            }
        }
    }
    let mut out = Vec::with_capacity(n);
    for v in 0..n {
        let Some(z) = &pos[v] else {
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
            let rho = horo[v].clone().unwrap_or_else(|| zero.clone());
            let c = z.scale(&(one.clone() - &rho));
            out.push(Circle {
                centre: [c.re, c.im],
                radius: rho,
            });
        }
    }
    Ok(out)
}

/// Place `r` tangent to the interior circle `p` (hyperbolic centre `zp`) in direction `w`
/// (a unit complex number in `p`'s frame).
#[allow(clippy::too_many_arguments)]
fn place<T: Real>(
    t: &[T],
    interior: &[bool],
    p: usize,
    zp: &Complex<T>,
    r: usize,
    w: &Complex<T>,
    pos: &mut [Option<Complex<T>>],
    horo: &mut [Option<T>],
) {
    let one = t[p].one_like();
    if interior[r] {
        let d = (t[p].clone() + &t[r]) / &(one + &(t[p].clone() * &t[r]));
        pos[r] = Some(from_frame(zp, &w.scale(&d)));
    } else {
        let zeta = from_frame(zp, w);
        let touch = from_frame(zp, &w.scale(&t[p]));
        let re = touch.re.clone() * &zeta.re + &(touch.im.clone() * &zeta.im);
        let rho = zeta.sub(&touch).norm_sq() / &((one - &re) * &re.lit(2.0));
        pos[r] = Some(zeta);
        horo[r] = Some(rho);
    }
}

/// Place `r` in the face `a → b → r` (counter-clockwise) whose `a` and `b` are placed
/// horocycles (`[a, b, r]`): the map `φ(z) = i(ζ_a + z)/(ζ_a − z)` to the upper half-plane
/// sends `a`'s horocycle to the line `y = H`, `b`'s to the circle of diameter `H` on
/// `x_b`; a circle tangent to both with `s = e^{−r} = (1 − t)/(1 + t)` has its hyperbolic
/// centre at `x_b + H√(1 − s²) + iHs` (`√(1 − s²) = 2√t/(1 + t)`; a horocycle: the point
/// `x_b + H`, touching the line at `x_b + H + iH`). `φ⁻¹(w) = ζ_a(w − i)/(w + i)`.
fn place_from_horocycles<T: Real>(
    t: &[T],
    interior: &[bool],
    [a, b, r]: [usize; 3],
    pos: &mut [Option<Complex<T>>],
    horo: &mut [Option<T>],
) {
    let (Some(za), Some(zb), Some(rho_a)) = (pos[a].clone(), pos[b].clone(), horo[a].clone())
    else {
        return;
    };
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
    let xb = phi(&zb).re;
    let tr = &t[r];
    let two = one.lit(2.0);
    let sq = tr.sqrt() * &two / &(one.clone() + tr);
    let x = xb + &(h.clone() * &sq);
    if interior[r] {
        let s = (one.clone() - tr) / &(one.clone() + tr);
        pos[r] = Some(phi_inv(&Complex { re: x, im: h * &s }));
    } else {
        let zeta = phi_inv(&Complex {
            re: x.clone(),
            im: zero,
        });
        let touch = phi_inv(&Complex { re: x, im: h });
        let re = touch.re.clone() * &zeta.re + &(touch.im.clone() * &zeta.im);
        let rho = zeta.sub(&touch).norm_sq() / &((one - &re) * &two);
        pos[r] = Some(zeta);
        horo[r] = Some(rho);
    }
}
