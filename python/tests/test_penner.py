"""The Python package against independent results: numpy's own lengths, angle sums and
Euler characteristic, Gauss–Bonnet, and the oracle re-checking the claims that
uniformize returns. Every test has its negative control (a perturbed input that is
refused or rejected)."""

import threading
import time
from fractions import Fraction

import numpy as np
import pytest

import penner
from conftest import (
    angle_sums,
    euler,
    face_lengths,
    octahedron,
    tetrahedron,
    torus,
    write_obj,
)


# --- surfaces and read_mesh -------------------------------------------------------------


def test_surface_lengths_and_euler_match_numpy(octa):
    V, F = octa
    s = penner.surface(V, F)
    assert (s.n_vertices, s.n_faces) == (6, 8)
    assert s.euler_characteristic == euler(F, len(V)) == 2
    np.testing.assert_allclose(s.l, face_lengths(V, F), rtol=1e-15)
    np.testing.assert_array_equal(s.F, F)
    np.testing.assert_array_equal(s.V, V)


def test_per_face_lengths_give_the_same_surface(tet):
    V, F = tet
    l = face_lengths(V, F)
    s = penner.surface(F=F, l=l)
    assert s.V is None and s.euler_characteristic == 2
    np.testing.assert_array_equal(s.l, l)
    # Gauss–Bonnet from numpy's angles of penner's lengths: Σ (2π − θ_i) = 2πχ.
    defect = 2 * np.pi * len(V) - angle_sums(s.F, s.l, len(V)).sum()
    assert abs(defect - 2 * np.pi * s.euler_characteristic) < 1e-12


def test_int32_float32_lists_and_non_contiguous_arrays_are_accepted(tet):
    V, F = tet
    ref = penner.surface(V, F).l
    wide = np.zeros((4, 6))
    wide[:, ::2] = V  # a strided view
    for v, f in [
        (V.astype(np.float32), F.astype(np.int32)),
        (wide[:, ::2], F),
        (np.asfortranarray(V), np.asfortranarray(F)),
        (V.tolist(), F.tolist()),
        (V.astype(np.int64), F.astype(np.uint16)),
    ]:
        np.testing.assert_array_equal(penner.surface(v, f).l, ref)


def test_exact_decimal_strings_are_exact():
    # A right isosceles triangle doubled, legs 1/10 (not a binary64 number): the squared
    # hypotenuse is exactly 2/100, and T16 (cross ratios under scaling) holds exactly.
    V = [["0", "0", "0"], ["0.1", "0", "0"], ["0", "1/10", "0"]]
    F = [[0, 1, 2], [0, 2, 1]]
    s = penner.surface(V, F)
    np.testing.assert_array_equal(s.l[0], [np.sqrt(0.02), 0.1, 0.1])
    rows = penner.check(s, precision=("exact",), only=["T16"])
    assert [r["result"]["verdict"] for r in rows] == ["holds"]
    assert rows[0]["result"]["certified"] is True
    # T01 has no exact form: asking for it alone is refused, not silently empty.
    with pytest.raises(penner.InputError, match="T01: the check has no form"):
        penner.check(s, precision=("exact",), only=["T01"])


def test_read_mesh_round_trips_an_obj(tmp_path, octa):
    V, F = octa
    path = write_obj(tmp_path / "octa.obj", V, F)
    V2, F2 = penner.read_mesh(path)
    np.testing.assert_array_equal(V2, V)
    np.testing.assert_array_equal(F2, F)
    assert V2.dtype == np.float64 and F2.shape == (8, 3)


def test_read_mesh_refusals_name_the_line_or_file(tmp_path, octa):
    V, F = octa
    bad = F.copy()
    bad[3, 1] = 17
    path = write_obj(tmp_path / "bad.obj", V, bad)
    with pytest.raises(penner.InputError, match="line 10"):
        penner.read_mesh(path)
    with pytest.raises(OSError):
        penner.read_mesh(tmp_path / "missing.obj")
    with pytest.raises(penner.InputError, match="unknown surface format"):
        penner.read_mesh(write_obj(tmp_path / "octa.txt", V, F))


# --- bad input: InputError naming the element --------------------------------------------


@pytest.mark.parametrize(
    "change, message",
    [
        (lambda V, F: (np.where(np.arange(12).reshape(4, 3) == 5, np.nan, V), F), r"V\[1, 2\]"),
        (lambda V, F: (np.where(np.arange(12).reshape(4, 3) == 0, np.inf, V), F), r"V\[0, 0\]"),
        (lambda V, F: (V[:, :2], F), r"V has shape \[4, 2\]"),
        (lambda V, F: (V, F[:, :2]), r"F has shape \[4, 2\]"),
        (lambda V, F: (V, np.where(np.arange(12).reshape(4, 3) == 7, 4, F)), r"F\[2, 1\] = 4"),
        (lambda V, F: (V, np.where(np.arange(12).reshape(4, 3) == 3, -1, F)), r"F\[1, 0\] = -1"),
        (lambda V, F: (V, F.astype(float)), "F has dtype float64"),
        (lambda V, F: (np.array([V[0], V[0], V[2], V[3]]), F), "vertices 0 and 1 has length 0"),
        (lambda V, F: ([["1", "1", "x"]] + V[1:].tolist(), F), r"V\[0, 2\]: `x` is not a number"),
    ],
)
def test_bad_input_raises_input_error_naming_the_element(tet, change, message):
    V, F = tet
    penner.surface(V, F)  # the unperturbed input is accepted
    v, f = change(V, F)
    with pytest.raises(penner.InputError, match=message):
        penner.surface(v, f)
    with pytest.raises(penner.InputError, match=message):
        penner.check(v, f, precision=("f64",), only=["T01"])


def test_triangle_inequality_and_unequal_sides_are_refused(tet):
    V, F = tet
    l = face_lengths(V, F)
    penner.surface(F=F, l=l)
    # A doubled triangle: face 1 = (0, 2, 1) has the sides of face 0 in the order 0, 2, 1.
    two = np.array([[0, 1, 2], [0, 2, 1]])
    assert penner.surface(F=two, l=[[3, 4, 5], [3, 5, 4]]).n_faces == 2
    with pytest.raises(penner.InputError, match="face 0"):
        penner.surface(F=two, l=[[1, 1, 3], [1, 3, 1]])
    with pytest.raises(penner.InputError, match="face 0.*degenerate"):
        penner.surface(F=two, l=[[1, 1, 2], [1, 2, 1]])
    with pytest.raises(penner.InputError, match=r"l\[0, 1\] = 4 and l\[1, 2\] = 6 .* differ"):
        penner.surface(F=two, l=[[3, 4, 5], [3, 5, 6]])
    with pytest.raises(penner.InputError, match=r"l\[0, 1\] = -4: a length must be positive"):
        penner.surface(F=two, l=[[3, -4, 5], [3, 5, -4]])
    with pytest.raises(penner.InputError, match=r"(?i)l\[1, 0\] = nan"):
        penner.surface(F=two, l=[[3, 4, 5], [np.nan, 5, 4]])
    with pytest.raises(penner.InputError, match="exactly one"):
        penner.surface(V, F, l=l)


# --- check -----------------------------------------------------------------------------


def test_check_rows_hold_on_the_octahedron(octa):
    V, F = octa
    rows = penner.check(V, F)
    assert rows and {r["precision"] for r in rows} <= {"f64", "dd", "mpfr-256"}
    assert {"case", "theorem", "title", "precision", "precision_bits", "result", "seconds"} <= set(rows[0])
    verdicts = {r["result"]["verdict"] for r in rows}
    assert verdicts <= {"holds", "not_applicable"}, verdicts
    ids = {r["theorem"] for r in rows}
    assert ids <= {c for c, _ in penner.catalogue()}
    t01 = [r for r in rows if r["theorem"] == "T01"]
    assert [r["precision"] for r in t01] == ["f64", "dd", "mpfr-256"]


