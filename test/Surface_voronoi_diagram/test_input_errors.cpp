// Invalid input in a Release build (issue 52): every case the issue lists is an exception
// naming the element, or a reported merge; never a signal, never a silent answer. The suite
// is compiled with NDEBUG in Release, so these checks are the ones that stay on.
#include "test_support.h"

#include <CGAL/Surface_voronoi_diagram/Euclidean_embedding.h>
#include <CGAL/Surface_voronoi_diagram/Geodesic_metric.h>
#include <CGAL/Surface_voronoi_diagram/Vertex_embedding.h>
#include <CGAL/Surface_voronoi_diagram/exceptions.h>
#include <CGAL/Surface_voronoi_diagram/validate_input.h>
#include <test_meshes.h>

#include <array>
#include <limits>
#include <set>
#include <string>
#include <vector>

// this file's own names: the suite compiles its files together (see CMakeLists.txt)
namespace svd_test_input_errors {

using namespace svd_test;
namespace SV = CGAL::Surface_voronoi;
namespace GEN = svd_test::meshes;
typedef SV::Euclidean_embedding<Mesh> Euclidean;
typedef SV::Geodesic_metric<Mesh> Geodesic;

// `f()` throws an `Exception` whose message holds `text`
template <class Exception, class F>
void require_error(F f, const std::string& text)
{
  try
  {
    f();
    FAIL("nothing thrown (expected: " << text << ")");
  }
  catch(const Exception& e)
  {
    INFO(e.what());
    CHECK(std::string(e.what()).find(text) != std::string::npos);
  }
}

// A flat 4 x 4 grid of unit cells, each split into two triangles except cell `quad_cell`,
// left a quad: the quad is face 2 * quad_cell.
Mesh grid_with_quad(std::size_t quad_cell)
{
  Mesh m;
  std::vector<Mesh::Vertex_index> v;
  for(int j = 0; j <= 4; ++j)
    for(int i = 0; i <= 4; ++i) v.push_back(m.add_vertex(Point(i, j, 0)));
  std::size_t cell = 0;
  for(int j = 0; j < 4; ++j)
    for(int i = 0; i < 4; ++i, ++cell)
    {
      const auto a = v[5 * j + i], b = v[5 * j + i + 1], c = v[5 * (j + 1) + i + 1], d = v[5 * (j + 1) + i];
      if(cell == quad_cell)
        REQUIRE(m.add_face(a, b, c, d) != Mesh::null_face());
      else
      {
        REQUIRE(m.add_face(a, b, c) != Mesh::null_face());
        REQUIRE(m.add_face(a, c, d) != Mesh::null_face());
      }
    }
  return m;
}

Mesh sphere(int levels)
{
  Mesh m;
  GEN::make_icosphere(m, levels, 1.0);
  return m;
}

TEST_CASE("input errors: a face that is not a triangle is named, whatever the metric", "[input_errors]")
{
  const Mesh m = grid_with_quad(5);   // the quad is face 10
  const std::vector<Mesh::Vertex_index> sites = { Mesh::Vertex_index(0), Mesh::Vertex_index(24) };
  const std::string named = "face 10 is not a triangle";
  // biharmonic and geodesic: their constructors index the mesh (a SIGFPE in the stitcher, a
  // misleading "barycentric coordinates do not sum to 1" before)
  require_error<SV::Input_error>([&] { CGAL::Biharmonic_embedding<Mesh> e(m, SV::parameters::embedding_dimension(3)); }, named);
  require_error<SV::Input_error>([&] { Geodesic g(m); }, named);
  // Euclidean: the diagram (a SIGFPE in the stitcher's exact location before)
  Euclidean e(m);
  require_error<SV::Input_error>([&] { CGAL::Surface_voronoi_diagram<Mesh, Euclidean> vd(m, e, sites); }, named);
  const auto problems = SV::validate_input(m, sites);
  REQUIRE(problems.size() == 1);
  CHECK(problems[0].kind == SV::Input_problem::NOT_A_TRIANGLE);
  CHECK(problems[0].element == 10);
}

TEST_CASE("input errors: a non-finite vertex coordinate is named by the metrics and the diagram", "[input_errors]")
{
  for(const double bad : { std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity() })
  {
    Mesh m = sphere(2);
    const auto sites = area_uniform_locations(m, 20, 3);
    Euclidean before(m);   // built while the mesh is valid
    const Mesh::Vertex_index v(37);
    m.point(v) = Point(0.5, bad, 0.1);
    const std::string named = "vertex 37 has a non-finite coordinate";
    require_error<SV::Input_error>([&] { Euclidean e(m); }, named);
    // (in Debug the biharmonic metric said "a face has zero area", naming nothing)
    require_error<SV::Input_error>([&] { CGAL::Biharmonic_embedding<Mesh> e(m); }, named);
    require_error<SV::Input_error>([&] { Geodesic g(m); }, named);
    // the diagram, before anything reaches the exact arithmetic (GMP on NaN in the face cutter)
    require_error<SV::Input_error>([&] { CGAL::Surface_voronoi_diagram<Mesh, Euclidean> vd(m, before, sites); }, named);
    const auto problems = SV::validate_input(m, sites);
    REQUIRE(!problems.empty());
    CHECK(problems[0].kind == SV::Input_problem::NON_FINITE_POINT);
    CHECK(problems[0].element == 37);
  }
}

TEST_CASE("input errors: a non-finite coordinate of a vertex embedding is named", "[input_errors]")
{
  Mesh m = sphere(2);
  auto coordinates = m.add_property_map<Mesh::Vertex_index, std::array<double, 2> >("v:coordinates").first;
  for(auto v : vertices(m)) coordinates[v] = {{ m.point(v).x(), m.point(v).y() + m.point(v).z() }};
  coordinates[Mesh::Vertex_index(12)][1] = std::numeric_limits<double>::quiet_NaN();
  auto e = SV::make_vertex_embedding(m, coordinates, 2);
  const auto sites = area_uniform_locations(m, 20, 3);
  require_error<SV::Input_error>([&] { CGAL::Surface_voronoi_diagram<Mesh, decltype(e)> vd(m, e, sites); },
                                 "the embedding of vertex 12 has a non-finite coordinate");
}

TEST_CASE("input errors: a non-finite power weight names the site", "[input_errors]")
{
  const Mesh m = sphere(2);
  const auto sites = area_uniform_locations(m, 20, 3);
  Euclidean e(m);
  for(const double bad : { std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                           -std::numeric_limits<double>::infinity() })
  {
    std::vector<double> weights(sites.size(), 0.);
    weights[7] = bad;
    // (a SIGFPE in the exact arithmetic before)
    require_error<SV::Input_error>([&] {
      CGAL::Surface_voronoi_diagram<Mesh, Euclidean> vd(m, e, sites, SV::parameters::site_weight_map(CGAL::make_property_map(weights)));
    }, "the weight of site 7 is not finite");
  }
}

TEST_CASE("input errors: a non-manifold vertex is named", "[input_errors]")
{
  // two open fans of three triangles sharing vertex 7 only (a Surface_mesh accepts it)
  Mesh m;
  std::vector<Mesh::Vertex_index> ring;
  for(int k = 0; k < 7; ++k) ring.push_back(m.add_vertex(Point(std::cos(0.5 * k), std::sin(0.5 * k), k < 4 ? 0. : 1.)));
  const auto c = m.add_vertex(Point(0, 0, 0.5));
  REQUIRE(std::size_t(c) == 7);
  const auto o = m.add_vertex(Point(2, 2, 2));
  for(int k = 0; k < 3; ++k) REQUIRE(m.add_face(c, ring[k], ring[k + 1]) != Mesh::null_face());
  for(int k = 4; k < 6; ++k) REQUIRE(m.add_face(c, ring[k], ring[k + 1]) != Mesh::null_face());
  REQUIRE(m.add_face(c, ring[6], o) != Mesh::null_face());
  REQUIRE(CGAL::is_valid_polygon_mesh(m));
  const std::vector<Mesh::Vertex_index> sites = { ring[1], ring[5] };
  Euclidean e(m);
  // (output without a word before)
  require_error<SV::Input_error>([&] { CGAL::Surface_voronoi_diagram<Mesh, Euclidean> vd(m, e, sites); },
                                 "vertex 7 is non-manifold");
  const auto problems = SV::validate_input(m, sites);
  REQUIRE(problems.size() == 1);
  CHECK(problems[0].kind == SV::Input_problem::NON_MANIFOLD_VERTEX);
  CHECK(problems[0].element == 7);
}

TEST_CASE("input errors: faces of zero area and degenerate faces are named", "[input_errors]")
{
  // one vertex of face 30 moved onto another: the two faces of that edge lose their area,
  // the first by index is named
  Mesh flat = sphere(2);
  const auto h = halfedge(Mesh::Face_index(30), flat);
  flat.point(target(h, flat)) = flat.point(source(h, flat));
  const std::size_t first = (std::min)(std::size_t(30), std::size_t(face(opposite(h, flat), flat)));
  Euclidean e(flat);
  const auto sites = area_uniform_locations(sphere(2), 10, 3);
  require_error<SV::Input_error>([&] { CGAL::Surface_voronoi_diagram<Mesh, Euclidean> vd(flat, e, sites); },
                                 "face " + std::to_string(first) + " has zero area");
  // a needle below 2^-44 of its squared longest edge (face 1)
  Mesh needle;
  const auto a = needle.add_vertex(Point(-0.5, 0, 0)), b = needle.add_vertex(Point(0.5, 0, 0));
  const auto c = needle.add_vertex(Point(0, -0.5, 0)), d = needle.add_vertex(Point(0, 1e-14, 0));
  needle.add_face(b, a, c);
  needle.add_face(a, b, d);
  Euclidean en(needle);
  require_error<SV::Input_error>([&] {
    CGAL::Surface_voronoi_diagram<Mesh, Euclidean> vd(needle, en, std::vector<Mesh::Vertex_index>{ c });
  }, "face 1 is degenerate");
}

TEST_CASE("input errors: sites out of range are named", "[input_errors]")
{
  const Mesh m = sphere(1);
  Euclidean e(m);
  const std::vector<Mesh::Vertex_index> vertex_sites = { Mesh::Vertex_index(0), Mesh::Vertex_index(1000) };
  require_error<SV::Input_error>([&] { CGAL::Surface_voronoi_diagram<Mesh, Euclidean> vd(m, e, vertex_sites); },
                                 "site 1 is not a vertex of the mesh");
  std::vector<Location<Mesh> > face_sites = area_uniform_locations(m, 3, 1);
  face_sites[2].first = Mesh::Face_index(5000);
  require_error<SV::Input_error>([&] { CGAL::Surface_voronoi_diagram<Mesh, Euclidean> vd(m, e, face_sites); },
                                 "site 2 is not in a face of the mesh");
}

TEST_CASE("input errors: duplicate sites are rejected by name, or merged and counted", "[input_errors]")
{
  const Mesh m = sphere(2);
  std::vector<Location<Mesh> > sites = area_uniform_locations(m, 20, 3);
  sites.push_back(sites[11]);   // site 20
  sites.push_back(sites[3]);    // site 21
  Euclidean e(m);
  typedef CGAL::Surface_voronoi_diagram<Mesh, Euclidean> Diagram;
  // the default, REJECT (a silent merge in Release before, unnamed in Debug): the first pair
  // by the later site
  try
  {
    Diagram vd(m, e, sites);
    FAIL("duplicate sites accepted");
  }
  catch(const SV::Coincident_sites_error& error)
  {
    CHECK(error.first == 11);
    CHECK(error.second == 20);
    CHECK(std::string(error.what()) == "sites 11 and 20 are at the same surface point");
    const SV::Input_error& as_input_error = error;   // one type, an Input_error
    CHECK(std::string(as_input_error.what()) == error.what());
  }
  const Diagram merged(m, e, sites, SV::parameters::coincident_sites(SV::Coincident_sites::MERGE));
  CHECK(merged.statistics().merged_sites == 2);
  CHECK(merged.merged_into(20) == 11);
  CHECK(merged.merged_into(21) == 3);
  CHECK(merged.merged_into(0) == Diagram::no_site);
  CHECK(merged.statistics().cells == 20);
  CHECK(merged.statistics().empty_cells == 2);
  const Diagram distinct(m, e, std::vector<Location<Mesh> >(sites.begin(), sites.begin() + 20));
  CHECK(distinct.statistics().merged_sites == 0);
}

TEST_CASE("input errors: far-away points snapped onto the same surface points", "[input_errors]")
{
  // 300 points far outside a convex icosphere, each on the ray of one of its 42 vertices: each
  // is moved onto the surface near that vertex, and the ones that land on the same surface
  // point coincide (78 surface points for 300 points in the issue)
  const Mesh m = sphere(1);
  REQUIRE(num_vertices(m) == 42);
  std::vector<Point> points;
  for(std::size_t k = 0; k < 300; ++k)
  {
    const Point& p = m.point(Mesh::Vertex_index(k % 42));
    const double s = 3. + double(k / 42);
    points.push_back(Point(s * p.x(), s * p.y(), s * p.z()));
  }
  Euclidean e(m);
  typedef CGAL::Surface_voronoi_diagram<Mesh, Euclidean> Diagram;
  const Diagram merged(m, e, points, SV::parameters::coincident_sites(SV::Coincident_sites::MERGE));
  // the oracle: equal site points (the located sites), counted here
  std::size_t expected_merged = 0, first_merged = Diagram::no_site;
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    std::size_t earlier = Diagram::no_site;
    for(std::size_t j = 0; j < i && earlier == Diagram::no_site; ++j)
      if(merged.site_point(j) == merged.site_point(i)) earlier = j;
    CHECK(merged.merged_into(i) == earlier);
    if(earlier != Diagram::no_site)
    {
      ++expected_merged;
      if(first_merged == Diagram::no_site) first_merged = i;
    }
  }
  REQUIRE(expected_merged > 0);   // the case is exercised
  CHECK(merged.statistics().merged_sites == expected_merged);
  CHECK(merged.statistics().cells == points.size() - expected_merged);
  try
  {
    Diagram vd(m, e, points);
    FAIL("coincident sites accepted");
  }
  catch(const SV::Coincident_sites_error& error)
  {
    CHECK(error.second == first_merged);
    CHECK(error.first == merged.merged_into(first_merged));
    CHECK(std::string(error.what()) == "sites " + std::to_string(error.first) + " and " + std::to_string(error.second)
                                       + " are at the same surface point");
  }
  // the geodesic metric refuses them the same way
  Geodesic g(m);
  require_error<SV::Coincident_sites_error>([&] { CGAL::Surface_voronoi_diagram<Mesh, Geodesic> vd(m, g, points); },
                                            "are at the same surface point");
}

} // namespace svd_test_input_errors
