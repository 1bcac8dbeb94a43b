// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later

#include "lattice.h"

#include <array>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace prstar {

namespace {

bool host_is_little_endian() {
  const std::uint16_t one = 1;
  unsigned char b;
  std::memcpy(&b, &one, 1);
  return b == 1;
}

// A deterministic jitter in [-0.1, 0.1) for interior lattice coordinates (0 on the boundary planes).
double jitter(std::size_t x, std::size_t y, std::size_t z, int axis, std::size_t n) {
  const std::size_t c = axis == 0 ? x : axis == 1 ? y : z;
  if (c == 0 || c == n) return 0.;
  std::uint64_t h = (x * 0x9E3779B97F4A7C15ull) ^ (y * 0xC2B2AE3D27D4EB4Full) ^ (z * 0x165667B19E3779F9ull) ^
                    (static_cast<std::uint64_t>(axis) << 61);
  h ^= h >> 29;
  h *= 0xBF58476D1CE4E5B9ull;
  h ^= h >> 32;
  return 0.2 * (static_cast<double>(h % 1000000) / 1e6) - 0.1;
}

// Buffered raw writes of plain values.
class Sink {
public:
  explicit Sink(std::ostream& out) : out_(out) { buffer_.reserve(1 << 20); }
  template <class T>
  void put(const T& v) {
    const char* p = reinterpret_cast<const char*>(&v);
    buffer_.insert(buffer_.end(), p, p + sizeof(T));
    if (buffer_.size() >= (1u << 20)) flush();
  }
  void flush() {
    out_.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
    buffer_.clear();
    if (!out_) throw std::runtime_error("cannot write the lattice (disk full?)");
  }

private:
  std::ostream& out_;
  std::vector<char> buffer_;
};

// The 6 tetrahedra of the cube: corners 0, the path's two middle corners, 7 (corner b has
// coordinates (b & 1, b >> 1 & 1, b >> 2 & 1)), listed positively oriented.
std::array<std::array<int, 4>, 6> kuhn_tetrahedra() {
  const int paths[6][2] = {{1, 3}, {1, 5}, {2, 3}, {2, 6}, {4, 5}, {4, 6}};
  std::array<std::array<int, 4>, 6> t;
  for (int k = 0; k < 6; ++k) {
    t[k] = {{0, paths[k][0], paths[k][1], 7}};
    // orientation on the unit cube, exactly (small integers)
    long long p[4][3];
    for (int i = 0; i < 4; ++i)
      for (int a = 0; a < 3; ++a) p[i][a] = (t[k][i] >> a) & 1;
    long long u[3][3];
    for (int i = 0; i < 3; ++i)
      for (int a = 0; a < 3; ++a) u[i][a] = p[i + 1][a] - p[0][a];
    const long long det = u[0][0] * (u[1][1] * u[2][2] - u[1][2] * u[2][1]) -
                          u[0][1] * (u[1][0] * u[2][2] - u[1][2] * u[2][0]) +
                          u[0][2] * (u[1][0] * u[2][1] - u[1][1] * u[2][0]);
    if (det < 0) std::swap(t[k][1], t[k][2]);
  }
  return t;
}

} // namespace

void write_lattice_vtu(std::ostream& out, const Lattice& lattice,
                       const std::function<void(std::size_t, std::size_t)>& progress) {
  const std::size_t n = lattice.cells, side = n + 1;
  if (n == 0) throw std::invalid_argument("--cells must be at least 1");
  const std::uint64_t nv = lattice.number_of_vertices(), nt = lattice.number_of_tetrahedra();
  // 32-bit connectivity and offsets where they fit: half the bytes of the file, and of every pass
  // that reads it again (VTK reads either width)
  const bool int32_connectivity = nv - 1 <= 0x7FFFFFFFull, int32_offsets = 4 * nt <= 0x7FFFFFFFull;
  const char* connectivity_type = int32_connectivity ? "Int32" : "Int64";
  const char* offset_type = int32_offsets ? "Int32" : "Int64";
  const std::uint64_t scalar_bytes = 8 * nv, point_bytes = 24 * nv,
                      connectivity_bytes = (int32_connectivity ? 16 : 32) * nt,
                      offset_bytes = (int32_offsets ? 4 : 8) * nt, type_bytes = nt;
  const std::uint64_t o_scalar = 0, o_points = o_scalar + 8 + scalar_bytes,
                      o_conn = o_points + 8 + point_bytes, o_offsets = o_conn + 8 + connectivity_bytes,
                      o_types = o_offsets + 8 + offset_bytes;
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\""
      << (host_is_little_endian() ? "LittleEndian" : "BigEndian") << "\" header_type=\"UInt64\">\n"
      << "<UnstructuredGrid>\n<Piece NumberOfPoints=\"" << nv << "\" NumberOfCells=\"" << nt << "\">\n"
      << "<PointData Scalars=\"scalar\">\n<DataArray type=\"Float64\" Name=\"scalar\" format=\"appended\" "
         "offset=\""
      << o_scalar << "\"/>\n</PointData>\n"
      << "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"appended\" offset=\""
      << o_points << "\"/>\n</Points>\n<Cells>\n"
      << "<DataArray type=\"" << connectivity_type << "\" Name=\"connectivity\" format=\"appended\" offset=\""
      << o_conn << "\"/>\n"
      << "<DataArray type=\"" << offset_type << "\" Name=\"offsets\" format=\"appended\" offset=\""
      << o_offsets << "\"/>\n"
      << "<DataArray type=\"UInt8\" Name=\"types\" format=\"appended\" offset=\"" << o_types << "\"/>\n"
      << "</Cells>\n</Piece>\n</UnstructuredGrid>\n<AppendedData encoding=\"raw\">\n_";
  const std::uint64_t total = nv + nt; // progress units: vertices, then tetrahedra
  std::uint64_t done = 0;
  {
    Sink sink(out);
    auto coordinates = [&](std::size_t x, std::size_t y, std::size_t z) {
      return std::array<double, 3>{{double(x) + jitter(x, y, z, 0, n), double(y) + jitter(x, y, z, 1, n),
                                    double(z) + jitter(x, y, z, 2, n)}};
    };
    sink.put(scalar_bytes);
    for (std::size_t z = 0; z < side; ++z) {
      for (std::size_t y = 0; y < side; ++y)
        for (std::size_t x = 0; x < side; ++x) {
          const auto p = coordinates(x, y, z);
          sink.put(p[0] * p[0] / double(side) + p[1] - p[2]);
        }
    }
    sink.put(point_bytes);
    for (std::size_t z = 0; z < side; ++z) {
      for (std::size_t y = 0; y < side; ++y)
        for (std::size_t x = 0; x < side; ++x)
          for (double c : coordinates(x, y, z)) sink.put(c);
      done += side * side;
      progress(static_cast<std::size_t>(done), static_cast<std::size_t>(total));
    }
    const auto kuhn = kuhn_tetrahedra();
    sink.put(connectivity_bytes);
    for (std::size_t z = 0; z < n; ++z) {
      for (std::size_t y = 0; y < n; ++y)
        for (std::size_t x = 0; x < n; ++x) {
          std::int64_t c[8];
          for (int b = 0; b < 8; ++b)
            c[b] = static_cast<std::int64_t>((x + (b & 1)) +
                                             side * ((y + ((b >> 1) & 1)) + side * (z + ((b >> 2) & 1))));
          for (const auto& t : kuhn)
            for (int k : t) {
              if (int32_connectivity)
                sink.put(static_cast<std::int32_t>(c[k]));
              else
                sink.put(c[k]);
            }
        }
      done += 6 * n * n;
      progress(static_cast<std::size_t>(done), static_cast<std::size_t>(total));
    }
    sink.put(offset_bytes);
    for (std::uint64_t t = 1; t <= nt; ++t) {
      if (int32_offsets)
        sink.put(static_cast<std::int32_t>(4 * t));
      else
        sink.put(static_cast<std::int64_t>(4 * t));
    }
    sink.put(type_bytes);
    for (std::uint64_t t = 0; t < nt; ++t) sink.put(static_cast<std::uint8_t>(10));
    sink.flush();
  }
  out << "\n</AppendedData>\n</VTKFile>\n";
  if (!out) throw std::runtime_error("cannot write the lattice (disk full?)");
}

} // namespace prstar
