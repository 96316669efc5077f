// Direct tests of stitch() (CGAL/Surface_voronoi_diagram/internal/stitching.h): small meshes,
// per-vertex squared distances to sites (both faces of an edge see the same corner values),
// every face cut by Face_cutter, then the partition is checked against independent oracles:
// no cracks, areas, one vertex per point, owners, the crossings on every mesh edge (counted
// here with exact rationals), and a valid polygon mesh built from the pieces. The adversarial
// cases put Voronoi vertices exactly on mesh edges and vertices and bisectors along edges.
// Last, the repair's connectivity check, on the cuts and on the stitched partition, is held
// against regions found here from the partition's shared piece edges.
#include <catch2/catch.hpp>

#include <CGAL/Surface_voronoi_diagram/internal/Stitching/Stitcher.h>
#include <CGAL/Surface_voronoi_diagram/internal/Cell_connectivity.h>
#include <CGAL/Surface_voronoi_diagram/internal/Propagation.h>

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <numeric>
#include <functional>
#include <random>
#include <set>
#include <vector>

// this file's own names: the suite compiles its files together (see CMakeLists.txt)
namespace svd_test_stitcher {

namespace {

namespace SVI = CGAL::Surface_voronoi::internal;
typedef CGAL::Exact_predicates_inexact_constructions_kernel St_kernel;
typedef CGAL::Surface_mesh<St_kernel::Point_3> St_mesh;
typedef SVI::Indexed_mesh<St_mesh> St_indexed;
typedef St_kernel::Vector_3 St_vector;
typedef std::array<double, 3> St_point;
typedef CGAL::Exact_rational St_q;

St_mesh st_make(const std::vector<St_point>& points, const std::vector<std::array<int, 3> >& faces)
{
  St_mesh m;
  std::vector<St_mesh::Vertex_index> v;
  for(const St_point& p : points) v.push_back(m.add_vertex(St_kernel::Point_3(p[0], p[1], p[2])));
  for(const auto& f : faces) REQUIRE(m.add_face(v[f[0]], v[f[1]], v[f[2]]) != St_mesh::null_face());
  return m;
}

// the square [0, s]^2 cut along its diagonal (0,0)-(s,s)
St_mesh st_square(double s) { return st_make({ { 0, 0, 0 }, { s, 0, 0 }, { s, s, 0 }, { 0, s, 0 } }, { { 0, 1, 2 }, { 0, 2, 3 } }); }

// six triangles around the origin
St_mesh st_fan() { return st_make({ { 0, 0, 0 }, { 8, 0, 0 }, { 4, 7, 0 }, { -4, 7, 0 }, { -8, 0, 0 }, { -4, -7, 0 }, { 4, -7, 0 } },
                 { { 0, 1, 2 }, { 0, 2, 3 }, { 0, 3, 4 }, { 0, 4, 5 }, { 0, 5, 6 }, { 0, 6, 1 } }); }

// n x n unit cells, diagonals in both directions, height z(x, y)
template <class Height>
St_mesh st_grid(int n, const Height& z)
{
  std::vector<St_point> p;
  std::vector<std::array<int, 3> > f;
  for(int j = 0; j <= n; ++j)
    for(int i = 0; i <= n; ++i) p.push_back({{ double(i), double(j), z(i, j) }});
  auto id = [n](int i, int j) { return j * (n + 1) + i; };
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < n; ++i)
    {
      const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if((i + j) % 2 == 0) { f.push_back({{ a, b, c }}); f.push_back({{ a, c, d }}); }
      else { f.push_back({{ a, b, d }}); f.push_back({{ b, c, d }}); }
    }
  return st_make(p, f);
}

// One stitched mesh. The mesh is kept here (the index maps of `mesh` refer to it), so a run is
// neither copied nor reused.
struct St_run
{
  St_mesh surface;
  St_indexed mesh;
  std::vector<std::vector<double> > field;   // field[site][vertex]
  SVI::Candidate_lists candidates;
  SVI::Face_cuts cuts;
  SVI::Partition part;
};

// every site a candidate of every face (odd faces: only those not dominated, as the pipeline
// keeps them, so that lists differ across edges), cuts and the stitch
std::unique_ptr<St_run> st_run_fields(const St_mesh& m, const std::vector<std::vector<double> >& field)
{
  std::unique_ptr<St_run> run(new St_run);
  St_run& r = *run;
  r.surface = m;
  r.mesh.build(r.surface, get(CGAL::vertex_point, r.surface));
  r.field = field;
  r.candidates.assign(r.mesh.number_of_faces(), {});
  r.cuts.reset(r.mesh.number_of_faces());
  for(std::size_t f = 0; f < r.mesh.number_of_faces(); ++f)
  {
    const auto& t = r.mesh.triangles[f];
    for(std::size_t s = 0; s < field.size(); ++s)
      r.candidates[f].push_back({ std::uint32_t(s), {{ field[s][t[0]], field[s][t[1]], field[s][t[2]] }} });
    if(f % 2) SVI::clean_candidate_list(r.candidates[f]);
    r.cuts.set(f, SVI::Face_cutter(r.candidates[f]).cut());
  }
  SVI::stitch(r.mesh, SVI::Candidate_table(SVI::Candidate_lists(r.candidates)), r.cuts, r.part);   // packed, as the builder does
  return run;
}

// the fields of a linear embedding: squared distances from the vertices to the sites
std::unique_ptr<St_run> st_run(const St_mesh& m, const std::vector<St_point>& sites)
{
  std::vector<std::vector<double> > field(sites.size());
  for(std::size_t s = 0; s < sites.size(); ++s)
    for(St_mesh::Vertex_index v : vertices(m))
    {
      const St_kernel::Point_3& p = m.point(v);
      field[s].push_back(CGAL::square(p.x() - sites[s][0]) + CGAL::square(p.y() - sites[s][1]) + CGAL::square(p.z() - sites[s][2]));
    }
  return st_run_fields(m, field);
}

// number of points strictly inside edge e where the lowest (value, site) pair changes,
// from the corner values taken as exact
int st_changes_along(const St_run& r, std::size_t e)
{
  const std::size_t a = r.mesh.edge_vertices[e][0], b = r.mesh.edge_vertices[e][1];
  const std::size_t n = r.field.size();
  auto value = [&](std::size_t i, const St_q& t) -> St_q { return (1 - t) * St_q(r.field[i][a]) + t * St_q(r.field[i][b]); };
  std::vector<St_q> ts = { St_q(0), St_q(1) };   // 0, 1 and every crossing of two sites
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t j = 0; j < i; ++j)
    {
      const St_q h0 = value(i, 0) - value(j, 0), h1 = value(i, 1) - value(j, 1);
      if(h0 != h1 && h0 / (h0 - h1) > 0 && h0 / (h0 - h1) < 1) ts.push_back(h0 / (h0 - h1));
    }
  std::sort(ts.begin(), ts.end());
  ts.erase(std::unique(ts.begin(), ts.end()), ts.end());
  int changes = 0;
  std::size_t previous = n;
  for(std::size_t k = 0; k + 1 < ts.size(); ++k)   // the lowest pair between two crossings
  {
    const St_q t = (ts[k] + ts[k + 1]) / 2;
    std::size_t best = 0;
    for(std::size_t i = 1; i < n; ++i)
      if(value(i, t) < value(best, t)) best = i;
    changes += previous != n && best != previous;
    previous = best;
  }
  return changes;
}

