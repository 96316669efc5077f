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
// Propagation (SurfaceVoronoi, stage 1): for every face, the sites whose distance field can
// win somewhere in it. A site's field enters a face only from a face where it was admitted,
// so a site never appears on the far side of a wall it cannot reach along the surface.
//
// On large meshes with many sites and a metric whose values can be read concurrently, the
// first propagation runs block by block (Face_blocks.h), in rounds: each block drains its own
// queue, and what leaves it waits in the block's outbox for the next round, when each block
// takes what was sent to it, in block order. The rounds and their order depend on the blocks
// alone, so a run on any number of threads gives the same candidates. A field admitted in a
// block before a field that dominates it arrived from another block stays admitted (lists only
// grow) and may go on a little further than in one global order: a cell can then come out in
// pieces, which the repair mends as it mends any other.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_PROPAGATION_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_PROPAGATION_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/internal/Candidate.h>
#include <CGAL/Surface_voronoi_diagram/internal/Candidate_table.h>
#include <CGAL/Surface_voronoi_diagram/internal/Face_blocks.h>
#include <CGAL/Surface_voronoi_diagram/internal/Flat_hash_table.h>
#include <CGAL/Surface_voronoi_diagram/internal/Indexed_mesh.h>
#include <CGAL/Surface_voronoi_diagram/internal/parallel.h>

#include <algorithm>
#include <array>
#include <deque>
#include <cstdint>
#include <numeric>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

// Whether `Fields::value()` may be called from several threads at once (its
// `concurrent_values`; false if it does not say).
template <class Fields, class = void>
struct Values_are_concurrent : std::false_type {};
template <class Fields>
struct Values_are_concurrent<Fields, std::enable_if_t<Fields::concurrent_values> > : std::true_type {};

struct Propagation_statistics
{
  std::size_t events = 0;
  std::size_t admitted = 0;
  std::size_t blocks = 1;   // the blocks of the first propagation (1: one global order)
  std::size_t rounds = 1;   // its rounds

  void add(const Propagation_statistics& other)
  {
    events += other.events;
    admitted += other.admitted;
  }
};

/// The propagation and its state, so that the connectivity repair can re-run it locally.
/// `Fields` gives `value(site, vertex)`; `Blocked` says whether local edge k of face f is a
/// breakline.
template <class TriangleMesh, class Fields, class Blocked>
class Propagation
{
public:
  typedef Indexed_mesh<TriangleMesh> Mesh;

  /// The faces of a block of the first propagation, and the sites per block below which it
  /// runs in one global order: blocks of fewer cells would mostly hold fields that the
  /// neighbouring blocks' sites dominate.
  static constexpr std::size_t faces_per_block = 16384;
  static constexpr std::size_t sites_per_block = 64;

  /// `breakline_site_faces`: the (site, face) pairs where a site on a breakline starts, its own
  /// face among them (`Breaklines::faces_of_sites_on_breaklines()`); `parallel`: the blocks of
  /// the first propagation, if any, run on concurrent threads (same result)
  Propagation(const Mesh& mesh, const Fields& fields, const std::vector<std::size_t>& site_faces,
              const std::vector<std::pair<std::size_t, std::size_t> >& breakline_site_faces, const Blocked& blocked,
              bool parallel = false)
    : m_mesh(mesh), m_fields(fields), m_site_faces(site_faces), m_breakline_site_faces(breakline_site_faces), m_blocked(blocked),
      m_parallel(parallel)
  {}

  /// Blocks of other sizes than the defaults (before `run()`): smaller ones for values that
  /// cost far more than a field's crossing (lazy metrics), and in tests, small meshes in blocks.
  void set_block_sizes(std::size_t faces, std::size_t sites)
  {
    CGAL_precondition(faces > 0 && sites > 0);
    m_faces_per_block = faces;
    m_sites_per_block = sites;
  }

  /// The number of blocks the first propagation runs in (1: one global order); blocks need
  /// values that can be read concurrently.
  std::size_t number_of_blocks() const
  {
    if(!Values_are_concurrent<Fields>::value) return 1;
    const std::size_t blocks = (std::min)(m_mesh.number_of_faces() / m_faces_per_block, m_site_faces.size() / m_sites_per_block);
    return blocks >= 4 ? blocks : 1;
  }

  Candidate_lists candidates;
  Propagation_statistics statistics;

  /// the first propagation, from every site
  void run()
  {
    link_faces();
    candidates.assign(m_mesh.number_of_faces(), Candidate_list());
    const std::size_t blocks = number_of_blocks();
    if(blocks > 1)
      run_in_blocks(blocks);
    else
    {
      for_each_start([this](std::uint32_t site, std::size_t f) { offer(m_front, site, f, Candidate::at_site); });
      auto no_ban = [](std::size_t, std::size_t) { return false; };
      drain(m_front, no_ban, false);
    }
    parallel_for_each_index(candidates.size(), m_parallel, [this](std::size_t f) { clean_candidate_list(candidates[f]); });
  }

  /// A Lloyd step's propagation: from the candidates of the diagram before the sites moved
  /// (`previous`: the same sites by index, on this mesh), which are mostly this diagram's too.
  /// The previous candidates are the lists to start from, with the fields' new values; each
  /// site's field then spreads from its own face, site by site in the order of their faces
  /// (into a neighbour where the site is already a candidate without computing anything, into
  /// another unless dominated there; never on from a face where it is dominated), and a
  /// previous candidate its field does not reach is dropped. The fields that a dropped or
  /// dominated candidate may have stopped are offered again around its face, until no face
  /// loses one. Spreading site by site keeps to the cells' few faces, where the first
  /// propagation's queue jumps across the mesh in the order of the values (it was half of a
  /// Lloyd step). From sites that moved far, the candidates can differ from a fresh
  /// propagation's, whose order of values decides which of two fields stops the other: a cell
  /// may come out in pieces, which the repair mends, as after a propagation in blocks.
  /// Sequential (the candidates' cleaning excepted).
  void run_from(const Candidate_sites& previous)
  {
    const std::size_t nf = m_mesh.number_of_faces();
    CGAL_precondition(previous.number_of_faces() == nf);
    link_faces();
    candidates.assign(m_mesh.number_of_faces(), Candidate_list());
    for(std::size_t f = 0; f < nf; ++f)
    {
      candidates[f].reserve(previous.first[f + 1] - previous.first[f]);
      for(std::uint32_t i = previous.first[f]; i < previous.first[f + 1]; ++i)
      {
        CGAL_precondition(previous.sites[i] < m_site_faces.size());
        candidates[f].push_back(Candidate(previous.sites[i], field_values(previous.sites[i], f), unreached));
      }
    }
    // every site's field from its own face (and those of a site on a breakline)
    std::vector<std::vector<std::size_t> > extra_starts(m_site_faces.size());
    for(const std::pair<std::size_t, std::size_t>& x : m_breakline_site_faces)
      if(x.second != m_site_faces[x.first]) extra_starts[x.first].push_back(x.second);
    std::vector<std::uint32_t> order(m_site_faces.size());
    std::iota(order.begin(), order.end(), std::uint32_t(0));
    std::stable_sort(order.begin(), order.end(), [this](std::uint32_t a, std::uint32_t b) { return m_site_faces[a] < m_site_faces[b]; });
    std::vector<std::pair<std::uint32_t, std::uint32_t> > again;   // (site, face) to spread (again)
    for(std::uint32_t s : order)
    {
      again.clear();
      start_at(s, m_site_faces[s], again);
      for(std::size_t f : extra_starts[s]) start_at(s, f, again);
      for(std::size_t next = 0; next < again.size(); ++next) spread(s, again[next].second, again);
    }
    // The previous candidates no field reached are dropped, and the dominated candidates as
    // after any propagation; what they stopped is offered again around the faces that lost
    // one, until none does: every field a face holds is then held or dominated across each of
    // its edges, as after a fresh propagation.
    std::vector<std::uint8_t> changed(nf, 0);
    auto prune = [this, &changed](std::size_t f) {
      Candidate_list& list = candidates[f];
      const std::size_t before = list.size();
      list.erase(std::remove_if(list.begin(), list.end(), [](const Candidate& x) { return x.from_edge == unreached; }), list.end());
      clean_candidate_list(list);
      if(list.size() != before) changed[f] = 1;
    };
    parallel_for_each_index(nf, m_parallel, prune);
    std::vector<std::uint32_t> changed_faces, touched;
    for(std::size_t f = 0; f < nf; ++f)
      if(changed[f]) changed_faces.push_back(static_cast<std::uint32_t>(f));
    for(std::size_t round = 0; !changed_faces.empty(); ++round)
    {
      if(round == max_rounds_from_previous) { run(); return; }   // not expected: start afresh
      again.clear();
      for(std::uint32_t f : changed_faces)
      {
        changed[f] = 0;
        for(const Candidate& x : candidates[f]) again.emplace_back(x.site, f);
        for(int k = 0; k < 3; ++k)
        {
          const std::uint32_t g = m_links[f].neighbor[k];
          if(g != no_link)
            for(const Candidate& x : candidates[g]) again.emplace_back(x.site, g);
        }
      }
      const std::size_t offered = again.size();
      for(std::size_t next = 0; next < again.size(); ++next)
      {
        const std::pair<std::uint32_t, std::uint32_t> x = again[next];
        spread(x.first, x.second, again);
      }
      touched.clear();
      for(std::size_t next = offered; next < again.size(); ++next) touched.push_back(again[next].second);
      std::sort(touched.begin(), touched.end());
      touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
      changed_faces.clear();
      for(std::uint32_t f : touched)
      {
        prune(f);
        if(changed[f]) changed_faces.push_back(f);
      }
    }
    for(const Candidate_list& list : candidates) statistics.admitted += list.size();
  }