def test_check_only_and_precision_are_validated(tet):
    V, F = tet
    assert {r["theorem"] for r in penner.check(V, F, precision="f64", only=["T01"])} == {"T01"}
    with pytest.raises(penner.InputError, match="no check `T99`"):
        penner.check(V, F, only=["T99"])
    with pytest.raises(penner.InputError, match="precision"):
        penner.check(V, F, precision=("f65",))


def test_check_sees_a_perturbed_surface_as_a_different_metric(tet):
    # The metric penner checks is the one given: moving a vertex changes the lengths that
    # numpy computes and penner reports, and Gauss–Bonnet still holds (χ does not move).
    V, F = tet
    W = V.copy()
    W[0] += [0.25, -0.125, 0.0625]
    s = penner.surface(W, F)
    np.testing.assert_allclose(s.l, face_lengths(W, F), rtol=1e-15)
    assert not np.allclose(s.l, face_lengths(V, F))
    rows = penner.check(W, F, precision=("f64",), only=["T01"])
    assert rows[0]["result"]["verdict"] == "holds"


# --- uniformize and certify --------------------------------------------------------------


def test_uniformize_octahedron_cones_against_numpy_angles(octa):
    V, F = octa
    targets = [1, 1, Fraction(3, 2), "3/2", 1.5, 1.5]  # Θ_i/π, Σ (2 − t_i) = 2χ
    r = penner.uniformize(V, F, targets=targets)
    assert r.certified and r.reason is None and r.metric == "input"
    assert r.u.shape == (6,) and len(r.u_exact) == 6
    np.testing.assert_allclose([float(Fraction(x)) for x in r.u_exact], r.u, rtol=1e-15)
    # numpy's law of cosines on the returned metric gives the targets.
    theta = angle_sums(r.F_out, r.l_out, 6)
    np.testing.assert_allclose(theta, np.pi * np.array([1, 1, 1.5, 1.5, 1.5, 1.5]), atol=1e-10)
    # l_out is e^{(u_i+u_j)/2} times the input lengths on the (unflipped) triangulation.
    if r.ptolemy_flips == 0:
        l0 = face_lengths(V, r.F_out)
        ui = r.u[r.F_out]
        scale = np.exp([(ui[:, (i + 1) % 3] + ui[:, (i + 2) % 3]) / 2 for i in range(3)]).T
        np.testing.assert_allclose(r.l_out, l0 * scale, rtol=1e-12)
    # The layout's triangles have the lengths of l_out.
    np.testing.assert_allclose(
        np.linalg.norm(r.uv[:, [1, 2, 0]] - r.uv[:, [2, 0, 1]], axis=2), r.l_out, rtol=1e-9
    )
    # The oracle re-checks the claim from scratch.
    answer = penner.certify(r.claim)
    assert answer["verdict"] == "holds" and answer["certified"] is True


def test_a_tampered_claim_is_not_accepted(octa):
    V, F = octa
    r = penner.uniformize(V, F, targets=[1, 1, 1.5, 1.5, 1.5, 1.5])
    claim = dict(r.claim)
    claim["u"] = list(claim["u"])
    claim["u"][2] = "0.1"
    assert penner.certify(claim)["verdict"] != "holds"
    with pytest.raises(penner.InputError):
        penner.certify({"penner_claim": 1, "kind": "uniformization"})
    with pytest.raises(penner.InputError):
        penner.certify("{not json")


def test_uniformize_flat_torus(tmp_path):
    V, F = torus(5, 5)
    r = penner.uniformize(V, F, flat=True)
    assert r.certified, r.reason
    assert r.metric in ("input", "rounded")
    np.testing.assert_allclose(angle_sums(r.F_out, r.l_out, len(V)), 2 * np.pi, atol=1e-10)
    # The same through a file path.
    path = write_obj(tmp_path / "torus.obj", V, F)
    r2 = penner.uniformize(str(path), flat=True)
    np.testing.assert_allclose(r2.u, r.u, atol=1e-12)


def test_uniformize_refusals_and_uncertified_results(tet, octa):
    V, F = tet
    with pytest.raises(penner.InputError, match="Gauss–Bonnet"):
        penner.uniformize(V, F, targets=[1, 1, 1, 1.5])
    with pytest.raises(penner.InputError, match="3 values for 4 vertices"):
        penner.uniformize(V, F, targets=[1, 1, 1])
    with pytest.raises(penner.InputError, match="required"):
        penner.uniformize(V, F)
    with pytest.raises(penner.InputError, match="not both"):
        penner.uniformize(V, F, targets=[1] * 4, flat=True)
    with pytest.raises(penner.InputError, match="Gauss–Bonnet"):
        penner.uniformize(V, F, flat=True)  # a sphere is not flat
    with pytest.raises(penner.InputError, match="precision"):
        penner.uniformize(V, F, targets=[1] * 4, precision=64)
    with pytest.raises(penner.InputError, match=r"targets\[2\]"):
        penner.uniformize(V, F, targets=[1, 1, float("nan"), 1])
    # Not certified is a result with the reason, not an exception or an empty list.
    r = penner.uniformize(V, F, targets=[1] * 4, certify=False)
    assert not r.certified and r.claim is None and "certify=False" in r.reason
    assert r.u.shape == (4,)
    # A surface with boundary (test_pipelines.py): its targets are refused by their count.
    with pytest.raises(penner.InputError, match="3 values for 4 vertices"):
        penner.uniformize(V, F[:3], targets=[1, 1, 1])


def test_precisions_f64_and_dd_certify(octa):
    V, F = octa
    t = [1, 1, 1.5, 1.5, 1.5, 1.5]
    for p in ("f64", "dd", 128):
        r = penner.uniformize(V, F, targets=t, precision=p)
        assert r.certified, (p, r.reason)
        assert penner.certify(r.claim)["verdict"] == "holds"


# --- the GIL is released -----------------------------------------------------------------


def test_threads_run_while_penner_works():
    V, F = torus(10, 10)
    s = penner.surface(V, F)
    reference = penner.uniformize(s, flat=True)
    inside = {}

    def work():
        inside["start"] = time.perf_counter()
        inside["result"] = penner.check(s, precision=("f64", "dd", 256))
        inside["end"] = time.perf_counter()

    t = threading.Thread(target=work)
    ticks = []
    t.start()
    while t.is_alive():
        ticks.append(time.perf_counter())
        time.sleep(0.001)
    t.join()
    start, end = inside["start"], inside["end"]
    assert end - start > 0.05, "the call is too short to tell"
    during = [x for x in ticks if start + 0.2 * (end - start) < x < end - 0.01]
    # With the GIL held for the call, the main thread could not tick at all inside it.
    assert len(during) >= 5, (len(during), end - start)

    # Two uniformizations at once both complete, with the sequential result.
    out = [None, None]

    def solve(k):
        out[k] = penner.uniformize(s, flat=True)

    threads = [threading.Thread(target=solve, args=(k,)) for k in range(2)]
    for th in threads:
        th.start()
    for th in threads:
        th.join()
    for r in out:
        assert r.certified == reference.certified
        np.testing.assert_array_equal(r.u, reference.u)


def test_a_large_mesh_round_trips():
    # 10⁵ faces: the arrays in and out agree with numpy's, and T01 holds.
    V, F = torus(224, 224)
    assert len(F) > 10**5
    s = penner.surface(V, F.astype(np.int32))
    np.testing.assert_array_equal(s.F, F)
    np.testing.assert_array_equal(s.V, V)
    np.testing.assert_allclose(s.l, face_lengths(V, F), rtol=1e-15)
    assert s.euler_characteristic == 0
    rows = penner.check(s, precision=("f64",), only=["T01"])
    assert rows[0]["result"]["verdict"] == "holds"


