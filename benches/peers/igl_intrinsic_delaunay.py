#!/usr/bin/env python3
"""Time libigl's intrinsic Delaunay (flips only, and flips + cotan Laplacian) on the OBJ
meshes written by `PENNER_EXPORT_MESHES=<dir> cargo bench --bench delaunay`.

Not part of CI. Needs `pip install libigl numpy scipy`.

    python3 benches/peers/igl_intrinsic_delaunay.py /tmp/penner-meshes

For each mesh it prints the median wall time of
`igl.intrinsic_delaunay_triangulation` (flips only, from precomputed edge lengths) and
`igl.intrinsic_delaunay_cotmatrix` (flips + Laplacian), and how many edges libigl's own
`is_intrinsic_delaunay` flags afterwards (its test is a floating-point comparison).
"""
import glob
import os
import sys
import time

import igl
import numpy as np


def read_obj(path):
    v, f = [], []
    with open(path) as fh:
        for line in fh:
            p = line.split()
            if not p:
                continue
            if p[0] == "v":
                v.append([float(x) for x in p[1:4]])
            elif p[0] == "f":
                f.append([int(x.split("/")[0]) - 1 for x in p[1:4]])
    return np.array(v, dtype=np.float64), np.array(f, dtype=np.int64)


def median_time(fn, repeats):
    ts = []
    out = None
    for _ in range(repeats):
        t0 = time.perf_counter()
        out = fn()
        ts.append(time.perf_counter() - t0)
    ts.sort()
    return ts[len(ts) // 2], out


def main():
    d = sys.argv[1] if len(sys.argv) > 1 else "/tmp/penner-meshes"
    repeats = int(os.environ.get("REPEATS", "5"))
    for path in sorted(glob.glob(os.path.join(d, "*.obj"))):
        V, F = read_obj(path)
        l = igl.edge_lengths(V, F)
        t_flip, res = median_time(lambda: igl.intrinsic_delaunay_triangulation(l, F), repeats)
        l2, F2 = res[0], res[1]
        t_lap, _ = median_time(lambda: igl.intrinsic_delaunay_cotmatrix(V, F), repeats)
        D = igl.is_intrinsic_delaunay(l2, F2)
        bad = int((D == 0).sum())
        print(
            f"{os.path.basename(path)}: F={len(F)} flips-only {t_flip * 1e3:.1f} ms, "
            f"flips+cotmatrix {t_lap * 1e3:.1f} ms, half-edges not Delaunay by igl's test: {bad}"
        )


if __name__ == "__main__":
    main()
