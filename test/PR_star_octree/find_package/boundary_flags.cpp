// Boundary flags of a cube cut into 12 tetrahedra around its centre, through the installed
// package: 8 boundary corners, 1 interior centre, 12 boundary triangles.
#include <CGAL/PR_star_octree.h>
#include <CGAL/PR_star_octree/boundary.h>
#include <CGAL/property_map.h>

#include <array>
#include <iostream>
#include <vector>

namespace PSO = CGAL::PR_star_octree;
using Point = CGAL::Epick::Point_3;

int main() {
  // Vertex 0 is the centre; vertex 1 + i is the corner (i & 1, i >> 1 & 1, i >> 2 & 1).
  std::vector<Point> points{{0.5, 0.5, 0.5}};
  for (int i = 0; i < 8; ++i) points.emplace_back(i & 1, i >> 1 & 1, i >> 2 & 1);
  const int faces[6][4] = {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4},
                           {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}};
  std::vector<std::array<int, 4>> tetrahedra; // each face of the cube: two triangles coned to the centre
  for (const auto& f : faces) {
    tetrahedra.push_back({0, 1 + f[0], 1 + f[1], 1 + f[2]});
    tetrahedra.push_back({0, 1 + f[0], 1 + f[2], 1 + f[3]});
  }

  CGAL::PR_star_octree_3<> tree(PSO::make_input(points, tetrahedra), PSO::parameters::bucket_size(2));
  std::vector<PSO::Vertex_type> type(points.size()); // in the input numbering
  const auto counts = PSO::compute_boundary(tree, CGAL::make_property_map(type));

  for (std::size_t v = 0; v < points.size(); ++v)
    std::cout << "vertex " << v << ": "
              << (type[v] == PSO::Vertex_type::BOUNDARY   ? "boundary"
                  : type[v] == PSO::Vertex_type::INTERIOR ? "interior"
                                                          : "other")
              << '\n';
  std::cout << "boundary vertices: " << counts.boundary_vertices << '\n'
            << "interior vertices: " << counts.interior_vertices << '\n'
            << "boundary triangles: " << counts.boundary_triangles << '\n';
  return 0;
}
