// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later

#include "PRStarParaViewCore.h"

#include <CGAL/PR_star_octree.h>
#include <CGAL/PR_star_octree/IO.h>
#include <CGAL/PR_star_octree/Indexed_tetrahedral_mesh.h>
#include <CGAL/PR_star_octree/boundary.h>
#include <CGAL/PR_star_octree/distortion.h>
#include <CGAL/PR_star_octree/scalar_topology.h>
#include <CGAL/PR_star_octree/simplification.h>
#include <CGAL/PR_star_octree/validity.h>

#include <boost/property_map/property_map.hpp>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSignedCharArray.h>
#include <vtkStringArray.h>
#include <vtkTypeInt32Array.h>
#include <vtkTypeInt64Array.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>
#include <memory>
#include <stdexcept>
#include <thread>
#include <vector>

namespace prstar_paraview {

namespace {

namespace PSO = CGAL::PR_star_octree;
namespace params = CGAL::PR_star_octree::parameters;
using Octree = CGAL::PR_star_octree_3<>;
using Index = Octree::Index;
using Point_3 = Octree::Point_3;

// ---------------------------------------------------------------------------------------------
// The grid's tetrahedra, read in place (the InputMesh concept of PR_star_octree_3)
// ---------------------------------------------------------------------------------------------

class Grid_input {
public:
  // `keep_cell(c)`: whether cell c (a tetrahedron) is given to the octree (all by default)
  explicit Grid_input(vtkUnstructuredGrid* g, vtkDataArray* labels = nullptr,
                      const std::vector<char>* keep_cell = nullptr)
      : grid_(g), labels_(labels) {
    const vtkIdType nc = g->GetNumberOfCells();
    vtkUnsignedCharArray* types = g->GetCellTypesArray();
    bool all = types != nullptr;
    if (all) {
      const unsigned char* t = types->GetPointer(0);
      all = std::all_of(t, t + nc, [](unsigned char x) { return x == VTK_TETRA; });
    }
    if (all && keep_cell == nullptr) {
      all_ = true;
      tetrahedra_ = static_cast<std::size_t>(nc);
    } else {
      for (vtkIdType c = 0; c < nc; ++c) {
        if (g->GetCellType(c) != VTK_TETRA) {
          ++other_;
          continue;
        }
        if (keep_cell == nullptr || (*keep_cell)[static_cast<std::size_t>(c)]) cells_.push_back(c);
      }
      tetrahedra_ = cells_.size();
    }
    vtkCellArray* cells = g->GetCells();
    if (cells != nullptr && nc > 0) {
      if (cells->IsStorage64Bit()) {
        off64_ = cells->GetOffsetsArray64()->GetPointer(0);
        conn64_ = cells->GetConnectivityArray64()->GetPointer(0);
      } else {
        off32_ = cells->GetOffsetsArray32()->GetPointer(0);
        conn32_ = cells->GetConnectivityArray32()->GetPointer(0);
      }
    }
    vtkDataArray* p = g->GetPoints() != nullptr ? g->GetPoints()->GetData() : nullptr;
    if (auto* d = vtkDoubleArray::FastDownCast(p)) pd_ = d->GetPointer(0);
    if (auto* f = vtkFloatArray::FastDownCast(p)) pf_ = f->GetPointer(0);
    if (labels_ != nullptr) {
      if (labels_->GetNumberOfComponents() != 1 || labels_->GetNumberOfTuples() != nc)
        throw std::runtime_error(std::string("the label array '") + name(labels_) +
                                 "' must have one component per cell");
      const int t = labels_->GetDataType();
      if (t == VTK_FLOAT || t == VTK_DOUBLE) {
        for (std::size_t i = 0; i < tetrahedra_; ++i) {
          const double x = labels_->GetComponent(cell(i), 0);
          if (!(x == std::floor(x)) || std::abs(x) > 2147483647.)
            throw std::runtime_error(std::string("the label array '") + name(labels_) + "' has the value " +
                                     std::to_string(x) + " at cell " + std::to_string(cell(i)) +
                                     ", not an integer");
        }
      }
    }
  }

  std::size_t number_of_vertices() const { return static_cast<std::size_t>(grid_->GetNumberOfPoints()); }
  std::size_t number_of_tetrahedra() const { return tetrahedra_; }
  // vtkFloatArray points stay 32-bit floats in the octree (Coordinate_precision::as_input)
  bool has_float32_points() const { return pd_ == nullptr && pf_ != nullptr; }
  Point_3 point(std::size_t i) const {
    if (pd_ != nullptr) return Point_3(pd_[3 * i], pd_[3 * i + 1], pd_[3 * i + 2]);
    if (pf_ != nullptr) return Point_3(pf_[3 * i], pf_[3 * i + 1], pf_[3 * i + 2]);
    double x[3];
    grid_->GetPoint(static_cast<vtkIdType>(i), x);
    return Point_3(x[0], x[1], x[2]);
  }
  std::array<long long, 4> tetrahedron(std::size_t t) const {
    const vtkIdType c = cell(t);
    std::array<long long, 4> r;
    if (conn64_ != nullptr) {
      const auto* p = conn64_ + off64_[c];
      for (int k = 0; k < 4; ++k) r[k] = static_cast<long long>(p[k]);
    } else {
      const auto* p = conn32_ + off32_[c];
      for (int k = 0; k < 4; ++k) r[k] = static_cast<long long>(p[k]);
    }
    return r;
  }
  bool has_scalar_field() const { return false; }
  double scalar(std::size_t) const { return 0; }
  bool has_tetrahedron_labels() const { return labels_ != nullptr; }
  int tetrahedron_label(std::size_t t) const { return static_cast<int>(labels_->GetComponent(cell(t), 0)); }

  /// the grid's cell of tetrahedron t
  vtkIdType cell(std::size_t t) const { return all_ ? static_cast<vtkIdType>(t) : cells_[t]; }
  std::size_t other_cells() const { return other_; }
  static const char* name(vtkDataArray* a) { return a->GetName() != nullptr ? a->GetName() : "(unnamed)"; }

private:
  vtkUnstructuredGrid* grid_;
  vtkDataArray* labels_;
  bool all_ = false;
  std::size_t tetrahedra_ = 0, other_ = 0;
  std::vector<vtkIdType> cells_;
  const vtkTypeInt64* off64_ = nullptr;
  const vtkTypeInt64* conn64_ = nullptr;
  const vtkTypeInt32* off32_ = nullptr;
  const vtkTypeInt32* conn32_ = nullptr;
  const double* pd_ = nullptr;
  const float* pf_ = nullptr;
};

// ---------------------------------------------------------------------------------------------
// Threads and progress
// ---------------------------------------------------------------------------------------------

// The thread limit of Options::threads for as long as it lives.
class Thread_scope {
public:
  explicit Thread_scope(int threads) {
#ifdef CGAL_LINKED_WITH_TBB
    if (threads > 0)
      limit_ = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                     static_cast<std::size_t>(threads));
#else
    (void)threads;
#endif
  }

private:
#ifdef CGAL_LINKED_WITH_TBB
  std::unique_ptr<tbb::global_control> limit_;
#endif
};

// The package's progress callback F(done, total) -> Options::progress(fraction in [from, to]), on
// the thread that created it (ParaView's progress handler expects the main thread), throttled.
class Progress {
public:
  Progress(const Options& o, double from = 0, double to = 1)
      : f_(&o.progress), from_(from), to_(to), thread_(std::this_thread::get_id()) {}
  void operator()(std::size_t done, std::size_t total) const {
    if (!*f_ || total == 0 || std::this_thread::get_id() != thread_) return;
    const auto now = std::chrono::steady_clock::now();
    if (done < total && now - last_ < std::chrono::milliseconds(50)) return;
    last_ = now;
    (*f_)(from_ + (to_ - from_) * double(done) / double(total));
  }

private:
  const std::function<void(double)>* f_;
  double from_, to_;
  std::thread::id thread_;
  mutable std::chrono::steady_clock::time_point last_{};
};

// The k_v of the Options: -1 (and below) automatic, 0 one leaf.
std::size_t bucket_size_of(const Options& o) {
  return o.bucket_size < 0    ? Octree::automatic_bucket_size
         : o.bucket_size == 0 ? Octree::infinite_bucket_size
                              : std::size_t(o.bucket_size);
}

// What the results need of the octree's permutations: vertices in the grid's numbering (results per
// point), tetrahedra too (results per cell), or neither (the octree itself).
enum class Numbering { NONE, VERTICES, VERTICES_AND_TETRAHEDRA };

// The octree of the grid's tetrahedra, keeping the permutations the results need (each costs 4 bytes
// an element and its time).
std::unique_ptr<Octree> make_octree(const Grid_input& input, const Options& o, Numbering n) {
  const std::size_t kv = bucket_size_of(o);
  try {
    return std::make_unique<Octree>(input,
                                    params::bucket_size(kv)
                                        .vertex_permutation(n != Numbering::NONE)
                                        .tetrahedron_permutation(n == Numbering::VERTICES_AND_TETRAHEDRA));
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(e.what());
  }
}

// `out` := the points (as doubles) and tetrahedra of `mesh`, nothing else; returns the number of
// points.
template <class Mesh>
vtkIdType set_tetrahedral_grid(const Mesh& mesh, vtkUnstructuredGrid* out) {
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  pts->SetNumberOfPoints(static_cast<vtkIdType>(mesh.points.size()));
  for (std::size_t i = 0; i < mesh.points.size(); ++i) {
    const auto& q = mesh.points[i];
    pts->SetPoint(static_cast<vtkIdType>(i), q.x(), q.y(), q.z());
  }
  vtkNew<vtkCellArray> cells;
  cells->AllocateExact(static_cast<vtkIdType>(mesh.tetrahedra.size()),
                       4 * static_cast<vtkIdType>(mesh.tetrahedra.size()));
  for (const auto& t : mesh.tetrahedra) {
    const vtkIdType ids[4] = {vtkIdType(t[0]), vtkIdType(t[1]), vtkIdType(t[2]), vtkIdType(t[3])};
    cells->InsertNextCell(4, ids);
  }
  out->Initialize();
  out->SetPoints(pts);
  out->SetCells(VTK_TETRA, cells);
  return pts->GetNumberOfPoints();
}

std::uint8_t vertex_code(PSO::Vertex_type t) {
  return static_cast<std::uint8_t>(PSO::vertex_type_code(t));
}

struct Code_map { // WritablePropertyMap: grid point -> code of `prstar boundary`
  using key_type = std::size_t;
  using value_type = PSO::Vertex_type;
  using reference = value_type;
  using category = boost::writable_property_map_tag;
  std::uint8_t* codes;
  friend void put(const Code_map& m, std::size_t v, PSO::Vertex_type t) { m.codes[v] = vertex_code(t); }
};

template <class Array, class T>
vtkSmartPointer<Array> make_array(const char* name, const std::vector<T>& values, int components = 1) {
  auto a = vtkSmartPointer<Array>::New();
  a->SetName(name);
  a->SetNumberOfComponents(components);
  a->SetNumberOfTuples(static_cast<vtkIdType>(values.size() / std::size_t(components)));
  std::copy(values.begin(), values.end(), a->GetPointer(0));
  return a;
}

template <class Array>
void add_field(vtkFieldData* fd, const char* name, double value) {
  auto a = vtkSmartPointer<Array>::New();
  a->SetName(name);
  a->SetNumberOfTuples(1);
  a->SetValue(0, static_cast<typename Array::ValueType>(value));
  fd->AddArray(a);
}

// A field for the applications: `field` (one component, a value per point), or z.
std::vector<double> field_values(vtkUnstructuredGrid* in, vtkDataArray* field) {
  const vtkIdType n = in->GetNumberOfPoints();
  std::vector<double> v(static_cast<std::size_t>(n));
  if (field != nullptr && (field->GetNumberOfComponents() != 1 || field->GetNumberOfTuples() != n))
    throw std::runtime_error(std::string("the field '") + Grid_input::name(field) +
                             "' must be a point array with one component");
  for (vtkIdType i = 0; i < n; ++i) {
    double x[3];
    if (field == nullptr) in->GetPoint(i, x);
    v[std::size_t(i)] = field != nullptr ? field->GetComponent(i, 0) : x[2];
    if (!std::isfinite(v[std::size_t(i)]))
      throw std::runtime_error(std::string("the field '") + (field ? Grid_input::name(field) : "z") +
                               "' is not finite at point " + std::to_string(i));
  }
  return v;
}

std::string count_line(const Grid_input& input) {
  std::string s = std::to_string(input.number_of_tetrahedra()) + " tetrahedra";
  if (input.other_cells() > 0)
    s += " (" + std::to_string(input.other_cells()) + " cells of other types passed through)";
  return s;
}

Outcome outcome(const Grid_input& input, std::string summary) {
  Outcome r;
  r.tetrahedra = input.number_of_tetrahedra();
  r.other_cells = input.other_cells();
  r.summary = std::move(summary);
  return r;
}

} // namespace

