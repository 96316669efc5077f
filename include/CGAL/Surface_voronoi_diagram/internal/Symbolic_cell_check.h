// Copyright (c) 2026 The Surface_voronoi_diagram authors.
// All rights reserved.
//
// This file is part of the Surface_voronoi_diagram package for CGAL (www.cgal.org).
//
// $URL$
// $Id$
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The connectivity check on the per-face cuts, before stitching. Stitching the whole mesh
// again after each repair round cost two thirds of a round (a round changes a few dozen
// faces), so the repair rounds decide on the cuts and the partition is stitched once, after
// them; the stitched check then confirms, and a disagreement falls back to stitched rounds.
//
// A site's piece of a face is convex (a lower envelope of affine fields), so a face holds at
// most one piece per site and a cell's pieces connect only across mesh edges: two pieces of a
// site in neighbouring faces are one region when their segments on the shared edge overlap
// with positive length. The segment ends are computed as the stitcher places them. A face
// where the cutter met an exact tie can have segments of zero length that the stitcher welds
// away, so with such a face anywhere the check declines and the caller stitches instead.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_SYMBOLIC_CELL_CHECK_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_SYMBOLIC_CELL_CHECK_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/internal/Candidate.h>
#include <CGAL/Surface_voronoi_diagram/internal/Disjoint_sets.h>
#include <CGAL/Surface_voronoi_diagram/internal/Face_cuts.h>
#include <CGAL/Surface_voronoi_diagram/internal/Indexed_mesh.h>
#include <CGAL/Surface_voronoi_diagram/internal/Partition.h>
#include <CGAL/Surface_voronoi_diagram/internal/Site.h>
#include <CGAL/Surface_voronoi_diagram/internal/parallel.h>
#include <CGAL/Surface_voronoi_diagram/internal/unite_face_by_face.h>

#include <boost/container/small_vector.hpp>

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

template <class TriangleMesh>
class Symbolic_cell_check
{
public:
  typedef Indexed_mesh<TriangleMesh> Mesh;

  /// `breakline_site_faces`, if given: the faces where the sites on breaklines start
  /// (`Breaklines::faces_of_sites_on_breaklines()`), whose pieces of such a site are one
  /// region through the site's location
  Symbolic_cell_check(const Mesh& mesh, const Candidate_lists& candidates, const Face_cuts& cuts,
                      const std::vector<std::pair<std::size_t, std::size_t> >* breakline_site_faces = nullptr)
    : m_mesh(mesh), m_candidates(candidates), m_cuts(cuts), m_breakline_site_faces(breakline_site_faces)
  {}

  /// Finds the cells in several pieces. If it can decide (no face with an exact tie, and every
  /// broken cell holds its site's own location), returns true with their number in `broken`
  /// and, in `orphans`, the (site, face) of every piece outside its site's own region, in face
  /// order (what `ban_orphan_pieces()` bans on the stitched partition); otherwise returns false.
  ///
  /// When `site_pairs` is given, it receives the sites of every two pieces of different
  /// sites that share a stretch of a bisector or of a mesh edge (what `cell_components()`
  /// gives on the stitched partition), and `regions_of_site` the number of regions of each
  /// site. With `parallel`, the faces are visited in concurrent chunks whose findings are
  /// merged in chunk order: the same result, in the same order.
  template <class Blocked_edge>
  bool run(const std::vector<Site>& sites, const Blocked_edge& blocked_edge, std::size_t& broken,
           std::vector<std::pair<std::size_t, std::size_t> >& orphans,
           std::vector<std::pair<std::size_t, std::size_t> >* site_pairs = nullptr,
           std::vector<std::size_t>* regions_of_site = nullptr, bool parallel = false)
  {
    orphans.clear();
    const std::size_t nf = m_mesh.number_of_faces();
    if(!number_pieces()) return false;
    Disjoint_sets regions(m_site_of_piece.size());
    if(site_pairs) site_pairs->clear();
    unite_face_by_face(nf, parallel, regions, site_pairs, [&](std::size_t begin, std::size_t end, Union_sink& out) {
      for(std::size_t f = begin; f < end; ++f)
      {
        if(out.wants_pairs()) bisector_pairs(f, out);
        for(int k = 0; k < 3; ++k)
        {
          const std::size_t g = m_mesh.neighbors[f][k];
          if(g == Mesh::none || g < f) continue;
          across(f, k, g, !blocked_edge(m_mesh.edges[f][k]), out);
        }
      }
    });

    if(m_breakline_site_faces)
      for(const std::pair<std::size_t, std::size_t>& x : *m_breakline_site_faces)
      {
        const std::size_t own = piece_of(sites[x.first].face, x.first), side = piece_of(x.second, x.first);
        if(own != no_site && side != no_site) regions.unite(own, side);
      }

    // the regions of each site, in the order of their first piece
    const std::size_t n = sites.size();
    std::vector<std::size_t> root_of_first(n, no_site);
    std::vector<std::uint8_t> is_broken(n, 0);
    broken = 0;
    if(regions_of_site) regions_of_site->assign(n, 0);
    for(std::size_t p = 0; p < m_site_of_piece.size(); ++p)
    {
      const std::size_t s = m_site_of_piece[p];
      if(s == no_site) continue;
      const std::size_t r = regions.find(p);
      if(regions_of_site && r == p) ++(*regions_of_site)[s];   // a region's root is its smallest piece
      if(root_of_first[s] == no_site) root_of_first[s] = r;
      else if(root_of_first[s] != r && !is_broken[s]) { is_broken[s] = 1; ++broken; }
    }
    if(broken == 0) return true;
    // a broken cell keeps the region holding its site's location
    std::vector<std::size_t> own_region(n, no_site);
    for(std::size_t i = 0; i < n; ++i)
    {
      if(!is_broken[i]) continue;
      const std::size_t p = piece_of(sites[i].face, i);
      if(p == no_site) return false;   // a weighted site outside its cell: the largest region is kept, by area
      own_region[i] = regions.find(p);
    }
    for(std::size_t f = 0; f < nf; ++f)
      for(std::size_t p = m_piece_begin[f]; p < m_piece_begin[f + 1]; ++p)
      {
        const std::size_t s = m_site_of_piece[p];
        if(s != no_site && is_broken[s] && regions.find(p) != own_region[s]) orphans.emplace_back(s, f);
      }
    return true;
  }

  /// The check of the first round, right after the first propagation (`Propagation::run()`),
  /// in proportion to what is broken. Each field came from the site's candidate in one
  /// neighbouring face, admitted before it (`Candidate::from_edge`), so these links lead back
  /// to the sites' faces. A piece is rooted when every piece on its way back overlaps the
  /// next one on their shared edge; a rooted piece is connected to its site's piece in the
  /// site's face. A piece whose link does not hold (a "break": its field came from a face
  /// where the site has no piece, or one it does not overlap) that a short search through
  /// overlaps across edges (not breaklines) connects to a rooted piece is fine too; a site
  /// with a break that does not connect so is a suspect, and only the suspects' pieces are
  /// searched whole: their regions, and the pieces outside the region of the site's face.
  /// Gives what `run()` gives (without the neighbour pairs); false where `run()` must decide:
  /// a face met an exact tie, a suspect has no piece in its own face, or the breaks are many.
  /// Not to be called after repair rounds, whose refilled faces break the order of the links.
  template <class Blocked_edge>
  bool run_from_links(const std::vector<Site>& sites, const Blocked_edge& blocked_edge, std::size_t& broken,
                      std::vector<std::pair<std::size_t, std::size_t> >& orphans,
                      std::vector<std::size_t>& regions_of_site, bool parallel) const
  {
    const std::size_t nf = m_mesh.number_of_faces(), n = sites.size();
    const std::size_t chunk = 4096;
    // the faces whose cut is degenerate (an exact tie), one mark per chunk of them
    std::vector<std::uint8_t> tie(number_of_chunks(nf, chunk), 0);
    // in face order, as binary searches want
    const std::vector<Piece_ref> breaks = gather_in_chunk_order<Piece_ref>(nf, chunk, parallel,
        [&](std::size_t begin, std::size_t end, std::vector<Piece_ref>& found) {
      for(std::size_t f = begin; f < end; ++f)
      {
        const Face_cuts::Cut cut = m_cuts[f];
        if(cut.degenerate) tie[begin / chunk] = 1;
        // a face of one candidate keeps its edges whole (see joined_to_parent()): most faces
        if(cut.whole_face || m_candidates[f].empty()) continue;
        const std::size_t pieces = cut.pieces.size();
        for(std::size_t local = 0; local < pieces; ++local)
          if(!joined_to_parent(f, local))
            found.push_back(Piece_ref{ f, local });
      }
    });
    if(std::find(tie.begin(), tie.end(), std::uint8_t(1)) != tie.end()) return false;
    if(breaks.size() > 4096) return false;
    std::vector<std::uint8_t> suspect(n, 0);
    bool any_suspect = false;
    for(const Piece_ref& x : breaks)
    {
      const std::uint32_t site = candidate_of(x.face, x.local).site;
      if(!suspect[site] && !reaches_rooted_piece(x, breaks, blocked_edge)) suspect[site] = 1, any_suspect = true;
    }
    regions_of_site.assign(n, 0);
    for(std::size_t i = 0; i < n; ++i)
      regions_of_site[i] = (piece_in_face(sites[i].face, static_cast<std::uint32_t>(i)) != no_site) ? 1 : 0;
    broken = 0;
    orphans.clear();
    if(!any_suspect) return true;
    return search_whole(sites, suspect, blocked_edge, broken, orphans, regions_of_site);
  }

