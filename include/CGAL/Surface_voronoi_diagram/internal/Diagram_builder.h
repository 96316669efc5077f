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
// The construction of a diagram, stage by stage: propagation (or the RVD's global
// candidates), cutting, stitching, the connectivity repair, and the per-site summary.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_DIAGRAM_BUILDER_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_DIAGRAM_BUILDER_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/parameters.h>
#include <CGAL/Surface_voronoi_diagram/internal/Cell_connectivity.h>
#include <CGAL/Surface_voronoi_diagram/internal/Cut_cell_measures.h>
#include <CGAL/Surface_voronoi_diagram/internal/Diagram_data.h>
#include <CGAL/Surface_voronoi_diagram/internal/Face_cuts.h>
#include <CGAL/Surface_voronoi_diagram/internal/Propagation.h>
#include <CGAL/Surface_voronoi_diagram/internal/Stage_times.h>
#include <CGAL/Surface_voronoi_diagram/internal/global_nearest.h>
#include <CGAL/Surface_voronoi_diagram/internal/parallel.h>
#include <CGAL/Surface_voronoi_diagram/internal/Stitching/Stitcher.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <functional>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

struct Builder_settings
{
  Candidate_selection candidates = Candidate_selection::PROPAGATION;
  bool repair = true;
  std::size_t max_repair_rounds = 100;
  bool has_weights = false;
  bool parallel = false;   // propagation blocks, cutting, stitching and checking in concurrent chunks (TBB)
  bool cells_only = false; // no vertex owners (Lloyd's diagrams)
  const Candidate_sites* previous = nullptr;   // Lloyd's: the candidates before the sites moved (embedding metrics)
};

// `MaySelectGlobally`: whether the caller may ask for GLOBAL_NEAREST candidates;
// `ForRelaxation`: whether it may ask for Lloyd's warm start and cells-only diagrams;
// `Updating`: whether it may call update(). Without them, the paths they take are not compiled in.
template <class TriangleMesh, class Fields, bool MaySelectGlobally = true, bool ForRelaxation = true, bool Updating = true>
class Diagram_builder
{
public:
  typedef Indexed_mesh<TriangleMesh> Mesh;

  Diagram_builder(Diagram_data<TriangleMesh>& data, const Fields& fields, const Builder_settings& settings,
                  const std::function<bool(double)>& callback, Stage_times* times)
    : m_data(data), m_mesh(*data.mesh), m_fields(fields), m_settings(settings), m_callback(callback), m_timer(times),
      m_blocked{ &m_mesh, &data.breaklines }, m_banned(m_mesh.number_of_faces())
  {}

  /// computes the cells; returns false if the callback stopped it
  bool run()
  {
    start_statistics();
    const std::vector<std::size_t> faces = site_faces();
    Field_propagation propagation(m_mesh, m_fields, faces, m_data.breakline_site_faces, m_blocked, m_settings.parallel);
    propagate(propagation);
    if(!progress(0.4)) return false;
    m_cuts.reset(m_mesh.number_of_faces());
    cut_faces(nullptr);
    m_timer.stop("cutting");
    if(!progress(0.7)) return false;

    Cell_connectivity cells(m_data.sites, m_data.breakline_site_faces);
    return repair_and_stitch(propagation, cells, 0);
  }

