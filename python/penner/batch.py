"""``python -m penner.batch``: run ``check``, ``uniformize`` or ``delaunay`` over a corpus of
surface files on Dask, one task per file, one JSON line per file in the output.

::

    python -m penner.batch meshes/ extra.off --command check --out results.jsonl
    python -m penner.batch meshes/ --command uniformize --flat --out flat.jsonl \\
        --workers 8 --timeout 600 --retries 1
    python -m penner.batch meshes/ --command check --out results.jsonl --resume
    python -m penner.batch meshes/ --command check --out r.jsonl --scheduler tcp://host:8786

Directories are searched recursively for ``.obj``, ``.off`` and ``.json`` files; files
named on the command line are taken whatever their suffix. Without ``--scheduler`` the
run uses a ``dask.distributed.LocalCluster`` of ``--workers`` processes with one thread
each when ``distributed`` is installed, else dask's local ``processes`` scheduler.

Each row (:func:`penner.dask.run_one`, plus ``status``) is appended to ``--out`` as soon
as its task completes, so an interrupted run continues with ``--resume``, which skips the
files already in the output. ``status`` is ``"ok"`` (a verdict), ``"error"`` (the file was
refused, e.g. ``penner.InputError``, or the task raised: ``error`` says what),
``"timeout"`` (``--timeout`` seconds passed; with a timeout each task runs in a child
process of its worker, which is killed) or ``"lost"`` (its worker died more than
``--retries`` times). Nothing is written but the output: check rows count the failures'
minimal reproducers, they are not written next to the dataset.

An existing output is never overwritten: without ``--resume`` the run refuses it (exit 3).
The run ends with a one-line summary on stderr (rows per status, wall time).

On a SLURM cluster, start the workers with ``dask-jobqueue`` and pass the scheduler::

    from dask_jobqueue import SLURMCluster
    cluster = SLURMCluster(cores=1, processes=1, memory="4GB", walltime="02:00:00")
    cluster.scale(jobs=64)
    print(cluster.scheduler_address)   # → --scheduler tcp://…

(the workers need ``penner`` installed; ``--retries`` then applies only to task errors,
worker loss follows that scheduler's ``distributed.scheduler.allowed-failures``).
"""

from __future__ import annotations

import argparse
import json
import math
import os
import subprocess
import sys
import time
from typing import Any, Dict, Iterable, List, Optional, Sequence, Set

from penner.dask import run_one

__all__ = ["find_files", "main", "run_task"]

SUFFIXES = (".obj", ".off", ".json")
COMMANDS = ("check", "uniformize", "delaunay")
EXIT_REFUSED = 3

# The child process of a task with a timeout: options and path in on stdin, the row out
# on stdout.
_CHILD = (
    "import json, sys\n"
    "from penner.dask import run_one\n"
    "a = json.load(sys.stdin)\n"
    "o = a['options']\n"
    "if 'precision' in o and isinstance(o['precision'], list): o['precision'] = tuple(o['precision'])\n"
    "r = run_one(a['path'], a['command'], **o)\n"
    "sys.stdout.write(json.dumps(r, default=str))\n"
)


def find_files(args: Iterable[str]) -> List[str]:
    """The mesh files named by ``args``: directories searched recursively (sorted) for
    ``.obj``/``.off``/``.json``, glob patterns expanded, files as given; each once."""
    import glob

    out: List[str] = []
    seen: Set[str] = set()

    def add(p: str) -> None:
        key = os.path.abspath(p)
        if key not in seen:
            seen.add(key)
            out.append(p)

    for a in args:
        if os.path.isdir(a):
            found = []
            for root, dirs, files in os.walk(a):
                dirs.sort()
                for f in files:
                    if f.lower().endswith(SUFFIXES):
                        found.append(os.path.join(root, f))
            for p in sorted(found):
                add(p)
        elif os.path.exists(a):
            add(a)
        elif glob.has_magic(a):
            for p in sorted(glob.glob(a, recursive=True)):
                if os.path.isfile(p):
                    add(p)
        else:
            add(a)  # becomes a row with its OSError
    return out


