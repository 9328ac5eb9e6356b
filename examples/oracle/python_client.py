#!/usr/bin/env python3
"""Using penner as an oracle from Python (standard library only).

Writes claims about a unit tetrahedron, runs `penner certify` on each, parses the JSON
answer and checks the verdict and exit code. Usage:

    python3 examples/oracle/python_client.py [path/to/penner]

Exit status 0 when every answer is the expected one.
"""

import json
import math
from decimal import Decimal, getcontext
import os
import subprocess
import sys
import tempfile

PENNER = sys.argv[1] if len(sys.argv) > 1 else os.environ.get("PENNER", "target/release/penner")

TETRAHEDRON = {
    "vertices": 4,
    "faces": [[0, 1, 2], [0, 2, 3], [0, 3, 1], [1, 3, 2]],
    "lengths": ["1"] * 6,
}

# pi to 40 digits, as an exact decimal string: each vertex of the unit tetrahedron
# carries three corners of pi/3.
PI = "3.141592653589793238462643383279502884197"


def hyperbolic_u(digits=60):
    """u* of the unit tetrahedron read as a hyperbolic metric (all sides 1) with cone angles
    pi/2: each equilateral corner is pi/6, so cosh l = 3 + 2 sqrt 3, sinh^2(l/2) = 1 + sqrt 3,
    and sinh^2(l/2) = e^{2u} sinh^2(1/2) gives u* = ln((1 + sqrt 3)/sinh^2(1/2))/2. Computed
    here with `decimal`, as another implementation would compute its u."""
    getcontext().prec = digits + 10
    half = Decimal(1) / 2
    s = (half.exp() - (-half).exp()) / 2
    u = ((1 + Decimal(3).sqrt()) / (s * s)).ln() / 2
    return f"{u:.{digits}f}"


def hyperbolic_claim(target, u):
    """A `hyperbolic_uniformization` claim: the tetrahedron's hyperbolic metric scaled by u
    at every vertex has cone angles target*pi; a solution within 1e-40 of u."""
    return {"penner_claim": 1, "kind": "hyperbolic_uniformization", "max_bits": 256,
            "surface": TETRAHEDRON, "targets": [target] * 4, "u": [u] * 4,
            "radius": "1e-40", "residual_bound": "1e-40"}


SCHEMA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "schema", "claim-v1.schema.json")


def validator():
    """A validator for schema/claim-v1.schema.json when the `jsonschema` package is
    installed (optional), else None."""
    try:
        import jsonschema  # noqa: PLC0415
    except ImportError:
        return None
    with open(SCHEMA) as f:
        return jsonschema.Draft202012Validator(json.load(f))


def certify(claim):
    """Write `claim` to a file, run penner, return (exit code, parsed answer)."""
    with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
        json.dump(claim, f)
        path = f.name
    try:
        proc = subprocess.run([PENNER, "certify", path], capture_output=True, text=True, timeout=120)
    finally:
        os.unlink(path)
    return proc.returncode, json.loads(proc.stdout)


