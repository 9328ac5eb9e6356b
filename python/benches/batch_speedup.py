"""Wall time of ``python -m penner.batch`` (a ``LocalCluster`` of ``--workers`` processes)
against a sequential loop in one process over the same files, calling the same function
the workers call (:func:`penner.batch.run_task`, no timeout).

::

    python python/benches/batch_speedup.py CORPUS_DIR --command uniformize --sphere
    python python/benches/batch_speedup.py CORPUS_DIR --command check --precision f64 dd

The sequential loop runs first, then the batch command as a child process, timed from
its start to its exit (interpreter start, cluster start and shutdown included). The two
runs must give the same ``verdict`` and ``certified`` for every file, else the script
exits with code 1 and prints the files that differ. Prints one JSON object: the files,
the two wall times and their ratio, the CPU seconds of each run (the batch's: of its
process tree, as reaped), the sum of the per-file ``seconds`` of each run, and the
1-minute load average before and after (other work on the machine slows both runs).

Needs ``penner`` installed with ``distributed`` (``pip install ".[dask]"``). The corpus
used for docs/benchmarks.md is described in python/benches/README.md.
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import subprocess
import sys
import tempfile
import time

from penner.batch import _parse_precision, find_files, run_task


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("inputs", nargs="+")
    ap.add_argument("--command", required=True, choices=("check", "uniformize", "delaunay"))
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--precision", nargs="+")
    ap.add_argument("--flat", action="store_true")
    ap.add_argument("--sphere", action="store_true")
    ap.add_argument("--hyperbolic", action="store_true")
    args = ap.parse_args()

    files = find_files(args.inputs)
    if not files:
        ap.error("no .obj, .off or .json file in " + " ".join(args.inputs))
    options = _parse_precision(args.precision, args.command)
    flags = []
    for flag in ("flat", "sphere", "hyperbolic"):
        if getattr(args, flag):
            options[flag] = True
            flags.append(f"--{flag}")
    if args.precision:
        flags += ["--precision", *args.precision]

    # Sequential: one process, one file after the other.
    load_start = os.getloadavg()[0]
    cpu = time.process_time()
    start = time.perf_counter()
    seq = {os.path.abspath(p): run_task(p, args.command, options, None) for p in files}
    t_seq = time.perf_counter() - start
    cpu_seq = time.process_time() - cpu

    # Dask: the batch command, as a user runs it.
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "rows.jsonl")
        cmd = [sys.executable, "-m", "penner.batch", *files, "--command", args.command,
               "--workers", str(args.workers), "--out", out, *flags]
        children = resource.getrusage(resource.RUSAGE_CHILDREN)
        start = time.perf_counter()
        p = subprocess.run(cmd, capture_output=True, text=True)
        t_par = time.perf_counter() - start
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpu_par = (after.ru_utime + after.ru_stime) - (children.ru_utime + children.ru_stime)
        if p.returncode != 0:
            sys.stderr.write(p.stderr)
            return 1
        with open(out, encoding="utf-8") as fh:
            par = {os.path.abspath(r["file"]): r for r in map(json.loads, fh)}

    differ = [f for f in seq
              if f not in par or any(seq[f].get(k) != par[f].get(k) for k in ("verdict", "certified", "status"))]
    report = {
        "files": len(files),
        "command": args.command,
        "options": flags,
        "workers": args.workers,
        "cpus": os.cpu_count(),
        "sequential_wall_s": round(t_seq, 2),
        "batch_wall_s": round(t_par, 2),
        "speedup": round(t_seq / t_par, 2),
        "sequential_cpu_s": round(cpu_seq, 2),
        "batch_cpu_s": round(cpu_par, 2),
        "sequential_task_s": round(sum(r["seconds"] or 0 for r in seq.values()), 2),
        "batch_task_s": round(sum(r.get("seconds") or 0 for r in par.values()), 2),
        "statuses": sorted({r["status"] for r in seq.values()}),
        "verdicts": sorted({str(r["verdict"]) for r in seq.values()}),
        "load_average_1min_start_end": [round(load_start, 2), round(os.getloadavg()[0], 2)],
        "batch_summary": p.stderr.strip().splitlines()[-1] if p.stderr.strip() else "",
    }
    print(json.dumps(report, indent=1))
    if differ:
        print("verdicts differ between the runs: " + ", ".join(differ), file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
