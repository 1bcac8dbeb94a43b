// Scalar-field topology: the critical points of a noisy field on a grid of cubes cut into
// tetrahedra, its discrete (Forman) gradient, and its Morse complexes with the noise cancelled by
// persistence.  The field has two bumps and one well inside the grid, and noise of 2% of their
// height everywhere: after the cancellation, two descending 3-cells (one per bump) remain.
#include <CGAL/PR_star_octree.h>
#include <CGAL/PR_star_octree/scalar_topology.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <iterator>
#include <random>
#include <vector>

namespace PSO = CGAL::PR_star_octree;
namespace params = CGAL::PR_star_octree::parameters;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Octree = CGAL::PR_star_octree_3<Kernel>;

int main() {
  const int n = 16; // n x n x n cubes
  std::vector<Point> points;
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) points.emplace_back(i, j, k);
  auto id = [&](int i, int j, int k) { return (k * (n + 1) + j) * (n + 1) + i; };
  std::vector<std::array<int, 4>> tetrahedra;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        int c[8];
        for (int b = 0; b < 8; ++b) c[b] = id(i + (b & 1), j + ((b >> 1) & 1), k + ((b >> 2) & 1));
        // the six paths from corner 0 to corner 7 (a conforming Kuhn subdivision)
        const int paths[6][2] = {{1, 3}, {1, 5}, {2, 3}, {2, 6}, {4, 5}, {4, 6}};
        for (const auto& p : paths) tetrahedra.push_back({c[0], c[p[0]], c[p[1]], c[7]});
      }
  const Octree octree(PSO::make_input(points, tetrahedra), params::bucket_size(50));

  // The field, in the user's vertex order: bumps at (4, 8, 8) and (12, 8, 8), a well at (8, 8, 3).
  std::mt19937 random(7);
  std::uniform_real_distribution<double> noise(-0.02, 0.02);
  auto bump = [](const Point& p, double x, double y, double z, double height) {
    const double d2 = CGAL::squared_distance(p, Point(x, y, z));
    return height * std::exp(-d2 / 8.0);
  };
  std::vector<double> f(points.size());
  for (std::size_t v = 0; v < points.size(); ++v)
    f[v] = bump(points[v], 4, 8, 8, 1.0) + bump(points[v], 12, 8, 8, 0.8) + bump(points[v], 8, 8, 3, -1.0) +
           noise(random);
  const auto field = CGAL::make_property_map(f);

  // 1. The piecewise-linear critical points: the type of every vertex (TTK's codes) in a property
  //    map, the vertices that are not regular in a list.
  std::vector<PSO::Critical_type> type(points.size());
  std::vector<PSO::Critical_point> critical;
  const PSO::Critical_point_counts c =
      PSO::compute_critical_points(octree, field, CGAL::make_property_map(type),
                                   params::critical_points_output(std::back_inserter(critical)));
  const auto on_boundary = std::count_if(critical.begin(), critical.end(),
                                         [](const PSO::Critical_point& p) { return p.on_boundary; });
  std::cout << "critical points: " << c.minima << " minima, " << c.saddles_1 << " 1-saddles, " << c.saddles_2
            << " 2-saddles, " << c.maxima << " maxima, " << c.degenerate << " degenerate (" << on_boundary
            << " of the " << critical.size() << " on the boundary)\n";

  // 2. The discrete gradient (ProcessLowerStars, leaf by leaf): c0 - c1 + c2 - c3 is the Euler
  //    characteristic of the mesh, 1 for the grid.
  const PSO::Forman_gradient<Octree> gradient = PSO::compute_forman_gradient(octree, field);
  std::cout << "critical simplices: " << gradient.number_of_critical_simplices(0) << " vertices, "
            << gradient.number_of_critical_simplices(1) << " edges, "
            << gradient.number_of_critical_simplices(2) << " triangles, "
            << gradient.number_of_critical_simplices(3) << " tetrahedra; alternating sum "
            << gradient.alternating_sum() << ", " << gradient.bytes_per_tetrahedron()
            << " bytes per tetrahedron\n";

  // 3. The Morse complexes, the pairs of persistence below 5% of the field's range cancelled.
  const auto [lowest, highest] = std::minmax_element(f.begin(), f.end());
  const double threshold = 0.05 * (*highest - *lowest);
  std::vector<PSO::Morse_arc> arcs;
  const PSO::Morse_complexes<Octree> m = PSO::compute_morse_complexes(
      octree, field, params::persistence_threshold(threshold).arcs_output(std::back_inserter(arcs)));
  std::cout << m.persistence_pairs.size() << " persistence pairs, " << arcs.size()
            << " arcs; after the cancellation: " << m.ascending_cells << " ascending 3-cells, "
            << m.descending_cells << " descending 3-cells\n";
  std::size_t kept_minima = 0, kept_maxima = 0;
  for (const PSO::Persistence_pair& p : m.persistence_pairs) {
    if (p.persistence() < threshold) continue;
    const bool minimum = p.type == PSO::Persistence_pair::MINIMUM_SADDLE;
    (minimum ? kept_minima : kept_maxima) += 1;
    std::cout << "  " << (minimum ? "minimum " : "maximum ") << p.extremum << " at " << points[p.extremum]
              << ": ";
    if (p.is_essential())
      std::cout << "essential\n";
    else
      std::cout << "persistence " << p.persistence() << " (saddle " << p.saddle << ")\n";
  }
  // Each extremum kept names one cell: the ascending 3-cells partition the vertices, the descending
  // 3-cells the tetrahedra (but for those whose gradient path leaves through the boundary).
  const bool ok = gradient.alternating_sum() == 1 && m.ascending_cells == kept_minima &&
                  m.descending_cells == kept_maxima && m.descending_cells == 2;
  std::cout << (ok ? "as expected" : "UNEXPECTED") << '\n';
  return ok ? 0 : 1;
}
