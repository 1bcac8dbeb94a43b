// Simplify a Mesh_3 complex to half its tetrahedra with local half-edge collapses on the PR-star
// octree, check the result, and write it out (Medit .mesh).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/make_mesh_3.h>

#include <CGAL/PR_star_octree/IO.h>
#include <CGAL/PR_star_octree/Mesh_complex_3_input.h>
#include <CGAL/PR_star_octree/simplification.h>
#include <CGAL/PR_star_octree/validity.h>

#include <iostream>
#include <string>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Domain = CGAL::Labeled_mesh_domain_3<K>;
using Tr = CGAL::Mesh_triangulation_3<Domain, CGAL::Default, CGAL::Sequential_tag>::type;
using C3t3 = CGAL::Mesh_complex_3_in_triangulation_3<Tr>;
using Criteria = CGAL::Mesh_criteria_3<Tr>;

int main(int argc, char** argv) {
  const std::string out = argc > 1 ? argv[1] : "simplified_ball.mesh";
  namespace params = CGAL::parameters;
  auto ball = [](const K::Point_3& p) { return CGAL::squared_distance(p, K::Point_3(CGAL::ORIGIN)) - 1.; };
  Domain domain = Domain::create_implicit_mesh_domain(ball, K::Sphere_3(CGAL::ORIGIN, 4.));
  Criteria criteria(params::facet_angle = 25, params::facet_size = 0.15, params::facet_distance = 0.015,
                    params::cell_radius_edge_ratio = 3, params::cell_size = 0.15);
  C3t3 c3t3 = CGAL::make_mesh_3<C3t3>(domain, criteria);

  // Remove half of the tetrahedra, with k_v = 100.
  const auto result =
      CGAL::PR_star_octree::simplify(CGAL::PR_star_octree::make_input(c3t3),
                                     CGAL::PR_star_octree::parameters::target_fraction(0.5).bucket_size(100));
  const auto& s = result.statistics;
  std::cout << s.input_tetrahedra << " -> " << s.output_tetrahedra << " tetrahedra in " << s.rounds
            << " rounds\n";

  const auto validity = CGAL::PR_star_octree::check_validity(result.mesh.points, result.mesh.tetrahedra);
  std::cout << (validity.valid ? "valid" : "NOT valid") << ", Euler characteristic "
            << validity.euler_characteristic << '\n';
  CGAL::PR_star_octree::IO::write_tetrahedral_mesh(out, result.mesh);
  std::cout << "wrote " << out << '\n';
  return validity.valid ? 0 : 1;
}
