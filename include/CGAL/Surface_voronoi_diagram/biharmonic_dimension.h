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

/// \ingroup PkgSurfaceVoronoiDiagramMetrics
/// The memory, in bytes, that the columns of `Biharmonic_green_metric` take for `sites` sites
/// on a mesh of `vertices` vertices: one `double` per vertex and site.
inline double biharmonic_green_metric_bytes(std::size_t vertices, std::size_t sites)
{
  return 8. * double(vertices) * double(sites);
}

/// \ingroup PkgSurfaceVoronoiDiagramMetrics
/// The program's `--dimension auto`: whether to use the full spectrum
/// (`Biharmonic_green_metric`) for `sites` sites on a mesh of `vertices` vertices, rather than an
/// embedding of dimension `biharmonic_dimension_for_sites(sites)`: whenever its columns fit in
/// `budget` bytes (`biharmonic_green_metric_bytes()`; 2 GiB by default).
///
/// The full spectrum is the limit the embeddings approach as their dimension grows, and at
/// thousands of sites they are far from it: on the models of the remeshing benchmark (3000
/// sites, 10 Lloyd steps, sites added until the dual is valid), dimension 100 gives a valid dual
/// on 3 models of 9, the full spectrum on 7 (see the manual's section on the biharmonic
/// dimension). Its cost is two solves per site and diagram, where an embedding is computed
/// once.
inline bool biharmonic_full_spectrum_for_sites(std::size_t vertices, std::size_t sites,
                                               double budget = 2147483648.)
{
  return biharmonic_green_metric_bytes(vertices, sites) <= budget;
}

} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_BIHARMONIC_DIMENSION_H