// ---------------------------------------------------------------------------------------------
// Boundary
// ---------------------------------------------------------------------------------------------

Outcome boundary(vtkUnstructuredGrid* in, vtkUnstructuredGrid* out, vtkPolyData* surface, const Options& o) {
  const Grid_input input(in, o.labels);
  const Thread_scope threads(o.threads);
  const auto tree = make_octree(input, o, Numbering::VERTICES);
  const std::size_t nv = input.number_of_vertices();
  std::vector<std::uint8_t> codes(nv, 3);
  const Progress p(o, 0.05, surface != nullptr ? 0.6 : 1.0);
  const PSO::Boundary_counts b =
      PSO::compute_boundary(*tree, Code_map{codes.data()}, params::progress(std::cref(p)));
  std::vector<PSO::Surface_triangle> triangles;
  if (surface != nullptr) {
    const Progress q(o, 0.6, 1.0);
    PSO::boundary_surface(*tree, std::back_inserter(triangles), params::progress(std::cref(q)));
  }
  out->ShallowCopy(in);
  out->GetPointData()->AddArray(make_array<vtkUnsignedCharArray>("boundary", codes));

  std::size_t interfaces = 0;
  if (surface != nullptr) {
    // the vertices the surface uses, in the order of their first use
    std::vector<vtkIdType> local(nv, -1);
    std::vector<vtkIdType> vertex;
    vtkNew<vtkCellArray> polys;
    const std::size_t n = triangles.size();
    std::vector<std::int32_t> inside(n), outside(n);
    std::vector<std::uint8_t> interface(n);
    std::vector<std::uint8_t> type; // boundary_type per surface vertex
    for (std::size_t i = 0; i < n; ++i) {
      const auto& t = triangles[i];
      vtkIdType ids[3];
      for (int k = 0; k < 3; ++k) {
        const std::size_t v = t.vertices[k];
        if (local[v] < 0) {
          local[v] = static_cast<vtkIdType>(vertex.size());
          vertex.push_back(static_cast<vtkIdType>(v));
          type.push_back(codes[v] == 2 ? 3 : 2); // interface only until a boundary triangle says 1
        }
        ids[k] = local[v];
        if (!t.interface && codes[v] != 2) type[std::size_t(local[v])] = 1;
      }
      polys->InsertNextCell(3, ids);
      inside[i] = t.inside;
      outside[i] = t.interface ? t.outside : -1;
      interface[i] = t.interface ? 1 : 0;
      interfaces += t.interface;
    }
    vtkNew<vtkPoints> pts;
    pts->SetDataTypeToDouble();
    pts->SetNumberOfPoints(static_cast<vtkIdType>(vertex.size()));
    for (std::size_t i = 0; i < vertex.size(); ++i) {
      double x[3];
      in->GetPoint(vertex[i], x);
      pts->SetPoint(static_cast<vtkIdType>(i), x);
    }
    surface->Initialize();
    surface->SetPoints(pts);
    surface->SetPolys(polys);
    vtkPointData* spd = surface->GetPointData();
    spd->CopyAllocate(in->GetPointData(), static_cast<vtkIdType>(vertex.size()));
    for (std::size_t i = 0; i < vertex.size(); ++i)
      spd->CopyData(in->GetPointData(), vertex[i], static_cast<vtkIdType>(i));
    std::vector<std::int64_t> vid(vertex.begin(), vertex.end());
    spd->AddArray(make_array<vtkTypeInt64Array>("vertex", vid));
    spd->AddArray(make_array<vtkUnsignedCharArray>("boundary_type", type));
    vtkCellData* scd = surface->GetCellData();
    scd->AddArray(make_array<vtkTypeInt32Array>("label_inside", inside));
    scd->AddArray(make_array<vtkTypeInt32Array>("label_outside", outside));
    scd->AddArray(make_array<vtkUnsignedCharArray>("interface", interface));
  }
  vtkFieldData* fd = out->GetFieldData();
  add_field<vtkTypeInt64Array>(fd, "interior_vertices", double(b.interior_vertices));
  add_field<vtkTypeInt64Array>(fd, "boundary_vertices", double(b.boundary_vertices));
  add_field<vtkTypeInt64Array>(fd, "nonmanifold_vertices", double(b.nonmanifold_vertices));
  add_field<vtkTypeInt64Array>(fd, "unreferenced_vertices", double(b.unreferenced_vertices));
  add_field<vtkTypeInt64Array>(fd, "boundary_triangles", double(b.boundary_triangles));
  add_field<vtkTypeInt64Array>(fd, "boundary_tetrahedra", double(b.boundary_tetrahedra));
  std::string s = count_line(input) + ": " + std::to_string(b.boundary_vertices) + " boundary, " +
                  std::to_string(b.interior_vertices) + " interior, " +
                  std::to_string(b.nonmanifold_vertices) + " non-manifold vertices";
  if (surface != nullptr)
    s += "; surface of " + std::to_string(triangles.size()) + " triangles (" + std::to_string(interfaces) +
         " on interfaces)";
  return outcome(input, s);
}

// ---------------------------------------------------------------------------------------------
// Curvature and distortion
// ---------------------------------------------------------------------------------------------

namespace {

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

} // namespace

Outcome curvature(vtkUnstructuredGrid* in, vtkDataArray* field, vtkUnstructuredGrid* out, const Options& o) {
  const Grid_input input(in, o.labels);
  const std::vector<double> values = field_values(in, field);
  const Thread_scope threads(o.threads);
  const auto tree = make_octree(input, o, Numbering::VERTICES);
  Curvature_arrays a(input.number_of_vertices());
  const Progress p(o, 0.05, 1.0);
  const PSO::Vertex_type_counts c =
      PSO::compute_curvature(*tree, values.data(), Curvature_arrays::Map{&a}, params::progress(std::cref(p)));
  for (std::size_t v = 0; v < a.code.size(); ++v)
    if (a.code[v] > 1) a.distortion[v] = a.domain[v] = std::numeric_limits<double>::quiet_NaN();
  out->ShallowCopy(in);
  vtkPointData* pd = out->GetPointData();
  pd->AddArray(make_array<vtkUnsignedCharArray>("boundary", a.code));
  pd->AddArray(make_array<vtkDoubleArray>("distortion", a.distortion));
  pd->AddArray(make_array<vtkDoubleArray>("domain_curvature", a.domain));
  pd->SetActiveScalars("distortion");
  return outcome(input, count_line(input) + ": distortion of '" + (field ? Grid_input::name(field) : "z") +
                            "' at " + std::to_string(c.interior_vertices + c.boundary_vertices) +
                            " manifold vertices");
}

// ---------------------------------------------------------------------------------------------
// Validity
// ---------------------------------------------------------------------------------------------

Outcome validate(vtkUnstructuredGrid* in, vtkUnstructuredGrid* out, const Options& o) {
  const Grid_input input(in, o.labels);
  const Thread_scope threads(o.threads);
  const auto tree = make_octree(input, o, Numbering::VERTICES_AND_TETRAHEDRA);
  std::vector<PSO::Validity_problem> problems;
  const Progress p(o, 0.05, 1.0);
  const PSO::Validity_result r = PSO::check_validity(
      *tree, params::problems_output(std::back_inserter(problems)).progress(std::cref(p)));
  std::vector<std::uint8_t> cell(static_cast<std::size_t>(in->GetNumberOfCells()), 0);
  std::vector<std::uint8_t> point(input.number_of_vertices(), 0);
  using Kind = PSO::Validity_problem_kind;
  for (const auto& q : problems) {
    switch (q.kind) {
    case Kind::INVERTED_TETRAHEDRON:
      cell[std::size_t(input.cell(q.tetrahedron))] |= 1;
      break;
    case Kind::FLAT_TETRAHEDRON:
      cell[std::size_t(input.cell(q.tetrahedron))] |= 2;
      break;
    case Kind::NONMANIFOLD_TRIANGLE:
      for (std::size_t t : q.tetrahedra) cell[std::size_t(input.cell(t))] |= 4;
      for (int k = 0; k < 3; ++k) point[q.vertices[k]] |= 4;
      break;
    case Kind::NONMANIFOLD_VERTEX:
      point[q.vertices[0]] |= 1;
      break;
    case Kind::UNREFERENCED_VERTEX:
      point[q.vertices[0]] |= 2;
      break;
    }
  }
  out->ShallowCopy(in);
  out->GetCellData()->AddArray(make_array<vtkUnsignedCharArray>("problem", cell));
  out->GetPointData()->AddArray(make_array<vtkUnsignedCharArray>("problem", point));
  vtkFieldData* fd = out->GetFieldData();
  add_field<vtkTypeInt64Array>(fd, "valid", r.valid ? 1 : 0);
  add_field<vtkTypeInt64Array>(fd, "tetrahedra", double(r.tetrahedra));
  add_field<vtkTypeInt64Array>(fd, "inverted", double(r.inverted));
  add_field<vtkTypeInt64Array>(fd, "degenerate", double(r.degenerate));
  add_field<vtkTypeInt64Array>(fd, "nonmanifold_triangles", double(r.nonmanifold_triangles));
  add_field<vtkTypeInt64Array>(fd, "nonmanifold_vertices", double(r.nonmanifold_vertices));
  add_field<vtkTypeInt64Array>(fd, "unreferenced_vertices", double(r.unreferenced_vertices));
  add_field<vtkTypeInt64Array>(fd, "euler_characteristic", double(r.euler_characteristic));
  add_field<vtkTypeInt64Array>(fd, "boundary_triangles", double(r.boundary_triangles));
  add_field<vtkTypeInt64Array>(fd, "boundary_components", double(r.boundary_components));
  std::string s = count_line(input) + ": " + (r.valid ? "valid" : "NOT valid") + " (" +
                  std::to_string(r.inverted) + " inverted, " + std::to_string(r.degenerate) + " flat, " +
                  std::to_string(r.nonmanifold_triangles) + " non-manifold triangles, " +
                  std::to_string(r.nonmanifold_vertices) + " non-manifold vertices, " +
                  std::to_string(r.unreferenced_vertices) + " unreferenced vertices; Euler characteristic " +
                  std::to_string(r.euler_characteristic) + ", " + std::to_string(r.boundary_components) +
                  " boundary components)";
  return outcome(input, s);
}

// ---------------------------------------------------------------------------------------------
// The octree's leaves
// ---------------------------------------------------------------------------------------------

Outcome octree_leaves(vtkUnstructuredGrid* in, vtkUnstructuredGrid* out, const Options& o) {
  const Grid_input input(in, o.labels);
  const Thread_scope threads(o.threads);
  if (o.progress) o.progress(0.1);
  const auto tree = make_octree(input, o, Numbering::NONE);
  const std::size_t n = tree->number_of_leaves();
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  pts->SetNumberOfPoints(static_cast<vtkIdType>(8 * n));
  vtkNew<vtkCellArray> cells;
  std::vector<std::int64_t> depth(n), vertices(n), tetrahedra(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto leaf = tree->leaves()[i];
    const CGAL::Bbox_3 b = tree->node_bbox(leaf);
    vtkIdType ids[8];
    for (int c = 0; c < 8; ++c) { // VTK_VOXEL order: x fastest, then y, then z
      ids[c] = static_cast<vtkIdType>(8 * i + std::size_t(c));
      pts->SetPoint(ids[c], c & 1 ? b.xmax() : b.xmin(), c & 2 ? b.ymax() : b.ymin(),
                    c & 4 ? b.zmax() : b.zmin());
    }
    cells->InsertNextCell(8, ids);
    depth[i] = static_cast<std::int64_t>(tree->depth(leaf));
    vertices[i] = static_cast<std::int64_t>(tree->node(leaf).number_of_vertices());
    tetrahedra[i] = static_cast<std::int64_t>(tree->node(leaf).number_of_tetrahedra());
  }
  out->Initialize();
  out->SetPoints(pts);
  out->SetCells(VTK_VOXEL, cells);
  vtkCellData* cd = out->GetCellData();
  cd->AddArray(make_array<vtkTypeInt64Array>("depth", depth));
  cd->AddArray(make_array<vtkTypeInt64Array>("vertices", vertices));
  cd->AddArray(make_array<vtkTypeInt64Array>("tetrahedra", tetrahedra));
  cd->SetActiveScalars("tetrahedra");
  const PSO::Statistics s = tree->statistics();
  vtkFieldData* fd = out->GetFieldData();
  add_field<vtkTypeInt64Array>(fd, "vertices", double(s.vertices));
  add_field<vtkTypeInt64Array>(fd, "tetrahedra", double(s.tetrahedra));
  add_field<vtkTypeInt64Array>(fd, "kv", s.infinite_bucket_size ? -1. : double(s.bucket_size));
  add_field<vtkTypeInt64Array>(fd, "nodes", double(s.nodes));
  add_field<vtkTypeInt64Array>(fd, "leaves", double(s.leaves));
  add_field<vtkTypeInt64Array>(fd, "empty_leaves", double(s.empty_leaves));
  add_field<vtkTypeInt64Array>(fd, "depth", double(s.depth));
  add_field<vtkDoubleArray>(fd, "chi", s.chi);
  add_field<vtkTypeInt64Array>(fd, "max_leaf_vertices", double(s.max_leaf_vertices));
  add_field<vtkTypeInt64Array>(fd, "max_leaf_tetrahedra", double(s.max_leaf_tetrahedra));
  add_field<vtkTypeInt64Array>(fd, "bytes", double(s.bytes.total()));
  if (o.progress) o.progress(1.0);
  return outcome(input, count_line(input) + ": " + std::to_string(n) + " leaves, depth " +
                            std::to_string(s.depth) + ", chi " + std::to_string(s.chi));
}

// ---------------------------------------------------------------------------------------------
// Simplification
// ---------------------------------------------------------------------------------------------

namespace {

struct Constrained_map { // ReadablePropertyMap: input vertex -> bool
  using key_type = std::size_t;
  using value_type = bool;
  using reference = bool;
  using category = boost::readable_property_map_tag;
  const std::vector<char>* v;
  friend bool get(const Constrained_map& m, std::size_t i) { return (*m.v)[i] != 0; }
};

struct Progress_visitor : PSO::Simplification_visitor_base {
  const Progress* progress = nullptr;
  std::size_t input = 0, removed = 0, total = 1;
  void report(std::size_t r) {
    removed = (std::max)(removed, (std::min)(r, total));
    (*progress)(removed, total);
  }
  template <class CollapseProfile>
  void on_collapse(const CollapseProfile&) {
    (*progress)(removed, total);
  }
  void on_round_started(std::size_t, std::size_t, std::size_t tetrahedra) {
    report(input - (std::min)(tetrahedra, input));
  }
  void on_round_finished(std::size_t, std::size_t n) { report(removed + n); }
};

} // namespace

Outcome simplify(vtkUnstructuredGrid* in, const Simplify_options& s, vtkUnstructuredGrid* out,
                 const Options& o) {
  if (!(s.target > 0 && s.target < 1)) throw std::runtime_error("the target reduction must be in (0, 1)");
  const Grid_input input(in, o.labels, s.cells);
  if (input.number_of_tetrahedra() == 0) { // an empty piece under MPI, or no tetrahedra at all
    out->Initialize();
    return outcome(input, count_line(input) + ": nothing to simplify");
  }
  // the error bound: a percentage of the diagonal of the points' bounding box, as prstar simplify
  double bounds[6] = {0, 0, 0, 0, 0, 0};
  if (in->GetNumberOfPoints() > 0) in->GetPoints()->GetBounds(bounds); // all the points, as the CLI
  const double dx = bounds[1] - bounds[0], dy = bounds[3] - bounds[2], dz = bounds[5] - bounds[4];
  const double bound = s.max_error < 0 ? std::numeric_limits<double>::infinity()
                                       : s.max_error / 100 * std::sqrt(dx * dx + dy * dy + dz * dz);
  const Thread_scope threads(o.threads);
  const Progress p(o, 0.02, 1.0);
  Progress_visitor visitor;
  visitor.progress = &p;
  visitor.input = input.number_of_tetrahedra();
  visitor.total = (std::max<std::size_t>)(1, std::size_t(std::ceil(s.target * double(visitor.input))));
  const std::size_t kv = bucket_size_of(o);
  std::vector<char> none;
  const std::vector<char>& constrained = s.constrained != nullptr ? *s.constrained : none;
  if (s.constrained != nullptr && constrained.size() != input.number_of_vertices())
    throw std::runtime_error("internal: constrained vertices of the wrong size");
  PSO::Simplification_result<Point_3> res;
  try {
    auto np = params::target_fraction(s.target)
                  .bucket_size(kv)
                  .min_dihedral_angle(s.min_dihedral)
                  .max_dihedral_angle(s.max_dihedral)
                  .min_radius_ratio(s.min_radius_ratio)
                  .optimization_rounds(static_cast<std::size_t>((std::max)(0, s.optimize)))
                  .feature_angle(s.feature_angle)
                  .max_boundary_error(bound)
                  .collapse_priority(s.quadric ? PSO::Collapse_priority::QUADRIC_ERROR
                                               : PSO::Collapse_priority::EDGE_LENGTH)
                  .collapse_placement(s.optimal ? PSO::Collapse_placement::OPTIMAL
                                                : PSO::Collapse_placement::HALF_EDGE)
                  .visitor(std::ref(visitor));
    if (s.constrained != nullptr)
      res = PSO::simplify(input, np.vertex_is_constrained_map(Constrained_map{&constrained}));
    else
      res = PSO::simplify(input, np);
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(e.what());
  }
  const auto& mesh = res.mesh;
  const vtkIdType npts = set_tetrahedral_grid(mesh, out);
  // point and cell data of the input elements each output element stands for
  vtkPointData* pd = out->GetPointData();
  pd->CopyAllocate(in->GetPointData(), npts);
  for (std::size_t i = 0; i < res.input_vertex.size(); ++i)
    pd->CopyData(in->GetPointData(), static_cast<vtkIdType>(res.input_vertex[i]), static_cast<vtkIdType>(i));
  vtkCellData* cd = out->GetCellData();
  cd->CopyAllocate(in->GetCellData(), static_cast<vtkIdType>(mesh.tetrahedra.size()));
  for (std::size_t t = 0; t < res.input_tetrahedron.size(); ++t)
    cd->CopyData(in->GetCellData(), input.cell(res.input_tetrahedron[t]), static_cast<vtkIdType>(t));
  const auto& st = res.statistics;
  vtkFieldData* fd = out->GetFieldData();
  add_field<vtkTypeInt64Array>(fd, "input_tetrahedra", double(input.number_of_tetrahedra()));
  add_field<vtkTypeInt64Array>(fd, "output_tetrahedra", double(mesh.tetrahedra.size()));
  add_field<vtkTypeInt64Array>(fd, "rounds", double(st.rounds));
  add_field<vtkDoubleArray>(fd, "max_boundary_error", bound);
  const bool reached = st.stop == PSO::Simplification_stop::TARGET_REACHED;
  add_field<vtkTypeInt64Array>(fd, "target_reached", reached ? 1 : 0);
  const double removed = 1 - double(mesh.tetrahedra.size()) / double(input.number_of_tetrahedra());
  std::string line = count_line(input) + " -> " + std::to_string(mesh.tetrahedra.size()) + " (" +
                     std::to_string(int(std::lround(100 * removed))) + "% removed in " +
                     std::to_string(st.rounds) + " rounds)";
  if (!reached) line += "; stopped before the target: nothing more could be collapsed under the guards";
  return outcome(input, line);
}

// ---------------------------------------------------------------------------------------------
// Scalar-field topology
// ---------------------------------------------------------------------------------------------

namespace {

struct Type_map { // WritablePropertyMap: grid point -> TTK code
  using key_type = std::size_t;
  using value_type = PSO::Critical_type;
  using reference = value_type;
  using category = boost::writable_property_map_tag;
  std::int8_t* codes;
  friend void put(const Type_map& m, std::size_t v, PSO::Critical_type t) {
    m.codes[v] = static_cast<std::int8_t>(t);
  }
};

std::string field_name(vtkDataArray* field) {
  return field ? Grid_input::name(field) : "z";
}

} // namespace

Outcome critical_points(vtkUnstructuredGrid* in, vtkDataArray* field, vtkUnstructuredGrid* out,
                        vtkPolyData* points, const Options& o) {
  const Grid_input input(in, o.labels);
  const std::vector<double> values = field_values(in, field);
  const Thread_scope threads(o.threads);
  const auto tree = make_octree(input, o, Numbering::VERTICES);
  std::vector<std::int8_t> types(input.number_of_vertices(),
                                 static_cast<std::int8_t>(PSO::Critical_type::REGULAR));
  std::vector<PSO::Critical_point> critical;
  const Progress p(o, 0.05, 1.0);
  const auto map = CGAL::make_property_map(values);
  const PSO::Critical_point_counts c = PSO::compute_critical_points(
      *tree, map, Type_map{types.data()},
      params::critical_points_output(std::back_inserter(critical)).progress(std::cref(p)));
  out->ShallowCopy(in);
  out->GetPointData()->AddArray(make_array<vtkSignedCharArray>("critical_type", types));
  const std::size_t k = critical.size();
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  pts->SetNumberOfPoints(static_cast<vtkIdType>(k));
  vtkNew<vtkCellArray> verts;
  std::vector<std::int64_t> vertex(k);
  std::vector<std::int8_t> type(k);
  std::vector<double> value(k);
  std::vector<std::int32_t> lower(k), upper(k);
  std::vector<std::uint8_t> on_boundary(k);
  for (std::size_t i = 0; i < k; ++i) {
    const auto& q = critical[i];
    double x[3];
    in->GetPoint(static_cast<vtkIdType>(q.vertex), x);
    pts->SetPoint(static_cast<vtkIdType>(i), x);
    const vtkIdType id = static_cast<vtkIdType>(i);
    verts->InsertNextCell(1, &id);
    vertex[i] = static_cast<std::int64_t>(q.vertex);
    type[i] = static_cast<std::int8_t>(q.type);
    value[i] = q.value;
    lower[i] = static_cast<std::int32_t>(q.lower_components);
    upper[i] = static_cast<std::int32_t>(q.upper_components);
    on_boundary[i] = q.on_boundary ? 1 : 0;
  }
  points->Initialize();
  points->SetPoints(pts);
  points->SetVerts(verts);
  vtkPointData* pd = points->GetPointData();
  pd->AddArray(make_array<vtkTypeInt64Array>("vertex", vertex));
  pd->AddArray(make_array<vtkSignedCharArray>("critical_type", type));
  pd->AddArray(make_array<vtkDoubleArray>("value", value));
  pd->AddArray(make_array<vtkTypeInt32Array>("lower_components", lower));
  pd->AddArray(make_array<vtkTypeInt32Array>("upper_components", upper));
  pd->AddArray(make_array<vtkUnsignedCharArray>("on_boundary", on_boundary));
  pd->SetActiveScalars("critical_type");
  vtkFieldData* fd = out->GetFieldData();
  add_field<vtkTypeInt64Array>(fd, "minima", double(c.minima));
  add_field<vtkTypeInt64Array>(fd, "saddles_1", double(c.saddles_1));
  add_field<vtkTypeInt64Array>(fd, "saddles_2", double(c.saddles_2));
  add_field<vtkTypeInt64Array>(fd, "maxima", double(c.maxima));
  add_field<vtkTypeInt64Array>(fd, "degenerate", double(c.degenerate));
  return outcome(input, count_line(input) + ": critical points of '" + field_name(field) +
                            "': " + std::to_string(c.minima) + " minima, " + std::to_string(c.saddles_1) +
                            " 1-saddles, " + std::to_string(c.saddles_2) + " 2-saddles, " +
                            std::to_string(c.maxima) + " maxima, " + std::to_string(c.degenerate) +
                            " degenerate");
}

