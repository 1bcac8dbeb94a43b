// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// bench_topology: the scalar-field topology of scalar_topology.h (critical points, Forman gradient,
// Morse complexes) on the PR-star octree against a global implementation on the extended IA
// (baselines/topology_baseline.h), with compute_boundary() as the reference time.
//
// usage: bench_topology [--field NAME|analytic|auto] [--threads N] [--kv K] [--reps R]
//                       [--phases LIST] [--ia-orders file,prstar] [--limit-gb G] [--limit-seconds S]
//                       [--json] [--json-file OUT.json] MESH
//
// The mesh is read once.  Each phase then runs in its own forked child (R children per phase,
// the minimum time is reported), which builds its structure untimed (except for the build phases)
// and runs the phase once, so that each measurement is fresh and its peak RSS is its own:
//   build       PR-star octree construction (the mesh moved into it, k_v = --kv, no tetrahedron
//               permutation: the lean construction of bench_scale and of the prstar tool)
//   boundary    compute_boundary() (the vertex types; the reference of the targets)
//   critical    compute_critical_points()
//   gradient    compute_forman_gradient()
//   morse       compute_morse_complexes() (links, gradient, both segmentations, persistence pairs)
//   ia-build    the extended IA (TT and VT*, referencing the mesh's arrays; sequential)
//   ia-critical, ia-gradient, ia-segmentation   the baseline's (a), (b), (c) (TBB, same threads)
// The IA phases run on the file's vertex order and on the PR-star order (the mesh re-indexed by an
// octree with k_v = 100, as bench_relations does), since a locality-friendly order alone speeds up
// a global structure; package / IA ratios are given against both ("same order": PR-star).
//
// Memory, per child (Linux /proc/self/status; the child's peak is reset by /proc/self/clear_refs
// when it starts and again just before the phase):
//   peak RSS        the child's whole peak: the mesh and the field (in memory before the fork), the
//                   structure, the phase;
//   phase peak RSS  the peak during the phase alone (the mesh, the structure and the phase; the
//                   structure's construction transients excluded: the free heap is trimmed first);
//   phase extra     the peak during the phase minus the RSS just before it (structure built).
// The whole peak includes each structure's construction transients (the octree: one copy of V;
// the IA: its temporary full VT).  The JSON also gives "above input", the whole peak minus the RSS
// at the fork (bench_relations' "peak RSS").
// An IA child whose RSS exceeds --limit-gb (default 12) or whose run exceeds --limit-seconds
// (default 600) is killed and reported as skipped.
//
// The baseline must give the package's critical types and counts, its numbers of critical
// simplices per dimension (and the same simplices: an order-independent checksum) and the same Morse
// cells per vertex and per tetrahedron: each is printed as MATCH or MISMATCH.
//
// The field: --field NAME takes the point-data array NAME; "analytic" is a sum of sines and cosines
// of the coordinates (scaled to the bounding box) plus a deterministic noise hashed from each
// vertex's coordinates, of amplitude 1e-3 of the smooth field's range; "auto" (default) takes the
// mesh's first point-data array, else the analytic field.

#include <CGAL/PR_star_octree.h>
#include <CGAL/PR_star_octree/IO.h>
#include <CGAL/PR_star_octree/boundary.h>
#include <CGAL/PR_star_octree/parameters.h>
#include <CGAL/PR_star_octree/scalar_topology.h>
#include <CGAL/property_map.h>

#include "baselines/Extended_IA.h"
#include "baselines/topology_baseline.h"
#include "bench_util.h"

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#endif

#include <malloc.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace {

using prstar_bench::base_name;
using prstar_bench::now;
using prstar_bench::status_kib;

using Mesh = CGAL::PR_star_octree::Indexed_tetrahedral_mesh<>;
using Octree = CGAL::PR_star_octree_3<>;
using Index = std::uint32_t;
using IA = prstar_baselines::Extended_IA<Index>;
namespace params = CGAL::PR_star_octree::parameters;
namespace PSO = CGAL::PR_star_octree;
namespace topo = prstar_baselines::topology;
using topo::mix;

enum Phase {
  BUILD,
  BOUNDARY,
  CRITICAL,
  GRADIENT,
  MORSE,
  IA_BUILD,
  IA_CRITICAL,
  IA_GRADIENT,
  IA_SEGMENTATION
};
const char* const phase_key[] = {"build",    "boundary",    "critical",    "gradient",       "morse",
                                 "ia-build", "ia-critical", "ia-gradient", "ia-segmentation"};
const char* const phase_title[] = {"octree build",
                                   "compute_boundary",
                                   "critical points",
                                   "Forman gradient",
                                   "Morse complexes (+ persistence)",
                                   "IA build (TT, VT*)",
                                   "critical points",
                                   "Forman gradient",
                                   "segmentation (gradient + cells)"};
constexpr int number_of_phases = 9;
bool is_ia(int p) {
  return p >= IA_BUILD;
}

// What one child measures.
struct Result {
  int status = -1; // 0 ok, 1 failed, 2 killed (memory), 3 killed (time), -1 not run
  double seconds = 0;
  std::size_t start_rss = 0, process_peak = 0, phase_peak = 0, phase_extra = 0, stored_bytes = 0;
  std::uint64_t check[12] = {};
  char message[160] = {};
  std::size_t above_input() const { return process_peak > start_rss ? process_peak - start_rss : 0; }
};

