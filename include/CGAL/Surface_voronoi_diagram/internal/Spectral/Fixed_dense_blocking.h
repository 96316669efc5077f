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
// Eigen sizes the blocks of its dense products, triangular solves and Cholesky factors from
// the cache sizes it reads from the processor when a program first multiplies, and the
// order of summation follows the blocks. The supernodal factor's fronts, and hence the
// embedding, then differed in their last bits from one machine to another: igea's
// biharmonic diagram (134k vertices) gave other PLY bytes on an EPYC whose Eigen reads
// 32 KiB / 512 KiB / 256 MiB than on the machine the regression matrix was recorded on.
// While one of these guards lives, Eigen blocks as if the caches were always those sizes,
// and puts back what it had read afterwards.
//
// Eigen keeps the sizes in one variable of the process: a dense product that another thread
// of the caller runs meanwhile is blocked by these sizes too (a change of its rounding, not
// of its result's accuracy).

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_SPECTRAL_FIXED_DENSE_BLOCKING_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_SPECTRAL_FIXED_DENSE_BLOCKING_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <Eigen/Core>

#include <cstddef>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

class Fixed_dense_blocking
{
public:
  // the sizes Eigen 3.4 reads on the 2-core EPYC machines the package is measured on, so
  // that their blocking, and their speed, are those of before
  static constexpr std::ptrdiff_t l1 = 32 * 1024;
  static constexpr std::ptrdiff_t l2 = 512 * 1024;
  static constexpr std::ptrdiff_t l3 = 256 * 1024 * 1024;

  Fixed_dense_blocking() : Fixed_dense_blocking(l1, l2, l3) {}
  /// other sizes (the tests play other machines with it)
  Fixed_dense_blocking(std::ptrdiff_t l1_bytes, std::ptrdiff_t l2_bytes, std::ptrdiff_t l3_bytes)
    : m_l1(Eigen::l1CacheSize()), m_l2(Eigen::l2CacheSize()), m_l3(Eigen::l3CacheSize())
  {
    Eigen::setCpuCacheSizes(l1_bytes, l2_bytes, l3_bytes);
  }
  ~Fixed_dense_blocking() { Eigen::setCpuCacheSizes(m_l1, m_l2, m_l3); }

  Fixed_dense_blocking(const Fixed_dense_blocking&) = delete;
  Fixed_dense_blocking& operator=(const Fixed_dense_blocking&) = delete;

private:
  std::ptrdiff_t m_l1, m_l2, m_l3;
};

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_SPECTRAL_FIXED_DENSE_BLOCKING_H
