// Copyright (c) 2026 The Surface_voronoi_diagram authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The value D_i(v) = squared distance(site i, vertex v) - w_i that propagation and cutting
// work with, for both kinds of metric: embeddings (coordinates read once into a dense
// array, site embedded by barycentric interpolation) and lazy metrics (asked on demand).

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_SITE_FIELDS_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_SITE_FIELDS_H

#include <CGAL/Surface_voronoi_diagram/exceptions.h>
#include <CGAL/Surface_voronoi_diagram/metric_concepts.h>
#include <CGAL/Surface_voronoi_diagram/internal/Indexed_mesh.h>

#include <CGAL/Polygon_mesh_processing/locate.h>

#include <array>
#include <cmath>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

/// A site as the pipeline sees it: a face of the indexed mesh and barycentric coordinates
/// in that face's corner order, plus its power weight.
struct Site
{
  std::size_t face = 0;
  std::array<double, 3> barycentric = {{ 1., 0., 0. }};
  double weight = 0.;
};

template <class TriangleMesh, class Metric, bool is_embedding = Is_embedding<Metric>::value>
class Site_fields;

// Embedding metrics: one dense row per vertex, one per site.
template <class TriangleMesh, class Metric>
class Site_fields<TriangleMesh, Metric, true>
{
public:
  Site_fields(const Indexed_mesh<TriangleMesh>& mesh, Metric& metric, const std::vector<Site>& sites, const TriangleMesh&)
  {
    m_weights.resize(sites.size());
    for(std::size_t i = 0; i < sites.size(); ++i) m_weights[i] = sites[i].weight;
    m_dimension = metric.dimension();
    if(m_dimension == 0)
      throw Input_error("the metric's embedding has dimension 0");
    const std::size_t n = mesh.number_of_vertices();
    m_vertex_coordinates.resize(n * m_dimension);
    for(std::size_t v = 0; v < n; ++v)
    {
      metric.coordinates(mesh.vertex_handles[v], &m_vertex_coordinates[v * m_dimension]);
      for(std::size_t k = 0; k < m_dimension; ++k)
        if(!std::isfinite(m_vertex_coordinates[v * m_dimension + k]))
          throw Numerical_error("the embedding of vertex " + std::to_string(v) + " is not finite");
    }
    m_site_coordinates.assign(sites.size() * m_dimension, 0.);
    for(std::size_t i = 0; i < sites.size(); ++i)
      for(int k = 0; k < 3; ++k)
      {
        const double* x = &m_vertex_coordinates[mesh.triangles[sites[i].face][k] * m_dimension];
        for(std::size_t c = 0; c < m_dimension; ++c)
          m_site_coordinates[i * m_dimension + c] += sites[i].barycentric[k] * x[c];
      }
  }

  double value(std::size_t site, std::size_t vertex) const
  {
    const double* x = &m_vertex_coordinates[vertex * m_dimension];
    const double* s = &m_site_coordinates[site * m_dimension];
    double d = 0;
    for(std::size_t c = 0; c < m_dimension; ++c)
    {
      const double e = x[c] - s[c];
      d += e * e;
    }
    return d - m_weights[site];
  }

  static constexpr bool is_exact() { return true; }
  std::size_t dimension() const { return m_dimension; }
  const double* site_coordinates(std::size_t i) const { return &m_site_coordinates[i * m_dimension]; }
  const double* vertex_coordinates(std::size_t v) const { return &m_vertex_coordinates[v * m_dimension]; }

private:
  std::vector<double> m_weights;
  std::size_t m_dimension = 0;
  std::vector<double> m_vertex_coordinates, m_site_coordinates;
};

// Lazy metrics: the metric is told the sites once, then asked per (site, vertex).
template <class TriangleMesh, class Metric>
class Site_fields<TriangleMesh, Metric, false>
{
public:
  typedef CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double> Face_location;

  Site_fields(const Indexed_mesh<TriangleMesh>& mesh, Metric& metric, const std::vector<Site>& sites, const TriangleMesh& tm)
    : m_mesh(mesh), m_metric(metric)
  {
    m_weights.resize(sites.size());
    for(std::size_t i = 0; i < sites.size(); ++i) m_weights[i] = sites[i].weight;
    std::vector<Face_location> locations;
    locations.reserve(sites.size());
    for(const Site& s : sites)
      locations.emplace_back(mesh.face_handles[s.face], s.barycentric);
    m_metric.set_sites(tm, locations);
  }

  double value(std::size_t site, std::size_t vertex) const
  {
    const double d = m_metric.squared_distance(site, m_mesh.vertex_handles[vertex]);
    if(!(d >= 0) || !std::isfinite(d))
      throw Numerical_error("the metric returned an invalid squared distance for site " + std::to_string(site));
    return d - m_weights[site];
  }

  static constexpr bool is_exact() { return false; }

private:
  const Indexed_mesh<TriangleMesh>& m_mesh;
  Metric& m_metric;
  std::vector<double> m_weights;
};

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif
