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
// A fill-reducing ordering for Eigen's simplicial Cholesky factorizations: METIS nested
// dissection (Debian's libmetis-dev), for builds that define CGAL_USE_METIS.
//
// METIS is called directly rather than through SuiteSparse's CHOLMOD: linking CHOLMOD brings
// OpenBLAS, whose thread pool starts with the process and spins on the second core (0.1 s of
// system time on every run, even one that never orders a matrix). Nor is CHOLMOD's own
// supernodal factorization used: it runs its dense blocks through the BLAS, whose rounding
// depends on the number of BLAS threads and on the processor's kernels (an OpenBLAS
// factorization of the same matrix differs in its last bits between 1 and 2 threads, and
// between Haswell and SkylakeX kernels), so the embedding, and every diagram built on it,
// would not be reproducible bit for bit. An ordering is a permutation: integers, the same on
// every machine (METIS seeds its random numbers with a constant), and the simplicial
// factorization that follows is the package's own compiled code. On a 537k-vertex Laplacian
// the METIS ordering has 37% fewer non-zeros in the factor than Eigen's approximate minimum
// degree (25.6M against 40.7M) and 3.5 times fewer flops.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_SPECTRAL_NESTED_DISSECTION_ORDERING_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_SPECTRAL_NESTED_DISSECTION_ORDERING_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <Eigen/Sparse>
#include <Eigen/OrderingMethods>

#ifdef CGAL_USE_METIS
#include <metis.h>
#endif

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

#ifdef CGAL_USE_METIS

/// An ordering functor for `Eigen::SimplicialLLT` and `Eigen::SimplicialLDLT`: METIS nested
/// dissection from `smallest_size` rows up, Eigen's AMD below (and when METIS reports a
/// failure, such as no memory). Like Eigen's orderings it returns the inverse permutation:
/// `perm.indices()[k]` is the k-th row eliminated.
template <typename StorageIndex>
class Nested_dissection_ordering
{
public:
  typedef Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, StorageIndex> PermutationType;

  /// Below this size METIS costs more than it saves: on the 20k-vertex boot it adds 0.05 s to
  /// a 0.1 s eigen-solve; at 134k it saves 8% of it, at 537k half.
  static constexpr Eigen::Index smallest_size = 100000;

  /// `matrix` holds the full symmetric pattern (Eigen passes both triangles)
  template <typename MatrixType>
  void operator()(const MatrixType& matrix, PermutationType& perm)
  {
    if(matrix.rows() >= smallest_size && metis(matrix, perm))
      return;
    Eigen::AMDOrdering<StorageIndex> amd;
    amd(matrix, perm);
  }

  /// the METIS ordering alone, of the pattern of `matrix` (either triangle, or both, may be
  /// stored); false if METIS failed
  template <typename MatrixType>
  static bool metis(const MatrixType& matrix, PermutationType& perm)
  {
    // METIS takes the adjacency graph: both directions of every off-diagonal entry, no loops.
    const idx_t n = static_cast<idx_t>(matrix.rows());
    Eigen::SparseMatrix<double, Eigen::ColMajor, idx_t> pattern(matrix.rows(), matrix.cols());
    pattern = matrix.template triangularView<Eigen::StrictlyLower>();
    Eigen::SparseMatrix<double, Eigen::ColMajor, idx_t> transposed = pattern.transpose();
    pattern += transposed;
    pattern.makeCompressed();
    std::vector<idx_t> xadj(pattern.outerIndexPtr(), pattern.outerIndexPtr() + n + 1);
    std::vector<idx_t> adjncy(pattern.innerIndexPtr(), pattern.innerIndexPtr() + pattern.nonZeros());
    std::vector<idx_t> order(static_cast<std::size_t>(n)), position(static_cast<std::size_t>(n));
    idx_t options[METIS_NOPTIONS];
    METIS_SetDefaultOptions(options);
    idx_t nvtxs = n;
    if(n == 0 || METIS_NodeND(&nvtxs, xadj.data(), adjncy.data(), nullptr, options, order.data(), position.data()) != METIS_OK)
      return false;
    perm.resize(matrix.rows());
    for(std::size_t k = 0; k < order.size(); ++k)
      perm.indices()[static_cast<Eigen::Index>(k)] = static_cast<StorageIndex>(order[k]);
    return true;
  }
};

#endif // CGAL_USE_METIS

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_SPECTRAL_NESTED_DISSECTION_ORDERING_H
