// Copyright (c) 2026 The Surface_voronoi_diagram authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Tests of the surface_voronoi program's input/output contract: the sites file grammar and
// the checked reading of meshes, the arrangement's PLY (examples/Surface_voronoi_diagram/surface_voronoi/). Error
// messages are part of the contract (the program prints them), so the tests check what they
// name, not only that they throw.

#include <surface_voronoi/read_checked_mesh.h>
#include <surface_voronoi/sites_file.h>
#include <surface_voronoi/write_arrangement_PLY.h>

#include "test_support.h"
#include <test_meshes.h>

#include <CGAL/Surface_voronoi_diagram.h>
#include <CGAL/Surface_voronoi_diagram/Euclidean_embedding.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <catch2/catch.hpp>

#include <array>
#include <cfloat>
#include <cmath>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <random>
#include <sstream>
#include <cstdint>
#include <string>
#include <vector>

// this file's own names: the suite compiles its files together (see CMakeLists.txt)
namespace svd_test_io {

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Surface_mesh;
typedef CGAL::Polyhedron_3<K> Polyhedron;
typedef std::vector<std::vector<std::size_t>> Polygons;

namespace SVIO = svd_program;
namespace PMP = CGAL::Polygon_mesh_processing;

std::vector<SVIO::Site_record> read_sites(const std::string& text)
{
  std::istringstream in(text);
  return SVIO::read_sites_file(in);
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof(double)) == 0; }

// A fresh directory per test, removed at the end of the test.
class Temp_dir
{
public:
  explicit Temp_dir(const std::string& name)
    : path_(std::filesystem::temp_directory_path() /
            ("svd_test_io_" + name + "_" + unique_suffix()))
  {
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~Temp_dir()
  {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  std::string file(const std::string& name, const std::string& content) const
  {
    const std::string p = (path_ / name).string();
    std::ofstream out(p, std::ios::binary);
    out << content;
    return p;
  }
  std::string path(const std::string& name) const { return (path_ / name).string(); }

private:
  // Test cases may run in parallel processes (one per case under ctest).
  static std::string unique_suffix()
  {
    std::random_device device;
    return std::to_string(device()) + "_" +
           std::to_string(std::chrono::steady_clock::now().time_since_epoch().count());
  }

  std::filesystem::path path_;
};

// Unit cube corners; faces listed outward (counterclockwise seen from outside).
std::vector<Point> cube_points()
{
  return { Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0), Point(0, 1, 0),
           Point(0, 0, 1), Point(1, 0, 1), Point(1, 1, 1), Point(0, 1, 1) };
}

Polygons cube_quads()
{
  return { { 0, 3, 2, 1 }, { 4, 5, 6, 7 }, { 0, 1, 5, 4 },
           { 1, 2, 6, 5 }, { 2, 3, 7, 6 }, { 3, 0, 4, 7 } };
}

Polygons cube_triangles()
{
  Polygons triangles;
  for(const std::vector<std::size_t>& q : cube_quads())
  {
    triangles.push_back({ q[0], q[1], q[2] });
    triangles.push_back({ q[0], q[2], q[3] });
  }
  return triangles;
}

// Tetrahedron with outward faces on the given 4 point indices.
void add_tetrahedron(Polygons& polygons, std::size_t a, std::size_t b, std::size_t c, std::size_t d)
{
  polygons.push_back({ a, c, b });
  polygons.push_back({ a, b, d });
  polygons.push_back({ b, c, d });
  polygons.push_back({ c, a, d });
}

template <class Mesh>
void require_closed_unit_cube(const Mesh& mesh)
{
  REQUIRE(CGAL::is_valid_polygon_mesh(mesh));
  REQUIRE(CGAL::is_triangle_mesh(mesh));
  REQUIRE(CGAL::is_closed(mesh));
  REQUIRE(vertices(mesh).size() == 8);
  REQUIRE(faces(mesh).size() == 12);
  REQUIRE(PMP::area(mesh) == Approx(6.0));
  REQUIRE(PMP::volume(mesh) == Approx(1.0)); // positive: outward orientation kept
  REQUIRE_NOTHROW(SVIO::check_triangle_mesh(mesh));
}

const char* const cube_off =
    "OFF\n8 6 0\n"
    "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
    "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n";

const char* const cube_obj =
    "# unit cube\n"
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
    "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";

std::string cube_ply()
{
  std::string s = "ply\nformat ascii 1.0\nelement vertex 8\nproperty double x\nproperty double y\n"
                  "property double z\nelement face 6\nproperty list uchar int vertex_indices\nend_header\n"
                  "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
                  "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n";
  return s;
}

std::string cube_stl()
{
  const std::vector<Point> p = cube_points();
  std::ostringstream s;
  s << "solid cube\n";
  for(const std::vector<std::size_t>& t : cube_triangles())
  {
    s << "facet normal 0 0 0\nouter loop\n";
    for(std::size_t v : t)
      s << "vertex " << p[v].x() << " " << p[v].y() << " " << p[v].z() << "\n";
    s << "endloop\nendfacet\n";
  }
  s << "endsolid cube\n";
  return s.str();
}

double triangle_area_sum(const Surface_mesh& mesh)
{
  double sum = 0;
  for(auto f : faces(mesh))
    sum += PMP::face_area(f, mesh);
  return sum;
}

} // namespace

// ---------------------------------------------------------------- sites file

