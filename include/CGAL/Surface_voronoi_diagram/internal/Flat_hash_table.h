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
// An open-addressing hash table keyed by unsigned integers (linear probing, at most half
// full), the package's one: propagation records which (site, face) pairs were offered, and
// each fast-marching front maps its vertices to their values. One flat array instead of
// node-based containers keeps these hot loops free of small allocations.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_FLAT_HASH_TABLE_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_FLAT_HASH_TABLE_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

/// The slot of a set of keys; a map's slot adds members after `key`.
template <class Key>
struct Key_slot
{
  Key key;
};

/// A table of slots keyed by their unsigned member `key`; the key `Key(-1)` is reserved.
/// A set is `Flat_hash_table<Key_slot<K> >`; a map declares its own slot, which keeps it
/// as compact as the mapped data allow.
template <class Slot>
class Flat_hash_table
{
public:
  typedef typename std::remove_cv<decltype(Slot::key)>::type Key;
  static constexpr Key empty_key = Key(-1);

  /// empties the table and sizes it for `expected` keys
  void reset(std::size_t expected)
  {
    std::size_t capacity = 64;
    while(capacity < 2 * expected) capacity *= 2;
    m_slots.assign(capacity, empty_slot());
    m_size = 0;
  }

  std::size_t size() const { return m_size; }

  /// makes room for `n` more keys, so that the next `n` insertions keep the slots valid
  void reserve_more(std::size_t n)
  {
    while(2 * (m_size + n) > m_slots.size()) grow();
  }

  /// the slot of `key`, or null
  const Slot* find(Key key) const
  {
    if(m_slots.empty()) return nullptr;
    for(std::size_t i = home(key);; i = (i + 1) & (m_slots.size() - 1))
    {
      if(m_slots[i].key == key) return &m_slots[i];
      if(m_slots[i].key == empty_key) return nullptr;
    }
  }

  /// the slot of `key`, inserted as `fresh` (whose key is overwritten) if it was not there;
  /// the second member says whether it was inserted. The slot stays valid until the next
  /// insertion.
  std::pair<Slot*, bool> insert(Key key, const Slot& fresh = Slot())
  {
    if(2 * (m_size + 1) > m_slots.size()) grow();
    std::size_t i = home(key);
    while(m_slots[i].key != empty_key)
    {
      if(m_slots[i].key == key) return std::make_pair(&m_slots[i], false);
      i = (i + 1) & (m_slots.size() - 1);
    }
    m_slots[i] = fresh;
    m_slots[i].key = key;
    ++m_size;
    return std::make_pair(&m_slots[i], true);
  }

private:
  static Slot empty_slot()
  {
    Slot s = Slot();
    s.key = empty_key;
    return s;
  }

  std::size_t home(Key key) const
  {
    std::uint64_t h = static_cast<std::uint64_t>(key);
    h ^= h >> 33;
    h *= 0xff51afd7ed558ccdull;
    h ^= h >> 33;
    return static_cast<std::size_t>(h) & (m_slots.size() - 1);
  }

  void grow()
  {
    std::vector<Slot> old;
    old.swap(m_slots);
    m_slots.assign((std::max)(std::size_t(64), 2 * old.size()), empty_slot());
    for(const Slot& s : old)
      if(s.key != empty_key)
      {
        std::size_t i = home(s.key);
        while(m_slots[i].key != empty_key) i = (i + 1) & (m_slots.size() - 1);
        m_slots[i] = s;
      }
  }

  std::vector<Slot> m_slots;
  std::size_t m_size = 0;
};

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_FLAT_HASH_TABLE_H
