// Tests of CGAL/Surface_voronoi_diagram/bisector_polylines.h: the polylines between Voronoi
// vertices and the Voronoi vertices, checked against Euclidean distances to the sites (the
// Euclidean metric's bisectors are exact), against the arrangement's bisector edges and
// against Euler's formula.
#include "test_support.h"

#include <CGAL/Surface_voronoi_diagram/Euclidean_embedding.h>
#include <CGAL/Surface_voronoi_diagram/bisector_polylines.h>
#include <test_meshes.h>

#include <cmath>
#include <map>
#include <set>
#include <vector>

// this file's own names: the suite compiles its files together (see CMakeLists.txt)
namespace svd_test_bisector_polylines {

using namespace svd_test;
namespace SV = CGAL::Surface_voronoi;
namespace GEN = svd_test::meshes;

namespace {

typedef SV::Euclidean_embedding<Mesh> Euclidean;
typedef CGAL::Surface_voronoi_diagram<Mesh, Euclidean> Euclidean_diagram;
typedef SV::Bisector_polyline<Point> Polyline;
typedef SV::Voronoi_vertex<Point> Vertex;
const std::size_t no_site = std::size_t(-1);

double distance(const Point& a, const Point& b) { return std::sqrt(CGAL::to_double(CGAL::squared_distance(a, b))); }

double nearest_distance(const Euclidean_diagram& vd, const Point& p)
{
  double best = std::numeric_limits<double>::infinity();
  for(std::size_t i = 0; i < vd.number_of_sites(); ++i) best = (std::min)(best, distance(p, vd.site_point(i)));
  return best;
}

double length(const Polyline& l)
{
  double s = 0;
  for(std::size_t k = 0; k + 1 < l.points.size(); ++k) s += distance(l.points[k], l.points[k + 1]);
  return s;
}

// The total length of the bisector edges of the arrangement, as make_arrangement() marks them.
double arrangement_bisector_length(const Euclidean_diagram& vd)
{
  Mesh arrangement;
  auto bisector = arrangement.add_property_map<Mesh::Edge_index, bool>("e:bisector", false).first;
  SV::make_arrangement(vd, arrangement, CGAL::parameters::edge_is_constrained_map(bisector));
  double s = 0;
  for(Mesh::Edge_index e : arrangement.edges())
    if(bisector[e])
      s += distance(arrangement.point(arrangement.source(arrangement.halfedge(e))),
                    arrangement.point(arrangement.target(arrangement.halfedge(e))));
  return s;
}

struct Output
{
  std::vector<Polyline> polylines;
  std::vector<Vertex> vertices;
};

Output output_of(const Euclidean_diagram& vd)
{
  Output o;
  SV::bisector_polylines(vd, std::back_inserter(o.polylines));
  SV::voronoi_vertices(vd, std::back_inserter(o.vertices));
  return o;
}

} // namespace

TEST_CASE("bisector polylines: on a sphere, equidistant from their two sites, between Voronoi vertices", "[bisector_polylines]")
{
  Mesh sphere;
  GEN::make_icosphere(sphere, 4, 1.0);
  Euclidean e(sphere);
  const Euclidean_diagram vd(sphere, e, area_uniform_locations(sphere, 30, 11));
  const std::size_t n = vd.number_of_sites();
  const Output o = output_of(vd);
  const double tolerance = 1e-9;

  // Voronoi vertices: at least three sites, all of them nearest
  std::map<std::array<double, 3>, std::size_t> degree_of;
  std::size_t equidistant = 0;
  for(const Vertex& v : o.vertices)
  {
    REQUIRE(v.sites.size() >= 3);
    bool all = true;
    for(std::size_t s : v.sites)
    {
      REQUIRE(s < n);
      all &= (distance(v.point, vd.site_point(s)) - nearest_distance(vd, v.point) < tolerance);
    }
    equidistant += all;
    degree_of[{{ v.point.x(), v.point.y(), v.point.z() }}] = 0;
    // counter-clockwise seen from outside: the sites' triangle faces outwards
    const Point a = vd.site_point(v.sites[0]), b = vd.site_point(v.sites[1]), c = vd.site_point(v.sites[2]);
    CHECK(CGAL::cross_product(b - a, c - a) * (v.point - CGAL::ORIGIN) > 0);
  }
  CHECK(equidistant == o.vertices.size());

  // polylines: two sites, ends at Voronoi vertices, every point on their bisector and no
  // other site nearer
  std::size_t on_bisector = 0, points = 0, left_of_first = 0, segments = 0;
  std::set<std::pair<std::size_t, std::size_t> > pairs;
  for(const Polyline& l : o.polylines)
  {
    REQUIRE(l.sites[0] < l.sites[1]);
    REQUIRE(l.sites[1] < n);
    REQUIRE(l.points.size() >= 2);
    CHECK_FALSE(l.is_closed());   // every cell is a disk with three or more neighbours
    pairs.insert(std::make_pair(l.sites[0], l.sites[1]));
    for(const Point* end : { &l.points.front(), &l.points.back() })
    {
      const auto found = degree_of.find({{ end->x(), end->y(), end->z() }});
      REQUIRE(found != degree_of.end());
      ++found->second;
    }
    const Point a = vd.site_point(l.sites[0]), b = vd.site_point(l.sites[1]);
    for(const Point& p : l.points)
    {
      ++points;
      const double da = distance(p, a), db = distance(p, b);
      on_bisector += (std::abs(da - db) < tolerance && da - nearest_distance(vd, p) < tolerance);
    }
    // the cell of sites[0] on the left, the outward normal up
    for(std::size_t k = 0; k + 1 < l.points.size(); ++k)
    {
      const K::Vector_3 along = l.points[k + 1] - l.points[k];
      if(along.squared_length() < 1e-16) continue;
      const Point m = CGAL::midpoint(l.points[k], l.points[k + 1]);
      const K::Vector_3 left = CGAL::cross_product(m - CGAL::ORIGIN, along);
      const Point q = m + left * (1e-3 / std::sqrt(left.squared_length()));
      ++segments;
      left_of_first += (distance(q, a) < distance(q, b));
    }
  }
  CHECK(on_bisector == points);
  CHECK(left_of_first == segments);

  // each Voronoi vertex ends as many polylines as it has sites; Euler's formula for the
  // graph of the cells' boundaries: V - E + F = 2 with one face per site
  std::size_t degree_mismatch = 0, sum_of_degrees = 0;
  for(const Vertex& v : o.vertices)
  {
    degree_mismatch += (degree_of[{{ v.point.x(), v.point.y(), v.point.z() }}] != v.sites.size());
    sum_of_degrees += v.sites.size();
  }
  CHECK(degree_mismatch == 0);
  CHECK(2 * o.polylines.size() == sum_of_degrees);
  CHECK(long(o.vertices.size()) - long(o.polylines.size()) + long(n) == 2);

  // the pairs are the diagram's neighbours, each once (cells with the closed-ball property)
  std::set<std::pair<std::size_t, std::size_t> > neighbor_pairs;
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t j : vd.neighbors(i))
      if(i < j) neighbor_pairs.insert(std::make_pair(i, j));
  CHECK(pairs == neighbor_pairs);
  CHECK(pairs.size() == o.polylines.size());

  // all the bisector edges of the arrangement, no more
  double total = 0;
  for(const Polyline& l : o.polylines) total += length(l);
  CHECK(total == Approx(arrangement_bisector_length(vd)).epsilon(1e-12));
}

TEST_CASE("bisector polylines: three bands around a torus share closed loops and no Voronoi vertex", "[bisector_polylines]")
{
  const double major = 1.0, minor = 0.4, pi = std::acos(-1.);
  Mesh torus;
  GEN::make_torus(torus, major, minor, 90, 36);
  Euclidean e(torus);
  std::vector<Point> sites;
  for(double u : { 0.0, 2 * pi / 3, 4 * pi / 3 }) sites.push_back(Point((major + minor) * std::cos(u), (major + minor) * std::sin(u), 0.));
  const Euclidean_diagram vd(torus, e, sites);
  const Output o = output_of(vd);
  CHECK(o.vertices.empty());
  REQUIRE(o.polylines.size() == 3);
  std::set<std::pair<std::size_t, std::size_t> > pairs;
  for(const Polyline& l : o.polylines)
  {
    CHECK(l.is_closed());
    pairs.insert(std::make_pair(l.sites[0], l.sites[1]));
    // a circle around the tube, inscribed polygon: a little shorter than 2 pi r
    CHECK(length(l) < 2 * pi * minor);
    CHECK(length(l) > 0.99 * 2 * pi * minor);
    for(const Point& p : l.points)
      CHECK(std::abs(distance(p, vd.site_point(l.sites[0])) - distance(p, vd.site_point(l.sites[1]))) < 1e-9);
  }
  CHECK(pairs == std::set<std::pair<std::size_t, std::size_t> >{ { 0, 1 }, { 0, 2 }, { 1, 2 } });
}

