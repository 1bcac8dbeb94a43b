# Copyright (c) 2026 The PR-star octree project.
# SPDX-License-Identifier: LGPL-3.0-or-later
"""Mesh files and other libraries: :func:`read` and :func:`write` (the package's own readers and
writers, chosen by the file's extension), and the conversions from and to meshio
(:func:`from_meshio`, :func:`to_meshio`) and VTK (:func:`from_vtk`, :func:`to_vtk`), in memory.

The conversions take what the package's readers take from a file of the same content: the
tetrahedra (other cells are counted in ``skipped_cells``), one-component point and cell arrays,
and as labels the first integer-valued cell array named as in :data:`LABEL_ARRAY_NAMES`.
"""

from __future__ import annotations

import os
import warnings
from typing import Any, Dict, List, Optional, Tuple, Union

import numpy as np

from ._core import Mesh
from ._prstar import InvalidMeshError, _extensions, _is_label_array_name, _read, _vtk_cell_type_name, _write

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

#: The file extensions :func:`read` and :func:`write` know (from the package's format table), as
#: ``prstar --help`` lists them: ``.node/.ele`` are the two files of a TetGen mesh.
EXTENSIONS: Tuple[str, ...] = tuple(e.strip() for e in _extensions().split(","))

#: The names of the cell arrays taken as the tetrahedron labels (the first one, in array order, whose
#: values are all integers), as the package's VTK, VTU and XDMF readers do: the package's ``label``,
#: ``labels``, ``subdomain``, VTK's ``CellEntityIds``, meshio's ``gmsh:physical`` and ``medit:ref``,
#: deal.II's ``MaterialIds``.
LABEL_ARRAY_NAMES: Tuple[str, ...] = tuple(
    n for n in ("label", "labels", "subdomain", "CellEntityIds", "gmsh:physical", "medit:ref", "MaterialIds")
    if _is_label_array_name(n))

# meshio's cell type names -> VTK cell types (VTK's numbering), so that the cells skipped by
# from_meshio are named as the package's readers name them (by VTK type) in ``skipped_cells``.
_MESHIO_VTK_TYPES = {
    "vertex": 1, "line": 3, "triangle": 5, "polygon": 7, "quad": 9, "tetra": 10, "hexahedron": 12,
    "wedge": 13, "pyramid": 14, "line3": 21, "triangle6": 22, "quad8": 23, "tetra10": 24,
    "hexahedron20": 25, "wedge15": 26, "pyramid13": 27,
}

_INT32 = np.iinfo(np.int32)

# meshio's bookkeeping of gmsh entities (not data): skipped by from_meshio, as the package's gmsh
# reader skips the entity tags.
_MESHIO_GMSH_ENTITIES = ("gmsh:dim_tags", "gmsh:geometrical")


def _path(path: PathLike, function: str) -> str:
    try:
        return os.fsdecode(os.fspath(path))
    except TypeError:
        raise TypeError(f"{function}: path must be a str or an os.PathLike, not {type(path).__name__}") from None


def read(path: PathLike, *, max_memory: Optional[Union[int, float]] = None) -> Mesh:
    """Reads a tetrahedral mesh file with the package's reader of its extension (:data:`EXTENSIONS`):
    ``.vtu``, ``.vtk``, ``.node``/``.ele`` (both files are read), ``.mesh``, ``.meshb``, ``.msh``,
    ``.off``/``.ts``, ``.xdmf``/``.xmf``.  The arrays the reader made are handed over without a
    copy; the GIL is released while the file is read.

    Args:
        path: the file (a str or an ``os.PathLike``).
        max_memory: the bytes the mesh may need in memory: a file whose header announces a bigger
            mesh is refused before anything is allocated.  None (default): the memory the system
            reports as available; ``math.inf``: no check.

    Returns:
        A :class:`Mesh`: points (n, 3) float64, tetrahedra (m, 4) uint32, labels (m,) int32 or None
        when the file has none, point_data and cell_data (float64 arrays by name, in file order),
        label_names (gmsh ``$PhysicalNames``), skipped_cells (the cells of other types, by VTK name,
        counted).

    Raises:
        OSError: the file cannot be read, is malformed (the message names the file and, for text,
            the line) or announces a mesh above ``max_memory``.
        ValueError: an extension the package does not know (the message lists those it knows), or a
            bad ``max_memory``.
    """
    d = _read(_path(path, "read"), max_memory)
    return Mesh(d["points"], d["tetrahedra"], d["labels"], d["point_data"], d["cell_data"], d["label_names"],
                d["skipped_cells"])


def _as_mesh(obj: Any, function: str) -> Optional[Mesh]:
    """A Mesh for what write() accepts as a whole mesh: a Mesh, a meshio.Mesh, a vtkUnstructuredGrid;
    None for anything else (arrays)."""
    if isinstance(obj, Mesh):
        return obj
    if type(obj).__module__.split(".")[0] == "meshio" and hasattr(obj, "cells"):
        return from_meshio(obj)
    if hasattr(obj, "GetCellTypesArray") and hasattr(obj, "GetPoints"):
        return from_vtk(obj)
    return None


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
    """Writes a tetrahedral mesh with the package's writer of the extension of ``path``
    (:data:`EXTENSIONS`), as ``meshio.write`` (a mesh) or ``meshio.write_points_cells`` (arrays).

    The file is written to a temporary beside ``path`` and renamed at the end: an error (or a crash)
    never leaves a half-written file under ``path``, and an existing file is replaced whole or not at
    all.  The arrays are read in place (any dtype, any memory layout) and the GIL is released while
    the file is written.

    What each format keeps: labels in every format but ``.off``; point data in ``.vtu``, ``.vtk``,
    ``.node``, ``.msh``, ``.xdmf`` (``.off``: the first array only); cell data in ``.vtu``, ``.vtk``,
    ``.msh``, ``.xdmf``; label names in ``.msh``.  ``prstar convert`` names what a format drops.

    Args:
        path: the file (str or ``os.PathLike``); its extension chooses the format.  A TetGen mesh is
            two files, ``.node`` and ``.ele``; an XDMF file keeps its heavy data in ``<stem>.h5``
            (unless ``binary=False``: inline XML).
        mesh_or_points: a :class:`Mesh`, a ``meshio.Mesh`` or a ``vtkUnstructuredGrid`` (converted as
            :func:`from_meshio`, :func:`from_vtk`), a ``(points, tetrahedra)`` pair, or the points,
            (n, 3) float.
        tetrahedra: (m, 4) integer vertex indices (0-based), with points only.
        labels: (m,) integer labels of the tetrahedra (with a mesh: replace its labels).
        point_data: name -> (n,) array of finite values (with a mesh: added to its arrays, replacing
            those of the same name).
        cell_data: name -> (m,) array of finite values, the labels apart (with a mesh: as
            point_data).
        label_names: label -> name (gmsh ``$PhysicalNames``; with a mesh: added to its names).
        binary: binary (True) or text (False) where the format has both; None: the format's default
            (binary ``.vtu``, ``.meshb``, ``.xdmf`` with an ``.h5``; text for the others).
        compression: ``"zlib"`` or ``"none"`` (binary ``.vtu`` only); None: zlib for a binary ``.vtu``.
        version: the version of the format written, e.g. 2.2 or 4.1 (default) for ``.msh``, 5.1 or
            4.2 (default) for ``.vtk``, 1 to 4 for ``.meshb``.
        overwrite: replace an existing file (default); False: raise FileExistsError instead.

    Raises:
        ValueError: wrong arrays (shape, dtype, sizes, non-finite values), an unknown extension, an
            option the format cannot honour; :class:`InvalidMeshError` (a ValueError) for a vertex
            index out of range, a vertex twice in a tetrahedron or a non-finite coordinate.
        FileExistsError: ``overwrite=False`` and the file (one of the files) exists.
        OSError: the file cannot be written (the message names it); nothing is left behind.
    """
    target = _path(path, "write")
    if not isinstance(overwrite, bool):
        raise TypeError("write: overwrite must be True or False")
    mesh = _as_mesh(mesh_or_points, "write")
    if mesh is None and tetrahedra is None and isinstance(mesh_or_points, (tuple, list)) and len(mesh_or_points) == 2:
        points, tetrahedra = mesh_or_points
    elif mesh is None:
        if tetrahedra is None:
            raise TypeError("write: give a prstar.Mesh (or a meshio.Mesh, a vtkUnstructuredGrid), a "
                            "(points, tetrahedra) pair, or points and tetrahedra")
        points = mesh_or_points
    else:
        if tetrahedra is not None:
            raise TypeError("write: tetrahedra given with a mesh (they are the mesh's own)")
        points, tetrahedra = mesh.points, mesh.tetrahedra
        labels = mesh.labels if labels is None else labels
        point_data = {**mesh.point_data, **(point_data or {})}
        cell_data = {**mesh.cell_data, **(cell_data or {})}
        label_names = {**mesh.label_names, **(label_names or {})}
    names = {int(k): str(v) for k, v in (label_names or {}).items()}
    _write(target, points, tetrahedra, labels, dict(point_data or {}), dict(cell_data or {}), names, binary,
           compression, version, overwrite)


