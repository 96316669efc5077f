// Copyright (c) 2026 The Surface_voronoi_diagram authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Propagation (SurfaceVoronoi, stage 1): for every face, the sites whose distance field can
// win somewhere in it. A site's field enters a face only from a face where it was admitted,
// so a site never appears on the far side of a wall it cannot reach along the surface.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_PROPAGATION_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_PROPAGATION_H

#include <CGAL/Surface_voronoi_diagram/internal/Indexed_mesh.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <queue>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

/// A site's field on one face: its values D at the three corners.
struct Face_field
{
  std::uint32_t site;
  std::array<double, 3> value;
};

/// (value, site) compared lexicographically: ties go to the lower site index everywhere,
/// which is the symbolic perturbation that makes both sides of every edge agree.
inline bool lexicographically_less(double a, std::uint32_t i, double b, std::uint32_t j)
{
  return a < b || (a == b && i < j);
}

inline bool dominates(const Face_field& b, const Face_field& x)
{
  for(int k = 0; k < 3; ++k)
    if(!lexicographically_less(b.value[k], b.site, x.value[k], x.site))
      return false;
  return true;
}

/// Drops the fields dominated by another one (they cannot win any area) and sorts by site,
/// so that cutting does not depend on the order in which fields arrived.
inline void clean_candidate_list(std::vector<Face_field>& list)
{
  if(list.size() > 1)
  {
    std::size_t kept = 0;
    for(std::size_t a = 0; a < list.size(); ++a)
    {
      bool dominated = false;
      for(std::size_t b = 0; b < list.size() && !dominated; ++b)
        dominated = (b != a) && dominates(list[b], list[a]);
      if(!dominated) list[kept++] = list[a];
    }
    list.resize(kept);
    std::sort(list.begin(), list.end(), [](const Face_field& a, const Face_field& b) { return a.site < b.site; });
  }
}

struct Propagation_statistics
{
  std::size_t events = 0;
  std::size_t admitted = 0;
  std::size_t pruned = 0;
};

/// An open-addressing set of 64-bit keys: which (site, face) pairs were offered already.
/// One flat table instead of a vector per face keeps propagation free of small allocations.
class Key_set
{
public:
  explicit Key_set(std::size_t expected = 1024) { reset(expected); }

  void reset(std::size_t expected)
  {
    std::size_t capacity = 1024;
    while(capacity < 2 * expected) capacity *= 2;
    m_keys.assign(capacity, empty);
    m_size = 0;
  }

  /// inserts `key`; returns false if it was there
  bool insert(std::uint64_t key)
  {
    if(2 * (m_size + 1) > m_keys.size()) grow();
    std::size_t i = slot(key);
    while(m_keys[i] != empty)
    {
      if(m_keys[i] == key) return false;
      i = (i + 1) & (m_keys.size() - 1);
    }
    m_keys[i] = key;
    ++m_size;
    return true;
  }

private:
  static constexpr std::uint64_t empty = ~std::uint64_t(0);
  std::size_t slot(std::uint64_t key) const
  {
    key ^= key >> 33;
    key *= 0xff51afd7ed558ccdull;
    key ^= key >> 33;
    return static_cast<std::size_t>(key) & (m_keys.size() - 1);
  }
  void grow()
  {
    std::vector<std::uint64_t> old;
    old.swap(m_keys);
    m_keys.assign(old.size() * 2, empty);
    m_size = 0;
    for(std::uint64_t k : old)
      if(k != empty) insert(k);
  }
  std::vector<std::uint64_t> m_keys;
  std::size_t m_size = 0;
};

/// The propagation and its state, so that the connectivity repair can re-run it locally.
template <class TriangleMesh, class Fields, class Blocked>
class Propagation
{
public:
  typedef Indexed_mesh<TriangleMesh> Mesh;

  Propagation(const Mesh& mesh, const Fields& fields, const std::vector<std::size_t>& site_faces,
              const Blocked& blocked)
    : m_mesh(mesh), m_fields(fields), m_site_faces(site_faces), m_blocked(blocked),
      m_epoch(mesh.number_of_faces(), 0)
  {}

  std::vector<std::vector<Face_field> > candidates;
  Propagation_statistics statistics;

  /// the first propagation, from every site
  void run()
  {
    candidates.assign(m_mesh.number_of_faces(), std::vector<Face_field>());
    m_tested.reset(8 * m_mesh.number_of_faces());
    for(std::size_t i = 0; i < m_site_faces.size(); ++i)
      offer(static_cast<std::uint32_t>(i), m_site_faces[i]);
    auto no_ban = [](std::size_t, std::size_t) { return false; };
    drain(no_ban, nullptr);
    for(std::vector<Face_field>& list : candidates) clean_candidate_list(list);
  }

  /// After the repair banned (site, face) pairs: the banned fields are removed from the
  /// `dirty` faces, whose lists are then refilled from their neighbours' fields, and the
  /// propagation goes on from there. `touched` receives every face whose list changed.
  template <class Banned>
  void repropagate(const std::vector<std::size_t>& dirty, const Banned& banned, std::vector<std::size_t>& touched)
  {
    std::vector<std::uint8_t> is_touched(m_mesh.number_of_faces(), 0);
    for(std::size_t f : dirty)
    {
      std::vector<Face_field>& list = candidates[f];
      list.erase(std::remove_if(list.begin(), list.end(), [&](const Face_field& x) { return banned(x.site, f); }),
                 list.end());
      ++m_epoch[f];   // forget what was offered to f: everything may be offered again
      is_touched[f] = 1;
    }
    for(std::size_t f : dirty)
    {
      for(const Face_field& x : candidates[f]) m_tested.insert(key(x.site, f));
      for(int k = 0; k < 3; ++k)
      {
        const std::size_t g = m_mesh.neighbors[f][k];
        if(g == Mesh::none || m_blocked(f, k)) continue;
        for(const Face_field& x : candidates[g])
          if(!banned(x.site, f)) offer(x.site, f);
      }
    }
    for(std::size_t i = 0; i < m_site_faces.size(); ++i)
      if(is_touched[m_site_faces[i]] && !banned(i, m_site_faces[i]))
        offer(static_cast<std::uint32_t>(i), m_site_faces[i]);
    drain(banned, &is_touched);
    touched.clear();
    for(std::size_t f = 0; f < is_touched.size(); ++f)
      if(is_touched[f])
      {
        clean_candidate_list(candidates[f]);
        touched.push_back(f);
      }
  }

private:
  struct Event
  {
    double key;
    std::uint32_t site;
    std::uint32_t face;
    std::array<double, 3> value;
  };
  struct Later
  {
    bool operator()(const Event& a, const Event& b) const
    {
      if(a.key != b.key) return a.key > b.key;
      if(a.site != b.site) return a.site > b.site;
      return a.face > b.face;
    }
  };

  std::uint64_t key(std::uint32_t site, std::size_t face) const
  {
    return (std::uint64_t(site) * m_mesh.number_of_faces() + face) * 256 + (m_epoch[face] & 255);
  }

  // offers the field of `site` to face `f`, once per (site, face) and epoch
  void offer(std::uint32_t site, std::size_t f)
  {
    if(!m_tested.insert(key(site, f))) return;
    Event e;
    e.site = site;
    e.face = static_cast<std::uint32_t>(f);
    for(int k = 0; k < 3; ++k)
      e.value[k] = m_fields.value(site, m_mesh.triangles[f][k]);
    // lists only grow: a field dominated now stays dominated, so do not queue it
    const Face_field x = { e.site, e.value };
    for(const Face_field& b : candidates[f])
      if(dominates(b, x)) { ++statistics.pruned; return; }
    e.key = (std::min)((std::min)(e.value[0], e.value[1]), e.value[2]);
    m_queue.push(e);
  }

  template <class Banned>
  void drain(const Banned& banned, std::vector<std::uint8_t>* touched)
  {
    while(!m_queue.empty())
    {
      const Event e = m_queue.top();
      m_queue.pop();
      ++statistics.events;
      const Face_field x = { e.site, e.value };
      std::vector<Face_field>& list = candidates[e.face];
      bool pruned = false;
      for(const Face_field& b : list)
        if(dominates(b, x)) { pruned = true; break; }
      if(pruned)
      {
        ++statistics.pruned;
        continue;
      }
      list.push_back(x);
      ++statistics.admitted;
      if(touched) (*touched)[e.face] = 1;
      for(int k = 0; k < 3; ++k)
      {
        const std::size_t g = m_mesh.neighbors[e.face][k];
        if(g == Mesh::none || m_blocked(e.face, k) || banned(e.site, g)) continue;
        offer(e.site, g);
      }
    }
  }

  const Mesh& m_mesh;
  const Fields& m_fields;
  const std::vector<std::size_t>& m_site_faces;
  Blocked m_blocked;
  std::vector<std::uint32_t> m_epoch;
  Key_set m_tested;
  std::priority_queue<Event, std::vector<Event>, Later> m_queue;
};

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif
