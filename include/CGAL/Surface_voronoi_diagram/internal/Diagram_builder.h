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
#include <CGAL/Surface_voronoi_diagram/internal/Cell_components.h>
#include <CGAL/Surface_voronoi_diagram/internal/Cell_repair.h>
#include <CGAL/Surface_voronoi_diagram/internal/Cut_cell_measures.h>
#include <CGAL/Surface_voronoi_diagram/internal/Diagram_data.h>
#include <CGAL/Surface_voronoi_diagram/internal/Face_cuts.h>
#include <CGAL/Surface_voronoi_diagram/internal/Propagation.h>
#include <CGAL/Surface_voronoi_diagram/internal/Stage_times.h>
#include <CGAL/Surface_voronoi_diagram/internal/Symbolic_cell_check.h>
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
// `ForRelaxation`: whether it may ask for Lloyd's warm start and cells-only diagrams. Without
// them, the paths they take are not compiled in.
template <class TriangleMesh, class Fields, bool MaySelectGlobally = true, bool ForRelaxation = true>
class Diagram_builder
{
public:
  typedef Indexed_mesh<TriangleMesh> Mesh;

  Diagram_builder(Diagram_data<TriangleMesh>& data, const Fields& fields, const Builder_settings& settings,
                  const std::function<bool(double)>& callback, Stage_times* times)
    : m_data(data), m_mesh(*data.mesh), m_fields(fields), m_settings(settings), m_callback(callback), m_timer(times)
  {}

  /// computes the cells; returns false if the callback stopped it
  bool run()
  {
    Diagram_data<TriangleMesh>& d = m_data;
    const std::size_t n = d.sites.size();
    std::vector<std::size_t> site_faces(n);
    for(std::size_t i = 0; i < n; ++i) site_faces[i] = d.sites[i].face;
    Banned_fields banned(m_mesh.number_of_faces());
    const bool global_nearest = use_global_nearest();
    auto is_blocked = [&](std::size_t f, int k) { return !d.breaklines.empty() && d.breaklines.is_blocked(m_mesh.edges[f][k]); };
    auto is_banned = [&](std::size_t site, std::size_t f) { return banned.contains(site, f); };

    d.statistics = Diagram_statistics();
    d.statistics.sites = n;
    d.statistics.merged_sites = d.number_of_merged_sites();
    d.statistics.surface_area = m_mesh.total_area;

    typedef Propagation<TriangleMesh, Fields, decltype(is_blocked)> Field_propagation;
    Field_propagation propagation(m_mesh, m_fields, site_faces, d.breakline_site_faces, is_blocked, m_settings.parallel);
    // A lazy metric's value (a fast-marching front advanced) costs far more than a field's
    // crossing into another block, and smaller blocks keep their fronts in cache: blocks of a
    // quarter the size
    if(!std::is_same<Fields, Embedding_values>::value)
      propagation.set_block_sizes(Field_propagation::faces_per_block / 4, Field_propagation::sites_per_block);
    if(global_nearest)
      find_global_nearest(propagation.candidates);
    else if(!start_from_previous(propagation))
      propagation.run();
    m_fields.propagation_done();
    m_timer.stop("propagation");
    if(!progress(0.4)) return false;

    m_cuts.reset(m_mesh.number_of_faces());
    cut_faces(propagation.candidates, nullptr);
    d.statistics.propagation_events = propagation.statistics.events;
    d.statistics.admitted_fields = propagation.statistics.admitted;
    d.statistics.propagation_blocks = propagation.statistics.blocks;
    d.statistics.propagation_rounds = propagation.statistics.rounds;
    m_timer.stop("cutting");
    if(!progress(0.7)) return false;

    // The repair rounds decide on the cuts, and the partition is stitched once, after them
    // (see Symbolic_cell_check.h). The check on the stitched partition runs where the cuts
    // cannot decide (an exact tie), and where stitching welded or dropped what the cuts keep
    // apart (features below double precision); its rounds then go on from there.
    std::vector<std::size_t> dirty, touched;
    auto blocked_edge = [&](std::size_t e) { return d.breaklines.is_blocked(e); };
    std::size_t round = 0;
    bool first_check_done = false, decided_on_cuts = false;
    std::vector<std::size_t> regions_of_site;
    // the sites a repair round can have changed: those on the faces it touched, before or after
    std::vector<std::uint32_t> sites_before;
    std::vector<std::uint8_t> affected;
    // a repair round, once the banned fields' faces are in `dirty`
    auto repair_round = [&]() {
      sites_before.clear();
      propagation.repropagate(dirty, is_banned, touched, &sites_before);
      cut_faces(propagation.candidates, &touched);
      affected.assign(n, 0);
      for(std::uint32_t s : sites_before) affected[s] = 1;
      for(std::size_t f : touched)
        for(const Candidate& x : propagation.candidates[f]) affected[x.site] = 1;
      d.statistics.repair_rounds = round + 1;
      d.statistics.banned_fields = banned.size();
    };
    auto round_done = [&]() { return progress(0.7 + 0.25 * double(round + 1) / double(round + 2)); };
    if(!global_nearest && m_settings.repair)
    {
      Symbolic_cell_check<TriangleMesh> check(m_mesh, propagation.candidates, m_cuts, &d.breakline_site_faces);
      std::vector<std::pair<std::size_t, std::size_t> > orphans;
      for(;; ++round)
      {
        // in proportion to what is broken: the first round follows the propagation's links,
        // the later ones search the sites a repair changed
        std::size_t broken = 0;
        const bool decided = (round == 0)
            ? check.run_from_links(d.sites, blocked_edge, broken, orphans, regions_of_site, m_settings.parallel)
            : check.run_on_sites(d.sites, touched, affected, blocked_edge, broken, orphans, regions_of_site);
        if(!decided && !check.run(d.sites, blocked_edge, broken, orphans, nullptr, &regions_of_site, m_settings.parallel))
          break;
        if(!first_check_done) d.statistics.broken_cells_before_repair = broken;
        first_check_done = true;
        decided_on_cuts = (broken == 0);
        if(broken == 0 || round >= m_settings.max_repair_rounds) break;
        dirty.clear();
        for(const std::pair<std::size_t, std::size_t>& x : orphans)
        {
          banned.insert(x.first, x.second);
          if(dirty.empty() || dirty.back() != x.second) dirty.push_back(x.second);
        }
        repair_round();
        if(!round_done()) return false;
      }
    }
    m_timer.stop("repair");
    if constexpr(ForRelaxation)
    {
      if(m_settings.cells_only && decided_on_cuts)
        return measure_on_cuts(propagation.candidates, regions_of_site);
    }
    propagation.release_working_state();   // a repair after stitching builds it again
    // packed for stitching, where the memory peaks; a repair after it unpacks them
    d.candidates = Candidate_table(std::move(propagation.candidates), m_settings.parallel);
    // what the candidates alone decide (the vertices' owners) beside the stitching's naming
    // of the vertices, which runs on one thread: the two write to different arrays
    stitch(m_mesh, d.candidates, m_cuts, d.partition, m_settings.parallel, [&]() { summarize_candidates(); });
    m_timer.stop("cutting");

    bool restitched = false;
    for(;; ++round)
    {
      if(decided_on_cuts && d.partition.welded_vertices == 0 && d.partition.dropped_pieces == 0)
      {
        d.statistics.broken_cells = 0;
        break;
      }
      decided_on_cuts = false;   // from here on, the stitched partition decides
      const Cell_components components = cell_components(m_mesh, d.partition, n, blocked_edge, nullptr, m_settings.parallel, &d.breakline_site_faces);
      regions_of_site.assign(n, 0);
      for(std::size_t i = 0; i < n; ++i) regions_of_site[i] = components.site_components[i].size();
      const std::size_t broken = number_of_broken_cells(components);
      if(!first_check_done) d.statistics.broken_cells_before_repair = broken;
      first_check_done = true;
      d.statistics.broken_cells = broken;
      if(broken == 0 || global_nearest || !m_settings.repair || round >= m_settings.max_repair_rounds)
        break;
      ban_orphan_pieces(d.sites, d.partition, components, banned, dirty);
      propagation.candidates = d.candidates.to_lists();
      d.candidates.clear();
      repair_round();
      d.candidates = Candidate_table(std::move(propagation.candidates), m_settings.parallel);
      stitch(m_mesh, d.candidates, m_cuts, d.partition, m_settings.parallel);
      restitched = true;
      if(!round_done()) return false;
    }
    if(restitched) summarize_candidates();   // the candidates a repair changed
    m_timer.stop("repair");
    // the cells' areas: part of building the cells, whatever the repair did (timed as repair)
    summarize(regions_of_site);
    m_timer.stop("cutting");
    return progress(1.);
  }

private:
  static const Embedding_values* embedding_of(const Embedding_values& fields) { return &fields; }
  template <class Lazy>
  static const Embedding_values* embedding_of(const Lazy&) { return nullptr; }

  bool progress(double fraction) const { return !m_callback || m_callback(fraction); }

  // Lloyd's diagrams: the cuts have decided that every cell is whole, and the measures of the
  // cells are taken on them, without a partition
  bool measure_on_cuts(Candidate_lists& candidates, const std::vector<std::size_t>& regions_of_site)
  {
    Diagram_data<TriangleMesh>& d = m_data;
    d.measures = Cut_cell_measurer<TriangleMesh>(m_mesh, candidates, m_cuts, d.sites, embedding_of(m_fields),
                                                 d.centroid_density.get()).run();
    d.statistics.broken_cells = 0;
    d.candidates = Candidate_table(std::move(candidates), m_settings.parallel);
    summarize_candidates();
    summarize(regions_of_site);
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

  void find_global_nearest(Candidate_lists& candidates) const
  {
    find_global_nearest(candidates, std::integral_constant<bool, MaySelectGlobally && std::is_same<Fields, Embedding_values>::value>());
  }
  void find_global_nearest(Candidate_lists& candidates, std::true_type) const
  {
    global_nearest_candidates(m_mesh, m_fields, m_data.sites.size(), m_settings.has_weights, candidates);
  }
  void find_global_nearest(Candidate_lists&, std::false_type) const {}

  void cut_faces(const Candidate_lists& candidates, const std::vector<std::size_t>* which)
  {
    if(which)
      m_cuts.cut(candidates, which->size(), [which](std::size_t k) { return (*which)[k]; }, m_settings.parallel);
    else
      m_cuts.cut(candidates, m_mesh.number_of_faces(), [](std::size_t k) { return k; }, m_settings.parallel);
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
    s.unreached_components = 0;
    for(auto u : unreached_component) s.unreached_components += u;
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
  void summarize(const std::vector<std::size_t>& regions_of_site)
  {
    Diagram_data<TriangleMesh>& d = m_data;
    Diagram_statistics& s = d.statistics;
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
      d.cell_pieces[i] = regions_of_site[i];
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
  Face_cuts m_cuts;
};

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_DIAGRAM_BUILDER_H
