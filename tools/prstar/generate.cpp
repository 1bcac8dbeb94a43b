// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Mesh generation with CGAL Mesh_3 and TetGen (see generate.h).

#include "generate.h"

#include <CGAL/PR_star_octree/Mesh_complex_3_input.h>

#include <CGAL/Mesh_3/Worksharing_data_structures.h> // CGAL 5.5: needed before exude_mesh_3.h when TBB is linked
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/exude_mesh_3.h>
#include <CGAL/perturb_mesh_3.h>
#include <CGAL/refine_mesh_3.h>

#ifndef TETLIBRARY
#define TETLIBRARY
#endif
#include <tetgen.h>

#include <unistd.h>

#include <array>
#include <chrono>
#include <cmath>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <unordered_map>

namespace prstar {
namespace {

using K = Generate_kernel;
using Point = K::Point_3;
using Vector = K::Vector_3;
using Segment = K::Segment_3;
using Tr = Generate_triangulation;
using Criteria = CGAL::Mesh_criteria_3<Tr>;
using Surface = CGAL::Surface_mesh<Point>;
using Output_mesh = CGAL::PR_star_octree::Indexed_tetrahedral_mesh<>;

// ---------------------------------------------------------------------------------------------
// Implicit shapes: negative inside.  Only the sign matters to Mesh_3.
// ---------------------------------------------------------------------------------------------

double sq(double x) {
  return x * x;
}

struct Implicit_shape {
  const char* name;
  const char* description;
  double (*function)(const Point&);
  Point center;             // of the bounding sphere
  double radius;            // of the bounding sphere, which strictly contains the shape
  std::vector<Point> seeds; // one point inside each connected component
};

const std::vector<Implicit_shape>& shapes() {
  static const std::vector<Implicit_shape> all = {
      {"sphere",
       "unit ball centred at the origin",
       [](const Point& p) { return sq(p.x()) + sq(p.y()) + sq(p.z()) - 1.; },
       Point(0, 0, 0),
       1.5,
       {Point(0, 0, 0)}},
      {"torus",
       "torus around the z axis, radii R = 1 and r = 0.4",
       [](const Point& p) { return sq(std::sqrt(sq(p.x()) + sq(p.y())) - 1.) + sq(p.z()) - sq(0.4); },
       Point(0, 0, 0),
       1.6,
       {Point(1, 0, 0), Point(-1, 0, 0)}},
      {"balls",
       "two overlapping balls (centres (-0.5,0,0), (0.4,0,0), radii 0.6, 0.5) and a separate ball "
       "(centre (0,1.2,0), radius 0.35): two connected components",
       [](const Point& p) {
         const double a = sq(p.x() + 0.5) + sq(p.y()) + sq(p.z()) - sq(0.6);
         const double b = sq(p.x() - 0.4) + sq(p.y()) + sq(p.z()) - sq(0.5);
         const double c = sq(p.x()) + sq(p.y() - 1.2) + sq(p.z()) - sq(0.35);
         return (std::min)(a, (std::min)(b, c));
       },
       Point(0, 0.3, 0),
       2.,
       {Point(-0.5, 0, 0), Point(0.4, 0, 0), Point(0, 1.2, 0)}},
      {"cube",
       "cube [-1,1]^3 (sharp edges are not protected, so they come out rounded)",
       [](const Point& p) {
         return (std::max)(std::abs(p.x()), (std::max)(std::abs(p.y()), std::abs(p.z()))) - 1.;
       },
       Point(0, 0, 0),
       2.,
       {Point(0, 0, 0)}},
      {"ellipsoid",
       "ellipsoid centred at the origin, semi-axes 1, 0.6, 0.4",
       [](const Point& p) { return sq(p.x()) + sq(p.y() / 0.6) + sq(p.z() / 0.4) - 1.; },
       Point(0, 0, 0),
       1.2,
       {Point(0, 0, 0)}},
      {"cylinder",
       "cylinder around the z axis, radius 0.5, z in [-1,1] (rims not protected)",
       [](const Point& p) { return (std::max)(sq(p.x()) + sq(p.y()) - sq(0.5), std::abs(p.z()) - 1.); },
       Point(0, 0, 0),
       1.5,
       {Point(0, 0, 0)}},
  };
  return all;
}

const Implicit_shape& find_shape(const std::string& name) {
  for (const Implicit_shape& s : shapes())
    if (name == s.name) return s;
  std::string known;
  for (const Implicit_shape& s : shapes()) known += std::string(known.empty() ? "" : ", ") + s.name;
  throw std::runtime_error("unknown shape '" + name + "' (known shapes: " + known + ")");
}

// ---------------------------------------------------------------------------------------------
// Options and progress
// ---------------------------------------------------------------------------------------------

struct Sizes {
  double cell_size, facet_size, facet_distance, facet_angle, cell_radius_edge_ratio;
};

Sizes check_options(const Generate_options& o) {
  if (o.shape.empty() == o.surface_file.empty())
    throw std::runtime_error("give either an implicit shape or a surface file, not both and not neither");
  if (!o.shape.empty()) find_shape(o.shape);
  auto finite = [](double x) { return std::isfinite(x); };
  if (!(o.cell_size > 0) || !finite(o.cell_size))
    throw std::runtime_error("cell size must be a positive number (got " + std::to_string(o.cell_size) + ")");
  if (!(o.facet_size >= 0) || !finite(o.facet_size))
    throw std::runtime_error("facet size must be >= 0 (0: the cell size)");
  if (!(o.facet_distance >= 0) || !finite(o.facet_distance))
    throw std::runtime_error("facet distance must be >= 0 (0: a tenth of the cell size)");
  if (!(o.facet_angle > 0 && o.facet_angle <= 30))
    throw std::runtime_error("facet angle must be in (0, 30] degrees (Mesh_3 may not terminate above 30)");
  if (!(o.cell_radius_edge_ratio >= 2) || !finite(o.cell_radius_edge_ratio))
    throw std::runtime_error("cell radius-edge ratio must be >= 2 (Mesh_3 may not terminate below 2)");
  return {o.cell_size, o.facet_size > 0 ? o.facet_size : o.cell_size,
          o.facet_distance > 0 ? o.facet_distance : o.cell_size / 10, o.facet_angle,
          o.cell_radius_edge_ratio};
}

class Progress {
public:
  explicit Progress(const Generate_options& o)
      : on_(!o.quiet && ::isatty(2) == 1), start_(std::chrono::steady_clock::now()) {}
  bool on() const { return on_; }
  void say(const std::string& message) const {
    if (on_) std::cerr << "prstar: " << message << std::endl;
  }
  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }
  void done(std::size_t nv, std::size_t nt) const {
    if (!on_) return;
    std::ostringstream s;
    s << "done: " << nv << " vertices, " << nt << " tetrahedra in " << std::fixed << std::setprecision(2)
      << seconds() << " s";
    say(s.str());
  }

private:
  bool on_;
  std::chrono::steady_clock::time_point start_;
};

std::string seconds(const Progress& progress) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(2) << progress.seconds() << " s";
  return s.str();
}

