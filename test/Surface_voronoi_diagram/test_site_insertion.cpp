// Tests of CGAL/Surface_voronoi_diagram/site_insertion.h: the paper's insertion mode.
#include "test_support.h"

#include <CGAL/Surface_voronoi_diagram/Euclidean_embedding.h>
#include <CGAL/Surface_voronoi_diagram/Geodesic_metric.h>
#include <CGAL/Surface_voronoi_diagram/refinement.h>
#include <test_meshes.h>
#include <CGAL/Surface_voronoi_diagram/site_insertion.h>

#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/boost/graph/generators.h>

#include <chrono>

// this file's own names: the suite compiles its files together (see CMakeLists.txt)
namespace svd_test_site_insertion {

using namespace svd_test;
namespace SV = CGAL::Surface_voronoi;
namespace GEN = svd_test::meshes;

namespace {

// Inner edges (both faces from the same input face) must be locally Delaunay.
template <class Result>
std::size_t non_delaunay_inner_edges(const Result& r)
{
  const auto& m = r.mesh;
  std::size_t bad = 0;
  for(auto e : edges(m))
  {
    const auto h = halfedge(e, m), o = opposite(h, m);
    if(is_border(h, m) || is_border(o, m)) continue;
    if(r.input_face[face(h, m)] != r.input_face[face(o, m)]) continue;
    const Point a = m.point(source(h, m)), b = m.point(target(h, m));
    const Point c = m.point(target(next(h, m), m)), d = m.point(target(next(o, m), m));
    // opposite angles sum to at most pi
    const double ac = std::acos(std::max(-1., std::min(1., CGAL::to_double((a - c) * (b - c)) /
                                                              std::sqrt(CGAL::to_double((a - c).squared_length() * (b - c).squared_length())))));
    const double ad = std::acos(std::max(-1., std::min(1., CGAL::to_double((a - d) * (b - d)) /
                                                              std::sqrt(CGAL::to_double((a - d).squared_length() * (b - d).squared_length())))));
    bad += (ac + ad > CGAL_PI + 1e-9);
  }
  return bad;
}

} // namespace

TEST_CASE("insertion: sites become vertices of a valid Delaunay-refined copy", "[insertion]")
{
  Mesh m;
  GEN::make_torus(m, 1.0, 0.35, 30, 12);
  auto sites = area_uniform_locations(m, 200, 6);
  // a site on an edge, a site at a vertex, and several sites in one face
  const auto f0 = *faces(m).begin();
  sites.push_back(Location<Mesh>(f0, {{ 0.5, 0.5, 0. }}));
  sites.push_back(Location<Mesh>(*std::next(faces(m).begin(), 10), {{ 0., 0., 1. }}));
  const auto f1 = *std::next(faces(m).begin(), 20);
  sites.push_back(Location<Mesh>(f1, {{ 0.2, 0.3, 0.5 }}));
  sites.push_back(Location<Mesh>(f1, {{ 0.25, 0.3, 0.45 }}));
  sites.push_back(Location<Mesh>(f1, {{ 0.6, 0.2, 0.2 }}));

  auto r = SV::insert_sites(m, sites);
  CHECK(CGAL::is_valid_polygon_mesh(r.mesh));
  CHECK(CGAL::is_triangle_mesh(r.mesh));
  CHECK(CGAL::is_closed(r.mesh));
  CHECK(CGAL::Polygon_mesh_processing::area(r.mesh) == Approx(CGAL::Polygon_mesh_processing::area(m)).epsilon(1e-12));
  REQUIRE(r.site_vertices.size() == sites.size());
  for(std::size_t i = 0; i < sites.size(); ++i)
    CHECK(CGAL::to_double(CGAL::squared_distance(r.mesh.point(r.site_vertices[i]), point_of(sites[i], m))) < 1e-24);
  // the vertex site reused the mesh vertex; the others are new
  CHECK(num_vertices(r.mesh) == num_vertices(m) + sites.size() - 1);
  CHECK(r.edges_split == 1);
  CHECK(non_delaunay_inner_edges(r) == 0);
  // every face lies in the input face it names
  for(auto f : faces(r.mesh))
  {
    const auto in = r.input_face[f];
    REQUIRE(in != Mesh::null_face());
    const auto h = halfedge(in, m);
    const K::Triangle_3 t(m.point(source(h, m)), m.point(target(h, m)), m.point(target(next(h, m), m)));
    for(auto v : vertices_around_face(halfedge(f, r.mesh), r.mesh))
      CHECK(CGAL::to_double(CGAL::squared_distance(t, r.mesh.point(v))) < 1e-20);
  }
}

TEST_CASE("insertion: the diagram on the augmented mesh satisfies the invariants", "[insertion]")
{
  Mesh m;
  GEN::Lampshade_options lo;
  lo.target_vertices = 2000;
  GEN::make_thin_lampshade(m, lo);
  const auto sites = area_uniform_locations(m, 80, 12);
  auto r = SV::insert_sites(m, sites);
  CGAL::Biharmonic_embedding<Mesh> e(r.mesh);
  CGAL::Surface_voronoi_diagram<Mesh> vd(r.mesh, e, r.site_vertices);
  check_invariants(vd);
  for(std::size_t i = 0; i < sites.size(); ++i)
    CHECK(vd.site_of(r.site_vertices[i]) == i);
}

namespace {

// The unit cube as 12 triangles: a coarse CAD mesh.
Mesh coarse_cube()
{
  Mesh m;
  CGAL::make_hexahedron(Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0), Point(0, 1, 0),
                        Point(0, 1, 1), Point(0, 0, 1), Point(1, 0, 1), Point(1, 1, 1), m);
  CGAL::Polygon_mesh_processing::triangulate_faces(m);
  return m;
}

// The labels of `samples` area-uniform points of `m` against the brute-force nearest of
// `site_points` (points whose two nearest sites tie within rounding skipped): {checked, wrong}.
template <class Diagram>
std::pair<std::size_t, std::size_t> nearest_site_labels(const Diagram& vd, const Mesh& m, const std::vector<Point>& site_points,
                                                        std::size_t samples, unsigned seed)
{
  std::size_t wrong = 0, checked = 0;
  for(const auto& l : area_uniform_locations(m, samples, seed))
  {
    const Point p = point_of(l, m);
    std::vector<std::pair<double, std::size_t> > d;
    for(std::size_t i = 0; i < site_points.size(); ++i) d.emplace_back(CGAL::to_double(CGAL::squared_distance(p, site_points[i])), i);
    std::partial_sort(d.begin(), d.begin() + 2, d.end());
    if(d[1].first - d[0].first < 1e-12 * (1 + d[0].first)) continue;
    ++checked;
    wrong += (vd.site_of(l) != d[0].second);
  }
  return { checked, wrong };
}

double seconds_since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

} // namespace

