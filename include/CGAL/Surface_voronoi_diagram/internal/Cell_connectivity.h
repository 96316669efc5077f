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
// "One site, one region": the connectivity check of the cells. Propagation keeps far-away
// islands out but does not by itself make every cell connected (a site admitted in a face
// where it wins nothing can still win beyond it), so each repair round finds the cells in
// several regions, bans the site of each orphan piece (outside its cell's principal region)
// from the piece's face, and re-runs the propagation locally from there.
//
// One check, on two views of the pieces: the per-face cuts (`Cut_pieces`), so that the repair
// rounds need no stitching, and the stitched partition (`Stitched_pieces`), which decides
// where the cuts cannot (an exact tie) and where stitching welded or dropped what the cuts
// keep apart (features below double precision).

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_CELL_CONNECTIVITY_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_CELL_CONNECTIVITY_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/internal/Bisector_points.h>
#include <CGAL/Surface_voronoi_diagram/internal/Candidate_table.h>
#include <CGAL/Surface_voronoi_diagram/internal/Disjoint_sets.h>
#include <CGAL/Surface_voronoi_diagram/internal/Face_cuts.h>
#include <CGAL/Surface_voronoi_diagram/internal/Indexed_mesh.h>
#include <CGAL/Surface_voronoi_diagram/internal/Partition.h>
#include <CGAL/Surface_voronoi_diagram/internal/Site.h>
#include <CGAL/Surface_voronoi_diagram/internal/parallel.h>

#include <boost/container/small_vector.hpp>

#include <algorithm>
#include <cstdint>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

/// The (site, face) pairs the repair excluded.
class Banned_fields
{
public:
  explicit Banned_fields(std::size_t number_of_faces = 0) : m_faces(number_of_faces) {}
  bool contains(std::size_t site, std::size_t face) const
  {
    return !m_set.empty() && m_set.count(std::uint64_t(site) * m_faces + face) != 0;
  }
  void insert(std::size_t site, std::size_t face) { m_set.insert(std::uint64_t(site) * m_faces + face); }
  std::size_t size() const { return m_set.size(); }
  /// forgets the pairs for which `drop(site, face)` is true
  template <class Drop>
  void erase_if(const Drop& drop)
  {
    for(auto it = m_set.begin(); it != m_set.end();)
      it = drop(std::size_t(*it / m_faces), std::size_t(*it % m_faces)) ? m_set.erase(it) : std::next(it);
  }

private:
  std::uint64_t m_faces;
  std::unordered_set<std::uint64_t> m_set;
};

/// The regions of the cells and their orphan pieces, on a view of the pieces (`Cut_pieces`,
/// `Stitched_pieces`) that names them by numbers ascending face by face and gives the pieces
/// of some sites with their sites, a piece's face and area (if it has one), and the pieces of
/// its site joined to it (across mesh edges that are not breaklines, or inside its face).
class Cell_connectivity
{
public:
  typedef std::vector<std::pair<std::size_t, std::size_t> > Site_faces;

  /// `breakline_site_faces`: the faces where the sites on breaklines start
  /// (`Breaklines::faces_of_sites_on_breaklines()`), whose pieces of such a site are one
  /// region through the site's location
  Cell_connectivity(const std::vector<Site>& sites, const Site_faces& breakline_site_faces)
    : regions_of_site(sites.size(), 0), m_sites(sites), m_breakline_site_faces(breakline_site_faces)
  {}

  /// Finds the regions of the cells of the sites `which` marks (all if null); the others keep
  /// their count in `regions_of_site`, and are taken for whole. A broken cell keeps the region
  /// of its site's location, or, for a weighted site outside its cell, its largest region:
  /// false if the view has no areas to choose it by. With `parallel`, the pieces are visited
  /// in concurrent chunks whose unions are merged in chunk order (a union's representative is
  /// the set's smallest piece, whatever the order of the unions): the same result.
  template <class Pieces>
  bool check(const Pieces& view, const std::vector<std::uint8_t>* which, bool parallel)
  {
    const std::size_t n = m_sites.size();
    auto searched = [&](std::size_t s) { return s != no_site && (!which || (*which)[s]); };
    std::vector<std::size_t> chosen, site;   // the pieces searched, ascending, and their sites
    view.for_each_piece(which, [&](std::size_t p, std::size_t s) {
      chosen.push_back(p);
      site.push_back(s);
    });
    const std::size_t m = chosen.size();
    const bool dense = (m == 0 || chosen.back() + 1 == m);   // every piece of a view numbered 0, 1, ...
    auto index = [&](std::size_t p) {
      return dense ? p : std::size_t(std::lower_bound(chosen.begin(), chosen.end(), p) - chosen.begin());
    };
    Disjoint_sets regions(m);
    auto join = [&](std::size_t begin, std::size_t end, auto&& unite) {
      for(std::size_t i = begin; i < end; ++i)
        if(site[i] != no_site)
          view.for_each_joined(chosen[i], [&](std::size_t q) { unite(i, index(q)); }, true);
    };
    typedef std::pair<std::size_t, std::size_t> Union;
    if(parallel)
    {
      for(const Union& u : gather_in_chunk_order<Union>(m, 8192, true, [&](std::size_t begin, std::size_t end, std::vector<Union>& found) {
            join(begin, end, [&](std::size_t a, std::size_t b) { found.emplace_back(a, b); });
          }))
        regions.unite(u.first, u.second);
    }
    else
      join(0, m, [&](std::size_t a, std::size_t b) { regions.unite(a, b); });
    // a site on a breakline: its pieces around its location are one region through it
    std::size_t first = no_site;
    for(std::size_t k = 0; k < m_breakline_site_faces.size(); ++k)
    {
      const std::size_t s = m_breakline_site_faces[k].first;
      if(k == 0 || s != m_breakline_site_faces[k - 1].first) first = no_site;
      const std::size_t p = searched(s) ? view.piece_of(m_breakline_site_faces[k].second, s) : no_site;
      if(p == no_site) continue;
      if(first == no_site) first = index(p);
      else regions.unite(first, index(p));
    }

    for(std::size_t s = 0; s < n; ++s)
      if(searched(s)) regions_of_site[s] = 0;
    for(std::size_t i = 0; i < m; ++i)
      if(regions.find(i) == i && site[i] != no_site) ++regions_of_site[site[i]];
    broken = 0;
    orphans.clear();
    std::vector<std::size_t> principal(n, no_site);
    for(std::size_t s = 0; s < n; ++s)
    {
      if(regions_of_site[s] <= 1) continue;
      ++broken;
      const std::size_t own = view.piece_of(m_sites[s].face, s);
      if(own != no_site) principal[s] = regions.find(index(own));
      else if(!Pieces::has_area) return false;
    }
    if(broken == 0) return true;
    if constexpr(Pieces::has_area)   // the largest region of a site outside its cell, the first of equal ones
    {
      std::vector<double> area(m, 0.);
      for(std::size_t i = 0; i < m; ++i) area[regions.find(i)] += view.area(chosen[i]);
      for(std::size_t i = 0; i < m; ++i)
      {
        const std::size_t s = site[i], r = regions.find(i);
        if(s != no_site && regions_of_site[s] > 1 && view.piece_of(m_sites[s].face, s) == no_site
           && (principal[s] == no_site || area[r] > area[principal[s]]))
          principal[s] = r;
      }
    }
    for(std::size_t i = 0; i < m; ++i)
    {
      const std::size_t s = site[i];
      if(s != no_site && regions_of_site[s] > 1 && regions.find(i) != principal[s]) orphans.emplace_back(s, view.face(chosen[i]));
    }
    return true;
  }

  std::vector<std::size_t> regions_of_site;
  std::size_t broken = 0;                                   // the cells in more than one region
  std::vector<std::pair<std::size_t, std::size_t> > orphans;   // (site, face) of the orphan pieces, in face order

private:
  const std::vector<Site>& m_sites;
  const Site_faces& m_breakline_site_faces;
};

/// The pieces of the per-face cuts, each named by its face and its index in the face's cut
/// (`face << 32 | index`), so that a check of a few sites reads the cuts of their faces only.
/// A site's piece of a face is convex (a lower envelope of affine fields), so a face holds at
/// most one piece per site and a cell's pieces join only across mesh edges: two pieces of a
/// site in neighbouring faces are joined when their segments on the shared edge overlap with
/// positive length, the segment ends computed as the stitcher places them. A face where the
/// cutter met an exact tie can have segments of zero length that the stitcher welds away: the
/// cuts do not decide then (`has_tie()`).
template <class TriangleMesh, class Blocked_edge>
class Cut_pieces
{
public:
  typedef Indexed_mesh<TriangleMesh> Mesh;
  static constexpr bool has_area = false;

  Cut_pieces(const Mesh& mesh, const Candidate_table& candidates, const Face_cuts& cuts, const Blocked_edge& blocked_edge)
    : m_mesh(mesh), m_candidates(candidates), m_cuts(cuts), m_blocked_edge(blocked_edge)
  {}

  std::size_t face(std::size_t p) const { return p >> 32; }
  double area(std::size_t) const { return 0.; }

  /// Calls `fn(p, site)` for the pieces of the sites `which` marks (all if null), ascending.
  template <class Fn>
  void for_each_piece(const std::vector<std::uint8_t>* which, const Fn& fn) const
  {
    for(std::size_t f = 0; f < m_mesh.number_of_faces(); ++f)
    {
      const Candidate_range list = m_candidates[f];
      bool any = !which;
      for(std::size_t j = 0; j < list.size() && !any; ++j) any = ((*which)[list[j].site] != 0);
      if(!any || list.empty()) continue;   // most faces, for a few sites: their cuts are not read
      const Face_cuts::Cut cut = m_cuts[f];
      const std::size_t count = cut.whole_face ? 1 : cut.pieces.size();
      for(std::size_t local = 0; local < count; ++local)
      {
        const std::uint32_t site = list[cut.whole_face ? 0 : cut.pieces[local].candidate].site;
        if(!which || (*which)[site]) fn(f << 32 | local, std::size_t(site));
      }
    }
  }

  std::size_t piece_of(std::size_t f, std::size_t site) const
  {
    const Face_cuts::Cut cut = m_cuts[f];
    const Candidate_range list = m_candidates[f];
    if(list.empty()) return no_site;
    if(cut.whole_face) return list[0].site == site ? f << 32 : no_site;
    for(std::size_t local = 0; local < cut.pieces.size(); ++local)
      if(list[cut.pieces[local].candidate].site == site) return f << 32 | local;
    return no_site;
  }

  /// whether one of `faces` (all if null) met an exact tie
  bool has_tie(const std::vector<std::size_t>* faces) const
  {
    const std::size_t count = faces ? faces->size() : m_mesh.number_of_faces();
    for(std::size_t k = 0; k < count; ++k)
      if(m_cuts[faces ? (*faces)[k] : k].degenerate) return true;
    return false;
  }

  /// Calls `visit(q)` for every piece q of p's site (after p, if `later_only`) in a face across
  /// an edge of p that is not a breakline, where the two overlap.
  template <class Visit>
  void for_each_joined(std::size_t p, const Visit& visit, bool later_only = false) const
  {
    const std::size_t f = face(p), site = candidate_of(p).site;
    for(int k = 0; k < 3; ++k)
    {
      const std::size_t g = m_mesh.neighbors[f][k];
      if(g == Mesh::none || (later_only && g < f) || m_blocked_edge(m_mesh.edges[f][k])) continue;
      const std::size_t q = piece_of(g, site);
      if(q != no_site && overlap(p, k, q)) visit(q);
    }
  }

  /// The sites the first round searches, after the first propagation (`Propagation::run()`),
  /// in proportion to what is broken. Each field came from the site's candidate in one
  /// neighbouring face, admitted before it (`Candidate::from_edge`), so these links lead back
  /// to the sites' faces. A piece is rooted when every piece on its way back overlaps the
  /// next one on their shared edge; a rooted piece is connected to its site's piece in the
  /// site's face. A piece whose link does not hold (a "break") that a short search through
  /// the joined pieces connects to a rooted piece is fine too; a site with a break that does
  /// not connect so is a suspect, marked in `suspect`. False if the breaks are many (then
  /// every site is searched). Not for the cuts after a repair round, whose refilled faces
  /// break the order of the links.
  bool find_suspects(std::vector<std::uint8_t>& suspect, bool parallel) const
  {
    // ascending, as binary searches want
    const std::vector<std::size_t> breaks = gather_in_chunk_order<std::size_t>(m_mesh.number_of_faces(), 4096, parallel,
        [&](std::size_t begin, std::size_t end, std::vector<std::size_t>& found) {
      for(std::size_t f = begin; f < end; ++f)
      {
        const Face_cuts::Cut cut = m_cuts[f];
        if(cut.whole_face || m_candidates[f].empty()) continue;   // a face in one piece keeps its edges whole
        for(std::size_t local = 0; local < cut.pieces.size(); ++local)
          if(!joined_to_parent(f << 32 | local)) found.push_back(f << 32 | local);
      }
    });
    if(breaks.size() > 4096) return false;
    for(std::size_t p : breaks)
      if(!suspect[candidate_of(p).site] && !reaches_rooted_piece(p, breaks)) suspect[candidate_of(p).site] = 1;
    return true;
  }

private:
  const Candidate& candidate_of(std::size_t p) const
  {
    const std::size_t f = face(p);
    const Face_cuts::Cut cut = m_cuts[f];
    return m_candidates[f][cut.whole_face ? 0 : cut.pieces[p & 0xffffffffu].candidate];
  }

  // Whether pieces p and q overlap on the edge between their faces (local edge k of p's face).
  bool overlap(std::size_t p, int k, std::size_t q) const
  {
    const std::size_t f = face(p), g = face(q);
    int kg = 0;
    while(kg < 3 && m_mesh.neighbors[g][kg] != f) ++kg;
    double lo_f, hi_f, lo_g, hi_g;
    return kg < 3 && segment_on_edge(p, k, lo_f, hi_f) && segment_on_edge(q, kg, lo_g, hi_g)
           && (std::max)(lo_f, lo_g) < (std::min)(hi_f, hi_g);
  }

  // Whether the link of piece p holds, read on p's side alone. After the first propagation,
  // the fields of two faces across an edge that is not a breakline have one lower envelope
  // along it: each face was offered every candidate of the other, and one it does not keep is
  // dominated there by one it keeps, so lies above it along the edge. The envelope's pieces
  // are decided exactly (a tie flags the face degenerate), so a site's stretch of the edge,
  // and the numbers that place it, are the same on both sides: the piece overlaps the one its
  // field came from exactly when its own stretch has positive length.
  bool joined_to_parent(std::size_t p) const
  {
    const Candidate& x = candidate_of(p);
    double lo, hi;
    return x.from_edge == Candidate::at_site || (segment_on_edge(p, x.from_edge, lo, hi) && lo < hi);
  }

  // Whether the way back from piece p reaches its site's face without a break.
  bool is_rooted(std::size_t p, const std::vector<std::size_t>& breaks) const
  {
    for(std::size_t steps = 0; steps <= m_mesh.number_of_faces(); ++steps)
    {
      if(std::binary_search(breaks.begin(), breaks.end(), p)) return false;
      const Candidate& x = candidate_of(p);
      if(x.from_edge == Candidate::at_site) return true;
      const std::size_t g = m_mesh.neighbors[face(p)][x.from_edge];
      const std::size_t q = (g == Mesh::none) ? no_site : piece_of(g, x.site);
      if(q == no_site || !overlap(p, x.from_edge, q)) return false;
      p = q;
    }
    return false;
  }

