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

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {

/// \ingroup PkgSurfaceVoronoiDiagramSites
/// The location of the point of `tm` nearest to each of `points`, in the order of `points`:
/// what `CGAL::Polygon_mesh_processing::locate_with_AABB_tree()` gives, without a tree. The
/// points are put in a uniform grid, and one pass over the faces offers each face to the
/// points within a search radius of it, a few times the faces' mean size; a point with no
/// face within that radius is searched for again with a radius four times larger. A point near
/// the surface thus meets a few dozen faces. The nearest face wins, the first in `faces(tm)`
/// among equally near ones.
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
  typedef internal::Point_d Point_d;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  CGAL_precondition_msg(CGAL::is_triangle_mesh(tm), "the mesh must be a triangle mesh");

  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm));
  const auto gt = CGAL::parameters::choose_parameter<typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters>::type>(
      get_parameter(np, CGAL::internal_np::geom_traits));
  auto finite = [](const Point_d& p) { return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z()); };
  // the corners in the order of CGAL's AABB face-graph primitives, whose projections these repeat
  auto triangle = [&](face_descriptor f) {
    const auto h = halfedge(f, tm);
    return internal::Double_kernel::Triangle_3(internal::to_point_d(get(vpm, target(h, tm))),
                                               internal::to_point_d(get(vpm, target(next(h, tm), tm))),
                                               internal::to_point_d(get(vpm, source(h, tm))));
  };
  std::vector<Point_d> ps;
  for(const auto& point : points)
  {
    ps.push_back(internal::to_point_d(point));
    if(!finite(ps.back())) throw Input_error("point " + std::to_string(ps.size() - 1) + " has a coordinate that is not a finite number");
  }
  CGAL::Bbox_3 all;
  for(const Point_d& p : ps) all += p.bbox();
  for(auto v : vertices(tm))
  {
    if(halfedge(v, tm) == boost::graph_traits<TriangleMesh>::null_halfedge()) continue;
    const Point_d p = internal::to_point_d(get(vpm, v));
    if(!finite(p)) throw Input_error("a vertex of the mesh has a coordinate that is not a finite number");
    all += p.bbox();
  }
  // the faces' mean size, from every eighth face
  double extent = 0;
  std::size_t number_of_faces = 0;
  for(face_descriptor f : faces(tm))
    if(number_of_faces++ % 8 == 0)
    {
      const CGAL::Bbox_3 b = triangle(f).bbox();
      extent += (b.xmax() - b.xmin()) + (b.ymax() - b.ymin()) + (b.zmax() - b.zmin());
    }
  if(number_of_faces == 0) throw Input_error("the mesh has no face to locate points on");
  struct Nearest { face_descriptor face; Point_d point; double squared_distance; };
  std::vector<Nearest> nearest(ps.size());
  std::vector<std::uint32_t> open(ps.size());
  for(std::size_t i = 0; i < ps.size(); ++i) open[i] = std::uint32_t(i);
  const internal::Double_kernel kernel;
  // A face nearer than r to a point has its box, grown by r, around the point: a point whose
  // nearest face found is within r has met every face as near. Past the diagonal of the box
  // around the mesh and the points, every point's nearest face is within r.
  const double diagonal = 1.01 * std::sqrt(CGAL::square(all.xmax() - all.xmin()) + CGAL::square(all.ymax() - all.ymin())
                                           + CGAL::square(all.zmax() - all.zmin()));
  for(double r = (std::max)(extent / double(3 * ((number_of_faces + 7) / 8)), diagonal * 0x1p-20); !open.empty(); r = (std::min)(4 * r, diagonal))
  {
    const internal::Face_grid grid(open.size(), [&](std::size_t i, int) { return ps[open[i]]; }, r);
    for(std::uint32_t i : open) nearest[i].squared_distance = std::numeric_limits<double>::infinity();
    const double grown = r * (1 + 1e-9);
    for(face_descriptor f : faces(tm))
    {
      const auto t = triangle(f);
      const CGAL::Bbox_3 b = t.bbox();
      const Point_d lo(b.xmin() - grown, b.ymin() - grown, b.zmin() - grown), hi(b.xmax() + grown, b.ymax() + grown, b.zmax() + grown);
      grid.for_each_near(lo, hi, [&](std::size_t j) {
        const Point_d& p = ps[open[j]];
        Nearest& n = nearest[open[j]];
        // the distance to the face's box, a lower bound on the distance to the face, with a margin for rounding
        double box2 = 0;
        for(int a = 0; a < 3; ++a) box2 += CGAL::square((std::max)({ b.min(a) - p[a], p[a] - b.max(a), 0. }));
        if(box2 > r * r || box2 > n.squared_distance * (1 + 1e-9)) return;
        const Point_d q = kernel.construct_projected_point_3_object()(t, p);
        const double d2 = CGAL::squared_distance(p, q);
        if(d2 < n.squared_distance) n = Nearest{ f, q, d2 };
      });
    }
    std::vector<std::uint32_t> still;
    for(std::uint32_t i : open)
      if(!(nearest[i].squared_distance <= r * r) && r < diagonal) still.push_back(i);
    open.swap(still);
  }
  typedef typename boost::range_value<PointRange>::type Point;
  std::vector<CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double> > out;
  out.reserve(ps.size());
  for(const Nearest& n : nearest)
    out.push_back(internal::locate_in_face(Point(n.point.x(), n.point.y(), n.point.z()), n.face, tm, vpm, gt));
  return out;
}

} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_LOCATE_POINTS_H