// issue 52: a 12-triangle cube with 3,000 sites (250 per face). The constructor computes the
// diagram of the mesh it is given, whatever the sites per face (each face is cut among its
// candidates, at a cost above quadratic in their number); the manual's way for a coarse mesh is
// to insert the sites (the embeddings then have vertices between them) or, for the geodesic
// metric, to refine. Both ways are checked here, for each metric, against oracles: the
// brute-force nearest site (Euclidean), and the invariants (areas add up, every cell non-empty
// and one piece, each site owns its own location).
TEST_CASE("coarse mesh: a 12-triangle cube with 3000 sites, every metric", "[insertion][coarse]")
{
  const Mesh m = coarse_cube();
  REQUIRE(num_faces(m) == 12);
  const auto sites = SV::random_sites(m, 3000, CGAL::parameters::random_seed(0));
  REQUIRE(sites.size() == 3000);
  std::vector<Point> site_points;
  for(const auto& l : sites) site_points.push_back(point_of(l, m));
  typedef SV::Euclidean_embedding<Mesh> Euclidean;

  SECTION("Euclidean and RVD on the cube as it is: the brute-force nearest site")
  {
    for(bool rvd : { false, true })
    {
      INFO((rvd ? "rvd" : "euclidean"));
      Euclidean e(m);
      const auto t0 = std::chrono::steady_clock::now();
      CGAL::Surface_voronoi_diagram<Mesh, Euclidean> vd(m, e, sites,
          SV::parameters::candidate_selection(rvd ? SV::Candidate_selection::GLOBAL_NEAREST : SV::Candidate_selection::PROPAGATION));
      UNSCOPED_INFO("cube, 3000 sites, " << (rvd ? "rvd" : "euclidean") << " on the cube: " << seconds_since(t0) << " s");
      const auto [checked, wrong] = nearest_site_labels(vd, m, site_points, 20000, 5);
      CHECK(checked > 19000);
      CHECK(wrong == 0);
      if(!rvd)
        check_invariants(vd);
    }
  }
  SECTION("the sites inserted: Euclidean, biharmonic, geodesic")
  {
    const auto r = SV::insert_sites(m, sites);
    REQUIRE(r.site_vertices.size() == 3000);
    {
      Euclidean e(r.mesh);
      CGAL::Surface_voronoi_diagram<Mesh, Euclidean> vd(r.mesh, e, r.site_vertices);
      check_invariants(vd);
      // the same metric on a finer triangulation of the same planes: the nearest site still
      const auto [checked, wrong] = nearest_site_labels(vd, r.mesh, site_points, 20000, 6);
      CHECK(checked > 19000);
      CHECK(wrong == 0);
    }
    {
      CGAL::Biharmonic_embedding<Mesh> e(r.mesh, SV::parameters::embedding_dimension(SV::biharmonic_dimension_for_sites(3000)));
      const auto t0 = std::chrono::steady_clock::now();
      CGAL::Surface_voronoi_diagram<Mesh> vd(r.mesh, e, r.site_vertices);
      UNSCOPED_INFO("biharmonic on the augmented cube: " << seconds_since(t0) << " s");
      check_invariants(vd);
      CHECK(vd.statistics().empty_cells == 0);
    }
    {
      SV::Geodesic_metric<Mesh> g(r.mesh);
      CGAL::Surface_voronoi_diagram<Mesh, SV::Geodesic_metric<Mesh> > vd(r.mesh, g, r.site_vertices);
      check_invariants(vd);
    }
  }
  SECTION("geodesic: on the cube as it is, and refined for the sites")
  {
    {
      SV::Geodesic_metric<Mesh> g(m);
      const auto t0 = std::chrono::steady_clock::now();
      CGAL::Surface_voronoi_diagram<Mesh, SV::Geodesic_metric<Mesh> > vd(m, g, sites);
      UNSCOPED_INFO("geodesic on the cube: " << seconds_since(t0) << " s");
      check_invariants(vd);
    }
    Mesh refined;
    const SV::Refined_sites<Mesh> r = SV::refine_for_sites(m, sites, refined);
    REQUIRE(!r.vertex_limit_reached);
    CHECK(r.edges_split > 0);
    SV::Geodesic_metric<Mesh> g(refined);
    CGAL::Surface_voronoi_diagram<Mesh, SV::Geodesic_metric<Mesh> > vd(refined, g, r.sites);
    check_invariants(vd);
    // on a cube's face the geodesic distance near a site is the Euclidean one: a point much
    // nearer one site than any other (half the spacing against twice it) is in that cell
    std::size_t checked = 0, wrong = 0;
    for(const auto& l : area_uniform_locations(refined, 5000, 7))
    {
      const Point p = point_of(l, refined);
      std::vector<double> d;
      for(const Point& s : site_points) d.push_back(CGAL::to_double(CGAL::squared_distance(p, s)));
      const std::size_t nearest = std::size_t(std::min_element(d.begin(), d.end()) - d.begin());
      std::nth_element(d.begin(), d.begin() + 1, d.end());
      if(d[1] < 4 * d[0]) continue;
      ++checked;
      wrong += vd.site_of(l) != nearest;
    }
    CHECK(checked > 100);
    CHECK(wrong == 0);
  }
  SECTION("biharmonic on the cube as it is: the largest dimension it allows")
  {
    CGAL::Biharmonic_embedding<Mesh> e(m, SV::parameters::embedding_dimension(CGAL::Biharmonic_embedding<Mesh>::maximum_dimension(m)));
    const auto t0 = std::chrono::steady_clock::now();
    CGAL::Surface_voronoi_diagram<Mesh> vd(m, e, sites);
    UNSCOPED_INFO("biharmonic (d = 6) on the cube: " << seconds_since(t0) << " s");
    check_invariants(vd);
  }
}

} // namespace svd_test_site_insertion
