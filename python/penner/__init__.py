"""penner: certified checks of discrete conformal geometry, from numpy arrays.

A surface is given in the ``(V, F)`` convention of the field, or by per-face lengths, or by
a file:

* ``V`` — vertex positions, an (n, 3) array of float64 (any float dtype is widened
  losslessly; each value is taken as the exact binary64 number it is) or of exact decimal
  strings (``"0.1"``, ``"3/2"``, ``"1e-30"``);
* ``F`` — faces, an (m, 3) array of vertex indices (int32/int64), counter-clockwise;
* ``l`` — per-face lengths, an (m, 3) array, ``l[f, i]`` the length of the side of face
  ``f`` opposite its corner ``i`` (libigl's layout), floats or exact strings, in place of
  ``V``;
* a path to a ``.json``, ``.obj`` or ``.off`` file (coordinates read exactly), in place of
  ``V`` and ``F``;
* a :class:`Surface` made by :func:`surface` or :func:`read`.

Every function validates the surface exactly (positive lengths, strict triangle
inequalities) and raises :class:`InputError` naming the element (``V[2, 1]``,
``F[3, 0]``, ``l[5, 2]``, a face) on bad input. The work runs in Rust with the GIL
released, so threads (and Dask's threaded scheduler) run in parallel.

Example::

    >>> import numpy as np, penner
    >>> V = np.array([[1, 1, 1], [1, -1, -1], [-1, 1, -1], [-1, -1, 1]], float)
    >>> F = np.array([[0, 1, 2], [0, 2, 3], [0, 3, 1], [1, 3, 2]])
    >>> rows = penner.check(V, F, precision=("f64",), only=["T01"])
    >>> rows[0]["result"]["verdict"]
    'holds'
    >>> r = penner.uniformize(V, F, targets=[1, 1, 1, 1])   # cone angles Θ_i = π
    >>> r.certified, penner.certify(r.claim)["verdict"]
    (True, 'holds')
    >>> s = penner.uniformize(V, F, sphere=True)             # inscribed in the unit sphere
    >>> s.uv.shape, penner.certify(s.claim)["verdict"]
    ((4, 3), 'holds')
    >>> F2, l2, info = penner.intrinsic_delaunay(V, F)       # libigl's (m, 3) lengths
    >>> info["certificate"]
    'input_metric'
"""

from __future__ import annotations

import json
import os
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any, Dict, List, Optional, Sequence, Tuple, Union

import numpy as np

from . import _penner
from ._penner import InputError, Surface

__all__ = [
    "CheckRows",
    "InputError",
    "Surface",
    "Parametrization",
    "UniformizeResult",
    "catalogue",
    "certify",
    "check",
    "intrinsic_delaunay",
    "lobachevsky",
    "pack",
    "parametrize",
    "read",
    "read_mesh",
    "surface",
    "uniformize",
]

__version__ = _penner.__version__

PathLike = Union[str, "os.PathLike[str]"]


def _is_path(x: Any) -> bool:
    return isinstance(x, (str, bytes, os.PathLike))


def _exact_rows(a: Any, name: str) -> List[List[str]]:
    """Rows of exact literals from an array or nested sequence of strings."""
    rows = []
    for i, r in enumerate(a):
        if isinstance(r, (str, bytes)) or not hasattr(r, "__len__"):
            raise InputError(f"{name}[{i}] is not a row of three numbers")
        rows.append([_literal(x, f"{name}[{i}]") for x in r])
    return rows


def _literal(x: Any, where: str) -> str:
    """One exact literal: a string as given, an int or Fraction exactly, a float at its
    exact binary64 value."""
    if isinstance(x, (str, np.str_)):
        return str(x)
    if isinstance(x, bytes):
        return x.decode()
    if isinstance(x, (bool, np.bool_)):
        raise InputError(f"{where}: {x!r} is not a number")
    if isinstance(x, (int, np.integer)):
        return str(int(x))
    if isinstance(x, Fraction):
        return f"{x.numerator}/{x.denominator}"
    if isinstance(x, (float, np.floating)):
        x = float(x)
        if x != x or x in (float("inf"), float("-inf")):
            raise InputError(f"{where} = {x}: not a finite number")
        p, q = x.as_integer_ratio()
        return f"{p}/{q}"
    raise InputError(f"{where}: {x!r} is not a number")


