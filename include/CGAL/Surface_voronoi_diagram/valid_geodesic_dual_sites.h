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
// Sites added until the dual is valid, with the geodesic metric on refined copies of the
// mesh: the metric knows distances at vertices only, so where the added sites crowd (a thin
// bar that several rings of sites must go around) the mesh is refined for them before more
// are added. Without this, the sites added on a bar meshed with long needles only piled up.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_VALID_GEODESIC_DUAL_SITES_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_VALID_GEODESIC_DUAL_SITES_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/Geodesic_metric.h>
#include <CGAL/Surface_voronoi_diagram/parameters.h>
#include <CGAL/Surface_voronoi_diagram/refinement.h>
#include <CGAL/Surface_voronoi_diagram/valid_dual_sites.h>
#include <CGAL/Surface_voronoi_diagram/internal/Double_kernel.h>

#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

// A point of (or on the border of) face f of tm, as a location of f (clamped and normalized,
// so that rounding does not step outside the face).
template <class TriangleMesh, class VertexPointMap>
CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double>
location_in_input_face(const TriangleMesh& tm, const VertexPointMap& vpm,
                       typename boost::graph_traits<TriangleMesh>::face_descriptor f, const Point_d& p)
{
  const auto dvpm = make_double_point_map(vpm);
  const auto h = halfedge(f, tm);
  // corners in the order of Face_location's coordinates: source(h), target(h), target(next(h))
  return { f, clamped_barycentric(barycentric_coordinates(get(dvpm, source(h, tm)), get(dvpm, target(h, tm)),
                                                         get(dvpm, target(next(h, tm), tm)), p)) };
}

// The diagram's parameters that mean the same on a refined copy: those keyed by site index
// (`site_weight_map`) and the candidate selection; the maps keyed by `tm`'s elements do not.
template <class NamedParameters, class Function>
auto with_site_parameters(const NamedParameters& np, const Function& f)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const auto chain = parameters::candidate_selection(
      choose_parameter(get_parameter(np, internal_np::candidate_selection), Candidate_selection::PROPAGATION),
      CGAL::parameters::number_of_iterations(choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), std::size_t(3))));
  if constexpr(CGAL::parameters::is_default_parameter<NamedParameters, internal_np::site_weight_map_t>::value)
    return f(chain);
  else
    return f(parameters::site_weight_map(get_parameter(np, internal_np::site_weight_map), chain));
}
} // namespace internal

