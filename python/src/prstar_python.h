// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// What the translation units of the Python module (_prstar) share: the octree type, numpy arrays
// read in place as the octree's input (any dtype the module accepts, any strides), vectors handed to
// numpy without a copy, the thread limit, the Python progress callback, and the GIL rules.
//
// GIL: every computation runs with the GIL released (`Compute_scope`); the progress callback takes
// it back for the call into Python, at most ten times a second.  The numpy arrays read during a
// computation are held by the calling frame, so they stay alive; the module does not write to them.

#ifndef PRSTAR_PYTHON_H
#define PRSTAR_PYTHON_H

#include <CGAL/PR_star_octree.h>
#include <CGAL/PR_star_octree/Indexed_tetrahedral_mesh.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <array>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace prstar_python {

namespace py = pybind11;
namespace PSO = CGAL::PR_star_octree;
namespace params = CGAL::PR_star_octree::parameters;

using Octree = CGAL::PR_star_octree_3<>;
using Index = Octree::Index;
using Point_3 = Octree::Point_3;
using Mesh = PSO::Indexed_tetrahedral_mesh<>;

/// The exception for a mesh the package refuses (an index out of range, a vertex listed twice in a
/// tetrahedron, a non-finite coordinate, ...): `prstar.InvalidMeshError`, a `ValueError`.
struct Invalid_mesh : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

// ---------------------------------------------------------------------------------------------
// numpy arrays in, read in place
// ---------------------------------------------------------------------------------------------

/// A read-only view of a 1- or 2-dimensional numpy array of one of the numeric dtypes, any strides:
/// `get(i, j)` converts to `T` on the fly.  Holds a reference to the array.
template <class T>
class Array_view {
public:
  Array_view() = default;
  /// `what` names the argument in errors; `columns` is the required second dimension (0: a 1-D
  /// array); `kinds` the dtype kinds accepted ("f", "iu", "fiu").
  Array_view(py::handle obj, const char* what, py::ssize_t columns, const std::string& kinds);

  std::size_t size() const { return static_cast<std::size_t>(rows_); }
  bool empty() const { return rows_ == 0; }
  T get(std::size_t i, std::size_t j = 0) const {
    return dispatch([&](auto u) {
      using U = decltype(u);
      return static_cast<T>(
          load<U>(data_ + static_cast<py::ssize_t>(i) * s0_ + static_cast<py::ssize_t>(j) * s1_));
    });
  }
  /// the first `N` values of row `i`, with one dtype dispatch for the row (the octree's copy of a
  /// big array calls this once per point or tetrahedron)
  template <std::size_t N>
  std::array<T, N> row(std::size_t i) const {
    return dispatch([&](auto u) {
      using U = decltype(u);
      const char* p = data_ + static_cast<py::ssize_t>(i) * s0_;
      std::array<T, N> r;
      for (std::size_t k = 0; k < N; ++k)
        r[k] = static_cast<T>(load<U>(p + static_cast<py::ssize_t>(k) * s1_));
      return r;
    });
  }
  const py::array& array() const { return array_; }
  /// the numpy dtype character after normalisation ('f', 'd', 'i', 'l', ...)
  char code() const { return code_; }

private:
  // calls f(U()) with U the element type of the array
  template <class F>
  auto dispatch(F&& f) const {
    switch (code_) {
    case 'f':
      return f(float());
    case 'b':
      return f(std::int8_t());
    case 'h':
      return f(std::int16_t());
    case 'i':
      return f(std::int32_t());
    case 'l':
      return f(std::int64_t());
    case 'B':
      return f(std::uint8_t());
    case 'H':
      return f(std::uint16_t());
    case 'I':
      return f(std::uint32_t());
    case 'L':
      return f(std::uint64_t());
    default:
      return f(double());
    }
  }
  template <class U>
  static U load(const char* p) {
    U u;
    std::memcpy(&u, p, sizeof(U));
    return u;
  }
  py::array array_;
  const char* data_ = nullptr;
  py::ssize_t rows_ = 0, s0_ = 0, s1_ = 0;
  char code_ = 0;
};

/// The octree's input (the InputMesh concept of `PR_star_octree_3`) read from numpy arrays in
/// place: points (n, 3) float32/float64, tetrahedra (m, 4) of any integer dtype (negative indices
/// stay negative so that the octree refuses them), optional labels (m,) integer and field (n,)
/// floating or integer.  The octree copies each value once, into its own arrays.
class Numpy_input {
public:
  Numpy_input(py::handle points, py::handle tetrahedra, py::handle labels = py::none(),
              py::handle field = py::none());

  std::size_t number_of_vertices() const { return points_.size(); }
  std::size_t number_of_tetrahedra() const { return tetrahedra_.size(); }
  Point_3 point(std::size_t i) const {
    const auto c = points_.row<3>(i);
    return Point_3(c[0], c[1], c[2]);
  }
  std::array<long long, 4> tetrahedron(std::size_t t) const { return tetrahedra_.row<4>(t); }
  bool has_scalar_field() const { return has_field_; }
  double scalar(std::size_t i) const { return field_.get(i); }
  bool has_tetrahedron_labels() const { return has_labels_; }
  int tetrahedron_label(std::size_t t) const { return labels_.get(t); }
  /// float32 points stay 32-bit floats in the octree (`Coordinate_precision::as_input`)
  bool has_float32_points() const { return points_.code() == 'f'; }

private:
  Array_view<double> points_;
  Array_view<long long> tetrahedra_;
  Array_view<int> labels_;
  Array_view<double> field_;
  bool has_labels_ = false, has_field_ = false;
};

