// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Files: `_read` (a mesh file into numpy arrays, handed over without copies) and `_write` (numpy
// arrays into a mesh file, through a temporary in the same folder renamed at the end, so that a
// failed or interrupted write never leaves a half-written file under the name asked for).  The
// format is chosen by the extension, from the package's format table (IO/formats.h).

#include "prstar_python.h"

#include <CGAL/PR_star_octree/IO.h>
#include <CGAL/PR_star_octree/IO/internal/vtk_cells.h>

#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>
#include <sys/stat.h>
#include <vector>

namespace prstar_python {

namespace {

namespace PIO = CGAL::PR_star_octree::IO;

static_assert(std::is_same<Mesh::Index, Index>::value, "the mesh and the octree index vertices alike");

/// HDF5 (the heavy data of XDMF files) is not thread-safe in Debian's build: the module reads and
/// writes XDMF files one at a time, while the other formats go in parallel.
std::mutex& hdf5_mutex() {
  static std::mutex m;
  return m;
}

std::unique_lock<std::mutex> lock_if_hdf5(const PIO::Mesh_format<Mesh>& format) {
  if (std::string(format.key) == "xdmf") return std::unique_lock<std::mutex>(hdf5_mutex());
  return std::unique_lock<std::mutex>();
}

/// An output file that exists while the caller asked not to overwrite it: FileExistsError.
struct File_exists : std::runtime_error {
  explicit File_exists(const std::string& file) : std::runtime_error(file), file(file) {}
  std::string file;
};

const PIO::Mesh_format<Mesh>& format_of(const std::string& path) {
  const PIO::Mesh_format<Mesh>* f = PIO::find_mesh_format<Mesh>(path);
  // An unknown extension is a wrong argument rather than a problem of the file (nothing is
  // opened): ValueError, naming the supported extensions.
  if (f == nullptr) throw std::invalid_argument(path + ": " + PIO::internal::unknown_extension_message(path));
  return *f;
}

bool exists(const std::string& file) {
  struct stat st;
  return ::lstat(file.c_str(), &st) == 0;
}

std::string base_name(const std::string& file) {
  const std::size_t slash = file.find_last_of('/');
  return slash == std::string::npos ? file : file.substr(slash + 1);
}

std::string replace_all(std::string s, const std::string& from, const std::string& to) {
  if (from.empty()) return s;
  for (std::size_t p = s.find(from); p != std::string::npos; p = s.find(from, p + to.size()))
    s.replace(p, from.size(), to);
  return s;
}

// The files the writer of `format` makes for `name`: the file itself, both files of a TetGen mesh
// (.node first), and the HDF5 file of an XDMF file's heavy data (made unless the XDMF is inline).
std::vector<std::string> written_files(const PIO::Mesh_format<Mesh>& format, const std::string& name) {
  const std::string key = format.key;
  if (key == "tetgen") {
    const auto names = PIO::internal::tetgen_file_names(name);
    return {names.first, names.second};
  }
  if (key == "xdmf") return {name, PIO::internal::xdmf_h5_name(name)};
  return {name};
}

// ---------------------------------------------------------------------------------------------
// Reading
// ---------------------------------------------------------------------------------------------

py::dict data_dict(std::vector<PSO::Data_array>& arrays) {
  py::dict d; // insertion order = file order (the first point-data array is "the" scalar field)
  for (PSO::Data_array& a : arrays) d[py::str(a.name)] = to_numpy(std::move(a.values));
  return d;
}

py::dict read(const std::string& path, py::handle max_memory) {
  const PIO::Mesh_format<Mesh>& format = format_of(path);
  std::size_t limit = 0; // 0: the library's default (the memory available)
  if (!max_memory.is_none()) {
    if (py::isinstance<py::float_>(max_memory) && std::isinf(max_memory.cast<double>()) &&
        max_memory.cast<double>() > 0)
      limit = PIO::Memory_limit::unlimited;
    else if (py::isinstance<py::int_>(max_memory) && !py::isinstance<py::bool_>(max_memory) &&
             max_memory.cast<py::int_>() > py::int_(0))
      limit = max_memory.cast<py::int_>() >= py::int_(PIO::Memory_limit::unlimited)
                  ? PIO::Memory_limit::unlimited
                  : max_memory.cast<std::size_t>();
    else
      throw std::invalid_argument("max_memory: expected None, a positive number of bytes or math.inf");
  }
  Mesh mesh;
  {
    Compute_scope scope(0);
    // The limit is the calling thread's, and the reader checks it on this thread, from the counts
    // of the file's header, before it allocates the arrays.
    std::unique_ptr<PIO::Memory_limit> scoped;
    if (limit != 0) scoped = std::make_unique<PIO::Memory_limit>(limit);
    const auto lock = lock_if_hdf5(format);
    PIO::read_tetrahedral_mesh(path, mesh);
  }
  py::dict d;
  d["points"] = points_to_numpy(std::move(mesh.points));
  d["tetrahedra"] = tetrahedra_to_numpy(std::move(mesh.tetrahedra));
  if (mesh.tetrahedron_labels.empty())
    d["labels"] = py::none();
  else
    d["labels"] = to_numpy(std::move(mesh.tetrahedron_labels));
  d["point_data"] = data_dict(mesh.point_data);
  d["cell_data"] = data_dict(mesh.cell_data);
  py::dict names, skipped;
  for (const auto& n : mesh.label_names) names[py::int_(n.first)] = n.second;
  for (const auto& c : mesh.skipped_cells) skipped[py::str(c.first)] = c.second;
  d["label_names"] = names;
  d["skipped_cells"] = skipped;
  return d;
}

// ---------------------------------------------------------------------------------------------
// Writing
// ---------------------------------------------------------------------------------------------

// The named arrays given as a dict, read in place (converted and checked later, GIL released).
struct Named_view {
  std::string name;
  Array_view<double> values;
};

std::vector<Named_view> named_views(const py::dict& d, const char* what) {
  std::vector<Named_view> r;
  for (const auto& item : d) {
    if (!py::isinstance<py::str>(item.first))
      throw py::type_error(std::string(what) + ": the names must be str, not " +
                           py::cast<std::string>(py::str(item.first.get_type().attr("__name__"))));
    const std::string name = item.first.cast<std::string>();
    if (name.empty()) throw std::invalid_argument(std::string(what) + ": an array has an empty name");
    const std::string label = std::string(what) + "['" + name + "']";
    r.push_back({name, Array_view<double>(item.second, label.c_str(), 0, "fiu")});
  }
  return r;
}

std::vector<PSO::Data_array> data_arrays(const std::vector<Named_view>& views, std::size_t n,
                                         const char* what, const char* per) {
  std::vector<PSO::Data_array> r;
  for (const Named_view& v : views) {
    const std::string label = std::string(what) + "['" + v.name + "']";
    if (v.values.size() != n)
      throw std::invalid_argument(label + ": " + std::to_string(v.values.size()) + " values for " +
                                  std::to_string(n) + " " + per);
    PSO::Data_array a{v.name, std::vector<double>(n)};
    for (std::size_t i = 0; i < n; ++i) {
      a.values[i] = v.values.get(i);
      // refused here, as a wrong argument, rather than by the writer as a file error
      if (!std::isfinite(a.values[i]))
        throw std::invalid_argument(label + ": the value at index " + std::to_string(i) + " is not finite");
    }
    r.push_back(std::move(a));
  }
  return r;
}

// The write options as the Python arguments give them (None: the format's default).
PIO::internal::Write_options write_options(py::handle binary, py::handle compression, py::handle version) {
  PIO::internal::Write_options o;
  if (!binary.is_none()) {
    if (!py::isinstance<py::bool_>(binary)) throw py::type_error("binary: expected None, True or False");
    o.has_binary = true;
    o.binary = binary.cast<bool>();
  }
  if (!compression.is_none()) {
    const std::string c = py::isinstance<py::str>(compression) ? compression.cast<std::string>() : "?";
    if (c != "zlib" && c != "none")
      throw std::invalid_argument("compression: expected None, 'zlib' or 'none'");
    o.has_compression = true;
    o.compression = c == "zlib" ? PIO::Compression::zlib : PIO::Compression::none;
  }
  if (!version.is_none()) {
    double v = 0;
    if (py::isinstance<py::str>(version)) {
      const std::string s = version.cast<std::string>();
      std::size_t used = 0;
      try {
        v = std::stod(s, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used == 0 || used != s.size()) throw std::invalid_argument("version: '" + s + "' is not a number");
    } else if ((py::isinstance<py::float_>(version) || py::isinstance<py::int_>(version)) &&
               !py::isinstance<py::bool_>(version)) {
      v = version.cast<double>();
    } else {
      throw py::type_error("version: expected None, a number or a string such as '2.2'");
    }
    o.has_version = true;
    o.version = v;
  }
  return o;
}

// Moves `from` to `to`; with `overwrite` false, never replaces an existing `to` (a hard link fails
// when `to` exists, atomically; where the file system has no hard links, checked just before).
void install(const std::string& from, const std::string& to, bool overwrite) {
  if (!overwrite) {
    if (::link(from.c_str(), to.c_str()) == 0) {
      ::unlink(from.c_str());
      return;
    }
    if (errno == EEXIST) throw File_exists(to);
    if (exists(to)) throw File_exists(to);
  }
  if (std::rename(from.c_str(), to.c_str()) != 0)
    throw PIO::Write_error(to, std::string("cannot write the output file: ") + std::strerror(errno));
}

void write(const std::string& path, py::handle points, py::handle tetrahedra, py::handle labels,
           const py::dict& point_data, const py::dict& cell_data, const py::dict& label_names,
           py::handle binary, py::handle compression, py::handle version, bool overwrite) {
  const PIO::Mesh_format<Mesh>& format = format_of(path);
  const PIO::internal::Write_options given = write_options(binary, compression, version);
  try { // an option the format cannot honour is a wrong argument, told before anything is written
    PIO::internal::resolve_write_options(given, *format.write_options, format.name, path);
  } catch (const PIO::Write_error& e) {
    throw std::invalid_argument(e.what());
  }
  // The arrays, read in place (any dtype, any strides); checked and copied below without the GIL.
  const Array_view<double> pts(points, "points", 3, "fiu");
  const Array_view<long long> tets(tetrahedra, "tetrahedra", 4, "iu");
  Array_view<long long> labs;
  const bool has_labels = !labels.is_none();
  if (has_labels) labs = Array_view<long long>(labels, "labels", 0, "iu");
  const std::vector<Named_view> pd = named_views(point_data, "point_data"),
                                cd = named_views(cell_data, "cell_data");
  std::map<int, std::string> names;
  for (const auto& item : label_names) {
    if (!py::isinstance<py::int_>(item.first) || !py::isinstance<py::str>(item.second))
      throw py::type_error("label_names: expected a dict int -> str");
    names[item.first.cast<int>()] = item.second.cast<std::string>();
  }
  const std::vector<std::string> outs = written_files(format, path);
  if (!overwrite)
    for (const std::string& f : outs)
      if (exists(f)) throw File_exists(f);
  // The temporary: beside the output (a rename within one file system), with the output's
  // extension (it chooses the writer), unique in the process (threads may write concurrently).
  static std::atomic<unsigned long> counter{0};
  const std::size_t dot = path.find_last_of('.');
  const std::string mark = ".prstar-tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
  const std::string tmp = path.substr(0, dot) + mark + path.substr(dot);
  const std::vector<std::string> tmps = written_files(format, tmp);

  Compute_scope scope(0);
  Mesh mesh;
  const std::size_t nv = pts.size(), nt = tets.size();
  if (nv > std::numeric_limits<Index>::max())
    throw std::invalid_argument("points: " + std::to_string(nv) +
                                " vertices, more than the 32-bit indices allow");
  mesh.points.reserve(nv);
  for (std::size_t i = 0; i < nv; ++i) {
    const double x = pts.get(i, 0), y = pts.get(i, 1), z = pts.get(i, 2);
    if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
      throw Invalid_mesh("points: vertex " + std::to_string(i) + " has a non-finite coordinate");
    mesh.points.emplace_back(x, y, z);
  }
  mesh.tetrahedra.resize(nt);
  const bool unsigned64 = tets.code() == 'L';
  for (std::size_t t = 0; t < nt; ++t)
    for (std::size_t k = 0; k < 4; ++k) {
      const long long v = tets.get(t, k);
      // uint64 values above the signed range read as negative: told with their real value
      if (v < 0 || static_cast<unsigned long long>(v) >= nv)
        throw Invalid_mesh(
            "tetrahedra: tetrahedron " + std::to_string(t) + " has vertex index " +
            (unsigned64 ? std::to_string(static_cast<unsigned long long>(v)) : std::to_string(v)) +
            " out of range [0, " + std::to_string(nv) + ")");
      mesh.tetrahedra[t][k] = static_cast<Index>(v);
      // a file with a vertex twice in a tetrahedron is refused by every reader: not written
      for (std::size_t j = 0; j < k; ++j)
        if (mesh.tetrahedra[t][j] == mesh.tetrahedra[t][k])
          throw Invalid_mesh("tetrahedra: tetrahedron " + std::to_string(t) + " lists vertex " +
                             std::to_string(v) + " twice");
    }
  if (has_labels) {
    if (labs.size() != nt)
      throw std::invalid_argument("labels: " + std::to_string(labs.size()) + " values for " +
                                  std::to_string(nt) + " tetrahedra");
    mesh.tetrahedron_labels.resize(nt);
    const bool u64 = labs.code() == 'L';
    for (std::size_t t = 0; t < nt; ++t) {
      const long long l = labs.get(t);
      if ((u64 && l < 0) || l < std::numeric_limits<int>::min() || l > std::numeric_limits<int>::max())
        throw std::invalid_argument("labels: the label of tetrahedron " + std::to_string(t) +
                                    " does not fit a 32-bit integer");
      mesh.tetrahedron_labels[t] = static_cast<int>(l);
    }
  }
  mesh.point_data = data_arrays(pd, nv, "point_data", "vertices");
  mesh.cell_data = data_arrays(cd, nt, "cell_data", "tetrahedra");
  for (const auto& a : mesh.cell_data)
    if (has_labels && a.name == "label")
      throw std::invalid_argument("cell_data['label']: 'label' is the name the files give the labels "
                                  "(pass them as labels=)");
  mesh.label_names = std::move(names);

  auto clean = [&] {
    for (const std::string& t : tmps) std::remove(t.c_str());
  };
  try {
    const auto lock = lock_if_hdf5(format);
    if (std::string(format.key) == "xdmf") // the .xdmf names its heavy data file by the final name
      PIO::internal::write_xdmf_file(tmp, mesh, given, tmps[1], base_name(outs[1]));
    else
      format.write_file(tmp, mesh, given);
    std::vector<std::string> installed;
    try {
      for (std::size_t i = 0; i < tmps.size(); ++i) {
        if (i > 0 && !exists(tmps[i])) continue; // an inline XDMF has no .h5
        install(tmps[i], outs[i], overwrite);
        installed.push_back(outs[i]);
      }
    } catch (const File_exists&) {
      // the pair (triple) of files is written whole or not at all
      for (const std::string& f : installed) std::remove(f.c_str());
      throw;
    }
  } catch (const PIO::Write_error& e) {
    clean();
    // The user knows the output by its name, not by the temporary's.
    std::string message = e.message(), file = e.file();
    for (std::size_t i = 0; i < tmps.size(); ++i) {
      message = replace_all(message, tmps[i], outs[i]);
      file = replace_all(file, tmps[i], outs[i]);
    }
    throw PIO::Write_error(file, message);
  } catch (...) {
    clean();
    throw;
  }
}

} // namespace

void bind_io(py::module_& m) {
  // Tried before the module's translator (pybind11 tries the last registered first).
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const File_exists& e) {
      // OSError(errno, strerror, filename) with EEXIST is FileExistsError
      py::object error = py::reinterpret_borrow<py::object>(PyExc_FileExistsError)(
          EEXIST, "the file exists (give overwrite=True to replace it)", e.file);
      PyErr_SetObject(PyExc_FileExistsError, error.ptr());
    }
  });
  m.def("_read", &read, py::arg("path"), py::arg("max_memory") = py::none(),
        "Reads a mesh file into a dict of numpy arrays (see prstar.read).");
  m.def("_write", &write, py::arg("path"), py::arg("points"), py::arg("tetrahedra"), py::arg("labels"),
        py::arg("point_data"), py::arg("cell_data"), py::arg("label_names"), py::arg("binary") = py::none(),
        py::arg("compression") = py::none(), py::arg("version") = py::none(), py::arg("overwrite") = true,
        "Writes numpy arrays as a mesh file, through a temporary renamed at the end (see prstar.write).");
  m.def(
      "_vtk_cell_type_name",
      [](long long type) { return std::string(PIO::internal::vtk_cell_type_name(type)); },
      "The name the VTK readers give a VTK cell type in skipped_cells.");
  m.def(
      "_is_label_array_name",
      [](const std::string& name) { return PIO::internal::is_vtk_label_array_name(name); },
      "Whether the VTK readers take a cell array of this name (integer-valued) as the labels.");
  m.def(
      "_extensions", [] { return PIO::mesh_format_extensions(); }, "The extensions read and written.");
}

} // namespace prstar_python
