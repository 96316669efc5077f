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
#include <random>

// this file's own names: the suite compiles its files together (see CMakeLists.txt)
namespace svd_test_refinement {

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

  // too few vertices allowed: the refinement stops there and says so
  Mesh tiny_mesh;
  const auto tiny = SV::refine_for_sites(m, sites, tiny_mesh, SV::parameters::refinement_max_vertices(100));
  CHECK(tiny.vertex_limit_reached);
  CHECK(num_vertices(tiny_mesh) <= 100);
}

TEST_CASE("refinement: a site exactly on an input edge or vertex stays exactly on one of the refined mesh", "[refinement]")
{
  Mesh m;
  GEN::make_torus(m, 1.0, 0.35, 10, 5);
  // points at irrational fractions of edges (so that the splits do not meet them), and at vertices
  std::vector<Location<Mesh> > sites;
  std::size_t k = 0;
  for(auto f : faces(m))
  {
    if(k % 7 == 0) sites.emplace_back(f, std::array<double, 3>{{ 0., 1 / std::sqrt(2.), 1 - 1 / std::sqrt(2.) }});
    if(k % 7 == 3) sites.emplace_back(f, std::array<double, 3>{{ 0., 0., 1. }});
    ++k;
  }
  Mesh refined;
  const auto r = SV::refine_for_sites(m, sites, refined);
  REQUIRE(r.edges_split > 0);
  REQUIRE(r.sites.size() == sites.size());
  std::size_t on_edge = 0;
  for(std::size_t i = 0; i < sites.size(); ++i)
  {
    const auto& b = r.sites[i].second;
    const std::size_t zeros = (b[0] == 0.) + (b[1] == 0.) + (b[2] == 0.);
    on_edge += (zeros >= (sites[i].second[0] == 0. && sites[i].second[1] == 0. ? 2u : 1u));
    CHECK(CGAL::squared_distance(point_of(sites[i], m), point_of(r.sites[i], refined)) < 1e-24);
  }
  CHECK(on_edge == sites.size());
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

// The local rule (refinement_local_spacing): on a coarse square where 150 sites crowd one
// corner (0.09 wide) and 50 lie on a lattice wider than the mean spacing over the rest, the edges in the
// crowded corner come down to the spacing of the sites there, which the mean rule
// (sqrt(area / sites)) leaves several times as coarse; elsewhere, where the local spacing is
// capped by the mean one, both rules refine alike. Same surface, sites in place.
TEST_CASE("refinement: the local spacing refines where the sites crowd, and only there", "[refinement]")
{
  Mesh m;
  GEN::make_planar_grid(m, 5, 5);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> corner(0.01, 0.09);
  std::vector<Location<Mesh> > sites;
  for(int k = 0; k < 150; ++k) sites.push_back(CGAL::Polygon_mesh_processing::locate(Point(corner(rng), corner(rng), 0), m));
  for(int i = 0; i < 7; ++i)
    for(int j = 0; j < 7; ++j) sites.push_back(CGAL::Polygon_mesh_processing::locate(Point(0.3 + 0.1 * i, 0.3 + 0.1 * j, 0), m));
  sites.push_back(CGAL::Polygon_mesh_processing::locate(Point(0.95, 0.1, 0), m));
  Mesh mean_mesh, local_mesh;
  const auto mean = SV::refine_for_sites(m, sites, mean_mesh);
  const auto local = SV::refine_for_sites(m, sites, local_mesh, SV::parameters::refinement_local_spacing(true));
  REQUIRE(!mean.vertex_limit_reached);
  REQUIRE(!local.vertex_limit_reached);
  CHECK(PMP::area(local_mesh) == Approx(1.).epsilon(1e-12));
  REQUIRE(local.sites.size() == sites.size());
  for(std::size_t i = 0; i < sites.size(); ++i)
    CHECK(CGAL::squared_distance(point_of(sites[i], m), point_of(local.sites[i], local_mesh)) < 1e-24);

  // the oracle's spacing of the crowded sites: the largest distance from one of them to its
  // nearest other site, at most the mean spacing
  const double mean_spacing = std::sqrt(1. / 200);
  double crowded = 0;
  for(std::size_t i = 0; i < 150; ++i)
  {
    double nearest = mean_spacing;
    for(std::size_t j = 0; j < sites.size(); ++j)
      if(j != i) nearest = (std::min)(nearest, std::sqrt(CGAL::squared_distance(point_of(sites[i], m), point_of(sites[j], m))));
    crowded = (std::max)(crowded, nearest);
  }
  REQUIRE(crowded < 0.5 * mean_spacing);
  // in the crowded corner (away from its edge, where the sparse sites' spacing takes over),
  // edges are within the trigger (0.75) of that spacing, allowing for the diagonals a split
  // leaves at most as long as the legs of a grid triangle (a factor sqrt(2))
  auto longest_in_corner = [](const Mesh& g) {
    double longest = 0;
    for(auto e : edges(g))
    {
      const Point mid = CGAL::midpoint(g.point(source(halfedge(e, g), g)), g.point(target(halfedge(e, g), g)));
      if(mid.x() < 0.07 && mid.y() < 0.07) longest = (std::max)(longest, std::sqrt(PMP::squared_edge_length(e, g)));
    }
    return longest;
  };
  CHECK(longest_in_corner(local_mesh) <= 0.75 * std::sqrt(2.) * crowded);
  CHECK(longest_in_corner(mean_mesh) > 0.75 * std::sqrt(2.) * crowded);
  // away from the corner the two rules agree on the vertex count to within a fifth
  auto vertices_outside = [](const Mesh& g) {
    std::size_t count = 0;
    for(auto v : vertices(g)) count += (g.point(v).x() > 0.4 || g.point(v).y() > 0.4);
    return count;
  };
  INFO("outside the corner: mean rule " << vertices_outside(mean_mesh) << ", local rule " << vertices_outside(local_mesh));
  CHECK(std::abs(double(vertices_outside(local_mesh)) - double(vertices_outside(mean_mesh))) <= 0.2 * double(vertices_outside(mean_mesh)));
}

} // namespace svd_test_refinement
