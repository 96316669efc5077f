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
// Deprecated: the options of the diagram are named parameters now (parameters.h); this
// header keeps the old struct for one release.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_OPTIONS_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_OPTIONS_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/Diagram_statistics.h>
#include <CGAL/Surface_voronoi_diagram/parameters.h>

#include <CGAL/config.h>

#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {

/// \ingroup PkgSurfaceVoronoiDiagramDeprecated
/// \deprecated Use the named parameters `site_weight_map`, `candidate_selection`,
/// `repair_cells`, `max_repair_rounds` and `max_site_distance`.
struct CGAL_DEPRECATED_MSG("use the named parameters of Surface_voronoi_diagram")
Diagram_options
{
  /// power weights by site index (empty: all zero)
  std::vector<double> weights;
  /// candidate selection
  Candidate_selection candidates = Candidate_selection::PROPAGATION;
  /// whether broken cells are repaired
  bool repair = true;
  /// the most repair rounds
  std::size_t max_repair_rounds = 100;
  /// the farthest a site given as a point may be from the surface
  double max_site_distance = std::numeric_limits<double>::infinity();
};

} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_OPTIONS_H
