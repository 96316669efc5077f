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
// Any per-vertex embedding the user already has (a spectral embedding of their own, a
// feature space, ...), read from a property map.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_VERTEX_EMBEDDING_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_VERTEX_EMBEDDING_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/exceptions.h>
#include <CGAL/Surface_voronoi_diagram/metric_concepts.h>

#include <CGAL/assertions.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <string>

namespace CGAL {
namespace Surface_voronoi {

/// \ingroup PkgSurfaceVoronoiDiagramMetrics
/// A user-supplied embedding: `get(map, v)` returns a random-access range of `dimension`
/// numbers (`std::vector<double>`, `std::array<double, N>`, `Eigen::VectorXd`, ...). The
/// ranges are read when a diagram is built: a number that is not finite, or a range of another
/// size, makes the diagram throw `Input_error` (in every build). Squared distances,
/// and power weights, are in the squared units of these coordinates.
/// \tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
/// \tparam VertexCoordinatesMap a model of `ReadablePropertyMap` whose key type is the vertex
///         descriptor of `TriangleMesh` and whose value type is a random-access range of
///         numbers convertible to `double`, with a `size()` member
/// \cgalModels `SurfaceVoronoiEmbedding`
/// \sa `make_vertex_embedding()`
template <class TriangleMesh, class VertexCoordinatesMap>
class Vertex_embedding
{
public:
  /// \name Types
  /// @{

  /// the mesh type
  typedef TriangleMesh Triangle_mesh;
  /// `Embedding_tag`
  typedef Embedding_tag Metric_category;
  /// a vertex of the mesh
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  /// @}

  /// the embedding of the vertices of `tm` given by `map`, of dimension `dimension`. Both
  /// `tm` and what `map` reads must stay alive while the embedding is used.
  /// \pre `dimension >= 1`
  Vertex_embedding(const TriangleMesh& tm, VertexCoordinatesMap map, std::size_t dimension)
    : m_tm(&tm), m_map(map), m_dimension(dimension)
  {
    CGAL_precondition_msg(dimension >= 1, "a vertex embedding needs at least one coordinate");
  }

  /// \name SurfaceVoronoiEmbedding
  /// @{

  /// the mesh the embedding belongs to
  const Triangle_mesh& triangle_mesh() const { return *m_tm; }

  /// the dimension given at construction
  std::size_t dimension() const { return m_dimension; }

  /// writes the `dimension()` coordinates of `v` to `out`
  /// \throws Input_error if the range of `v` does not hold `dimension()` numbers
  template <class OutputIterator>
  OutputIterator coordinates(vertex_descriptor v, OutputIterator out) const
  {
    const auto& c = get(m_map, v);
    if(static_cast<std::size_t>(c.size()) != m_dimension)
      throw Input_error("a vertex embedding has " + std::to_string(c.size()) + " coordinates, expected "
                        + std::to_string(m_dimension));
    for(std::size_t k = 0; k < m_dimension; ++k)
      *out++ = static_cast<double>(c[k]);
    return out;
  }
  /// @}

private:
  const TriangleMesh* m_tm;
  VertexCoordinatesMap m_map;
  std::size_t m_dimension;
};

/// \ingroup PkgSurfaceVoronoiDiagramMetrics
/// Makes a `Vertex_embedding` of dimension `dimension` of the vertices of `tm` from the
/// property map `map`, deducing the template arguments.
template <class TriangleMesh, class VertexCoordinatesMap>
Vertex_embedding<TriangleMesh, VertexCoordinatesMap>
make_vertex_embedding(const TriangleMesh& tm, VertexCoordinatesMap map, std::size_t dimension)
{
  return Vertex_embedding<TriangleMesh, VertexCoordinatesMap>(tm, map, dimension);
}

} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_VERTEX_EMBEDDING_H