TEST_CASE("IO sites file: comments, blank lines, CRLF, tabs and weights are parsed", "[io][sites]")
{
  const std::string text = "# header comment\r\n"
                           "\r\n"
                           "   \t  \n"
                           "1 2 3\r\n"
                           "\t-1.5\t2.5e1   3e-2 # trailing comment\n"
                           "    # indented comment\n"
                           "0.25 0.5 0.75 2\r\n"
                           "7 8 9"; // no final newline
  const std::vector<SVIO::Site_record> sites = read_sites(text);
  REQUIRE(sites.size() == 4);
  CHECK(sites[0].x == 1.0);
  CHECK(sites[0].y == 2.0);
  CHECK(sites[0].z == 3.0);
  CHECK_FALSE(sites[0].has_weight);
  CHECK(sites[0].weight == 0.0);
  CHECK(sites[0].line == 4);
  CHECK(sites[1].x == -1.5);
  CHECK(sites[1].y == 25.0);
  CHECK(sites[1].z == 0.03);
  CHECK(sites[1].line == 5);
  CHECK(sites[2].has_weight);
  CHECK(sites[2].weight == 2.0);
  CHECK(sites[2].z == 0.75);
  CHECK(sites[2].line == 7);
  CHECK(sites[3].z == 9.0);
  CHECK(sites[3].line == 8);
}

TEST_CASE("IO sites file: an empty or comment-only file has no sites", "[io][sites]")
{
  CHECK(read_sites("").empty());
  CHECK(read_sites("# nothing\n\n  \t\r\n").empty());
}

TEST_CASE("IO sites file: write then read round-trips awkward doubles exactly", "[io][sites]")
{
  const std::vector<double> awkward = {
    0.1, 1.0 / 3.0, -0.0, 5e-324 /* smallest subnormal */, DBL_MIN, DBL_MAX, -DBL_MAX,
    std::nextafter(1.0, 2.0), 9007199254740993.0, 1e-300, 123456789.123456789, -2.5e-7
  };
  std::vector<Point> points;
  std::vector<double> weights;
  for(std::size_t i = 0; i < awkward.size(); ++i)
  {
    points.push_back(Point(awkward[i], awkward[(i + 1) % awkward.size()], awkward[(i + 5) % awkward.size()]));
    weights.push_back(awkward[(i + 3) % awkward.size()]);
  }

  SECTION("with weights")
  {
    std::stringstream file;
    SVIO::write_sites_file(file, points, weights);
    const std::vector<SVIO::Site_record> sites = SVIO::read_sites_file(file);
    REQUIRE(sites.size() == points.size());
    for(std::size_t i = 0; i < sites.size(); ++i)
    {
      CHECK(same_bits(sites[i].x, points[i].x()));
      CHECK(same_bits(sites[i].y, points[i].y()));
      CHECK(same_bits(sites[i].z, points[i].z()));
      CHECK(sites[i].has_weight);
      CHECK(same_bits(sites[i].weight, weights[i]));
      CHECK(sites[i].line == i + 1);
    }
  }
  SECTION("without weights, or all zero, lines have 3 fields")
  {
    for(const std::vector<double>& w : { std::vector<double>(), std::vector<double>(points.size(), 0.0) })
    {
      std::stringstream file;
      SVIO::write_sites_file(file, points, w);
      std::istringstream again(file.str());
      for(const auto& record : SVIO::tokenize_records(again))
        CHECK(record.second.size() == 3);
      const std::vector<SVIO::Site_record> sites = SVIO::read_sites_file(file);
      REQUIRE(sites.size() == points.size());
      for(std::size_t i = 0; i < sites.size(); ++i)
      {
        CHECK(same_bits(sites[i].x, points[i].x()));
        CHECK(same_bits(sites[i].z, points[i].z()));
        CHECK_FALSE(sites[i].has_weight);
      }
    }
  }
}

TEST_CASE("IO sites file: wrong field count cites the physical line", "[io][sites]")
{
  const std::string text = "# comment\n\n1 2 3\n\n# another\n   \n1 2\n";
  REQUIRE_THROWS_AS(read_sites(text), SVIO::Input_error);
  REQUIRE_THROWS_WITH(read_sites(text),
                      "sites file line 7: expected 3 or 4 numbers (x y z [weight]), found 2");
  REQUIRE_THROWS_WITH(read_sites("1 2 3\n1 2 3 4 5\n"), Catch::Contains("line 2") && Catch::Contains("found 5"));
  REQUIRE_THROWS_WITH(read_sites("1 2 3\r\n\r\n1\r\n"), Catch::Contains("line 3") && Catch::Contains("found 1"));
}

TEST_CASE("IO sites file: a token that is not entirely a number cites the line", "[io][sites]")
{
  REQUIRE_THROWS_WITH(read_sites("1 2 3\n\nabc 2 3\n"), "sites file line 3: 'abc' is not a number");
  REQUIRE_THROWS_WITH(read_sites("1 2 3x\n"), Catch::Contains("line 1") && Catch::Contains("'3x' is not a number"));
  REQUIRE_THROWS_WITH(read_sites("\n1,5 2 3\n"), Catch::Contains("line 2") && Catch::Contains("'1,5'"));
  REQUIRE_THROWS_WITH(read_sites("0x10 2 3\n"), Catch::Contains("'0x10' is not a number"));
  REQUIRE_THROWS_WITH(read_sites("1 2 3 w\n"), Catch::Contains("'w' is not a number"));
  REQUIRE_THROWS_WITH(read_sites("1 2 3\n1 2 \v3\n"), Catch::Contains("line 2") && Catch::Contains("'\\x0B3'"));
}

TEST_CASE("IO sites file: NaN, infinity and overflow are non-finite errors citing the line", "[io][sites]")
{
  const std::string nine_lines = "1 2 3\n#\n#\n#\n#\n#\n#\n#\n";
  REQUIRE_THROWS_WITH(read_sites(nine_lines + "nan 2 3\n"), "sites file line 9: non-finite value 'nan'");
  REQUIRE_THROWS_WITH(read_sites(nine_lines + "1 inf 3\n"), "sites file line 9: non-finite value 'inf'");
  REQUIRE_THROWS_WITH(read_sites(nine_lines + "1 2 -Infinity\n"), Catch::Contains("line 9") && Catch::Contains("non-finite"));
  REQUIRE_THROWS_WITH(read_sites(nine_lines + "1 2 1e999\n"), "sites file line 9: non-finite value '1e999'");
  REQUIRE_THROWS_WITH(read_sites("1 2 3 NaN\n"), "sites file line 1: non-finite value 'NaN'");
}

TEST_CASE("IO sites file: underflow reads as the nearest double", "[io][sites]")
{
  const std::vector<SVIO::Site_record> sites = read_sites("1e-400 4.9406564584124654e-324 -1e-400\n");
  REQUIRE(sites.size() == 1);
  CHECK(sites[0].x == 0.0);
  CHECK(sites[0].y == std::numeric_limits<double>::denorm_min());
  CHECK(sites[0].z == 0.0);
}

TEST_CASE("IO sites file: reading from a file, and a missing file names it", "[io][sites]")
{
  Temp_dir dir("sites");
  const std::string path = dir.file("sites.txt", "# two sites\r\n1 2 3\r\n4 5 6 0.5\r\n");
  const std::vector<SVIO::Site_record> sites = SVIO::read_sites_file(path);
  REQUIRE(sites.size() == 2);
  CHECK(sites[1].weight == 0.5);
  CHECK(sites[1].line == 3);
  const std::string missing = dir.path("missing.txt");
  REQUIRE_THROWS_AS(SVIO::read_sites_file(missing), SVIO::Input_error);
  REQUIRE_THROWS_WITH(SVIO::read_sites_file(missing), Catch::Contains("cannot open") && Catch::Contains(missing));
}

TEST_CASE("IO sites file: writing rejects what cannot be read back", "[io][sites]")
{
  std::ostringstream out;
  const std::vector<Point> points = { Point(0, 0, 0), Point(1, 1, 1) };
  REQUIRE_THROWS_AS(SVIO::write_sites_file(out, points, std::vector<double>(3, 1.0)), SVIO::Input_error);
  const std::vector<Point> bad = { Point(0, 0, 0), Point(std::nan(""), 1, 1) };
  REQUIRE_THROWS_WITH(SVIO::write_sites_file(out, bad), Catch::Contains("site 1"));
  REQUIRE_THROWS_WITH(SVIO::write_sites_file(out, points, { 0.0, std::numeric_limits<double>::infinity() }),
                      Catch::Contains("site 1"));
}

TEST_CASE("IO tokenize_records: physical line numbers and fields", "[io][sites]")
{
  std::istringstream in("a b\n\n  # c d\nx\ty  z#w\r\n\r\n");
  const auto records = SVIO::tokenize_records(in);
  REQUIRE(records.size() == 2);
  CHECK(records[0].first == 1);
  CHECK(records[0].second == std::vector<std::string>{ "a", "b" });
  CHECK(records[1].first == 4);
  CHECK(records[1].second == std::vector<std::string>{ "x", "y", "z" });
}

TEST_CASE("IO parse_index_pairs: two non-negative integers per line", "[io][breaklines]")
{
  std::istringstream good("# breaklines\n0 1\r\n\n 12\t7 # comment\n");
  const std::vector<SVIO::Index_pair_record> pairs = SVIO::parse_index_pairs(good);
  REQUIRE(pairs.size() == 2);
  CHECK(pairs[0].first == 0);
  CHECK(pairs[0].second == 1);
  CHECK(pairs[0].line == 2);
  CHECK(pairs[1].first == 12);
  CHECK(pairs[1].second == 7);
  CHECK(pairs[1].line == 4);

  auto parse = [](const std::string& text) {
    std::istringstream in(text);
    return SVIO::parse_index_pairs(in);
  };
  REQUIRE_THROWS_WITH(parse("0 1\n\n\n1 2 3\n"), "breaklines file line 4: expected 2 non-negative integers, found 3");
  REQUIRE_THROWS_WITH(parse("0 1\n-3 2\n"), "breaklines file line 2: '-3' is not a non-negative integer");
  REQUIRE_THROWS_WITH(parse("1.5 2\n"), Catch::Contains("line 1") && Catch::Contains("'1.5'"));
  REQUIRE_THROWS_WITH(parse("#\n1 99999999999999999999999\n"),
                      "breaklines file line 2: '99999999999999999999999' is out of range");
}

// ---------------------------------------------------------- polygon soups

TEST_CASE("IO soup check: a valid closed triangle soup passes", "[io][mesh]")
{
  REQUIRE_NOTHROW(SVIO::check_polygon_soup(cube_points(), cube_triangles()));
  REQUIRE_NOTHROW(SVIO::check_polygon_soup(cube_points(), cube_quads()));
}

TEST_CASE("IO soup check: an empty mesh is an error", "[io][mesh]")
{
  REQUIRE_THROWS_WITH(SVIO::check_polygon_soup(cube_points(), Polygons()), "the mesh is empty (no faces)");
  REQUIRE_THROWS_WITH(SVIO::check_polygon_soup(std::vector<Point>(), Polygons()), "the mesh is empty (no faces)");
}

TEST_CASE("IO soup check: a NaN coordinate names the vertex", "[io][mesh]")
{
  std::vector<Point> points = cube_points();
  points[5] = Point(1, std::numeric_limits<double>::quiet_NaN(), 1);
  REQUIRE_THROWS_AS(SVIO::check_polygon_soup(points, cube_triangles()), SVIO::Input_error);
  REQUIRE_THROWS_WITH(SVIO::check_polygon_soup(points, cube_triangles()),
                      "vertex 5 has a non-finite coordinate (nan)");
}

TEST_CASE("IO soup check: an infinite coordinate names the vertex", "[io][mesh]")
{
  std::vector<Point> points = cube_points();
  points[6] = Point(1, 1, std::numeric_limits<double>::infinity());
  REQUIRE_THROWS_WITH(SVIO::check_polygon_soup(points, cube_triangles()),
                      "vertex 6 has a non-finite coordinate (inf)");
  points[6] = Point(-std::numeric_limits<double>::infinity(), 1, 1);
  REQUIRE_THROWS_WITH(SVIO::check_polygon_soup(points, cube_triangles()),
                      "vertex 6 has a non-finite coordinate (-inf)");
}

