// Power diagrams (paper 4.7.1): per-site weights, |E(x) - E(s)|^2 - w, exact per triangle.
#include "test_support.h"

#include <CGAL/Surface_voronoi_diagram/Euclidean_embedding.h>
#include <CGAL/Surface_voronoi_diagram/Geodesic_metric.h>
#include <CGAL/Surface_voronoi_diagram/power_weights.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <test_meshes.h>
#include <CGAL/Surface_voronoi_diagram/parameters.h>

#include <boost/property_map/property_map.hpp>

#include <limits>
#include <map>
#include <string>

// this file's own names: the suite compiles its files together (see CMakeLists.txt)
namespace svd_test_power_diagram {

using namespace svd_test;
namespace SV = CGAL::Surface_voronoi;
namespace GEN = svd_test::meshes;
typedef SV::Euclidean_embedding<Mesh> Euclidean;

TEST_CASE("power: all-zero weights give exactly the plain diagram", "[power]")
{
  Mesh m;
  GEN::make_torus(m, 1.0, 0.35, 40, 16);
  const auto sites = area_uniform_locations(m, 60, 4);
  CGAL::Biharmonic_embedding<Mesh> e(m);
  const std::vector<double> zero(sites.size(), 0.);
  CGAL::Surface_voronoi_diagram<Mesh> plain(m, e, sites),
                                      weighted(m, e, sites, SV::parameters::site_weight_map(CGAL::make_property_map(zero)));
  REQUIRE(SV::internal::Diagram_access::data(plain).partition.pieces.size() == SV::internal::Diagram_access::data(weighted).partition.pieces.size());
  for(std::size_t p = 0; p < SV::internal::Diagram_access::data(plain).partition.pieces.size(); ++p)
  {
    CHECK(SV::internal::Diagram_access::data(plain).partition.pieces[p].site == SV::internal::Diagram_access::data(weighted).partition.pieces[p].site);
    CHECK(SV::internal::Diagram_access::data(plain).partition.pieces[p].vertices == SV::internal::Diagram_access::data(weighted).partition.pieces[p].vertices);
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
  std::vector<double> weights(sites.size(), 0.);
  double previous = -1;
  std::size_t grew = 0;
  for(double w : { 0.0, 0.01, 0.02, 0.05, 0.1, 0.2 })
  {
    weights[3] = w;
    CGAL::Surface_voronoi_diagram<Mesh, Euclidean> vd(m, e, sites, SV::parameters::site_weight_map(CGAL::make_property_map(weights)));
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
  std::vector<double> weights(sites.size(), 0.);
  weights[5] = -10.0;   // farther than anything on a unit sphere (squared distances <= 4)
  CGAL::Surface_voronoi_diagram<Mesh, Euclidean> vd(m, e, sites, SV::parameters::site_weight_map(CGAL::make_property_map(weights)));
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

namespace {

template <class Diagram>
void require_same_partition(const Diagram& a, const Diagram& b)
{
  REQUIRE(SV::internal::Diagram_access::data(a).partition.pieces.size() == SV::internal::Diagram_access::data(b).partition.pieces.size());
  for(std::size_t p = 0; p < SV::internal::Diagram_access::data(a).partition.pieces.size(); ++p)
  {
    CHECK(SV::internal::Diagram_access::data(a).partition.pieces[p].site == SV::internal::Diagram_access::data(b).partition.pieces[p].site);
    CHECK(SV::internal::Diagram_access::data(a).partition.pieces[p].vertices == SV::internal::Diagram_access::data(b).partition.pieces[p].vertices);
  }
  for(std::size_t i = 0; i < a.number_of_sites(); ++i)
  {
    CHECK(a.site_weight(i) == b.site_weight(i));
    CHECK(a.cell_area(i) == b.cell_area(i));
  }
}

} // namespace

TEST_CASE("power: a vertex weight map gives exactly the diagram of the equivalent vector", "[power]")
{
  Mesh m;
  GEN::make_torus(m, 1.0, 0.35, 40, 16);
  std::vector<Mesh::Vertex_index> sites;
  for(std::size_t i = 3; i < num_vertices(m); i += 11) sites.push_back(Mesh::Vertex_index(Mesh::size_type(i)));
  // every vertex has a weight, sites or not: only the sites' may be read
  auto w = m.add_property_map<Mesh::Vertex_index, float>("v:weight", 0.f).first;
  for(Mesh::Vertex_index v : vertices(m)) w[v] = float(std::size_t(v) % 7) * 0.01f;
  std::vector<double> by_index;
  for(Mesh::Vertex_index v : sites) by_index.push_back(double(w[v]));
  Euclidean e(m);
  typedef CGAL::Surface_voronoi_diagram<Mesh, Euclidean> Diagram;
  Diagram from_vector(m, e, sites, SV::parameters::site_weight_map(CGAL::make_property_map(by_index)));
  Diagram from_map(m, e, sites, SV::parameters::site_weight_map(w));
  require_same_partition(from_map, from_vector);
  check_invariants(from_map, false);
  // and the weights did change the diagram, so the comparison means something
  Diagram plain(m, e, sites);
  std::size_t changed = 0;
  for(std::size_t i = 0; i < sites.size(); ++i) changed += (plain.cell_area(i) != from_map.cell_area(i));
  CHECK(changed > sites.size() / 2);

  // the map chains with CGAL's named parameters, as the head of the chain or appended to it
  auto none = m.add_property_map<Mesh::Edge_index, bool>("e:none", false).first;
  Diagram chained(m, e, sites, SV::parameters::site_weight_map(w).edge_is_constrained_map(none));
  require_same_partition(chained, from_vector);
  Diagram appended(m, e, sites, SV::parameters::site_weight_map(w, CGAL::parameters::edge_is_constrained_map(none)));
  require_same_partition(appended, from_vector);
}

TEST_CASE("power: a weight map on point sites, with the RVD baseline", "[power]")
{
  Mesh m;
  GEN::make_icosphere(m, 3, 1.0);
  std::vector<Point> sites;
  std::map<Point, double> weight_of;
  for(const auto& l : area_uniform_locations(m, 40, 9))
  {
    sites.push_back(point_of(l, m));
    weight_of[sites.back()] = (sites.size() % 5 == 0) ? 0.3 : 0.;
  }
  std::vector<double> by_index;
  for(const Point& p : sites) by_index.push_back(weight_of[p]);
  const auto rvd = SV::parameters::candidate_selection(SV::Candidate_selection::GLOBAL_NEAREST);
  Euclidean e(m);
  typedef CGAL::Surface_voronoi_diagram<Mesh, Euclidean> Diagram;
  Diagram from_vector(m, e, sites, SV::parameters::site_weight_map(CGAL::make_property_map(by_index), rvd));
  Diagram from_map(m, e, sites, SV::parameters::site_weight_map(boost::make_assoc_property_map(weight_of), rvd));
  require_same_partition(from_map, from_vector);
  CHECK(from_map.site_weight(4) == 0.3);
}

TEST_CASE("power: bad weights are named by validate_input", "[power]")
{
  Mesh m;
  GEN::make_icosphere(m, 2, 1.0);
  const std::vector<Mesh::Vertex_index> sites = { Mesh::Vertex_index(0), Mesh::Vertex_index(10), Mesh::Vertex_index(20) };
  auto w = m.add_property_map<Mesh::Vertex_index, double>("v:weight", 0.).first;
  Euclidean e(m);
  typedef CGAL::Surface_voronoi_diagram<Mesh, Euclidean> Diagram;
  for(double bad : { std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                     -std::numeric_limits<double>::infinity() })
  {
    w[Mesh::Vertex_index(10)] = bad;
    const auto problems = SV::validate_input(m, sites, SV::parameters::site_weight_map(w));
    REQUIRE(problems.size() == 1);
    CHECK(problems[0].kind == SV::Input_problem::NON_FINITE_WEIGHT);
    CHECK(problems[0].element == 1);
    CHECK(problems[0].message == "the weight of site 1 is not finite");
  }
  w[Mesh::Vertex_index(10)] = 0.5;
  CHECK(SV::validate_input(m, sites, SV::parameters::site_weight_map(w)).empty());
  // a map by site index gives the same diagram as the map by vertex
  const std::vector<double> by_index = { 0., 0.5, 0. };
  Diagram a(m, e, sites, SV::parameters::site_weight_map(w));
  Diagram b(m, e, sites, SV::parameters::site_weight_map(CGAL::make_property_map(by_index)));
  require_same_partition(a, b);
  CHECK(b.site_weight(1) == 0.5);
}

// A lazy metric that adds a term of the vertex alone to the geodesic values, as the concept
// allows (Biharmonic_green_metric subtracts one): weights must not see it.
struct Geodesic_with_vertex_term
{
  typedef SV::Lazy_metric_tag Metric_category;
  typedef Mesh Triangle_mesh;
  typedef Mesh::Vertex_index vertex_descriptor;
  SV::Geodesic_metric<Mesh> geodesic;
  explicit Geodesic_with_vertex_term(const Mesh& m) : geodesic(m) {}
  const Mesh& triangle_mesh() const { return geodesic.triangle_mesh(); }
  void set_sites(const std::vector<Location<Mesh> >& sites) { geodesic.set_sites(sites); }
  double squared_distance(std::size_t i, vertex_descriptor v) { return geodesic.squared_distance(i, v) + 3. + double(std::size_t(v) % 7); }
};

TEST_CASE("power: weight_for_length is the squared length where the metric measures lengths", "[power]")
{
  Mesh sphere;
  GEN::make_icosphere(sphere, 3, 1.0);
  const Euclidean euclidean(sphere);   // an embedding may be const
  for(const auto& site : area_uniform_locations(sphere, 10, 3))
    for(double l : { 0.01, 0.1, 0.5 })
      CHECK(SV::weight_for_length(euclidean, site, l) == Approx(l * l).epsilon(1e-12));

  // on a plane, geodesic distances are straight-line distances; a term of the vertex alone
  // that a lazy metric adds to every site's values changes nothing
  Mesh plane;
  GEN::make_planar_grid(plane, 30, 30, 1.0, 1.0, 0.2, 5);
  SV::Geodesic_metric<Mesh> geodesic(plane);
  Geodesic_with_vertex_term shifted(plane);
  for(const auto& site : area_uniform_locations(plane, 10, 6))
    for(double l : { 0.01, 0.05, 0.2 })
    {
      const double w = SV::weight_for_length(geodesic, site, l);
      CHECK(w == Approx(l * l).epsilon(1e-9));
      CHECK(SV::weight_for_length(shifted, site, l) == Approx(w).epsilon(1e-9));
    }

  CHECK(SV::weight_for_length(euclidean, area_uniform_locations(sphere, 1, 1)[0], 0.) == 0.);
  for(double bad : { -0.1, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity() })
    CHECK_THROWS_AS(SV::weight_for_length(euclidean, area_uniform_locations(sphere, 1, 1)[0], bad), SV::Input_error);
}

namespace {

// The number of empty cells when every other site has the weight for half the straight-line
// distance to its nearest site, and the rest 0; checks that the weights do enlarge their cells.
template <class Metric>
std::size_t empty_cells_with_half_spacing_weights(const Mesh& m, Metric& metric, const std::vector<Location<Mesh> >& sites)
{
  std::vector<Point> points;
  for(const auto& l : sites) points.push_back(point_of(l, m));
  std::vector<double> weights(sites.size(), 0.);
  for(std::size_t i = 0; i < sites.size(); i += 2)
  {
    double nearest = std::numeric_limits<double>::infinity();
    for(std::size_t j = 0; j < sites.size(); ++j)
      if(j != i) nearest = (std::min)(nearest, CGAL::squared_distance(points[i], points[j]));
    weights[i] = SV::weight_for_length(metric, sites[i], 0.5 * std::sqrt(nearest));
  }
  typedef CGAL::Surface_voronoi_diagram<Mesh, Metric> Diagram;
  const Diagram plain(m, metric, sites);
  const Diagram weighted(m, metric, sites, SV::parameters::site_weight_map(CGAL::make_property_map(weights)));
  REQUIRE(plain.statistics().empty_cells == 0);
  double plain_area = 0, weighted_area = 0;
  for(std::size_t i = 0; i < sites.size(); i += 2)
  {
    plain_area += plain.cell_area(i);
    weighted_area += weighted.cell_area(i);
  }
  CHECK(weighted_area > 1.02 * plain_area);
  return weighted.statistics().empty_cells;
}

} // namespace

TEST_CASE("power: weights for half the nearest-site distance empty no cell on CGAL's elephant and bear",
          "[power][cgal_data]")
{
  for(const std::string name : { "elephant.off", "bear.off" })
  {
    const std::string file = std::string(SVD_CGAL_MESHES) + "/" + name;
    Mesh m;
    if(std::string(SVD_CGAL_MESHES).empty() || !CGAL::IO::read_polygon_mesh(file, m))
    {
      WARN("CGAL's data set not found: " << file << " skipped");
      continue;
    }
    const auto sites = SV::random_sites(m, 300, CGAL::parameters::random_seed(0));
    INFO(name);
    {
      Euclidean e(m);
      INFO("Euclidean");
      CHECK(empty_cells_with_half_spacing_weights(m, e, sites) == 0);
    }
    {
      CGAL::Biharmonic_embedding<Mesh> b(m);
      INFO("biharmonic");
      CHECK(empty_cells_with_half_spacing_weights(m, b, sites) == 0);
    }
    {
      SV::Geodesic_metric<Mesh> g(m);
      INFO("geodesic");
      CHECK(empty_cells_with_half_spacing_weights(m, g, sites) == 0);
    }
  }
}

} // namespace svd_test_power_diagram