// ---------------------------------------------------------------------------------------------
// Surface files
// ---------------------------------------------------------------------------------------------

Surface read_surface(const std::string& file) {
  if (!std::ifstream(file)) throw std::runtime_error("cannot open surface file '" + file + "'");
  Surface surface;
  if (!CGAL::IO::read_polygon_mesh(file, surface, CGAL::parameters::verbose(false)) || surface.is_empty())
    throw std::runtime_error("'" + file + "' is not a readable, non-empty, 2-manifold polygon surface");
  if (!CGAL::is_triangle_mesh(surface)) throw std::runtime_error("'" + file + "' is not a triangle mesh");
  if (!CGAL::is_closed(surface))
    throw std::runtime_error("'" + file + "' is not a closed surface (it has border edges)");
  if (CGAL::Polygon_mesh_processing::does_self_intersect(surface))
    throw std::runtime_error("'" + file + "' is self-intersecting");
  return surface;
}

CGAL::Bbox_3 surface_bbox(const Surface& surface) {
  CGAL::Bbox_3 box;
  for (Surface::Vertex_index v : surface.vertices()) box += surface.point(v).bbox();
  return box;
}

double diagonal(const CGAL::Bbox_3& b) {
  return std::sqrt(sq(b.xmax() - b.xmin()) + sq(b.ymax() - b.ymin()) + sq(b.zmax() - b.zmin()));
}

