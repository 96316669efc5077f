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
// Power weights are in the squared units of the metric, and these units are not lengths:
// biharmonic distances are several times smaller than lengths, by a factor that varies over
// the surface, and a lazy metric may add a term of the vertex to its values. A weight sized
// by one global factor is too large where the metric is locally short and empties cells
// there; this helper measures the metric around the site itself.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_POWER_WEIGHTS_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_POWER_WEIGHTS_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/exceptions.h>
#include <CGAL/Surface_voronoi_diagram/metric_concepts.h>
#include <CGAL/Surface_voronoi_diagram/internal/Double_kernel.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <map>
#include <queue>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {

namespace internal {

// the corners of a face in the order of the barycentric coordinates of a `Face_location`
template <class TriangleMesh>
std::array<typename boost::graph_traits<TriangleMesh>::vertex_descriptor, 3>
face_corners(typename boost::graph_traits<TriangleMesh>::face_descriptor f, const TriangleMesh& tm)
{
  const auto h = halfedge(f, tm);
  return {{ source(h, tm), target(h, tm), target(next(h, tm), tm) }};
}

// The vertices where the metric is sampled around a site (see `weight_for_length()`): the
// search runs along the edges so that vertices across a thin wall, near in space but far on
// the surface, are not taken.
template <class TriangleMesh, class VertexPointMap>
std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>
power_weight_samples(const TriangleMesh& tm, const VertexPointMap& vpm,
                     const CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double>& site,
                     const Point_d& p, double length)
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor V;
  constexpr std::size_t at_least = 8, at_most = 24;
  typedef std::pair<double, V> Item;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item> > queue;
  for(V c : face_corners(site.first, tm))
    queue.push(Item(std::sqrt(CGAL::squared_distance(p, to_point_d(get(vpm, c)))), c));
  std::map<V, bool> done;
  std::vector<V> reached;
  while(!queue.empty())
  {
    const Item top = queue.top();
    queue.pop();
    if(done[top.second]) continue;
    if(top.first > 2 * length && reached.size() >= at_least) break;
    done[top.second] = true;
    const Point_d q = to_point_d(get(vpm, top.second));
    if(q != p) reached.push_back(top.second);
    for(V w : CGAL::vertices_around_target(top.second, tm))
      if(!done[w]) queue.push(Item(top.first + std::sqrt(CGAL::squared_distance(q, to_point_d(get(vpm, w)))), w));
  }
  if(reached.size() <= at_most) return reached;
  std::vector<V> spread;
  for(std::size_t k = 0; k < at_most; ++k) spread.push_back(reached[(k + 1) * reached.size() / at_most - 1]);
  return spread;
}

// The squared distances of the metric between the site and the samples. For an embedding,
// between the embedded points (the site's by barycentric interpolation). For a lazy metric,
// the site and one site at each sample vertex are given to `set_sites()`, and the value of
// the site at a sample is taken minus that of the sample's own site there, which removes any
// term of the vertex alone that the model adds to all sites' values.
template <class Metric, class Location, class VertexRange>
std::vector<double> squared_metric_distances(Metric& metric, const Location& site, const VertexRange& samples)
{
  const auto& tm = metric.triangle_mesh();
  std::vector<double> out;
  if constexpr(Is_embedding<typename std::remove_const<Metric>::type>::value)
  {
    const std::size_t d = metric.dimension();
    std::vector<double> e(d, 0.), c(d);
    const auto corners = face_corners(site.first, tm);
    for(int k = 0; k < 3; ++k)
    {
      metric.coordinates(corners[k], c.begin());
      for(std::size_t j = 0; j < d; ++j) e[j] += site.second[k] * c[j];
    }
    for(auto v : samples)
    {
      metric.coordinates(v, c.begin());
      double s = 0;
      for(std::size_t j = 0; j < d; ++j) s += (c[j] - e[j]) * (c[j] - e[j]);
      out.push_back(s);
    }
  }
  else
  {
    std::vector<Location> sites(1, site);
    for(auto v : samples) sites.push_back(CGAL::Polygon_mesh_processing::locate_vertex<double>(v, tm));
    metric.set_sites(sites);
    std::size_t i = 1;
    for(auto v : samples)
      out.push_back(metric.squared_distance(0, v) - metric.squared_distance(i++, v));
  }
  return out;
}

} // namespace internal

/// \ingroup PkgSurfaceVoronoiDiagramMetrics
/// The power weight, in the squared units of `metric`, for the length `length` at the site
/// `site`: `length` squared times the smallest ratio of the metric's squared distance to the
/// squared length, between the site and the vertices around it.
///
/// <b>What a weight means.</b> With weights, site \f$ i \f$ owns the points \f$ x \f$ where
/// \f$ D_i(x) = d^2(x, s_i) - w_i \f$ is smallest, \f$ d \f$ being the metric's distance.
/// Between two sites \f$ \delta \f$ apart in the metric, the weights move the boundary
/// \f$ (w_i - w_j) / (2 \delta) \f$ towards \f$ s_j \f$, and \f$ s_j \f$ loses its own location,
/// and usually its whole cell, once \f$ w_i - w_j \geq \delta^2 \f$. A weight is large or
/// small only against the squared spacing of the sites around it, in the metric's units,
/// which for the biharmonic metric differ from lengths by a factor that varies over the
/// surface. This function measures that factor around the site: the weight for a length
/// \f$ l \f$ moves the boundary with a site \f$ \delta \f$ away by at most about
/// \f$ l^2 / (2 \delta) \f$ in length, as the weight \f$ l^2 \f$ does in the Euclidean metric.
/// With the Euclidean embedding, the weight for half the distance from a site to its nearest
/// site is a quarter of the squared spacing, and no site loses its own location; with the
/// other metrics the smallest ratio keeps the weight at most that in every sampled direction.
///
/// <b>What it computes.</b> Lengths are straight-line distances between points of the mesh.
/// Let \f$ p \f$ be the point of `site`. The samples are vertices found by a search along
/// the edges of `metric.triangle_mesh()`, from the corners of the site's face, the length of a
/// path being the distance from \f$ p \f$ to its first corner plus the lengths of its edges:
/// every vertex at a path length of at most `2 * length`, and at least the 8 nearest, except a
/// vertex at \f$ p \f$ itself; when there are more than 24, 24 of them spread evenly over the
/// order in which the search reached them. The search along the edges keeps out the vertices
/// across a thin wall, near in space but not on the surface. With \f$ D(v) \f$ the metric's
/// squared distance between the site and sample \f$ v \f$, the function returns
/// \f[ \mathrm{length}^2 \; \min_v \frac{\max(D(v), 0)}{|v - p|^2} . \f]
/// The smallest ratio, not a mean, because a metric may shorten some directions much more than
/// others (an embedding of low dimension barely tells apart the sides of a limb), and a weight
/// must not be large in any of them. \f$ D(v) \f$ is
/// - for a model of `SurfaceVoronoiEmbedding`, the squared distance between the embedded
///   points (the site's interpolated in its face): for `Surface_voronoi::Euclidean_embedding`
///   the ratio is 1 and the weight `length * length`; for `CGAL::Biharmonic_embedding` the
///   ratio varies over the mesh;
/// - for a model of `SurfaceVoronoiLazyMetric`, `metric.squared_distance(0, v)` minus
///   `metric.squared_distance(k, v)` after `metric.set_sites()` was given the site followed by
///   one site at each sample (site \f$ k \f$ at sample \f$ v \f$): the difference removes
///   any term of the vertex alone, such as the one `Surface_voronoi::Biharmonic_green_metric`
///   subtracts. For `Surface_voronoi::Geodesic_metric` the ratio is that of squared geodesic to
///   squared straight-line distances, 1 or a little more.
///
/// A lazy metric is left with these sites set (distances it had computed for a diagram are
/// gone); a diagram built with it afterwards sets its own. Each call costs one `set_sites()` of
/// up to 25 sites (for `Surface_voronoi::Biharmonic_green_metric`, two solves per site). A
/// site given as a vertex `v` has the location
/// `CGAL::Polygon_mesh_processing::locate_vertex<double>(v, tm)`, and a site given as a point
/// the location the diagram snaps it to (`CGAL::Polygon_mesh_processing::locate()`).
///
/// \tparam Metric a model of `SurfaceVoronoiEmbedding` (possibly `const`) or of
///         `SurfaceVoronoiLazyMetric`
/// \param metric the metric
/// \param site a location in a face of `metric.triangle_mesh()`
/// \param length a length on the mesh, in the units of its points
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of
///       `metric.triangle_mesh()`, for the lengths}
///     \cgalParamType{a model of `ReadablePropertyMap`}
///     \cgalParamDefault{`get_const_property_map(CGAL::vertex_point, metric.triangle_mesh())`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the weight, in the squared units of the metric
/// \throws Input_error if `length` is negative or not finite, if the site's face is not a
///         triangle, or if the metric's squared distances around the site are not finite
template <class Metric, class NamedParameters = CGAL::parameters::Default_named_parameters>
double weight_for_length(Metric& metric,
                         const CGAL::Polygon_mesh_processing::Face_location<typename Metric::Triangle_mesh, double>& site,
                         double length,
                         const NamedParameters& np = CGAL::parameters::default_values())
{
  if(!std::isfinite(length) || length < 0)
    throw Input_error("weight_for_length: the length must be finite and not negative");
  const auto& tm = metric.triangle_mesh();
  if(degree(site.first, tm) != 3)
    throw Input_error("weight_for_length: the site's face is not a triangle");
  if(length == 0) return 0;
  const auto vpm = CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                                                      get_const_property_map(CGAL::vertex_point, tm));
  const internal::Point_d p = CGAL::Polygon_mesh_processing::construct_point(
      site, tm, CGAL::parameters::vertex_point_map(internal::make_double_point_map(vpm)).geom_traits(internal::Double_kernel()));
  const auto samples = internal::power_weight_samples(tm, vpm, site, p, length);
  const std::vector<double> squared = internal::squared_metric_distances(metric, site, samples);
  double ratio = std::numeric_limits<double>::infinity();
  for(std::size_t k = 0; k < samples.size(); ++k)
  {
    if(!std::isfinite(squared[k]))
      throw Input_error("weight_for_length: the metric's squared distances around the site are not finite");
    ratio = (std::min)(ratio, (std::max)(squared[k], 0.) / CGAL::squared_distance(p, internal::to_point_d(get(vpm, samples[k]))));
  }
  if(!std::isfinite(ratio))   // no sample: every vertex in reach is at the site's point
    throw Input_error("weight_for_length: no vertex around the site is apart from it (faces of zero area?)");
  return length * length * ratio;
}

} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_POWER_WEIGHTS_H
