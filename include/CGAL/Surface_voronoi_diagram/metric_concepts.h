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
// The tags that tell the diagram which of the two metric concepts a model follows.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_METRIC_CONCEPTS_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_METRIC_CONCEPTS_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <type_traits>

namespace CGAL {
namespace Surface_voronoi {

/// \ingroup PkgSurfaceVoronoiDiagramMetrics
/// `Metric_category` of a model of `SurfaceVoronoiEmbedding`: per-vertex coordinates in
/// \f$ \mathbb{R}^d \f$. The embedding of a surface point is the barycentric interpolation of
/// its face's corners, and per-face cutting of squared distances is exact. A metric whose
/// `Metric_category` is any other type is used as a `SurfaceVoronoiLazyMetric`.
struct Embedding_tag {};

/// \ingroup PkgSurfaceVoronoiDiagramMetrics
/// `Metric_category` of a model of `SurfaceVoronoiLazyMetric`: squared distances between a
/// site and a vertex, computed on demand, only where the site propagates. Inside a face the
/// squared distance is interpolated linearly, an approximation (\cgalCite{cgal:bddvd},
/// eq. 4-5).
struct Lazy_metric_tag {};

namespace internal {
template <class Metric>
struct Is_embedding
  : std::is_same<typename Metric::Metric_category, Embedding_tag>
{};
} // namespace internal

} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_METRIC_CONCEPTS_H
