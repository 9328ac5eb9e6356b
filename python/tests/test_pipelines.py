"""The library pipelines from Python — uniformization with boundary, to the sphere and
hyperbolic; the flips to intrinsic Delaunay; the maximal circle packing; check's failure
files — each against an independent computation in numpy (angle sums by the law of
cosines, Euclidean or hyperbolic; the Delaunay condition from the lengths; scipy's
Delaunay triangulation or a brute-force empty-circle test; tangency of the circles), the
oracle re-checking the claims, and a negative control for each."""

import numpy as np
import pytest

import penner
from conftest import angle_sums, corner_angles, face_lengths, octahedron, torus

EPS64 = np.finfo(np.float64).eps


def grid(n, m):
    """A planar n × m grid of unit squares, each split by a diagonal (a disk)."""
    V = np.array([[i, j, 0.0] for j in range(m + 1) for i in range(n + 1)])
    idx = lambda i, j: j * (n + 1) + i  # noqa: E731
    F = []
    for j in range(m):
        for i in range(n):
            F += [[idx(i, j), idx(i + 1, j), idx(i + 1, j + 1)], [idx(i, j), idx(i + 1, j + 1), idx(i, j + 1)]]
    return V, np.array(F, dtype=np.int64)


def boundary_vertices(F):
    """Vertices on a boundary edge (an edge in one face only)."""
    count = {}
    for f in F:
        for i in range(3):
            e = tuple(sorted((int(f[i]), int(f[(i + 1) % 3]))))
            count[e] = count.get(e, 0) + 1
    return sorted({v for e, c in count.items() if c == 1 for v in e})


def edge_pairs(F):
    """Interior edges as pairs of (face, corner opposite the edge) on both sides, from the
    directed sides (F[f, i+1], F[f, i+2]); refuses repeated directed sides."""
    side = {}
    for f, t in enumerate(F):
        for i in range(3):
            key = (int(t[(i + 1) % 3]), int(t[(i + 2) % 3]))
            assert key not in side, "a repeated edge: the pairing by vertices is ambiguous"
            side[key] = (f, i)
    return [(side[(a, b)], side[(b, a)]) for (a, b) in side if a < b and (b, a) in side]


def cot_sums(F, l):
    """cot α + cot β over the interior edges, from the lengths alone (cot of the corner
    opposite side x: (y² + z² − x²)/(4·area), area by Heron)."""
    x, y, z = l[:, 0], l[:, 1], l[:, 2]
    s = (x + y + z) / 2
    area = np.sqrt(np.maximum(s * (s - x) * (s - y) * (s - z), 0))
    cot = np.empty_like(l)
    for i in range(3):
        a, b, c = l[:, i], l[:, (i + 1) % 3], l[:, (i + 2) % 3]
        cot[:, i] = (b * b + c * c - a * a) / (4 * area)
    pairs = edge_pairs(F)
    return np.array([cot[f, i] + cot[g, j] for (f, i), (g, j) in pairs]), cot


def hyperbolic_angle_sums(F, l, n):
    """Angle sums from hyperbolic lengths: cos α = (cosh b cosh c − cosh a)/(sinh b sinh c)."""
    ang = np.empty_like(l)
    for i in range(3):
        a, b, c = l[:, i], l[:, (i + 1) % 3], l[:, (i + 2) % 3]
        ang[:, i] = np.arccos(np.clip((np.cosh(b) * np.cosh(c) - np.cosh(a)) / (np.sinh(b) * np.sinh(c)), -1, 1))
    s = np.zeros(n)
    np.add.at(s, F.ravel(), ang.ravel())
    return s


def skewed_octahedron():
    V, F = octahedron()
    V = V * np.array([1.0, 1.3, 0.8])
    V[0] = [1.2, 0.1, 0.2]
    return V, F


# --- uniformize: a surface with boundary ------------------------------------------------


def test_boundary_flat_with_even_boundary_against_numpy_angles():
    V, F = grid(3, 3)
    V[5, :2] += [0.2, 0.1]  # an interior vertex off the grid
    r = penner.uniformize(V, F, flat=True)
    assert r.target == "boundary" and r.certified, r.reason
    assert r.metric in ("input", "rounded") and r.reason is None
    assert r.details["layout_of"].startswith("the surface") and r.details["folds"] == 0
    # numpy's law of cosines on l_out: 2π inside, π − 2π/#boundary on the boundary (the
    # curvature 2πχ = 2π spread evenly).
    bd = boundary_vertices(F)
    want = np.full(len(V), 2 * np.pi)
    want[bd] = np.pi - 2 * np.pi / len(bd)
    np.testing.assert_allclose(angle_sums(r.F_out, r.l_out, len(V)), want, atol=1e-9)
    # The layout is one flat disk: every corner of a vertex at the same place, and the
    # triangles have the lengths l_out.
    pos = {}
    for f in range(len(r.F_out)):
        for i in range(3):
            pos.setdefault(int(r.F_out[f, i]), []).append(r.uv[f, i])
    assert max(np.ptp(np.array(p), axis=0).max() for p in pos.values()) < 1e-9
    np.testing.assert_allclose(
        np.linalg.norm(r.uv[:, [1, 2, 0]] - r.uv[:, [2, 0, 1]], axis=2), r.l_out, rtol=1e-9
    )
    # The oracle re-checks the double's claim; a tampered one is not accepted.
    assert r.claim["kind"] == "uniformization"
    assert penner.certify(r.claim)["verdict"] == "holds"
    bad = dict(r.claim, u=list(r.claim["u"]))
    bad["u"][0] = "0.25"
    assert penner.certify(bad)["verdict"] != "holds"


def test_boundary_rectangle_targets_and_refusals():
    V, F = grid(2, 3)
    corners = [0, 2, 9, 11]
    bd = boundary_vertices(F)
    # φ_v/π: 1/2 at the four corners, 1 elsewhere on the boundary, 2 inside: a rectangle.
    t = [2] * len(V)
    for v in bd:
        t[v] = "1/2" if v in corners else 1
    r = penner.uniformize(V, F, targets=t, precision="f64")
    assert r.certified, r.reason
    want = np.pi * np.array([float(eval(str(x))) for x in t])
    np.testing.assert_allclose(angle_sums(r.F_out, r.l_out, len(V)), want, atol=1e-9)
    assert penner.certify(r.claim)["verdict"] == "holds"
    # Negative controls: no targets; targets against Gauss–Bonnet; not asked to certify.
    with pytest.raises(penner.InputError, match="required"):
        penner.uniformize(V, F)
    with pytest.raises(penner.InputError):
        penner.uniformize(V, F, targets=[2] * len(V))
    r = penner.uniformize(V, F, flat=True, certify=False)
    assert not r.certified and r.claim is None and "certify=False" in r.reason


# --- uniformize: the sphere -------------------------------------------------------------


