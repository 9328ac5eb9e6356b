"""The package against the command line, run as a separate program: the same rows as
`penner check --json` (but for the timings) and the same failure files; bit for bit, the
same claims as `penner uniformize -o` and the same triangulation and lengths as
`penner delaunay -o`. Runs when PENNER_BIN names the `penner` binary (.ci/run sets it);
skipped otherwise."""

import json
import os
import subprocess

import pytest

import penner
from conftest import octahedron, torus, write_obj
from test_pipelines import planar_point_set, skewed_octahedron

BIN = os.environ.get("PENNER_BIN")
pytestmark = pytest.mark.skipif(not BIN, reason="PENNER_BIN (the penner binary) is not set")


def without_seconds(rows):
    return [{k: v for k, v in r.items() if k != "seconds"} for r in rows]


def test_check_rows_match_the_cli(tmp_path):
    path = write_obj(tmp_path / "octa.obj", *octahedron())
    out = subprocess.run(
        [BIN, "check", str(path), "--json", "--precision", "f64,dd,256"],
        capture_output=True, text=True, check=True,
    )
    cli = json.loads(out.stdout)["rows"]
    mine = penner.check(str(path), precision=("f64", "dd", 256))
    assert without_seconds(mine) == without_seconds(cli)


def test_uniformize_claim_matches_the_cli_bit_for_bit(tmp_path):
    path = write_obj(tmp_path / "torus.obj", *torus(4, 4))
    claim = tmp_path / "claim.json"
    subprocess.run([BIN, "uniformize", str(path), "--flat", "-o", str(claim)],
                   capture_output=True, text=True, check=True)
    r = penner.uniformize(str(path), flat=True)
    assert r.certified
    assert json.loads(claim.read_text()) == r.claim
    # Control: a different surface gives a different claim.
    assert penner.uniformize(*torus(5, 5), flat=True).claim != r.claim


def test_negative_control_rows_and_failure_files_match_the_cli(tmp_path):
    path = write_obj(tmp_path / "octa.obj", *octahedron())
    out = subprocess.run(
        [BIN, "check", str(path), "--json", "--precision", "f64", "--only", "T01",
         "--negative-controls"],
        capture_output=True, text=True,
    )
    cli = json.loads(out.stdout)
    mine = penner.check(str(path), precision=("f64",), only=["T01"], negative_controls=True)
    assert without_seconds(mine) == without_seconds(cli["rows"])
    files = [json.loads(open(f["file"]).read()) for f in cli["failure_files"]]
    assert files and mine.failures == files


@pytest.mark.parametrize("flips,precision", [("euclidean", "f64"), ("ptolemy", "256")])
def test_intrinsic_delaunay_matches_the_cli_bit_for_bit(tmp_path, flips, precision):
    V, F = planar_point_set()
    path = write_obj(tmp_path / "points.obj", V, F)
    out, summary = tmp_path / "out.json", tmp_path / "summary.json"
    subprocess.run(
        [BIN, "delaunay", str(path), "--flips", flips, "--precision", precision,
         "-o", str(out), "--summary", str(summary)],
        capture_output=True, text=True, check=True,
    )
    F2, l2, info = penner.intrinsic_delaunay(str(path), flips=flips, precision=precision)
    cli = penner.read(out)
    assert F2.tobytes() == cli.F.tobytes() and l2.tobytes() == cli.l.tobytes()
    assert info["summary"] == json.loads(summary.read_text())
    # Control: the input triangulation is not the output.
    assert penner.read(path).F.tobytes() != F2.tobytes()


def test_sphere_claim_matches_the_cli_bit_for_bit(tmp_path):
    path = write_obj(tmp_path / "octa.obj", *skewed_octahedron())
    claim = tmp_path / "claim.json"
    subprocess.run([BIN, "uniformize", str(path), "--sphere", "-o", str(claim)],
                   capture_output=True, text=True, check=True)
    r = penner.uniformize(str(path), sphere=True)
    assert r.certified and json.loads(claim.read_text()) == r.claim
