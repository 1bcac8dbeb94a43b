// Reads a tetrahedral mesh file (.mesh, .node/.ele, .vtk, .vtu, .off/.ts) and prints the storage
// statistics of its PR-star octree for a few bucket thresholds.
#include <CGAL/PR_star_octree.h>
#include <CGAL/PR_star_octree/IO.h>

#include <iostream>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: " << argv[0] << " MESH\n";
    return 2;
  }
  CGAL::PR_star_octree::Indexed_tetrahedral_mesh<> mesh;
  try {
    CGAL::PR_star_octree::IO::read_tetrahedral_mesh(argv[1], mesh);
  } catch (const CGAL::PR_star_octree::IO::Read_error& e) {
    std::cerr << e.what() << '\n'; // names the file, the line and the problem
    return 1;
  }
  for (std::size_t kv : {20, 100, 400}) {
    CGAL::PR_star_octree_3<> octree(CGAL::PR_star_octree::make_input(mesh),
                                    CGAL::PR_star_octree::parameters::bucket_size(kv));
    const auto s = octree.statistics();
    std::cout << "k_v = " << kv << ": |N| = " << s.nodes << ", |N_leaf| = " << s.leaves << ", chi = " << s.chi
              << ", overhead = " << s.prstar_overhead_per_vertex
              << " |V| (extended IA: " << s.ia_overhead_per_vertex << " |V|)\n";
  }
  return 0;
}
