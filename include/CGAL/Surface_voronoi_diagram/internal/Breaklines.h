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
// The breaklines of a diagram: mesh edges no cell crosses (the named parameter
// `edge_is_constrained_map`), by global edge index.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_BREAKLINES_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_BREAKLINES_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/internal/Indexed_mesh.h>
#include <CGAL/Surface_voronoi_diagram/internal/Partition.h>
#include <CGAL/Surface_voronoi_diagram/internal/Site.h>

#include <algorithm>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

class Breaklines
{
public:
  Breaklines() {}

  /// reads the map edge -> bool for every edge of `mesh`
  template <class TriangleMesh, class EdgeIsConstrainedMap>
  Breaklines(const Indexed_mesh<TriangleMesh>& mesh, const TriangleMesh& tm, const EdgeIsConstrainedMap& ecm)
    : m_number_of_vertices(mesh.number_of_vertices())
  {
    m_blocked.assign(mesh.number_of_edges(), 0);
    for(std::size_t f = 0; f < mesh.number_of_faces(); ++f)
    {
      auto h = halfedge(mesh.face_handles[f], tm);
      for(int k = 0; k < 3; ++k, h = next(h, tm))
        if(get(ecm, edge(h, tm))) m_blocked[mesh.edges[f][k]] = 1;
    }
    for(std::size_t e = 0; e < mesh.number_of_edges(); ++e)
      if(m_blocked[e]) m_corner_edge[mesh.edge_vertices[e][0] * m_number_of_vertices + mesh.edge_vertices[e][1]] = e;
    // no breakline: `is_blocked()` then answers without touching a per-edge array (a cache
    // miss per propagation step on a large mesh)
    if(empty()) std::vector<std::uint8_t>().swap(m_blocked);
  }

  bool empty() const { return m_corner_edge.empty(); }
  std::size_t size() const { return m_corner_edge.size(); }
  bool is_blocked(std::size_t edge) const { return !m_blocked.empty() && m_blocked[edge] != 0; }

  /// whether the partition vertices `u` and `w` both lie on one breakline edge of the mesh
  template <class TriangleMesh>
  bool joins(const Indexed_mesh<TriangleMesh>& mesh, const Partition& partition, std::size_t u, std::size_t w) const
  {
    if(empty()) return false;
    const Partition::Vertex& a = partition.vertices[u];
    const Partition::Vertex& b = partition.vertices[w];
    if(a.kind == Partition::IN_FACE || b.kind == Partition::IN_FACE) return false;
    const std::size_t e = (a.kind == Partition::ON_EDGE) ? a.element : (b.kind == Partition::ON_EDGE ? b.element : no_site);
    double t;
    if(e != no_site) return is_blocked(e) && partition.on_mesh_edge(mesh, u, e, t) && partition.on_mesh_edge(mesh, w, e, t);
    // two corners: the mesh edge joining them, if any
    const auto it = m_corner_edge.find((std::min)(a.element, b.element) * m_number_of_vertices + (std::max)(a.element, b.element));
    return it != m_corner_edge.end() && is_blocked(it->second);
  }

  /// The faces where the sites on breaklines start, as (site, face) pairs sorted by site then
  /// face, their own face among them. A site on a breakline edge starts on both sides of the
  /// edge; a site at a vertex where a breakline passes or ends starts in every face around
  /// the vertex. Such a site owns what is nearest to it on every side, and its cell is one
  /// cell through its location. A site is on an edge or at a vertex when its barycentric
  /// coordinates are exactly 0 there (as `feature_line_sites()` makes them).
  template <class TriangleMesh>
  std::vector<std::pair<std::size_t, std::size_t> > faces_of_sites_on_breaklines(const Indexed_mesh<TriangleMesh>& mesh,
                                                                          const std::vector<Site>& sites) const
  {
    std::vector<std::pair<std::size_t, std::size_t> > out;
    if(empty()) return out;
    std::vector<std::size_t> fan;
    for(std::size_t i = 0; i < sites.size(); ++i)
    {
      const Site& s = sites[i];
      int zeros = 0, zero = -1, one = -1;
      for(int c = 0; c < 3; ++c)
      {
        if(s.barycentric[c] == 0.) ++zeros, zero = c;
        else one = c;
      }
      if(zeros == 1)
      {
        const int k = (zero + 1) % 3;   // the local edge opposite the zero corner
        const auto g = mesh.neighbors[s.face][k];
        if(g == Indexed_mesh<TriangleMesh>::none || !is_blocked(mesh.edges[s.face][k])) continue;
        out.emplace_back(i, s.face);
        out.emplace_back(i, g);
      }
      else if(zeros == 2)
      {
        const std::size_t v = mesh.triangles[s.face][one];
        faces_around(mesh, s.face, v, fan);
        bool touches_breakline = false;
        for(std::size_t f : fan)
        {
          const int c = mesh.corner_of(f, v);
          touches_breakline |= is_blocked(mesh.edges[f][c]) || is_blocked(mesh.edges[f][(c + 2) % 3]);
        }
        if(!touches_breakline) continue;
        for(std::size_t f : fan) out.emplace_back(i, f);
      }
    }
    std::sort(out.begin(), out.end());
    return out;
  }

private:
  // the faces around vertex v, from face f, turning both ways until the fan closes or ends
  template <class TriangleMesh>
  static void faces_around(const Indexed_mesh<TriangleMesh>& mesh, std::size_t f, std::size_t v, std::vector<std::size_t>& fan)
  {
    fan.assign(1, f);
    for(int way = 0; way < 2; ++way)
      for(std::size_t g = f;;)
      {
        const int c = mesh.corner_of(g, v);
        const auto h = mesh.neighbors[g][way == 0 ? c : (c + 2) % 3];
        if(h == Indexed_mesh<TriangleMesh>::none) break;
        if(h == f || fan.size() > mesh.number_of_faces()) return;   // a closed fan
        fan.push_back(h);
        g = h;
      }
  }

  std::vector<std::uint8_t> m_blocked;                      // by global edge
  std::unordered_map<std::size_t, std::size_t> m_corner_edge;   // blocked edges by their sorted vertex pair
  std::size_t m_number_of_vertices = 0;
};

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_BREAKLINES_H