  /// Frees what the first propagation read besides the candidates (the faces' links: tens of
  /// bytes per face), for the stages that do not need it; `repropagate()` makes those of the
  /// faces it reaches.
  void release_working_state() { std::vector<Face_link>().swap(m_links); }

  /// After the repair banned (site, face) pairs, or an update moved sites, on the candidates
  /// of `table`: the banned candidates are removed from the `dirty` faces, whose lists are then
  /// refilled from their neighbours' candidates, and the propagation goes on from there, on
  /// copies of the lists of the faces it reaches (few: no pass over the mesh). `touched`
  /// receives every face whose list changed, in order, its list replaced in `table`, and
  /// `sites_before`, if given, the sites those lists held before (with repetitions). The sites
  /// `leaving` marks, if given, leave the dirty faces too (an update's moved sites, whose
  /// fields start again from their sites).
  template <class Banned>
  void repropagate(Candidate_table& table, const std::vector<std::size_t>& dirty, const Banned& banned,
                   std::vector<std::size_t>& touched, std::vector<std::uint32_t>* sites_before = nullptr,
                   const std::vector<std::uint8_t>* leaving = nullptr)
  {
    m_table = &table;
    m_reached.reset(16 * dirty.size());
    m_sites_before = sites_before;
    for(std::size_t f : dirty)
    {
      Candidate_list& list = this->list(f);
      mark_touched(f);
      list.erase(std::remove_if(list.begin(), list.end(),
                                [&](const Candidate& x) { return (leaving && (*leaving)[x.site]) || banned(x.site, f); }),
                 list.end());
    }
    for(std::size_t f : dirty)
    {
      const Face_link l = link(f);
      for(int k = 0; k < 3; ++k)
        if(l.neighbor[k] != no_link)
          for(const Candidate& x : list(l.neighbor[k]))   // a deque's lists stay in place
            if(!banned(x.site, f)) offer(m_front, x.site, f, static_cast<std::uint8_t>(k));
    }
    for_each_start([&](std::uint32_t site, std::size_t f) {
      const Reached* r = m_reached.find(static_cast<std::uint32_t>(f));
      if(r && m_local[r->index].touched && !banned(site, f)) offer(m_front, site, f, Candidate::at_site);
    });
    drain(m_front, banned, true);
    m_sites_before = nullptr;
    touched.clear();
    for(Local_list& x : m_local)
      if(x.touched)
      {
        clean_candidate_list(x.list);
        table.replace(x.face, x.list);
        touched.push_back(x.face);
      }
    std::sort(touched.begin(), touched.end());
    m_local.clear();
    m_reached.reset(0);
    m_table = nullptr;
  }

  /// Calls `start(site, face)` for each site and its face, in site order, then for the other
  /// faces where the sites on breaklines start.
  template <class Start>
  void for_each_start(const Start& start) const
  {
    for(std::size_t i = 0; i < m_site_faces.size(); ++i) start(static_cast<std::uint32_t>(i), m_site_faces[i]);
    for(const std::pair<std::size_t, std::size_t>& x : m_breakline_site_faces)
      if(x.second != m_site_faces[x.first]) start(static_cast<std::uint32_t>(x.first), x.second);
  }

private:
  // Small, so that the heap moves little memory: the field's values wait in the face's list,
  // as a candidate marked `waiting` (computed once: a lazy metric's values can be expensive).
  struct Event
  {
    double key;
    std::uint32_t site;
    std::uint32_t face;
  };
  struct Later
  {
    bool operator()(const Event& a, const Event& b) const
    {
      if(a.key != b.key) return a.key > b.key;
      if(a.site != b.site) return a.site > b.site;
      return a.face > b.face;
    }
  };
  // A field offered across an edge into another block: its values at the edge's two corners
  // (those of the face it leaves), the third computed by the receiving block if it takes it.
  struct Crossing
  {
    std::array<double, 3> value;   // value[fresh] not yet computed
    std::uint32_t site;
    std::uint32_t face;
    std::uint8_t fresh;            // the corner of `face` not on the edge
  };
  // What one order of events works with: the whole mesh's, or one block's in a round.
  struct Front
  {
    std::vector<Event> queue;   // a binary heap (std::push_heap), its earliest event first
    Propagation_statistics statistics;
    std::uint32_t block = 0;
    std::vector<Crossing> outbox;                        // in blocks: the fields leaving the block
  };

  // A site is offered to a face once: the face's list holds it from the offer on, marked
  // `waiting` until its event is taken from the queue. An offer dominated on arrival or when
  // taken leaves nothing, and the same offer again is dominated again (lists only grow, and
  // dominance is transitive), so the list alone tells whether to offer, in a line of memory the
  // dominance check reads anyway.
  static constexpr std::uint8_t waiting = 0x80;   // a flag in `from_edge`

  static bool is_waiting(const Candidate& x) { return (x.from_edge & waiting) != 0; }

  // whether a candidate of `list` taken from the queue dominates `x`
  static bool dominated_in(const Candidate_list& list, const Candidate& x)
  {
    for(const Candidate& b : list)
      if(!is_waiting(b) && dominates(b, x)) return true;
    return false;
  }

  std::array<double, 3> field_values(std::uint32_t site, std::size_t f) const
  {
    std::array<double, 3> value;
    for(int k = 0; k < 3; ++k)
      value[k] = m_fields.value(site, m_mesh.triangles[f][k]);
    return value;
  }

  // What the propagation reads of a face when it leaves it, in one place: across local edge
  // k, the neighbour (`none` across a breakline), where the edge's two corners are among the
  // neighbour's corners, and the neighbour's third vertex. Aligned so that a face's links
  // lie in one cache line.
  struct alignas(32) Face_link
  {
    std::uint32_t neighbor[3];
    std::uint32_t fresh_vertex[3];
    std::uint8_t shared_corners[3];   // corner of f.c_k in the neighbour | that of f.c_(k+1) << 2
  };
  static constexpr std::uint32_t no_link = std::uint32_t(-1);

  // `from_edge` of a previous candidate that a Lloyd step's propagation has not reached yet
  static constexpr std::uint8_t unreached = 4;
  // the rounds of offers after which run_from() gives up and propagates afresh
  static constexpr std::size_t max_rounds_from_previous = 64;

  static Candidate* find_site(Candidate_list& list, std::uint32_t site)
  {
    for(Candidate& x : list)
      if(x.site == site) return &x;
    return nullptr;
  }

  // run_from(): the field of `site` starts in its face `f`
  void start_at(std::uint32_t site, std::size_t f, std::vector<std::pair<std::uint32_t, std::uint32_t> >& again)
  {
    Candidate* x = find_site(candidates[f], site);
    if(x && x->from_edge != unreached) return;   // a second start in the same face
    if(!x)
      candidates[f].push_back(Candidate(site, field_values(site, f), Candidate::at_site));
    else
      x->from_edge = Candidate::at_site;
    again.emplace_back(site, static_cast<std::uint32_t>(f));
  }

