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
// The connectivity checks (on the cuts and on the stitched partition) visit the mesh face by
// face, uniting pieces of one cell and listing pairs of neighbouring sites. In parallel the
// faces are visited in chunks that gather what they find, merged afterwards in chunk order:
// the same sets (a union's representative is the set's smallest element, whatever the order
// of the unions) and the same pairs in the same order as one sequential visit.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_UNITE_FACE_BY_FACE_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_UNITE_FACE_BY_FACE_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/internal/Disjoint_sets.h>
#include <CGAL/Surface_voronoi_diagram/internal/parallel.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

typedef std::vector<std::pair<std::size_t, std::size_t> > Index_pairs;

/// Where a visit puts what it finds: unions straight into `sets`, or gathered in `unions` for
/// a chunk; pairs of neighbouring sites in `pairs`, if wanted.
struct Union_sink
{
  Disjoint_sets* sets;
  Index_pairs* unions;
  Index_pairs* pairs;

  void unite(std::size_t a, std::size_t b)
  {
    if(sets) sets->unite(a, b);
    else unions->emplace_back(a, b);
  }
  void pair(std::size_t s, std::size_t t)
  {
    if(pairs) pairs->emplace_back(s, t);
  }
  bool wants_pairs() const { return pairs != nullptr; }
};

/// Calls `visit(begin, end, sink)` over the faces [0, number_of_faces), in one sequential
/// visit or, with `parallel`, in chunks merged in chunk order; the unions end in `sets`, the
/// pairs (if `pairs` is given) are appended to `pairs`.
template <class Visit>
void unite_face_by_face(std::size_t number_of_faces, bool parallel, Disjoint_sets& sets, Index_pairs* pairs,
                        const Visit& visit)
{
  if(!parallel)
  {
    Union_sink direct{ &sets, nullptr, pairs };
    visit(std::size_t(0), number_of_faces, direct);
    return;
  }
  const std::size_t chunk = 8192;
  std::vector<Index_pairs> unions(number_of_chunks(number_of_faces, chunk)), found_pairs(unions.size());
  for_each_chunk(number_of_faces, chunk, true, [&](std::size_t begin, std::size_t end, std::size_t c) {
    Union_sink gathered{ nullptr, &unions[c], pairs ? &found_pairs[c] : nullptr };
    visit(begin, end, gathered);
  });
  for(std::size_t c = 0; c < unions.size(); ++c)
  {
    for(const std::pair<std::size_t, std::size_t>& ab : unions[c]) sets.unite(ab.first, ab.second);
    if(pairs) pairs->insert(pairs->end(), found_pairs[c].begin(), found_pairs[c].end());
    Index_pairs().swap(unions[c]);
    Index_pairs().swap(found_pairs[c]);
  }
}

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_UNITE_FACE_BY_FACE_H
