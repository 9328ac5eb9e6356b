"""Run :func:`penner.check`, :func:`penner.intrinsic_delaunay` or :func:`penner.uniformize` over many surface files with Dask.

One task per file (``dask.delayed``); every task returns one row, and a file that cannot
be read or is refused becomes a row with its ``error`` instead of stopping the others.
The work inside each task runs with the GIL released, so Dask's default threaded
scheduler uses every core; ``scheduler=`` passes any other (``"processes"``, or a
``dask.distributed`` client's). Dask is an optional dependency: ``pip install .[dask]``.

>>> from penner.dask import check_corpus
>>> table = check_corpus(["a.obj", "b.off"], command="check", precision=("f64",))
"""

from __future__ import annotations

import os
import time
from typing import Any, Dict, Iterable, List, Optional, Sequence, Union

import penner

__all__ = ["check_corpus", "run_one"]


def run_one(path: Union[str, "os.PathLike[str]"], command: str = "check", **options: Any) -> Dict[str, Any]:
    """One row for one file: ``file``, ``command``, ``verdict``, ``certified``,
    ``seconds``, ``error`` (None unless the file was refused) and, for ``check``, the
    counts of rows per verdict (``holds``, ``fails``, ``undecided``, ``not_applicable``)
    and of ``failures`` (minimal reproducers); for ``delaunay``, the ``flips`` and the
    ``certificate`` as the verdict."""
    start = time.perf_counter()
    row: Dict[str, Any] = {
        "file": os.fspath(path),
        "command": command,
        "verdict": None,
        "certified": None,
        "seconds": None,
        "error": None,
    }
    try:
        s = penner.read(path)
        if command == "check":
            rows = penner.check(s, **options)
            verdicts = [r["result"].get("verdict") for r in rows]
            for word in ("holds", "fails", "undecided", "not_applicable"):
                row[word] = verdicts.count(word)
            if row["fails"]:
                row["verdict"] = "fails"
            elif row["undecided"] or "error" in verdicts:
                row["verdict"] = "undecided"
            else:
                row["verdict"] = "holds"
            row["certified"] = all(
                r["result"].get("certified", False)
                for r in rows
                if r["result"].get("verdict") == "holds"
            )
            row["failures"] = len(rows.failures)
        elif command == "delaunay":
            _, _, info = penner.intrinsic_delaunay(s, **options)
            row["verdict"] = info["certificate"]
            row["certified"] = info["holds"]
            row["flips"] = info["flips"]
        elif command == "uniformize":
            r = penner.uniformize(s, **options)
            row["verdict"] = "certified" if r.certified else "not certified"
            row["certified"] = r.certified
            row["reason"] = r.reason
            row["residual"] = r.residual
        else:
            raise ValueError(f"command: expected 'check', 'delaunay' or 'uniformize', got {command!r}")
    except (penner.InputError, OSError, NotImplementedError) as e:
        row["error"] = f"{type(e).__name__}: {e}"
    row["seconds"] = time.perf_counter() - start
    return row


def check_corpus(
    paths: Iterable[Union[str, "os.PathLike[str]"]],
    command: str = "check",
    *,
    scheduler: Optional[Any] = None,
    as_frame: Optional[bool] = None,
    **options: Any,
) -> Any:
    """Map ``command`` (``"check"``, ``"delaunay"`` or ``"uniformize"``, with ``options`` passed on) over
    the files ``paths``, one ``dask.delayed`` task each, and collect one row per file in
    the order given (:func:`run_one`).

    Returns a pandas DataFrame when pandas is installed (``as_frame=None`` or True), else a
    list of dicts.
    """
    if command not in ("check", "delaunay", "uniformize"):
        raise ValueError(f"command: expected 'check', 'delaunay' or 'uniformize', got {command!r}")
    import dask

    tasks = [dask.delayed(run_one, pure=False)(p, command, **options) for p in paths]
    kw = {} if scheduler is None else {"scheduler": scheduler}
    rows: List[Dict[str, Any]] = list(dask.compute(*tasks, **kw))
    if as_frame is False:
        return rows
    try:
        import pandas
    except ImportError:
        if as_frame:
            raise
        return rows
    return pandas.DataFrame(rows)
