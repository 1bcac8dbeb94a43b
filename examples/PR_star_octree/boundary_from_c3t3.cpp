// From a Mesh_3 complex to boundary flags: mesh a ball with CGAL Mesh_3, build the PR-star octree
// of the cells in the complex, and classify every vertex as interior or boundary.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/make_mesh_3.h>

#include <CGAL/PR_star_octree.h>
#include <CGAL/PR_star_octree/Mesh_complex_3_input.h>
#include <CGAL/PR_star_octree/boundary.h>
#include <CGAL/property_map.h>

#include <array>
#include <iostream>
#include <iterator>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Domain = CGAL::Labeled_mesh_domain_3<K>;
using Tr = CGAL::Mesh_triangulation_3<Domain, CGAL::Default, CGAL::Sequential_tag>::type;
using C3t3 = CGAL::Mesh_complex_3_in_triangulation_3<Tr>;
using Criteria = CGAL::Mesh_criteria_3<Tr>;

int main() {
  namespace params = CGAL::parameters;
  auto ball = [](const K::Point_3& p) { return CGAL::squared_distance(p, K::Point_3(CGAL::ORIGIN)) - 1.; };
  Domain domain = Domain::create_implicit_mesh_domain(ball, K::Sphere_3(CGAL::ORIGIN, 4.));
  Criteria criteria(params::facet_angle = 25, params::facet_size = 0.2, params::facet_distance = 0.02,
                    params::cell_radius_edge_ratio = 3, params::cell_size = 0.2);
  C3t3 c3t3 = CGAL::make_mesh_3<C3t3>(domain, criteria);

  // The adapter iterates the cells in the complex only; vertices are numbered as first met.
  const auto input = CGAL::PR_star_octree::make_input(c3t3);
  CGAL::PR_star_octree_3<K> octree(input, CGAL::PR_star_octree::parameters::bucket_size(50));

  // The type of every vertex, in the adapter's numbering (the order of `input`), and the boundary
  // triangles oriented outward.
  std::vector<CGAL::PR_star_octree::Vertex_type> types(input.number_of_vertices());
  std::vector<std::array<std::size_t, 3>> triangles;
  const auto boundary = CGAL::PR_star_octree::compute_boundary(
      octree, CGAL::make_property_map(types),
      CGAL::PR_star_octree::parameters::boundary_triangles_output(std::back_inserter(triangles)));

  std::cout << input.number_of_tetrahedra() << " tetrahedra, " << boundary.boundary_vertices
            << " boundary and " << boundary.interior_vertices << " interior vertices, " << triangles.size()
            << " boundary triangles\n";
  // Back to CGAL's handles: the flag of each vertex of the complex.
  std::size_t on_boundary = 0;
  for (std::size_t v = 0; v < types.size(); ++v)
    if (types[v] == CGAL::PR_star_octree::Vertex_type::BOUNDARY)
      on_boundary += (input.vertex_handle(v) != nullptr);
  std::cout << on_boundary << " vertex handles flagged as boundary\n";
  return boundary.nonmanifold_vertices == 0 ? 0 : 1;
}
