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
// Input: points near the surface (sites read from a file, measured points) as face
// locations, the nearest point of the surface to each.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_LOCATE_POINTS_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_LOCATE_POINTS_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/exceptions.h>
#include <CGAL/Surface_voronoi_diagram/internal/Double_kernel.h>
#include <CGAL/Surface_voronoi_diagram/internal/Face_grid.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {

/// \ingroup PkgSurfaceVoronoiDiagramSites
/// The location of the point of `tm` nearest to each of `points`, in the order of `points`:
/// what `CGAL::Polygon_mesh_processing::locate_with_AABB_tree()` gives, without a tree. The
/// faces are put in a uniform grid of their bounding boxes, built in time linear in the size
/// of `tm`, and each point searches the cells around it until no face farther out can be
/// nearer; the nearest face wins, the first in `faces(tm)` among equally near ones. A point
/// near the surface thus meets a few dozen faces; a point far from it (several times the size
/// of a face, away from every face) may meet every face.
///
/// Distances are measured in doubles, as `CGAL::Simple_cartesian<double>` measures them.
///
/// \tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
/// \tparam PointRange a model of `ConstRange` whose value type is the point type of the vertex
///         point map
/// \param tm a triangle mesh with at least one face
/// \param points the points to locate
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
///     \cgalParamType{a model of `ReadablePropertyMap`}
///     \cgalParamDefault{`get_const_property_map(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{the traits passed to `CGAL::Polygon_mesh_processing::locate_in_face()`}
///     \cgalParamType{a model of `Kernel`}
///     \cgalParamDefault{the kernel of the vertex point map's point type}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \pre `tm` is a triangle mesh
/// \throws Surface_voronoi::Input_error if `tm` has no face, or if a point or a vertex has a
///         coordinate that is not a finite number (checked in every build)
template <class TriangleMesh, class PointRange, class NamedParameters = CGAL::parameters::Default_named_parameters>
std::vector<CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double> >
locate_points(const TriangleMesh& tm, const PointRange& points, const NamedParameters& np = CGAL::parameters::default_values())
{
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  typedef internal::Double_kernel::Triangle_3 Triangle;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  CGAL_precondition_msg(CGAL::is_triangle_mesh(tm), "the mesh must be a triangle mesh");

  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm));
  const auto gt = CGAL::parameters::choose_parameter<typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters>::type>(
      get_parameter(np, CGAL::internal_np::geom_traits));
  auto finite = [](const internal::Point_d& p) { return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z()); };
  std::vector<face_descriptor> fs;
  std::vector<Triangle> triangles;
  for(face_descriptor f : faces(tm))
  {
    const auto h = halfedge(f, tm);
    fs.push_back(f);
    // the corners in the order of CGAL's AABB face-graph primitives, whose projections these repeat
    triangles.emplace_back(internal::to_point_d(get(vpm, target(h, tm))), internal::to_point_d(get(vpm, target(next(h, tm), tm))),
                           internal::to_point_d(get(vpm, source(h, tm))));
    for(int k = 0; k < 3; ++k)
      if(!finite(triangles.back()[k])) throw Input_error("a vertex of the mesh has a coordinate that is not a finite number");
  }
  if(fs.empty()) throw Input_error("the mesh has no face to locate points on");
  const internal::Face_grid grid(fs.size(), [&](std::size_t f, int k) { return triangles[f][k]; });
  const internal::Double_kernel kernel;
  std::vector<CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double> > out;
  for(const auto& point : points)
  {
    const internal::Point_d p = internal::to_point_d(point);
    if(!finite(p)) throw Input_error("point " + std::to_string(out.size()) + " has a coordinate that is not a finite number");
    auto nearest = [&](std::size_t f) { return kernel.construct_projected_point_3_object()(triangles[f], p); };
    const std::size_t f = grid.nearest(p, [&](std::size_t g) { return CGAL::squared_distance(nearest(g), p); });
    const internal::Point_d q = nearest(f);
    out.push_back(internal::locate_in_face(typename std::decay<decltype(point)>::type(q.x(), q.y(), q.z()), fs[f], tm, vpm, gt));
  }
  return out;
}

} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_LOCATE_POINTS_H
