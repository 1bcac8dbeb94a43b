# Copyright (c) 2026 The PR-star octree project.
# SPDX-License-Identifier: LGPL-3.0-or-later
"""The topology of a scalar field sampled at the vertices (``prstar critical`` and ``prstar morse``):
critical points of the piecewise-linear field, the discrete (Forman) gradient, the Morse complexes,
the persistence pairs of the extrema and the Morse-Smale arcs."""

from __future__ import annotations

import math
import numbers
from dataclasses import dataclass, field as _field
from typing import Any, Dict, Iterator, Optional, Union

import numpy as np

from ._core import Mesh, MeshLike, ProgressCallback, _field_values, _octree
from . import _prstar

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

#: critical type codes (TTK's ``CriticalType``, those of the CLI's ``critical_type`` arrays)
MINIMUM, SADDLE1, SADDLE2, MAXIMUM, DEGENERATE, REGULAR = 0, 1, 2, 3, 4, 5
#: the names the CLI prints for the codes 0..5
CRITICAL_TYPE_NAMES = ("minimum", "1-saddle", "2-saddle", "maximum", "degenerate", "regular")
#: the ``kind`` of a persistence pair: a minimum with a 1-saddle, or a 2-saddle with a maximum
MINIMUM_SADDLE, SADDLE_MAXIMUM = 0, 1


def _field_name(mesh: MeshLike, field: Any) -> Optional[str]:
    """The counts' ``field``: the name given, the Mesh's first point-data array by default, None for an
    array (or an Octree's own field)."""
    if isinstance(field, str):
        return field
    if field is None and isinstance(mesh, Mesh) and mesh.point_data:
        return next(iter(mesh.point_data))
    return None


@dataclass
class CriticalPointsResult:
    """What :func:`critical_points` returns (vertex indices are the user's).

    Attributes:
        types: (n,) int8 critical type per vertex: MINIMUM 0, SADDLE1 1, SADDLE2 2, MAXIMUM 3,
            DEGENERATE 4, REGULAR 5 (vertices in no tetrahedron are REGULAR).
        vertices: (k,) int64 the vertices that are not regular, increasing.
        lower_components: (k,) int32 connected components of their lower links.
        upper_components: (k,) int32 connected components of their upper links.
        values: (k,) float64 the field at them.
        on_boundary: (k,) bool whether their link is not a closed surface (boundary or non-manifold).
        counts: the counts of ``prstar critical --json`` (vertices, tetrahedra, kv, field, field_min,
            field_max, minima, saddles_1, saddles_2, maxima, degenerate, regular, unreferenced,
            join_multiplicity, split_multiplicity, interior; and gradient with ``gradient=True``:
            critical_vertices, critical_edges, critical_triangles, critical_tetrahedra,
            alternating_sum, euler_characteristic, bytes_per_tetrahedron).
        critical_simplices: with ``gradient=True``, the critical simplices of the Forman gradient:
            a dict of ``dimension`` (s,) int8, ``vertices`` (s, 4) int64 (the highest vertex in the
            field order first, -1 for unused entries) and ``value`` (s,) float64 (at the highest
            vertex), by dimension then increasing field order; None otherwise.
    """

    types: np.ndarray
    vertices: np.ndarray
    lower_components: np.ndarray
    upper_components: np.ndarray
    values: np.ndarray
    on_boundary: np.ndarray
    counts: Dict[str, Any] = _field(default_factory=dict)
    critical_simplices: Optional[Dict[str, np.ndarray]] = None

    @property
    def euler_characteristic(self) -> Optional[int]:
        """The Euler characteristic of the mesh (checked against the gradient), with ``gradient=True``."""
        g = self.counts.get("gradient")
        return None if g is None else int(g["euler_characteristic"])


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
    """Classifies every vertex by the connected components of its lower and upper links (the field
    compared as the pair (value, vertex index), so that flat regions are well defined), as
    ``prstar critical``: minimum (empty lower link), maximum (empty upper link), 1-saddle (2 lower
    components, 1 upper), 2-saddle (1 lower, 2 upper), degenerate (other counts), regular.  The link
    of a boundary vertex is its disc (TTK's convention).

    Args:
        mesh: a :class:`Mesh`, a ``(points, tetrahedra)`` pair, or an :class:`Octree`.
        field: the name of a point-data array of a Mesh (default: its first one, as the CLI), 'x',
            'y' or 'z' for a coordinate, or an array of one value per vertex (for an Octree built
            with ``field=``, None uses that one).  It must be finite.
        gradient: also compute the Forman gradient (ProcessLowerStars) and check, as ``prstar
            critical --gradient``, that its critical simplices add up to the Euler characteristic
            (RuntimeError otherwise: a bug to report).
        bucket_size: the bucket threshold k_v (default ``"auto"``: chosen from the mesh, as
            ``--kv auto``; ``math.inf``: one leaf), when an octree
            is built.
        max_depth: the depth bound of the octree built.
        threads: the number of threads (default: all cores), when an octree is built.
        progress: called as ``progress(done, total)`` (leaves), at most ten times a second, with the
            GIL held; an exception it raises stops the computation.

    Raises:
        ValueError: a field that is not finite, of the wrong length, or an unknown name.
    """
    values = _field_values(mesh, field, "critical_points")
    tree = _octree(mesh, "critical_points", bucket_size, max_depth, threads)
    d = _prstar._critical_points(tree, values, bool(gradient), progress)
    counts = dict(d["counts"])
    counts["field"] = _field_name(mesh, field)
    return CriticalPointsResult(
        types=d["types"],
        vertices=d["vertices"],
        lower_components=d["lower_components"],
        upper_components=d["upper_components"],
        values=d["values"],
        on_boundary=d["on_boundary"],
        counts=counts,
        critical_simplices=d.get("critical_simplices"),
    )


