// Tests of CGAL/Surface_voronoi_diagram/refinement.h: the refined copy is the same surface,
// its edges are short enough, the sites stay where they were, and on a coarse mesh the
// geodesic metric needs it to come close to the exact geodesic Voronoi diagram.
#include "test_support.h"

#include <CGAL/Surface_voronoi_diagram/Geodesic_metric.h>
#include <test_meshes.h>
#include <fidelity.h>   // benchmark/Surface_voronoi_diagram: the fidelity measurement
#include <CGAL/Surface_voronoi_diagram/refinement.h>

#include <CGAL/Polygon_mesh_processing/measure.h>

#include <map>

using namespace svd_test;
namespace SV = CGAL::Surface_voronoi;
namespace GEN = svd_test::meshes;
namespace PMP = CGAL::Polygon_mesh_processing;

TEST_CASE("refinement: the same surface, short edges, the sites in place", "[refinement]")
{
  Mesh m;
  GEN::make_torus(m, 1.0, 0.35, 10, 5);   // coarse: 50 vertices, long thin faces
  const auto sites = area_uniform_locations(m, 200, 5);
  Mesh refined;
  auto input_face = refined.add_property_map<Mesh::Face_index, Mesh::Face_index>("f:input_face").first;
  const auto r = SV::refine_for_sites(m, sites, refined, CGAL::parameters::default_values(),
                                      SV::parameters::input_face_map(input_face));
  REQUIRE(!r.vertex_limit_reached);
  REQUIRE(r.edges_split > 0);
  CHECK(CGAL::is_valid_polygon_mesh(refined));
  CHECK(CGAL::is_triangle_mesh(refined));
  CHECK(PMP::area(refined) == Approx(PMP::area(m)).epsilon(1e-12));
  // every edge is below the trigger, and the ones the refinement made are near the target
  std::size_t long_edges = 0;
  for(auto e : edges(refined))
    long_edges += std::sqrt(PMP::squared_edge_length(e, refined)) > r.target_edge_length * 0.75 / 0.4;
  CHECK(long_edges == 0);

  // every refined face lies inside its input face: the areas add up face by face
  std::map<Mesh::Face_index, double> area_by_input;
  for(auto f : faces(refined)) area_by_input[input_face[f]] += PMP::face_area(f, refined);
  std::size_t wrong = 0;
  for(auto f : faces(m)) wrong += std::abs(area_by_input[f] - PMP::face_area(f, m)) > 1e-12 * PMP::area(m);
  CHECK(wrong == 0);

  REQUIRE(r.sites.size() == sites.size());
  double moved = 0;
  for(std::size_t i = 0; i < sites.size(); ++i)
    moved = (std::max)(moved, std::sqrt(CGAL::to_double(CGAL::squared_distance(point_of(sites[i], m), point_of(r.sites[i], refined)))));
  CHECK(moved < 1e-12);

  // a fine mesh is left as it is; so is a mesh whose edges are all below the trigger
  Mesh again_mesh;
  const auto again = SV::refine_for_sites(refined, r.sites, again_mesh);
  CHECK(!again.vertex_limit_reached);
  CHECK(again.edges_split == 0);
  CHECK(num_vertices(again_mesh) == num_vertices(refined));
  Mesh lenient_mesh;
  const auto lenient = SV::refine_for_sites(m, sites, lenient_mesh, SV::parameters::refinement_trigger_ratio(100));
  CHECK(!lenient.vertex_limit_reached);
  CHECK(lenient.edges_split == 0);
  // refinement is deterministic
  Mesh twice_mesh;
  const auto twice = SV::refine_for_sites(m, sites, twice_mesh);
  CHECK(!twice.vertex_limit_reached);
  REQUIRE(num_vertices(twice_mesh) == num_vertices(refined));
  std::size_t same = 0;
  for(auto v : vertices(refined)) same += (twice_mesh.point(v) == refined.point(v));
  CHECK(same == num_vertices(refined));

  // too few vertices allowed: the refinement stops there and says so (the deprecated overload
  // threw Input_error instead: test_deprecated.cpp)
  Mesh tiny_mesh;
  const auto tiny = SV::refine_for_sites(m, sites, tiny_mesh, SV::parameters::refinement_max_vertices(100));
  CHECK(tiny.vertex_limit_reached);
  CHECK(num_vertices(tiny_mesh) <= 100);
}

TEST_CASE("refinement: on a coarse mesh the geodesic metric needs it", "[refinement][geodesic]")
{
  Mesh m;
  GEN::make_torus(m, 1.0, 0.35, 10, 5);
  const auto sites = area_uniform_locations(m, 150, 9);

  SV::Geodesic_metric<Mesh> coarse_metric(m);
  CGAL::Surface_voronoi_diagram<Mesh, SV::Geodesic_metric<Mesh> > coarse(m, coarse_metric, sites);
  const svd_bench::Fidelity_report before = svd_bench::measure_fidelity(coarse, 3000, 17, 0);

  Mesh refined;
  const auto r = SV::refine_for_sites(m, sites, refined);
  REQUIRE(!r.vertex_limit_reached);
  SV::Geodesic_metric<Mesh> metric(refined);
  CGAL::Surface_voronoi_diagram<Mesh, SV::Geodesic_metric<Mesh> > fine(refined, metric, r.sites);
  check_invariants(fine);
  const svd_bench::Fidelity_report after = svd_bench::measure_fidelity(fine, 3000, 17, 4);
  INFO("mislabeled: coarse " << before.mislabeled_share << ", refined " << after.mislabeled_share);
  CHECK(before.mislabeled_share > 0.04);
  CHECK(before.mislabeled_share > 5 * after.mislabeled_share);
  CHECK(after.mislabeled_share <= 0.03);
  CHECK(after.through_wall_upper == 0);
}

TEST_CASE("refinement: a thin strip reaches a small vertex cap quickly and gives no sites", "[refinement][numerics]")
{
  // a 1 x 1e-6 strip of two needles: splitting down to the area-derived length never ends
  // in practice (over 500,000 vertices for 2 sites); the cap stops it
  Mesh m;
  const auto a = m.add_vertex(Point(0, 0, 0)), b = m.add_vertex(Point(1, 0, 0));
  const auto c = m.add_vertex(Point(1, 1e-6, 0)), d = m.add_vertex(Point(0, 1e-6, 0));
  m.add_face(a, b, c);
  m.add_face(a, c, d);
  const auto sites = area_uniform_locations(m, 2, 1);
  Mesh refined;
  const auto r = SV::refine_for_sites(m, sites, refined, SV::parameters::refinement_max_vertices(1536));
  CHECK(r.vertex_limit_reached);
  CHECK(r.sites.empty());
  CHECK(num_vertices(refined) <= 1536);
}
