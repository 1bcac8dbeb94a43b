// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The shared machinery of the Python module (see prstar_python.h).

#include "prstar_python.h"

#include <cmath>
#include <limits>

namespace prstar_python {

namespace {

// The dtype character of `a` normalised to the fixed-size codes used by `Array_view::get`
// ('l' is int64 and 'L' uint64 whatever the platform calls them), or 0 when not numeric.
char normalised_code(const py::dtype& dt) {
  const char kind = dt.kind();
  const auto size = dt.itemsize();
  if (kind == 'f') return size == 4 ? 'f' : size == 8 ? 'd' : 0;
  if (kind == 'i') return size == 1 ? 'b' : size == 2 ? 'h' : size == 4 ? 'i' : size == 8 ? 'l' : 0;
  if (kind == 'u') return size == 1 ? 'B' : size == 2 ? 'H' : size == 4 ? 'I' : size == 8 ? 'L' : 0;
  return 0;
}

std::string kinds_text(const std::string& kinds) {
  if (kinds == "f") return "a floating-point dtype (float32 or float64)";
  if (kinds == "iu") return "an integer dtype (int32, int64, uint32, ...)";
  return "a numeric dtype";
}

} // namespace

template <class T>
Array_view<T>::Array_view(py::handle obj, const char* what, py::ssize_t columns, const std::string& kinds) {
  // Anything numpy can view as an array (lists too); an ndarray is taken as it is (no copy).
  if (py::isinstance<py::array>(obj))
    array_ = py::reinterpret_borrow<py::array>(obj);
  else
    array_ = py::array::ensure(obj);
  if (!array_) throw py::value_error(std::string(what) + ": not an array");
  const py::dtype dt = array_.dtype();
  if (dt.kind() == 'b' && kinds.find('i') != std::string::npos)
    throw py::value_error(std::string(what) + ": boolean array, expected " + kinds_text(kinds));
  code_ = kinds.find(dt.kind()) != std::string::npos ? normalised_code(dt) : 0;
  if (code_ == 0)
    throw py::value_error(std::string(what) + ": dtype " +
                          py::cast<std::string>(py::str(static_cast<const py::handle&>(dt))) + ", expected " +
                          kinds_text(kinds));
  const py::ssize_t dims = columns == 0 ? 1 : 2;
  auto shape_text = [&] {
    std::string s = "(";
    for (py::ssize_t k = 0; k < array_.ndim(); ++k) s += (k ? ", " : "") + std::to_string(array_.shape(k));
    return s + (array_.ndim() == 1 ? ",)" : ")");
  };
  if (array_.ndim() != dims || (dims == 2 && array_.shape(1) != columns))
    throw py::value_error(std::string(what) + ": shape " + shape_text() + ", expected " +
                          (dims == 1 ? std::string("(n,)") : "(n, " + std::to_string(columns) + ")"));
  rows_ = array_.shape(0);
  s0_ = array_.strides(0);
  s1_ = dims == 2 ? array_.strides(1) : 0;
  data_ = static_cast<const char*>(array_.data());
}

template class Array_view<double>;
template class Array_view<long long>;
template class Array_view<int>;

Numpy_input::Numpy_input(py::handle points, py::handle tetrahedra, py::handle labels, py::handle field)
    : points_(points, "points", 3, "fiu"), tetrahedra_(tetrahedra, "tetrahedra", 4, "iu") {
  const std::size_t nv = points_.size(), nt = tetrahedra_.size();
  if (!labels.is_none()) {
    labels_ = Array_view<int>(labels, "labels", 0, "iu");
    if (labels_.size() != nt)
      throw py::value_error("labels: " + std::to_string(labels_.size()) + " values for " +
                            std::to_string(nt) + " tetrahedra");
    // labels are C ints: a value out of that range is refused, not wrapped
    const char c = labels_.code();
    if (c == 'l' || c == 'L' || c == 'I') {
      Array_view<long long> wide(labels, "labels", 0, "iu");
      for (std::size_t t = 0; t < nt; ++t) {
        const long long l = wide.get(t);
        if (l < std::numeric_limits<int>::min() || l > std::numeric_limits<int>::max() ||
            (c == 'L' && static_cast<unsigned long long>(l) >
                             static_cast<unsigned long long>(std::numeric_limits<int>::max())))
          throw py::value_error("labels: the label of tetrahedron " + std::to_string(t) +
                                " does not fit a 32-bit integer");
      }
    }
    has_labels_ = true;
  }
  if (!field.is_none()) {
    field_ = Array_view<double>(field, "field", 0, "fiu");
    if (field_.size() != nv)
      throw py::value_error("field: " + std::to_string(field_.size()) + " values for " + std::to_string(nv) +
                            " vertices");
    for (std::size_t i = 0; i < nv; ++i)
      if (!std::isfinite(field_.get(i)))
        throw py::value_error("field: the value at vertex " + std::to_string(i) + " is not finite");
    has_field_ = true;
  }
  // uint64 indices above the signed range would turn negative: refused here, with the real value
  if (tetrahedra_.code() == 'L') {
    const auto* base = static_cast<const char*>(tetrahedra_.array().data());
    const auto s0 = tetrahedra_.array().strides(0), s1 = tetrahedra_.array().strides(1);
    for (std::size_t t = 0; t < nt; ++t)
      for (std::size_t k = 0; k < 4; ++k) {
        std::uint64_t v;
        std::memcpy(&v, base + static_cast<py::ssize_t>(t) * s0 + static_cast<py::ssize_t>(k) * s1, sizeof v);
        if (v >= nv)
          throw Invalid_mesh("tetrahedron " + std::to_string(t) + " has vertex index " + std::to_string(v) +
                             " out of range [0, " + std::to_string(nv) + ")");
      }
  }
}

py::array_t<double> points_to_numpy(std::vector<Point_3>&& points) {
  static_assert(sizeof(Point_3) == 3 * sizeof(double), "Point_3 is three doubles");
  const auto n = static_cast<py::ssize_t>(points.size());
  return to_numpy<double>(std::move(points), {n, 3});
}

py::array_t<Index> tetrahedra_to_numpy(std::vector<std::array<Index, 4>>&& tetrahedra) {
  const auto n = static_cast<py::ssize_t>(tetrahedra.size());
  return to_numpy<Index>(std::move(tetrahedra), {n, 4});
}

void Progress::operator()(std::size_t done, std::size_t total) const {
  if (f_.is_none()) return;
  const auto now = std::chrono::steady_clock::now();
  if (done != total && now - last_ < std::chrono::milliseconds(100)) return;
  last_ = now;
  py::gil_scoped_acquire gil;
  if (PyErr_CheckSignals() != 0) throw py::error_already_set();
  f_(done, total);
}

std::size_t thread_count(py::handle threads) {
  if (threads.is_none()) return 0;
  if (!py::isinstance<py::int_>(threads) || py::isinstance<py::bool_>(threads))
    throw py::type_error("threads: expected None or a positive int");
  const long long n = threads.cast<long long>();
  if (n < 1 || n > 4096) throw py::value_error("threads: must be a positive integer (or None: all cores)");
  return static_cast<std::size_t>(n);
}

Compute_scope::Compute_scope(std::size_t threads) {
#ifdef CGAL_LINKED_WITH_TBB
  if (threads > 0)
    limit_ = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, threads);
#else
  (void)threads;
#endif
}

