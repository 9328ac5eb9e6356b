//! A second, independent certifier for small meshes: the interval Krawczyk operator on the
//! free scale factors (dense, at most [`KRAWCZYK_LIMIT`] free vertices). proof: B72
//!
//! With `y = u' − u` on the box `Y = [−r, r]ⁿ`, `F(y) = Θ − θ(u + y)` (free vertices) and an
//! interval enclosure `J ⊇ {F'(u + y) : y ∈ Y}` (the interval `−L` over the box), and any
//! real matrix `R` (here `fl(H_mid⁻¹)` by dense Gauss–Jordan), the Krawczyk image
//! `K = −R·F(u) + (I − R·J)·Y` satisfies: if `K ⊂ int Y`, `F` has exactly one zero in
//! `u + Y`. Interval arithmetic in `f64` with outward rounding (B21); the enclosures of
//! `F(u)` and `J` come from the shared MPFR interval computation (B71 step 1 checks the
//! Penner cell on the same box).

use super::certificate::{prepare, Carried, CertificateData, CertificateError, I};
use crate::scalar::Interval;
use rug::float::Round;

/// The largest number of free vertices the dense certifier accepts.
pub const KRAWCZYK_LIMIT: usize = 2000;

/// The outcome of [`krawczyk`].
#[derive(Clone, Debug, PartialEq)]
pub enum KrawczykOutcome {
    /// A unique zero lies in the box; `width` is the largest half-width of `K` (a bound on
    /// `|u* − u|_∞`).
    Holds {
        /// `max_i |K_i|`, rounded up.
        width: f64,
    },
    /// No conclusion.
    Undecided {
        /// Why.
        reason: String,
    },
}

type F = Interval<f64>;

fn outward(x: &I) -> F {
    x.to_f64_outward()
}

/// The box radius in binary64, rounded down: the box tested is inside the one `prepare`
/// checked (B72 hypotheses).
fn radius_down(radius: &rug::Rational) -> f64 {
    rug::Float::with_val_round(53, radius, Round::Down)
        .0
        .to_f64()
}

/// Dense inverse by Gauss–Jordan with partial pivoting (plain `f64`: `R` needs no rigor).
fn inverse(mut a: Vec<Vec<f64>>) -> Option<Vec<Vec<f64>>> {
    let n = a.len();
    let mut inv: Vec<Vec<f64>> = (0..n)
        .map(|i| (0..n).map(|j| f64::from(u8::from(i == j))).collect())
        .collect();
    for c in 0..n {
        let p = (c..n).max_by(|&x, &y| a[x][c].abs().total_cmp(&a[y][c].abs()))?;
        if a[p][c] == 0.0 {
            return None;
        }
        a.swap(c, p);
        inv.swap(c, p);
        let d = a[c][c];
        for j in 0..n {
            a[c][j] /= d;
            inv[c][j] /= d;
        }
        for r in 0..n {
            if r != c && a[r][c] != 0.0 {
                let f = a[r][c];
                for j in 0..n {
                    a[r][j] -= f * a[c][j];
                    inv[r][j] -= f * inv[c][j];
                }
            }
        }
    }
    Some(inv)
}

/// Run the Krawczyk test on the box of `data` at `bits` of MPFR precision for the
/// enclosures. proof: B72
pub fn krawczyk(data: &CertificateData, bits: u32) -> Result<KrawczykOutcome, CertificateError> {
    let carried = Carried::of(data, None, bits)?;
    let p = match prepare(data, &carried, super::certificate::Rung::Mpfr) {
        Ok(p) => p,
        Err(reason) => return Ok(KrawczykOutcome::Undecided { reason }),
    };
    let n = p.free.len();
    if n > KRAWCZYK_LIMIT {
        return Ok(KrawczykOutcome::Undecided {
            reason: format!("{n} free vertices: more than the dense limit {KRAWCZYK_LIMIT}"),
        });
    }
    // J = −L over the box (free rows and columns), sparse by rows; H_mid dense.
    let mut jac: Vec<Vec<(usize, F)>> = vec![Vec::new(); n];
    let mut mid = vec![vec![0.0; n]; n];
    for (i, j, w) in p.laplacian.entries() {
        if let (Some(a), Some(b)) = (p.free_idx[i], p.free_idx[j]) {
            let h = outward(&(-w.into_owned()));
            mid[a][b] = 0.5 * (h.lo() + h.hi());
            jac[a].push((b, h));
        }
    }
    let Some(r) = inverse(mid) else {
        return Ok(KrawczykOutcome::Undecided {
            reason: "the midpoint Hessian is singular in f64".into(),
        });
    };
    // An f64 radius not above the certificate's (the box checked by `prepare`).
    let rad = radius_down(&data.radius);
    if rad.is_nan() || rad <= 0.0 {
        return Ok(KrawczykOutcome::Undecided {
            reason: "radius underflows binary64".into(),
        });
    }
    let g: Vec<F> = p.residual.iter().map(outward).collect();
    match krawczyk_image(&g, &jac, &r, rad) {
        Ok(width) => Ok(KrawczykOutcome::Holds { width }),
        Err(KrawczykEscape { row, image }) => Ok(KrawczykOutcome::Undecided {
            reason: format!(
                "Krawczyk image of v{} is [{:e}, {:e}], not inside the box of radius {rad:e}",
                p.free[row],
                image.lo(),
                image.hi()
            ),
        }),
    }
}

/// A component of the Krawczyk image that is not inside the open box.
#[derive(Clone, Debug)]
pub struct KrawczykEscape {
    /// The row (free-vertex index) of the component.
    pub row: usize,
    /// Its enclosure `K_row`.
    pub image: Interval<f64>,
}

/// The inclusion test of B72 on dense data: with the residual enclosure `g ⊇ F(u)`, the
/// Jacobian enclosure `jac ⊇ F'(u + Y)` by sparse rows, any real matrix `r` and the box
/// `Y = [−rad, rad]ⁿ`, every component of
/// `K = −r·g + (I − r·jac)·Y`
/// (interval arithmetic in binary64 with outward rounding, B21) must lie in the open
/// interval `(−rad, rad)`. Returns `max_i |K_i|` (a bound on the distance from `u` to the
/// unique zero) or the first component that escapes. proof: B72
pub fn krawczyk_image(
    g: &[F],
    jac: &[Vec<(usize, F)>],
    r: &[Vec<f64>],
    rad: f64,
) -> Result<f64, KrawczykEscape> {
    let n = g.len();
    let y = F::new(-rad, rad);
    let zero = F::new(0.0, 0.0);
    let mut width: f64 = 0.0;
    for (i, ri) in r.iter().enumerate() {
        // c_i = e_i − (R J)_i, as a dense interval row.
        let mut c: Vec<F> = (0..n)
            .map(|j| {
                if i == j {
                    F::new(1.0, 1.0)
                } else {
                    zero.clone()
                }
            })
            .collect();
        let mut k = zero.clone();
        for (m, &rim) in ri.iter().enumerate() {
            if rim == 0.0 {
                continue;
            }
            let rim_i = F::new(rim, rim);
            k -= &(rim_i.clone() * &g[m]);
            for (j, jmj) in &jac[m] {
                c[*j] = c[*j].clone() - &(rim_i.clone() * jmj);
            }
        }
        for cj in &c {
            k += &(cj.clone() * &y);
        }
        if !(k.is_valid() && *k.lo() > -rad && *k.hi() < rad) {
            return Err(KrawczykEscape { row: i, image: k });
        }
        width = width.max(k.lo().abs()).max(k.hi().abs());
    }
    Ok(width)
}

#[cfg(test)]
mod terms {
    //! Each term of B72's inclusion `−R·F(u) + (I − R·J)·Y ⊂ int Y` decides a verdict on a
    //! one-dimensional system built by hand: `F(y) = g + J·y` with `J ∈ [−1 − a, −1 + a]`,
    //! `R = −1` (the inverse of the midpoint), `Y = [−1, 1]`, so that
    //! `K = g + [−a, a]` exactly in binary64.
    use super::*;
    use crate::scalar::Precision;
    use rug::Rational;

    fn point(x: f64) -> F {
        F::new(x, x)
    }

