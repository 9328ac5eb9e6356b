"""penner.dask over a small corpus of files: one row per file in the order given, a bad
file reported in its row without stopping the others. Skipped without dask."""

import numpy as np
import pytest

dask = pytest.importorskip("dask")

import penner  # noqa: E402
from penner.dask import check_corpus  # noqa: E402
from conftest import octahedron, tetrahedron, torus, write_obj  # noqa: E402


@pytest.fixture
def corpus(tmp_path):
    V, F = octahedron()
    bad = F.copy()
    bad[0, 0] = 42
    return [
        write_obj(tmp_path / "tet.obj", *tetrahedron()),
        write_obj(tmp_path / "bad.obj", V, bad),
        write_obj(tmp_path / "octa.obj", V, F),
    ]


def test_check_corpus_one_row_per_file(corpus):
    rows = check_corpus(corpus, "check", precision=("f64",), as_frame=False)
    assert [r["file"] for r in rows] == [str(p) for p in corpus]
    good = [rows[0], rows[2]]
    for r in good:
        assert r["error"] is None and r["verdict"] == "holds" and r["fails"] == 0
        # The same rows as a direct call (an independent count).
        direct = penner.check(penner.read(r["file"]), precision=("f64",))
        assert r["holds"] == sum(x["result"]["verdict"] == "holds" for x in direct)
    # The negative control: the bad file is a row naming its line, not an exception.
    assert rows[1]["verdict"] is None and "InputError" in rows[1]["error"]
    assert "line" in rows[1]["error"]


def test_uniformize_corpus_and_frame(tmp_path):
    pandas = pytest.importorskip("pandas")
    paths = [write_obj(tmp_path / f"torus{n}.obj", *torus(n, n)) for n in (4, 5)]
    paths.append(write_obj(tmp_path / "tet.obj", *tetrahedron()))  # a sphere is not flat
    table = check_corpus(paths, "uniformize", flat=True)
    assert isinstance(table, pandas.DataFrame) and len(table) == 3
    assert list(table["certified"][:2]) == [True, True]
    assert "Gauss–Bonnet" in table["error"][2]
    assert np.all(table["seconds"] >= 0)
    with pytest.raises(ValueError, match="command"):
        check_corpus(paths, "flip")


def test_delaunay_corpus(corpus):
    rows = check_corpus(corpus, "delaunay", as_frame=False)
    assert [r["verdict"] for r in (rows[0], rows[2])] == ["input_metric"] * 2
    assert rows[0]["certified"] and rows[0]["flips"] == penner.intrinsic_delaunay(corpus[0])[2]["flips"]
    assert rows[1]["verdict"] is None and "InputError" in rows[1]["error"]
