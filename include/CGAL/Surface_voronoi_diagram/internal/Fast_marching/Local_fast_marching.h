// Copyright (c) 2026 The Surface_voronoi_diagram authors.
// All rights reserved.
//
// This file is part of the Surface_voronoi_diagram package for CGAL (www.cgal.org).
//
// $URL$
// $Id$
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : The Surface_voronoi_diagram authors
//
// Geodesic distances from many sites, each computed only as far as it is asked for.
//
// Every site owns a fast-marching front that is advanced on demand: asking for the distance
// of site i at vertex v marches site i's front until v is accepted, and no further. The
// diagram asks only for the vertices around the faces a site propagates into, so the work
// is about a few geodesic balls of cell size per site: it grows with the mesh, not with
// mesh x sites. A front's sequence of accepted vertices does not depend on when it is
// advanced, so the values (and the diagram) are the same whatever order the queries come in.
// Triangles obtuse at the updated vertex also take the update through their split vertex,
// so that values there are not left to edge paths.
// Queries may come from several threads: each front has a lock of its own, so threads asking
// for different sites do not wait for each other, and two asking for one site take turns (the
// values are the same in any order, see above).

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_FAST_MARCHING_LOCAL_FAST_MARCHING_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_FAST_MARCHING_LOCAL_FAST_MARCHING_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/internal/Double_kernel.h>
#include <CGAL/Surface_voronoi_diagram/internal/Flat_hash_table.h>
#include <CGAL/Surface_voronoi_diagram/internal/Fast_marching/Fast_marching_mesh.h>
#include <CGAL/Surface_voronoi_diagram/internal/Fast_marching/point_source_update.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <mutex>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

/// A site's start: a point in a face, given by barycentric coordinates.
struct Marching_seed
{
  std::uint32_t face = 0;
  Barycentric barycentric = {{ 1., 0., 0. }};
};

/// Lazily advanced fast-marching fronts, one per site, over a shared `Fast_marching_mesh`.
template <class TriangleMesh>
class Local_fast_marching
{
public:
  typedef Fast_marching_mesh<TriangleMesh> Marching_mesh;

  explicit Local_fast_marching(const Marching_mesh& mesh) : m_marching(mesh), m_mesh(mesh.mesh()) {}

  /// a copy of the fronts, with locks of its own
  Local_fast_marching(const Local_fast_marching& other)
    : m_marching(other.m_marching), m_mesh(other.m_mesh), m_seeds(other.m_seeds), m_fronts(other.m_fronts),
      m_locks(new std::mutex[other.m_seeds.size()]), m_forgotten_accepted(other.m_forgotten_accepted)
  {}
  Local_fast_marching& operator=(const Local_fast_marching&) = delete;

  void set_seeds(const std::vector<Marching_seed>& seeds)
  {
    m_seeds = seeds;
    m_fronts.assign(seeds.size(), Front());
    m_locks.reset(new std::mutex[seeds.size()]);
    m_forgotten_accepted = 0;
  }

  std::size_t number_of_seeds() const { return m_seeds.size(); }

  /// Frees every front (no query may run meanwhile). A later query marches its site's front
  /// again from the seed, which gives the same values: a front's sequence of accepted vertices
  /// is fixed by the mesh.
  void forget_fronts()
  {
    m_forgotten_accepted = accepted_vertices();
    std::vector<Front>(m_seeds.size()).swap(m_fronts);
  }

  /// the work done since `set_seeds()`, for the statistics: the vertices accepted by all the
  /// fronts, forgotten ones included (no query may run meanwhile)
  std::size_t accepted_vertices() const
  {
    std::size_t n = m_forgotten_accepted;
    for(const Front& front : m_fronts) n += front.accepted;
    return n;
  }

  /// the geodesic distance from site `i` to vertex `v`; +infinity if `v` cannot be reached.
  /// Threads may ask at once.
  double distance(std::size_t i, std::uint32_t v)
  {
    const std::lock_guard<std::mutex> guard(m_locks[i]);
    Front& front = m_fronts[i];
    if(const Slot* s = front.values.find(v))
      if(s->accepted()) return s->value();
    if(!front.started) start(i);
    while(!front.heap.empty())
      if(pop(i) == v) return front.values.find(v)->value();
    return std::numeric_limits<double>::infinity();
  }