def _json_safe(x: Any) -> Any:
    if isinstance(x, float):
        return x if math.isfinite(x) else None
    if isinstance(x, dict):
        return {str(k): _json_safe(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [_json_safe(v) for v in x]
    if hasattr(x, "item") and callable(x.item):  # numpy scalars
        return _json_safe(x.item())
    if x is None or isinstance(x, (str, int, bool)):
        return x
    return str(x)


def _blank(path: str, command: str) -> Dict[str, Any]:
    return {"file": path, "command": command, "verdict": None, "certified": None,
            "seconds": None, "error": None}


def run_task(path: str, command: str, options: Dict[str, Any], timeout: Optional[float] = None) -> Dict[str, Any]:
    """One row with its ``status``, never an exception: :func:`penner.dask.run_one` in
    this process, or with ``timeout`` in a child process killed after ``timeout`` seconds."""
    start = time.perf_counter()
    try:
        if timeout is None:
            row = run_one(path, command, **options)
        else:
            try:
                p = subprocess.run(
                    [sys.executable, "-c", _CHILD],
                    input=json.dumps({"path": path, "command": command, "options": options}),
                    capture_output=True, text=True, timeout=timeout,
                )
            except subprocess.TimeoutExpired:
                row = _blank(path, command)
                row["status"] = "timeout"
                row["error"] = f"timeout: no result after {timeout:g} s"
                row["seconds"] = time.perf_counter() - start
                return row
            if p.returncode != 0:
                tail = (p.stderr.strip().splitlines() or [f"exit code {p.returncode}"])[-1]
                raise RuntimeError(f"the task's process ended with code {p.returncode}: {tail}")
            row = json.loads(p.stdout)
    except Exception as e:  # a row, never a crash of the run
        row = _blank(path, command)
        row["error"] = f"{type(e).__name__}: {e}"
        row["seconds"] = time.perf_counter() - start
    row["status"] = "error" if row.get("error") else "ok"
    return row


def _done_files(out: str) -> Set[str]:
    done: Set[str] = set()
    with open(out, encoding="utf-8") as fh:
        for line in fh:
            try:
                row = json.loads(line)
            except ValueError:
                continue  # a line cut by an interruption: that file runs again
            if isinstance(row, dict) and isinstance(row.get("file"), str):
                done.add(os.path.abspath(row["file"]))
    return done


class _Writer:
    """Appends one line per row, flushed at once; counts statuses; a progress line on a
    terminal."""

    def __init__(self, out: str, total: int):
        self.fh = open(out, "a", encoding="utf-8")
        if self.fh.tell() > 0:  # an interrupted last line gets its own line ending
            with open(out, "rb") as r:
                r.seek(-1, os.SEEK_END)
                if r.read(1) != b"\n":
                    self.fh.write("\n")
        self.total = total
        self.counts: Dict[str, int] = {}
        self.written: Set[str] = set()
        self.tty = sys.stderr.isatty()

    def write(self, row: Dict[str, Any]) -> None:
        key = os.path.abspath(row["file"])
        if key in self.written:  # a task completed twice (a worker lost after finishing)
            return
        self.written.add(key)
        self.fh.write(json.dumps(_json_safe(row), allow_nan=False) + "\n")
        self.fh.flush()
        st = row.get("status", "ok")
        self.counts[st] = self.counts.get(st, 0) + 1
        if self.tty:
            n = len(self.written)
            width = 30
            bar = "#" * (width * n // max(self.total, 1))
            sys.stderr.write(f"\r[{bar:<{width}}] {n}/{self.total}")
            sys.stderr.flush()

    def close(self) -> None:
        if self.tty and self.written:
            sys.stderr.write("\n")
        self.fh.close()


def _run_distributed(files, command, options, args, writer) -> None:
    import dask
    from distributed import Client, LocalCluster, as_completed

    from penner import batch as this  # by reference, also when run as __main__

    cluster = None
    if args.scheduler:
        client = Client(args.scheduler)
    else:
        import logging

        # Worker loss: a task whose worker dies is run again up to --retries times.
        with dask.config.set({"distributed.scheduler.allowed-failures": args.retries}):
            cluster = LocalCluster(
                n_workers=args.workers, threads_per_worker=1, processes=True,
                dashboard_address=None, silence_logs=logging.CRITICAL,
            )
        client = Client(cluster)
    try:
        futures = {}
        for p in files:
            f = client.submit(this.run_task, p, command, options, args.timeout,
                              pure=False, retries=args.retries, key=f"penner-batch-{len(futures)}")
            futures[f] = p
        for f in as_completed(futures):
            try:
                row = f.result()
            except Exception as e:  # KilledWorker after the retries, or a lost scheduler
                row = _blank(futures[f], command)
                row["status"] = "lost"
                row["error"] = f"{type(e).__name__}: {e}"
            writer.write(row)
    finally:
        client.close()
        if cluster is not None:
            cluster.close()


def _run_processes(files, command, options, args, writer) -> None:
    import dask
    from dask.callbacks import Callback

    from penner import batch as this

    class Stream(Callback):
        def _posttask(self, key, result, dsk, state, worker_id):
            if isinstance(result, dict) and "status" in result:
                writer.write(result)

    todo = list(files)
    for attempt in range(args.retries + 1):
        tasks = [dask.delayed(this.run_task, pure=False)(p, command, options, args.timeout) for p in todo]
        try:
            with Stream():
                dask.compute(*tasks, scheduler="processes", num_workers=args.workers)
            return
        except Exception as e:  # a worker process died: the pool is broken
            todo = [p for p in todo if os.path.abspath(p) not in writer.written]
            last = e
    for p in todo:
        row = _blank(p, command)
        row["status"] = "lost"
        row["error"] = f"{type(last).__name__}: {last}"
        writer.write(row)


def _parse_precision(values: Optional[Sequence[str]], command: str) -> Dict[str, Any]:
    if not values:
        return {}
    vals = [int(v) if v.isdigit() else v for v in values]
    if command == "check":
        return {"precision": tuple(vals)}
    if len(vals) != 1:
        raise SystemExit(f"penner.batch: --precision takes one value for {command}")
    return {"precision": vals[0]}


def main(argv: Optional[Sequence[str]] = None) -> int:
    ap = argparse.ArgumentParser(
        prog="python -m penner.batch",
        description="Run penner over a corpus of mesh files on Dask, one JSON line per file.",
        formatter_class=argparse.RawDescriptionHelpFormatter,
        epilog=__doc__[__doc__.index("On a SLURM cluster"):] if __doc__ else None,
    )
    ap.add_argument("inputs", nargs="+", metavar="DIR_OR_FILES",
                    help="directories (searched recursively for .obj/.off/.json), files or globs")
    ap.add_argument("--command", required=True, choices=COMMANDS)
    ap.add_argument("--out", required=True, help="the JSON-lines output (never overwritten)")
    ap.add_argument("--scheduler", help="address of an existing dask.distributed scheduler")
    ap.add_argument("--workers", type=int, default=os.cpu_count() or 1,
                    help="local worker processes (default: one per core)")
    ap.add_argument("--timeout", type=float, default=None,
                    help="seconds per task; its child process is killed after them")
    ap.add_argument("--retries", type=int, default=1, help="runs again after a lost worker (default 1)")
    ap.add_argument("--resume", action="store_true",
                    help="append to an existing output, skipping the files already in it")
    ap.add_argument("--precision", nargs="+", metavar="P",
                    help="check: precisions (f64 dd 256 …); uniformize/delaunay: one")
    ap.add_argument("--flat", action="store_true", help="uniformize: flat target (genus 1)")
    ap.add_argument("--sphere", action="store_true", help="uniformize: inscribed in the sphere")
    ap.add_argument("--hyperbolic", action="store_true", help="uniformize: hyperbolic lengths")
    ap.add_argument("--flips", choices=("euclidean", "ptolemy"), help="delaunay: the flips")
    args = ap.parse_args(argv)

    if args.workers < 1 or args.retries < 0 or (args.timeout is not None and args.timeout <= 0):
        ap.error("--workers ≥ 1, --retries ≥ 0 and --timeout > 0 are required")
    options = _parse_precision(args.precision, args.command)
    for flag in ("flat", "sphere", "hyperbolic"):
        if getattr(args, flag):
            if args.command != "uniformize":
                ap.error(f"--{flag} is an option of --command uniformize")
            options[flag] = True
    if args.flips:
        if args.command != "delaunay":
            ap.error("--flips is an option of --command delaunay")
        options["flips"] = args.flips

    if os.path.exists(args.out) and not args.resume:
        print(f"penner.batch: {args.out} exists; refusing to overwrite it "
              "(--resume appends to it, skipping the files already done)", file=sys.stderr)
        return EXIT_REFUSED
    files = find_files(args.inputs)
    if not files:
        print("penner.batch: no .obj, .off or .json file in " + " ".join(args.inputs), file=sys.stderr)
        return EXIT_REFUSED
    done = _done_files(args.out) if os.path.exists(args.out) else set()
    todo = [p for p in files if os.path.abspath(p) not in done]

    start = time.perf_counter()
    writer = _Writer(args.out, len(todo))
    try:
        if todo:
            try:
                import distributed  # noqa: F401
                have_distributed = True
            except ImportError:
                have_distributed = False
            if args.scheduler and not have_distributed:
                print("penner.batch: --scheduler needs dask.distributed (pip install distributed)",
                      file=sys.stderr)
                return EXIT_REFUSED
            if have_distributed:
                _run_distributed(todo, args.command, options, args, writer)
            else:
                _run_processes(todo, args.command, options, args, writer)
    finally:
        writer.close()
    wall = time.perf_counter() - start
    counts = ", ".join(f"{k} {v}" for k, v in sorted(writer.counts.items())) or "nothing run"
    print(f"penner.batch: {len(writer.written)} rows ({counts}), {len(files) - len(todo)} skipped "
          f"as already in {args.out}, {wall:.2f} s", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
