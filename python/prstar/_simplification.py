# Copyright (c) 2026 The PR-star octree project.
# SPDX-License-Identifier: LGPL-3.0-or-later
"""Validation, simplification and remeshing: :func:`validate` (``prstar validate``), :func:`simplify`
(``prstar simplify``) and :func:`remesh` (``prstar remesh``), with the options, defaults, checks and
messages of the command-line tool."""

from __future__ import annotations

import math
import numbers
from dataclasses import dataclass, field as _field
from typing import Any, Dict, List, Optional, Tuple, Union

import numpy as np

from ._core import Mesh, MeshLike, ProgressCallback, _octree
from ._prstar import Octree, _remesh, _simplify, _validate

__all__ = ["ValidationReport", "validate", "SimplifyResult", "simplify", "RemeshResult", "remesh"]

# The kinds of problems, in the order in which the library (and ``prstar validate --json``) lists them.
_KINDS = ("inverted_tetrahedron", "flat_tetrahedron", "nonmanifold_triangle", "nonmanifold_vertex",
          "unreferenced_vertex")
# How many problems of each kind the summary lists, as the CLI's table.
_SUMMARY_PROBLEMS = 10


@dataclass
class ValidationReport:
    """What :func:`validate` returns: the counts of ``prstar validate --json`` and the elements that are
    wrong, in the user's numbering (from 0).

    Attributes:
        valid: no inverted, flat or non-manifold element (vertices in no tetrahedron are a warning only).
        counts: the keys of ``prstar validate --json``: valid, tetrahedra, inverted, degenerate,
            nonmanifold_triangles, nonmanifold_vertices, unreferenced_vertices, euler_characteristic,
            boundary_triangles, boundary_components, seconds (of the check, the octree built apart).
        inverted_tetrahedra: (k,) int64 the tetrahedra of the minority sign as listed (all non-flat
            tetrahedra must have one sign; on a tie the negative ones are reported).
        flat_tetrahedra: (k,) int64 the tetrahedra whose four vertices are coplanar (exact predicate).
        nonmanifold_triangles: (k, 3) int64 the triangles in three or more tetrahedra (vertices
            increasing).
        nonmanifold_triangle_tetrahedra: for each of those triangles, its tetrahedra (an int64 array,
            increasing).
        nonmanifold_vertices: (k,) int64 the vertices whose link is neither a sphere nor a disc.
        unreferenced_vertices: (k,) int64 the vertices in no tetrahedron (a warning).
        positive: the tetrahedra positively oriented as listed.
        negative: the tetrahedra negatively oriented as listed.
    """

    valid: bool
    counts: Dict[str, Any]
    inverted_tetrahedra: np.ndarray
    flat_tetrahedra: np.ndarray
    nonmanifold_triangles: np.ndarray
    nonmanifold_triangle_tetrahedra: List[np.ndarray]
    nonmanifold_vertices: np.ndarray
    unreferenced_vertices: np.ndarray
    positive: int = 0
    negative: int = 0
    # the four vertices (as listed) of the inverted and flat tetrahedra, for `problems()`
    _inverted_vertices: np.ndarray = _field(default_factory=lambda: np.zeros((0, 4), np.int64), repr=False)
    _flat_vertices: np.ndarray = _field(default_factory=lambda: np.zeros((0, 4), np.int64), repr=False)

    @property
    def euler_characteristic(self) -> int:
        """V - E + F - T over the referenced vertices."""
        return int(self.counts["euler_characteristic"])

    @property
    def boundary_components(self) -> int:
        """The connected components of the boundary surface (triangles joined through edges)."""
        return int(self.counts["boundary_components"])

    def _reason(self, kind: str, tetrahedra: Optional[np.ndarray] = None) -> str:
        # the words of `prstar validate` (its JSON's "reason")
        if kind == "inverted_tetrahedron":
            sign = "negative" if self.negative <= self.positive else "positive"
            return f"inverted ({sign} as listed, the minority sign)"
        if kind == "flat_tetrahedron":
            return "flat (its four vertices are coplanar)"
        if kind == "nonmanifold_triangle":
            assert tetrahedra is not None
            return f"in {len(tetrahedra)} tetrahedra ({', '.join(str(int(t)) for t in tetrahedra)})"
        if kind == "nonmanifold_vertex":
            return "non-manifold (its link is neither a sphere nor a disc)"
        return "unreferenced (in no tetrahedron; a warning, the mesh stays valid)"

    def problems(self) -> List[Dict[str, Any]]:
        """Every problem as ``prstar validate --json`` lists it (sorted by kind, then element): dicts with
        ``kind``, ``tetrahedron`` (of a tetrahedron), ``vertex`` (of a vertex), ``vertices``,
        ``tetrahedra`` (of a triangle) and ``reason``."""
        out: List[Dict[str, Any]] = []
        for kind, ids, vertices in (("inverted_tetrahedron", self.inverted_tetrahedra, self._inverted_vertices),
                                    ("flat_tetrahedron", self.flat_tetrahedra, self._flat_vertices)):
            for t, v in zip(ids.tolist(), vertices.tolist()):
                out.append({"kind": kind, "tetrahedron": t, "vertices": v, "reason": self._reason(kind)})
        for tri, tets in zip(self.nonmanifold_triangles.tolist(), self.nonmanifold_triangle_tetrahedra):
            out.append({"kind": "nonmanifold_triangle", "vertices": tri, "tetrahedra": tets.tolist(),
                        "reason": self._reason("nonmanifold_triangle", tets)})
        for kind, ids in (("nonmanifold_vertex", self.nonmanifold_vertices),
                          ("unreferenced_vertex", self.unreferenced_vertices)):
            for v in ids.tolist():
                out.append({"kind": kind, "vertex": v, "vertices": [v], "reason": self._reason(kind)})
        return out

    def summary(self) -> str:
        """The report in words, as the table of ``prstar validate`` (the first problems of each kind)."""
        c = self.counts
        rows = [
            ("tetrahedra", c["tetrahedra"]),
            ("  positive as listed", self.positive),
            ("  negative as listed", self.negative),
            ("  inverted (minority sign)", c["inverted"]),
            ("  flat (degenerate)", c["degenerate"]),
            ("triangles in 3+ tetrahedra", c["nonmanifold_triangles"]),
            ("non-manifold vertices", c["nonmanifold_vertices"]),
            ("unreferenced vertices (warning)", c["unreferenced_vertices"]),
            ("Euler characteristic", c["euler_characteristic"]),
            ("boundary triangles", c["boundary_triangles"]),
            ("boundary components", c["boundary_components"]),
        ]
        width = max(len(r[0]) for r in rows)
        lines = [f"{'valid' if self.valid else 'INVALID'} ({c['seconds']:.3f} s)"]
        lines += [f"  {name:<{width}}  {value}" for name, value in rows]
        problems = self.problems()
        if problems:
            lines.append(f"problems (user numbering from 0, at most {_SUMMARY_PROBLEMS} of each kind; all of them "
                         "in problems()):")
            plural = {"inverted_tetrahedron": "inverted tetrahedra", "flat_tetrahedron": "flat tetrahedra",
                      "nonmanifold_triangle": "triangles in 3+ tetrahedra",
                      "nonmanifold_vertex": "non-manifold vertices", "unreferenced_vertex": "unreferenced vertices"}
            for kind in _KINDS:
                of_kind = [p for p in problems if p["kind"] == kind]
                for p in of_kind[:_SUMMARY_PROBLEMS]:
                    if "tetrahedron" in p:
                        what = f"tetrahedron {p['tetrahedron']} (vertices {' '.join(map(str, p['vertices']))})"
                    elif kind == "nonmanifold_triangle":
                        what = "triangle " + " ".join(map(str, p["vertices"]))
                    else:
                        what = f"vertex {p['vertex']}"
                    lines.append(f"  {what}: {p['reason']}")
                if len(of_kind) > _SUMMARY_PROBLEMS:
                    lines.append(f"  ... and {len(of_kind) - _SUMMARY_PROBLEMS} more {plural[kind]}")
        return "\n".join(lines)

    def __str__(self) -> str:
        return self.summary()

    def __bool__(self) -> bool:
        return bool(self.valid)


def validate(
    mesh: MeshLike,
    *,
    bucket_size: Optional[Union[int, float, str]] = None,
    max_depth: Optional[int] = None,
    threads: Optional[int] = None,
    progress: Optional[ProgressCallback] = None,
) -> ValidationReport:
    """Checks a mesh leaf by leaf, as ``prstar validate``: the orientation of every tetrahedron (exact
    predicate; all must have one sign as listed), flat tetrahedra, triangles in three or more
    tetrahedra, non-manifold vertices, the Euler characteristic and the boundary components; vertices
    in no tetrahedron are a warning.  An invalid mesh is a report with ``valid`` False, not an error.

    Args:
        mesh: a :class:`Mesh`, a ``(points, tetrahedra)`` pair, or an :class:`Octree`.
        bucket_size: the bucket threshold k_v of the octree built (default ``"auto"``: chosen from
            the mesh, as ``--kv auto``; ``math.inf``: one leaf);
            the result does not depend on it.
        max_depth: the depth bound of the octree built.
        threads: the number of threads (default: all cores), when an octree is built.
        progress: called as ``progress(done, total)`` (two passes over the leaves), at most ten times a
            second, with the GIL held; an exception it raises stops the check.

    Raises:
        InvalidMeshError: arrays the octree refuses (an index out of range, a vertex twice in a
            tetrahedron, a non-finite coordinate).
    """
    tree = _octree(mesh, "validate", bucket_size, max_depth, threads)
    d = _validate(tree, progress)
    counts = dict(d["counts"])
    offsets = d["triangle_offsets"]
    tets = d["triangle_tetrahedra"]
    return ValidationReport(
        valid=bool(counts["valid"]),
        counts=counts,
        inverted_tetrahedra=d["inverted_tetrahedra"],
        flat_tetrahedra=d["flat_tetrahedra"],
        nonmanifold_triangles=d["nonmanifold_triangles"],
        nonmanifold_triangle_tetrahedra=[tets[offsets[i]:offsets[i + 1]] for i in range(len(offsets) - 1)],
        nonmanifold_vertices=d["nonmanifold_vertices"],
        unreferenced_vertices=d["unreferenced_vertices"],
        positive=int(d["positive"]),
        negative=int(d["negative"]),
        _inverted_vertices=d["inverted_vertices"],
        _flat_vertices=d["flat_vertices"],
    )


@dataclass
class SimplifyResult:
    """What :func:`simplify` returns.

    Attributes:
        mesh: the simplified :class:`Mesh`: points (n, 3) float64, tetrahedra (m, 4) uint32, all
            positively oriented; the labels (int32) of the input, its point data and cell data carried
            along (a vertex keeps the data of the input vertex it stands for); with an Octree built with
            a field, that field as point data "scalar".
        statistics: the keys of ``prstar simplify --json`` (but ``output``): input_tetrahedra,
            output_tetrahedra, removed_tetrahedra (input - output: by the collapses and the flips),
            input_vertices, output_vertices, kv (``math.inf`` for one leaf), rounds, max_queue, seconds,
            stop, blocked and blocked_last_round {different_leaves, feature, boundary, flip, link,
            quality, error}, optimization {vertex_moves, flips_2_3, flips_3_2, flips_4_4,
            edge_removals, splits, tetrahedra_added, tetrahedra_deleted (by the flips), rounds,
            refused_moves, refused_flips, refused_splits (each as blocked)}, input_quality and
            output_quality {min_dihedral, max_dihedral, min_radius_ratio, share_under_5,
            share_under_10}, boundary_error {bound (``math.inf``: none), input_to_output,
            output_to_input, relative}.
        stop: why it stopped: "target_reached", "nothing_left" (no target: no edge under max_length can
            go), "blocked" (a round removed nothing before the target), "max_rounds".
        target_reached: False when it stopped before the target ("blocked", "max_rounds": the CLI's exit
            status 4); the mesh is then the last valid one reached.
        input_vertex: (n,) int64 for each output vertex, the input vertex it stands for.
        input_tetrahedron: (m,) int64 for each output tetrahedron, its index in the input.
    """

    mesh: Mesh
    statistics: Dict[str, Any]
    stop: str
    target_reached: bool
    input_vertex: np.ndarray
    input_tetrahedron: np.ndarray
    target: float = 0.0

    @property
    def message(self) -> str:
        """Why it stopped before the target, in the words of ``prstar simplify`` (empty when it did not)."""
        if self.target_reached:
            return ""
        s = self.statistics
        removed = 100.0 * s["removed_tetrahedra"] / s["input_tetrahedra"] if s["input_tetrahedra"] else 0.0
        text = f"stopped before the target: removed {removed:.1f}% of the tetrahedra, target {100 * self.target:.1f}%; "
        if self.stop == "max_rounds":
            return text + "the maximum number of rounds was reached"
        why = sorted(s["blocked_last_round"].items(), key=lambda kv: -kv[1])  # stable: the JSON's order on ties
        return (text + f"the last round removed nothing, its candidates blocked mostly by {why[0][0]} "
                f"({why[0][1]}), then {why[1][0]} ({why[1][1]})")

    def summary(self) -> str:
        """The result in words, as the table of ``prstar simplify``."""
        s = self.statistics
        qi, qo, e = s["input_quality"], s["output_quality"], s["boundary_error"]
        removed = 100.0 * s["removed_tetrahedra"] / s["input_tetrahedra"] if s["input_tetrahedra"] else 0.0
        bound_text = f"{e['bound']:.6g}" if math.isfinite(e["bound"]) else "none"
        lines = [
            f"tetrahedra: {s['input_tetrahedra']} -> {s['output_tetrahedra']} ({removed:.1f}% removed)",
            f"vertices: {s['input_vertices']} -> {s['output_vertices']}",
            f"smallest dihedral angle: {qi['min_dihedral']:.2f} -> {qo['min_dihedral']:.2f}",
            f"under 5 / 10 degrees: {100 * qi['share_under_5']:.3f}% / {100 * qi['share_under_10']:.2f}% -> "
            f"{100 * qo['share_under_5']:.3f}% / {100 * qo['share_under_10']:.2f}%",
            f"largest dihedral angle: {qi['max_dihedral']:.2f} -> {qo['max_dihedral']:.2f}",
            f"smallest radius ratio: {qi['min_radius_ratio']:.3f} -> {qo['min_radius_ratio']:.3f}",
            f"boundary distance: {100 * e['relative']:.3f}% of the diagonal (bound {bound_text})",
            f"rounds: {s['rounds']} ({self.stop}), {s['seconds']:.3f} s",
        ]
        o = s["optimization"]
        if o["rounds"] or o["vertex_moves"] or o["flips_2_3"] or o["flips_3_2"] or o["flips_4_4"]:
            lines.append(f"optimisation: {o['vertex_moves']} vertex moves, flips 2-3 / 3-2 / 4-4 {o['flips_2_3']} / "
                         f"{o['flips_3_2']} / {o['flips_4_4']}, {o['edge_removals']} edge removals, "
                         f"{o['rounds']} rounds")
        if self.message:
            lines.append(self.message)
        return "\n".join(lines)

    def __str__(self) -> str:
        return self.summary()


def _real(name: str, value: Any, function: str = "simplify") -> float:
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise TypeError(f"{function}: {name} must be a number, not {type(value).__name__}")
    return float(value)


def _integer(name: str, value: Any, low: int, high: int, meaning: str, function: str) -> int:
    """An integer in [low, high], as the CLI's count options (a float with an integer value too)."""
    d = _real(name, value, function)
    if not (low <= d <= high and d == math.floor(d)):
        raise ValueError(f"{function}: {name} must be an integer in [{low}, {high}]{meaning}")
    return int(d)


def _guards(function: str, min_dihedral: Any, max_dihedral: Any, min_radius_ratio: Any,
            feature_angle: Any) -> Tuple[float, float, float, float]:
    """The quality floors, the ceiling and the feature angle, checked as the CLI's options."""
    lo = _real("min_dihedral", min_dihedral, function)
    if not (0 <= lo <= 70.5):
        raise ValueError(f"{function}: min_dihedral must be in [0, 70.5] degrees (0: no floor)")
    # every tetrahedron has a dihedral angle of at least 70.53 degrees (the regular one's)
    hi = _real("max_dihedral", max_dihedral, function)
    if not (70.6 <= hi <= 180):
        raise ValueError(f"{function}: max_dihedral must be in [70.6, 180] degrees (180: no ceiling)")
    ratio = _real("min_radius_ratio", min_radius_ratio, function)
    if not (0 <= ratio <= 1):
        raise ValueError(f"{function}: min_radius_ratio must be in [0, 1] (0: no floor)")
    angle = _real("feature_angle", feature_angle, function)
    if not (0 <= angle <= 180):
        raise ValueError(f"{function}: feature_angle must be in [0, 180] degrees (180: no sharp edges)")
    return lo, hi, ratio, angle


def _fraction(name: str, value: Any, example: str) -> float:
    """A fraction as the CLI takes it: a number (0.3) or a percentage string ("30%")."""
    if isinstance(value, str):
        text = value.strip()
        percent = text.endswith("%")
        try:
            d = float(text[:-1] if percent else text)
        except ValueError:
            d = math.nan
        if not math.isfinite(d):
            raise ValueError(f"simplify: {name}: {value!r} is not a fraction (e.g. 0.3 or '30%')")
        d = d / 100 if percent else d
    else:
        d = _real(name, value)
    if not (0 < d < 1):
        raise ValueError(f"simplify: {name} must be a fraction of the tetrahedra in (0, 1), e.g. {example}")
    return d


def _max_error(value: Any, function: str = "simplify") -> Tuple[float, bool]:
    """(bound, relative): a distance, a percentage of the bounding-box diagonal, or no bound."""
    message = f"{function}: max_error must be a distance, a percentage of the bounding-box diagonal ('0.2%') or None"
    if value is None:
        return math.inf, False
    if isinstance(value, str):
        text = value.strip()
        if text in ("none", "inf"):
            return math.inf, False
        relative = text.endswith("%")
        try:
            d = float(text[:-1] if relative else text)
        except ValueError:
            raise ValueError(message) from None
    else:
        d = _real("max_error", value, function)
        if d == math.inf:
            return math.inf, False
        relative = False
    if not (d >= 0) or not math.isfinite(d):
        raise ValueError(message)
    return d, relative


def _source(function: str, mesh: MeshLike) -> Tuple[Any, Any, Any, Optional[Mesh]]:
    """(source, tetrahedra, labels, the Mesh whose data is carried) for ``_simplify`` and ``_remesh``."""
    if isinstance(mesh, Octree):
        return mesh, None, None, None
    if isinstance(mesh, Mesh):
        return mesh.points, mesh.tetrahedra, mesh.labels, mesh
    if isinstance(mesh, (tuple, list)) and len(mesh) == 2:
        return mesh[0], mesh[1], None, None
    raise TypeError(f"{function}: expected a prstar.Mesh, an Octree or a (points, tetrahedra) pair, "
                    f"not {type(mesh).__name__}")


def _result_mesh(d: Dict[str, Any], carried: Optional[Mesh]) -> Mesh:
    """The output Mesh of ``_simplify`` or ``_remesh``, with the data of ``carried``."""
    input_vertex, input_tetrahedron = d["input_vertex"], d["input_tetrahedron"]
    point_data = dict(d["point_data"])
    cell_data: Dict[str, Any] = {}
    label_names: Dict[int, str] = {}
    if carried is not None:
        # as the CLI: every array follows the input vertex / tetrahedron each output one stands for
        point_data.update({k: np.asarray(v)[input_vertex] for k, v in carried.point_data.items()})
        cell_data = {k: np.asarray(v)[input_tetrahedron] for k, v in carried.cell_data.items()}
        label_names = dict(carried.label_names)
    return Mesh(d["points"], d["tetrahedra"], d["labels"], point_data=point_data, cell_data=cell_data,
                label_names=label_names)


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
    """Simplifies a mesh by edge collapses leaf by leaf (paper Section 9), as ``prstar simplify``: each
    leaf collapses its short edges and improves its tetrahedra by flips and vertex moves, then the mesh
    is compacted and the octree rebuilt, until the target is met or a round removes nothing; ``optimize``
    rounds of flips and moves follow.  Sharp edges, corners and the surfaces between labels are kept, no
    operation creates a tetrahedron under a quality floor (``min_dihedral``, ``min_radius_ratio``, both
    at once) or over the ceiling (``max_dihedral``) unless it replaces worse ones, and the surface stays
    within ``max_error`` of the input's.

    Args:
        mesh: a :class:`Mesh` (labels, point data and cell data carried along), a ``(points,
            tetrahedra)`` pair (read in place), or an :class:`Octree` (its arrays in the user's
            numbering: labels and field carried along; the arrays are not needed again).
        target: stop once this fraction of the tetrahedra is removed: a number in (0, 1) or a
            percentage string ("75%").
        keep: stop once this fraction is left (``keep=0.25`` is ``target=0.75``); not with ``target``.
        max_length: collapse only edges shorter than this (with a target: both).
        min_dihedral: the floor on the smallest dihedral angle of a tetrahedron made, in degrees, in
            [0, 70.5] (default 5; 0: none).
        min_radius_ratio: the floor on the radius ratio 3r/R of a tetrahedron made, in [0, 1] (default
            0.1; 0: none).
        max_dihedral: the ceiling on the largest dihedral angle of a tetrahedron made, in degrees, in
            [70.6, 180] (default 165; 180: none).
        optimize: the rounds of flips and vertex moves after the collapses, in [0, 1000] (default 2; 0:
            coarsen only, no vertex moves and no flips).
        feature_angle: surface edges bending more than this (degrees, [0, 180]) are sharp features.
        max_error: the bound on the distance to the input surface: a distance, a percentage string of
            the bounding-box diagonal ("0.2%", the default), or None / "none" for no bound.
        priority: "length" (shortest edge first) or "quadric" (smallest surface error first).
        placement: "half-edge" (the removed end goes into the other) or "optimal" (the merged vertex at
            the best point of the edge when both ends are inside or on one smooth surface patch).
        bucket_size: the bucket threshold k_v of the octrees of the rounds (default ``"auto"``, or the Octree's;
            ``math.inf``: one leaf, the global algorithm).
        threads: the number of threads (default: all cores, or the Octree's).
        progress: called as ``progress(removed, to_remove)`` (tetrahedra, never decreasing) at the start
            and the end of each round and, at most ten times a second, during a round, with the GIL
            held; ``(to_remove, to_remove)`` last when the target is reached; an exception it raises
            stops the simplification.

    Returns:
        a :class:`SimplifyResult`; stopping before the target is no error (``target_reached`` False).

    Raises:
        ValueError: a bad option (the messages of ``prstar simplify``), bad arrays.
        InvalidMeshError: arrays the octree refuses.
    """
    if target is None and keep is None and max_length is None:
        raise ValueError("simplify: give target, keep or max_length")
    if target is not None and keep is not None:
        raise ValueError("simplify: give target or keep, not both")
    fraction = 0.0
    if target is not None:
        fraction = _fraction("target", target, "0.5 or '50%'")
    elif keep is not None:
        fraction = 1 - _fraction("keep", keep, "0.25 or '25%'")
    length = math.inf if max_length is None else _real("max_length", max_length)
    if not (length > 0):
        raise ValueError("simplify: max_length must be positive")
    lo, hi, ratio, angle = _guards("simplify", min_dihedral, max_dihedral, min_radius_ratio, feature_angle)
    rounds = _integer("optimize", optimize, 0, 1000, " (0: coarsen only)", "simplify")
    error, relative = _max_error(max_error)
    if priority not in ("length", "quadric"):
        raise ValueError(f"simplify: priority must be 'length' or 'quadric', not {priority!r}")
    if placement not in ("half-edge", "optimal"):
        raise ValueError(f"simplify: placement must be 'half-edge' or 'optimal', not {placement!r}")

    source, tetrahedra, labels, carried = _source("simplify", mesh)
    d = _simplify(source, tetrahedra, labels, target_fraction=fraction, max_edge_length=length, min_dihedral=lo,
                  max_dihedral=hi, min_radius_ratio=ratio, optimization_rounds=rounds, feature_angle=angle,
                  max_error=error, error_relative=relative, quadric=priority == "quadric",
                  optimal=placement == "optimal", bucket_size=bucket_size, threads=threads, progress=progress)
    out = _result_mesh(d, carried)
    input_vertex, input_tetrahedron = d["input_vertex"], d["input_tetrahedron"]
    statistics = dict(d["statistics"])
    stop = str(statistics["stop"])
    return SimplifyResult(mesh=out, statistics=statistics, stop=stop,
                          target_reached=stop not in ("blocked", "max_rounds"), input_vertex=input_vertex,
                          input_tetrahedron=input_tetrahedron, target=fraction)


@dataclass
class RemeshResult:
    """What :func:`remesh` returns.

    Attributes:
        mesh: the remeshed :class:`Mesh`: points (n, 3) float64, tetrahedra (m, 4) uint32, all
            positively oriented; the labels (int32) of the input, its point data and cell data carried
            along (a vertex keeps the data of the input vertex it stands for; a vertex made by a split,
            that of the first end of its edge); with an Octree built with a field, that field as point
            data "scalar".
        statistics: the keys of ``prstar remesh --json`` (but ``output``): input_tetrahedra,
            output_tetrahedra, input_vertices, output_vertices, edge_length (the target length, None
            with a size field), size_field (its name, "<array>" for an array, None without), kv
            (``math.inf`` for one leaf), iterations, rounds, seconds, operations {vertex_moves,
            flips_2_3, flips_3_2, flips_4_4, edge_removals, splits, tetrahedra_added,
            tetrahedra_deleted (by the flips and splits), collapses}, refused {collapses,
            splits, flips, moves: each {different_leaves, feature, boundary, flip, link, quality,
            error}}, input_quality and output_quality {min_dihedral, max_dihedral, min_radius_ratio,
            share_under_5, share_under_10}, input_edges and output_edges {edges, share_in_range (the
            edges within [0.8 h, 1.33 h] of their target h), share_short, share_long, median_ratio (of
            length / h)}, boundary_error {bound (``math.inf``: none), input_to_output, output_to_input,
            relative}.  With a size field, an edge's target is the mean of its ends' values; on the
            output, a vertex's value is the one it carries.
        input_vertex: (n,) int64 for each output vertex, the input vertex whose data it carries.
        input_tetrahedron: (m,) int64 for each output tetrahedron, the input tetrahedron it lies in part
            of (its label and cell data).
    """

    mesh: Mesh
    statistics: Dict[str, Any]
    input_vertex: np.ndarray
    input_tetrahedron: np.ndarray

    def summary(self) -> str:
        """The result in words, as the table of ``prstar remesh``."""
        s = self.statistics
        qi, qo, e = s["input_quality"], s["output_quality"], s["boundary_error"]
        ei, eo, op = s["input_edges"], s["output_edges"], s["operations"]
        bound_text = f"{e['bound']:.6g}" if math.isfinite(e["bound"]) else "none"
        target = f"h = {s['edge_length']:.6g}" if s["edge_length"] is not None else f"size field {s['size_field']}"
        return "\n".join([
            f"remeshed to {target}",
            f"tetrahedra: {s['input_tetrahedra']} -> {s['output_tetrahedra']}",
            f"vertices: {s['input_vertices']} -> {s['output_vertices']}",
            f"edges within [0.8 h, 1.33 h]: {100 * ei['share_in_range']:.2f}% -> {100 * eo['share_in_range']:.2f}%",
            f"median edge length / h: {ei['median_ratio']:.3f} -> {eo['median_ratio']:.3f}",
            f"smallest dihedral angle: {qi['min_dihedral']:.2f} -> {qo['min_dihedral']:.2f}",
            f"largest dihedral angle: {qi['max_dihedral']:.2f} -> {qo['max_dihedral']:.2f}",
            f"under 5 / 10 degrees: {100 * qi['share_under_5']:.3f}% / {100 * qi['share_under_10']:.2f}% -> "
            f"{100 * qo['share_under_5']:.3f}% / {100 * qo['share_under_10']:.2f}%",
            f"smallest radius ratio: {qi['min_radius_ratio']:.3f} -> {qo['min_radius_ratio']:.3f}",
            f"boundary distance: {100 * e['relative']:.3f}% of the diagonal (bound {bound_text})",
            f"operations: {op['splits']} splits, {op['collapses']} collapses, flips 2-3 / 3-2 / 4-4 "
            f"{op['flips_2_3']} / {op['flips_3_2']} / {op['flips_4_4']}, {op['edge_removals']} edge removals, "
            f"{op['vertex_moves']} vertex moves",
            f"rounds: {s['rounds']} (of {s['iterations']}), {s['seconds']:.3f} s",
        ])

    def __str__(self) -> str:
        return self.summary()


def _number_text(v: float) -> str:
    """A float as the CLI prints it (the shortest text that reads back; no ".0" on integers)."""
    text = repr(float(v))
    return text[:-2] if text.endswith(".0") else text


def _edge_length(value: Any) -> Tuple[float, bool]:
    """(length, relative): a positive length, or a percentage of the bounding-box diagonal ("2%")."""
    message = ("remesh: edge_length must be a positive length or a percentage of the bounding-box diagonal "
               "(e.g. 0.05 or '2%')")
    relative = False
    if isinstance(value, str):
        text = value.strip()
        relative = text.endswith("%")
        try:
            d = float(text[:-1] if relative else text)
        except ValueError:
            raise ValueError(message) from None
    else:
        d = _real("edge_length", value, "remesh")
    if not (d > 0) or not math.isfinite(d):
        raise ValueError(message)
    return d, relative


def _size_field(mesh: MeshLike, field: Any) -> Tuple[np.ndarray, str]:
    """The target per vertex (float64) and its name in the statistics, checked as the CLI does."""
    if isinstance(field, str):
        if not isinstance(mesh, Mesh):
            raise ValueError(f"remesh: size_field {field!r}: a name needs a prstar.Mesh with point_data "
                             "(or give an array of one value per vertex)")
        if field not in mesh.point_data:
            have = ", ".join(mesh.point_data) or "none"
            raise ValueError(f"remesh: no point-data array named {field!r} for size_field (the mesh has: {have})")
        values, name = mesh.point_data[field], field
    else:
        values, name = field, "<array>"
    try:
        h = np.asarray(values, dtype=np.float64)
    except (TypeError, ValueError):
        raise ValueError("remesh: size_field must be a point-data name or an array of one number per vertex") from None
    if isinstance(mesh, Octree):
        n = mesh.number_of_vertices
    elif isinstance(mesh, Mesh):
        n = mesh.number_of_vertices
    else:
        n = len(mesh[0])
    if h.shape != (n,):
        raise ValueError(f"remesh: size_field: shape {h.shape}, expected ({n},): one target length per vertex")
    bad = np.flatnonzero(~(np.isfinite(h) & (h > 0)))
    if len(bad):
        v = int(bad[0])
        raise ValueError(f"remesh: size field '{name}': the target edge length at vertex {v} is "
                         f"{_number_text(h[v])} (it must be positive and finite)")
    return h, name


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
    """Remeshes a mesh towards a target edge length h leaf by leaf, as ``prstar remesh``: each round
    splits the edges longer than 4/3 h, collapses those shorter than 4/5 h, flips and moves vertices
    where the worst tetrahedron around gets better, then compacts the mesh and rebuilds the octree.
    Every operation is checked with exact orientation tests; sharp edges, corners and the surfaces
    between labels are kept, no tetrahedron is made under a quality floor or over the ceiling unless it
    replaces worse ones, and the surface stays within ``max_error`` of the input's.

    Args:
        mesh: a :class:`Mesh` (labels, point data and cell data carried along), a ``(points,
            tetrahedra)`` pair (read in place), or an :class:`Octree` (its arrays in the user's
            numbering).
        edge_length: the target edge length: a positive number, or a percentage string of the
            bounding-box diagonal ("2%").  Not with ``size_field``.
        size_field: the target at each vertex: the name of a point-data array of a Mesh, or an array of
            one positive value per vertex (an edge's target is the mean of its ends').
        iterations: the rounds, in [1, 1000] (default 5); they stop earlier when one changes nothing.
        min_dihedral, max_dihedral, min_radius_ratio, feature_angle, max_error: as :func:`simplify`.
        bucket_size: the bucket threshold k_v of the octrees of the rounds (default ``"auto"``, or the Octree's;
            ``math.inf``: one leaf).
        threads: the number of threads (default: all cores, or the Octree's).

    Returns:
        a :class:`RemeshResult`.

    Raises:
        ValueError: a bad option or size field (the messages of ``prstar remesh``), bad arrays.
        InvalidMeshError: arrays the octree refuses.
    """
    if edge_length is None and size_field is None:
        raise ValueError("remesh: give edge_length or size_field")
    if edge_length is not None and size_field is not None:
        raise ValueError("remesh: give edge_length or size_field, not both")
    length, length_relative = (0.0, False) if edge_length is None else _edge_length(edge_length)
    rounds = _integer("iterations", iterations, 1, 1000, "", "remesh")
    lo, hi, ratio, angle = _guards("remesh", min_dihedral, max_dihedral, min_radius_ratio, feature_angle)
    error, relative = _max_error(max_error, "remesh")
    source, tetrahedra, labels, carried = _source("remesh", mesh)
    sizing, name = (np.zeros(0), None) if size_field is None else _size_field(mesh, size_field)
    d = _remesh(source, tetrahedra, labels, edge_length=length, edge_length_relative=length_relative, sizing=sizing,
                size_field=name, iterations=rounds, min_dihedral=lo, max_dihedral=hi, min_radius_ratio=ratio,
                feature_angle=angle, max_error=error, error_relative=relative, bucket_size=bucket_size,
                threads=threads)
    return RemeshResult(mesh=_result_mesh(d, carried), statistics=dict(d["statistics"]),
                        input_vertex=d["input_vertex"], input_tetrahedron=d["input_tetrahedron"])
