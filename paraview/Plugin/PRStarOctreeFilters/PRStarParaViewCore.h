// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The package's work for the ParaView plugin, in one translation unit (PRStarParaViewCore.cxx, the
// only one that includes CGAL): each function reads the tetrahedra of a vtkUnstructuredGrid in
// place as the octree's input, runs one application of the package's public API and writes VTK
// arrays or datasets.  The filter classes (vtkPRStar*.h) hold the properties and call these.
//
// Cells other than tetrahedra are passed through: the octree sees the tetrahedra only, and their
// number is returned (`Outcome::other_cells`) so that the filter can report it.  Vertices in no
// tetrahedron get the code 3 ("in no tetrahedron") of `prstar boundary`.
//
// Every function throws std::runtime_error with a message for the user (a bad mesh, a bad option);
// the filters turn it into a vtkErrorMacro.

#ifndef PRSTAR_PARAVIEW_CORE_H
#define PRSTAR_PARAVIEW_CORE_H

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

class vtkDataArray;
class vtkPolyData;
class vtkUnstructuredGrid;

namespace prstar_paraview {

/// What every function takes besides its input.
struct Options {
  int bucket_size = -1; ///< k_v; -1: chosen by the octree (automatic); 0: one leaf (k_v = infinity)
  int threads = 0;      ///< 0: all the cores
  /// called with the fraction done, on the calling thread only, at most about 20 times a second
  std::function<void(double)> progress;
  /// tetrahedron labels (an integer cell array of the input), or nullptr
  vtkDataArray* labels = nullptr;
};

/// What a function reports besides its output.
struct Outcome {
  std::size_t tetrahedra = 0;  ///< tetrahedra given to the octree
  std::size_t other_cells = 0; ///< cells of other types, passed through
  std::string summary;         ///< one line for the log
};

/// `out` = `in` with the point array `boundary` (0 interior, 1 boundary, 2 non-manifold, 3 in no
/// tetrahedron); `surface` (when not nullptr) = the boundary surface and the interfaces between
/// labels, outward oriented, over the vertices it uses, with the cell arrays `label_inside`,
/// `label_outside` (-1 on the boundary) and `interface`, the point arrays `vertex` (the index in
/// `in`) and `boundary_type` (1 boundary, 2 interface only, 3 non-manifold), and `in`'s point data.
Outcome boundary(vtkUnstructuredGrid* in, vtkUnstructuredGrid* out, vtkPolyData* surface, const Options& o);

/// `out` = `in` with the point arrays `boundary`, `distortion` (of `field`) and `domain_curvature`
/// (NaN where undefined: non-manifold vertices and those in no tetrahedron).  `field` nullptr: the
/// z coordinate.
Outcome curvature(vtkUnstructuredGrid* in, vtkDataArray* field, vtkUnstructuredGrid* out, const Options& o);

/// `out` = `in` with the cell array `problem` (bit flags: 1 inverted, 2 flat, 4 in a triangle of 3+
/// tetrahedra), the point array `problem` (1 non-manifold, 2 unreferenced, 4 on a triangle of 3+
/// tetrahedra) and the field data of `prstar validate --json` (valid, inverted, ...).
Outcome validate(vtkUnstructuredGrid* in, vtkUnstructuredGrid* out, const Options& o);

/// The leaf boxes of the octree of `in` as voxels with the cell arrays `depth`, `vertices` and
/// `tetrahedra` (as `prstar stats --octree`), and the statistics as field data.
Outcome octree_leaves(vtkUnstructuredGrid* in, vtkUnstructuredGrid* out, const Options& o);

/// The options of `simplify()`, as `prstar simplify` names them.
struct Simplify_options {
  double target = 0.5;           ///< fraction of the tetrahedra to remove, in (0, 1)
  double min_dihedral = 5;       ///< degrees; 0: none
  double min_radius_ratio = 0.1; ///< 0: none
  double max_dihedral = 165;     ///< degrees; 180: none
  double feature_angle = 40;     ///< degrees
  double max_error = 0.2;        ///< percent of the bounding box diagonal; negative: no bound
  int optimize = 2;              ///< rounds of flips and vertex moves after the collapses
  bool quadric = false;          ///< priority: quadric error (true) or edge length
  bool optimal = false;          ///< placement: optimal (true) or half-edge
  /// vertices that must stay (the vertices a piece shares with the other pieces under MPI), by
  /// point index of `in`, or nullptr
  const std::vector<char>* constrained = nullptr;
  /// the cells to simplify (the cells a piece owns under MPI), by cell index of `in`, or nullptr: all
  const std::vector<char>* cells = nullptr;
};

/// The simplified mesh of the tetrahedra of `in`: tetrahedra only, the labels, and every point and
/// cell array of `in` carried along (each output vertex and tetrahedron takes the values of the input
/// element it stands for).
Outcome simplify(vtkUnstructuredGrid* in, const Simplify_options& s, vtkUnstructuredGrid* out,
                 const Options& o);

/// `out` = `in` with the point array `critical_type` (0 minimum, 1 1-saddle, 2 2-saddle, 3 maximum,
/// 4 degenerate, 5 regular: TTK's codes) of `field`; `points` = the critical points as vertices with
/// the point arrays `vertex`, `critical_type`, `value`, `lower_components`, `upper_components`,
/// `on_boundary`.  `field` nullptr: the z coordinate.
Outcome critical_points(vtkUnstructuredGrid* in, vtkDataArray* field, vtkUnstructuredGrid* out,
                        vtkPolyData* points, const Options& o);

/// `out` = `in` with the Morse segmentation of `field` after the cancellation of the pairs of
/// persistence under `persistence` (a fraction of the field's range, in [0, 1]): the point arrays
/// `ascending_cell` (the vertex of the minimum whose ascending cell holds the vertex) and
/// `critical_type`, the cell array `descending_cell` (the vertex of its maximum, -1 for a gradient
/// path out through the boundary), and the counts as field
/// data.
Outcome morse_segmentation(vtkUnstructuredGrid* in, vtkDataArray* field, double persistence,
                           vtkUnstructuredGrid* out, const Options& o);

/// Reads `file` with the package's readers (and their memory checks) into `out`: the tetrahedra,
/// the cell array `label` and the field data `label_ids` / `label_names` when the file has them,
/// and its point and cell data.  The summary lists the cells the reader skipped.
Outcome read(const std::string& file, vtkUnstructuredGrid* out);

/// The extensions `read` takes, for the reader's messages.
std::string readable_extensions();

} // namespace prstar_paraview

#endif // PRSTAR_PARAVIEW_CORE_H
