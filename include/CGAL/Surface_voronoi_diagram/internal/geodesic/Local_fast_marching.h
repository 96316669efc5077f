// Copyright (c) 2026 The Surface_voronoi_diagram authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Geodesic distances from many sites, each computed only as far as it is asked for.
//
// Every site owns a fast-marching front that is advanced on demand: asking for the distance
// of site i at vertex v marches site i's front until v is accepted, and no further. The
// diagram asks only for the vertices around the faces a site propagates into, so the work
// is about a few geodesic balls of cell size per site: it grows with the mesh, not with
// mesh x sites. A front's sequence of accepted vertices does not depend on when it is
// advanced, so the values (and the diagram) are the same whatever order the queries come in.
//
// The triangle update treats the front as a point source unfolded into the triangle's plane
// (the circle-intersection update), which is exact on developable patches seen directly from
// the source, unlike the plane-wave update of classic fast marching. Triangles obtuse at the
// updated vertex are handled by an extra virtual triangle found by unfolding neighbours
// (Kimmel and Sethian's remedy), so that values there are not left to edge paths.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_GEODESIC_LOCAL_FAST_MARCHING_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_GEODESIC_LOCAL_FAST_MARCHING_H

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

typedef std::array<double, 3> Vector_3d;
typedef std::array<double, 2> Vector_2d;

inline Vector_3d difference(const Vector_3d& a, const Vector_3d& b) { return {{ a[0] - b[0], a[1] - b[1], a[2] - b[2] }}; }
inline double dot(const Vector_3d& a, const Vector_3d& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline double length(const Vector_3d& a) { return std::sqrt(dot(a, a)); }

/// The distance at `c` of a point source that is at distance `da` from `a` and `db` from `b`
/// and lies on the other side of the line ab than `c`, in the frame where a = (0, 0),
/// b = (ab, 0) and c = (cx, cy), cy > 0; +infinity when no such source exists or when the
/// straight path from it to `c` misses the segment ab.
inline double point_source_in_frame(double ab, double cx, double cy, double da, double db)
{
  const double inf = std::numeric_limits<double>::infinity();
  if(!(ab > 0) || !(cy > 0)) return inf;
  const double sx = (da * da - db * db + ab * ab) / (2 * ab);
  const double sy2 = da * da - sx * sx;
  if(sy2 < 0) return inf;
  const double sy = -std::sqrt(sy2);
  const double x0 = sx + (-sy / (cy - sy)) * (cx - sx);   // where the path from the source meets line ab
  if(x0 < 0 || x0 > ab) return inf;
  return std::sqrt((cx - sx) * (cx - sx) + (cy - sy) * (cy - sy));
}

/// The same update with a, b and c anywhere in the plane.
inline double point_source_update(const Vector_2d& a, const Vector_2d& b, const Vector_2d& c, double da, double db)
{
  const double ux = b[0] - a[0], uy = b[1] - a[1];
  const double L = std::sqrt(ux * ux + uy * uy);
  if(!(L > 0)) return std::numeric_limits<double>::infinity();
  const double cx = ((c[0] - a[0]) * ux + (c[1] - a[1]) * uy) / L;
  const double cy = std::abs((c[1] - a[1]) * ux - (c[0] - a[0]) * uy) / L;
  return point_source_in_frame(L, cx, cy, da, db);
}

/// The same update on a triangle abc given by its side lengths.
inline double point_source_update(double ab, double ac, double bc, double da, double db)
{
  if(!(ab > 0)) return std::numeric_limits<double>::infinity();
  const double cx = (ac * ac - bc * bc + ab * ab) / (2 * ab);
  const double cy2 = ac * ac - cx * cx;
  return point_source_in_frame(ab, cx, cy2 > 0 ? std::sqrt(cy2) : 0., da, db);
}

/// The mesh as fast marching needs it: faces around each vertex and, for each corner with
/// an obtuse angle, a vertex unfolded from the faces beyond the opposite edge that splits
/// the corner into two acute virtual triangles.
class Fast_marching_mesh
{
public:
  static constexpr std::uint32_t none = std::uint32_t(-1);

  /// Corner c of a face, obtuse, with opposite corners a and b: the split vertex d and the
  /// unfolded positions of a, b and d in a plane where c is the origin.
  struct Split
  {
    std::uint32_t face, corner, vertex;
    Vector_2d a, b, d;
  };

  std::vector<Vector_3d> points;
  std::vector<std::array<std::uint32_t, 3> > triangles;
  /// One face around a vertex a, as the update from a needs it: the two other corners
  /// (next and previous in the face's order), the three side lengths, and the split of
  /// each of the two other corners if it is obtuse. Kept together so that an update reads
  /// one contiguous record instead of three arrays indexed by face.
  struct Ring_face
  {
    std::uint32_t next, prev;
    std::uint32_t split_next = none, split_prev = none;   // into `splits`
    double a_next, a_prev, opposite;
  };
  std::vector<std::uint32_t> ring_offsets;                  // CSR into `ring`
  std::vector<Ring_face> ring;
  std::vector<Split> splits;
  std::vector<std::uint32_t> vertex_split_offsets, vertex_splits; // splits whose d is the vertex (CSR)

  /// the point of face `f` with barycentric coordinates `b`
  Vector_3d point_at(std::uint32_t f, const std::array<double, 3>& b) const
  {
    Vector_3d x = {{ 0., 0., 0. }};
    for(int k = 0; k < 3; ++k)
      for(int c = 0; c < 3; ++c) x[c] += b[k] * points[triangles[f][k]][c];
    return x;
  }

  /// `neighbors[f][k]` is the face across local edge k (corners k, k+1), or `none_face`
  template <class Neighbors>
  void build(const std::vector<Vector_3d>& pts, const std::vector<std::array<std::uint32_t, 3> >& tris,
             const Neighbors& neighbors, std::size_t none_face)
  {
    points = pts;
    triangles = tris;
    const std::size_t n = points.size(), m = triangles.size();
    std::vector<std::array<double, 3> > edge_lengths(m);   // per face, of local edge k (corners k, k+1)
    for(std::size_t f = 0; f < m; ++f)
      for(int k = 0; k < 3; ++k)
        edge_lengths[f][k] = length(difference(points[triangles[f][(k + 1) % 3]], points[triangles[f][k]]));
    ring_offsets.assign(n + 1, 0);
    for(const auto& t : triangles)
      for(std::uint32_t v : t) ++ring_offsets[v + 1];
    for(std::size_t v = 0; v < n; ++v) ring_offsets[v + 1] += ring_offsets[v];
    splits.clear();
    std::vector<std::array<std::uint32_t, 3> > split_of(m, std::array<std::uint32_t, 3>{{ none, none, none }});
    for(std::size_t f = 0; f < m; ++f)
      for(int k = 0; k < 3; ++k)
      {
        Split s;
        if(find_split(f, k, neighbors, none_face, s))
        {
          split_of[f][k] = static_cast<std::uint32_t>(splits.size());
          splits.push_back(s);
        }
      }

    ring.resize(ring_offsets[n]);
    std::vector<std::uint32_t> fill(ring_offsets.begin(), ring_offsets.end() - 1);
    for(std::size_t f = 0; f < m; ++f)
      for(int k = 0; k < 3; ++k)
      {
        const int kn = (k + 1) % 3, kp = (k + 2) % 3;
        Ring_face r;
        r.next = triangles[f][kn];
        r.prev = triangles[f][kp];
        r.split_next = split_of[f][kn];
        r.split_prev = split_of[f][kp];
        r.a_next = edge_lengths[f][k];     // local edge k joins corners k and k+1
        r.a_prev = edge_lengths[f][kp];
        r.opposite = edge_lengths[f][kn];
        ring[fill[triangles[f][k]]++] = r;
      }
    vertex_split_offsets.assign(n + 1, 0);
    for(const Split& s : splits) ++vertex_split_offsets[s.vertex + 1];
    for(std::size_t v = 0; v < n; ++v) vertex_split_offsets[v + 1] += vertex_split_offsets[v];
    vertex_splits.resize(splits.size());
    fill.assign(vertex_split_offsets.begin(), vertex_split_offsets.end() - 1);
    for(std::size_t s = 0; s < splits.size(); ++s) vertex_splits[fill[splits[s].vertex]++] = static_cast<std::uint32_t>(s);
  }

private:
  // Unfolds the faces beyond the edge opposite an obtuse corner, one after the other, until a
  // vertex falls in the cone of directions that make a right or acute angle with both sides
  // of the corner. Gives up after a few faces or at a border.
  template <class Neighbors>
  bool find_split(std::size_t f, int k, const Neighbors& neighbors, std::size_t none_face, Split& split) const
  {
    const auto& t = triangles[f];
    const std::uint32_t vc = t[k], va = t[(k + 1) % 3], vb = t[(k + 2) % 3];
    const Vector_3d ca = difference(points[va], points[vc]), cb = difference(points[vb], points[vc]);
    if(dot(ca, cb) >= 0) return false;   // not obtuse
    const double la = length(ca);
    if(!(la > 0)) return false;
    const double bx = dot(cb, ca) / la;
    const double by2 = dot(cb, cb) - bx * bx;
    if(!(by2 > 0)) return false;
    const Vector_2d pa = {{ la, 0. }}, pb = {{ bx, std::sqrt(by2) }};

    std::size_t face = f;
    std::uint32_t ea = va, eb = vb;     // the edge to unfold across, and its unfolded ends
    Vector_2d qa = pa, qb = pb;
    for(int step = 0; step < 10; ++step)
    {
      std::size_t g = none_face;
      const auto& tf = triangles[face];
      for(int j = 0; j < 3; ++j)
        if((tf[j] == ea && tf[(j + 1) % 3] == eb) || (tf[j] == eb && tf[(j + 1) % 3] == ea))
          g = neighbors[face][j];
      if(g == none_face) return false;
      std::uint32_t d = none;
      for(std::uint32_t v : triangles[g])
        if(v != ea && v != eb) d = v;
      if(d == none || d == vc) return false;
      // d keeps its distances to ea and eb, on the far side of qa-qb from c
      const double L = std::sqrt((qb[0] - qa[0]) * (qb[0] - qa[0]) + (qb[1] - qa[1]) * (qb[1] - qa[1]));
      if(!(L > 0)) return false;
      const double la_d = length(difference(points[d], points[ea]));
      const double lb_d = length(difference(points[d], points[eb]));
      const double dx = (la_d * la_d - lb_d * lb_d + L * L) / (2 * L);
      const double dy2 = la_d * la_d - dx * dx;
      if(!(dy2 > 0)) return false;
      const Vector_2d u = {{ (qb[0] - qa[0]) / L, (qb[1] - qa[1]) / L }};
      Vector_2d w = {{ -u[1], u[0] }};
      if(w[0] * qa[0] + w[1] * qa[1] < 0) { w[0] = -w[0]; w[1] = -w[1]; }   // away from c
      const double dy = std::sqrt(dy2);
      const Vector_2d pd = {{ qa[0] + dx * u[0] + dy * w[0], qa[1] + dx * u[1] + dy * w[1] }};
      const bool right_of_a = pd[0] * pa[0] + pd[1] * pa[1] >= 0;   // angle a-c-d at most 90 degrees
      const bool right_of_b = pd[0] * pb[0] + pd[1] * pb[1] >= 0;
      if(right_of_a && right_of_b)
      {
        split.face = static_cast<std::uint32_t>(f);
        split.corner = static_cast<std::uint32_t>(k);
        split.vertex = d;
        split.a = pa;
        split.b = pb;
        split.d = pd;
        return true;
      }
      if(!right_of_b) { qa = pd; ea = d; }   // the cone lies between d and b
      else            { qb = pd; eb = d; }   // between a and d
      face = g;
    }
    return false;
  }
};

/// A site's start: a point in a face, given by barycentric coordinates.
struct Marching_seed
{
  std::uint32_t face = 0;
  std::array<double, 3> barycentric = {{ 1., 0., 0. }};
};

/// Lazily advanced fast-marching fronts, one per site, over a shared `Fast_marching_mesh`.
class Local_fast_marching
{
public:
  explicit Local_fast_marching(const Fast_marching_mesh& mesh) : m_mesh(mesh) {}

  void set_seeds(const std::vector<Marching_seed>& seeds)
  {
    m_seeds = seeds;
    m_fronts.assign(seeds.size(), Front());
    accepted_vertices = 0;
  }

  /// the geodesic distance from site `i` to vertex `v`; +infinity if `v` cannot be reached
  double distance(std::size_t i, std::uint32_t v)
  {
    Front& front = m_fronts[i];
    if(const Slot* s = front.find(v))
      if(s->accepted) return s->value;
    if(!front.started) start(i);
    while(!front.heap.empty())
      if(pop(i) == v) return front.find(v)->value;
    return std::numeric_limits<double>::infinity();
  }

  /// the geodesic distance from site `i` to the point of `face` with barycentric coordinates
  /// `b`: straight in the plane of the site's own face, otherwise the point-source update
  /// from each edge of the face, or a path through a corner
  double distance_at(std::size_t i, std::uint32_t face, const std::array<double, 3>& b)
  {
    const auto& t = m_mesh.triangles[face];
    const auto& P = m_mesh.points;
    if(face == m_seeds[i].face)
      return length(difference(m_mesh.point_at(face, b), m_mesh.point_at(face, m_seeds[i].barycentric)));
    std::array<double, 3> d;
    for(int k = 0; k < 3; ++k) d[k] = distance(i, t[k]);
    // the face in its plane: corner 0 at the origin, corner 1 on the x axis
    const Vector_3d e1 = difference(P[t[1]], P[t[0]]), e2 = difference(P[t[2]], P[t[0]]);
    const double l1 = length(e1);
    const double c2x = dot(e2, e1) / l1, c2y = std::sqrt((std::max)(0., dot(e2, e2) - c2x * c2x));
    const std::array<Vector_2d, 3> q = {{ {{ 0., 0. }}, {{ l1, 0. }}, {{ c2x, c2y }} }};
    const Vector_2d p = {{ b[1] * l1 + b[2] * c2x, b[2] * c2y }};
    double best = std::numeric_limits<double>::infinity();
    for(int k = 0; k < 3; ++k)
    {
      const double dx = p[0] - q[k][0], dy = p[1] - q[k][1];
      best = (std::min)(best, d[k] + std::sqrt(dx * dx + dy * dy));
      best = (std::min)(best, point_source_update(q[k], q[(k + 1) % 3], p, d[k], d[(k + 1) % 3]));
    }
    return best;
  }

  std::size_t accepted_vertices = 0;   // work done so far, for the statistics

private:
  struct Slot
  {
    std::uint32_t vertex;
    bool accepted;
    double value;
  };
  struct Heap_item
  {
    double value;
    std::uint32_t vertex;
    bool operator<(const Heap_item& o) const
    {
      // a max-heap of this order pops the smallest value, ties to the lower vertex
      return value > o.value || (value == o.value && vertex > o.vertex);
    }
  };

  // One front: its heap and an open-addressing map vertex -> (value, accepted). A small map
  // per site stays in cache, where one map keyed by (site, vertex) for all sites does not.
  struct Front
  {
    static constexpr std::uint32_t empty = std::uint32_t(-1);
    bool started = false;
    std::vector<Heap_item> heap;
    std::vector<Slot> slots;
    std::size_t size = 0;

    const Slot* find(std::uint32_t v) const
    {
      if(slots.empty()) return nullptr;
      std::size_t i = hash(v) & (slots.size() - 1);
      while(slots[i].vertex != empty)
      {
        if(slots[i].vertex == v) return &slots[i];
        i = (i + 1) & (slots.size() - 1);
      }
      return nullptr;
    }
    Slot& find_or_insert(std::uint32_t v)
    {
      if(2 * (size + 1) > slots.size()) grow();
      std::size_t i = hash(v) & (slots.size() - 1);
      while(slots[i].vertex != empty)
      {
        if(slots[i].vertex == v) return slots[i];
        i = (i + 1) & (slots.size() - 1);
      }
      ++size;
      slots[i] = Slot{ v, false, std::numeric_limits<double>::infinity() };
      return slots[i];
    }
    static std::size_t hash(std::uint32_t v) { return std::size_t(v) * 0x9E3779B1u >> 7; }
    void grow()
    {
      std::vector<Slot> old;
      old.swap(slots);
      slots.assign((std::max)(std::size_t(64), 2 * old.size()), Slot{ empty, false, 0. });
      for(const Slot& s : old)
        if(s.vertex != empty)
        {
          std::size_t i = hash(s.vertex) & (slots.size() - 1);
          while(slots[i].vertex != empty) i = (i + 1) & (slots.size() - 1);
          slots[i] = s;
        }
    }
  };

  void propose(Front& front, std::uint32_t v, double value)
  {
    Slot& s = front.find_or_insert(v);
    if(!s.accepted) lower(front, s, value);
  }

  // lowers the tentative value of a vertex not accepted yet, and queues it
  static void lower(Front& front, Slot& s, double value)
  {
    if(!(value < s.value)) return;
    s.value = value;
    front.heap.push_back(Heap_item{ value, s.vertex });
    std::push_heap(front.heap.begin(), front.heap.end());
  }

  // The seed face's corners get their straight-line distances in the face's plane.
  void start(std::size_t i)
  {
    Front& front = m_fronts[i];
    front.started = true;
    const Marching_seed& s = m_seeds[i];
    const auto& t = m_mesh.triangles[s.face];
    const Vector_3d p = m_mesh.point_at(s.face, s.barycentric);
    for(int k = 0; k < 3; ++k)
      propose(front, t[k], length(difference(m_mesh.points[t[k]], p)));
  }

  // accepts the front's nearest vertex and updates its neighbours; returns it
  std::uint32_t pop(std::size_t i)
  {
    Front& front = m_fronts[i];
    while(!front.heap.empty())
    {
      std::pop_heap(front.heap.begin(), front.heap.end());
      const Heap_item top = front.heap.back();
      front.heap.pop_back();
      Slot& s = front.find_or_insert(top.vertex);
      if(s.accepted || top.value != s.value) continue;   // a stale copy
      s.accepted = true;
      ++accepted_vertices;
      update_around(front, top.vertex, top.value);
      return top.vertex;
    }
    return Fast_marching_mesh::none;
  }

  static double accepted_value(const Front& front, std::uint32_t v)
  {
    const Slot* s = front.find(v);
    return (s && s->accepted) ? s->value : std::numeric_limits<double>::quiet_NaN();
  }
  static bool is_accepted(const Front& front, std::uint32_t v)
  {
    const Slot* s = front.find(v);
    return s && s->accepted;
  }

  void update_around(Front& front, std::uint32_t a, double da)
  {
    for(std::uint32_t r = m_mesh.ring_offsets[a]; r < m_mesh.ring_offsets[a + 1]; ++r)
    {
      const Fast_marching_mesh::Ring_face& rf = m_mesh.ring[r];
      update_corner(front, da, rf.next, rf.prev, rf.a_next, rf.a_prev, rf.opposite, rf.split_next);
      update_corner(front, da, rf.prev, rf.next, rf.a_prev, rf.a_next, rf.opposite, rf.split_prev);
    }
    // `a` may be the split vertex of obtuse corners elsewhere
    for(std::uint32_t r = m_mesh.vertex_split_offsets[a]; r < m_mesh.vertex_split_offsets[a + 1]; ++r)
    {
      const Fast_marching_mesh::Split& s = m_mesh.splits[m_mesh.vertex_splits[r]];
      const std::uint32_t c = m_mesh.triangles[s.face][s.corner];
      if(!is_accepted(front, c)) propose(front, c, split_update(front, s));
    }
  }

  // updates corner c of a face (a, b, c) from a, just accepted with value da
  void update_corner(Front& front, double da, std::uint32_t c, std::uint32_t b, double ac, double ab, double bc,
                     std::uint32_t split)
  {
    // one probe for c: the slot found here stays valid, the lookups below do not insert
    Slot& sc = front.find_or_insert(c);
    if(sc.accepted) return;
    double best = da + ac;
    const double db = accepted_value(front, b);
    if(db == db) best = (std::min)(best, point_source_update(ab, ac, bc, da, db));
    if(split != Fast_marching_mesh::none) best = (std::min)(best, split_update(front, m_mesh.splits[split]));
    lower(front, sc, best);
  }

  // the updates of an obtuse corner through its two acute virtual triangles (c, a, d), (c, d, b)
  double split_update(const Front& front, const Fast_marching_mesh::Split& s) const
  {
    const auto& t = m_mesh.triangles[s.face];
    const double dd = accepted_value(front, s.vertex);
    if(!(dd == dd)) return std::numeric_limits<double>::infinity();
    const double da = accepted_value(front, t[(s.corner + 1) % 3]);
    const double db = accepted_value(front, t[(s.corner + 2) % 3]);
    const Vector_2d origin = {{ 0., 0. }};
    double best = dd + std::sqrt(s.d[0] * s.d[0] + s.d[1] * s.d[1]);
    if(da == da) best = (std::min)(best, point_source_update(s.a, s.d, origin, da, dd));
    if(db == db) best = (std::min)(best, point_source_update(s.d, s.b, origin, dd, db));
    return best;
  }

  const Fast_marching_mesh& m_mesh;
  std::vector<Marching_seed> m_seeds;
  std::vector<Front> m_fronts;
};

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif
