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
// The faces' candidate lists once they no longer change, in one array. The propagation grows
// a list per face (`Candidate_lists`, room for three candidates inline: 120 bytes a face);
// on large meshes most faces end with one candidate, so the final lists take far less packed
// one after another (32 bytes a candidate and 4 a face). Stitching and everything after it read them
// here; a repair after stitching unpacks them again (`to_lists()`).

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_CANDIDATE_TABLE_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_CANDIDATE_TABLE_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/internal/Candidate.h>
#include <CGAL/Surface_voronoi_diagram/internal/parallel.h>

#include <CGAL/assertions.h>

#include <boost/range/iterator_range.hpp>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

class Candidate_table
{
public:
  /// the candidates of one face
  typedef boost::iterator_range<const Candidate*> List;

  Candidate_table() = default;

  /// packs `lists`, which are left empty (their memory freed)
  explicit Candidate_table(Candidate_lists&& lists, bool parallel = false)
  {
    const std::size_t nf = lists.size(), chunk = 8192;
    // where each chunk of faces' candidates begin
    const std::vector<std::size_t> chunk_first = chunk_offsets(nf, chunk, parallel, [&](std::size_t begin, std::size_t end) {
      std::size_t candidates = 0;
      for(std::size_t f = begin; f < end; ++f) candidates += lists[f].size();
      return candidates;
    });
    const std::size_t total = chunk_first.back();
    CGAL_precondition_msg(total < std::size_t(std::uint32_t(-1)), "too many candidates for 32-bit offsets");
    m_first.resize(nf + 1);
    m_first[nf] = static_cast<std::uint32_t>(total);
    m_items.resize(total);
    // The lists on the heap are freed afterwards, on one thread: freed by the threads of the
    // copy, most of them allocated by another thread, they would queue on the allocator's
    // locks.
    for_each_chunk(nf, chunk, parallel, [&](std::size_t begin, std::size_t end, std::size_t c) {
      std::size_t first = chunk_first[c];
      for(std::size_t f = begin; f < end; ++f)
      {
        m_first[f] = static_cast<std::uint32_t>(first);
        std::copy(lists[f].begin(), lists[f].end(), m_items.data() + first);
        first += lists[f].size();
      }
    });
    Candidate_lists().swap(lists);
  }

  /// the number of faces
  std::size_t size() const { return m_first.empty() ? 0 : m_first.size() - 1; }
  /// the number of candidates of all faces
  std::size_t number_of_candidates() const { return m_items.size(); }

  List operator[](std::size_t f) const
  {
    CGAL_assertion(f < size());
    return List(m_items.data() + m_first[f], m_items.data() + m_first[f + 1]);
  }

  /// the lists again, for a propagation to grow them
  Candidate_lists to_lists() const
  {
    Candidate_lists lists(size(), Candidate_list());
    for(std::size_t f = 0; f < lists.size(); ++f) lists[f].assign((*this)[f].begin(), (*this)[f].end());
    return lists;
  }

  void clear()
  {
    std::vector<std::uint32_t>().swap(m_first);
    std::vector<Candidate>().swap(m_items);
  }

private:
  std::vector<std::uint32_t> m_first;   // face f's candidates: m_items[m_first[f]] .. m_items[m_first[f + 1]]
  std::vector<Candidate> m_items;
};

/// The sites of each face's candidates, without their values: the diagram a Lloyd step
/// starts from (`Propagation::run_from()`), a few bytes per candidate.
struct Candidate_sites
{
  explicit Candidate_sites(const Candidate_table& table)
    : first(table.size() + 1, 0)
  {
    sites.reserve(table.number_of_candidates());
    for(std::size_t f = 0; f < table.size(); ++f)
    {
      first[f] = static_cast<std::uint32_t>(sites.size());
      for(const Candidate& x : table[f]) sites.push_back(x.site);
    }
    first[table.size()] = static_cast<std::uint32_t>(sites.size());
  }

  std::size_t number_of_faces() const { return first.empty() ? 0 : first.size() - 1; }

  std::vector<std::uint32_t> first;   // face f's sites: sites[first[f]] .. sites[first[f + 1]]
  std::vector<std::uint32_t> sites;
};

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_CANDIDATE_TABLE_H
