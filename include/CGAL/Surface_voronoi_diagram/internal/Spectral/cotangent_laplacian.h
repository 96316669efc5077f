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
// Cotangent stiffness matrix and lumped (barycentric) mass matrix of a triangle mesh.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_SPECTRAL_COTANGENT_LAPLACIAN_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_SPECTRAL_COTANGENT_LAPLACIAN_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/internal/Double_kernel.h>

#include <CGAL/assertions.h>

#include <Eigen/Sparse>

#include <array>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

/// Assembles the positive semi-definite cotangent stiffness matrix `L` and the lumped mass
/// matrix `M` (a third of each incident triangle's area per vertex) from indexed triangles.
/// The three cotangents of a face share its one cross product (cot = dot / |cross|), which
/// CGAL::Weights::cotangent would recompute per corner.
/// \pre no triangle has zero area (its cotangents would be infinite)
template <class Index>
void assemble_cotangent_laplacian(const std::vector<Point_d>& points,
                                  const std::vector<std::array<Index, 3> >& triangles,
                                  Eigen::SparseMatrix<double>& L,
                                  Eigen::SparseMatrix<double>& M)
{
  const Eigen::Index n = static_cast<Eigen::Index>(points.size());
  std::vector<Eigen::Triplet<double> > lt;
  lt.reserve(triangles.size() * 12);
  Eigen::VectorXd mass = Eigen::VectorXd::Zero(n);

  for(const std::array<Index, 3>& t : triangles)
  {
    const Point_d* p[3] = { &points[t[0]], &points[t[1]], &points[t[2]] };
    const double twice_area = std::sqrt(CGAL::cross_product(*p[1] - *p[0], *p[2] - *p[0]).squared_length());
    CGAL_precondition_msg(twice_area > 0 && std::isfinite(twice_area), "a face has zero area");
    for(int k = 0; k < 3; ++k)
    {
      // cot of the angle at corner k weighs the opposite edge (k+1, k+2)
      const double half_cot = 0.5 * ((*p[(k + 1) % 3] - *p[k]) * (*p[(k + 2) % 3] - *p[k])) / twice_area;
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

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_SPECTRAL_COTANGENT_LAPLACIAN_H
