"""Peak memory of a 10⁵-face round trip through the package: numpy ``(V, F)`` in, the
surface made and flipped to intrinsic Delaunay (and, with ``--uniformize``, flattened)
in Rust, numpy arrays out.

::

    python python/benches/peak_memory.py                # torus 224 × 224: 100 352 faces
    python python/benches/peak_memory.py --uniformize   # also penner.uniformize(s, flat=True)

Linux only: the peak resident set size (``VmHWM``) is reset before each step by writing
``5`` to ``/proc/self/clear_refs``, so each step's figure is its own peak; ``increase``
is that peak minus the resident size before the step. Next to it, the bytes of the
arrays the step takes and returns, and ``tracemalloc``'s peak of the allocations made
through Python's allocators during the step (numpy arrays and Python objects, not Rust's
heap): the copies made on the Python side. Prints one JSON object.
"""

from __future__ import annotations

import argparse
import gc
import json
import os
import subprocess
import sys
import time
import tracemalloc

import numpy as np

import penner

PAGE = os.sysconf("SC_PAGE_SIZE")


def status(key: str) -> int:
    """``VmHWM`` / ``VmRSS`` of this process in bytes."""
    with open("/proc/self/status") as fh:
        for line in fh:
            if line.startswith(key + ":"):
                return int(line.split()[1]) * 1024
    raise RuntimeError(f"{key} not in /proc/self/status")


def reset_peak() -> None:
    with open("/proc/self/clear_refs", "w") as fh:
        fh.write("5")


def torus(n: int, m: int, R: float = 3.0, r: float = 1.0):
    """The torus of revolution on an n × m grid, two triangles per cell (as
    python/tests/conftest.py builds it, vectorized)."""
    t = 2 * np.pi * np.arange(n) / n
    p = 2 * np.pi * np.arange(m) / m
    T, P = np.meshgrid(t, p, indexing="ij")
    V = np.stack([(R + r * np.cos(P)) * np.cos(T), (R + r * np.cos(P)) * np.sin(T), r * np.sin(P)], -1)
    V = V.reshape(-1, 3)
    i, j = np.meshgrid(np.arange(n), np.arange(m), indexing="ij")
    i, j = i.ravel(), j.ravel()
    idx = lambda a, b: (a % n) * m + (b % m)  # noqa: E731
    F = np.empty((2 * n * m, 3), dtype=np.int64)
    F[0::2] = np.stack([idx(i, j), idx(i + 1, j), idx(i + 1, j + 1)], -1)
    F[1::2] = np.stack([idx(i, j), idx(i + 1, j + 1), idx(i, j + 1)], -1)
    return np.ascontiguousarray(V), F


STEPS = ("surface", "intrinsic_delaunay", "uniformize")


def one(name: str, n: int, m: int) -> dict:
    """Step ``name`` in this (fresh) process: the arrays made, then the call."""
    rss_import = status("VmRSS")
    V, F = torus(n, m)
    in_bytes = V.nbytes + F.nbytes
    gc.collect()
    before = status("VmRSS")
    reset_peak()
    tracemalloc.start()
    start = time.perf_counter()
    if name == "surface":
        out = penner.surface(V, F)
        arrays = []
        extra = {}
    elif name == "intrinsic_delaunay":
        F2, l2, info = penner.intrinsic_delaunay(V, F)
        arrays = [F2, l2]
        extra = {"certificate": info["certificate"], "flips": info["flips"]}
    elif name == "uniformize":
        r = penner.uniformize(V, F, flat=True)
        arrays = [a for a in (r.u, r.F_out, r.l_out, r.uv) if a is not None]
        extra = {"certified": r.certified}
    else:
        raise ValueError(name)
    seconds = time.perf_counter() - start
    _, py_peak = tracemalloc.get_traced_memory()
    tracemalloc.stop()
    peak = status("VmHWM")
    after = status("VmRSS")
    out_bytes = sum(a.nbytes for a in arrays)
    return {
        "step": name,
        "seconds": round(seconds, 2),
        "rss_after_import_MB": round(rss_import / 1e6, 1),
        "rss_with_arrays_MB": round(before / 1e6, 1),
        "peak_MB": round(peak / 1e6, 1),
        "rss_after_MB": round(after / 1e6, 1),
        "increase_MB": round((peak - before) / 1e6, 1),
        "arrays_in_MB": round(in_bytes / 1e6, 2),
        "arrays_out_MB": round(out_bytes / 1e6, 2),
        "increase_over_arrays": round((peak - before) / (in_bytes + out_bytes), 1),
        "python_allocations_peak_MB": round(py_peak / 1e6, 2),
        # Arrays handed over from Rust without a copy are views of a Rust buffer.
        "outputs_own_their_data": [bool(a.flags.owndata) for a in arrays],
        **extra,
    }


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--n", type=int, default=224)
    ap.add_argument("--m", type=int, default=224)
    ap.add_argument("--uniformize", action="store_true")
    ap.add_argument("--one", choices=STEPS, help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args.one:
        print(json.dumps(one(args.one, args.n, args.m)))
        return 0
    steps = STEPS if args.uniformize else STEPS[:2]
    rows = []
    for name in steps:  # each in a fresh process: its peak is its own
        p = subprocess.run([sys.executable, __file__, "--one", name, "--n", str(args.n), "--m", str(args.m)],
                           capture_output=True, text=True, check=True)
        rows.append(json.loads(p.stdout))
    V, F = torus(args.n, args.m)
    print(json.dumps({"faces": len(F), "vertices": len(V), "V_MB": round(V.nbytes / 1e6, 2),
                      "F_MB": round(F.nbytes / 1e6, 2), "steps": rows}, indent=1))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