@dataclass
class MorseArcs:
    """The Morse-Smale arcs (gradient paths from a saddle to an extremum) as the CLI's ``--arcs`` .vtp
    holds them: the polylines' points one after the other.

    Arc ``i`` is ``points[offsets[i]:offsets[i + 1]]`` (``arcs[i]``): it starts at the barycentre of its
    saddle (a critical edge for ``saddle_dimension`` 1, a critical triangle for 2), then follows
    vertices down to a minimum (dimension 1) or barycentres of tetrahedra up to a maximum
    (dimension 2).

    Attributes:
        points: (p, 3) float64.
        offsets: (k + 1,) int64.
        saddle_dimension: (k,) int8, 1 or 2.
        saddle: (k,) int64 the saddle's position among the gradient's critical simplices
            (:attr:`MorseResult.critical_simplices`).
        saddle_vertex: (k,) int64 the saddle's highest vertex.
        extremum: (k,) int64 the extremum's vertex (for a maximum, the highest vertex of its critical
            tetrahedron); -1 when the path leaves the domain through its boundary.
        saddle_value: (k,) float64 the field at the saddle.
    """

    points: np.ndarray
    offsets: np.ndarray
    saddle_dimension: np.ndarray
    saddle: np.ndarray
    saddle_vertex: np.ndarray
    extremum: np.ndarray
    saddle_value: np.ndarray

    def __len__(self) -> int:
        return int(self.offsets.shape[0]) - 1

    def __getitem__(self, i: int) -> np.ndarray:
        """The points (m, 3) of arc ``i``."""
        n = len(self)
        if i < 0:
            i += n
        if not 0 <= i < n:
            raise IndexError(f"arc {i} out of range [0, {n})")
        return self.points[self.offsets[i]:self.offsets[i + 1]]

    def __iter__(self) -> Iterator[np.ndarray]:
        return (self[i] for i in range(len(self)))


@dataclass
class MorseResult:
    """What :func:`morse_complexes` returns (vertex and tetrahedron indices are the user's).

    Attributes:
        ascending_cell: (n,) int64 per vertex: the vertex of the minimum whose ascending 3-cell holds
            it (after the cancellations), -1 for a vertex in no tetrahedron.
        descending_cell: (m,) int64 per tetrahedron: the vertex of the maximum whose descending 3-cell
            holds it (after the cancellations), -1 when its gradient path leaves the domain.
        critical_types: (n,) int8 per vertex, as :attr:`CriticalPointsResult.types`.
        pairs: the persistence pairs (the rows of ``prstar morse --csv``), a dict of (p,) arrays:
            ``kind`` int8 (MINIMUM_SADDLE 0 / SADDLE_MAXIMUM 1), ``extremum`` int64, ``saddle`` int64
            (-1 for an essential pair), ``extremum_value``, ``saddle_value`` (NaN when essential),
            ``birth``, ``death``, ``persistence`` float64 (infinite when essential), ``essential`` bool;
            minimum-saddle pairs first, each kind by increasing extremum value.
        arcs: the Morse-Smale arcs (:class:`MorseArcs`), None with ``arcs=False``.
        critical_simplices: the critical simplices of the Forman gradient (as
            :attr:`CriticalPointsResult.critical_simplices`).
        counts: the counts of ``prstar morse --json`` (vertices, tetrahedra, kv, field, field_min,
            field_max, persistence (the fraction of the range, None for an absolute threshold),
            threshold, critical_points, gradient, ascending_cells, descending_cells,
            outflow_tetrahedra, minimum_saddle_pairs, saddle_maximum_pairs, minimum_saddle_pairs_kept,
            saddle_maximum_pairs_kept, arcs).
    """

    ascending_cell: np.ndarray
    descending_cell: np.ndarray
    critical_types: np.ndarray
    pairs: Dict[str, np.ndarray]
    arcs: Optional[MorseArcs]
    critical_simplices: Dict[str, np.ndarray]
    counts: Dict[str, Any] = _field(default_factory=dict)

    @property
    def threshold(self) -> float:
        """The absolute persistence threshold applied (pairs strictly below it cancelled)."""
        return float(self.counts["threshold"])

    def pairs_array(self) -> np.ndarray:
        """The persistence pairs as one numpy structured array (fields as the keys of :attr:`pairs`)."""
        keys = list(self.pairs)
        out = np.empty(len(self.pairs["kind"]), dtype=[(k, self.pairs[k].dtype) for k in keys])
        for k in keys:
            out[k] = self.pairs[k]
        return out


