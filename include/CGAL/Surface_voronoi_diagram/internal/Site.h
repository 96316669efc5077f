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
// A site as the pipeline sees it.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_SITE_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_SITE_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <array>
#include <cstddef>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

/// A face of the indexed mesh and barycentric coordinates in that face's corner order,
/// plus the site's power weight.
struct Site
{
  std::size_t face = 0;
  std::array<double, 3> barycentric = {{ 1., 0., 0. }};
  double weight = 0.;
};

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_SITE_H