const std::vector<Index>& Py_octree::from_original() {
  if (from_original_.size() != tree->number_of_vertices()) from_original_ = tree->vertex_from_original();
  return from_original_;
}

std::size_t bucket_size_argument(py::handle kv) {
  if (kv.is_none()) return Octree::infinite_bucket_size;
  if (py::isinstance<py::str>(kv) && kv.cast<std::string>() == "auto") return Octree::automatic_bucket_size;
  if (py::isinstance<py::float_>(kv)) {
    const double d = kv.cast<double>();
    if (std::isinf(d) && d > 0) return Octree::infinite_bucket_size;
    if (d >= 1 && d == std::floor(d) && d < 1e15) return static_cast<std::size_t>(d);
    throw py::value_error("bucket_size: must be a positive integer or math.inf");
  }
  if (!py::isinstance<py::int_>(kv) || py::isinstance<py::bool_>(kv))
    throw py::type_error("bucket_size: expected a positive int (or math.inf for a single leaf, or \"auto\")");
  const long long n = kv.cast<long long>();
  if (n < 1) throw py::value_error("bucket_size: must be a positive integer (or math.inf for a single leaf)");
  return static_cast<std::size_t>(n);
}

std::size_t max_depth_argument(py::handle depth) {
  if (depth.is_none()) return Octree::default_max_depth;
  if (!py::isinstance<py::int_>(depth) || py::isinstance<py::bool_>(depth))
    throw py::type_error("max_depth: expected None or a positive int");
  const long long n = depth.cast<long long>();
  if (n < 1 || n > 64) throw py::value_error("max_depth: must be in [1, 64]");
  return static_cast<std::size_t>(n);
}

std::vector<double> field_argument(Py_octree& o, py::handle field, const char* function) {
  const Octree& tree = o.get();
  const std::size_t nv = tree.number_of_vertices();
  std::vector<double> values(nv);
  const std::string fn(function);
  int axis = -1;
  if (field.is_none()) {
    if (!tree.has_scalar_field())
      throw py::value_error(fn +
                            ": no field: give field= (an array of one value per vertex, or 'x', 'y', 'z'), "
                            "or build the Octree with field=");
    const auto& from = o.from_original();
    for (std::size_t v = 0; v < nv; ++v) values[v] = tree.scalar(from[v]);
    return values;
  }
  if (py::isinstance<py::str>(field)) {
    const std::string s = field.cast<std::string>();
    if (s == "x" || s == "y" || s == "z")
      axis = s[0] - 'x';
    else
      throw py::value_error(
          fn + ": field '" + s +
          "': a name is looked up in a Mesh's point_data; with an Octree give 'x', 'y', 'z' "
          "or an array");
    const auto& from = o.from_original();
    for (std::size_t v = 0; v < nv; ++v) values[v] = tree.coordinates(tree.point(from[v]))[axis];
    return values;
  }
  Array_view<double> a(field, "field", 0, "fiu");
  if (a.size() != nv)
    throw py::value_error(fn + ": field has " + std::to_string(a.size()) + " values for " +
                          std::to_string(nv) + " vertices");
  for (std::size_t v = 0; v < nv; ++v) {
    values[v] = a.get(v);
    if (!std::isfinite(values[v]))
      throw py::value_error(fn + ": the field's value at vertex " + std::to_string(v) + " is not finite");
  }
  return values;
}

} // namespace prstar_python