Outcome morse_segmentation(vtkUnstructuredGrid* in, vtkDataArray* field, double persistence,
                           vtkUnstructuredGrid* out, const Options& o) {
  if (!(persistence >= 0 && persistence <= 1))
    throw std::runtime_error("the persistence threshold must be a fraction of the field's range in [0, 1]");
  const Grid_input input(in, o.labels);
  const std::vector<double> values = field_values(in, field);
  const Thread_scope threads(o.threads);
  const auto tree = make_octree(input, o, Numbering::VERTICES_AND_TETRAHEDRA);
  // the field's range over the vertices of the tetrahedra: the base of the threshold (as prstar morse)
  std::vector<char> referenced(values.size(), 0);
  for (std::size_t t = 0; t < input.number_of_tetrahedra(); ++t)
    for (long long v : input.tetrahedron(t)) referenced[std::size_t(v)] = 1;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (std::size_t v = 0; v < values.size(); ++v)
    if (referenced[v]) lo = (std::min)(lo, values[v]), hi = (std::max)(hi, values[v]);
  const double threshold = hi >= lo ? persistence * (hi - lo) : 0;
  const Progress p(o, 0.05, 1.0);
  const auto map = CGAL::make_property_map(values);
  const auto m = PSO::compute_morse_complexes(
      *tree, map, params::persistence_threshold(threshold).progress(std::cref(p)));
  const std::size_t nv = input.number_of_vertices();
  constexpr std::size_t no_cell = PSO::Morse_complexes<Octree>::no_cell;
  std::vector<std::int64_t> ascending(nv);
  std::vector<std::int8_t> types(nv);
  for (std::size_t v = 0; v < nv; ++v) {
    ascending[v] = m.ascending_cell[v] == no_cell ? -1 : static_cast<std::int64_t>(m.ascending_cell[v]);
    types[v] = static_cast<std::int8_t>(m.critical_type[v]);
  }
  std::vector<std::int64_t> descending(static_cast<std::size_t>(in->GetNumberOfCells()), -1);
  for (std::size_t t = 0; t < input.number_of_tetrahedra(); ++t)
    descending[std::size_t(input.cell(t))] =
        m.descending_cell[t] == no_cell ? -1 : static_cast<std::int64_t>(m.descending_cell[t]);
  out->ShallowCopy(in);
  out->GetPointData()->AddArray(make_array<vtkTypeInt64Array>("ascending_cell", ascending));
  out->GetPointData()->AddArray(make_array<vtkSignedCharArray>("critical_type", types));
  out->GetCellData()->AddArray(make_array<vtkTypeInt64Array>("descending_cell", descending));
  vtkFieldData* fd = out->GetFieldData();
  add_field<vtkDoubleArray>(fd, "persistence_threshold", threshold);
  add_field<vtkTypeInt64Array>(fd, "ascending_cells", double(m.ascending_cells));
  add_field<vtkTypeInt64Array>(fd, "descending_cells", double(m.descending_cells));
  return outcome(input, count_line(input) + ": Morse segmentation of '" + field_name(field) +
                            "' at persistence " + std::to_string(threshold) + ": " +
                            std::to_string(m.ascending_cells) + " ascending cells, " +
                            std::to_string(m.descending_cells) + " descending cells");
}

// ---------------------------------------------------------------------------------------------
// Reading
// ---------------------------------------------------------------------------------------------

std::string readable_extensions() {
  return PSO::IO::readable_extensions();
}

Outcome read(const std::string& file, vtkUnstructuredGrid* out) {
  PSO::Indexed_tetrahedral_mesh<> mesh;
  PSO::IO::read_tetrahedral_mesh(file, mesh); // Read_error (a std::runtime_error) names file and line
  set_tetrahedral_grid(mesh, out);
  for (const auto& a : mesh.point_data)
    out->GetPointData()->AddArray(make_array<vtkDoubleArray>(a.name.c_str(), a.values));
  for (const auto& a : mesh.cell_data)
    out->GetCellData()->AddArray(make_array<vtkDoubleArray>(a.name.c_str(), a.values));
  if (!mesh.tetrahedron_labels.empty()) {
    std::vector<std::int32_t> labels(mesh.tetrahedron_labels.begin(), mesh.tetrahedron_labels.end());
    out->GetCellData()->AddArray(make_array<vtkTypeInt32Array>("label", labels));
    out->GetCellData()->SetActiveScalars("label");
  }
  if (!mesh.label_names.empty()) {
    vtkNew<vtkTypeInt32Array> ids;
    ids->SetName("label_ids");
    vtkNew<vtkStringArray> names;
    names->SetName("label_names");
    for (const auto& [id, name] : mesh.label_names) {
      ids->InsertNextValue(id);
      names->InsertNextValue(name);
    }
    out->GetFieldData()->AddArray(ids);
    out->GetFieldData()->AddArray(names);
  }
  if (!mesh.point_data.empty()) out->GetPointData()->SetActiveScalars(mesh.point_data.front().name.c_str());
  Outcome r;
  r.tetrahedra = mesh.tetrahedra.size();
  r.summary = file + ": " + std::to_string(mesh.points.size()) + " vertices, " +
              std::to_string(mesh.tetrahedra.size()) + " tetrahedra";
  if (!mesh.tetrahedron_labels.empty()) r.summary += ", labels";
  for (const auto& [type, count] : mesh.skipped_cells) {
    r.summary += "; skipped " + std::to_string(count) + " " + type + " cells";
    r.other_cells += count;
  }
  return r;
}

} // namespace prstar_paraview