  // Whether a short search through the pieces joined to a break finds a rooted one.
  bool reaches_rooted_piece(std::size_t start, const std::vector<std::size_t>& breaks) const
  {
    boost::container::small_vector<std::size_t, 64> seen(1, start);
    for(std::size_t next = 0; next < seen.size(); ++next)
    {
      if(next > 0 && is_rooted(seen[next], breaks)) return true;
      for_each_joined(seen[next], [&](std::size_t r) {
        if(seen.size() < 64 && std::find(seen.begin(), seen.end(), r) == seen.end()) seen.push_back(r);
      });
    }
    return false;
  }

  // The segment of piece p on local edge k of its face, as parameters along the mesh edge
  // (from its lower vertex index); false if it has none.
  bool segment_on_edge(std::size_t p, int k, double& lo, double& hi) const
  {
    const std::size_t f = face(p);
    const Face_cuts::Cut cut = m_cuts[f];
    if(cut.whole_face || cut.pieces.size() <= 1)
    {
      lo = 0.;
      hi = 1.;
      return true;
    }
    const Face_cuts::Piece piece = cut.pieces[p & 0xffffffffu];
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
    const Candidate_range list = m_candidates[f];
    const std::uint32_t s = list[owner].site, t = list[v.other].site;
    const double* lo = (s < t ? list[owner] : list[v.other]).value.data();
    const double* hi = (s < t ? list[v.other] : list[owner]).value.data();
    const int ca = m_mesh.corner_of(f, va), cb = m_mesh.corner_of(f, vb);
    return edge_crossing_parameter(lo, hi, ca, cb);
  }

  const Mesh& m_mesh;
  const Candidate_table& m_candidates;
  const Face_cuts& m_cuts;
  Blocked_edge m_blocked_edge;
};

/// The pieces of the stitched partition: two pieces are adjacent when they share a piece
/// edge (a positive-length segment), and joined when they are of one site, except across a
/// breakline.
template <class TriangleMesh, class Blocked_edge>
class Stitched_pieces
{
public:
  typedef Indexed_mesh<TriangleMesh> Mesh;
  static constexpr bool has_area = true;

  Stitched_pieces(const Mesh& mesh, const Partition& partition, const Blocked_edge& blocked_edge)
    : m_mesh(mesh), m_partition(partition), m_blocked_edge(blocked_edge)
  {}

  std::size_t site(std::size_t p) const { return m_partition.pieces[p].site; }
  std::size_t face(std::size_t p) const { return m_partition.pieces[p].face; }
  double area(std::size_t p) const { return m_partition.pieces[p].area; }
  std::size_t piece_of(std::size_t f, std::size_t site) const { return m_partition.piece_of(f, site); }

  /// Calls `fn(p, site)` for the pieces of the sites `which` marks (all pieces if null), ascending.
  template <class Fn>
  void for_each_piece(const std::vector<std::uint8_t>* which, const Fn& fn) const
  {
    for(std::size_t p = 0; p < m_partition.pieces.size(); ++p)
      if(!which || (site(p) != no_site && (*which)[site(p)])) fn(p, site(p));
  }

  template <class Visit>
  void for_each_joined(std::size_t p, const Visit& visit, bool later_only = false) const
  {
    for_each_adjacent(p, [&](std::size_t q, std::size_t e) {
      if((q > p || !later_only) && site(q) == site(p) && (e == no_site || !m_blocked_edge(e))) visit(q);
    });
  }

