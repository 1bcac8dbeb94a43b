# Copyright (c) 2026 The PR-star octree project.
# SPDX-License-Identifier: LGPL-3.0-or-later
"""Type stubs of prstar._files: mesh files (``read``, ``write``) and the conversions from and to
meshio and VTK."""

import os
from typing import Any, Dict, Optional, Tuple, Union

from ._core import Mesh

__all__ = [
    "read",
    "write",
    "from_meshio",
    "to_meshio",
    "from_vtk",
    "to_vtk",
    "EXTENSIONS",
    "LABEL_ARRAY_NAMES",
]

PathLike = Union[str, "os.PathLike[str]"]

EXTENSIONS: Tuple[str, ...]
"""The extensions read and written: '.vtu', '.vtk', '.node/.ele', '.mesh', '.meshb', '.msh', '.off/.ts',
'.xdmf/.xmf'."""

LABEL_ARRAY_NAMES: Tuple[str, ...]
"""The cell-array names taken as labels (the first integer-valued one): label, labels, subdomain,
CellEntityIds, gmsh:physical, medit:ref, MaterialIds."""

def read(path: PathLike, *, max_memory: Optional[Union[int, float]] = None) -> Mesh:
    """Reads a mesh file with the package's reader of its extension (arrays handed over without a
    copy, GIL released).  max_memory: bytes the mesh may need (None: the memory available;
    math.inf: no check).  OSError for a file that cannot be read or is malformed (file and line in
    the message) or too big; ValueError for an unknown extension."""

def write(
    path: PathLike,
    mesh_or_points: Any,
    tetrahedra: Any = None,
    *,
    labels: Any = None,
    point_data: Optional[Dict[str, Any]] = None,
    cell_data: Optional[Dict[str, Any]] = None,
    label_names: Optional[Dict[int, str]] = None,
    binary: Optional[bool] = None,
    compression: Optional[str] = None,
    version: Optional[Union[float, str]] = None,
    overwrite: bool = True,
) -> None:
    """Writes a Mesh, a meshio.Mesh, a vtkUnstructuredGrid, a (points, tetrahedra) pair or points and
    tetrahedra with the package's writer of the extension of path, through a temporary renamed at
    the end.  The keyword arrays are added to a mesh's.  ValueError (InvalidMeshError) for bad
    arrays or options, FileExistsError with overwrite=False, OSError when the file cannot be
    written."""

def from_meshio(m: Any) -> Mesh:
    """A Mesh from a meshio.Mesh: the tetra blocks (others counted in skipped_cells), one-component
    data, labels from the first integer cell array named as in LABEL_ARRAY_NAMES, label names from
    field_data of dimension 3."""

def to_meshio(mesh: Mesh, *, labels_name: str = "gmsh:physical") -> Any:
    """A meshio.Mesh of one tetra block; the labels as the int32 cell array labels_name, label_names
    as field_data {name: [label, 3]}."""

def from_vtk(grid: Any) -> Mesh:
    """A Mesh from a vtkUnstructuredGrid: the VTK_TETRA cells (others counted in skipped_cells),
    one-component arrays, labels as from_meshio."""

def to_vtk(mesh: Mesh) -> Any:
    """A vtkUnstructuredGrid of VTK_TETRA cells: labels as the int32 cell array 'label', the data as
    double arrays."""
