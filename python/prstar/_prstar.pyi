# Copyright (c) 2026 The PR-star octree project.
# SPDX-License-Identifier: LGPL-3.0-or-later
"""Type stubs of the compiled part of prstar (the public names; the functions whose names start
with an underscore are the package's own)."""

from typing import Any, Dict, Optional, Union

import numpy as np
import numpy.typing as npt

class InvalidMeshError(ValueError):
    """A mesh the package refuses: a vertex index out of range or listed twice in a tetrahedron, a
    non-finite coordinate, a mesh too big for 32-bit indices."""

class Octree:
    """The PR-star octree of a tetrahedral mesh (the C++ class ``PR_star_octree_3``).

    The arrays are read in place (any dtype accepted, any memory layout) and copied once, into the
    octree: points (n, 3) floating or integer, tetrahedra (m, 4) integer, labels (m,) integer,
    field (n,) numeric.  Raises ValueError for bad shapes or dtypes and InvalidMeshError for a mesh
    the package refuses.
    """

    def __init__(
        self,
        points: npt.ArrayLike,
        tetrahedra: npt.ArrayLike,
        *,
        bucket_size: Union[int, float, str, None] = "auto",
        max_depth: Optional[int] = None,
        labels: Optional[npt.ArrayLike] = None,
        field: Optional[npt.ArrayLike] = None,
        threads: Optional[int] = None,
        _relations: int = 0,
    ) -> None: ...
    @property
    def number_of_vertices(self) -> int: ...
    @property
    def number_of_tetrahedra(self) -> int: ...
    @property
    def bucket_size(self) -> Union[int, float]:
        """k_v (the one chosen with ``bucket_size="auto"``, the default); ``math.inf`` for a single leaf."""
    @property
    def depth(self) -> int: ...
    @property
    def number_of_leaves(self) -> int: ...
    @property
    def has_labels(self) -> bool: ...
    @property
    def has_field(self) -> bool: ...
    @property
    def threads(self) -> Optional[int]: ...
    def statistics(self) -> Dict[str, Any]:
        """The keys of ``prstar stats --json`` (storage in ``bytes`` and ``bytes_detail``)."""
    def leaves(self) -> Dict[str, np.ndarray]:
        """box_min, box_max (L, 3); vertex_begin, vertex_end (octree numbering); depth; tetrahedra."""
    def vertex_order(self) -> np.ndarray:
        """(n,) uint32: the user's index of each vertex of the octree's numbering."""
    def tetrahedron_order(self) -> np.ndarray:
        """(m,) uint32: the user's index of each tetrahedron of the octree's numbering."""
    # the package's own (called by boundary() and curvature())
    def _boundary(self, surface: bool, progress: Any = None) -> Dict[str, Any]: ...
    def _curvature(self, field: Any = None, progress: Any = None) -> Dict[str, Any]: ...

# The package's own functions, called by its Python modules (not public API).
def _read(*args: Any, **kwargs: Any) -> Any: ...
def _write(*args: Any, **kwargs: Any) -> Any: ...
def _extensions(*args: Any, **kwargs: Any) -> Any: ...
def _is_label_array_name(*args: Any, **kwargs: Any) -> Any: ...
def _vtk_cell_type_name(*args: Any, **kwargs: Any) -> Any: ...
def _validate(*args: Any, **kwargs: Any) -> Any: ...
def _simplify(*args: Any, **kwargs: Any) -> Any: ...
def _remesh(*args: Any, **kwargs: Any) -> Any: ...
def _critical_points(*args: Any, **kwargs: Any) -> Any: ...
def _morse_complexes(*args: Any, **kwargs: Any) -> Any: ...
