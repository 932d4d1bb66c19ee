"""Exact mass properties of polyhedra and polygons: the Python binding of libpolymass.

    import polymass
    p = polymass.mass_properties(vertices, faces, density=2700.0)
    p.mass, p.center_of_mass, p.inertia

Units are the caller's (lengths L, density M/L^3, mass M, inertia M*L^2). The
inertia tensor has the negated products of inertia off its diagonal
(Ixy = -integral rho x y dV), as URDF, SDFormat, MuJoCo, PhysX and Bullet expect.
Integration runs about a point inside the mesh, so parts far from the origin
keep their digits.

Options are per call: ``options=polymass.Options(...)``, or its fields as keywords
(``weld=True``, ``skip_intersection_check=True``, ``modes=("solid", "repair")``).
`Mesh` analyses a surface once and answers every question from it (its verdict,
diagnostics, shells, provenance, moments, mass properties of any density).

The C library is the copy the package carries, unless the environment variable
POLYMASS_LIBRARY names another (a path, or libpolymass.so.2 for the one the loader
finds).
"""

from . import _header
from ._library import ffi as _ffi
from ._library import lib as _lib
from ._options import Options
from .batch import batch
from .diagnostics import Checks, Diagnostics, Shell
from .errors import (
    Error,
    FaceTooSmallError,
    InconsistentOrientationError,
    IndexOutOfRangeError,
    InternalError,
    IntersectingSurfaceError,
    InvalidArgumentError,
    InvertedError,
    NonFiniteError,
    NonManifoldError,
    NonPlanarFaceError,
    OpenSurfaceError,
    OutOfMemoryError,
    ResultOutOfRangeError,
    TopologyError,
    ZeroAreaError,
    ZeroVolumeError,
)
from .mesh import Mesh, check
from .moments import Moments, moments
from .packed import PackedMassProperties, packed_mass_properties
from .polygons import PolygonProperties, polygon_properties
from .solids import (
    ErrorBound,
    MassProperties,
    Provenance,
    Repair,
    Warnings,
    mass_properties,
)
from .welding import Welded, weld

__version__: str = _header.POLYMASS_VERSION_STRING
"""The version of the header this binding was built from (the package's version)."""


def library_version() -> str:
    """The version of the C library loaded at run time ("MAJOR.MINOR.PATCH")."""
    return str(_ffi.string(_lib.polymass_version_string()).decode())


__all__ = [
    "Checks",
    "Diagnostics",
    "Error",
    "ErrorBound",
    "FaceTooSmallError",
    "InconsistentOrientationError",
    "IndexOutOfRangeError",
    "InternalError",
    "IntersectingSurfaceError",
    "InvalidArgumentError",
    "InvertedError",
    "MassProperties",
    "Mesh",
    "Moments",
    "NonFiniteError",
    "NonManifoldError",
    "NonPlanarFaceError",
    "OpenSurfaceError",
    "Options",
    "OutOfMemoryError",
    "PackedMassProperties",
    "PolygonProperties",
    "Provenance",
    "Repair",
    "ResultOutOfRangeError",
    "Shell",
    "TopologyError",
    "Warnings",
    "Welded",
    "ZeroAreaError",
    "ZeroVolumeError",
    "__version__",
    "batch",
    "check",
    "library_version",
    "mass_properties",
    "moments",
    "packed_mass_properties",
    "polygon_properties",
    "weld",
]