  /// Computes the cells again after the sites `changed` marks moved (the caller passes
  /// unweighted moves only), from the candidates, cuts and bans of the previous computation,
  /// the partition then stitched again around the faces cut again: the changed fields leave
  /// every face and start again from their sites, the faces that lost one are refilled from
  /// their neighbours (`Propagation::repropagate()`, which stops where a kept field
  /// dominates), those whose lists changed are cut again, and the cells they hold are checked
  /// and repaired as after a repair round. The result is the fresh diagram's: the lower
  /// envelope of each face's candidates, with the same bans. Computes afresh (`run()`) where
  /// the previous computation left cells broken. False if the callback stopped it.
  bool update(const std::vector<std::uint8_t>& changed)
  {
    Diagram_data<TriangleMesh>& d = m_data;
    const std::size_t nf = m_mesh.number_of_faces();
    if(d.cuts.number_of_faces() != nf || d.statistics.broken_cells != 0 || use_global_nearest())
    {
      d.clear_cells();
      return run();
    }
    Cell_connectivity cells(d.sites, d.breakline_site_faces);
    cells.regions_of_site = d.cell_pieces;
    start_statistics();
    const std::vector<std::size_t> faces = site_faces();
    Field_propagation propagation(m_mesh, m_fields, faces, d.breakline_site_faces, m_blocked, m_settings.parallel);
    m_cuts = std::move(d.cuts);
    m_banned = std::move(d.banned);
    m_recut.assign(nf, 0);
    if(d.recut_faces > nf)   // the old pieces of faces cut again as many as the live ones: all cut again
    {
      m_cuts.reset(nf);
      cut_faces(nullptr);
      d.recut_faces = 0;
    }
    // the faces that hold a changed field or a changed site lose their bans too
    std::vector<std::size_t> dirty;
    for(std::size_t f = 0; f < nf; ++f)
      for(const Candidate& x : d.candidates[f])
        if(changed[x.site])
        {
          dirty.push_back(f);
          break;
        }
    propagation.for_each_start([&](std::size_t site, std::size_t f) {
      if(changed[site]) dirty.push_back(f);
    });
    std::sort(dirty.begin(), dirty.end());
    dirty.erase(std::unique(dirty.begin(), dirty.end()), dirty.end());
    m_banned.erase_if([&](std::size_t site, std::size_t f) { return changed[site] || std::binary_search(dirty.begin(), dirty.end(), f); });
    std::vector<std::uint32_t> sites_before;
    propagation.repropagate(d.candidates, dirty, is_banned(), m_touched, &sites_before, &changed);
    m_fields.propagation_done();
    d.statistics.propagation_events = propagation.statistics.events;
    m_timer.stop("propagation");
    cut_faces(&m_touched);
    d.recut_faces += m_touched.size();
    // the cells with a piece in a face cut again, before or after; the others are as they were
    m_affected = changed;
    for(std::uint32_t s : sites_before) m_affected[s] = 1;
    for(std::size_t f : m_touched)
      for(const Candidate& x : d.candidates[f]) m_affected[x.site] = 1;
    return repair_and_stitch(propagation, cells, 1);
  }

private:
  // whether mesh edge e, or local edge k of face f, is a breakline
  struct Blocked
  {
    const Mesh* mesh;
    const Breaklines* breaklines;
    bool operator()(std::size_t e) const { return !breaklines->empty() && breaklines->is_blocked(e); }
    bool operator()(std::size_t f, int k) const { return (*this)(mesh->edges[f][k]); }
  };
  typedef Propagation<TriangleMesh, Fields, Blocked> Field_propagation;

  // The repair rounds decide on the cuts, and the partition is stitched once, after them.
  // From a round the cuts cannot decide (an exact tie, a broken weighted site outside its
  // cell), or where stitching welded or dropped what the cuts keep apart, the stitched
  // partition decides, stitched again after each round. Round 0 checks every cell, a later
  // one those the previous round (or an update) changed.
  bool repair_and_stitch(Field_propagation& propagation, Cell_connectivity& cells, std::size_t first_round)
  {
    bool on_partition = !repairs();
    for(std::size_t round = first_round;; ++round)
    {
      const bool decided = !on_partition && check_cuts(cells, round);
      if(!decided || cells.broken == 0 || round >= m_settings.max_repair_rounds)   // the partition decides, or is the result
      {
        if constexpr(ForRelaxation)
          if(decided && cells.broken == 0 && m_settings.cells_only) return measure_on_cuts(cells);
        stitch_partition();
        const Partition& partition = m_data.partition;
        on_partition = !decided || cells.broken != 0 || partition.welded_vertices != 0 || partition.dropped_pieces != 0;
        if(on_partition) cells.check(Stitched_pieces<TriangleMesh, Blocked>(m_mesh, partition, m_blocked), nullptr, m_settings.parallel);
      }
      if(round == 0) m_data.statistics.broken_cells_before_repair = cells.broken;
      if(cells.broken == 0 || !repairs() || round >= m_settings.max_repair_rounds) break;
      repair(propagation, cells.orphans, round);
      if(!progress(0.7 + 0.25 * double(round + 1) / double(round + 2))) return false;
    }
    m_timer.stop("repair");
    // the cells' areas: part of building the cells, whatever the repair did
    summarize(cells);
    m_data.cuts = std::move(m_cuts);
    m_data.banned = std::move(m_banned);
    if(first_round == 0) m_data.recut_faces = 0;
    m_timer.stop("cutting");
    return progress(1.);
  }

  static const Embedding_values* embedding_of(const Embedding_values& fields) { return &fields; }
  template <class Lazy>
  static const Embedding_values* embedding_of(const Lazy&) { return nullptr; }

  bool progress(double fraction) const { return !m_callback || m_callback(fraction); }
  // one type for the repair's and the update's refilling: one instantiation of it
  auto is_banned() const { return [this](std::size_t site, std::size_t f) { return m_banned.contains(site, f); }; }
  bool repairs() const { return m_settings.repair && !use_global_nearest(); }

  void start_statistics()
  {
    Diagram_statistics& s = m_data.statistics;
    s = Diagram_statistics();
    s.sites = m_data.sites.size();
    s.merged_sites = m_data.number_of_merged_sites();
    s.surface_area = m_mesh.total_area;
  }

  std::vector<std::size_t> site_faces() const
  {
    std::vector<std::size_t> faces;
    for(const Site& site : m_data.sites) faces.push_back(site.face);
    return faces;
  }

  // the candidates of every face: the global nearest, or the propagation's
  void propagate(Field_propagation& propagation)
  {
    // A lazy metric's value (a fast-marching front advanced) costs far more than a field's
    // crossing into another block, and smaller blocks keep their fronts in cache: blocks of a
    // quarter the size
    if(!std::is_same<Fields, Embedding_values>::value)
      propagation.set_block_sizes(Field_propagation::faces_per_block / 4, Field_propagation::sites_per_block);
    if(use_global_nearest())
    {
      if constexpr(MaySelectGlobally && std::is_same<Fields, Embedding_values>::value)
        global_nearest_candidates(m_mesh, m_fields, m_data.sites.size(), m_settings.has_weights, propagation.candidates);
    }
    else if(!start_from_previous(propagation))
      propagation.run();
    m_fields.propagation_done();
    propagation.release_working_state();   // a repair's propagation makes the links it needs
    // packed for the stages after it; a repair replaces the lists it changes
    m_data.candidates = Candidate_table(std::move(propagation.candidates), m_settings.parallel);
    Diagram_statistics& s = m_data.statistics;
    s.propagation_events = propagation.statistics.events;
    s.admitted_fields = propagation.statistics.admitted;
    s.propagation_blocks = propagation.statistics.blocks;
    s.propagation_rounds = propagation.statistics.rounds;
    m_timer.stop("propagation");
  }

  // The check on the cuts, in proportion to what is broken: the first round searches the
  // sites the propagation's links suspect, a later one the sites the repair changed (every
  // other site was whole: a broken cell's orphans were banned, which touched their faces).
  // False where the cuts cannot decide.
  bool check_cuts(Cell_connectivity& cells, std::size_t round)
  {
    const Cut_pieces<TriangleMesh, Blocked> pieces(m_mesh, m_data.candidates, m_cuts, m_blocked);
    if(pieces.has_tie(round == 0 ? nullptr : &m_touched)) return false;
    if(round > 0) return cells.check(pieces, &m_affected, m_settings.parallel);
    // the sites no link suspects are whole, or empty
    for(std::size_t i = 0; i < m_data.sites.size(); ++i)
      cells.regions_of_site[i] = (pieces.piece_of(m_data.sites[i].face, i) != no_site) ? 1 : 0;
    m_affected.assign(m_data.sites.size(), 0);
    const bool few_breaks = pieces.find_suspects(m_affected, m_settings.parallel);
    return cells.check(pieces, few_breaks ? &m_affected : nullptr, m_settings.parallel);
  }

  void stitch_partition()
  {
    m_timer.stop("repair");
    // what the candidates alone decide (the vertices' owners) beside the stitching's naming
    // of the vertices, which runs on one thread: the two write to different arrays
    // an update's partition: the old one, stitched again around the faces cut again
    bool restitched = false;
    if constexpr(Updating)
      restitched = !m_recut.empty() && Stitcher<TriangleMesh>(m_mesh, m_data.candidates, m_cuts).run_on(m_data.partition, m_recut);
    if(restitched)
    {
      summarize_candidates();
      std::fill(m_recut.begin(), m_recut.end(), 0);
    }
    else
      stitch(m_mesh, m_data.candidates, m_cuts, m_data.partition, m_settings.parallel, [&]() { summarize_candidates(); });
    m_timer.stop("cutting");
  }

  // Bans the site of each orphan piece from the piece's face, refills the faces around with
  // the propagation and cuts them again; the sites on the faces it touched, before or after,
  // are those it can have changed.
  void repair(Field_propagation& propagation, const std::vector<std::pair<std::size_t, std::size_t> >& orphans, std::size_t round)
  {
    std::vector<std::size_t> dirty;
    for(const std::pair<std::size_t, std::size_t>& x : orphans)
    {
      m_banned.insert(x.first, x.second);
      if(dirty.empty() || dirty.back() != x.second) dirty.push_back(x.second);
    }
    std::vector<std::uint32_t> sites_before;
    propagation.repropagate(m_data.candidates, dirty, is_banned(), m_touched, &sites_before);
    cut_faces(&m_touched);
    m_affected.assign(m_data.sites.size(), 0);
    for(std::uint32_t s : sites_before) m_affected[s] = 1;
    for(std::size_t f : m_touched)
      for(const Candidate& x : m_data.candidates[f]) m_affected[x.site] = 1;
    m_data.statistics.repair_rounds = round + 1;
    m_data.statistics.banned_fields = m_banned.size();
  }

  // Lloyd's diagrams: the cuts have decided that every cell is whole, and the measures of the
  // cells are taken on them, without a partition
  bool measure_on_cuts(const Cell_connectivity& cells)
  {
    m_timer.stop("repair");
    Diagram_data<TriangleMesh>& d = m_data;
    d.measures = Cut_cell_measurer<TriangleMesh>(m_mesh, d.candidates, m_cuts, d.sites, embedding_of(m_fields),
                                                 d.centroid_density.get()).run();
    summarize_candidates();
    summarize(cells);
    m_timer.stop("cutting");
    return progress(1.);
  }

  // Lloyd's diagrams over an embedding start from the candidates before the sites moved
  template <class Field_propagation>
  bool start_from_previous(Field_propagation& propagation) const
  {
    if constexpr(ForRelaxation && std::is_same<Fields, Embedding_values>::value)
      if(m_settings.previous)
      {
        propagation.run_from(*m_settings.previous);
        return true;
      }
    return false;
  }

  bool use_global_nearest() const
  {
    if(!MaySelectGlobally || m_settings.candidates != Candidate_selection::GLOBAL_NEAREST) return false;
    CGAL_precondition_msg((std::is_same<Fields, Embedding_values>::value),
                          "the restricted Voronoi diagram (GLOBAL_NEAREST) needs an embedding metric");
    return std::is_same<Fields, Embedding_values>::value;
  }