/// \ingroup PkgSurfaceVoronoiDiagramSites
/// Adds sites until the dual triangulation of the geodesic diagram (`Geodesic_metric`) is a
/// valid mesh of the surface, as `add_sites_for_valid_dual()` does, on copies of `tm` refined
/// for the sites.
///
/// Each pass refines `tm` for the sites so far (`refine_for_sites()` with
/// `refinement_local_spacing`), builds the metric on the copy (on `tm` itself when no edge
/// needs splitting) and adds sites there (`add_sites_for_valid_dual()` with
/// `stop_on_coarse_mesh`). A pass ends where the added sites crowd closer than its mesh
/// resolves, and the next one refines there. The passes end with one that adds no site (its
/// dual valid, or the budget spent, or no site to add), so that the validity returned is that
/// of the diagram on `refine_for_sites()` of `tm` for the returned sites with
/// `refinement_local_spacing`: the mesh to build the final diagram on. After 24 passes that
/// all added sites, the validity is that of the last one's mesh.
/// Sites are returned as locations of `tm`, the given ones first and unmoved.
///
/// \tparam ConcurrencyTag the concurrency tag of the diagrams built; default `CGAL::Sequential_tag`
/// \tparam TriangleMesh a model of `MutableFaceGraph` whose faces are triangles (the refined
///         copies are of this type)
/// \param tm the mesh
/// \param sites the given sites
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{maximum_number_of_added_sites}
///     \cgalParamDescription{how many sites may be added at most, over all passes}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{a quarter of the given sites, and at least 64}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_iterations}
///     \cgalParamDescription{the Lloyd steps of the added sites after each round}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{3}
///   \cgalParamNEnd
///   \cgalParamNBegin{Surface_voronoi::parameters::refinement_max_vertices}
///     \cgalParamDescription{the most vertices a refined copy may have; a pass whose refinement
///       reaches it ends the passes}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{20,000,000}
///   \cgalParamNEnd
///   \cgalParamNBegin{Surface_voronoi::parameters::candidate_selection}
///     \cgalParamDescription{the diagrams' candidate selection}
///     \cgalParamType{`Surface_voronoi::Candidate_selection`}
///     \cgalParamDefault{`Candidate_selection::PROPAGATION`}
///   \cgalParamNEnd
///   \cgalParamNBegin{Surface_voronoi::parameters::site_weight_map}
///     \cgalParamDescription{the sites' power weights, by site index (covering the indices of
///       the sites that may be added, which weigh what the map gives them)}
///     \cgalParamType{a model of `ReadablePropertyMap` from `std::size_t` to `double`}
///     \cgalParamDefault{no weights}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
///     \cgalParamType{a model of `ReadablePropertyMap`}
///     \cgalParamDefault{`get_const_property_map(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the sites (on `tm`), how many were added, and the validity of the last pass's dual
/// \pre the preconditions of the diagram's constructor hold for `sites`
template <class ConcurrencyTag = CGAL::Sequential_tag, class TriangleMesh, typename CGAL_NP_TEMPLATE_PARAMETERS>
Valid_dual_result<TriangleMesh>
add_sites_for_valid_geodesic_dual(const TriangleMesh& tm,
                                  const std::vector<CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double> >& sites,
                                  const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;

  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm));
  const std::size_t max_added = choose_parameter(get_parameter(np, internal_np::maximum_number_of_added_sites),
                                                 default_maximum_number_of_added_sites(sites.size()));
  const std::size_t max_vertices = choose_parameter(get_parameter(np, internal_np::refinement_max_vertices), std::size_t(20000000));
  // a pass adds at least one site, or ends the loop; those ended by crowding are few
  const int max_passes = 24;

  Valid_dual_result<TriangleMesh> r;
  r.sites = sites;
  // Each pass refines for all the sites so far; the loop ends with a pass that adds none, so
  // that its mesh is the final diagram's and its validity the one reported.
  for(int pass = 0; pass < max_passes; ++pass)
  {
    TriangleMesh refined;
    auto input_face = get(CGAL::dynamic_face_property_t<face_descriptor>(), refined);
    const Refined_sites<TriangleMesh> refinement = refine_for_sites(tm, r.sites, refined,
        parameters::refinement_max_vertices(max_vertices, parameters::refinement_local_spacing(true, CGAL::parameters::vertex_point_map(vpm))),
        parameters::input_face_map(input_face));
    if(refinement.vertex_limit_reached) break;
    const std::size_t before = r.sites_added;
    const bool on_input = (refinement.edges_split == 0);   // the mesh resolves the sites as it is
    // on the input mesh as it is, or on the refined one
    auto add_sites = [&](const TriangleMesh& mesh, const auto& mesh_vpm, const auto& mesh_sites) {
      Geodesic_metric<TriangleMesh> metric(mesh, CGAL::parameters::vertex_point_map(mesh_vpm));
      return internal::with_site_parameters(np, [&](const auto& chain) {
        return add_sites_for_valid_dual<ConcurrencyTag>(mesh, metric, mesh_sites,
                   parameters::maximum_number_of_added_sites(max_added - before, parameters::stop_on_coarse_mesh(true, chain.vertex_point_map(mesh_vpm))));
      });
    };
    const Valid_dual_result<TriangleMesh> here = on_input ? add_sites(tm, vpm, r.sites)
                                                          : add_sites(refined, get_const_property_map(CGAL::vertex_point, refined), refinement.sites);
    r.validity = here.validity;
    r.rounds += here.rounds;
    r.nothing_to_cut = here.nothing_to_cut;
    r.no_room_for_sites = here.no_room_for_sites;
    r.mesh_too_coarse = here.mesh_too_coarse;
    if(here.sites_added == 0) break;
    // the sites, back on tm: the given ones as they were, the added ones in the input faces
    // their refined faces lie in
    if(on_input)
      r.sites = here.sites;
    else
    {
      const auto rvpm = internal::make_double_point_map(get_const_property_map(CGAL::vertex_point, refined));
      for(std::size_t i = r.sites.size(); i < here.sites.size(); ++i)
      {
        const auto& l = here.sites[i];
        const internal::Point_d p = CGAL::Polygon_mesh_processing::construct_point(
            l, refined, CGAL::parameters::vertex_point_map(rvpm).geom_traits(internal::Double_kernel()));
        r.sites.push_back(internal::location_in_input_face(tm, vpm, get(input_face, l.first), p));
      }
    }
    r.sites_added = before + here.sites_added;
  }
  return r;
}

} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_VALID_GEODESIC_DUAL_SITES_H
