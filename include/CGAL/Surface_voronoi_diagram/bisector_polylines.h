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
// Output: the cells' boundaries as ranges of points, each with the sites it separates: the
// bisector polylines between Voronoi vertices, and the Voronoi vertices.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_BISECTOR_POLYLINES_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_BISECTOR_POLYLINES_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/internal/Labelled_arrangement.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {

/// \ingroup PkgSurfaceVoronoiDiagramOutputs
/// A maximal piece of the boundary between two regions, written by `bisector_polylines()`.
/// \tparam Point_3 the point type, `Diagram::Point_3`
template <class Point_3>
struct Bisector_polyline
{
  /// the two sites whose cells the polyline separates, ascending; the second is
  /// `std::size_t(-1)` (the diagram's `no_site`) where the polyline separates a cell from
  /// area no site reaches
  std::array<std::size_t, 2> sites;
  /// the points, in the order that keeps the cell of `sites[0]` on the left (seen with the
  /// surface's orientation: the boundary of that cell counter-clockwise); a closed loop
  /// repeats its first point at its end
  std::vector<Point_3> points;

  /// whether the polyline is a closed loop (its first and last points are the same)
  bool is_closed() const { return points.size() > 1 && points.front() == points.back(); }
};

/// \ingroup PkgSurfaceVoronoiDiagramOutputs
/// A point where three or more regions meet, written by `voronoi_vertices()`.
/// \tparam Point_3 the point type, `Diagram::Point_3`
template <class Point_3>
struct Voronoi_vertex
{
  /// the point
  Point_3 point;
  /// the regions around the point, counter-clockwise seen with the surface's orientation, each
  /// run of faces once: a site, or `std::size_t(-1)` (the diagram's `no_site`) for the
  /// surface's border and for area no site reaches. A cell that touches itself at the point
  /// appears once per run.
  std::vector<std::size_t> sites;
};

/// \ingroup PkgSurfaceVoronoiDiagramOutputs
/// Writes the boundaries between the regions of `diagram` (its cells, and the area no site
/// reaches) as polylines: each maximal chain of boundary edges of the arrangement
/// (`make_arrangement()`) between two regions, with its points in order. A polyline runs
/// from a Voronoi vertex to a Voronoi vertex (see `voronoi_vertices()`; a bisector that meets
/// the surface's border ends there), or is a closed loop when two regions share a whole
/// boundary loop with no third region on it (a cell around a handle, a cell inside another).
/// Rarely, a polyline also ends where two cells touch at a single point. Every point where a
/// polyline bends, where it crosses an edge of the input, is one of its points.
///
/// The border of the surface is not written: it separates nothing (`make_voronoi_polygon_mesh()`
/// writes the cells with it). Neither are breaklines inside a cell.
///
/// \tparam Diagram a `CGAL::Surface_voronoi_diagram`
/// \tparam OutputIterator an output iterator accepting `Bisector_polyline<Diagram::Point_3>`
/// \returns the output iterator past the last polyline
/// \pre `!diagram.is_cancelled()`
template <class Diagram, class OutputIterator>
OutputIterator bisector_polylines(const Diagram& diagram, OutputIterator out)
{
  typedef typename Diagram::Point_3 Point_3;
  typedef internal::Labelled_arrangement Arrangement;
  typedef Arrangement::Vertex Vertex;
  typedef Arrangement::Halfedge Halfedge;
  CGAL_precondition_msg(!diagram.is_cancelled(), "the diagram was cancelled: it has no cells");
  const Arrangement arrangement(diagram);
  const Arrangement::Mesh& mesh = arrangement.mesh();
  const auto construct = diagram.geom_traits().construct_point_3_object();
  auto point = [&](Vertex v) {
    const internal::Point_d& p = mesh.point(v);
    return construct(p.x(), p.y(), p.z());
  };
  // the border is no bisector: a region boundary edge with a face on both sides
  auto is_bisector = [&](Halfedge h) {
    return !mesh.is_border(mesh.edge(h)) && arrangement.is_region_boundary(h);
  };
  // as a site index, -1 (unreached) the largest
  auto site_index = [](std::int64_t label) { return label < 0 ? std::size_t(-1) : std::size_t(label); };

  // polylines stop at Voronoi vertices, and where the boundary does not simply go on (the
  // rare point where two cells touch)
  std::vector<std::uint8_t> stops(mesh.number_of_vertices(), 0);
  for(Vertex v : mesh.vertices())
  {
    std::size_t degree = 0;
    if(!mesh.is_isolated(v))
      for(Halfedge h : CGAL::halfedges_around_target(v, mesh)) degree += is_bisector(h);
    stops[std::size_t(v)] = (degree > 0 && (degree != 2 || arrangement.is_voronoi_vertex(v)));
  }

  std::vector<std::uint8_t> done(mesh.number_of_edges(), 0);
  Bisector_polyline<Point_3> polyline;
  // The chain from `start` on, its region on the left, until a stop or back at `start`;
  // written with the lower site's cell on the left.
  auto follow = [&](Halfedge start) {
    polyline.points.clear();
    polyline.points.push_back(point(mesh.source(start)));
    Halfedge h = start;
    for(;;)
    {
      done[std::size_t(mesh.edge(h))] = 1;
      polyline.points.push_back(point(mesh.target(h)));
      if(stops[std::size_t(mesh.target(h))]) break;
      h = arrangement.next_on_region_boundary(h);
      if(h == start || done[std::size_t(mesh.edge(h))]) break;
    }
    const std::size_t left = site_index(arrangement.label(start));
    const std::size_t right = site_index(arrangement.label(mesh.opposite(start)));
    polyline.sites = {{ (std::min)(left, right), (std::max)(left, right) }};
    if(left > right) std::reverse(polyline.points.begin(), polyline.points.end());
    *out++ = polyline;
  };

  // chains from a stop first; what is left are closed loops
  for(Halfedge h : mesh.halfedges())
    if(is_bisector(h) && stops[std::size_t(mesh.source(h))] && !done[std::size_t(mesh.edge(h))]) follow(h);
  for(Halfedge h : mesh.halfedges())
    if(is_bisector(h) && !done[std::size_t(mesh.edge(h))]
       && site_index(arrangement.label(h)) < site_index(arrangement.label(mesh.opposite(h))))
      follow(h);
  return out;
}

/// \ingroup PkgSurfaceVoronoiDiagramOutputs
/// Writes the Voronoi vertices of `diagram`: the vertices of its arrangement
/// (`make_arrangement()`) where three or more regions meet, a region being a cell, the area no
/// site reaches, or the outside of the surface's border (so a bisector meeting the border
/// makes a Voronoi vertex there). They are the points `make_arrangement()`'s
/// `vertex_is_constrained_map` marks, and the ends of the polylines of `bisector_polylines()`.
///
/// \tparam Diagram a `CGAL::Surface_voronoi_diagram`
/// \tparam OutputIterator an output iterator accepting `Voronoi_vertex<Diagram::Point_3>`
/// \returns the output iterator past the last vertex
/// \pre `!diagram.is_cancelled()`
template <class Diagram, class OutputIterator>
OutputIterator voronoi_vertices(const Diagram& diagram, OutputIterator out)
{
  typedef typename Diagram::Point_3 Point_3;
  typedef internal::Labelled_arrangement Arrangement;
  CGAL_precondition_msg(!diagram.is_cancelled(), "the diagram was cancelled: it has no cells");
  const Arrangement arrangement(diagram);
  const Arrangement::Mesh& mesh = arrangement.mesh();
  const auto construct = diagram.geom_traits().construct_point_3_object();
  std::vector<std::int64_t> ring, cycle;
  Voronoi_vertex<Point_3> vertex;
  for(Arrangement::Vertex v : mesh.vertices())
  {
    if(!arrangement.is_voronoi_vertex(v)) continue;
    arrangement.labels_around(v, ring);
    // counter-clockwise; the border and the unreached area are both "no site"
    std::reverse(ring.begin(), ring.end());
    for(std::int64_t& label : ring)
      if(label < 0) label = -1;
    internal::cells_in_circular_order(ring, cycle);
    const internal::Point_d& p = mesh.point(v);
    vertex.point = construct(p.x(), p.y(), p.z());
    vertex.sites.clear();
    for(std::int64_t label : cycle) vertex.sites.push_back(label < 0 ? std::size_t(-1) : std::size_t(label));
    *out++ = vertex;
  }
  return out;
}

} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_BISECTOR_POLYLINES_H
