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

struct Propagation_statistics
{
  std::size_t events = 0;
  std::size_t admitted = 0;
  std::size_t pruned = 0;
};

/// Computes the candidate lists. `blocked(f, k)` says whether fields may not cross local
/// edge k of face f (breaklines); border edges are never crossed. `banned(site, f)` lists
/// (site, face) pairs excluded by the connectivity repair.
template <class TriangleMesh, class Fields, class Blocked, class Banned>
void propagate(const Indexed_mesh<TriangleMesh>& mesh,
               const Fields& fields,
               const std::vector<std::size_t>& site_faces,
               const Blocked& blocked,
               const Banned& banned,
               std::vector<std::vector<Face_field> >& candidates,
               Propagation_statistics& stats)
{
  const std::size_t nf = mesh.number_of_faces();
  candidates.assign(nf, std::vector<Face_field>());
  std::vector<std::vector<std::uint32_t> > tested(nf);

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
  std::priority_queue<Event, std::vector<Event>, Later> queue;

  auto make_event = [&](std::uint32_t site, std::size_t face) {
    Event e;
    e.site = site;
    e.face = static_cast<std::uint32_t>(face);
    for(int k = 0; k < 3; ++k)
      e.value[k] = fields.value(site, mesh.triangles[face][k]);
    e.key = (std::min)((std::min)(e.value[0], e.value[1]), e.value[2]);
    return e;
  };

  for(std::size_t i = 0; i < site_faces.size(); ++i)
  {
    const std::size_t f = site_faces[i];
    if(banned(i, f))
      continue;
    tested[f].push_back(static_cast<std::uint32_t>(i));
    queue.push(make_event(static_cast<std::uint32_t>(i), f));
  }

  while(!queue.empty())
  {
    const Event e = queue.top();
    queue.pop();
    ++stats.events;
    const Face_field x = { e.site, e.value };
    std::vector<Face_field>& list = candidates[e.face];
    bool pruned = false;
    for(const Face_field& b : list)
      if(dominates(b, x)) { pruned = true; break; }
    if(pruned)
    {
      ++stats.pruned;
      continue;
    }
    list.push_back(x);
    ++stats.admitted;
    for(int k = 0; k < 3; ++k)
    {
      const std::size_t g = mesh.neighbors[e.face][k];
      if(g == Indexed_mesh<TriangleMesh>::none || blocked(e.face, k))
        continue;
      std::vector<std::uint32_t>& t = tested[g];
      if(std::find(t.begin(), t.end(), e.site) != t.end())
        continue;
      t.push_back(e.site);
      if(banned(e.site, g))
        continue;
      queue.push(make_event(e.site, g));
    }
  }

  // Cutting and stitching iterate candidates in site order, so results do not depend on
  // the order in which fields arrived.
  // A field admitted early may be dominated by one admitted later: it cannot win any area,
  // so drop it before cutting.
  for(std::vector<Face_field>& list : candidates)
  {
    if(list.size() > 1)
    {
      std::vector<Face_field> kept;
      kept.reserve(list.size());
      for(const Face_field& x : list)
      {
        bool dominated = false;
        for(const Face_field& b : list)
          if(b.site != x.site && dominates(b, x)) { dominated = true; break; }
        if(!dominated) kept.push_back(x);
      }
      list.swap(kept);
    }
    std::sort(list.begin(), list.end(), [](const Face_field& a, const Face_field& b) { return a.site < b.site; });
  }
}

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif
