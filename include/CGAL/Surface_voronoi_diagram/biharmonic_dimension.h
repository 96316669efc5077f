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
// How many cells a biharmonic embedding of dimension d resolves, and the dimension that
// resolves n sites: the rule behind the program's --dimension auto.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_BIHARMONIC_DIMENSION_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_BIHARMONIC_DIMENSION_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <algorithm>
#include <cstddef>

namespace CGAL {
namespace Surface_voronoi {

/// \ingroup PkgSurfaceVoronoiDiagramMetrics
/// The number of sites whose cells a biharmonic embedding of dimension `d` resolves:
/// `sites_per_dimension * d`, with `sites_per_dimension` = 30.
///
/// The embedding keeps the eigenfunctions \f$ \phi_1 \dots \phi_d \f$, which by Weyl's law
/// (\f$ \lambda_k \approx 4 \pi k / A \f$ on a surface of area \f$ A \f$) vary on lengths of
/// about \f$ \sqrt{A / d} \f$ and no shorter: cells much smaller than that are not told apart,
/// and come out in pieces or wrapped around thin parts. The factor was measured on the models
/// of the remeshing benchmark (3000 sites; see the manual's section on the biharmonic
/// dimension): with fewer than `d * 30` sites, few cells are not disks.
inline std::size_t biharmonic_resolved_sites(std::size_t d)
{
  const std::size_t sites_per_dimension = 30;
  return d * sites_per_dimension;
}

/// \ingroup PkgSurfaceVoronoiDiagramMetrics
/// The embedding dimension for `n` sites (the program's `--dimension auto`): the smallest
/// dimension that resolves them (`biharmonic_resolved_sites()`), and at least 10, the
/// reference paper's default. The caller caps it by
/// `Biharmonic_embedding::maximum_dimension()`.
inline std::size_t biharmonic_dimension_for_sites(std::size_t n)
{
  const std::size_t per = biharmonic_resolved_sites(1);
  return (std::max)(std::size_t(10), (n + per - 1) / per);
}

} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_BIHARMONIC_DIMENSION_H
