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
// Remeshing by the dual (\cgalCite{cgal:bddvd}, 4.7.3): the restricted Delaunay triangulation dual to the
// diagram, one triangle per Voronoi vertex (a fan of triangles where more than three cells
// meet), on the sites, oriented with the surface.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_DUAL_TRIANGULATION_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_DUAL_TRIANGULATION_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/arrangement.h>
#include <CGAL/Surface_voronoi_diagram/internal/Double_kernel.h>
#include <CGAL/Surface_voronoi_diagram/internal/Labelled_arrangement.h>

#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <array>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {
/// \ingroup PkgSurfaceVoronoiDiagramOutputs
/// Writes the dual triangulation of `diagram` as a polygon soup: `points` receives the sites
/// (in site order) and `triangles` one triangle per Voronoi vertex of the arrangement, its
/// sites in counter-clockwise order seen from the surface's outside (the order of the cells
/// around the vertex). Where k > 3 cells meet, a fan of k - 2 triangles. Voronoi vertices on
/// the border of the surface give no triangle. This is the remeshing of the reference paper
/// \cgalCite{cgal:bddvd} (section 4.7.3); `CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh()`
/// turns the soup into a mesh when the function returns `true`.
/// \tparam Diagram a `CGAL::Surface_voronoi_diagram`
/// \tparam PointOutputIterator an output iterator accepting `Diagram::Point_3`
/// \tparam TriangleOutputIterator an output iterator accepting `std::array<std::size_t, 3>`
/// \param diagram the diagram
/// \param points receives the points of the sites
/// \param triangles receives the triangles, as indices of sites
/// \returns `true` if the soup is a valid polygon mesh (a 2-manifold, possibly with border),
///          which is the case when every cell is a disk
/// \pre `!diagram.is_cancelled()`
template <class Diagram, class PointOutputIterator, class TriangleOutputIterator>
bool dual_triangulation(const Diagram& diagram, PointOutputIterator points, TriangleOutputIterator triangles)
{
  CGAL_precondition_msg(!diagram.is_cancelled(), "the diagram was cancelled: it has no cells");
  typedef CGAL::Surface_mesh<internal::Point_d> Mesh;
  Mesh arrangement;
  auto site = arrangement.add_property_map<Mesh::Face_index, std::int64_t>("f:site", -1).first;
  make_arrangement(diagram, arrangement, CGAL::parameters::face_patch_map(site));

  for(std::size_t i = 0; i < diagram.number_of_sites(); ++i) *points++ = diagram.site_point(i);

  std::vector<std::array<std::size_t, 3> > soup;
  std::vector<std::int64_t> labels, ring;
  for(Mesh::Vertex_index v : arrangement.vertices())
  {
    if(CGAL::is_border(v, arrangement)) continue;
    // the cells around v, in the order of the faces around it
    labels.clear();
    for(Mesh::Halfedge_index h : CGAL::halfedges_around_target(v, arrangement))
      labels.push_back(site[face(h, arrangement)]);
    internal::cells_in_circular_order(labels, ring);
    if(ring.size() < 3) continue;
    bool reached = true;
    for(std::int64_t s : ring) reached &= (s >= 0);
    if(!reached) continue;
    // halfedges_around_target turns clockwise around v (seen from outside): reverse it
    for(std::size_t k = 1; k + 1 < ring.size(); ++k)
      soup.push_back({{ std::size_t(ring[0]), std::size_t(ring[k + 1]), std::size_t(ring[k]) }});
  }
  for(const auto& t : soup) *triangles++ = t;
  return !soup.empty() && CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(soup);
}

} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_DUAL_TRIANGULATION_H
