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
// "One site, one region": the connected pieces of every cell. Propagation keeps far-away
// islands out but does not by itself make cells connected (a site admitted in a face where
// it wins nothing can still win beyond it), so the diagram checks and repairs.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_CELL_COMPONENTS_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_CELL_COMPONENTS_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/internal/Disjoint_sets.h>
#include <CGAL/Surface_voronoi_diagram/internal/Indexed_mesh.h>
#include <CGAL/Surface_voronoi_diagram/internal/Partition.h>
#include <CGAL/Surface_voronoi_diagram/internal/unite_face_by_face.h>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

/// Calls `adjacent(p, q, e)` once for every pair of pieces sharing a piece edge with p < q
/// and p in a face of [first_face, last_face), where `e` is the mesh edge the shared edge
/// lies on, or `no_site` inside a face. Pieces only meet within a face or across one of its
/// edges, so the search stays local.
template <class TriangleMesh, class Callback>
void for_each_piece_adjacency(const Indexed_mesh<TriangleMesh>& mesh, const Partition& partition,
                              std::size_t first_face, std::size_t last_face, Callback adjacent)
{
  auto on_edge = [&](std::size_t id, std::size_t e) {
    const Partition::Vertex& v = partition.vertices[id];
    if(v.kind == Partition::AT_CORNER) return v.element == mesh.edge_vertices[e][0] || v.element == mesh.edge_vertices[e][1];
    return v.kind == Partition::ON_EDGE && v.element == e;
  };
  auto has_edge = [&](std::size_t q, std::size_t u, std::size_t w) {
    const Partition::Vertex_cycle& v = partition.pieces[q].vertices;
    for(std::size_t j = 0; j < v.size(); ++j)
      if(v[j] == u && v[(j + 1) % v.size()] == w) return true;
    return false;
  };
  auto is_whole_face = [&](std::size_t g) { return partition.face_begin[g + 1] == partition.face_begin[g] + 1; };
  for(std::size_t f = first_face; f < last_face; ++f)
  {
    // A face in one piece (most faces, when sites are fewer than faces) meets a neighbour in
    // one piece along the whole edge: no search through the pieces' vertices.
    if(is_whole_face(f))
    {
      const std::size_t p = partition.face_begin[f];
      bool all_whole = true;
      for(int k = 0; k < 3; ++k)
      {
        const std::size_t g = mesh.neighbors[f][k];
        all_whole = all_whole && (g == Indexed_mesh<TriangleMesh>::none || is_whole_face(g));
      }
      if(all_whole)
      {
        for(int k = 0; k < 3; ++k)
        {
          const std::size_t g = mesh.neighbors[f][k];
          if(g != Indexed_mesh<TriangleMesh>::none && partition.face_begin[g] > p) adjacent(p, partition.face_begin[g], mesh.edges[f][k]);
        }
        continue;
      }
    }
    for(std::size_t p = partition.face_begin[f]; p < partition.face_begin[f + 1]; ++p)
    {
      const Partition::Vertex_cycle& v = partition.pieces[p].vertices;
      for(std::size_t j = 0; j < v.size(); ++j)
      {
        const std::size_t u = v[j], w = v[(j + 1) % v.size()];
        // The piece across (u, w) owns (w, u): across the mesh edge both lie on, else in the
        // same face. Each pair is reported once, from its lower piece index; when the guided
        // search finds nothing (a border, or a vertex whose location is ambiguous), every
        // candidate piece is tried.
        int local = -1;
        for(int k = 0; k < 3 && local < 0; ++k)
          if(on_edge(u, mesh.edges[f][k]) && on_edge(w, mesh.edges[f][k])) local = k;
        bool found = false;
        auto search_face = [&](std::size_t q_begin, std::size_t q_end, std::size_t e) {
          for(std::size_t q = q_begin; q < q_end && !found; ++q)
            if(has_edge(q, w, u))
            {
              found = true;
              if(q > p) adjacent(p, q, e);
            }
        };
        // (a search once the piece is found does nothing)
        if(local >= 0 && mesh.neighbors[f][local] != Indexed_mesh<TriangleMesh>::none)
          search_face(partition.face_begin[mesh.neighbors[f][local]], partition.face_begin[mesh.neighbors[f][local] + 1],
                      mesh.edges[f][local]);
        search_face(partition.face_begin[f], partition.face_begin[f + 1], no_site);
        for(int k = 0; k < 3 && !found; ++k)
        {
          const std::size_t g = mesh.neighbors[f][k];
          if(g != Indexed_mesh<TriangleMesh>::none)
            search_face(partition.face_begin[g], partition.face_begin[g + 1], mesh.edges[f][k]);
        }
      }
    }
  }
}

struct Cell_components
{
  std::vector<std::size_t> piece_component;            // component id of each piece
  std::vector<std::size_t> component_site;             // site of each component (no_site allowed)
  std::vector<double> component_area;
  std::vector<std::vector<std::size_t> > site_components;  // components of each site
};

/// Pieces of one site are connected when they share a piece edge (a positive-length
/// segment), except across a blocked mesh edge (a breakline). If `site_pairs` is given, it
/// receives the sites of every two adjacent pieces of different sites (the same pass finds
/// the cells' neighbours). With `parallel`, the faces are searched in concurrent chunks whose
/// findings are merged in chunk order: the same components, numbered alike, and the same
/// pairs in the same order (a union's representative is the set's smallest piece, whatever
/// the order of the unions).
template <class TriangleMesh, class Blocked_edge>
Cell_components cell_components(const Indexed_mesh<TriangleMesh>& mesh, const Partition& partition,
                                std::size_t number_of_sites, const Blocked_edge& blocked_edge,
                                std::vector<std::pair<std::size_t, std::size_t> >* site_pairs = nullptr,
                                bool parallel = false,
                                const std::vector<std::pair<std::size_t, std::size_t> >* breakline_site_faces = nullptr)
{
  const std::size_t np = partition.pieces.size();
  Disjoint_sets pieces_of_a_cell(np);
  if(site_pairs) site_pairs->clear();
  unite_face_by_face(mesh.number_of_faces(), parallel, pieces_of_a_cell, site_pairs,
                     [&](std::size_t begin, std::size_t end, Union_sink& out) {
    for_each_piece_adjacency(mesh, partition, begin, end, [&](std::size_t p, std::size_t q, std::size_t e) {
      if(partition.pieces[p].site != partition.pieces[q].site)
        out.pair(partition.pieces[p].site, partition.pieces[q].site);
      else if(e == no_site || !blocked_edge(e))
        out.unite(p, q);
    });
  });
  // a site on a breakline: its pieces around its location are one component through it
  if(breakline_site_faces)
  {
    std::size_t first = no_site;
    for(std::size_t k = 0; k < breakline_site_faces->size(); ++k)
    {
      const std::pair<std::size_t, std::size_t>& x = (*breakline_site_faces)[k];
      if(k == 0 || x.first != (*breakline_site_faces)[k - 1].first) first = no_site;
      const std::size_t p = partition.piece_of(x.second, x.first);
      if(p == no_site) continue;
      if(first == no_site) first = p;
      else pieces_of_a_cell.unite(first, p);
    }
  }

  Cell_components cc;
  cc.piece_component.assign(np, 0);
  cc.site_components.assign(number_of_sites, std::vector<std::size_t>());
  std::vector<std::size_t> root_component(np, no_site);
  for(std::size_t p = 0; p < np; ++p)
  {
    const std::size_t r = pieces_of_a_cell.find(p);
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

/// The sites whose cells share a piece edge with each site's cell, ascending, from the
/// stitched partition. Computed on demand: the construction gathers no neighbours, since most
/// uses of a diagram (Lloyd's steps, the outputs) never ask.
template <class TriangleMesh>
std::vector<std::vector<std::size_t> > site_neighbors(const Indexed_mesh<TriangleMesh>& mesh, const Partition& partition,
                                                      std::size_t number_of_sites)
{
  std::vector<std::vector<std::size_t> > out(number_of_sites);
  if(partition.pieces.empty()) return out;   // a cancelled construction
  for_each_piece_adjacency(mesh, partition, 0, mesh.number_of_faces(), [&](std::size_t p, std::size_t q, std::size_t) {
    const std::size_t a = partition.pieces[p].site, b = partition.pieces[q].site;
    if(a != b && a != no_site && b != no_site)
    {
      out[a].push_back(b);
      out[b].push_back(a);
    }
  });
  for(std::vector<std::size_t>& list : out)
  {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  return out;
}

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_CELL_COMPONENTS_H
