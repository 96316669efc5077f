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
// The package's named parameters. They use CGAL's own mechanism (a tag in `internal_np` and
// a `Named_function_parameters` chain), so they mix with CGAL's parameters:
// `Surface_voronoi::parameters::embedding_dimension(20).vertex_point_map(vpm)`, or, to append
// a package parameter to a chain that starts with CGAL's,
// `Surface_voronoi::parameters::embedding_dimension(20, CGAL::parameters::vertex_point_map(vpm))`.
// What each parameter means is documented with the functions and classes that read it.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_PARAMETERS_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_PARAMETERS_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Named_function_parameters.h>

#include <cstddef>

namespace CGAL {
namespace Surface_voronoi {

/// \ingroup PkgSurfaceVoronoiDiagramRef
/// How the candidate sites of each face are chosen (named parameter `candidate_selection`).
enum class Candidate_selection
{
  /// SurfaceVoronoi's propagation: a site enters a face only from a neighbouring face where
  /// it was admitted (the default; never crosses border edges or breaklines)
  PROPAGATION,
  /// every site that is nearest somewhere in the face, with no propagation and no repair:
  /// the classic restricted Voronoi diagram (RVD), a baseline for embedding metrics
  GLOBAL_NEAREST
};

/// \ingroup PkgSurfaceVoronoiDiagramRef
/// What the diagram does with two sites at the same surface point (named parameter
/// `coincident_sites`).
enum class Coincident_sites
{
  /// the diagram's constructor throws `Coincident_sites_error` naming both, in every build
  /// (`validate_input()` lists every such pair); the default
  REJECT,
  /// the later site is merged into the earlier one: it keeps its index but owns no area,
  /// `Surface_voronoi_diagram::merged_into()` names the site that owns its cell, and
  /// `Diagram_statistics::merged_sites` counts the merged sites
  MERGE
};

namespace internal_np {
enum site_weight_map_t { site_weight_map };
enum candidate_selection_t { candidate_selection };
enum repair_cells_t { repair_cells };
enum max_repair_rounds_t { max_repair_rounds };
enum max_site_distance_t { max_site_distance };
enum coincident_sites_t { coincident_sites };
enum embedding_dimension_t { embedding_dimension };
enum eigen_tolerance_t { eigen_tolerance };
enum max_eigen_solver_restarts_t { max_eigen_solver_restarts };
enum refinement_trigger_ratio_t { refinement_trigger_ratio };
enum refinement_edge_length_ratio_t { refinement_edge_length_ratio };
enum refinement_max_vertices_t { refinement_max_vertices };
enum refinement_local_spacing_t { refinement_local_spacing };
enum stop_on_coarse_mesh_t { stop_on_coarse_mesh };
enum input_face_map_t { input_face_map };
enum stage_times_t { stage_times };
enum cells_only_t { cells_only };
enum prepared_mesh_t { prepared_mesh };
enum checked_mesh_topology_t { checked_mesh_topology };
enum first_moving_site_t { first_moving_site };
enum maximum_number_of_added_sites_t { maximum_number_of_added_sites };
enum vertex_density_map_t { vertex_density_map };
enum max_density_ratio_t { max_density_ratio };
enum centroid_density_t { centroid_density };
enum sample_border_t { sample_border };
enum corner_angle_t { corner_angle };
enum placed_sites_t { placed_sites };
enum maximum_column_memory_t { maximum_column_memory };
} // namespace internal_np

namespace parameters {

#define CGAL_SURFACE_VORONOI_NAMED_PARAMETER(NAME)                                                               \
  template <class T>                                                                                             \
  CGAL::Named_function_parameters<T, internal_np::NAME##_t> NAME(const T& value)                                 \
  {                                                                                                              \
    return CGAL::Named_function_parameters<T, internal_np::NAME##_t>(value);                                    \
  }                                                                                                              \
  template <class T, class NP_T, class NP_Tag, class NP_Base>                                                    \
  CGAL::Named_function_parameters<T, internal_np::NAME##_t, CGAL::Named_function_parameters<NP_T, NP_Tag, NP_Base> > \
  NAME(const T& value, const CGAL::Named_function_parameters<NP_T, NP_Tag, NP_Base>& chain)                     \
  {                                                                                                              \
    return CGAL::Named_function_parameters<T, internal_np::NAME##_t,                                            \
                                           CGAL::Named_function_parameters<NP_T, NP_Tag, NP_Base> >(value, chain); \
  }

#ifdef DOXYGEN_RUNNING
/// \addtogroup PkgSurfaceVoronoiDiagramNamedParameters
/// @{

/// A chain of named parameters holding `value` as `site_weight_map`: the power weights of the
/// sites, as a readable property map whose key is the sites' type or `std::size_t` (the site
/// index) and whose value converts to `double`; read by `CGAL::Surface_voronoi_diagram`,
/// `lloyd_relaxation()` and `validate_input()`.
template <class T>
unspecified_type site_weight_map(const T& value);
/// The chain `chain` with `site_weight_map(value)` added to it.
template <class T, class NamedParameters>
unspecified_type site_weight_map(const T& value, const NamedParameters& chain);

/// A chain of named parameters holding `value` as `candidate_selection`: the
/// `Candidate_selection` of `CGAL::Surface_voronoi_diagram`: propagation, or every globally
/// nearest site (the restricted Voronoi diagram).
template <class T>
unspecified_type candidate_selection(const T& value);
/// The chain `chain` with `candidate_selection(value)` added to it.
template <class T, class NamedParameters>
unspecified_type candidate_selection(const T& value, const NamedParameters& chain);

/// A chain of named parameters holding `value` as `repair_cells`: whether
/// `CGAL::Surface_voronoi_diagram` repairs cells found in several pieces (`bool`).
template <class T>
unspecified_type repair_cells(const T& value);
/// The chain `chain` with `repair_cells(value)` added to it.
template <class T, class NamedParameters>
unspecified_type repair_cells(const T& value, const NamedParameters& chain);

/// A chain of named parameters holding `value` as `max_repair_rounds`: the most repair rounds
/// of `CGAL::Surface_voronoi_diagram` (`std::size_t`, less than 65535).
template <class T>
unspecified_type max_repair_rounds(const T& value);
/// The chain `chain` with `max_repair_rounds(value)` added to it.
template <class T, class NamedParameters>
unspecified_type max_repair_rounds(const T& value, const NamedParameters& chain);

/// A chain of named parameters holding `value` as `max_site_distance`: the farthest a site
/// given as a point may be from the surface (`double`), for `CGAL::Surface_voronoi_diagram` and
/// `validate_input()`.
template <class T>
unspecified_type max_site_distance(const T& value);
/// The chain `chain` with `max_site_distance(value)` added to it.
template <class T, class NamedParameters>
unspecified_type max_site_distance(const T& value, const NamedParameters& chain);

/// A chain of named parameters holding `value` as `coincident_sites`: the `Coincident_sites`
/// policy of `CGAL::Surface_voronoi_diagram` and `validate_input()`.
template <class T>
unspecified_type coincident_sites(const T& value);
/// The chain `chain` with `coincident_sites(value)` added to it.
template <class T, class NamedParameters>
unspecified_type coincident_sites(const T& value, const NamedParameters& chain);

/// A chain of named parameters holding `value` as `embedding_dimension`: the dimension `d` of
/// `CGAL::Biharmonic_embedding` (`std::size_t`).
template <class T>
unspecified_type embedding_dimension(const T& value);
/// The chain `chain` with `embedding_dimension(value)` added to it.
template <class T, class NamedParameters>
unspecified_type embedding_dimension(const T& value, const NamedParameters& chain);

/// A chain of named parameters holding `value` as `eigen_tolerance`: the relative tolerance of
/// the eigen-solver of `CGAL::Biharmonic_embedding` (`double`).
template <class T>
unspecified_type eigen_tolerance(const T& value);
/// The chain `chain` with `eigen_tolerance(value)` added to it.
template <class T, class NamedParameters>
unspecified_type eigen_tolerance(const T& value, const NamedParameters& chain);

/// A chain of named parameters holding `value` as `max_eigen_solver_restarts`: the most
/// restarts of the eigen-solver of `CGAL::Biharmonic_embedding` (`std::size_t`).
template <class T>
unspecified_type max_eigen_solver_restarts(const T& value);
/// The chain `chain` with `max_eigen_solver_restarts(value)` added to it.
template <class T, class NamedParameters>
unspecified_type max_eigen_solver_restarts(const T& value, const NamedParameters& chain);

/// A chain of named parameters holding `value` as `refinement_trigger_ratio`: the length,
/// relative to the site spacing, above which `refine_for_sites()` splits edges (`double`).
template <class T>
unspecified_type refinement_trigger_ratio(const T& value);
/// The chain `chain` with `refinement_trigger_ratio(value)` added to it.
template <class T, class NamedParameters>
unspecified_type refinement_trigger_ratio(const T& value, const NamedParameters& chain);

/// A chain of named parameters holding `value` as `refinement_edge_length_ratio`: the length,
/// relative to the site spacing, down to which `refine_for_sites()` splits edges (`double`).
template <class T>
unspecified_type refinement_edge_length_ratio(const T& value);
/// The chain `chain` with `refinement_edge_length_ratio(value)` added to it.
template <class T, class NamedParameters>
unspecified_type refinement_edge_length_ratio(const T& value, const NamedParameters& chain);

/// A chain of named parameters holding `value` as `refinement_max_vertices`: the largest number
/// of vertices `refine_for_sites()` may make (`std::size_t`).
template <class T>
unspecified_type refinement_max_vertices(const T& value);
/// The chain `chain` with `refinement_max_vertices(value)` added to it.
template <class T, class NamedParameters>
unspecified_type refinement_max_vertices(const T& value, const NamedParameters& chain);

/// A chain of named parameters holding `value` as `refinement_local_spacing`: whether
/// `refine_for_sites()` measures the site spacing near each edge instead of on average (`bool`).
template <class T>
unspecified_type refinement_local_spacing(const T& value);
/// The chain `chain` with `refinement_local_spacing(value)` added to it.
template <class T, class NamedParameters>
unspecified_type refinement_local_spacing(const T& value, const NamedParameters& chain);

/// A chain of named parameters holding `value` as `stop_on_coarse_mesh`: whether
/// `add_sites_for_valid_dual()` returns as soon as the sites it added crowd closer than the
/// mesh resolves, for the caller to refine the mesh (`bool`).
template <class T>
unspecified_type stop_on_coarse_mesh(const T& value);
/// The chain `chain` with `stop_on_coarse_mesh(value)` added to it.
template <class T, class NamedParameters>
unspecified_type stop_on_coarse_mesh(const T& value, const NamedParameters& chain);

/// A chain of named parameters holding `value` as `input_face_map`: a writable property map
/// from output faces to input faces, filled by `make_arrangement()` and `refine_for_sites()`.
template <class T>
unspecified_type input_face_map(const T& value);
/// The chain `chain` with `input_face_map(value)` added to it.
template <class T, class NamedParameters>
unspecified_type input_face_map(const T& value, const NamedParameters& chain);

/// A chain of named parameters holding `value` as `maximum_number_of_added_sites`: how many
/// sites `add_sites_for_valid_dual()` may add at most (`std::size_t`).
template <class T>
unspecified_type maximum_number_of_added_sites(const T& value);
/// The chain `chain` with `maximum_number_of_added_sites(value)` added to it.
template <class T, class NamedParameters>
unspecified_type maximum_number_of_added_sites(const T& value, const NamedParameters& chain);

/// A chain of named parameters holding `value` as `vertex_density_map`: the wanted number of
/// sites per unit area, up to a constant factor, at each vertex of the mesh, as a readable
/// property map whose key is the vertex descriptor and whose value converts to `double`
/// (finite, not negative, not zero on every face; interpolated linearly across faces); read
/// by `random_sites()`, `blue_noise_sites()` and `lloyd_relaxation()`.
template <class T>
unspecified_type vertex_density_map(const T& value);
/// The chain `chain` with `vertex_density_map(value)` added to it.
template <class T, class NamedParameters>
unspecified_type vertex_density_map(const T& value, const NamedParameters& chain);

/// A chain of named parameters holding `value` as `max_density_ratio`: the largest density
/// `curvature_density()` writes, the smallest being 1 (`double`, at least 1).
template <class T>
unspecified_type max_density_ratio(const T& value);
/// The chain `chain` with `max_density_ratio(value)` added to it.
template <class T, class NamedParameters>
unspecified_type max_density_ratio(const T& value, const NamedParameters& chain);

/// A chain of named parameters holding `value` as `placed_sites`: sites already placed that
/// `blue_noise_sites()` keeps its new sites away from (a `std::vector` of face locations).
template <class T>
unspecified_type placed_sites(const T& value);
/// The chain `chain` with `placed_sites(value)` added to it.
template <class T, class NamedParameters>
unspecified_type placed_sites(const T& value, const NamedParameters& chain);

/// A chain of named parameters holding `value` as `first_moving_site`: the index of the first
/// site `lloyd_relaxation()` moves, the ones before it staying in place (`std::size_t`).
template <class T>
unspecified_type first_moving_site(const T& value);
/// The chain `chain` with `first_moving_site(value)` added to it.
template <class T, class NamedParameters>
unspecified_type first_moving_site(const T& value, const NamedParameters& chain);

/// A chain of named parameters holding `value` as `sample_border`: whether
/// `feature_line_sites()` counts the border edges of the mesh among its feature lines (`bool`).
template <class T>
unspecified_type sample_border(const T& value);
/// The chain `chain` with `sample_border(value)` added to it.
template <class T, class NamedParameters>
unspecified_type sample_border(const T& value, const NamedParameters& chain);

/// A chain of named parameters holding `value` as `corner_angle`: the turn, in degrees, above
/// which `feature_line_sites()` takes a vertex inside a feature line for a corner (`double`).
template <class T>
unspecified_type corner_angle(const T& value);
/// The chain `chain` with `corner_angle(value)` added to it.
template <class T, class NamedParameters>
unspecified_type corner_angle(const T& value, const NamedParameters& chain);

/// A chain of named parameters holding `value` as `maximum_column_memory`: the most bytes the
/// columns of `Biharmonic_green_metric` may take for one set of sites (`double`).
template <class T>
unspecified_type maximum_column_memory(const T& value);
/// The chain `chain` with `maximum_column_memory(value)` added to it.
template <class T, class NamedParameters>
unspecified_type maximum_column_memory(const T& value, const NamedParameters& chain);

/// A chain of named parameters holding `value` as `prepared_mesh`: a `Prepared_mesh` of the
/// mesh, shared by `validate_input()`, the metrics and `CGAL::Surface_voronoi_diagram` (and
/// the diagrams of `lloyd_relaxation()`) instead of each preparing its own.
template <class T>
unspecified_type prepared_mesh(const T& value);
/// The chain `chain` with `prepared_mesh(value)` added to it.
template <class T, class NamedParameters>
unspecified_type prepared_mesh(const T& value, const NamedParameters& chain);

/// A chain of named parameters holding `value` as `checked_mesh_topology`: whether the caller
/// has checked what `Prepared_mesh` then skips (`bool`); read by the constructor of `Prepared_mesh`.
template <class T>
unspecified_type checked_mesh_topology(const T& value);
/// The chain `chain` with `checked_mesh_topology(value)` added to it.
template <class T, class NamedParameters>
unspecified_type checked_mesh_topology(const T& value, const NamedParameters& chain);

/// A chain of named parameters holding `value` as `stage_times`: a pointer to a `Stage_times`
/// that `CGAL::Surface_voronoi_diagram` and `CGAL::Biharmonic_embedding` add the seconds of
/// their stages to.
template <class T>
unspecified_type stage_times(const T& value);
/// The chain `chain` with `stage_times(value)` added to it.
template <class T, class NamedParameters>
unspecified_type stage_times(const T& value, const NamedParameters& chain);

/// @}
#else
CGAL_SURFACE_VORONOI_NAMED_PARAMETER(site_weight_map)
CGAL_SURFACE_VORONOI_NAMED_PARAMETER(candidate_selection)
CGAL_SURFACE_VORONOI_NAMED_PARAMETER(repair_cells)
CGAL_SURFACE_VORONOI_NAMED_PARAMETER(max_repair_rounds)
CGAL_SURFACE_VORONOI_NAMED_PARAMETER(max_site_distance)
CGAL_SURFACE_VORONOI_NAMED_PARAMETER(coincident_sites)
CGAL_SURFACE_VORONOI_NAMED_PARAMETER(embedding_dimension)
CGAL_SURFACE_VORONOI_NAMED_PARAMETER(eigen_tolerance)
CGAL_SURFACE_VORONOI_NAMED_PARAMETER(max_eigen_solver_restarts)
CGAL_SURFACE_VORONOI_NAMED_PARAMETER(refinement_trigger_ratio)
CGAL_SURFACE_VORONOI_NAMED_PARAMETER(refinement_edge_length_ratio)
CGAL_SURFACE_VORONOI_NAMED_PARAMETER(refinement_max_vertices)
CGAL_SURFACE_VORONOI_NAMED_PARAMETER(refinement_local_spacing)
CGAL_SURFACE_VORONOI_NAMED_PARAMETER(stop_on_coarse_mesh)
CGAL_SURFACE_VORONOI_NAMED_PARAMETER(input_face_map)
CGAL_SURFACE_VORONOI_NAMED_PARAMETER(maximum_number_of_added_sites)
CGAL_SURFACE_VORONOI_NAMED_PARAMETER(vertex_density_map)
CGAL_SURFACE_VORONOI_NAMED_PARAMETER(max_density_ratio)
CGAL_SURFACE_VORONOI_NAMED_PARAMETER(sample_border)
CGAL_SURFACE_VORONOI_NAMED_PARAMETER(corner_angle)
CGAL_SURFACE_VORONOI_NAMED_PARAMETER(placed_sites)
CGAL_SURFACE_VORONOI_NAMED_PARAMETER(maximum_column_memory)
CGAL_SURFACE_VORONOI_NAMED_PARAMETER(prepared_mesh)
CGAL_SURFACE_VORONOI_NAMED_PARAMETER(checked_mesh_topology)
CGAL_SURFACE_VORONOI_NAMED_PARAMETER(stage_times)
// lloyd_relaxation() keeps the sites before this index in place (the sites on feature lines,
// placed first; add_sites_for_valid_dual() relaxes only the sites it added).
CGAL_SURFACE_VORONOI_NAMED_PARAMETER(first_moving_site)
#endif

} // namespace parameters

namespace internal {
// Named parameters of lloyd_relaxation()'s diagrams, not API: the cells only, with their
// centroids weighted by a density (a std::shared_ptr to a std::vector<double> by vertex index).
CGAL_SURFACE_VORONOI_NAMED_PARAMETER(cells_only)
CGAL_SURFACE_VORONOI_NAMED_PARAMETER(centroid_density)
} // namespace internal

#undef CGAL_SURFACE_VORONOI_NAMED_PARAMETER

} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_PARAMETERS_H
