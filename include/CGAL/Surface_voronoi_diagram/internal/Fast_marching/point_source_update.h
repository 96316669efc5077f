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
// The triangle update of fast marching with a point source: the front reaching a triangle
// is taken as coming from one point, unfolded into the triangle's plane (the
// circle-intersection update). It is exact on developable patches seen directly from the
// source, unlike the plane-wave update of classic fast marching.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_FAST_MARCHING_POINT_SOURCE_UPDATE_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_FAST_MARCHING_POINT_SOURCE_UPDATE_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/internal/Double_kernel.h>

#include <cmath>
#include <limits>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

typedef Double_kernel::Point_2 Point_2d;

/// The distance at `c` of a point source that is at distance `da` from `a` and `db` from `b`
/// and lies on the other side of the line ab than `c`, in the frame where a = (0, 0),
/// b = (ab, 0) and c = (cx, cy), cy > 0; +infinity when no such source exists or when the
/// straight path from it to `c` misses the segment ab.
inline double point_source_in_frame(double ab, double cx, double cy, double da, double db)
{
  const double inf = std::numeric_limits<double>::infinity();
  if(!(ab > 0) || !(cy > 0)) return inf;
  const double sx = (da * da - db * db + ab * ab) / (2 * ab);
  const double sy2 = da * da - sx * sx;
  if(sy2 < 0) return inf;
  const double sy = -std::sqrt(sy2);
  const double x0 = sx + (-sy / (cy - sy)) * (cx - sx);   // where the path from the source meets line ab
  if(x0 < 0 || x0 > ab) return inf;
  return std::sqrt((cx - sx) * (cx - sx) + (cy - sy) * (cy - sy));
}

/// The same update with a, b and c anywhere in the plane.
inline double point_source_update(const Point_2d& a, const Point_2d& b, const Point_2d& c, double da, double db)
{
  const double ux = b.x() - a.x(), uy = b.y() - a.y();
  const double L = std::sqrt(ux * ux + uy * uy);
  if(!(L > 0)) return std::numeric_limits<double>::infinity();
  const double cx = ((c.x() - a.x()) * ux + (c.y() - a.y()) * uy) / L;
  const double cy = std::abs((c.y() - a.y()) * ux - (c.x() - a.x()) * uy) / L;
  return point_source_in_frame(L, cx, cy, da, db);
}

/// The same update on a triangle abc given by its side lengths.
inline double point_source_update(double ab, double ac, double bc, double da, double db)
{
  if(!(ab > 0)) return std::numeric_limits<double>::infinity();
  const double cx = (ac * ac - bc * bc + ab * ab) / (2 * ab);
  const double cy2 = ac * ac - cx * cx;
  return point_source_in_frame(ab, cx, cy2 > 0 ? std::sqrt(cy2) : 0., da, db);
}

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_FAST_MARCHING_POINT_SOURCE_UPDATE_H
