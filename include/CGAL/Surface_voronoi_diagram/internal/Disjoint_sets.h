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
// Disjoint sets over the indices 0..n-1, the package's one union-find: the lower root wins
// a union, so a set's representative is its smallest index unless a caller links roots
// explicitly (welding keeps the most specific vertex instead).

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_DISJOINT_SETS_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_DISJOINT_SETS_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <algorithm>
#include <cstddef>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

// CGAL::Union_find allocates a node per element and hands out handles; the pipeline unions
// millions of plain indices, for which a flat parent array is smaller and faster.
class Disjoint_sets
{
public:
  explicit Disjoint_sets(std::size_t n = 0) { reset(n); }

  void reset(std::size_t n)
  {
    m_parent.resize(n);
    std::iota(m_parent.begin(), m_parent.end(), std::size_t(0));
  }

  std::size_t size() const { return m_parent.size(); }

  /// appends a new singleton set and returns its index
  std::size_t add()
  {
    m_parent.push_back(m_parent.size());
    return m_parent.size() - 1;
  }

  std::size_t find(std::size_t x)
  {
    while(m_parent[x] != x)
    {
      m_parent[x] = m_parent[m_parent[x]];   // path halving
      x = m_parent[x];
    }
    return x;
  }

  /// merges the sets of `a` and `b`; the smaller root becomes the representative
  void unite(std::size_t a, std::size_t b)
  {
    a = find(a);
    b = find(b);
    if(a != b) m_parent[(std::max)(a, b)] = (std::min)(a, b);
  }

  /// makes root `child` a member of root `parent`'s set
  void link(std::size_t child, std::size_t parent) { m_parent[child] = parent; }

private:
  std::vector<std::size_t> m_parent;
};

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_DISJOINT_SETS_H
