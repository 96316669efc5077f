// Copyright (c) 2026 The Surface_voronoi_diagram authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// "One site, one region": the connected pieces of every cell. Propagation keeps far-away
// islands out but does not by itself make cells connected (a site admitted in a face where
// it wins nothing can still win beyond it), so the diagram checks and repairs.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_CONNECTIVITY_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_CONNECTIVITY_H

#include <CGAL/Surface_voronoi_diagram/internal/stitching.h>

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

struct Cell_components
{
  std::vector<std::size_t> piece_component;            // component id of each piece
  std::vector<std::size_t> component_site;             // site of each component (no_site allowed)
  std::vector<double> component_area;
  std::vector<std::vector<std::size_t> > site_components;  // components of each site
};

/// Pieces of one site are connected when they share a piece edge (a positive-length
/// segment), except across a blocked mesh edge (a breakline).
template <class TriangleMesh, class Blocked_edge>
Cell_components cell_components(const Indexed_mesh<TriangleMesh>& mesh, const Partition& partition,
                                std::size_t number_of_sites, const Blocked_edge& blocked_edge)
{
  const std::size_t np = partition.pieces.size();
  std::vector<std::size_t> parent(np);
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  auto find = [&](std::size_t x) {
    while(parent[x] != x) { parent[x] = parent[parent[x]]; x = parent[x]; }
    return x;
  };
  auto unite = [&](std::size_t a, std::size_t b) {
    a = find(a); b = find(b);
    if(a != b) parent[(std::max)(a, b)] = (std::min)(a, b);
  };
  auto on_blocked_edge = [&](std::size_t u, std::size_t w, std::size_t f) {
    for(int k = 0; k < 3; ++k)
    {
      const std::size_t e = mesh.edges[f][k];
      if(!blocked_edge(e)) continue;
      auto on = [&](std::size_t id) {
        const Partition::Vertex& v = partition.vertices[id];
        if(v.kind == Partition::AT_CORNER) return v.element == mesh.edge_vertices[e][0] || v.element == mesh.edge_vertices[e][1];
        return v.kind == Partition::ON_EDGE && v.element == e;
      };
      if(on(u) && on(w)) return true;
    }
    return false;
  };

  std::unordered_map<std::uint64_t, std::size_t> first_piece;
  first_piece.reserve(np * 2);
  const std::uint64_t nv = partition.vertices.size();
  for(std::size_t p = 0; p < np; ++p)
  {
    const Partition::Piece& piece = partition.pieces[p];
    const std::size_t n = piece.vertices.size();
    for(std::size_t k = 0; k < n; ++k)
    {
      std::uint64_t u = piece.vertices[k], w = piece.vertices[(k + 1) % n];
      if(u > w) std::swap(u, w);
      auto r = first_piece.emplace(u * nv + w, p);
      if(r.second) continue;
      const std::size_t q = r.first->second;
      if(partition.pieces[q].site == piece.site && partition.pieces[q].face != piece.face
         && !on_blocked_edge(static_cast<std::size_t>(u), static_cast<std::size_t>(w), piece.face))
        unite(p, q);
    }
  }

  Cell_components cc;
  cc.piece_component.assign(np, 0);
  cc.site_components.assign(number_of_sites, std::vector<std::size_t>());
  std::vector<std::size_t> root_component(np, no_site);
  for(std::size_t p = 0; p < np; ++p)
  {
    const std::size_t r = find(p);
    if(root_component[r] == no_site)
    {
      root_component[r] = cc.component_site.size();
      cc.component_site.push_back(partition.pieces[p].site);
      cc.component_area.push_back(0.);
      if(partition.pieces[p].site != no_site)
        cc.site_components[partition.pieces[p].site].push_back(root_component[r]);
    }
    cc.piece_component[p] = root_component[r];
    cc.component_area[root_component[r]] += partition.pieces[p].area;
  }
  return cc;
}

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif
