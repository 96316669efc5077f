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
// Geodesic distances along the surface, computed per site only where the site propagates.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_GEODESIC_METRIC_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_GEODESIC_METRIC_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/exceptions.h>
#include <CGAL/Surface_voronoi_diagram/metric_concepts.h>
#include <CGAL/Surface_voronoi_diagram/parameters.h>
#include <CGAL/Surface_voronoi_diagram/Prepared_mesh.h>
#include <CGAL/Surface_voronoi_diagram/internal/Indexed_mesh.h>
#include <CGAL/Surface_voronoi_diagram/internal/Input_validation.h>
#include <CGAL/Surface_voronoi_diagram/internal/Site_locator.h>
#include <CGAL/Surface_voronoi_diagram/internal/Fast_marching/Local_fast_marching.h>

#include <CGAL/assertions.h>
#include <CGAL/Default.h>
#include <CGAL/tags.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {

/// \ingroup PkgSurfaceVoronoiDiagramMetrics
/// Geodesic distances along the surface: the metric whose Voronoi cells are the geodesic
/// Voronoi cells, up to the accuracy of fast marching and to the linear interpolation of
/// squared distances inside a face. Squared distances, and power weights, are squared lengths.
///
/// Each site's distances are computed by its own fast-marching front, advanced only as far
/// as the diagram asks, that is over the faces where the site can still win and one ring
/// beyond. The cost therefore grows with the mesh size (times a small factor), not with
/// mesh size times the number of sites, and there is no precomputation. The triangle update
/// treats the front as a point source unfolded into the triangle's plane, so distances are
/// exact on developable patches in direct sight of the site; obtuse corners are split by an
/// unfolded neighbour vertex. Walls are respected because distances are measured along the
/// surface: two sides of a thin shell are as far apart as the path around the rim.
///
/// Accuracy depends on the resolution: with fewer than about 10 vertices per site the cells
/// become coarse (see `refine_for_sites()`). Fast marching on triangulated domains follows
/// Kimmel and Sethian \cgalCite{cgal:ks-cgpm-98}.
///
/// Threads may ask for distances at once (`Has_concurrent_squared_distance`): each site's
/// front has its own lock, and its values do not depend on the order of the queries. A diagram
/// with `CGAL::Parallel_tag` therefore propagates on all its threads, in the blocks it uses for
/// embeddings (the same cells on any number of threads).
///
/// <b>One diagram at a time.</b> The fronts are state: `set_sites()` starts them afresh.
/// A diagram built with the metric calls `set_sites()` in its constructor, asks distances
/// while it is constructed, and never uses the metric afterwards, so the metric may then be
/// queried (`distance()`), destroyed, or given to another diagram (which starts it afresh).
/// Copies share no state: a copy marches its own fronts.
///
/// \tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
/// \tparam VertexPointMap a model of `ReadablePropertyMap` from vertices to points; default:
///         the mesh's internal `CGAL::vertex_point` map
///
/// \cgalModels `SurfaceVoronoiLazyMetric`
template <class TriangleMesh, class VertexPointMap = Default>
class Geodesic_metric
{
  typedef internal::Indexed_mesh<TriangleMesh> Indexed;
  typedef internal::Fast_marching_mesh<TriangleMesh> Marching_mesh;
  typedef internal::Local_fast_marching<TriangleMesh> Marching;

public:
  /// \name Types
  /// @{

  /// the mesh type
  typedef TriangleMesh Triangle_mesh;
  /// `Lazy_metric_tag`
  typedef Lazy_metric_tag Metric_category;
  /// a vertex of the mesh
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  /// the vertex point map: `VertexPointMap`, or by default the mesh's internal
  /// `CGAL::vertex_point` map
  typedef typename Default::Get<VertexPointMap,
            typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>::type Vertex_point_map;
  /// a point in a face: the face and barycentric coordinates
  typedef CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double> Face_location;
  /// `CGAL::Tag_true`: threads may ask for distances at once (each front has its own lock)
  typedef CGAL::Tag_true Has_concurrent_squared_distance;
  /// @}

