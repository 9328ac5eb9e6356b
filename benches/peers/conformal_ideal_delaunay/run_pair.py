#!/usr/bin/env python3
"""Prepare the inputs and time the whole `penner uniformize` command against
ConformalIdealDelaunay's double-precision run (the `cid_run` driver of build.sh).

    python3 benches/peers/conformal_ideal_delaunay/run_pair.py prepare [--dir D]
    python3 benches/peers/conformal_ideal_delaunay/run_pair.py run [--dir D] [-n 3] [MESH ...]

`prepare` writes into D (default /work/peer-cid/inputs), for every mesh, `M.obj`,
`M-targets.json` (Θ_i/π as exact strings, penner's `--targets`) and `M_Th_hat` (Θ_i in
radians, `%.17g`, the peer's format):
  - sphere-10000, sphere-100000, torus-10000, torus-100000 from
    `target/release/examples/uniformize_targets KIND FACES write D` (the noisy icosphere with
    four cones of π at the vertices nearest (±1,±1,±1), even number of minus signs; the
    torus of radii 1 and 0.3 on an n × n/2 grid sheared by 5 columns per row, all 2π);
    the Θ/π strings are converted to radians as float(Θ/π)·π;
  - aircraft, elephant, fertility_tri: the peer's data/examples OBJ and `*_Th_hat`; each
    value divided by π and rounded to the nearest quarter (checked within 1e-12) gives the
    exact Θ/π string (as tests/data/real/aircraft_targets.json was made).

`run` times, in turn (A, B, C, A, B, C, … `-n` rounds after one warm-up round), with
`/usr/bin/time -f`:
  peer   cid_run M.obj M_Th_hat --eps 1e-10        (double, no overlay, max |Θ−θ| ≤ 1e-10,
                                                     penner's f64 tolerance)
  cert   penner uniformize M.obj --targets M-targets.json --precision 256 -o cert.json
  num    penner uniformize M.obj --targets M-targets.json --no-certify   (exit status 2:
                                                     numerical, no claim; `-o` not allowed)
and prints the median user CPU, wall and peak RSS of each and the ratios of medians
ours/peer. `--peer-default` adds the peer's script defaults (eps 0, 50 Newton iterations,
as its figures/compare_efficiency runs) as a fourth command.
"""
import argparse
import json
import math
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
from fractions import Fraction

REPO = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))
PENNER = os.environ.get("PENNER", os.path.join(os.environ.get("CARGO_TARGET_DIR", os.path.join(REPO, "target")), "release", "penner"))
EXAMPLE = os.path.join(os.path.dirname(PENNER), "examples", "uniformize_targets")
CID_ROOT = os.environ.get("CID_ROOT", "/work/peer-cid")
CID_RUN = os.path.join(CID_ROOT, "build", "cid_run")
CID_DATA = os.path.join(CID_ROOT, "src", "data", "examples")
GENERATED = ["sphere-10000", "torus-10000", "sphere-100000", "torus-100000"]
PEER_EXAMPLES = ["aircraft", "elephant", "fertility_tri"]


def prepare(d):
    os.makedirs(d, exist_ok=True)
    for name in GENERATED:
        kind, faces = name.split("-")
        if not os.path.exists(os.path.join(d, name + ".obj")):
            subprocess.run([EXAMPLE, kind, faces, "write", d], check=True)
        q = json.load(open(os.path.join(d, name + "-targets.json")))
        with open(os.path.join(d, name + "_Th_hat"), "w") as f:
            for s in q:
                f.write("%.17g\n" % (float(Fraction(s)) * math.pi))
    for name in PEER_EXAMPLES:
        shutil.copy(os.path.join(CID_DATA, name + ".obj"), os.path.join(d, name + ".obj"))
        shutil.copy(os.path.join(CID_DATA, name + "_Th_hat"), os.path.join(d, name + "_Th_hat"))
        out = []
        for line in open(os.path.join(d, name + "_Th_hat")):
            if not line.strip():
                continue
            x = float(line) / math.pi
            q = Fraction(round(4 * x), 4)
            assert abs(x - float(q)) < 1e-12, (name, line)
            out.append(str(q))
        json.dump(out, open(os.path.join(d, name + "-targets.json"), "w"))


def faces(path):
    return sum(1 for line in open(path) if line.startswith("f "))


def timed(cmd, log):
    fmt = "%U %S %e %M"
    with tempfile.NamedTemporaryFile("r", suffix=".time") as t:
        with open(log, "a") as lg:
            lg.write("$ " + " ".join(cmd) + "\n")
            lg.flush()
            r = subprocess.run(["/usr/bin/time", "-f", fmt, "-o", t.name] + cmd, stdout=lg, stderr=lg)
        u, s, e, m = open(t.name).read().split()[-4:]
    return dict(rc=r.returncode, user=float(u), sys=float(s), wall=float(e), rss=int(m) / 1024.0)


def run(d, meshes, n, peer_default):
    work = tempfile.mkdtemp(prefix="cid_pair_")
    log = os.path.join(work, "log.txt")
    rows = []
    for name in meshes:
        obj = os.path.join(d, name + ".obj")
        t = os.path.join(d, name + "-targets.json")
        th = os.path.join(d, name + "_Th_hat")
        cmds = {
            "peer": [CID_RUN, obj, th, "--eps", "1e-10", "-o", os.path.join(work, "u.txt")],
            "cert": [PENNER, "uniformize", obj, "--targets", t, "--precision", "256", "-o", os.path.join(work, "cert.json")],
            "num": [PENNER, "uniformize", obj, "--targets", t, "--no-certify"],
        }
        if peer_default:
            cmds["peer50"] = [CID_RUN, obj, th, "-o", os.path.join(work, "u50.txt")]
        res = {k: [] for k in cmds}
        for rnd in range(n + 1):
            for k, c in cmds.items():
                if k == "cert" and os.path.exists(c[-1]):
                    os.remove(c[-1])  # penner writes only new files
                m = timed(c, log)
                if rnd > 0:
                    res[k].append(m)
        med = {k: {f: statistics.median(x[f] for x in v) for f in ("user", "wall", "rss")} for k, v in res.items()}
        rcs = {k: sorted(set(x["rc"] for x in v)) for k, v in res.items()}
        rows.append((name, faces(obj), med, rcs))
        p = med["peer"]
        line = "%-14s %7d  peer %.2f/%.2f s %.0f MiB | cert %.2f/%.2f s (%.2fx user) %.0f MiB | num %.2f/%.2f s (%.2fx user) %.0f MiB" % (
            name, faces(obj), p["user"], p["wall"], p["rss"],
            med["cert"]["user"], med["cert"]["wall"], med["cert"]["user"] / p["user"], med["cert"]["rss"],
            med["num"]["user"], med["num"]["wall"], med["num"]["user"] / p["user"], med["num"]["rss"])
        if peer_default:
            line += " | peer eps0/50 itr %.2f/%.2f s" % (med["peer50"]["user"], med["peer50"]["wall"])
        print(line, "rc", rcs, flush=True)
    print("log:", log)
    return rows


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("what", choices=["prepare", "run"])
    ap.add_argument("meshes", nargs="*")
    ap.add_argument("--dir", default=os.path.join(CID_ROOT, "inputs"))
    ap.add_argument("-n", type=int, default=3)
    ap.add_argument("--peer-default", action="store_true")
    a = ap.parse_intermixed_args()
    if a.what == "prepare":
        prepare(a.dir)
    else:
        run(a.dir, a.meshes or GENERATED + PEER_EXAMPLES, a.n, a.peer_default)


if __name__ == "__main__":
    sys.exit(main())