TEST_CASE("IO soup check: a zero-area face names the face", "[io][mesh]")
{
  std::vector<Point> points = cube_points();
  points.push_back(Point(0.5, 0, 0)); // 8: on the edge (0, 1), so collinear with it
  Polygons triangles = cube_triangles();
  triangles.push_back({ 0, 8, 1 });
  REQUIRE_THROWS_WITH(SVIO::check_polygon_soup(points, triangles), "face 12 has zero area");

  // Coincident corners (distinct indices, same coordinates) are zero area too.
  points.push_back(Point(0, 0, 0)); // 9
  Polygons coincident = { { 0, 9, 2 } };
  REQUIRE_THROWS_WITH(SVIO::check_polygon_soup(points, coincident), "face 0 has zero area");

  // A polygon is zero-area when all its corners are collinear.
  points.push_back(Point(2, 0, 0)); // 10
  Polygons flat_quad = { { 0, 1, 2 }, { 0, 8, 1, 10 } };
  REQUIRE_THROWS_WITH(SVIO::check_polygon_soup(points, flat_quad), "face 1 has zero area");
}

TEST_CASE("IO soup check: a bad vertex index names face and vertex", "[io][mesh]")
{
  Polygons triangles = cube_triangles();
  triangles[4][1] = 99;
  REQUIRE_THROWS_WITH(SVIO::check_polygon_soup(cube_points(), triangles),
                      "face 4 references vertex 99 but the mesh has 8 vertices");
}

TEST_CASE("IO soup check: a repeated vertex or fewer than 3 vertices names the face", "[io][mesh]")
{
  Polygons triangles = cube_triangles();
  triangles[3] = { 1, 5, 1 };
  REQUIRE_THROWS_WITH(SVIO::check_polygon_soup(cube_points(), triangles), "face 3 repeats vertex 1");
  triangles = cube_triangles();
  triangles[2] = { 1, 5 };
  REQUIRE_THROWS_WITH(SVIO::check_polygon_soup(cube_points(), triangles), "face 2 has fewer than 3 vertices");
}

TEST_CASE("IO soup check: three triangles on one edge are a non-manifold edge", "[io][mesh]")
{
  const std::vector<Point> points = { Point(0, 0, 0), Point(1, 0, 0), Point(0.5, 1, 0),
                                      Point(0.5, -1, 0), Point(0.5, 0, 1) };
  const Polygons triangles = { { 0, 1, 2 }, { 1, 0, 3 }, { 0, 1, 4 } };
  REQUIRE_THROWS_WITH(SVIO::check_polygon_soup(points, triangles),
                      "edge (0, 1) is non-manifold: shared by 3 faces (0, 1, 2)");
}

TEST_CASE("IO soup check: two tetrahedra sharing only a vertex make it non-manifold", "[io][mesh]")
{
  const std::vector<Point> points = { Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1),
                                      Point(3, 3, 3), Point(-1, 0, 0), Point(0, -1, 0), Point(0, 0, -1) };
  Polygons polygons;
  add_tetrahedron(polygons, 0, 1, 2, 3);
  add_tetrahedron(polygons, 4, 5, 6, 7); // far part, so the shared vertex is the only contact
  for(std::vector<std::size_t>& p : polygons)
    for(std::size_t& v : p)
      if(v == 4)
        v = 0; // glue the second tetrahedron at vertex 0
  REQUIRE_THROWS_WITH(SVIO::check_polygon_soup(points, polygons),
                      "vertex 0 is non-manifold: its faces form 2 separate fans");
}

TEST_CASE("IO soup check: a Moebius strip is not orientable", "[io][mesh]")
{
  // A strip of 5 quads (10 triangles) whose ends are glued with a half twist.
  const std::size_t n = 5;
  std::vector<Point> points;
  for(std::size_t i = 0; i < n; ++i)
  {
    const double a = 2 * CGAL_PI * static_cast<double>(i) / n, t = a / 2;
    for(int s : { -1, 1 })
      points.push_back(Point((2 + s * 0.5 * std::cos(t)) * std::cos(a),
                             (2 + s * 0.5 * std::cos(t)) * std::sin(a), s * 0.5 * std::sin(t)));
  }
  Polygons triangles;
  for(std::size_t i = 0; i < n; ++i)
  {
    std::size_t a0 = 2 * i, a1 = 2 * i + 1, b0 = 2 * ((i + 1) % n), b1 = b0 + 1;
    if(i + 1 == n)
      std::swap(b0, b1); // the half twist
    triangles.push_back({ a0, b0, b1 });
    triangles.push_back({ a0, b1, a1 });
  }
  REQUIRE_THROWS_WITH(SVIO::check_polygon_soup(points, triangles), Catch::Contains("not orientable"));
  Surface_mesh mesh;
  REQUIRE_THROWS_AS(SVIO::build_checked_triangle_mesh(points, triangles, mesh), SVIO::Input_error);
}