// how many vertices used by pieces lie within `tol` of x
std::size_t st_near(const St_run& r, const St_point& x, double tol)
{
  std::set<std::size_t> ids;
  for(const SVI::Partition::Piece& p : r.part.pieces)
    for(std::size_t id : p.vertices)
    {
      const SVI::Point_d& q = r.part.vertices[id].point;
      if(std::abs(q[0] - x[0]) + std::abs(q[1] - x[1]) + std::abs(q[2] - x[2]) <= tol) ids.insert(id);
    }
  return ids.size();
}

St_vector st_vec(const SVI::Point_d& p) { return St_vector(p[0], p[1], p[2]); }

// Every invariant of a partition; returns the area owned by each site.
std::vector<double> st_check(const St_run& r)
{
  const SVI::Partition& part = r.part;
  std::map<std::pair<std::size_t, std::size_t>, int> directed;
  std::set<std::size_t> used;
  std::vector<double> site_area(r.field.size(), 0.);
  double total = 0;
  for(const SVI::Partition::Piece& p : part.pieces)
  {
    REQUIRE(p.vertices.size() >= 3);
    REQUIRE(p.site < r.field.size());
    St_vector newell(0, 0, 0), x(0, 0, 0);   // twice the area times the normal; the centroid
    for(std::size_t k = 0; k < p.vertices.size(); ++k)
    {
      const std::size_t u = p.vertices[k], w = p.vertices[(k + 1) % p.vertices.size()];
      REQUIRE(u < part.vertices.size());
      used.insert(u);
      ++directed[{ u, w }];
      newell = newell + CGAL::cross_product(st_vec(part.vertices[u].point), st_vec(part.vertices[w].point));
      x = x + st_vec(part.vertices[u].point) / double(p.vertices.size());
    }
    // positive area, oriented as its face
    const auto& t = r.mesh.triangles[p.face];
    const St_vector a = st_vec(r.mesh.points[t[0]]), b = st_vec(r.mesh.points[t[1]]), c = st_vec(r.mesh.points[t[2]]);
    const St_vector face_n = CGAL::cross_product(b - a, c - a);
    CHECK(newell * face_n > 0);
    total += 0.5 * std::sqrt(newell.squared_length());
    site_area[p.site] += 0.5 * std::sqrt(newell.squared_length());
    // the owner at the centroid, from the fields interpolated at its barycentric coordinates
    auto bary = [&](const St_vector& u, const St_vector& w) { return CGAL::cross_product(u - x, w - x) * face_n / face_n.squared_length(); };
    const double b0 = bary(b, c), b1 = bary(c, a), b2 = bary(a, b);
    auto value = [&](std::size_t s) { return b0 * r.field[s][t[0]] + b1 * r.field[s][t[1]] + b2 * r.field[s][t[2]]; };
    double lowest = value(p.site), scale = 0;
    for(std::size_t s = 0; s < r.field.size(); ++s)
    {
      lowest = (std::min)(lowest, value(s));
      for(int k = 0; k < 3; ++k) scale = (std::max)(scale, std::abs(r.field[s][t[k]]));
    }
    CHECK(value(p.site) <= lowest + 1e-9 * scale);
  }
  CHECK(std::abs(total - r.mesh.total_area) <= 1e-12 * r.mesh.total_area);
  // no cracks: every piece edge once, matched by its reverse unless it runs along a border edge
  auto on_edge = [&](std::size_t id, std::size_t e) {
    const SVI::Partition::Vertex& v = part.vertices[id];
    if(v.kind == SVI::Partition::AT_CORNER) return v.element == r.mesh.edge_vertices[e][0] || v.element == r.mesh.edge_vertices[e][1];
    return v.kind == SVI::Partition::ON_EDGE && v.element == e;
  };
  std::vector<bool> border(r.mesh.number_of_edges(), false);
  for(std::size_t f = 0; f < r.mesh.number_of_faces(); ++f)
    for(int k = 0; k < 3; ++k)
      if(r.mesh.neighbors[f][k] == St_indexed::none) border[r.mesh.edges[f][k]] = true;
  for(const auto& entry : directed)
  {
    const std::size_t u = entry.first.first, w = entry.first.second;
    CHECK(entry.second == 1);
    if(directed.count({ w, u })) continue;
    bool on_border = false;
    for(std::size_t e = 0; e < border.size(); ++e) on_border |= border[e] && on_edge(u, e) && on_edge(w, e);
    INFO("unmatched piece edge " << u << " -> " << w);
    CHECK(on_border);
  }
  // one vertex per point: no two used ids at the same position, nor a rounding error apart
  // (an exact tie named differently by two faces must become one vertex)
  for(std::size_t id : used)
  {
    const SVI::Partition::Vertex& v = part.vertices[id];
    if(v.kind == SVI::Partition::AT_CORNER) CHECK(v.point == r.mesh.points[v.element]);
    CHECK(st_near(r, St_point{{ v.point.x(), v.point.y(), v.point.z() }}, 1e-9) == 1);
  }
  // the crossings on each mesh edge: one vertex each
  for(std::size_t e = 0; e < r.mesh.number_of_edges(); ++e)
  {
    int on = 0;
    for(std::size_t id : used) on += part.vertices[id].kind == SVI::Partition::ON_EDGE && part.vertices[id].element == e;
    INFO("mesh edge " << e);
    CHECK(on == st_changes_along(r, e));
  }
  // the pieces as faces of a polygon mesh
  St_mesh out;
  std::map<std::size_t, St_mesh::Vertex_index> vmap;
  for(std::size_t id : used) vmap[id] = out.add_vertex(CGAL::ORIGIN + st_vec(part.vertices[id].point));
  for(const SVI::Partition::Piece& p : part.pieces)
  {
    std::vector<St_mesh::Vertex_index> vs;
    for(std::size_t id : p.vertices) vs.push_back(vmap[id]);
    CHECK(CGAL::Euler::add_face(vs, out) != St_mesh::null_face());
  }
  CHECK(CGAL::is_valid_polygon_mesh(out));
  return site_area;
}

