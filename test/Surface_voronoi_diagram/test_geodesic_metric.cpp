// Tests of CGAL/Surface_voronoi_diagram/Geodesic_metric.h: its distances against exact
// polyhedral geodesics (CGAL's Surface_mesh_shortest_path), its diagram against the exact
// geodesic Voronoi diagram, the laziness that keeps its cost proportional to the mesh, and
// its determinism.
#include "test_support.h"

#include <CGAL/Surface_voronoi_diagram/Euclidean_embedding.h>
#include <CGAL/Surface_voronoi_diagram/Geodesic_metric.h>
#include <test_meshes.h>
#include <fidelity.h>   // benchmark/Surface_voronoi_diagram: the fidelity measurement

// this file's own names: the suite compiles its files together (see CMakeLists.txt)
namespace svd_test_geodesic_metric {

using namespace svd_test;
namespace SV = CGAL::Surface_voronoi;
namespace GEN = svd_test::meshes;
typedef SV::Geodesic_metric<Mesh> Geodesic;
typedef CGAL::Surface_voronoi_diagram<Mesh, Geodesic> Geodesic_diagram;

namespace {

// Largest and mean relative error of the metric's distances from one site to every vertex,
// against an exact single-source tree; vertices closer than `near` are skipped (relative
// errors there say nothing).
void distance_errors(const Mesh& m, const Location<Mesh>& site, double near, double& max_error, double& mean_error)
{
  Geodesic g(m);
  g.set_sites({ site });
  std::vector<Location<Mesh> > targets;
  std::vector<Mesh::Vertex_index> vs;
  for(auto v : vertices(m))
  {
    targets.push_back(CGAL::Polygon_mesh_processing::locate_vertex<double>(v, m));
    vs.push_back(v);
  }
  svd_bench::Geodesic_reference<Mesh> exact(m, { site });
  const std::vector<double> d = exact.distances(0, targets);
  max_error = 0;
  mean_error = 0;
  std::size_t n = 0;
  for(std::size_t k = 0; k < vs.size(); ++k)
  {
    if(d[k] < near) continue;
    const double e = std::abs(std::sqrt(g.squared_distance(0, vs[k])) - d[k]) / d[k];
    max_error = (std::max)(max_error, e);
    mean_error += e;
    ++n;
  }
  mean_error /= double(n);
}

} // namespace

TEST_CASE("geodesic metric: exact on a plane, close to exact geodesics on curved and thin meshes", "[geodesic]")
{
  double max_error, mean_error;
  {
    // a flat, irregular grid: straight lines are geodesics and the point-source update is
    // exact wherever the front has both ends of an edge (edge paths alone would be ~5% off)
    Mesh m;
    GEN::make_planar_grid(m, 25, 25, 1.0, 1.0, 0.2, 7);
    distance_errors(m, area_uniform_locations(m, 1, 3).front(), 1e-3, max_error, mean_error);
    INFO("plane: max relative error " << max_error << " mean " << mean_error);
    CHECK(max_error < 2e-3);
    CHECK(mean_error < 1e-4);
  }
  {
    Mesh m;
    GEN::make_icosphere(m, 4, 1.0);
    distance_errors(m, area_uniform_locations(m, 1, 5).front(), 0.05, max_error, mean_error);
    INFO("sphere: max " << max_error << " mean " << mean_error);
    CHECK(max_error < 0.02);
    CHECK(mean_error < 0.005);
  }
  {
    // a thin U-fold: the far sheet is reached around the bend, never across the gap
    Mesh m;
    GEN::U_fold_options uo;
    uo.target_vertices = 2500;
    GEN::make_u_fold(m, uo);
    distance_errors(m, area_uniform_locations(m, 1, 11).front(), 0.02, max_error, mean_error);
    INFO("U-fold: max " << max_error << " mean " << mean_error);
    CHECK(max_error < 0.05);
    CHECK(mean_error < 0.01);
  }
}

TEST_CASE("geodesic metric: the diagram is the exact geodesic Voronoi diagram up to a few percent", "[geodesic][thin]")
{
  std::vector<Mesh> ms(3);
  GEN::Lampshade_options lo;
  lo.target_vertices = 3000;
  GEN::make_thin_lampshade(ms[0], lo);
  GEN::U_fold_options uo;
  uo.target_vertices = 3000;
  GEN::make_u_fold(ms[1], uo);
  GEN::make_torus(ms[2], 1.0, 0.35, 60, 24);
  const char* names[] = { "lampshade", "u_fold", "torus" };
  for(std::size_t k = 0; k < ms.size(); ++k)
  {
    const Mesh& m = ms[k];
    const auto sites = area_uniform_locations(m, 40, 21);
    Geodesic g(m);
    Geodesic_diagram vd(m, g, sites);
    check_invariants(vd);
    const svd_bench::Fidelity_report f = svd_bench::measure_fidelity(vd, 3000, 99, 4);
    INFO(names[k] << ": mislabeled " << f.mislabeled_share << ", through a wall <= " << f.through_wall_upper);
    CHECK(f.mislabeled_share <= 0.03);
    CHECK(f.through_wall_upper == 0);
    CHECK(f.unreached_share == 0);
    CHECK(f.broken_cells == 0);

    // the Euclidean propagation on the same sites is measurably farther from geodesic on
    // the thin shells: the test can tell the two metrics apart
    if(k < 2)
    {
      SV::Euclidean_embedding<Mesh> e(m);
      CGAL::Surface_voronoi_diagram<Mesh, SV::Euclidean_embedding<Mesh> > ve(m, e, sites);
      CHECK(svd_bench::measure_fidelity(ve, 3000, 99, 0).mislabeled_share > 2 * f.mislabeled_share);
    }
  }
}

TEST_CASE("geodesic metric: the work grows with the mesh, not with mesh x sites", "[geodesic]")
{
  Mesh m;
  GEN::make_torus(m, 1.0, 0.35, 80, 30);
  const double nv = double(num_vertices(m));
  for(std::size_t n : { 30, 300 })
  {
    Geodesic g(m);
    Geodesic_diagram vd(m, g, area_uniform_locations(m, n, 4));
    const double per_vertex = double(g.number_of_computed_distances()) / nv;
    INFO(n << " sites: " << per_vertex << " distances per vertex");
    CHECK(per_vertex < 12);
    CHECK(per_vertex > 1);   // every vertex got a distance from some site
  }
}

TEST_CASE("geodesic metric: deterministic, and independent of the order of queries", "[geodesic]")
{
  Mesh m;
  GEN::Lampshade_options lo;
  lo.target_vertices = 2000;
  GEN::make_thin_lampshade(m, lo);
  const auto sites = area_uniform_locations(m, 60, 8);
  Geodesic g1(m), g2(m);
  Geodesic_diagram a(m, g1, sites), b(m, g2, sites);
  for(std::size_t i = 0; i < sites.size(); ++i)
    CHECK(a.cell_area(i) == b.cell_area(i));

  // a front advanced in one go or in small steps gives the same values, bit for bit
  Geodesic eager(m), lazy(m);
  eager.set_sites(sites);
  lazy.set_sites(sites);
  std::vector<Mesh::Vertex_index> vs(vertices(m).begin(), vertices(m).end());
  std::vector<double> far(sites.size());
  for(std::size_t i = 0; i < sites.size(); ++i)
    far[i] = eager.squared_distance(i, vs.back());   // marches far first
  std::size_t differ = 0;
  for(std::size_t k = 0; k < vs.size(); k += 7)
    for(std::size_t i = 0; i < sites.size(); i += 5)
      differ += (lazy.squared_distance(i, vs[k]) != eager.squared_distance(i, vs[k]));
  CHECK(differ == 0);
}

TEST_CASE("geodesic metric: distances asked again after forget_distances() are the same", "[geodesic]")
{
  Mesh m;
  GEN::make_torus(m, 1.0, 0.35, 60, 24);
  const auto sites = area_uniform_locations(m, 40, 3);
  Geodesic g(m);
  const Geodesic_diagram vd(m, g, sites);   // which frees the fronts after its propagation
  CHECK(vd.number_of_sites() == sites.size());
  std::vector<Mesh::Vertex_index> vs(vertices(m).begin(), vertices(m).end());
  std::vector<double> first;
  for(std::size_t k = 0; k < vs.size(); k += 11)
    for(std::size_t i = 0; i < sites.size(); i += 3) first.push_back(g.squared_distance(i, vs[k]));
  const std::size_t work = g.number_of_computed_distances();
  g.forget_distances();
  std::vector<double> again;
  for(std::size_t k = 0; k < vs.size(); k += 11)
    for(std::size_t i = 0; i < sites.size(); i += 3) again.push_back(g.squared_distance(i, vs[k]));
  CHECK(again == first);
  CHECK(g.number_of_computed_distances() > work);   // marched again, not kept
}

namespace {

// A user's lazy metric over the geodesic distances, with or without the concept's optional
// members, counting which ones the diagram calls.
template <bool WithOptionalMembers>
struct Counting_geodesic
{
  typedef SV::Lazy_metric_tag Metric_category;
  typedef Mesh Triangle_mesh;
  typedef Mesh::Vertex_index vertex_descriptor;
  Geodesic geodesic;
  std::size_t by_vertex = 0, by_index = 0, forgotten = 0;
  explicit Counting_geodesic(const Mesh& m) : geodesic(m) {}
  const Mesh& triangle_mesh() const { return geodesic.triangle_mesh(); }
  void set_sites(const std::vector<Location<Mesh> >& sites) { geodesic.set_sites(sites); }
  double squared_distance(std::size_t i, vertex_descriptor v) { ++by_vertex; return geodesic.squared_distance(i, v); }

