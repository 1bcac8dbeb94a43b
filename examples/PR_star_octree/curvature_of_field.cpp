// Discrete distortion of a scalar field: the field f(x, y, z) = x^2 + y^2 + z^2 on a small grid of
// cubes, each cut into six tetrahedra; interior vertices get the distortion of the lifted mesh.
#include <CGAL/PR_star_octree.h>
#include <CGAL/PR_star_octree/distortion.h>

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

  CGAL::PR_star_octree_3<Kernel> octree(CGAL::PR_star_octree::make_input(points, tetrahedra), 20);
  // Any functor from an octree vertex to a double is a field.
  auto field = [&](std::uint32_t v) {
    const Point& p = octree.point(v);
    return p.x() * p.x() + p.y() * p.y() + p.z() * p.z();
  };
  const auto curvature = CGAL::PR_star_octree::compute_curvature(octree, field);

  // The centre of the grid, in the user's numbering, and its distortion.
  const std::uint32_t centre = static_cast<std::uint32_t>(id(n / 2, n / 2, n / 2));
  for (std::uint32_t v = 0; v < octree.number_of_vertices(); ++v)
    if (octree.original_vertex(v) == centre)
      std::cout << "distortion at the centre: " << curvature[v].distortion
                << " (interior: " << (curvature[v].type == CGAL::PR_star_octree::Vertex_type::INTERIOR)
                << ")\n";
  // A linear field has no distortion at interior vertices.
  const auto flat =
      CGAL::PR_star_octree::compute_curvature(octree, CGAL::PR_star_octree::coordinate_field(octree, 0));
  double worst = 0;
  for (const auto& c : flat)
    if (c.type == CGAL::PR_star_octree::Vertex_type::INTERIOR)
      worst = std::max(worst, std::abs(c.distortion));
  std::cout << "largest |distortion| of the field x at interior vertices: " << worst << '\n';
  return worst < 1e-9 ? 0 : 1;
}