// stitches squared distances to `sites` and checks it; each point of `single` must be one vertex
std::vector<double> st_case(const St_mesh& m, const std::vector<St_point>& sites, const std::vector<St_point>& single = {})
{
  const std::unique_ptr<St_run> r = st_run(m, sites);
  const std::vector<double> area = st_check(*r);
  for(const St_point& x : single) CHECK(st_near(*r, x, 1e-12) == 1);
  return area;
}

void st_expect_areas(const std::vector<double>& area, const std::vector<double>& expected)
{
  REQUIRE(area.size() == expected.size());
  for(std::size_t s = 0; s < area.size(); ++s) CHECK(area[s] == Approx(expected[s]).epsilon(1e-12).margin(1e-12));
}

} // namespace

TEST_CASE("stitch: generic sites on two triangles, a fan and a curved grid", "[stitcher]")
{
  st_case(st_square(8), { { 1, 2, 0 }, { 6.3, 1.1, 0 }, { 3.7, 6.2, 0 }, { 7.1, 7.4, 0 } });
  st_case(st_fan(), { { 1, 1, 0 }, { -3, 2.5, 0 }, { -1, -4, 0 }, { 5, -2, 0.5 } });
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(-0.5, 6.5);
  for(int n = 0; n < 8; ++n)
  {
    std::vector<St_point> sites;
    for(int k = 0; k < 9; ++k) sites.push_back({{ u(rng), u(rng), 0.3 * u(rng) }});
    const auto r = st_run(st_grid(6, [](int i, int j) { return 0.4 * std::sin(0.9 * i) * std::cos(0.7 * j); }), sites);
    INFO("random configuration " << n);
    st_check(*r);
    CHECK(r->part.pieces.size() > r->mesh.number_of_faces());
  }
}

TEST_CASE("stitch: a Voronoi vertex exactly on a mesh edge", "[stitcher]")
{
  // three sites at distance 5 from (4, 4), on the diagonal of the square
  st_case(st_square(8), { { 7, 8, 0 }, { 0, 7, 0 }, { 4, -1, 0 } }, { { 4, 4, 0 } });
  // at points that are not doubles: (19/6, 19/6), (29/6, 29/6)
  st_case(st_square(8), { { 4, -1, 0 }, { 0, 6, 0 }, { 5, 7, 0 } }, { { 19. / 6, 19. / 6, 0 } });
  st_case(st_square(8), { { 1, 3, 0 }, { 8, 2, 0 }, { 4, 9, 0 } }, { { 29. / 6, 29. / 6, 0 } });
  // on the border edge y = 0, at (4, 0)
  st_case(st_square(8), { { 4, 5, 0 }, { 0, -3, 0 }, { 8, -3, 0 } }, { { 4, 0, 0 } });
}

TEST_CASE("stitch: a tie on an edge that double arithmetic places differently per site pair", "[stitcher]")
{
  // Fields x_s at (0,0) and -2 x_s at (8,8): along the diagonal every pair of sites crosses at
  // t = 1/3 exactly, but t = dx / (dx - dy) rounds differently for each pair, since the
  // differences dx of values of unrelated magnitudes are rounded. The stitch must still make
  // one vertex of it. The other two corners get arbitrary values.
  const double x[4] = { 0.1, 1234.567, -7.3e-3, 3.0e5 / 7 };
  const double at1[4] = { 5, -100, 40, 3 }, at3[4] = { -2, 7, 1000, -50 };
  std::vector<std::vector<double> > field;
  for(int s = 0; s < 4; ++s) field.push_back({ x[s], at1[s], -2 * x[s], at3[s] });
  auto r = st_run_fields(st_square(8), field);
  st_check(*r);
  CHECK(st_near(*r, {{ 8. / 3, 8. / 3, 0 }}, 1e-9) == 1);
  // three of them, with the corners swapped between the faces
  field.pop_back();
  std::swap(field[0][1], field[0][3]);
  r = st_run_fields(st_square(8), field);
  st_check(*r);
  CHECK(st_near(*r, {{ 8. / 3, 8. / 3, 0 }}, 1e-9) == 1);
}

TEST_CASE("stitch: a Voronoi vertex exactly on a mesh vertex", "[stitcher]")
{
  // three sites at distance 5 from the fan's centre, and from a corner of the square
  for(double a : st_case(st_fan(), { { 3, 4, 0 }, { -4, 3, 0 }, { 0, -5, 0 } }, { { 0, 0, 0 } })) CHECK(a > 0);
  for(double a : st_case(st_square(8), { { 8, 5, 0 }, { 5, 4, 0 }, { 4, -3, 0 } }, { { 8, 0, 0 } })) CHECK(a > 0);
}

TEST_CASE("stitch: four cocircular sites meeting at one point", "[stitcher]")
{
  // inside the upper face at (2, 5), the bisectors being x = 2 and y = 5; on the diagonal at (4, 4)
  st_expect_areas(st_case(st_square(8), { { 5, 9, 0 }, { -1, 9, 0 }, { -1, 1, 0 }, { 5, 1, 0 } }, { { 2, 5, 0 } }),
                  { 18, 6, 10, 30 });
  st_expect_areas(st_case(st_square(8), { { 7, 8, 0 }, { 1, 8, 0 }, { 1, 0, 0 }, { 7, 0, 0 } }, { { 4, 4, 0 } }),
                  { 16, 16, 16, 16 });
  // on the diagonal at (95/26, 95/26), and inside the upper face at (31/7, 40/7): not doubles
  st_case(st_square(8), { { 8, 6, 0 }, { -1, 2, 0 }, { 2, -1, 0 }, { 6, 8, 0 } }, { { 95. / 26, 95. / 26, 0 } });
  st_case(st_square(8), { { 5, 1, 0 }, { 1, 9, 0 }, { 0, 4, 0 }, { 9, 7, 0 } }, { { 31. / 7, 40. / 7, 0 } });
  // at the fan's centre
  st_case(st_fan(), { { 3, 4, 0 }, { -3, 4, 0 }, { -3, -4, 0 }, { 3, -4, 0 } }, { { 0, 0, 0 } });
}

TEST_CASE("stitch: a bisector running exactly along a mesh edge", "[stitcher]")
{
  // sites symmetric about the diagonal: each owns one face
  st_expect_areas(st_case(st_square(8), { { 6, 2, 0 }, { 2, 6, 0 } }), { 32, 32 });
  // a third site cuts the diagonal where both bisectors with it meet it, at (6.1, 6.1) and at
  // (29/6, 29/6): the two faces name that point with different site pairs
  std::vector<double> area = st_case(st_square(8), { { 6, 2, 0 }, { 2, 6, 0 }, { 9, 9, 0 } });
  CHECK(area[0] == Approx(area[1]).epsilon(1e-12));
  st_case(st_square(8), { { 6, 2, 0 }, { 2, 6, 0 }, { 7, 7, 0 } }, { { 29. / 6, 29. / 6, 0 } });
  // along a border edge: the site below gets nothing
  CHECK(st_case(st_square(8), { { 4, 3, 0 }, { 4, -3, 0 }, { 9, 1, 0 } })[1] == 0);
}

TEST_CASE("stitch: a lattice of sites whose bisectors run along grid lines", "[stitcher]")
{
  std::vector<St_point> sites;
  for(int j = 0; j <= 6; j += 2)
    for(int i = 0; i <= 6; i += 2) sites.push_back({{ double(i), double(j), 0 }});
  const auto flat = [](int, int) { return 0.; };
  const auto r = st_run(st_grid(6, flat), sites);
  const std::vector<double> area = st_check(*r);
  CHECK(r->part.pieces.size() == r->mesh.number_of_faces());   // every face inside one cell
  // cells: [0, 1], [1, 3], [3, 5], [5, 6] in each direction
  const double extent[4] = { 1, 2, 2, 1 };
  for(std::size_t s = 0; s < sites.size(); ++s) CHECK(area[s] == Approx(extent[s % 4] * extent[s / 4]).epsilon(1e-12));
  // shifted by half a cell: bisectors through the middle of cells, four sites meeting on
  // cell diagonals at (1.5, 1.5), ...
  for(St_point& s : sites) { s[0] += 0.5; s[1] += 0.5; }
  const std::vector<double> shifted = st_case(st_grid(6, flat), sites, { { 1.5, 1.5, 0 }, { 3.5, 5.5, 0 } });
  const double shifted_extent[4] = { 1.5, 2, 2, 0.5 };
  for(std::size_t s = 0; s < sites.size(); ++s)
    CHECK(shifted[s] == Approx(shifted_extent[s % 4] * shifted_extent[s / 4]).epsilon(1e-12));
}

TEST_CASE("stitch: a triple point on a needle, where two sites' fields differ by 1e-20", "[stitcher][numerics]")
{
  // Found by fuzz_pipeline: a face 2^-32 wide, two sites 1e-10 apart on its short edge and a
  // third far away. In doubles d0 - d1 and d0 - d2 round to the same vector, so the cross
  // product that places the triple point was 0 and its coordinates NaN (NaN cell areas). The
  // triple point is (7/32, 1/8, 21/32) in barycentric coordinates, exactly.
  const double w = std::ldexp(1., -32);
  const St_mesh m = st_make({ { 0, 0, -1 }, { 0, 0, 0 }, { 0, w, -1 } }, { { 0, 1, 2 } });
  const double tiny = std::ldexp(1., -66);
  const std::vector<std::vector<double> > field = { { 0.0625, 0.5625, 0.0625 }, { tiny, 1, tiny }, { 4 * tiny, 1, 0 } };
  const auto r = st_run_fields(m, field);
  std::size_t triple_points = 0;
  double area = 0;
  std::set<std::size_t> owners;
  for(const SVI::Partition::Piece& p : r->part.pieces)
  {
    St_vector newell(0, 0, 0);
    for(std::size_t k = 0; k < p.vertices.size(); ++k)
    {
      const SVI::Point_d& u = r->part.vertices[p.vertices[k]].point;
      for(int c = 0; c < 3; ++c) REQUIRE(std::isfinite(u[c]));
      newell = newell + CGAL::cross_product(st_vec(u), st_vec(r->part.vertices[p.vertices[(k + 1) % p.vertices.size()]].point));
    }
    area += 0.5 * std::sqrt(newell.squared_length());
    owners.insert(p.site);
  }
  for(const SVI::Partition::Vertex& v : r->part.vertices)
    if(v.kind == SVI::Partition::IN_FACE)
    {
      ++triple_points;
      CHECK(v.point.x() == 0);
      CHECK(v.point.y() == Approx(21. / 32 * w).epsilon(1e-12));
      CHECK(v.point.z() == Approx(-0.875).epsilon(1e-15));
    }
  CHECK(triple_points == 1);
  CHECK(owners.size() == 3);
  CHECK(area == Approx(r->mesh.total_area).epsilon(1e-9));
}

// An oracle for the connectivity check, independent of its views: the pieces of a site are
// joined where one has the piece edge (u, w) and the other (w, u), except across a blocked
// mesh edge; its regions, and the pieces outside the region of the site's location (or, for a
// site without a piece there, outside its largest region), as (site, face) pairs.
struct Oracle_regions
{
  std::vector<std::size_t> regions_of_site;
  std::set<std::pair<std::size_t, std::size_t> > orphans;
};

template <class Blocked>
Oracle_regions oracle_regions(const St_indexed& mesh, const SVI::Partition& part, const std::vector<SVI::Site>& sites,
                              const Blocked& blocked)
{
  const std::size_t np = part.pieces.size();
  std::vector<std::size_t> parent(np);
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  std::function<std::size_t(std::size_t)> root = [&](std::size_t x) { return parent[x] == x ? x : parent[x] = root(parent[x]); };
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::size_t> owner_of_edge;
  for(std::size_t p = 0; p < np; ++p)
  {
    const auto& v = part.pieces[p].vertices;
    for(std::size_t j = 0; j < v.size(); ++j) owner_of_edge[std::make_pair(v[j], v[(j + 1) % v.size()])] = p;
  }
  for(std::size_t p = 0; p < np; ++p)
  {
    const auto& v = part.pieces[p].vertices;
    for(std::size_t j = 0; j < v.size(); ++j)
    {
      const auto it = owner_of_edge.find(std::make_pair(v[(j + 1) % v.size()], v[j]));
      if(it == owner_of_edge.end()) continue;
      const std::size_t q = it->second, f = part.pieces[p].face, g = part.pieces[q].face;
      if(part.pieces[p].site != part.pieces[q].site || part.pieces[p].site == SVI::no_site) continue;
      bool across_blocked = false;
      for(int k = 0; k < 3; ++k)
        across_blocked |= (f != g && mesh.neighbors[f][k] == g && blocked(mesh.edges[f][k]));
      if(!across_blocked) parent[root(p)] = root(q);
    }
  }
  Oracle_regions out;
  out.regions_of_site.assign(sites.size(), 0);
  std::vector<std::set<std::size_t> > roots(sites.size());
  std::map<std::size_t, double> area;
  for(std::size_t p = 0; p < np; ++p)
    if(part.pieces[p].site != SVI::no_site)
    {
      roots[part.pieces[p].site].insert(root(p));
      area[root(p)] += part.pieces[p].area;
    }
  for(std::size_t i = 0; i < sites.size(); ++i)
  {
    out.regions_of_site[i] = roots[i].size();
    if(roots[i].size() <= 1) continue;
    const std::size_t own = part.piece_of(sites[i].face, i);
    std::size_t kept = (own != SVI::no_site) ? root(own) : *roots[i].begin();
    if(own == SVI::no_site)
      for(std::size_t r : roots[i])
        if(area[r] > area[kept]) kept = r;
    for(std::size_t p = 0; p < np; ++p)
      if(part.pieces[p].site == i && root(p) != kept) out.orphans.insert(std::make_pair(i, std::size_t(part.pieces[p].face)));
  }
  return out;
}

// The connectivity check (Cell_connectivity.h: broken cells, orphan pieces, regions per site),
// on the cuts and on the stitched partition, against the oracle: random candidate subsets per
// face make cells in many pieces, and neighbouring faces that disagree along their edge (a
// site winning different stretches of it on each side), as the repair's bans do.
TEST_CASE("cell check: on the cuts and on the partition, the oracle's broken cells and orphans", "[stitcher][repair]")
{
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> u(-0.5, 10.5);
  int decided = 0, with_broken = 0, outside = 0;
  for(int trial = 0; trial < 40; ++trial)
  {
    INFO("trial " << trial);
    const St_mesh m = st_grid(10, [](int i, int j) { return 0.5 * std::sin(0.8 * i) * std::cos(0.6 * j); });
    std::vector<St_point> sites;
    for(int k = 0; k < 12; ++k) sites.push_back({{ u(rng), u(rng), 0.2 * u(rng) }});
    St_run r;
    r.surface = m;
    r.mesh.build(r.surface, get(CGAL::vertex_point, r.surface));
    for(const St_point& s : sites)
    {
      std::vector<double> f;
      for(St_mesh::Vertex_index v : vertices(r.surface))
      {
        const St_kernel::Point_3& p = r.surface.point(v);
        f.push_back(CGAL::square(p.x() - s[0]) + CGAL::square(p.y() - s[1]) + CGAL::square(p.z() - s[2]));
      }
      r.field.push_back(f);
    }
    // each face keeps each site with probability 1/3 (at least one), some faces none
    std::bernoulli_distribution keep(1. / 3), unreached(0.02);
    r.candidates.assign(r.mesh.number_of_faces(), {});
    r.cuts.reset(r.mesh.number_of_faces());
    for(std::size_t f = 0; f < r.mesh.number_of_faces(); ++f)
    {
      if(unreached(rng)) continue;
      const auto& t = r.mesh.triangles[f];
      for(std::size_t s = 0; s < sites.size(); ++s)
        if(keep(rng) || (s + 1 == sites.size() && r.candidates[f].empty()))
          r.candidates[f].push_back({ std::uint32_t(s), {{ r.field[s][t[0]], r.field[s][t[1]], r.field[s][t[2]] }} });
      SVI::clean_candidate_list(r.candidates[f]);
      if(r.candidates[f].size() == 1)
      {
        SVI::Face_cut whole;
        whole.whole_face = true;
        r.cuts.set(f, whole);
      }
      else
        r.cuts.set(f, SVI::Face_cutter(r.candidates[f]).cut());
    }
    SVI::stitch(r.mesh, SVI::Candidate_table(SVI::Candidate_lists(r.candidates)), r.cuts, r.part);   // packed, as the builder does
    // each site located in a face holding a piece of it (the last such face), odd trials
    // with a site outside its cell (located in a face without a piece of it, as weights do)
    std::vector<SVI::Site> located(sites.size());
    for(const SVI::Partition::Piece& p : r.part.pieces)
      if(p.site != SVI::no_site) located[p.site].face = p.face;
    if(trial % 2 == 1)
      for(std::size_t f = 0; f < r.mesh.number_of_faces(); ++f)
        if(r.part.piece_of(f, 0) == SVI::no_site) located[0].face = f;
    auto blocked = [](std::size_t e) { return e % 29 == 0; };   // a few breaklines
    const std::vector<std::pair<std::size_t, std::size_t> > no_breakline_sites;
    const Oracle_regions oracle = oracle_regions(r.mesh, r.part, located, blocked);
    auto orphan_set = [](const SVI::Cell_connectivity& c) {
      CHECK(std::is_sorted(c.orphans.begin(), c.orphans.end(), [](const auto& x, const auto& y) { return x.second < y.second; }));
      return std::set<std::pair<std::size_t, std::size_t> >(c.orphans.begin(), c.orphans.end());
    };
    std::size_t oracle_broken = 0;
    for(std::size_t n : oracle.regions_of_site) oracle_broken += (n > 1);

    // the stitched partition always decides
    SVI::Cell_connectivity on_partition(located, no_breakline_sites);
    REQUIRE(on_partition.check(SVI::Stitched_pieces<St_mesh, decltype(blocked)>(r.mesh, r.part, blocked), nullptr, trial % 4 == 0));
    CHECK(on_partition.regions_of_site == oracle.regions_of_site);
    CHECK(on_partition.broken == oracle_broken);
    CHECK(orphan_set(on_partition) == oracle.orphans);
    outside += (trial % 2 == 1 && oracle.regions_of_site[0] > 1);

    // the cuts, where they decide (no exact tie, no broken cell outside its site's location)
    // and stitching welded and dropped nothing
    SVI::Cell_connectivity on_cuts(located, no_breakline_sites);
    const SVI::Candidate_table table{ SVI::Candidate_lists(r.candidates) };
    const SVI::Cut_pieces<St_mesh, decltype(blocked)> cut_pieces(r.mesh, table, r.cuts, blocked);
    if(cut_pieces.has_tie(nullptr) || !on_cuts.check(cut_pieces, nullptr, trial % 4 == 0)) continue;
    if(r.part.welded_vertices != 0 || r.part.dropped_pieces != 0) continue;
    ++decided;
    CHECK(on_cuts.regions_of_site == oracle.regions_of_site);
    CHECK(on_cuts.broken == oracle_broken);
    CHECK(orphan_set(on_cuts) == oracle.orphans);
    with_broken += (on_cuts.broken > 0);
  }
  // the trials must exercise the check: most decide on the cuts, and most of those have
  // broken cells; some sites outside their cell are broken
  CHECK(decided >= 15);
  CHECK(with_broken >= 15);
  CHECK(outside >= 10);
}

