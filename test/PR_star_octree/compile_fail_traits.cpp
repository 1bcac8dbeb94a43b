// Must NOT compile: a geometric traits class without Point_3 / Orientation_3.
// The test passes when the compiler output contains the readable static_assert message.
#include <CGAL/PR_star_octree.h>

#include <array>
#include <vector>

struct Not_a_kernel {
  using FT = double;
};

int main() {
  std::vector<CGAL::Epick::Point_3> points;
  std::vector<std::array<int, 4>> tetrahedra;
  CGAL::PR_star_octree_3<Not_a_kernel> tree(CGAL::PR_star_octree::make_input(points, tetrahedra));
  return static_cast<int>(tree.number_of_vertices());
}
