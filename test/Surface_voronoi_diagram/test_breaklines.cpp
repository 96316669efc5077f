// Breaklines (paper 4.7.2): no cell crosses a constrained edge; propagation stops there and
// the arrangement keeps the breakline as a cell boundary.
#include "test_support.h"

#include <CGAL/Surface_voronoi_diagram/Euclidean_embedding.h>
#include <CGAL/Surface_voronoi_diagram/Geodesic_metric.h>
#include <test_meshes.h>

// this file's own names: the suite compiles its files together (see CMakeLists.txt)
namespace svd_test_breaklines {

using namespace svd_test;
namespace SV = CGAL::Surface_voronoi;
namespace GEN = svd_test::meshes;
typedef SV::Euclidean_embedding<Mesh> Euclidean;

namespace {

// edges of a regular grid on the boundary of the square [lo, hi]^2 (a closed loop), or on
// the segment x = 0.5, y in [0, top] (an open line)
template <class Pred>
Mesh::Property_map<Mesh::Edge_index, bool> mark(Mesh& m, Pred on_line)
{
  auto map = m.add_property_map<Mesh::Edge_index, bool>("e:breakline", false).first;
  for(auto e : edges(m))
  {
    const Point a = m.point(source(halfedge(e, m), m)), b = m.point(target(halfedge(e, m), m));
    map[e] = on_line(a) && on_line(b);
  }
  return map;
}

bool near(double a, double b) { return std::abs(a - b) < 1e-9; }

} // namespace

TEST_CASE("breaklines: a closed loop separates the sites inside from those outside", "[breaklines]")
{
  Mesh m;
  GEN::make_planar_grid(m, 21, 21, 1.0, 1.0);   // spacing 0.05
  const double lo = 0.25, hi = 0.75;
  auto on_square = [&](const Point& p) {
    const double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y());
    const bool in_x = x > lo - 1e-9 && x < hi + 1e-9, in_y = y > lo - 1e-9 && y < hi + 1e-9;
    return ((near(x, lo) || near(x, hi)) && in_y) || ((near(y, lo) || near(y, hi)) && in_x);
  };
  auto loop = mark(m, on_square);
  std::size_t marked = 0;
  for(auto e : edges(m)) marked += loop[e];
  REQUIRE(marked == 40);
  // sites inside and outside; an outside site is closer to much of the inside than the inside one
  std::vector<Point> sites = { Point(0.3, 0.3, 0), Point(0.8, 0.8, 0), Point(0.1, 0.5, 0), Point(0.9, 0.2, 0) };
  auto inside = [&](const Point& p) { return p.x() > lo && p.x() < hi && p.y() > lo && p.y() < hi; };
  Euclidean e(m);
  CGAL::Surface_voronoi_diagram<Mesh, Euclidean> vd(m, e, sites, CGAL::parameters::edge_is_constrained_map(loop));
  check_invariants(vd);
  CHECK(SV::internal::Diagram_access::data(vd).breaklines.size() == 40);
  std::size_t checked = 0;
  for(const auto& l : area_uniform_locations(m, 2000, 3))
  {
    const Point p = point_of(l, m);
    if(near(p.x(), lo) || near(p.x(), hi) || near(p.y(), lo) || near(p.y(), hi)) continue;
    CHECK(inside(sites[vd.site_of(l)]) == inside(p));
    ++checked;
  }
  CHECK(checked > 1900);
  // the inside cell is the whole inside square
  CHECK(vd.cell_area(0) == Approx(0.25).epsilon(1e-12));

  // the arrangement keeps the loop as a cell boundary
  Mesh out;
  auto boundary = out.add_property_map<Mesh::Edge_index, bool>("e:boundary", false).first;
  SV::make_arrangement(vd, out, CGAL::parameters::edge_is_constrained_map(boundary));
  double loop_length = 0;
  for(auto ed : edges(out))
    if(boundary[ed] && on_square(out.point(source(halfedge(ed, out), out))) && on_square(out.point(target(halfedge(ed, out), out))))
      loop_length += std::sqrt(CGAL::to_double(CGAL::squared_distance(out.point(source(halfedge(ed, out), out)),
                                                                      out.point(target(halfedge(ed, out), out)))));
  CHECK(loop_length == Approx(2.0).epsilon(1e-12));

