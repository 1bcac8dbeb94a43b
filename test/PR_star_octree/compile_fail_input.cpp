// Must NOT compile: an input mesh that is not a model of PRStarOctreeInputMesh.
// The test passes when the compiler output contains the readable static_assert message.
#include <CGAL/PR_star_octree.h>

struct Not_a_mesh {
  int size() const { return 0; }
};

int main() {
  CGAL::PR_star_octree_3<> tree(Not_a_mesh{});
  return static_cast<int>(tree.number_of_vertices());
}
