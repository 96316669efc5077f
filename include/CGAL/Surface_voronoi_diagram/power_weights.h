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
// Power weights are in the squared units of the metric: squared lengths for the Euclidean
// and geodesic metrics, but biharmonic distances are several times smaller than lengths.
// This helper converts a squared length into the metric's units.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_POWER_WEIGHTS_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_POWER_WEIGHTS_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/metric_concepts.h>
#include <CGAL/Surface_voronoi_diagram/internal/Double_kernel.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Dynamic_property_map.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <queue>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {

namespace internal {

// The mean ratio of squared embedding distance to squared length over pairs of vertices
// between 0.8 and 1.25 times `length` apart: from 64 vertices spread over the vertex order, a
// Dijkstra search along the edges (so that pairs on two sides of a thin wall are not taken)
// up to a path of 1.6 times `length` (or to the whole component of a small mesh).
template <class Metric, class NamedParameters>
double squared_length_ratio(const Metric& metric, double length, const NamedParameters& np, std::true_type)
{
  typedef typename Metric::Triangle_mesh Mesh;
  const Mesh& tm = metric.triangle_mesh();
  const auto vpm = CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                                                      get_const_property_map(CGAL::vertex_point, tm));
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor V;
  const std::vector<V> all(vertices(tm).begin(), vertices(tm).end());
  if(all.size() < 2) return 1.;
  auto index = get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm);
  for(std::size_t i = 0; i < all.size(); ++i) put(index, all[i], i);
  const std::size_t d = metric.dimension();
  std::vector<double> coordinates(all.size() * d);
  for(std::size_t i = 0; i < all.size(); ++i) metric.coordinates(all[i], coordinates.begin() + std::ptrdiff_t(i * d));
  std::vector<double> path(all.size(), -1.);
  double metric_sum = 0, length_sum = 0;
  const std::size_t sources = (std::min)(all.size(), std::size_t(64));
  for(std::size_t s = 0; s < sources; ++s)
  {
    const std::size_t source_index = s * all.size() / sources;
    std::vector<std::size_t> reached;
    typedef std::pair<double, std::size_t> Item;
    std::priority_queue<Item, std::vector<Item>, std::greater<Item> > queue;
    queue.push(Item(0., source_index));
    std::fill(path.begin(), path.end(), -1.);
    while(!queue.empty())
    {
      const Item top = queue.top();
      queue.pop();
      if(path[top.second] >= 0) continue;
      path[top.second] = top.first;
      reached.push_back(top.second);
      if(top.first > 1.6 * length) break;
      for(auto h : CGAL::halfedges_around_target(all[top.second], tm))
      {
        const std::size_t w = get(index, source(h, tm));
        if(path[w] < 0)
          queue.push(Item(top.first + std::sqrt(CGAL::squared_distance(to_point_d(get(vpm, all[top.second])), to_point_d(get(vpm, all[w])))), w));
      }
    }
    const Point_d p = to_point_d(get(vpm, all[source_index]));
    double farthest = 0;
    for(std::size_t v : reached) farthest = (std::max)(farthest, CGAL::squared_distance(p, to_point_d(get(vpm, all[v]))));
    farthest = std::sqrt(farthest);
    const double low = (std::min)(0.8 * length, 0.8 * farthest), high = (std::min)(1.25 * length, farthest);
    for(std::size_t v : reached)
    {
      const double chord = std::sqrt(CGAL::squared_distance(p, to_point_d(get(vpm, all[v]))));
      if(v == source_index || chord < low || chord > high) continue;
      for(std::size_t k = 0; k < d; ++k)
      {
        const double e = coordinates[v * d + k] - coordinates[source_index * d + k];
        metric_sum += e * e;
      }
      length_sum += chord * chord;
    }
  }
  return length_sum > 0 ? metric_sum / length_sum : 1.;
}

template <class Metric, class NamedParameters>
double squared_length_ratio(const Metric&, double, const NamedParameters&, std::false_type)
{
  return 1.;
}

} // namespace internal

/// \ingroup PkgSurfaceVoronoiDiagramMetrics
/// The power weight, in the squared units of `metric`, that corresponds to the squared length
/// `squared_length` on the mesh. For an embedding, `squared_length` times the mean ratio of
/// squared embedding distance to squared length between vertices about `sqrt(squared_length)`
/// apart (along the mesh's edges, from 64 vertices): 1 for `Surface_voronoi::Euclidean_embedding`,
/// and for `CGAL::Biharmonic_embedding` a ratio that depends on the mesh (measured with d = 10
/// on the bundled lampshade, of diameter 1.1: between 0.087 and 0.100 for lengths from the
/// mean edge length to a fifth of the diameter). For a lazy metric (whose squared
/// distances are squared lengths, as `Surface_voronoi::Geodesic_metric`'s are),
/// `squared_length` itself.
///
/// A weight `w` moves the boundary between two cells about `w / (2 D)` towards the
/// neighbour, where `D` is the distance between the sites: weights beyond the squared
/// spacing of the sites empty cells.
///
/// \tparam Metric a model of `SurfaceVoronoiEmbedding` or of `SurfaceVoronoiLazyMetric`
/// \param metric the metric
/// \param squared_length a squared length on the mesh `metric.triangle_mesh()`
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of
///       `metric.triangle_mesh()` (used for embeddings only)}
///     \cgalParamType{a model of `ReadablePropertyMap`}
///     \cgalParamDefault{`get_const_property_map(CGAL::vertex_point, metric.triangle_mesh())`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the weight that moves bisectors as a difference `squared_length` of squared
///          lengths would
template <class Metric, class NamedParameters = CGAL::parameters::Default_named_parameters>
double weight_for_squared_length(const Metric& metric, double squared_length,
                                 const NamedParameters& np = CGAL::parameters::default_values())
{
  return squared_length * internal::squared_length_ratio(metric, std::sqrt(squared_length), np, internal::Is_embedding<Metric>());
}

} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_POWER_WEIGHTS_H
