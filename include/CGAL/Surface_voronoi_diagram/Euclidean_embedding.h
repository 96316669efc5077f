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
// The identity embedding (x, y, z): with propagation it is SurfaceVoronoi's EDBVD baseline
// (\cgalCite{cgal:xwx-svdm-22}), with every site in every face the classic restricted
// Voronoi diagram (RVD).

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_EUCLIDEAN_EMBEDDING_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_EUCLIDEAN_EMBEDDING_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/exceptions.h>
#include <CGAL/Surface_voronoi_diagram/metric_concepts.h>

#include <CGAL/Default.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/number_utils.h>

#include <cmath>
#include <string>

namespace CGAL {
namespace Surface_voronoi {

/// \ingroup PkgSurfaceVoronoiDiagramMetrics
/// The Euclidean embedding: every vertex is embedded at its own position, so squared
/// distances, and power weights, are squared lengths. With the diagram's propagation it is
/// SurfaceVoronoi's Euclidean variant (EDBVD) \cgalCite{cgal:xwx-svdm-22}; with
/// `Candidate_selection::GLOBAL_NEAREST` it gives the classic restricted Voronoi diagram (RVD).
/// Coordinates are read as `double`, whatever the kernel.
/// \tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
/// \tparam VertexPointMap a model of `ReadablePropertyMap` from vertices to points; default:
///         the mesh's internal `CGAL::vertex_point` map
/// \cgalModels `SurfaceVoronoiEmbedding`
template <class TriangleMesh, class VertexPointMap = Default>
class Euclidean_embedding
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
  /// the vertex point map: `VertexPointMap`, or by default the mesh's internal
  /// `CGAL::vertex_point` map
  typedef typename Default::Get<VertexPointMap,
            typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>::type Vertex_point_map;
  /// @}

  /// The embedding of `tm`, which must stay alive while the embedding is used.
  ///
  /// \param tm the mesh
  /// \param np an optional sequence of named parameters among the ones listed below
  ///
  /// \cgalNamedParamsBegin
  ///   \cgalParamNBegin{vertex_point_map}
  ///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
  ///     \cgalParamType{`Vertex_point_map`}
  ///     \cgalParamDefault{`get_const_property_map(CGAL::vertex_point, tm)`}
  ///   \cgalParamNEnd
  /// \cgalNamedParamsEnd
  ///
  /// \throws Input_error in every build if a vertex has a coordinate that is not a finite
  ///         number (the message names the vertex, by its position in `vertices(tm)`)
  template <class NamedParameters = CGAL::parameters::Default_named_parameters>
  explicit Euclidean_embedding(const TriangleMesh& tm,
                               const NamedParameters& np = CGAL::parameters::default_values())
    : m_tm(&tm),
      m_vpm(CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                                               get_const_property_map(CGAL::vertex_point, tm)))
  {
    std::size_t index = 0;
    for(vertex_descriptor v : vertices(tm))
    {
      double c[3];
      coordinates(v, c);
      if(!(std::isfinite(c[0]) && std::isfinite(c[1]) && std::isfinite(c[2])))
        throw Input_error("vertex " + std::to_string(index) + " has a non-finite coordinate");
      ++index;
    }
  }

  /// \name SurfaceVoronoiEmbedding
  /// @{

  /// the mesh the embedding belongs to
  const Triangle_mesh& triangle_mesh() const { return *m_tm; }

  /// returns 3
  std::size_t dimension() const { return 3; }

  /// writes the three coordinates of `v` to `out`
  template <class OutputIterator>
  OutputIterator coordinates(vertex_descriptor v, OutputIterator out) const
  {
    const auto& p = get(m_vpm, v);
    *out++ = CGAL::to_double(p.x());
    *out++ = CGAL::to_double(p.y());
    *out++ = CGAL::to_double(p.z());
    return out;
  }
  /// @}

private:
  const TriangleMesh* m_tm;
  Vertex_point_map m_vpm;
};

} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_EUCLIDEAN_EMBEDDING_H