# ---------------------------------------------------------------------------------------------
# Conversions: what they share
# ---------------------------------------------------------------------------------------------


def _check_tetrahedra(tetrahedra: np.ndarray, nv: int, function: str) -> np.ndarray:
    """The tetrahedra as uint32 (the dtype :func:`read` gives), checked as the package's readers
    check them: indices in [0, nv), four distinct vertices."""
    t = np.asarray(tetrahedra)
    if t.size == 0:
        return np.zeros((0, 4), dtype=np.uint32)
    if t.ndim != 2 or t.shape[1] != 4 or t.dtype.kind not in "iu":
        raise ValueError(f"{function}: tetrahedra of shape {t.shape} and dtype {t.dtype}, expected (m, 4) integers")
    bad = np.flatnonzero(((t < 0) | (t >= nv)).any(axis=1))
    if bad.size:
        i = int(bad[0])
        raise InvalidMeshError(f"{function}: tetrahedron {i} has a vertex index out of range [0, {nv}): "
                               f"{t[i].tolist()}")
    s = np.sort(t, axis=1)
    twice = np.flatnonzero((s[:, 1:] == s[:, :-1]).any(axis=1))
    if twice.size:
        i = int(twice[0])
        raise InvalidMeshError(f"{function}: tetrahedron {i} lists a vertex twice: {t[i].tolist()}")
    return t.astype(np.uint32, copy=False)


def _scalar(values: Any) -> Optional[np.ndarray]:
    """A one-component numeric array as (k,) float64 values, or None for anything else (vectors,
    tensors, strings): the package's readers keep one-component arrays only."""
    a = np.asarray(values)
    if a.ndim == 2 and a.shape[1] == 1:
        a = a[:, 0]
    if a.ndim != 1 or a.dtype.kind not in "fiub":
        return None
    return a.astype(np.float64, copy=False)


def _integer_labels(values: np.ndarray) -> Optional[np.ndarray]:
    """``values`` (float64) as int32 labels when they are all integers of the int32 range, else None."""
    if values.size and not (np.all(np.isfinite(values)) and np.all(values == np.floor(values))
                            and values.min() >= _INT32.min and values.max() <= _INT32.max):
        return None
    return values.astype(np.int32)


def _labels_and_cell_data(arrays: List[Tuple[str, np.ndarray]]) -> Tuple[Optional[np.ndarray], Dict[str, np.ndarray]]:
    """Splits one-component cell arrays (name, values of the tetrahedra) as the package's readers
    do: the first integer-valued array named as in LABEL_ARRAY_NAMES gives the labels, the others
    are cell data."""
    labels = None
    cell_data: Dict[str, np.ndarray] = {}
    for name, values in arrays:
        if labels is None and name in LABEL_ARRAY_NAMES:
            labels = _integer_labels(values)
            if labels is not None:
                continue
        cell_data[name] = values
    return labels, cell_data


def _warn_skipped(function: str, what: str, names: List[str]) -> None:
    if names:
        warnings.warn(f"{function}: {what} of several components skipped (the package keeps one-component "
                      f"arrays): {', '.join(names)}", stacklevel=3)


# ---------------------------------------------------------------------------------------------
# meshio
# ---------------------------------------------------------------------------------------------


def _meshio() -> Any:
    try:
        import meshio
    except ImportError as e:
        raise ImportError("this function needs meshio (Debian: python3-meshio; pip: meshio)") from e
    return meshio


def from_meshio(m: Any) -> Mesh:
    """A :class:`Mesh` from a ``meshio.Mesh``, in memory.

    Kept, as the package's readers keep them from a file: the ``tetra`` cell blocks, concatenated in
    order (the cells of other types, ``tetra10`` included, are counted in ``skipped_cells`` under
    the VTK names the readers use: ``triangle``, ``quadratic tetrahedron``...); the one-component
    point-data arrays (as float64; arrays of several components are skipped with a warning); the
    cell data of the tetrahedra: the first integer-valued array named as in
    :data:`LABEL_ARRAY_NAMES` (meshio's ``gmsh:physical``, ``medit:ref``, ...) gives the labels,
    the other one-component arrays are cell data; the names of the volume groups of ``field_data``
    (``{name: [tag, 3]}``, gmsh's ``$PhysicalNames``) as label_names.  meshio's gmsh entity tags
    (``gmsh:geometrical``, ``gmsh:dim_tags``) are left out, as the package's gmsh reader leaves them.

    Args:
        m: a ``meshio.Mesh``.

    Raises:
        ImportError: meshio is not installed.
        ValueError: the points are not 3-D, or there are cells but no tetrahedron.
        InvalidMeshError: a vertex index out of range or twice in a tetrahedron.
    """
    points = np.asarray(m.points, dtype=np.float64)
    if points.ndim != 2 or points.shape[1] != 3:
        raise ValueError(f"from_meshio: points of shape {points.shape}, expected (n, 3) (a 3-D mesh)")
    blocks = list(m.cells)
    keep = [b.type == "tetra" for b in blocks]
    skipped: Dict[str, int] = {}
    for b, k in zip(blocks, keep):
        if not k and len(b.data):
            t = _MESHIO_VTK_TYPES.get(b.type)
            name = _vtk_cell_type_name(t) if t is not None else b.type
            skipped[name] = skipped.get(name, 0) + len(b.data)
    if blocks and not any(keep) and any(len(b.data) for b in blocks):
        raise ValueError("from_meshio: no tetrahedron among the cells (" +
                         ", ".join(f"{n} {c}" for n, c in skipped.items()) + "): not a tetrahedral mesh")
    tets = [np.asarray(b.data) for b, k in zip(blocks, keep) if k]
    tetrahedra = _check_tetrahedra(np.concatenate(tets) if tets else np.zeros((0, 4), np.int64), len(points),
                                   "from_meshio")
    point_data, several = {}, []
    for name, values in m.point_data.items():
        if name in _MESHIO_GMSH_ENTITIES:
            continue
        a = _scalar(values)
        if a is None or a.shape[0] != len(points):
            several.append(name)
        else:
            point_data[name] = a
    _warn_skipped("from_meshio", "point-data arrays", several)
    cell_arrays, several = [], []
    for name, per_block in m.cell_data.items():
        if name in _MESHIO_GMSH_ENTITIES:
            continue
        parts = [_scalar(v) for v, k in zip(per_block, keep) if k]
        if not parts or any(p is None for p in parts):
            several.append(name)
        else:
            cell_arrays.append((name, np.concatenate(parts)))
    _warn_skipped("from_meshio", "cell-data arrays", several)
    labels, cell_data = _labels_and_cell_data(cell_arrays)
    label_names = {}
    for name, value in (getattr(m, "field_data", None) or {}).items():
        v = np.asarray(value).ravel()
        if v.size == 2 and v[1] == 3:
            label_names[int(v[0])] = str(name)
    return Mesh(points, tetrahedra, labels, point_data, cell_data, label_names, skipped)


def to_meshio(mesh: Mesh, *, labels_name: str = "gmsh:physical") -> Any:
    """A ``meshio.Mesh`` of one ``tetra`` cell block, in memory: the points and data arrays shared,
    not copied; the tetrahedra as int64, the dtype of meshio's readers (some of its writers refuse
    uint32).

    Args:
        mesh: a :class:`Mesh`.
        labels_name: the name of the cell-data array of the labels (int32), when the mesh has labels.
            The default, meshio's ``gmsh:physical``, is what meshio's gmsh writer takes as physical
            groups; its medit writer takes the first integer cell array, and its VTU, VTK and XDMF
            writers write the array under that name, which the package's readers (and
            :func:`from_meshio`) take back as the labels.

    The point and cell data become meshio's (the cell data as a list of one array); label_names
    become ``field_data`` ``{name: [label, 3]}``, gmsh's convention.  skipped_cells is not kept.

    Raises:
        ImportError: meshio is not installed.
    """
    meshio = _meshio()
    cell_data = {}
    if mesh.labels is not None:
        cell_data[labels_name] = [np.asarray(mesh.labels, dtype=np.int32)]
    for name, values in mesh.cell_data.items():
        if name in cell_data:
            raise ValueError(f"to_meshio: a cell-data array is named {name!r}, the name of the labels "
                             "(give another labels_name)")
        cell_data[name] = [values]
    field_data = {name: np.array([label, 3]) for label, name in mesh.label_names.items()}
    return meshio.Mesh(np.asarray(mesh.points), [("tetra", np.asarray(mesh.tetrahedra, dtype=np.int64))],
                       point_data=dict(mesh.point_data), cell_data=cell_data, field_data=field_data)


# ---------------------------------------------------------------------------------------------
# VTK
# ---------------------------------------------------------------------------------------------

_VTK_TETRA = 10


def _vtk() -> Any:
    try:
        from vtkmodules.util import numpy_support
    except ImportError as e:
        raise ImportError("this function needs VTK's Python bindings (Debian: python3-vtk9; pip: vtk)") from e
    return numpy_support


def from_vtk(grid: Any) -> Mesh:
    """A :class:`Mesh` from a ``vtkUnstructuredGrid``, in memory (no file in between).

    Kept, as the package's VTK readers keep them from a file: the cells of type ``VTK_TETRA``, in
    order (the others are counted in ``skipped_cells`` by VTK name: ``triangle``, ``hexahedron``,
    ``quadratic tetrahedron``...); the one-component point arrays (float64); of the one-component
    cell arrays of the tetrahedra, the first integer-valued one named as in
    :data:`LABEL_ARRAY_NAMES` (``label``, ``CellEntityIds``, ``MaterialIds``...) gives the labels,
    the others are cell data.  Arrays of several components are skipped with a warning, non-numeric
    arrays silently.

    Raises:
        ImportError: VTK's Python bindings are not installed.
        TypeError: ``grid`` is not a vtkUnstructuredGrid.
        ValueError: there are cells but no tetrahedron; a tetrahedron without 4 vertices.
        InvalidMeshError: a vertex index out of range or twice in a tetrahedron.
    """
    ns = _vtk()
    if not (hasattr(grid, "IsA") and grid.IsA("vtkUnstructuredGrid")):
        raise TypeError(f"from_vtk: expected a vtkUnstructuredGrid, not {type(grid).__name__}")
    pts = grid.GetPoints()
    points = (np.zeros((0, 3)) if pts is None or pts.GetNumberOfPoints() == 0 else
              ns.vtk_to_numpy(pts.GetData()).astype(np.float64).reshape(-1, 3))
    nc = grid.GetNumberOfCells()
    if nc:
        cells = grid.GetCells()
        offsets = ns.vtk_to_numpy(cells.GetOffsetsArray()).astype(np.int64)
        connectivity = ns.vtk_to_numpy(cells.GetConnectivityArray()).astype(np.int64)
        types = ns.vtk_to_numpy(grid.GetCellTypesArray())
    else:
        offsets, connectivity, types = np.zeros(1, np.int64), np.zeros(0, np.int64), np.zeros(0, np.uint8)
    keep = types == _VTK_TETRA
    skipped: Dict[str, int] = {}
    for t, count in zip(*np.unique(types[~keep], return_counts=True)):
        name = _vtk_cell_type_name(int(t))
        skipped[name] = skipped.get(name, 0) + int(count)
    if nc and not keep.any():
        raise ValueError("from_vtk: no tetrahedron among the cells (" +
                         ", ".join(f"{n} {c}" for n, c in skipped.items()) + "): not a tetrahedral mesh")
    starts = offsets[:-1][keep]
    sizes = (offsets[1:] - offsets[:-1])[keep]
    if np.any(sizes != 4):
        i = int(np.flatnonzero(keep)[np.flatnonzero(sizes != 4)[0]])
        raise ValueError(f"from_vtk: cell {i} is a tetrahedron with {int(offsets[i + 1] - offsets[i])} vertices")
    tetrahedra = _check_tetrahedra(connectivity[starts[:, None] + np.arange(4)], len(points), "from_vtk")

    def arrays(data: Any, n: int, what: str, rows: Optional[np.ndarray]) -> List[Tuple[str, np.ndarray]]:
        r, several = [], []
        for i in range(data.GetNumberOfArrays()):
            a = data.GetArray(i)  # None for the arrays that are not numeric (strings)
            if a is None or a.GetNumberOfTuples() != n:
                continue
            if a.GetNumberOfComponents() != 1:
                several.append(a.GetName())
                continue
            v = ns.vtk_to_numpy(a).astype(np.float64)
            r.append((a.GetName() or "", v if rows is None else v[rows]))
        _warn_skipped("from_vtk", what, several)
        return r

    point_data = dict(arrays(grid.GetPointData(), len(points), "point arrays", None))
    labels, cell_data = _labels_and_cell_data(arrays(grid.GetCellData(), nc, "cell arrays", keep))
    return Mesh(points, tetrahedra, labels, point_data, cell_data, {}, skipped)


