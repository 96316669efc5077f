// Copyright (c) 2026 The Surface_voronoi_diagram authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Geodesic distances along the surface, computed per site only where the site propagates.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_GEODESIC_METRIC_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_GEODESIC_METRIC_H

#include <CGAL/Surface_voronoi_diagram/exceptions.h>
#include <CGAL/Surface_voronoi_diagram/metric_concepts.h>
#include <CGAL/Surface_voronoi_diagram/internal/Indexed_mesh.h>
#include <CGAL/Surface_voronoi_diagram/internal/geodesic/Local_fast_marching.h>

#include <CGAL/Default.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {

/// \ingroup PkgSurfaceVoronoiDiagramMetrics
/// Geodesic distances along the surface: the metric whose Voronoi cells are the geodesic
/// Voronoi cells, up to the accuracy of fast marching and to the linear interpolation of
/// squared distances inside a face.
///
/// Each site's distances are computed by its own fast-marching front, advanced only as far
/// as the diagram asks, that is over the faces where the site can still win and one ring
/// beyond. The cost therefore grows with the mesh size (times a small factor), not with
/// mesh size times the number of sites, and there is no precomputation. The triangle update
/// treats the front as a point source unfolded into the triangle's plane, so distances are
/// exact on developable patches in direct sight of the site; obtuse corners are split by an
/// unfolded neighbour vertex.
///
/// Walls are respected because distances are measured along the surface: two sides of a thin
/// shell are as far apart as the path around the rim.
///
/// Accuracy depends on the resolution: with fewer than about 10 vertices per site the cells
/// become coarse (see `refine_for_sites()` in the manual's section on coarse meshes).
///
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \tparam VertexPointMap a readable property map from vertices to 3D points
///
/// \cgalModels `SurfaceVoronoiMetric`
template <class TriangleMesh, class VertexPointMap = Default>
class Geodesic_metric
{
public:
  typedef TriangleMesh Triangle_mesh;
  typedef Lazy_metric_tag Metric_category;
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename Default::Get<VertexPointMap,
            typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>::type Vertex_point_map;
  typedef CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double> Face_location;

  /// Reads the mesh. Named parameter: `vertex_point_map`.
  /// \throws Input_error if the mesh is empty, not triangulated, or has a degenerate face
  template <class NamedParameters = CGAL::parameters::Default_named_parameters>
  explicit Geodesic_metric(const TriangleMesh& tm, const NamedParameters& np = CGAL::parameters::default_values())
    : m_state(std::make_shared<State>())
  {
    const Vertex_point_map vpm = CGAL::parameters::choose_parameter(
        CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm));
    m_state->mesh.build(tm, vpm);
    const internal::Indexed_mesh<TriangleMesh>& im = m_state->mesh;
    if(im.number_of_vertices() >= std::size_t(std::uint32_t(-1)))
      throw Input_error("the mesh has too many vertices for the geodesic metric");
    std::vector<std::array<std::uint32_t, 3> > triangles(im.number_of_faces());
    for(std::size_t f = 0; f < triangles.size(); ++f)
      for(int k = 0; k < 3; ++k) triangles[f][k] = static_cast<std::uint32_t>(im.triangles[f][k]);
    m_state->marching_mesh.build(im.points, triangles, im.neighbors, internal::Indexed_mesh<TriangleMesh>::none);
  }

  /// Called by the diagram with the sites. Starts from scratch: no distance of an earlier
  /// set of sites is kept.
  void set_sites(const TriangleMesh& /* tm */, const std::vector<Face_location>& sites)
  {
    std::vector<internal::Marching_seed> seeds(sites.size());
    for(std::size_t i = 0; i < sites.size(); ++i)
    {
      seeds[i].face = static_cast<std::uint32_t>(get(m_state->mesh.face_index, sites[i].first));
      seeds[i].barycentric = { sites[i].second[0], sites[i].second[1], sites[i].second[2] };
    }
    m_state->marching.reset(new internal::Local_fast_marching(m_state->marching_mesh));
    m_state->marching->set_seeds(seeds);
  }

  /// the squared geodesic distance between site `i` and vertex `v`
  /// \pre `set_sites()` was called, `v` is on the same connected component as site `i`
  double squared_distance(std::size_t i, vertex_descriptor v)
  {
    if(!m_state->marching)
      throw Input_error("Geodesic_metric: set_sites() must be called before distances are asked for");
    const double d = m_state->marching->distance(i, static_cast<std::uint32_t>(get(m_state->mesh.vertex_index, v)));
    return d * d;
  }

  /// the geodesic distance between site `i` and the surface point `l` (a location in a face):
  /// straight inside the site's own face, otherwise from the distances at the face's corners
  /// by the same point-source update as between vertices
  double distance(std::size_t i, const Face_location& l)
  {
    if(!m_state->marching)
      throw Input_error("Geodesic_metric: set_sites() must be called before distances are asked for");
    return m_state->marching->distance_at(i, static_cast<std::uint32_t>(get(m_state->mesh.face_index, l.first)),
                                          { l.second[0], l.second[1], l.second[2] });
  }

  /// the number of (site, vertex) distances computed since the last `set_sites()`: the work
  /// done, a small multiple of the number of vertices when the sites are spread out
  std::size_t number_of_computed_distances() const
  {
    return m_state->marching ? m_state->marching->accepted_vertices : 0;
  }

private:
  struct State
  {
    internal::Indexed_mesh<TriangleMesh> mesh;
    internal::Fast_marching_mesh marching_mesh;
    std::unique_ptr<internal::Local_fast_marching> marching;
  };
  // shared so that the metric stays CopyConstructible and cheap to copy, as the concept asks
  std::shared_ptr<State> m_state;
};

} // namespace Surface_voronoi
} // namespace CGAL

#endif
