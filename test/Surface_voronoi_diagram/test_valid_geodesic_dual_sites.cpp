// Tests of CGAL/Surface_voronoi_diagram/valid_geodesic_dual_sites.h: sites added until the
// geodesic diagram's dual is valid, on copies of the mesh refined for the sites.
#include "test_support.h"

#include <CGAL/Surface_voronoi_diagram/Geodesic_metric.h>
#include <CGAL/Surface_voronoi_diagram/dual_triangulation.h>
#include <CGAL/Surface_voronoi_diagram/dual_validity.h>
#include <CGAL/Surface_voronoi_diagram/refinement.h>
#include <CGAL/Surface_voronoi_diagram/valid_geodesic_dual_sites.h>

#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/boost/graph/generators.h>

// this file's own names: the suite compiles its files together (see CMakeLists.txt)
namespace svd_test_valid_geodesic_dual_sites {

using namespace svd_test;
namespace SV = CGAL::Surface_voronoi;

// A thin bar meshed by its eight corners alone: twelve needles a whole bar long, on which the
// geodesic metric (distances at vertices) tells no two sites apart. Sites crowd around the
// bar for its dual to be valid; the function refines the mesh for them as they come. The
// oracle: the diagram built afresh on the mesh refined for the returned sites (the one the
// documentation names) has a valid dual, of genus 0.
TEST_CASE("valid geodesic dual: a bar meshed with needles gets a valid dual on refined copies", "[dual][validity][geodesic]")
{
  Mesh bar;
  CGAL::make_hexahedron(Point(0, 0, 0), Point(1, 0, 0), Point(1, 0.06, 0), Point(0, 0.06, 0),
                        Point(0, 0.06, 0.06), Point(0, 0, 0.06), Point(1, 0, 0.06), Point(1, 0.06, 0.06), bar);
  CGAL::Polygon_mesh_processing::triangulate_faces(bar);
  REQUIRE(num_vertices(bar) == 8);
  const auto given = area_uniform_locations(bar, 20, 4);

  const SV::Valid_dual_result<Mesh> r = SV::add_sites_for_valid_geodesic_dual(bar, given);
  INFO(r.validity.reason() << "; added " << r.sites_added << " in " << r.rounds << " rounds");
  CHECK(r.validity.is_valid());
  CHECK(r.sites_added > 0);
  REQUIRE(r.sites.size() == given.size() + r.sites_added);
  for(std::size_t i = 0; i < given.size(); ++i) CHECK(r.sites[i] == given[i]);
  for(const auto& s : r.sites) CHECK(std::size_t(s.first) < num_faces(bar));

  Mesh refined;
  const auto refinement = SV::refine_for_sites(bar, r.sites, refined, SV::parameters::refinement_local_spacing(true));
  REQUIRE(!refinement.vertex_limit_reached);
  REQUIRE(refinement.edges_split > 0);
  SV::Geodesic_metric<Mesh> metric(refined);
  const CGAL::Surface_voronoi_diagram<Mesh, SV::Geodesic_metric<Mesh> > vd(refined, metric, refinement.sites);
  std::vector<Point> points;
  std::vector<std::array<std::size_t, 3> > triangles;
  SV::dual_triangulation(vd, std::back_inserter(points), std::back_inserter(triangles));
  const SV::Dual_validity again = SV::validate_dual_triangulation(vd, points, triangles);
  INFO("afresh: " << again.reason());
  CHECK(again.is_valid());
  CHECK(again.genus == 0);
}

} // namespace svd_test_valid_geodesic_dual_sites