def test_sphere_positions_are_inscribed_convex_and_conformal():
    V, F = skewed_octahedron()
    r = penner.uniformize(V, F, sphere=True)
    assert r.target == "sphere" and r.certified, r.reason
    assert r.uv.shape == (6, 3) and r.metric == "input"
    # On the unit sphere, and convex: every face's plane has the other vertices strictly
    # on one side, the same side for every face (the faces all turn the same way).
    np.testing.assert_allclose(np.linalg.norm(r.uv, axis=1), 1, atol=1e-12)
    P = r.uv
    signs = set()
    for a, b, c in r.F_out:
        nrm = np.cross(P[b] - P[a], P[c] - P[a])
        side = ((P - P[a]) @ nrm)[[v for v in range(6) if v not in (a, b, c)]]
        assert np.all(np.abs(side) > 1e-6)
        signs |= set(np.sign(side).tolist())
    assert len(signs) == 1
    # Conformal: the length cross ratios of the chords equal the input's on every
    # interior edge (both on the input triangulation when no flip happened).
    if r.euclidean_flips == 0 and r.ptolemy_flips == 0:
        l_in, l_out = face_lengths(V, F), face_lengths(P, F)
        for (f, i), (g, j) in edge_pairs(F):
            cr = lambda l: (l[f, (i + 1) % 3] * l[g, (j + 1) % 3]) / (l[f, (i + 2) % 3] * l[g, (j + 2) % 3])  # noqa: E731
            assert abs(np.log(cr(l_out)) - np.log(cr(l_in))) < 1e-9
    # The planar disk: the surface minus the pole's star, laid out flat.
    assert r.layout.shape == (len(r.F_layout), 3, 2) and r.pole not in r.F_layout
    claim = r.claim
    assert claim["kind"] == "sphere_uniformization"
    assert penner.certify(claim)["verdict"] == "holds"
    # Negative controls: a tampered claim; refused options and surfaces.
    bad = dict(claim, u=list(claim["u"]))
    bad["u"][0] = "0.5"
    assert penner.certify(bad)["verdict"] != "holds"
    with pytest.raises(penner.InputError, match="dd"):
        penner.uniformize(V, F, sphere=True, precision="dd")
    with pytest.raises(penner.InputError, match="targets"):
        penner.uniformize(V, F, sphere=True, flat=True)
    with pytest.raises(penner.InputError, match="pole"):
        penner.uniformize(V, F, sphere=True, pole=9)
    with pytest.raises(penner.InputError):
        penner.uniformize(*torus(4, 4), sphere=True)


# --- uniformize: hyperbolic -------------------------------------------------------------


def test_hyperbolic_cone_torus_against_numpy_hyperbolic_angles():
    V, F = torus(4, 4)
    r = penner.uniformize(V, F, hyperbolic=True, targets=["7/4"] * 16)
    assert r.target == "hyperbolic" and r.certified, r.reason
    assert r.uv is None and r.metric in ("input", "rounded") and r.radius > 0
    # Hyperbolic law of cosines on the returned lengths gives the cone angles 7π/4.
    np.testing.assert_allclose(hyperbolic_angle_sums(r.F_out, r.l_out, 16), 1.75 * np.pi, atol=1e-9)
    # Gauss–Bonnet: the area Σ(2π − Θ) − 2πχ = 16·π/4.
    assert abs(r.details["gauss_bonnet"] - 4 * np.pi) < 1e-12
    assert r.claim["kind"] == "hyperbolic_uniformization"
    assert penner.certify(r.claim)["verdict"] == "holds"
    bad = dict(r.claim, u=list(r.claim["u"]))
    bad["u"][3] = "0.125"
    assert penner.certify(bad)["verdict"] != "holds"
    # Negative control: flat targets on a torus leave no area (Gauss–Bonnet).
    with pytest.raises(penner.InputError, match="Gauss–Bonnet"):
        penner.uniformize(V, F, hyperbolic=True)
    with pytest.raises(penner.InputError, match="at most one"):
        penner.uniformize(V, F, hyperbolic=True, sphere=True)


# --- intrinsic Delaunay -----------------------------------------------------------------


def planar_point_set(seed=3, k=14, inner=30):
    """k points on an ellipse (convex position, no four on a circle: no Delaunay ties) and
    `inner` random points inside, triangulated without regard to Delaunay: a fan of the
    polygon, then each inner point splits the triangle containing it into three."""
    rng = np.random.default_rng(seed)
    a = np.sort(rng.uniform(0, 2 * np.pi, k))
    P = [np.array([np.cos(t), 0.6 * np.sin(t)]) for t in a]
    F = [[0, i, i + 1] for i in range(1, k - 1)]
    while len(P) < k + inner:
        q = rng.uniform(-0.8, 0.8, 2)
        if q[0] ** 2 + (q[1] / 0.6) ** 2 > 0.64:
            continue
        for f, (x, y, z) in enumerate(F):
            bc = np.linalg.solve(np.array([P[y] - P[x], P[z] - P[x]]).T, q - P[x])
            if bc.min() > 1e-3 and bc.sum() < 1 - 1e-3:
                n = len(P)
                P.append(q)
                F[f:f + 1] = [[x, y, n], [y, z, n], [z, x, n]]
                break
    V = np.hstack([np.array(P), np.zeros((len(P), 1))])
    return V, np.array(F, dtype=np.int64)


