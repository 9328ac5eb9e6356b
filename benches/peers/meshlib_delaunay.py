#!/usr/bin/env python3
"""Time MeshLib's load + intrinsic Delaunay edge flips on OFF/OBJ files, the peer of
`penner delaunay FILE --precision f64`.

Not part of CI. Needs `pip install meshlib`.

    python3 benches/peers/meshlib_delaunay.py /tmp/fmt/g17.off [/tmp/fmt/g17.obj ...]

For each file it loads the mesh (`mrmeshpy.loadMesh`), builds its edge lengths
(`EdgeLengthMesh.fromMesh`, ℓ = |p_j − p_i| in float32 positions) and flips to the
intrinsic Delaunay triangulation (`makeDeloneEdgeFlips` on the `EdgeLengthMesh`, every edge
considered at most NUM_ITERS times, default 1000), and prints the wall time of load and of
flips and the number of flips; with CHECK=1 also how many edges MeshLib's own `isDelone`
test still flags (not timed, slow: a Python loop over the edges). For the whole command,
wrap it in `/usr/bin/time -f '%U %M'` with one file.
"""
import os
import sys
import time

import meshlib.mrmeshpy as mr


def main():
    iters = int(os.environ.get("NUM_ITERS", "1000"))
    for path in sys.argv[1:]:
        t0 = time.perf_counter()
        mesh = mr.loadMesh(path)
        t1 = time.perf_counter()
        elm = mr.EdgeLengthMesh.fromMesh(mesh)
        flips = mr.makeDeloneEdgeFlips(elm, mr.IntrinsicDeloneSettings(), iters)
        t2 = time.perf_counter()
        top = elm.topology
        bad = "not checked"
        if os.environ.get("CHECK") == "1":
            bad = sum(
                1
                for e in range(top.undirectedEdgeSize())
                if not top.isLoneEdge(mr.EdgeId(2 * e))
                and not elm.isDelone(mr.UndirectedEdgeId(e))
            )
        print(
            f"{os.path.basename(path)}: F={top.numValidFaces()} load {(t1 - t0) * 1e3:.0f} ms, "
            f"flips {(t2 - t1) * 1e3:.0f} ms ({flips} flips), "
            f"load+flips {(t2 - t0) * 1e3:.0f} ms, edges not Delaunay by isDelone: {bad}"
        )


if __name__ == "__main__":
    main()