  /// The check of a later round, after `Propagation::repropagate()` refilled the faces
  /// `touched`. A site's cell is in one region or several by its own pieces alone, so only
  /// the sites `affected` (those with a candidate on a touched face, before or after) can have
  /// changed, and only their pieces are searched whole; `regions_of_site` holds the counts of
  /// the round before and gets theirs. Every other site was whole then: a broken cell's
  /// orphans were banned, which touched their faces. Gives what `run()` gives (without the
  /// neighbour pairs); false where `run()` must decide: a touched face met an exact tie, or a
  /// broken cell has no piece in its site's face.
  template <class Blocked_edge>
  bool run_on_sites(const std::vector<Site>& sites, const std::vector<std::size_t>& touched,
                    const std::vector<std::uint8_t>& affected, const Blocked_edge& blocked_edge, std::size_t& broken,
                    std::vector<std::pair<std::size_t, std::size_t> >& orphans,
                    std::vector<std::size_t>& regions_of_site) const
  {
    CGAL_precondition(regions_of_site.size() == sites.size() && affected.size() == sites.size());
    for(std::size_t f : touched)
      if(m_cuts[f].degenerate) return false;
    broken = 0;
    orphans.clear();
    return search_whole(sites, affected, blocked_edge, broken, orphans, regions_of_site);
  }

private:
  // The regions of each site in `which`, searched through all its pieces (from the one in its
  // site's face, which is region 0), into `regions_of_site`; their broken cells are counted in
  // `broken` and the pieces outside region 0 go to `orphans`, in face order. False if a broken
  // cell has no piece in its site's face.
  template <class Blocked_edge>
  bool search_whole(const std::vector<Site>& sites, const std::vector<std::uint8_t>& which, const Blocked_edge& blocked_edge,
                    std::size_t& broken, std::vector<std::pair<std::size_t, std::size_t> >& orphans,
                    std::vector<std::size_t>& regions_of_site) const
  {
    const std::size_t n = sites.size();
    std::vector<std::vector<Piece_ref> > pieces_of(n);
    for_each_piece_of(which, [&](std::size_t f, std::size_t local, std::uint32_t site) { pieces_of[site].push_back(Piece_ref{ f, local }); });
    std::vector<std::uint8_t> is_broken(n, 0);
    std::vector<std::vector<std::uint8_t> > in_own_region(n);
    for(std::size_t i = 0; i < n; ++i)
    {
      if(!which[i]) continue;
      const std::vector<Piece_ref>& pieces = pieces_of[i];
      const std::size_t own = piece_in_face(sites[i].face, static_cast<std::uint32_t>(i));
      std::vector<std::size_t> region(pieces.size(), no_site);
      std::size_t regions = 0;
      auto flood = [&](std::size_t first) {
        if(region[first] != no_site) return;
        std::vector<std::size_t> stack(1, first);
        region[first] = regions;
        while(!stack.empty())
        {
          const Piece_ref p = pieces[stack.back()];
          stack.pop_back();
          for_each_joined_neighbour(p, static_cast<std::uint32_t>(i), blocked_edge, [&](const Piece_ref& r) {
            const std::size_t j = std::size_t(std::lower_bound(pieces.begin(), pieces.end(), r) - pieces.begin());
            if(region[j] == no_site) { region[j] = regions; stack.push_back(j); }
          });
        }
      };
      auto index_of = [&](std::size_t f, std::size_t local) {
        return std::size_t(std::lower_bound(pieces.begin(), pieces.end(), Piece_ref{ f, local }) - pieces.begin());
      };
      if(own != no_site)
      {
        flood(index_of(sites[i].face, own));
        // a site on a breakline: its pieces on every side of it are its own region too
        for(auto r = breakline_faces_of(i); r.first != r.second; ++r.first)
        {
          const std::size_t side = piece_in_face(r.first->second, static_cast<std::uint32_t>(i));
          if(side != no_site) flood(index_of(r.first->second, side));
        }
        ++regions;
      }
      for(std::size_t j = 0; j < pieces.size(); ++j)
        if(region[j] == no_site) flood(j), ++regions;
      regions_of_site[i] = regions;
      if(regions > 1)
      {
        if(own == no_site) return false;   // a weighted site outside its cell: the largest region is kept, by area
        is_broken[i] = 1;
        ++broken;
        in_own_region[i].resize(pieces.size());
        for(std::size_t j = 0; j < pieces.size(); ++j) in_own_region[i][j] = (region[j] == 0);
      }
    }
    // the broken cells' pieces outside their site's region, in the order of their faces
    std::vector<std::pair<Piece_ref, std::size_t> > outside;
    for(std::size_t i = 0; i < n; ++i)
      if(is_broken[i])
        for(std::size_t j = 0; j < pieces_of[i].size(); ++j)
          if(!in_own_region[i][j]) outside.emplace_back(pieces_of[i][j], i);
    std::sort(outside.begin(), outside.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    for(const auto& x : outside) orphans.emplace_back(x.second, x.first.face);
    return true;
  }

  // Calls fn(f, local, site) for every piece of the sites `which` marks, in face order. Most
  // faces have no such candidate, and their cuts are not read.
  template <class Fn>
  void for_each_piece_of(const std::vector<std::uint8_t>& which, const Fn& fn) const
  {
    const std::size_t nf = m_mesh.number_of_faces();
    for(std::size_t f = 0; f < nf; ++f)
    {
      const Candidate_list& list = m_candidates[f];
      bool any = false;
      for(const Candidate& c : list) any |= (which[c.site] != 0);
      if(!any) continue;
      const Face_cuts::Cut cut = m_cuts[f];
      if(cut.whole_face)
      {
        if(which[list[0].site]) fn(f, std::size_t(0), list[0].site);
        continue;
      }
      for(std::size_t local = 0; local < cut.pieces.size(); ++local)
      {
        const std::uint32_t site = list[cut.pieces[local].candidate].site;
        if(which[site]) fn(f, local, site);
      }
    }
  }

  // the (site, face) pairs of site i in `m_breakline_site_faces`
  std::pair<const std::pair<std::size_t, std::size_t>*, const std::pair<std::size_t, std::size_t>*> breakline_faces_of(std::size_t i) const
  {
    typedef std::pair<std::size_t, std::size_t> Pair;
    if(!m_breakline_site_faces || m_breakline_site_faces->empty()) return { nullptr, nullptr };
    const Pair* begin = m_breakline_site_faces->data();
    const Pair* end = begin + m_breakline_site_faces->size();
    const Pair* first = std::lower_bound(begin, end, Pair(i, 0));
    const Pair* last = std::lower_bound(first, end, Pair(i + 1, 0));
    return { first, last };
  }

  // The index in face g's cut of the piece of `site`, or no_site.
  std::size_t piece_in_face(std::size_t g, std::uint32_t site) const
  {
    const Face_cuts::Cut cut = m_cuts[g];
    const Candidate_list& list = m_candidates[g];
    if(list.empty()) return no_site;
    if(cut.whole_face) return list[0].site == site ? 0 : no_site;
    for(std::size_t local = 0; local < cut.pieces.size(); ++local)
      if(list[cut.pieces[local].candidate].site == site) return local;
    return no_site;
  }

  // The local edge of face g shared with its neighbour f, or 3 if they share none.
  int edge_towards(std::size_t g, std::size_t f) const
  {
    int k = 0;
    while(k < 3 && m_mesh.neighbors[g][k] != f) ++k;
    return k;
  }

  // A piece, as its face and its index in the face's cut.
  struct Piece_ref
  {
    std::size_t face, local;
    bool operator==(const Piece_ref& o) const { return face == o.face && local == o.local; }
    bool operator<(const Piece_ref& o) const { return face < o.face || (face == o.face && local < o.local); }
  };

  const Candidate& candidate_of(std::size_t f, std::size_t local) const
  {
    const Face_cuts::Cut cut = m_cuts[f];
    return m_candidates[f][cut.whole_face ? 0 : cut.pieces[local].candidate];
  }

  // Whether pieces (f, a) and (g, b) overlap on the edge between f and g (local edge k of f).
  bool overlap(std::size_t f, std::size_t a, int k, std::size_t g, std::size_t b) const
  {
    const int kg = edge_towards(g, f);
    double lo_f, hi_f, lo_g, hi_g;
    return kg < 3 && segment_on_edge(f, a, k, lo_f, hi_f) && segment_on_edge(g, b, kg, lo_g, hi_g)
           && (std::max)(lo_f, lo_g) < (std::min)(hi_f, hi_g);
  }

  // In `up`, the piece of the same site in the face the field of piece (f, local) came from,
  // if the two overlap (JOINED); AT_SITE for a field that started in f.
  enum Link { JOINED, BROKEN, AT_SITE };
  Link parent(std::size_t f, std::size_t local, Piece_ref& up) const
  {
    const Candidate& x = candidate_of(f, local);
    if(x.from_edge == Candidate::at_site) return AT_SITE;
    const int k = x.from_edge;
    const std::size_t g = m_mesh.neighbors[f][k];
    if(g == Mesh::none) return BROKEN;
    const std::size_t q = piece_in_face(g, x.site);
    if(q == no_site || !overlap(f, local, k, g, q)) return BROKEN;
    up = Piece_ref{ g, q };
    return JOINED;
  }

  // Whether the link of piece (f, local) holds, read on f's side alone. After the first
  // propagation, the fields of two faces across an edge that is not a breakline have one lower
  // envelope along it: each face was offered every candidate of the other, and one it does not
  // keep is dominated there by one it keeps, so lies above it along the edge. The envelope's
  // pieces are decided exactly (a tie flags the face degenerate), so a site's stretch of the
  // edge, and the numbers that place it, are the same on both sides: the piece overlaps the
  // one its field came from exactly when its own stretch has positive length.
  bool joined_to_parent(std::size_t f, std::size_t local) const
  {
    const Candidate& x = candidate_of(f, local);
    if(x.from_edge == Candidate::at_site) return true;
    double lo, hi;
    return segment_on_edge(f, local, x.from_edge, lo, hi) && lo < hi;
  }

  // Whether the way back from piece p reaches its site's face without a break.
  bool is_rooted(Piece_ref p, const std::vector<Piece_ref>& breaks) const
  {
    for(std::size_t steps = 0; steps <= m_mesh.number_of_faces(); ++steps)
    {
      if(std::binary_search(breaks.begin(), breaks.end(), p)) return false;
      const Link link = parent(p.face, p.local, p);
      if(link == AT_SITE) return true;
      if(link == BROKEN) return false;
    }
    return false;
  }

  // Calls `visit(r)` for every piece r of `site` in a face across an edge of piece p that is
  // not a breakline, where the two overlap: the pieces p is connected to directly.
  template <class Blocked_edge, class Visit>
  void for_each_joined_neighbour(const Piece_ref& p, std::uint32_t site, const Blocked_edge& blocked_edge, const Visit& visit) const
  {
    for(int k = 0; k < 3; ++k)
    {
      const std::size_t g = m_mesh.neighbors[p.face][k];
      if(g == Mesh::none || blocked_edge(m_mesh.edges[p.face][k])) continue;
      const std::size_t q = piece_in_face(g, site);
      if(q != no_site && overlap(p.face, p.local, k, g, q)) visit(Piece_ref{ g, q });
    }
  }

  // Whether a short search through the pieces of the break's site that overlap across edges
  // (not breaklines) finds a rooted one.
  template <class Blocked_edge>
  bool reaches_rooted_piece(const Piece_ref& start, const std::vector<Piece_ref>& breaks, const Blocked_edge& blocked_edge) const
  {
    const std::uint32_t site = candidate_of(start.face, start.local).site;
    boost::container::small_vector<Piece_ref, 64> seen;
    seen.push_back(start);
    for(std::size_t next = 0; next < seen.size(); ++next)
    {
      const Piece_ref p = seen[next];
      if(next > 0 && is_rooted(p, breaks)) return true;
      for_each_joined_neighbour(p, site, blocked_edge, [&](const Piece_ref& r) {
        if(seen.size() < 64 && std::find(seen.begin(), seen.end(), r) == seen.end()) seen.push_back(r);
      });
    }
    return false;
  }

  // Pieces numbered face by face: a face nobody reached is one piece of no site. False if a
  // face met an exact tie.
  bool number_pieces()
  {
    const std::size_t nf = m_mesh.number_of_faces();
    m_piece_begin.assign(nf + 1, 0);
    m_site_of_piece.clear();
    m_site_of_piece.reserve(nf + nf / 2);
    for(std::size_t f = 0; f < nf; ++f)
    {
      if(m_cuts[f].degenerate) return false;
      m_piece_begin[f] = m_site_of_piece.size();
      const Candidate_list& list = m_candidates[f];
      if(list.empty())
        m_site_of_piece.push_back(no_site);
      else if(m_cuts[f].whole_face)
        m_site_of_piece.push_back(list[0].site);
      else
        for(const Face_cuts::Piece piece : m_cuts[f].pieces) m_site_of_piece.push_back(list[piece.candidate].site);
    }
    m_piece_begin[nf] = m_site_of_piece.size();
    return true;
  }

  std::size_t piece_of(std::size_t f, std::size_t site) const
  {
    for(std::size_t p = m_piece_begin[f]; p < m_piece_begin[f + 1]; ++p)
      if(m_site_of_piece[p] == site) return p;
    return no_site;
  }

  // The piece of face f with index `local` in it, and its segment on local edge k as
  // parameters along the mesh edge (from its lower vertex index); false if it has none.
  bool segment_on_edge(std::size_t f, std::size_t local, int k, double& lo, double& hi) const
  {
    const Face_cuts::Cut cut = m_cuts[f];
    if(cut.whole_face || cut.pieces.size() <= 1)
    {
      lo = 0.;
      hi = 1.;
      return true;
    }
    const Face_cuts::Piece piece = cut.pieces[local];
    const std::size_t m = piece.vertices.size();
    for(std::size_t j = 0; j < m; ++j)
    {
      const Piece_edge_support& s = piece.supports[j];
      if(!s.on_mesh_edge || s.local != k) continue;
      const double a = parameter(f, piece.candidate, piece.vertices[j], k);
      const double b = parameter(f, piece.candidate, piece.vertices[(j + 1) % m], k);
      lo = (std::min)(a, b);
      hi = (std::max)(a, b);
      return true;
    }
    return false;
  }

  // Where a vertex of a piece of `owner` lies along local edge k of face f, computed as the
  // stitcher places it.
  double parameter(std::size_t f, std::uint32_t owner, const Symbolic_vertex& v, int k) const
  {
    const std::size_t e = m_mesh.edges[f][k];
    const std::size_t va = m_mesh.edge_vertices[e][0], vb = m_mesh.edge_vertices[e][1];
    if(v.kind == Symbolic_vertex::CORNER)
      return m_mesh.triangles[f][v.local] == va ? 0. : 1.;
    const Candidate_list& list = m_candidates[f];
    const std::uint32_t s = list[owner].site, t = list[v.other].site;
    const double* lo = (s < t ? list[owner] : list[v.other]).value.data();
    const double* hi = (s < t ? list[v.other] : list[owner]).value.data();
    const int ca = m_mesh.corner_of(f, va), cb = m_mesh.corner_of(f, vb);
    const double da = lo[ca] - hi[ca], db = lo[cb] - hi[cb];
    const double u = da / (da - db);
    return (std::min)(1., (std::max)(0., u));
  }

  // the sites on both sides of every bisector stretch inside face f
  void bisector_pairs(std::size_t f, Union_sink& out) const
  {
    const Face_cuts::Cut cut = m_cuts[f];
    if(cut.whole_face || cut.pieces.size() <= 1) return;
    const Candidate_list& list = m_candidates[f];
    for(const Face_cuts::Piece piece : cut.pieces)
      for(const Piece_edge_support& support : piece.supports)
        if(!support.on_mesh_edge && piece.candidate < support.other)
          out.pair(list[piece.candidate].site, list[support.other].site);
  }

  // The pieces on both sides of local edge k of f (g across it) whose segments on the edge
  // overlap: one region if they are of one site and `connect`, a pair of neighbours if not.
  void across(std::size_t f, int k, std::size_t g, bool connect, Union_sink& out) const
  {
    // most faces are one piece, and a face in one piece is the whole triangle: no segments
    const std::size_t pf = m_piece_begin[f], pg = m_piece_begin[g];
    if(m_piece_begin[f + 1] == pf + 1 && m_piece_begin[g + 1] == pg + 1)
    {
      meet(pf, pg, connect, out);
      return;
    }
    const int kg = edge_towards(g, f);
    if(kg == 3) return;
    // each side's stretches on the edge, computed once
    struct Stretch { std::size_t piece; double lo, hi; };
    boost::container::small_vector<Stretch, 8> on_f, on_g;
    double lo, hi;
    for(std::size_t p = pf; p < m_piece_begin[f + 1]; ++p)
      if(segment_on_edge(f, p - pf, k, lo, hi)) on_f.push_back(Stretch{ p, lo, hi });
    for(std::size_t q = pg; q < m_piece_begin[g + 1]; ++q)
      if(segment_on_edge(g, q - pg, kg, lo, hi)) on_g.push_back(Stretch{ q, lo, hi });
    for(const Stretch& a : on_f)
      for(const Stretch& b : on_g)
        if((out.wants_pairs() || m_site_of_piece[a.piece] == m_site_of_piece[b.piece]) && (std::max)(a.lo, b.lo) < (std::min)(a.hi, b.hi))
          meet(a.piece, b.piece, connect, out);
  }

  void meet(std::size_t p, std::size_t q, bool connect, Union_sink& out) const
  {
    const std::size_t s = m_site_of_piece[p], t = m_site_of_piece[q];
    if(s != t)
      out.pair(s, t);
    else if(connect && s != no_site)
      out.unite(p, q);
  }

  const Mesh& m_mesh;
  const Candidate_lists& m_candidates;
  const Face_cuts& m_cuts;
  const std::vector<std::pair<std::size_t, std::size_t> >* m_breakline_site_faces;
  std::vector<std::size_t> m_piece_begin;
  std::vector<std::size_t> m_site_of_piece;
};

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_SYMBOLIC_CELL_CHECK_H
