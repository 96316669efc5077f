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
// What the construction of a diagram did, and the seconds it took by stage.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_DIAGRAM_STATISTICS_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_DIAGRAM_STATISTICS_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <cstddef>
#include <map>
#include <string>

namespace CGAL {
namespace Surface_voronoi {

/// \ingroup PkgSurfaceVoronoiDiagramRef
/// Counts describing the construction of a `CGAL::Surface_voronoi_diagram` (its timings are
/// in `Stage_times`).
struct Diagram_statistics
{
  /// the number of sites
  std::size_t sites = 0;
  /// the non-empty cells
  std::size_t cells = 0;
  /// the cells without area (a power weight too small, a merged site)
  std::size_t empty_cells = 0;
  /// the sites merged into an earlier site at the same surface point (with
  /// `Coincident_sites::MERGE`; each is also counted in `empty_cells`)
  std::size_t merged_sites = 0;
  /// the connected pieces of all cells, after repair
  std::size_t pieces = 0;
  /// the cells in more than one piece before repair
  std::size_t broken_cells_before_repair = 0;
  /// the cells in more than one piece after repair (0 unless repair was off or ran out of rounds)
  std::size_t broken_cells = 0;
  /// the repair rounds run
  std::size_t repair_rounds = 0;
  /// the (site, face) pairs the repair excluded
  std::size_t banned_fields = 0;
  /// the faces no site reaches
  std::size_t unreached_faces = 0;
  /// the connected components holding unreached faces
  std::size_t unreached_components = 0;
  /// the area no site reaches
  double unreached_area = 0;
  /// the area of the surface
  double surface_area = 0;
  /// the fields offered to a face during propagation
  std::size_t propagation_events = 0;
  /// the fields admitted into a face's candidate list
  std::size_t admitted_fields = 0;
  /// the blocks of faces the first propagation ran in (1: one global order; see the manual's
  /// section on parallel runs)
  std::size_t propagation_blocks = 1;
  /// the rounds in which the blocks exchanged the fields that crossed between them (1 in one
  /// global order)
  std::size_t propagation_rounds = 1;
  /// the mean length of a face's candidate list
  double mean_candidates_per_face = 0;
  /// the longest candidate list
  std::size_t max_candidates_per_face = 0;
  /// the partition vertices welded because they coincide exactly
  std::size_t welded_vertices = 0;
  /// the partition vertices inserted into pieces' edges to avoid T-junctions
  std::size_t inserted_vertices = 0;
};

/// \ingroup PkgSurfaceVoronoiDiagramRef
/// The wall-clock seconds spent in each stage by the calls given a pointer to this object
/// with the named parameter `Surface_voronoi::parameters::stage_times`, added up over them
/// (clear `seconds` to start again); without that parameter nothing is timed. The stages:
/// - of `CGAL::Surface_voronoi_diagram` (its constructor and `update()`): `"setup"` (the
///   mesh, the sites and the metric's values read), `"propagation"` (the candidate sites of
///   each face), `"cutting"` (the faces cut among their candidates, the cells measured) and
///   `"repair"` (cells found in several pieces made whole);
/// - of `CGAL::Biharmonic_embedding`: `"assembly"` (the Laplacian) and `"solve"` (the
///   eigen-solver), which also counts its operator applications in `counts["eigen_operations"]`.
struct Stage_times
{
  /// seconds by stage
  std::map<std::string, double> seconds;
  /// counts of work by name
  std::map<std::string, double> counts;
  /// the seconds of `stage`, 0 if it was not timed
  double operator[](const std::string& stage) const
  {
    const auto it = seconds.find(stage);
    return it == seconds.end() ? 0. : it->second;
  }
};

} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_DIAGRAM_STATISTICS_H