def _numbers(a: Any, name: str) -> Dict[str, Any]:
    """``{name: float64 array}`` or ``{name_exact: rows of strings}``."""
    key = name.lower()
    arr = a if isinstance(a, np.ndarray) else None
    if arr is None:
        try:
            arr = np.asarray(a)
        except (ValueError, TypeError) as e:  # ragged rows
            raise InputError(f"{name}: not an (rows, 3) array ({e})") from None
    kind = arr.dtype.kind
    if kind == "f":
        return {key: np.asarray(arr, dtype=np.float64)}
    if kind in "iu":
        if arr.size and int(np.max(np.abs(arr.astype(object)))) > 2**53:
            return {key + "_exact": _exact_rows(arr.tolist(), name)}
        return {key: arr.astype(np.float64)}
    if kind in "USO":
        if arr.ndim != 2:
            raise InputError(f"{name} has shape {arr.shape}: expected (rows, 3)")
        return {key + "_exact": _exact_rows(arr.tolist(), name)}
    raise InputError(f"{name} has dtype {arr.dtype}: expected floats or exact strings")


def _faces(F: Any) -> np.ndarray:
    arr = np.asarray(F)
    if arr.dtype.kind not in "iu":
        if arr.dtype.kind == "f" or arr.size == 0:
            raise InputError(
                f"F has dtype {arr.dtype}: expected integer vertex indices (int32 or int64)"
            )
        raise InputError(f"F has dtype {arr.dtype}: expected integer vertex indices")
    if arr.dtype.kind == "u" and arr.size and int(arr.max()) > np.iinfo(np.int64).max:
        raise InputError("F: a vertex index exceeds the int64 range")
    return arr.astype(np.int64, copy=False)


def surface(
    V: Any = None,
    F: Any = None,
    *,
    l: Any = None,
    name: str = "array",
) -> Surface:
    """Make a :class:`Surface` from ``(V, F)``, from ``F`` and per-face lengths ``l``, or
    from a file path given as ``V``.

    The surface is validated exactly; for positions the metric is the exact squared
    lengths ``|p_i − p_j|²`` of the coordinates as given.

    >>> s = penner.surface(F=[[0, 1, 2], [0, 2, 1]], l=[["1", "1", "1"]] * 2)
    >>> s.euler_characteristic
    2
    """
    if isinstance(V, Surface):
        return V
    if _is_path(V):
        if F is not None or l is not None:
            raise InputError("a path stands for the whole surface: give no F or l with it")
        return read(V)
    if F is None:
        raise InputError("F (the faces) is required")
    if (V is None) == (l is None):
        raise InputError("give exactly one of the positions V or the per-face lengths l")
    kw: Dict[str, Any] = {"f": _faces(F), "name": name}
    kw.update(_numbers(V, "V") if V is not None else _numbers(l, "l"))
    return _penner.make_surface(**kw)


def read(path: PathLike) -> Surface:
    """Read a surface file (``.json``, ``.obj``, ``.off``) into a :class:`Surface`.

    Coordinates and lengths are read exactly. Raises ``OSError`` when the file cannot be
    opened and :class:`InputError` (naming the line or element) when it is refused.
    """
    return _penner.read(os.fspath(path))


def read_mesh(path: PathLike) -> Tuple[Optional[np.ndarray], np.ndarray]:
    """Read a surface file and return ``(V, F)``: positions (n, 3) float64 (nearest
    binary64 values of the exact coordinates; ``None`` for a surface given by lengths only)
    and faces (m, 3) int64.

    >>> V, F = penner.read_mesh("bunny.obj")
    """
    s = read(path)
    return s.V, s.F


