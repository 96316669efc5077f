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
// Everything a diagram holds once computed. The public class owns one of these and answers
// queries from it; the outputs read it through `Diagram_access`.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_DIAGRAM_DATA_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_DIAGRAM_DATA_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/Diagram_statistics.h>
#include <CGAL/Surface_voronoi_diagram/internal/Breaklines.h>
#include <CGAL/Surface_voronoi_diagram/internal/Candidate_table.h>
#include <CGAL/Surface_voronoi_diagram/internal/Cell_connectivity.h>
#include <CGAL/Surface_voronoi_diagram/internal/Cut_cell_measures.h>
#include <CGAL/Surface_voronoi_diagram/internal/Face_cuts.h>
#include <CGAL/Surface_voronoi_diagram/internal/Indexed_mesh.h>
#include <CGAL/Surface_voronoi_diagram/internal/Partition.h>
#include <CGAL/Surface_voronoi_diagram/internal/Site.h>
#include <CGAL/Surface_voronoi_diagram/internal/Site_fields.h>

#include <algorithm>
#include <memory>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

template <class TriangleMesh>
struct Diagram_data
{
  std::shared_ptr<const Indexed_mesh<TriangleMesh> > mesh;
  Breaklines breaklines;
  std::vector<Site> sites;
  std::vector<std::size_t> merged_into;          // by site: the site owning its cell, or no_site
  std::vector<std::pair<std::size_t, std::size_t> > breakline_site_faces;   // (site, face): where sites on breaklines start
  std::unique_ptr<Embedding_values> embedding;   // embedding metrics only
  Candidate_table candidates;                    // after propagation and repair
  Partition partition;                           // empty when the cells were measured on the cuts
  Face_cuts cuts;                                // for the updates: the cuts the partition was stitched from,
  Banned_fields banned;                          // and the repair's bans
  std::size_t recut_faces = 0;                   // faces cut again by updates since `cuts` was reset
  Cell_measures measures;                        // Lloyd's diagrams: the cells measured on the cuts
  std::shared_ptr<const std::vector<double> > centroid_density;   // Lloyd's: by vertex, or null
  std::vector<double> cell_area;
  std::vector<std::size_t> cell_pieces;
  std::vector<std::size_t> vertex_site;          // owner of each mesh vertex
  Diagram_statistics statistics;
  bool cancelled = false;

  /// forgets the cells (a cancelled construction holds none)
  void clear_cells()
  {
    candidates.clear();
    partition = Partition();
    cuts = Face_cuts();
    banned = Banned_fields();
    measures = Cell_measures();
    cell_area.assign(sites.size(), 0.);
    cell_pieces.assign(sites.size(), 0);
    vertex_site.assign(mesh ? mesh->number_of_vertices() : 0, no_site);
    statistics = Diagram_statistics();
    statistics.sites = sites.size();
    statistics.merged_sites = number_of_merged_sites();
  }

  std::size_t number_of_merged_sites() const
  {
    return std::size_t(std::count_if(merged_into.begin(), merged_into.end(), [](std::size_t s) { return s != no_site; }));
  }
};

/// The outputs' way into a diagram (`make_arrangement()`, `dual_triangulation()`, `draw()`),
/// so that the public class exposes no internal type.
struct Diagram_access
{
  template <class Diagram>
  static const auto& data(const Diagram& diagram) { return diagram.m_data; }
};

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_DIAGRAM_DATA_H
