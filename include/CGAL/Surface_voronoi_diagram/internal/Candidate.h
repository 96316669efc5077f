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
// A candidate of a face: a site whose distance field may win somewhere in the face, with
// the field's values at the face's three corners. Propagation produces the per-face lists,
// cutting reads them, stitching places vertices from them.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_CANDIDATE_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_CANDIDATE_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <boost/container/small_vector.hpp>
#include <boost/range/iterator_range.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

/// A site's field on one face: D = squared distance - weight at the three corners, in the
/// face's corner order.
struct Candidate
{
  /// `from_edge` of a field that started in its face (the site's own face)
  static constexpr std::uint8_t at_site = 3;

  Candidate() = default;
  Candidate(std::uint32_t s, const std::array<double, 3>& v, std::uint8_t from = at_site)
    : site(s), from_edge(from), value(v)
  {}

  std::uint32_t site;
  // The local edge of the face across which the propagation brought this field (from the
  // site's candidate in the neighbour there, admitted before this one), or `at_site`: the
  // check of the cells follows these links back to the sites (Cell_connectivity.h).
  std::uint8_t from_edge = at_site;
  std::array<double, 3> value;
};

/// The candidates of one face: most faces have one to three,
/// kept inline, so that a million faces are not a million heap blocks to allocate and free.
typedef boost::container::small_vector<Candidate, 3> Candidate_list;
/// One list per face.
typedef std::vector<Candidate_list> Candidate_lists;
/// The candidates of one face as the stages after the propagation read them (`Candidate_table`).
typedef boost::iterator_range<const Candidate*> Candidate_range;

/// (value, site) compared lexicographically: ties go to the lower site index everywhere,
/// which is the symbolic perturbation that makes both sides of every edge agree.
inline bool lexicographically_less(double a, std::uint32_t i, double b, std::uint32_t j)
{
  return a < b || (a == b && i < j);
}

/// whether `b` is below `x` at all three corners, so that `x` cannot win anywhere in the face
inline bool dominates(const Candidate& b, const Candidate& x)
{
  for(int k = 0; k < 3; ++k)
    if(!lexicographically_less(b.value[k], b.site, x.value[k], x.site))
      return false;
  return true;
}

/// whether a candidate of `list` of another site dominates `x`
inline bool is_dominated(const Candidate_list& list, const Candidate& x)
{
  for(const Candidate& b : list)
    if(b.site != x.site && dominates(b, x)) return true;
  return false;
}

/// Drops the candidates dominated by another one (they cannot win any area) and sorts by
/// site, so that cutting does not depend on the order in which candidates arrived.
inline void clean_candidate_list(Candidate_list& list)
{
  if(list.size() > 1)
  {
    std::size_t kept = 0;
    for(std::size_t a = 0; a < list.size(); ++a)
      if(!is_dominated(list, list[a])) list[kept++] = list[a];
    list.resize(kept);
    std::sort(list.begin(), list.end(), [](const Candidate& a, const Candidate& b) { return a.site < b.site; });
  }
}

/// the values of `site` on face `f`, or null if it is not a candidate there
// `List`: a `Candidate_list` or a `Candidate_table::List`
template <class List>
const double* values_of(const List& list, std::uint32_t site)
{
  for(const Candidate& x : list)
    if(x.site == site) return x.value.data();
  return nullptr;
}

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_CANDIDATE_H
