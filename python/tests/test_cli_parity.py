"""The package against the command line, run as a separate program: the same rows as
`penner check --json` (but for the timings) and, bit for bit, the same claim as
`penner uniformize -o`. Runs when PENNER_BIN names the `penner` binary (.ci/run sets it);
skipped otherwise."""

import json
import os
import subprocess

import pytest

import penner
from conftest import octahedron, torus, write_obj

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
