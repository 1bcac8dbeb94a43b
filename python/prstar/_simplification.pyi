# Copyright (c) 2026 The PR-star octree project.
# SPDX-License-Identifier: LGPL-3.0-or-later
"""Type stubs of prstar._simplification: validation (``prstar validate``), simplification
(``prstar simplify``) and remeshing (``prstar remesh``)."""

from dataclasses import dataclass
from typing import Any, Dict, List, Optional, Union

import numpy as np

from ._core import Mesh, MeshLike, ProgressCallback

__all__ = ["ValidationReport", "validate", "SimplifyResult", "simplify", "RemeshResult", "remesh"]

@dataclass
class ValidationReport:
    """What validate returns: the counts of ``prstar validate --json`` and the wrong elements (user numbering)."""

    valid: bool
    counts: Dict[str, Any]  # valid, tetrahedra, inverted, degenerate, nonmanifold_triangles, ..., seconds
    inverted_tetrahedra: np.ndarray  # (k,) int64, the minority sign as listed (negative on a tie)
    flat_tetrahedra: np.ndarray  # (k,) int64
    nonmanifold_triangles: np.ndarray  # (k, 3) int64, vertices increasing
    nonmanifold_triangle_tetrahedra: List[np.ndarray]  # the tetrahedra of each, increasing
    nonmanifold_vertices: np.ndarray  # (k,) int64
    unreferenced_vertices: np.ndarray  # (k,) int64 (a warning)
    positive: int = ...  # tetrahedra positively oriented as listed
    negative: int = ...  # tetrahedra negatively oriented as listed
    _inverted_vertices: np.ndarray = ...  # (k, 4) the vertices of the inverted tetrahedra, as listed
    _flat_vertices: np.ndarray = ...  # (k, 4) those of the flat ones
    @property
    def euler_characteristic(self) -> int:
        """V - E + F - T over the referenced vertices."""
    @property
    def boundary_components(self) -> int:
        """Connected components of the boundary surface (through edges)."""
    def problems(self) -> List[Dict[str, Any]]:
        """Every problem as ``prstar validate --json`` lists it."""
    def summary(self) -> str:
        """The report in words (the CLI's table, the first 10 problems of each kind)."""
    def __bool__(self) -> bool: ...

def validate(
    mesh: MeshLike,
    *,
    bucket_size: Optional[Union[int, float, str]] = None,
    max_depth: Optional[int] = None,
    threads: Optional[int] = None,
    progress: Optional[ProgressCallback] = None,
) -> ValidationReport:
    """Orientation, flat and non-manifold elements, Euler characteristic, boundary components
    (``prstar validate``); an invalid mesh is a report, not an error."""

@dataclass
class SimplifyResult:
    """What simplify returns: the simplified mesh and the statistics of ``prstar simplify --json``."""

    mesh: Mesh  # points (n, 3) float64, tetrahedra (m, 4) uint32 positive, labels int32 or None, data carried
    statistics: Dict[str, Any]
    stop: str  # "target_reached", "nothing_left", "blocked", "max_rounds"
    target_reached: bool  # False: stopped before the target (the CLI's exit status 4)
    input_vertex: np.ndarray  # (n,) int64 the input vertex of each output vertex
    input_tetrahedron: np.ndarray  # (m,) int64 the input tetrahedron of each output tetrahedron
    target: float = ...  # the fraction of the tetrahedra to remove (0: none)
    @property
    def message(self) -> str:
        """Why it stopped before the target ("" when it did not)."""
    def summary(self) -> str:
        """The result in words (the CLI's table)."""

def simplify(
    mesh: MeshLike,
    *,
    target: Optional[Union[float, str]] = None,
    keep: Optional[Union[float, str]] = None,
    max_length: Optional[float] = None,
    min_dihedral: float = 5.0,
    min_radius_ratio: float = 0.1,
    max_dihedral: float = 165.0,
    optimize: int = 2,
    feature_angle: float = 40.0,
    max_error: Optional[Union[float, str]] = "0.2%",
    priority: str = "length",
    placement: str = "half-edge",
    bucket_size: Optional[Union[int, float, str]] = None,
    threads: Optional[int] = None,
    progress: Optional[ProgressCallback] = None,
) -> SimplifyResult:
    """Edge-collapse simplification leaf by leaf (``prstar simplify``): target/keep as 0.3 or "30%",
    the floors and the ceiling all at once, ``optimize`` rounds of flips and moves after the collapses,
    max_error a distance, "0.2%" of the diagonal or None; ValueError for a bad option."""

@dataclass
class RemeshResult:
    """What remesh returns: the remeshed mesh and the statistics of ``prstar remesh --json``."""

    mesh: Mesh  # points (n, 3) float64, tetrahedra (m, 4) uint32 positive, labels int32 or None, data carried
    statistics: Dict[str, Any]
    input_vertex: np.ndarray  # (n,) int64 the input vertex whose data each output vertex carries
    input_tetrahedron: np.ndarray  # (m,) int64 the input tetrahedron each output tetrahedron lies in part of
    def summary(self) -> str:
        """The result in words (the CLI's table)."""

def remesh(
    mesh: MeshLike,
    *,
    edge_length: Optional[Union[float, str]] = None,
    size_field: Optional[Union[str, Any]] = None,
    iterations: int = 5,
    min_dihedral: float = 5.0,
    max_dihedral: float = 165.0,
    min_radius_ratio: float = 0.1,
    feature_angle: float = 40.0,
    max_error: Optional[Union[float, str]] = "0.2%",
    bucket_size: Optional[Union[int, float, str]] = None,
    threads: Optional[int] = None,
) -> RemeshResult:
    """Local remeshing to a target edge length (``prstar remesh``): edge_length a length or "2%" of the
    diagonal, or size_field a point-data name or an array; ValueError for a bad option."""
