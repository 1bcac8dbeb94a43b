# Copyright (c) 2026 The PR-star octree project.
# SPDX-License-Identifier: LGPL-3.0-or-later
"""What the modules of the package share: the Mesh class, and how an application gets its octree
and its field from what the user gives."""

from __future__ import annotations

from typing import Any, Callable, Dict, Optional, Tuple, Union

import numpy as np

from ._prstar import Octree

#: vertex type codes (``BoundaryResult.vertex_types``), those of ``prstar boundary``
INTERIOR, BOUNDARY, NONMANIFOLD, UNREFERENCED = 0, 1, 2, 3

ProgressCallback = Callable[[int, int], Any]


class Mesh:
    """A tetrahedral mesh as numpy arrays (what :func:`read` returns and :func:`write` takes).

    Attributes:
        points: (n, 3) float64 coordinates.
        tetrahedra: (m, 4) vertex indices (uint32 when read by the package).
        labels: (m,) int32 per-tetrahedron labels (subdomains, gmsh physical groups), or None.
        point_data: dict name -> (n,) float64 array.
        cell_data: dict name -> (m,) float64 array (the labels apart).
        label_names: dict label -> name (gmsh $PhysicalNames), possibly empty.
        skipped_cells: dict cell type -> count of the cells of other types a reader met.
    """

    __slots__ = ("points", "tetrahedra", "labels", "point_data", "cell_data", "label_names", "skipped_cells")

    def __init__(
        self,
        points: Any,
        tetrahedra: Any,
        labels: Any = None,
        point_data: Optional[Dict[str, Any]] = None,
        cell_data: Optional[Dict[str, Any]] = None,
        label_names: Optional[Dict[int, str]] = None,
        skipped_cells: Optional[Dict[str, int]] = None,
    ) -> None:
        self.points = np.asarray(points)
        self.tetrahedra = np.asarray(tetrahedra)
        self.labels = None if labels is None else np.asarray(labels)
        self.point_data = {} if point_data is None else {str(k): np.asarray(v) for k, v in point_data.items()}
        self.cell_data = {} if cell_data is None else {str(k): np.asarray(v) for k, v in cell_data.items()}
        self.label_names = {} if label_names is None else {int(k): str(v) for k, v in label_names.items()}
        self.skipped_cells = {} if skipped_cells is None else dict(skipped_cells)

    @property
    def number_of_vertices(self) -> int:
        return int(self.points.shape[0])

    @property
    def number_of_tetrahedra(self) -> int:
        return int(self.tetrahedra.shape[0])

    def __repr__(self) -> str:
        parts = [f"{self.number_of_vertices} vertices", f"{self.number_of_tetrahedra} tetrahedra"]
        if self.labels is not None:
            n = len(np.unique(self.labels))
            parts.append("1 label" if n == 1 else f"{n} labels")
        if self.point_data:
            parts.append("point_data " + ", ".join(self.point_data))
        if self.cell_data:
            parts.append("cell_data " + ", ".join(self.cell_data))
        return "prstar.Mesh(" + "; ".join(parts) + ")"


MeshLike = Union[Mesh, Octree, Tuple[Any, Any]]


def _check_no_build_arguments(function: str, bucket_size: Any, max_depth: Any, threads: Any) -> None:
    given = [n for n, v in (("bucket_size", bucket_size), ("max_depth", max_depth), ("threads", threads)) if v is not None]
    if given:
        raise ValueError(
            f"{function}: {', '.join(given)} given with an Octree: they are the Octree's own "
            "(give them to prstar.Octree(...))"
        )


# CGAL::PR_star_octree::Relations of the functions whose leaves build more or less than the default
# (links and triangles): VERTEX_LINKS | LOCAL_TETRAHEDRA for the curvature, VERTEX_TETRAHEDRA for the
# lower stars of the scalar-field topology.
_RELATIONS = {"curvature": 32 | 64, "critical_points": 1, "morse_complexes": 1}


def _octree(
    mesh: MeshLike,
    function: str,
    bucket_size: Any = None,
    max_depth: Any = None,
    threads: Any = None,
    field: Any = None,
) -> Octree:
    """An Octree for ``mesh``: the Octree itself, or one built on a Mesh or (points, tetrahedra)."""
    if isinstance(mesh, Octree):
        _check_no_build_arguments(function, bucket_size, max_depth, threads)
        return mesh
    kv = "auto" if bucket_size is None else bucket_size
    # the relations the function's leaves build, which the automatic k_v is sized for (as the tool's)
    relations = _RELATIONS.get(function, 0)
    if isinstance(mesh, Mesh):
        return Octree(mesh.points, mesh.tetrahedra, bucket_size=kv, max_depth=max_depth, labels=mesh.labels,
                      field=field, threads=threads, _relations=relations)
    if isinstance(mesh, (tuple, list)) and len(mesh) == 2:
        return Octree(mesh[0], mesh[1], bucket_size=kv, max_depth=max_depth, field=field, threads=threads,
                      _relations=relations)
    raise TypeError(f"{function}: expected a prstar.Mesh, an Octree or a (points, tetrahedra) pair, "
                    f"not {type(mesh).__name__}")


def _field_values(mesh: MeshLike, field: Any, function: str) -> Any:
    """The field for ``mesh``: a Mesh's point-data array by name (the first one by default, as the CLI's
    ``--field``), 'x'/'y'/'z', or an array of one value per vertex."""
    if isinstance(field, str) and field not in ("x", "y", "z"):
        if not isinstance(mesh, Mesh):
            raise ValueError(f"{function}: field {field!r}: a name needs a prstar.Mesh with point_data "
                             "(or give an array, or 'x', 'y', 'z')")
        if field not in mesh.point_data:
            have = ", ".join(mesh.point_data) or "none"
            raise ValueError(f"{function}: no point-data array {field!r} (the mesh has: {have}; "
                             "or give 'x', 'y', 'z' for a coordinate)")
        return mesh.point_data[field]
    if field is None and isinstance(mesh, Mesh):
        if not mesh.point_data:
            raise ValueError(f"{function}: the mesh has no point data: give field= (a point-data name, "
                             "'x', 'y', 'z', or an array)")
        return next(iter(mesh.point_data.values()))
    if field is None and not isinstance(mesh, Octree):
        raise ValueError(f"{function}: give field= ('x', 'y', 'z' or an array of one value per vertex)")
    return field


