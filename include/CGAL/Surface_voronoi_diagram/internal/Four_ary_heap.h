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
// The propagation's queue of events: a heap with four children a node instead of two. A pop
// moves an element half as many levels down, and the four children of a node lie in one cache
// line, so the queue's share of the propagation drops. With a strict total order (no two
// events compare equal) it pops the same sequence as `std::priority_queue`.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_FOUR_ARY_HEAP_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_FOUR_ARY_HEAP_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

/// `Later(a, b)`: `a` is popped after `b` (the comparator of a `std::priority_queue` whose top
/// comes first).
template <class T, class Later>
class Four_ary_heap
{
public:
  bool empty() const { return m_items.empty(); }
  std::size_t size() const { return m_items.size(); }
  const T& top() const { CGAL_assertion(!empty()); return m_items.front(); }

  void push(const T& x)
  {
    std::size_t i = m_items.size();
    m_items.push_back(x);
    while(i > 0)
    {
      const std::size_t parent = (i - 1) / 4;
      if(!m_later(m_items[parent], x)) break;
      m_items[i] = m_items[parent];
      i = parent;
    }
    m_items[i] = x;
  }

  // Bottom-up: the hole left at the top goes down to a leaf along the earliest children,
  // without comparing the last item on the way, which then goes up from there. The last item
  // came from the bottom and mostly stays near it: about three comparisons per level instead
  // of four.
  void pop()
  {
    CGAL_assertion(!empty());
    const T x = m_items.back();
    m_items.pop_back();
    const std::size_t n = m_items.size();
    if(n == 0) return;
    std::size_t i = 0;
    for(;;)
    {
      const std::size_t first = 4 * i + 1;
      if(first >= n) break;
      std::size_t earliest = first;
      const std::size_t end = (std::min)(first + 4, n);
      for(std::size_t c = first + 1; c < end; ++c)
        if(m_later(m_items[earliest], m_items[c])) earliest = c;
      m_items[i] = m_items[earliest];
      i = earliest;
    }
    while(i > 0)
    {
      const std::size_t parent = (i - 1) / 4;
      if(!m_later(m_items[parent], x)) break;
      m_items[i] = m_items[parent];
      i = parent;
    }
    m_items[i] = x;
  }

  /// frees the storage (the heap must be empty)
  void release()
  {
    CGAL_assertion(empty());
    std::vector<T>().swap(m_items);
  }

private:
  std::vector<T> m_items;
  Later m_later;
};

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_FOUR_ARY_HEAP_H
