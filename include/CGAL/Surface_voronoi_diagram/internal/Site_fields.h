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
// The value D_i(v) = squared distance(site i, vertex v) - w_i that propagation and cutting
// work with, for both kinds of metric: embeddings (coordinates read once into a dense array,
// each site embedded by barycentric interpolation) and lazy metrics (asked on demand, keyed
// by vertex index when the metric offers it, by vertex descriptor otherwise).

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_SITE_FIELDS_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_SITE_FIELDS_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/exceptions.h>
#include <CGAL/Surface_voronoi_diagram/metric_concepts.h>
#include <CGAL/Surface_voronoi_diagram/internal/Indexed_mesh.h>
#include <CGAL/Surface_voronoi_diagram/internal/Site.h>

#include <CGAL/assertions.h>
#include <CGAL/Polygon_mesh_processing/locate.h>

#include <cmath>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

// Whether a lazy metric offers the index-keyed hook `indexed_squared_distance(i, v)`, which
// skips the index -> descriptor -> index round trip per value.
template <class Metric, class = void>
struct Has_indexed_squared_distance : std::false_type {};
template <class Metric>
struct Has_indexed_squared_distance<Metric, decltype(void(std::declval<Metric&>().indexed_squared_distance(std::size_t(0), std::size_t(0))))>
  : std::true_type {};

// Whether a lazy metric can free the distances it computed (`forget_distances()`), which a
// diagram no longer needs once its propagation is done.
template <class Metric, class = void>
struct Has_forget_distances : std::false_type {};
template <class Metric>
struct Has_forget_distances<Metric, decltype(void(std::declval<Metric&>().forget_distances()))>
  : std::true_type {};

// Whether a lazy metric's `squared_distance()` may be called from several threads at once:
// its `Has_concurrent_squared_distance` is `CGAL::Tag_true` (false if it does not say).
template <class Metric, class = void>
struct Has_concurrent_squared_distance : std::false_type {};
template <class Metric>
struct Has_concurrent_squared_distance<Metric, std::void_t<typename Metric::Has_concurrent_squared_distance> >
  : std::bool_constant<Metric::Has_concurrent_squared_distance::value> {};

// Whether a metric offers the mesh it prepared (`prepared_mesh()`), which the diagram shares.
template <class Metric, class = void>
struct Has_prepared_mesh : std::false_type {};
template <class Metric>
struct Has_prepared_mesh<Metric, decltype(void(std::declval<const Metric&>().prepared_mesh()))>
  : std::true_type {};

/// the metric's indexed copy of its mesh, or none
template <class TriangleMesh, class Metric>
std::shared_ptr<const Indexed_mesh<TriangleMesh> > indexed_mesh_of(const Metric& metric)
{
  if constexpr(Has_prepared_mesh<Metric>::value)
    return metric.prepared_mesh().indexed_mesh();
  else
    return std::shared_ptr<const Indexed_mesh<TriangleMesh> >();
}

/// The coordinates of an embedding, read once: one dense row per vertex and per site.
class Embedding_values
{
public:
  /// `value()` reads only: threads may call it at once
  static constexpr bool concurrent_values = true;

  template <class Metric, class TriangleMesh>
  Embedding_values(const Indexed_mesh<TriangleMesh>& mesh, const Metric& metric, const std::vector<Site>& sites)
  {
    m_dimension = metric.dimension();
    CGAL_precondition_msg(m_dimension > 0, "the embedding has dimension 0");
    if(!(m_dimension == 3 && coordinates_are_points(mesh, metric)))
    {
      const std::size_t n = mesh.number_of_vertices();
      m_vertex_coordinates.resize(n * m_dimension);
      for(std::size_t v = 0; v < n; ++v)
      {
        metric.coordinates(mesh.vertex_handles[v], m_vertex_coordinates.data() + v * m_dimension);
        // (nothing non-finite may reach the exact predicates of the cutting)
        for(std::size_t k = 0; k < m_dimension; ++k)
          if(!std::isfinite(m_vertex_coordinates[v * m_dimension + k]))
            throw Input_error("the embedding of vertex " + std::to_string(v) + " has a non-finite coordinate");
      }
    }
    set_sites(mesh, sites);
  }

  /// the sites' coordinates and weights, read again (an update of the diagram)
  template <class TriangleMesh>
  void set_sites(const Indexed_mesh<TriangleMesh>& mesh, const std::vector<Site>& sites)
  {
    m_site_coordinates.assign(sites.size() * m_dimension, 0.);
    m_weights.resize(sites.size());
    for(std::size_t i = 0; i < sites.size(); ++i)
    {
      m_weights[i] = sites[i].weight;
      for(int k = 0; k < 3; ++k)
      {
        const double* x = vertex_coordinates(mesh.triangles[sites[i].face][k]);
        for(std::size_t c = 0; c < m_dimension; ++c)
          m_site_coordinates[i * m_dimension + c] += sites[i].barycentric[k] * x[c];
      }
    }
  }

  double value(std::size_t site, std::size_t vertex) const
  {
    const double* x = vertex_coordinates(vertex);
    const double* s = site_coordinates(site);
    double d = 0;
    for(std::size_t c = 0; c < m_dimension; ++c)
    {
      const double e = x[c] - s[c];
      d += e * e;
    }
    return d - m_weights[site];
  }

  /// the coordinates stay: the cells' measures read them
  void propagation_done() const {}

  std::size_t dimension() const { return m_dimension; }
  const double* site_coordinates(std::size_t i) const { return &m_site_coordinates[i * m_dimension]; }
  const double* vertex_coordinates(std::size_t v) const
  {
    return m_points ? &(*m_points)[v].x() : &m_vertex_coordinates[v * m_dimension];
  }

private:
  // Whether the embedding is the mesh's own points (the Euclidean one): they are then read
  // from the indexed mesh, which the diagram owns, instead of copied (24 bytes a vertex).
  template <class Metric, class TriangleMesh>
  bool coordinates_are_points(const Indexed_mesh<TriangleMesh>& mesh, const Metric& metric)
  {
    for(std::size_t v = 0; v < mesh.number_of_vertices(); ++v)
    {
      double c[3];
      metric.coordinates(mesh.vertex_handles[v], c);
      const Point_d& p = mesh.points[v];
      if(!(c[0] == p.x() && c[1] == p.y() && c[2] == p.z())) return false;   // (a NaN is not)
    }
    m_points = &mesh.points;
    return true;
  }

  std::size_t m_dimension = 0;
  const std::vector<Point_d>* m_points = nullptr;   // the mesh's, when they are the coordinates
  std::vector<double> m_vertex_coordinates, m_site_coordinates, m_weights;
};

/// A lazy metric during the construction of one diagram: told the sites once, then asked
/// per (site, vertex).
template <class TriangleMesh, class Metric>
class Lazy_values
{
public:
  typedef CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double> Face_location;

  /// `value()` may fill the metric's caches: one thread at a time, unless the metric says
  /// that threads may ask at once (`Has_concurrent_squared_distance`)
  static constexpr bool concurrent_values = Has_concurrent_squared_distance<Metric>::value;

  Lazy_values(const Indexed_mesh<TriangleMesh>& mesh, Metric& metric, const std::vector<Site>& sites)
    : m_mesh(mesh), m_metric(metric)
  {
    m_weights.resize(sites.size());
    std::vector<Face_location> locations;
    locations.reserve(sites.size());
    for(std::size_t i = 0; i < sites.size(); ++i)
    {
      m_weights[i] = sites[i].weight;
      locations.emplace_back(mesh.face_handles[sites[i].face], sites[i].barycentric);
    }
    m_metric.set_sites(locations);
  }

  /// the propagation has asked for every value it needed: what the metric keeps of them
  /// may go (a repair asks again, and gets the same values)
  void propagation_done() const
  {
    if constexpr(Has_forget_distances<Metric>::value) m_metric.forget_distances();
  }

  double value(std::size_t site, std::size_t vertex) const
  {
    double d;
    if constexpr(Has_indexed_squared_distance<Metric>::value)
      d = m_metric.indexed_squared_distance(site, vertex);
    else
      d = m_metric.squared_distance(site, m_mesh.vertex_handles[vertex]);
    if(!(d >= 0) || !std::isfinite(d))
      throw Numerical_error("the metric returned an invalid squared distance for site " + std::to_string(site));
    return d - m_weights[site];
  }

private:
  const Indexed_mesh<TriangleMesh>& m_mesh;
  Metric& m_metric;
  std::vector<double> m_weights;
};

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_SITE_FIELDS_H