// ---------------------------------------------------------------------------------------------
// Vectors out, without a copy
// ---------------------------------------------------------------------------------------------

/// A numpy array of shape `shape` over the data of `v`, which is moved into a capsule that the
/// array owns (no copy).  `T` is the element type (a `Point_3` vector is viewed as doubles through
/// `Element`).
template <class Element, class T>
py::array_t<Element> to_numpy(std::vector<T>&& v, std::vector<py::ssize_t> shape) {
  static_assert(sizeof(T) % sizeof(Element) == 0, "");
  auto* owner = new std::vector<T>(std::move(v));
  py::capsule capsule(owner, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  std::vector<py::ssize_t> strides(shape.size());
  py::ssize_t s = sizeof(Element);
  for (std::size_t k = shape.size(); k-- > 0;) {
    strides[k] = s;
    s *= shape[k];
  }
  return py::array_t<Element>(shape, strides, reinterpret_cast<const Element*>(owner->data()), capsule);
}

/// 1-D numpy array over `v` (moved, no copy).
template <class T>
py::array_t<T> to_numpy(std::vector<T>&& v) {
  const auto n = static_cast<py::ssize_t>(v.size());
  return to_numpy<T, T>(std::move(v), {n});
}

/// The points of a vector of `Point_3` as an (n, 3) float64 array, no copy (Point_3 of
/// `Epick` is three doubles).
py::array_t<double> points_to_numpy(std::vector<Point_3>&& points);
/// (m, 4) uint32 tetrahedra, no copy.
py::array_t<Index> tetrahedra_to_numpy(std::vector<std::array<Index, 4>>&& tetrahedra);

// ---------------------------------------------------------------------------------------------
// Threads, progress, GIL
// ---------------------------------------------------------------------------------------------

/// A progress callback `f(done, total)` from Python, called with the GIL held, at most every 0.1 s
/// (and always at the end); callable from any thread (the package never calls it from two at once).
/// An exception raised by `f` (KeyboardInterrupt included: Ctrl-C is checked at each call) stops the
/// computation and reaches the caller.
class Progress {
public:
  explicit Progress(py::object f = py::none()) : f_(std::move(f)) {}
  bool active() const { return !f_.is_none(); }
  void operator()(std::size_t done, std::size_t total) const;

private:
  py::object f_;
  mutable std::chrono::steady_clock::time_point last_{};
};

/// A `threads` argument: `None` (all cores) or a positive integer.
std::size_t thread_count(py::handle threads);

/// What every computation holds while it runs: the thread limit (when `threads` > 0), then the GIL
/// released.  Destroyed in the reverse order: the GIL taken back first.
class Compute_scope {
public:
  explicit Compute_scope(std::size_t threads);

private:
#ifdef CGAL_LINKED_WITH_TBB
  std::unique_ptr<tbb::global_control> limit_;
#endif
  py::gil_scoped_release release_;
};

// ---------------------------------------------------------------------------------------------
// The octree object of the module
// ---------------------------------------------------------------------------------------------

/// `prstar.Octree`: the octree with both permutations kept (results in the user's numbering of
/// vertices and tetrahedra) and the thread count given at construction.
struct Py_octree {
  std::unique_ptr<Octree> tree;
  std::size_t threads = 0;           ///< 0: all cores
  std::vector<Index> from_original_; ///< user vertex -> octree vertex (made on first use)

  const Octree& get() const { return *tree; }
  /// user vertex -> octree vertex
  const std::vector<Index>& from_original();
};

/// The parameters shared by every octree construction.
inline auto octree_parameters(std::size_t bucket_size, std::size_t max_depth,
                              unsigned relations = PSO::default_bucket_size_relations) {
  return params::bucket_size(bucket_size)
      .bucket_size_relations(relations)
      .maximum_depth(max_depth)
      .vertex_permutation(true)
      .tetrahedron_permutation(true);
}

/// `bucket_size` as Python gives it: a positive int, `None`/`math.inf` for a single leaf, or "auto"
/// (the octree chooses).
std::size_t bucket_size_argument(py::handle kv);
/// `max_depth`: `None` (the library's default, 32) or an int in [1, 64].
std::size_t max_depth_argument(py::handle depth);

/// A field for the applications: `None` (the octree's own field), "x"/"y"/"z", or a (n,) array in the
/// user's vertex order; returned in the user's order, checked finite (ValueError naming the vertex).
std::vector<double> field_argument(Py_octree& o, py::handle field, const char* function);

/// The binding functions of each translation unit, called by PYBIND11_MODULE in module.cpp.
void bind_octree(py::module_& m);
void bind_io(py::module_& m);
void bind_simplification(py::module_& m);
void bind_topology(py::module_& m);

} // namespace prstar_python

#endif // PRSTAR_PYTHON_H
