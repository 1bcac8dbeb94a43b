// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_IO_INTERNAL_XDMF_WRITER_H
#define CGAL_PR_STAR_OCTREE_IO_INTERNAL_XDMF_WRITER_H

// The XDMF 3 writer: one Uniform grid, Tetrahedron topology, XYZ geometry, scalar attributes; the
// heavy data in `<stem>.h5` beside the `.xdmf` (xdmf_hdf5.h) or inline in the XML.

#include <CGAL/PR_star_octree/IO/Read_error.h>
#include <CGAL/PR_star_octree/IO/Write_options.h>
#include <CGAL/PR_star_octree/IO/internal/text.h>
#include <CGAL/PR_star_octree/IO/internal/xdmf_hdf5.h>
#include <CGAL/PR_star_octree/Indexed_tetrahedral_mesh.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace CGAL {
namespace PR_star_octree {
namespace IO {
namespace internal {

/// What the XDMF writer accepts: heavy data in HDF5 (`use_binary_mode(true)`, the default; without
/// HDF5 in the build, inline XML is the default and HDF5 is refused) or inline XML
/// (`use_binary_mode(false)`), no compression, version 3.0.
inline constexpr Write_support xdmf_write_support{
    true, true, true, false, false, {"3.0", nullptr, nullptr, nullptr}, nullptr};

#ifdef CGAL_PR_STAR_OCTREE_USE_HDF5
inline namespace xdmf_with_hdf5 {
#else
inline namespace xdmf_without_hdf5 {
#endif

/// The HDF5 file of an XDMF file: `<stem>.h5` beside it.
inline std::string xdmf_h5_name(const std::string& xdmf) {
  std::filesystem::path p(xdmf);
  p.replace_extension(".h5");
  return p.string();
}

/// Writes `filename`; the heavy data (HDF5 storage) go to `h5_file` (default `<stem>.h5`), named in
/// the `.xdmf` as `h5_reference` (default: the file name of `h5_file`, beside the `.xdmf`).  A program
/// that writes through a temporary and renames it (as `prstar` does) writes `TMP.xdmf` and `TMP.h5`
/// with the reference `OUT.h5`, then renames both.
template <class Mesh>
void write_xdmf_file(const std::string& filename, const Mesh& mesh, const Write_options& given,
                     const std::string& h5_file = std::string(),
                     const std::string& h5_reference = std::string()) {
  Write_options g = given;
  if (!g.has_binary && !xdmf_hdf5_available()) { // the default of a build without HDF5: inline XML
    g.has_binary = true;
    g.binary = false;
  }
  const Write_options o = resolve_write_options(g, xdmf_write_support, "XDMF", filename);
  check_named_arrays_for_writing(mesh, {}, filename);
  const bool float32 = write_float32_points(mesh, filename);
  if (o.binary && !xdmf_hdf5_available()) throw Write_error(filename, xdmf_no_hdf5_message());
  const bool hdf = o.binary;
  const std::string h5 = h5_file.empty() ? xdmf_h5_name(filename) : h5_file;
  if (hdf && std::filesystem::path(h5) == std::filesystem::path(filename))
    throw Write_error(filename,
                      "the heavy data would go to the file itself: give the file the extension .xdmf");
  const std::string h5_ref =
      h5_reference.empty() ? std::filesystem::path(h5).filename().string() : h5_reference;
  const std::size_t nv = mesh.points.size(), nt = mesh.tetrahedra.size();
  const auto coordinate = [&](std::size_t i) {
    const auto& p = mesh.points[i / 3];
    return CGAL::to_double(i % 3 == 0 ? p.x() : i % 3 == 1 ? p.y() : p.z());
  };

  if (hdf) {
    Xdmf_h5_writer w(h5);
    if (float32)
      w.template write<float>("/Mesh/geometry", nv, 3,
                              [&](std::size_t i) { return static_cast<float>(coordinate(i)); });
    else
      w.template write<double>("/Mesh/geometry", nv, 3, coordinate);
    w.template write<std::int64_t>(
        "/Mesh/topology", nt, 4, [&](std::size_t i) { return std::int64_t(mesh.tetrahedra[i / 4][i % 4]); });
    for (std::size_t k = 0; k < mesh.point_data.size(); ++k)
      w.template write<double>("/PointData/" + std::to_string(k), nv, 0,
                               [&](std::size_t i) { return mesh.point_data[k].values[i]; });
    if (!mesh.tetrahedron_labels.empty())
      w.template write<std::int32_t>("/CellData/label", nt, 0,
                                     [&](std::size_t i) { return std::int32_t(mesh.tetrahedron_labels[i]); });
    for (std::size_t k = 0; k < mesh.cell_data.size(); ++k)
      w.template write<double>("/CellData/" + std::to_string(k), nt, 0,
                               [&](std::size_t i) { return mesh.cell_data[k].values[i]; });
    w.close();
  }

  std::ofstream out;
  open_for_writing(out, filename);
  std::string buf;
  // a DataItem: in the HDF5 file (dataset `path`) or inline, `rows` x `columns` values
  const auto item = [&](const char* type, int precision, std::size_t rows, std::size_t columns,
                        const std::string& path, const auto& value) {
    buf += "        <DataItem DataType=\"";
    buf += type;
    buf += "\" Precision=\"";
    append_integer(buf, precision);
    buf += "\" Dimensions=\"";
    append_integer(buf, rows);
    if (columns != 0) {
      buf += ' ';
      append_integer(buf, columns);
    }
    buf += "\" Format=\"";
    buf += hdf ? "HDF\">" : "XML\">";
    if (hdf) {
      xml_escape(buf, h5_ref + ":" + path);
    } else {
      const std::size_t per_row = columns == 0 ? 1 : columns;
      for (std::size_t r = 0; r < rows; ++r) {
        buf += "\n         ";
        for (std::size_t c = 0; c < per_row; ++c) {
          buf += ' ';
          value(buf, r * per_row + c);
        }
        flush_buffer(out, buf, filename);
      }
      buf += "\n        ";
    }
    buf += "</DataItem>\n";
  };
  const auto real = [](const auto& values) {
    return [&values](std::string& b, std::size_t i) { append_double(b, values[i]); };
  };
  buf += "<?xml version=\"1.0\"?>\n<Xdmf Version=\"3.0\">\n  <Domain>\n    <Grid Name=\"mesh\" "
         "GridType=\"Uniform\">\n      <Topology TopologyType=\"Tetrahedron\" NumberOfElements=\"";
  append_integer(buf, nt);
  buf += "\" NodesPerElement=\"4\">\n";
  item("Int", 8, nt, 4, "/Mesh/topology", [&](std::string& b, std::size_t i) {
    append_integer(b, std::int64_t(mesh.tetrahedra[i / 4][i % 4]));
  });
  buf += "      </Topology>\n      <Geometry GeometryType=\"XYZ\">\n";
  item("Float", float32 ? 4 : 8, nv, 3, "/Mesh/geometry", [&](std::string& b, std::size_t i) {
    if (float32)
      append_float(b, coordinate(i)); // the shortest text that reads back as the same float
    else
      append_double(b, coordinate(i));
  });
  buf += "      </Geometry>\n";
  const auto attribute = [&](const std::string& name, const char* center) {
    buf += "      <Attribute Name=\"";
    xml_escape(buf, name);
    buf += "\" AttributeType=\"Scalar\" Center=\"";
    buf += center;
    buf += "\">\n";
  };
  for (std::size_t k = 0; k < mesh.point_data.size(); ++k) {
    attribute(mesh.point_data[k].name, "Node");
    item("Float", 8, nv, 0, "/PointData/" + std::to_string(k), real(mesh.point_data[k].values));
    buf += "      </Attribute>\n";
  }
  if (!mesh.tetrahedron_labels.empty()) {
    attribute("label", "Cell");
    item("Int", 4, nt, 0, "/CellData/label",
         [&](std::string& b, std::size_t i) { append_integer(b, mesh.tetrahedron_labels[i]); });
    buf += "      </Attribute>\n";
  }
  for (std::size_t k = 0; k < mesh.cell_data.size(); ++k) {
    attribute(mesh.cell_data[k].name, "Cell");
    item("Float", 8, nt, 0, "/CellData/" + std::to_string(k), real(mesh.cell_data[k].values));
    buf += "      </Attribute>\n";
  }
  buf += "    </Grid>\n  </Domain>\n</Xdmf>\n";
  flush_buffer(out, buf, filename, true);
  close_written(out, filename);
}

} // namespace xdmf_with_hdf5 / xdmf_without_hdf5
} // namespace internal
} // namespace IO
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_IO_INTERNAL_XDMF_WRITER_H