def empty_circle(V, F, tol=1e-12):
    """Brute force: no point strictly inside any face's circumcircle. With b, c, d
    relative to a and lifted to (x, y, x² + y²), det[b; c; d] has the sign opposite to
    the orientation of (a, b, c) exactly when d is inside the circle through a, b, c."""
    P = V[:, :2]
    for a, b, c in F:
        u, w = P[b] - P[a], P[c] - P[a]
        orient = np.sign(u[0] * w[1] - u[1] * w[0])
        rows = [np.append(P[v] - P[a], (P[v] - P[a]) @ (P[v] - P[a])) for v in (b, c)]
        for d in range(len(P)):
            if d in (a, b, c):
                continue
            w = P[d] - P[a]
            if orient * np.linalg.det(np.array(rows + [np.append(w, w @ w)])) < -tol:
                return False
    return True


def test_intrinsic_delaunay_of_a_planar_point_set_is_its_delaunay_triangulation():
    V, F = planar_point_set()
    # Negative control: the input is far from Delaunay in numpy's eyes.
    s_in, _ = cot_sums(F, face_lengths(V, F))
    assert s_in.min() < -0.1 and not empty_circle(V, F)
    F2, l2, info = penner.intrinsic_delaunay(V, F)
    assert info["flips"] > 0 and info["certificate"] == "input_metric" and info["holds"]
    assert info["summary"]["flips"] == info["flips"] and info["summary"]["certificate"] == "input_metric"
    # l_out are the planar distances of the same points (Euclidean flips of a flat metric).
    np.testing.assert_allclose(l2, face_lengths(V, F2), rtol=1e-13)
    # The Delaunay condition in numpy from the lengths: cot α + cot β ≥ −1e-9 (the
    # binary64 law of cosines on these well-shaped triangles is good to ~1e-13).
    s_out, _ = cot_sums(F2, l2)
    assert s_out.min() >= -1e-9
    faces = {tuple(sorted(f)) for f in F2.tolist()}
    try:
        from scipy.spatial import Delaunay
    except ImportError:  # the independent check without scipy: empty circumcircles
        assert empty_circle(V, F2)
    else:
        assert faces == {tuple(sorted(f)) for f in Delaunay(V[:, :2]).simplices.tolist()}
        assert empty_circle(V, F2)


def test_intrinsic_delaunay_of_a_bumpy_sphere_options_and_refusals():
    rng = np.random.default_rng(7)
    V, F = octahedron()
    # Subdivide once (24 → 32 faces… via edge midpoints) and push vertices off the sphere.
    mids, Fs, Vl = {}, [], list(V)
    def mid(a, b):
        k = tuple(sorted((a, b)))
        if k not in mids:
            mids[k] = len(Vl)
            Vl.append((V[a] + V[b]) / 2)
        return mids[k]
    for a, b, c in F:
        x, y, z = mid(a, b), mid(b, c), mid(c, a)
        Fs += [[a, x, z], [x, b, y], [z, y, c], [x, y, z]]
    W = np.array(Vl) * rng.uniform(0.7, 1.3, (len(Vl), 1))
    Fs = np.array(Fs)
    for flips, prec in (("euclidean", "f64"), ("euclidean", 256), ("ptolemy", "dd")):
        F2, l2, info = penner.intrinsic_delaunay(W, Fs, flips=flips, precision=prec)
        assert info["holds"], info
        s_out, _ = cot_sums(F2, l2)
        assert s_out.min() >= -1e-9, (flips, prec)
    # The angle sums of the Euclidean result are the input's (the cone metric is kept).
    F2, l2, info = penner.intrinsic_delaunay(W, Fs)
    np.testing.assert_allclose(
        angle_sums(F2, l2, len(W)), angle_sums(Fs, face_lengths(W, Fs), len(W)), atol=1e-10
    )
    with pytest.raises(penner.InputError, match="flips"):
        penner.intrinsic_delaunay(W, Fs, flips="lawson")
    with pytest.raises(penner.InputError, match="exact"):
        penner.intrinsic_delaunay(W, Fs, precision="exact")
    with pytest.raises(penner.InputError, match="precision"):
        penner.intrinsic_delaunay(W, Fs, precision="f64,dd")
    bad = Fs.copy()
    bad[0, 0] = 99
    with pytest.raises(penner.InputError, match=r"F\[0, 0\]"):
        penner.intrinsic_delaunay(W, bad)