  /// Reads the mesh, which must stay alive while the metric is used; no distance is computed
  /// before `set_sites()`.
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
  ///   \cgalParamNBegin{Surface_voronoi::parameters::prepared_mesh}
  ///     \cgalParamDescription{the mesh prepared once, shared with the other calls given it}
  ///     \cgalParamType{`Surface_voronoi::Prepared_mesh<TriangleMesh, C>`, `C` any concurrency tag}
  ///     \cgalParamDefault{the mesh prepared by this call}
  ///   \cgalParamNEnd
  /// \cgalNamedParamsEnd
  ///
  /// \pre `tm` is a valid polygon mesh without faces of zero area, with fewer than
  ///      \f$ 2^{32} - 1 \f$ vertices and faces
  /// \throws Input_error in every build if a face of `tm` is not a triangle or a vertex has a
  ///         coordinate that is not a finite number (the message names the face or vertex, by
  ///         its position in `faces(tm)` or `vertices(tm)`)
  template <class NamedParameters = CGAL::parameters::Default_named_parameters>
  explicit Geodesic_metric(const TriangleMesh& tm, const NamedParameters& np = CGAL::parameters::default_values())
  {
    const Vertex_point_map vpm = CGAL::parameters::choose_parameter(
        CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm));
    CGAL_precondition_msg(num_vertices(tm) < std::size_t(std::uint32_t(-1)) && num_faces(tm) < std::size_t(std::uint32_t(-1)),
                          "the mesh has too many elements for the geodesic metric");
    m_mesh = internal::shared_or_new_indexed_mesh(internal::prepared_mesh_of<TriangleMesh>(np).indexed_mesh(), tm, vpm);
    internal::throw_non_finite_points(*m_mesh);   // (the copy refuses faces that are not triangles)
    m_marching_mesh = std::make_shared<const Marching_mesh>(*m_mesh);
  }

  /// a copy with fronts of its own
  Geodesic_metric(const Geodesic_metric& other)
    : m_mesh(other.m_mesh), m_marching_mesh(other.m_marching_mesh),
      m_marching(other.m_marching ? new Marching(*other.m_marching) : nullptr)
  {}
  /// \cond SKIP_IN_MANUAL
  Geodesic_metric(Geodesic_metric&&) = default;
  Geodesic_metric& operator=(const Geodesic_metric&) = delete;
  /// \endcond

  /// the mesh the metric was built on
  const Triangle_mesh& triangle_mesh() const { return *m_mesh->source_mesh; }

  /// Starts from scratch with these sites: no distance of an earlier set is kept.
  /// \throws Input_error if a site is not in a face of the mesh
  void set_sites(const std::vector<Face_location>& sites)
  {
    const internal::Site_locator<TriangleMesh> locator(triangle_mesh(), *m_mesh, std::numeric_limits<double>::infinity());
    std::vector<internal::Marching_seed> seeds(sites.size());
    for(std::size_t i = 0; i < sites.size(); ++i)
    {
      const internal::Site s = locator.locate(sites[i], i);
      seeds[i].face = static_cast<std::uint32_t>(s.face);
      // the coordinates as given: the diagram passes them already normalized
      seeds[i].barycentric = { sites[i].second[0], sites[i].second[1], sites[i].second[2] };
    }
    m_marching.reset(new Marching(*m_marching_mesh));
    m_marching->set_seeds(seeds);
  }

  /// the squared geodesic distance between site `i` and vertex `v`
  /// \pre `set_sites()` was called
  /// \throws Input_error if `i` is not a site index
  double squared_distance(std::size_t i, vertex_descriptor v)
  {
    return indexed_squared_distance(i, get(m_mesh->vertex_index, v));
  }

  /// the geodesic distance between site `i` and the surface point `l` (a location in a face):
  /// straight inside the site's own face, otherwise from the distances at the face's corners
  /// by the same point-source update as between vertices
  /// \pre `set_sites()` was called
  /// \throws Input_error if `i` is not a site index or `l` is not in a face of the mesh
  double distance(std::size_t i, const Face_location& l)
  {
    check_site(i);
    const internal::Site_locator<TriangleMesh> locator(triangle_mesh(), *m_mesh, std::numeric_limits<double>::infinity());
    const std::size_t f = locator.locate(l, i).face;
    return m_marching->distance_at(i, static_cast<std::uint32_t>(f), { l.second[0], l.second[1], l.second[2] });
  }

  /// Frees the distances computed so far, whose memory grows with the area the fronts
  /// covered. A distance asked afterwards
  /// is marched again from its site, to the same value. A diagram calls it once its
  /// propagation is done, before it cuts and stitches the faces.
  void forget_distances()
  {
    if(m_marching) m_marching->forget_fronts();
  }

  /// the number of (site, vertex) distances computed since the last `set_sites()`: the work
  /// done, a small multiple of the number of vertices when the sites are spread out
  std::size_t number_of_computed_distances() const
  {
    return m_marching ? m_marching->accepted_vertices() : 0;
  }

  /// the mesh as the metric prepared it, which the diagrams built with it share
  Prepared_mesh<TriangleMesh> prepared_mesh() const { return Prepared_mesh<TriangleMesh>(m_mesh); }

  /// `squared_distance(i, v)` for the `k`-th vertex `v` in the order of `vertices(tm)`
  /// \pre `set_sites()` was called
  /// \throws Input_error if `i` is not a site index or `k` not a vertex index
  double indexed_squared_distance(std::size_t i, std::size_t k)
  {
    check_site(i);
    if(k >= m_mesh->number_of_vertices()) throw Input_error("Geodesic_metric: the vertex is not a vertex of the mesh");
    const double d = m_marching->distance(i, static_cast<std::uint32_t>(k));
    return d * d;
  }

private:
  void check_site(std::size_t i) const
  {
    CGAL_precondition_msg(m_marching != nullptr, "set_sites() must be called before distances are asked for");
    if(!m_marching || i >= m_marching->number_of_seeds())
      throw Input_error("Geodesic_metric: " + std::to_string(i) + " is not a site index");
  }

  std::shared_ptr<const Indexed> m_mesh;                  // immutable: shared by copies
  std::shared_ptr<const Marching_mesh> m_marching_mesh;   // immutable: shared by copies
  std::unique_ptr<Marching> m_marching;                   // the fronts: each copy its own
};

} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_GEODESIC_METRIC_H