struct Options {
  std::string field = "auto";
  std::size_t threads = 2, kv = Octree::default_bucket_size;
  int reps = 1;
  std::vector<bool> phases = std::vector<bool>(number_of_phases, true);
  bool ia_file = true, ia_prstar = true;
  double limit_gb = 12, limit_seconds = 600;
  bool json = false;
  std::string json_file, mesh;
};

std::size_t rss_now() {
  return status_kib("VmRSS:") * 1024;
}
std::size_t hwm_now() {
  return status_kib("VmHWM:") * 1024;
}
void reset_peak() {
  std::ofstream("/proc/self/clear_refs") << "5";
}

// Runs `job(result)` in a forked child; the parent watches its RSS and time and kills it beyond
// the limits (0: none).
template <class Job>
Result in_watched_child(Job&& job, std::size_t limit_bytes, double limit_seconds) {
  int fd[2];
  Result r;
  if (pipe(fd) != 0) {
    r.status = 1;
    std::snprintf(r.message, sizeof r.message, "pipe failed");
    return r;
  }
  std::cout.flush();
  std::cerr.flush();
  const pid_t pid = fork();
  if (pid == 0) {
    close(fd[0]);
    reset_peak();
    Result c;
    c.start_rss = rss_now();
    try {
      job(c);
      c.status = 0;
    } catch (const std::exception& e) {
      c.status = 1;
      std::snprintf(c.message, sizeof c.message, "%s", e.what());
    }
    if (write(fd[1], &c, sizeof c) != static_cast<ssize_t>(sizeof c)) _exit(1);
    _exit(0);
  }
  close(fd[1]);
  const double t0 = now();
  int status = 0, killed = 0;
  const std::string status_file = "/proc/" + std::to_string(pid) + "/status";
  for (;;) {
    const pid_t w = waitpid(pid, &status, WNOHANG);
    if (w == pid) break;
    if (killed == 0) {
      std::size_t rss = 0;
      std::ifstream f(status_file);
      std::string line;
      while (std::getline(f, line))
        if (line.rfind("VmRSS:", 0) == 0) rss = std::stoull(line.substr(6)) * 1024;
      if (limit_bytes > 0 && rss > limit_bytes)
        killed = 2;
      else if (limit_seconds > 0 && now() - t0 > limit_seconds)
        killed = 3;
      if (killed) kill(pid, SIGKILL);
    }
    usleep(20000);
  }
  Result c;
  const ssize_t n = read(fd[0], &c, sizeof c);
  close(fd[0]);
  if (killed) {
    r.status = killed;
    std::snprintf(r.message, sizeof r.message, "%s",
                  killed == 2 ? "killed: RSS over the limit" : "killed: over the time limit");
    r.seconds = now() - t0;
    return r;
  }
  if (n != static_cast<ssize_t>(sizeof c) || WIFSIGNALED(status)) {
    r.status = 1;
    std::snprintf(r.message, sizeof r.message, "the child failed%s",
                  WIFSIGNALED(status) ? (" (signal " + std::to_string(WTERMSIG(status)) + ")").c_str() : "");
    return r;
  }
  return c;
}

// The thread limit and a warm TBB pool in the child (the parent never starts TBB before forking).
struct Threads {
#ifdef CGAL_LINKED_WITH_TBB
  tbb::global_control control;
  explicit Threads(std::size_t n) : control(tbb::global_control::max_allowed_parallelism, n) {
    tbb::parallel_for(0, static_cast<int>(4 * n), [](int) {});
  }
#else
  explicit Threads(std::size_t) {}
#endif
};

// Times `phase()` once after the structure exists, filling the memory figures.
template <class F>
void measure(Result& r, F&& phase) {
  const std::size_t before = hwm_now();
  malloc_trim(0); // the free heap pages of the structure's construction are not counted as in use
  reset_peak();
  const std::size_t base = rss_now();
  const double t0 = now();
  phase();
  r.seconds = now() - t0;
  const std::size_t after = hwm_now();
  r.phase_peak = after;
  r.phase_extra = after > base ? after - base : 0;
  r.process_peak = (std::max)(before, after);
}

// ---- the checks: order-independent checksums in the user's vertex indices ----------------------

void critical_checks(Result& r, const PSO::Critical_point_counts& c) {
  r.check[0] = c.minima;
  r.check[1] = c.saddles_1;
  r.check[2] = c.saddles_2;
  r.check[3] = c.maxima;
  r.check[4] = c.degenerate;
  r.check[5] = c.regular;
  r.check[6] = c.unreferenced;
}
std::uint64_t type_hash(std::uint64_t user, PSO::Critical_type t) {
  return mix(mix(user) ^ static_cast<std::uint64_t>(t));
}
std::uint64_t label_hash(std::uint64_t key, std::uint64_t label) {
  return mix(key ^ mix(label));
}

// ---- the phases --------------------------------------------------------------------------------

struct Input {
  Mesh* mesh;                       // the mesh in the parent (moved into the octree by a package child)
  const std::vector<double>* field; // in the mesh's numbering
  const std::vector<Index>* key;    // the user's index of each vertex (PR-star order), or null
};

void run_package(Phase p, const Input& in, const Options& o, Result& r) {
  Threads threads(o.threads);
  const std::vector<double>& field = *in.field;
  const auto field_map = CGAL::make_property_map(field);
  const auto np = params::bucket_size(o.kv).tetrahedron_permutation(false);
  std::unique_ptr<Octree> tree;
  if (p == BUILD) {
    measure(r, [&] { tree = std::make_unique<Octree>(std::move(*in.mesh), np); });
    r.check[0] = tree->statistics().leaves;
    r.stored_bytes = tree->statistics().bytes.total();
    return;
  }
  tree = std::make_unique<Octree>(std::move(*in.mesh), np);
  const std::size_t nv = tree->number_of_vertices(), nt = tree->number_of_tetrahedra();
  if (p == BOUNDARY) {
    std::vector<PSO::Vertex_type> types(nv);
    PSO::Boundary_counts b;
    measure(r, [&] { b = PSO::compute_boundary(*tree, CGAL::make_property_map(types)); });
    r.check[0] = b.boundary_vertices;
  } else if (p == CRITICAL) {
    std::vector<PSO::Critical_type> types(nv);
    PSO::Critical_point_counts c;
    measure(r, [&] { c = PSO::compute_critical_points(*tree, field_map, CGAL::make_property_map(types)); });
    critical_checks(r, c);
    for (std::size_t v = 0; v < nv; ++v) r.check[7] += type_hash(v, types[v]);
  } else if (p == GRADIENT) {
    std::unique_ptr<PSO::Forman_gradient<Octree>> g;
    measure(r, [&] {
      g = std::make_unique<PSO::Forman_gradient<Octree>>(PSO::compute_forman_gradient(*tree, field_map));
    });
    for (int d = 0; d < 4; ++d) r.check[d] = g->number_of_critical_simplices(d);
    for (const auto& c : g->critical_simplices()) {
      std::array<std::uint64_t, 4> u{};
      for (int i = 0; i <= c.dimension; ++i) u[i] = c.vertices[i];
      r.check[4] += topo::simplex_hash(u, c.dimension + 1);
    }
    r.check[5] = static_cast<std::uint64_t>(g->alternating_sum());
    r.stored_bytes = g->memory_bytes();
  } else if (p == MORSE) {
    std::unique_ptr<PSO::Morse_complexes<Octree>> m;
    measure(r, [&] {
      m = std::make_unique<PSO::Morse_complexes<Octree>>(PSO::compute_morse_complexes(*tree, field_map));
    });
    for (int d = 0; d < 4; ++d) r.check[d] = m->gradient.number_of_critical_simplices(d);
    for (const auto& c : m->gradient.critical_simplices()) {
      std::array<std::uint64_t, 4> u{};
      for (int i = 0; i <= c.dimension; ++i) u[i] = c.vertices[i];
      r.check[4] += topo::simplex_hash(u, c.dimension + 1);
    }
    for (std::size_t v = 0; v < nv; ++v) r.check[5] += label_hash(mix(v), m->ascending_cell[v]);
    for (std::size_t t = 0; t < nt; ++t) { // the octree's tetrahedron t: its vertices in the user's numbering
      std::array<std::uint64_t, 4> u{};
      for (int i = 0; i < 4; ++i) u[i] = tree->original_vertex(tree->tetrahedron(static_cast<Index>(t))[i]);
      r.check[6] += label_hash(topo::simplex_hash(u, 4), m->descending_cell[t]);
    }
    r.check[7] = m->ascending_cells;
    r.check[8] = m->descending_cells;
    r.check[9] = m->outflow_tetrahedra;
    r.check[10] = m->persistence_pairs.size();
    r.stored_bytes = m->gradient.memory_bytes();
  }
}

void run_ia(Phase p, const Input& in, const Options& o, Result& r) {
  Threads threads(o.threads);
  const Mesh& mesh = *in.mesh;
  const std::size_t nv = mesh.points.size(), nt = mesh.tetrahedra.size();
  const topo::Vertex_order<Index> order{in.field->data(), in.key ? in.key->data() : nullptr};
  std::unique_ptr<IA> ia;
  if (p == IA_BUILD) {
    measure(r, [&] { ia = std::make_unique<IA>(nv, mesh.tetrahedra); });
    r.stored_bytes = ia->overhead_bytes();
    return;
  }
  ia = std::make_unique<IA>(nv, mesh.tetrahedra);
  if (p == IA_CRITICAL) {
    std::vector<PSO::Critical_type> types(nv);
    PSO::Critical_point_counts c;
    measure(r, [&] { c = topo::critical_points(*ia, order, types); });
    critical_checks(r, c);
    for (std::size_t v = 0; v < nv; ++v) r.check[7] += type_hash(order.user(static_cast<Index>(v)), types[v]);
  } else if (p == IA_GRADIENT) {
    std::unique_ptr<topo::Gradient<Index>> g;
    measure(r, [&] {
      g = std::make_unique<topo::Gradient<Index>>();
      topo::forman_gradient(*ia, order, *g);
    });
    for (int d = 0; d < 4; ++d) r.check[d] = g->counts[static_cast<std::size_t>(d)];
    r.check[4] = g->critical_hash;
    r.check[5] = static_cast<std::uint64_t>(g->alternating_sum());
    r.stored_bytes = g->memory_bytes();
  } else if (p == IA_SEGMENTATION) {
    std::unique_ptr<topo::Segmentation<Index>> s;
    measure(r, [&] {
      s = std::make_unique<topo::Segmentation<Index>>();
      topo::segmentation(*ia, order, *s);
    });
    for (int d = 0; d < 4; ++d) r.check[d] = s->gradient.counts[static_cast<std::size_t>(d)];
    r.check[4] = s->gradient.critical_hash;
    for (std::size_t v = 0; v < nv; ++v)
      r.check[5] += label_hash(mix(order.user(static_cast<Index>(v))), s->ascending_cell[v]);
    for (std::size_t t = 0; t < nt; ++t) {
      std::array<std::uint64_t, 4> u{};
      for (int i = 0; i < 4; ++i) u[i] = order.user(mesh.tetrahedra[t][i]);
      r.check[6] += label_hash(topo::simplex_hash(u, 4), s->descending_cell[t]);
    }
    r.check[7] = s->ascending_cells;
    r.check[8] = s->descending_cells;
    r.check[9] = s->outflow_tetrahedra;
    r.stored_bytes = s->gradient.memory_bytes();
  }
}

// The best of `reps` children: the minimum time; the largest peaks.
Result run_phase(Phase p, const Input& in, const Options& o, const std::string& label) {
  Result best;
  for (int k = 0; k < o.reps; ++k) {
    std::cerr << "  " << label << ' ' << phase_key[p] << " (" << k + 1 << '/' << o.reps << ") ..."
              << std::flush;
    const std::size_t limit = is_ia(p) ? static_cast<std::size_t>(o.limit_gb * 1073741824.0) : 0;
    const double seconds = is_ia(p) ? o.limit_seconds : 0;
    const Result r = in_watched_child(
        [&](Result& c) { is_ia(p) ? run_ia(p, in, o, c) : run_package(p, in, o, c); }, limit, seconds);
    std::cerr << ' ' << (r.status == 0 ? std::to_string(r.seconds) + " s" : std::string(r.message)) << '\n';
    if (r.status != 0) return r;
    if (best.status != 0) {
      best = r;
      continue;
    }
    const std::size_t peak = (std::max)(best.process_peak, r.process_peak),
                      extra = (std::max)(best.phase_extra, r.phase_extra),
                      phase_peak = (std::max)(best.phase_peak, r.phase_peak),
                      start = (std::min)(best.start_rss, r.start_rss);
    if (r.seconds < best.seconds) best = r;
    best.process_peak = peak;
    best.phase_extra = extra;
    best.phase_peak = phase_peak;
    best.start_rss = start;
  }
  return best;
}

// ---- the field ---------------------------------------------------------------------------------

std::vector<double> analytic_field(const Mesh& m, std::string& description) {
  const std::size_t nv = m.points.size();
  std::array<double, 3> lo{{0, 0, 0}}, hi{{0, 0, 0}};
  for (std::size_t v = 0; v < nv; ++v)
    for (int a = 0; a < 3; ++a) {
      const double c = m.points[v][a];
      lo[a] = v == 0 ? c : (std::min)(lo[a], c);
      hi[a] = v == 0 ? c : (std::max)(hi[a], c);
    }
  const double extent = (std::max)({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2], 1e-300});
  const double pi = 3.14159265358979323846;
  std::vector<double> f(nv);
  double fmin = 0, fmax = 0;
  for (std::size_t v = 0; v < nv; ++v) {
    const double u = (m.points[v][0] - lo[0]) / extent, w = (m.points[v][1] - lo[1]) / extent,
                 z = (m.points[v][2] - lo[2]) / extent;
    f[v] = std::sin(3 * pi * u) * std::cos(2 * pi * w) + std::sin(2 * pi * (z + 0.5 * u)) +
           0.5 * std::cos(5 * pi * w + 1.0);
    fmin = v == 0 ? f[v] : (std::min)(fmin, f[v]);
    fmax = v == 0 ? f[v] : (std::max)(fmax, f[v]);
  }
  const double amplitude = 1e-3 * (fmax - fmin);
  for (std::size_t v = 0; v < nv; ++v) {
    std::uint64_t h = 0;
    for (int a = 0; a < 3; ++a) {
      const double c = m.points[v][a];
      std::uint64_t bits;
      std::memcpy(&bits, &c, sizeof bits);
      h = mix(h ^ bits);
    }
    f[v] += amplitude * (static_cast<double>(h >> 11) / 9007199254740992.0 * 2 - 1);
  }
  description = "analytic: sin(3 pi u) cos(2 pi v) + sin(2 pi (w + u/2)) + cos(5 pi v + 1)/2 (u, v, w the "
                "coordinates over the largest extent) + hashed noise of amplitude 1e-3 of its range";
  return f;
}

// ---- output ------------------------------------------------------------------------------------

std::string fmt(const char* f, double v) {
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}
std::string mib(std::size_t bytes) {
  return fmt("%.1f", double(bytes) / 1048576.0);
}
std::string grouped(std::size_t n) {
  std::string s = std::to_string(n), r;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (i && (s.size() - i) % 3 == 0) r += ',';
    r += s[i];
  }
  return r;
}
std::string json_string(const std::string& s) {
  std::string r = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') r += '\\';
    r += c;
  }
  return r + "\"";
}

struct Run {
  std::string name, field_description;
  std::size_t vertices = 0, tetrahedra = 0, input_rss = 0;
  double field_min = 0, field_max = 0, read_seconds = 0;
  Result pkg[5];
  Result ia[2][4]; // [file, prstar][build, critical, gradient, segmentation]
  bool ia_run[2] = {false, false};
};

const char* const order_name[] = {"file", "PR-star"};

bool same(const Result& a, const Result& b, int from, int to) {
  for (int i = from; i < to; ++i)
    if (a.check[i] != b.check[i]) return false;
  return true;
}

// MATCH / MISMATCH / "-" (not both measured)
std::string verdict(const Result& a, const Result& b, int from, int to) {
  if (a.status != 0 || b.status != 0) return "-";
  return same(a, b, from, to) ? "MATCH" : "MISMATCH";
}

double ratio(double a, double b) {
  return b > 0 ? a / b : 0;
}

void print_table(const Run& run, const Options& o, std::ostream& out) {
  const Result& boundary = run.pkg[BOUNDARY];
  out << "### " << run.name << ": " << grouped(run.vertices) << " vertices, " << grouped(run.tetrahedra)
      << " tetrahedra\n\n"
      << "field: " << run.field_description << " (range " << fmt("%.6g", run.field_min) << " to "
      << fmt("%.6g", run.field_max) << "); " << o.threads << " threads; k_v = " << o.kv << "; "
      << (o.reps > 1 ? "best of " + std::to_string(o.reps) + " runs" : std::string("one run"))
      << " per phase, each in a fresh process; mesh and field in memory before the phases: "
      << mib(run.input_rss) << " MiB RSS\n\n";
  out << "| phase | structure | order | time s | / boundary | peak RSS MiB | phase peak RSS MiB | phase "
         "extra MiB | phase extra B/tet |\n|---|---|---|---:|---:|---:|---:|---:|---:|\n";
  const double T = double(run.tetrahedra);
  auto row = [&](const char* phase, const char* structure, const char* order, const Result& r) {
    out << "| " << phase << " | " << structure << " | " << order << " | ";
    if (r.status == -1) {
      out << "not run | | | | | |\n";
      return;
    }
    if (r.status != 0) {
      out << "skipped (" << r.message << ") | | | | | |\n";
      return;
    }
    out << fmt("%.3f", r.seconds) << " | "
        << (boundary.status == 0 ? fmt("%.2f", ratio(r.seconds, boundary.seconds)) : "-") << " | "
        << mib(r.process_peak) << " | " << mib(r.phase_peak) << " | " << mib(r.phase_extra) << " | "
        << fmt("%.1f", double(r.phase_extra) / T) << " |\n";
  };
  for (int p = BUILD; p <= MORSE; ++p) row(phase_title[p], "PR-star", "-", run.pkg[p]);
  for (int k = 0; k < 2; ++k)
    if (run.ia_run[k])
      for (int p = 0; p < 4; ++p) row(phase_title[IA_BUILD + p], "extended IA", order_name[k], run.ia[k][p]);
  out << '\n';

  // package / IA, per phase and with each structure's construction added ("+ build")
  out << "| package / IA | IA order | time | time + build | peak RSS | phase peak RSS | phase extra "
         "|\n|---|---|---:|---:|---:|---:|---:|\n";
  const char* pair_name[] = {"octree build / IA build", "critical points", "Forman gradient",
                             "Morse complexes / segmentation"};
  const int pkg_phase[] = {BUILD, CRITICAL, GRADIENT, MORSE};
  auto measured = [&](int i, int k) {
    return run.pkg[pkg_phase[i]].status == 0 && run.ia[k][i].status == 0 && run.pkg[BUILD].status == 0 &&
           run.ia[k][0].status == 0;
  };
  auto with_build = [&](int i, int k) {
    if (i == 0) return ratio(run.pkg[BUILD].seconds, run.ia[k][0].seconds);
    return ratio(run.pkg[pkg_phase[i]].seconds + run.pkg[BUILD].seconds,
                 run.ia[k][i].seconds + run.ia[k][0].seconds);
  };
  for (int k = 1; k >= 0; --k) {
    if (!run.ia_run[k]) continue;
    for (int i = 0; i < 4; ++i) {
      const Result &a = run.pkg[pkg_phase[i]], &b = run.ia[k][i];
      out << "| " << pair_name[i] << " | " << order_name[k] << " | ";
      if (!measured(i, k)) {
        out << "- | - | - | - | - |\n";
        continue;
      }
      out << fmt("%.2f", ratio(a.seconds, b.seconds)) << " | " << fmt("%.2f", with_build(i, k)) << " | "
          << fmt("%.2f", ratio(double(a.process_peak), double(b.process_peak))) << " | "
          << fmt("%.2f", ratio(double(a.phase_peak), double(b.phase_peak))) << " | "
          << fmt("%.2f", ratio(double(a.phase_extra), double(b.phase_extra))) << " |\n";
    }
  }
  out << '\n';

  // the targets of the issue
  const Result &crit = run.pkg[CRITICAL], &grad = run.pkg[GRADIENT];
  auto met = [](bool ok) { return ok ? "yes" : "**no**"; };
  out << "| target | measured | met |\n|---|---|---|\n";
  if (crit.status == 0 && boundary.status == 0)
    out << "| critical points <= 1.0x boundary | " << fmt("%.2f", ratio(crit.seconds, boundary.seconds))
        << "x | " << met(crit.seconds <= boundary.seconds) << " |\n";
  if (grad.status == 0 && boundary.status == 0)
    out << "| Forman gradient <= 2x boundary | " << fmt("%.2f", ratio(grad.seconds, boundary.seconds))
        << "x | " << met(grad.seconds <= 2 * boundary.seconds) << " |\n";
  if (grad.status == 0)
    out << "| gradient extra memory <= 4 B/tet | stored " << fmt("%.2f", double(grad.stored_bytes) / T)
        << " B/tet; phase extra peak " << fmt("%.2f", double(grad.phase_extra) / T) << " B/tet | "
        << met(double(grad.stored_bytes) / T <= 4.0) << " (stored), "
        << met(double(grad.phase_extra) / T <= 4.0) << " (peak) |\n";
  for (int i = 1; i < 4; ++i) {
    std::string time, peak, time_met, peak_met;
    for (int k = 1; k >= 0; --k) {
      if (!run.ia_run[k] || !measured(i, k)) continue;
      const Result &a = run.pkg[pkg_phase[i]], &b = run.ia[k][i];
      const std::string sep = time.empty() ? "" : "; ";
      time += sep + fmt("%.2f", ratio(a.seconds, b.seconds)) + "x (" + order_name[k] +
              " order; with the builds " + fmt("%.2f", with_build(i, k)) + "x)";
      peak += sep + fmt("%.2f", ratio(double(a.process_peak), double(b.process_peak))) + "x (" +
              order_name[k] + " order; phase peak " +
              fmt("%.2f", ratio(double(a.phase_peak), double(b.phase_peak))) + "x)";
      time_met += (time_met.empty() ? "" : " / ") + std::string(met(a.seconds <= b.seconds));
      peak_met += (peak_met.empty() ? "" : " / ") + std::string(met(2 * a.process_peak <= b.process_peak));
    }
    if (time.empty()) continue;
    out << "| " << pair_name[i] << ": package / IA time <= 1.0x | " << time << " | " << time_met << " |\n";
    out << "| " << pair_name[i] << ": package / IA peak RSS <= 0.5x | " << peak << " | " << peak_met
        << " |\n";
  }
  out << '\n';

  // the checks
  out << "| check (package vs IA) |";
  for (int i = 0; i < 2; ++i)
    if (run.ia_run[i]) out << " IA " << order_name[i] << " order |";
  out << "\n|---|";
  for (int i = 0; i < 2; ++i)
    if (run.ia_run[i]) out << "---|";
  out << '\n';
  auto check_row = [&](const char* what, int pkg, int ia, int from, int to) {
    out << "| " << what << " |";
    for (int i = 0; i < 2; ++i)
      if (run.ia_run[i]) out << ' ' << verdict(run.pkg[pkg], run.ia[i][ia], from, to) << " |";
    out << '\n';
  };
  check_row("critical type of every vertex, counts per type", CRITICAL, 1, 0, 8);
  check_row("critical simplices per dimension", GRADIENT, 2, 0, 4);
  check_row("the critical simplices themselves (checksum)", GRADIENT, 2, 4, 5);
  check_row("gradient of the Morse run: critical simplices", MORSE, 3, 0, 5);
  check_row("ascending cell of every vertex", MORSE, 3, 5, 6);
  check_row("descending cell of every tetrahedron, outflow", MORSE, 3, 6, 7);
  check_row("numbers of ascending / descending cells, outflow", MORSE, 3, 7, 10);
  out << '\n';
  if (crit.status == 0)
    out << "critical points: " << crit.check[0] << " minima, " << crit.check[1] << " 1-saddles, "
        << crit.check[2] << " 2-saddles, " << crit.check[3] << " maxima, " << crit.check[4]
        << " degenerate; ";
  if (grad.status == 0)
    out << "critical simplices " << grad.check[0] << " / " << grad.check[1] << " / " << grad.check[2] << " / "
        << grad.check[3] << " (alternating sum " << static_cast<long long>(grad.check[5]) << "); ";
  const Result& m = run.pkg[MORSE];
  if (m.status == 0)
    out << m.check[7] << " ascending and " << m.check[8] << " descending cells, " << m.check[9]
        << " outflow tetrahedra, " << m.check[10] << " persistence pairs";
  out << "\n\n";
}

void print_json(const Run& run, const Options& o, std::ostream& out) {
  auto result = [&](const Result& r) {
    std::ostringstream s;
    s << "{\"status\": " << json_string(r.status == 0 ? "ok" : r.status == -1 ? "not run" : r.message);
    if (r.status == 0) {
      s << ", \"seconds\": " << r.seconds << ", \"peak_rss_bytes\": " << r.process_peak
        << ", \"above_input_bytes\": " << r.above_input() << ", \"phase_peak_rss_bytes\": " << r.phase_peak
        << ", \"phase_extra_bytes\": " << r.phase_extra << ", \"stored_bytes\": " << r.stored_bytes
        << ", \"checks\": [";
      for (int i = 0; i < 12; ++i) s << (i ? ", " : "") << r.check[i];
      s << ']';
    }
    s << '}';
    return s.str();
  };
  out << "{\"mesh\": " << json_string(run.name) << ", \"vertices\": " << run.vertices
      << ", \"tetrahedra\": " << run.tetrahedra << ", \"field\": " << json_string(run.field_description)
      << ", \"field_min\": " << run.field_min << ", \"field_max\": " << run.field_max
      << ", \"threads\": " << o.threads << ", \"kv\": " << o.kv << ", \"reps\": " << o.reps
      << ", \"read_seconds\": " << run.read_seconds << ", \"input_rss_bytes\": " << run.input_rss
      << ",\n \"package\": {";
  for (int p = BUILD; p <= MORSE; ++p)
    out << (p ? ",\n   " : "") << json_string(phase_key[p]) << ": " << result(run.pkg[p]);
  out << "}";
  for (int k = 0; k < 2; ++k) {
    if (!run.ia_run[k]) continue;
    out << ",\n \"ia_" << (k ? "prstar" : "file") << "_order\": {";
    for (int p = 0; p < 4; ++p)
      out << (p ? ",\n   " : "") << json_string(phase_key[IA_BUILD + p]) << ": " << result(run.ia[k][p]);
    out << "}";
  }
  const Result &b = run.pkg[BOUNDARY], &c = run.pkg[CRITICAL], &g = run.pkg[GRADIENT];
  const double T = double(run.tetrahedra);
  out << ",\n \"ratios\": {\"critical_over_boundary\": "
      << (b.status == 0 && c.status == 0 ? ratio(c.seconds, b.seconds) : 0)
      << ", \"gradient_over_boundary\": "
      << (b.status == 0 && g.status == 0 ? ratio(g.seconds, b.seconds) : 0)
      << ", \"gradient_stored_bytes_per_tet\": " << (g.status == 0 ? double(g.stored_bytes) / T : 0)
      << ", \"gradient_phase_extra_bytes_per_tet\": " << (g.status == 0 ? double(g.phase_extra) / T : 0);
  const int pkg_phase[] = {BUILD, CRITICAL, GRADIENT, MORSE};
  for (int k = 0; k < 2; ++k) {
    if (!run.ia_run[k]) continue;
    for (int i = 0; i < 4; ++i) {
      const Result &x = run.pkg[pkg_phase[i]], &y = run.ia[k][i];
      if (x.status != 0 || y.status != 0) continue;
      const std::string n = std::string(phase_key[pkg_phase[i]]) + "_over_ia_" + (k ? "prstar" : "file");
      const Result &xb = run.pkg[BUILD], &yb = run.ia[k][0];
      if (i > 0 && xb.status == 0 && yb.status == 0)
        out << ", " << json_string(n + "_time_with_builds") << ": "
            << ratio(x.seconds + xb.seconds, y.seconds + yb.seconds);
      out << ", " << json_string(n + "_time") << ": " << ratio(x.seconds, y.seconds) << ", "
          << json_string(n + "_peak_rss") << ": " << ratio(double(x.process_peak), double(y.process_peak))
          << ", " << json_string(n + "_above_input") << ": "
          << ratio(double(x.above_input()), double(y.above_input())) << ", "
          << json_string(n + "_phase_peak_rss") << ": " << ratio(double(x.phase_peak), double(y.phase_peak));
    }
  }
  out << "},\n \"checks\": {";
  bool first = true;
  for (int k = 0; k < 2; ++k) {
    if (!run.ia_run[k]) continue;
    const std::string s = k ? "_prstar" : "_file";
    const std::pair<const char*, std::string> v[] = {
        {"critical_types", verdict(run.pkg[CRITICAL], run.ia[k][1], 0, 8)},
        {"critical_simplices", verdict(run.pkg[GRADIENT], run.ia[k][2], 0, 5)},
        {"morse_cells", verdict(run.pkg[MORSE], run.ia[k][3], 0, 10)}};
    for (const auto& e : v) {
      out << (first ? "" : ", ") << json_string(e.first + s) << ": " << json_string(e.second);
      first = false;
    }
  }
  out << "}}\n";
}

[[noreturn]] void usage() {
  std::cerr
      << "usage: bench_topology [--field NAME|analytic|auto] [--threads N] [--kv K] [--reps R]\n"
         "                      [--phases build,boundary,critical,gradient,morse,ia-build,ia-critical,\n"
         "                                ia-gradient,ia-segmentation] [--ia-orders file,prstar]\n"
         "                      [--limit-gb G] [--limit-seconds S] [--json] [--json-file OUT] MESH\n";
  std::exit(2);
}

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> r;
  std::stringstream in(s);
  std::string item;
  while (std::getline(in, item, ',')) r.push_back(item);
  return r;
}

} // namespace

int main(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) usage();
      return argv[++i];
    };
    if (a == "--field")
      o.field = value();
    else if (a == "--threads")
      o.threads = std::max<std::size_t>(1, std::stoull(value()));
    else if (a == "--kv") {
      const std::string k = value();
      o.kv = k == "inf" ? Octree::infinite_bucket_size : std::stoull(k);
    } else if (a == "--reps")
      o.reps = std::max(1, std::atoi(value().c_str()));
    else if (a == "--limit-gb")
      o.limit_gb = std::atof(value().c_str());
    else if (a == "--limit-seconds")
      o.limit_seconds = std::atof(value().c_str());
    else if (a == "--json")
      o.json = true;
    else if (a == "--json-file")
      o.json_file = value();
    else if (a == "--phases") {
      o.phases.assign(number_of_phases, false);
      for (const std::string& p : split(value())) {
        const auto it = std::find(std::begin(phase_key), std::end(phase_key), p);
        if (it == std::end(phase_key)) usage();
        o.phases[static_cast<std::size_t>(it - std::begin(phase_key))] = true;
      }
    } else if (a == "--ia-orders") {
      o.ia_file = o.ia_prstar = false;
      for (const std::string& s : split(value())) {
        if (s == "file")
          o.ia_file = true;
        else if (s == "prstar")
          o.ia_prstar = true;
        else
          usage();
      }
    } else if (!a.empty() && a[0] == '-')
      usage();
    else if (o.mesh.empty())
      o.mesh = a;
    else
      usage();
  }
  if (o.mesh.empty()) usage();

  Run run;
  run.name = base_name(o.mesh);
  auto mesh = std::make_unique<Mesh>();
  std::vector<double> field;
  try {
    const double t0 = now();
    PSO::IO::read_tetrahedral_mesh(o.mesh, *mesh);
    run.read_seconds = now() - t0;
    std::string name = o.field;
    if (name == "auto") name = mesh->point_data.empty() ? "analytic" : mesh->point_data.front().name;
    if (name == "analytic") {
      field = analytic_field(*mesh, run.field_description);
    } else {
      const auto* a = mesh->find_point_data(name);
      if (!a) throw std::runtime_error(o.mesh + ": no point-data array named '" + name + "'");
      field = a->values;
      run.field_description = "point array '" + name + "'";
    }
  } catch (const std::exception& e) {
    std::cerr << e.what() << '\n';
    return 1;
  }
  mesh->point_data.clear();
  mesh->point_data.shrink_to_fit();
  mesh->cell_data.clear();
  malloc_trim(0);
  run.vertices = mesh->points.size();
  run.tetrahedra = mesh->tetrahedra.size();
  {
    std::vector<char> used(run.vertices, 0);
    for (const auto& t : mesh->tetrahedra)
      for (Index v : t) used[v] = 1;
    bool first = true;
    for (std::size_t v = 0; v < run.vertices; ++v)
      if (used[v]) {
        run.field_min = first ? field[v] : (std::min)(run.field_min, field[v]);
        run.field_max = first ? field[v] : (std::max)(run.field_max, field[v]);
        first = false;
      }
  }
  run.input_rss = rss_now();
  std::cerr << run.name << ": " << run.vertices << " vertices, " << run.tetrahedra << " tetrahedra, read in "
            << run.read_seconds << " s; field: " << run.field_description << '\n';

  Input file_input{mesh.get(), &field, nullptr};
  for (int p = BUILD; p <= MORSE; ++p)
    if (o.phases[p]) run.pkg[p] = run_phase(static_cast<Phase>(p), file_input, o, "PR-star");
  auto run_ia_phases = [&](int k, const Input& in) {
    bool any = false;
    for (int p = 0; p < 4; ++p)
      if (o.phases[IA_BUILD + p]) {
        run.ia[k][p] = run_phase(static_cast<Phase>(IA_BUILD + p), in, o, std::string("IA ") + order_name[k]);
        any = true;
      }
    run.ia_run[k] = any;
  };
  if (o.ia_file) run_ia_phases(0, file_input);
  if (o.ia_prstar && std::any_of(o.phases.begin() + IA_BUILD, o.phases.end(), [](bool b) { return b; })) {
    // the PR-star order: an octree with k_v = 100 (sequential: the parent does not start TBB)
    std::cerr << "  re-indexing the mesh in the PR-star order ...\n";
    auto ordered = std::make_unique<Mesh>();
    std::vector<Index> key;
    std::vector<double> ordered_field;
    {
      const Octree tree(
          PSO::make_input(*mesh),
          params::bucket_size(100).tetrahedron_permutation(false).concurrency_tag(CGAL::Sequential_tag()));
      ordered->points.assign(tree.points().begin(), tree.points().end());
      ordered->tetrahedra.assign(tree.tetrahedra().begin(), tree.tetrahedra().end());
      key.resize(tree.number_of_vertices());
      ordered_field.resize(key.size());
      for (std::size_t v = 0; v < key.size(); ++v) {
        key[v] = tree.original_vertex(static_cast<Index>(v));
        ordered_field[v] = field[key[v]];
      }
    }
    mesh.reset();
    std::vector<double>().swap(field);
    malloc_trim(0);
    run_ia_phases(1, Input{ordered.get(), &ordered_field, &key});
  }

  if (!o.json_file.empty()) {
    std::ofstream f(o.json_file);
    print_json(run, o, f);
    if (!f) {
      std::cerr << o.json_file << ": cannot write\n";
      return 1;
    }
  }
  if (o.json)
    print_json(run, o, std::cout);
  else
    print_table(run, o, std::cout);
  bool mismatch = false;
  for (int k = 0; k < 2; ++k)
    if (run.ia_run[k])
      mismatch = mismatch || verdict(run.pkg[CRITICAL], run.ia[k][1], 0, 8) == "MISMATCH" ||
                 verdict(run.pkg[GRADIENT], run.ia[k][2], 0, 5) == "MISMATCH" ||
                 verdict(run.pkg[MORSE], run.ia[k][3], 0, 10) == "MISMATCH";
  return mismatch ? 3 : 0;
}
