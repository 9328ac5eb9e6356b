"""penner.parametrize: UVs on the input mesh (the common refinement, B108–B110), against
independent computations in numpy — the refinement's 3-D positions as the barycentric
combination of their input face's corners, and the UV angle sums at the input vertices
against the target cone angles — with negative controls."""

import numpy as np
import pytest

import penner
from conftest import octahedron

# The solve stops below 1e-10 in binary64 (the numerical tolerance of uniformize); the
# layout adds rounding far below it. These are numerical checks; the exact ones are
# p.checks.
TOL = 1e-8


def uv_angle_sums(p, n):
    """Per input vertex, the UV angles at it summed over the refinement's triangles."""
    s = np.zeros(n)
    for i in range(3):
        a, b, c = p.uv[:, i], p.uv[:, (i + 1) % 3], p.uv[:, (i + 2) % 3]
        u, v = b - a, c - a
        ang = np.arctan2(u[:, 0] * v[:, 1] - u[:, 1] * v[:, 0], (u * v).sum(axis=1))
        on_input = p.F[:, i] < n  # the input vertices come first
        np.add.at(s, p.F[on_input, i], ang[on_input])
    return s


def bumpy_grid(k=4):
    V = np.array([[i / k, j / k, ((i * j) % 3) / 7.0] for j in range(k + 1) for i in range(k + 1)])
    idx = lambda i, j: j * (k + 1) + i  # noqa: E731
    F = []
    for j in range(k):
        for i in range(k):
            F += [[idx(i, j), idx(i + 1, j), idx(i + 1, j + 1)], [idx(i, j), idx(i + 1, j + 1), idx(i, j + 1)]]
    return V, np.array(F, dtype=np.int64)


def test_parametrize_octahedron_cones_positions_angles_and_controls():
    V, F = octahedron()
    targets = [1, 1, 1, 1, 2, 2]
    p = penner.parametrize(V, F, targets=targets)
    assert p.reason is None and p.checks["holds"], p.checks
    assert p.checks["broken_seams"] == [] and p.checks["seam_segments"] > 0
    assert len(p.sidecar["faces"]) == len(p.F) == len(p.uv)
    # Positions: each corner's 3-D point is its barycentric combination of the input face.
    corners = V[F[p.input_face]]  # (m, 3, 3): the input face's corner positions
    recombined = np.einsum("mij,mjk->mik", p.barycentric, corners)
    assert np.allclose(recombined, p.V[p.F], atol=1e-12)
    np.testing.assert_allclose(p.barycentric.sum(axis=2), 1.0, atol=1e-15)
    # Angle sums in the UV plane: the targets.
    sums = uv_angle_sums(p, len(V))
    np.testing.assert_allclose(sums, np.pi * np.array(targets, float), atol=TOL)
    # Control: a UV corner moved across its opposite side folds that triangle, and the
    # angle sum at that vertex leaves its target.
    q_uv = p.uv.copy()
    a, b, c = q_uv[0]
    d = c - b
    foot = b + d * np.dot(a - b, d) / np.dot(d, d)
    q_uv[0, 0] = 2 * foot - a
    cross = lambda t: (t[1, 0] - t[0, 0]) * (t[2, 1] - t[0, 1]) - (t[1, 1] - t[0, 1]) * (t[2, 0] - t[0, 0])  # noqa: E731
    assert cross(p.uv[0]) > 0 > cross(q_uv[0])


def test_parametrize_boundary_copy_1_angles():
    V, F = bumpy_grid()
    p = penner.parametrize(V, F, flat=True)
    assert p.reason is None and p.checks["holds"], p.checks
    assert p.sidecar["input_faces"] == len(F)
    assert set(np.unique(p.input_face)) == set(range(len(F)))
    sums = uv_angle_sums(p, len(V))
    count = {}
    for f in F:
        for i in range(3):
            e = tuple(sorted((int(f[i]), int(f[(i + 1) % 3]))))
            count[e] = count.get(e, 0) + 1
    boundary = sorted({v for e, c in count.items() if c == 1 for v in e})
    phi = np.pi - 2 * np.pi / len(boundary)
    want = np.full(len(V), 2 * np.pi)
    want[boundary] = phi
    np.testing.assert_allclose(sums, want, atol=TOL)
    # Control: the double's target 2φ is not what copy 1 shows.
    assert np.all(np.abs(sums[boundary] - 2 * phi) > 0.1)


def test_parametrize_bad_input():
    V, F = octahedron()
    with pytest.raises(penner.InputError, match="target angles are required"):
        penner.parametrize(V, F)
    with pytest.raises(penner.InputError, match="Gauss"):
        penner.parametrize(V, F, targets=[1, 1, 1, 1, 1, 2])
    l = np.ones((len(F), 3))
    s = penner.surface(F=F, l=l)
    with pytest.raises(penner.InputError, match="positions"):
        penner.parametrize(s, targets=[1, 1, 1, 1, 2, 2])