def numpy_allocations_peak(fn):
    """fn's result and the peak of the memory allocated through Python's allocators
    while it runs (numpy's array buffers included; Rust's heap not)."""
    import tracemalloc

    tracemalloc.start()
    try:
        out = fn()
        return out, tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()


def test_a_large_mesh_crosses_without_numpy_copies():
    # 10⁵ faces through intrinsic_delaunay. float64 V and int64 F go to Rust as they are
    # (Rust copies them once into its own memory), and F_out, l_out are Rust's buffers
    # handed to numpy: while the call runs, Python's allocators hold less than one copy of
    # the smallest array (V), so no array was copied on the Python side.
    V, F = torus(224, 224)
    assert len(F) > 10**5 and V.dtype == np.float64 and F.dtype == np.int64
    (F2, l2, info), peak = numpy_allocations_peak(lambda: penner.intrinsic_delaunay(V, F))
    assert F2.shape == F.shape and l2.shape == F.shape and info["flips"] > 0
    assert peak < V.nbytes, (peak, V.nbytes)
    for a in (F2, l2):
        assert not a.flags.owndata and a.base is not None and not isinstance(a.base, np.ndarray)
    # Negative control: int32 faces are widened to int64 by the wrapper, a copy of F
    # (2 × V's bytes) that the measure sees.
    F32 = F.astype(np.int32)
    _, peak32 = numpy_allocations_peak(lambda: penner.intrinsic_delaunay(V, F32))
    assert peak32 >= F.nbytes > V.nbytes, (peak32, F.nbytes)


def test_help_reads():
    text = penner.__doc__ + penner.uniformize.__doc__ + penner.check.__doc__
    for word in ("(V, F)", "GIL", "InputError", "Gauss–Bonnet", "Θ_i/π"):
        assert word in text
    assert penner.InputError.__doc__ and issubclass(penner.InputError, ValueError)


# --- Lobachevsky's function -------------------------------------------------------------


def clausen_series(x, terms=200000):
    """Л(x) = ½ Σ_k sin(2kx)/k², summed in numpy (tail below 1/(2·terms))."""
    k = np.arange(1, terms + 1)
    return 0.5 * np.sum(np.sin(2 * np.outer(np.atleast_1d(x), k)) / k**2, axis=1)


def test_lobachevsky_against_its_series_and_its_maximum():
    # Л(π/6) = ½ Cl₂(π/3) = 0.50747080320482681251…, the maximum of Л.
    assert abs(penner.lobachevsky(np.pi / 6) - 0.5074708032048268) < 4e-16
    x = np.array([0.1, 0.5, 1.0, 2.5, -0.7, 10.0])
    for p in ("f64", "dd", 128):
        np.testing.assert_allclose(penner.lobachevsky(x, p), clausen_series(x), atol=1e-5)
    # Period π, odd: Л(x + π) = Л(x) = −Л(−x).
    np.testing.assert_allclose(penner.lobachevsky(x + np.pi), penner.lobachevsky(x), atol=1e-14)
    np.testing.assert_allclose(penner.lobachevsky(-x), -penner.lobachevsky(x), atol=0)
    enc = penner.lobachevsky(x, 256, enclosure=True)
    assert enc.shape == (6, 2)
    mid = penner.lobachevsky(x, 256)
    assert np.all(enc[:, 0] <= mid) and np.all(mid <= enc[:, 1])
    assert np.all(enc[:, 1] - enc[:, 0] <= 2 * np.spacing(np.abs(mid)))
    # Negative controls: the enclosure excludes a perturbed value; NaN and a bad
    # precision are refused.
    assert not np.any((enc[:, 0] <= mid + 1e-12) & (mid + 1e-12 <= enc[:, 1]))
    with pytest.raises(penner.InputError, match=r"x\[1\] = NaN"):
        penner.lobachevsky([0.1, np.nan])
    with pytest.raises(penner.InputError, match="precision"):
        penner.lobachevsky(0.1, precision=20)
