// Copyright (c) 2026 The Surface_voronoi_diagram authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Cotangent stiffness matrix and lumped (barycentric) mass matrix of a triangle mesh.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_SPECTRAL_COTANGENT_LAPLACIAN_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_SPECTRAL_COTANGENT_LAPLACIAN_H

#include <CGAL/Surface_voronoi_diagram/exceptions.h>

#include <Eigen/Sparse>

#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

/// Assembles the positive semi-definite cotangent stiffness matrix `L` and the lumped
/// mass matrix `M` (a third of each incident triangle's area per vertex) from indexed
/// triangles. Throws `Input_error` on a degenerate triangle, since its cotangents are
/// infinite and every eigenvector would be garbage.
inline void assemble_cotangent_laplacian(const std::vector<std::array<double, 3> >& points,
                                         const std::vector<std::array<std::size_t, 3> >& triangles,
                                         Eigen::SparseMatrix<double>& L,
                                         Eigen::SparseMatrix<double>& M)
{
  const Eigen::Index n = static_cast<Eigen::Index>(points.size());
  std::vector<Eigen::Triplet<double> > lt;
  lt.reserve(triangles.size() * 9);
  Eigen::VectorXd mass = Eigen::VectorXd::Zero(n);

  for(std::size_t f = 0; f < triangles.size(); ++f)
  {
    const std::array<std::size_t, 3>& t = triangles[f];
    const std::array<double, 3>* p[3] = { &points[t[0]], &points[t[1]], &points[t[2]] };
    double twice_area = 0;
    {
      const double a[3] = { (*p[1])[0] - (*p[0])[0], (*p[1])[1] - (*p[0])[1], (*p[1])[2] - (*p[0])[2] };
      const double b[3] = { (*p[2])[0] - (*p[0])[0], (*p[2])[1] - (*p[0])[1], (*p[2])[2] - (*p[0])[2] };
      const double c[3] = { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
      twice_area = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    }
    if(!(twice_area > 0) || !std::isfinite(twice_area))
      throw Input_error("face " + std::to_string(f) + " has zero area: the cotangent Laplacian is undefined there");

    for(int k = 0; k < 3; ++k)
    {
      // cot of the angle at corner k weighs the opposite edge (k+1, k+2)
      const std::array<double, 3>& o = *p[k];
      const std::array<double, 3>& u = *p[(k + 1) % 3];
      const std::array<double, 3>& w = *p[(k + 2) % 3];
      const double a[3] = { u[0] - o[0], u[1] - o[1], u[2] - o[2] };
      const double b[3] = { w[0] - o[0], w[1] - o[1], w[2] - o[2] };
      const double dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
      const double half_cot = 0.5 * dot / twice_area;
      const Eigen::Index i = static_cast<Eigen::Index>(t[(k + 1) % 3]);
      const Eigen::Index j = static_cast<Eigen::Index>(t[(k + 2) % 3]);
      lt.emplace_back(i, j, -half_cot);
      lt.emplace_back(j, i, -half_cot);
      lt.emplace_back(i, i, half_cot);
      lt.emplace_back(j, j, half_cot);
    }
    for(int k = 0; k < 3; ++k)
      mass[static_cast<Eigen::Index>(t[k])] += twice_area / 6.0;
  }

  L.resize(n, n);
  L.setFromTriplets(lt.begin(), lt.end());
  M.resize(n, n);
  std::vector<Eigen::Triplet<double> > mt;
  mt.reserve(static_cast<std::size_t>(n));
  for(Eigen::Index i = 0; i < n; ++i)
    mt.emplace_back(i, i, mass[i]);
  M.setFromTriplets(mt.begin(), mt.end());
}

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif
