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
/// the mesh has no labels or for label 0), its bounding box, and the runs of consecutive
/// tetrahedra with the same label (one element block each, so that the order of the tetrahedra is
/// kept).
struct Gmsh_volumes {
  std::vector<int> labels;                      // label of entity k (tag k + 1)
  std::vector<std::array<double, 6>> boxes;     // min x y z, max x y z
  std::vector<std::array<std::size_t, 3>> runs; // first tetrahedron, end, entity index

  template <class Mesh>
  explicit Gmsh_volumes(const Mesh& mesh) {
    const bool has_labels = !mesh.tetrahedron_labels.empty();
    std::map<int, std::size_t> entity_of;
    const double inf = std::numeric_limits<double>::infinity();
    const auto entity = [&](int label) {
      const auto it = entity_of.find(label);
      if (it != entity_of.end()) return it->second;
      entity_of.emplace(label, labels.size());
      labels.push_back(label);
      boxes.push_back({inf, inf, inf, -inf, -inf, -inf});
      return labels.size() - 1;
    };
    for (std::size_t t = 0; t < mesh.tetrahedra.size(); ++t) {
      const int label = has_labels ? mesh.tetrahedron_labels[t] : 0;
      const std::size_t e = entity(label);
      if (runs.empty() || runs.back()[2] != e)
        runs.push_back({t, t + 1, e});
      else
        runs.back()[1] = t + 1;
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
    for (auto& b : boxes)
      if (b[0] > b[3]) b = {0, 0, 0, 0, 0, 0};
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

  // $Elements: one block per run of equal labels, element tags 1..nt in the order of the mesh
  if (binary) {
    for (std::uint64_t c : {std::uint64_t(volumes.runs.size()), std::uint64_t(nt), std::uint64_t(nt ? 1 : 0),
                            std::uint64_t(nt)})
      append_binary<std::uint64_t>(buf, c);
  } else {
    append_integer(buf, volumes.runs.size());
    buf += ' ';
    append_integer(buf, nt);
    buf += nt ? " 1 " : " 0 ";
    append_integer(buf, nt);
    buf += '\n';
  }
  for (const auto& run : volumes.runs) {
    if (binary) {
      append_binary<std::int32_t>(buf, 3);
      append_binary<std::int32_t>(buf, static_cast<std::int32_t>(run[2] + 1));
      append_binary<std::int32_t>(buf, 4);
      append_binary<std::uint64_t>(buf, run[1] - run[0]);
    } else {
      buf += "3 ";
      append_integer(buf, run[2] + 1);
      buf += " 4 ";
      append_integer(buf, run[1] - run[0]);
      buf += '\n';
    }
    for (std::size_t t = run[0]; t < run[1]; ++t) {
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
    }
  }
  buf += binary ? "\n$EndElements\n" : "$EndElements\n";
  flush_buffer(out, buf, name, true);
}

template <class Mesh>
void write_gmsh_22(std::ostream& out, const Mesh& mesh, bool binary, const std::string& name) {
  const Gmsh_volumes volumes(mesh);
  const std::size_t nv = mesh.points.size(), nt = mesh.tetrahedra.size();
  const std::size_t int_max = static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max());
  if (binary && (nv >= int_max || nt >= int_max))
    throw Write_error(name,
                      "too many vertices or tetrahedra for the 32-bit integers of a binary .msh 2.2 file "
                      "(use version 4.1)");
  std::vector<std::size_t> entity_of_tet(volumes.runs.empty() ? 0 : nt);
  for (const auto& run : volumes.runs)
    for (std::size_t t = run[0]; t < run[1]; ++t) entity_of_tet[t] = run[2];

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
  for (std::size_t t = 0; t < nt; ++t) {
    const std::size_t e = entity_of_tet[t];
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
  flush_buffer(out, buf, name, true);
}

} // namespace internal
} // namespace IO
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_IO_INTERNAL_GMSH_WRITER_H
