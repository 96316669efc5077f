// Copyright (c) 2026 The Surface_voronoi_diagram authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Any per-vertex embedding the user already has (a spectral embedding of their own, a
// feature space, ...), read from a property map.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_VERTEX_EMBEDDING_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_VERTEX_EMBEDDING_H

#include <CGAL/Surface_voronoi_diagram/exceptions.h>
#include <CGAL/Surface_voronoi_diagram/metric_concepts.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <cmath>
#include <string>

namespace CGAL {
namespace Surface_voronoi {

/// \ingroup PkgSurfaceVoronoiDiagramMetrics
/// A user-supplied embedding: `get(map, v)` returns a random-access range of `dimension`
/// numbers (`std::vector<double>`, `std::array<double, N>`, `Eigen::VectorXd`, ...).
/// The ranges are read when the diagram is built; a range of the wrong size or with a
/// non-finite value makes the diagram throw `Input_error`.
/// \cgalModels `SurfaceVoronoiEmbedding`
template <class TriangleMesh, class VertexCoordinatesMap>
class Vertex_embedding
{
public:
  typedef TriangleMesh Triangle_mesh;
  typedef Embedding_tag Metric_category;
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;

  Vertex_embedding(VertexCoordinatesMap map, std::size_t dimension)
    : m_map(map), m_dimension(dimension)
  {
    if(dimension == 0)
      throw Input_error("a vertex embedding needs at least one coordinate");
  }

  std::size_t dimension() const { return m_dimension; }

  void coordinates(vertex_descriptor v, double* out) const
  {
    const auto& c = get(m_map, v);
    if(static_cast<std::size_t>(c.size()) != m_dimension)
      throw Input_error("a vertex embedding has " + std::to_string(c.size()) + " coordinates, expected "
                        + std::to_string(m_dimension));
    for(std::size_t k = 0; k < m_dimension; ++k)
    {
      out[k] = static_cast<double>(c[k]);
      if(!std::isfinite(out[k]))
        throw Input_error("a vertex embedding has a non-finite coordinate");
    }
  }

private:
  VertexCoordinatesMap m_map;
  std::size_t m_dimension;
};

/// \ingroup PkgSurfaceVoronoiDiagramMetrics
/// Makes a `Vertex_embedding` from a property map.
template <class TriangleMesh, class VertexCoordinatesMap>
Vertex_embedding<TriangleMesh, VertexCoordinatesMap>
make_vertex_embedding(const TriangleMesh&, VertexCoordinatesMap map, std::size_t dimension)
{
  return Vertex_embedding<TriangleMesh, VertexCoordinatesMap>(map, dimension);
}

} // namespace Surface_voronoi
} // namespace CGAL

#endif