// ---------------------------------------------------------------------------------------------
// Mesh_3
// ---------------------------------------------------------------------------------------------

// A Labeled_mesh_domain_3 and what it refers to (the surface and its inside test, for surface files),
// plus segments crossing the boundary of each component, used to seed the refinement: Mesh_3's own
// initial points shoot random segments from one centre and may miss components altogether.
struct Prepared_domain {
  std::string what;
  std::unique_ptr<Surface> surface;
  std::unique_ptr<CGAL::Side_of_triangle_mesh<Surface, K>> inside;
  std::unique_ptr<Generate_domain> domain;
  std::vector<Segment> probes;
};

Prepared_domain prepare_domain(const Generate_options& o) {
  Prepared_domain d;
  const double relative_error_bound = 1e-6;
  if (!o.shape.empty()) {
    const Implicit_shape& s = find_shape(o.shape);
    d.what = s.name;
    d.domain = std::make_unique<Generate_domain>(Generate_domain::create_implicit_mesh_domain(
        s.function, K::Sphere_3(s.center, sq(s.radius)),
        CGAL::parameters::relative_error_bound = relative_error_bound));
    const double far = 4 * s.radius; // from any seed, beyond the bounding sphere
    for (const Point& seed : s.seeds)
      for (int axis = 0; axis < 3; ++axis)
        for (double sign : {-1., 1.}) {
          const Vector dir(axis == 0 ? sign : 0., axis == 1 ? sign : 0., axis == 2 ? sign : 0.);
          d.probes.emplace_back(seed, seed + far * dir);
        }
    return d;
  }
  d.what = o.surface_file;
  d.surface = std::make_unique<Surface>(read_surface(o.surface_file));
  d.inside = std::make_unique<CGAL::Side_of_triangle_mesh<Surface, K>>(*d.surface);
  const CGAL::Side_of_triangle_mesh<Surface, K>* inside = d.inside.get();
  std::function<int(const Point&)> label = [inside](const Point& p) {
    return (*inside)(p) == CGAL::ON_BOUNDED_SIDE ? 1 : 0;
  };
  const CGAL::Bbox_3 b = surface_bbox(*d.surface);
  const double margin = 0.05 * diagonal(b);
  const CGAL::Bbox_3 box(b.xmin() - margin, b.ymin() - margin, b.zmin() - margin, b.xmax() + margin,
                         b.ymax() + margin, b.zmax() + margin);
  d.domain = std::make_unique<Generate_domain>(label, box, relative_error_bound);
  // short segments across the surface at the centroids of about 64 faces spread over the input
  const Surface& sm = *d.surface;
  const std::size_t nf = sm.number_of_faces();
  const std::size_t step = (std::max<std::size_t>)(1, nf / 64);
  const double eps = 1e-3 * diagonal(b);
  for (std::size_t i = 0; i < nf; i += step) {
    const Surface::Face_index f(static_cast<Surface::size_type>(i));
    std::array<Point, 3> p;
    int k = 0;
    for (Surface::Vertex_index v : CGAL::vertices_around_face(sm.halfedge(f), sm)) p[k++] = sm.point(v);
    const Vector n = CGAL::cross_product(p[1] - p[0], p[2] - p[0]);
    const double len = std::sqrt(n.squared_length());
    if (!(len > 0)) continue;
    const Point c = CGAL::centroid(p[0], p[1], p[2]);
    d.probes.emplace_back(c - (eps / len) * n, c + (eps / len) * n);
  }
  return d;
}