def _target_literals(targets: Optional[Sequence[Any]]) -> Optional[List[str]]:
    """The targets ``Θ_i/π`` as exact literals, one per vertex (None stays None)."""
    if targets is None:
        return None
    if isinstance(targets, (str, bytes)):
        raise InputError("targets: expected one Θ_i/π per vertex, not a string")
    seq = targets.ravel().tolist() if isinstance(targets, np.ndarray) else list(targets)
    return [_literal(x, f"targets[{i}]") for i, x in enumerate(seq)]


def _surface_of(V: Any, F: Any, l: Any) -> Surface:
    if isinstance(V, Surface):
        return V
    return surface(V, F, l=l)


def catalogue() -> List[Tuple[str, str]]:
    """The checks of this build, as ``(id, title)`` pairs (``docs/catalogue.md``)."""
    return list(_penner.catalogue())


class CheckRows(list):
    """The rows of :func:`check` (a list of dicts, as ``penner check --json`` prints them)
    with ``failures``: per failing check, the document of its failure file
    (``penner_failure``, the check, precision, witnesses and a minimal reproducing
    ``surface``, which ``penner replay`` re-runs)."""

    failures: List[Dict[str, Any]]

    def __init__(self, rows: Sequence[Dict[str, Any]] = (), failures: Sequence[Dict[str, Any]] = ()):
        super().__init__(rows)
        self.failures = list(failures)

    def __reduce__(self):  # pickled (Dask) with its failures
        return (CheckRows, (list(self), self.failures))


def check(
    V: Any = None,
    F: Any = None,
    *,
    l: Any = None,
    precision: Sequence[Union[str, int]] = ("f64", "dd", 256),
    only: Optional[Sequence[str]] = None,
    reproducers: bool = True,
    negative_controls: bool = False,
) -> CheckRows:
    """Run every applicable check (or those named in ``only``, e.g. ``["T01", "T21"]``) at
    each precision (``"f64"``, ``"dd"``, MPFR bits 53..65536, ``"exact"``), as
    ``penner check`` does (the library's ``check_surface``).

    Returns one dict per (check, precision), as ``penner check --json`` prints them:
    ``case``, ``theorem``, ``title``, ``precision``, ``precision_bits``, ``seconds`` and
    ``result`` (``verdict``: ``holds`` / ``fails`` / ``undecided`` / ``not_applicable``,
    whether it is ``certified``, the witnesses of a failure). T01, for instance, is Gauss–Bonnet:
    ``Σ_i (2π − Σ angles at i) = 2πχ``. The list's ``failures`` holds, per failing check,
    its failure file's document with a minimal reproducer (none with
    ``reproducers=False``; nothing is written to disk). ``negative_controls=True`` runs the
    perturbed controls instead (each must fail).

    >>> rows = penner.check(V, F, precision=("f64",), only=["T01"])
    >>> rows[0]["result"]["verdict"], rows.failures
    ('holds', [])
    """
    s = _surface_of(V, F, l)
    if isinstance(precision, (str, int)):
        precision = [precision]
    rows, failures = _penner.check(
        s,
        [str(p) for p in precision],
        [str(x) for x in (only or [])],
        bool(reproducers),
        bool(negative_controls),
    )
    return CheckRows(rows, failures)


_RESULT_FIELDS = (
    "certified u u_exact F_out l_out uv radius distance residual metric metric_reason claim "
    "reason converged stop newton_steps euclidean_flips ptolemy_flips shift bits "
    "residual_max_f64 target layout F_layout pole"
).split()


@dataclass(frozen=True)
class UniformizeResult:
    """The outcome of :func:`uniformize`.

    ``certified`` is True when an exact solution ``u*`` of ``θ_i(u*) = Θ_i`` is proved to
    lie within ``distance`` (2-norm, and in the box of sup-norm ``radius``) of ``u``;
    otherwise ``reason`` says why (not converged, not certified, not asked, a step that
    did not go through), and the numerical solution is still returned.

    Attributes:
        target: ``"closed"``, ``"boundary"``, ``"sphere"`` or ``"hyperbolic"``.
        u: (n,) float64 log scale factors (the certificate's centre when certified; for
            the sphere, the disk problem's, NaN at the pole; NaN everywhere when nothing
            was computed).
        u_exact: the same as exact decimal strings (the values of the claim).
        F_out: (m, 3) the final triangulation (intrinsic Delaunay for the scaled metric;
            with boundary, copy 1 of the double when its seam is intact, else the whole
            double, whose copy-2 vertices are numbered from n).
        l_out: (m, 3) its lengths ``e^{(u_i+u_j)/2} ℓ_ij``, ``l_out[f, i]`` opposite corner
            ``i`` (hyperbolic lengths for ``hyperbolic``; chords of ``uv`` for the sphere).
        uv: (m, 3, 2) a planar layout per corner (a fundamental domain cut along the
            edges outside a dual spanning tree; NaN for faces not reached); for the sphere
            the inscribed positions (n, 3) on the unit sphere; None for ``hyperbolic``:
            the hyperbolic target returns the metric (``u``, ``F_out``, ``l_out``), and
            no layout of it in the hyperbolic plane is computed.
        layout, F_layout: the sphere's planar disk (the surface punctured at ``pole``):
            (k, 3, 2) per corner of its faces ``F_layout`` (k, 3).
        certified, radius, distance, residual: the certificate (``residual`` bounds
            ``‖Θ − θ(u)‖₂`` when certified, else is the numerical ``max |Θ − θ|``).
        metric: ``"input"`` (the certificate is about the input's exact metric) or
            ``"rounded"`` (about its binary64 rounding; ``metric_reason`` says why).
        claim: the claim (``uniformization`` — of the double for a surface with boundary —,
            ``sphere_uniformization`` or ``hyperbolic_uniformization``) that
            :func:`certify` (and ``penner certify``) re-checks from scratch, or None.
        reason: why the result is not certified, or None.
        details: what only one target has (``folds``, ``seam_flips``, ``layout_of``,
            ``mirror_asymmetry`` with boundary; ``planar``, ``deviation`` and
            ``layout_failure`` for the sphere — why vertices binary64 cannot place are
            NaN in ``uv`` and ``layout``, or None;
            ``area``, ``gauss_bonnet`` for ``hyperbolic``).
    """

    certified: bool
    u: np.ndarray
    u_exact: List[str]
    F_out: np.ndarray
    l_out: np.ndarray
    uv: Optional[np.ndarray]
    radius: Optional[float]
    distance: Optional[float]
    residual: float
    metric: Optional[str]
    metric_reason: Optional[str]
    claim: Optional[Dict[str, Any]]
    reason: Optional[str]
    converged: bool
    stop: str
    newton_steps: int
    euclidean_flips: int
    ptolemy_flips: int
    shift: int
    bits: int
    residual_max_f64: float = field(repr=False, default=float("nan"))
    target: str = "closed"
    layout: Optional[np.ndarray] = field(repr=False, default=None)
    F_layout: Optional[np.ndarray] = field(repr=False, default=None)
    pole: Optional[int] = None
    details: Dict[str, Any] = field(repr=False, default_factory=dict)

    def __bool__(self) -> bool:
        return self.certified


