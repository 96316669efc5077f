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
// Where the cells of a diagram lack the closed-ball property, read on its arrangement, and
// the checks of a triangle soup that validate_dual_triangulation() needs.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_DUAL_CELL_DEFECTS_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_DUAL_CELL_DEFECTS_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/arrangement.h>
#include <CGAL/Surface_voronoi_diagram/internal/Disjoint_sets.h>
#include <CGAL/Surface_voronoi_diagram/internal/Double_kernel.h>
#include <CGAL/Surface_voronoi_diagram/internal/Indexed_mesh.h>
#include <CGAL/Surface_voronoi_diagram/internal/Labelled_arrangement.h>
#include <CGAL/Surface_voronoi_diagram/internal/Site.h>

#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

// The number of connected components of the graph whose edges are `edges` (pairs of vertex
// ids), and whether none of its vertices has more than two edges.
inline std::pair<std::size_t, bool> components_of_edges(const std::vector<std::pair<std::size_t, std::size_t> >& edges)
{
  std::vector<std::size_t> ends;
  for(const auto& e : edges)
  {
    ends.push_back(e.first);
    ends.push_back(e.second);
  }
  std::sort(ends.begin(), ends.end());
  bool degree_ok = true;
  for(std::size_t k = 0; k + 2 < ends.size() && degree_ok; ++k) degree_ok = (ends[k] != ends[k + 2]);
  ends.erase(std::unique(ends.begin(), ends.end()), ends.end());
  auto index = [&](std::size_t v) { return std::size_t(std::lower_bound(ends.begin(), ends.end(), v) - ends.begin()); };
  Disjoint_sets parts(ends.size());
  std::size_t components = ends.size();
  for(const auto& e : edges)
  {
    const std::size_t a = parts.find(index(e.first)), b = parts.find(index(e.second));
    if(a != b)
    {
      parts.link(a, b);
      --components;
    }
  }
  return { components, degree_ok };
}

// Cells not closed disks: Labelled_arrangement::cells_not_disks(). Two cells share several
// arcs when the bisector edges between them form several components; three cells meet several
// times when several Voronoi vertices (inside the surface, exactly three cells around) have
// them.
template <class Diagram>
void find_dual_cell_defects(const Diagram& diagram, std::vector<std::size_t>& cells_not_disks,
                            std::vector<std::pair<std::size_t, std::size_t> >& pairs_in_several_arcs,
                            std::vector<std::array<std::size_t, 3> >& triples_at_several_vertices,
                            std::size_t& vertices_of_more_than_three_cells,
                            std::map<std::array<std::size_t, 3>, std::vector<std::array<double, 3> > >& surface_normals_of_triple)
{
  typedef Labelled_arrangement::Mesh Mesh;
  typedef Mesh::Halfedge_index Halfedge;
  const Labelled_arrangement labelled(diagram);
  const Mesh& arrangement = labelled.mesh();
  const std::size_t n = diagram.number_of_sites();
  const std::int64_t border = Labelled_arrangement::border;

  labelled.cells_not_disks(n, cells_not_disks);

  // edges between two cells (the lower first), each an arc's piece (from vertex to vertex)
  typedef std::pair<std::size_t, std::size_t> Pair;
  std::vector<std::pair<Pair, Pair> > bisector_edges;
  for(Mesh::Edge_index e : arrangement.edges())
  {
    const Halfedge h = arrangement.halfedge(e), o = arrangement.opposite(h);
    const std::int64_t a = labelled.label(h), b = labelled.label(o);
    if(a >= 0 && b >= 0 && a != b)
      bisector_edges.emplace_back(Pair((std::min)(a, b), (std::max)(a, b)), Pair(arrangement.source(h), arrangement.target(h)));
  }

  // Voronoi vertices
  std::map<std::array<std::size_t, 3>, std::size_t> vertices_of_triple;
  std::vector<std::int64_t> ring, cycle;
  std::vector<std::array<double, 3> > normals;
  vertices_of_more_than_three_cells = 0;
  for(Mesh::Vertex_index v : arrangement.vertices())
  {
    if(arrangement.is_isolated(v)) continue;
    labelled.labels_around(v, ring);
    // a Voronoi vertex inside the surface: the cells around, each once in circular order
    if(std::find(ring.begin(), ring.end(), border) != ring.end()) continue;
    cells_in_circular_order(ring, cycle);
    if(cycle.size() < 3 || std::find_if(cycle.begin(), cycle.end(), [](std::int64_t s) { return s < 0; }) != cycle.end())
      continue;
    // the surface's normals there: those of the faces around (pieces of input triangles, so
    // facing as the surface does), each from its area vector; on a crease or a thin rim they
    // point several ways
    normals.clear();
    for(Halfedge h : CGAL::halfedges_around_target(v, arrangement))
    {
      const Point_d& o = arrangement.point(v);
      Vector_d area(0., 0., 0.);
      for(Halfedge g = arrangement.next(h); arrangement.target(g) != v; g = arrangement.next(g))
        area = area + CGAL::cross_product(arrangement.point(arrangement.source(g)) - o, arrangement.point(arrangement.target(g)) - o);
      const double length = std::sqrt(area.squared_length());
      if(length > 0) normals.push_back({{ area.x() / length, area.y() / length, area.z() / length }});
    }
    // the triangles dual_triangulation() makes here: one, or a fan from the first cell
    for(std::size_t k = 1; k + 1 < cycle.size(); ++k)
    {
      std::array<std::size_t, 3> triple = {{ std::size_t(cycle[0]), std::size_t(cycle[k]), std::size_t(cycle[k + 1]) }};
      std::sort(triple.begin(), triple.end());
      std::vector<std::array<double, 3> >& all = surface_normals_of_triple[triple];
      all.insert(all.end(), normals.begin(), normals.end());
      if(cycle.size() == 3) ++vertices_of_triple[triple];
    }
    if(cycle.size() > 3) ++vertices_of_more_than_three_cells;
  }

  // the arcs between two cells: components of their bisector edges, joined at vertices
  std::sort(bisector_edges.begin(), bisector_edges.end());
  pairs_in_several_arcs.clear();
  std::vector<Pair> arc;
  for(std::size_t begin = 0; begin < bisector_edges.size();)
  {
    std::size_t end = begin;
    arc.clear();
    for(; end < bisector_edges.size() && bisector_edges[end].first == bisector_edges[begin].first; ++end)
      arc.push_back(bisector_edges[end].second);
    if(components_of_edges(arc).first > 1) pairs_in_several_arcs.push_back(bisector_edges[begin].first);
    begin = end;
  }

  triples_at_several_vertices.clear();
  for(const auto& t : vertices_of_triple)
    if(t.second > 1) triples_at_several_vertices.push_back(t.first);
}

// The unit normal of a site's face (zero for a degenerate face).
template <class TriangleMesh>
std::array<double, 3> site_face_normal(const Indexed_mesh<TriangleMesh>& mesh, const Site& site)
{
  const std::size_t f = site.face;
  const Vector_d normal = CGAL::cross_product(mesh.corner(f, 1) - mesh.corner(f, 0), mesh.corner(f, 2) - mesh.corner(f, 0));
  const double length = std::sqrt(normal.squared_length());
  if(!(length > 0)) return {{ 0., 0., 0. }};
  return {{ normal.x() / length, normal.y() / length, normal.z() / length }};
}

// The sum of the unit normals of the faces of a triangle's three sites.
template <class TriangleMesh>
std::array<double, 3> sum_of_site_face_normals(const Indexed_mesh<TriangleMesh>& mesh, const std::vector<Site>& sites,
                                               const std::array<std::size_t, 3>& triangle)
{
  std::array<double, 3> sum = {{ 0., 0., 0. }};
  for(std::size_t i : triangle)
  {
    const std::array<double, 3> n = site_face_normal(mesh, sites[i]);
    for(int k = 0; k < 3; ++k) sum[k] += n[k];
  }
  return sum;
}

// The vertices of a triangle soup (on vertices 0 .. n-1) whose triangles do not form one fan:
// their link (the opposite edges) is not one path or one cycle. Triangles with a repeated
// vertex are left out.
inline std::size_t number_of_non_manifold_soup_vertices(std::size_t n, const std::vector<std::array<std::size_t, 3> >& soup)
{
  std::vector<std::vector<std::pair<std::size_t, std::size_t> > > link(n);
  for(const std::array<std::size_t, 3>& t : soup)
  {
    if(t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) continue;
    for(int k = 0; k < 3; ++k) link[t[k]].emplace_back(t[(k + 1) % 3], t[(k + 2) % 3]);
  }
  std::size_t bad = 0;
  for(std::size_t v = 0; v < n; ++v)
  {
    if(link[v].empty()) continue;
    const std::pair<std::size_t, bool> parts = components_of_edges(link[v]);
    if(!parts.second || parts.first != 1) ++bad;
  }
  return bad;
}

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_DUAL_CELL_DEFECTS_H
