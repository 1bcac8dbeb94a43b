// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_IO_INTERNAL_GMSH_WRITER_H
#define CGAL_PR_STAR_OCTREE_IO_INTERNAL_GMSH_WRITER_H

// The gmsh `.msh` writer (versions 2.2 and 4.1, ASCII and binary), behind `write_gmsh()` of
// `CGAL/PR_star_octree/IO/gmsh.h`.

#include <CGAL/PR_star_octree/IO/Read_error.h>
#include <CGAL/PR_star_octree/IO/internal/file_bytes.h>
#include <CGAL/PR_star_octree/IO/internal/text.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <ostream>
#include <string>
#include <vector>

namespace CGAL {
namespace PR_star_octree {
namespace IO {
namespace internal {

/// One volume entity per label (in order of first appearance; one entity without physical tag when
/// the mesh has no labels or for label 0), its bounding box and its number of tetrahedra, the
/// entity of each tetrahedron, and the order of the tetrahedra in the 4.1 element blocks: one block
/// per entity, each with its tetrahedra in the order of the mesh.
struct Gmsh_volumes {
  std::vector<int> labels;                  // label of entity k (tag k + 1)
  std::vector<std::array<double, 6>> boxes; // min x y z, max x y z
  std::vector<std::size_t> counts;          // number of tetrahedra of entity k
  std::vector<std::uint32_t> entity_of;     // entity of each tetrahedron (empty: all in entity 0)

  template <class Mesh>
  explicit Gmsh_volumes(const Mesh& mesh) {
    const bool has_labels = !mesh.tetrahedron_labels.empty();
    const std::size_t nt = mesh.tetrahedra.size();
    std::map<int, std::uint32_t> entity_index;
    const double inf = std::numeric_limits<double>::infinity();
    const auto entity = [&](int label) {
      const auto it = entity_index.find(label);
      if (it != entity_index.end()) return it->second;
      const std::uint32_t e = static_cast<std::uint32_t>(labels.size());
      entity_index.emplace(label, e);
      labels.push_back(label);
      boxes.push_back({inf, inf, inf, -inf, -inf, -inf});
      counts.push_back(0);
      return e;
    };
    int last_label = 0;
    std::uint32_t last_entity = 0;
    if (has_labels) entity_of.resize(nt);
    for (std::size_t t = 0; t < nt; ++t) {
      const int label = has_labels ? mesh.tetrahedron_labels[t] : 0;
      if (t == 0 || label != last_label) {
        last_entity = entity(label);
        last_label = label;
      }
      const std::uint32_t e = last_entity;
      if (has_labels) entity_of[t] = e;
      ++counts[e];
      for (const auto v : mesh.tetrahedra[t]) {
        const auto& p = mesh.points[static_cast<std::size_t>(v)];
        const double c[3] = {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
        for (int k = 0; k < 3; ++k) {
          boxes[e][k] = std::min(boxes[e][k], c[k]);
          boxes[e][k + 3] = std::max(boxes[e][k + 3], c[k]);
        }
      }
    }
    if (labels.empty()) entity(0); // the nodes need an entity
    if (labels.size() == 1) entity_of = std::vector<std::uint32_t>();
    for (auto& b : boxes)
      if (b[0] > b[3]) b = {0, 0, 0, 0, 0, 0};
  }

  std::size_t entity(std::size_t t) const { return entity_of.empty() ? 0 : entity_of[t]; }

  /// Calls `f(t)` for every tetrahedron `t`, entity by entity, each entity's tetrahedra in the
  /// order of the mesh (the order of the 4.1 element blocks), and `block(e)` before the first
  /// tetrahedron of each entity `e` that has some.
  template <class Block, class F>
  void for_each_grouped(Block block, F f) const {
    const std::size_t ne = labels.size();
    const std::size_t nt = entity_of.size();
    if (ne == 1 || nt == 0) {
      if (counts[0] != 0) block(std::size_t(0));
      for (std::size_t t = 0; t < counts[0]; ++t) f(t);
      return;
    }
    // the tetrahedra of each entity: a counting sort of their indices (32-bit when they fit)
    std::vector<std::size_t> start(ne + 1, 0);
    for (std::size_t e = 0; e < ne; ++e) start[e + 1] = start[e] + counts[e];
    bool grouped = true; // already in entity order: no index array
    for (std::size_t t = 1; t < nt && grouped; ++t) grouped = entity_of[t] >= entity_of[t - 1];
    if (grouped) {
      for (std::size_t e = 0; e < ne; ++e) {
        if (counts[e] != 0) block(e);
        for (std::size_t t = start[e]; t < start[e + 1]; ++t) f(t);
      }
    } else if (nt <= std::numeric_limits<std::uint32_t>::max()) {
      grouped_by_index<std::uint32_t>(start, block, f);
    } else {
      grouped_by_index<std::uint64_t>(start, block, f);
    }
  }

private:
  template <class Int, class Block, class F>
  void grouped_by_index(std::vector<std::size_t> start, Block& block, F& f) const {
    std::vector<Int> order(entity_of.size());
    std::vector<std::size_t> next(start.begin(), start.end() - 1);
    for (std::size_t t = 0; t < entity_of.size(); ++t) order[next[entity_of[t]]++] = static_cast<Int>(t);
    for (std::size_t e = 0; e + 1 < start.size(); ++e) {
      if (counts[e] != 0) block(e);
      for (std::size_t k = start[e]; k < start[e + 1]; ++k) f(static_cast<std::size_t>(order[k]));
    }
  }
};

template <class Mesh>
void write_gmsh_physical_names(std::string& buf, const Mesh& mesh, const Gmsh_volumes& volumes) {
  std::vector<int> named;
  for (const int label : volumes.labels)
    if (label != 0 && mesh.label_names.count(label)) named.push_back(label);
  if (named.empty()) return;
  buf += "$PhysicalNames\n";
  append_integer(buf, named.size());
  buf += '\n';
  for (const int label : named) {
    buf += "3 ";
    append_integer(buf, label);
    buf += " \"";
    for (const char c : mesh.label_names.at(label))
      if (c != '"' && c != '\n' && c != '\r') buf += c;
    buf += "\"\n";
  }
  buf += "$EndPhysicalNames\n";
}

inline void append_xyz(std::string& buf, double x, double y, double z) {
  append_double(buf, x);
  buf += ' ';
  append_double(buf, y);
  buf += ' ';
  append_double(buf, z);
}

/// The checks of the gmsh writer: those of every writer of named arrays, names that fit between the
/// quotes of a string tag, and the 32-bit tags of binary data sections.
template <class Mesh>
void check_mesh_for_gmsh(const Mesh& mesh, bool binary, const std::string& name) {
  check_named_arrays_for_writing(mesh, {}, name);
  const auto check_name = [&](const Data_array& a, const char* kind) {
    if (a.name.find_first_of("\"\n\r") != std::string::npos)
      throw Write_error(name, std::string(kind) + " '" + a.name +
                                  "': a double quote or a line break cannot be written in a .msh view name");
  };
  for (const Data_array& a : mesh.point_data) check_name(a, "point data");
  for (const Data_array& a : mesh.cell_data) check_name(a, "cell data");
  const std::size_t int_max = static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max());
  if (binary && (!mesh.point_data.empty() || !mesh.cell_data.empty()) &&
      (mesh.points.size() >= int_max || mesh.tetrahedra.size() >= int_max))
    throw Write_error(name, "too many vertices or tetrahedra for the 32-bit tags of the binary $NodeData and "
                            "$ElementData sections (write an ASCII file)");
}

/// Appends the header of a `$NodeData` or `$ElementData` section (`section` without the `$`): one
/// string tag (the view name), one real tag (time 0), three integer tags (time step 0, one
/// component, `n` entries).
inline void append_gmsh_data_header(std::string& buf, const char* section, const std::string& view,
                                    std::size_t n) {
  buf += '$';
  buf += section;
  buf += "\n1\n\"";
  buf += view;
  buf += "\"\n1\n0\n3\n0\n1\n";
  append_integer(buf, n);
  buf += '\n';
}

inline void append_gmsh_data_entry(std::string& buf, std::size_t tag, double value, bool binary) {
  if (binary) {
    append_binary<std::int32_t>(buf, static_cast<std::int32_t>(tag));
    append_binary<double>(buf, value);
  } else {
    append_integer(buf, tag);
    buf += ' ';
    append_double(buf, value);
    buf += '\n';
  }
}

/// Appends the `$NodeData` sections (one view per point-data array, node tag = vertex index + 1)
/// and the `$ElementData` sections (one view per cell-data array, element tag = tetrahedron
/// index + 1, the entries in the order of the elements in the file: grouped by entity in 4.1).
template <class Mesh>
void write_gmsh_data(std::ostream& out, std::string& buf, const Mesh& mesh, const Gmsh_volumes& volumes,
                     bool binary, bool grouped, const std::string& name) {
  for (const Data_array& a : mesh.point_data) {
    append_gmsh_data_header(buf, "NodeData", a.name, a.values.size());
    for (std::size_t i = 0; i < a.values.size(); ++i) {
      append_gmsh_data_entry(buf, i + 1, a.values[i], binary);
      flush_buffer(out, buf, name);
    }
    buf += binary ? "\n$EndNodeData\n" : "$EndNodeData\n";
  }
  for (const Data_array& a : mesh.cell_data) {
    append_gmsh_data_header(buf, "ElementData", a.name, a.values.size());
    const auto entry = [&](std::size_t t) {
      append_gmsh_data_entry(buf, t + 1, a.values[t], binary);
      flush_buffer(out, buf, name);
    };
    if (grouped)
      volumes.for_each_grouped([](std::size_t) {}, entry);
    else
      for (std::size_t t = 0; t < a.values.size(); ++t) entry(t);
    buf += binary ? "\n$EndElementData\n" : "$EndElementData\n";
  }
}

template <class Mesh>
void write_gmsh_41(std::ostream& out, const Mesh& mesh, bool binary, const std::string& name) {
  const Gmsh_volumes volumes(mesh);
  const std::size_t nv = mesh.points.size(), nt = mesh.tetrahedra.size();
  std::string buf = binary ? "$MeshFormat\n4.1 1 8\n" : "$MeshFormat\n4.1 0 8\n";
  if (binary) {
    append_binary<std::int32_t>(buf, 1);
    buf += '\n';
  }
  buf += "$EndMeshFormat\n";
  write_gmsh_physical_names(buf, mesh, volumes);

  // $Entities: volumes only
  buf += "$Entities\n";
  const std::size_t ne = volumes.labels.size();
  if (binary) {
    for (std::uint64_t c : {std::uint64_t(0), std::uint64_t(0), std::uint64_t(0), std::uint64_t(ne)})
      append_binary<std::uint64_t>(buf, c);
  } else {
    buf += "0 0 0 ";
    append_integer(buf, ne);
    buf += '\n';
  }
  for (std::size_t e = 0; e < ne; ++e) {
    const bool physical = volumes.labels[e] != 0;
    if (binary) {
      append_binary<std::int32_t>(buf, static_cast<std::int32_t>(e + 1));
      for (const double c : volumes.boxes[e]) append_binary<double>(buf, c);
      append_binary<std::uint64_t>(buf, physical ? 1 : 0);
      if (physical) append_binary<std::int32_t>(buf, volumes.labels[e]);
      append_binary<std::uint64_t>(buf, 0);
    } else {
      append_integer(buf, e + 1);
      for (const double c : volumes.boxes[e]) {
        buf += ' ';
        append_double(buf, c);
      }
      if (physical) {
        buf += " 1 ";
        append_integer(buf, volumes.labels[e]);
        buf += " 0\n";
      } else {
        buf += " 0 0\n";
      }
    }
  }
  buf += binary ? "\n$EndEntities\n$Nodes\n" : "$EndEntities\n$Nodes\n";

  // $Nodes: one block in the first volume
  if (binary) {
    for (std::uint64_t c :
         {std::uint64_t(1), std::uint64_t(nv), std::uint64_t(nv ? 1 : 0), std::uint64_t(nv)})
      append_binary<std::uint64_t>(buf, c);
    append_binary<std::int32_t>(buf, 3);
    append_binary<std::int32_t>(buf, 1);
    append_binary<std::int32_t>(buf, 0);
    append_binary<std::uint64_t>(buf, nv);
    for (std::size_t i = 0; i < nv; ++i) {
      append_binary<std::uint64_t>(buf, i + 1);
      flush_buffer(out, buf, name);
    }
    for (const auto& p : mesh.points) {
      append_binary<double>(buf, CGAL::to_double(p.x()));
      append_binary<double>(buf, CGAL::to_double(p.y()));
      append_binary<double>(buf, CGAL::to_double(p.z()));
      flush_buffer(out, buf, name);
    }
    buf += '\n';
  } else {
    buf += "1 ";
    append_integer(buf, nv);
    buf += nv ? " 1 " : " 0 ";
    append_integer(buf, nv);
    buf += "\n3 1 0 ";
    append_integer(buf, nv);
    buf += '\n';
    for (std::size_t i = 0; i < nv; ++i) {
      append_integer(buf, i + 1);
      buf += '\n';
      flush_buffer(out, buf, name);
    }
    for (const auto& p : mesh.points) {
      append_xyz(buf, CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
      buf += '\n';
      flush_buffer(out, buf, name);
    }
  }
  buf += "$EndNodes\n$Elements\n";

  // $Elements: one block per entity (label), its tetrahedra in the order of the mesh, element tag =
  // tetrahedron index + 1 (not renumbered by the grouping)
  std::size_t blocks = 0;
  for (const std::size_t c : volumes.counts) blocks += c != 0 ? 1 : 0;
  if (binary) {
    for (std::uint64_t c :
         {std::uint64_t(blocks), std::uint64_t(nt), std::uint64_t(nt ? 1 : 0), std::uint64_t(nt)})
      append_binary<std::uint64_t>(buf, c);
  } else {
    append_integer(buf, blocks);
    buf += ' ';
    append_integer(buf, nt);
    buf += nt ? " 1 " : " 0 ";
    append_integer(buf, nt);
    buf += '\n';
  }
  volumes.for_each_grouped(
      [&](std::size_t e) {
        if (binary) {
          append_binary<std::int32_t>(buf, 3);
          append_binary<std::int32_t>(buf, static_cast<std::int32_t>(e + 1));
          append_binary<std::int32_t>(buf, 4);
          append_binary<std::uint64_t>(buf, volumes.counts[e]);
        } else {
          buf += "3 ";
          append_integer(buf, e + 1);
          buf += " 4 ";
          append_integer(buf, volumes.counts[e]);
          buf += '\n';
        }
      },
      [&](std::size_t t) {
        if (binary) {
          append_binary<std::uint64_t>(buf, t + 1);
          for (const auto v : mesh.tetrahedra[t])
            append_binary<std::uint64_t>(buf, static_cast<std::uint64_t>(v) + 1);
        } else {
          append_integer(buf, t + 1);
          for (const auto v : mesh.tetrahedra[t]) {
            buf += ' ';
            append_integer(buf, static_cast<unsigned long long>(v) + 1);
          }
          buf += '\n';
        }
        flush_buffer(out, buf, name);
      });
  buf += binary ? "\n$EndElements\n" : "$EndElements\n";
  write_gmsh_data(out, buf, mesh, volumes, binary, true, name);
  flush_buffer(out, buf, name, true);
}

template <class Mesh>
void write_gmsh_22(std::ostream& out, const Mesh& mesh, bool binary, const std::string& name) {
  const std::size_t nv = mesh.points.size(), nt = mesh.tetrahedra.size();
  const std::size_t int_max = static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max());
  if (binary && (nv >= int_max || nt >= int_max))
    throw Write_error(name,
                      "too many vertices or tetrahedra for the 32-bit integers of a binary .msh 2.2 file "
                      "(use version 4.1)");
  const Gmsh_volumes volumes(mesh);

  std::string buf = binary ? "$MeshFormat\n2.2 1 8\n" : "$MeshFormat\n2.2 0 8\n";
  if (binary) {
    append_binary<std::int32_t>(buf, 1);
    buf += '\n';
  }
  buf += "$EndMeshFormat\n";
  write_gmsh_physical_names(buf, mesh, volumes);
  buf += "$Nodes\n";
  append_integer(buf, nv);
  buf += '\n';
  for (std::size_t i = 0; i < nv; ++i) {
    const auto& p = mesh.points[i];
    if (binary) {
      append_binary<std::int32_t>(buf, static_cast<std::int32_t>(i + 1));
      append_binary<double>(buf, CGAL::to_double(p.x()));
      append_binary<double>(buf, CGAL::to_double(p.y()));
      append_binary<double>(buf, CGAL::to_double(p.z()));
    } else {
      append_integer(buf, i + 1);
      buf += ' ';
      append_xyz(buf, CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
      buf += '\n';
    }
    flush_buffer(out, buf, name);
  }
  buf += binary ? "\n$EndNodes\n$Elements\n" : "$EndNodes\n$Elements\n";
  append_integer(buf, nt);
  buf += '\n';
  if (binary && nt > 0) {
    append_binary<std::int32_t>(buf, 4);
    append_binary<std::int32_t>(buf, static_cast<std::int32_t>(nt));
    append_binary<std::int32_t>(buf, 2);
  }
  // the elements in the order of the mesh, element tag = tetrahedron index + 1, each with the
  // physical tag and the entity of its label
  for (std::size_t t = 0; t < nt; ++t) {
    const std::size_t e = volumes.entity(t);
    const int physical = volumes.labels[e];
    if (binary) {
      append_binary<std::int32_t>(buf, static_cast<std::int32_t>(t + 1));
      append_binary<std::int32_t>(buf, physical);
      append_binary<std::int32_t>(buf, static_cast<std::int32_t>(e + 1));
      for (const auto v : mesh.tetrahedra[t])
        append_binary<std::int32_t>(buf, static_cast<std::int32_t>(v + 1));
    } else {
      append_integer(buf, t + 1);
      buf += " 4 2 ";
      append_integer(buf, physical);
      buf += ' ';
      append_integer(buf, e + 1);
      for (const auto v : mesh.tetrahedra[t]) {
        buf += ' ';
        append_integer(buf, static_cast<unsigned long long>(v) + 1);
      }
      buf += '\n';
    }
    flush_buffer(out, buf, name);
  }
  buf += binary ? "\n$EndElements\n" : "$EndElements\n";
  write_gmsh_data(out, buf, mesh, volumes, binary, false, name);
  flush_buffer(out, buf, name, true);
}

} // namespace internal
} // namespace IO
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_IO_INTERNAL_GMSH_WRITER_H