void insert_initial_points(Generate_c3t3& c3t3, const Prepared_domain& d) {
  const Generate_domain& domain = *d.domain;
  Tr& tr = c3t3.triangulation();
  std::vector<std::pair<Point, Generate_domain::Index>> points;
  const auto do_intersect = domain.do_intersect_surface_object();
  const auto intersection = domain.construct_intersection_object();
  for (const Segment& s : d.probes)
    if (do_intersect(s)) {
      const Generate_domain::Intersection i = intersection(s);
      if (std::get<2>(i) != 0) points.emplace_back(std::get<0>(i), std::get<1>(i));
    }
  domain.construct_initial_points_object()(std::back_inserter(points), 20);
  const auto weighted = tr.geom_traits().construct_weighted_point_3_object();
  for (const auto& p : points) {
    const Tr::Vertex_handle v = tr.insert(weighted(p.first));
    if (v == Tr::Vertex_handle()) continue;
    c3t3.set_dimension(v, 2);
    c3t3.set_index(v, p.second);
  }
}

// Runs Mesh_3: the full volume mesh, or (surface_only) the restricted Delaunay surface only.
Generate_c3t3 run_mesh_3(const Generate_options& o, const Sizes& s, bool surface_only,
                         const Progress& progress) {
  namespace P = CGAL::parameters;
  Prepared_domain d = prepare_domain(o);
  progress.say(std::string(surface_only ? "meshing the surface of " : "meshing ") + d.what +
               " with Mesh_3 ...");
  Generate_c3t3 c3t3;
  insert_initial_points(c3t3, d);
  if (surface_only) {
    const Criteria criteria(P::facet_angle = s.facet_angle, P::facet_size = s.facet_size,
                            P::facet_distance = s.facet_distance);
    CGAL::refine_mesh_3(c3t3, *d.domain, criteria, P::no_reset_c3t3(), P::no_perturb(), P::no_exude());
  } else {
    const Criteria criteria(P::facet_angle = s.facet_angle, P::facet_size = s.facet_size,
                            P::facet_distance = s.facet_distance,
                            P::cell_radius_edge_ratio = s.cell_radius_edge_ratio, P::cell_size = s.cell_size);
    CGAL::refine_mesh_3(c3t3, *d.domain, criteria, P::no_reset_c3t3(), P::no_perturb(), P::no_exude());
    progress.say("refined: " + std::to_string(c3t3.number_of_cells_in_complex()) + " tetrahedra, " +
                 seconds(progress));
    // Sliver removal with time_limit = 0 (no time limit), so that the result does not depend on the
    // machine's speed (CGAL's default limit is the refinement time), and explicit bounds on the
    // minimum dihedral angle, so that it stays cheap: perturbation up to 10 degrees (its default,
    // 12, can take ten times the refinement time near the crease of `balls`), then exudation up to
    // 15 degrees (its default, 90, visits every cell for a gain of well under a degree).
    // Measured at cell size 0.05: minimum dihedral angle >= 10 degrees on every implicit shape,
    // for 0.5-1.6 times the refinement time.
    CGAL::perturb_mesh_3(c3t3, *d.domain, P::time_limit = 0., P::sliver_bound = 10.);
    progress.say("perturbed, " + seconds(progress));
    CGAL::exude_mesh_3(c3t3, P::time_limit = 0., P::sliver_bound = 15.);
    progress.say("exuded, " + seconds(progress));
    if (c3t3.number_of_cells_in_complex() == 0)
      throw std::runtime_error("Mesh_3 produced no tetrahedra for " + d.what +
                               " (is the cell size too large?)");
  }
  return c3t3;
}

// ---------------------------------------------------------------------------------------------
// TetGen
// ---------------------------------------------------------------------------------------------

struct Triangle_soup {
  std::vector<Point> points;
  std::vector<std::array<int, 3>> triangles;
};

