#!/usr/bin/env bash
# Fill DIR with the long-mode real meshes: the Stanford bunny from the pymeshlab wheel
# (PyPI), and, given a checkout of github.com/geometryprocessing/ConformalIdealDelaunay,
# its elephant and fertility examples with their cone targets as exact Θ/π strings.
# Usage: tests/data/real/fetch_long.sh DIR [CONFORMAL_IDEAL_DELAUNAY_CHECKOUT]
set -euo pipefail
dir=$1
mkdir -p "$dir"
tmp=$(mktemp -d)
python3 -m pip download --no-deps --dest "$tmp" pymeshlab==2025.7.post1 >/dev/null
python3 - "$tmp" "$dir" <<'PY'
import glob, sys, zipfile
tmp, out = sys.argv[1], sys.argv[2]
with zipfile.ZipFile(glob.glob(f"{tmp}/pymeshlab-*.whl")[0]) as z:
    for name in z.namelist():
        if name.endswith("sample_meshes/bunny.obj"):
            open(f"{out}/bunny.obj", "wb").write(z.read(name))
PY
if [ "$#" -ge 2 ]; then
  for m in elephant fertility_tri; do
    cp "$2/data/examples/$m.obj" "$dir/"
    python3 - "$2/data/examples/${m}_Th_hat" "$dir/${m}_targets.json" <<'PY'
import math, sys
from fractions import Fraction
th = [float(x) for x in open(sys.argv[1]).read().split()]
q = [Fraction(round(t / math.pi * 4), 4) for t in th]
assert all(abs(t / math.pi - float(a)) < 1e-12 for t, a in zip(th, q))
open(sys.argv[2], "w").write("[" + ", ".join(f'"{a}"' for a in q) + "]\n")
PY
  done
fi
rm -rf "$tmp"
ls -la "$dir"
