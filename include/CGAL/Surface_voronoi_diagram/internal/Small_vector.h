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
// A small vector of trivially copyable elements whose first N live inside it, with a 32-bit
// size and capacity: the candidate lists of the faces and the vertex ids of the partition's
// pieces, one per face and one per piece, all alive at the diagram's peak. boost's
// small_vector (Boost 1.74 has no 32-bit size for it) takes 16 bytes more for each: a piece's
// 4 ids take 24 bytes against 40, a face's 2 candidates 72 against 88.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_SMALL_VECTOR_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_SMALL_VECTOR_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <iterator>
#include <type_traits>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

template <class T, unsigned N>
class Small_vector
{
  static_assert(std::is_trivially_copyable<T>::value && std::is_trivially_destructible<T>::value,
                "elements are copied as they are and never destroyed");
  static_assert(N > 0, "some elements inside");

public:
  typedef T value_type;
  typedef T* iterator;
  typedef const T* const_iterator;

  Small_vector() : m_size(0), m_capacity(inline_capacity) {}
  /// `n` value-initialized elements
  explicit Small_vector(std::size_t n) : Small_vector() { resize(n); }
  Small_vector(std::initializer_list<T> elements) : Small_vector() { assign(elements.begin(), elements.end()); }
  Small_vector(const Small_vector& other) : Small_vector() { assign(other.begin(), other.end()); }
  Small_vector(Small_vector&& other) noexcept : Small_vector() { take(other); }
  Small_vector& operator=(const Small_vector& other)
  {
    if(this != &other) assign(other.begin(), other.end());
    return *this;
  }
  Small_vector& operator=(Small_vector&& other) noexcept
  {
    if(this != &other)
    {
      release();
      take(other);
    }
    return *this;
  }
  ~Small_vector() { release(); }

  std::size_t size() const { return m_size; }
  bool empty() const { return m_size == 0; }
  const T* data() const { return is_inline() ? m_inline : m_heap; }
  T* data() { return is_inline() ? m_inline : m_heap; }
  const_iterator begin() const { return data(); }
  const_iterator end() const { return data() + m_size; }
  iterator begin() { return data(); }
  iterator end() { return data() + m_size; }
  const T& operator[](std::size_t i) const { return data()[i]; }
  T& operator[](std::size_t i) { return data()[i]; }
  const T& front() const { return data()[0]; }
  const T& back() const { return data()[m_size - 1]; }

  void reserve(std::size_t n)
  {
    if(n > m_capacity) grow(n);
  }
  void push_back(const T& x)
  {
    if(m_size == m_capacity)
    {
      const T copy = x;   // `x` may be one of the elements
      grow(2 * std::size_t(m_capacity));
      data()[m_size++] = copy;
    }
    else
      data()[m_size++] = x;
  }
  void pop_back() { --m_size; }
  void clear() { m_size = 0; }
  /// new elements are value-initialized
  void resize(std::size_t n)
  {
    reserve(n);
    std::fill(data() + (std::min)(std::size_t(m_size), n), data() + n, T());
    m_size = static_cast<std::uint32_t>(n);
  }
  /// removes `[first, last)`
  iterator erase(const_iterator first, const_iterator last)
  {
    T* elements = data();
    const std::size_t from = static_cast<std::size_t>(first - elements), to = static_cast<std::size_t>(last - elements);
    std::copy(elements + to, elements + m_size, elements + from);
    m_size = static_cast<std::uint32_t>(m_size - (to - from));
    return elements + from;
  }
  template <class InputIterator>
  void assign(InputIterator first, InputIterator last)
  {
    const std::size_t n = static_cast<std::size_t>(std::distance(first, last));
    m_size = 0;
    reserve(n);
    T* out = data();
    for(; first != last; ++first) *out++ = static_cast<T>(*first);
    m_size = static_cast<std::uint32_t>(n);
  }
  /// `[first, last)` before `position` (the range must not be in this vector)
  template <class InputIterator>
  void insert(const_iterator position, InputIterator first, InputIterator last)
  {
    const std::size_t at = static_cast<std::size_t>(position - begin());
    const std::size_t n = static_cast<std::size_t>(std::distance(first, last));
    reserve(std::size_t(m_size) + n);
    T* elements = data();
    std::copy_backward(elements + at, elements + m_size, elements + m_size + n);
    for(T* out = elements + at; first != last; ++first) *out++ = static_cast<T>(*first);
    m_size = static_cast<std::uint32_t>(m_size + n);
  }

  friend bool operator==(const Small_vector& a, const Small_vector& b)
  {
    return a.m_size == b.m_size && std::equal(a.begin(), a.end(), b.begin());
  }
  friend bool operator!=(const Small_vector& a, const Small_vector& b) { return !(a == b); }

private:
  static constexpr std::uint32_t inline_capacity = N;

  // a heap block is only ever larger than the inline room, so the capacity tells where the elements are
  bool is_inline() const { return m_capacity == inline_capacity; }

  void grow(std::size_t n)
  {
    CGAL_precondition_msg(n <= std::size_t(0xffffffffu), "more than 2^32 elements in a small vector");
    T* block = new T[n];
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
  // `other`'s elements into this empty inline vector; `other` is left empty
  void take(Small_vector& other)
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
    T m_inline[N];
    T* m_heap;
  };
};

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_SMALL_VECTOR_H
