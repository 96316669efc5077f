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
// The arrangement with the site of each face, as the outputs that read the cells' boundaries
// need it (the polygon mesh of the cells, the bisector polylines, the Voronoi vertices, the
// dual's defects), and which cells are closed disks.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_LABELLED_ARRANGEMENT_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_LABELLED_ARRANGEMENT_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/arrangement.h>
#include <CGAL/Surface_voronoi_diagram/internal/Disjoint_sets.h>
#include <CGAL/Surface_voronoi_diagram/internal/Double_kernel.h>

#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

// The cells around a vertex, each run of faces of one cell once, from the labels of the faces
// in their order around it (a run across the start counted once): the cycle whose fan
// dual_triangulation() makes, and validate_dual_triangulation() checks, at a Voronoi vertex,
// and the sites voronoi_vertices() lists.
inline void cells_in_circular_order(const std::vector<std::int64_t>& labels, std::vector<std::int64_t>& cycle)
{
  cycle.clear();
  for(std::int64_t s : labels)
    if(cycle.empty() || cycle.back() != s) cycle.push_back(s);
  while(cycle.size() > 1 && cycle.front() == cycle.back()) cycle.pop_back();
}

// The label of a halfedge is the site of its face: -1 where no site reaches, -2 on the
// surface's border. Border and unreached area are told apart, as make_arrangement()'s
// vertex_is_constrained_map does, so that every output agrees on what a Voronoi vertex is.
class Labelled_arrangement
{
public:
  typedef CGAL::Surface_mesh<Point_d> Mesh;
  typedef Mesh::Vertex_index Vertex;
  typedef Mesh::Halfedge_index Halfedge;
  typedef Mesh::Face_index Face;
  static constexpr std::int64_t unreached = -1;
  static constexpr std::int64_t border = -2;

  template <class Diagram>
  explicit Labelled_arrangement(const Diagram& diagram)
  {
    m_site = m_mesh.add_property_map<Face, std::int64_t>("f:site", std::int64_t(unreached)).first;
    make_arrangement(diagram, m_mesh, CGAL::parameters::face_patch_map(m_site));
  }
  // the site map points into the mesh
  Labelled_arrangement(const Labelled_arrangement&) = delete;
  Labelled_arrangement& operator=(const Labelled_arrangement&) = delete;

  const Mesh& mesh() const { return m_mesh; }
  std::int64_t label(Halfedge h) const { return m_mesh.is_border(h) ? border : m_site[m_mesh.face(h)]; }
  // a halfedge on the boundary of its face's region (cell, unreached area)
  bool is_region_boundary(Halfedge h) const { return label(h) != label(m_mesh.opposite(h)); }

  // The labels of the faces around `v`, clockwise seen from the outside (the order of
  // halfedges_around_target).
  void labels_around(Vertex v, std::vector<std::int64_t>& ring) const
  {
    ring.clear();
    for(Halfedge h : CGAL::halfedges_around_target(v, m_mesh)) ring.push_back(label(h));
  }

  // Three or more regions meet at `v`, the border and the unreached area each counting as one.
  bool is_voronoi_vertex(Vertex v) const
  {
    if(m_mesh.is_isolated(v)) return false;
    std::vector<std::int64_t> ring;
    labels_around(v, ring);
    std::sort(ring.begin(), ring.end());
    return std::unique(ring.begin(), ring.end()) - ring.begin() >= 3;
  }

  // The region boundary halfedge that follows `h` (a region boundary halfedge) along the
  // boundary of its region, the region on the left: the turn around target(h) inside the region.
  // Where the region has several runs of faces around the vertex this is the boundary of the
  // run `h` borders.
  Halfedge next_on_region_boundary(Halfedge h) const
  {
    Halfedge g = m_mesh.next(h);
    while(!is_region_boundary(g)) g = m_mesh.next(m_mesh.opposite(g));
    return g;
  }

  // A cell is a closed disk when it is one piece, touches itself at no vertex (its faces
  // around each vertex are one run) and has Euler characteristic V - E + F = 1 (a connected
  // surface of genus g with b boundary loops has 2 - 2g - b). Writes the sites (of `n`) of
  // the other cells, empty ones included, ascending.
  void cells_not_disks(std::size_t n, std::vector<std::size_t>& out) const
  {
    std::vector<long> euler(n, 0);
    std::vector<std::uint8_t> not_disk(n, 0);
    Disjoint_sets pieces(m_mesh.number_of_faces());
    // edges: once for each cell beside them
    for(Mesh::Edge_index e : m_mesh.edges())
    {
      const Halfedge h = m_mesh.halfedge(e), o = m_mesh.opposite(h);
      const std::int64_t a = label(h), b = label(o);
      if(a >= 0) --euler[std::size_t(a)];
      if(b >= 0 && b != a) --euler[std::size_t(b)];
      if(a >= 0 && a == b)
        pieces.unite(std::size_t(m_mesh.face(h)), std::size_t(m_mesh.face(o)));
    }

    // vertices: once for each cell around them; a cell in several runs around one touches itself
    std::vector<std::int64_t> ring;
    for(Vertex v : m_mesh.vertices())
    {
      if(m_mesh.is_isolated(v)) continue;
      labels_around(v, ring);
      for(std::size_t k = 0; k < ring.size(); ++k)
      {
        const std::int64_t s = ring[k];
        if(s < 0 || std::find(ring.begin(), ring.begin() + k, s) != ring.begin() + k) continue;   // once per cell
        ++euler[std::size_t(s)];
        std::size_t runs = 0;
        for(std::size_t j = 0; j < ring.size(); ++j)
          runs += (ring[j] == s && ring[(j + ring.size() - 1) % ring.size()] != s);
        if(runs > 1) not_disk[std::size_t(s)] = 1;
      }
    }

    // faces, and the cells' pieces, through the edges with the cell on both sides
    std::vector<std::size_t> first_root(n, std::size_t(-1));
    for(Face f : m_mesh.faces())
    {
      if(m_site[f] < 0) continue;
      const std::size_t s = std::size_t(m_site[f]), root = pieces.find(std::size_t(f));
      ++euler[s];
      if(first_root[s] == std::size_t(-1)) first_root[s] = root;
      else if(first_root[s] != root) not_disk[s] = 1;
    }
    out.clear();
    for(std::size_t s = 0; s < n; ++s)
      if(first_root[s] == std::size_t(-1) || not_disk[s] || euler[s] != 1) out.push_back(s);   // no face, or not a disk
  }

private:
  Mesh m_mesh;
  Mesh::Property_map<Face, std::int64_t> m_site;
};

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_LABELLED_ARRANGEMENT_H
