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
// "One site, one region": the connectivity check and repair. Propagation keeps far-away
// islands out but does not by itself make every cell connected (a site admitted in a face
// where it wins nothing can still win beyond it), so each round finds the cells in several
// pieces, bans each orphan piece's site from the piece's face, and re-runs the propagation
// locally from the banned faces' neighbours.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_CELL_REPAIR_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_CELL_REPAIR_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/internal/Cell_components.h>
#include <CGAL/Surface_voronoi_diagram/internal/Partition.h>
#include <CGAL/Surface_voronoi_diagram/internal/Site.h>

#include <algorithm>
#include <cstdint>
#include <unordered_set>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

/// The (site, face) pairs the repair excluded.
class Banned_fields
{
public:
  explicit Banned_fields(std::size_t number_of_faces) : m_faces(number_of_faces) {}
  bool contains(std::size_t site, std::size_t face) const
  {
    return !m_set.empty() && m_set.count(std::uint64_t(site) * m_faces + face) != 0;
  }
  void insert(std::size_t site, std::size_t face) { m_set.insert(std::uint64_t(site) * m_faces + face); }
  std::size_t size() const { return m_set.size(); }

private:
  std::uint64_t m_faces;
  std::unordered_set<std::uint64_t> m_set;
};

/// The component holding the site's own location; with weights a site may not own its
/// location, and then its largest component is kept.
inline std::size_t principal_component(const Site& site, std::size_t i, const Partition& partition,
                                       const Cell_components& components)
{
  const std::size_t own = partition.piece_of(site.face, i);
  if(own != no_site) return components.piece_component[own];
  std::size_t best = components.site_components[i].front();
  for(std::size_t c : components.site_components[i])
    if(components.component_area[c] > components.component_area[best]) best = c;
  return best;
}

/// the number of cells in more than one piece
inline std::size_t number_of_broken_cells(const Cell_components& components)
{
  std::size_t broken = 0;
  for(const std::vector<std::size_t>& parts : components.site_components) broken += (parts.size() > 1);
  return broken;
}

/// Bans the site of every orphan piece (a piece outside its cell's principal component) from
/// the piece's face; `dirty_faces` receives those faces, sorted.
inline void ban_orphan_pieces(const std::vector<Site>& sites, const Partition& partition,
                              const Cell_components& components, Banned_fields& banned,
                              std::vector<std::size_t>& dirty_faces)
{
  std::vector<std::uint8_t> is_orphan(components.component_site.size(), 0);
  for(std::size_t i = 0; i < sites.size(); ++i)
  {
    const std::vector<std::size_t>& parts = components.site_components[i];
    if(parts.size() <= 1) continue;
    const std::size_t principal = principal_component(sites[i], i, partition, components);
    for(std::size_t c : parts)
      if(c != principal) is_orphan[c] = 1;
  }
  dirty_faces.clear();
  for(std::size_t p = 0; p < partition.pieces.size(); ++p)
    if(is_orphan[components.piece_component[p]])
    {
      const Partition::Piece& piece = partition.pieces[p];
      banned.insert(piece.site, piece.face);
      dirty_faces.push_back(piece.face);
    }
  std::sort(dirty_faces.begin(), dirty_faces.end());
  dirty_faces.erase(std::unique(dirty_faces.begin(), dirty_faces.end()), dirty_faces.end());
}

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_CELL_REPAIR_H
