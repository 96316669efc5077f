// Copyright (c) 2026 The Surface_voronoi_diagram authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stitching: the per-face pieces become one consistent partition of the surface. Vertices
// are identified by combinatorial keys (a mesh vertex; bisector {i,j} crossing mesh edge e;
// triple point {i,j,k} in face f), and positions are computed once per key from values
// both faces share, so the two sides of an edge produce the same vertices bit for bit.
// Exact ties (a Voronoi vertex exactly on a mesh edge or corner, four sites meeting at a
// point) give one point several keys: those are welded by exact comparison, and vertices
// that lie on a mesh edge are inserted into every piece edge running along it, so the
// result has no cracks and no T-junctions.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_STITCHING_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_STITCHING_H

#include <CGAL/Surface_voronoi_diagram/internal/Indexed_mesh.h>
#include <CGAL/Surface_voronoi_diagram/internal/cutting.h>
#include <CGAL/Surface_voronoi_diagram/internal/exact_predicates.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <numeric>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

constexpr std::size_t no_site = std::size_t(-1);

/// The surface partitioned into convex pieces, each inside one face and owned by one site.
struct Partition
{
  enum Location_kind : std::uint8_t { AT_CORNER, ON_EDGE, IN_FACE };
  struct Vertex
  {
    std::array<double, 3> point;
    Location_kind kind;
    std::size_t element;   // mesh vertex, mesh edge or face
    double t;              // ON_EDGE: parameter from the edge's lower vertex index
  };
  struct Piece
  {
    std::size_t face;
    std::size_t site;      // no_site where no site reaches
    std::vector<std::size_t> vertices;
    double area;
  };

  std::vector<Vertex> vertices;
  std::vector<Piece> pieces;                // grouped by face, in face order, sites ascending
  std::vector<std::size_t> face_begin;      // pieces of face f: [face_begin[f], face_begin[f+1])
  std::size_t welded_vertices = 0;
  std::size_t inserted_vertices = 0;
};

namespace stitching_detail {

struct Key
{
  std::uint64_t a;
  std::uint32_t b, c, d;
  std::uint8_t kind;
  bool operator==(const Key& o) const { return kind == o.kind && a == o.a && b == o.b && c == o.c && d == o.d; }
};

struct Origin
{
  Key key;
  std::size_t face;   // a face whose candidate list holds every site of the key
};

} // namespace stitching_detail

namespace stitching_detail {

inline bool collinear_polygon(const Partition& out, const std::vector<std::size_t>& ids)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel EK;
  auto point = [&](std::size_t id) {
    const std::array<double, 3>& p = out.vertices[id].point;
    return EK::Point_3(p[0], p[1], p[2]);
  };
  const EK::Point_3 a = point(ids[0]);
  std::size_t k = 1;
  while(k < ids.size() && point(ids[k]) == a) ++k;
  if(k == ids.size()) return true;
  const EK::Point_3 b = point(ids[k]);
  for(std::size_t j = k + 1; j < ids.size(); ++j)
    if(!CGAL::collinear(a, b, point(ids[j]))) return false;
  return true;
}

} // namespace stitching_detail

inline double piece_area(const Partition& out, const std::vector<std::size_t>& ids)
{
  std::array<double, 3> s = {{ 0., 0., 0. }};
  const std::array<double, 3>& o = out.vertices[ids[0]].point;
  for(std::size_t k = 1; k + 1 < ids.size(); ++k)
  {
    const std::array<double, 3>& a = out.vertices[ids[k]].point;
    const std::array<double, 3>& b = out.vertices[ids[k + 1]].point;
    const std::array<double, 3> u = {{ a[0] - o[0], a[1] - o[1], a[2] - o[2] }};
    const std::array<double, 3> w = {{ b[0] - o[0], b[1] - o[1], b[2] - o[2] }};
    const std::array<double, 3> c = {{ u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0] }};
    for(int j = 0; j < 3; ++j) s[j] += c[j];
  }
  return 0.5 * std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
}

template <class TriangleMesh>
void weld_coincident_positions(Partition& out, const Indexed_mesh<TriangleMesh>& mesh)
{
  using namespace stitching_detail;
  // Two vertices can only coincide if some face uses both, so compare within each face.
  std::vector<std::size_t> rep(out.vertices.size());
  std::iota(rep.begin(), rep.end(), std::size_t(0));
  auto find = [&](std::size_t x) {
    while(rep[x] != x) { rep[x] = rep[rep[x]]; x = rep[x]; }
    return x;
  };
  bool any = false;
  std::vector<std::size_t> used;
  const std::size_t nf = out.face_begin.size() - 1;
  for(std::size_t f = 0; f < nf; ++f)
  {
    used.clear();
    for(std::size_t p = out.face_begin[f]; p < out.face_begin[f + 1]; ++p)
      used.insert(used.end(), out.pieces[p].vertices.begin(), out.pieces[p].vertices.end());
    std::sort(used.begin(), used.end(), [&](std::size_t a, std::size_t b) {
      return out.vertices[a].point < out.vertices[b].point || (out.vertices[a].point == out.vertices[b].point && a < b);
    });
    for(std::size_t k = 1; k < used.size(); ++k)
      if(used[k] != used[k - 1] && out.vertices[used[k]].point == out.vertices[used[k - 1]].point)
      {
        // the survivor keeps the most specific location: a corner, else an edge point
        const std::size_t a = find(used[k - 1]), b = find(used[k]);
        if(a == b) continue;
        const bool a_first = out.vertices[a].kind < out.vertices[b].kind
                             || (out.vertices[a].kind == out.vertices[b].kind && a < b);
        if(a_first) rep[b] = a; else rep[a] = b;
        any = true;
      }
  }
  if(any)
  {
    for(std::size_t id = 0; id < rep.size(); ++id)
      if(find(id) != id) ++out.welded_vertices;
    for(Partition::Piece& p : out.pieces)
    {
      std::vector<std::size_t> cleaned;
      for(std::size_t id : p.vertices)
      {
        const std::size_t r = find(id);
        if(cleaned.empty() || cleaned.back() != r) cleaned.push_back(r);
      }
      while(cleaned.size() > 1 && cleaned.front() == cleaned.back()) cleaned.pop_back();
      p.vertices.swap(cleaned);
    }
  }
  for(Partition::Piece& p : out.pieces)
    p.area = p.vertices.size() < 3 ? 0. : piece_area(out, p.vertices);

  // collinear pieces: their long side's neighbour gets the middle vertices
  std::vector<std::size_t> degenerate;
  for(std::size_t k = 0; k < out.pieces.size(); ++k)
  {
    const Partition::Piece& p = out.pieces[k];
    // only a piece without area in double can be exactly collinear
    if(p.vertices.size() < 3 || (p.area <= 1e-12 * mesh.face_areas[p.face] && collinear_polygon(out, p.vertices)))
      degenerate.push_back(k);
  }
  if(degenerate.empty()) return;
  std::unordered_map<std::uint64_t, std::size_t> edge_owner;   // directed edge -> piece
  const std::uint64_t nv = out.vertices.size();
  std::vector<std::uint8_t> dropped(out.pieces.size(), 0);
  for(std::size_t k : degenerate) dropped[k] = 1;
  for(std::size_t k = 0; k < out.pieces.size(); ++k)
  {
    if(dropped[k]) continue;
    const auto& v = out.pieces[k].vertices;
    for(std::size_t j = 0; j < v.size(); ++j)
      edge_owner[std::uint64_t(v[j]) * nv + v[(j + 1) % v.size()]] = k;
  }
  for(std::size_t k : degenerate)
  {
    const auto& v = out.pieces[k].vertices;
    if(v.size() < 3) continue;   // two vertices: the pieces on both sides already share the edge
    // order the vertices along the line
    const std::array<double, 3>& o = out.vertices[v[0]].point;
    std::array<double, 3> dir = {{ 0, 0, 0 }};
    double best = -1;
    for(std::size_t id : v)
    {
      const std::array<double, 3>& q = out.vertices[id].point;
      const double d = (q[0] - o[0]) * (q[0] - o[0]) + (q[1] - o[1]) * (q[1] - o[1]) + (q[2] - o[2]) * (q[2] - o[2]);
      if(d > best) { best = d; dir = {{ q[0] - o[0], q[1] - o[1], q[2] - o[2] }}; }
    }
    auto along = [&](std::size_t id) {
      const std::array<double, 3>& q = out.vertices[id].point;
      return (q[0] - o[0]) * dir[0] + (q[1] - o[1]) * dir[1] + (q[2] - o[2]) * dir[2];
    };
    std::vector<std::size_t> sorted(v.begin(), v.end());
    std::sort(sorted.begin(), sorted.end(), [&](std::size_t a, std::size_t b) { return along(a) < along(b); });
    sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
    // every edge (u, w) of the dropped piece: the piece across it, owning (w, u), gets the
    // vertices strictly between w and u
    for(std::size_t j = 0; j < v.size(); ++j)
    {
      const std::size_t u = v[j], w = v[(j + 1) % v.size()];
      auto it = edge_owner.find(std::uint64_t(w) * nv + u);
      if(it == edge_owner.end()) continue;
      const double tw = along(w), tu = along(u);
      std::vector<std::size_t> between;
      for(std::size_t id : sorted)
        if(id != u && id != w && along(id) > (std::min)(tu, tw) && along(id) < (std::max)(tu, tw)) between.push_back(id);
      if(between.empty()) continue;
      if(tw > tu) std::reverse(between.begin(), between.end());
      auto& q = out.pieces[it->second].vertices;
      for(std::size_t i = 0; i < q.size(); ++i)
        if(q[i] == w && q[(i + 1) % q.size()] == u)
        {
          q.insert(q.begin() + std::ptrdiff_t(i + 1), between.begin(), between.end());
          out.inserted_vertices += between.size();
          break;
        }
    }
  }
  std::vector<Partition::Piece> kept;
  kept.reserve(out.pieces.size());
  for(std::size_t k = 0; k < out.pieces.size(); ++k)
    if(!dropped[k]) kept.push_back(std::move(out.pieces[k]));
  out.pieces.swap(kept);
  out.face_begin.assign(nf + 1, out.pieces.size());
  for(std::size_t p = out.pieces.size(); p-- > 0;)
    out.face_begin[out.pieces[p].face] = p;
  for(std::size_t f = nf; f-- > 0;)
    if(out.face_begin[f] > out.face_begin[f + 1]) out.face_begin[f] = out.face_begin[f + 1];
}

/// Builds the partition from the candidate lists and the per-face cuts.
template <class TriangleMesh>
void stitch(const Indexed_mesh<TriangleMesh>& mesh,
            const std::vector<std::vector<Face_field> >& candidates,
            const std::vector<Face_cut>& cuts,
            Partition& out)
{
  using namespace stitching_detail;
  const std::size_t nf = mesh.number_of_faces();
  out = Partition();
  std::vector<Origin> origins;

  auto site_of = [&](std::size_t f, std::uint32_t c) { return candidates[f][c].site; };
  auto key_of = [&](std::size_t f, std::uint32_t owner, const Piece_vertex& v) -> Key {
    switch(v.kind)
    {
    case Piece_vertex::CORNER:
      return Key{ mesh.triangles[f][v.local], 0, 0, 0, 0 };
    case Piece_vertex::EDGE:
    {
      std::uint32_t s = site_of(f, owner), t = site_of(f, v.other);
      if(s > t) std::swap(s, t);
      return Key{ mesh.edges[f][v.local], s, t, 0, 1 };
    }
    default:
    {
      std::array<std::uint32_t, 3> s = {{ site_of(f, owner), site_of(f, v.other), site_of(f, v.third) }};
      std::sort(s.begin(), s.end());
      return Key{ f, s[0], s[1], s[2], 2 };
    }
    }
  };
  // Vertex ids without hashing: corners by mesh vertex; bisector crossings on the edge's
  // faces (the one processed first owns them); triple points inside their face.
  std::vector<std::size_t> corner_id(mesh.number_of_vertices(), no_site);
  struct Edge_entry { std::size_t edge; std::uint32_t lo, hi; std::size_t id; };
  std::vector<Edge_entry> edge_entries;            // grouped by face, in face order
  std::vector<std::size_t> edge_entries_begin(nf + 1, 0);
  std::size_t triple_begin = 0;                    // triple points of the current face start here
  auto id_of = [&](const Key& k, std::size_t f) -> std::size_t {
    if(k.kind == 0)
    {
      std::size_t& id = corner_id[static_cast<std::size_t>(k.a)];
      if(id == no_site) { id = origins.size(); origins.push_back(Origin{ k, f }); }
      return id;
    }
    if(k.kind == 1)
    {
      const std::size_t e = static_cast<std::size_t>(k.a);
      auto find_in = [&](std::size_t begin, std::size_t end) -> std::size_t {
        for(std::size_t j = begin; j < end; ++j)
          if(edge_entries[j].edge == e && edge_entries[j].lo == k.b && edge_entries[j].hi == k.c) return edge_entries[j].id;
        return no_site;
      };
      for(int l = 0; l < 3; ++l)
        if(mesh.edges[f][l] == e)
        {
          const std::size_t g = mesh.neighbors[f][l];
          if(g != Indexed_mesh<TriangleMesh>::none && g < f)
          {
            const std::size_t id = find_in(edge_entries_begin[g], edge_entries_begin[g + 1]);
            if(id != no_site) return id;
          }
        }
      std::size_t id = find_in(edge_entries_begin[f], edge_entries.size());
      if(id != no_site) return id;
      id = origins.size();
      origins.push_back(Origin{ k, f });
      edge_entries.push_back(Edge_entry{ e, k.b, k.c, id });
      return id;
    }
    for(std::size_t id = triple_begin; id < origins.size(); ++id)
      if(origins[id].key == k) return id;
    origins.push_back(Origin{ k, f });
    return origins.size() - 1;
  };

  // 1. pieces with vertex ids; faces nobody reached are one piece of no site
  std::vector<std::uint8_t> face_degenerate(nf, 0);
  out.face_begin.assign(nf + 1, 0);
  for(std::size_t f = 0; f < nf; ++f)
  {
    out.face_begin[f] = out.pieces.size();
    edge_entries_begin[f] = edge_entries.size();
    triple_begin = origins.size();
    face_degenerate[f] = cuts[f].degenerate;
    if(candidates[f].empty())
    {
      Partition::Piece p{ f, no_site, {}, 0. };
      for(int k = 0; k < 3; ++k)
        p.vertices.push_back(id_of(Key{ mesh.triangles[f][k], 0, 0, 0, 0 }, f));
      out.pieces.push_back(std::move(p));
      continue;
    }
    for(const Raw_piece& rp : cuts[f].pieces)
    {
      Partition::Piece p{ f, candidates[f][rp.candidate].site, {}, 0. };
      p.vertices.reserve(rp.vertices.size());
      for(const Piece_vertex& v : rp.vertices)
        p.vertices.push_back(id_of(key_of(f, rp.candidate, v), f));
      out.pieces.push_back(std::move(p));
    }
  }
  out.face_begin[nf] = out.pieces.size();
  edge_entries_begin[nf] = edge_entries.size();

  // 2. one position per key
  auto values_of = [&](std::size_t f, std::uint32_t site) -> const double* {
    for(const Face_field& x : candidates[f])
      if(x.site == site) return x.value.data();
    return nullptr;
  };
  auto corner_of = [&](std::size_t f, std::size_t v) {
    for(int k = 0; k < 3; ++k)
      if(mesh.triangles[f][k] == v) return k;
    return -1;
  };
  out.vertices.resize(origins.size());
  for(std::size_t id = 0; id < origins.size(); ++id)
  {
    const Key& k = origins[id].key;
    const std::size_t f = origins[id].face;
    Partition::Vertex& pv = out.vertices[id];
    if(k.kind == 0)
    {
      pv = Partition::Vertex{ mesh.points[k.a], Partition::AT_CORNER, static_cast<std::size_t>(k.a), 0. };
    }
    else if(k.kind == 1)
    {
      const std::size_t e = static_cast<std::size_t>(k.a);
      const std::size_t va = mesh.edge_vertices[e][0], vb = mesh.edge_vertices[e][1];
      const int ca = corner_of(f, va), cb = corner_of(f, vb);
      const double* lo = values_of(f, k.b);
      const double* hi = values_of(f, k.c);
      const double da = lo[ca] - hi[ca], db = lo[cb] - hi[cb];
      double t = da / (da - db);
      t = (std::min)(1., (std::max)(0., t));
      const std::array<double, 3>& pa = mesh.points[va];
      const std::array<double, 3>& pb = mesh.points[vb];
      pv = Partition::Vertex{ { pa[0] + t * (pb[0] - pa[0]), pa[1] + t * (pb[1] - pa[1]), pa[2] + t * (pb[2] - pa[2]) },
                              Partition::ON_EDGE, e, t };
    }
    else
    {
      const double* d0 = values_of(f, k.b);
      const double* d1 = values_of(f, k.c);
      const double* d2 = values_of(f, k.d);
      double r1[3], r2[3];
      for(int c = 0; c < 3; ++c) { r1[c] = d0[c] - d1[c]; r2[c] = d0[c] - d2[c]; }
      std::array<double, 3> b = {{ r1[1] * r2[2] - r1[2] * r2[1], r1[2] * r2[0] - r1[0] * r2[2], r1[0] * r2[1] - r1[1] * r2[0] }};
      double s = 0;
      for(double& x : b) s += x;
      for(double& x : b) x /= s;
      // rounding may push the point a hair outside its face: keep it on the face
      double s2 = 0;
      for(double& x : b) { x = (std::max)(0., x); s2 += x; }
      for(double& x : b) x /= s2;
      pv = Partition::Vertex{ mesh.point_at(f, b), Partition::IN_FACE, f, 0. };
    }
  }

  // 3. weld vertices that coincide exactly (only possible around exact ties)
  std::vector<std::size_t> rep(origins.size());
  std::iota(rep.begin(), rep.end(), std::size_t(0));
  bool any_degenerate = false;
  for(std::size_t f = 0; f < nf; ++f) any_degenerate |= (face_degenerate[f] != 0);
  if(any_degenerate)
  {
    // exact location of every vertex of a degenerate face
    struct Exact_location
    {
      int kind;                 // 0 corner, 1 edge, 2 face
      std::size_t element;
      std::array<Exact, 3> c;   // edge: t in c[0]; face: barycentric
    };
    auto less = [](const Exact_location& x, const Exact_location& y) {
      if(x.kind != y.kind) return x.kind < y.kind;
      if(x.element != y.element) return x.element < y.element;
      for(int k = 0; k < 3; ++k)
      {
        if(x.c[k] < y.c[k]) return true;
        if(y.c[k] < x.c[k]) return false;
      }
      return false;
    };
    std::map<Exact_location, std::size_t, decltype(less)> groups(less);
    auto exact_t = [&](std::size_t f, std::size_t e, std::uint32_t s_lo, std::uint32_t s_hi) {
      const std::size_t va = mesh.edge_vertices[e][0], vb = mesh.edge_vertices[e][1];
      const int ca = corner_of(f, va), cb = corner_of(f, vb);
      const double* lo = values_of(f, s_lo);
      const double* hi = values_of(f, s_hi);
      const Exact da = Exact(lo[ca]) - Exact(hi[ca]), db = Exact(lo[cb]) - Exact(hi[cb]);
      return Exact(da / (da - db));
    };
    auto locate = [&](std::size_t id) -> Exact_location {
      const Key& k = origins[id].key;
      const std::size_t f = origins[id].face;
      if(k.kind == 0) return Exact_location{ 0, static_cast<std::size_t>(k.a), {} };
      if(k.kind == 1)
      {
        Exact_location l{ 1, static_cast<std::size_t>(k.a), {} };
        l.c[0] = exact_t(f, static_cast<std::size_t>(k.a), k.b, k.c);
        return l;
      }
      const double* d0 = values_of(f, k.b);
      const double* d1 = values_of(f, k.c);
      const double* d2 = values_of(f, k.d);
      std::array<Exact, 3> r1, r2, b;
      for(int c = 0; c < 3; ++c) { r1[c] = Exact(d0[c]) - Exact(d1[c]); r2[c] = Exact(d0[c]) - Exact(d2[c]); }
      b[0] = r1[1] * r2[2] - r1[2] * r2[1];
      b[1] = r1[2] * r2[0] - r1[0] * r2[2];
      b[2] = r1[0] * r2[1] - r1[1] * r2[0];
      const Exact s = b[0] + b[1] + b[2];
      for(Exact& x : b) x = x / s;
      int zeros = 0, nonzero = -1;
      for(int c = 0; c < 3; ++c) { if(CGAL::is_zero(b[c])) ++zeros; else nonzero = c; }
      if(zeros == 2)
        return Exact_location{ 0, mesh.triangles[f][nonzero], {} };
      if(zeros == 1)
      {
        int z = 0;
        while(!CGAL::is_zero(b[z])) ++z;
        // on the local edge opposite corner z: corners z+1 -> z+2 form local edge z+1
        const int k = (z + 1) % 3;
        const std::size_t e = mesh.edges[f][k];
        const std::size_t va = mesh.edge_vertices[e][0];
        const int cb = (mesh.triangles[f][k] == va) ? (k + 1) % 3 : k;
        Exact_location l{ 1, e, {} };
        l.c[0] = b[cb];
        return l;
      }
      Exact_location l{ 2, f, {} };
      l.c = b;
      return l;
    };
    std::vector<std::uint8_t> seen(origins.size(), 0);
    for(std::size_t f = 0; f < nf; ++f)
    {
      if(!face_degenerate[f]) continue;
      // the degenerate face and its neighbours: a point on a shared edge has keys in both
      std::size_t faces_to_scan[4] = { f, mesh.neighbors[f][0], mesh.neighbors[f][1], mesh.neighbors[f][2] };
      for(std::size_t g : faces_to_scan)
      {
        if(g == Indexed_mesh<TriangleMesh>::none) continue;
        for(std::size_t p = out.face_begin[g]; p < out.face_begin[g + 1]; ++p)
          for(std::size_t id : out.pieces[p].vertices)
          {
            if(seen[id]) continue;
            seen[id] = 1;
            Exact_location l = locate(id);
            if(l.kind == 0)
            {
              // a corner: represented by the corner's own key
              const std::size_t cid = id_of(Key{ l.element, 0, 0, 0, 0 }, origins[id].face);
              if(cid >= rep.size())
              {
                rep.push_back(cid);
                seen.push_back(1);
                out.vertices.push_back(Partition::Vertex{ mesh.points[l.element], Partition::AT_CORNER, l.element, 0. });
              }
              rep[id] = cid;
              continue;
            }
            auto r = groups.emplace(l, id);
            if(!r.second)
              rep[id] = r.first->second;
            else if(l.kind == 1 && origins[id].key.kind == 2)
            {
              // a triple point exactly on a mesh edge: it becomes an edge vertex
              out.vertices[id].kind = Partition::ON_EDGE;
              out.vertices[id].element = l.element;
              out.vertices[id].t = CGAL::to_double(l.c[0]);
            }
          }
      }
    }
    for(std::size_t id = 0; id < rep.size(); ++id)
      if(rep[id] != id) ++out.welded_vertices;
    for(Partition::Piece& p : out.pieces)
    {
      for(std::size_t& id : p.vertices) id = rep[id];
      std::vector<std::size_t> cleaned;
      for(std::size_t id : p.vertices)
        if(cleaned.empty() || cleaned.back() != id) cleaned.push_back(id);
      while(cleaned.size() > 1 && cleaned.front() == cleaned.back()) cleaned.pop_back();
      p.vertices.swap(cleaned);
    }
    out.pieces.erase(std::remove_if(out.pieces.begin(), out.pieces.end(),
                                    [](const Partition::Piece& p) { return p.vertices.size() < 3; }),
                     out.pieces.end());
    out.face_begin.assign(nf + 1, out.pieces.size());
    for(std::size_t p = out.pieces.size(); p-- > 0;)
      out.face_begin[out.pieces[p].face] = p;
    for(std::size_t f = nf; f-- > 0;)
      if(out.face_begin[f] > out.face_begin[f + 1]) out.face_begin[f] = out.face_begin[f + 1];
  }

  // 4. every vertex on a mesh edge goes into the piece edges that run along that edge
  // (the points of each edge, sorted by parameter, in one flat array)
  struct Edge_point { std::size_t edge; double t; std::size_t id; };
  std::vector<Edge_point> edge_points;
  for(std::size_t id = 0; id < out.vertices.size(); ++id)
    if(rep[id] == id && out.vertices[id].kind == Partition::ON_EDGE)
      edge_points.push_back(Edge_point{ out.vertices[id].element, out.vertices[id].t, id });
  std::sort(edge_points.begin(), edge_points.end(), [](const Edge_point& a, const Edge_point& b) {
    return a.edge < b.edge || (a.edge == b.edge && (a.t < b.t || (a.t == b.t && a.id < b.id)));
  });
  std::vector<std::uint32_t> points_on_edge(mesh.number_of_edges(), 0);
  for(const Edge_point& x : edge_points) ++points_on_edge[x.edge];
  auto range_of = [&](std::size_t e) {
    auto lo = std::lower_bound(edge_points.begin(), edge_points.end(), e,
                               [](const Edge_point& x, std::size_t edge) { return x.edge < edge; });
    return std::make_pair(lo, lo + points_on_edge[e]);
  };
  auto t_on = [&](std::size_t id, std::size_t e, bool& ok) -> double {
    const Partition::Vertex& v = out.vertices[id];
    ok = true;
    if(v.kind == Partition::AT_CORNER)
    {
      if(v.element == mesh.edge_vertices[e][0]) return 0.;
      if(v.element == mesh.edge_vertices[e][1]) return 1.;
    }
    else if(v.kind == Partition::ON_EDGE && v.element == e)
      return v.t;
    ok = false;
    return 0.;
  };
  // the vertices strictly inside the piece edge (u, w) lying along mesh edge e, in order
  auto between = [&](std::size_t u, std::size_t w, std::size_t e, std::vector<std::size_t>& found) {
    found.clear();
    bool ok_u, ok_w;
    const double tu = t_on(u, e, ok_u), tw = t_on(w, e, ok_w);
    if(!ok_u || !ok_w) return false;
    const double lo = (std::min)(tu, tw), hi = (std::max)(tu, tw);
    const auto r = range_of(e);
    for(auto it = r.first; it != r.second; ++it)
      if(it->t > lo && it->t < hi && it->id != u && it->id != w) found.push_back(it->id);
    if(tu > tw) std::reverse(found.begin(), found.end());
    return true;
  };
  std::vector<std::size_t> found, refined;
  for(Partition::Piece& p : out.pieces)
  {
    const std::size_t f = p.face;
    // a piece whose face has no point on its edges has nothing to receive
    bool candidate = false;
    for(int le = 0; le < 3; ++le) candidate |= points_on_edge[mesh.edges[f][le]] > 0;
    if(!candidate) continue;
    const std::size_t n = p.vertices.size();
    bool changed = false;
    refined.clear();
    for(std::size_t k = 0; k < n; ++k)
    {
      const std::size_t u = p.vertices[k], w = p.vertices[(k + 1) % n];
      refined.push_back(u);
      for(int le = 0; le < 3; ++le)
      {
        const std::size_t e = mesh.edges[f][le];
        if(points_on_edge[e] == 0) continue;
        if(!between(u, w, e, found)) continue;
        if(!found.empty())
        {
          refined.insert(refined.end(), found.begin(), found.end());
          out.inserted_vertices += found.size();
          changed = true;
        }
        break;
      }
    }
    if(changed) p.vertices = refined;
  }

  // 5. features smaller than double precision: vertices whose computed positions are
  // bit-identical are one vertex, and pieces left without area are removed (a piece whose
  // corners are collinear hands its middle vertices to the pieces across its long side)
  weld_coincident_positions(out, mesh);

}

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif
