// Copyright (c) 2026 The Surface_voronoi_diagram authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Tags that tell the diagram how a metric model gives its distances.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_METRIC_CONCEPTS_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_METRIC_CONCEPTS_H

#include <type_traits>

namespace CGAL {
namespace Surface_voronoi {

/// \ingroup PkgSurfaceVoronoiDiagramMetrics
/// `Metric_category` of a model of `SurfaceVoronoiEmbedding`: per-vertex coordinates in R^d.
/// The embedding of a surface point is the barycentric interpolation of its face's corners,
/// and per-face cutting of squared distances is exact.
struct Embedding_tag {};

/// \ingroup PkgSurfaceVoronoiDiagramMetrics
/// `Metric_category` of a model of `SurfaceVoronoiMetric` that is not an embedding: it gives
/// squared distances between a site and a vertex, possibly computed lazily, only where the
/// site propagates. Inside a face the squared distance is interpolated linearly (an
/// approximation, paper eq. 4-5).
struct Lazy_metric_tag {};

namespace internal {
template <class Metric>
struct Is_embedding
  : std::is_same<typename Metric::Metric_category, Embedding_tag>
{};
} // namespace internal

} // namespace Surface_voronoi
} // namespace CGAL

#endif