  void cut_faces(const std::vector<std::size_t>* which)
  {
    const Candidate_table& candidates = m_data.candidates;
    if(which && !m_recut.empty())
      for(std::size_t f : *which) m_recut[f] = 1;
    // one instantiation of the cutting for both: every face, or those of `which`
    m_cuts.cut(candidates, which ? which->size() : m_mesh.number_of_faces(),
               [which](std::size_t k) { return which ? (*which)[k] : k; }, m_settings.parallel);
  }

  // The statistics of the candidate lists, and the vertices' owners: the lowest (value,
  // site) among the candidates of the faces around each vertex.
  void summarize_candidates()
  {
    Diagram_data<TriangleMesh>& d = m_data;
    Diagram_statistics& s = d.statistics;
    std::vector<std::uint8_t> unreached_component(m_mesh.number_of_components, 0);
    std::size_t total_candidates = 0, most = 0, unreached_faces = 0;
    for(std::size_t f = 0; f < m_mesh.number_of_faces(); ++f)
    {
      total_candidates += d.candidates[f].size();
      most = (std::max)(most, d.candidates[f].size());
      if(d.candidates[f].empty())
      {
        ++unreached_faces;
        unreached_component[m_mesh.face_component[f]] = 1;
      }
    }
    s.max_candidates_per_face = most;
    s.unreached_faces = unreached_faces;
    s.unreached_components = std::size_t(std::count(unreached_component.begin(), unreached_component.end(), 1));
    s.mean_candidates_per_face = double(total_candidates) / double(m_mesh.number_of_faces());
    if(m_settings.cells_only) return;

    d.vertex_site.assign(m_mesh.number_of_vertices(), no_site);
    std::vector<double> best(m_mesh.number_of_vertices(), 0.);
    for(std::size_t f = 0; f < m_mesh.number_of_faces(); ++f)
      for(const Candidate& x : d.candidates[f])
        for(int k = 0; k < 3; ++k)
        {
          const std::size_t v = m_mesh.triangles[f][k];
          if(d.vertex_site[v] == no_site || x.value[k] < best[v] || (x.value[k] == best[v] && x.site < d.vertex_site[v]))
          {
            d.vertex_site[v] = x.site;
            best[v] = x.value[k];
          }
        }
  }

  // The cells' areas and pieces, once the candidates are summarized.
  void summarize(const Cell_connectivity& cells)
  {
    Diagram_data<TriangleMesh>& d = m_data;
    Diagram_statistics& s = d.statistics;
    s.broken_cells = cells.broken;
    const std::size_t n = d.sites.size();
    d.cell_area.assign(n, 0.);
    d.cell_pieces.assign(n, 0);
    if(d.measures.valid)
    {
      d.cell_area = d.measures.area;
      s.unreached_area = d.measures.unreached_area;
    }
    for(const Partition::Piece& p : d.partition.pieces)
    {
      if(p.site == no_site) s.unreached_area += p.area;
      else d.cell_area[p.site] += p.area;
    }
    for(std::size_t i = 0; i < n; ++i)
    {
      d.cell_pieces[i] = cells.regions_of_site[i];
      if(d.cell_pieces[i] == 0) ++s.empty_cells;
      else ++s.cells;
      s.pieces += d.cell_pieces[i];
    }
    s.welded_vertices = d.partition.welded_vertices;
    s.inserted_vertices = d.partition.inserted_vertices;
  }

  Diagram_data<TriangleMesh>& m_data;
  const Mesh& m_mesh;
  const Fields& m_fields;
  Builder_settings m_settings;
  const std::function<bool(double)>& m_callback;
  Stage_timer m_timer;
  Blocked m_blocked;
  Face_cuts m_cuts;
  Banned_fields m_banned;
  std::vector<std::size_t> m_touched;      // the faces the last repair round refilled
  std::vector<std::uint8_t> m_recut;       // an update's: the faces cut again since the partition was stitched
  std::vector<std::uint8_t> m_affected;    // the sites the next check on the cuts searches
};

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_DIAGRAM_BUILDER_H