  // without a site inside, the inside is unreached, not an error
  std::vector<Point> outside_only = { Point(0.8, 0.8, 0), Point(0.1, 0.5, 0) };
  CGAL::Surface_voronoi_diagram<Mesh, Euclidean> empty_inside(m, e, outside_only,
                                                              CGAL::parameters::edge_is_constrained_map(loop));
  CHECK(empty_inside.unreached_area() == Approx(0.25).epsilon(1e-12));
}

TEST_CASE("breaklines: an open breakline only bends cells around its end", "[breaklines]")
{
  Mesh m;
  GEN::make_planar_grid(m, 21, 21, 1.0, 1.0);
  const double top = 0.6;
  auto line = mark(m, [&](const Point& p) { return near(CGAL::to_double(p.x()), 0.5) && p.y() < top + 1e-9; });
  // a site left of the line and one far right: without the line, the left site owns a band
  // right of the line; with it, its field must go around the end at (0.5, 0.6)
  std::vector<Point> sites = { Point(0.45, 0.1, 0), Point(0.95, 0.1, 0) };
  Euclidean e(m);
  CGAL::Surface_voronoi_diagram<Mesh, Euclidean> free_vd(m, e, sites);
  CGAL::Surface_voronoi_diagram<Mesh, Euclidean> vd(m, e, sites, CGAL::parameters::edge_is_constrained_map(line));
  check_invariants(vd);
  // each cell is one region; the left site still reaches the right of the line, but only
  // around the end, so its cell there is connected to the rest through y > 0.6
  CHECK(vd.number_of_pieces(0) == 1);
  CHECK(vd.number_of_pieces(1) == 1);
  // far from the line and its end nothing changes
  std::size_t same = 0, far = 0;
  for(const auto& l : area_uniform_locations(m, 2000, 5))
  {
    const Point p = point_of(l, m);
    if(std::abs(CGAL::to_double(p.x()) - 0.5) < 0.3) continue;
    ++far;
    same += (vd.site_of(l) == free_vd.site_of(l));
  }
  CHECK(same == far);
  // the areas are those of a plain Voronoi diagram with both sites (Euclidean distances are
  // unchanged; the field only had to travel around the end)
  CHECK(vd.cell_area(0) == Approx(free_vd.cell_area(0)).epsilon(1e-9));
}

namespace {

// The face location of the point (1 - t) a + t b on the mesh edge from vertex a to vertex b,
// exactly on the edge (the third coordinate exactly 0).
Location<Mesh> on_edge(const Mesh& m, Mesh::Vertex_index a, Mesh::Vertex_index b, double t)
{
  const auto h = m.halfedge(a, b);
  REQUIRE(h != Mesh::null_halfedge());
  const auto f = m.face(h);
  Location<Mesh> l(f, {{ 0., 0., 0. }});
  auto g = m.halfedge(f);
  for(int k = 0; k < 3; ++k, g = m.next(g))
    l.second[k] = (m.source(g) == a) ? 1 - t : (m.source(g) == b ? t : 0.);
  return l;
}

Mesh::Vertex_index vertex_at(const Mesh& m, double x, double y)
{
  for(auto v : m.vertices())
    if(near(CGAL::to_double(m.point(v).x()), x) && near(CGAL::to_double(m.point(v).y()), y)) return v;
  FAIL("no vertex there");
  return Mesh::null_vertex();
}

} // namespace

