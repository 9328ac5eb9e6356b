#!/usr/bin/env python3
"""UVs on the input mesh, side by side: ConformalIdealDelaunay's overlay run (double) against
`penner uniformize … --uv`, on the inputs `run_pair.py prepare` writes.

    python3 benches/peers/conformal_ideal_delaunay/overlay_pair.py [--dir D] [-n 1] [MESH ...]

For every mesh, in turn (`-n` rounds after none as warm-up: overlay runs are long):
  peer   cid_run M.obj M_Th_hat --overlay --eps 1e-10 -o peer.obj   (conformal_parametrization_VL
                                                   <double>: the overlay mesh and its layout)
  num    penner uniformize M.obj --targets M-targets.json --no-certify --uv ours.obj
  cert   penner uniformize M.obj --targets M-targets.json --precision 256 -o cert.json --uv ours.obj
then the size of each written mesh (penner's with its sidecar), its triangle count, and its
folds counted with one exact test for both (`examples/uv_folds`: the orientation of every UV
triangle in ℚ on the written decimals). Prints median user CPU, wall and peak RSS.
"""
import argparse
import os
import re
import statistics
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(__file__))
from run_pair import CID_ROOT, CID_RUN, GENERATED, PEER_EXAMPLES, PENNER, timed  # noqa: E402

FOLDS = os.path.join(os.path.dirname(PENNER), "examples", "uv_folds")


def folds(path):
    if not os.path.exists(path):
        return "no output"
    out = subprocess.run([FOLDS, path], capture_output=True, text=True).stdout
    m = re.search(r"(\d+) UV triangles, (\d+) clockwise \(folded\), (\d+) of zero area", out)
    return "%s tris, %s folded, %s zero-area" % m.groups() if m else out.strip()


def size_mb(*paths):
    return sum(os.path.getsize(p) for p in paths if os.path.exists(p)) / 1e6


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("meshes", nargs="*")
    ap.add_argument("--dir", default=os.path.join(CID_ROOT, "inputs"))
    ap.add_argument("-n", type=int, default=1)
    ap.add_argument("--no-cert", action="store_true", help="skip the certified run")
    a = ap.parse_args()
    work = tempfile.mkdtemp(prefix="cid_overlay_")
    log = os.path.join(work, "log.txt")
    for name in a.meshes or PEER_EXAMPLES + GENERATED:
        obj = os.path.join(a.dir, name + ".obj")
        t = os.path.join(a.dir, name + "-targets.json")
        th = os.path.join(a.dir, name + "_Th_hat")
        peer_out = os.path.join(work, name + "-peer.obj")
        ours = os.path.join(work, name + "-ours.obj")
        cmds = {
            "peer": [CID_RUN, obj, th, "--overlay", "--eps", "1e-10", "-o", peer_out],
            "num": [PENNER, "uniformize", obj, "--targets", t, "--no-certify", "--uv", ours],
        }
        if not a.no_cert:
            cmds["cert"] = [PENNER, "uniformize", obj, "--targets", t, "--precision", "256",
                            "-o", os.path.join(work, "cert.json"), "--uv", ours]
        res = {k: [] for k in cmds}
        for _ in range(a.n):
            for k, c in cmds.items():
                for p in (ours, ours + ".json", os.path.join(work, "cert.json")):
                    if os.path.exists(p):
                        os.remove(p)  # penner writes only new files
                res[k].append(timed(c, log))
                if k == "num":
                    ours_report = (size_mb(ours, ours + ".json"), folds(ours))
        med = {k: {f: statistics.median(x[f] for x in v) for f in ("user", "wall", "rss")} for k, v in res.items()}
        rcs = {k: sorted(set(x["rc"] for x in v)) for k, v in res.items()}
        p = med["peer"]
        line = "%-14s peer %.2f/%.2f s %.0f MiB, %.1f MB, %s | num %.2f/%.2f s (%.2fx) %.0f MiB, %.1f MB, %s" % (
            name, p["user"], p["wall"], p["rss"], size_mb(peer_out), folds(peer_out),
            med["num"]["user"], med["num"]["wall"], med["num"]["user"] / p["user"], med["num"]["rss"],
            ours_report[0], ours_report[1])
        if "cert" in med:
            line += " | cert %.2f/%.2f s (%.2fx) %.0f MiB" % (
                med["cert"]["user"], med["cert"]["wall"], med["cert"]["user"] / p["user"], med["cert"]["rss"])
        print(line, "rc", rcs, flush=True)
    print("log:", log)


if __name__ == "__main__":
    sys.exit(main())