def uniformize(
    V: Any = None,
    F: Any = None,
    *,
    l: Any = None,
    targets: Optional[Sequence[Any]] = None,
    flat: bool = False,
    sphere: bool = False,
    hyperbolic: bool = False,
    pole: Optional[int] = None,
    precision: Union[str, int] = 256,
    certify: bool = True,
) -> UniformizeResult:
    """Discrete uniformization with Ptolemy flips: find ``u`` such that the metric
    ``e^{(u_i+u_j)/2} ℓ_ij`` (on the intrinsic Delaunay triangulation it reaches) has cone
    angle ``Θ_i`` at every vertex.

    * A closed surface (T24): flat (``Θ_i = 2π``, genus 1) with ``flat=True``, or
      ``targets``, one ``Θ_i/π`` per vertex (ints, ``Fraction``, exact strings such as
      ``"2/3"``; floats are taken at their exact binary64 value), with
      ``Σ_i (2π − Θ_i) = 2πχ`` (Gauss–Bonnet).
    * A surface with boundary (B79): ``targets`` are ``Θ_v/π`` at interior vertices and
      the boundary angle sums ``φ_v/π`` at boundary vertices; ``flat=True`` is flat inside
      with the boundary curvature spread evenly. Solved and certified on the double.
    * ``sphere=True`` (genus 0, B74–B76): the conformally equivalent convex polyhedron
      inscribed in the unit sphere; ``uv`` holds its vertices (n, 3), ``layout`` the
      planar disk of the surface punctured at ``pole`` (default: chosen).
    * ``hyperbolic=True`` (B38, B39): the lengths read as hyperbolic lengths, ``targets``
      default ``2π``; the certificate is about the binary64 lengths. The result is the
      hyperbolic metric (``u``, ``F_out``, ``l_out``); ``uv`` is None, as no layout in
      the hyperbolic plane is computed.

    The solve runs in binary64, is refined at ``precision`` (``"f64"``, ``"dd"`` or MPFR
    bits 128..4096) and certified in MPFR interval arithmetic, for the input's exact
    metric where possible. Not converging or not certifying is a result with
    ``certified=False`` and ``reason``, never an exception; bad input (including targets
    that violate Gauss–Bonnet, ``precision="dd"`` with ``sphere=True``) raises
    :class:`InputError`.

    >>> r = penner.uniformize(V, F, targets=[1, 1, 1, 1])
    >>> r.certified, r.u.shape
    (True, (4,))
    """
    s = _surface_of(V, F, l)
    t = _target_literals(targets)
    if pole is not None:
        if isinstance(pole, (bool, np.bool_)) or not isinstance(pole, (int, np.integer)) or pole < 0:
            raise InputError(f"pole: {pole!r} is not a vertex index")
        pole = int(pole)
    d = _penner.uniformize(
        s, t, bool(flat), str(precision), bool(certify), bool(sphere), bool(hyperbolic), pole
    )
    known = {k: d.pop(k) for k in list(d) if k in _RESULT_FIELDS}
    return UniformizeResult(**known, details=d)


@dataclass(frozen=True)
class Parametrization:
    """The outcome of :func:`parametrize`: texture coordinates on the input mesh.

    Attributes:
        V: (k, 3) float64 positions of the refinement's vertices on the input surface (the
            input vertices first, in their order, then the crossings of input edges with
            edges of the final triangulation).
        F: (m, 3) int64 its triangles, counterclockwise.
        uv: (m, 3, 2) float64 texture coordinates per corner (cut along a cut graph).
        input_face, final_face: (m,) the face of the input and of the final triangulation
            each triangle lies in.
        barycentric: (m, 3, 3) float64 the corners' barycentric coordinates in their input
            face (row ``i``: corner ``i``; the columns follow the input face's corners).
        obj, sidecar: the OBJ text and sidecar that ``penner uniformize … --uv`` writes
            (the sidecar's decimals exact, each barycentric row summing to 1 in ℚ).
        checks: the exact checks of that text (B109, B110): ``holds``, ``uv_folds``,
            ``input_folds``, ``untiled_faces``, and ``seam_segments``/``broken_seams``
            when every cone angle is a multiple of π/2 (else None).
        reason: why no UV mesh was computed (then every other field is None), or None.
    """

    V: Optional[np.ndarray]
    F: Optional[np.ndarray]
    uv: Optional[np.ndarray]
    input_face: Optional[np.ndarray]
    final_face: Optional[np.ndarray]
    barycentric: Optional[np.ndarray]
    obj: Optional[str] = field(repr=False)
    sidecar: Optional[Dict[str, Any]] = field(repr=False)
    checks: Optional[Dict[str, Any]]
    reason: Optional[str]

    def __bool__(self) -> bool:
        return bool(self.checks and self.checks["holds"])


