// Copyright (c) 2026 The Surface_voronoi_diagram authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Options of the diagram. CGAL 5.5's list of named parameters is closed to external
// packages, so package-specific settings live in this plain struct; maps and traits
// (vertex_point_map, edge_is_constrained_map) remain CGAL named parameters.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_OPTIONS_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_OPTIONS_H

#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {

/// \ingroup PkgSurfaceVoronoiDiagramRef
/// How the candidate sites of each face are chosen.
enum class Candidate_selection
{
  /// SurfaceVoronoi's propagation: a site enters a face only from a neighbouring face where
  /// it was admitted (the default; never crosses border edges or breaklines)
  PROPAGATION,
  /// every site that is nearest somewhere in the face, with no propagation and no repair:
  /// the classic restricted Voronoi diagram (RVD), a baseline
  GLOBAL_NEAREST
};

/// \ingroup PkgSurfaceVoronoiDiagramRef
/// Options of `CGAL::Surface_voronoi_diagram`.
struct Diagram_options
{
  /// power weights, one per site in site order, in squared units of the metric (empty: all
  /// zero); see also the named parameter `Surface_voronoi::parameters::site_weight_map`
  std::vector<double> weights;
  /// candidate selection (propagation, or the RVD baseline)
  Candidate_selection candidates = Candidate_selection::PROPAGATION;
  /// check that every cell is one connected region and repair it when not (ignored by
  /// the RVD baseline, which is never repaired)
  bool repair = true;
  /// upper bound on repair rounds; cells still broken afterwards are reported in the statistics
  std::size_t max_repair_rounds = 100;
  /// a site given as a point farther than this from the surface is an error
  double max_site_distance = std::numeric_limits<double>::infinity();
};

/// \ingroup PkgSurfaceVoronoiDiagramRef
/// What the construction did, with the seconds spent per stage.
struct Diagram_statistics
{
  std::size_t sites = 0;
  std::size_t cells = 0;                    ///< non-empty cells
  std::size_t empty_cells = 0;
  std::size_t pieces = 0;                   ///< connected pieces of all cells, after repair
  std::size_t broken_cells_before_repair = 0;
  std::size_t broken_cells = 0;             ///< cells in more than one piece, after repair
  std::size_t repair_rounds = 0;
  std::size_t banned_fields = 0;
  std::size_t unreached_faces = 0;
  std::size_t unreached_components = 0;
  double unreached_area = 0;
  double surface_area = 0;
  std::size_t propagation_events = 0;
  std::size_t admitted_fields = 0;
  double mean_candidates_per_face = 0;
  std::size_t max_candidates_per_face = 0;
  std::size_t welded_vertices = 0;
  std::size_t inserted_vertices = 0;
  double setup_seconds = 0;                 ///< mesh copy, checks, site location, metric read-out
  double propagation_seconds = 0;
  double cutting_seconds = 0;
  double repair_seconds = 0;                ///< connectivity check, repair rounds and per-site summary
};

} // namespace Surface_voronoi
} // namespace CGAL

#endif
