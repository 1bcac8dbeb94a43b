// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The distributed form of stats, boundary, curvature and validate, run by every rank under mpirun
// (`mpirun -np N prstar boundary MESH ...`): each rank reads its part of MESH, the ranks build the
// distributed octree (Distributed_octree_3), compute, and print what one process prints (rank 0,
// once).  -o OUT.pvtu writes one piece per rank; any other output gathers the mesh on rank 0 and
// writes one file as one process would.  Built only with MPI.

#include "commands.h"
#include <CGAL/PR_star_octree/boundary.h>

#include <CGAL/PR_star_octree/Distributed_octree_3.h>
#include <CGAL/PR_star_octree/IO/distributed.h>
#include <CGAL/PR_star_octree/distributed_algorithms.h>
#include <CGAL/PR_star_octree/parameters.h>
#include <CGAL/property_map.h>

#include <mpi.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace prstar {

namespace {

using Distributed = CGAL::PR_star_octree::Distributed_octree_3<>;
namespace params = CGAL::PR_star_octree::parameters;
namespace PRS = CGAL::PR_star_octree;

int world_rank() {
  int r = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &r);
  return r;
}

// Reads this rank's part of the input and builds the distributed octree; the progress is shown by
// rank 0 only.
std::unique_ptr<Distributed> build(const Options& o, Progress_bar& progress) {
  int ranks = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  progress.phase("reading " + o.input() + " (" + std::to_string(ranks) + " ranks)");
  PRS::Distributed_mesh_part part = PRS::IO::read_mesh_part(o.input());
  progress.phase("partitioning and building the local octrees (k_v = " + bucket_size_string(o.kv()) + ")");
  // --compact and --coordinates as for one process; without either, plain tetrahedra (a rank
  // builds in place, never by streaming) and the coordinates as read (doubles)
  auto tree =
      std::make_unique<Distributed>(std::move(part), params::bucket_size(o.kv())
                                                         .maximum_depth(o.max_depth())
                                                         .compact_tetrahedra(o.compact())
                                                         .coordinate_precision(o.coordinate_precision()));
  // with --kv auto, each rank's octree chooses k_v for its own part: reported as "auto"
  o.set_used_kv(o.kv(), o.kv() == CGAL::PR_star_octree::automatic_bucket_size);
  return tree;
}

// Writes `arrays` (by part index, ghosts included) with the mesh: a .pvtu with one piece per rank,
// or any other format gathered on rank 0.
void write_output(const std::string& out, const Distributed& tree,
                  const std::vector<PRS::IO::Distributed_point_array>& arrays) {
  if (out.size() > 5 && out.substr(out.size() - 5) == ".pvtu") {
    PRS::IO::write_pvtu(out, tree, arrays);
    return;
  }
  const Mesh mesh = PRS::IO::gather_mesh(tree, arrays);
  PRS::internal::run_collectively(tree.communicator(), [&] {
    if (tree.rank() == 0) write_mesh_file(out, mesh);
  });
}

// Writes the curvature of a vertex into three arrays (by part index).
struct Curvature_put {
  using key_type = std::size_t;
  using value_type = PRS::Vertex_curvature;
  using reference = void;
  using category = boost::writable_property_map_tag;
  double *code, *distortion, *domain;
  friend void put(const Curvature_put& m, std::size_t i, const PRS::Vertex_curvature& c) {
    m.code[i] = vertex_type_code(c.type);
    m.distortion[i] = c.distortion;
    m.domain[i] = c.domain_curvature;
  }
};

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

int stats_distributed(const Options& o) {
  if (o.kvs().size() > 1) throw Usage_error("a list of k_v is not distributed yet: give one");
  if (!o.output("--octree").empty()) throw Usage_error("--octree is not distributed yet");
  Progress_bar progress(o.show_progress() && world_rank() == 0);
  const auto start = std::chrono::steady_clock::now();
  const auto tree = build(o, progress);
  progress.phase("counting edges and triangles");
  const PRS::Simplex_counts c = PRS::count_simplices(*tree, params::progress(progress.callback()));
  progress.finish();
  const double seconds = seconds_since(start);
  // the cost of the distribution, over the ranks
  const MPI_Comm comm = tree->communicator();
  std::uint64_t mine[4] = {tree->local_octree().number_of_tetrahedra(), tree->number_of_ghost_tetrahedra(),
                           tree->number_of_ghost_vertices(), tree->bytes_sent()},
                sum[4], most[4];
  MPI_Reduce(mine, sum, 4, MPI_UINT64_T, MPI_SUM, 0, comm);
  MPI_Reduce(mine, most, 4, MPI_UINT64_T, MPI_MAX, 0, comm);
  if (tree->rank() != 0) return exit_success;
  const double ghost_fraction = sum[0] ? double(sum[1]) / double(sum[0]) : 0.;
  if (o.json()) {
    Json j;
    j.begin_object().field("vertices", c.vertices).field("tetrahedra", c.tetrahedra);
    j.field("edges", c.edges)
        .field("triangles", c.triangles)
        .field("boundary_triangles", c.boundary_triangles);
    j.field("nonmanifold_triangles", c.nonmanifold_triangles);
    j.field("euler_characteristic", c.euler_characteristic()).key("kv");
    json_kv(j, o).field("ranks", tree->number_of_ranks());
    j.field("ghost_tetrahedra", sum[1])
        .field("ghost_fraction", ghost_fraction)
        .field("ghost_vertices", sum[2]);
    j.field("max_rank_tetrahedra", most[0]).field("bytes_sent", sum[3]);
    j.field("compact_tetrahedra", tree->local_octree().is_compact())
        .field("float32_coordinates", tree->local_octree().has_float_coordinates())
        .field("seconds", seconds);
    j.end_object();
    std::cout << j.str() << '\n';
    return exit_success;
  }
  std::cout << o.input() << ": " << c.vertices << " vertices, " << c.tetrahedra << " tetrahedra, on "
            << tree->number_of_ranks() << " ranks (k_v = " << o.kv_label() << ", " << fixed(seconds, 3)
            << " s)\n";
  std::cout << "  " << c.edges << " edges, " << c.triangles << " triangles (" << c.boundary_triangles
            << " on the boundary), Euler characteristic " << c.euler_characteristic() << "\n";
  if (c.nonmanifold_triangles)
    std::cout << "  warning: " << c.nonmanifold_triangles
              << " triangles are shared by three or more tetrahedra\n";
  Table t({"distribution", "value"});
  t.add({"ghost tetrahedra (all ranks)",
         std::to_string(sum[1]) + " (" + fixed(100. * ghost_fraction, 2) + "%)"});
  t.add({"ghost vertices (all ranks)", std::to_string(sum[2])});
  t.add({"largest rank", std::to_string(most[0]) + " tetrahedra"});
  t.add({"bytes sent (all ranks)", human_bytes(double(sum[3]))});
  t.add({"local octrees",
         std::string(tree->local_octree().is_compact() ? "compact" : "plain") + " tetrahedra, " +
             (tree->local_octree().has_float_coordinates() ? "float32" : "double") + " coordinates"});
  std::cout << t.str();
  return exit_success;
}

int boundary_distributed(const Options& o) {
  if (!o.output("--surface").empty()) throw Usage_error("--surface is not distributed yet");
  Progress_bar progress(o.show_progress() && world_rank() == 0);
  const auto start = std::chrono::steady_clock::now();
  const auto tree = build(o, progress);
  progress.phase("classifying the vertices");
  std::vector<double> codes(tree->number_of_local_vertices(), 3.);
  std::vector<PRS::Vertex_type> types(tree->number_of_owned_vertices());
  const PRS::Boundary_counts b =
      PRS::compute_boundary(*tree, CGAL::make_property_map(types), params::progress(progress.callback()));
  const double seconds = seconds_since(start);
  progress.finish();
  const std::string out = o.output();
  if (!out.empty()) {
    progress.phase("writing " + out);
    for (std::size_t i = 0; i < types.size(); ++i) codes[i] = vertex_type_code(types[i]);
    tree->update_ghosts(codes);
    write_output(out, *tree, {{"boundary", &codes}});
    progress.finish();
  }
  if (tree->rank() == 0)
    report_boundary(o, tree->number_of_vertices(), tree->number_of_tetrahedra(), b, seconds, -1,
                    tree->local_octree().is_compact());
  return exit_success;
}

int curvature_distributed(const Options& o) {
  Progress_bar progress(o.show_progress() && world_rank() == 0);
  const auto start = std::chrono::steady_clock::now();
  const auto tree = build(o, progress);
  // the field, by part index (ghosts included): a point array or a coordinate
  std::string field_name = o.get("--field");
  const int axis = (field_name == "x" || field_name == "y" || field_name == "z") ? field_name[0] - 'x' : -1;
  std::vector<double> coordinate;
  const std::vector<double>* field = nullptr;
  const auto& names = tree->point_array_names();
  if (axis >= 0) {
    const auto& octree = tree->local_octree();
    coordinate.resize(tree->number_of_local_vertices());
    for (Distributed::Index v = 0; v < octree.number_of_vertices(); ++v)
      coordinate[octree.original_vertex(v)] = octree.coordinates(octree.point(v))[axis];
    field = &coordinate;
  } else {
    const auto it = field_name.empty() ? names.begin() : std::find(names.begin(), names.end(), field_name);
    if (it == names.end()) {
      std::string known;
      for (const auto& n : names) known += (known.empty() ? "" : ", ") + n;
      throw PRS::Distributed_error(o.input() + ": " + // the same on every rank

                                   (field_name.empty() ? std::string("the mesh has no point data")
                                                       : "no point-data array named '" + field_name + "'") +
                                   (known.empty() ? "" : " (it has: " + known + ")") +
                                   "; use --field x|y|z for a coordinate");
    }
    field_name = *it;
    field = &tree->point_array(std::size_t(it - names.begin()));
    std::string error;
    for (std::size_t i = 0; i < tree->number_of_owned_vertices() && error.empty(); ++i)
      if (!std::isfinite((*field)[i]))
        error = o.input() + ": field '" + field_name + "' is not finite at vertex " +
                std::to_string(tree->global_vertex_id(i));
    PRS::internal::agree_on_errors(tree->communicator(), error);
  }
  progress.phase("computing the distortion");
  const std::size_t n = tree->number_of_local_vertices();
  std::vector<double> codes(n, 3.), distortion(n, 0.), domain(n, 0.);
  Curvature_put map{codes.data(), distortion.data(), domain.data()};
  PRS::compute_curvature(*tree, CGAL::make_property_map(*field), map, params::progress(progress.callback()));
  const double seconds = seconds_since(start);
  progress.finish();

  // the summary over the owned vertices of every rank, added exactly
  Curvature_summary mine;
  for (std::size_t i = 0; i < tree->number_of_owned_vertices(); ++i)
    mine.add(int(codes[i]), distortion[i], domain[i]);
  Curvature_summary summary;
  for (const auto& s : PRS::internal::all_gather(tree->communicator(), mine)) summary.add(s);

  const std::string out = o.output(), csv = o.output("--csv");
  if (!out.empty() || !csv.empty()) {
    tree->update_ghosts(codes);
    tree->update_ghosts(distortion);
    tree->update_ghosts(domain);
  }
  if (!csv.empty()) { // as one process writes it: in the input's order, nan where undefined
    progress.phase("writing " + csv);
    const Mesh mesh = PRS::IO::gather_mesh(
        *tree, {{"boundary", &codes}, {"distortion", &distortion}, {"domain_curvature", &domain}});
    PRS::internal::run_collectively(tree->communicator(), [&] {
      if (tree->rank() != 0) return;
      const auto& a = mesh.point_data;
      write_curvature_csv(csv, mesh.points.size(), [&](std::size_t v) {
        const auto& p = mesh.points[v];
        return Curvature_row{p.x(), p.y(), p.z(), int(a[0].values[v]), a[1].values[v], a[2].values[v]};
      });
    });
    progress.finish();
  }
  if (!out.empty()) {
    // as one process writes them: the undefined values (non-manifold vertices) as 0
    for (auto* a : {&distortion, &domain})
      for (double& x : *a)
        if (!std::isfinite(x)) x = 0;
    progress.phase("writing " + out);
    write_output(out, *tree,
                 {{"boundary", &codes}, {"distortion", &distortion}, {"domain_curvature", &domain}});
    progress.finish();
  }
  if (tree->rank() == 0)
    report_curvature(o, tree->number_of_vertices(), tree->number_of_tetrahedra(), field_name, summary,
                     seconds, tree->local_octree().is_compact());
  return exit_success;
}

int validate_distributed(const Options& o) {
  if (!o.output().empty())
    throw Usage_error("-o is not distributed: the problem lists are one-process only (run without mpirun)");
  Progress_bar progress(o.show_progress() && world_rank() == 0);
  const auto start = std::chrono::steady_clock::now();
  const auto tree = build(o, progress);
  progress.phase("checking the mesh");
  const PRS::Validity_result r = PRS::check_validity(*tree, params::progress(progress.callback()));
  const double seconds = seconds_since(start);
  progress.finish();
  if (tree->rank() != 0) return r.valid ? exit_success : exit_invalid_mesh;
  return report_validity(o, r, seconds, nullptr, tree->local_octree().is_compact());
}

} // namespace

void add_distributed_runs(std::vector<Command>& commands) {
  for (Command& c : commands) {
    if (c.name() == "stats") c.run_distributed(stats_distributed);
    if (c.name() == "boundary") c.run_distributed(boundary_distributed);
    if (c.name() == "curvature") c.run_distributed(curvature_distributed);
    if (c.name() == "validate") c.run_distributed(validate_distributed);
  }
}

} // namespace prstar