  /// the geodesic distance from site `i` to the point of `face` with barycentric coordinates
  /// `b`: straight in the plane of the site's own face, otherwise the point-source update
  /// from each edge of the face, or a path through a corner
  double distance_at(std::size_t i, std::uint32_t face, const Barycentric& b)
  {
    if(face == m_seeds[i].face)
      return std::sqrt((m_mesh.point_at(face, m_seeds[i].barycentric) - m_mesh.point_at(face, b)).squared_length());
    std::array<double, 3> d;
    for(int k = 0; k < 3; ++k) d[k] = distance(i, m_marching.vertex(face, k));
    // the face in its plane: corner 0 at the origin, corner 1 on the x axis
    const Vector_d e1 = m_mesh.corner(face, 1) - m_mesh.corner(face, 0), e2 = m_mesh.corner(face, 2) - m_mesh.corner(face, 0);
    const double l1 = std::sqrt(e1.squared_length());
    const double c2x = (e2 * e1) / l1, c2y = std::sqrt((std::max)(0., e2 * e2 - c2x * c2x));
    const std::array<Point_2d, 3> q = {{ Point_2d(0., 0.), Point_2d(l1, 0.), Point_2d(c2x, c2y) }};
    const Point_2d p(b[1] * l1 + b[2] * c2x, b[2] * c2y);
    double best = std::numeric_limits<double>::infinity();
    for(int k = 0; k < 3; ++k)
    {
      const double dx = p.x() - q[k].x(), dy = p.y() - q[k].y();
      best = (std::min)(best, d[k] + std::sqrt(dx * dx + dy * dy));
      best = (std::min)(best, point_source_update(q[k], q[(k + 1) % 3], p, d[k], d[(k + 1) % 3]));
    }
    return best;
  }

private:
  // A vertex's value in a front, 12 bytes where a bool beside a double would take 16: the
  // double is kept in two 4-byte words, and negated once the vertex is accepted (values are
  // never negative; the sign bit of 0 is kept as well).
  struct Slot
  {
    std::uint32_t key;      // the vertex
    std::uint32_t bits[2];

    double stored() const { double v; std::memcpy(&v, bits, sizeof v); return v; }
    void store(double v) { std::memcpy(bits, &v, sizeof v); }
    bool accepted() const { return std::signbit(stored()); }
    double value() const { return std::fabs(stored()); }
    void accept() { store(-value()); }
  };
  static_assert(sizeof(double) == 2 * sizeof(std::uint32_t), "a double is kept in two 32-bit words");
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

  // One front: its heap and its vertices' values. A small table per site stays in cache,
  // where one table keyed by (site, vertex) for all sites does not.
  struct Front
  {
    bool started = false;
    std::size_t accepted = 0;   // vertices accepted, for the statistics
    std::vector<Heap_item> heap;
    Flat_hash_table<Slot> values;

    Slot& find_or_insert(std::uint32_t v)
    {
      Slot fresh;
      fresh.key = v;
      fresh.store(std::numeric_limits<double>::infinity());
      return *values.insert(v, fresh).first;
    }
  };

  void propose(Front& front, std::uint32_t v, double value)
  {
    Slot& s = front.find_or_insert(v);
    if(!s.accepted()) lower(front, s, value);
  }

  // lowers the tentative value of a vertex not accepted yet, and queues it
  static void lower(Front& front, Slot& s, double value)
  {
    if(!(value < s.value())) return;
    s.store(value);
    front.heap.push_back(Heap_item{ value, s.key });
    std::push_heap(front.heap.begin(), front.heap.end());
  }

  // The seed face's corners get their straight-line distances in the face's plane.
  void start(std::size_t i)
  {
    Front& front = m_fronts[i];
    front.started = true;
    const Marching_seed& s = m_seeds[i];
    const Point_d p = m_mesh.point_at(s.face, s.barycentric);
    for(int k = 0; k < 3; ++k)
      propose(front, m_marching.vertex(s.face, k), std::sqrt((p - m_mesh.corner(s.face, k)).squared_length()));
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
      if(s.accepted() || top.value != s.value()) continue;   // a stale copy
      s.accept();
      ++front.accepted;
      update_around(front, top.vertex, top.value);
      return top.vertex;
    }
    return Marching_mesh::none;
  }

  static double accepted_value(const Front& front, std::uint32_t v)
  {
    const Slot* s = front.values.find(v);
    return (s && s->accepted()) ? s->value() : std::numeric_limits<double>::quiet_NaN();
  }
  static bool is_accepted(const Front& front, std::uint32_t v) { return !std::isnan(accepted_value(front, v)); }

  void update_around(Front& front, std::uint32_t a, double da)
  {
    const std::uint32_t begin = m_marching.ring_offsets[a], end = m_marching.ring_offsets[a + 1];
    // two slots per face around `a`, found once for both of its updates: room for them now,
    // so that the slots stay valid through the loop
    front.values.reserve_more(2 * std::size_t(end - begin));
    for(std::uint32_t r = begin; r < end; ++r)
    {
      const std::uint32_t corner = m_marching.ring[r];
      const std::uint32_t f = Marching_mesh::face_of_corner(corner);
      const int k = Marching_mesh::local_corner(corner), kn = (k + 1) % 3, kp = (k + 2) % 3;
      const typename Marching_mesh::Face_record& rf = m_marching.faces[f];
      // local edge k joins a to next, kp joins prev to a, kn is opposite a
      const double a_next = rf.edge_length[k], a_prev = rf.edge_length[kp], opposite = rf.edge_length[kn];
      Slot& next = front.find_or_insert(m_marching.vertex(f, kn));
      Slot& prev = front.find_or_insert(m_marching.vertex(f, kp));
      update_corner(front, da, next, prev, a_next, a_prev, opposite, rf.split[kn]);
      update_corner(front, da, prev, next, a_prev, a_next, opposite, rf.split[kp]);
    }
    // `a` may be the split vertex of obtuse corners elsewhere
    for(std::uint32_t r = m_marching.vertex_split_offsets[a]; r < m_marching.vertex_split_offsets[a + 1]; ++r)
    {
      const typename Marching_mesh::Split& s = m_marching.splits[m_marching.vertex_splits[r]];
      const std::uint32_t c = m_marching.vertex(s.face, int(s.corner));
      if(!is_accepted(front, c)) propose(front, c, split_update(front, s));
    }
  }

  // updates corner c of a face (a, b, c) from a, just accepted with value da
  void update_corner(Front& front, double da, Slot& c, const Slot& b, double ac, double ab, double bc, std::uint32_t split)
  {
    if(c.accepted()) return;
    double best = da + ac;
    if(b.accepted()) best = (std::min)(best, point_source_update(ab, ac, bc, da, b.value()));
    if(split != Marching_mesh::none) best = (std::min)(best, split_update(front, m_marching.splits[split]));
    lower(front, c, best);
  }

  // the updates of an obtuse corner through its two acute virtual triangles (c, a, d), (c, d, b)
  double split_update(const Front& front, const typename Marching_mesh::Split& s) const
  {
    const double dd = accepted_value(front, s.vertex);
    if(!(dd == dd)) return std::numeric_limits<double>::infinity();
    const double da = accepted_value(front, m_marching.vertex(s.face, int((s.corner + 1) % 3)));
    const double db = accepted_value(front, m_marching.vertex(s.face, int((s.corner + 2) % 3)));
    const Point_2d origin(0., 0.);
    double best = dd + std::sqrt(s.d.x() * s.d.x() + s.d.y() * s.d.y());
    if(da == da) best = (std::min)(best, point_source_update(s.a, s.d, origin, da, dd));
    if(db == db) best = (std::min)(best, point_source_update(s.d, s.b, origin, dd, db));
    return best;
  }

  const Marching_mesh& m_marching;
  const Indexed_mesh<TriangleMesh>& m_mesh;
  std::vector<Marching_seed> m_seeds;
  std::vector<Front> m_fronts;
  std::unique_ptr<std::mutex[]> m_locks;      // one a front
  std::size_t m_forgotten_accepted = 0;      // by the fronts freed since set_seeds()
};

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_FAST_MARCHING_LOCAL_FAST_MARCHING_H
