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
// Validation of a diagram's input, for callers that want every problem named instead of the
// constructor's first exception: the command-line program calls it before anything else.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_VALIDATE_INPUT_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_VALIDATE_INPUT_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/parameters.h>
#include <CGAL/Surface_voronoi_diagram/Prepared_mesh.h>
#include <CGAL/Surface_voronoi_diagram/internal/Indexed_mesh.h>
#include <CGAL/Surface_voronoi_diagram/internal/Input_validation.h>
#include <CGAL/Surface_voronoi_diagram/internal/Site_locator.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {

/// \ingroup PkgSurfaceVoronoiDiagramRef
/// Checks the input of a `CGAL::Surface_voronoi_diagram` (the mesh, the sites and the named
/// parameters that concern them) and returns what is wrong, at most ten problems of each
/// kind, in the order of the mesh's elements and the sites; an empty result means that the
/// diagram's constructor will neither throw `Input_error` nor fail a precondition for this
/// input. The constructor stops at the first problem it meets (and checks the halfedge
/// structure in debug builds only); this function checks everything in every build and lists
/// every problem: call it on input that may be invalid (the `surface_voronoi` program calls it
/// before anything else).
///
/// Among the mesh's problems: a face whose area is below \f$ 2^{-44} \f$ (about 5.7e-14)
/// times its squared longest edge is degenerate (`Input_problem::ZERO_AREA_FACE`, its message
/// says "degenerate"; a thin needle or cap above that threshold is valid, never refused by an
/// exact zero-area test); a vertex with a coordinate beyond \f$ 2^{200} \f$ (about 1.6e60) in
/// magnitude is out of range (`Input_problem::COORDINATE_OUT_OF_RANGE`), and so is a face
/// whose longest edge is below \f$ 2^{-200} \f$ (`Input_problem::ZERO_AREA_FACE`, "too
/// small"): within that range the squares and squared areas the diagram computes neither
/// overflow nor underflow. Scale such a mesh by a power of two (exact) first.
///
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \tparam SiteRange a range of `vertex_descriptor`, `Polygon_mesh_processing::Face_location`
///         or points, as for the diagram
/// \param tm the mesh
/// \param sites the sites
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
///     \cgalParamType{a model of `ReadablePropertyMap`}
///     \cgalParamDefault{`get_const_property_map(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{Surface_voronoi::parameters::prepared_mesh}
///     \cgalParamDescription{the mesh prepared once, shared with the other calls given it; those
///       that follow do not check it again if it is found valid}
///     \cgalParamType{`Prepared_mesh<TriangleMesh, C>`, `C` any concurrency tag}
///     \cgalParamDefault{the mesh prepared by this call}
///   \cgalParamNEnd
///   \cgalParamNBegin{Surface_voronoi::parameters::site_weight_map}
///     \cgalParamDescription{the power weights, as for the diagram: their values must be finite}
///     \cgalParamType{a model of `ReadablePropertyMap`}
///     \cgalParamDefault{no weights}
///   \cgalParamNEnd
///   \cgalParamNBegin{Surface_voronoi::parameters::max_site_distance}
///     \cgalParamDescription{sites given as points farther than this from the surface are reported}
///     \cgalParamType{`double`}
///     \cgalParamDefault{infinity}
///   \cgalParamNEnd
///   \cgalParamNBegin{Surface_voronoi::parameters::coincident_sites}
///     \cgalParamDescription{with `Coincident_sites::MERGE`, sites at the same surface point are not a problem}
///     \cgalParamType{`Coincident_sites`}
///     \cgalParamDefault{`Coincident_sites::REJECT`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the problems found, empty if there are none
template <class TriangleMesh, class SiteRange, class NamedParameters = CGAL::parameters::Default_named_parameters>
std::vector<Input_problem> validate_input(const TriangleMesh& tm, const SiteRange& sites,
                                          const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  std::vector<Input_problem> problems;
  internal::Problem_list list(problems, 10);
  const auto prepared = internal::prepared_mesh_of<TriangleMesh>(np);
  const std::shared_ptr<const internal::Indexed_mesh<TriangleMesh> >& given = prepared.indexed_mesh();
  const bool topology_checked = prepared.topology_checked() && given->source_mesh == &tm;
  if(!topology_checked && !CGAL::is_valid_polygon_mesh(tm))
  {
    list.add(Input_problem::INVALID_MESH, 0, "the mesh is not a valid polygon mesh (its halfedges are inconsistent)");
    return problems;
  }
  if(faces(tm).empty())
  {
    list.add(Input_problem::EMPTY_MESH, 0, "the mesh is empty (no faces)");
    return problems;
  }
  if(!topology_checked && !internal::find_non_triangles(tm, list)) return problems;
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, tm));
  const std::shared_ptr<const internal::Indexed_mesh<TriangleMesh> > indexed = internal::shared_or_new_indexed_mesh(given, tm, vpm);
  const internal::Indexed_mesh<TriangleMesh>& mesh = *indexed;
  const std::size_t before = problems.size();
  internal::find_mesh_problems(mesh, list, !topology_checked);
  if(problems.size() == before)   // a diagram on the same copy does not check it again
    mesh.checked.raise(topology_checked ? internal::Mesh_check_level::WITHOUT_FANS : internal::Mesh_check_level::WITH_FANS);

  const double max_distance = choose_parameter(get_parameter(np, internal_np::max_site_distance),
                                               std::numeric_limits<double>::infinity());
  const internal::Site_locator<TriangleMesh> locator(tm, mesh, max_distance);
  std::vector<internal::Site> located;
  std::vector<std::size_t> located_index;
  std::size_t index = 0;
  for(const auto& s : sites)
  {
    internal::Site site;
    const std::string error = locator.try_locate(s, index, site);
    if(error.empty())
    {
      located.push_back(site);
      located_index.push_back(index);
    }
    else
      list.add(locator.last_was_too_far() ? Input_problem::SITE_TOO_FAR : Input_problem::SITE_NOT_ON_MESH, index, error);
    ++index;
  }
  if(index == 0)
    list.add(Input_problem::NO_SITES, 0, "there are no sites");
  internal::check_weights(sites, np, list);
  const Coincident_sites policy = choose_parameter(get_parameter(np, internal_np::coincident_sites), Coincident_sites::REJECT);
  if(policy == Coincident_sites::REJECT)
    for(const auto& pair : internal::find_coincident_sites(mesh, located))
      list.add(Input_problem::COINCIDENT_SITES, located_index[pair.first],
               "sites " + std::to_string(located_index[pair.first]) + " and " + std::to_string(located_index[pair.second])
               + " are at the same surface point", located_index[pair.second]);
  return problems;
}

} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_VALIDATE_INPUT_H