def parametrize(
    V: Any = None,
    F: Any = None,
    *,
    targets: Optional[Sequence[Any]] = None,
    flat: bool = False,
) -> Parametrization:
    """UVs on the input mesh, as ``penner uniformize … --no-certify --uv OUT.obj``: solve
    for the cone angles ``targets`` (``Θ_i/π``; with boundary ``φ_v/π`` at boundary
    vertices) or ``flat=True`` in binary64, then build the common refinement of the input
    triangulation and the final one (B108, B111; with boundary on copy 1 of the double)
    and lay it out with the solved metric (B109). The result's ``checks`` are exact, on the
    written text: no fold, every input face tiled. The surface needs vertex positions.
    Bad input raises :class:`InputError`; a UV mesh that could not be computed is a result
    with ``reason``.

    >>> p = penner.parametrize(V, F, targets=[1, 1, 1, 1])
    >>> p.checks["holds"], p.F.shape[1], p.uv.shape[1:]
    (True, 3, (3, 2))
    """
    s = _surface_of(V, F, None)
    t = _target_literals(targets)
    return Parametrization(**_penner.parametrize(s, t, bool(flat)))


def intrinsic_delaunay(
    V: Any = None,
    F: Any = None,
    *,
    l: Any = None,
    flips: str = "euclidean",
    precision: Union[str, int] = "f64",
    replay: bool = True,
) -> Tuple[np.ndarray, np.ndarray, Dict[str, Any]]:
    """Flip the surface to its intrinsic Delaunay triangulation, as ``penner delaunay``
    does: every interior edge ``ij`` with opposite angles ``α, β`` then has
    ``cot α + cot β ≥ 0`` (``α + β ≤ π``), each decision certified (B61–B63).

    ``flips`` is ``"euclidean"`` (the lengths of the flipped diagonals are those of the
    flat quadrilateral) or ``"ptolemy"`` (``ℓ_new = (ℓ_a ℓ_c + ℓ_b ℓ_d)/ℓ_e``);
    ``precision`` ``"f64"``, ``"dd"``, MPFR bits or ``"exact"`` (Ptolemy flips of exact
    lengths). A rounded run is replayed on the input's exact metric (``replay``, B80).

    Returns ``(F_out, l_out, info)``: the faces (m, 3) int64, the lengths (m, 3) float64
    in libigl's layout (``l_out[f, i]`` opposite corner ``i``, as
    ``igl.intrinsic_delaunay_cotmatrix`` returns them), and ``info`` with ``flips``,
    ``certificate`` (``"input_metric"``, ``"rounded_metric"`` or ``"none"``), ``holds``,
    ``words``, ``flip_sequence`` (edge indices) and ``summary`` (the document of
    ``penner delaunay --summary``). Bad input or options raise :class:`InputError`.

    >>> F2, l2, info = penner.intrinsic_delaunay(V, F)
    >>> info["certificate"], l2.shape
    ('input_metric', (4, 3))
    """
    s = _surface_of(V, F, l)
    if not isinstance(flips, str):
        raise InputError(f"flips: expected \"euclidean\" or \"ptolemy\", got {flips!r}")
    return tuple(_penner.intrinsic_delaunay(s, flips, str(precision), bool(replay)))  # type: ignore[return-value]