  // run_from(): the field of `site`, reached in face `f`, goes on into the neighbours where it
  // is not yet (those it enters go to `again`, with the site)
  void spread(std::uint32_t site, std::size_t f, std::vector<std::pair<std::uint32_t, std::uint32_t> >& again)
  {
    ++statistics.events;
    const Candidate* here = find_site(candidates[f], site);
    CGAL_assertion(here != nullptr && here->from_edge != unreached);
    if(is_dominated(candidates[f], *here)) return;
    const Candidate x = *here;   // the lists below may grow
    const Face_link& l = m_links[f];
    for(int k = 0; k < 3; ++k)
    {
      const std::uint32_t g = l.neighbor[k];
      if(g == no_link) continue;
      Candidate_list& list = candidates[g];
      if(Candidate* seen = find_site(list, site))
      {
        if(seen->from_edge != unreached) continue;
        seen->from_edge = edge_brought_across(l, k);   // its values are the same numbers: the field is one of the vertex
      }
      else
      {
        const Candidate y = carried_across(x, l, k);
        if(is_dominated(list, y)) continue;
        list.push_back(y);
      }
      again.emplace_back(site, g);
    }
  }

  void link_faces()
  {
    m_links.resize(m_mesh.number_of_faces());
    parallel_for_each_index(m_links.size(), m_parallel, [this](std::size_t f) { m_links[f] = make_link(f); });
  }

  Face_link make_link(std::size_t f) const
  {
    Face_link l;
    for(int k = 0; k < 3; ++k)
    {
      const std::size_t g = m_mesh.neighbors[f][k];
      l.neighbor[k] = no_link;
      l.fresh_vertex[k] = 0;
      l.shared_corners[k] = 0;
      if(g == Mesh::none || m_blocked(f, k)) continue;
      const int a = m_mesh.corner_of(g, m_mesh.triangles[f][k]), b = m_mesh.corner_of(g, m_mesh.triangles[f][(k + 1) % 3]);
      CGAL_assertion(a >= 0 && a < 3 && b >= 0 && b < 3 && a != b);
      l.neighbor[k] = static_cast<std::uint32_t>(g);
      l.fresh_vertex[k] = static_cast<std::uint32_t>(m_mesh.triangles[g][3 - a - b]);
      l.shared_corners[k] = static_cast<std::uint8_t>(a | (b << 2));
    }
    return l;
  }

  // a repropagate() without the whole mesh's links makes those of the faces it reaches
  Face_link link(std::size_t f) const { return m_links.empty() ? make_link(f) : m_links[f]; }

  // The list of face f: the propagation's, or in repropagate(), a copy of the table's made
  // when the face is first reached (apart, so that the first propagation's stays inline).
  Candidate_list& list(std::size_t f) { return m_table ? reached_list(f) : candidates[f]; }

  Candidate_list& reached_list(std::size_t f)
  {
    const std::pair<Reached*, bool> r = m_reached.insert(static_cast<std::uint32_t>(f));
    if(r.second)
    {
      r.first->index = static_cast<std::uint32_t>(m_local.size());
      const Candidate_range c = (*m_table)[f];
      m_local.push_back(Local_list{ Candidate_list(c.begin(), c.end()), f, false });
    }
    return m_local[r.first->index].list;
  }

  // The first propagation in `count` blocks (see the file's comment). Each block's faces are
  // touched by that block's front alone; the values are read concurrently.
  void run_in_blocks(std::size_t count)
  {
    m_block_of = face_blocks(m_mesh, count, m_parallel);
    std::vector<std::size_t> faces_of(count, 0);
    for(std::uint32_t b : m_block_of) ++faces_of[b];
    std::vector<Front> fronts(count);
    for(std::size_t b = 0; b < count; ++b) fronts[b].block = static_cast<std::uint32_t>(b);
    // the sites' starts, each in its face's block, in site order
    std::vector<std::vector<std::pair<std::uint32_t, std::size_t> > > starts(count);
    for_each_start([&](std::uint32_t site, std::size_t f) { starts[m_block_of[f]].emplace_back(site, f); });
    auto no_ban = [](std::size_t, std::size_t) { return false; };
    for_each_chunk(count, 1, m_parallel, [&](std::size_t b, std::size_t, std::size_t) {
      for(const std::pair<std::uint32_t, std::size_t>& x : starts[b]) offer(fronts[b], x.first, x.second, Candidate::at_site);
      drain(fronts[b], no_ban, false);
    });
    std::size_t rounds = 1;
    std::vector<std::vector<Crossing> > inbox(count);
    for(;;)
    {
      // what each block sent, by receiving block and in the order sent, senders in block order
      bool sent = false;
      for(Front& front : fronts)
      {
        std::stable_sort(front.outbox.begin(), front.outbox.end(),
                         [&](const Crossing& a, const Crossing& b) { return m_block_of[a.face] < m_block_of[b.face]; });
        for(const Crossing& x : front.outbox) inbox[m_block_of[x.face]].push_back(x);
        sent = sent || !front.outbox.empty();
        std::vector<Crossing>().swap(front.outbox);
      }
      if(!sent) break;
      ++rounds;
      for_each_chunk(count, 1, m_parallel, [&](std::size_t b, std::size_t, std::size_t) {
        if(inbox[b].empty()) return;
        Front& front = fronts[b];
        for(const Crossing& c : inbox[b])
        {
          if(find_site(candidates[c.face], c.site)) continue;   // offered before
          Candidate x(c.site, c.value, static_cast<std::uint8_t>((c.fresh + 1) % 3));
          x.value[c.fresh] = m_fields.value(c.site, m_mesh.triangles[c.face][c.fresh]);
          queue_unless_dominated(front, x, c.face);
        }
        std::vector<Crossing>().swap(inbox[b]);
        drain(front, no_ban, false);
      });
    }
    for(const Front& front : fronts) statistics.add(front.statistics);
    statistics.blocks = count;
    statistics.rounds = rounds;
    std::vector<std::uint32_t>().swap(m_block_of);
  }

  // Offers the field of `site` to face `f`, unless offered before, as brought across local
  // edge `from_edge` of f.
  void offer(Front& front, std::uint32_t site, std::size_t f, std::uint8_t from_edge)
  {
    if(find_site(list(f), site)) return;
    Candidate x(site, field_values(site, f), from_edge);
    queue_unless_dominated(front, x, f);
  }

  // Offers the field of the candidate `from` across local edge k of its face, whose links are
  // `l` (carried_across()). Into another block, the offer goes to the outbox.
  void offer_across(Front& front, const Candidate& from, const Face_link& l, int k)
  {
    const std::size_t f = l.neighbor[k];
    const int a = l.shared_corners[k] & 3, b = l.shared_corners[k] >> 2, fresh = 3 - a - b;
    if(!m_block_of.empty() && m_block_of[f] != front.block)
    {
      Crossing c;
      c.value[a] = from.value[k];
      c.value[b] = from.value[(k + 1) % 3];
      c.value[fresh] = 0.;
      c.site = from.site;
      c.face = static_cast<std::uint32_t>(f);
      c.fresh = static_cast<std::uint8_t>(fresh);
      front.outbox.push_back(c);
      return;
    }
    if(find_site(list(f), from.site)) return;
    queue_unless_dominated(front, carried_across(from, l, k), f);
  }

  // The field of candidate `from` of a face, as brought across its local edge k into the
  // neighbour there (`l`: the face's links): its values at the two shared corners are taken
  // instead of computed again (the same numbers: the field is a function of the vertex), which
  // spares two of three lookups of a vertex's coordinates; the edge brought across is the one
  // opposite the corner not shared.
  Candidate carried_across(const Candidate& from, const Face_link& l, int k) const
  {
    const int a = l.shared_corners[k] & 3, b = l.shared_corners[k] >> 2, fresh = 3 - a - b;
    Candidate x(from.site, {{ 0., 0., 0. }}, edge_brought_across(l, k));
    x.value[a] = from.value[k];
    x.value[b] = from.value[(k + 1) % 3];
    x.value[fresh] = m_fields.value(from.site, l.fresh_vertex[k]);
    return x;
  }

  // the local edge of the neighbour across local edge k: the one opposite its corner not shared
  static std::uint8_t edge_brought_across(const Face_link& l, int k)
  {
    const int a = l.shared_corners[k] & 3, b = l.shared_corners[k] >> 2;
    return static_cast<std::uint8_t>((3 - a - b + 1) % 3);
  }

  void queue_unless_dominated(Front& front, const Candidate& x, std::size_t f)
  {
    // lists only grow: a field dominated now stays dominated, so do not queue it
    Candidate_list& list = this->list(f);
    if(dominated_in(list, x)) return;
    // past the inline room, the room doubles (boost's growth factor would reallocate at
    // every candidate of the usual three or four)
    if(list.size() == list.capacity()) list.reserve(2 * list.capacity());
    list.push_back(x);
    list.back().from_edge = static_cast<std::uint8_t>(x.from_edge | waiting);
    front.queue.push_back(Event{ (std::min)((std::min)(x.value[0], x.value[1]), x.value[2]), x.site, static_cast<std::uint32_t>(f) });
    std::push_heap(front.queue.begin(), front.queue.end(), Later());
  }

  // repropagate(): face f's list changes (its copy is written back to the table)
  void mark_touched(std::size_t f)
  {
    Local_list& x = m_local[m_reached.find(static_cast<std::uint32_t>(f))->index];
    if(x.touched) return;
    x.touched = true;
    if(m_sites_before)
      for(const Candidate& c : x.list)
        if(!is_waiting(c)) m_sites_before->push_back(c.site);
  }

  template <class Banned>
  void drain(Front& front, const Banned& banned, bool mark)
  {
    auto& queue = front.queue;
    while(!queue.empty())
    {
      std::pop_heap(queue.begin(), queue.end(), Later());
      const Event e = queue.back();
      queue.pop_back();
      ++front.statistics.events;
      Candidate_list& list = this->list(e.face);
      Candidate* entry = find_site(list, e.site);
      CGAL_assertion(entry != nullptr && is_waiting(*entry));
      if(dominated_in(list, *entry))
      {
        list.erase(list.begin() + (entry - list.data()));
        continue;
      }
      if(mark) mark_touched(e.face);
      entry->from_edge = static_cast<std::uint8_t>(entry->from_edge & ~waiting);
      const Candidate x = *entry;
      ++front.statistics.admitted;
      const Face_link l = link(e.face);
      for(int k = 0; k < 3; ++k)
        if(l.neighbor[k] != no_link && !banned(e.site, l.neighbor[k])) offer_across(front, x, l, k);
    }
    if(&front == &m_front) statistics.add(front.statistics), front.statistics = Propagation_statistics();
    // The queue's buffers grow to the front's widest extent (hundreds of megabytes on millions
    // of faces) and would be held through cutting and stitching: a repair's propagation is
    // local and grows its own.
    std::vector<Event>().swap(queue);
  }

  const Mesh& m_mesh;
  const Fields& m_fields;
  const std::vector<std::size_t>& m_site_faces;
  const std::vector<std::pair<std::size_t, std::size_t> >& m_breakline_site_faces;
  Blocked m_blocked;
  bool m_parallel;
  std::size_t m_faces_per_block = faces_per_block, m_sites_per_block = sites_per_block;
  std::vector<Face_link> m_links;   // the breaklines are in them: no link across one
  Front m_front;                    // the global order's (the first propagation's without blocks, the repair's)
  std::vector<std::uint32_t> m_block_of;   // during a run in blocks
  std::vector<std::uint32_t>* m_sites_before = nullptr;   // during repropagate()
  // repropagate()'s copies of the lists of the faces it reached, by face
  struct Reached
  {
    std::uint32_t key;
    std::uint32_t index;   // into m_local
  };
  struct Local_list
  {
    Candidate_list list;
    std::size_t face;
    bool touched;   // changed: written back
  };
  Candidate_table* m_table = nullptr;
  Flat_hash_table<Reached> m_reached;
  std::deque<Local_list> m_local;
};

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_PROPAGATION_H