def to_vtk(mesh: Mesh) -> Any:
    """A ``vtkUnstructuredGrid`` of ``VTK_TETRA`` cells, in memory (no file in between): the points,
    the tetrahedra, the labels as the int32 cell array ``label`` (the name the package's writers
    give them), the point and cell data as double arrays of their names.  The arrays are copied
    into VTK's.

    Args:
        mesh: a :class:`Mesh`.

    Raises:
        ImportError: VTK's Python bindings are not installed.
        ValueError: arrays of the wrong shapes; InvalidMeshError: vertex indices out of range.
    """
    ns = _vtk()
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkUnstructuredGrid

    points = np.ascontiguousarray(mesh.points, dtype=np.float64)
    if points.ndim != 2 or points.shape[1] != 3:
        raise ValueError(f"to_vtk: points of shape {points.shape}, expected (n, 3)")
    tetrahedra = _check_tetrahedra(mesh.tetrahedra, len(points), "to_vtk")
    m = len(tetrahedra)
    grid = vtkUnstructuredGrid()
    p = vtkPoints()
    p.SetData(ns.numpy_to_vtk(points, deep=1))
    grid.SetPoints(p)
    cells = vtkCellArray()
    offsets = np.arange(0, 4 * m + 1, 4, dtype=np.int64)
    connectivity = np.ascontiguousarray(tetrahedra, dtype=np.int64).ravel()
    cells.SetData(ns.numpy_to_vtkIdTypeArray(offsets, deep=1), ns.numpy_to_vtkIdTypeArray(connectivity, deep=1))
    grid.SetCells(_VTK_TETRA, cells)

    def add(data: Any, name: str, values: Any, n: int, dtype: Any) -> None:
        v = np.ascontiguousarray(values, dtype=dtype)
        if v.shape != (n,):
            raise ValueError(f"to_vtk: array {name!r} of shape {v.shape}, expected ({n},)")
        a = ns.numpy_to_vtk(v, deep=1)
        a.SetName(name)
        data.AddArray(a)

    if mesh.labels is not None:
        add(grid.GetCellData(), "label", mesh.labels, m, np.int32)
    for name, values in mesh.point_data.items():
        add(grid.GetPointData(), name, values, len(points), np.float64)
    for name, values in mesh.cell_data.items():
        if name == "label" and mesh.labels is not None:
            raise ValueError("to_vtk: a cell-data array is named 'label', the name of the labels")
        add(grid.GetCellData(), name, values, m, np.float64)
    return grid