def pack(
    F: Any,
    mode: str = "disk",
    *,
    puncture: int = 0,
    bits: int = 128,
    epsilon: Union[str, float, Fraction] = "1e-20",
) -> Dict[str, Any]:
    """The maximal circle packing of a triangulation (Koebe–Andreev–Thurston, T11), as
    ``penner pack`` computes it: circles with disjoint interiors, ``|c_i − c_j| = r_i + r_j``
    on every edge, boundary circles internally tangent to the unit circle
    (``|c_i| + r_i = 1``), ``mode="disk"`` for a disk, or ``mode="sphere"`` for a sphere
    punctured at ``puncture`` (its circles in the unit disk, and caps on the sphere).

    ``F`` is the faces (m, 3) (or a :class:`Surface` or a path: only its faces count).
    The packing is computed at ``bits`` MPFR bits (53: binary64) and its tangency
    certified within ``epsilon`` (an exact literal) by exact predicates on the exact
    values of the computed circles, refined at twice the bits while it misses.

    Returns a dict: ``centres`` (n, 2), ``radii`` (n,), ``unit_disk`` (n,) bool (tangent
    to the unit circle), ``faces`` (the packed disk's faces; for the sphere, without the
    star of the puncture, whose row of ``centres`` is NaN), ``caps`` (n, 4) rows
    ``(N_x, N_y, N_z, H)`` of the caps ``{P: N·P > H}`` for the sphere, ``certified``,
    ``verdict`` (``"holds"`` or ``"undecided"``: the packing exists, a miss is the
    computation's), ``reason``, ``max_defect``, ``bits`` reached and ``document`` (the
    exact values, as ``penner pack -o``). Bad input raises :class:`InputError`.

    >>> p = penner.pack(F_octahedron, mode="sphere")
    >>> p["certified"], p["caps"].shape
    (True, (6, 4))
    """
    if mode not in ("disk", "sphere"):
        raise InputError(f"mode: expected \"disk\" or \"sphere\", got {mode!r}")
    if isinstance(F, Surface) or _is_path(F):
        F = surface(F).F
    for name, x in (("puncture", puncture), ("bits", bits)):
        if isinstance(x, (bool, np.bool_)) or not isinstance(x, (int, np.integer)) or not 0 <= x < 2**31:
            raise InputError(f"{name}: {x!r} is not a non-negative integer (below 2³¹)")
    eps = _literal(epsilon, "epsilon")
    return _penner.pack(_faces(F), mode == "sphere", int(puncture), int(bits), eps)


def certify(claim: Union[Dict[str, Any], str]) -> Dict[str, Any]:
    """Answer a claim (protocol v1, ``docs/oracle.md``; a dict or its JSON text) from
    scratch, as ``penner certify`` does: ``{"verdict": "holds" | "refuted" | "undecided",
    "certified": …, "counterexample": …, "witnesses": …}``. A malformed claim raises
    :class:`InputError`.

    >>> penner.certify(penner.uniformize(V, F, targets=[1, 1, 1, 1]).claim)["verdict"]
    'holds'
    """
    if isinstance(claim, (str, bytes)):
        text = claim if isinstance(claim, str) else claim.decode()
    else:
        try:
            text = json.dumps(claim, allow_nan=False)
        except (TypeError, ValueError) as e:
            raise InputError(f"claim: not a JSON document ({e})") from None
    return _penner.certify(text)


def lobachevsky(
    x: Any, precision: Union[str, int] = "f64", enclosure: bool = False
) -> Union[float, np.ndarray]:
    """Lobachevsky's function ``Л(x) = −∫₀ˣ log|2 sin t| dt = ½ Cl₂(2x)`` of a float or an
    array, evaluated at ``precision`` (``"f64"``, ``"dd"`` or MPFR bits 53..65536) and
    rounded to binary64. With ``enclosure=True``, an array ``[..., 2]`` of bounds
    ``(lo, hi)`` rounded outward from a rigorous MPFR enclosure at ``precision`` bits
    (at least 53), so ``lo ≤ Л(x) ≤ hi`` for the binary64 ``x``. NaN or an infinite ``x``
    raises :class:`InputError`.

    >>> penner.lobachevsky(np.pi / 6)      # the maximum of Л
    0.5074708032048268
    """
    a = np.asarray(x, dtype=np.float64)
    out = _penner.lobachevsky(a.ravel().tolist(), str(precision), bool(enclosure))
    if enclosure:
        return out.reshape(a.shape + (2,))
    return float(out[0]) if a.ndim == 0 else out.reshape(a.shape)
