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
// The location of a point in a given face, as the package computes it.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_LOCATE_IN_FACE_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_LOCATE_IN_FACE_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/internal/Double_kernel.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/boost/graph/named_params_helper.h>

namespace CGAL {
namespace Surface_voronoi {

/// \ingroup PkgSurfaceVoronoiDiagramSites
/// The location of `p`, a point of face `f` of `tm` (or its projection on the face's plane),
/// in `f`: what `CGAL::Polygon_mesh_processing::locate_in_face()` gives, except on a needle or
/// a cap too thin for its formula, where the barycentric coordinates are ratios of areas
/// (finite, and exact zeros on axis-aligned edges). These are the coordinates that
/// `locate_points()` returns and that the diagram gives its sites.
///
/// \tparam Point the point type of the vertex point map
/// \tparam TriangleMesh a model of `FaceGraph` whose faces are triangles
/// \param p the point
/// \param f the face
/// \param tm the mesh
/// \param np an optional sequence of named parameters among `vertex_point_map` and
///        `geom_traits`, as for `locate_points()`
template <class Point, class TriangleMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double>
locate_in_face(const Point& p, typename boost::graph_traits<TriangleMesh>::face_descriptor f, const TriangleMesh& tm,
               const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  return internal::locate_in_face(p, f, tm,
      choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm)),
      choose_parameter<typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters>::type>(get_parameter(np, CGAL::internal_np::geom_traits)));
}

} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_LOCATE_IN_FACE_H
