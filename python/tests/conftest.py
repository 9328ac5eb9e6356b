"""Surfaces built here with numpy, and the independent numpy computations the tests
compare penner's results with (lengths, corner angles by the law of cosines, Euler
characteristic)."""

import numpy as np
import pytest


def outward(V, F):
    """F with every face turned so its normal points away from the origin (convex solids
    centred at the origin)."""
    F = np.array(F, dtype=np.int64)
    for k, (a, b, c) in enumerate(F):
        n = np.cross(V[b] - V[a], V[c] - V[a])
        if np.dot(n, V[a] + V[b] + V[c]) < 0:
            F[k] = [a, c, b]
    return F


def tetrahedron():
    V = np.array([[1, 1, 1], [1, -1, -1], [-1, 1, -1], [-1, -1, 1]], dtype=np.float64)
    F = outward(V, [[0, 1, 2], [0, 2, 3], [0, 3, 1], [1, 2, 3]])
    return V, F


def octahedron():
    V = np.array(
        [[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]],
        dtype=np.float64,
    )
    F = [[a, b, c] for a in (0, 1) for b in (2, 3) for c in (4, 5)]
    return V, outward(V, F)


def torus(n=6, m=6, R=3.0, r=1.0):
    """An embedded torus of revolution sampled on an n × m grid (genus 1)."""
    th = 2 * np.pi * np.arange(n) / n
    ph = 2 * np.pi * np.arange(m) / m
    V = np.array(
        [
            [(R + r * np.cos(p)) * np.cos(t), (R + r * np.cos(p)) * np.sin(t), r * np.sin(p)]
            for t in th
            for p in ph
        ]
    )
    idx = lambda i, j: (i % n) * m + (j % m)  # noqa: E731
    F = []
    for i in range(n):
        for j in range(m):
            F.append([idx(i, j), idx(i + 1, j), idx(i + 1, j + 1)])
            F.append([idx(i, j), idx(i + 1, j + 1), idx(i, j + 1)])
    return V, np.array(F, dtype=np.int64)


def face_lengths(V, F):
    """l[f, i] = |V[F[f, i+1]] − V[F[f, i+2]]|, the side opposite corner i."""
    return np.stack(
        [np.linalg.norm(V[F[:, (i + 1) % 3]] - V[F[:, (i + 2) % 3]], axis=1) for i in range(3)],
        axis=1,
    )


def corner_angles(l):
    """Corner angles from per-face lengths by the law of cosines."""
    a = np.empty_like(l)
    for i in range(3):
        x, y, z = l[:, i], l[:, (i + 1) % 3], l[:, (i + 2) % 3]
        a[:, i] = np.arccos(np.clip((y * y + z * z - x * x) / (2 * y * z), -1, 1))
    return a


def angle_sums(F, l, n):
    s = np.zeros(n)
    np.add.at(s, F.ravel(), corner_angles(l).ravel())
    return s


def euler(F, n):
    edges = {tuple(sorted((int(f[i]), int(f[(i + 1) % 3])))) for f in F for i in range(3)}
    return n - len(edges) + len(F)


def write_obj(path, V, F):
    with open(path, "x") as fh:
        for p in V:
            fh.write("v {} {} {}\n".format(*[repr(float(x)) for x in p]))
        for f in F:
            fh.write("f {} {} {}\n".format(*[int(i) + 1 for i in f]))
    return path


@pytest.fixture
def tet():
    return tetrahedron()


@pytest.fixture
def octa():
    return octahedron()
