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
// Backing the pages of a block before a thread writes it: a large array written once, in
// order, by one thread spends much of that thread's time in first touches (the kernel finding
// and zeroing each 4 KB page). A second thread, idle while the first one writes, can take
// those faults ahead of it. This changes no value, only which thread waits for the pages.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_POPULATE_PAGES_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_POPULATE_PAGES_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <utility>

#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
inline std::uintptr_t page_size()
{
  static const std::uintptr_t page = std::uintptr_t(sysconf(_SC_PAGESIZE));
  return page;
}
#endif

/// Asks the system to back, writable, the whole pages inside `[begin, begin + bytes)` now, as
/// the first writes to them would (Linux 5.14 and later, `MADV_POPULATE_WRITE`; the contents
/// are left as they are), slice by slice through the blocks given, so that the pages their
/// writers reach next come first when they are written side by side from their starts on.
/// Elsewhere, or where the system refuses, nothing happens.
inline void populate_pages_in_step(std::initializer_list<std::pair<const void*, std::size_t> > blocks,
                                   std::size_t slices = 16)
{
#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
  const std::uintptr_t page = page_size();
  for(std::size_t s = 0; s < slices; ++s)
    for(const std::pair<const void*, std::size_t>& b : blocks)
    {
      const std::uintptr_t first = (reinterpret_cast<std::uintptr_t>(b.first) + page - 1) & ~(page - 1);
      const std::uintptr_t last = (reinterpret_cast<std::uintptr_t>(b.first) + b.second) & ~(page - 1);
      if(last <= first) continue;
      const std::uintptr_t pages = (last - first) / page;
      const std::uintptr_t from = first + pages * s / slices * page, to = first + pages * (s + 1) / slices * page;
      if(to > from)
        (void)madvise(reinterpret_cast<void*>(from), to - from, MADV_POPULATE_WRITE);   // advice: a refusal changes nothing
    }
#else
  (void)blocks;
  (void)slices;
#endif
}

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_POPULATE_PAGES_H
