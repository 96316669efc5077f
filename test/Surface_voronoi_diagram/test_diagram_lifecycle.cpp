// The diagram as an object: it is movable; it does not use the metric after its
// construction (a lazy metric may be destroyed or reused); a callback reports progress and
// can stop the diagram, the embedding and Lloyd without an exception.
#include "test_support.h"

#include <CGAL/Surface_voronoi_diagram/Euclidean_embedding.h>
#include <CGAL/Surface_voronoi_diagram/Geodesic_metric.h>
#include <CGAL/Surface_voronoi_diagram/lloyd_relaxation.h>
#include <test_meshes.h>

#include <memory>
#include <vector>

// this file's own names: the suite compiles its files together (see CMakeLists.txt)
namespace svd_test_diagram_lifecycle {

using namespace svd_test;
namespace SV = CGAL::Surface_voronoi;
namespace GEN = svd_test::meshes;

namespace {
typedef SV::Geodesic_metric<Mesh> Geodesic;
typedef CGAL::Surface_voronoi_diagram<Mesh, Geodesic> Geodesic_diagram;
typedef SV::Euclidean_embedding<Mesh> Euclidean;
typedef CGAL::Surface_voronoi_diagram<Mesh, Euclidean> Euclidean_diagram;
}

TEST_CASE("lifecycle: a diagram outlives its lazy metric and can be moved", "[lifecycle]")
{
  Mesh m;
  GEN::make_torus(m, 1.0, 0.35, 40, 16);
  const auto sites = area_uniform_locations(m, 50, 2);
  std::unique_ptr<Geodesic> metric(new Geodesic(m));
  std::unique_ptr<Geodesic_diagram> d(new Geodesic_diagram(m, *metric, sites));
  const double energy = d->energy();
  const double area = d->cell_area(7);
  metric.reset();   // the diagram keeps what it needs
  CHECK(d->energy() == energy);
  Geodesic_diagram moved(std::move(*d));
  d.reset();
  CHECK(moved.energy() == energy);
  CHECK(moved.cell_area(7) == area);
  check_invariants(moved);
}

TEST_CASE("lifecycle: one lazy metric, two diagrams, no shared state between copies", "[lifecycle]")
{
  Mesh m;
  GEN::make_torus(m, 1.0, 0.35, 40, 16);
  const auto a_sites = area_uniform_locations(m, 40, 3), b_sites = area_uniform_locations(m, 60, 4);
  Geodesic metric(m);
  const Geodesic_diagram a(m, metric, a_sites);
  const double a_energy = a.energy();
  const Geodesic_diagram b(m, metric, b_sites);   // restarts the metric's fronts
  CHECK(a.energy() == a_energy);                    // a is not affected
  Geodesic fresh(m);
  const Geodesic_diagram b2(m, fresh, b_sites);
  CHECK(b.energy() == b2.energy());
  // a copy marches its own fronts: using the copy leaves the original's distances alone
  Geodesic copy(metric);
  const double before = metric.distance(0, b.site_location(1));
  copy.set_sites(a_sites);
  CHECK(metric.distance(0, b.site_location(1)) == before);
  CHECK(metric.number_of_computed_distances() != copy.number_of_computed_distances());
}

TEST_CASE("lifecycle: the callback sees the work advance and can cancel", "[lifecycle][callback]")
{
  Mesh m;
  GEN::make_torus(m, 1.0, 0.35, 40, 16);
  const auto sites = area_uniform_locations(m, 50, 5);
  Euclidean e(m);
  std::vector<double> seen;
  const Euclidean_diagram full(m, e, sites, CGAL::parameters::callback([&](double f) { seen.push_back(f); return true; }));
  CHECK(!full.is_cancelled());
  REQUIRE(seen.size() >= 3);
  CHECK(std::is_sorted(seen.begin(), seen.end()));
  CHECK(seen.back() == 1.);
  check_invariants(full);

  // stopping at the second call: no exception, and no cells
  int calls = 0;
  const Euclidean_diagram stopped(m, e, sites, CGAL::parameters::callback([&](double) { return ++calls < 2; }));
  CHECK(stopped.is_cancelled());
  CHECK(calls == 2);
  CHECK(stopped.number_of_sites() == sites.size());
  CHECK(stopped.cell_area(0) == 0.);
  CHECK(stopped.site_of(sites[0]) == Euclidean_diagram::no_site);
  CHECK(stopped.statistics().cells == 0);

  // the embedding
  int embedding_calls = 0;
  const CGAL::Biharmonic_embedding<Mesh> cancelled(m, CGAL::parameters::callback([&](double) { return ++embedding_calls < 3; }));
  CHECK(cancelled.is_cancelled());
  CHECK(cancelled.dimension() == 0);
  const CGAL::Biharmonic_embedding<Mesh> done(m, CGAL::parameters::callback([](double) { return true; }));
  CHECK(!done.is_cancelled());
  CHECK(done.dimension() == 10);

  // Lloyd: stopped during the third diagram, it returns the sites of the second
  const auto three = SV::lloyd_relaxation(m, e, sites, CGAL::parameters::number_of_iterations(2));
  int lloyd_calls = 0;
  const std::size_t per_diagram = seen.size();
  const auto cut = SV::lloyd_relaxation(m, e, sites, CGAL::parameters::number_of_iterations(5).callback(
      [&](double) { return ++lloyd_calls <= int(2 * per_diagram); }));
  CHECK(cut.cancelled);
  CHECK(cut.energies.size() == 2);
  REQUIRE(cut.sites.size() == sites.size());
  for(std::size_t i = 0; i < sites.size(); ++i)
  {
    CHECK(cut.sites[i].first == three.sites[i].first);
    CHECK(cut.sites[i].second == three.sites[i].second);
  }
}

} // namespace svd_test_diagram_lifecycle
