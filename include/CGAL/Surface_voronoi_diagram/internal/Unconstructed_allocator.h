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
// An allocator for large arrays filled in concurrent chunks: `resize()` leaves the new
// elements unconstructed, and the code that fills them constructs each in place (with
// `std::uninitialized_copy` or placement new). A value-initializing `resize()` wrote every
// page on one thread first: first touches of fresh pages can be a large share of a pass over
// them, and they then run on every thread.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_UNCONSTRUCTED_ALLOCATOR_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_UNCONSTRUCTED_ALLOCATOR_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <memory>
#include <new>
#include <utility>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

/// `std::allocator` but for `construct(p)` without arguments, which does nothing: a vector
/// resized with it holds storage whose elements the caller must construct before any use.
template <class T>
struct Unconstructed_allocator : std::allocator<T>
{
  template <class U> struct rebind { typedef Unconstructed_allocator<U> other; };

  Unconstructed_allocator() = default;
  template <class U> Unconstructed_allocator(const Unconstructed_allocator<U>&) noexcept {}

  template <class U> void construct(U*) noexcept {}
  template <class U, class... Args> void construct(U* p, Args&&... args)
  {
    ::new(static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

template <class T, class U>
bool operator==(const Unconstructed_allocator<T>&, const Unconstructed_allocator<U>&) { return true; }
template <class T, class U>
bool operator!=(const Unconstructed_allocator<T>&, const Unconstructed_allocator<U>&) { return false; }

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_UNCONSTRUCTED_ALLOCATOR_H
