// The code shown in the user manual (doc/PR_star_octree/PR_star_octree.txt), between the
// `//! [name]` markers that its `\snippet` commands refer to.  Built and run by the test
// `manual_snippets`, which checks the results against what is known of the mesh below (a cube of
// 3 x 3 x 3 unit cells, each cut into six tetrahedra): the manual cannot show code that does not
// compile or does not do what it says.
#include <CGAL/PR_star_octree.h>
#include <CGAL/PR_star_octree/IO.h>
#include <CGAL/PR_star_octree/Leaf_topology.h>
#include <CGAL/PR_star_octree/boundary.h>
#include <CGAL/PR_star_octree/distortion.h>
#include <CGAL/PR_star_octree/parameters.h>
#include <CGAL/PR_star_octree/scalar_topology.h>
#include <CGAL/PR_star_octree/simplification.h>
#include <CGAL/PR_star_octree/validity.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

namespace PSO = CGAL::PR_star_octree;
namespace params = CGAL::PR_star_octree::parameters;
using Point = CGAL::Epick::Point_3;
using Octree = CGAL::PR_star_octree_3<>;

namespace {

int failures = 0;
void check(bool ok, const char* what) {
  if (!ok) {
    std::cerr << "FAILED: " << what << '\n';
    ++failures;
  }
}

constexpr int n = 3; // cells per side

// The n^3 unit cells of [0, n]^3, each cut into the six tetrahedra around its main diagonal (a
// conforming mesh: every cell uses the same diagonal direction), all listed with the sign of the
// permutation of the axes corrected so that they have one orientation.
void make_grid(std::vector<Point>& points, std::vector<std::array<int, 4>>& tetrahedra) {
  auto id = [](int x, int y, int z) { return x + (n + 1) * (y + (n + 1) * z); };
  for (int z = 0; z <= n; ++z)
    for (int y = 0; y <= n; ++y)
      for (int x = 0; x <= n; ++x) points.emplace_back(x, y, z);
  const int axes[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x)
        for (const auto& a : axes) {
          std::array<int, 3> p{x, y, z};
          std::array<int, 4> t;
          t[0] = id(p[0], p[1], p[2]);
          for (int k = 0; k < 3; ++k) {
            ++p[a[k]];
            t[k + 1] = id(p[0], p[1], p[2]);
          }
          const int inversions = (a[0] > a[1]) + (a[0] > a[2]) + (a[1] > a[2]);
          if (inversions % 2 == 1) std::swap(t[2], t[3]); // all of one orientation: valid as listed
          tetrahedra.push_back(t);
        }
}

bool is_interior(const Point& p) {
  auto in = [](double c) { return c > 0 && c < n; };
  return in(p.x()) && in(p.y()) && in(p.z());
}

} // namespace

int main(int argc, char** argv) {
  const std::string folder = argc > 1 ? argv[1] : ".";
  std::vector<Point> points;
  std::vector<std::array<int, 4>> tetrahedra;
  make_grid(points, tetrahedra);

  //! [build]
  // points: std::vector<Point_3>, tetrahedra: std::vector<std::array<int, 4>> (the user's numbering)
  Octree tree(PSO::make_input(points, tetrahedra), params::bucket_size(8));
  //! [build]

  {
    //! [statistics]
    const PSO::Statistics s = tree.statistics();
    std::cout << s.nodes << " nodes, " << s.leaves << " leaves, chi = " << s.chi << "; overhead "
              << s.prstar_overhead_per_vertex << " |V| (extended IA: " << s.ia_overhead_per_vertex
              << " |V|), " << s.bytes.total() << " bytes\n";
    //! [statistics]
    check(s.vertices == points.size() && s.tetrahedra == tetrahedra.size(), "statistics: sizes");
    check(s.chi >= 1 && s.chi <= 4, "statistics: 1 <= chi <= 4");
  }

  {
    //! [boundary]
    std::vector<PSO::Vertex_type> type(points.size()); // written in the user's numbering
    std::vector<std::array<std::size_t, 3>> triangles; // boundary triangles, user's numbering
    const PSO::Boundary_counts b =
        PSO::compute_boundary(tree, CGAL::make_property_map(type),
                              params::boundary_triangles_output(std::back_inserter(triangles)));
    std::cout << b.interior_vertices << " interior and " << b.boundary_vertices << " boundary vertices, "
              << triangles.size() << " boundary triangles\n";
    //! [boundary]
    std::size_t wrong = 0;
    for (std::size_t v = 0; v < points.size(); ++v)
      wrong += type[v] != (is_interior(points[v]) ? PSO::Vertex_type::INTERIOR : PSO::Vertex_type::BOUNDARY);
    check(wrong == 0, "boundary: vertex types in the user's numbering");
    check(b.interior_vertices == (n - 1) * (n - 1) * (n - 1), "boundary: interior count");
    check(triangles.size() == 6 * n * n * 2 && b.boundary_triangles == triangles.size(),
          "boundary: two triangles per cell face on the boundary");
    for (const auto& t : triangles)
      for (std::size_t v : t) check(!is_interior(points[v]), "boundary: triangle corners on the boundary");
  }

  {
    //! [distortion]
    std::vector<double> f(points.size()); // a scalar field, in the user's numbering
    for (std::size_t v = 0; v < points.size(); ++v) f[v] = (points[v] - CGAL::ORIGIN).squared_length();
    std::vector<double> distortion(points.size()), domain_curvature(points.size());
    PSO::compute_discrete_distortion(tree, CGAL::make_property_map(f), CGAL::make_property_map(distortion),
                                     params::domain_curvature_map(CGAL::make_property_map(domain_curvature)));
    // Everything at once (solid-angle sums, distortion, domain curvature, type) for the field z:
    std::vector<PSO::Vertex_curvature> curvature(points.size());
    PSO::compute_curvature(tree, PSO::coordinate_field_map(tree, 2), CGAL::make_property_map(curvature));
    //! [distortion]
    bool linear_flat = true, domain_flat = true, curved = false;
    for (std::size_t v = 0; v < points.size(); ++v) {
      if (!is_interior(points[v])) continue;
      linear_flat = linear_flat && std::abs(curvature[v].distortion) < 1e-9;
      domain_flat = domain_flat && std::abs(domain_curvature[v]) < 1e-9;
      curved = curved || std::abs(distortion[v]) > 1e-6;
    }
    check(linear_flat, "distortion: a linear field has none at interior vertices");
    check(domain_flat, "distortion: the domain is flat at interior vertices");
    check(curved, "distortion: |p|^2 is distorted somewhere inside");
  }

  {
    //! [topology]
    // f: two wells, at the vertices a and b (not joined by an edge), in the user's numbering
    const Point a(1, 1, 2), b(2, 2, 1);
    std::vector<double> f(points.size());
    for (std::size_t v = 0; v < points.size(); ++v)
      f[v] = (std::min)(CGAL::squared_distance(points[v], a), CGAL::squared_distance(points[v], b));
    std::vector<PSO::Critical_type> type(points.size()); // TTK's codes: 0 minimum ... 5 regular
    const PSO::Critical_point_counts c =
        PSO::compute_critical_points(tree, CGAL::make_property_map(f), CGAL::make_property_map(type));
    const PSO::Forman_gradient<Octree> g = PSO::compute_forman_gradient(tree, CGAL::make_property_map(f));
    // The Morse complexes; the pairs of persistence below 1.5 are cancelled, the arcs collected:
    std::vector<PSO::Morse_arc> arcs;
    const PSO::Morse_complexes<Octree> m = PSO::compute_morse_complexes(
        tree, CGAL::make_property_map(f),
        params::persistence_threshold(1.5).arcs_output(std::back_inserter(arcs)));
    std::cout << c.minima << " minima, " << c.saddles_1
              << " 1-saddles; gradient: c0 - c1 + c2 - c3 = " << g.alternating_sum() << "; "
              << m.ascending_cells << " ascending 3-cell(s), " << m.persistence_pairs.size()
              << " persistence pairs, " << arcs.size() << " arcs\n";
    // m.ascending_cell[v]: the minimum whose 3-cell holds vertex v (user's numbering)
    //! [topology]
    auto index = [](int x, int y, int z) {
      return static_cast<std::size_t>(x + (n + 1) * (y + (n + 1) * z));
    };
    check(c.minima == 2 && type[index(1, 1, 2)] == PSO::Critical_type::MINIMUM &&
              type[index(2, 2, 1)] == PSO::Critical_type::MINIMUM,
          "topology: the two wells are the minima");
    check(g.alternating_sum() == 1, "topology: the gradient's alternating sum is the Euler characteristic");
    std::size_t finite = 0;
    for (const PSO::Persistence_pair& p : m.persistence_pairs)
      if (p.type == PSO::Persistence_pair::MINIMUM_SADDLE && !p.is_essential()) {
        ++finite;
        check(p.persistence() == 1.0, "topology: the wells merge at f = 1");
      }
    check(finite == 1, "topology: one finite minimum-saddle pair");
    check(m.ascending_cells == 1 && m.ascending_cell[index(1, 1, 2)] == m.ascending_cell[index(2, 2, 1)],
          "topology: one ascending 3-cell after the cancellation");
    const auto full = PSO::compute_morse_complexes(tree, CGAL::make_property_map(f));
    check(full.ascending_cells == 2 && full.ascending_cell[index(1, 1, 2)] == index(1, 1, 2) &&
              full.ascending_cell[index(2, 2, 1)] == index(2, 2, 1),
          "topology: two ascending 3-cells without cancellation");
  }

  {
    //! [validity]
    const PSO::Validity_result r = PSO::check_validity(tree);
    std::cout << (r.valid ? "valid" : "not valid") << ": " << r.inverted << " inverted, " << r.degenerate
              << " flat tetrahedra, " << r.nonmanifold_vertices
              << " non-manifold vertices, Euler characteristic " << r.euler_characteristic << ", "
              << r.boundary_components << " boundary component(s)\n";
    // Or straight from the arrays (the octree is built inside):
    const PSO::Validity_result same = PSO::check_validity(points, tetrahedra, params::bucket_size(8));
    //! [validity]
    check(r.valid && r.euler_characteristic == 1 && r.boundary_components == 1, "validity: a valid ball");
    check(same.valid == r.valid && same.boundary_triangles == r.boundary_triangles, "validity: from arrays");
  }

  {
    //! [local]
    // Per leaf: the local relations asked for, built once, handed to the functor, discarded.
    std::vector<std::size_t> star_size(points.size()); // user's numbering
    PSO::for_each_leaf(tree, PSO::VERTEX_TETRAHEDRA, [&](const PSO::Leaf_topology<Octree>& local) {
      for (auto v = local.vertex_begin(); v < local.vertex_end();
           ++v) // the leaf's vertices (octree numbering)
        star_size[tree.original_vertex(v)] = local.vertex_tetrahedra(v).size();
    });
    // One query, octree numbering: the star of the user's vertex 0.
    std::vector<Octree::Index> star;
    PSO::vertex_star(tree, tree.vertex_from_original()[0], std::back_inserter(star));
    const PSO::Simplex_counts c =
        PSO::count_simplices(tree, params::progress([](std::size_t done, std::size_t total) {
                               std::cerr << done << '/' << total << '\r';
                             }));
    std::cout << c.vertices << " vertices, " << c.edges << " edges, " << c.triangles << " triangles, "
              << c.tetrahedra << " tetrahedra: Euler characteristic " << c.euler_characteristic() << '\n';
    //! [local]
    std::size_t incidences = 0;
    for (std::size_t s : star_size) incidences += s;
    check(incidences == 4 * tetrahedra.size(), "local: the stars cover every tetrahedron four times");
    std::size_t star_0 = 0; // brute force
    for (const auto& t : tetrahedra) star_0 += t[0] == 0 || t[1] == 0 || t[2] == 0 || t[3] == 0;
    check(star.size() == star_0 && star_size[0] == star_0, "local: the star of the user's vertex 0");
    check(c.euler_characteristic() == 1 && c.tetrahedra == tetrahedra.size(), "local: simplex counts");
  }

  {
    //! [simplification]
    const auto result =
        PSO::simplify(PSO::make_input(points, tetrahedra), params::target_fraction(0.25).bucket_size(8));
    const PSO::Simplification_statistics& s = result.statistics;
    std::cout << s.input_tetrahedra << " -> " << s.output_tetrahedra << " tetrahedra, " << s.collapses
              << " collapses in " << s.rounds << " round(s)\n";
    // result.mesh: an Indexed_tetrahedral_mesh; result.input_vertex[i]: the input index of its vertex i
    //! [simplification]
    check(s.output_tetrahedra == result.mesh.number_of_tetrahedra() &&
              s.output_tetrahedra < tetrahedra.size(),
          "simplification: some tetrahedra removed");
    check(result.input_vertex.size() == result.mesh.number_of_vertices(), "simplification: vertex origins");
    check(PSO::check_validity(result.mesh.points, result.mesh.tetrahedra).valid,
          "simplification: valid result");
  }

  {
    const std::string filename = folder + "/manual_snippets_grid.mesh";
    PSO::Indexed_tetrahedral_mesh<> grid;
    grid.points = points;
    for (const auto& t : tetrahedra)
      grid.tetrahedra.push_back(
          {std::uint32_t(t[0]), std::uint32_t(t[1]), std::uint32_t(t[2]), std::uint32_t(t[3])});
    PSO::IO::write_tetrahedral_mesh(filename, grid);

    //! [io]
    PSO::Indexed_tetrahedral_mesh<> mesh; // .mesh, .node/.ele, .vtk, .vtu, .off/.ts, by the extension
    try {
      PSO::IO::read_tetrahedral_mesh(filename, mesh);
    } catch (const PSO::IO::Read_error& e) { // names the file and the line
      std::cerr << e.what() << '\n';
      return EXIT_FAILURE;
    }
    Octree from_file(PSO::make_input(mesh), params::bucket_size(8)); // point data 0, if any: the scalar field
    PSO::IO::write_tetrahedral_mesh(folder + "/manual_snippets_grid.vtu", mesh);
    //! [io]
    check(from_file.number_of_tetrahedra() == tetrahedra.size(), "io: read back");
  }

  std::cout << (failures ? "FAILED\n" : "all manual snippets ran as documented\n");
  return failures ? EXIT_FAILURE : EXIT_SUCCESS;
}
