// Copyright (c) 2026 The Surface_voronoi_diagram authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The identity embedding (x, y, z): with propagation it is SurfaceVoronoi's EDBVD baseline,
// with every site in every face the classic restricted Voronoi diagram (RVD).

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_EUCLIDEAN_EMBEDDING_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_EUCLIDEAN_EMBEDDING_H

#include <CGAL/Surface_voronoi_diagram/metric_concepts.h>

#include <CGAL/Default.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/number_utils.h>

namespace CGAL {
namespace Surface_voronoi {

/// \ingroup PkgSurfaceVoronoiDiagramMetrics
/// The Euclidean embedding: every vertex is embedded at its own position.
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \tparam VertexPointMap a readable property map from vertices to 3D points
/// \cgalModels `SurfaceVoronoiEmbedding`
template <class TriangleMesh, class VertexPointMap = Default>
class Euclidean_embedding
{
public:
  typedef TriangleMesh Triangle_mesh;
  typedef Embedding_tag Metric_category;
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename Default::Get<VertexPointMap,
            typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>::type Vertex_point_map;

  template <class NamedParameters = CGAL::parameters::Default_named_parameters>
  explicit Euclidean_embedding(const TriangleMesh& tm,
                               const NamedParameters& np = CGAL::parameters::default_values())
    : m_vpm(CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                                               get_const_property_map(CGAL::vertex_point, tm)))
  {}

  std::size_t dimension() const { return 3; }

  void coordinates(vertex_descriptor v, double* out) const
  {
    const auto& p = get(m_vpm, v);
    out[0] = CGAL::to_double(p.x());
    out[1] = CGAL::to_double(p.y());
    out[2] = CGAL::to_double(p.z());
  }

private:
  Vertex_point_map m_vpm;
};

} // namespace Surface_voronoi
} // namespace CGAL

#endif