namespace {

// Euclidean fields of a few sites at face centroids of a steeply folded grid: they reach
// across the folds and leave cells in several pieces.
struct Folded_grid_fields
{
  static constexpr bool concurrent_values = true;   // so that the propagation may run in blocks
  const std::vector<std::vector<double> >* field;
  double value(std::size_t site, std::size_t v) const { return (*field)[site][v]; }
};

void folded_grid_sites(double amplitude, std::size_t number_of_sites, std::mt19937& rng, St_run& r,
                       std::vector<SVI::Site>& located, std::vector<std::size_t>& site_faces)
{
  r.surface = st_grid(14, [&](int i, int j) { return amplitude * std::sin(1.3 * i) * std::cos(0.4 * j); });
  r.mesh.build(r.surface, get(CGAL::vertex_point, r.surface));
  std::uniform_int_distribution<std::size_t> any_face(0, r.mesh.number_of_faces() - 1);
  located.assign(number_of_sites, SVI::Site());
  site_faces.clear();
  for(std::size_t s = 0; s < located.size(); ++s)
  {
    located[s].face = any_face(rng);
    site_faces.push_back(located[s].face);
    const auto& t = r.mesh.triangles[located[s].face];
    std::array<double, 3> c = {{ 0., 0., 0. }};
    for(int k = 0; k < 3; ++k)
      for(int j = 0; j < 3; ++j) c[j] += r.mesh.points[t[k]][j] / 3.;
    std::vector<double> f;
    for(const auto& p : r.mesh.points) f.push_back(CGAL::square(p[0] - c[0]) + CGAL::square(p[1] - c[1]) + CGAL::square(p[2] - c[2]));
    r.field.push_back(f);
  }
}

// as the diagram cuts them: a face with one candidate whole, without a piece
void cut_listed_faces(const SVI::Candidate_table& candidates, const std::vector<std::size_t>& faces, SVI::Face_cuts& cuts)
{
  cuts.cut(candidates, faces.size(), [&faces](std::size_t k) { return faces[k]; }, false);
}

bool folded_grid_blocked_edge(std::size_t e) { return e % 37 == 0; }

typedef SVI::Cut_pieces<St_mesh, bool (*)(std::size_t)> Folded_grid_cut_pieces;

// The connectivity check on the cuts of every site (`which` null) or of the sites `which`
// marks; false where the cuts do not decide.
bool check_folded_grid_cuts(const St_run& r, const SVI::Candidate_table& candidates, SVI::Cell_connectivity& cells,
                            const std::vector<std::uint8_t>* which = nullptr)
{
  const Folded_grid_cut_pieces pieces(r.mesh, candidates, r.cuts, &folded_grid_blocked_edge);
  return !pieces.has_tie(nullptr) && cells.check(pieces, which, false);
}

// A real propagation over a folded grid (folded_grid_sites()), and the cuts of all its faces.
// Not copied: the propagation holds references to the members.
struct Folded_grid_propagation
{
  typedef std::function<bool(std::size_t, int)> Blocked;
  St_run r;
  std::vector<SVI::Site> located;
  std::vector<std::size_t> site_faces;
  std::vector<std::pair<std::size_t, std::size_t> > breakline_site_faces;   // none: no site on the fold
  Folded_grid_fields fields{ nullptr };
  std::unique_ptr<SVI::Propagation<St_mesh, Folded_grid_fields, Blocked> > propagation;
  SVI::Candidate_table table;   // the propagation's candidates, packed as the diagram packs them

  /// `faces_per_block`: if not 0, the first propagation runs in blocks of that many faces
  Folded_grid_propagation(double amplitude, std::size_t number_of_sites, std::mt19937& rng, std::size_t faces_per_block = 0)
  {
    folded_grid_sites(amplitude, number_of_sites, rng, r, located, site_faces);
    fields.field = &r.field;
    const St_indexed* mesh = &r.mesh;
    propagation.reset(new SVI::Propagation<St_mesh, Folded_grid_fields, Blocked>(r.mesh, fields, site_faces, breakline_site_faces,
        Blocked([mesh](std::size_t f, int k) { return folded_grid_blocked_edge(mesh->edges[f][k]); })));
    if(faces_per_block > 0) propagation->set_block_sizes(faces_per_block, 1);
    propagation->run();
    std::vector<std::size_t> all_faces(r.mesh.number_of_faces());
    std::iota(all_faces.begin(), all_faces.end(), std::size_t(0));
    r.cuts.reset(all_faces.size());
    table = SVI::Candidate_table(std::move(propagation->candidates));
    cut_listed_faces(table, all_faces, r.cuts);
  }
  Folded_grid_propagation(const Folded_grid_propagation&) = delete;
  Folded_grid_propagation& operator=(const Folded_grid_propagation&) = delete;
};

} // namespace

// The first round's check (Cut_pieces::find_suspects(): the propagation's links back to the
// sites, and a whole search of the suspects' pieces only) against the check of every site on
// the cuts, its oracle, on real propagations over a steeply folded grid: where it decides, the
// same broken cells, regions per site and orphans, in the same order.
TEST_CASE("cell check: the first round, from the propagation's links, finds what the full check finds", "[stitcher][repair]")
{
  // in one global order, and in blocks of 24 faces (the links then cross blocks, and fields
  // admitted before a dominating one arrived from another block break more of them)
  for(std::size_t faces_per_block : { std::size_t(0), std::size_t(24) })
  {
    INFO("faces per block: " << faces_per_block);
    std::mt19937 rng(5);
    int decided = 0, with_broken = 0, in_blocks = 0, searched_fewer = 0;
    for(int trial = 0; trial < 40; ++trial)
    {
      INFO("trial " << trial);
      Folded_grid_propagation grid(1.5 + 0.1 * trial, 6 + trial % 10, rng, faces_per_block);
      St_run& r = grid.r;
      const std::vector<SVI::Site>& located = grid.located;
      auto& propagation = *grid.propagation;
      in_blocks += (propagation.statistics.blocks > 1 && propagation.statistics.rounds > 1);

      SVI::Cell_connectivity full(located, grid.breakline_site_faces), quick(located, grid.breakline_site_faces);
      if(!check_folded_grid_cuts(r, grid.table, full)) continue;   // an exact tie
      const Folded_grid_cut_pieces pieces(r.mesh, grid.table, r.cuts, &folded_grid_blocked_edge);
      for(std::size_t i = 0; i < located.size(); ++i) quick.regions_of_site[i] = (pieces.piece_of(located[i].face, i) != SVI::no_site);
      std::vector<std::uint8_t> suspect(located.size(), 0);
      REQUIRE(pieces.find_suspects(suspect, trial % 2 == 0));
      if(!quick.check(pieces, &suspect, false)) continue;
      ++decided;
      searched_fewer += (std::count(suspect.begin(), suspect.end(), 1) < std::ptrdiff_t(located.size()));
      CHECK(quick.broken == full.broken);
      CHECK(quick.regions_of_site == full.regions_of_site);
      CHECK(quick.orphans == full.orphans);
      with_broken += (full.broken > 0);
    }
    // the trials must exercise it: most decide, many of those have broken cells, and the
    // links spare some sites the search
    CHECK(decided >= 30);
    CHECK(with_broken >= 10);
    CHECK(searched_fewer >= 20);
    CHECK(in_blocks == (faces_per_block > 0 ? 40 : 0));
  }
}

// The later rounds' check (only the sites on the faces a repair round touched, before or
// after, searched whole; the others keep their count) against the check of every site,
// round after round of the repair, on the same folded grids.
TEST_CASE("cell check: a later round, on the sites the repair changed, finds what the full check finds", "[stitcher][repair]")
{
  std::mt19937 rng(11);
  int rounds_compared = 0, with_broken = 0, partial = 0;
  for(int trial = 0; trial < 120; ++trial)
  {
    INFO("trial " << trial);
    // odd trials propagate in blocks: the repair then starts from offers rebuilt from the lists
    Folded_grid_propagation grid(1.5 + 0.03 * trial, 8 + trial % 25, rng, trial % 2 ? 24 : 0);
    St_run& r = grid.r;
    const std::vector<SVI::Site>& located = grid.located;
    auto& propagation = *grid.propagation;

    SVI::Cell_connectivity local(located, grid.breakline_site_faces);
    SVI::Banned_fields banned(r.mesh.number_of_faces());
    auto is_banned = [&](std::size_t site, std::size_t f) { return banned.contains(site, f); };
    if(!check_folded_grid_cuts(r, grid.table, local)) continue;
    for(int round = 1; round <= 6 && local.broken > 0; ++round)
    {
      INFO("round " << round);
      std::vector<std::size_t> dirty, touched;
      for(const auto& x : local.orphans)
      {
        banned.insert(x.first, x.second);
        if(dirty.empty() || dirty.back() != x.second) dirty.push_back(x.second);
      }
      std::vector<std::uint32_t> sites_before;
      propagation.repropagate(grid.table, dirty, is_banned, touched, &sites_before);
      cut_listed_faces(grid.table, touched, r.cuts);
      std::vector<std::uint8_t> affected(located.size(), 0);
      for(std::uint32_t s : sites_before) affected[s] = 1;
      for(std::size_t f : touched)
        for(const SVI::Candidate& x : grid.table[f]) affected[x.site] = 1;
      partial += (std::count(affected.begin(), affected.end(), 1) < std::ptrdiff_t(located.size()));

      SVI::Cell_connectivity full(located, grid.breakline_site_faces);
      if(!check_folded_grid_cuts(r, grid.table, full)) break;
      if(!check_folded_grid_cuts(r, grid.table, local, &affected)) break;
      ++rounds_compared;
      with_broken += (full.broken > 0);
      CHECK(local.broken == full.broken);
      CHECK(local.regions_of_site == full.regions_of_site);
      CHECK(local.orphans == full.orphans);
    }
  }
  // the repair must run: many rounds compared, some still broken after a round, and the
  // rounds must leave some sites out of the search
  CHECK(rounds_compared >= 40);
  CHECK(with_broken >= 2);
  CHECK(partial >= 40);
}

// The diagram frees the propagation's faces' links after the first propagation, and a repair
// makes those of the faces it reaches: it must admit exactly the fields it admits with the
// links kept, round after round, on the folded grids.
TEST_CASE("propagation: a repair after the working state was freed admits what the kept state admits", "[stitcher][repair]")
{
  int rounds_compared = 0, rounds_admitting = 0;
  for(int trial = 0; trial < 80; ++trial)
  {
    INFO("trial " << trial);
    std::mt19937 rng_kept(100 + trial), rng_freed(100 + trial);
    Folded_grid_propagation kept(1.5 + 0.05 * trial, 8 + trial % 20, rng_kept);
    Folded_grid_propagation freed(1.5 + 0.05 * trial, 8 + trial % 20, rng_freed);
    St_run& r = kept.r;
    SVI::Cell_connectivity cells(kept.located, kept.breakline_site_faces);
    SVI::Banned_fields banned(r.mesh.number_of_faces());
    auto is_banned = [&](std::size_t site, std::size_t f) { return banned.contains(site, f); };
    if(!check_folded_grid_cuts(r, kept.table, cells)) continue;
    for(int round = 1; round <= 6 && cells.broken > 0; ++round)
    {
      INFO("round " << round);
      std::vector<std::size_t> dirty, touched_kept, touched_freed;
      for(const auto& x : cells.orphans)
      {
        banned.insert(x.first, x.second);
        if(dirty.empty() || dirty.back() != x.second) dirty.push_back(x.second);
      }
      const std::size_t admitted_before = kept.propagation->statistics.admitted;
      kept.propagation->repropagate(kept.table, dirty, is_banned, touched_kept);
      freed.propagation->release_working_state();
      freed.propagation->repropagate(freed.table, dirty, is_banned, touched_freed);
      ++rounds_compared;
      CHECK(touched_freed == touched_kept);
      bool same = true;
      for(std::size_t f = 0; f < r.mesh.number_of_faces(); ++f)
      {
        const SVI::Candidate_range a = kept.table[f], b = freed.table[f];
        same = same && a.size() == b.size();
        for(std::size_t j = 0; same && j < a.size(); ++j)
          same = a[j].site == b[j].site && a[j].from_edge == b[j].from_edge && a[j].value == b[j].value;
      }
      CHECK(same);
      CHECK(freed.propagation->statistics.admitted == kept.propagation->statistics.admitted);
      rounds_admitting += (kept.propagation->statistics.admitted > admitted_before);
      cut_listed_faces(kept.table, touched_kept, r.cuts);
      if(!check_folded_grid_cuts(r, kept.table, cells)) break;
    }
  }
  // the repairs must run, and admit fields again (the offers rebuilt decide those)
  CHECK(rounds_compared >= 40);
  CHECK(rounds_admitting >= 20);
}

