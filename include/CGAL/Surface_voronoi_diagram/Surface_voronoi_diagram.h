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
// The Voronoi diagram of sites on a triangle-mesh surface, computed at construction, then
// queried, and computed again from its previous state after its sites change.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_SURFACE_VORONOI_DIAGRAM_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_SURFACE_VORONOI_DIAGRAM_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/disable_warnings.h>

#include <CGAL/Surface_voronoi_diagram/Biharmonic_embedding.h>
#include <CGAL/Surface_voronoi_diagram/Diagram_statistics.h>
#include <CGAL/Surface_voronoi_diagram/exceptions.h>
#include <CGAL/Surface_voronoi_diagram/metric_concepts.h>
#include <CGAL/Surface_voronoi_diagram/parameters.h>
#include <CGAL/Surface_voronoi_diagram/Prepared_mesh.h>
#include <CGAL/Surface_voronoi_diagram/internal/Breaklines.h>
#include <CGAL/Surface_voronoi_diagram/internal/Cell_geometry.h>
#include <CGAL/Surface_voronoi_diagram/internal/Diagram_builder.h>
#include <CGAL/Surface_voronoi_diagram/internal/Diagram_data.h>
#include <CGAL/Surface_voronoi_diagram/internal/Indexed_mesh.h>
#include <CGAL/Surface_voronoi_diagram/internal/callback.h>
#include <CGAL/Surface_voronoi_diagram/internal/Input_validation.h>
#include <CGAL/Surface_voronoi_diagram/internal/Site_fields.h>
#include <CGAL/Surface_voronoi_diagram/internal/Site_locator.h>
#include <CGAL/Surface_voronoi_diagram/internal/Stage_times.h>
#include <CGAL/Surface_voronoi_diagram/internal/parallel.h>

#include <CGAL/assertions.h>
#include <CGAL/Default.h>
#include <CGAL/Iterator_range.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/property_map.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {

/// \ingroup PkgSurfaceVoronoiDiagramRef
///
/// The Voronoi diagram of sites on a triangle-mesh surface, under a metric that is a model
/// of `SurfaceVoronoiEmbedding` (per-vertex coordinates, such as `CGAL::Biharmonic_embedding`)
/// or of `SurfaceVoronoiLazyMetric` (distances computed on demand, such as
/// `Surface_voronoi::Geodesic_metric`), by SurfaceVoronoi's propagate-and-cut
/// \cgalCite{cgal:xwx-svdm-22} with the biharmonic embedding as default metric
/// \cgalCite{cgal:bddvd}. The diagram is computed at construction, checked (and
/// repaired) so that every cell is one connected region, and then answers queries; the
/// outputs (`Surface_voronoi::make_arrangement()`, `Surface_voronoi::dual_triangulation()`,
/// the viewer `draw()`) read it.
///
/// The diagram keeps a pointer to the mesh, which must stay alive and unchanged while the
/// diagram is used; it does not use the metric after its construction, except for the updates
/// of a diagram over a lazy metric (see `update()`). It can be moved, not copied.
///
/// <b>Numerical range.</b> Coordinates up to \f$ 2^{200} \f$ (about 1.6e60) in magnitude and
/// faces whose longest edge is at least \f$ 2^{-200} \f$ (about 6.2e-61), so that squared
/// areas neither overflow nor underflow; a face is degenerate below an area of
/// \f$ 2^{-44} \f$ (about 5.7e-14) times its squared longest edge. Thinner needles and caps
/// are valid: barycentric coordinates on a face whose Gram determinant is below
/// \f$ 2^{-40} \f$ of its scale (where PMP's formula divides by noise or zero) are computed
/// from cross products instead. The biharmonic
/// metric's eigen-solver may still fail (`Surface_voronoi::Numerical_error`) on a mesh made
/// mostly of needles thinner than about 1e-10 of their length (a 4-vertex rhombus of height
/// 1e-11: its shift follows their cotangents); the other metrics do not. Callers with data
/// outside the range scale it by a power of two (exact) first, as the `surface_voronoi`
/// program does.
///
/// <b>Errors.</b> Invalid input that is cheap to detect throws `Surface_voronoi::Input_error`
/// naming the element, in every build: a face that is not a triangle, a non-finite or
/// out-of-range coordinate, a face of zero area or degenerate, an isolated or non-manifold
/// vertex, a site that is not on the mesh, a non-finite weight or embedding coordinate, and
/// (`Surface_voronoi::Coincident_sites_error`) two sites at the same surface point unless
/// they are merged. Nothing non-finite reaches the exact arithmetic. What is costly to check
/// (a halfedge structure that is not a valid polygon mesh) and the sites being empty stay
/// preconditions (`CGAL_precondition`, debug builds); `Surface_voronoi::validate_input()`
/// checks everything in every build and lists every problem. A numerical failure that valid
/// input can still meet throws `Surface_voronoi::Numerical_error`.
///
/// \tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
/// \tparam Metric a model of `SurfaceVoronoiEmbedding` or `SurfaceVoronoiLazyMetric`
/// \tparam VertexPointMap a model of `ReadablePropertyMap` from vertices to points; default:
///         the mesh's internal `CGAL::vertex_point` map
/// \tparam GeomTraits a model of `Kernel` for the points the diagram returns; default: the
///         kernel of the point type of `VertexPointMap`
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` (the default), `CGAL::Parallel_tag` or
///         `CGAL::Parallel_if_available_tag`: with a parallel tag, and TBB linked (the macro
///         `CGAL_LINKED_WITH_TBB`, which the package's CMake target defines when it finds
///         TBB), cutting the faces, stitching the pieces and checking the cells run on all the
///         threads TBB allows (limit them with `tbb::global_control`); the propagation stays
///         sequential. The diagram is the same, bit for bit, with any number of threads.
template <class TriangleMesh,
          class Metric = Biharmonic_embedding<TriangleMesh>,
          class VertexPointMap = Default,
          class GeomTraits = Default,
          class ConcurrencyTag = Sequential_tag>
class Surface_voronoi_diagram
{
  typedef Surface_voronoi::internal::Indexed_mesh<TriangleMesh> Indexed_mesh;
  typedef Surface_voronoi::internal::Diagram_data<TriangleMesh> Data;
  friend struct Surface_voronoi::internal::Diagram_access;

public:
  /// \name Types
  /// @{

  /// the mesh type
  typedef TriangleMesh Triangle_mesh;
  /// the metric type, a model of `SurfaceVoronoiEmbedding` or `SurfaceVoronoiLazyMetric`
  typedef Metric Metric_type;
  /// a vertex of the mesh
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  /// a face of the mesh
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  /// the vertex point map: `VertexPointMap`, or by default the mesh's internal
  /// `CGAL::vertex_point` map
  typedef typename Default::Get<VertexPointMap,
            typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>::type Vertex_point_map;
  /// the geometric traits: `GeomTraits`, or by default the kernel of the points of
  /// `Vertex_point_map`. The diagram computes in `double` whatever the kernel; the traits
  /// construct the points it returns (`site_point()`, `cell_centroid()`).
  typedef typename Default::Get<GeomTraits,
            typename Kernel_traits<typename boost::property_traits<Vertex_point_map>::value_type>::Kernel>::type Geom_traits;
  /// the point type of the geometric traits
  typedef typename Geom_traits::Point_3 Point_3;
  /// a point in a face: the face and barycentric coordinates
  typedef CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double> Face_location;
  /// @}

  /// the index `site_of()` returns where no site reaches, and `merged_into()` for a site that
  /// was not merged: `std::size_t(-1)`
  static constexpr std::size_t no_site = std::size_t(-1);

  /// Computes the diagram.
  ///
  /// \tparam SiteRange a range of `vertex_descriptor`, of `Face_location` or of points
  ///         (a point is moved to the nearest surface point)
  /// \param tm the surface; it must stay alive and unchanged while the diagram is used
  /// \param metric the metric, built on `tm` (a lazy metric is told the sites and asked
  ///        distances during the construction, and not used afterwards except by `update()`)
  /// \param sites the sites; a site's index is its position in the range
  /// \param np an optional sequence of named parameters among the ones listed below
  ///
  /// \cgalNamedParamsBegin
  ///   \cgalParamSectionBegin{Input}
  ///   \cgalParamNBegin{vertex_point_map}
  ///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
  ///     \cgalParamType{`VertexPointMap`}
  ///     \cgalParamDefault{`get_const_property_map(CGAL::vertex_point, tm)`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{geom_traits}
  ///     \cgalParamDescription{an instance of the geometric traits, used to construct the points
  ///       the diagram returns}
  ///     \cgalParamType{`Geom_traits`}
  ///     \cgalParamDefault{a default-constructed `Geom_traits`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{edge_is_constrained_map}
  ///     \cgalParamDescription{breaklines: a property map telling which edges of `tm` no cell crosses.
  ///       A site on a breakline (a face location with a barycentric coordinate exactly 0, on a
  ///       breakline edge, or two, at a vertex a breakline passes through or ends at) starts on
  ///       every side of it: its cell holds what is nearest to it on each side, and is one cell
  ///       through the site. This is what `feature_line_sites()` places.}
  ///     \cgalParamType{a model of `ReadablePropertyMap` with `edge_descriptor` as key and `bool` as value}
  ///     \cgalParamDefault{no breaklines}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{Surface_voronoi::parameters::site_weight_map}
  ///     \cgalParamDescription{power weights, which make the diagram a power diagram: a point
  ///       belongs to the site minimizing its squared distance minus the weight. Weights are in
  ///       the squared units of the metric (see `Surface_voronoi::weight_for_length()`);
  ///       a large weight can empty other cells (counted in `statistics().empty_cells`)}
  ///     \cgalParamType{a model of `ReadablePropertyMap` whose key is the sites' type (as the
  ///       range holds them) or `std::size_t` (the site index), and whose value converts to `double`}
  ///     \cgalParamDefault{all weights zero}
  ///     \cgalParamExtra{a weight that is not finite makes the constructor throw `Surface_voronoi::Input_error`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{Surface_voronoi::parameters::max_site_distance}
  ///     \cgalParamDescription{a site given as a point farther than this from the surface makes
  ///       the constructor throw `Surface_voronoi::Site_too_far_error`}
  ///     \cgalParamType{`double`}
  ///     \cgalParamDefault{infinity}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{Surface_voronoi::parameters::coincident_sites}
  ///     \cgalParamDescription{what two sites at the same surface point (the same location once
  ///       sites given as points are moved onto the surface) mean: an error (`REJECT`: the
  ///       constructor throws `Surface_voronoi::Coincident_sites_error` naming both), or the later
  ///       site merged into the earlier one (`MERGE`: it keeps its index, owns no area,
  ///       `merged_into()` names the site that owns its cell, and `statistics().merged_sites`
  ///       counts the merged sites)}
  ///     \cgalParamType{`Surface_voronoi::Coincident_sites`}
  ///     \cgalParamDefault{`Surface_voronoi::Coincident_sites::REJECT`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{Surface_voronoi::parameters::prepared_mesh}
  ///     \cgalParamDescription{the mesh prepared once, shared with the other calls given it}
  ///     \cgalParamType{`Surface_voronoi::Prepared_mesh<TriangleMesh, C>`, `C` any concurrency tag}
  ///     \cgalParamDefault{the metric's, if it has one, else the mesh prepared by this call}
  ///   \cgalParamNEnd
  ///   \cgalParamSectionEnd
  ///   \cgalParamSectionBegin{Algorithm}
  ///   \cgalParamNBegin{Surface_voronoi::parameters::candidate_selection}
  ///     \cgalParamDescription{propagation (SurfaceVoronoi) or every globally nearest site (the
  ///       restricted Voronoi diagram, for embedding metrics only)}
  ///     \cgalParamType{`Surface_voronoi::Candidate_selection`}
  ///     \cgalParamDefault{`Surface_voronoi::Candidate_selection::PROPAGATION`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{Surface_voronoi::parameters::repair_cells}
  ///     \cgalParamDescription{whether cells found in several pieces are repaired (never with
  ///       `GLOBAL_NEAREST`)}
  ///     \cgalParamType{`bool`}
  ///     \cgalParamDefault{`true`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{Surface_voronoi::parameters::max_repair_rounds}
  ///     \cgalParamDescription{the most repair rounds; cells still broken afterwards are counted
  ///       in `statistics().broken_cells`}
  ///     \cgalParamType{`std::size_t`}
  ///     \cgalParamDefault{100}
  ///     \cgalParamExtra{less than 65535}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{Surface_voronoi::parameters::stage_times}
  ///     \cgalParamDescription{receives the seconds of the stages `"setup"`, `"propagation"`, `"cutting"` and `"repair"`, of the construction and of every `update()`, which it must outlive (see `Surface_voronoi::Stage_times`)}
  ///     \cgalParamType{`Surface_voronoi::Stage_times*`}
  ///     \cgalParamDefault{`nullptr`: nothing is timed}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{callback}
  ///     \cgalParamDescription{called from time to time with the fraction of the work done (in
  ///       [0, 1]) for progress reports; returning `false` stops the construction, which
  ///       returns normally: the diagram is then `is_cancelled()` and holds no cells}
  ///     \cgalParamType{a callable `bool(double)`}
  ///     \cgalParamDefault{none}
  ///   \cgalParamNEnd
  ///   \cgalParamSectionEnd
  /// \cgalNamedParamsEnd
  ///
  /// The diagram is that of the mesh given, whatever the number of sites in a face; a face is
  /// cut among the sites that reach it, at a cost that grows faster than the square of their
  /// number. On a coarse mesh with many sites per face (hundreds: a 12-triangle cube with
  /// 3,000 sites), insert the sites first (`Surface_voronoi::insert_sites()`, then the metric
  /// and the diagram on the augmented mesh) or, for the geodesic metric, refine the mesh for
  /// them (`Surface_voronoi::refine_for_sites()`): an embedding or a distance sampled at
  /// vertices also needs vertices between the sites.
  ///
  /// With an embedding (`SurfaceVoronoiEmbedding`) the constructor reads the coordinates of
  /// every vertex once; a lazy metric (`SurfaceVoronoiLazyMetric`) is told the sites with
  /// `set_sites()` and asked distances while the diagram is built. Either way the metric is not
  /// used after the constructor returns, except by the updates of a diagram over a lazy metric.
  ///
  /// \pre `tm` is a valid polygon mesh (its halfedges are consistent); the sites are not
  ///      empty. `Surface_voronoi::validate_input()` checks these too.
  /// \throws Surface_voronoi::Input_error in every build, the message naming the face, vertex
  ///         or site (by its position in `faces(tm)`, `vertices(tm)` or `sites`), if a face is
  ///         not a triangle, a vertex has a non-finite coordinate or one beyond
  ///         \f$ 2^{200} \f$ in magnitude, a face has no area, a longest edge below
  ///         \f$ 2^{-200} \f$, or an area below \f$ 2^{-44} \f$ times its squared longest
  ///         edge (needles and caps above that are computed with), a vertex belongs to no face
  ///         or is non-manifold, a site is not on `tm` (a descriptor of another mesh, a point
  ///         that is not finite), a weight or an embedding coordinate is not finite, if
  ///         `metric.triangle_mesh()` is not `tm`, or if there are \f$ 2^{32} - 1 \f$ sites or more
  /// \throws Surface_voronoi::Coincident_sites_error (an `Input_error`) with `Coincident_sites::REJECT`,
  ///         if two sites are at the same surface point
  /// \throws Surface_voronoi::Site_too_far_error as said for `max_site_distance`
  /// \throws Surface_voronoi::Numerical_error if a lazy metric returns an invalid distance
  template <class SiteRange, class NamedParameters = CGAL::parameters::Default_named_parameters>
  Surface_voronoi_diagram(const TriangleMesh& tm,
                          Metric& metric,
                          const SiteRange& sites,
                          const NamedParameters& np = CGAL::parameters::default_values())
    : m_tm(&tm)
  {
    construct(metric, sites, np);
  }

  /// \cond SKIP_IN_MANUAL
  Surface_voronoi_diagram(Surface_voronoi_diagram&&) = default;
  Surface_voronoi_diagram& operator=(Surface_voronoi_diagram&&) = default;
  Surface_voronoi_diagram(const Surface_voronoi_diagram&) = delete;
  Surface_voronoi_diagram& operator=(const Surface_voronoi_diagram&) = delete;
  /// \endcond

  /// whether the `callback` named parameter stopped the construction; a cancelled diagram
  /// keeps its sites but has no cells (no site owns anything, every cell area is 0)
  bool is_cancelled() const { return m_data.cancelled; }

  /// \name Sites
  /// @{

  /// the number of sites
  std::size_t number_of_sites() const { return m_data.sites.size(); }
  /// the location of site `i` (its face and barycentric coordinates)
  /// \pre `i < number_of_sites()`
  Face_location site_location(std::size_t i) const
  {
    CGAL_precondition(i < number_of_sites());
    return Face_location(m_data.mesh->face_handles[m_data.sites[i].face], m_data.sites[i].barycentric);
  }
  /// the point of site `i`
  /// \pre `i < number_of_sites()`
  Point_3 site_point(std::size_t i) const
  {
    CGAL_precondition(i < number_of_sites());
    return to_point(m_data.mesh->point_at(m_data.sites[i].face, m_data.sites[i].barycentric));
  }
  /// the power weight of site `i`
  /// \pre `i < number_of_sites()`
  double site_weight(std::size_t i) const
  {
    CGAL_precondition(i < number_of_sites());
    return m_data.sites[i].weight;
  }
  /// with `Coincident_sites::MERGE`, the site whose cell site `i` was merged into, else `no_site`
  /// \pre `i < number_of_sites()`
  std::size_t merged_into(std::size_t i) const
  {
    CGAL_precondition(i < number_of_sites());
    return m_data.merged_into[i];
  }
  /// @}

  /// \name Queries
  /// @{

  /// the site whose cell contains the point; ties go to the lower site index; `no_site`
  /// where no site reaches
  /// \pre `l.first` is a face of the mesh
  std::size_t site_of(const Face_location& l) const
  {
    if(m_data.cancelled) return no_site;
    const std::size_t f = get(m_data.mesh->face_index, l.first);
    std::size_t best = no_site;
    double best_value = 0;
    for(const auto& x : m_data.candidates[f])
    {
      const double v = l.second[0] * x.value[0] + l.second[1] * x.value[1] + l.second[2] * x.value[2];
      if(best == no_site || v < best_value || (v == best_value && x.site < best))
      {
        best = x.site;
        best_value = v;
      }
    }
    return best;
  }

  /// the site owning vertex `v` of the mesh (ties to the lower index), `no_site` if none
  std::size_t site_of(vertex_descriptor v) const
  {
    return m_data.cancelled ? no_site : m_data.vertex_site[get(m_data.mesh->vertex_index, v)];
  }

  /// the area of the cell of site `i`
  /// \pre `i < number_of_sites()`
  double cell_area(std::size_t i) const
  {
    CGAL_precondition(i < number_of_sites());
    return m_data.cell_area[i];
  }
  /// the number of connected pieces of the cell of site `i` (1 for a good cell, 0 if empty)
  /// \pre `i < number_of_sites()`
  std::size_t number_of_pieces(std::size_t i) const
  {
    CGAL_precondition(i < number_of_sites());
    return m_data.cell_pieces[i];
  }
  /// the sites whose cells share a boundary segment with the cell of `i`, ascending; found
  /// for all sites on the first call (a pass over the cells' pieces), not by the construction
  /// \pre `i < number_of_sites()`
  const std::vector<std::size_t>& neighbors(std::size_t i) const
  {
    CGAL_precondition(i < number_of_sites());
    if(m_neighbors.size() != number_of_sites())
      m_neighbors = Surface_voronoi::internal::site_neighbors(*m_data.mesh, m_data.partition, number_of_sites());
    return m_neighbors[i];
  }
  /// the area no site reaches (components without sites, regions closed off by breaklines)
  double unreached_area() const { return m_data.statistics.unreached_area; }
  /// the number of faces no site reaches
  std::size_t number_of_unreached_faces() const { return m_data.statistics.unreached_faces; }
  /// the area of the whole surface
  double surface_area() const { return m_data.mesh->total_area; }
  /// what the construction did
  const Surface_voronoi::Diagram_statistics& statistics() const { return m_data.statistics; }
  /// @}

  /// \name Arrangement
  /// The faces of the arrangement, read without building it (`Surface_voronoi::make_arrangement()`
  /// builds it): each a convex polygon inside one face of the mesh and one cell, its corners
  /// numbered among the arrangement's vertices, which adjacent faces share. A cancelled
  /// diagram has none.
  /// @{

  /// the number of vertices of the arrangement (some may be a corner of no face)
  std::size_t number_of_arrangement_vertices() const { return m_data.partition.vertices.size(); }
  /// the point of vertex `i` of the arrangement
  /// \pre `i < number_of_arrangement_vertices()`
  Point_3 arrangement_point(std::size_t i) const { return to_point(m_data.partition.vertices[i].point); }
  /// the number of faces of the arrangement, which `make_arrangement()` adds in the order of their indices
  std::size_t number_of_arrangement_faces() const { return m_data.partition.pieces.size(); }
  /// the vertices of face `k` of the arrangement, counterclockwise as the faces of the mesh
  /// \pre `k < number_of_arrangement_faces()`
  CGAL::Iterator_range<const std::uint32_t*> arrangement_face_vertices(std::size_t k) const
  { const auto& v = m_data.partition.pieces[k].vertices; return CGAL::make_range(v.data(), v.data() + v.size()); }
  /// the site whose cell holds face `k` of the arrangement, `no_site` where no site reaches
  /// \pre `k < number_of_arrangement_faces()`
  std::size_t arrangement_face_site(std::size_t k) const { return m_data.partition.pieces[k].site; }
  /// the face of the mesh that holds face `k` of the arrangement
  /// \pre `k < number_of_arrangement_faces()`
  face_descriptor arrangement_input_face(std::size_t k) const { return m_data.mesh->face_handles[m_data.partition.pieces[k].face]; }
  /// @}

  /// \name Cell measures
  /// @{

  /// the area-weighted centroids of all cells in space (not on the surface), in site order;
  /// the site's own point for an empty cell (computed once, on the first call)
  const std::vector<Point_3>& cell_centroids() const
  {
    if(m_centroids.size() != number_of_sites())
    {
      m_centroids.clear();
      for(const Surface_voronoi::internal::Point_d& p : Surface_voronoi::internal::cell_centroids(m_data))
        m_centroids.push_back(to_point(p));
    }
    return m_centroids;
  }

  /// the area-weighted centroid of the cell of site `i` (see `cell_centroids()`)
  /// \pre `i < number_of_sites()`
  Point_3 cell_centroid(std::size_t i) const
  {
    CGAL_precondition(i < number_of_sites());
    return cell_centroids()[i];
  }

  /// The energy of the diagram, the sum over sites of the integral over their cell of the
  /// squared distance to the site: exact for embeddings (|E(x) - E(s)|^2 is quadratic on a
  /// triangle, integrated with the edge-midpoint rule), the integral of the linearly
  /// interpolated squared distance for lazy metrics. Weights are not subtracted.
  double energy() const { return Surface_voronoi::internal::energy(m_data); }
  /// @}

  /// \name Updates
  /// The diagram can be computed again after its sites change, from its previous state: the
  /// indexed mesh, the breaklines, the embedding's coordinates and the named parameters given
  /// to the constructor are kept, and the cells' candidates, cuts and pieces, so that an update
  /// costs less than a construction. With an embedding and no power weights, an update that
  /// only moves sites propagates, cuts and stitches again only the faces the moved
  /// sites' fields reach before or after (falling back to the whole mesh where cells left
  /// broken or exact ties are met); other changes compute the cells over the whole mesh. The
  /// changes are recorded by `move_site()`,
  /// `insert_site()`, `remove_site()` and `set_site_weight()`, which change nothing that the
  /// queries read, and take effect at `update()`. The updated diagram is the one the
  /// constructor would compute from the same sites in the same order, with the same named
  /// parameters.
  ///
  /// Indices are those of a `std::vector` of the sites being edited: a change names a site by
  /// its index among the sites as changed so far, `insert_site()` appends, and
  /// `remove_site(i)` moves every later site down by one index (the indices of the updated
  /// diagram are compacted, with no empty slot).
  ///
  /// A diagram over a lazy metric (`SurfaceVoronoiLazyMetric`) asks the metric again at
  /// `update()`: the metric must then be alive, and is told the new sites. An embedding is not
  /// used after the constructor. `release_update_state()` releases what only the updates need.
  /// @{

  /// records that site `i` moves to `s` (a `vertex_descriptor`, a `Face_location` or a point,
  /// located as by the constructor), keeping its weight
  /// \pre `i < number_of_sites_after_update()` and the update state was not released
  /// \throws Surface_voronoi::Input_error as the constructor, if `s` is not on the mesh
  template <class SiteDescription>
  void move_site(std::size_t i, const SiteDescription& s)
  {
    begin_changes();
    CGAL_precondition(i < m_next_sites.size());
    const double weight = m_next_sites[i].weight;
    m_next_sites[i] = m_locator->locate(s, i);
    m_next_sites[i].weight = weight;
  }

  /// records that a site at `s` (as for `move_site()`) with power weight `weight` is appended;
  /// returns its index, `number_of_sites_after_update() - 1`
  /// \pre the update state was not released
  /// \throws Surface_voronoi::Input_error if `s` is not on the mesh or `weight` is not finite
  template <class SiteDescription>
  std::size_t insert_site(const SiteDescription& s, double weight = 0)
  {
    begin_changes();
    check_weight(weight, m_next_sites.size());
    m_next_sites.push_back(m_locator->locate(s, m_next_sites.size()));
    m_next_sites.back().weight = weight;
    m_resized = true;
    m_settings.has_weights = m_settings.has_weights || weight != 0;
    return m_next_sites.size() - 1;
  }

  /// records that site `i` is removed: the sites after it move down by one index
  /// \pre `i < number_of_sites_after_update()`, which is more than 1, and the update state
  ///      was not released
  void remove_site(std::size_t i)
  {
    begin_changes();
    CGAL_precondition(i < m_next_sites.size() && m_next_sites.size() > 1);
    m_next_sites.erase(m_next_sites.begin() + std::ptrdiff_t(i));
    m_resized = true;
  }

  /// records that the power weight of site `i` becomes `weight` (see the named parameter
  /// `site_weight_map`)
  /// \pre `i < number_of_sites_after_update()` and the update state was not released
  /// \throws Surface_voronoi::Input_error if `weight` is not finite
  void set_site_weight(std::size_t i, double weight)
  {
    begin_changes();
    CGAL_precondition(i < m_next_sites.size());
    check_weight(weight, i);
    m_next_sites[i].weight = weight;
    m_settings.has_weights = m_settings.has_weights || weight != 0;
  }

  /// the number of sites the diagram will have after `update()`: `number_of_sites()` changed
  /// by the insertions and removals recorded since
  std::size_t number_of_sites_after_update() const { return m_next_sites.empty() ? number_of_sites() : m_next_sites.size(); }

  /// Computes the diagram of the sites as changed, from its previous state; does nothing if
  /// no change was recorded. The `callback` given to the constructor reports its progress
  /// and may stop it, as for the constructor: the diagram is then `is_cancelled()`, with the
  /// changed sites and no cells, and the next update computes it from scratch.
  /// \pre the update state was not released; with a lazy metric, the metric given to the
  ///      constructor is alive
  /// \throws Surface_voronoi::Coincident_sites_error, Surface_voronoi::Numerical_error as the
  ///         constructor
  void update()
  {
    namespace SVi = Surface_voronoi::internal;
    CGAL_precondition_msg(m_locator != nullptr, "the update state was released");
    if(m_next_sites.empty()) return;
    SVi::Stage_timer timer(m_times);
    // Lloyd's cells-only diagrams, whose sites only move, start their propagation from the
    // previous candidates: faster, but where a field stops another that a later field
    // outweighs, the order of the propagation, and so the cells, can differ from a fresh
    // diagram's
    std::unique_ptr<SVi::Candidate_sites> previous;
    if(SVi::Is_embedding<Metric>::value && m_settings.cells_only && !m_resized && !m_data.cancelled)
      previous.reset(new SVi::Candidate_sites(m_data.candidates));
    // the sites that moved, for an update from the previous cells: with an embedding (whose
    // kept values only the moved sites' change) and without weights (a heavier field can stop
    // another that wins beyond it, so that the fresh propagation's order decides the cells)
    std::vector<std::uint8_t> changed;
    if(SVi::Is_embedding<Metric>::value && !m_settings.cells_only && !m_resized && !m_data.cancelled)
      for(std::size_t i = 0; i < m_next_sites.size(); ++i)
      {
        const SVi::Site &a = m_data.sites[i], &b = m_next_sites[i];
        if(a.weight != 0 || b.weight != 0) { changed.clear(); break; }
        changed.push_back(a.face != b.face || a.barycentric != b.barycentric);
      }
    m_data.sites.swap(m_next_sites);
    std::vector<SVi::Site>().swap(m_next_sites);
    m_resized = false;
    m_data.cancelled = false;
    if(changed.empty()) m_data.clear_cells();
    m_centroids.clear();
    m_neighbors.clear();
    compute<true, true, true>(previous.get(), timer, changed.empty() ? nullptr : &changed);
  }

  /// releases what only the updates need (the search structure built to locate sites given
  /// as points, the cuts of the faces, the changes recorded and not applied) and forgets the metric; the queries are
  /// unaffected, and no change or update may follow
  void release_update_state()
  {
    m_locator.reset();
    m_metric = nullptr;
    m_data.cuts = Surface_voronoi::internal::Face_cuts();
    m_data.banned = Surface_voronoi::internal::Banned_fields();
    std::vector<Surface_voronoi::internal::Site>().swap(m_next_sites);
    m_resized = false;
  }
  /// @}

  /// \name Access
  /// @{

  /// the mesh the diagram was built on
  const TriangleMesh& triangle_mesh() const { return *m_tm; }
  /// the vertex point map of the mesh
  Vertex_point_map vertex_point_map() const { return m_vpm; }
  /// the geometric traits the diagram constructs its points with
  const Geom_traits& geom_traits() const { return m_traits; }
  /// @}

private:
  Point_3 to_point(const Surface_voronoi::internal::Point_d& p) const
  {
    return m_traits.construct_point_3_object()(p.x(), p.y(), p.z());
  }

  template <class SiteRange, class NamedParameters>
  void construct(Metric& metric, const SiteRange& sites, const NamedParameters& np)
  {
    using CGAL::parameters::choose_parameter;
    using CGAL::parameters::get_parameter;
    using CGAL::parameters::is_default_parameter;
    namespace SVi = Surface_voronoi::internal;
    namespace SVnp = Surface_voronoi::internal_np;
    const TriangleMesh& tm = *m_tm;
    if(&metric.triangle_mesh() != &tm)
      throw Surface_voronoi::Input_error("the metric was built on another mesh");

    m_vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm));
    m_traits = choose_parameter<Geom_traits>(get_parameter(np, CGAL::internal_np::geom_traits));
    m_times = choose_parameter(get_parameter(np, SVnp::stage_times), static_cast<Surface_voronoi::Stage_times*>(nullptr));
    m_callback = Surface_voronoi::internal::callback_of(np);
    SVi::Stage_timer timer(m_times);

    const auto prepared = SVi::prepared_mesh_of<TriangleMesh>(np);
    const std::shared_ptr<const Indexed_mesh>& given = prepared.indexed_mesh();
    m_data.mesh = SVi::shared_or_new_indexed_mesh(given ? given : SVi::indexed_mesh_of<TriangleMesh>(metric), tm, m_vpm,
                                                  SVi::use_threads<ConcurrencyTag>());
    // the copy has refused faces that are not triangles
    SVi::throw_mesh_problems(*m_data.mesh, !(prepared.topology_checked() && m_data.mesh == given));

    // breaklines
    if(!is_default_parameter<NamedParameters, CGAL::internal_np::edge_is_constrained_t>::value)
      m_data.breaklines = SVi::Breaklines(*m_data.mesh, tm,
          choose_parameter(get_parameter(np, CGAL::internal_np::edge_is_constrained),
                           CGAL::Constant_property_map<typename boost::graph_traits<TriangleMesh>::edge_descriptor, bool>(false)));

    // sites and their weights
    m_locator.reset(new SVi::Site_locator<TriangleMesh>(tm, *m_data.mesh,
        choose_parameter(get_parameter(np, SVnp::max_site_distance), std::numeric_limits<double>::infinity())));
    constexpr bool has_weights = !is_default_parameter<NamedParameters, SVnp::site_weight_map_t>::value;
    for(const auto& s : sites)
    {
      m_data.sites.push_back(m_locator->locate(s, m_data.sites.size()));
      if constexpr(has_weights)
        m_data.sites.back().weight = SVi::site_weight(get_parameter(np, SVnp::site_weight_map), s, m_data.sites.size() - 1);
      check_weight(m_data.sites.back().weight, m_data.sites.size() - 1);
    }
    m_policy = choose_parameter(get_parameter(np, SVnp::coincident_sites), Surface_voronoi::Coincident_sites::REJECT);

    m_settings.candidates = choose_parameter(get_parameter(np, SVnp::candidate_selection),
                                             Surface_voronoi::Candidate_selection::PROPAGATION);
    m_settings.repair = choose_parameter(get_parameter(np, SVnp::repair_cells), true);
    m_settings.max_repair_rounds = choose_parameter(get_parameter(np, SVnp::max_repair_rounds), std::size_t(100));
    CGAL_precondition_msg(m_settings.max_repair_rounds < 65535, "max_repair_rounds must be less than 65535");
    m_settings.has_weights = has_weights;
    m_settings.parallel = SVi::use_threads<ConcurrencyTag>();
    m_settings.cells_only = choose_parameter(get_parameter(np, SVnp::cells_only), false);
    m_data.centroid_density = choose_parameter(get_parameter(np, SVnp::centroid_density), std::shared_ptr<const std::vector<double> >());
    CGAL_precondition(!m_data.centroid_density || m_data.centroid_density->size() == m_data.mesh->number_of_vertices());
    m_metric = &metric;
    // the restricted Voronoi diagram's search, and Lloyd's cells-only diagrams, are compiled
    // only where the named parameters asking for them are given (and in update())
    constexpr bool may_select_globally = !is_default_parameter<NamedParameters, SVnp::candidate_selection_t>::value;
    constexpr bool for_relaxation = !is_default_parameter<NamedParameters, SVnp::cells_only_t>::value;
    compute<may_select_globally, for_relaxation, false>(nullptr, timer);
  }

  static void check_weight(double w, std::size_t i)
  {
    if(!std::isfinite(w))
      throw Surface_voronoi::Input_error("the weight of site " + std::to_string(i) + " is not finite");
  }

  // the cells of `m_data.sites`, with the propagation started from `previous` if given
  // (embedding metrics), updated from the previous cells if `changed` is (`Updating` only)
  template <bool MaySelectGlobally, bool ForRelaxation, bool Updating>
  void compute(const Surface_voronoi::internal::Candidate_sites* previous, Surface_voronoi::internal::Stage_timer& timer,
               const std::vector<std::uint8_t>* changed = nullptr)
  {
    namespace SVi = Surface_voronoi::internal;
    CGAL_precondition_msg(!m_data.sites.empty(), "there are no sites");
    if(m_data.sites.size() >= std::size_t(std::numeric_limits<std::uint32_t>::max()))
      throw Surface_voronoi::Input_error("too many sites");
    m_data.merged_into.assign(m_data.sites.size(), no_site);
    for(const auto& pair : SVi::find_coincident_sites(*m_data.mesh, m_data.sites))
    {
      if(m_policy != Surface_voronoi::Coincident_sites::MERGE)
        throw Surface_voronoi::Coincident_sites_error("sites " + std::to_string(pair.first) + " and " + std::to_string(pair.second)
                                                      + " are at the same surface point", pair.first, pair.second);
      m_data.merged_into[pair.second] = pair.first;
    }
    // sites on breaklines start on every side of them
    std::vector<std::pair<std::size_t, std::size_t> >& starts = m_data.breakline_site_faces;
    starts = m_data.breaklines.faces_of_sites_on_breaklines(*m_data.mesh, m_data.sites);
    starts.erase(std::remove_if(starts.begin(), starts.end(),
                                [&](const std::pair<std::size_t, std::size_t>& x) { return m_data.merged_into[x.first] != no_site; }),
                 starts.end());
    m_settings.previous = (previous && previous->number_of_faces() == m_data.mesh->number_of_faces()) ? previous : nullptr;
    if(m_callback && !m_callback(0.05)) { cancel(); return; }
    // the fields over the embedding's values, stored for the queries and the updates, or over
    // the lazy metric
    auto build = [&](const auto& fields) {
      timer.stop("setup");
      SVi::Diagram_builder<TriangleMesh, std::decay_t<decltype(fields)>, MaySelectGlobally, ForRelaxation, Updating>
          builder(m_data, fields, m_settings, m_callback, m_times);
      bool done;
      if constexpr(Updating) done = changed ? builder.update(*changed) : builder.run();
      else done = builder.run();
      if(!done) cancel();
      m_settings.previous = nullptr;   // the caller's, gone after this computation
    };
    if constexpr(SVi::Is_embedding<Metric>::value)
    {
      if(!m_data.embedding)
      {
        CGAL_precondition_msg(!is_cancelled_metric(*m_metric, 0), "the embedding was cancelled");
        m_data.embedding.reset(new SVi::Embedding_values(*m_data.mesh, *m_metric, m_data.sites));
      }
      else
        m_data.embedding->set_sites(*m_data.mesh, m_data.sites);
      build(*m_data.embedding);
    }
    else
      build(SVi::Lazy_values<TriangleMesh, Metric>(*m_data.mesh, *m_metric, m_data.sites));
  }

  // the changes asked since the last computation: the sites as they are to be (empty when
  // there is none)
  void begin_changes()
  {
    CGAL_precondition_msg(m_locator != nullptr, "the update state was released");
    if(m_next_sites.empty()) m_next_sites = m_data.sites;
  }

  // metrics without is_cancelled() are never cancelled (chosen by int/long, not by "...":
  // clang refuses to pass a class object through "..." in builds with preconditions)
  template <class M>
  static auto is_cancelled_metric(const M& m, int) -> decltype(bool(m.is_cancelled())) { return m.is_cancelled(); }
  template <class M>
  static bool is_cancelled_metric(const M&, long) { return false; }

  void cancel()
  {
    m_data.cancelled = true;
    m_data.clear_cells();
  }

  const TriangleMesh* m_tm;
  Vertex_point_map m_vpm;
  Geom_traits m_traits;
  Data m_data;
  // what update() needs besides the data: how the diagram is computed, and the changes
  Metric* m_metric = nullptr;
  std::unique_ptr<Surface_voronoi::internal::Site_locator<TriangleMesh> > m_locator;
  Surface_voronoi::internal::Builder_settings m_settings;
  Surface_voronoi::Coincident_sites m_policy = Surface_voronoi::Coincident_sites::REJECT;
  std::function<bool(double)> m_callback;
  Surface_voronoi::Stage_times* m_times = nullptr;
  std::vector<Surface_voronoi::internal::Site> m_next_sites;
  bool m_resized = false;   // whether sites were inserted or removed since the last computation
  mutable std::vector<Point_3> m_centroids;
  mutable std::vector<std::vector<std::size_t> > m_neighbors;
};

} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_SURFACE_VORONOI_DIAGRAM_H
