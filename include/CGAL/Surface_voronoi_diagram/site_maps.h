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
// Output: the cells as labels of the input mesh itself, written into the user's property
// maps (as Polygon_mesh_processing::compute_vertex_normals() writes normals): a site per
// vertex, and per face the site of a cell that covers it whole.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_SITE_MAPS_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_SITE_MAPS_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/arrangement.h>
#include <CGAL/Surface_voronoi_diagram/internal/Diagram_data.h>

#include <CGAL/assertions.h>
#include <CGAL/property_map.h>

#include <boost/graph/graph_traits.hpp>

namespace CGAL {
namespace Surface_voronoi {

/// \ingroup PkgSurfaceVoronoiDiagramOutputs
/// Writes the site of every vertex of the diagram's mesh into `vertex_site_map`: the site
/// whose cell contains the vertex, as `diagram.site_of(v)` answers (ties to the lower site
/// index), and `-1`, converted to the value type, where no site reaches.
///
/// \tparam Diagram a `CGAL::Surface_voronoi_diagram`
/// \tparam VertexSiteMap a model of `WritablePropertyMap` with `Diagram::vertex_descriptor` as
///         key and an integer type as value
/// \pre `!diagram.is_cancelled()`
/// \sa `compute_face_sites()`
template <class Diagram, class VertexSiteMap>
void compute_vertex_sites(const Diagram& diagram, VertexSiteMap vertex_site_map)
{
  typedef typename boost::property_traits<VertexSiteMap>::value_type Site_value;
  CGAL_precondition_msg(!diagram.is_cancelled(), "the diagram was cancelled: it has no cells");
  for(typename Diagram::vertex_descriptor v : vertices(diagram.triangle_mesh()))
    put(vertex_site_map, v, internal::site_value<Site_value>(diagram.site_of(v)));
}

/// \ingroup PkgSurfaceVoronoiDiagramOutputs
/// Writes into `face_site_map`, for every face of the diagram's mesh, the site whose cell
/// covers the whole face (every piece of the face in the arrangement belongs to that cell),
/// and `-1`, converted to the value type, for a face that a bisector cuts (its pieces belong
/// to several regions) or that no site reaches.
///
/// \tparam Diagram a `CGAL::Surface_voronoi_diagram`
/// \tparam FaceSiteMap a model of `WritablePropertyMap` with `Diagram::face_descriptor` as key
///         and an integer type as value
/// \pre `!diagram.is_cancelled()`
/// \sa `compute_vertex_sites()`, `make_arrangement()` (the pieces of the cut faces)
template <class Diagram, class FaceSiteMap>
void compute_face_sites(const Diagram& diagram, FaceSiteMap face_site_map)
{
  typedef typename boost::property_traits<FaceSiteMap>::value_type Site_value;
  CGAL_precondition_msg(!diagram.is_cancelled(), "the diagram was cancelled: it has no cells");
  const auto& data = internal::Diagram_access::data(diagram);
  const internal::Partition& partition = data.partition;
  CGAL_assertion(partition.face_begin.size() == data.mesh->number_of_faces() + 1);
  for(std::size_t f = 0; f < data.mesh->number_of_faces(); ++f)
  {
    const std::size_t begin = partition.face_begin[f], end = partition.face_begin[f + 1];
    std::size_t site = internal::no_site;
    if(begin < end)
    {
      site = partition.pieces[begin].site;
      for(std::size_t p = begin + 1; p < end && site != internal::no_site; ++p)
        if(partition.pieces[p].site != site) site = internal::no_site;
    }
    put(face_site_map, data.mesh->face_handles[f], internal::site_value<Site_value>(site));
  }
}

} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_SITE_MAPS_H