def _persistence_argument(persistence: Any, threshold: Any) -> Dict[str, Any]:
    """``persistence`` (a fraction of the range, as the CLI's --persistence: 0.05 or "5%") or
    ``threshold`` (absolute), as {"threshold": absolute or 0, "relative": fraction or None}."""
    if threshold is not None:
        if not (persistence == 0 or persistence == "0" or persistence == "0%"):
            raise ValueError("morse_complexes: give persistence (a fraction of the field's range) or "
                             "threshold (an absolute value), not both")
        if isinstance(threshold, bool) or not isinstance(threshold, numbers.Real):
            raise TypeError("morse_complexes: threshold: expected a number (in the field's units)")
        t = float(threshold)
        if not math.isfinite(t) or t < 0:
            raise ValueError(f"morse_complexes: threshold {threshold!r}: must be a finite number >= 0")
        return {"threshold": t, "relative": None}
    if isinstance(persistence, str):
        s = persistence.strip()
        percent = s.endswith("%")
        try:
            value = float(s[:-1] if percent else s)
        except ValueError:
            raise ValueError(f"morse_complexes: persistence {persistence!r} is not a fraction (0.05) or a "
                             "percentage ('5%')") from None
        if percent:
            value /= 100
    elif isinstance(persistence, bool) or not isinstance(persistence, numbers.Real):
        raise TypeError("morse_complexes: persistence: expected a fraction of the field's range (0.05) or a "
                        "percentage string such as '5%'")
    else:
        value = float(persistence)
    if not math.isfinite(value) or not 0 <= value <= 1:
        raise ValueError(f"morse_complexes: persistence {persistence!r}: must be a fraction of the field's "
                         "range in [0, 1] (or a percentage); for an absolute value give threshold=")
    return {"threshold": 0.0, "relative": value}


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
    """The Morse complexes of a scalar field and the persistence pairs of its extrema, as ``prstar
    morse``: the Forman gradient by the lower stars, the ascending 3-cells of the minima (per vertex),
    the descending 3-cells of the maxima (per tetrahedron), the minimum-saddle and saddle-maximum
    pairs, and the Morse-Smale arcs.  The pairs of persistence strictly below the threshold are
    cancelled: their extremum's cell joins the cell it merges into.

    Args:
        mesh: a :class:`Mesh`, a ``(points, tetrahedra)`` pair, or an :class:`Octree`.
        field: as :func:`critical_points`.
        persistence: the cancellation threshold as a fraction of the field's range over the vertices
            of the tetrahedra, as the CLI's ``--persistence``: ``0.05`` or ``"5%"``.  Default 0:
            nothing cancelled.
        threshold: the cancellation threshold as an absolute value, in the field's units (instead
            of ``persistence``).
        arcs: also return the Morse-Smale arcs.
        bucket_size, max_depth, threads, progress: as :func:`critical_points`.

    Raises:
        ValueError: a bad field (as :func:`critical_points`) or persistence.
        RuntimeError: the gradient's critical simplices do not add up to the Euler characteristic (a
            bug to report).
    """
    p = _persistence_argument(persistence, threshold)
    values = _field_values(mesh, field, "morse_complexes")
    tree = _octree(mesh, "morse_complexes", bucket_size, max_depth, threads)
    d = _prstar._morse_complexes(tree, values, p["threshold"], p["relative"], bool(arcs), progress)
    counts = dict(d["counts"])
    counts["field"] = _field_name(mesh, field)
    a = d.get("arcs")
    return MorseResult(
        ascending_cell=d["ascending_cell"],
        descending_cell=d["descending_cell"],
        critical_types=d["critical_types"],
        pairs=dict(d["pairs"]),
        arcs=None if a is None else MorseArcs(**{k: a[k] for k in a}),
        critical_simplices=dict(d["critical_simplices"]),
        counts=counts,
    )