// A partition has about as many vertices, and more pieces, than the mesh has faces: a vertex
// is 40 bytes, a piece's site index 32 bits that still read as the library's `no_site`.
TEST_CASE("stitcher: partition vertices are 40 bytes, a piece's site index keeps no_site", "[stitcher]")
{
  static_assert(sizeof(SVI::Partition::Vertex) == 40, "a vertex: point, parameter, 32-bit element, kind");
  for(std::size_t site : { std::size_t(0), std::size_t(1), std::size_t(0xfffffffeu), SVI::no_site })
  {
    const SVI::Site_index_32 stored(site);
    CHECK(std::size_t(stored) == site);
  }
  SVI::Partition::Piece p{ 7, SVI::no_site, {}, 0. };
  CHECK(p.site == SVI::no_site);
  p.site = 12;
  CHECK(p.site == 12u);
  CHECK(p.site != SVI::no_site);
}

TEST_CASE("stitcher: the packed candidate table reads back every list, also after lists are replaced", "[stitcher]")
{
  std::mt19937 rng(5);
  for(bool parallel : { false, true })
  {
    // empty lists, inline ones, and lists on the heap, over more faces than a parallel chunk
    SVI::Candidate_lists lists(10000, SVI::Candidate_list());
    for(std::size_t f = 0; f < lists.size(); ++f)
      for(std::size_t k = 0, n = std::size_t(rng() % 6); k < n; ++k)
        lists[f].push_back(SVI::Candidate(std::uint32_t(rng() % 1000), {{ double(rng()), double(f), double(k) }},
                                          std::uint8_t(rng() % 4)));
    const SVI::Candidate_lists original = lists;
    const SVI::Candidate_table table(std::move(lists), parallel);
    CHECK(lists.empty());
    REQUIRE(table.size() == original.size());
    std::size_t total = 0;
    auto same = [](const SVI::Candidate& a, const SVI::Candidate& b) {
      return a.site == b.site && a.from_edge == b.from_edge && a.value == b.value;
    };
    for(std::size_t f = 0; f < original.size(); ++f)
    {
      const SVI::Candidate_table::List l = table[f];
      REQUIRE(l.size() == original[f].size());
      CHECK(l.empty() == original[f].empty());
      for(std::size_t k = 0; k < l.size(); ++k) CHECK(same(l[k], original[f][k]));
      for(std::size_t k = 0; k < l.size(); ++k)
      {
        // the values of a site's first candidate in the list
        const double* v = SVI::values_of(l, l[k].site);
        REQUIRE(v != nullptr);
        CHECK(*v == *SVI::values_of(original[f], l[k].site));
      }
      CHECK(SVI::values_of(l, 1000u) == nullptr);
      total += l.size();
    }
    CHECK(table.number_of_candidates() == total);
    // lists replaced, longer (at the end), shorter (in place) or emptied, until the table packs
    // itself again: every face reads its last list
    SVI::Candidate_table replaced(table);
    SVI::Candidate_lists want = original;
    for(int k = 0; k < 30000; ++k)
    {
      const std::size_t f = rng() % want.size();
      SVI::Candidate_list list;
      for(std::size_t j = 0, n = std::size_t(rng() % 7); j < n; ++j)
        list.push_back(SVI::Candidate(std::uint32_t(rng() % 1000), {{ double(k), double(f), double(j) }}));
      replaced.replace(f, list);
      want[f] = list;
    }
    std::size_t replaced_total = 0;
    for(std::size_t f = 0; f < want.size(); ++f)
    {
      REQUIRE(replaced[f].size() == want[f].size());
      for(std::size_t k = 0; k < want[f].size(); ++k) CHECK(same(replaced[f][k], want[f][k]));
      replaced_total += want[f].size();
    }
    CHECK(replaced.number_of_candidates() == replaced_total);
    // copies hold the same candidates, apart from the original
    SVI::Candidate_table assigned;
    assigned = table;
    const SVI::Candidate_table copied(assigned);
    SVI::Candidate_table moved(std::move(assigned));
    for(const SVI::Candidate_table* t : std::initializer_list<const SVI::Candidate_table*>{ &copied, &moved })
    {
      REQUIRE(t->size() == table.size());
      CHECK(t->number_of_candidates() == total);
      for(std::size_t f = 0; f < original.size(); ++f)
      {
        REQUIRE((*t)[f].size() == original[f].size());
        if(!original[f].empty()) CHECK((*t)[f].begin() != table[f].begin());
        for(std::size_t k = 0; k < original[f].size(); ++k) CHECK(same((*t)[f][k], original[f][k]));
      }
    }
    moved.clear();
    CHECK(moved.size() == 0);
    CHECK(moved.number_of_candidates() == 0);
    CHECK(copied.number_of_candidates() == total);
  }
  const SVI::Candidate_table none;
  CHECK(none.size() == 0);
  const SVI::Candidate_table none_copied(none);
  CHECK(none_copied.size() == 0);
  CHECK(none_copied.number_of_candidates() == 0);
}

} // namespace svd_test_stitcher