// The topology check runs with 32-bit indices whenever the soup allows, with 64-bit ones
// beyond: both must give the same verdict and the same message on every kind of soup.
TEST_CASE("IO soup check: 32-bit and 64-bit indices give the same verdicts and messages", "[io][mesh]")
{
  std::vector<Polygons> soups;
  soups.push_back(cube_triangles());
  Polygons flipped = cube_triangles();
  std::swap(flipped[4][1], flipped[4][2]);   // orientable, not consistently oriented
  soups.push_back(flipped);
  soups.push_back({ { 0, 1, 2 }, { 1, 0, 3 }, { 0, 1, 4 } });   // a non-manifold edge
  Polygons two_tetrahedra;
  add_tetrahedron(two_tetrahedra, 0, 1, 2, 3);
  add_tetrahedron(two_tetrahedra, 0, 5, 6, 7);   // sharing vertex 0 only
  soups.push_back(two_tetrahedra);
  Polygons moebius;
  for(std::size_t i = 0; i < 5; ++i)
  {
    std::size_t a0 = 2 * i, a1 = 2 * i + 1, b0 = 2 * ((i + 1) % 5), b1 = b0 + 1;
    if(i == 4)
      std::swap(b0, b1);
    moebius.push_back({ a0, b0, b1 });
    moebius.push_back({ a0, b1, a1 });
  }
  soups.push_back(moebius);
  Polygons open_fan = { { 0, 1, 2 }, { 0, 2, 3 }, { 0, 3, 4 }, { 4, 3, 5, 6 } };   // a border and a quad
  soups.push_back(open_fan);
  std::vector<std::string> verdicts;
  for(std::size_t k = 0; k < soups.size(); ++k)
  {
    INFO("soup " << k);
    std::size_t vertices = 0, corners = 0;
    for(const std::vector<std::size_t>& p : soups[k])
    {
      corners += p.size();
      for(std::size_t v : p) vertices = (std::max)(vertices, v + 1);
    }
    std::string narrow, wide;
    const SVIO::internal::Face_namer name(nullptr, std::string());
    try { narrow = SVIO::internal::check_soup_topology_with<std::uint32_t>(soups[k], vertices, corners, name) ? "oriented" : "orientable"; }
    catch(const SVIO::Input_error& e) { narrow = e.what(); }
    try { wide = SVIO::internal::check_soup_topology_with<std::size_t>(soups[k], vertices, corners, name) ? "oriented" : "orientable"; }
    catch(const SVIO::Input_error& e) { wide = e.what(); }
    CHECK(narrow == wide);
    verdicts.push_back(wide);
  }
  // and the soups are what they are meant to be
  CHECK(verdicts[0] == "oriented");
  CHECK(verdicts[1] == "orientable");
  CHECK(verdicts[2] == "edge (0, 1) is non-manifold: shared by 3 faces (0, 1, 2)");
  CHECK(verdicts[3] == "vertex 0 is non-manifold: its faces form 2 separate fans");
  CHECK_THAT(verdicts[4], Catch::Contains("not orientable"));
  CHECK(verdicts[5] == "oriented");
}

// ------------------------------------------------------- building meshes

TEST_CASE("IO build: a quad cube is triangulated into a closed triangle mesh", "[io][mesh]")
{
  Surface_mesh mesh;
  const SVIO::Mesh_reading_report report = SVIO::build_checked_triangle_mesh(cube_points(), cube_quads(), mesh);
  CHECK(report.number_of_points == 8);
  CHECK(report.number_of_polygons == 6);
  CHECK(report.number_of_triangles == 12);
  CHECK(report.polygons_triangulated == 6);
  CHECK_FALSE(report.reoriented);
  CHECK(report.isolated_points == 0);
  require_closed_unit_cube(mesh);
}

TEST_CASE("IO build: a non-convex L-shaped hexagon triangulates to the right area", "[io][mesh]")
{
  // The L of area 3, starting at a corner from which a fan would leave the
  // polygon; placed in a tilted plane so the projection is exercised.
  const double l[6][2] = { { 2, 1 }, { 1, 1 }, { 1, 2 }, { 0, 2 }, { 0, 0 }, { 2, 0 } };
  const K::Vector_3 u(1, 2, 2), v(2, 1, -2); // orthogonal, both of length 3
  const Point origin(0.5, -1, 3);
  std::vector<Point> points;
  for(const auto& c : l)
    points.push_back(origin + c[0] / 3.0 * u + c[1] / 3.0 * v);
  Surface_mesh mesh;
  const SVIO::Mesh_reading_report report =
      SVIO::build_checked_triangle_mesh(points, Polygons{ { 0, 1, 2, 3, 4, 5 } }, mesh);
  CHECK(report.number_of_triangles == 4);
  CHECK(report.polygons_triangulated == 1);
  REQUIRE(CGAL::is_valid_polygon_mesh(mesh));
  // Unsigned areas: a triangle sticking out of the L would add area.
  CHECK(triangle_area_sum(mesh) == Approx(3.0));
  // All triangles keep the polygon's orientation.
  const K::Vector_3 normal = CGAL::cross_product(u, v);
  for(auto f : faces(mesh))
    CHECK(PMP::compute_face_normal(f, mesh) * normal > 0);

  // Reversed order (the other orientation) works as well.
  Surface_mesh reversed;
  SVIO::build_checked_triangle_mesh(points, Polygons{ { 5, 4, 3, 2, 1, 0 } }, reversed);
  CHECK(triangle_area_sum(reversed) == Approx(3.0));
}

TEST_CASE("IO build: a self-intersecting polygon is an error naming the face", "[io][mesh]")
{
  const std::vector<Point> points = { Point(0, 0, 0), Point(1, 1, 0), Point(1, 0, 0), Point(0, 1, 0),
                                      Point(5, 5, 5), Point(6, 5, 5), Point(5, 6, 5) };
  const Polygons polygons = { { 4, 5, 6 }, { 0, 1, 2, 3 } };
  Surface_mesh mesh;
  REQUIRE_THROWS_WITH(SVIO::build_checked_triangle_mesh(points, polygons, mesh),
                      Catch::Contains("face 1") && Catch::Contains("cannot be triangulated"));
}

TEST_CASE("IO build: a diagonal that makes a non-manifold edge names the polygons", "[io][mesh]")
{
  // Two quads glued along their whole boundary are a manifold soup, but both
  // get the same diagonal, which then has four triangles.
  const std::vector<Point> points = { Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0), Point(0, 1, 0) };
  const Polygons pillow = { { 0, 1, 2, 3 }, { 0, 3, 2, 1 } };
  REQUIRE_NOTHROW(SVIO::check_polygon_soup(points, pillow));
  Surface_mesh mesh;
  REQUIRE_THROWS_WITH(SVIO::build_checked_triangle_mesh(points, pillow, mesh),
                      Catch::Matches("edge \\((0, 2|1, 3)\\) is non-manifold: shared by 4 faces \\(0, 0, 1, 1\\)"
                                     " after triangulating polygons"));
}

TEST_CASE("IO build: an inconsistently oriented cube soup is reoriented", "[io][mesh]")
{
  Polygons triangles = cube_triangles();
  for(std::size_t f : { 1, 4, 5, 9 })
    std::reverse(triangles[f].begin(), triangles[f].end());
  REQUIRE_NOTHROW(SVIO::check_polygon_soup(cube_points(), triangles));

  Surface_mesh mesh;
  const SVIO::Mesh_reading_report report = SVIO::build_checked_triangle_mesh(cube_points(), triangles, mesh);
  CHECK(report.reoriented);
  REQUIRE(CGAL::is_valid_polygon_mesh(mesh));
  REQUIRE(CGAL::is_closed(mesh));
  CHECK(faces(mesh).size() == 12);
  CHECK(std::abs(PMP::volume(mesh)) == Approx(1.0));

  Polyhedron poly;
  CHECK(SVIO::build_checked_triangle_mesh(cube_points(), triangles, poly).reoriented);
  CHECK(CGAL::is_closed(poly));
  CHECK(std::abs(PMP::volume(poly)) == Approx(1.0));
}

TEST_CASE("IO build: isolated points are counted and dropped, errors keep file indices", "[io][mesh]")
{
  // Two unused points before the cube, shifting every index by 2.
  std::vector<Point> points = { Point(9, 9, 9), Point(8, 8, 8) };
  for(const Point& p : cube_points())
    points.push_back(p);
  Polygons triangles = cube_triangles();
  for(std::vector<std::size_t>& t : triangles)
    for(std::size_t& v : t)
      v += 2;
  Surface_mesh mesh;
  const SVIO::Mesh_reading_report report = SVIO::build_checked_triangle_mesh(points, triangles, mesh);
  CHECK(report.isolated_points == 2);
  CHECK(report.number_of_points == 10);
  require_closed_unit_cube(mesh);

  points[7] = Point(1, std::numeric_limits<double>::quiet_NaN(), 1);
  REQUIRE_THROWS_WITH(SVIO::build_checked_triangle_mesh(points, triangles, mesh),
                      "vertex 7 has a non-finite coordinate (nan)");
  // The failed call did not touch the mesh.
  CHECK(faces(mesh).size() == 12);
}

// The program builds a Surface_mesh from a checked soup itself, in linear time: it must be the
// mesh CGAL's builder gives, element for element, for the outputs' indices to stay the same.
TEST_CASE("IO build: a Surface_mesh is built exactly as polygon_soup_to_polygon_mesh builds it", "[io][mesh]")
{
  auto same_connectivity = [](const Surface_mesh& a, const Surface_mesh& b) {
    REQUIRE(a.number_of_vertices() == b.number_of_vertices());
    REQUIRE(a.number_of_halfedges() == b.number_of_halfedges());
    REQUIRE(a.number_of_faces() == b.number_of_faces());
    std::size_t differ = 0;
    for(Surface_mesh::Halfedge_index h : a.halfedges())
      differ += (a.next(h) != b.next(h) || a.prev(h) != b.prev(h) || a.target(h) != b.target(h) || a.face(h) != b.face(h));
    for(Surface_mesh::Vertex_index v : a.vertices()) differ += (a.halfedge(v) != b.halfedge(v) || a.point(v) != b.point(v));
    for(Surface_mesh::Face_index f : a.faces()) differ += (a.halfedge(f) != b.halfedge(f));
    CHECK(differ == 0);
    CHECK(b.is_valid(false));
  };
  // closed and bordered surfaces, several components, faces and corners in random orders
  svd_test::meshes::internal::Soup soup = svd_test::meshes::internal::icosphere(3, 1.0);
  Surface_mesh torus;
  svd_test::meshes::make_torus(torus, 3, 1, 24, 12);
  std::map<Surface_mesh::Vertex_index, std::size_t> index;
  for(Surface_mesh::Vertex_index v : torus.vertices())
    index[v] = soup.add_point({{ torus.point(v).x() + 5, torus.point(v).y(), torus.point(v).z() }});
  std::mt19937 random(7);
  std::set<std::size_t> beside_a_hole;
  for(Surface_mesh::Face_index f : torus.faces())
  {
    std::array<std::size_t, 3> t;
    std::size_t k = 0;
    for(Surface_mesh::Vertex_index v : CGAL::vertices_around_face(torus.halfedge(f), torus)) t[k++] = index[v];
    // holes of one face, no two at a vertex (which would make it non-manifold)
    if(random() % 3 == 0 && std::none_of(t.begin(), t.end(), [&](std::size_t v) { return beside_a_hole.count(v); }))
      beside_a_hole.insert(t.begin(), t.end());
    else
      soup.triangles.push_back(t);
  }
  for(int trial = 0; trial < 4; ++trial)
  {
    std::vector<Point> points;
    for(const auto& p : soup.points) points.emplace_back(p[0], p[1], p[2]);
    Polygons polygons;
    std::vector<std::array<std::size_t, 3>> triangles;
    for(std::array<std::size_t, 3> t : soup.triangles)
    {
      std::rotate(t.begin(), t.begin() + random() % 3, t.end());
      triangles.push_back(t);
    }
    std::shuffle(triangles.begin(), triangles.end(), random);
    // a valid soup uses every point: drop the torus's points its holes left alone
    std::vector<std::size_t> renumber(points.size(), std::size_t(-1));
    std::vector<Point> used;
    for(auto& t : triangles)
      for(std::size_t& v : t)
      {
        if(renumber[v] == std::size_t(-1)) renumber[v] = used.size(), used.push_back(points[v]);
        v = renumber[v];
      }
    for(const auto& t : triangles) polygons.push_back({ t[0], t[1], t[2] });
    Surface_mesh expected, built;
    PMP::polygon_soup_to_polygon_mesh(used, triangles, expected);
    const SVIO::Mesh_reading_report report = SVIO::build_checked_triangle_mesh(used, polygons, built);
    REQUIRE(!report.reoriented);
    REQUIRE(!CGAL::is_closed(built));
    same_connectivity(expected, built);
  }
}

