// Tests of CGAL/Surface_voronoi_diagram/dual_triangulation.h: remeshing by the dual.
#include "test_support.h"

#include <CGAL/Surface_voronoi_diagram/Euclidean_embedding.h>
#include <CGAL/Surface_voronoi_diagram/dual_triangulation.h>
#include <test_meshes.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

// this file's own names: the suite compiles its files together (see CMakeLists.txt)
namespace svd_test_dual_triangulation {

using namespace svd_test;
namespace SV = CGAL::Surface_voronoi;
namespace GEN = svd_test::meshes;

TEST_CASE("dual: a sphere's diagram gives a closed, outward-oriented triangulation of the sites", "[dual]")
{
  Mesh m;
  GEN::make_icosphere(m, 4, 1.0);
  const auto sites = area_uniform_locations(m, 60, 2);
  CGAL::Biharmonic_embedding<Mesh> e(m);
  CGAL::Surface_voronoi_diagram<Mesh> vd(m, e, sites);
  std::vector<Point> points;
  std::vector<std::array<std::size_t, 3> > triangles;
  const bool manifold = SV::dual_triangulation(vd, std::back_inserter(points), std::back_inserter(triangles));
  CHECK(manifold);
  REQUIRE(points.size() == sites.size());
  CHECK(triangles.size() == 2 * sites.size() - 4);
  Mesh dual;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, triangles, dual);
  CHECK(CGAL::is_valid_polygon_mesh(dual));
  CHECK(CGAL::is_closed(dual));
  CHECK(num_vertices(dual) - num_edges(dual) + num_faces(dual) == 2);
  std::size_t outward = 0;
  for(const auto& t : triangles)
  {
    const K::Vector_3 n = CGAL::cross_product(points[t[1]] - points[t[0]], points[t[2]] - points[t[0]]);
    outward += (n * (points[t[0]] - CGAL::ORIGIN) > 0);
  }
  CHECK(outward == triangles.size());
}

TEST_CASE("dual: a planar patch gives the Delaunay triangles of the sites, a mesh with a border", "[dual]")
{
  Mesh m;
  GEN::make_planar_grid(m, 31, 31, 1.0, 1.0, 0.2, 4);
  const auto sites = area_uniform_locations(m, 40, 6);
  SV::Euclidean_embedding<Mesh> e(m);
  CGAL::Surface_voronoi_diagram<Mesh, SV::Euclidean_embedding<Mesh> > vd(m, e, sites);
  std::vector<Point> points;
  std::vector<std::array<std::size_t, 3> > triangles;
  CHECK(SV::dual_triangulation(vd, std::back_inserter(points), std::back_inserter(triangles)));
  // every dual triangle is counter-clockwise (the grid faces +z) and its circumcircle holds
  // no other site (the empty-circle property of Delaunay triangles)
  for(const auto& t : triangles)
  {
    const K::Point_2 a(points[t[0]].x(), points[t[0]].y()), b(points[t[1]].x(), points[t[1]].y()), c(points[t[2]].x(), points[t[2]].y());
    CHECK(CGAL::orientation(a, b, c) == CGAL::LEFT_TURN);
    for(const Point& p : points)
      CHECK(CGAL::side_of_bounded_circle(a, b, c, K::Point_2(p.x(), p.y())) != CGAL::ON_BOUNDED_SIDE);
  }
}

} // namespace svd_test_dual_triangulation
