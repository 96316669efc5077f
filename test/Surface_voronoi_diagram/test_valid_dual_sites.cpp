// Tests of CGAL/Surface_voronoi_diagram/valid_dual_sites.h: sites added until the dual
// triangulation is a valid mesh, the given sites kept in place.
#include "test_support.h"

#include <CGAL/Surface_voronoi_diagram/Euclidean_embedding.h>
#include <CGAL/Surface_voronoi_diagram/Geodesic_metric.h>
#include <CGAL/Surface_voronoi_diagram/lloyd_relaxation.h>
#include <CGAL/Surface_voronoi_diagram/sampling.h>
#include <CGAL/Surface_voronoi_diagram/dual_triangulation.h>
#include <CGAL/Surface_voronoi_diagram/dual_validity.h>
#include <CGAL/Surface_voronoi_diagram/valid_dual_sites.h>
#include <test_meshes.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <algorithm>
#include <cmath>

// this file's own names: the suite compiles its files together (see CMakeLists.txt)
namespace svd_test_valid_dual_sites {

using namespace svd_test;
namespace SV = CGAL::Surface_voronoi;
namespace GEN = svd_test::meshes;

namespace {

typedef SV::Euclidean_embedding<Mesh> Euclidean;
typedef CGAL::Surface_voronoi_diagram<Mesh, Euclidean> Euclidean_diagram;

std::vector<Location<Mesh> > sites_around_torus(const Mesh& torus, double outer_radius, std::size_t n)
{
  const double pi = std::acos(-1.);
  std::vector<Location<Mesh> > sites;
  for(std::size_t k = 0; k < n; ++k)
  {
    const double a = 2 * pi * double(k) / double(n);
    sites.push_back(CGAL::Polygon_mesh_processing::locate(Point(outer_radius * std::cos(a), outer_radius * std::sin(a), 0.), torus));
  }
  return sites;
}

// The dual of these sites, checked afresh: the oracle of what the function reports.
SV::Dual_validity check_afresh(const Mesh& m, Euclidean& e, const std::vector<Location<Mesh> >& sites, long& genus)
{
  const Euclidean_diagram vd(m, e, sites);
  std::vector<Point> points;
  std::vector<std::array<std::size_t, 3> > triangles;
  SV::dual_triangulation(vd, std::back_inserter(points), std::back_inserter(triangles));
  const SV::Dual_validity v = SV::validate_dual_triangulation(vd, points, triangles);
  genus = -1;
  if(v.is_polygon_mesh)
  {
    Mesh dual;
    CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, triangles, dual);
    const long euler = long(dual.number_of_vertices()) - long(dual.number_of_edges()) + long(dual.number_of_faces());
    genus = (2 - euler) / 2;   // one closed component
  }
  return v;
}

} // namespace

TEST_CASE("valid dual: three rings around a torus get sites until the dual is a torus, the given sites in place", "[dual][validity]")
{
  Mesh torus;
  GEN::make_torus(torus, 1.0, 0.4, 90, 36);
  Euclidean e(torus);
  const auto given = sites_around_torus(torus, 1.4, 3);
  {
    long genus = 0;
    REQUIRE_FALSE(check_afresh(torus, e, given, genus).is_valid());
  }
  const SV::Valid_dual_result<Mesh> r = SV::add_sites_for_valid_dual(torus, e, given);
  INFO(r.validity.reason());
  CHECK(r.validity.is_valid());
  CHECK(r.sites_added > 0);
  CHECK(r.sites_added <= SV::default_maximum_number_of_added_sites(given.size()));
  CHECK(r.rounds > 0);
  REQUIRE(r.sites.size() == given.size() + r.sites_added);
  for(std::size_t i = 0; i < given.size(); ++i)
  {
    CHECK(r.sites[i].first == given[i].first);
    CHECK(r.sites[i].second == given[i].second);
  }
  // the oracle: the dual of the returned sites, built and checked again, is a valid torus
  long genus = -1;
  const SV::Dual_validity again = check_afresh(torus, e, r.sites, genus);
  CHECK(again.is_valid());
  CHECK(genus == 1);
  CHECK(r.validity.genus == 1);
}

TEST_CASE("valid dual: the default budget is a quarter of the given sites, and at least 64", "[dual][validity]")
{
  CHECK(SV::default_maximum_number_of_added_sites(0) == 64);
  CHECK(SV::default_maximum_number_of_added_sites(259) == 64);
  CHECK(SV::default_maximum_number_of_added_sites(260) == 65);
  CHECK(SV::default_maximum_number_of_added_sites(3000) == 750);
}

TEST_CASE("valid dual: sites whose dual is valid already are returned as they are", "[dual][validity]")
{
  Mesh sphere;
  GEN::make_icosphere(sphere, 4, 1.0);
  Euclidean e(sphere);
  const auto given = area_uniform_locations(sphere, 80, 3);
  const SV::Valid_dual_result<Mesh> r = SV::add_sites_for_valid_dual(sphere, e, given);
  CHECK(r.validity.is_valid());
  CHECK(r.sites_added == 0);
  CHECK(r.rounds == 0);
  CHECK_FALSE(r.nothing_to_cut);
  CHECK(r.sites == given);
}

TEST_CASE("valid dual: a budget too small stops with the dual's reason, within the budget", "[dual][validity]")
{
  Mesh torus;
  GEN::make_torus(torus, 1.0, 0.4, 90, 36);
  Euclidean e(torus);
  const auto given = sites_around_torus(torus, 1.4, 3);
  const SV::Valid_dual_result<Mesh> r = SV::add_sites_for_valid_dual(torus, e, given, SV::parameters::maximum_number_of_added_sites(1));
  CHECK_FALSE(r.validity.is_valid());
  CHECK(r.sites_added <= 1);
  CHECK(r.sites.size() == given.size() + r.sites_added);
  CHECK_FALSE(r.validity.reason().empty());
}

// A component without sites has no cell to cut: the loop stops at once and says so
// (nothing_to_cut), adds nothing, and the validity names the missing component.
TEST_CASE("valid dual: a component without sites stops the loop with nothing to cut", "[dual][validity]")
{
  Mesh m, other;
  GEN::make_icosphere(m, 3, 1.0);
  const auto given = area_uniform_locations(m, 40, 7);   // before the second sphere is added
  GEN::make_icosphere(other, 3, 1.0);
  for(auto v : vertices(other)) other.point(v) = other.point(v) + K::Vector_3(5, 0, 0);
  CGAL::copy_face_graph(other, m);
  Euclidean e(m);
  const SV::Valid_dual_result<Mesh> r = SV::add_sites_for_valid_dual(m, e, given);
  CHECK_FALSE(r.validity.is_valid());
  CHECK(r.nothing_to_cut);
  CHECK_FALSE(r.no_room_for_sites);
  CHECK(r.sites_added == 0);
  CHECK(r.sites == given);
  // the sphere with the sites alone is valid: the missing component is the only defect
  Mesh alone;
  GEN::make_icosphere(alone, 3, 1.0);
  Euclidean e_alone(alone);
  long genus = 0;
  CHECK(check_afresh(alone, e_alone, area_uniform_locations(alone, 40, 7), genus).is_valid());
}

// Where a flipped triangle gets its site: the Voronoi vertex of its three cells. The oracle:
// on a planar patch with the Euclidean embedding, such a vertex is the circumcentre of its
// three sites, equally far from them (up to the cutting's rounding), and no site is nearer.
TEST_CASE("valid dual: the Voronoi vertices of three cells are equally far from their sites, and none is nearer", "[dual][validity]")
{
  Mesh m;
  GEN::make_planar_grid(m, 31, 31, 1.0, 1.0, 0.2, 4);
  Euclidean e(m);
  const auto sites = area_uniform_locations(m, 40, 6);
  const Euclidean_diagram vd(m, e, sites);
  const auto vertices = SV::internal::voronoi_vertex_locations<Mesh>(vd);
  std::vector<Point> site_points;
  for(const auto& l : sites) site_points.push_back(CGAL::Polygon_mesh_processing::construct_point(l, m));
  CHECK(vertices.size() >= 40);   // about twice the sites, less those on the border
  for(const auto& v : vertices)
  {
    const Point p = CGAL::Polygon_mesh_processing::construct_point(v.second, m);
    const double d0 = std::sqrt(CGAL::squared_distance(p, site_points[v.first[0]]));
    const double d1 = std::sqrt(CGAL::squared_distance(p, site_points[v.first[1]]));
    const double d2 = std::sqrt(CGAL::squared_distance(p, site_points[v.first[2]]));
    CHECK(std::abs(d0 - d1) <= 1e-9);
    CHECK(std::abs(d0 - d2) <= 1e-9);
    for(const Point& q : site_points)
      CHECK(std::sqrt(CGAL::squared_distance(p, q)) >= d0 - 1e-9);
  }
}

// A thin plate with the geodesic metric: a cell reaches around the plate's rim to meet two
// cells of the other side, and their dual triangle folds over the rim (flipped). The remedy is
// a site on the rim; once there, Lloyd must not pull it back onto a side.
TEST_CASE("valid dual: folds over a thin plate's rim get sites on the rim, and the dual becomes valid", "[dual][validity]")
{
  Mesh plate;
  GEN::Slab_options o;
  o.target_vertices = 2000;
  GEN::make_thin_slab(plate, o);
  SV::Geodesic_metric<Mesh> geodesic(plate);
  const auto given = SV::lloyd_relaxation(plate, geodesic, SV::blue_noise_sites(plate, 100, CGAL::parameters::random_seed(1)),
                                          CGAL::parameters::number_of_iterations(5)).sites;
  const CGAL::Surface_voronoi_diagram<Mesh, SV::Geodesic_metric<Mesh> > before(plate, geodesic, given);
  std::vector<Point> points;
  std::vector<std::array<std::size_t, 3> > triangles;
  SV::dual_triangulation(before, std::back_inserter(points), std::back_inserter(triangles));
  REQUIRE(SV::validate_dual_triangulation(before, points, triangles).flipped_triangles > 0);

  const SV::Valid_dual_result<Mesh> r = SV::add_sites_for_valid_dual(plate, geodesic, given);
  INFO(r.validity.reason());
  CHECK(r.validity.is_valid());
  REQUIRE(r.sites.size() == given.size() + r.sites_added);
  for(std::size_t i = 0; i < given.size(); ++i) CHECK(r.sites[i] == given[i]);

  // on the rim: on the plate's outline (the plate lies flat in the bounding box's two longest
  // directions, its rim faces across the shortest), where a site at a Voronoi vertex, on a
  // side, does not lie
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(plate);
  std::array<double, 3> extent = {{ box.xmax() - box.xmin(), box.ymax() - box.ymin(), box.zmax() - box.zmin() }};
  const int flat = int(std::min_element(extent.begin(), extent.end()) - extent.begin());
  const double band = 1e-9 * (extent[0] + extent[1] + extent[2]);
  std::size_t on_rim = 0;
  for(std::size_t i = given.size(); i < r.sites.size(); ++i)
  {
    const Point p = CGAL::Polygon_mesh_processing::construct_point(r.sites[i], plate);
    bool near = false;
    for(int k = 0; k < 3; ++k)
      if(k != flat) near |= (p[k] - box.min(k) <= band || box.max(k) - p[k] <= band);
    on_rim += near;
  }
  CHECK(on_rim > 0);
  // the oracle: the dual of the returned sites, built and checked again
  const CGAL::Surface_voronoi_diagram<Mesh, SV::Geodesic_metric<Mesh> > after(plate, geodesic, r.sites);
  points.clear();
  triangles.clear();
  SV::dual_triangulation(after, std::back_inserter(points), std::back_inserter(triangles));
  CHECK(SV::validate_dual_triangulation(after, points, triangles).is_valid());
}

// stop_on_coarse_mesh: an added site crowds the mesh when its face has an edge longer than
// 1.5 times its distance to the nearest other site (at least a sixteenth of the mean spacing).
// On a square of two triangles a site added 0.01 from a given one does; on a fine grid it
// does not, nor does one 0.0005 away (below the floor); given sites never count.
TEST_CASE("valid dual: an added site crowds a coarse mesh and not a fine one", "[dual][validity]")
{
  auto crowds = [](const Mesh& m, const std::vector<Point>& points, std::size_t first_added) {
    std::vector<Location<Mesh> > sites;
    for(const Point& p : points) sites.push_back(CGAL::Polygon_mesh_processing::locate(p, m));
    Euclidean e(m);
    const Euclidean_diagram vd(m, e, sites);
    return SV::internal::added_sites_crowd_the_mesh(vd, first_added);
  };
  Mesh coarse, fine;
  GEN::make_planar_grid(coarse, 2, 2);
  GEN::make_planar_grid(fine, 101, 101);
  const std::vector<Point> close = { Point(0.2, 0.2, 0), Point(0.8, 0.8, 0), Point(0.21, 0.2, 0) };
  CHECK(crowds(coarse, close, 2));
  CHECK_FALSE(crowds(coarse, close, 3));   // no added site
  CHECK_FALSE(crowds(fine, close, 2));
  CHECK_FALSE(crowds(fine, { Point(0.2, 0.2, 0), Point(0.8, 0.8, 0), Point(0.2005, 0.2, 0) }, 2));
  // on a grid of spacing 0.1 (diagonals 0.14), 0.05 from a site crowds, 0.6 does not
  Mesh medium;
  GEN::make_planar_grid(medium, 11, 11);
  CHECK(crowds(medium, { Point(0.2, 0.2, 0), Point(0.8, 0.8, 0), Point(0.25, 0.2, 0) }, 2));
  CHECK_FALSE(crowds(medium, { Point(0.2, 0.2, 0), Point(0.8, 0.8, 0), Point(0.8, 0.2, 0) }, 2));
}

// Where the added sites do not crowd the mesh, stop_on_coarse_mesh changes nothing.
TEST_CASE("valid dual: on a fine mesh stop_on_coarse_mesh changes nothing", "[dual][validity]")
{
  Mesh torus;
  GEN::make_torus(torus, 1.0, 0.4, 90, 36);
  Euclidean e(torus);
  const auto given = sites_around_torus(torus, 1.4, 3);
  const SV::Valid_dual_result<Mesh> plain = SV::add_sites_for_valid_dual(torus, e, given);
  const SV::Valid_dual_result<Mesh> checked = SV::add_sites_for_valid_dual(torus, e, given, SV::parameters::stop_on_coarse_mesh(true));
  CHECK_FALSE(checked.mesh_too_coarse);
  CHECK(checked.validity.is_valid());
  CHECK(checked.sites == plain.sites);
}

} // namespace svd_test_valid_dual_sites
