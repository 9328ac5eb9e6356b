#!/usr/bin/env python3
"""Write one mesh in the four numpy formattings, as OFF and as OBJ, for the read
benchmarks and the peer drivers.

Not part of CI. Needs `pip install numpy`.

    cargo run --release --example noisy_sphere -- 1000000 > /tmp/sphere.off
    python3 benches/peers/write_formattings.py /tmp/sphere.off /tmp/fmt

reads the OFF (vertices as float64, faces as 0-based triples) and writes into the output
directory, with `numpy.savetxt`:

    g17.off  g17.obj   `%.17g`  (shortest of fixed/scientific, 17 significant digits)
    g.off    g.obj     `%g`     (6 significant digits)
    f6.off   f6.obj    `%.6f`   (fixed point, 6 decimals)
    e17.off  e17.obj   `%.17e`  (scientific, 18 significant digits, mixed exponents)
    g17w.obj           `%.17g` with a homogeneous `w = 1` on every `v` line

The `%g` and `%.6f` files round the positions, so their meshes differ slightly from the
others (and `%.6f` may round a coordinate to 0); they are the same triangulation.
"""
import os
import sys

import numpy as np


def read_off(path):
    with open(path) as fh:
        lines = [l for l in (x.split("#")[0].strip() for x in fh) if l]
    assert lines[0].split()[0] == "OFF"
    head = lines[0].split()[1:] or lines[1].split()
    start = 1 if lines[0].split()[1:] else 2
    nv, nf = int(head[0]), int(head[1])
    v = np.array([[float(t) for t in l.split()[:3]] for l in lines[start : start + nv]])
    f = np.array(
        [[int(t) for t in l.split()[1:4]] for l in lines[start + nv : start + nv + nf]],
        dtype=np.int64,
    )
    return v, f


FORMATS = {"g17": "%.17g", "g": "%g", "f6": "%.6f", "e17": "%.17e"}


def main():
    src = sys.argv[1] if len(sys.argv) > 1 else "/tmp/sphere.off"
    out = sys.argv[2] if len(sys.argv) > 2 else "/tmp/fmt"
    os.makedirs(out, exist_ok=True)
    v, f = read_off(src)
    for name, fmt in FORMATS.items():
        with open(os.path.join(out, name + ".off"), "w") as fh:
            fh.write(f"OFF\n{len(v)} {len(f)} 0\n")
            np.savetxt(fh, v, fmt=fmt, delimiter=" ")
            np.savetxt(fh, f, fmt="3 %d %d %d")
        with open(os.path.join(out, name + ".obj"), "w") as fh:
            np.savetxt(fh, v, fmt="v " + " ".join([fmt] * 3))
            np.savetxt(fh, f + 1, fmt="f %d %d %d")
    with open(os.path.join(out, "g17w.obj"), "w") as fh:
        np.savetxt(fh, v, fmt="v %.17g %.17g %.17g 1")
        np.savetxt(fh, f + 1, fmt="f %d %d %d")
    print(f"{len(v)} vertices, {len(f)} faces written to {out}")


if __name__ == "__main__":
    main()
