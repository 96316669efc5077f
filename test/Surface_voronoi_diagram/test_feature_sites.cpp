// Tests of CGAL/Surface_voronoi_diagram/feature_sites.h: sites on the border and the breaklines.
#include "test_support.h"

#include <test_meshes.h>
#include <CGAL/Surface_voronoi_diagram/feature_sites.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <vector>

// this file's own names: the suite compiles its files together (see CMakeLists.txt)
namespace svd_test_feature_sites {

using namespace svd_test;
namespace SV = CGAL::Surface_voronoi;
namespace GEN = svd_test::meshes;
namespace PMP = CGAL::Polygon_mesh_processing;

namespace {

typedef Location<Mesh> Loc;

// the spacing of n sites packed hexagonally on an area (or a density integral) `mass`
double spacing(double mass, std::size_t n) { return std::sqrt(2 * mass / (std::sqrt(3.) * double(n))); }

std::size_t zeros(const Loc& l)
{
  return std::size_t(l.second[0] == 0) + std::size_t(l.second[1] == 0) + std::size_t(l.second[2] == 0);
}

bool at_vertex(const Loc& l)
{
  return zeros(l) == 2 && (l.second[0] == 1 || l.second[1] == 1 || l.second[2] == 1);
}

// the corners of the location's face, in the order of its barycentric coordinates
std::array<Mesh::Vertex_index, 3> corners(const Loc& l, const Mesh& m)
{
  const auto h = halfedge(l.first, m);
  return {{ source(h, m), target(h, m), target(next(h, m), m) }};
}

// the vertices with a non-zero coordinate
std::vector<Mesh::Vertex_index> support(const Loc& l, const Mesh& m)
{
  std::vector<Mesh::Vertex_index> out;
  const auto c = corners(l, m);
  for(int i = 0; i < 3; ++i)
    if(l.second[i] != 0) out.push_back(c[i]);
  return out;
}

double coordinate_at(const Loc& l, const Mesh& m, Mesh::Vertex_index v)
{
  const auto c = corners(l, m);
  for(int i = 0; i < 3; ++i)
    if(c[i] == v) return l.second[i];
  return 0;
}

bool same_bits(const std::vector<Loc>& a, const std::vector<Loc>& b)
{
  if(a.size() != b.size()) return false;
  for(std::size_t i = 0; i < a.size(); ++i)
    if(!(a[i].first == b[i].first && a[i].second == b[i].second)) return false;
  return true;
}

// the distance from p to the border of the unit square
double to_square_border(const Point& p)
{
  return (std::min)({ std::abs(p.x()), std::abs(1 - p.x()), std::abs(p.y()), std::abs(1 - p.y()) });
}

// the position of a point of the unit square's border along it, counter-clockwise from (0, 0)
double square_arc(const Point& p)
{
  const double e = 1e-12;
  if(std::abs(p.y()) < e) return p.x();
  if(std::abs(p.x() - 1) < e) return 1 + p.y();
  if(std::abs(p.y() - 1) < e) return 3 - p.x();
  return 4 - p.y();
}

// whether the gaps between sorted values are all equal to `gap` within a relative 1e-9
bool even_gaps(std::vector<double> s, double gap)
{
  std::sort(s.begin(), s.end());
  for(std::size_t i = 0; i + 1 < s.size(); ++i)
    if(std::abs(s[i + 1] - s[i] - gap) > 1e-9 * gap) return false;
  return true;
}

// the closed cube [0, 1]^3, `cells` grid cells along each edge
Mesh unit_cube(std::size_t cells)
{
  GEN::internal::Soup soup;
  GEN::internal::Welder welder(soup, 1e-9);
  GEN::internal::add_box_faces(welder, soup, {{0., 0., 0.}}, {{1., 1., 1.}}, {{cells, cells, cells}}, true, 1.0);
  soup.orient_outward();
  Mesh m;
  GEN::internal::write_soup(soup, m);
  return m;
}

// the edges whose two faces meet at a dihedral angle (between their normals) above 30 degrees
Mesh::Property_map<Mesh::Edge_index, bool> mark_creases(Mesh& m)
{
  auto crease = m.add_property_map<Mesh::Edge_index, bool>("e:crease", false).first;
  for(auto e : edges(m))
  {
    if(is_border(e, m)) continue;
    const auto a = PMP::compute_face_normal(face(halfedge(e, m), m), m);
    const auto b = PMP::compute_face_normal(face(opposite(halfedge(e, m), m), m), m);
    crease[e] = CGAL::to_double(a * b) < std::cos(30 * CGAL_PI / 180);
  }
  return crease;
}

} // namespace

TEST_CASE("feature sites: the border of a square, corners and even sides", "[feature_sites]")
{
  Mesh m;
  GEN::make_planar_grid(m, 21, 21, 1.0, 1.0);
  const std::size_t n = 400;
  const double h = spacing(1.0, n);
  const std::size_t per_side = std::size_t(std::lround(1 / h)) - 1;
  REQUIRE(per_side == 18);   // 1 / h = 18.6, so the sides are not a trivial count
  const std::vector<Loc> sites = SV::feature_line_sites(m, n);
  REQUIRE(sites.size() == 4 + 4 * per_side);

  // the four corners first, at the vertices, by vertex index: (0,0), (1,0), (0,1), (1,1)
  const Point expected[4] = { Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(1, 1, 0) };
  for(int i = 0; i < 4; ++i)
  {
    CHECK(at_vertex(sites[i]));
    CHECK(point_of(sites[i], m) == expected[i]);
  }
  // every site on the border, on an edge (a zero coordinate), none inside it
  std::vector<std::vector<double> > side(4);
  for(std::size_t i = 0; i < sites.size(); ++i)
  {
    const Point p = point_of(sites[i], m);
    CHECK(zeros(sites[i]) >= 1);
    CHECK(to_square_border(p) < 1e-12);
    CHECK(p.z() == 0);
    if(i < 4) continue;
    CHECK(!at_vertex(sites[i]));
    const double s = square_arc(p);
    side[std::size_t(s)].push_back(s - std::floor(s));
  }
  // per side the count of round(L / h) - 1, and even gaps from corner to corner
  for(std::size_t k = 0; k < 4; ++k)
  {
    INFO("side " << k);
    CHECK(side[k].size() == per_side);
    side[k].push_back(0.);
    side[k].push_back(1.);
    CHECK(even_gaps(side[k], 1. / double(per_side + 1)));
  }
  // each chain's sites follow each other along the chain: consecutive ones a gap apart
  for(std::size_t c = 0; c < 4; ++c)
    for(std::size_t j = 0; j + 1 < per_side; ++j)
    {
      const std::size_t i = 4 + c * per_side + j;
      const double d = std::sqrt(CGAL::to_double(CGAL::squared_distance(point_of(sites[i], m), point_of(sites[i + 1], m))));
      CHECK(d == Approx(1. / double(per_side + 1)).epsilon(1e-9));
    }

  // without the border and without breaklines, nothing is a feature line
  CHECK(SV::feature_line_sites(m, n, SV::parameters::sample_border(false)).empty());
  // the feature sites alone may be more than n: they are returned all the same
  CHECK(SV::feature_line_sites(m, 1).size() == 4);
}

TEST_CASE("feature sites: a border without corners is a closed loop with even sites", "[feature_sites]")
{
  // with a corner angle above 90 degrees the square's border is one loop without corners
  Mesh m;
  GEN::make_planar_grid(m, 21, 21, 1.0, 1.0);
  const std::size_t n = 400;
  const std::size_t k = std::size_t(std::lround(4 / spacing(1.0, n)));
  const std::vector<Loc> sites = SV::feature_line_sites(m, n, SV::parameters::corner_angle(95.));
  REQUIRE(sites.size() == k);
  // it starts at the loop's smallest vertex, (0, 0), and walks one way around it
  CHECK(at_vertex(sites[0]));
  CHECK(point_of(sites[0], m) == Point(0, 0, 0));
  std::vector<double> s;
  for(const Loc& l : sites) s.push_back(square_arc(point_of(l, m)));
  bool up = true, down = true;
  for(std::size_t i = 1; i + 1 < s.size(); ++i)
  {
    up &= s[i + 1] > s[i];
    down &= s[i + 1] < s[i];
  }
  CHECK(up != down);
  s.push_back(4.);
  CHECK(even_gaps(s, 4. / double(k)));
  // below the turn of 90 degrees, the four corners are back
  CHECK(SV::feature_line_sites(m, n, SV::parameters::corner_angle(89.)).size() == 4 + 4 * (std::size_t(std::lround(1 / spacing(1.0, n))) - 1));
}

TEST_CASE("feature sites: a breakline loop around a torus", "[feature_sites]")
{
  const std::size_t nu = 48, nv = 16;
  Mesh m;
  GEN::make_torus(m, 1.0, 0.4, nu, nv);
  // the outer equator: the vertices (i, 0), of index i * nv
  auto on_ring = [&](Mesh::Vertex_index v) { return v.idx() % nv == 0; };
  auto ring = m.add_property_map<Mesh::Edge_index, bool>("e:ring", false).first;
  std::size_t marked = 0;
  for(auto e : edges(m))
  {
    ring[e] = on_ring(source(halfedge(e, m), m)) && on_ring(target(halfedge(e, m), m));
    marked += ring[e];
  }
  REQUIRE(marked == nu);
  const double chord = 2 * 1.4 * std::sin(CGAL_PI / double(nu)), length = double(nu) * chord;
  const double area = CGAL::to_double(PMP::area(m));

  // the position along the ring, from vertex 0
  auto arc = [&](const Loc& l) {
    const std::vector<Mesh::Vertex_index> on = support(l, m);
    REQUIRE(!on.empty());
    REQUIRE(on.size() <= 2);
    for(auto v : on) REQUIRE(on_ring(v));
    if(on.size() == 1) return double(on[0].idx() / nv) * chord;
    std::size_t a = on[0].idx() / nv, b = on[1].idx() / nv;
    if((a + 1) % nu != b) std::swap(a, b);
    REQUIRE((a + 1) % nu == b);
    return (double(a) + coordinate_at(l, m, Mesh::Vertex_index(Mesh::size_type(b * nv)))) * chord;
  };

  for(std::size_t n : { std::size_t(300), std::size_t(1) })
  {
    INFO("n = " << n);
    const std::size_t k = (std::max)(std::size_t(3), std::size_t(std::lround(length / spacing(area, n))));
    if(n == 1) CHECK(k == 3);
    const std::vector<Loc> sites = SV::feature_line_sites(m, n, CGAL::parameters::edge_is_constrained_map(ring));
    REQUIRE(sites.size() == k);
    CHECK(at_vertex(sites[0]));
    CHECK(support(sites[0], m)[0] == Mesh::Vertex_index(0));
    std::vector<double> s;
    for(const Loc& l : sites)
    {
      CHECK(zeros(l) >= 1);
      s.push_back(arc(l));
    }
    s.push_back(length);
    CHECK(even_gaps(s, length / double(k)));
  }

  // with a corner angle below the ring's turns (7.5 degrees) every ring vertex is a corner,
  // and each edge gets round(chord / h) - 1 sites inside
  const std::size_t n = 20000;
  const std::size_t inside = std::size_t(std::lround(chord / spacing(area, n))) - 1;
  REQUIRE(inside >= 1);
  const std::vector<Loc> sites =
      SV::feature_line_sites(m, n, SV::parameters::corner_angle(5., CGAL::parameters::edge_is_constrained_map(ring)));
  CHECK(sites.size() == nu * (1 + inside));
}

TEST_CASE("feature sites: the creases of a cube", "[feature_sites]")
{
  const std::size_t cells = 8;
  Mesh m = unit_cube(cells);
  auto crease = mark_creases(m);
  std::size_t marked = 0;
  for(auto e : edges(m)) marked += crease[e];
  REQUIRE(marked == 12 * cells);
  // the crease vertices have 3 crease edges at the cube's corners, 2 elsewhere
  std::size_t degree3 = 0;
  for(auto v : vertices(m))
  {
    std::size_t d = 0;
    for(auto h : halfedges_around_target(v, m)) d += crease[edge(h, m)];
    CHECK((d == 0 || d == 2 || d == 3));
    degree3 += (d == 3);
  }
  REQUIRE(degree3 == 8);

  const std::size_t n = 600;
  const std::size_t per_crease = std::size_t(std::lround(1 / spacing(6.0, n))) - 1;
  REQUIRE(per_crease == 8);
  const std::vector<Loc> sites = SV::feature_line_sites(m, n, CGAL::parameters::edge_is_constrained_map(crease));
  REQUIRE(sites.size() == 8 + 12 * per_crease);
  auto on_face = [](double c) { return std::abs(c) < 1e-12 || std::abs(c - 1) < 1e-12; };
  std::set<std::array<double, 3> > cube_corners;
  for(std::size_t i = 0; i < 8; ++i)
  {
    CHECK(at_vertex(sites[i]));
    const Point p = point_of(sites[i], m);
    cube_corners.insert({{ p.x(), p.y(), p.z() }});
    CHECK((on_face(p.x()) && on_face(p.y()) && on_face(p.z())));
  }
  CHECK(cube_corners.size() == 8);
  // every site on a crease edge; each crease has its count; no two sites at one point
  std::map<std::array<int, 3>, std::size_t> per_line;   // by the two fixed coordinates, -1 for the free one
  for(std::size_t i = 8; i < sites.size(); ++i)
  {
    const std::vector<Mesh::Vertex_index> on = support(sites[i], m);
    REQUIRE(on.size() == 2);
    const auto h = halfedge(on[0], on[1], m);
    REQUIRE(h.second);
    CHECK(crease[edge(h.first, m)]);
    const Point p = point_of(sites[i], m);
    std::array<int, 3> key;
    int fixed = 0;
    for(int c = 0; c < 3; ++c)
    {
      key[c] = on_face(p[c]) ? int(std::lround(p[c])) : -1;
      fixed += (key[c] >= 0);
    }
    CHECK(fixed == 2);
    ++per_line[key];
  }
  CHECK(per_line.size() == 12);
  for(const auto& kv : per_line) CHECK(kv.second == per_crease);
  double closest = std::numeric_limits<double>::infinity();
  for(std::size_t i = 0; i < sites.size(); ++i)
    for(std::size_t j = i + 1; j < sites.size(); ++j)
      closest = (std::min)(closest, CGAL::to_double(CGAL::squared_distance(point_of(sites[i], m), point_of(sites[j], m))));
  CHECK(std::sqrt(closest) == Approx(1. / double(per_crease + 1)).epsilon(1e-9));

  // the same on a Polyhedron_3: as many sites, at the same points
  Polyhedron p;
  CGAL::copy_face_graph(m, p);
  std::map<std::pair<Point, Point>, bool> by_ends;
  for(auto e : edges(m))
  {
    const Point a = m.point(source(halfedge(e, m), m)), b = m.point(target(halfedge(e, m), m));
    by_ends[std::make_pair((std::min)(a, b), (std::max)(a, b))] = crease[e];
  }
  auto p_crease = get(CGAL::dynamic_edge_property_t<bool>(), p);
  for(auto e : edges(p))
  {
    const Point a = source(halfedge(e, p), p)->point(), b = target(halfedge(e, p), p)->point();
    put(p_crease, e, by_ends[std::make_pair((std::min)(a, b), (std::max)(a, b))]);
  }
  const auto p_sites = SV::feature_line_sites(p, n, CGAL::parameters::edge_is_constrained_map(p_crease));
  REQUIRE(p_sites.size() == sites.size());
  std::size_t matched = 0;
  for(const Loc& l : sites)
  {
    const Point a = point_of(l, m);
    double nearest = std::numeric_limits<double>::infinity();
    for(const auto& pl : p_sites) nearest = (std::min)(nearest, CGAL::to_double(CGAL::squared_distance(a, PMP::construct_point(pl, p))));
    matched += (nearest < 1e-24);
  }
  CHECK(matched == sites.size());
}

TEST_CASE("feature sites: a breakline across a square makes junctions", "[feature_sites]")
{
  Mesh m;
  GEN::make_planar_grid(m, 21, 21, 1.0, 1.0);
  auto middle = m.add_property_map<Mesh::Edge_index, bool>("e:middle", false).first;
  for(auto e : edges(m))
    middle[e] = std::abs(m.point(source(halfedge(e, m), m)).x() - 0.5) < 1e-12 &&
                std::abs(m.point(target(halfedge(e, m), m)).x() - 0.5) < 1e-12;
  const std::size_t n = 400;
  const std::size_t per_half_side = std::size_t(std::lround(0.5 / spacing(1.0, n))) - 1;   // round(9.3) - 1
  const std::size_t per_side = std::size_t(std::lround(1 / spacing(1.0, n))) - 1;
  const std::vector<Loc> sites = SV::feature_line_sites(m, n, CGAL::parameters::edge_is_constrained_map(middle));
  // corners: the square's four and the breakline's two ends on the border (3 feature edges)
  REQUIRE(sites.size() == 6 + 4 * per_half_side + 3 * per_side);
  const Point expected[6] = { Point(0, 0, 0), Point(0.5, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0.5, 1, 0), Point(1, 1, 0) };
  for(int i = 0; i < 6; ++i)
  {
    CHECK(at_vertex(sites[i]));
    CHECK(point_of(sites[i], m) == expected[i]);
  }
  std::size_t on_break = 0;
  for(const Loc& l : sites)
    on_break += (std::abs(point_of(l, m).x() - 0.5) < 1e-12);
  CHECK(on_break == 2 + per_side);
  // the breakline alone: two ends, and the line between them
  const std::vector<Loc> alone =
      SV::feature_line_sites(m, n, SV::parameters::sample_border(false, CGAL::parameters::edge_is_constrained_map(middle)));
  CHECK(alone.size() == 2 + per_side);
}

TEST_CASE("feature sites: a density twice as large shortens the gaps by sqrt(2)", "[feature_sites]")
{
  Mesh m;
  GEN::make_planar_grid(m, 41, 41, 1.0, 1.0);   // spacing 0.025: the density steps up over [0.5, 0.525]
  auto density = m.add_property_map<Mesh::Vertex_index, double>("v:density", 1.).first;
  for(auto v : vertices(m)) density[v] = (m.point(v).x() > 0.5 + 1e-9) ? 2. : 1.;
  // its integral, face by face
  double mass = 0;
  for(auto f : faces(m))
  {
    double mean = 0;
    for(auto v : vertices_around_face(halfedge(f, m), m)) mean += density[v] / 3;
    mass += CGAL::to_double(PMP::face_area(f, m)) * mean;
  }
  CHECK(mass == Approx(1.5).epsilon(0.02));
  const std::size_t n = 400;
  const auto np = SV::parameters::vertex_density_map(density);
  const std::vector<Loc> sites = SV::feature_line_sites(m, n, np);
  CHECK(same_bits(sites, SV::feature_line_sites(m, n, np)));
  // the bottom side: the integral of sqrt(rho) is 0.5 + 0.025 (2 sqrt(2) - 1) 2/3 + 0.475 sqrt(2)
  const double root_integral = 0.5 + 0.025 * (2 * std::sqrt(2.) - 1) * 2 / 3 + 0.475 * std::sqrt(2.);
  const std::size_t expected = std::size_t(std::lround(root_integral / spacing(mass, n))) - 1;
  std::vector<double> xs;
  for(const Loc& l : sites)
  {
    const Point p = point_of(l, m);
    if(p.y() == 0 && p.x() > 0 && p.x() < 1) xs.push_back(p.x());
  }
  CHECK(xs.size() == expected);
  xs.push_back(0.);
  xs.push_back(1.);
  std::sort(xs.begin(), xs.end());
  // the gaps wholly inside either half are all the same there, sqrt(2) times shorter on the right
  std::vector<double> left, right;
  for(std::size_t i = 0; i + 1 < xs.size(); ++i)
  {
    if(xs[i + 1] <= 0.5) left.push_back(xs[i + 1] - xs[i]);
    if(xs[i] >= 0.525) right.push_back(xs[i + 1] - xs[i]);
  }
  REQUIRE(left.size() >= 5);
  REQUIRE(right.size() >= 5);
  for(double g : left) CHECK(g == Approx(left[0]).epsilon(1e-9));
  for(double g : right) CHECK(g == Approx(right[0]).epsilon(1e-9));
  CHECK(left[0] / right[0] == Approx(std::sqrt(2.)).epsilon(1e-9));
  // the left side (density 1) keeps round(L / h) - 1 sites, h from the integral of the density
  std::size_t on_left = 0;
  for(const Loc& l : sites)
  {
    const Point p = point_of(l, m);
    on_left += (p.x() == 0 && p.y() > 0 && p.y() < 1);
  }
  CHECK(on_left == std::size_t(std::lround(1 / spacing(mass, n))) - 1);
}

TEST_CASE("feature sites: determinism, closed meshes, bad densities", "[feature_sites]")
{
  Mesh cube = unit_cube(6);
  auto crease = mark_creases(cube);
  const auto a = SV::feature_line_sites(cube, 500, CGAL::parameters::edge_is_constrained_map(crease));
  const auto b = SV::feature_line_sites(cube, 500, CGAL::parameters::edge_is_constrained_map(crease));
  CHECK(!a.empty());
  CHECK(same_bits(a, b));
  // a closed mesh without breaklines has no feature line
  Mesh sphere;
  GEN::make_icosphere(sphere, 2, 1.0);
  CHECK(SV::feature_line_sites(sphere, 100).empty());

  Mesh m;
  GEN::make_planar_grid(m, 5, 5, 1.0, 1.0);
  auto density = m.add_property_map<Mesh::Vertex_index, double>("v:density", 1.).first;
  density[Mesh::Vertex_index(12)] = -1.;
  CHECK_THROWS_AS(SV::feature_line_sites(m, 50, SV::parameters::vertex_density_map(density)), SV::Input_error);
  density[Mesh::Vertex_index(12)] = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_AS(SV::feature_line_sites(m, 50, SV::parameters::vertex_density_map(density)), SV::Input_error);
  for(auto v : vertices(m)) density[v] = 0.;
  CHECK_THROWS_AS(SV::feature_line_sites(m, 50, SV::parameters::vertex_density_map(density)), SV::Input_error);
  // a density of zero on the border only: the corners, and nothing between them
  for(auto v : vertices(m)) density[v] = (v == Mesh::Vertex_index(12)) ? 1. : 0.;
  CHECK(SV::feature_line_sites(m, 50, SV::parameters::vertex_density_map(density)).size() == 4);
}

TEST_CASE("feature sites: along a varying density, the sites equidistribute sqrt(rho)", "[feature_sites]")
{
  // a coarse grid whose bottom side has two edges, the density 1, 3, 9 at x = 0, 0.5, 1
  Mesh m;
  GEN::make_planar_grid(m, 3, 3, 1.0, 1.0);
  auto density = m.add_property_map<Mesh::Vertex_index, double>("v:density", 1.).first;
  for(auto v : vertices(m))
  {
    const double x = m.point(v).x();
    density[v] = 1 + 8 * x * x;
  }
  double mass = 0;
  for(auto f : faces(m))
  {
    double mean = 0;
    for(auto v : vertices_around_face(halfedge(f, m), m)) mean += density[v] / 3;
    mass += CGAL::to_double(PMP::face_area(f, m)) * mean;
  }
  // the integral of sqrt(rho) from 0 to x along the bottom, rho linear on each edge, by the midpoint rule
  auto rho = [](double x) { return x < 0.5 ? 1 + 4 * x : 3 + 12 * (x - 0.5); };
  auto integral = [&](double x) {
    const int steps = 200000;
    double s = 0;
    for(int i = 0; i < steps; ++i) s += std::sqrt(rho((i + 0.5) * x / steps));
    return s * x / steps;
  };
  const double total = integral(1.);
  for(std::size_t n : { std::size_t(100), std::size_t(1000) })
  {
    INFO("n = " << n);
    const std::size_t k = std::size_t(std::lround(total / spacing(mass, n))) - 1;
    const std::vector<Loc> sites = SV::feature_line_sites(m, n, SV::parameters::vertex_density_map(density));
    std::vector<double> xs;
    for(const Loc& l : sites)
    {
      const Point p = point_of(l, m);
      if(p.y() == 0 && p.x() > 0 && p.x() < 1) xs.push_back(p.x());
    }
    REQUIRE(xs.size() == k);
    std::sort(xs.begin(), xs.end());
    for(std::size_t j = 0; j < k; ++j)
      CHECK(integral(xs[j]) / total == Approx(double(j + 1) / double(k + 1)).margin(1e-7));
  }
}

} // namespace svd_test_feature_sites