TEST_CASE("bisector polylines: on a planar patch they are straight and end on the border", "[bisector_polylines]")
{
  Mesh grid;
  GEN::make_planar_grid(grid, 30, 30, 1.0, 1.0, 0.2, 2);
  Euclidean e(grid);
  const Euclidean_diagram vd(grid, e, area_uniform_locations(grid, 12, 3));
  const Output o = output_of(vd);
  std::set<std::array<double, 2> > vertex_points;
  std::size_t on_border = 0;
  for(const Vertex& v : o.vertices)
  {
    vertex_points.insert({{ v.point.x(), v.point.y() }});
    const bool at_border = v.point.x() == 0 || v.point.x() == 1 || v.point.y() == 0 || v.point.y() == 1;
    const bool lists_border = std::count(v.sites.begin(), v.sites.end(), no_site) == 1;
    CHECK(at_border == lists_border);
    on_border += at_border;
  }
  CHECK(on_border > 0);
  for(const Polyline& l : o.polylines)
  {
    CHECK(l.sites[1] < vd.number_of_sites());   // the border separates nothing
    CHECK_FALSE(l.is_closed());
    CHECK(vertex_points.count({{ l.points.front().x(), l.points.front().y() }}) == 1);
    CHECK(vertex_points.count({{ l.points.back().x(), l.points.back().y() }}) == 1);
    // the planar bisector is a straight line: every point on the chord
    const K::Vector_2 chord(l.points.back().x() - l.points.front().x(), l.points.back().y() - l.points.front().y());
    for(const Point& p : l.points)
    {
      const K::Vector_2 w(p.x() - l.points.front().x(), p.y() - l.points.front().y());
      CHECK(std::abs(chord.x() * w.y() - chord.y() * w.x()) < 1e-12);
    }
  }
}

TEST_CASE("bisector polylines: the area no site reaches is the second side", "[bisector_polylines]")
{
  // a loop of breaklines around a square with no site inside: the inside is unreached
  Mesh grid;
  GEN::make_planar_grid(grid, 21, 21, 1.0, 1.0);   // spacing 0.05
  const double lo = 0.25, hi = 0.75;
  auto on_square = [&](const Point& p) { return on_square_outline(p, lo, hi); };
  auto inside = [&](const Point& p) { return p.x() > lo && p.x() < hi && p.y() > lo && p.y() < hi; };
  const auto loop = mark_square_outline(grid, lo, hi);
  const std::vector<Point> sites = { Point(0.8, 0.8, 0), Point(0.1, 0.5, 0), Point(0.9, 0.1, 0) };
  Euclidean e(grid);
  const Euclidean_diagram vd(grid, e, sites, CGAL::parameters::edge_is_constrained_map(loop));
  REQUIRE(vd.unreached_area() == Approx(0.25).epsilon(1e-12));
  const Output o = output_of(vd);

  double around_square = 0;
  for(const Polyline& l : o.polylines)
  {
    if(l.sites[1] != no_site)
    {
      CHECK(l.sites[1] < sites.size());
      continue;
    }
    CHECK(l.sites[0] < sites.size());
    around_square += length(l);
    for(std::size_t k = 0; k + 1 < l.points.size(); ++k)
    {
      CHECK(on_square(l.points[k]));
      // the cell on the left: outside the square
      const K::Vector_3 along = l.points[k + 1] - l.points[k];
      const Point m = CGAL::midpoint(l.points[k], l.points[k + 1]);
      CHECK_FALSE(inside(m + K::Vector_3(-along.y(), along.x(), 0) * 0.01));
    }
  }
  CHECK(around_square == Approx(2.0).epsilon(1e-12));
  // where a bisector meets the square, two cells and the unreached area
  std::size_t on_the_square = 0;
  for(const Vertex& v : o.vertices)
    if(on_square(v.point))
    {
      ++on_the_square;
      CHECK(v.sites.size() == 3);
      CHECK(std::count(v.sites.begin(), v.sites.end(), no_site) == 1);
    }
  CHECK(on_the_square == 3);
}

} // namespace svd_test_bisector_polylines
