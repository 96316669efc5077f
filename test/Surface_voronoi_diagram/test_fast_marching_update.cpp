// Direct tests of the fast-marching core (CGAL/Surface_voronoi_diagram/internal/geodesic/
// Local_fast_marching.h): the point-source triangle update against the closed form of a
// source unfolded in the plane, in its three forms, and Local_fast_marching on flat meshes,
// where the geodesic distance is the Euclidean one: a jittered grid, a strip of obtuse
// triangles (where only the split of the obtuse corner sees the source), the independence of
// the values from the order of the queries, and a second component that nothing reaches.
#include <catch2/catch.hpp>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_voronoi_diagram/internal/Fast_marching/Local_fast_marching.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <random>
#include <utility>
#include <vector>

// this file's own names: the suite compiles its files together (see CMakeLists.txt)
namespace svd_test_fast_marching_update {

namespace {

namespace SVI = CGAL::Surface_voronoi::internal;
typedef std::array<double, 2> Fm_2;
const double fm_inf = std::numeric_limits<double>::infinity();

SVI::Point_2d fm_point(const Fm_2& p) { return SVI::Point_2d(p[0], p[1]); }
double fm_dist(const Fm_2& p, const Fm_2& q) { return std::hypot(p[0] - q[0], p[1] - q[1]); }

// The closed form: a source s on the other side of line ab than c reaches c straight if the
// segment s-c crosses segment ab. Returns the parameter of the crossing along ab.
double fm_crossing(const Fm_2& s, const Fm_2& a, const Fm_2& b, const Fm_2& c)
{
  // solve s + u (c - s) = a + t (b - a)
  const double ex = c[0] - s[0], ey = c[1] - s[1], fx = b[0] - a[0], fy = b[1] - a[1];
  const double den = ex * (-fy) - ey * (-fx);
  return (ex * (a[1] - s[1]) - ey * (a[0] - s[0])) / den;
}

bool fm_close(double got, double expected, double rel)
{
  return std::abs(got - expected) <= rel * std::abs(expected);
}

// A flat triangle mesh for fast marching: points and corners as the test writes them, made
// into a Surface_mesh (vertices and faces keep their order) and its indexed copy.
typedef CGAL::Surface_mesh<CGAL::Epick::Point_3> Fm_surface;
struct Fm_mesh
{
  std::vector<std::array<double, 3> > points;
  std::vector<std::array<std::uint32_t, 3> > triangles;
  Fm_surface surface;
  std::unique_ptr<SVI::Indexed_mesh<Fm_surface> > indexed;
  std::unique_ptr<SVI::Fast_marching_mesh<Fm_surface> > marching;

  void add(double x, double y) { points.push_back({{ x, y, 0. }}); }
  void face(std::uint32_t a, std::uint32_t b, std::uint32_t c) { triangles.push_back({{ a, b, c }}); }
  void build()
  {
    std::vector<Fm_surface::Vertex_index> v;
    for(const auto& p : points) v.push_back(surface.add_vertex(CGAL::Epick::Point_3(p[0], p[1], p[2])));
    for(const auto& t : triangles) REQUIRE(surface.add_face(v[t[0]], v[t[1]], v[t[2]]) != Fm_surface::null_face());
    indexed.reset(new SVI::Indexed_mesh<Fm_surface>(surface, get(CGAL::vertex_point, surface)));
    marching.reset(new SVI::Fast_marching_mesh<Fm_surface>(*indexed));
  }
  // seeds written in the test's corner order, in the indexed mesh's (which may start at
  // another corner of the face)
  std::vector<SVI::Marching_seed> in_indexed_order(std::vector<SVI::Marching_seed> seeds) const
  {
    for(SVI::Marching_seed& s : seeds)
    {
      std::array<double, 3> b = s.barycentric;
      for(int k = 0; k < 3; ++k)
        for(int j = 0; j < 3; ++j)
          if(indexed->triangles[s.face][k] == triangles[s.face][j]) b[k] = s.barycentric[j];
      s.barycentric = b;
    }
    return seeds;
  }
  // the seed's point (test's corner order)
  std::array<double, 3> seed_point(const SVI::Marching_seed& s) const
  {
    std::array<double, 3> p = {{ 0., 0., 0. }};
    for(int k = 0; k < 3; ++k)
      for(int c = 0; c < 3; ++c) p[c] += s.barycentric[k] * points[triangles[s.face][k]][c];
    return p;
  }
};

double fm_length(const std::array<double, 3>& p, const std::array<double, 3>& q)
{
  return std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
}

// (n+1)^2 vertices on [0,1]^2 with inner vertices moved by up to `jitter` cells, cells split
// along alternating diagonals
void fm_grid(Fm_mesh& m, int n, double jitter, unsigned seed, double dx = 0)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-jitter, jitter);
  const std::uint32_t base = std::uint32_t(m.points.size());
  for(int j = 0; j <= n; ++j)
    for(int i = 0; i <= n; ++i)
    {
      const bool inner = i > 0 && j > 0 && i < n && j < n;
      m.add(dx + (i + (inner ? u(rng) : 0.)) / n, (j + (inner ? u(rng) : 0.)) / n);
    }
  auto id = [&](int i, int j) { return base + std::uint32_t(j * (n + 1) + i); };
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < n; ++i)
      if((i + j) % 2) { m.face(id(i, j), id(i + 1, j), id(i + 1, j + 1)); m.face(id(i, j), id(i + 1, j + 1), id(i, j + 1)); }
      else { m.face(id(i, j), id(i + 1, j), id(i, j + 1)); m.face(id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)); }
}

} // namespace

TEST_CASE("point source update: a source unfolded in the plane", "[fast_marching_update]")
{
  std::mt19937 rng(123);
  std::uniform_real_distribution<double> u(0, 1);
  int hits = 0, misses = 0;
  for(int n = 0; n < 20000; ++n)
  {
    // in the frame: a = (0,0), b = (ab, 0), c above, the source below
    const double ab = 0.5 + 1.5 * u(rng);
    const Fm_2 a = {{ 0, 0 }}, b = {{ ab, 0 }};
    const Fm_2 s = {{ -1.5 + 4 * u(rng), -0.2 - 2 * u(rng) }}, c = {{ -1.5 + 4 * u(rng), 0.2 + 2 * u(rng) }};
    const double da = fm_dist(s, a), db = fm_dist(s, b);
    const double t = fm_crossing(s, a, b, c);
    if(std::abs(t) < 0.01 || std::abs(t - 1) < 0.01) continue;   // too close to call
    const bool hit = t > 0 && t < 1;
    const double expected = hit ? fm_dist(s, c) : fm_inf;
    hits += hit;
    misses += !hit;
    // the same triangle moved by a rigid motion (a reflection half of the time)
    const double th = 6.283185307179586 * u(rng), tx = 10 * u(rng) - 5, ty = 10 * u(rng) - 5;
    const double flip = n % 2 ? -1. : 1.;
    auto move = [&](const Fm_2& p) -> Fm_2 {
      return {{ tx + std::cos(th) * p[0] - std::sin(th) * flip * p[1], ty + std::sin(th) * p[0] + std::cos(th) * flip * p[1] }};
    };
    const Fm_2 ma = move(a), mb = move(b), mc = move(c);
    const double results[5] = {
      SVI::point_source_in_frame(ab, c[0], c[1], da, db),
      SVI::point_source_update(fm_point(ma), fm_point(mb), fm_point(mc), da, db),
      SVI::point_source_update(fm_point(mb), fm_point(ma), fm_point(mc), db, da),                                  // a <-> b
      SVI::point_source_update(fm_dist(a, b), fm_dist(a, c), fm_dist(b, c), da, db),  // side lengths
      SVI::point_source_update(fm_dist(a, b), fm_dist(b, c), fm_dist(a, c), db, da)
    };
    INFO("ab " << ab << " source " << s[0] << " " << s[1] << " c " << c[0] << " " << c[1]);
    for(double r : results)
    {
      if(hit) CHECK(fm_close(r, expected, 1e-12));
      else CHECK(r == fm_inf);
    }
  }
  CHECK(hits > 3000);
  CHECK(misses > 3000);
}

