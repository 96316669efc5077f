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

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

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

/// The Gram determinant `d00 d11 - d01^2` of a triangle's two edge vectors from corner 0,
/// relative to `d00 d11`, is the squared sine of the angle at corner 0. Below this ratio
/// (2^-40, a sine below about 1e-6) the determinant has lost most of its digits to
/// cancellation (its relative error is about 2^-52 / ratio) and may even be exactly zero on a
/// valid needle or cap: `barycentric_coordinates()` then uses cross products instead.
constexpr double needle_gram_ratio = 0x1p-40;

/// whether the Gram determinant of triangle (p0, p1, p2) at corner 0 is below
/// `needle_gram_ratio` of `d00 d11` (or not a finite number): PMP's barycentric coordinates
/// (and `locate`) must not be used on it
inline bool is_needle(const Point_d& p0, const Point_d& p1, const Point_d& p2)
{
  const Vector_d v0 = p1 - p0, v1 = p2 - p0;
  const double d00 = v0 * v0, d01 = v0 * v1, d11 = v1 * v1;
  const double gram = d00 * d11 - d01 * d01;
  return !(gram > needle_gram_ratio * (d00 * d11) && std::isfinite(gram));
}

/// `b` clamped to the triangle and normalized: rounding may leave a coordinate of a point on
/// (or just beside) a face a few ulps below zero, and a location must not step outside it.
inline Barycentric clamped_barycentric(Barycentric b)
{
  double sum = 0;
  for(double& c : b) { c = (std::max)(c, 0.); sum += c; }
  for(double& c : b) c /= sum;
  return b;
}

/// barycentric coordinates of `x` in triangle (p0, p1, p2), of its projection on the
/// triangle's plane if `x` is off it: the package's one way to compute them. PMP's formula
/// (the Gram determinant of the edge vectors) wherever it is sound, bit for bit; on a needle
/// or a cap whose determinant is below `needle_gram_ratio` of `d00 d11` (where that formula
/// divides by noise or by zero), the ratios of the areas of the sub-triangles x p_j p_k to
/// the triangle's, by cross products taken from `x` (their relative error is about 2^-52
/// over the sine of the triangle's smallest angle, not its square, and a point on the line
/// of an edge gets an exact 0 where the edge is axis-aligned). A triangle without any
/// computable normal (coincident or collinear corners, or squares that overflow) gives the
/// projection of `x` on its longest edge, or (1, 0, 0) if its corners coincide: never NaN
/// or infinite for finite input.
inline Barycentric barycentric_coordinates(const Point_d& p0, const Point_d& p1, const Point_d& p2, const Point_d& x)
{
  if(!is_needle(p0, p1, p2))
    return CGAL::Polygon_mesh_processing::barycentric_coordinates(p0, p1, p2, x, Double_kernel());
  const Point_d* p[3] = { &p0, &p1, &p2 };
  const Vector_d n = CGAL::cross_product(p1 - p0, p2 - p0);
  const double nn = n * n;
  Barycentric b = {{ 0., 0., 0. }};
  if(nn > 0 && std::isfinite(nn))
  {
    for(int k = 0; k < 3; ++k)
      b[k] = (n * CGAL::cross_product(*p[(k + 1) % 3] - x, *p[(k + 2) % 3] - x)) / nn;
    if(std::isfinite(b[0]) && std::isfinite(b[1]) && std::isfinite(b[2])) return b;
    b = {{ 0., 0., 0. }};
  }
  // no normal: the longest edge (a, b), corners ia and ib, the third corner gets 0
  int ia = 0;
  double longest = -1;
  for(int k = 0; k < 3; ++k)
  {
    const double l = CGAL::squared_distance(*p[k], *p[(k + 1) % 3]);
    if(l > longest) { longest = l; ia = k; }
  }
  const int ib = (ia + 1) % 3;
  if(!(longest > 0) || !std::isfinite(longest))
  {
    b[0] = 1.;
    return b;
  }
  const double t = ((x - *p[ia]) * (*p[ib] - *p[ia])) / longest;
  b[ia] = 1. - t;
  b[ib] = t;
  return b;
}

/// The location of `p`, a point of face `f`, in `f`: PMP's `locate_in_face()` (with `vpm`
/// and `gt`), or `barycentric_coordinates()` above when `f` `is_needle()`.
template <class Point, class TriangleMesh, class VertexPointMap, class GeomTraits>
CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double>
locate_in_face(const Point& p, typename boost::graph_traits<TriangleMesh>::face_descriptor f, const TriangleMesh& tm,
               const VertexPointMap& vpm, const GeomTraits& gt)
{
  const auto h = halfedge(f, tm);
  const Point_d p0 = to_point_d(get(vpm, source(h, tm))), p1 = to_point_d(get(vpm, target(h, tm))),
                p2 = to_point_d(get(vpm, target(next(h, tm), tm)));
  if(!is_needle(p0, p1, p2))
    return CGAL::Polygon_mesh_processing::locate_in_face(p, f, tm, CGAL::parameters::vertex_point_map(vpm).geom_traits(gt));
  return CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double>(f, barycentric_coordinates(p0, p1, p2, to_point_d(p)));
}

// Among the faces `fs` of `pm`, the one in which `p` has the largest smallest barycentric
// coordinate (the first among equals; a null face if `fs` is empty), and those coordinates
template <class FaceRange, class PolygonMesh, class VertexPointMap>
std::pair<typename boost::graph_traits<PolygonMesh>::face_descriptor, Barycentric>
innermost_face(const FaceRange& fs, const PolygonMesh& pm, const VertexPointMap& vpm, const Point_d& p)
{
  std::pair<typename boost::graph_traits<PolygonMesh>::face_descriptor, Barycentric> best(
      boost::graph_traits<PolygonMesh>::null_face(), {{ 1., 0., 0. }});
  double best_min = -std::numeric_limits<double>::infinity();
  for(const auto f : fs)
  {
    const auto h = halfedge(f, pm);
    const Barycentric b = barycentric_coordinates(to_point_d(get(vpm, source(h, pm))), to_point_d(get(vpm, target(h, pm))),
                                                  to_point_d(get(vpm, target(next(h, pm), pm))), p);
    if((std::min)({ b[0], b[1], b[2] }) > best_min)
    {
      best_min = (std::min)({ b[0], b[1], b[2] });
      best = { f, b };
    }
  }
  return best;
}

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_DOUBLE_KERNEL_H
