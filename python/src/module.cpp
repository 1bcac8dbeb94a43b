// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The Python module `_prstar` (wrapped by the pure-Python package `prstar`): the octree from numpy
// arrays, its statistics and leaves, the boundary, the distortion and curvature; the exceptions.
// The other translation units bind files (io.cpp), validation and simplification
// (simplification.cpp) and the scalar-field topology (topology.cpp).

#include "prstar_python.h"

#include <CGAL/PR_star_octree/IO/Read_error.h>
#include <CGAL/PR_star_octree/boundary.h>
#include <CGAL/PR_star_octree/distortion.h>

#include <boost/property_map/property_map.hpp>

#include <cmath>
#include <iterator>
#include <limits>
#include <stdexcept>

namespace prstar_python {

namespace {

// 0 interior, 1 boundary, 2 non-manifold, 3 in no tetrahedron: the codes of `prstar boundary`
std::uint8_t vertex_code(PSO::Vertex_type t) {
  return static_cast<std::uint8_t>(PSO::vertex_type_code(t));
}

struct Code_map { // WritablePropertyMap: user vertex -> code
  using key_type = std::size_t;
  using value_type = PSO::Vertex_type;
  using reference = value_type;
  using category = boost::writable_property_map_tag;
  std::uint8_t* codes;
  friend void put(const Code_map& m, std::size_t v, PSO::Vertex_type t) { m.codes[v] = vertex_code(t); }
};

py::dict statistics_dict(const PSO::Statistics& s) {
  py::dict d;
  d["vertices"] = s.vertices;
  d["tetrahedra"] = s.tetrahedra;
  if (s.infinite_bucket_size)
    d["kv"] = std::numeric_limits<double>::infinity();
  else
    d["kv"] = s.bucket_size;
  d["kv_automatic"] = s.automatic_bucket_size;
  d["nodes"] = s.nodes;
  d["leaves"] = s.leaves;
  d["empty_leaves"] = s.empty_leaves;
  d["depth"] = s.depth;
  d["max_depth"] = s.max_depth;
  d["chi"] = s.chi;
  d["max_leaf_vertices"] = s.max_leaf_vertices;
  d["max_leaf_tetrahedra"] = s.max_leaf_tetrahedra;
  d["depth_limited_leaves"] = s.depth_limited_leaves;
  d["coincident_leaves"] = s.coincident_leaves;
  d["duplicate_vertices"] = s.duplicate_vertices;
  d["unreferenced_vertices"] = s.unreferenced_vertices;
  d["reoriented_tetrahedra"] = s.reoriented_tetrahedra;
  d["degenerate_tetrahedra"] = s.degenerate_tetrahedra;
  if (!s.subdomains.empty()) {
    py::dict sub;
    for (const auto& l : s.subdomains) sub[py::str(std::to_string(l.first))] = l.second;
    d["subdomains"] = sub;
  }
  d["prstar_overhead_per_vertex"] = s.prstar_overhead_per_vertex;
  d["prstar_total_per_vertex"] = s.prstar_total_per_vertex;
  d["ia_overhead_per_vertex"] = s.ia_overhead_per_vertex;
  d["ia_total_per_vertex"] = s.ia_total_per_vertex;
  d["bytes"] = s.bytes.total();
  d["float32_coordinates"] = s.float32_coordinates;
  py::dict b;
  b["points"] = s.bytes.points;
  b["scalars"] = s.bytes.scalars;
  b["tetrahedra"] = s.bytes.tetrahedra;
  if (s.bytes.labels) b["labels"] = s.bytes.labels;
  b["nodes"] = s.bytes.nodes;
  b["leaf_tetrahedra"] = s.bytes.leaf_tetrahedra;
  b["permutations"] = s.bytes.permutations;
  b["reorientation"] = s.bytes.reorientation;
  b["index"] = s.bytes.index();
  d["bytes_detail"] = b;
  return d;
}

// The leaves as arrays: boxes, vertex ranges (octree numbering), depths, tetrahedron counts.
py::dict leaves_dict(const Octree& tree) {
  const auto& leaves = tree.leaves();
  const std::size_t n = leaves.size();
  std::vector<double> lo(3 * n), hi(3 * n);
  std::vector<Index> begin(n), end(n);
  std::vector<std::uint32_t> depth(n);
  std::vector<std::uint64_t> tets(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto leaf = leaves[i];
    const CGAL::Bbox_3 b = tree.node_bbox(leaf);
    lo[3 * i] = b.xmin(), lo[3 * i + 1] = b.ymin(), lo[3 * i + 2] = b.zmin();
    hi[3 * i] = b.xmax(), hi[3 * i + 1] = b.ymax(), hi[3 * i + 2] = b.zmax();
    const auto r = tree.vertex_range(leaf);
    begin[i] = r.first;
    end[i] = r.second;
    depth[i] = static_cast<std::uint32_t>(tree.depth(leaf));
    tets[i] = tree.node(leaf).number_of_tetrahedra();
  }
  const auto ns = static_cast<py::ssize_t>(n);
  py::dict d;
  d["box_min"] = to_numpy<double>(std::move(lo), {ns, 3});
  d["box_max"] = to_numpy<double>(std::move(hi), {ns, 3});
  d["vertex_begin"] = to_numpy(std::move(begin));
  d["vertex_end"] = to_numpy(std::move(end));
  d["depth"] = to_numpy(std::move(depth));
  d["tetrahedra"] = to_numpy(std::move(tets));
  return d;
}

std::unique_ptr<Py_octree> make_octree(py::handle points, py::handle tetrahedra, py::handle bucket_size,
                                       py::handle max_depth, py::handle labels, py::handle field,
                                       py::handle threads, unsigned relations) {
  const Numpy_input input(points, tetrahedra, labels, field);
  auto o = std::make_unique<Py_octree>();
  o->threads = thread_count(threads);
  const std::size_t kv = bucket_size_argument(bucket_size), depth = max_depth_argument(max_depth);
  {
    Compute_scope scope(o->threads);
    try {
      o->tree = std::make_unique<Octree>(
          input, octree_parameters(kv, depth, relations ? relations : PSO::default_bucket_size_relations));
    } catch (const std::invalid_argument& e) {
      throw Invalid_mesh(e.what());
    }
  }
  return o;
}

struct Boundary_out {
  py::array_t<std::uint8_t> vertex_types;
  py::dict counts;
  py::object triangles = py::none(), inside = py::none(), outside = py::none(), interface = py::none();
};

py::dict boundary(Py_octree& o, bool surface, py::object progress) {
  const Octree& tree = o.get();
  const std::size_t nv = tree.number_of_vertices();
  std::vector<std::uint8_t> codes(nv, 3);
  std::vector<PSO::Surface_triangle> triangles;
  PSO::Boundary_counts b;
  const Progress p(std::move(progress));
  {
    Compute_scope scope(o.threads);
    b = PSO::compute_boundary(tree, Code_map{codes.data()}, params::progress(std::cref(p)));
    if (surface) PSO::boundary_surface(tree, std::back_inserter(triangles));
  }
  py::dict d;
  py::dict c;
  c["vertices"] = nv;
  c["tetrahedra"] = tree.number_of_tetrahedra();
  c["interior_vertices"] = b.interior_vertices;
  c["boundary_vertices"] = b.boundary_vertices;
  c["nonmanifold_vertices"] = b.nonmanifold_vertices;
  c["unreferenced_vertices"] = b.unreferenced_vertices;
  c["boundary_triangles"] = b.boundary_triangles;
  c["boundary_tetrahedra"] = b.boundary_tetrahedra;
  c["boundary_face_tetrahedra"] = b.boundary_face_tetrahedra;
  d["vertex_types"] = to_numpy(std::move(codes));
  if (surface) {
    const std::size_t n = triangles.size();
    std::vector<Index> tri(3 * n);
    std::vector<std::int32_t> inside(n), outside(n);
    std::vector<std::uint8_t> interface(n);
    std::size_t interfaces = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const auto& t = triangles[i];
      for (int k = 0; k < 3; ++k) tri[3 * i + k] = static_cast<Index>(t.vertices[k]);
      inside[i] = t.inside;
      outside[i] = t.interface ? t.outside : -1;
      interface[i] = t.interface ? 1 : 0;
      interfaces += t.interface;
    }
    c["interface_triangles"] = interfaces;
    d["triangles"] = to_numpy<Index>(std::move(tri), {static_cast<py::ssize_t>(n), 3});
    d["label_inside"] = to_numpy(std::move(inside));
    d["label_outside"] = to_numpy(std::move(outside));
    d["interface"] = to_numpy(std::move(interface)).attr("astype")("bool");
  }
  d["counts"] = c;
  return d;
}

// The curvature arrays of every vertex in the user's numbering.
struct Curvature_arrays {
  std::vector<std::uint8_t> code;
  std::vector<double> distortion, domain;
  explicit Curvature_arrays(std::size_t nv)
      : code(nv, 3), distortion(nv, std::numeric_limits<double>::quiet_NaN()),
        domain(nv, std::numeric_limits<double>::quiet_NaN()) {}
  struct Map {
    using key_type = std::size_t;
    using value_type = PSO::Vertex_curvature;
    using reference = value_type;
    using category = boost::writable_property_map_tag;
    Curvature_arrays* a;
    friend void put(const Map& m, std::size_t v, const value_type& c) {
      m.a->code[v] = vertex_code(c.type);
      m.a->distortion[v] = c.distortion;
      m.a->domain[v] = c.domain_curvature;
    }
  };
};

py::dict curvature(Py_octree& o, py::handle field, py::object progress) {
  std::vector<double> values = field_argument(o, field, "curvature");
  const Octree& tree = o.get();
  Curvature_arrays a(tree.number_of_vertices());
  PSO::Vertex_type_counts counts;
  const Progress p(std::move(progress));
  {
    Compute_scope scope(o.threads);
    counts = PSO::compute_curvature(tree, values.data(), Curvature_arrays::Map{&a},
                                    params::progress(std::cref(p)));
  }
  // undefined (non-manifold, unreferenced): NaN, as the CLI's CSV
  for (std::size_t v = 0; v < a.code.size(); ++v)
    if (a.code[v] > 1) a.distortion[v] = a.domain[v] = std::numeric_limits<double>::quiet_NaN();
  py::dict d;
  d["vertex_types"] = to_numpy(std::move(a.code));
  d["distortion"] = to_numpy(std::move(a.distortion));
  d["domain_curvature"] = to_numpy(std::move(a.domain));
  py::dict c;
  c["interior_vertices"] = counts.interior_vertices;
  c["boundary_vertices"] = counts.boundary_vertices;
  c["nonmanifold_vertices"] = counts.nonmanifold_vertices;
  c["unreferenced_vertices"] = counts.unreferenced_vertices;
  d["counts"] = c;
  return d;
}

} // namespace

void bind_octree(py::module_& m) {
  py::class_<Py_octree>(m, "Octree",
                        R"(The PR-star octree of a tetrahedral mesh (the C++ class PR_star_octree_3).

Built from numpy arrays, which are read in place and copied once into the octree:
points (n, 3) float32 or float64, tetrahedra (m, 4) of any integer dtype, labels (m,) integer,
field (n,) numeric.  Any memory layout (C, Fortran, strided) is accepted without a conversion.
Results of the applications come in the user's vertex and tetrahedron order.)")
      .def(py::init(&make_octree), py::arg("points"), py::arg("tetrahedra"), py::kw_only(),
           py::arg("bucket_size") = "auto", py::arg("max_depth") = py::none(), py::arg("labels") = py::none(),
           py::arg("field") = py::none(), py::arg("threads") = py::none(), py::arg("_relations") = 0u)
      .def_property_readonly("number_of_vertices",
                             [](const Py_octree& o) { return o.get().number_of_vertices(); })
      .def_property_readonly("number_of_tetrahedra",
                             [](const Py_octree& o) { return o.get().number_of_tetrahedra(); })
      .def_property_readonly("bucket_size",
                             [](const Py_octree& o) -> py::object {
                               if (o.get().bucket_size() == Octree::infinite_bucket_size)
                                 return py::float_(std::numeric_limits<double>::infinity());
                               return py::int_(o.get().bucket_size());
                             })
      .def_property_readonly("depth", [](const Py_octree& o) { return o.get().depth(); })
      .def_property_readonly("number_of_leaves",
                             [](const Py_octree& o) { return o.get().number_of_leaves(); })
      .def_property_readonly("has_labels",
                             [](const Py_octree& o) { return o.get().has_tetrahedron_labels(); })
      .def_property_readonly("has_field", [](const Py_octree& o) { return o.get().has_scalar_field(); })
      .def_property_readonly("threads",
                             [](const Py_octree& o) -> py::object {
                               if (o.threads == 0) return py::none();
                               return py::int_(o.threads);
                             })
      .def("__repr__",
           [](const Py_octree& o) {
             const Octree& t = o.get();
             const std::string kv = t.bucket_size() == Octree::infinite_bucket_size
                                        ? std::string("inf")
                                        : std::to_string(t.bucket_size());
             return "prstar.Octree(" + std::to_string(t.number_of_vertices()) + " vertices, " +
                    std::to_string(t.number_of_tetrahedra()) + " tetrahedra, bucket_size=" + kv + ", " +
                    (t.number_of_leaves() == 1 ? std::string("1 leaf")
                                               : std::to_string(t.number_of_leaves()) + " leaves") +
                    ", depth " + std::to_string(t.depth()) + ")";
           })
      .def("statistics", [](const Py_octree& o) { return statistics_dict(o.get().statistics()); })
      .def("leaves", [](const Py_octree& o) { return leaves_dict(o.get()); })
      .def("vertex_order",
           [](const Py_octree& o) {
             const auto& p = o.get().vertex_permutation();
             return to_numpy(std::vector<Index>(p.begin(), p.end()));
           })
      .def("tetrahedron_order",
           [](const Py_octree& o) {
             const auto& p = o.get().tetrahedron_permutation();
             return to_numpy(std::vector<Index>(p.begin(), p.end()));
           })
      .def("_boundary", &boundary, py::arg("surface"), py::arg("progress") = py::none())
      .def("_curvature", &curvature, py::arg("field") = py::none(), py::arg("progress") = py::none());
}

} // namespace prstar_python

PYBIND11_MODULE(_prstar, m) {
  namespace pp = prstar_python;
  namespace py = pybind11;
  m.doc() = "The compiled part of the prstar package (use `import prstar`).";
  static py::exception<pp::Invalid_mesh> invalid_mesh(m, "InvalidMeshError", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const pp::Invalid_mesh& e) {
      invalid_mesh(e.what());
    } catch (const CGAL::PR_star_octree::IO::Read_error& e) {
      PyErr_SetString(PyExc_OSError, e.what());
    } catch (const CGAL::PR_star_octree::IO::Write_error& e) {
      PyErr_SetString(PyExc_OSError, e.what());
    } catch (const std::invalid_argument& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });
  pp::bind_octree(m);
  pp::bind_io(m);
  pp::bind_simplification(m);
  pp::bind_topology(m);
}
