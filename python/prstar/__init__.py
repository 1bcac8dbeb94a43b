# Copyright (c) 2026 The PR-star octree project.
# SPDX-License-Identifier: LGPL-3.0-or-later
"""The PR-star octree for tetrahedral meshes, from Python.

A tetrahedral mesh is numpy arrays: ``points`` (n, 3), ``tetrahedra`` (m, 4), optional per-
tetrahedron ``labels`` and per-vertex fields.  The package builds a PR-star octree on them
(:class:`Octree`) and runs its applications leaf by leaf, in parallel, with the GIL released:

>>> import prstar
>>> mesh = prstar.read("part.vtu")                     # every format the package reads
>>> b = prstar.boundary(mesh)                          # vertex types, boundary triangles, counts
>>> c = prstar.curvature(mesh, field="temperature")    # discrete distortion per vertex
>>> small = prstar.simplify(mesh, target=0.5)          # half the tetrahedra, labels kept
>>> prstar.write("small.vtu", small.mesh)

Every application takes a :class:`Mesh`, a ``(points, tetrahedra)`` pair or an :class:`Octree`
(built once, reused); the keyword arguments and defaults are those of the ``prstar`` command-line
tool (``bucket_size`` is its ``--kv``).  Results are in the user's vertex and tetrahedron order.
"""

from __future__ import annotations

from dataclasses import dataclass, field as _field
from typing import Any, Dict, Optional, Union

import numpy as np

from ._core import (BOUNDARY, INTERIOR, NONMANIFOLD, UNREFERENCED, Mesh, MeshLike, ProgressCallback,
                    _field_values, _octree)
from ._prstar import InvalidMeshError, Octree

__all__ = [
    "Octree",
    "Mesh",
    "InvalidMeshError",
    "INTERIOR",
    "BOUNDARY",
    "NONMANIFOLD",
    "UNREFERENCED",
    "BoundaryResult",
    "CurvatureResult",
    "boundary",
    "curvature",
    "distortion",
]

__version__ = "0.1.0"


@dataclass
class BoundaryResult:
    """What :func:`boundary` returns.

    Attributes:
        vertex_types: (n,) uint8 per vertex: INTERIOR 0, BOUNDARY 1, NONMANIFOLD 2, UNREFERENCED 3
            (in no tetrahedron).
        counts: the counts of ``prstar boundary --json`` (vertices, interior_vertices, boundary_vertices,
            nonmanifold_vertices, unreferenced_vertices, boundary_triangles, boundary_tetrahedra,
            boundary_face_tetrahedra, and interface_triangles with ``surface=True``).
        triangles: (k, 3) uint32 surface triangles (user's vertex indices), oriented outward (normals
            out of the mesh; for an interface, towards the larger label); None without ``surface``.
        label_inside: (k,) int32 the label of the tetrahedron inside (the smaller label of an interface).
        label_outside: (k,) int32 the larger label of an interface, -1 on the boundary.
        interface: (k,) bool, True for a triangle between two labels.
    """

    vertex_types: np.ndarray
    counts: Dict[str, int]
    triangles: Optional[np.ndarray] = None
    label_inside: Optional[np.ndarray] = None
    label_outside: Optional[np.ndarray] = None
    interface: Optional[np.ndarray] = None

    @property
    def boundary_triangles(self) -> Optional[np.ndarray]:
        """The triangles on the boundary of the domain (the interfaces between labels left out)."""
        if self.triangles is None or self.interface is None:
            return None
        return self.triangles[~self.interface]