  /// Calls `adjacent(q, e)` for every piece q sharing a piece edge with p, where `e` is the
  /// mesh edge the shared edge lies on, or `no_site` inside a face. Pieces only meet within a
  /// face or across one of its edges, so the search stays local.
  template <class Adjacent>
  void for_each_adjacent(std::size_t p, const Adjacent& adjacent) const
  {
    const Partition& partition = m_partition;
    const std::size_t f = partition.pieces[p].face;
    auto is_whole_face = [&](std::size_t g) { return partition.face_begin[g + 1] == partition.face_begin[g] + 1; };
    // A face in one piece (most faces, when sites are fewer than faces) meets a neighbour in
    // one piece along the whole edge: no search through the pieces' vertices.
    bool all_whole = is_whole_face(f);
    for(int k = 0; k < 3 && all_whole; ++k)
      all_whole = (m_mesh.neighbors[f][k] == Mesh::none || is_whole_face(m_mesh.neighbors[f][k]));
    if(all_whole)
    {
      for(int k = 0; k < 3; ++k)
        if(m_mesh.neighbors[f][k] != Mesh::none) adjacent(std::size_t(partition.face_begin[m_mesh.neighbors[f][k]]), std::size_t(m_mesh.edges[f][k]));
      return;
    }
    double t;
    auto on_edge = [&](std::size_t id, std::size_t e) { return partition.on_mesh_edge(m_mesh, id, e, t); };
    auto has_edge = [&](std::size_t q, std::size_t u, std::size_t w) {
      const Partition::Vertex_cycle& v = partition.pieces[q].vertices;
      for(std::size_t j = 0; j < v.size(); ++j)
        if(v[j] == u && v[(j + 1) % v.size()] == w) return true;
      return false;
    };
    const Partition::Vertex_cycle& v = partition.pieces[p].vertices;
    for(std::size_t j = 0; j < v.size(); ++j)
    {
      // The piece across (u, w) owns (w, u): across the mesh edge both lie on, else in the
      // same face. When the guided search finds nothing (a border, or a vertex whose location
      // is ambiguous), every candidate piece is tried.
      const std::size_t u = v[j], w = v[(j + 1) % v.size()];
      int local = -1;
      for(int k = 0; k < 3 && local < 0; ++k)
        if(on_edge(u, m_mesh.edges[f][k]) && on_edge(w, m_mesh.edges[f][k])) local = k;
      bool found = false;
      auto search_face = [&](std::size_t g, std::size_t e) {
        for(std::size_t q = partition.face_begin[g]; q < partition.face_begin[g + 1] && !found; ++q)
          if(has_edge(q, w, u))
          {
            found = true;
            adjacent(q, e);
          }
      };
      if(local >= 0 && m_mesh.neighbors[f][local] != Mesh::none) search_face(m_mesh.neighbors[f][local], m_mesh.edges[f][local]);
      search_face(f, no_site);
      for(int k = 0; k < 3 && !found; ++k)
        if(m_mesh.neighbors[f][k] != Mesh::none) search_face(m_mesh.neighbors[f][k], m_mesh.edges[f][k]);
    }
  }

private:
  const Mesh& m_mesh;
  const Partition& m_partition;
  Blocked_edge m_blocked_edge;
};

/// The sites whose cells share a piece edge with each site's cell, ascending, from the
/// stitched partition. Computed on demand: the construction gathers no neighbours, since most
/// uses of a diagram (Lloyd's steps, the outputs) never ask.
template <class TriangleMesh>
std::vector<std::vector<std::size_t> > site_neighbors(const Indexed_mesh<TriangleMesh>& mesh, const Partition& partition,
                                                      std::size_t number_of_sites)
{
  std::vector<std::vector<std::size_t> > out(number_of_sites);
  auto no_breakline = [](std::size_t) { return false; };
  const Stitched_pieces<TriangleMesh, decltype(no_breakline)> pieces(mesh, partition, no_breakline);
  for(std::size_t p = 0; p < partition.pieces.size(); ++p)
    pieces.for_each_adjacent(p, [&](std::size_t q, std::size_t) {
      const std::size_t a = pieces.site(p), b = pieces.site(q);
      if(q > p && a != b && a != no_site && b != no_site)
      {
        out[a].push_back(b);
        out[b].push_back(a);
      }
    });
  for(std::vector<std::size_t>& list : out)
  {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  return out;
}

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_CELL_CONNECTIVITY_H