// A triangle soup is checked by pairing its halfedges on the way to the mesh; whatever that
// pairing refuses must get the full check's verdict, and the soups it passes must be valid.
TEST_CASE("IO build: triangle soups get the full check's verdict", "[io][mesh]")
{
  const std::vector<Point> points = { Point(0, 0, 0), Point(1, 0, 0), Point(0.5, 1, 0), Point(0.5, -1, 0), Point(0.5, 0, 1),
                                      Point(2, 0, 0), Point(2, 1, 0) };
  Polygons two_fans;   // a bowtie: two triangles meeting at vertex 1 only
  two_fans = { { 0, 1, 2 }, { 1, 5, 6 } };
  Polygons tetrahedron;
  add_tetrahedron(tetrahedron, 0, 1, 2, 4);
  const std::vector<Polygons> soups = {
    { { 0, 1, 2 }, { 1, 0, 3 }, { 0, 1, 4 } },   // three triangles on an edge
    { { 0, 1, 2 }, { 0, 1, 3 } },                // an edge twice in one direction: re-oriented
    { { 0, 1, 2 }, { 0, 1, 2 } },                // a triangle twice
    { { 0, 1, 2 }, { 2, 1, 0 } },                // a triangle and its reverse
    { { 0, 1, 2 }, { 1, 0, 3 }, { 0, 1, 4 }, { 1, 0, 2 } },   // an edge in four triangles
    two_fans, tetrahedron
  };
  for(const Polygons& soup : soups)
  {
    std::string expected, got;
    try { SVIO::check_polygon_soup(points, soup); }
    catch(const SVIO::Input_error& e) { expected = e.what(); }
    Surface_mesh mesh;
    try
    {
      SVIO::build_checked_triangle_mesh(points, soup, mesh);
      CHECK(CGAL::is_valid_polygon_mesh(mesh));
    }
    catch(const SVIO::Input_error& e) { got = e.what(); }
    CHECK(got == expected);
  }
}

// ---------------------------------------------------------- reading files

TEMPLATE_TEST_CASE("IO read: OFF, OBJ, STL and PLY files give the closed cube", "[io][mesh][file]",
                   Surface_mesh, Polyhedron)
{
  Temp_dir dir("read");
  struct Case { std::string name, content; std::size_t triangulated; };
  const std::vector<Case> cases = { { "cube.off", cube_off, 6 },
                                    { "cube.OBJ", cube_obj, 6 },
                                    { "cube.stl", cube_stl(), 0 },
                                    { "cube.ply", cube_ply(), 6 } };
  for(const Case& c : cases)
  {
    INFO(c.name);
    TestType mesh;
    const SVIO::Mesh_reading_report report = SVIO::read_checked_triangle_mesh(dir.file(c.name, c.content), mesh);
    CHECK(report.number_of_points == 8);
    CHECK(report.number_of_triangles == 12);
    CHECK(report.polygons_triangulated == c.triangulated);
    require_closed_unit_cube(mesh);
  }
}

TEST_CASE("IO read: unknown extension, missing file and malformed content name the file", "[io][mesh][file]")
{
  Temp_dir dir("read_errors");
  Surface_mesh mesh;
  const std::string unknown = dir.file("cube.xyz", cube_off);
  REQUIRE_THROWS_AS(SVIO::read_checked_triangle_mesh(unknown, mesh), SVIO::Input_error);
  REQUIRE_THROWS_WITH(SVIO::read_checked_triangle_mesh(unknown, mesh),
                      Catch::Contains(unknown) && Catch::Contains("unknown extension '.xyz'"));
  const std::string no_extension = dir.file("cube", cube_off);
  REQUIRE_THROWS_WITH(SVIO::read_checked_triangle_mesh(no_extension, mesh),
                      Catch::Contains(no_extension) && Catch::Contains("no file extension"));
  const std::string missing = dir.path("missing.off");
  REQUIRE_THROWS_WITH(SVIO::read_checked_triangle_mesh(missing, mesh),
                      Catch::Contains(missing) && Catch::Contains("cannot open"));
  const std::string garbage = dir.file("garbage.off", "OFF\n3 1 0\n0 0 0\n1 zero 0\n");
  REQUIRE_THROWS_WITH(SVIO::read_checked_triangle_mesh(garbage, mesh), Catch::Contains(garbage));
}

TEST_CASE("IO read: a defect in a file is reported with the file and the element", "[io][mesh][file]")
{
  Temp_dir dir("read_defect");
  const std::string path = dir.file("fin.off",
                                    "OFF\n5 3 0\n0 0 0\n1 0 0\n0.5 1 0\n0.5 -1 0\n0.5 0 1\n"
                                    "3 0 1 2\n3 1 0 3\n3 0 1 4\n");
  Polyhedron mesh;
  REQUIRE_THROWS_WITH(SVIO::read_checked_triangle_mesh(path, mesh),
                      Catch::Contains(path) &&
                          Catch::Contains("edge (0, 1) is non-manifold: shared by 3 faces (0, 1, 2)"));
}

// ------------------------------------------------------ meshes in memory