def test_intrinsic_delaunay_from_exact_lengths():
    # Per-face lengths (libigl's layout) with exact Ptolemy flips: a kite split by its
    # long diagonal (0,0)–(4,0); one flip to (2,1)–(2,−1), of length 2 exactly.
    F = np.array([[0, 1, 2], [1, 0, 3]])
    V = np.array([[0, 0, 0], [4, 0, 0], [2, 1, 0], [2, -1, 0]], float)
    l = face_lengths(V, F)
    F2, l2, info = penner.intrinsic_delaunay(F=F, l=l)
    assert info["flips"] == 1
    assert np.isclose(l2, 2.0, rtol=1e-15).sum() == 2  # the new diagonal, in both faces
    s, _ = cot_sums(F2, l2)
    assert s.min() >= -1e-12
    # Exact Ptolemy flips of the binary64 lengths taken exactly: the Ptolemy diagonal
    # (√5·√5 + √5·√5)/4 = 5/2 (rounded lengths: within a few ulps).
    F3, l3, info = penner.intrinsic_delaunay(F=F, l=l, flips="ptolemy", precision="exact")
    assert info["flips"] == 1 and info["certificate"] == "input_metric"
    assert np.isclose(l3, 2.5, rtol=1e-14).sum() == 2


# --- pack -------------------------------------------------------------------------------


def tangency_defects(p):
    """|c_i − c_j| − (r_i + r_j) per edge of the packed faces, and 1 − |c_i| − r_i at the
    circles tangent to the unit circle."""
    c, r, F = p["centres"], p["radii"], p["faces"]
    E = {tuple(sorted((int(f[i]), int(f[(i + 1) % 3])))) for f in F for i in range(3)}
    E = np.array(sorted(E))
    d = np.linalg.norm(c[E[:, 0]] - c[E[:, 1]], axis=1) - (r[E[:, 0]] + r[E[:, 1]])
    u = p["unit_disk"]
    b = 1 - np.linalg.norm(c[u], axis=1) - r[u]
    return d, b


def test_pack_disk_tangency_in_numpy_and_a_perturbed_radius():
    V, F = grid(3, 2)
    p = penner.pack(F, mode="disk", epsilon="1e-20")
    assert p["certified"] and p["verdict"] == "holds", p["reason"]
    assert p["centres"].shape == (len(V), 2) and p["radii"].shape == (len(V),)
    assert np.all(p["radii"] > 0) and p["max_defect"] <= 1e-20
    # The certified exact defects are ≤ ε; rounding centres and radii to binary64 moves
    # each quantity by ≤ 2⁻⁵³·|x| and numpy's norm adds a few ulps: tolerance
    # ε + 8·eps·(|c_i| + |c_j| + r_i + r_j + 1).
    tol = 1e-20 + 8 * EPS64 * 4
    d, b = tangency_defects(p)
    assert np.abs(d).max() <= tol and np.abs(b).max() <= tol, (np.abs(d).max(), np.abs(b).max())
    assert p["unit_disk"].sum() == len(boundary_vertices(F))
    # Negative control: a radius perturbed by 1e-9 fails the same numpy check.
    q = dict(p, radii=p["radii"].copy())
    q["radii"][5] *= 1 + 1e-9
    d, b = tangency_defects(q)
    assert max(np.abs(d).max(), np.abs(b).max()) > tol
    # The exact document as `penner pack -o` writes it.
    assert p["document"]["status"] == "holds" and len(p["document"]["radii"]) == len(V)


