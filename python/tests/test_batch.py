"""``python -m penner.batch`` run as a user runs it (a subprocess) on a corpus written here:
one row per file against the library called directly, the malformed file's error row,
``--resume``, the refusal to overwrite, timeouts, dask's processes scheduler without
``distributed``, and a worker killed mid-run. Skipped without dask."""

import json
import os
import subprocess
import sys
import time

import pytest

pytest.importorskip("dask")

import penner  # noqa: E402
from conftest import octahedron, torus, write_obj  # noqa: E402


def batch(*args, env=None, timeout=300):
    return subprocess.run(
        [sys.executable, "-m", "penner.batch", *map(str, args)],
        capture_output=True, text=True, timeout=timeout, env=env,
    )


def rows_of(path):
    with open(path, encoding="utf-8") as fh:
        return [json.loads(line) for line in fh]


@pytest.fixture
def corpus(tmp_path):
    d = tmp_path / "meshes"
    (d / "sub").mkdir(parents=True)
    write_obj(d / "octa.obj", *octahedron())
    write_obj(d / "sub" / "torus.obj", *torus(5, 5))
    (d / "bad.obj").write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n")
    (d / "notes.txt").write_text("not a mesh\n")  # not picked up from a directory
    return d


def by_name(rows):
    return {os.path.basename(r["file"]): r for r in rows}


def test_check_rows_resume_and_refusal(corpus, tmp_path):
    out = tmp_path / "results.jsonl"
    p = batch(corpus, "--command", "check", "--out", out, "--workers", 2, "--precision", "f64")
    assert p.returncode == 0, p.stderr
    rows = rows_of(out)
    assert sorted(by_name(rows)) == ["bad.obj", "octa.obj", "torus.obj"]
    r = by_name(rows)
    for name in ("octa.obj", "torus.obj"):
        row = r[name]
        assert row["status"] == "ok" and row["error"] is None and row["command"] == "check"
        direct = penner.check(penner.read(row["file"]), precision=("f64",))
        for word in ("holds", "fails", "undecided", "not_applicable"):
            assert row[word] == sum(x["result"]["verdict"] == word for x in direct)
        assert row["seconds"] >= 0
    assert r["octa.obj"]["verdict"] == "holds"
    # The malformed file is a row naming its line, not a crash of the run.
    bad = r["bad.obj"]
    assert bad["status"] == "error" and bad["verdict"] is None
    assert "InputError" in bad["error"] and "line 4" in bad["error"]
    assert "ok 2" in p.stderr and "error 1" in p.stderr  # the one-line summary

    # --resume runs nothing new and leaves the rows as they were.
    before = out.read_text()
    p = batch(corpus, "--command", "check", "--out", out, "--resume", "--precision", "f64")
    assert p.returncode == 0, p.stderr
    assert out.read_text() == before
    assert "0 rows" in p.stderr and "3 skipped" in p.stderr

    # Without --resume an existing output is refused, exit 3, untouched.
    p = batch(corpus, "--command", "check", "--out", out)
    assert p.returncode == 3 and "refusing to overwrite" in p.stderr
    assert out.read_text() == before


def test_resume_after_an_interruption(corpus, tmp_path):
    """Only the files missing from the output run; a line cut mid-write runs again."""
    out = tmp_path / "r.jsonl"
    octa = str(corpus / "octa.obj")
    out.write_text(json.dumps({"file": octa, "command": "delaunay", "status": "ok"}) + "\n"
                   + '{"file": "cut mid-wri')
    p = batch(corpus, "--command", "delaunay", "--out", out, "--resume", "--workers", 1)
    assert p.returncode == 0, p.stderr
    lines = out.read_text().splitlines()
    assert lines[1] == '{"file": "cut mid-wri'
    new = [json.loads(x) for x in lines[2:]]
    assert sorted(by_name(new)) == ["bad.obj", "torus.obj"]
    torus_row = by_name(new)["torus.obj"]
    _, _, info = penner.intrinsic_delaunay(torus_row["file"])
    assert torus_row["verdict"] == info["certificate"] and torus_row["flips"] == info["flips"]


def test_uniformize_files_and_timeout(corpus, tmp_path):
    files = [corpus / "sub" / "torus.obj", corpus / "octa.obj"]
    out = tmp_path / "u.jsonl"
    p = batch(*files, "--command", "uniformize", "--flat", "--out", out, "--timeout", 120)
    assert p.returncode == 0, p.stderr
    r = by_name(rows_of(out))
    direct = penner.uniformize(str(files[0]), flat=True)
    assert r["torus.obj"]["certified"] is direct.certified is True
    assert r["octa.obj"]["status"] == "error" and "Gauss–Bonnet" in r["octa.obj"]["error"]
    # A timeout far below a process's start-up: every task is a "timeout" row.
    out2 = tmp_path / "t.jsonl"
    p = batch(corpus, "--command", "delaunay", "--out", out2, "--timeout", 0.001)
    assert p.returncode == 0, p.stderr
    rows = rows_of(out2)
    assert len(rows) == 3 and {r["status"] for r in rows} == {"timeout"}
    assert "timeout 3" in p.stderr


def test_without_distributed_uses_dask_processes(corpus, tmp_path):
    shadow = tmp_path / "shadow"
    shadow.mkdir()
    (shadow / "distributed.py").write_text("raise ImportError('hidden by the test')\n")
    env = dict(os.environ, PYTHONPATH=str(shadow) + os.pathsep + os.environ.get("PYTHONPATH", ""))
    out = tmp_path / "p.jsonl"
    p = batch(corpus, "--command", "check", "--out", out, "--workers", 2,
              "--precision", "f64", env=env)
    assert p.returncode == 0, p.stderr
    r = by_name(rows_of(out))
    assert len(r) == 3 and r["octa.obj"]["verdict"] == "holds" and r["bad.obj"]["status"] == "error"


def test_no_files_and_bad_options(tmp_path):
    p = batch(tmp_path, "--command", "check", "--out", tmp_path / "o.jsonl")
    assert p.returncode == 3 and "no .obj" in p.stderr
    p = batch(tmp_path, "--command", "check", "--flat", "--out", tmp_path / "o.jsonl")
    assert p.returncode == 2 and "--flat" in p.stderr
    assert not (tmp_path / "o.jsonl").exists()


def test_killed_worker(tmp_path):
    """A worker of the cluster is killed while it runs a task: the task runs again, every
    file gets exactly one row."""
    distributed = pytest.importorskip("distributed")
    import signal

    d = tmp_path / "big"
    d.mkdir()
    V, F = torus(16, 16)
    for k in range(6):
        write_obj(d / f"torus{k}.obj", V, F)
    out = tmp_path / "k.jsonl"
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        proc = subprocess.Popen(
            [sys.executable, "-m", "penner.batch", str(d), "--command", "check",
             "--out", str(out), "--scheduler", cluster.scheduler_address],
            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
        )
        try:
            killed = None
            deadline = time.time() + 120
            while killed is None and time.time() < deadline and proc.poll() is None:
                busy = client.run(lambda dask_worker: (os.getpid(), len(dask_worker.state.executing)))
                for pid, n in busy.values():
                    if n:
                        os.kill(pid, signal.SIGKILL)
                        killed = pid
                        break
                time.sleep(0.05)
            _, err = proc.communicate(timeout=300)
        finally:
            if proc.poll() is None:
                proc.kill()
    assert killed is not None, "no worker was seen running a task"
    assert proc.returncode == 0, err
    rows = rows_of(out)
    names = [os.path.basename(r["file"]) for r in rows]
    assert sorted(names) == [f"torus{k}.obj" for k in range(6)]  # all, no duplicates
    assert {r["status"] for r in rows} == {"ok"}
    direct = penner.check(V, F)
    assert {r["holds"] for r in rows} == {sum(x["result"]["verdict"] == "holds" for x in direct)}
