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
// Lloyd relaxation (centroidal Voronoi): every site moves to the centroid of its cell,
// projected back to the surface, and the diagram is computed again. The metric is built
// once: no eigen-solve per iteration.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_LLOYD_RELAXATION_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_LLOYD_RELAXATION_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/Surface_voronoi_diagram.h>
#include <CGAL/Surface_voronoi_diagram/internal/callback.h>
#include <CGAL/Surface_voronoi_diagram/internal/Input_validation.h>
#include <CGAL/Surface_voronoi_diagram/internal/Nearest_point_of_cell.h>
#include <CGAL/Surface_voronoi_diagram/internal/Site_locator.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <functional>
#include <memory>
#include <limits>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {

/// \ingroup PkgSurfaceVoronoiDiagramSites
/// What `lloyd_relaxation()` did.
/// \tparam TriangleMesh the mesh type of the sites
template <class TriangleMesh>
struct Lloyd_result
{
  /// the relaxed sites, as face locations
  std::vector<CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double> > sites;
  /// the energy (`Surface_voronoi_diagram::energy()`) of the initial diagram and after each iteration
  std::vector<double> energies;
  /// sites kept in place because their centroid projected onto another site's point
  std::size_t kept_in_place = 0;
  /// whether the `callback` stopped the relaxation; `sites` are then those reached by the
  /// iterations completed
  bool cancelled = false;
};

namespace internal {

// Moves back the sites whose new position coincides with another site's: the later site of
// a pair if it moved, else the earlier one. Positions are computed as the diagram computes
// them, so that the diagram then sees distinct sites.
template <class TriangleMesh, class Location>
std::size_t keep_sites_apart(const Indexed_mesh<TriangleMesh>& mesh, const TriangleMesh& tm,
                             std::vector<Location>& sites, const std::vector<Location>& previous)
{
  const Site_locator<TriangleMesh> locator(tm, mesh, std::numeric_limits<double>::infinity());
  std::size_t kept = 0;
  for(;;)
  {
    std::vector<Site> located;
    located.reserve(sites.size());
    for(std::size_t i = 0; i < sites.size(); ++i) located.push_back(locator.locate(sites[i], i));
    const auto pairs = find_coincident_sites(mesh, located);
    if(pairs.empty()) return kept;
    auto moved = [&](std::size_t i) { return sites[i].first != previous[i].first || sites[i].second != previous[i].second; };
    for(const auto& pair : pairs)
    {
      const std::size_t k = moved(pair.second) ? pair.second : pair.first;
      CGAL_assertion(moved(k));   // the previous sites were distinct
      if(!moved(k)) return kept;
      sites[k] = previous[k];
      ++kept;
    }
  }
}

// The weight of the centroids, by vertex in the order of `vertices(tm)` (the diagram's
// vertex indices): the square of the density of sites per unit area, since a centroidal
// Voronoi tessellation of the plane with weight w has about sqrt(w) sites per unit area
// (Gersho); null without a density map.
template <class TriangleMesh, class NamedParameters>
std::shared_ptr<const std::vector<double> > centroid_weights(const TriangleMesh& tm, const NamedParameters& np)
{
  if constexpr(CGAL::parameters::is_default_parameter<NamedParameters, Surface_voronoi::internal_np::vertex_density_map_t>::value)
  {
    CGAL_USE(tm);
    CGAL_USE(np);
    return nullptr;
  }
  else
  {
    const auto density = CGAL::parameters::get_parameter(np, Surface_voronoi::internal_np::vertex_density_map);
    auto w = std::make_shared<std::vector<double> >();
    bool positive = false;
    for(auto v : vertices(tm))
    {
      const double x = double(get(density, v));
      if(!(std::isfinite(x) && x >= 0)) throw Input_error("the vertex densities must be finite and not negative");
      w->push_back(x * x);
      positive = positive || x > 0;
    }
    if(!positive) throw Input_error("the vertex density must not be zero everywhere");
    return w;
  }
}

} // namespace internal

