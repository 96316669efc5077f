// Tests of CGAL/Surface_voronoi_diagram/sampling.h: random and blue-noise sites.
#include "test_support.h"

#include <test_meshes.h>
#include <CGAL/Surface_voronoi_diagram/sampling.h>
#include <CGAL/Simple_cartesian.h>

#include <limits>

// this file's own names: the suite compiles its files together (see CMakeLists.txt)
namespace svd_test_sampling {

using namespace svd_test;
namespace SV = CGAL::Surface_voronoi;
namespace GEN = svd_test::meshes;

namespace {
template <class Locations>
double min_distance(const Mesh& m, const Locations& ls)
{
  double best = 1e300;
  for(std::size_t i = 0; i < ls.size(); ++i)
    for(std::size_t j = i + 1; j < ls.size(); ++j)
      best = (std::min)(best, CGAL::to_double(CGAL::squared_distance(point_of(ls[i], m), point_of(ls[j], m))));
  return std::sqrt(best);
}
} // namespace

TEST_CASE("sampling: blue noise is deterministic, has N sites, and keeps them apart", "[sampling]")
{
  Mesh m;
  GEN::make_icosphere(m, 4, 1.0);
  const auto a = SV::blue_noise_sites(m, 300, CGAL::parameters::random_seed(7));
  const auto b = SV::blue_noise_sites(m, 300, CGAL::parameters::random_seed(7));
  const auto c = SV::blue_noise_sites(m, 300, CGAL::parameters::random_seed(8));
  REQUIRE(a.size() == 300);
  bool same = true, differ = false;
  for(std::size_t i = 0; i < a.size(); ++i)
  {
    same &= (a[i].first == b[i].first && a[i].second == b[i].second);
    differ |= !(a[i].first == c[i].first && a[i].second == c[i].second);
  }
  CHECK(same);
  CHECK(differ);
  const auto r = SV::random_sites(m, 300, CGAL::parameters::random_seed(7));
  // on the unit sphere with 300 sites, a hexagonal packing spaces them about 0.22 apart
  const double blue = min_distance(m, a), random = min_distance(m, r);
  INFO("minimum distance: blue noise " << blue << ", random " << random);
  CHECK(blue > 0.1);
  CHECK(blue > 3 * random);
  // a diagram on blue-noise sites has even cells
  CGAL::Biharmonic_embedding<Mesh> e(m);
  CGAL::Surface_voronoi_diagram<Mesh> vd(m, e, a);
  check_invariants(vd);
  double lo = 1e300, hi = 0;
  for(std::size_t i = 0; i < vd.number_of_sites(); ++i) { lo = (std::min)(lo, vd.cell_area(i)); hi = (std::max)(hi, vd.cell_area(i)); }
  CHECK(hi / lo < 4);
}

TEST_CASE("sampling: blue noise keeps its sites away from placed ones, which it does not return", "[sampling]")
{
  Mesh m;
  GEN::make_icosphere(m, 4, 1.0);
  // 60 sites placed on the equator, then 240 more
  std::vector<Location<Mesh> > placed;
  for(const auto& l : SV::random_sites(m, 10000, CGAL::parameters::random_seed(2)))
    if(std::abs(point_of(l, m).z()) < 0.01 && placed.size() < 60) placed.push_back(l);
  REQUIRE(placed.size() == 60);
  auto nearest_to_placed = [&](const std::vector<Location<Mesh> >& ls) {
    double best = 1e300;
    for(const auto& l : ls)
      for(const auto& q : placed)
        best = (std::min)(best, std::sqrt(CGAL::to_double(CGAL::squared_distance(point_of(l, m), point_of(q, m)))));
    return best;
  };
  const auto free_sites = SV::blue_noise_sites(m, 240, CGAL::parameters::random_seed(5));
  const auto around = SV::blue_noise_sites(m, 240, SV::parameters::placed_sites(placed, CGAL::parameters::random_seed(5)));
  REQUIRE(around.size() == 240);
  for(const auto& l : around)
    for(const auto& q : placed) CHECK(!(l.first == q.first && l.second == q.second));
  // 300 sites on the unit sphere are about 0.22 apart: without the placed sites in the
  // elimination, some land right beside them
  const double ignoring = nearest_to_placed(free_sites), avoiding = nearest_to_placed(around);
  INFO("nearest to a placed site: " << ignoring << " ignoring them, " << avoiding << " avoiding them");
  CHECK(ignoring < 0.05);
  CHECK(avoiding > 0.08);
}

namespace {
// a tetrahedron with its corners at `s` times the unit corners (0, e_x, e_y, e_z)
Mesh scaled_tetrahedron(double s)
{
  Mesh m;
  const auto a = m.add_vertex(Point(0, 0, 0)), b = m.add_vertex(Point(s, 0, 0));
  const auto c = m.add_vertex(Point(0, s, 0)), d = m.add_vertex(Point(0, 0, s));
  m.add_face(a, c, b);
  m.add_face(a, b, d);
  m.add_face(a, d, c);
  m.add_face(b, c, d);
  return m;
}
} // namespace

TEST_CASE("sampling: areas that overflow or underflow (coordinates near 1e308, 1e-310) still sample, and in bounded time",
          "[sampling][numerics]")
{
  // Before: an infinite total area made Boost's uniform_real recurse until the stack
  // overflowed, a zero total area made it loop forever.
  for(double s : { 1.5e308, 1e-310, 0x1p-1074 * 8 })
  {
    INFO("scale " << s);
    const Mesh m = scaled_tetrahedron(s);
    const auto r = SV::random_sites(m, 1000, CGAL::parameters::random_seed(3));
    REQUIRE(r.size() == 1000);
    std::map<Mesh::Face_index, std::size_t> per_face;
    for(const auto& l : r)
    {
      ++per_face[l.first];
      for(double b : l.second) CHECK((b >= 0 && b <= 1));
    }
    // on the scaled points the areas are those of the unit tetrahedron: every face is drawn
    if(s > 1e-320)
    {
      CHECK(per_face.size() == 4);
      // the slanted face has sqrt(3) times the area of the others
      const std::size_t slanted = per_face[Mesh::Face_index(3)];
      CHECK(slanted > 250);
      CHECK(slanted < 480);
    }
    const auto b = SV::blue_noise_sites(m, 50, CGAL::parameters::random_seed(3));
    CHECK(b.size() == 50);
  }
  // the same distribution as on the unit tetrahedron, at a power-of-two scale
  const auto unit = SV::random_sites(scaled_tetrahedron(1), 200, CGAL::parameters::random_seed(9));
  const auto big = SV::random_sites(scaled_tetrahedron(0x1p1000), 200, CGAL::parameters::random_seed(9));
  std::size_t same_faces = 0;
  for(std::size_t i = 0; i < unit.size(); ++i) same_faces += (unit[i].first == big[i].first);
  CHECK(same_faces == unit.size());
}

namespace {
// a unit square, sparse (density 1) left of x = 0.5 and dense (9) right of x = 0.6, with the
// column between interpolating: 4.1 of its 4.6 units of mass lie right of x = 0.5
Mesh::Property_map<Mesh::Vertex_index, double> two_density_square(Mesh& m)
{
  GEN::make_planar_grid(m, 11, 11, 1.0, 1.0);
  auto density = m.add_property_map<Mesh::Vertex_index, double>("v:test_density", 0.).first;
  for(auto v : vertices(m)) density[v] = (m.point(v).x() > 0.55) ? 9. : 1.;
  return density;
}

template <class Locations>
double fraction_right_of_half(const Mesh& m, const Locations& ls)
{
  std::size_t right = 0;
  for(const auto& l : ls) right += (point_of(l, m).x() > 0.5);
  return double(right) / double(ls.size());
}
} // namespace

TEST_CASE("sampling: random sites follow a vertex density map", "[sampling][density]")
{
  Mesh m;
  const auto density_map = two_density_square(m);
  const auto sites = SV::random_sites(m, 20000, SV::parameters::vertex_density_map(density_map, CGAL::parameters::random_seed(3)));
  REQUIRE(sites.size() == 20000);
  // 4.1 / 4.6 of the mass; the standard deviation of the fraction is 0.0022
  CHECK(std::abs(fraction_right_of_half(m, sites) - 4.1 / 4.6) < 0.01);
  // a uniform map of any level samples as no map at all does, in distribution
  const auto uniform = SV::random_sites(m, 20000, SV::parameters::vertex_density_map(
      CGAL::Constant_property_map<Mesh::Vertex_index, double>(5.), CGAL::parameters::random_seed(3)));
  CHECK(std::abs(fraction_right_of_half(m, uniform) - 0.5) < 0.01);
  // the same seed gives the same sites
  const auto again = SV::random_sites(m, 20000, SV::parameters::vertex_density_map(density_map, CGAL::parameters::random_seed(3)));
  CHECK(again == sites);
}

TEST_CASE("sampling: blue noise follows a vertex density map and spaces sites by it", "[sampling][density]")
{
  Mesh m;
  const auto density_map = two_density_square(m);
  const auto sites = SV::blue_noise_sites(m, 600, SV::parameters::vertex_density_map(density_map, CGAL::parameters::random_seed(4)));
  REQUIRE(sites.size() == 600);
  CHECK(std::abs(fraction_right_of_half(m, sites) - 4.1 / 4.6) < 0.04);
  // the spacing: three times closer where the density is nine times higher
  std::vector<Location<Mesh> > left, right;
  for(const auto& l : sites)
  {
    const double x = point_of(l, m).x();
    if(x < 0.45) left.push_back(l);
    if(x > 0.65) right.push_back(l);
  }
  const double ratio = min_distance(m, left) / min_distance(m, right);
  CHECK(ratio > 2.);
  CHECK(ratio < 4.5);
  // without a map, the sides are alike
  const auto plain = SV::blue_noise_sites(m, 600, CGAL::parameters::random_seed(4));
  CHECK(std::abs(fraction_right_of_half(m, plain) - 0.5) < 0.05);
}

TEST_CASE("sampling: a density map that is negative, not a number or zero everywhere is an error, not a hang", "[sampling][density]")
{
  Mesh m;
  GEN::make_planar_grid(m, 5, 5, 1.0, 1.0);
  for(const double bad : { -1., std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(), 0. })
  {
    INFO("density " << bad);
    auto density = m.add_property_map<Mesh::Vertex_index, double>("v:bad_density", 1.).first;
    density[*vertices(m).begin()] = bad;
    if(bad == 0.)
      for(auto v : vertices(m)) density[v] = 0.;
    CHECK_THROWS_AS(SV::random_sites(m, 10, SV::parameters::vertex_density_map(density)), SV::Input_error);
    CHECK_THROWS_AS(SV::blue_noise_sites(m, 10, SV::parameters::vertex_density_map(density)), SV::Input_error);
    m.remove_property_map(density);
  }
}


TEST_CASE("sampling: locate_points() finds the nearest face a scan of every face finds", "[sampling][locate]")
{
  // a torus (a hole the grid must not bridge) and a plane with needle triangles, points on,
  // near and far from the surface; the oracle projects on every face as locate_points() does
  Mesh torus, grid;
  GEN::make_torus(torus, 1.0, 0.3, 48, 16);
  GEN::make_planar_grid(grid, 30, 3, 30.0, 0.01);
  for(const Mesh* m : { &torus, &grid })
  {
    CGAL::Random random(7);
    std::vector<Point> points;
    for(const auto& l : area_uniform_locations(*m, 200, 3))
    {
      const Point p = point_of(l, *m);
      const double r = (points.size() % 4 == 0) ? 0. : (points.size() % 4 == 3 ? 40. : 0.05);
      auto jitter = [&]() { return r > 0 ? random.get_double(-r, r) : 0.; };
      points.emplace_back(p.x() + jitter(), p.y() + jitter(), p.z() + jitter());
    }
    const auto located = SV::locate_points(*m, points);
    REQUIRE(located.size() == points.size());
    for(std::size_t i = 0; i < points.size(); ++i)
    {
      double best = std::numeric_limits<double>::infinity();
      for(auto f : faces(*m))
      {
        const auto h = halfedge(f, *m);
        const CGAL::Simple_cartesian<double>::Triangle_3 t(
            {m->point(target(h, *m)).x(), m->point(target(h, *m)).y(), m->point(target(h, *m)).z()},
            {m->point(target(next(h, *m), *m)).x(), m->point(target(next(h, *m), *m)).y(), m->point(target(next(h, *m), *m)).z()},
            {m->point(source(h, *m)).x(), m->point(source(h, *m)).y(), m->point(source(h, *m)).z()});
        const CGAL::Simple_cartesian<double>::Point_3 p(points[i].x(), points[i].y(), points[i].z());
        best = (std::min)(best, CGAL::squared_distance(CGAL::Simple_cartesian<double>().construct_projected_point_3_object()(t, p), p));
      }
      const double found = CGAL::to_double(CGAL::squared_distance(point_of(located[i], *m), points[i]));
      CHECK(std::abs(std::sqrt(found) - std::sqrt(best)) <= 1e-9 * (1 + std::sqrt(best)));
    }
  }
  Mesh empty;
  CHECK_THROWS_AS(SV::locate_points(empty, std::vector<Point>(1, Point(0, 0, 0))), SV::Input_error);
  CHECK_THROWS_AS(SV::locate_points(torus, std::vector<Point>(1, Point(std::nan(""), 0, 0))), SV::Input_error);
}

} // namespace svd_test_sampling
