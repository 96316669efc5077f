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
// Where the vertices of a face's cut lie, in numbers: a bisector's crossing of a mesh edge
// and the triple point of three fields. Stitching places the partition's vertices with these,
// and Lloyd's cell measures the pieces of the cuts with the same ones, so that both see the
// same points.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_BISECTOR_POINTS_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_BISECTOR_POINTS_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/internal/Double_kernel.h>
#include <CGAL/Surface_voronoi_diagram/internal/exact_predicates.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

/// The parameter along the edge from corner `ca` to corner `cb` where the fields `lo` and
/// `hi` (values at the face's corners) are equal, kept in [0, 1].
inline double edge_crossing_parameter(const double* lo, const double* hi, int ca, int cb)
{
  const double da = lo[ca] - hi[ca], db = lo[cb] - hi[cb];
  const double t = da / (da - db);
  return (std::min)(1., (std::max)(0., t));
}

/// The barycentric coordinates where three fields are equal, in rationals; false when their
/// bisectors are parallel.
inline bool exact_triple_barycentric(const double* d0, const double* d1, const double* d2, std::array<Exact_number, 3>& b)
{
  std::array<Exact_number, 3> r1, r2;
  for(int c = 0; c < 3; ++c)
  {
    r1[c] = Exact_number(d0[c]) - Exact_number(d1[c]);
    r2[c] = Exact_number(d0[c]) - Exact_number(d2[c]);
  }
  b[0] = r1[1] * r2[2] - r1[2] * r2[1];
  b[1] = r1[2] * r2[0] - r1[0] * r2[2];
  b[2] = r1[0] * r2[1] - r1[1] * r2[0];
  const Exact_number s = b[0] + b[1] + b[2];
  if(CGAL::is_zero(s)) return false;
  for(Exact_number& x : b) x = x / s;
  return true;
}

/// Whether the rounded sum s of r1 x r2 is far enough from its rounding error (a few ulps of
/// |r1| |r2|) to divide by. It is not when two sites' fields differ by far less than the
/// third's (two sites 1e-10 apart on a needle): r1 and r2 then round to the same vector.
inline bool is_well_conditioned_triple(double s, const Vector_d& r1, const Vector_d& r2)
{
  const double n1 = std::abs(r1.x()) + std::abs(r1.y()) + std::abs(r1.z());
  const double n2 = std::abs(r2.x()) + std::abs(r2.y()) + std::abs(r2.z());
  const double bound = 64 * std::numeric_limits<double>::epsilon() * n1 * n2;
  return std::isfinite(s) && std::isfinite(bound) && std::abs(s) > bound;
}

/// The barycentric point where the three fields are equal (r1 x r2 of their differences),
/// in rationals where the doubles cannot decide, and kept on the face. Exact parallel
/// bisectors have no triple point and the cutter does not make one: the face's centroid is
/// only a guard.
inline Barycentric triple_point_barycentric(const double* d0, const double* d1, const double* d2)
{
  const Vector_d r1(d0[0] - d1[0], d0[1] - d1[1], d0[2] - d1[2]);
  const Vector_d r2(d0[0] - d2[0], d0[1] - d2[1], d0[2] - d2[2]);
  const Vector_d c = CGAL::cross_product(r1, r2);
  Barycentric b = {{ c.x(), c.y(), c.z() }};
  double s = 0;
  for(double& x : b) s += x;
  if(is_well_conditioned_triple(s, r1, r2))
    for(double& x : b) x /= s;
  else
  {
    std::array<Exact_number, 3> e;
    b = {{ 1. / 3, 1. / 3, 1. / 3 }};
    if(exact_triple_barycentric(d0, d1, d2, e))
      for(int k = 0; k < 3; ++k) b[k] = CGAL::to_double(e[k]);
  }
  // rounding may push the point a hair outside its face: keep it on the face
  double s2 = 0;
  for(double& x : b) { x = (std::max)(0., x); s2 += x; }
  for(double& x : b) x /= s2;
  return b;
}

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_BISECTOR_POINTS_H
