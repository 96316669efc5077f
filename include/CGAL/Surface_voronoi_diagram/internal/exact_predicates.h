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
// The signs that decide the combinatorics of the per-face lower envelope. Inputs are the
// doubles D_i(v) at the face's corners, taken as exact; each sign is first evaluated in
// double with a forward error bound and recomputed with exact rationals only when the
// bound does not certify it. So both faces of an edge, which see the same inputs, take the
// same decisions, and symmetric layouts with exact ties stay consistent.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_EXACT_PREDICATES_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_EXACT_PREDICATES_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Exact_rational.h>

#include <array>
#include <cmath>
#include <limits>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

typedef CGAL::Exact_rational Exact_number;

inline int sign_of(double x) { return (x > 0) - (x < 0); }
inline int sign_of(const Exact_number& x) { return CGAL::sign(x); }

// A static filter: a generous multiple of the unit roundoff for the short expressions below
// (every input is a difference of two doubles, one rounding, then at most three products and
// five sums). It decides almost every sign in a few flops, where an interval filter would
// change the rounding mode around each evaluation; the rest go to exact rationals.
constexpr double predicate_error_factor = 32 * 1.1102230246251565e-16;
// Products of tiny numbers lose absolute precision (subnormals), which a relative bound
// misses: a few subnormal units more cover it.
constexpr double predicate_error_floor = 64 * std::numeric_limits<double>::denorm_min();

/// sign(A*D - B*C) with A = a1-a2, B = b1-b2, C = c1-c2, D = d1-d2.
inline int sign_of_det2_of_differences(double a1, double a2, double b1, double b2,
                                       double c1, double c2, double d1, double d2)
{
  const double A = a1 - a2, B = b1 - b2, C = c1 - c2, D = d1 - d2;
  const double det = A * D - B * C;
  const double bound = predicate_error_factor * (std::abs(A * D) + std::abs(B * C)) + predicate_error_floor;
  if(det > bound) return 1;
  if(det < -bound) return -1;
  const Exact_number eA = Exact_number(a1) - Exact_number(a2), eB = Exact_number(b1) - Exact_number(b2);
  const Exact_number eC = Exact_number(c1) - Exact_number(c2), eD = Exact_number(d1) - Exact_number(d2);
  return sign_of(eA * eD - eB * eC);
}

/// Rows of differences r = p - q (componentwise), 3 components each.
struct Difference_row
{
  const double* p;
  const double* q;
};

template <class NT>
NT det3_rows(const std::array<std::array<NT, 3>, 3>& m)
{
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
       - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
       + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

inline double permanent3_abs(const std::array<std::array<double, 3>, 3>& m)
{
  auto a = [&](int i, int j) { return std::abs(m[i][j]); };
  return a(0, 0) * (a(1, 1) * a(2, 2) + a(1, 2) * a(2, 1))
       + a(0, 1) * (a(1, 0) * a(2, 2) + a(1, 2) * a(2, 0))
       + a(0, 2) * (a(1, 0) * a(2, 1) + a(1, 1) * a(2, 0));
}

/// sign of det[r0; r1; r2] where r2 is either a difference row or (1, 1, 1).
inline int sign_of_det3_of_differences(const Difference_row& r0, const Difference_row& r1,
                                       const Difference_row* r2)
{
  std::array<std::array<double, 3>, 3> m;
  for(int k = 0; k < 3; ++k)
  {
    m[0][k] = r0.p[k] - r0.q[k];
    m[1][k] = r1.p[k] - r1.q[k];
    m[2][k] = r2 ? r2->p[k] - r2->q[k] : 1.0;
  }
  const double det = det3_rows(m);
  const double bound = 2 * predicate_error_factor * permanent3_abs(m) + predicate_error_floor;
  if(det > bound) return 1;
  if(det < -bound) return -1;
  std::array<std::array<Exact_number, 3>, 3> e;
  for(int k = 0; k < 3; ++k)
  {
    e[0][k] = Exact_number(r0.p[k]) - Exact_number(r0.q[k]);
    e[1][k] = Exact_number(r1.p[k]) - Exact_number(r1.q[k]);
    e[2][k] = r2 ? Exact_number(r2->p[k]) - Exact_number(r2->q[k]) : Exact_number(1);
  }
  return sign_of(det3_rows(e));
}

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_EXACT_PREDICATES_H
