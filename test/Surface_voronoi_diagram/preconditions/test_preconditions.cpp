// The documented preconditions of the package fire: this file is compiled without NDEBUG
// (its own binary, svd_precondition_tests), so CGAL_precondition_msg is checked and throws
// CGAL::Precondition_exception. What is cheap to check throws Input_error in every build
// instead (test_input_errors.cpp in the Release suite).
#undef NDEBUG
#undef CGAL_NDEBUG

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>

#include <CGAL/Surface_voronoi_diagram.h>
#include <CGAL/Surface_voronoi_diagram/Euclidean_embedding.h>
#include <CGAL/Surface_voronoi_diagram/Geodesic_metric.h>
#include <CGAL/Surface_voronoi_diagram/Vertex_embedding.h>
#include <CGAL/Surface_voronoi_diagram/refinement.h>
#include <CGAL/Surface_voronoi_diagram/sampling.h>
#include <CGAL/property_map.h>

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

namespace {

typedef CGAL::Epick K;
typedef K::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef CGAL::Polygon_mesh_processing::Face_location<Mesh, double> Location;
typedef CGAL::Surface_voronoi::Euclidean_embedding<Mesh> Euclidean;
typedef CGAL::Surface_voronoi_diagram<Mesh, Euclidean> Diagram;
namespace SV = CGAL::Surface_voronoi;

// a subdivided icosahedron: 162 vertices
Mesh sphere()
{
  Mesh m;
  CGAL::make_icosahedron<Mesh, Point>(m, Point(0, 0, 0), 1.0);
  CGAL::Subdivision_method_3::Loop_subdivision(m, CGAL::parameters::number_of_iterations(2));
  return m;
}

std::vector<Location> some_sites(const Mesh& m, std::size_t n)
{
  return SV::random_sites(m, n, CGAL::parameters::random_seed(4));
}

// the precondition's message holds `text`
template <class F>
void require_precondition(F f, const std::string& text)
{
  try
  {
    f();
    FAIL("no precondition failed (expected: " << text << ")");
  }
  catch(const CGAL::Precondition_exception& e)
  {
    INFO(e.what());
    CHECK(std::string(e.what()).find(text) != std::string::npos);
  }
}

} // namespace

TEST_CASE("preconditions: the build checks them", "[preconditions]")
{
  // without this, every other case here would pass vacuously
  Mesh m = sphere();
  const std::vector<Location> none;
  Euclidean e(m);
  CHECK_THROWS_AS(Diagram(m, e, none), CGAL::Precondition_exception);
}

TEST_CASE("preconditions: the diagram's input", "[preconditions]")
{
  Mesh m = sphere();
  Euclidean e(m);
  require_precondition([&] { Diagram(m, e, std::vector<Location>()); }, "there are no sites");

  require_precondition([&] { Diagram(m, e, some_sites(m, 5), SV::parameters::max_repair_rounds(std::size_t(70000))); },
                       "max_repair_rounds");
  // (the mesh's problems, non-finite weights and coincident sites throw Input_error in every
  // build: test_input_errors.cpp)
}

TEST_CASE("preconditions: the restricted Voronoi diagram needs an embedding", "[preconditions]")
{
  Mesh m = sphere();
  SV::Geodesic_metric<Mesh> g(m);
  require_precondition([&] {
    CGAL::Surface_voronoi_diagram<Mesh, SV::Geodesic_metric<Mesh> >(m, g, some_sites(m, 5),
        SV::parameters::candidate_selection(SV::Candidate_selection::GLOBAL_NEAREST));
  }, "needs an embedding metric");
}

TEST_CASE("preconditions: queries and outputs", "[preconditions]")
{
  Mesh m = sphere();
  Euclidean e(m);
  const Diagram d(m, e, some_sites(m, 5));
  require_precondition([&] { d.cell_area(5); }, "i < number_of_sites()");
  require_precondition([&] { d.site_point(7); }, "i < number_of_sites()");
  // a cancelled diagram has no cells to output
  const Diagram cancelled(m, e, some_sites(m, 5), CGAL::parameters::callback([](double) { return false; }));
  REQUIRE(cancelled.is_cancelled());
  Mesh out;
  require_precondition([&] { SV::make_arrangement(cancelled, out); }, "cancelled");
  require_precondition([&] { SV::make_voronoi_polygon_mesh(cancelled, out); }, "cancelled");
  std::vector<SV::Bisector_polyline<K::Point_3> > polylines;
  require_precondition([&] { SV::bisector_polylines(cancelled, std::back_inserter(polylines)); }, "cancelled");
  std::vector<SV::Voronoi_vertex<K::Point_3> > vertices;
  require_precondition([&] { SV::voronoi_vertices(cancelled, std::back_inserter(vertices)); }, "cancelled");
  std::vector<int> labels(num_faces(m) + num_vertices(m));
  require_precondition([&] { SV::compute_vertex_sites(cancelled, CGAL::make_property_map(labels)); }, "cancelled");
  require_precondition([&] { SV::compute_face_sites(cancelled, CGAL::make_property_map(labels)); }, "cancelled");
}

TEST_CASE("preconditions: the metrics", "[preconditions]")
{
  Mesh m = sphere();   // 162 vertices, one component: at most 160 dimensions
  require_precondition([&] { CGAL::Biharmonic_embedding<Mesh>(m, SV::parameters::embedding_dimension(0)); }, "at least 1");
  require_precondition([&] { CGAL::Biharmonic_embedding<Mesh>(m, SV::parameters::embedding_dimension(161)); }, "too few vertices");
  SV::Geodesic_metric<Mesh> g(m);
  require_precondition([&] { g.squared_distance(0, *vertices(m).begin()); }, "set_sites()");
  auto coordinates = m.add_property_map<Mesh::Vertex_index, std::array<double, 2> >("v:c").first;
  require_precondition([&] { SV::make_vertex_embedding(m, coordinates, 0); }, "at least one coordinate");
  Mesh flat = sphere();
  const auto h = halfedge(*faces(flat).begin(), flat);
  flat.point(target(h, flat)) = flat.point(source(h, flat));
  require_precondition([&] { CGAL::Biharmonic_embedding<Mesh>{ flat }; }, "zero area");
}

TEST_CASE("preconditions: refinement and sampling", "[preconditions]")
{
  Mesh m = sphere();
  Mesh out;
  require_precondition([&] { SV::refine_for_sites(m, std::vector<Location>(), out); }, "needs sites");
  require_precondition([&] {
    SV::refine_for_sites(m, some_sites(m, 3), out, SV::parameters::refinement_trigger_ratio(0.1));
  }, "at most refinement_trigger_ratio");
  Mesh full = sphere();
  require_precondition([&] { SV::refine_for_sites(m, some_sites(m, 3), full); }, "must be empty");
  Mesh empty;
  require_precondition([&] { SV::random_sites(empty, 3); }, "empty");
}
