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
// The one kernel the pipeline computes with. Whatever the user's kernel (Epick, Epeck,
// Simple_cartesian<float>...), points are read from the vertex point map once, converted to
// doubles, and every later construction is made here, so that all kernels give the same
// diagram. The exact decisions (cutting, stitching) are taken on these doubles by
// exact_predicates.h; what is computed here only places vertices and measures areas.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_DOUBLE_KERNEL_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_DOUBLE_KERNEL_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/number_utils.h>
#include <CGAL/Polygon_mesh_processing/locate.h>

#include <boost/property_map/property_map.hpp>

#include <array>
#include <cmath>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

typedef CGAL::Simple_cartesian<double> Double_kernel;
typedef Double_kernel::Point_3 Point_d;
typedef Double_kernel::Vector_3 Vector_d;
typedef std::array<double, 3> Barycentric;

/// exact predicates on the same doubles (collinearity of welded pieces, in-face Delaunay flips)
typedef CGAL::Exact_predicates_inexact_constructions_kernel Exact_predicates_kernel;

/// a point of any kernel as doubles
template <class Point>
Point_d to_point_d(const Point& p)
{
  return Point_d(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
}

/// A readable property map giving the points of another property map as `Point_d`, so that
/// CGAL functions taking a `vertex_point_map` compute in doubles whatever the user's kernel.
template <class VertexPointMap>
struct Double_point_map
{
  typedef typename boost::property_traits<VertexPointMap>::key_type key_type;
  typedef Point_d value_type;
  typedef Point_d reference;
  typedef boost::readable_property_map_tag category;
  VertexPointMap map;
  friend Point_d get(const Double_point_map& m, const key_type& k) { return to_point_d(get(m.map, k)); }
};

template <class VertexPointMap>
Double_point_map<VertexPointMap> make_double_point_map(const VertexPointMap& map)
{
  return Double_point_map<VertexPointMap>{ map };
}

/// the area of triangle pqr
inline double triangle_area(const Point_d& p, const Point_d& q, const Point_d& r)
{
  return std::sqrt(Double_kernel().compute_squared_area_3_object()(p, q, r));
}

/// the point with barycentric coordinates `b` in triangle (p0, p1, p2): the weighted sum,
/// accumulated corner by corner (no division by the sum of the weights)
inline Point_d point_at(const Point_d& p0, const Point_d& p1, const Point_d& p2, const Barycentric& b)
{
  double x[3] = { 0., 0., 0. };
  const Point_d* p[3] = { &p0, &p1, &p2 };
  for(int k = 0; k < 3; ++k)
    for(int c = 0; c < 3; ++c) x[c] += b[k] * (*p[k])[c];
  return Point_d(x[0], x[1], x[2]);
}

/// barycentric coordinates of `x` in triangle (p0, p1, p2), of its projection on the
/// triangle's plane if `x` is off it: the package's one way to compute them (PMP's)
inline Barycentric barycentric_coordinates(const Point_d& p0, const Point_d& p1, const Point_d& p2, const Point_d& x)
{
  return CGAL::Polygon_mesh_processing::barycentric_coordinates(p0, p1, p2, x, Double_kernel());
}

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_DOUBLE_KERNEL_H
