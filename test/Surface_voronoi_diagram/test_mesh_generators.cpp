// Copyright (c) 2026 The Surface_voronoi_diagram authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Tests of the generated meshes (include/test_meshes.h). The other tests trust these shapes blindly
// (a leak through a thin wall is only meaningful if the wall is closed, outward
// oriented and really `thickness` thick), so every promise the header makes
// about topology, orientation, size, thickness and triangle quality is checked
// here, on meshes of a few thousand vertices to keep the run short.

#include <test_meshes.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/OFF.h>
#include <CGAL/boost/graph/helpers.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <set>
#include <string>
#include <vector>

// this file's own names: the suite compiles its files together (see CMakeLists.txt)
namespace svd_test_mesh_generators {

namespace {

namespace SVG = svd_test::meshes;
namespace PMP = CGAL::Polygon_mesh_processing;

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Surface_mesh;
typedef CGAL::Polyhedron_3<Kernel> Polyhedron;

const double pi = 3.14159265358979323846;

struct Mesh_report
{
  std::size_t vertices = 0, faces = 0;
  long euler = 0;
  double min_angle = 180;           // degrees, over all faces
  double min_angle_off_rims = 180;  // degrees, over faces whose every altitude exceeds 1.5 wall thicknesses
  double min_area = 1e300;
  double min_edge = 1e300;
  bool duplicated_points = false;
  CGAL::Bbox_3 bbox;
};

template <class Mesh>
Mesh_report report(const Mesh& mesh, double wall)
{
  Mesh_report r;
  r.vertices = num_vertices(mesh);
  r.faces = num_faces(mesh);
  r.euler = long(num_vertices(mesh)) - long(num_edges(mesh)) + long(num_faces(mesh));
  r.bbox = PMP::bbox(mesh);
  auto vpm = get(CGAL::vertex_point, mesh);
  std::set<std::array<double, 3> > seen;
  for(auto v : vertices(mesh)) {
    const Point& p = get(vpm, v);
    if(!seen.insert(std::array<double, 3>{{p.x(), p.y(), p.z()}}).second)
      r.duplicated_points = true;
  }
  for(auto f : faces(mesh)) {
    auto h = halfedge(f, mesh);
    const Point p[3] = {get(vpm, source(h, mesh)), get(vpm, target(h, mesh)),
                        get(vpm, target(next(h, mesh), mesh))};
    double longest = 0, angle = 180;
    for(int i = 0; i < 3; ++i) {
      const Kernel::Vector_3 u = p[(i + 1) % 3] - p[i], v = p[(i + 2) % 3] - p[i];
      angle = (std::min)(angle, std::atan2(std::sqrt(CGAL::cross_product(u, v).squared_length()), u * v) * 180 / pi);
      longest = (std::max)(longest, std::sqrt(u.squared_length()));
      r.min_edge = (std::min)(r.min_edge, std::sqrt(u.squared_length()));
    }
    const double area = std::sqrt(CGAL::squared_area(p[0], p[1], p[2]));
    r.min_area = (std::min)(r.min_area, area);
    r.min_angle = (std::min)(r.min_angle, angle);
    // Across a rim (or the U-fold's bend) a triangle cannot be much taller
    // than the wall; everywhere else it is about as tall as it is long.
    if(2 * area / longest > 1.5 * wall)
      r.min_angle_off_rims = (std::min)(r.min_angle_off_rims, angle);
  }
  return r;
}

template <class Mesh>
void check_closed_shell(const Mesh& mesh, long expected_euler)
{
  REQUIRE(CGAL::is_valid_polygon_mesh(mesh));
  REQUIRE(CGAL::is_triangle_mesh(mesh));
  REQUIRE(CGAL::is_closed(mesh));
  CHECK(long(num_vertices(mesh)) - long(num_edges(mesh)) + long(num_faces(mesh)) == expected_euler);
  CHECK(PMP::volume(mesh) > 0);  // outward orientation
}

struct Shell_case
{
  SVG::Shape shape;
  long euler;
};

// Lampshade: a thick tube open at both ends, so its surface is a torus.
const Shell_case shell_cases[] = {{SVG::Shape::lampshade, 0}, {SVG::Shape::vase, 2},   {SVG::Shape::pot, 2},
                                  {SVG::Shape::u_fold, 2},    {SVG::Shape::slab, 2},   {SVG::Shape::bowl, 2},
                                  {SVG::Shape::box, 2}};

SVG::Shell_options small_shell()
{
  SVG::Shell_options o;
  o.target_vertices = 2000;
  return o;
}

template <class Mesh>
std::vector<Point> points_of(const Mesh& mesh)
{
  std::vector<Point> points;
  for(auto v : vertices(mesh))
    points.push_back(get(CGAL::vertex_point, mesh, v));
  return points;
}

} // namespace

TEMPLATE_TEST_CASE("icosphere: 10*4^k+2 vertices on the sphere, uniform triangles", "[generators]", Surface_mesh,
                   Polyhedron)
{
  for(int k = 0; k <= 4; ++k) {
    TestType mesh;
    const double radius = 2.5;
    SVG::make_icosphere(mesh, k, radius);
    check_closed_shell(mesh, 2);
    CHECK(num_vertices(mesh) == std::size_t(10 * std::pow(4, k) + 2));
    CHECK(num_faces(mesh) == std::size_t(20 * std::pow(4, k)));
    for(const Point& p : points_of(mesh))
      CHECK(std::sqrt((p - CGAL::ORIGIN).squared_length()) == Approx(radius).epsilon(1e-13));
    const Mesh_report r = report(mesh, 0);
    CHECK(r.min_angle > 50);
    CHECK_FALSE(r.duplicated_points);
    // A uniform icosphere's triangles differ in area by less than a factor 1.5
    // (the 12 degree-5 corners are the smallest).
    if(k > 0)
      CHECK(PMP::area(mesh) / double(num_faces(mesh)) < 1.5 * r.min_area);
    CHECK(PMP::volume(mesh) == Approx(4 * pi * radius * radius * radius / 3).epsilon(k >= 3 ? 0.01 : 0.5));
  }
}

TEMPLATE_TEST_CASE("torus: grid counts, genus 1, volume", "[generators]", Surface_mesh, Polyhedron)
{
  TestType mesh;
  SVG::make_torus(mesh, 2.0, 0.5, 80, 24);
  check_closed_shell(mesh, 0);
  CHECK(num_vertices(mesh) == 80u * 24u);
  CHECK(num_faces(mesh) == 2u * 80u * 24u);
  CHECK(PMP::volume(mesh) == Approx(2 * pi * pi * 2.0 * 0.5 * 0.5).epsilon(0.02));
  const Mesh_report r = report(mesh, 0);
  CHECK(r.min_angle > 25);
  CHECK_FALSE(r.duplicated_points);
}

TEMPLATE_TEST_CASE("planar grid: exact area, facing +z, valid jitter", "[generators]", Surface_mesh, Polyhedron)
{
  for(double jitter : {0.0, 0.2}) {
    TestType mesh;
    SVG::make_planar_grid(mesh, 31, 21, 3.0, 2.0, jitter, 7);
    REQUIRE(CGAL::is_valid_polygon_mesh(mesh));
    REQUIRE(CGAL::is_triangle_mesh(mesh));
    CHECK_FALSE(CGAL::is_closed(mesh));
    CHECK(num_vertices(mesh) == 31u * 21u);
    CHECK(num_faces(mesh) == 2u * 30u * 20u);
    CHECK(long(num_vertices(mesh)) - long(num_edges(mesh)) + long(num_faces(mesh)) == 1);
    CHECK(PMP::area(mesh) == Approx(6.0).epsilon(1e-12));
    const CGAL::Bbox_3 box = PMP::bbox(mesh);
    CHECK(box.xmin() == 0);
    CHECK(box.ymin() == 0);
    CHECK(box.xmax() == 3.0);
    CHECK(box.ymax() == 2.0);
    CHECK(box.zmin() == 0);
    CHECK(box.zmax() == 0);
    // Every triangle counter-clockwise seen from +z: none flipped by the jitter.
    for(auto f : faces(mesh)) {
      auto h = halfedge(f, mesh);
      const Point a = get(CGAL::vertex_point, mesh, source(h, mesh));
      const Point b = get(CGAL::vertex_point, mesh, target(h, mesh));
      const Point c = get(CGAL::vertex_point, mesh, target(next(h, mesh), mesh));
      CHECK(CGAL::orientation(Kernel::Point_2(a.x(), a.y()), Kernel::Point_2(b.x(), b.y()),
                              Kernel::Point_2(c.x(), c.y())) == CGAL::LEFT_TURN);
    }
    CHECK(report(mesh, 0).min_angle > (jitter > 0 ? 5.0 : 30.0));
  }
}

TEST_CASE("planar grid: jitter is deterministic and moves interior vertices only", "[generators]")
{
  Surface_mesh a, b, c, plain;
  SVG::make_planar_grid(a, 12, 9, 1.0, 1.0, 0.2, 42);
  SVG::make_planar_grid(b, 12, 9, 1.0, 1.0, 0.2, 42);
  SVG::make_planar_grid(c, 12, 9, 1.0, 1.0, 0.2, 43);
  SVG::make_planar_grid(plain, 12, 9);
  const std::vector<Point> pa = points_of(a), pb = points_of(b), pc = points_of(c), pp = points_of(plain);
  CHECK(pa == pb);
  CHECK(pa != pc);
  std::size_t moved = 0;
  for(std::size_t i = 0; i < pa.size(); ++i) {
    const bool boundary = pp[i].x() == 0 || pp[i].y() == 0 || pp[i].x() == 1 || pp[i].y() == 1;
    if(boundary)
      CHECK(pa[i] == pp[i]);
    else if(pa[i] != pp[i])
      ++moved;
  }
  CHECK(moved == 10u * 7u);
}

TEST_CASE("thin shells: closed, outward, genus, size, triangle quality", "[generators]")
{
  const SVG::Shell_options o = small_shell();
  const double wall = o.thickness * o.size;
  for(const Shell_case& c : shell_cases) {
    INFO("shape " << SVG::shape_name(c.shape));
    Surface_mesh mesh;
    SVG::make_shape(c.shape, mesh, o);
    check_closed_shell(mesh, c.euler);
    const Mesh_report r = report(mesh, wall);
    INFO("vertices " << r.vertices << ", min angle " << r.min_angle << ", off rims " << r.min_angle_off_rims);
    CHECK(double(r.vertices) > 0.7 * double(o.target_vertices));
    CHECK(double(r.vertices) < 1.3 * double(o.target_vertices));
    CHECK_FALSE(r.duplicated_points);
    CHECK(r.min_edge > 1e-3 * wall);
    CHECK(r.min_area > 1e-6 * wall * wall);
    // Needles only across the rims and the U-fold's bend, where a triangle is
    // one wall thickness tall and one edge length long.
    CHECK(r.min_angle_off_rims > 20);
    CHECK(r.min_angle > 5);
    const double diagonal = std::sqrt(CGAL::square(r.bbox.xmax() - r.bbox.xmin()) +
                                      CGAL::square(r.bbox.ymax() - r.bbox.ymin()) +
                                      CGAL::square(r.bbox.zmax() - r.bbox.zmin()));
    CHECK(diagonal == Approx(o.size).epsilon(0.02));
    CHECK_FALSE(PMP::does_self_intersect(mesh));
  }
}

TEST_CASE("thin shells: the same mesh in a Polyhedron_3", "[generators]")
{
  SVG::Shell_options o = small_shell();
  o.target_vertices = 1000;
  for(const Shell_case& c : shell_cases) {
    INFO("shape " << SVG::shape_name(c.shape));
    Polyhedron poly;
    Surface_mesh sm;
    SVG::make_shape(c.shape, poly, o);
    SVG::make_shape(c.shape, sm, o);
    check_closed_shell(poly, c.euler);
    CHECK(num_vertices(poly) == num_vertices(sm));
    CHECK(num_faces(poly) == num_faces(sm));
    CHECK(PMP::volume(poly) == Approx(PMP::volume(sm)).epsilon(1e-12));
  }
}

TEST_CASE("thin shells: at least 10k vertices when asked, good triangles everywhere", "[generators]")
{
  SVG::Shell_options o;
  o.target_vertices = 10000;
  for(const Shell_case& c : shell_cases) {
    INFO("shape " << SVG::shape_name(c.shape));
    Surface_mesh mesh;
    SVG::make_shape(c.shape, mesh, o);
    CHECK(CGAL::is_closed(mesh));
    const Mesh_report r = report(mesh, o.thickness * o.size);
    CHECK(double(r.vertices) > 0.95 * double(o.target_vertices));
    CHECK(double(r.vertices) < 1.05 * double(o.target_vertices));
    // At this resolution even the rims stay above 15 degrees.
    CHECK(r.min_angle > 15);
  }
}

TEST_CASE("slab: the plate is exactly thickness thick", "[generators]")
{
  SVG::Slab_options o;
  o.target_vertices = 1500;
  o.thickness = 0.01;
  o.size = 2.0;
  Surface_mesh mesh;
  SVG::make_thin_slab(mesh, o);
  check_closed_shell(mesh, 2);
  const double t = o.thickness * o.size;
  const CGAL::Bbox_3 b = PMP::bbox(mesh);
  const double dx = b.xmax() - b.xmin(), dy = b.ymax() - b.ymin(), dz = b.zmax() - b.zmin();
  CHECK((std::min)({dx, dy, dz}) == Approx(t).epsilon(1e-12));
  CHECK(dz == Approx(t).epsilon(1e-12));
  CHECK(dx / dy == Approx(o.width / o.depth).epsilon(1e-12));
  CHECK(std::sqrt(dx * dx + dy * dy + dz * dz) == Approx(o.size).epsilon(1e-12));
  CHECK(PMP::volume(mesh) == Approx(dx * dy * dz).epsilon(1e-9));

  SECTION("rim_segments splits the rims")
  {
    o.rim_segments = 3;
    SVG::make_thin_slab(mesh, o);
    check_closed_shell(mesh, 2);
    std::vector<double> z;
    for(const Point& p : points_of(mesh))
      z.push_back(p.z());
    std::sort(z.begin(), z.end());
    std::size_t levels = 1;
    for(std::size_t i = 1; i < z.size(); ++i)
      if(z[i] - z[i - 1] > 1e-12)
        ++levels;
    CHECK(levels == 4u);
  }
}

TEST_CASE("u_fold: two parallel sheets at the stated gap, joined by a bend", "[generators]")
{
  SVG::U_fold_options o;
  o.target_vertices = 2000;
  Surface_mesh mesh;
  SVG::make_u_fold(mesh, o);
  check_closed_shell(mesh, 2);
  const double t = o.thickness * o.size, g = o.gap * t;
  const CGAL::Bbox_3 b = PMP::bbox(mesh);
  CHECK(b.zmax() - b.zmin() == Approx(g + 2 * t).epsilon(1e-12));
  CHECK(b.xmin() == Approx(-(g / 2 + t)).epsilon(1e-9));
  // Over the sheets (x > 0) every vertex lies on one of the four sheet planes,
  // and both inner planes are populated alike: the sheets are flat, parallel
  // and g apart.
  std::size_t on_plane[4] = {0, 0, 0, 0};
  const double planes[4] = {-(g / 2 + t), -g / 2, g / 2, g / 2 + t};
  std::size_t stray = 0;
  for(const Point& p : points_of(mesh)) {
    if(p.x() <= 0)
      continue;
    bool found = false;
    for(int i = 0; i < 4; ++i)
      if(std::abs(p.z() - planes[i]) < 1e-12 * o.size) {
        ++on_plane[i];
        found = true;
      }
    if(!found)
      ++stray;
  }
  CHECK(stray == 0);
  CHECK(on_plane[1] > 100);
  CHECK(on_plane[1] == on_plane[2]);
  CHECK(on_plane[0] == on_plane[3]);
  // Volume: two sheets and a half annulus (inscribed polygons, hence a bit less).
  const double L = b.xmax(), W = b.ymax() - b.ymin();
  const double ro = g / 2 + t, ri = g / 2;
  const double expected = W * (2 * L * t + pi * (ro * ro - ri * ri) / 2);
  CHECK(PMP::volume(mesh) == Approx(expected).epsilon(0.01));
}

TEST_CASE("revolved shells: every vertex on the outer or the inner surface", "[generators]")
{
  const double t = 0.005;
  SECTION("pot")
  {
    SVG::Pot_options o;
    o.target_vertices = 2000;
    Surface_mesh mesh;
    SVG::make_thin_pot(mesh, o);
    const double R = 1.0 / 3, H = 1.0 / 3;  // sqrt(8 R^2 + H^2) = 1
    for(const Point& p : points_of(mesh)) {
      const double rho = std::hypot(p.x(), p.y());
      if(p.z() > t * 1.0001 && p.z() < H * 0.9999)
        CHECK((std::abs(rho - R) < 1e-12 || std::abs(rho - (R - t)) < 1e-12));
    }
    const double expected = pi * (R * R * H - (R - t) * (R - t) * (H - t));
    CHECK(PMP::volume(mesh) == Approx(expected).epsilon(0.01));
  }
  SECTION("bowl")
  {
    Surface_mesh mesh;
    SVG::make_thin_bowl(mesh, small_shell());
    const double R = 1.0 / 3;
    for(const Point& p : points_of(mesh)) {
      const double d = std::sqrt((p - CGAL::ORIGIN).squared_length());
      CHECK((std::abs(d - R) < 1e-12 || std::abs(d - (R - t)) < 1e-12));
      CHECK(p.z() <= 1e-15);
    }
  }
  SECTION("lampshade")
  {
    SVG::Lampshade_options o;
    o.target_vertices = 2000;
    Surface_mesh mesh;
    SVG::make_thin_lampshade(mesh, o);
    check_closed_shell(mesh, 0);
    const double s = 1 / std::sqrt(8 * 1.0 + 1.2 * 1.2);
    const double r0 = s, r1 = 0.6 * s, H = 1.2 * s, L = std::hypot(r1 - r0, H);
    for(const Point& p : points_of(mesh)) {
      // Distance, in the (rho, z) half-plane, from the outer wall's line.
      const double rho = std::hypot(p.x(), p.y());
      const double d = ((r1 - r0) * p.z() - H * (rho - r0)) / L;
      CHECK((std::abs(d) < 1e-12 || std::abs(d - t) < 1e-12));
    }
  }
}

TEST_CASE("walled box: five plates of the stated thickness", "[generators]")
{
  SVG::Box_options o;
  o.target_vertices = 2000;
  Surface_mesh mesh;
  SVG::make_thin_walled_box(mesh, o);
  check_closed_shell(mesh, 2);
  const double t = o.thickness * o.size;
  const CGAL::Bbox_3 b = PMP::bbox(mesh);
  const double W = b.xmax() - b.xmin(), D = b.ymax() - b.ymin(), H = b.zmax() - b.zmin();
  CHECK(std::sqrt(W * W + D * D + H * H) == Approx(o.size).epsilon(1e-12));
  CHECK(PMP::volume(mesh) == Approx(W * D * H - (W - 2 * t) * (D - 2 * t) * (H - t)).epsilon(1e-9));
}

TEST_CASE("make_shape: names, dispatch, vertex counts", "[generators]")
{
  CHECK(SVG::all_shapes().size() == 10u);
  for(SVG::Shape shape : SVG::all_shapes()) {
    INFO("shape " << SVG::shape_name(shape));
    CHECK(SVG::shape_from_name(SVG::shape_name(shape)) == shape);
    SVG::Shell_options o;
    o.target_vertices = 1500;
    Surface_mesh mesh;
    SVG::make_shape(shape, mesh, o);
    REQUIRE(CGAL::is_valid_polygon_mesh(mesh));
    CHECK(CGAL::is_triangle_mesh(mesh));
    CHECK(CGAL::is_closed(mesh) == (shape != SVG::Shape::grid));
    if(shape == SVG::Shape::sphere)
      CHECK(num_vertices(mesh) == 2562u);  // 10 * 4^4 + 2 is the closest icosphere
    else {
      CHECK(double(num_vertices(mesh)) > 0.7 * 1500);
      CHECK(double(num_vertices(mesh)) < 1.3 * 1500);
    }
  }
  CHECK(SVG::shape_name(SVG::Shape::u_fold) == "u_fold");
  CHECK_THROWS_AS(SVG::shape_from_name("cube"), std::invalid_argument);
  CHECK_THROWS_WITH(SVG::shape_from_name("Sphere"), Catch::Contains("sphere, torus, grid"));
}

TEST_CASE("generators: deterministic output", "[generators]")
{
  Surface_mesh a, b;
  SVG::make_shape(SVG::Shape::vase, a, small_shell());
  SVG::make_shape(SVG::Shape::vase, b, small_shell());
  CHECK(points_of(a) == points_of(b));
  // The output graph is cleared first.
  SVG::make_icosphere(a, 1);
  CHECK(num_vertices(a) == 42u);
}

TEST_CASE("generators: bad parameters throw std::invalid_argument", "[generators]")
{
  Surface_mesh m;
  CHECK_THROWS_AS(SVG::make_icosphere(m, -1), std::invalid_argument);
  CHECK_THROWS_AS(SVG::make_icosphere(m, 2, 0.0), std::invalid_argument);
  CHECK_THROWS_AS(SVG::make_torus(m, 1.0, 1.5, 10, 10), std::invalid_argument);
  CHECK_THROWS_AS(SVG::make_torus(m, 1.0, 0.5, 2, 10), std::invalid_argument);
  CHECK_THROWS_AS(SVG::make_planar_grid(m, 1, 10), std::invalid_argument);
  CHECK_THROWS_AS(SVG::make_planar_grid(m, 10, 10, 1.0, -1.0), std::invalid_argument);
  CHECK_THROWS_AS(SVG::make_planar_grid(m, 10, 10, 1.0, 1.0, 0.3), std::invalid_argument);
  SVG::Shell_options bad;
  bad.thickness = 0;
  CHECK_THROWS_AS(SVG::make_thin_bowl(m, bad), std::invalid_argument);
  bad.thickness = 0.2;
  CHECK_THROWS_WITH(SVG::make_thin_bowl(m, bad), Catch::Contains("thickness too large"));
  bad.thickness = 0.005;
  bad.target_vertices = 10;
  CHECK_THROWS_AS(SVG::make_thin_vase(m, bad), std::invalid_argument);
  bad.target_vertices = 1000;
  bad.size = std::nan("");
  CHECK_THROWS_AS(SVG::make_shape(SVG::Shape::box, m, bad), std::invalid_argument);
  SVG::U_fold_options fold;
  fold.gap = -1;
  CHECK_THROWS_AS(SVG::make_u_fold(m, fold), std::invalid_argument);
  SVG::Pot_options pot;
  pot.thickness = 0.1;
  CHECK_THROWS_AS(SVG::make_thin_pot(m, pot), std::invalid_argument);
  CHECK_THROWS_AS(SVG::loop_subdivide(m, -1), std::invalid_argument);
}

TEST_CASE("loop_subdivide: four times the faces per level", "[generators]")
{
  Surface_mesh mesh;
  SVG::make_icosphere(mesh, 1);
  SVG::loop_subdivide(mesh, 2);
  CHECK(num_faces(mesh) == 80u * 16u);
  CHECK(num_vertices(mesh) == 642u);
  CHECK(CGAL::is_closed(mesh));
  SVG::loop_subdivide(mesh, 0);
  CHECK(num_faces(mesh) == 80u * 16u);
}

#ifdef SVD_SOURCE_DIR
TEST_CASE("data/lampshade_thin.off: a valid thin lampshade", "[generators][data]")
{
  const std::string path = std::string(SVD_SOURCE_DIR) + "/examples/Surface_voronoi_diagram/data/lampshade_thin.off";
  std::ifstream size_probe(path, std::ios::binary | std::ios::ate);
  REQUIRE(size_probe.good());
  CHECK(size_probe.tellg() < std::streamoff(1500000));
  Surface_mesh mesh;
  REQUIRE(CGAL::IO::read_OFF(path, mesh));
  check_closed_shell(mesh, 0);
  const double t = 0.005;
  const Mesh_report r = report(mesh, t);
  CHECK(r.vertices >= 6000u);
  CHECK(r.vertices <= 10000u);
  CHECK_FALSE(r.duplicated_points);
  CHECK(r.min_area > 1e-6 * t * t);
  CHECK(r.min_angle > 15);
  CHECK_FALSE(PMP::does_self_intersect(mesh));
  // Written with 9 significant digits: the wall is still t thick to ~1e-8.
  const double s = 1 / std::sqrt(8 * 1.0 + 1.2 * 1.2);
  const double r0 = s, r1 = 0.6 * s, H = 1.2 * s, L = std::hypot(r1 - r0, H);
  for(const Point& p : points_of(mesh)) {
    const double d = ((r1 - r0) * p.z() - H * (std::hypot(p.x(), p.y()) - r0)) / L;
    CHECK((std::abs(d) < 1e-8 || std::abs(d - t) < 1e-8));
  }
}
#endif

} // namespace svd_test_mesh_generators
