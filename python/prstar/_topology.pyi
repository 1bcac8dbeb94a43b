# Copyright (c) 2026 The PR-star octree project.
# SPDX-License-Identifier: LGPL-3.0-or-later
"""Type stubs of prstar._topology: the topology of a scalar field (``prstar critical``, ``prstar morse``)."""

from dataclasses import dataclass
from typing import Any, Dict, Iterator, Optional, Tuple, Union

import numpy as np

from ._core import MeshLike, ProgressCallback

__all__ = [
    "MINIMUM",
    "SADDLE1",
    "SADDLE2",
    "MAXIMUM",
    "DEGENERATE",
    "REGULAR",
    "CRITICAL_TYPE_NAMES",
    "MINIMUM_SADDLE",
    "SADDLE_MAXIMUM",
    "CriticalPointsResult",
    "MorseArcs",
    "MorseResult",
    "critical_points",
    "morse_complexes",
]

MINIMUM: int  # 0: empty lower link
SADDLE1: int  # 1: two lower components, one upper
SADDLE2: int  # 2: one lower component, two upper
MAXIMUM: int  # 3: empty upper link
DEGENERATE: int  # 4: any other count
REGULAR: int  # 5: one lower and one upper component (and vertices in no tetrahedron)
CRITICAL_TYPE_NAMES: Tuple[str, ...]  # "minimum", "1-saddle", "2-saddle", "maximum", "degenerate", "regular"
MINIMUM_SADDLE: int  # 0: the kind of a persistence pair of a minimum and a 1-saddle
SADDLE_MAXIMUM: int  # 1: the kind of a pair of a 2-saddle and a maximum

@dataclass
class CriticalPointsResult:
    """What critical_points returns: per-vertex types and the non-regular vertices with their links."""

    types: np.ndarray  # (n,) int8 TTK codes
    vertices: np.ndarray  # (k,) int64 the non-regular vertices, increasing
    lower_components: np.ndarray  # (k,) int32
    upper_components: np.ndarray  # (k,) int32
    values: np.ndarray  # (k,) float64
    on_boundary: np.ndarray  # (k,) bool
    counts: Dict[str, Any]  # the keys of `prstar critical --json`
    critical_simplices: Optional[Dict[str, np.ndarray]]  # with gradient=True: dimension, vertices, value
    def __init__(
        self,
        types: np.ndarray,
        vertices: np.ndarray,
        lower_components: np.ndarray,
        upper_components: np.ndarray,
        values: np.ndarray,
        on_boundary: np.ndarray,
        counts: Dict[str, Any] = ...,
        critical_simplices: Optional[Dict[str, np.ndarray]] = ...,
    ) -> None: ...
    @property
    def euler_characteristic(self) -> Optional[int]:
        """The Euler characteristic of the mesh (checked against the gradient), with gradient=True."""

def critical_points(
    mesh: MeshLike,
    field: Any = None,
    *,
    gradient: bool = False,
    bucket_size: Optional[Union[int, float, str]] = None,
    max_depth: Optional[int] = None,
    threads: Optional[int] = None,
    progress: Optional[ProgressCallback] = None,
) -> CriticalPointsResult:
    """The critical type of every vertex (lower/upper link components), as `prstar critical`; with
    gradient=True also the Forman gradient, checked against the Euler characteristic."""

@dataclass
class MorseArcs:
    """The Morse-Smale arcs as polylines: arc i is points[offsets[i]:offsets[i + 1]]."""

    points: np.ndarray  # (p, 3) float64
    offsets: np.ndarray  # (k + 1,) int64
    saddle_dimension: np.ndarray  # (k,) int8, 1 or 2
    saddle: np.ndarray  # (k,) int64 position among the critical simplices
    saddle_vertex: np.ndarray  # (k,) int64
    extremum: np.ndarray  # (k,) int64, -1 when the path leaves the domain
    saddle_value: np.ndarray  # (k,) float64
    def __init__(
        self,
        points: np.ndarray,
        offsets: np.ndarray,
        saddle_dimension: np.ndarray,
        saddle: np.ndarray,
        saddle_vertex: np.ndarray,
        extremum: np.ndarray,
        saddle_value: np.ndarray,
    ) -> None: ...
    def __len__(self) -> int: ...
    def __getitem__(self, i: int) -> np.ndarray:
        """The points (m, 3) of arc i."""
    def __iter__(self) -> Iterator[np.ndarray]: ...

@dataclass
class MorseResult:
    """What morse_complexes returns: the cells, the persistence pairs, the arcs, the counts."""

    ascending_cell: np.ndarray  # (n,) int64 per vertex, -1: in no tetrahedron
    descending_cell: np.ndarray  # (m,) int64 per tetrahedron (user's order), -1: path out of the domain
    critical_types: np.ndarray  # (n,) int8
    # kind, extremum, saddle, extremum_value, saddle_value, birth, death, persistence, essential
    pairs: Dict[str, np.ndarray]
    arcs: Optional[MorseArcs]
    critical_simplices: Dict[str, np.ndarray]  # dimension, vertices, value
    counts: Dict[str, Any]  # the keys of `prstar morse --json`
    def __init__(
        self,
        ascending_cell: np.ndarray,
        descending_cell: np.ndarray,
        critical_types: np.ndarray,
        pairs: Dict[str, np.ndarray],
        arcs: Optional[MorseArcs],
        critical_simplices: Dict[str, np.ndarray],
        counts: Dict[str, Any] = ...,
    ) -> None: ...
    @property
    def threshold(self) -> float:
        """The absolute persistence threshold applied."""
    def pairs_array(self) -> np.ndarray:
        """The persistence pairs as one numpy structured array."""

def morse_complexes(
    mesh: MeshLike,
    field: Any = None,
    *,
    persistence: Union[float, str] = 0.0,
    threshold: Optional[float] = None,
    arcs: bool = True,
    bucket_size: Optional[Union[int, float, str]] = None,
    max_depth: Optional[int] = None,
    threads: Optional[int] = None,
    progress: Optional[ProgressCallback] = None,
) -> MorseResult:
    """The Morse complexes and persistence pairs of a field, as `prstar morse`; persistence is a
    fraction of the field's range (0.05 or "5%", the CLI's --persistence), threshold an absolute value."""
