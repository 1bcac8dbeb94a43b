// A per-leaf application written on the public leaf executor: the valence and the star volume of
// every vertex into property maps, plus a total reduced in leaf order; then checked against a
// direct computation over all the tetrahedra.
#include <CGAL/PR_star_octree.h>
#include <CGAL/PR_star_octree/IO.h>
#include <CGAL/PR_star_octree/Leaf_executor.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <iostream>
#include <set>
#include <vector>

namespace PSO = CGAL::PR_star_octree;
using Octree = CGAL::PR_star_octree_3<>;

//! [per_leaf_application]
struct Leaf_summary {         // what a leaf hands to the reduction
  double star_volume_sum = 0; // sum of its vertices' star volumes
  std::size_t max_valence = 0;
};

// Valence (number of adjacent vertices) and star volume of every vertex, keyed by the user's
// vertex index; returns the sums, identical for any thread count (reduced in leaf order).
template <class ConcurrencyTag, class ValenceMap, class VolumeMap>
Leaf_summary valence_and_star_volume(const Octree& tree, ValenceMap valence, VolumeMap star_volume) {
  Leaf_summary total;
  PSO::Leaf_executor<ConcurrencyTag>().map_reduce(
      tree, PSO::VERTEX_TETRAHEDRA | PSO::VERTEX_VERTICES, /* per-thread state */ 0,
      [&](int, const PSO::Leaf_topology<Octree>& leaf) { // one leaf, maybe on another thread
        Leaf_summary sums;
        for (auto v = leaf.vertex_begin(); v < leaf.vertex_end(); ++v) {
          double volume = 0;
          for (auto t : leaf.vertex_tetrahedra(v)) {
            const auto& c = tree.tetrahedron(t); // positively oriented by the octree
            volume += CGAL::volume(tree.point(c[0]), tree.point(c[1]), tree.point(c[2]), tree.point(c[3]));
          }
          const std::size_t n = leaf.vertex_vertices(v).size();
          put(valence, tree.original_vertex(v), n); // each leaf writes only its own vertices
          put(star_volume, tree.original_vertex(v), volume);
          sums.star_volume_sum += volume;
          sums.max_valence = (std::max)(sums.max_valence, n);
        }
        return sums;
      },
      [&](Leaf_summary&& s) { // one leaf at a time, in leaf order
        total.star_volume_sum += s.star_volume_sum;
        total.max_valence = (std::max)(total.max_valence, s.max_valence);
      });
  return total;
}
//! [per_leaf_application]

int main(int argc, char** argv) {
  PSO::Indexed_tetrahedral_mesh<> mesh;
  if (argc > 1) {
    PSO::IO::read_tetrahedral_mesh(argv[1], mesh);
  } else { // a 12 x 12 x 12 grid of cubes, six tetrahedra each, around their diagonals
    const int n = 12;
    auto id = [n](int i, int j, int k) { return std::uint32_t((k * (n + 1) + j) * (n + 1) + i); };
    for (int k = 0; k <= n; ++k)
      for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) mesh.points.emplace_back(i, j, k);
    const int paths[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    for (int k = 0; k < n; ++k)
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
          for (const auto& path : paths) { // (i,j,k) to (i+1,j+1,k+1) one axis at a time
            int x[3] = {i, j, k};
            std::array<std::uint32_t, 4> t;
            t[0] = id(x[0], x[1], x[2]);
            for (int s = 0; s < 3; ++s) {
              ++x[path[s]];
              t[s + 1] = id(x[0], x[1], x[2]);
            }
            mesh.tetrahedra.push_back(t);
          }
  }
  const Octree tree(PSO::make_input(mesh), CGAL::PR_star_octree::parameters::bucket_size(50));
  const std::size_t nv = mesh.points.size();
  std::vector<std::size_t> valence(nv);
  std::vector<double> volume(nv);
  const Leaf_summary s = valence_and_star_volume<CGAL::Parallel_if_available_tag>(
      tree, CGAL::make_property_map(valence), CGAL::make_property_map(volume));
  std::cout << nv << " vertices, " << mesh.tetrahedra.size() << " tetrahedra, " << tree.number_of_leaves()
            << " leaves: largest valence " << s.max_valence << ", sum of star volumes " << s.star_volume_sum
            << '\n';

  // The same, directly over all the tetrahedra (global adjacency sets): the independent check.
  std::vector<std::set<std::size_t>> adjacent(nv);
  std::vector<double> direct(nv, 0.);
  for (const auto& t : mesh.tetrahedra) {
    const auto& p = mesh.points;
    const double vol = std::abs(CGAL::volume(p[t[0]], p[t[1]], p[t[2]], p[t[3]]));
    for (int a = 0; a < 4; ++a) {
      direct[t[a]] += vol;
      for (int b = 0; b < 4; ++b)
        if (a != b) adjacent[t[a]].insert(t[b]);
    }
  }
  std::size_t wrong = 0;
  for (std::size_t v = 0; v < nv; ++v)
    wrong += valence[v] != adjacent[v].size() || std::abs(volume[v] - direct[v]) > 1e-12 * (1 + direct[v]);
  const Leaf_summary again = valence_and_star_volume<CGAL::Sequential_tag>(
      tree, CGAL::make_property_map(valence), CGAL::make_property_map(volume));
  const bool same = again.star_volume_sum == s.star_volume_sum && again.max_valence == s.max_valence;
  std::cout << wrong << " vertices differ from the direct computation; sequential run "
            << (same ? "identical" : "DIFFERENT") << '\n';
  return wrong == 0 && same ? 0 : 1;
}
