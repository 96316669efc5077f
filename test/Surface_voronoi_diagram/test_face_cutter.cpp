// Direct tests of Face_cutter (CGAL/Surface_voronoi_diagram/internal/cutting.h) on hand-built
// candidate lists. Every symbolic piece vertex is evaluated here with exact rationals, so the
// checks are exact: the pieces are convex, their areas sum to the triangle's, every point
// sampled inside a piece has the piece's site as its lowest (value, site) pair, and every
// point of the triangle lies in the piece of its lowest pair.
#include <catch2/catch.hpp>

#include <CGAL/Surface_voronoi_diagram/internal/Face_cutter.h>
#include <CGAL/Surface_voronoi_diagram/internal/Face_cuts.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <random>
#include <set>
#include <sstream>
#include <utility>
#include <vector>

// this file's own names: the suite compiles its files together (see CMakeLists.txt)
namespace svd_test_face_cutter {

namespace {

namespace SVI = CGAL::Surface_voronoi::internal;
typedef CGAL::Exact_rational Fc_q;
typedef std::array<Fc_q, 3> Fc_bary;   // barycentric coordinates in the face
typedef SVI::Candidate_list Fc_list;

// The test triangle (0,0), (8,0), (0,8), counter-clockwise; fields are squared distances
// to integer sites, so every value is an exact integer.
const double fc_corner[3][2] = { { 0, 0 }, { 8, 0 }, { 0, 8 } };

Fc_list fc_fields(const std::vector<std::array<double, 2> >& sites, const std::vector<std::uint32_t>& ids = {})
{
  Fc_list list(sites.size());
  for(std::size_t i = 0; i < sites.size(); ++i)
  {
    list[i].site = ids.empty() ? std::uint32_t(i) : ids[i];
    for(int k = 0; k < 3; ++k)
      list[i].value[k] = CGAL::square(fc_corner[k][0] - sites[i][0]) + CGAL::square(fc_corner[k][1] - sites[i][1]);
  }
  return list;
}

Fc_q fc_value(const SVI::Candidate& f, const Fc_bary& b)
{
  return b[0] * Fc_q(f.value[0]) + b[1] * Fc_q(f.value[1]) + b[2] * Fc_q(f.value[2]);
}

// where a symbolic vertex of the piece of candidate `owner` is, solved here from the values
Fc_bary fc_position(const Fc_list& c, std::uint32_t owner, const SVI::Symbolic_vertex& v)
{
  Fc_bary b = {{ Fc_q(0), Fc_q(0), Fc_q(0) }};
  if(v.kind == SVI::Symbolic_vertex::CORNER) b[v.local] = 1;
  if(v.kind == SVI::Symbolic_vertex::CORNER) return b;
  if(v.kind == SVI::Symbolic_vertex::EDGE)
  {
    // (1-t) h(k0) + t h(k1) = 0 with h = D_owner - D_other
    const int k0 = v.local, k1 = (v.local + 1) % 3;
    const Fc_q h0 = Fc_q(c[owner].value[k0]) - Fc_q(c[v.other].value[k0]);
    const Fc_q h1 = Fc_q(c[owner].value[k1]) - Fc_q(c[v.other].value[k1]);
    b[k0] = 1 - h0 / (h0 - h1);
    b[k1] = h0 / (h0 - h1);
    return b;
  }
  // TRIPLE: b with h_oj . b = 0 and h_om . b = 0 is along h_oj x h_om; then b0 + b1 + b2 = 1
  Fc_bary r1, r2;
  for(int k = 0; k < 3; ++k)
  {
    r1[k] = Fc_q(c[owner].value[k]) - Fc_q(c[v.other].value[k]);
    r2[k] = Fc_q(c[owner].value[k]) - Fc_q(c[v.third].value[k]);
  }
  for(int k = 0; k < 3; ++k) b[k] = r1[(k + 1) % 3] * r2[(k + 2) % 3] - r1[(k + 2) % 3] * r2[(k + 1) % 3];
  const Fc_q sum = b[0] + b[1] + b[2];
  REQUIRE(sum != 0);
  for(Fc_q& x : b) x /= sum;
  return b;
}

// twice the signed area of triangle (p, q, r) in the (b1, b2) chart, where the face has area 1/2
Fc_q fc_cross(const Fc_bary& p, const Fc_bary& q, const Fc_bary& r)
{
  return (q[1] - p[1]) * (r[2] - p[2]) - (q[2] - p[2]) * (r[1] - p[1]);
}

bool fc_lower(const Fc_q& a, std::uint32_t i, const Fc_q& b, std::uint32_t j) { return a < b || (a == b && i < j); }

// index of the candidate with the lowest (value, site) pair at b
std::uint32_t fc_owner_at(const Fc_list& c, const Fc_bary& b)
{
  std::uint32_t best = 0;
  for(std::uint32_t l = 1; l < c.size(); ++l)
    if(fc_lower(fc_value(c[l], b), c[l].site, fc_value(c[best], b), c[best].site)) best = l;
  return best;
}

struct Fc_piece
{
  std::uint32_t candidate;
  std::vector<Fc_bary> points;
  Fc_q area;   // in the (b1, b2) chart: the whole face has 1/2
};

// Checks everything that must hold of any cut and returns the pieces with exact positions.
std::vector<Fc_piece> fc_check(const Fc_list& c, const SVI::Face_cut& cut, unsigned seed = 1)
{
  std::mt19937 rng(seed);
  std::ostringstream fields;
  for(const SVI::Candidate& f : c) fields << "site " << f.site << ": " << f.value[0] << " " << f.value[1] << " " << f.value[2] << "; ";
  INFO("candidates " << fields.str());
  std::vector<Fc_piece> pieces;
  std::vector<int> seen(c.size(), 0);
  Fc_q total = 0;
  for(const SVI::Symbolic_piece& rp : cut.pieces)
  {
    REQUIRE(rp.candidate < c.size());
    CHECK(++seen[rp.candidate] == 1);
    REQUIRE(rp.vertices.size() >= 3);
    REQUIRE(rp.supports.size() == rp.vertices.size());
    Fc_piece p{ rp.candidate, {}, 0 };
    for(const SVI::Symbolic_vertex& v : rp.vertices) p.points.push_back(fc_position(c, rp.candidate, v));
    const std::size_t n = p.points.size();
    for(std::size_t k = 0; k < n; ++k)
    {
      const Fc_bary &u = p.points[k], &w = p.points[(k + 1) % n];
      CHECK(fc_cross(u, w, p.points[(k + 2) % n]) >= 0);   // convex, counter-clockwise
      p.area += fc_cross(p.points[0], u, w) / 2;
      // the edge lies on what its support says: a mesh edge or the bisector with `other`
      const SVI::Piece_edge_support& s = rp.supports[k];
      if(s.on_mesh_edge) CHECK((u[(s.local + 2) % 3] == 0 && w[(s.local + 2) % 3] == 0));   // opposite corner's 0
      else
      {
        REQUIRE(s.other < c.size());
        CHECK(fc_value(c[rp.candidate], u) == fc_value(c[s.other], u));
        CHECK(fc_value(c[rp.candidate], w) == fc_value(c[s.other], w));
      }
    }
    CHECK(p.area > 0);
    total += p.area;
    // points strictly inside: positive weights on every vertex
    for(int sample = 0; sample < 20; ++sample)
    {
      Fc_bary x = {{ Fc_q(0), Fc_q(0), Fc_q(0) }};
      Fc_q sum = 0;
      for(const Fc_bary& q : p.points)
      {
        const Fc_q w = int(rng() % 1000) + 1;
        sum += w;
        for(int k = 0; k < 3; ++k) x[k] += w * q[k];
      }
      for(Fc_q& xk : x) xk /= sum;
      CHECK(fc_owner_at(c, x) == rp.candidate);
    }
    pieces.push_back(p);
  }
  CHECK(total == Fc_q(1) / 2);
  // coverage: a point of the face lies in the closed piece of a candidate with the lowest value
  // there (the lowest pair itself may own only a segment through it, which makes no piece)
  for(int sample = 0; sample < 200; ++sample)
  {
    const Fc_q w0 = int(rng() % 64), w1 = int(rng() % 64), w2 = int(rng() % 64) + 1;
    const Fc_bary x = {{ w0 / (w0 + w1 + w2), w1 / (w0 + w1 + w2), w2 / (w0 + w1 + w2) }};
    const Fc_q lowest = fc_value(c[fc_owner_at(c, x)], x);
    bool covered = false;
    for(const Fc_piece& p : pieces)
    {
      bool inside = fc_value(c[p.candidate], x) == lowest;
      for(std::size_t k = 0; k < p.points.size(); ++k)
        inside = inside && fc_cross(p.points[k], p.points[(k + 1) % p.points.size()], x) >= 0;
      covered = covered || inside;
    }
    CHECK(covered);
  }
  return pieces;
}

const Fc_piece* fc_piece_of(const std::vector<Fc_piece>& pieces, std::uint32_t candidate)
{
  for(const Fc_piece& p : pieces)
    if(p.candidate == candidate) return &p;
  return nullptr;
}

bool fc_has_point(const Fc_piece& p, const Fc_bary& x)
{
  for(const Fc_bary& q : p.points)
    if(q == x) return true;
  return false;
}

std::multiset<int> fc_kinds(const SVI::Symbolic_piece& p)
{
  std::multiset<int> kinds;
  for(const SVI::Symbolic_vertex& v : p.vertices)
    kinds.insert(100 * v.kind + 10 * v.local + (v.kind == SVI::Symbolic_vertex::CORNER ? 0 : int(v.other)));
  return kinds;
}

Fc_bary fc_at(int x, int y) { return {{ Fc_q(8 - x - y) / 8, Fc_q(x) / 8, Fc_q(y) / 8 }}; }

// fc_check, and the number of pieces, the degenerate flag, and a point every piece has
std::vector<Fc_piece> fc_expect(const Fc_list& c, const SVI::Face_cut& cut, std::size_t count, bool degenerate,
                                const Fc_bary& common = {{ Fc_q(-1), Fc_q(0), Fc_q(0) }})
{
  CHECK(cut.degenerate == degenerate);
  const std::vector<Fc_piece> pieces = fc_check(c, cut);
  CHECK(pieces.size() == count);
  if(common[0] >= 0)
    for(const Fc_piece& p : pieces) CHECK(fc_has_point(p, common));
  return pieces;
}

} // namespace

TEST_CASE("Face_cutter: one candidate owns the triangle", "[face_cutter]")
{
  const Fc_list c = fc_fields({ { { 3, 2 } } });
  const SVI::Face_cut cut = SVI::Face_cutter(c).cut();
  REQUIRE(cut.pieces.size() == 1);
  CHECK_FALSE(cut.degenerate);
  CHECK(fc_kinds(cut.pieces[0]) == std::multiset<int>{ 0, 10, 20 });
  fc_check(c, cut);
  // a second candidate above it at every corner changes nothing
  const Fc_list c2 = fc_fields({ { { 3, 2 } }, { { 40, 40 } } });
  const SVI::Face_cut cut2 = SVI::Face_cutter(c2).cut();
  REQUIRE(cut2.pieces.size() == 1);
  CHECK(cut2.pieces[0].candidate == 0);
  fc_check(c2, cut2);
}

TEST_CASE("Face_cutter: a bisector crossing two edges", "[face_cutter]")
{
  // bisector of (1,1) and (6,6) is x + y = 7: it crosses edge 0 at (7,0) and edge 2 at (0,7)
  const Fc_list c = fc_fields({ { { 1, 1 } }, { { 6, 6 } } });
  const SVI::Face_cut cut = SVI::Face_cutter(c).cut();
  CHECK_FALSE(cut.degenerate);
  const std::vector<Fc_piece> pieces = fc_check(c, cut);
  REQUIRE(pieces.size() == 2);
  const SVI::Symbolic_piece& p0 = cut.pieces[0].candidate == 0 ? cut.pieces[0] : cut.pieces[1];
  const SVI::Symbolic_piece& p1 = cut.pieces[0].candidate == 0 ? cut.pieces[1] : cut.pieces[0];
  // vertex kinds, coded 100 kind + 10 local + other: corner 0 and the crossings of edges 0, 2
  CHECK(fc_kinds(p0) == std::multiset<int>{ 0, 101, 121 });
  CHECK(fc_kinds(p1) == std::multiset<int>{ 10, 20, 100, 120 });
  // the shared edge: (u, w) on the bisector in one piece is (w, u) in the other
  std::vector<std::pair<Fc_bary, Fc_bary> > bisector_edges[2];
  for(int side = 0; side < 2; ++side)
  {
    const SVI::Symbolic_piece& rp = side == 0 ? p0 : p1;
    const Fc_piece& fp = *fc_piece_of(pieces, rp.candidate);
    for(std::size_t k = 0; k < rp.vertices.size(); ++k)
      if(!rp.supports[k].on_mesh_edge)
      {
        CHECK(rp.supports[k].other == std::uint32_t(1 - side));
        bisector_edges[side].emplace_back(fp.points[k], fp.points[(k + 1) % fp.points.size()]);
      }
  }
  REQUIRE((bisector_edges[0].size() == 1 && bisector_edges[1].size() == 1));
  CHECK(bisector_edges[0][0].first == bisector_edges[1][0].second);
  CHECK(bisector_edges[0][0].second == bisector_edges[1][0].first);
  CHECK(bisector_edges[0][0].first == fc_at(7, 0));
  CHECK(bisector_edges[0][0].second == fc_at(0, 7));
  // area of the corner piece: the triangle (0,0), (7,0), (0,7) is 49/64 of the face
  CHECK(fc_piece_of(pieces, 0)->area == Fc_q(49) / 128);
}

TEST_CASE("Face_cutter: three candidates meet at a triple point inside", "[face_cutter]")
{
  // three sites at distance 5 from (2, 2), spread around it (no two tie at a corner)
  const Fc_list c = fc_fields({ { { 6, 5 } }, { { -1, 6 } }, { { 2, -3 } } });
  const SVI::Face_cut cut = SVI::Face_cutter(c).cut();
  fc_expect(c, cut, 3, false, fc_at(2, 2));
  for(const SVI::Symbolic_piece& rp : cut.pieces)
  {
    const std::multiset<int> kinds = fc_kinds(rp);
    CHECK(std::count_if(kinds.begin(), kinds.end(), [](int k) { return k >= 200; }) == 1);   // one TRIPLE
  }
}

TEST_CASE("Face_cutter: identical fields go to the lower site index", "[face_cutter]")
{
  // candidates 0 and 1 have the same field; candidate 1 has the lower site index
  const Fc_list c = fc_fields({ { { 1, 1 } }, { { 1, 1 } } }, { 5, 3 });
  CHECK(fc_expect(c, SVI::Face_cutter(c).cut(), 1, false)[0].candidate == 1);
  // with a third site that takes part of the face (its crossings lie on both equal bisectors)
  const Fc_list c3 = fc_fields({ { { 1, 1 } }, { { 1, 1 } }, { { 6, 6 } } }, { 5, 3, 9 });
  const std::vector<Fc_piece> pieces = fc_expect(c3, SVI::Face_cutter(c3).cut(), 2, true);
  CHECK(fc_piece_of(pieces, 0) == nullptr);
  CHECK(fc_piece_of(pieces, 1) != nullptr);
}

TEST_CASE("Face_cutter: a bisector exactly through a corner", "[face_cutter]")
{
  // sites symmetric about y = x: the bisector runs from corner 0 to the middle of edge 1
  const Fc_list c = fc_fields({ { { 6, 2 } }, { { 2, 6 } } });
  for(const Fc_piece& p : fc_expect(c, SVI::Face_cutter(c).cut(), 2, true, fc_at(0, 0)))
  {
    CHECK(p.area == Fc_q(1) / 4);
    CHECK(p.points.size() == 3);
    CHECK(fc_has_point(p, fc_at(4, 4)));
  }
}

TEST_CASE("Face_cutter: Voronoi vertex exactly on an edge or a corner", "[face_cutter]")
{
  // on edge 0 at (2, 0): three sites at distance 5 from it, each keeps a piece
  Fc_list c = fc_fields({ { { 2, 5 } }, { { -2, -3 } }, { { 6, -3 } } });
  fc_expect(c, SVI::Face_cutter(c).cut(), 3, true, fc_at(2, 0));
  // at corner 0: three sites at distance 5 from it, two bisectors inside the corner
  c = fc_fields({ { { 4, -3 } }, { { 3, 4 } }, { { 0, 5 } } });
  fc_expect(c, SVI::Face_cutter(c).cut(), 3, true, fc_at(0, 0));
  // four cocircular sites meet at (2, 2); the bisectors are x = 2 and y = 2
  c = fc_fields({ { { 5, 6 } }, { { -1, 6 } }, { { -1, -2 } }, { { 5, -2 } } });
  const std::vector<Fc_piece> pieces = fc_expect(c, SVI::Face_cutter(c).cut(), 4, true, fc_at(2, 2));
  const int area[4] = { 8, 10, 4, 10 };   // out of the face's 32
  for(std::uint32_t i = 0; i < 4; ++i)
  {
    REQUIRE(fc_piece_of(pieces, i) != nullptr);
    CHECK(fc_piece_of(pieces, i)->area == Fc_q(area[i]) / 64);
  }
}

TEST_CASE("Face_cutter: dominated candidates get no piece", "[face_cutter]")
{
  // candidate 2 is below each other candidate at some corner, but above their lower envelope
  Fc_list c = { { 0, {{ 0, 10, 10 }} }, { 1, {{ 10, 0, 11 }} }, { 2, {{ 6, 6, 20 }} } };
  CHECK(fc_piece_of(fc_expect(c, SVI::Face_cutter(c).cut(), 2, false), 2) == nullptr);
  // now it touches the envelope at the middle of edge 0 only: a triple point on an edge
  c[2].value = {{ 5, 5, 20 }};
  CHECK(fc_piece_of(fc_expect(c, SVI::Face_cutter(c).cut(), 2, true), 2) == nullptr);
}

TEST_CASE("Face_cutter: random small integer sites, with the exact ties they bring", "[face_cutter]")
{
  std::mt19937 rng(4242);
  int degenerate = 0;
  for(int n = 0; n < 300; ++n)
  {
    std::vector<std::array<double, 2> > sites;
    std::vector<std::uint32_t> ids;
    const int count = 2 + int(rng() % 5);
    for(int i = 0; i < count; ++i)
    {
      sites.push_back({{ double(int(rng() % 13) - 3), double(int(rng() % 13) - 3) }});
      ids.push_back(std::uint32_t(rng() % 50));   // site indices in any order, some repeated fields
    }
    const Fc_list c = fc_fields(sites, ids);
    bool distinct = true;
    for(int i = 0; i < count; ++i)
      for(int j = 0; j < i; ++j) distinct = distinct && ids[i] != ids[j];
    if(!distinct) continue;
    INFO("configuration " << n);
    const SVI::Face_cut cut = SVI::Face_cutter(c).cut();
    degenerate += cut.degenerate;
    fc_check(c, cut, unsigned(n));
  }
  CHECK(degenerate > 20);   // the lattice sites must bring exact ties
}

// The flat store of all the faces' cuts (Face_cuts.h) must give back each face's cut as the
// cutter made it: the same pieces, vertices and supports, one whole face without a piece
// for a single candidate, nothing for none; after some faces are cut again on new lists
// (as repair does), those show the new cuts and the others are unchanged; and cutting in
// parallel chunks stores the same cuts as cutting in order.
TEST_CASE("face cuts: the flat store gives back every face's cut, also after faces are cut again", "[cutting]")
{
  std::mt19937 rng(77);
  auto random_list = [&]() {
    std::vector<std::array<double, 2> > sites;
    const int count = int(rng() % 6);   // 0 to 5 candidates
    for(int i = 0; i < count; ++i) sites.push_back({{ double(int(rng() % 13) - 3), double(int(rng() % 13) - 3) }});
    return fc_fields(sites);
  };
  const std::size_t nf = 20000;   // more than two chunks
  SVI::Candidate_lists lists(nf, SVI::Candidate_list());
  for(auto& l : lists) l = random_list();
  auto same = [](const SVI::Face_cuts::Cut& got, const SVI::Candidate_list& list) {
    if(list.empty()) return got.pieces.empty() && !got.whole_face && !got.degenerate;
    if(list.size() == 1) return got.pieces.empty() && got.whole_face;
    const SVI::Face_cut want = SVI::Face_cutter(list).cut();
    if(got.whole_face || got.degenerate != want.degenerate || got.pieces.size() != want.pieces.size()) return false;
    for(std::size_t p = 0; p < want.pieces.size(); ++p)
    {
      const SVI::Face_cuts::Piece g = got.pieces[p];
      const SVI::Symbolic_piece& w = want.pieces[p];
      if(g.candidate != w.candidate || g.vertices.size() != w.vertices.size() || g.supports.size() != w.supports.size()) return false;
      for(std::size_t k = 0; k < w.vertices.size(); ++k)
      {
        const SVI::Symbolic_vertex &a = g.vertices[k], &b = w.vertices[k];
        const SVI::Piece_edge_support &c = g.supports[k], &d = w.supports[k];
        if(a.kind != b.kind || a.local != b.local || (a.kind != SVI::Symbolic_vertex::CORNER && a.other != b.other)
           || (a.kind == SVI::Symbolic_vertex::TRIPLE && a.third != b.third))
          return false;
        if(c.on_mesh_edge != d.on_mesh_edge || (c.on_mesh_edge ? c.local != d.local : c.other != d.other)) return false;
      }
    }
    return true;
  };
  auto all_same = [&](const SVI::Face_cuts& cuts) {
    std::size_t wrong = 0;
    for(std::size_t f = 0; f < nf; ++f) wrong += !same(cuts[f], lists[f]);
    return wrong;
  };
  SVI::Face_cuts in_order, in_chunks;
  in_order.reset(nf);
  in_chunks.reset(nf);
  SVI::Candidate_table table{ SVI::Candidate_lists(lists) };
  in_order.cut(table, nf, [](std::size_t k) { return k; }, false);
  in_chunks.cut(table, nf, [](std::size_t k) { return k; }, true);
  CHECK(all_same(in_order) == 0);
  CHECK(all_same(in_chunks) == 0);

  std::vector<std::size_t> again;
  for(std::size_t f = 0; f < nf; f += 1 + rng() % 5)
  {
    again.push_back(f);
    lists[f] = random_list();
    table.replace(f, lists[f]);
  }
  in_order.cut(table, again.size(), [&again](std::size_t k) { return again[k]; }, false);
  in_chunks.cut(table, again.size(), [&again](std::size_t k) { return again[k]; }, true);
  CHECK(all_same(in_order) == 0);
  CHECK(all_same(in_chunks) == 0);
}

} // namespace svd_test_face_cutter