    /// `K` for the residual `g` and the Jacobian variation `a` (box radius 1).
    fn image(g: f64, a: f64) -> Result<f64, KrawczykEscape> {
        let jac = vec![vec![(0, F::new(-1.0 - a, -1.0 + a))]];
        krawczyk_image(&[point(g)], &jac, &[vec![-1.0]], 1.0)
    }

    /// B72 term `−R·F(u)`: with `g = 0.6`, `a = 0.5` the image `[0.1, 1.1]` leaves the box;
    /// without the residual term, or with it halved, it would be inside.
    #[test]
    fn term_b72_residual_term_decides() {
        assert!(image(0.6, 0.5).is_err());
        assert_eq!(image(0.0, 0.5).ok(), Some(0.5), "the term dropped");
        assert!(image(0.3, 0.5).is_ok(), "the term halved");
        // Either sign of the residual escapes: K is symmetric under g ↦ −g.
        assert!(image(-0.6, 0.5).is_err());
    }

    /// B72 term `(I − R·J)·Y`: the same input with the Jacobian collapsed to its midpoint
    /// (no variation over the box), or its variation halved, would be inside.
    #[test]
    fn term_b72_jacobian_over_the_box_decides() {
        assert!(image(0.6, 0.5).is_err());
        assert_eq!(image(0.6, 0.0).ok(), Some(0.6), "the variation dropped");
        assert!(image(0.6, 0.25).is_ok(), "the variation halved");
        // A variation small enough contracts: K = [0.5, 0.7] (without the identity, `I − R·J`
        // read as `−R·J = J`, K would be g + J·Y = [−0.5, 1.7], which claims less).
        assert!(image(0.6, 0.1).is_ok());
    }

    /// B72 term `Y = [−r, r]ⁿ`, the whole box on both sides of `u`: `F(y) = 1 − y/2` has
    /// its only zero at `y = 2` (closed form), outside `Y = [−1, 1]`. With `R = 2` (any real
    /// matrix is allowed) `K = −2 + 2·Y = [−4, 0]` escapes; over one end of the box only
    /// (`Y` read as `{1}`) it would be `{0}`, inside, a zero claimed where none is. Control:
    /// `F(y) = 1/4 − y/2` with `R = −2` (the inverse of `J`) gives `K = {1/2}`, the zero.
    #[test]
    fn term_b72_image_over_the_whole_box() {
        let jac = vec![vec![(0, point(-0.5))]];
        let e =
            krawczyk_image(&[point(1.0)], &jac, &[vec![2.0]], 1.0).expect_err("F has no zero in Y");
        assert_eq!((*e.image.lo(), *e.image.hi()), (-4.0, 0.0));
        assert_eq!(
            krawczyk_image(&[point(0.25)], &jac, &[vec![-2.0]], 1.0).ok(),
            Some(0.5)
        );
    }

    /// B72 term "inside the open box": `K = [0, 1]` touches the boundary of `Y = [−1, 1]`
    /// (existence but not uniqueness), on either side.
    #[test]
    fn term_b72_inclusion_is_strict() {
        let e = image(0.5, 0.5).expect_err("K = [0, 1] is not inside (−1, 1)");
        assert_eq!((*e.image.lo(), *e.image.hi()), (0.0, 1.0));
        assert!(image(-0.5, 0.5).is_err());
        assert!(image(0.5, 0.5 - f64::EPSILON).is_ok());
    }

    /// B72 hypothesis "enclosures converted outward": `±1/3` at 200 bits, whose nearest
    /// binary64 values lie on the wrong side for one end each, stay inside the converted
    /// interval; the box radius is rounded down (`1/10`'s nearest binary64 is above it).
    #[test]
    fn term_b72_enclosures_outward_radius_down() {
        let ctx = Precision::new(200).expect("precision");
        for q in [Rational::from((1, 3)), Rational::from((-1, 3))] {
            let x = outward(&I::from_rational(&q, ctx));
            let lo = Rational::from_f64(*x.lo()).expect("finite");
            let hi = Rational::from_f64(*x.hi()).expect("finite");
            assert!(lo < q && q < hi, "{q}: [{lo}, {hi}]");
        }
        let tenth = Rational::from((1, 10));
        let r = Rational::from_f64(radius_down(&tenth)).expect("finite");
        assert!(r < tenth && r > Rational::from((99, 1000)));
    }
}