Triangle_soup surface_of(const Generate_c3t3& c3t3) {
  Triangle_soup soup;
  const Tr& tr = c3t3.triangulation();
  std::unordered_map<Tr::Vertex_handle, int> index;
  const auto bare = tr.geom_traits().construct_point_3_object();
  for (auto f = c3t3.facets_in_complex_begin(); f != c3t3.facets_in_complex_end(); ++f) {
    std::array<int, 3> t;
    for (int k = 0; k < 3; ++k) {
      const Tr::Vertex_handle v = f->first->vertex(Tr::vertex_triple_index(f->second, k));
      auto ins = index.emplace(v, static_cast<int>(soup.points.size()));
      if (ins.second) soup.points.push_back(bare(tr.point(v)));
      t[k] = ins.first->second;
    }
    soup.triangles.push_back(t);
  }
  return soup;
}

Triangle_soup surface_of(const Surface& sm) {
  Triangle_soup soup;
  std::vector<int> index(sm.number_of_vertices() + sm.number_of_removed_vertices(), -1);
  for (Surface::Vertex_index v : sm.vertices()) {
    index[v] = static_cast<int>(soup.points.size());
    soup.points.push_back(sm.point(v));
  }
  for (Surface::Face_index f : sm.faces()) {
    std::array<int, 3> t;
    int k = 0;
    for (Surface::Vertex_index v : CGAL::vertices_around_face(sm.halfedge(f), sm)) t[k++] = index[v];
    soup.triangles.push_back(t);
  }
  return soup;
}

std::string tetgen_error(int code) {
  switch (code) {
  case 1:
    return "out of memory";
  case 2:
    return "internal error";
  case 3:
    return "the surface is self-intersecting";
  case 4:
    return "a very small input feature size was detected";
  case 5:
    return "two very close input facets were detected";
  case 10:
    return "invalid input";
  default:
    return "error code " + std::to_string(code);
  }
}

Output_mesh run_tetgen(const Triangle_soup& soup, double max_volume) {
  if (soup.triangles.empty()) throw std::runtime_error("TetGen: the boundary surface is empty");
  tetgenio in, out; // their destructors delete[] every list set below
  in.firstnumber = 0;
  in.numberofpoints = static_cast<int>(soup.points.size());
  in.pointlist = new REAL[3 * soup.points.size()];
  for (std::size_t i = 0; i < soup.points.size(); ++i) {
    in.pointlist[3 * i] = soup.points[i].x();
    in.pointlist[3 * i + 1] = soup.points[i].y();
    in.pointlist[3 * i + 2] = soup.points[i].z();
  }
  in.numberoffacets = static_cast<int>(soup.triangles.size());
  in.facetlist = new tetgenio::facet[soup.triangles.size()];
  for (std::size_t i = 0; i < soup.triangles.size(); ++i) {
    tetgenio::facet& f = in.facetlist[i];
    tetgenio::init(&f);
    f.numberofpolygons = 1;
    f.polygonlist = new tetgenio::polygon[1];
    tetgenio::init(&f.polygonlist[0]);
    f.polygonlist[0].numberofvertices = 3;
    f.polygonlist[0].vertexlist = new int[3];
    for (int k = 0; k < 3; ++k) f.polygonlist[0].vertexlist[k] = soup.triangles[i][k];
  }
  // p: the input is a PLC; q1.414: radius-edge ratio bound; a: volume bound; Q: quiet.
  std::ostringstream sw;
  sw << "pq1.414a" << std::fixed << std::setprecision(15) << max_volume << "Q";
  std::string switches = sw.str();
  try {
    tetrahedralize(&switches[0], &in, &out);
  } catch (int code) {
    throw std::runtime_error("TetGen failed: " + tetgen_error(code));
  }
  if (out.numberoftetrahedra <= 0 || out.tetrahedronlist == nullptr)
    throw std::runtime_error("TetGen produced no tetrahedra");

  // TetGen's tetrahedra have the opposite orientation to CGAL's; keep only used points.
  Output_mesh mesh;
  const int first = out.firstnumber;
  std::vector<std::uint32_t> renumber(static_cast<std::size_t>(out.numberofpoints), UINT32_MAX);
  mesh.tetrahedra.reserve(static_cast<std::size_t>(out.numberoftetrahedra));
  for (int t = 0; t < out.numberoftetrahedra; ++t) {
    Output_mesh::Tetrahedron tet;
    for (int k = 0; k < 4; ++k) {
      const int v = out.tetrahedronlist[t * out.numberofcorners + k] - first;
      if (v < 0 || v >= out.numberofpoints)
        throw std::runtime_error("TetGen output: vertex index out of range");
      std::uint32_t& r = renumber[static_cast<std::size_t>(v)];
      if (r == UINT32_MAX) {
        r = static_cast<std::uint32_t>(mesh.points.size());
        mesh.points.emplace_back(out.pointlist[3 * v], out.pointlist[3 * v + 1], out.pointlist[3 * v + 2]);
      }
      tet[k] = r;
    }
    const CGAL::Orientation o =
        CGAL::orientation(mesh.points[tet[0]], mesh.points[tet[1]], mesh.points[tet[2]], mesh.points[tet[3]]);
    if (o == CGAL::COPLANAR) throw std::runtime_error("TetGen produced a flat tetrahedron");
    if (o == CGAL::NEGATIVE) std::swap(tet[0], tet[1]);
    mesh.tetrahedra.push_back(tet);
  }
  mesh.tetrahedron_labels.assign(mesh.tetrahedra.size(), 1);
  return mesh;
}

} // namespace

// ---------------------------------------------------------------------------------------------
// Public functions
// ---------------------------------------------------------------------------------------------

std::vector<std::pair<std::string, std::string>> implicit_shapes() {
  std::vector<std::pair<std::string, std::string>> result;
  for (const Implicit_shape& s : shapes()) result.emplace_back(s.name, s.description);
  return result;
}

Generate_c3t3 generate_c3t3(const Generate_options& options) {
  const Sizes sizes = check_options(options);
  if (options.tetgen) throw std::runtime_error("generate_c3t3: a TetGen mesh is not a Mesh_3 complex");
  const Progress progress(options);
  Generate_c3t3 c3t3 = run_mesh_3(options, sizes, false, progress);
  if (progress.on()) {
    const CGAL::PR_star_octree::Mesh_complex_3_input<Generate_c3t3> input(c3t3);
    progress.done(input.number_of_vertices(), input.number_of_tetrahedra());
  }
  return c3t3;
}

CGAL::PR_star_octree::Indexed_tetrahedral_mesh<> generate_mesh(const Generate_options& options) {
  const Sizes sizes = check_options(options);
  const Progress progress(options);
  Output_mesh mesh;
  if (!options.tetgen) {
    const Generate_c3t3 c3t3 = run_mesh_3(options, sizes, false, progress);
    mesh = CGAL::PR_star_octree::c3t3_to_indexed_tetrahedral_mesh(c3t3);
  } else {
    Triangle_soup soup;
    if (!options.shape.empty()) {
      soup = surface_of(run_mesh_3(options, sizes, true, progress));
    } else {
      progress.say("reading " + options.surface_file + " ...");
      soup = surface_of(read_surface(options.surface_file));
    }
    progress.say("filling the surface (" + std::to_string(soup.points.size()) + " vertices, " +
                 std::to_string(soup.triangles.size()) + " triangles) with TetGen ...");
    // Mesh_3's cell_size bounds the circumradius: use the volume of the regular tetrahedron whose
    // circumradius is cell_size (edge 4 / sqrt(6) cell_size, volume 8 / (9 sqrt(3)) cell_size^3),
    // so that both meshers give meshes of comparable density for the same --cell-size.
    const double max_volume = std::pow(sizes.cell_size, 3) * 8. / (9. * std::sqrt(3.));
    mesh = run_tetgen(soup, max_volume);
  }
  progress.done(mesh.number_of_vertices(), mesh.number_of_tetrahedra());
  return mesh;
}

} // namespace prstar