def boundary(
    mesh: MeshLike,
    *,
    surface: bool = True,
    bucket_size: Optional[Union[int, float, str]] = None,
    max_depth: Optional[int] = None,
    threads: Optional[int] = None,
    progress: Optional[ProgressCallback] = None,
) -> BoundaryResult:
    """Classifies every vertex as interior, boundary or non-manifold (paper Section 7) and, with
    ``surface`` (default), returns the boundary triangles and the interfaces between labels, as
    ``prstar boundary --surface``.

    Args:
        mesh: a :class:`Mesh`, a ``(points, tetrahedra)`` pair, or an :class:`Octree`.
        surface: also return the surface triangles (``triangles``, ``label_inside``, ...).
        bucket_size: the bucket threshold k_v (default ``"auto"``: chosen from the mesh, as
            ``--kv auto``; ``math.inf``: one leaf), when an octree
            is built.
        max_depth: the depth bound of the octree built.
        threads: the number of threads (default: all cores), when an octree is built.
        progress: called as ``progress(done, total)`` (leaves), at most ten times a second, with the
            GIL held; an exception it raises stops the computation.
    """
    tree = _octree(mesh, "boundary", bucket_size, max_depth, threads)
    d = tree._boundary(bool(surface), progress)
    return BoundaryResult(
        vertex_types=d["vertex_types"],
        counts=dict(d["counts"]),
        triangles=d.get("triangles"),
        label_inside=d.get("label_inside"),
        label_outside=d.get("label_outside"),
        interface=d.get("interface"),
    )


@dataclass
class CurvatureResult:
    """What :func:`curvature` returns (arrays in the user's vertex order).

    Attributes:
        distortion: (n,) float64 discrete distortion of the field (NaN where undefined: non-manifold
            vertices and vertices in no tetrahedron).
        domain_curvature: (n,) float64 3D concentrated curvature of the domain (NaN where undefined).
        vertex_types: (n,) uint8 as :attr:`BoundaryResult.vertex_types`.
        counts: interior_vertices, boundary_vertices, nonmanifold_vertices, unreferenced_vertices.
    """

    distortion: np.ndarray
    domain_curvature: np.ndarray
    vertex_types: np.ndarray
    counts: Dict[str, int] = _field(default_factory=dict)


def curvature(
    mesh: MeshLike,
    field: Any = None,
    *,
    bucket_size: Optional[Union[int, float, str]] = None,
    max_depth: Optional[int] = None,
    threads: Optional[int] = None,
    progress: Optional[ProgressCallback] = None,
) -> CurvatureResult:
    """The discrete distortion of a scalar field at every vertex and the concentrated curvature of the
    domain (paper Section 8), as ``prstar curvature``.

    Args:
        mesh: a :class:`Mesh`, a ``(points, tetrahedra)`` pair, or an :class:`Octree`.
        field: the name of a point-data array of a Mesh (default: its first one, as the CLI), 'x',
            'y' or 'z' for a coordinate, or an array of one value per vertex (for an Octree built
            with ``field=``, None uses that one).
        bucket_size, max_depth, threads, progress: as :func:`boundary`.
    """
    values = _field_values(mesh, field, "curvature")
    tree = _octree(mesh, "curvature", bucket_size, max_depth, threads)
    d = tree._curvature(values, progress)
    return CurvatureResult(
        distortion=d["distortion"],
        domain_curvature=d["domain_curvature"],
        vertex_types=d["vertex_types"],
        counts=dict(d["counts"]),
    )


def distortion(
    mesh: MeshLike,
    field: Any = None,
    *,
    bucket_size: Optional[Union[int, float, str]] = None,
    max_depth: Optional[int] = None,
    threads: Optional[int] = None,
    progress: Optional[ProgressCallback] = None,
) -> np.ndarray:
    """The discrete distortion of ``field`` at every vertex, an (n,) float64 array (NaN where
    undefined); :func:`curvature` also gives the domain's curvature.  Arguments as :func:`curvature`."""
    return curvature(mesh, field, bucket_size=bucket_size, max_depth=max_depth, threads=threads,
                     progress=progress).distortion


# The other parts of the package: files and conversions, validation and simplification, the
# topology of scalar fields.
from ._files import *  # noqa: E402,F401,F403
from ._files import __all__ as _files_all  # noqa: E402
from ._simplification import *  # noqa: E402,F401,F403
from ._simplification import __all__ as _simplification_all  # noqa: E402
from ._topology import *  # noqa: E402,F401,F403
from ._topology import __all__ as _topology_all  # noqa: E402

__all__ += _files_all + _simplification_all + _topology_all

Octree.__module__ = "prstar"
InvalidMeshError.__module__ = "prstar"
