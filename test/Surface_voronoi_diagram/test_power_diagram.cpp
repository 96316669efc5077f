// Power diagrams (paper 4.7.1): per-site weights, |E(x) - E(s)|^2 - w, exact per triangle.
#include "test_support.h"

#include <CGAL/Surface_voronoi_diagram/Euclidean_embedding.h>
#include <CGAL/Surface_voronoi_diagram/mesh_generators.h>

using namespace svd_test;
namespace SV = CGAL::Surface_voronoi;
namespace GEN = CGAL::Surface_voronoi::generators;
typedef SV::Euclidean_embedding<Mesh> Euclidean;

TEST_CASE("power: all-zero weights give exactly the plain diagram", "[power]")
{
  Mesh m;
  GEN::make_torus(m, 1.0, 0.35, 40, 16);
  const auto sites = area_uniform_locations(m, 60, 4);
  CGAL::Biharmonic_embedding<Mesh> e(m);
  SV::Diagram_options zero;
  zero.weights.assign(sites.size(), 0.);
  CGAL::Surface_voronoi_diagram<Mesh> plain(m, e, sites), weighted(m, e, sites, zero);
  REQUIRE(plain.partition().pieces.size() == weighted.partition().pieces.size());
  for(std::size_t p = 0; p < plain.partition().pieces.size(); ++p)
  {
    CHECK(plain.partition().pieces[p].site == weighted.partition().pieces[p].site);
    CHECK(plain.partition().pieces[p].vertices == weighted.partition().pieces[p].vertices);
  }
  for(std::size_t i = 0; i < sites.size(); ++i)
    CHECK(plain.cell_area(i) == weighted.cell_area(i));
}

TEST_CASE("power: raising one weight never shrinks that cell", "[power]")
{
  Mesh m;
  GEN::make_icosphere(m, 4, 1.0);
  const auto sites = area_uniform_locations(m, 50, 7);
  Euclidean e(m);
  SV::Diagram_options o;
  o.weights.assign(sites.size(), 0.);
  double previous = -1;
  std::size_t grew = 0;
  for(double w : { 0.0, 0.01, 0.02, 0.05, 0.1, 0.2 })
  {
    o.weights[3] = w;
    CGAL::Surface_voronoi_diagram<Mesh, Euclidean> vd(m, e, sites, o);
    check_invariants(vd, false);
    CHECK(vd.site_of(vd.site_location(3)) == 3);
    CHECK(vd.cell_area(3) >= previous);
    grew += vd.cell_area(3) > previous * (1 + 1e-9);
    previous = vd.cell_area(3);
  }
  CHECK(grew >= 5);   // it really grows
}

TEST_CASE("power: a site with a very low weight may own nothing and is reported", "[power]")
{
  Mesh m;
  GEN::make_icosphere(m, 3, 1.0);
  const auto sites = area_uniform_locations(m, 30, 2);
  Euclidean e(m);
  SV::Diagram_options o;
  o.weights.assign(sites.size(), 0.);
  o.weights[5] = -10.0;   // farther than anything on a unit sphere (squared distances <= 4)
  CGAL::Surface_voronoi_diagram<Mesh, Euclidean> vd(m, e, sites, o);
  CHECK(vd.cell_area(5) == 0);
  CHECK(vd.number_of_pieces(5) == 0);
  CHECK(vd.statistics().empty_cells == 1);
  CHECK(vd.statistics().cells == sites.size() - 1);
  double sum = vd.unreached_area();
  for(std::size_t i = 0; i < sites.size(); ++i) sum += vd.cell_area(i);
  CHECK(sum == Approx(vd.surface_area()).epsilon(1e-9));
  CHECK(vd.unreached_area() == 0);
  for(std::size_t i = 0; i < sites.size(); ++i)
    if(i != 5) CHECK(vd.number_of_pieces(i) == 1);
}
