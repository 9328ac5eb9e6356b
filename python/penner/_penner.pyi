"""Type stub of the extension module ``penner._penner`` (the package ``penner`` wraps it)."""

from typing import Any, Dict, List, Optional, Tuple

import numpy as np
import numpy.typing as npt

__version__: str

class InputError(ValueError):
    """Bad input; the message names the element (``V[2, 1]``, ``F[3, 0]``, a face, a line)."""

class Surface:
    """A triangulated surface with an exact metric, validated when made."""

    @property
    def name(self) -> str: ...
    @property
    def n_vertices(self) -> int: ...
    @property
    def n_edges(self) -> int: ...
    @property
    def n_faces(self) -> int: ...
    @property
    def euler_characteristic(self) -> int: ...
    @property
    def is_closed(self) -> bool: ...
    @property
    def V(self) -> Optional[npt.NDArray[np.float64]]: ...
    @property
    def F(self) -> npt.NDArray[np.int64]: ...
    @property
    def l(self) -> npt.NDArray[np.float64]: ...

def make_surface(
    *,
    f: npt.NDArray[np.int64],
    v: Optional[npt.NDArray[np.float64]] = None,
    v_exact: Optional[List[List[str]]] = None,
    l: Optional[npt.NDArray[np.float64]] = None,
    l_exact: Optional[List[List[str]]] = None,
    name: str = "array",
) -> Surface: ...
def read(path: str) -> Surface: ...
def catalogue() -> List[Tuple[str, str]]: ...
def check(
    surface: Surface,
    precision: List[str],
    only: List[str],
    reproducers: bool = True,
    negative_controls: bool = False,
) -> Tuple[List[Dict[str, Any]], List[Dict[str, Any]]]: ...
def uniformize(
    surface: Surface,
    targets: Optional[List[str]] = None,
    flat: bool = False,
    precision: str = "256",
    certify: bool = True,
    sphere: bool = False,
    hyperbolic: bool = False,
    pole: Optional[int] = None,
) -> Dict[str, Any]:
    """The fields of ``penner.UniformizeResult``; ``"uv"`` is None for ``hyperbolic``
    (the hyperbolic metric is returned, no layout in the hyperbolic plane is computed)."""
def intrinsic_delaunay(
    surface: Surface, flips: str = "euclidean", precision: str = "f64", replay: bool = True
) -> Tuple[npt.NDArray[np.int64], npt.NDArray[np.float64], Dict[str, Any]]: ...
def pack(
    f: npt.NDArray[np.int64],
    sphere: bool = False,
    puncture: int = 0,
    bits: int = 128,
    epsilon: str = "1e-20",
    name: str = "array",
) -> Dict[str, Any]: ...
def certify(claim: str) -> Dict[str, Any]: ...
def lobachevsky(
    x: List[float], precision: str = "f64", enclosure: bool = False
) -> npt.NDArray[np.float64]: ...
def parametrize(
    surface: Surface, targets: Optional[List[str]] = None, flat: bool = False
) -> Dict[str, Any]:
    """The fields of ``penner.Parametrization``."""
