// Tests of the updates of Surface_voronoi_diagram (move_site(), insert_site(), remove_site(),
// set_site_weight(), update()): an updated diagram is the diagram computed afresh from the
// same sites in the same order, whatever the metric, including where cells needed repair.
#include "test_support.h"

#include <CGAL/Surface_voronoi_diagram/Biharmonic_embedding.h>
#include <CGAL/Surface_voronoi_diagram/Euclidean_embedding.h>
#include <CGAL/Surface_voronoi_diagram/Geodesic_metric.h>
#include <test_meshes.h>

#include <algorithm>
#include <vector>

// this file's own names: the suite compiles its files together (see CMakeLists.txt)
namespace svd_test_diagram_update {

using namespace svd_test;
namespace SV = CGAL::Surface_voronoi;
namespace GEN = svd_test::meshes;

namespace {

typedef SV::Euclidean_embedding<Mesh> Euclidean;
typedef CGAL::Biharmonic_embedding<Mesh> Biharmonic;
typedef SV::Geodesic_metric<Mesh> Geodesic;
typedef Location<Mesh> Loc;

// The same site owns every piece of every face, with the same area to 1e-9 of the surface's,
// and every vertex and cell agree.
template <class Diagram>
void check_same_diagram(const Diagram& updated, const Diagram& fresh)
{
  REQUIRE(!updated.is_cancelled());
  REQUIRE(updated.number_of_sites() == fresh.number_of_sites());
  const double tolerance = 1e-9 * fresh.surface_area();
  const auto& a = SV::internal::Diagram_access::data(updated).partition.pieces;
  const auto& b = SV::internal::Diagram_access::data(fresh).partition.pieces;
  REQUIRE(a.size() == b.size());
  std::size_t other_owner = 0, other_area = 0;
  for(std::size_t k = 0; k < a.size(); ++k)
  {
    other_owner += (a[k].face != b[k].face || a[k].site != b[k].site);
    other_area += !(std::abs(a[k].area - b[k].area) <= tolerance);
  }
  CHECK(other_owner == 0);
  CHECK(other_area == 0);
  // the same vertices, each used by a piece, at the same points around every piece
  REQUIRE(updated.number_of_arrangement_vertices() == fresh.number_of_arrangement_vertices());
  std::vector<std::uint8_t> used(updated.number_of_arrangement_vertices(), 0);
  std::size_t other_corner = 0;
  for(std::size_t k = 0; k < a.size(); ++k)
  {
    REQUIRE(a[k].vertices.size() == b[k].vertices.size());
    for(std::size_t j = 0; j < a[k].vertices.size(); ++j)
    {
      used[a[k].vertices[j]] = 1;
      other_corner += !(CGAL::squared_distance(updated.arrangement_point(a[k].vertices[j]),
                                               fresh.arrangement_point(b[k].vertices[j])) <= tolerance * tolerance);
    }
  }
  CHECK(other_corner == 0);
  CHECK(std::count(used.begin(), used.end(), 0) == 0);
  for(auto v : vertices(updated.triangle_mesh())) CHECK(updated.site_of(v) == fresh.site_of(v));
  for(std::size_t i = 0; i < fresh.number_of_sites(); ++i)
  {
    CHECK(std::abs(updated.cell_area(i) - fresh.cell_area(i)) <= tolerance);
    CHECK(updated.number_of_pieces(i) == fresh.number_of_pieces(i));
    CHECK(updated.site_weight(i) == fresh.site_weight(i));
    CHECK(updated.merged_into(i) == fresh.merged_into(i));
  }
  CHECK(updated.statistics().broken_cells == fresh.statistics().broken_cells);
  CHECK(std::abs(updated.unreached_area() - fresh.unreached_area()) <= tolerance);
}

// where the sites move: far (another random location) for even indices, a little inside their
// face for odd ones
std::vector<Loc> nearby(const Mesh& m, const std::vector<Loc>& sites, unsigned seed)
{
  const std::vector<Loc> other = area_uniform_locations(m, sites.size(), seed);
  std::vector<Loc> result;
  for(std::size_t i = 0; i < sites.size(); ++i)
  {
    if(i % 2 == 0) { result.push_back(other[i]); continue; }
    Loc l = sites[i];   // a small move inside its face
    for(int k = 0; k < 3; ++k) l.second[k] = 0.75 * l.second[k] + 0.25 / 3;
    result.push_back(l);
  }
  return result;
}

// Every kind of change on one diagram, each checked against a fresh diagram: moves, then
// insertions, then removals, then weights, then all of them in one update.
template <class Metric, class NP>
void check_updates(const Mesh& m, Metric& metric, std::vector<Loc> sites, const NP& np, bool needs_repair)
{
  typedef CGAL::Surface_voronoi_diagram<Mesh, Metric> Diagram;
  std::vector<double> weights(sites.size(), 0.);
  auto fresh = [&]() { return Diagram(m, metric, sites, SV::parameters::site_weight_map(CGAL::make_property_map(weights), np)); };
  Diagram vd = fresh();
  if(needs_repair) REQUIRE(vd.statistics().broken_cells_before_repair > 0);
  const std::vector<Loc> targets = nearby(m, sites, 101);
  SECTION("move")
  {
    for(std::size_t i = 3; i < sites.size(); i += 11)
    {
      vd.move_site(i, targets[i]);
      sites[i] = targets[i];
    }
    vd.update();
    check_same_diagram(vd, fresh());
  }
  SECTION("insert")
  {
    const std::vector<Loc> added = area_uniform_locations(m, 12, 102);
    for(const Loc& l : added)
    {
      CHECK(vd.insert_site(l) == sites.size());
      sites.push_back(l);
      weights.push_back(0.);
    }
    // a site given as a point and one as a vertex are located as by the constructor
    const Point p = point_of(area_uniform_locations(m, 1, 103)[0], m);
    vd.insert_site(p);
    CHECK(vd.number_of_sites_after_update() == sites.size() + 1);
    CHECK(vd.number_of_sites() + 13 == vd.number_of_sites_after_update());
    vd.update();
    sites.push_back(vd.site_location(sites.size()));
    weights.push_back(0.);
    check_same_diagram(vd, fresh());
  }
  SECTION("remove")
  {
    // indices are compacted: each removal moves the later sites down by one
    for(std::size_t i : { std::size_t(0), std::size_t(17), std::size_t(17), sites.size() - 4, std::size_t(40) })
    {
      vd.remove_site(i);
      sites.erase(sites.begin() + std::ptrdiff_t(i));
      weights.erase(weights.begin() + std::ptrdiff_t(i));
    }
    vd.update();
    check_same_diagram(vd, fresh());
  }
  SECTION("weights")
  {
    const double w = SV::weight_for_length(metric, sites[0], 0.3 * std::sqrt(vd.surface_area() / double(sites.size())));
    for(std::size_t i = 1; i < sites.size(); i += 5)
    {
      weights[i] = w * double(i % 4);
      vd.set_site_weight(i, weights[i]);
    }
    vd.update();
    check_same_diagram(vd, fresh());
    CHECK(vd.site_weight(1) == weights[1]);
  }
  SECTION("all at once, then again")
  {
    for(int round = 0; round < 2; ++round)
    {
      vd.move_site(5, targets[5]);
      sites[5] = targets[5];
      vd.remove_site(9);
      sites.erase(sites.begin() + 9);
      weights.erase(weights.begin() + 9);
      const Loc l = area_uniform_locations(m, 2, 104 + unsigned(round))[round];
      vd.insert_site(l, 1e-4);
      sites.push_back(l);
      weights.push_back(1e-4);
      vd.set_site_weight(2, -1e-4);
      weights[2] = -1e-4;
      vd.update();
      check_same_diagram(vd, fresh());
    }
  }
}

} // namespace

TEST_CASE("update: an updated diagram is the diagram computed afresh", "[update]")
{
  Mesh m;
  GEN::Lampshade_options lo;
  lo.target_vertices = 3000;
  GEN::make_thin_lampshade(m, lo);
  const auto sites = area_uniform_locations(m, 120, 21);
  SECTION("Euclidean: cells reach through the thin wall, and are repaired")
  {
    Euclidean e(m);
    check_updates(m, e, sites, CGAL::parameters::default_values(), true);
  }
  SECTION("biharmonic")
  {
    Biharmonic b(m);
    check_updates(m, b, sites, CGAL::parameters::default_values(), false);
  }
  SECTION("geodesic (a lazy metric)")
  {
    Geodesic g(m);
    check_updates(m, g, sites, CGAL::parameters::default_values(), false);
  }
}

// Small moves of many sites, round after round: each update starts from the previous cells
// and propagates from the changed sites only (far fewer events than a fresh propagation), and
// gives the fresh diagram.
template <class Metric>
void check_local_updates(const Mesh& m, Metric& metric, std::vector<Loc> sites)
{
  typedef CGAL::Surface_voronoi_diagram<Mesh, Metric> Diagram;
  Diagram vd(m, metric, sites);
  REQUIRE(vd.statistics().broken_cells_before_repair == 0);
  for(unsigned round = 0; round < 3; ++round)
  {
    for(std::size_t i = round; i < sites.size(); i += 30)
    {
      for(int k = 0; k < 3; ++k)   // a quarter of the way to a corner of its face
        sites[i].second[k] = 0.75 * sites[i].second[k] + (k == int(round) ? 0.25 : 0.);
      vd.move_site(i, sites[i]);
    }
    vd.update();
    const Diagram fresh(m, metric, sites);
    check_same_diagram(vd, fresh);
    CHECK(vd.statistics().propagation_events * 4 < fresh.statistics().propagation_events);
  }
}

TEST_CASE("update: small moves update the cells locally", "[update]")
{
  Mesh m;
  GEN::make_torus(m, 1.0, 0.35, 120, 48);
  const auto sites = area_uniform_locations(m, 300, 25);
  SECTION("Euclidean")
  {
    Euclidean e(m);
    check_local_updates(m, e, sites);
  }
  SECTION("biharmonic")
  {
    Biharmonic b(m);
    check_local_updates(m, b, sites);
  }
}

TEST_CASE("update: the update state can be released, the queries stay", "[update]")
{
  Mesh m;
  GEN::make_torus(m, 1.0, 0.35, 40, 16);
  const auto sites = area_uniform_locations(m, 40, 23);
  Euclidean e(m);
  CGAL::Surface_voronoi_diagram<Mesh, Euclidean> vd(m, e, sites);
  vd.move_site(3, sites[3]);   // to where it is: the same diagram
  const double area = vd.cell_area(3);
  vd.update();
  CHECK(vd.cell_area(3) == area);
  vd.release_update_state();
  CHECK(vd.cell_area(3) == area);
  CHECK(vd.site_of(vd.site_location(7)) == 7);
  CGAL::Surface_voronoi_diagram<Mesh, Euclidean> other(m, e, sites);
  CHECK_THROWS_AS(other.insert_site(Point(0, 0, std::nan(""))), SV::Input_error);
}

} // namespace svd_test_diagram_update