/// \ingroup PkgSurfaceVoronoiDiagramSites
/// Lloyd relaxation: from `sites` (face locations of `tm`), each iteration moves every site to
/// the area-weighted centroid of its cell, projected to the nearest point of the faces its cell
/// reaches (the faces where it is a candidate, and its own), and builds the diagram again.
/// Projecting onto the cell's own faces rather than onto the whole surface keeps a site on its
/// side of a thin wall, where the centroid of a cell on one side of a thin plate can be nearer
/// the other side. For the Euclidean embedding with `GLOBAL_NEAREST` candidates the energy
/// cannot increase (the projection is at least as near the centroid as the site was, and the
/// new cells minimize the energy for the sites); for the other metrics it is reported. An empty
/// cell keeps its site; a centroid projecting onto another site's point keeps its site. The
/// projection uses the geometric traits (named parameter `geom_traits`, by default the
/// kernel of the vertex point map), since it constructs the locations returned; the search
/// starts from the face whose bounding sphere is nearest the centroid and goes on through the
/// cell's faces in their order, and where faces share the nearest point (on their common edge
/// or vertex) the first searched keeps it.
/// The metric is built once by the caller: no embedding is computed again per iteration, and
/// the diagrams of the iterations compute the cells only (no neighbours, no vertex owners),
/// measuring their areas, centroids and energy on the per-face cuts without stitching them
/// into a partition, once the cuts show every cell whole.
///
/// \tparam ConcurrencyTag the concurrency tag of the diagrams built (see
///         `Surface_voronoi_diagram`); default: `CGAL::Sequential_tag`
/// \tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
/// \tparam Metric a model of `SurfaceVoronoiEmbedding` or of `SurfaceVoronoiLazyMetric`
/// \param tm the mesh
/// \param metric the metric, built on `tm`
/// \param sites the initial sites
/// \param np an optional sequence of named parameters: those of the diagram's constructor
///        (they apply to every diagram built) and the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`, for the
///       diagrams and for the projection}
///     \cgalParamType{a model of `ReadablePropertyMap`}
///     \cgalParamDefault{`get_const_property_map(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{an instance of the geometric traits, for the diagrams and for the
///       projection of the centroids}
///     \cgalParamType{a model of `Kernel`}
///     \cgalParamDefault{the kernel of the point type of the vertex point map}
///   \cgalParamNEnd
///   \cgalParamNBegin{Surface_voronoi::parameters::vertex_density_map}
///     \cgalParamDescription{the wanted number of sites per unit area, up to a constant factor,
///       at each vertex (interpolated linearly across faces; see `curvature_density()`): the
///       centroids are weighted by its square, which gives a centroidal tessellation about
///       that many sites per unit area. The energies reported stay those without the density.}
///     \cgalParamType{a model of `ReadablePropertyMap` with `vertex_descriptor` as key and a
///       value type convertible to `double` (finite, not negative, not zero everywhere)}
///     \cgalParamDefault{a uniform density}
///   \cgalParamNEnd
///   \cgalParamNBegin{Surface_voronoi::parameters::first_moving_site}
///     \cgalParamDescription{the sites before this index stay where they are: the sites that
///       `feature_line_sites()` placed on breaklines and on the border (already evenly spaced
///       along their lines), given first, while the others relax around them}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{0: every site moves}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_iterations}
///     \cgalParamDescription{the number of Lloyd steps}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{10}
///   \cgalParamNEnd
///   \cgalParamNBegin{callback}
///     \cgalParamDescription{called with the fraction of all iterations done; returning `false`
///       stops the relaxation, which returns the sites reached by the iterations completed
///       (their energy not computed) with `cancelled` set}
///     \cgalParamType{a callable `bool(double)`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the relaxed sites, the energy after each iteration and what was kept in place
/// \throws Surface_voronoi::Input_error if a density is negative or not a finite number, or
///         zero at every vertex (checked in every build), and as the diagram's constructor
/// \pre the preconditions of the diagram's constructor hold for `sites`
template <class ConcurrencyTag = CGAL::Sequential_tag, class TriangleMesh, class Metric, typename CGAL_NP_TEMPLATE_PARAMETERS>
Lloyd_result<TriangleMesh>
lloyd_relaxation(const TriangleMesh& tm, Metric& metric,
                 std::vector<CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double> > sites,
                 const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  typedef CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double> Location;
  typedef typename GetVertexPointMap<TriangleMesh, CGAL_NP_CLASS>::const_type VPM;
  typedef typename GetGeomTraits<TriangleMesh, CGAL_NP_CLASS>::type Geom_traits;
  typedef CGAL::Surface_voronoi_diagram<TriangleMesh, Metric, VPM, Geom_traits, ConcurrencyTag> Diagram;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;

  const VPM vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm));
  const auto locate_np = CGAL::parameters::vertex_point_map(vpm).geom_traits(choose_parameter<Geom_traits>(get_parameter(np, CGAL::internal_np::geom_traits)));
  const std::size_t iterations = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), std::size_t(10));
  const std::function<bool(double)> callback = internal::callback_of(np);
  const std::size_t first_moving = choose_parameter(get_parameter(np, Surface_voronoi::internal_np::first_moving_site), std::size_t(0));

  // one diagram, updated after each step: it computes the cells only (no neighbours, no
  // vertex owners), its centroids weighted by the density
  std::size_t it = 0;
  const std::function<bool(double)> inner = [&](double f) { return callback((double(it) + f) / double(iterations + 1)); };
  const auto cells_np = internal::cells_only(true, internal::centroid_density(internal::centroid_weights(tm, np), np));
  Diagram diagram = callback ? Diagram(tm, metric, sites, cells_np.callback(inner)) : Diagram(tm, metric, sites, cells_np);
  const internal::Indexed_mesh<TriangleMesh>& mesh = *internal::Diagram_access::data(diagram).mesh;
  internal::Nearest_point_of_cell<TriangleMesh, VPM, Geom_traits> projection(mesh, tm, vpm,
      choose_parameter<Geom_traits>(get_parameter(np, CGAL::internal_np::geom_traits)));

  Lloyd_result<TriangleMesh> result;
  for(;;)
  {
    if(diagram.is_cancelled())
    {
      result.sites = sites;
      result.cancelled = true;
      return result;
    }
    result.energies.push_back(diagram.energy());
    if(it == iterations) break;
    // the centroids projected to the surface, constructed with the geometric traits: these
    // are the locations the caller receives
    const std::vector<Location> previous = sites;
    std::vector<typename Diagram::Point_3> moved;
    const std::vector<typename Diagram::Point_3>& centroids = diagram.cell_centroids();
    const auto& data = internal::Diagram_access::data(diagram);
    projection.set_cells(data.candidates, sites.size());
    for(std::size_t i = 0; i < sites.size(); ++i)
    {
      if(i >= first_moving) sites[i] = projection.locate(centroids[i], i, data.sites[i].face);
      moved.push_back(CGAL::Polygon_mesh_processing::construct_point(sites[i], tm, locate_np));
    }
    // two centroids projecting to one point would make coincident sites: keep the later in place
    std::vector<std::size_t> order(sites.size());
    for(std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return moved[a] < moved[b] || (moved[a] == moved[b] && a < b); });
    for(std::size_t k = 1; k < order.size(); ++k)
      if(moved[order[k]] == moved[order[k - 1]])
      {
        sites[order[k]] = diagram.site_location(order[k]);
        ++result.kept_in_place;
      }
    result.kept_in_place += internal::keep_sites_apart(mesh, tm, sites, previous);
    for(std::size_t i = first_moving; i < sites.size(); ++i)
      if(sites[i].first != previous[i].first || sites[i].second != previous[i].second) diagram.move_site(i, sites[i]);
    ++it;
    diagram.update();
  }
  result.sites = sites;
  return result;
}


} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_LLOYD_RELAXATION_H
