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

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

/// Assembles the positive semi-definite cotangent stiffness matrix `L` and the lumped mass
/// matrix `M` (a third of each incident triangle's area per vertex) from indexed triangles.
/// The three cotangents of a face share its one cross product (cot = dot / |cross|), which
/// CGAL::Weights::cotangent would recompute per corner.
///
/// `L` is built in place, compressed, with sorted row indices: its pattern (the diagonal and
/// both directions of every edge) first, then each contribution added to its slot, face by
/// face. Each entry is the sum of its contributions in the order `setFromTriplets()` would
/// sum them given four triplets per corner in face order, the first one taking the entry,
/// so the matrix is the same bits as that assembly (a test compares them), without its
/// 12 triplets of 16 bytes per face (206 MB at 537k vertices) and its two sorting passes.
/// \pre no triangle has zero area (its cotangents would be infinite)
template <class Index>
void assemble_cotangent_laplacian(const std::vector<Point_d>& points,
                                  const std::vector<std::array<Index, 3> >& triangles,
                                  Eigen::SparseMatrix<double>& L,
                                  Eigen::SparseMatrix<double>& M)
{
  typedef Eigen::SparseMatrix<double>::StorageIndex Storage;
  const std::size_t n = points.size();
  const std::size_t largest_index = std::size_t((std::numeric_limits<Storage>::max)());
  CGAL_precondition_msg(n < largest_index, "too many vertices for the matrix's indices");

  // the pattern: column j holds j and the vertices sharing a triangle with it (both
  // directions of each edge, once), sorted; a vertex in no triangle has an empty column
  std::vector<std::size_t> begin(n + 1, 0);
  for(const std::array<Index, 3>& t : triangles)
    for(int k = 0; k < 3; ++k) begin[std::size_t(t[k]) + 1] += 2;
  for(std::size_t j = 0; j < n; ++j) begin[j + 1] += begin[j] + (begin[j + 1] > 0 ? 1 : 0);   // and the diagonal
  std::vector<Storage> rows(begin[n]);
  {
    std::vector<std::size_t> next(begin.begin(), begin.end() - 1);
    for(std::size_t j = 0; j < n; ++j)
      if(begin[j + 1] > begin[j]) rows[next[j]++] = Storage(j);
    for(const std::array<Index, 3>& t : triangles)
      for(int k = 0; k < 3; ++k)
      {
        const std::size_t j = std::size_t(t[k]);
        rows[next[j]++] = Storage(t[(k + 1) % 3]);
        rows[next[j]++] = Storage(t[(k + 2) % 3]);
      }
  }
  L.resize(Eigen::Index(n), Eigen::Index(n));   // compressed, its column offsets written below
  Storage* outer = L.outerIndexPtr();
  std::size_t nnz = 0;
  for(std::size_t j = 0; j < n; ++j)
  {
    const auto first = rows.begin() + std::ptrdiff_t(begin[j]), last = rows.begin() + std::ptrdiff_t(begin[j + 1]);
    std::sort(first, last);
    const auto end = std::unique(first, last);
    CGAL_precondition_msg(nnz + std::size_t(end - first) < largest_index, "too many non-zeros for the matrix's indices");
    outer[j] = Storage(nnz);
    for(auto it = first; it != end; ++it) rows[nnz++] = *it;   // compacted in place, forwards
  }
  outer[n] = Storage(nnz);
  rows.resize(nnz);
  std::vector<std::size_t>().swap(begin);

  L.resizeNonZeros(Eigen::Index(nnz));
  std::copy(rows.begin(), rows.end(), L.innerIndexPtr());
  double* value = L.valuePtr();
  std::vector<std::uint8_t> taken(nnz, 0);
  // the slot of entry (i, j): row i in column j's few rows
  auto add = [&](std::size_t i, std::size_t j, double v) {
    const Storage* first = L.innerIndexPtr() + outer[j];
    const Storage* last = L.innerIndexPtr() + outer[j + 1];
    const std::size_t slot = std::size_t(std::lower_bound(first, last, Storage(i)) - L.innerIndexPtr());
    CGAL_assertion(slot < std::size_t(outer[j + 1]) && std::size_t(L.innerIndexPtr()[slot]) == i);
    if(taken[slot]) value[slot] += v;
    else
    {
      value[slot] = v;
      taken[slot] = 1;
    }
  };

  Eigen::VectorXd mass = Eigen::VectorXd::Zero(Eigen::Index(n));
  for(const std::array<Index, 3>& t : triangles)
  {
    const Point_d* p[3] = { &points[t[0]], &points[t[1]], &points[t[2]] };
    const double twice_area = std::sqrt(CGAL::cross_product(*p[1] - *p[0], *p[2] - *p[0]).squared_length());
    CGAL_precondition_msg(twice_area > 0 && std::isfinite(twice_area), "a face has zero area");
    for(int k = 0; k < 3; ++k)
    {
      // cot of the angle at corner k weighs the opposite edge (k+1, k+2)
      const double half_cot = 0.5 * ((*p[(k + 1) % 3] - *p[k]) * (*p[(k + 2) % 3] - *p[k])) / twice_area;
      const std::size_t i = std::size_t(t[(k + 1) % 3]);
      const std::size_t j = std::size_t(t[(k + 2) % 3]);
      add(i, j, -half_cot);
      add(j, i, -half_cot);
      add(i, i, half_cot);
      add(j, j, half_cot);
    }
    for(int k = 0; k < 3; ++k)
      mass[Eigen::Index(t[k])] += twice_area / 6.0;
  }

  M.resize(Eigen::Index(n), Eigen::Index(n));
  M.resizeNonZeros(Eigen::Index(n));
  for(std::size_t j = 0; j < n; ++j)
  {
    M.outerIndexPtr()[j] = Storage(j);
    M.innerIndexPtr()[j] = Storage(j);
    M.valuePtr()[j] = mass[Eigen::Index(j)];
  }
  M.outerIndexPtr()[n] = Storage(n);
}

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_SPECTRAL_COTANGENT_LAPLACIAN_H
