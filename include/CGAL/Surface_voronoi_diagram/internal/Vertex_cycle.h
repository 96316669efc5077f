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
// The vertex ids of a partition piece: a small vector of 32-bit ids whose first four live
// inside it, with a 32-bit size and capacity. boost's small_vector of the same ids (Boost
// 1.74 has no 32-bit size for it) takes 40 bytes against 24, and a 537k-vertex mesh has 1.4
// million pieces, alive at the diagram's peak.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_VERTEX_CYCLE_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_VERTEX_CYCLE_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <iterator>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

class Vertex_cycle
{
public:
  typedef std::uint32_t value_type;
  typedef std::uint32_t* iterator;
  typedef const std::uint32_t* const_iterator;

  Vertex_cycle() : m_size(0), m_capacity(inline_capacity) {}
  Vertex_cycle(const Vertex_cycle& other) : Vertex_cycle() { assign(other.begin(), other.end()); }
  Vertex_cycle(Vertex_cycle&& other) noexcept : Vertex_cycle() { take(other); }
  Vertex_cycle& operator=(const Vertex_cycle& other)
  {
    if(this != &other) assign(other.begin(), other.end());
    return *this;
  }
  Vertex_cycle& operator=(Vertex_cycle&& other) noexcept
  {
    if(this != &other)
    {
      release();
      take(other);
    }
    return *this;
  }
  ~Vertex_cycle() { release(); }

  std::size_t size() const { return m_size; }
  bool empty() const { return m_size == 0; }
  const std::uint32_t* data() const { return is_inline() ? m_inline : m_heap; }
  std::uint32_t* data() { return is_inline() ? m_inline : m_heap; }
  const_iterator begin() const { return data(); }
  const_iterator end() const { return data() + m_size; }
  iterator begin() { return data(); }
  iterator end() { return data() + m_size; }
  const std::uint32_t& operator[](std::size_t i) const { return data()[i]; }
  std::uint32_t& operator[](std::size_t i) { return data()[i]; }
  const std::uint32_t& front() const { return data()[0]; }
  const std::uint32_t& back() const { return data()[m_size - 1]; }

  void reserve(std::size_t n)
  {
    if(n > m_capacity) grow(n);
  }
  void push_back(std::uint32_t id)
  {
    if(m_size == m_capacity) grow(2 * std::size_t(m_capacity));
    data()[m_size++] = id;
  }
  void pop_back() { --m_size; }
  void clear() { m_size = 0; }
  /// new ids are 0
  void resize(std::size_t n)
  {
    reserve(n);
    std::fill(data() + (std::min)(std::size_t(m_size), n), data() + n, std::uint32_t(0));
    m_size = static_cast<std::uint32_t>(n);
  }
  template <class InputIterator>
  void assign(InputIterator first, InputIterator last)
  {
    const std::size_t n = static_cast<std::size_t>(std::distance(first, last));
    m_size = 0;
    reserve(n);
    std::uint32_t* out = data();
    for(; first != last; ++first) *out++ = static_cast<std::uint32_t>(*first);
    m_size = static_cast<std::uint32_t>(n);
  }
  /// `[first, last)` before `position` (the range must not be in this cycle)
  template <class InputIterator>
  void insert(const_iterator position, InputIterator first, InputIterator last)
  {
    const std::size_t at = static_cast<std::size_t>(position - begin());
    const std::size_t n = static_cast<std::size_t>(std::distance(first, last));
    reserve(std::size_t(m_size) + n);
    std::uint32_t* ids = data();
    std::copy_backward(ids + at, ids + m_size, ids + m_size + n);
    for(std::uint32_t* out = ids + at; first != last; ++first) *out++ = static_cast<std::uint32_t>(*first);
    m_size = static_cast<std::uint32_t>(m_size + n);
  }

  friend bool operator==(const Vertex_cycle& a, const Vertex_cycle& b)
  {
    return a.m_size == b.m_size && std::equal(a.begin(), a.end(), b.begin());
  }
  friend bool operator!=(const Vertex_cycle& a, const Vertex_cycle& b) { return !(a == b); }

private:
  static constexpr std::uint32_t inline_capacity = 4;

  // a heap block is only ever larger than the inline room, so the capacity tells where the ids are
  bool is_inline() const { return m_capacity == inline_capacity; }

  void grow(std::size_t n)
  {
    CGAL_precondition_msg(n <= std::size_t(0xffffffffu), "a piece with more than 2^32 vertices");
    std::uint32_t* block = new std::uint32_t[n];
    std::copy(begin(), end(), block);
    const std::uint32_t size = m_size;
    release();
    m_heap = block;
    m_capacity = static_cast<std::uint32_t>(n);
    m_size = size;
  }
  void release()
  {
    if(!is_inline()) delete[] m_heap;
    m_capacity = inline_capacity;
  }
  // `other`'s ids into this empty inline cycle; `other` is left empty
  void take(Vertex_cycle& other)
  {
    if(other.is_inline())
      std::copy(other.begin(), other.end(), m_inline);
    else
    {
      m_heap = other.m_heap;
      m_capacity = other.m_capacity;
      other.m_capacity = inline_capacity;
    }
    m_size = other.m_size;
    other.m_size = 0;
  }

  std::uint32_t m_size;
  std::uint32_t m_capacity;
  union
  {
    std::uint32_t m_inline[inline_capacity];
    std::uint32_t* m_heap;
  };
};

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_VERTEX_CYCLE_H
