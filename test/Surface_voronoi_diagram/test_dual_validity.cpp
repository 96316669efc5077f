// Tests of CGAL/Surface_voronoi_diagram/dual_validity.h: whether a dual triangulation is a
// valid mesh of the surface, and the cells that keep it from being one.
#include "test_support.h"

#include <CGAL/Surface_voronoi_diagram/Euclidean_embedding.h>
#include <CGAL/Surface_voronoi_diagram/dual_triangulation.h>
#include <CGAL/Surface_voronoi_diagram/dual_validity.h>
#include <test_meshes.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <cmath>

// this file's own names: the suite compiles its files together (see CMakeLists.txt)
namespace svd_test_dual_validity {

using namespace svd_test;
namespace SV = CGAL::Surface_voronoi;
namespace GEN = svd_test::meshes;

namespace {

typedef SV::Euclidean_embedding<Mesh> Euclidean;
typedef CGAL::Surface_voronoi_diagram<Mesh, Euclidean> Euclidean_diagram;

struct Dual
{
  std::vector<Point> points;
  std::vector<std::array<std::size_t, 3> > triangles;
};

Dual dual_of(const Euclidean_diagram& vd)
{
  Dual d;
  SV::dual_triangulation(vd, std::back_inserter(d.points), std::back_inserter(d.triangles));
  return d;
}

// The genus of a closed or bordered mesh, computed here from its own counts: the oracle of
// the report's topology.
long genus_of(const Mesh& m)
{
  long border_loops = 0;
  std::set<Mesh::Halfedge_index> seen;
  for(Mesh::Halfedge_index h : m.halfedges())
    if(m.is_border(h) && seen.insert(h).second)
    {
      ++border_loops;
      for(Mesh::Halfedge_index g = m.next(h); g != h; g = m.next(g)) seen.insert(g);
    }
  const long euler = long(m.number_of_vertices()) - long(m.number_of_edges()) + long(m.number_of_faces());
  return (2 - border_loops - euler) / 2;   // one component
}

// Sites on a torus at the given angles around its axis, on the outer equator.
std::vector<Location<Mesh> > torus_sites(const Mesh& torus, double major, double minor, const std::vector<double>& angles)
{
  std::vector<Location<Mesh> > sites;
  for(double a : angles)
    sites.push_back(CGAL::Polygon_mesh_processing::locate(Point((major + minor) * std::cos(a), (major + minor) * std::sin(a), 0.), torus));
  return sites;
}

} // namespace

TEST_CASE("dual validity: well-spread sites on a sphere, a torus and a planar patch give a valid dual of the input's topology", "[dual][validity]")
{
  struct Case { const char* name; Mesh mesh; std::size_t sites; long genus; std::size_t loops; };
  std::vector<Case> cases(3);
  cases[0].name = "sphere"; GEN::make_icosphere(cases[0].mesh, 4, 1.0); cases[0].sites = 80; cases[0].genus = 0; cases[0].loops = 0;
  cases[1].name = "torus"; GEN::make_torus(cases[1].mesh, 1.0, 0.4, 90, 36); cases[1].sites = 300; cases[1].genus = 1; cases[1].loops = 0;
  cases[2].name = "patch"; GEN::make_planar_grid(cases[2].mesh, 31, 31, 1.0, 1.0, 0.2, 4); cases[2].sites = 40; cases[2].genus = 0; cases[2].loops = 1;
  for(const Case& c : cases)
  {
    INFO(c.name);
    Euclidean e(c.mesh);
    const Euclidean_diagram vd(c.mesh, e, area_uniform_locations(c.mesh, c.sites, 3));
    const Dual d = dual_of(vd);
    const SV::Dual_validity r = SV::validate_dual_triangulation(vd, d.points, d.triangles);
    INFO(r.reason());
    CHECK(r.is_valid());
    CHECK(r.reason().empty());
    CHECK(r.cells_not_disks.empty());
    CHECK(r.pairs_in_several_arcs.empty());
    CHECK(r.triples_at_several_vertices.empty());
    CHECK(r.triangles == d.triangles.size());
    CHECK(r.input_genus == c.genus);
    CHECK(r.input_boundary_loops == c.loops);
    CHECK(r.input_components == 1);
    // the report's topology against the dual mesh's own counts
    Mesh dual;
    CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(d.points, d.triangles, dual);
    CHECK(r.genus == genus_of(dual));
    CHECK(r.genus == c.genus);
    CHECK(r.boundary_loops == c.loops);
    CHECK(r.components == 1);
    CHECK(r.self_intersections == 0);
  }
}

TEST_CASE("dual validity: three sites around a torus make three rings, and their dual is not a valid mesh", "[dual][validity]")
{
  Mesh torus;
  GEN::make_torus(torus, 1.0, 0.4, 90, 36);
  Euclidean e(torus);
  const double pi = std::acos(-1.);
  // three sites on the outer equator, a third of a turn apart: each cell is a band around
  // the tube, an annulus, and every two of them share two arcs (one on each side of a band)
  const Euclidean_diagram vd(torus, e, torus_sites(torus, 1.0, 0.4, { 0., 2 * pi / 3, 4 * pi / 3 }));
  const Dual d = dual_of(vd);
  const SV::Dual_validity r = SV::validate_dual_triangulation(vd, d.points, d.triangles);
  CHECK_FALSE(r.is_valid());
  CHECK(r.cells_not_disks == std::vector<std::size_t>{ 0, 1, 2 });
  CHECK(r.pairs_in_several_arcs.empty());   // each two bands meet along one circle, one arc
  CHECK(r.triangles == 0);                  // no point where three bands meet
  CHECK(r.reason().find("cells not disks") != std::string::npos);
  CHECK(r.input_genus == 1);
}

TEST_CASE("dual validity: a triangle reversed, doubled or removed is found and named", "[dual][validity]")
{
  Mesh sphere;
  GEN::make_icosphere(sphere, 4, 1.0);
  Euclidean e(sphere);
  const Euclidean_diagram vd(sphere, e, area_uniform_locations(sphere, 80, 3));
  const Dual d = dual_of(vd);
  REQUIRE(SV::validate_dual_triangulation(vd, d.points, d.triangles).is_valid());

  SECTION("all reversed: every triangle faces inward")
  {
    std::vector<std::array<std::size_t, 3> > t = d.triangles;
    for(auto& x : t) std::swap(x[1], x[2]);
    const SV::Dual_validity r = SV::validate_dual_triangulation(vd, d.points, t);
    CHECK_FALSE(r.is_valid());
    CHECK(r.flipped_triangles == t.size());
    CHECK(r.is_polygon_mesh);
    CHECK(r.reason().find("flipped") != std::string::npos);
    CHECK(r.cells_not_disks.empty());   // the cells are fine: the triangulation is not
  }
  SECTION("one doubled: three non-manifold edges")
  {
    std::vector<std::array<std::size_t, 3> > t = d.triangles;
    t.push_back(t.front());
    const SV::Dual_validity r = SV::validate_dual_triangulation(vd, d.points, t);
    CHECK_FALSE(r.is_valid());
    CHECK(r.non_manifold_edges == 3);
    CHECK_FALSE(r.is_polygon_mesh);
  }
  SECTION("one removed: a boundary loop the closed input does not have")
  {
    std::vector<std::array<std::size_t, 3> > t(d.triangles.begin() + 1, d.triangles.end());
    const SV::Dual_validity r = SV::validate_dual_triangulation(vd, d.points, t);
    CHECK_FALSE(r.is_valid());
    CHECK(r.is_polygon_mesh);
    CHECK(r.boundary_loops == 1);
    CHECK(r.input_boundary_loops == 0);
    CHECK(r.reason().find("boundary loops") != std::string::npos);
  }
  SECTION("a repeated site: degenerate")
  {
    std::vector<std::array<std::size_t, 3> > t = d.triangles;
    t[0][1] = t[0][0];
    const SV::Dual_validity r = SV::validate_dual_triangulation(vd, d.points, t);
    CHECK_FALSE(r.is_valid());
    CHECK(r.degenerate_triangles == 1);
  }
}

} // namespace svd_test_dual_validity
