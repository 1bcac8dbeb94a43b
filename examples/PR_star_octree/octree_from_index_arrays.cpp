// Builds the PR-star octree of a mesh given as two plain arrays and walks its leaves.
#include <CGAL/PR_star_octree.h>

#include <array>
#include <iostream>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;

int main() {
  // The unit cube cut into six tetrahedra around its diagonal (0,0,0)-(1,1,1).
  std::vector<Point> points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0},
                               {0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}};
  std::vector<std::array<int, 4>> tetrahedra = {{0, 1, 3, 7}, {0, 1, 5, 7}, {0, 2, 3, 7},
                                                {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 4, 6, 7}};

  // Bucket threshold k_v = 2: a leaf splits when it would hold more than two vertices.
  CGAL::PR_star_octree_3<Kernel> octree(CGAL::PR_star_octree::make_input(points, tetrahedra),
                                        CGAL::PR_star_octree::parameters::bucket_size(2));

  for (auto leaf : octree.leaves()) {
    const auto& node = octree.node(leaf);
    if (node.number_of_vertices() == 0) continue;
    std::cout << "leaf " << leaf << ": vertices";
    for (auto v = node.vertex_begin; v < node.vertex_end; ++v) std::cout << ' ' << octree.original_vertex(v);
    std::cout << ", tetrahedra";
    for (auto t : octree.leaf_tetrahedra(leaf)) std::cout << ' ' << octree.original_tetrahedron(t);
    std::cout << '\n';
  }
  const auto stats = octree.statistics();
  std::cout << stats.nodes << " nodes, " << stats.leaves << " leaves, chi = " << stats.chi << '\n';
  return 0;
}
