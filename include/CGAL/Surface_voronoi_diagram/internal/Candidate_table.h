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
// The faces' candidate lists once the first propagation is done, in one array. The propagation
// grows a list per face (`Candidate_lists`, room for three candidates inline: 120 bytes a face);
// on large meshes most faces end with one candidate, so the final lists take far less packed
// one after another (32 bytes a candidate and 8 a face). The stages after the propagation read
// them here; a repair or an update replaces the lists of the faces it changed (`replace()`).

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_CANDIDATE_TABLE_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_CANDIDATE_TABLE_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/internal/Candidate.h>
#include <CGAL/Surface_voronoi_diagram/internal/parallel.h>

#include <CGAL/assertions.h>

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
  typedef Candidate_range List;

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
    m_faces.resize(nf);
    m_items.resize(total);
    // The lists on the heap are freed afterwards, on one thread: freed by the threads of the
    // copy, most of them allocated by another thread, they would queue on the allocator's
    // locks.
    for_each_chunk(nf, chunk, parallel, [&](std::size_t begin, std::size_t end, std::size_t c) {
      std::size_t first = chunk_first[c];
      for(std::size_t f = begin; f < end; ++f)
      {
        m_faces[f] = Range{ static_cast<std::uint32_t>(first), static_cast<std::uint32_t>(lists[f].size()) };
        std::copy(lists[f].begin(), lists[f].end(), m_items.data() + first);
        first += lists[f].size();
      }
    });
    Candidate_lists().swap(lists);
  }

  /// the number of faces
  std::size_t size() const { return m_faces.size(); }
  /// the number of candidates of all faces
  std::size_t number_of_candidates() const { return m_items.size() - m_unused; }

  List operator[](std::size_t f) const
  {
    CGAL_assertion(f < size());
    const Candidate* first = m_items.data() + m_faces[f].first;
    return List(first, first + m_faces[f].size);
  }

  /// Face f's candidates become `list`'s: in place if they fit, else at the end, the old ones
  /// left unused until those outnumber the others and the table is packed again.
  void replace(std::size_t f, const Candidate_list& list)
  {
    if(list.size() > m_faces[f].size)
    {
      if(m_unused > number_of_candidates()) pack();
      CGAL_precondition_msg(m_items.size() + list.size() < std::size_t(std::uint32_t(-1)), "too many candidates for 32-bit offsets");
      // grown by an eighth: a doubled array would stay twice the size of what a diagram keeps
      if(m_items.size() + list.size() > m_items.capacity()) m_items.reserve(m_items.size() + list.size() + m_items.size() / 8);
      m_unused += m_faces[f].size;
      m_faces[f].first = static_cast<std::uint32_t>(m_items.size());
      m_items.insert(m_items.end(), list.begin(), list.end());
    }
    else
    {
      std::copy(list.begin(), list.end(), m_items.begin() + m_faces[f].first);
      m_unused += m_faces[f].size - list.size();
    }
    m_faces[f].size = static_cast<std::uint32_t>(list.size());
  }

  void clear()
  {
    std::vector<Range>().swap(m_faces);
    std::vector<Candidate>().swap(m_items);
    m_unused = 0;
  }

private:
  struct Range
  {
    std::uint32_t first, size;   // face f's candidates: m_items[first] .. m_items[first + size]
  };

  // the lists one after another again, in face order
  void pack()
  {
    std::vector<Candidate> items;
    items.reserve(number_of_candidates() + number_of_candidates() / 8);
    for(Range& r : m_faces)
    {
      items.insert(items.end(), m_items.begin() + r.first, m_items.begin() + r.first + r.size);
      r.first = static_cast<std::uint32_t>(items.size() - r.size);
    }
    m_items.swap(items);
    m_unused = 0;
  }

  std::vector<Range> m_faces;
  std::vector<Candidate> m_items;
  std::size_t m_unused = 0;   // the candidates replace() left behind
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