  template <bool B = WithOptionalMembers, class = std::enable_if_t<B> >
  double indexed_squared_distance(std::size_t i, std::size_t k) { ++by_index; return geodesic.indexed_squared_distance(i, k); }
  template <bool B = WithOptionalMembers, class = std::enable_if_t<B> >
  void forget_distances() { ++forgotten; geodesic.forget_distances(); }
  template <bool B = WithOptionalMembers, class = std::enable_if_t<B> >
  SV::Prepared_mesh<Mesh> prepared_mesh() const { return geodesic.prepared_mesh(); }
};

} // namespace

TEST_CASE("geodesic metric: a user's metric with the optional members gets the same shortcuts", "[geodesic][concepts]")
{
  Mesh m;
  GEN::make_torus(m, 1.0, 0.35, 60, 24);
  const auto sites = area_uniform_locations(m, 40, 5);
  Counting_geodesic<true> with(m);
  Counting_geodesic<false> without(m);
  const long prepared_users = with.prepared_mesh().indexed_mesh().use_count();
  const CGAL::Surface_voronoi_diagram<Mesh, Counting_geodesic<true> > a(m, with, sites);
  const CGAL::Surface_voronoi_diagram<Mesh, Counting_geodesic<false> > b(m, without, sites);
  // the same cells either way
  for(auto v : vertices(m)) CHECK(a.site_of(v) == b.site_of(v));
  for(std::size_t i = 0; i < sites.size(); ++i) CHECK(a.cell_area(i) == b.cell_area(i));
  // the optional members are the ones asked, and the diagram shares the metric's mesh
  CHECK(with.by_vertex == 0);
  CHECK(with.by_index > 0);
  CHECK(with.forgotten == 1);
  CHECK(with.prepared_mesh().indexed_mesh().use_count() == prepared_users + 1);
  CHECK(without.by_vertex == with.by_index);
}

TEST_CASE("geodesic metric: clear errors", "[geodesic][errors]")
{
  Mesh m;
  GEN::make_icosphere(m, 2, 1.0);
  Geodesic g(m);
  // asked before any site is set (a failed precondition in a debug build)
  CHECK_THROWS(g.squared_distance(0, *vertices(m).begin()));
  g.set_sites(area_uniform_locations(m, 3, 1));
  CHECK_NOTHROW(g.squared_distance(2, *vertices(m).begin()));
  CHECK_THROWS_AS(g.squared_distance(3, *vertices(m).begin()), SV::Input_error);   // not a site index
}

} // namespace svd_test_geodesic_metric