def test_pack_sphere_caps_are_tangent_in_numpy():
    V, F = octahedron()
    p = penner.pack(F, mode="sphere", puncture=0, bits=128, epsilon="1e-20")
    assert p["certified"], p["reason"]
    caps = p["caps"]
    assert caps.shape == (6, 4) and np.isnan(p["centres"][0]).all()
    N, H = caps[:, :3], caps[:, 3]
    # Inversive distance (H H' − N·N')/√((|N|² − H²)(|N'|² − H'²)) = 1 on every edge.
    E = {tuple(sorted((int(f[i]), int(f[(i + 1) % 3])))) for f in F for i in range(3)}
    I = [
        (H[a] * H[b] - N[a] @ N[b]) / np.sqrt((N[a] @ N[a] - H[a] ** 2) * (N[b] @ N[b] - H[b] ** 2))
        for a, b in E
    ]
    assert np.abs(np.array(I) - 1).max() <= 1e-20 + 64 * EPS64
    d, b = tangency_defects(p)  # the disk picture, without the puncture
    assert np.abs(d).max() <= 1e-14 and np.abs(b).max() <= 1e-14
    # Negative control: a perturbed cap height is no longer tangent.
    H2 = H.copy()
    H2[2] += 1e-8
    a, b = 2, [v for v in range(6) if (min(2, v), max(2, v)) in E][0]
    I2 = (H2[a] * H2[b] - N[a] @ N[b]) / np.sqrt((N[a] @ N[a] - H2[a] ** 2) * (N[b] @ N[b] - H2[b] ** 2))
    assert abs(I2 - 1) > 64 * EPS64


def test_pack_refusals_and_an_undecided_result():
    V, F = torus(4, 4)
    with pytest.raises(penner.InputError):
        penner.pack(F, mode="disk")
    with pytest.raises(penner.InputError, match="mode"):
        penner.pack(F, mode="plane")
    with pytest.raises(penner.InputError, match="epsilon"):
        penner.pack(grid(2, 2)[1], epsilon="x")
    # The tetrahedron punctured at a vertex leaves no interior circle: not computed is a
    # result (undecided, with the reason), never an exception.
    T = np.array([[0, 1, 2], [0, 2, 3], [0, 3, 1], [1, 3, 2]])
    p = penner.pack(T, mode="sphere")
    assert not p["certified"] and p["verdict"] == "undecided" and "interior" in p["reason"]


# --- check: failures --------------------------------------------------------------------


def test_check_failures_hold_minimal_reproducers():
    V, F = octahedron()
    rows = penner.check(V, F, precision=("f64",), only=["T01"])
    assert rows.failures == [] and isinstance(rows, list)
    # The negative control of T01 fails by construction: its failure document carries a
    # reproducing surface that the check fails on again.
    rows = penner.check(V, F, precision=("f64",), only=["T01"], negative_controls=True)
    assert any(r["result"]["verdict"] == "fails" for r in rows)
    (f,) = rows.failures
    assert f["penner_failure"] == 1 and f["check"].startswith("T01") and f["precision"] == "f64"
    assert f["source_faces"] == 8 and f["witnesses"]
    assert "faces" in f["surface"] or "surface" in f["surface"] or f["surface"]
    none = penner.check(V, F, precision=("f64",), only=["T01"], negative_controls=True, reproducers=False)
    assert none.failures == [] and [r["result"]["verdict"] for r in none] == [r["result"]["verdict"] for r in rows]
