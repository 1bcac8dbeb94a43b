// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_IO_INTERNAL_XDMF_READER_H
#define CGAL_PR_STAR_OCTREE_IO_INTERNAL_XDMF_READER_H

// The XDMF (2 and 3) reader: the light data (XML) with the package's parser, the heavy data inline
// (Format="XML") or in HDF5 files (Format="HDF", xdmf_hdf5.h), the grid, topology (Tetrahedron or
// Mixed), geometry (XYZ) and scalar attributes of one grid into an Indexed_tetrahedral_mesh.

#include <CGAL/PR_star_octree/IO/Memory_limit.h>
#include <CGAL/PR_star_octree/IO/Read_error.h>
#include <CGAL/PR_star_octree/IO/internal/text.h>
#include <CGAL/PR_star_octree/IO/internal/vtk_cells.h>
#include <CGAL/PR_star_octree/IO/internal/xdmf_hdf5.h>
#include <CGAL/PR_star_octree/IO/internal/xml.h>
#include <CGAL/PR_star_octree/Indexed_tetrahedral_mesh.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <limits>
#include <map>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace PR_star_octree {
namespace IO {
namespace internal {
#ifdef CGAL_PR_STAR_OCTREE_USE_HDF5
inline namespace xdmf_with_hdf5 {
#else
inline namespace xdmf_without_hdf5 {
#endif

/// Cell attributes read as tetrahedron labels (the first integer-typed one whose values are all
/// `int`s): the names of the VTK readers (`label`, `CellEntityIds`, `gmsh:physical`, `medit:ref`...)
/// and `name_to_read`, the name meshio's and FEniCS's tutorials give the subdomain markers.
inline bool is_xdmf_label_name(const std::string& name) {
  return is_vtk_label_array_name(name) || name == "name_to_read";
}

/// The cells of an XDMF `Mixed` topology: the number of vertices of type `t` (0: its count follows
/// the type, as for poly-vertices, poly-lines and polygons; -1: a polyhedron, faces follow; -2:
/// unknown) and its name (as the VTK readers name them, for `skipped_cells`).
inline int xdmf_mixed_nodes(long long t) {
  switch (t) {
  case 1:
  case 2:
  case 3:
    return 0;
  case 4:
    return 3;
  case 5:
  case 6:
    return 4;
  case 7:
    return 5;
  case 8:
    return 6;
  case 9:
    return 8;
  case 16:
    return -1;
  case 34:
    return 3;
  case 35:
    return 9;
  case 36:
    return 6;
  case 37:
    return 8;
  case 38:
    return 10;
  case 39:
    return 13;
  case 40:
    return 15;
  case 41:
    return 18;
  case 48:
    return 20;
  case 49:
    return 24;
  case 50:
    return 27;
  default:
    return -2;
  }
}

inline const char* xdmf_mixed_name(long long t) {
  switch (t) {
  case 1:
    return "poly-vertex";
  case 2:
    return "poly-line";
  case 3:
    return "polygon";
  case 4:
    return "triangle";
  case 5:
    return "quad";
  case 6:
    return "tetrahedron";
  case 7:
    return "pyramid";
  case 8:
    return "wedge";
  case 9:
    return "hexahedron";
  case 16:
    return "polyhedron";
  case 34:
    return "quadratic edge";
  case 35:
    return "biquadratic quad";
  case 36:
    return "quadratic triangle";
  case 37:
    return "quadratic quad";
  case 38:
    return "quadratic tetrahedron";
  case 39:
    return "quadratic pyramid";
  case 40:
    return "quadratic wedge";
  case 41:
    return "biquadratic wedge";
  case 48:
    return "quadratic hexahedron";
  case 49:
    return "hexahedron of 24 nodes";
  case 50:
    return "triquadratic hexahedron";
  default:
    return "unknown cell type";
  }
}

/// A `<DataItem>`: where its values are and what they are.
struct Xdmf_item {
  const Xml_element* element = nullptr;
  bool has_dims = false;
  std::vector<unsigned long long> dims; ///< `Dimensions`
  Xdmf_number_kind kind = Xdmf_number_kind::FLOAT;
  std::size_t precision = 0; ///< bytes per value: `Precision` inline (0 when absent), the dataset's for HDF
  bool hdf = false;
  std::string h5_file, dataset, reference; ///< for HDF: the file (resolved), the path, the text
  unsigned long long announced = 0;        ///< the number of values: `Dimensions`, or the dataset's

  unsigned long long dims_count() const {
    unsigned long long n = 1;
    for (unsigned long long d : dims) n = (d != 0 && n > (~0ull) / d) ? ~0ull : n * d;
    return n;
  }
};

template <class Mesh>
class Xdmf_reader {
public:
  using Point_3 = typename Mesh::Point_3;
  using Index = typename Mesh::Index;
  using Tetrahedron = typename Mesh::Tetrahedron;

  /// `folder`: the folder of the `.xdmf` file, against which relative `.h5` names are resolved;
  /// `stream`: reading a stream (HDF5 references refused).
  Xdmf_reader(std::string_view text, const std::string& name, const std::string& folder, bool stream)
      : doc_(text, name), name_(name), folder_(folder), stream_(stream), h5_(name) {}

  void read(Mesh& result) {
    const Xml_element& root = doc_.root();
    if (root.name != "Xdmf")
      fail(root, "not an XDMF file: the root element is <" + std::string(root.name) + ">, not <Xdmf>");
    const Xml_element* domain = first_child(root, "Domain");
    if (domain == nullptr) fail(root, "<Xdmf> without a <Domain>");
    const Xml_element* grid = first_child(*domain, "Grid");
    if (grid == nullptr) fail(*domain, "<Domain> without a <Grid>");
    // a Collection (Temporal, Spatial) or a Tree: its first grid, recursively
    for (int depth = 0;; ++depth) {
      const std::string* type = grid->attribute("GridType");
      if (type == nullptr || iequals(*type, "Uniform")) break;
      if (iequals(*type, "Collection") || iequals(*type, "Tree")) {
        const Xml_element* inner = first_child(*grid, "Grid");
        if (inner == nullptr) fail(*grid, "<Grid GridType=\"" + *type + "\"> without a <Grid> inside");
        if (depth > 64) fail(*grid, "grids nested too deeply");
        grid = inner;
        continue;
      }
      fail(*grid, "GridType '" + *type + "' is not supported (Uniform, or a Collection of Uniform grids)");
    }
    const Xml_element* topology = first_child(*grid, "Topology");
    const Xml_element* geometry = first_child(*grid, "Geometry");
    if (topology == nullptr || geometry == nullptr) {
      // meshio's and DOLFINx's time series: <xi:include xpointer="...Grid[@Name='mesh']..."/>, the
      // topology and geometry of another grid of the domain
      const Xml_element* source = included_grid(*domain, *grid);
      if (source != nullptr) {
        if (topology == nullptr) topology = first_child(*source, "Topology");
        if (geometry == nullptr) geometry = first_child(*source, "Geometry");
      }
    }
    if (topology == nullptr) fail(*grid, "<Grid> without a <Topology>");
    if (geometry == nullptr) fail(*grid, "<Grid> without a <Geometry>");
    for (const Xml_element* e : {topology, geometry})
      if (e->attribute("Reference") != nullptr)
        fail(*e, "<" + std::string(e->name) + " Reference=...> is not supported");

    // the geometry
    const std::string* gtype = geometry->attribute("GeometryType");
    if (gtype == nullptr) gtype = geometry->attribute("Type");
    if (gtype != nullptr && !iequals(*gtype, "XYZ")) {
      if (iequals(*gtype, "XY"))
        fail(*geometry, "GeometryType 'XY': two-dimensional points, not a tetrahedral mesh in 3D (XYZ only)");
      fail(*geometry, "GeometryType '" + *gtype + "' is not supported (XYZ only)");
    }
    const Xdmf_item gitem = item(*geometry, "the geometry");
    if (gitem.has_dims && gitem.dims.size() >= 2 && gitem.dims.back() != 3)
      fail(*gitem.element, "the geometry has " + std::to_string(gitem.dims.back()) +
                               " coordinates per point (Dimensions), 3 expected");
    if (gitem.announced % 3 != 0)
      fail(*gitem.element,
           "the geometry has " + std::to_string(gitem.announced) + " values, not a multiple of 3 (XYZ)");
    const unsigned long long nv = gitem.announced / 3;
    if (nv > max_vertices<Index>())
      fail(*gitem.element, "the points do not fit in the index type of the mesh");

    // the topology
    const std::string* ttype = topology->attribute("TopologyType");
    if (ttype == nullptr) ttype = topology->attribute("Type");
    if (ttype == nullptr) fail(*topology, "<Topology> without a TopologyType");
    const bool mixed = iequals(*ttype, "Mixed");
    if (!mixed && !iequals(*ttype, "Tetrahedron"))
      fail(*topology,
           "TopologyType '" + *ttype + "' is not a tetrahedral mesh (Tetrahedron, or Mixed with tetrahedra)");
    const unsigned long long ne_attribute = count_attribute(*topology, "NumberOfElements");
    const bool has_ne = topology->attribute("NumberOfElements") != nullptr;
    if (!mixed) {
      if (const std::string* npe = topology->attribute("NodesPerElement"))
        if (trim(*npe) != "4")
          fail(*topology, "a Tetrahedron topology with NodesPerElement=\"" + *npe + "\" (4 expected)");
    }
    const long long base = static_cast<long long>(count_attribute(*topology, "BaseOffset"));
    const Xdmf_item titem = item(*topology, "the topology");
    if (titem.kind == Xdmf_number_kind::FLOAT)
      fail(*titem.element, "the topology has floating-point values (an integer type is needed)");
    unsigned long long nc = 0; // cells (tetrahedra for a Tetrahedron topology)
    if (!mixed) {
      if (titem.announced % 4 != 0)
        fail(*titem.element, "the topology has " + std::to_string(titem.announced) +
                                 " values, not a multiple of 4 (tetrahedra)");
      nc = titem.announced / 4;
      if (has_ne && ne_attribute != nc)
        fail(*topology, "NumberOfElements=\"" + std::to_string(ne_attribute) + "\" but the data hold " +
                            std::to_string(titem.announced) + " values (" + std::to_string(nc) +
                            " tetrahedra)");
    } else {
      nc = has_ne ? ne_attribute : titem.announced / 5;
    }

    // the attributes: which ones, and their items
    struct Attribute {
      std::string name;
      bool cell;
      Xdmf_item data;
    };
    std::vector<Attribute> attributes;
    std::size_t node_arrays = 0, cell_arrays = 0;
    for (std::size_t c : grid->children) {
      const Xml_element& a = doc_.element(c);
      if (a.name != "Attribute") continue;
      const std::string* center = a.attribute("Center");
      const std::string* atype = a.attribute("AttributeType");
      if (atype == nullptr) atype = a.attribute("Type");
      if (atype != nullptr && !iequals(*atype, "Scalar")) continue; // vectors, tensors: not scalar fields
      const bool node = center == nullptr || iequals(*center, "Node");
      const bool cell = center != nullptr && iequals(*center, "Cell");
      if (!node && !cell) continue; // Grid, Face, Edge centers
      const std::string* n = a.attribute("Name");
      Attribute at{n != nullptr ? *n
                                : (cell ? "cell_data_" + std::to_string(cell_arrays)
                                        : "point_data_" + std::to_string(node_arrays)),
                   cell, item(a, "attribute")};
      (cell ? cell_arrays : node_arrays) += 1;
      attributes.push_back(std::move(at));
    }

    // the memory: announced sizes checked before anything big is allocated (inline values are
    // bounded by the text, and counted against it first)
    bool announced_by_file = gitem.hdf || titem.hdf;
    if (announced_by_file || 2 * (gitem.announced + titem.announced) <= doc_.text().size() + 2)
      // (a Mixed topology is held whole while it is read: 5 values of 8 bytes per tetrahedron)
      check_memory(name_, geometry->line, nv, nc, sizeof(Point_3), sizeof(Tetrahedron) + 1 + (mixed ? 40 : 0),
                   node_arrays, cell_arrays);

    Mesh mesh;
    // points
    {
      mesh.points.reserve(static_cast<std::size_t>(
          gitem.hdf ? nv : std::min<unsigned long long>(nv, doc_.text().size() / 6 + 1)));
      double xyz[3];
      int k = 0;
      std::size_t index = 0;
      values<double>(gitem, gitem.announced, "the geometry", [&](const double* v, std::size_t n) {
        for (std::size_t i = 0; i < n; ++i) {
          if (!std::isfinite(v[i]))
            fail(*gitem.element, "point " + std::to_string(index) + " has a non-finite coordinate");
          xyz[k++] = v[i];
          if (k == 3) {
            mesh.points.emplace_back(xyz[0], xyz[1], xyz[2]);
            k = 0;
            ++index;
          }
        }
      });
      // 32-bit floats: an HDF5 dataset of them, or inline numbers of Precision="4" (then rounded to
      // the nearest floats, unless one is beyond their range: read as doubles)
      bool float32 = gitem.kind == Xdmf_number_kind::FLOAT && gitem.precision == 4;
      if (float32 && !gitem.hdf) float32 = round_points_to_float(mesh.points, 0);
      set_float32_points(mesh, float32);
    }

    // cells
    std::vector<char> kept; // for a Mixed topology: which cells are tetrahedra
    if (!mixed) {
      mesh.tetrahedra.reserve(static_cast<std::size_t>(
          titem.hdf ? nc : std::min<unsigned long long>(nc, doc_.text().size() / 8 + 1)));
      Tetrahedron t{};
      std::size_t k = 0, cell = 0;
      values<long long>(titem, titem.announced, "the topology", [&](const long long* v, std::size_t n) {
        for (std::size_t i = 0; i < n; ++i) {
          t[k] = vertex(*titem.element, cell, v[i], base, nv);
          if (++k == 4) {
            check_repeated(*titem.element, cell, t, base);
            mesh.tetrahedra.push_back(t);
            k = 0;
            ++cell;
          }
        }
      });
    } else {
      std::vector<long long> list;
      values<long long>(titem, titem.announced, "the topology",
                        [&](const long long* v, std::size_t n) { list.insert(list.end(), v, v + n); });
      std::size_t p = 0, cell = 0;
      const auto next = [&](const char* what) {
        if (p >= list.size())
          fail(*titem.element,
               "the Mixed topology ends inside cell " + std::to_string(cell) + " (" + what + ")");
        return list[p++];
      };
      while (p < list.size()) {
        const long long type = next("type");
        const int nodes = xdmf_mixed_nodes(type);
        if (nodes == -2)
          fail(*titem.element,
               "cell " + std::to_string(cell) + ": unknown XDMF cell type " + std::to_string(type));
        if (type == 6) {
          Tetrahedron t{};
          for (int k = 0; k < 4; ++k) t[k] = vertex(*titem.element, cell, next("vertex"), base, nv);
          check_repeated(*titem.element, cell, t, base);
          mesh.tetrahedra.push_back(t);
          kept.push_back(1);
        } else {
          long long skip = nodes;
          if (nodes == 0) {
            skip = next("number of vertices");
          } else if (nodes == -1) { // polyhedron: faces, each a count then its vertices
            const long long faces = next("number of faces");
            if (faces < 0 || static_cast<unsigned long long>(faces) > list.size())
              fail(*titem.element,
                   "cell " + std::to_string(cell) + ": invalid number of faces " + std::to_string(faces));
            skip = 0;
            for (long long f = 0; f < faces; ++f) {
              const long long m = next("face size");
              if (m < 0 || static_cast<unsigned long long>(m) > list.size() - p)
                fail(*titem.element,
                     "cell " + std::to_string(cell) + ": invalid face size " + std::to_string(m));
              p += static_cast<std::size_t>(m);
            }
          }
          if (skip < 0 || static_cast<unsigned long long>(skip) > list.size() - p)
            fail(*titem.element, "the Mixed topology ends inside cell " + std::to_string(cell) + " (" +
                                     xdmf_mixed_name(type) + ")");
          p += static_cast<std::size_t>(skip);
          ++mesh.skipped_cells[xdmf_mixed_name(type)];
          kept.push_back(0);
        }
        ++cell;
      }
      if (has_ne && cell != ne_attribute)
        fail(*topology, "NumberOfElements=\"" + std::to_string(ne_attribute) +
                            "\" but the Mixed topology holds " + std::to_string(cell) + " cells");
      if (cell > 0 && mesh.tetrahedra.empty())
        fail(*topology, "no tetrahedron among the " + std::to_string(cell) +
                            " cells of the Mixed topology (XDMF type 6), not a tetrahedral mesh");
      nc = cell;
      bool all = true;
      for (char c : kept) all = all && c;
      if (all) kept.clear();
    }

    // attributes
    bool has_labels = false;
    for (const Attribute& a : attributes) {
      const unsigned long long expected = a.cell ? nc : nv;
      std::vector<double> v;
      v.reserve(static_cast<std::size_t>(
          std::min<unsigned long long>(expected, a.data.hdf ? expected : doc_.text().size() / 2 + 1)));
      values<double>(a.data, expected, ("attribute " + quote(a.name)).c_str(),
                     [&](const double* x, std::size_t n) { v.insert(v.end(), x, x + n); });
      if (!a.cell) {
        for (const Data_array& d : mesh.point_data)
          if (d.name == a.name) fail(*a.data.element, "two point attributes are named " + quote(a.name));
        mesh.point_data.push_back(Data_array{a.name, std::move(v)});
        continue;
      }
      vtk_keep_cells(v, kept);
      if (!has_labels && a.data.kind != Xdmf_number_kind::FLOAT && is_xdmf_label_name(a.name) &&
          vtk_integer_valued(v)) {
        has_labels = true;
        mesh.tetrahedron_labels.reserve(v.size());
        for (double x : v) mesh.tetrahedron_labels.push_back(static_cast<int>(x));
        continue;
      }
      for (const Data_array& d : mesh.cell_data)
        if (d.name == a.name) fail(*a.data.element, "two cell attributes are named " + quote(a.name));
      mesh.cell_data.push_back(Data_array{a.name, std::move(v)});
    }
    result = std::move(mesh);
  }

private:
  [[noreturn]] void fail(const Xml_element& e, const std::string& message) const {
    throw Read_error(name_, e.line, message);
  }

  const Xml_element* first_child(const Xml_element& e, std::string_view name) const {
    for (std::size_t c : e.children)
      if (doc_.element(c).name == name) return &doc_.element(c);
    return nullptr;
  }

  /// The grid whose topology and geometry an `<xi:include>` of `grid` takes: the grid named in its
  /// xpointer (`Grid[@Name="mesh"]`), else the first Uniform grid of the domain with both.
  const Xml_element* included_grid(const Xml_element& domain, const Xml_element& grid) const {
    std::string wanted;
    bool include = false;
    for (std::size_t c : grid.children) {
      const Xml_element& e = doc_.element(c);
      const std::string_view n = e.name;
      if (n != "include" && (n.size() < 8 || n.substr(n.size() - 8) != ":include")) continue;
      include = true;
      if (const std::string* x = e.attribute("xpointer")) {
        const std::size_t at = x->find("@Name=");
        if (at != std::string::npos && at + 7 < x->size()) {
          const char q = (*x)[at + 6];
          const std::size_t end = x->find(q, at + 7);
          if (end != std::string::npos) wanted = x->substr(at + 7, end - at - 7);
        }
      }
    }
    if (!include) return nullptr;
    for (std::size_t c : domain.children) {
      const Xml_element& g = doc_.element(c);
      if (g.name != "Grid" || &g == &grid) continue;
      const std::string* n = g.attribute("Name");
      if (!wanted.empty() && (n == nullptr || *n != wanted)) continue;
      if (first_child(g, "Topology") != nullptr && first_child(g, "Geometry") != nullptr) return &g;
    }
    return nullptr;
  }

  /// A non-negative integer attribute (0 when absent).
  unsigned long long count_attribute(const Xml_element& e, const char* key) const {
    const std::string* v = e.attribute(key);
    if (v == nullptr) return 0;
    long long n = 0;
    if (parse_integer(trim(*v), n) != nullptr || n < 0)
      fail(e, std::string("invalid ") + key + " '" + *v + "'");
    return static_cast<unsigned long long>(n);
  }

  /// The `<DataItem>` of `parent` (`what` names it in messages), parsed and, for HDF5 data, located.
  Xdmf_item item(const Xml_element& parent, const char* what) {
    std::vector<const Xml_element*> items;
    for (std::size_t c : parent.children)
      if (doc_.element(c).name == "DataItem") items.push_back(&doc_.element(c));
    if (items.size() != 1)
      fail(parent, std::string(what) + ": <" + std::string(parent.name) +
                       "> must hold one <DataItem>, found " + std::to_string(items.size()));
    const Xml_element& e = *items.front();
    Xdmf_item r;
    r.element = &e;
    if (e.attribute("Reference") != nullptr)
      fail(e, std::string(what) + ": <DataItem Reference=...> is not supported");
    if (const std::string* it = e.attribute("ItemType"))
      if (!iequals(*it, "Uniform"))
        fail(e, std::string(what) + ": DataItem ItemType '" + *it + "' is not supported (Uniform only)");
    const std::string* type = e.attribute("NumberType");
    if (type == nullptr) type = e.attribute("DataType");
    if (type == nullptr || iequals(*type, "Float"))
      r.kind = Xdmf_number_kind::FLOAT;
    else if (iequals(*type, "Int") || iequals(*type, "Char"))
      r.kind = Xdmf_number_kind::INT;
    else if (iequals(*type, "UInt") || iequals(*type, "UChar"))
      r.kind = Xdmf_number_kind::UINT;
    else
      fail(e, std::string(what) + ": unknown NumberType '" + *type + "' (Float, Int, UInt, Char, UChar)");
    if (const std::string* p = e.attribute("Precision")) {
      const std::string_view t = trim(*p);
      if (t != "1" && t != "2" && t != "4" && t != "8")
        fail(e, std::string(what) + ": invalid Precision '" + *p + "' (1, 2, 4 or 8)");
      r.precision = static_cast<std::size_t>(t[0] - '0');
    }
    if (const std::string* d = e.attribute("Dimensions")) {
      r.has_dims = true;
      std::string_view s = *d;
      while (true) {
        s = trim(s);
        if (s.empty()) break;
        std::size_t k = 0;
        while (k < s.size() && !is_space(s[k])) ++k;
        long long x = 0;
        if (parse_integer(s.substr(0, k), x) != nullptr || x < 0)
          fail(e, std::string(what) + ": invalid Dimensions '" + *d + "'");
        r.dims.push_back(static_cast<unsigned long long>(x));
        s.remove_prefix(k);
      }
      if (r.dims.empty() || r.dims.size() > 8)
        fail(e, std::string(what) + ": invalid Dimensions '" + *d + "'");
      r.announced = r.dims_count();
      if (r.announced == ~0ull) fail(e, std::string(what) + ": Dimensions '" + *d + "' overflow");
    }
    const std::string* format = e.attribute("Format");
    if (format == nullptr || iequals(*format, "XML")) {
      if (!r.has_dims) { // the values present
        r.announced = 0;
        for_each_token(e, [&](std::string_view, std::size_t) { ++r.announced; });
      }
      return r;
    }
    if (!iequals(*format, "HDF"))
      fail(e, std::string(what) + ": DataItem Format '" + *format + "' is not supported (XML or HDF)");
    r.hdf = true;
    std::string storage;
    const std::string_view ref = trim(doc_.element_text(e, storage));
    r.reference = std::string(ref);
    // FILE:/path, or FILE:path (some writers leave the first '/' out)
    std::size_t colon = ref.find(":/");
    if (colon == std::string_view::npos) colon = ref.rfind(':');
    if (colon == std::string_view::npos || colon == 0 || colon + 1 == ref.size())
      fail(e, std::string(what) + ": the HDF5 reference " + quote(ref) + " is not FILE.h5:/path/to/dataset");
    if (stream_)
      fail(e, std::string(what) + ": the values are in the HDF5 file '" + std::string(ref.substr(0, colon)) +
                  "', which cannot be read from a stream (read the .xdmf file by its name)");
    const std::filesystem::path h5(std::string(ref.substr(0, colon)));
    r.h5_file =
        h5.is_absolute() || folder_.empty() ? h5.string() : (std::filesystem::path(folder_) / h5).string();
    r.dataset = std::string(ref.substr(colon + 1));
    if (r.dataset[0] != '/') r.dataset.insert(r.dataset.begin(), '/');
    if (!xdmf_hdf5_available()) throw Read_error(name_, 0, xdmf_no_hdf5_message());
    const Xdmf_h5_info info = h5_.info(r.h5_file, r.dataset, r.reference, e.line);
    r.kind = info.kind;
    r.precision = info.size;
    const unsigned long long n = info.count();
    if (r.has_dims && n != r.announced) {
      std::string shape;
      for (unsigned long long x : info.dims) shape += (shape.empty() ? "" : " x ") + std::to_string(x);
      fail(e, std::string(what) + ": the dataset " + r.reference + " has dimensions " +
                  (shape.empty() ? std::string("(scalar)") : shape) + " (" + std::to_string(n) +
                  " values), Dimensions=\"" + *e.attribute("Dimensions") + "\" announces " +
                  std::to_string(r.announced));
    }
    r.dims = info.dims;
    r.announced = n;
    return r;
  }

  /// Calls `f(token, offset)` for each blank-separated token of the text of `e`.
  template <class F>
  void for_each_token(const Xml_element& e, const F& f) const {
    const std::string_view text = doc_.text();
    for (const auto& part : e.text_parts) {
      std::size_t p = part.first;
      while (p < part.second) {
        while (p < part.second && is_space(text[p])) ++p;
        const std::size_t b = p;
        while (p < part.second && !is_space(text[p])) ++p;
        if (p > b) f(text.substr(b, p - b), b);
      }
    }
  }

  /// Reads the values of an item as `T` (double or long long), `expected` of them, handed to `sink`
  /// in chunks.
  template <class T>
  void values(const Xdmf_item& it, unsigned long long expected, const char* what,
              const std::function<void(const T*, std::size_t)>& sink) {
    const Xml_element& e = *it.element;
    if (std::is_integral<T>::value && it.kind == Xdmf_number_kind::FLOAT)
      fail(e, std::string(what) + " has floating-point values (an integer type is needed)");
    if (it.announced != expected)
      fail(e, std::string(what) + ": " + std::to_string(it.announced) + " values, " +
                  std::to_string(expected) + " expected");
    if (it.hdf) {
      unsigned long long got = 0;
      h5_.template read<T>(it.h5_file, it.dataset, it.reference, e.line, [&](const T* v, std::size_t n) {
        got += n;
        sink(v, n);
      });
      if (got != expected)
        fail(e, std::string(what) + ": " + std::to_string(got) + " values read, " + std::to_string(expected) +
                    " expected");
      return;
    }
    std::vector<T> chunk;
    chunk.reserve(8192);
    unsigned long long count = 0;
    for_each_token(e, [&](std::string_view tok, std::size_t offset) {
      if (count == expected)
        throw Read_error(name_, doc_.line_of(offset),
                         std::string(what) + ": more values than the " + std::to_string(expected) +
                             " expected");
      T v{};
      const char* why;
      if constexpr (std::is_integral<T>::value) {
        long long x = 0;
        why = parse_integer(tok, x);
        v = x;
      } else {
        why = parse_double(tok, v);
      }
      if (why != nullptr)
        throw Read_error(name_, doc_.line_of(offset),
                         std::string(what) + ": value " + std::to_string(count) + " " + quote(tok) + " " +
                             why);
      chunk.push_back(v);
      ++count;
      if (chunk.size() == 8192) {
        sink(chunk.data(), chunk.size());
        chunk.clear();
      }
    });
    if (!chunk.empty()) sink(chunk.data(), chunk.size());
    if (count != expected)
      fail(e, std::string(what) + ": " + std::to_string(count) + " values, " + std::to_string(expected) +
                  " expected");
  }

  Index vertex(const Xml_element& e, std::size_t cell, long long v, long long base,
               unsigned long long nv) const {
    const long long i = v - base;
    if (v < base || static_cast<unsigned long long>(i) >= nv)
      fail(e, "cell " + std::to_string(cell) + ": vertex index " + std::to_string(v) + " out of range (" +
                  (base != 0 ? "BaseOffset " + std::to_string(base) + ", " : std::string("0-based, ")) +
                  std::to_string(nv) + " points)");
    return static_cast<Index>(i);
  }

  void check_repeated(const Xml_element& e, std::size_t cell, const Tetrahedron& t, long long base) const {
    unsigned long long twice = 0;
    if (has_repeated_vertex(t, twice))
      fail(e, "cell " + std::to_string(cell) + ": vertex index " + std::to_string(twice + base) +
                  " listed twice");
  }

  const Xml_document doc_;
  std::string name_, folder_;
  bool stream_;
  Xdmf_h5_reader h5_;
};

template <class Mesh>
void read_xdmf_text(std::string_view text, const std::string& name, const std::string& folder, bool stream,
                    Mesh& mesh) {
  Xdmf_reader<Mesh> reader(text, name, folder, stream);
  reader.read(mesh);
}

} // namespace xdmf_with_hdf5 / xdmf_without_hdf5
} // namespace internal
} // namespace IO
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_IO_INTERNAL_XDMF_READER_H
