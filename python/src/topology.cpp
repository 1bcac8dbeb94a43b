// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The topology of a scalar field (scalar_topology.h) for the Python module: the critical points of
// the piecewise-linear field, the Forman gradient and its Euler check, the Morse complexes, the
// persistence pairs and the Morse-Smale arcs.  Everything comes back as numpy arrays in the user's
// numbering of vertices and tetrahedra, with the counts of `prstar critical --json` and `prstar morse
// --json` (the functions `prstar.critical_points` and `prstar.morse_complexes` in _topology.py).

#include "prstar_python.h"

#include <CGAL/PR_star_octree/scalar_topology.h>
#include <CGAL/property_map.h>

#include <boost/property_map/property_map.hpp>

#include <cmath>
#include <iterator>
#include <limits>
#include <stdexcept>

namespace prstar_python {

namespace {

const std::size_t no_vertex = PSO::Critical_simplex::no_vertex;

// A user index as a numpy int64, -1 for "none" (`no_vertex`, `no_cell`): what the CLI writes.
std::int64_t index_or_minus_one(std::size_t v) {
  return v == no_vertex ? -1 : static_cast<std::int64_t>(v);
}

// WritablePropertyMap: user vertex -> TTK code, straight into the int8 array handed to numpy.
struct Type_map {
  using key_type = std::size_t;
  using value_type = PSO::Critical_type;
  using reference = value_type;
  using category = boost::writable_property_map_tag;
  std::int8_t* codes;
  friend void put(const Type_map& m, std::size_t v, PSO::Critical_type t) {
    m.codes[v] = static_cast<std::int8_t>(t);
  }
};

// The field's range over the vertices of the tetrahedra, as the CLI's (take_field in cmd_topology.cpp):
// the base of a relative persistence threshold, and the counts' field_min/field_max.
std::pair<double, double> referenced_range(const Octree& tree, const std::vector<double>& values) {
  std::vector<char> referenced(tree.number_of_vertices(), 0);
  for (std::size_t t = 0; t < tree.number_of_tetrahedra(); ++t)
    for (Index v : tree.tetrahedron(static_cast<Index>(t))) referenced[v] = 1;
  bool first = true;
  double lo = 0, hi = 0;
  for (std::size_t v = 0; v < referenced.size(); ++v) {
    if (!referenced[v]) continue;
    const double x = values[tree.original_vertex(static_cast<Index>(v))];
    lo = first ? x : (std::min)(lo, x);
    hi = first ? x : (std::max)(hi, x);
    first = false;
  }
  return {lo, hi};
}

py::object kv_value(const Octree& tree) {
  if (tree.bucket_size() == Octree::infinite_bucket_size)
    return py::float_(std::numeric_limits<double>::infinity());
  return py::int_(tree.bucket_size());
}

// The check the CLI makes (checked_euler in cmd_topology.cpp): the critical simplices of a gradient
// add up to the Euler characteristic counted apart in the same pass.  A failure is a bug of the
// package, not of the input: RuntimeError.
long long checked_euler(const PSO::Forman_gradient<Octree>& g) {
  const long long chi = g.euler_characteristic();
  if (chi != g.alternating_sum())
    throw std::runtime_error("internal error: the critical simplices of the gradient (alternating sum " +
                             std::to_string(g.alternating_sum()) +
                             ") do not add up to the Euler characteristic " + std::to_string(chi) +
                             "; please report it with the mesh");
  return chi;
}

// The gradient's figures under the keys of the CLI's "gradient" object.
py::dict gradient_dict(const PSO::Forman_gradient<Octree>& g, long long chi) {
  py::dict d;
  d["critical_vertices"] = g.number_of_critical_simplices(0);
  d["critical_edges"] = g.number_of_critical_simplices(1);
  d["critical_triangles"] = g.number_of_critical_simplices(2);
  d["critical_tetrahedra"] = g.number_of_critical_simplices(3);
  d["alternating_sum"] = g.alternating_sum();
  d["euler_characteristic"] = chi;
  d["bytes_per_tetrahedron"] = g.bytes_per_tetrahedron();
  return d;
}

// The critical simplices of a gradient as arrays: dimension (k,), vertices (k, 4) (user's indices, the
// highest in the field order first, -1 for the unused entries), value (k,).  The position in these
// arrays is the `saddle` of a Morse arc.
py::dict critical_simplices_dict(const PSO::Forman_gradient<Octree>& g) {
  const auto& c = g.critical_simplices();
  const std::size_t k = c.size();
  std::vector<std::int8_t> dimension(k);
  std::vector<std::int64_t> vertices(4 * k);
  std::vector<double> value(k);
  for (std::size_t i = 0; i < k; ++i) {
    dimension[i] = static_cast<std::int8_t>(c[i].dimension);
    for (int j = 0; j < 4; ++j) vertices[4 * i + j] = index_or_minus_one(c[i].vertices[j]);
    value[i] = c[i].value;
  }
  py::dict d;
  d["dimension"] = to_numpy(std::move(dimension));
  d["vertices"] = to_numpy<std::int64_t>(std::move(vertices), {static_cast<py::ssize_t>(k), 4});
  d["value"] = to_numpy(std::move(value));
  return d;
}

py::dict critical_points(Py_octree& o, py::handle field, bool gradient, py::object progress) {
  const std::vector<double> values = field_argument(o, field, "critical_points");
  const Octree& tree = o.get();
  const std::size_t nv = tree.number_of_vertices();
  std::vector<std::int8_t> types(nv, static_cast<std::int8_t>(PSO::Critical_type::REGULAR));
  std::vector<PSO::Critical_point> points;
  PSO::Critical_point_counts counts;
  PSO::Forman_gradient<Octree> g;
  const Progress p(std::move(progress));
  {
    Compute_scope scope(o.threads);
    const auto map = CGAL::make_property_map(values);
    counts = PSO::compute_critical_points(
        tree, map, Type_map{types.data()},
        params::critical_points_output(std::back_inserter(points)).progress(std::cref(p)));
    if (gradient) g = PSO::compute_forman_gradient(tree, map, params::progress(std::cref(p)));
  }
  const std::size_t k = points.size();
  std::vector<std::int64_t> vertex(k);
  std::vector<std::int32_t> lower(k), upper(k);
  std::vector<double> value(k);
  std::vector<std::uint8_t> boundary(k);
  std::size_t interior[5] = {0, 0, 0, 0, 0};
  for (std::size_t i = 0; i < k; ++i) {
    const auto& c = points[i];
    vertex[i] = static_cast<std::int64_t>(c.vertex);
    lower[i] = static_cast<std::int32_t>(c.lower_components);
    upper[i] = static_cast<std::int32_t>(c.upper_components);
    value[i] = c.value;
    boundary[i] = c.on_boundary ? 1 : 0;
    if (!c.on_boundary) ++interior[static_cast<int>(c.type)];
  }
  const auto range = referenced_range(tree, values);
  py::dict c;
  c["vertices"] = nv;
  c["tetrahedra"] = tree.number_of_tetrahedra();
  c["kv"] = kv_value(tree);
  c["kv_automatic"] = tree.has_automatic_bucket_size();
  c["field_min"] = range.first;
  c["field_max"] = range.second;
  c["minima"] = counts.minima;
  c["saddles_1"] = counts.saddles_1;
  c["saddles_2"] = counts.saddles_2;
  c["maxima"] = counts.maxima;
  c["degenerate"] = counts.degenerate;
  c["regular"] = counts.regular;
  c["unreferenced"] = counts.unreferenced;
  c["join_multiplicity"] = counts.join_multiplicity;
  c["split_multiplicity"] = counts.split_multiplicity;
  py::dict in;
  const char* keys[5] = {"minima", "saddles_1", "saddles_2", "maxima", "degenerate"};
  for (int i = 0; i < 5; ++i) in[keys[i]] = interior[i];
  c["interior"] = in;
  py::dict d;
  if (gradient) {
    c["gradient"] = gradient_dict(g, checked_euler(g));
    d["critical_simplices"] = critical_simplices_dict(g);
  }
  d["types"] = to_numpy(std::move(types));
  d["vertices"] = to_numpy(std::move(vertex));
  d["lower_components"] = to_numpy(std::move(lower));
  d["upper_components"] = to_numpy(std::move(upper));
  d["values"] = to_numpy(std::move(value));
  d["on_boundary"] = to_numpy(std::move(boundary)).attr("astype")("bool");
  d["counts"] = c;
  return d;
}

// The persistence pairs as arrays (the rows of the CLI's --csv): kind 0 minimum-saddle, 1
// saddle-maximum; saddle -1 and saddle_value NaN for an essential pair; birth/death/persistence
// infinite there.
py::dict pairs_dict(const std::vector<PSO::Persistence_pair>& pairs) {
  const std::size_t k = pairs.size();
  std::vector<std::int8_t> kind(k);
  std::vector<std::int64_t> extremum(k), saddle(k);
  std::vector<double> ev(k), sv(k), birth(k), death(k), persistence(k);
  std::vector<std::uint8_t> essential(k);
  for (std::size_t i = 0; i < k; ++i) {
    const auto& p = pairs[i];
    kind[i] = static_cast<std::int8_t>(p.type);
    extremum[i] = static_cast<std::int64_t>(p.extremum);
    saddle[i] = index_or_minus_one(p.saddle);
    ev[i] = p.extremum_value;
    sv[i] = p.is_essential() ? std::numeric_limits<double>::quiet_NaN() : p.saddle_value;
    birth[i] = p.birth();
    death[i] = p.death();
    persistence[i] = p.persistence();
    essential[i] = p.is_essential() ? 1 : 0;
  }
  py::dict d;
  d["kind"] = to_numpy(std::move(kind));
  d["extremum"] = to_numpy(std::move(extremum));
  d["saddle"] = to_numpy(std::move(saddle));
  d["extremum_value"] = to_numpy(std::move(ev));
  d["saddle_value"] = to_numpy(std::move(sv));
  d["birth"] = to_numpy(std::move(birth));
  d["death"] = to_numpy(std::move(death));
  d["persistence"] = to_numpy(std::move(persistence));
  d["essential"] = to_numpy(std::move(essential)).attr("astype")("bool");
  return d;
}

// The arcs as the CLI's .vtp holds them: all the polylines' points one after the other, `offsets`
// (k + 1) delimiting them, and per arc saddle_dimension, saddle (its position among the critical
// simplices), saddle_vertex, extremum (-1: the path leaves the domain), saddle_value.
py::dict arcs_dict(const std::vector<PSO::Morse_arc>& arcs,
                   const std::vector<PSO::Critical_simplex>& critical) {
  const std::size_t k = arcs.size();
  std::size_t n = 0;
  for (const auto& a : arcs) n += a.points.size();
  std::vector<double> points;
  points.reserve(3 * n);
  std::vector<std::int64_t> offsets(k + 1, 0), saddle(k), saddle_vertex(k), extremum(k);
  std::vector<std::int8_t> dimension(k);
  std::vector<double> saddle_value(k);
  for (std::size_t i = 0; i < k; ++i) {
    const auto& a = arcs[i];
    for (const auto& q : a.points) points.insert(points.end(), q.begin(), q.end());
    offsets[i + 1] = offsets[i] + static_cast<std::int64_t>(a.points.size());
    dimension[i] = static_cast<std::int8_t>(a.saddle_dimension);
    saddle[i] = static_cast<std::int64_t>(a.saddle);
    saddle_vertex[i] = index_or_minus_one(critical[a.saddle].vertices[0]);
    extremum[i] = index_or_minus_one(a.extremum);
    saddle_value[i] = critical[a.saddle].value;
  }
  py::dict d;
  d["points"] = to_numpy<double>(std::move(points), {static_cast<py::ssize_t>(n), 3});
  d["offsets"] = to_numpy(std::move(offsets));
  d["saddle_dimension"] = to_numpy(std::move(dimension));
  d["saddle"] = to_numpy(std::move(saddle));
  d["saddle_vertex"] = to_numpy(std::move(saddle_vertex));
  d["extremum"] = to_numpy(std::move(extremum));
  d["saddle_value"] = to_numpy(std::move(saddle_value));
  return d;
}

// `threshold` absolute, or, when `relative` is not None, that fraction of the field's range over the
// vertices of the tetrahedra (computed as the CLI computes it, so that both cancel the same pairs).
py::dict morse_complexes(Py_octree& o, py::handle field, double threshold, py::object relative,
                         bool with_arcs, py::object progress) {
  const std::vector<double> values = field_argument(o, field, "morse_complexes");
  const Octree& tree = o.get();
  const auto range = referenced_range(tree, values);
  double fraction = std::numeric_limits<double>::quiet_NaN();
  if (!relative.is_none()) {
    fraction = relative.cast<double>();
    if (!(fraction >= 0 && fraction <= 1))
      throw std::invalid_argument("morse_complexes: persistence must be a percentage of the field's range in "
                                  "[0%, 100%]");
    threshold = fraction * (range.second - range.first);
  } else if (!(threshold >= 0) || std::isinf(threshold)) {
    throw std::invalid_argument(
        "morse_complexes: persistence must be a finite number >= 0 (or a percentage of "
        "the field's range, e.g. '5%')");
  }
  std::vector<PSO::Morse_arc> arcs;
  const Progress p(std::move(progress));
  PSO::Morse_complexes<Octree> m;
  {
    Compute_scope scope(o.threads);
    const auto map = CGAL::make_property_map(values);
    const auto np = params::persistence_threshold(threshold).progress(std::cref(p));
    m = with_arcs ? PSO::compute_morse_complexes(tree, map, np.arcs_output(std::back_inserter(arcs)))
                  : PSO::compute_morse_complexes(tree, map, np);
  }
  const long long chi = checked_euler(m.gradient);
  const std::size_t nv = tree.number_of_vertices(), nt = tree.number_of_tetrahedra();
  std::vector<std::int64_t> ascending(nv), descending(nt);
  std::vector<std::int8_t> types(nv);
  for (std::size_t v = 0; v < nv; ++v) {
    ascending[v] = index_or_minus_one(m.ascending_cell[v]);
    types[v] = static_cast<std::int8_t>(m.critical_type[v]);
  }
  // in the user's order: the octree of the module keeps the tetrahedron permutation
  for (std::size_t t = 0; t < nt; ++t) descending[t] = index_or_minus_one(m.descending_cell[t]);

  std::size_t kept[2] = {0, 0}, total[2] = {0, 0};
  for (const auto& q : m.persistence_pairs) {
    ++total[q.type];
    kept[q.type] += !(q.persistence() < threshold);
  }
  py::dict c;
  c["vertices"] = nv;
  c["tetrahedra"] = nt;
  c["kv"] = kv_value(tree);
  c["kv_automatic"] = tree.has_automatic_bucket_size();
  c["field_min"] = range.first;
  c["field_max"] = range.second;
  c["persistence"] = relative.is_none() ? py::object(py::none()) : py::object(py::float_(fraction));
  c["threshold"] = threshold;
  const auto& cp = m.critical_points;
  py::dict cpd;
  cpd["minima"] = cp.minima;
  cpd["saddles_1"] = cp.saddles_1;
  cpd["saddles_2"] = cp.saddles_2;
  cpd["maxima"] = cp.maxima;
  cpd["degenerate"] = cp.degenerate;
  cpd["regular"] = cp.regular;
  c["critical_points"] = cpd;
  c["gradient"] = gradient_dict(m.gradient, chi);
  c["ascending_cells"] = m.ascending_cells;
  c["descending_cells"] = m.descending_cells;
  c["outflow_tetrahedra"] = m.outflow_tetrahedra;
  c["minimum_saddle_pairs"] = total[0];
  c["saddle_maximum_pairs"] = total[1];
  c["minimum_saddle_pairs_kept"] = kept[0];
  c["saddle_maximum_pairs_kept"] = kept[1];
  py::dict d;
  if (with_arcs) {
    c["arcs"] = arcs.size();
    d["arcs"] = arcs_dict(arcs, m.gradient.critical_simplices());
  }
  d["ascending_cell"] = to_numpy(std::move(ascending));
  d["descending_cell"] = to_numpy(std::move(descending));
  d["critical_types"] = to_numpy(std::move(types));
  d["pairs"] = pairs_dict(m.persistence_pairs);
  d["critical_simplices"] = critical_simplices_dict(m.gradient);
  d["counts"] = c;
  return d;
}

} // namespace

void bind_topology(py::module_& m) {
  m.def("_critical_points", &critical_points, py::arg("octree"), py::arg("field"), py::arg("gradient"),
        py::arg("progress") = py::none(),
        "The critical points of a field (and with gradient=True its Forman gradient), as dicts of arrays; "
        "see prstar.critical_points.");
  m.def("_morse_complexes", &morse_complexes, py::arg("octree"), py::arg("field"), py::arg("threshold"),
        py::arg("relative"), py::arg("arcs"), py::arg("progress") = py::none(),
        "The Morse complexes and persistence pairs of a field, as dicts of arrays; see "
        "prstar.morse_complexes.");
}

} // namespace prstar_python
