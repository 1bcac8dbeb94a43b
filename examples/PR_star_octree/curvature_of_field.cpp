// Discrete distortion of a scalar field: the field f(x, y, z) = x^2 + y^2 + z^2 on a small grid of
// cubes, each cut into six tetrahedra; interior vertices get the distortion of the lifted mesh.
#include <CGAL/PR_star_octree.h>
#include <CGAL/PR_star_octree/distortion.h>
#include <CGAL/property_map.h>

#include <array>
#include <iostream>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;

int main() {
  const int n = 6; // n x n x n cubes
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

  CGAL::PR_star_octree_3<Kernel> octree(CGAL::PR_star_octree::make_input(points, tetrahedra),
                                        CGAL::PR_star_octree::parameters::bucket_size(20));
  // A field is a property map from the user's vertex index to a double.
  std::vector<double> field(points.size());
  for (std::size_t v = 0; v < points.size(); ++v)
    field[v] = points[v].x() * points[v].x() + points[v].y() * points[v].y() + points[v].z() * points[v].z();
  std::vector<CGAL::PR_star_octree::Vertex_curvature> curvature(points.size());
  CGAL::PR_star_octree::compute_curvature(octree, CGAL::make_property_map(field),
                                          CGAL::make_property_map(curvature));

  // The centre of the grid, in the user's numbering, and its distortion.
  const std::size_t centre = static_cast<std::size_t>(id(n / 2, n / 2, n / 2));
  std::cout << "distortion at the centre: " << curvature[centre].distortion
            << " (interior: " << (curvature[centre].type == CGAL::PR_star_octree::Vertex_type::INTERIOR)
            << ")\n";
  // A linear field has no distortion at interior vertices.
  std::vector<double> distortion(points.size());
  std::vector<CGAL::PR_star_octree::Vertex_type> types(points.size());
  CGAL::PR_star_octree::compute_discrete_distortion(
      octree, CGAL::PR_star_octree::coordinate_field_map(octree, 0), CGAL::make_property_map(distortion),
      CGAL::PR_star_octree::parameters::vertex_type_map(CGAL::make_property_map(types)));
  double worst = 0;
  for (std::size_t v = 0; v < points.size(); ++v)
    if (types[v] == CGAL::PR_star_octree::Vertex_type::INTERIOR)
      worst = std::max(worst, std::abs(distortion[v]));
  std::cout << "largest |distortion| of the field x at interior vertices: " << worst << '\n';
  return worst < 1e-9 ? 0 : 1;
}