TEST_CASE("point source update: no source, or a degenerate triangle", "[fast_marching_update]")
{
  // da + db < ab and |da - db| > ab: no point is at those distances from a and b
  CHECK(SVI::point_source_in_frame(2., 1., 1., 0.9, 0.9) == fm_inf);
  CHECK(SVI::point_source_in_frame(1., 0.5, 1., 3., 1.5) == fm_inf);
  CHECK(SVI::point_source_update(SVI::Point_2d(0., 0.), SVI::Point_2d(2., 0.), SVI::Point_2d(1., 1.), 0.9, 0.9) == fm_inf);
  CHECK(SVI::point_source_update(2., std::sqrt(2.), std::sqrt(2.), 0.9, 0.9) == fm_inf);
  // a = b, or c on line ab
  CHECK(SVI::point_source_in_frame(0., 1., 1., 1., 1.) == fm_inf);
  CHECK(SVI::point_source_in_frame(1., 0.5, 0., 1., 1.) == fm_inf);
  CHECK(SVI::point_source_update(SVI::Point_2d(1., 1.), SVI::Point_2d(1., 1.), SVI::Point_2d(0., 3.), 1., 1.) == fm_inf);
  CHECK(SVI::point_source_update(0., 1., 1., 1., 1.) == fm_inf);
  // the source on the line through a and b, between them: the distance from c is exact
  CHECK(SVI::point_source_in_frame(2., 1., 1., 1., 1.) == Approx(1.).epsilon(1e-12));
  // an exactly known case: source (1, -1), c = (1, 3)
  CHECK(SVI::point_source_in_frame(2., 1., 3., std::sqrt(2.), std::sqrt(2.)) == Approx(4.).epsilon(1e-15));
}

TEST_CASE("Local_fast_marching: flat jittered grid against Euclidean distances", "[fast_marching_update]")
{
  Fm_mesh m;
  fm_grid(m, 24, 0.3, 5);
  m.build();
  SVI::Local_fast_marching<Fm_surface> lfm(*m.marching);
  std::vector<SVI::Marching_seed> seeds(2);
  seeds[0].face = 2 * (24 * 11 + 12);
  seeds[0].barycentric = {{ 0.2, 0.3, 0.5 }};
  seeds[1].face = 7;
  seeds[1].barycentric = {{ 0.6, 0.3, 0.1 }};
  lfm.set_seeds(m.in_indexed_order(seeds));
  for(std::size_t i = 0; i < seeds.size(); ++i)
  {
    const std::array<double, 3> p = m.seed_point(seeds[i]);
    for(std::uint32_t v = 0; v < m.points.size(); ++v)
    {
      const double e = fm_length(m.points[v], p);
      const double d = lfm.distance(i, v);
      INFO("site " << i << " vertex " << v << " euclidean " << e);
      CHECK(std::abs(d - e) <= (std::max)(0.02 * e, 3e-3));
    }
    // the corners of the seed's face are straight
    for(std::uint32_t v : m.triangles[seeds[i].face])
      CHECK(lfm.distance(i, v) == Approx(fm_length(m.points[v], p)).epsilon(1e-14));
  }
}

TEST_CASE("Local_fast_marching: the split of obtuse corners gives straight distances", "[fast_marching_update]")
{
  // A fan from the seed vertex O = (0.5, -5) to a zigzag T_0 M_0 T_1 M_1 ... T_n (T_i = (i, 0),
  // M_i = (i + 1/2, -0.15)), a triangle M_i T_{i+1} T_i over each M_i, and over each top edge
  // T_i T_{i+1} an apex A_i = (i + 1/2, 0.1): a strip of 169-degree corners. O's neighbours
  // are exact (straight edges); the apexes far to the side are nearer to O than T_{i+1}, so
  // without the split through M_i they would be accepted from T_i along an edge.
  const int n = 14;
  Fm_mesh m;
  m.add(0.5, -5);                                      // O = 0
  for(int i = 0; i <= n; ++i) m.add(i, 0);             // T_i = 1 + i
  for(int i = 0; i < n; ++i) m.add(i + 0.5, -0.15);    // M_i = n + 2 + i
  for(int i = 0; i < n; ++i) m.add(i + 0.5, 0.1);      // A_i = 2n + 2 + i
  auto T = [&](int i) { return std::uint32_t(1 + i); };
  auto M = [&](int i) { return std::uint32_t(n + 2 + i); };
  auto A = [&](int i) { return std::uint32_t(2 * n + 2 + i); };
  for(int i = 0; i < n; ++i)
  {
    m.face(0, M(i), T(i));
    m.face(0, T(i + 1), M(i));
    m.face(M(i), T(i + 1), T(i));
    m.face(T(i), T(i + 1), A(i));
    if(i + 1 < n) m.face(T(i + 1), A(i + 1), A(i));
  }
  m.build();
  SVI::Local_fast_marching<Fm_surface> lfm(*m.marching);
  std::vector<SVI::Marching_seed> seeds(1);
  seeds[0].face = 0;
  seeds[0].barycentric = {{ 1., 0., 0. }};   // at O
  lfm.set_seeds(m.in_indexed_order(seeds));
  // the domain is star-shaped from O: every distance is straight
  for(std::uint32_t v = 0; v < m.points.size(); ++v)
  {
    const double e = fm_length(m.points[v], m.points[0]);
    INFO("vertex " << v << " euclidean " << e);
    CHECK(std::abs(lfm.distance(0, v) - e) <= 1e-12 * e);
  }
}

TEST_CASE("Local_fast_marching: values do not depend on the order of the queries", "[fast_marching_update]")
{
  Fm_mesh m;
  fm_grid(m, 16, 0.3, 77);
  m.build();
  std::vector<SVI::Marching_seed> seeds(3);
  const std::uint32_t faces[3] = { 5, 200, 411 };
  for(int i = 0; i < 3; ++i)
  {
    seeds[i].face = faces[i];
    seeds[i].barycentric = {{ 0.25, 0.25, 0.5 }};
  }
  const std::uint32_t nv = std::uint32_t(m.points.size());
  SVI::Local_fast_marching<Fm_surface> forward(*m.marching), backward(*m.marching);
  forward.set_seeds(m.in_indexed_order(seeds));
  backward.set_seeds(m.in_indexed_order(seeds));
  std::vector<std::vector<double> > first(3, std::vector<double>(nv)), second(3, std::vector<double>(nv));
  for(std::size_t i = 0; i < 3; ++i)
    for(std::uint32_t v = 0; v < nv; ++v) first[i][v] = forward.distance(i, v);
  // reverse vertex order, sites interleaved, some far vertices first
  std::mt19937 rng(3);
  std::vector<std::uint32_t> order(nv);
  for(std::uint32_t v = 0; v < nv; ++v) order[v] = nv - 1 - v;
  std::shuffle(order.begin(), order.begin() + nv / 3, rng);
  for(std::uint32_t v : order)
    for(std::size_t i = 3; i-- > 0;) second[i][v] = backward.distance(i, v);
  for(std::size_t i = 0; i < 3; ++i)
    for(std::uint32_t v = 0; v < nv; ++v)
    {
      INFO("site " << i << " vertex " << v);
      CHECK(first[i][v] == second[i][v]);   // bit for bit
    }
}

TEST_CASE("Local_fast_marching: a second component is unreachable", "[fast_marching_update]")
{
  Fm_mesh m;
  fm_grid(m, 6, 0.2, 9);
  const std::uint32_t first_count = std::uint32_t(m.points.size());
  fm_grid(m, 4, 0.2, 10, 3.0);   // a separate grid on [3, 4] x [0, 1]
  m.build();
  SVI::Local_fast_marching<Fm_surface> lfm(*m.marching);
  std::vector<SVI::Marching_seed> seeds(2);
  seeds[0].face = 3;
  seeds[0].barycentric = {{ 0.3, 0.3, 0.4 }};
  seeds[1].face = std::uint32_t(m.triangles.size() - 1);   // on the second grid
  seeds[1].barycentric = {{ 0.3, 0.3, 0.4 }};
  lfm.set_seeds(m.in_indexed_order(seeds));
  for(std::uint32_t v = first_count; v < m.points.size(); ++v) CHECK(lfm.distance(0, v) == fm_inf);
  for(std::uint32_t v = 0; v < first_count; ++v)
  {
    CHECK(std::isfinite(lfm.distance(0, v)));
    CHECK(lfm.distance(1, v) == fm_inf);
  }
  // the front is exhausted now; asking again gives the same answers
  CHECK(lfm.distance(0, first_count) == fm_inf);
  CHECK(lfm.distance(0, 0) == Approx(fm_length(m.points[0], m.seed_point(seeds[0]))).epsilon(0.03));
}

} // namespace svd_test_fast_marching_update