TEST_CASE("IO check_triangle_mesh: defects of an in-memory mesh name the element", "[io][mesh]")
{
  Surface_mesh mesh;
  SVIO::build_checked_triangle_mesh(cube_points(), cube_triangles(), mesh);
  REQUIRE_NOTHROW(SVIO::check_triangle_mesh(mesh, get(CGAL::vertex_point, mesh)));

  SECTION("empty")
  {
    REQUIRE_THROWS_WITH(SVIO::check_triangle_mesh(Surface_mesh()), "the mesh is empty (no faces)");
  }
  SECTION("non-finite coordinate")
  {
    auto v = *std::next(vertices(mesh).begin(), 3);
    mesh.point(v) = Point(0, std::numeric_limits<double>::infinity(), 0);
    REQUIRE_THROWS_WITH(SVIO::check_triangle_mesh(mesh), "vertex 3 has a non-finite coordinate (inf)");
  }
  SECTION("zero-area face")
  {
    // Flatten the cube onto the plane z = 0: the side faces become segments.
    for(auto v : vertices(mesh))
      mesh.point(v) = Point(mesh.point(v).x(), mesh.point(v).y(), 0);
    REQUIRE_THROWS_WITH(SVIO::check_triangle_mesh(mesh), Catch::Contains("has zero area"));
  }
  SECTION("non-triangle face")
  {
    Surface_mesh quads;
    SVIO::build_checked_triangle_mesh(cube_points(), cube_triangles(), quads);
    CGAL::Euler::join_face(*std::next(halfedges(quads).begin(), 4), quads);
    REQUIRE_THROWS_WITH(SVIO::check_triangle_mesh(quads), Catch::Contains("is not a triangle (it has 4 vertices)"));
  }
  SECTION("non-manifold vertex")
  {
    // Two triangles pinched at one vertex (Surface_mesh::add_face allows it).
    Surface_mesh bowtie;
    const auto c = bowtie.add_vertex(Point(0, 0, 0));
    const auto a0 = bowtie.add_vertex(Point(1, 0, 0)), a1 = bowtie.add_vertex(Point(1, 1, 0));
    const auto b0 = bowtie.add_vertex(Point(-1, 0, 0)), b1 = bowtie.add_vertex(Point(-1, -1, 0));
    REQUIRE(bowtie.add_face(c, a0, a1) != Surface_mesh::null_face());
    REQUIRE(bowtie.add_face(c, b0, b1) != Surface_mesh::null_face());
    REQUIRE_THROWS_WITH(SVIO::check_triangle_mesh(bowtie), Catch::StartsWith("vertex 0 is non-manifold"));
  }
}

TEST_CASE("IO check_triangle_mesh: works on Polyhedron_3", "[io][mesh]")
{
  Polyhedron poly;
  SVIO::build_checked_triangle_mesh(cube_points(), cube_quads(), poly);
  REQUIRE_NOTHROW(SVIO::check_triangle_mesh(poly));
  poly.vertices_begin()->point() = Point(std::numeric_limits<double>::quiet_NaN(), 0, 0);
  REQUIRE_THROWS_WITH(SVIO::check_triangle_mesh(poly), "vertex 0 has a non-finite coordinate (nan)");
}

// The program streams its --output PLY from the diagram's cells: the bytes must be those
// CGAL's writer gives for the arrangement as a Surface_mesh (the file's layout is a contract).
TEST_CASE("IO arrangement PLY: the streamed file has CGAL's writer's bytes", "[io][ply]")
{
  typedef svd_test::Mesh Mesh;
  for(int shape = 0; shape < 2; ++shape)
  {
    Mesh m;
    std::vector<Point> sites;
    if(shape == 0)
    {
      svd_test::meshes::make_torus(m, 1.0, 0.35, 40, 16);
      for(const auto& l : svd_test::area_uniform_locations(m, 60, 3)) sites.push_back(svd_test::point_of(l, m));
    }
    else
    {
      // two components, the sites on one: the other's faces have no site (-1, grey)
      svd_test::meshes::make_planar_grid(m, 12, 9);
      Mesh far;
      svd_test::meshes::make_planar_grid(far, 5, 4);
      for(auto v : vertices(far)) far.point(v) = Point(far.point(v).x() + 3, far.point(v).y(), far.point(v).z());
      const auto grid_faces = num_faces(m);
      CGAL::copy_face_graph(far, m);
      std::vector<svd_test::Location<Mesh> > in_grid;
      for(const auto& l : svd_test::area_uniform_locations(m, 200, 5))
        if(std::size_t(l.first) < grid_faces && in_grid.size() < 25) in_grid.push_back(l);
      for(const auto& l : in_grid) sites.push_back(svd_test::point_of(l, m));
    }
    CGAL::Surface_voronoi::Euclidean_embedding<Mesh> metric(m);
    const CGAL::Surface_voronoi_diagram<Mesh, CGAL::Surface_voronoi::Euclidean_embedding<Mesh> > vd(m, metric, sites);
    REQUIRE(vd.statistics().cells == sites.size());
    if(shape == 1) REQUIRE(vd.statistics().unreached_faces > 0);
    for(int scale : { 0, 3, -2 })
    {
      std::ostringstream streamed(std::ios::out | std::ios::binary);
      REQUIRE(SVIO::write_arrangement_binary_PLY(streamed, vd, scale));
      auto arrangement = SVIO::arrangement_for_PLY(vd);
      for(auto v : arrangement.vertices())
      {
        const auto p = arrangement.point(v);
        arrangement.point(v) = decltype(p)(std::ldexp(p.x(), scale), std::ldexp(p.y(), scale), std::ldexp(p.z(), scale));
      }
      std::ostringstream reference(std::ios::out | std::ios::binary);
      CGAL::IO::set_binary_mode(reference);
      REQUIRE(CGAL::IO::write_PLY(reference, arrangement, "surface_voronoi arrangement"));
      INFO("shape " << shape << ", scale " << scale);
      REQUIRE(streamed.str().size() == reference.str().size());
      CHECK(streamed.str() == reference.str());
    }
  }
}

} // namespace svd_test_io