def main():
    cases = [
        # (description, claim, expected verdict, expected exit code[, first counterexample])
        ("true cone angles",
         {"penner_claim": 1, "id": "tet-true", "kind": "cone_angles", "surface": TETRAHEDRON,
          "angles": [PI] * 4, "epsilon": "1e-35"},
         "holds", 0),
        ("cone angles off by 1e-9 at vertex 2",
         {"penner_claim": 1, "id": "tet-off", "kind": "cone_angles", "surface": TETRAHEDRON,
          "angles": [math.pi, math.pi, math.pi + 1e-9, math.pi], "epsilon": "1e-12"},
         "refuted", 1, "v2"),
        ("Ptolemy flip of a thin rhombus to Delaunay: new diagonal (1*1 + 1*1)/(19/10)",
         {"penner_claim": 1, "id": "rhombus-flip", "kind": "delaunay_flip", "flips": "ptolemy",
          "surface": {"vertices": 4, "faces": [[0, 1, 2], [0, 2, 3]],
                      "lengths": ["1", "1", "19/10", "1", "1"]},
          "result": {"vertices": 4, "faces": [[0, 1, 3], [1, 2, 3]],
                     "lengths": ["1", "20/19", "1", "1", "1"]}},
         "holds", 0),
        ("misspelt optional field (epsilom): refused, not read as epsilon = 0",
         {"penner_claim": 1, "id": "rhombus-typo", "kind": "delaunay_flip", "flips": "ptolemy",
          "surface": {"vertices": 4, "faces": [[0, 1, 2], [0, 2, 3]],
                      "lengths": ["1", "1", "19/10", "1", "1"]},
          "result": {"vertices": 4, "faces": [[0, 1, 3], [1, 2, 3]],
                     "lengths": ["1", "20/19", "1", "1", "1"]},
          "epsilom": "1e-9"},
         "bad_input", 3),
        ("Lobachevsky: Л(1/2) = Cl₂(1)/2",
         {"penner_claim": 1, "id": "lob-half", "kind": "lobachevsky", "x": "0.5",
          "y": "0.506979566180384252147287169443", "epsilon": "1e-25"},
         "holds", 0),
        ("circle packing: radii 1, 2, 3 on the 3-4-5 triangle, tangent exactly",
         {"penner_claim": 1, "id": "packing-345", "kind": "circle_packing",
          "surface": {"vertices": 3, "faces": [[0, 1, 2]]},
          "centres": [["0", "0"], ["3", "0"], ["0", "4"]], "radii": ["1", "2", "3"],
          "epsilon": "1e-30"},
         "holds", 0),
        ("circle packing mirrored (y -> -y): tangent, but the face turns clockwise",
         {"penner_claim": 1, "id": "packing-mirror", "kind": "circle_packing",
          "surface": {"vertices": 3, "faces": [[0, 1, 2]]},
          "centres": [["0", "0"], ["3", "0"], ["0", "-4"]], "radii": ["1", "2", "3"],
          "epsilon": "1e-30"},
         "refuted", 1, "face f0 (v0, v1, v2)"),
        ("circle pattern: unit circles touching on the tetrahedron, cone angles pi",
         {"penner_claim": 1, "id": "pattern-tet", "kind": "circle_pattern",
          "surface": {"vertices": 4, "faces": TETRAHEDRON["faces"]},
          "radii": ["1"] * 4, "phi_over_pi": ["0"] * 6, "angles": [PI] * 4, "epsilon": "1e-35"},
         "holds", 0),
        ("circle packing with both circles and caps: refused",
         {"penner_claim": 1, "id": "packing-both", "kind": "circle_packing",
          "surface": {"vertices": 3, "faces": [[0, 1, 2]]},
          "centres": [["0", "0"], ["3", "0"], ["0", "4"]], "radii": ["1", "2", "3"],
          "caps": [{"normal": ["0", "0", "1"], "height": "0"}] * 3, "epsilon": "1e-30"},
         "bad_input", 3),
        ("sphere uniformization of the tetrahedron, pole 0: the disk is one triangle, no unknowns",
         {"penner_claim": 1, "id": "tet-sphere", "kind": "sphere_uniformization",
          "surface": TETRAHEDRON, "euclidean_flips": [], "pole": 0, "flips": [],
          "u": [None] * 4, "radius": "1e-9", "final_faces": TETRAHEDRON["faces"],
          "residual_bound": "0"},
         "holds", 0),
        ("sphere uniformization without its pole: refused",
         {"penner_claim": 1, "id": "tet-sphere-pole", "kind": "sphere_uniformization",
          "surface": TETRAHEDRON, "euclidean_flips": [], "flips": [],
          "u": [None] * 4, "radius": "1e-9", "final_faces": TETRAHEDRON["faces"],
          "residual_bound": "0"},
         "bad_input", 3),
        ("hyperbolic uniformization: u* of another solver (60 digits), certified by penner",
         hyperbolic_claim("1/2", hyperbolic_u()), "holds", 0),
        ("hyperbolic uniformization with an (empty) flip sequence: the tetrahedron is hyperbolic Delaunay",
         dict(hyperbolic_claim("1/2", hyperbolic_u()), flips=[]), "holds", 0),
        ("hyperbolic uniformization: u rounded to 1.154349 (no solution within the radius, proved)",
         hyperbolic_claim("1/2", "1.154349"), "refuted", 1, "v0"),
        ("hyperbolic target 2*pi on a sphere: Gauss-Bonnet leaves no area",
         hyperbolic_claim("2", "0"), "refuted", 1, "targets (component of v0)"),
        ("unsupported protocol version",
         {"penner_claim": 99, "kind": "cone_angles", "surface": TETRAHEDRON},
         "bad_input", 3),
    ]
    failures = 0
    check = validator()
    for what, claim, verdict, code, *element in cases:
        rc, answer = certify(claim)
        ok = rc == code and answer["verdict"] == verdict
        if check is not None:
            # The schema accepts exactly the well-formed claims.
            ok = ok and check.is_valid(claim) == (verdict != "bad_input")
        print(f"{what}: verdict={answer['verdict']} certified={answer.get('certified')} "
              f"bits={answer.get('precision_bits')} exit={rc} -> {'ok' if ok else 'UNEXPECTED'}")
        if answer["verdict"] == "refuted":
            print(f"  first counterexample: {answer['counterexample']['element']}")
            ok = ok and [answer["counterexample"]["element"]] == element
        failures += not ok
    if failures:
        print(f"{failures} unexpected answer(s)", file=sys.stderr)
        sys.exit(1)


if __name__ == "__main__":
    main()