TEST_CASE("breaklines: a site on a breakline owns the nearest points on both sides", "[breaklines]")
{
  Mesh m;
  GEN::make_planar_grid(m, 21, 21, 1.0, 1.0);
  // y = 0.5 across the whole square: two halves that no cell crosses
  auto line = mark(m, [&](const Point& p) { return near(CGAL::to_double(p.y()), 0.5); });
  // on the line: a point inside an edge, and a vertex; off it, sites on both sides
  std::vector<Location<Mesh> > sites = {
    on_edge(m, vertex_at(m, 0.30, 0.5), vertex_at(m, 0.35, 0.5), 0.4),
    CGAL::Polygon_mesh_processing::locate_vertex<double>(vertex_at(m, 0.7, 0.5), m) };
  for(const Point& p : { Point(0.2, 0.8, 0), Point(0.8, 0.85, 0), Point(0.5, 0.2, 0), Point(0.1, 0.1, 0), Point(0.9, 0.3, 0) })
    sites.push_back(CGAL::Polygon_mesh_processing::locate(p, m));
  std::vector<Point> points;
  for(const auto& s : sites) points.push_back(point_of(s, m));
  const std::size_t on_line = 2;

  // the oracle: the nearest of the sites on the line and of those on the point's own side
  auto oracle = [&](const Point& p, std::size_t& label) {
    std::vector<std::pair<double, std::size_t> > d;
    for(std::size_t i = 0; i < points.size(); ++i)
      if(i < on_line || (points[i].y() > 0.5) == (p.y() > 0.5))
        d.emplace_back(std::sqrt(CGAL::to_double(CGAL::squared_distance(p, points[i]))), i);
    std::sort(d.begin(), d.end());
    label = d[0].second;
    return d[1].first - d[0].first > 1e-6;   // not a near tie
  };
  auto check_labels = [&](const auto& vd) {
    check_invariants(vd);
    std::array<std::array<std::size_t, 2>, 2> sides = {{ {{ 0, 0 }}, {{ 0, 0 }} }};
    std::size_t checked = 0, agree = 0;
    for(const auto& l : area_uniform_locations(m, 3000, 11))
    {
      const Point p = point_of(l, m);
      std::size_t label;
      if(near(CGAL::to_double(p.y()), 0.5) || !oracle(p, label)) continue;
      ++checked;
      agree += (vd.site_of(l) == label);
      if(label < on_line) ++sides[label][p.y() > 0.5];
    }
    CHECK(checked > 2900);
    CHECK(agree == checked);
    for(std::size_t i = 0; i < on_line; ++i)
    {
      CHECK(sides[i][0] > 20);
      CHECK(sides[i][1] > 20);
      CHECK(vd.number_of_pieces(i) == 1);
    }
  };
  Euclidean e(m);
  CGAL::Surface_voronoi_diagram<Mesh, Euclidean> euclidean(m, e, sites, CGAL::parameters::edge_is_constrained_map(line));
  check_labels(euclidean);
  // the same point a hair off the line is on one side only: its cell stays there
  std::vector<Location<Mesh> > nudged = sites;
  for(double& b : nudged[0].second) b = (b == 0.) ? 1e-12 : b - 0.5e-12;
  CGAL::Surface_voronoi_diagram<Mesh, Euclidean> one_side(m, e, nudged, CGAL::parameters::edge_is_constrained_map(line));
  std::array<std::size_t, 2> nudged_sides = {{ 0, 0 }};
  for(const auto& l : area_uniform_locations(m, 3000, 11))
    if(one_side.site_of(l) == 0) ++nudged_sides[point_of(l, m).y() > 0.5];
  CHECK((nudged_sides[0] == 0) != (nudged_sides[1] == 0));
  // the geodesic metric: on a plane, the same distances
  SV::Geodesic_metric<Mesh> g(m);
  CGAL::Surface_voronoi_diagram<Mesh, SV::Geodesic_metric<Mesh> > geodesic(m, g, sites, CGAL::parameters::edge_is_constrained_map(line));
  check_labels(geodesic);
}

} // namespace svd_test_breaklines
