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
// Stitching: the per-face pieces become one consistent partition of the surface. Vertices
// are named by `Vertex_key`s, and positions are computed once per key from values both
// faces share, so the two sides of an edge produce the same vertices bit for bit. Exact
// ties (a Voronoi vertex exactly on a mesh edge or corner, four sites meeting at a point)
// give one point several keys: those are welded by exact comparison, and vertices that lie
// on a mesh edge are inserted into every piece edge running along it, so the result has no
// cracks and no T-junctions.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_STITCHING_STITCHER_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_STITCHING_STITCHER_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/internal/Bisector_points.h>
#include <CGAL/Surface_voronoi_diagram/internal/Candidate_table.h>
#include <CGAL/Surface_voronoi_diagram/internal/Disjoint_sets.h>
#include <CGAL/Surface_voronoi_diagram/internal/Double_kernel.h>
#include <CGAL/Surface_voronoi_diagram/internal/Face_cuts.h>
#include <CGAL/Surface_voronoi_diagram/internal/Indexed_mesh.h>
#include <CGAL/Surface_voronoi_diagram/internal/Partition.h>
#include <CGAL/Surface_voronoi_diagram/internal/exact_predicates.h>
#include <CGAL/Surface_voronoi_diagram/internal/parallel.h>
#include <CGAL/Surface_voronoi_diagram/internal/Stitching/Vertex_key.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <functional>
#include <iterator>
#include <limits>
#include <map>
#include <numeric>
#include <tuple>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

template <class TriangleMesh>
class Stitcher
{
public:
  typedef Indexed_mesh<TriangleMesh> Mesh;

  /// With `parallel`, the steps that work vertex by vertex, piece by piece or face by face
  /// run in concurrent chunks; naming the vertices (ids in face order) stays sequential.
  Stitcher(const Mesh& mesh, const Candidate_table& candidates, const Face_cuts& cuts, bool parallel = false)
    : m_mesh(mesh), m_candidates(candidates), m_cuts(cuts), m_parallel(parallel)
  {}

  /// Builds the partition from the candidate lists and the per-face cuts. `beside`, if given,
  /// is work of the caller's that shares no data with the partition: with `parallel` it runs
  /// on another thread while the vertices are named (the one step on one thread), otherwise
  /// after that step.
  void run(Partition& out, const std::function<void()>& beside = std::function<void()>())
  {
    m_out = &out;
    out = Partition();
    name_vertices(beside);
    weld_exact_ties();
    release_naming();
    insert_edge_points();
    weld_coincident_positions();
    drop_collinear_pieces();
  }

  /// Stitches again, into `out` (the partition before the cuts of the faces `recut` marks
  /// changed), those faces and their neighbours, whose pieces meet theirs: the vertices on the
  /// edges around this region keep their ids, and the vertices no piece uses any more go. The
  /// pieces are those the whole stitching gives. False, with `out` unchanged, where the region
  /// meets what only the whole stitching handles: an exact tie, coincident positions, a piece
  /// without area, a crossing on the region's border that its face does not hold.
  bool run_on(Partition& out, const std::vector<std::uint8_t>& recut)
  {
    const std::size_t nf = m_mesh.number_of_faces(), old_vertices = out.vertices.size();
    m_out = &out;
    std::vector<std::uint8_t> in = recut;
    for(std::size_t f = 0; f < nf; ++f)
      for(int k = 0; k < 3 && recut[f]; ++k)
        if(m_mesh.neighbors[f][k] != Mesh::none) in[m_mesh.neighbors[f][k]] = 1;
    std::map<std::array<std::uint32_t, 3>, std::uint32_t> crossings;   // (edge, sites) inside the region
    std::vector<Partition::Piece> region;
    bool held = true;
    // a crossing on the border: the vertex of the (untouched) face's two pieces on that edge
    auto border_id = [&](std::size_t f, const Vertex_key& k) {
      const std::size_t p = out.piece_of(f, k.sites[0]), q = out.piece_of(f, k.sites[1]);
      if(p != no_site && q != no_site)
        for(std::uint32_t id : out.pieces[p].vertices)
          if(out.vertices[id].kind == Partition::ON_EDGE && out.vertices[id].element == k.element
             && std::find(out.pieces[q].vertices.begin(), out.pieces[q].vertices.end(), id) != out.pieces[q].vertices.end())
            return std::size_t(id);
      held = false;
      return std::size_t(0);
    };
    auto id_in_region = [&](const Vertex_key& k, std::size_t f) {
      if(k.kind == Vertex_key::MESH_VERTEX)   // a corner of f's old pieces
      {
        for(std::size_t p = out.face_begin[f]; p < out.face_begin[f + 1]; ++p)
          for(std::uint32_t id : out.pieces[p].vertices)
            if(out.vertices[id].kind == Partition::AT_CORNER && out.vertices[id].element == k.element) return std::size_t(id);
        held = false;
        return std::size_t(0);
      }
      if(k.kind == Vertex_key::TRIPLE_POINT) return id_of(k, f);
      for(int l = 0; l < 3; ++l)
        if(m_mesh.edges[f][l] == k.element && m_mesh.neighbors[f][l] != Mesh::none && !in[m_mesh.neighbors[f][l]])
          return border_id(f, k);
      const auto r = crossings.emplace(std::array<std::uint32_t, 3>{{ k.element, k.sites[0], k.sites[1] }}, 0);
      if(r.second) r.first->second = std::uint32_t(new_id(k, f));
      return std::size_t(r.first->second);
    };
    std::vector<std::size_t> faces;       // the region's
    std::vector<std::uint32_t> went, kept;   // the ids of its old pieces but corners, of the pieces around
    for(std::size_t f = 0; f < nf && held; ++f)
      if(in[f])
      {
        held = !m_cuts[f].degenerate;
        name_face(f, region, [&](const Vertex_key& k) { return id_in_region(k, f); });
        faces.push_back(f);
        for(std::size_t p = out.face_begin[f]; p < out.face_begin[f + 1]; ++p)
          for(std::uint32_t id : out.pieces[p].vertices)
            if(out.vertices[id].kind != Partition::AT_CORNER) went.push_back(id);
      }
    // the points on each edge of the region, from its pieces and those across its border
    std::vector<std::tuple<std::uint32_t, double, std::uint32_t> > on_edges;   // (edge, t, id)
    auto add_points = [&](const Partition::Piece& p) {
      for(std::uint32_t id : p.vertices)
        if(out.vertices[id].kind == Partition::ON_EDGE) on_edges.emplace_back(out.vertices[id].element, out.vertices[id].t, id);
    };
    for(const Partition::Piece& p : region) add_points(p);
    for(std::size_t f = 0; f < nf && held; ++f)
      for(int k = 0; k < 3 && in[f]; ++k)
      {
        const std::size_t g = m_mesh.neighbors[f][k];
        if(g != Mesh::none && !in[g])
          for(std::size_t p = out.face_begin[g]; p < out.face_begin[g + 1]; ++p) add_points(out.pieces[p]);
      }
    std::sort(on_edges.begin(), on_edges.end());
    on_edges.erase(std::unique(on_edges.begin(), on_edges.end()), on_edges.end());
    // the points strictly inside each piece edge along a mesh edge, in order, as insert_edge_points()
    auto points = [&](std::size_t e, double lo, double hi, const auto& add) {
      for(auto it = std::lower_bound(on_edges.begin(), on_edges.end(), std::make_tuple(std::uint32_t(e), lo, std::uint32_t(-1)));
          it != on_edges.end() && std::get<0>(*it) == e && std::get<1>(*it) < hi; ++it)
        add(std::get<2>(*it));
    };
    Partition::Vertex_cycle refined;
    for(Partition::Piece& p : region)
    {
      refine(p.vertices, p.face, points, refined);
      p.vertices = refined;
      p.area = piece_area(p.vertices);
      held = held && p.area > 1e-12 * m_mesh.face_areas[p.face];
    }
    // no two vertices of a face at one position (welded by the whole stitching)
    std::vector<std::pair<Point_d, std::size_t> > positions;
    for(auto a = region.begin(), b = a; a != region.end() && held; a = b)
    {
      b = std::find_if(a, region.end(), [&](const Partition::Piece& p) { return p.face != a->face; });
      find_coincident(a, b, positions, [&](std::size_t, std::size_t) { held = false; });
    }
    if(!held)
    {
      out.vertices.resize(old_vertices);
      return false;
    }
    // The ids only the region's old pieces used go to its new vertices; the vertices are
    // renumbered all over only where fewer are new than went (none may stay unused).
    for(const Partition::Piece& p : region) kept.insert(kept.end(), p.vertices.begin(), p.vertices.end());
    for(const std::tuple<std::uint32_t, double, std::uint32_t>& x : on_edges) kept.push_back(std::get<2>(x));
    for(std::vector<std::uint32_t>* ids : { &went, &kept })
    {
      std::sort(ids->begin(), ids->end());
      ids->erase(std::unique(ids->begin(), ids->end()), ids->end());
    }
    std::vector<std::uint32_t> holes;
    std::set_difference(went.begin(), went.end(), kept.begin(), kept.end(), std::back_inserter(holes));
    // (welded vertices can join a crossing to pieces around a corner: renumbered all over)
    const bool local = out.vertices.size() - old_vertices >= holes.size() && out.welded_vertices == 0;
    if(local)
    {
      auto moved = [&](std::size_t id) {
        const std::size_t i = id - old_vertices;
        return std::uint32_t(i < holes.size() ? holes[i] : id - holes.size());
      };
      for(std::size_t id = old_vertices; id < out.vertices.size(); ++id) out.vertices[moved(id)] = out.vertices[id];
      out.vertices.resize(out.vertices.size() - holes.size());
      for(Partition::Piece& p : region)
        for(std::uint32_t& id : p.vertices)
          if(id >= old_vertices) id = moved(id);
    }
    out.replace_pieces(faces, region);
    if(local) return true;
    std::vector<std::uint32_t> renumbered(out.vertices.size(), no_id);
    for(const Partition::Piece& p : out.pieces)
      for(std::uint32_t id : p.vertices) renumbered[id] = 0;
    std::size_t used = 0;
    for(std::size_t id = 0; id < out.vertices.size(); ++id)
      if(renumbered[id] == 0)
      {
        out.vertices[used] = out.vertices[id];
        renumbered[id] = std::uint32_t(used++);
      }
    out.vertices.resize(used);
    for(Partition::Piece& p : out.pieces)
      for(std::uint32_t& id : p.vertices) id = renumbered[id];
    return true;
  }

private:
  // A vertex id's key, and the face that named it, whose candidate list holds every site of
  // the key. (32-bit indices: a million-face mesh names about as many vertices)
  struct Origin
  {
    Vertex_key key;
    std::uint32_t face;
  };
  // A bisector crossing already named, grouped by the face that named it.
  struct Edge_crossing_entry
  {
    std::uint32_t edge;
    std::uint32_t low_site, high_site;
    std::uint32_t id;
  };

  std::uint32_t site_of(std::size_t f, std::uint32_t candidate) const { return m_candidates[f][candidate].site; }

  Vertex_key key_of(std::size_t f, std::uint32_t owner, const Symbolic_vertex& v) const
  {
    switch(v.kind)
    {
    case Symbolic_vertex::CORNER:
      return Vertex_key::mesh_vertex(m_mesh.triangles[f][v.local]);
    case Symbolic_vertex::EDGE:
      return Vertex_key::edge_crossing(m_mesh.edges[f][v.local], site_of(f, owner), site_of(f, v.other));
    default:
      return Vertex_key::triple_point(f, site_of(f, owner), site_of(f, v.other), site_of(f, v.third));
    }
  }

  // A new vertex, placed where face f's values put its key: the first face to name a key
  // places it, so the faces on both sides of an edge share its position bit for bit.
  std::size_t new_id(const Vertex_key& k, std::size_t f)
  {
    std::vector<Partition::Vertex>& vertices = m_out->vertices;
    CGAL_precondition_msg(vertices.size() < std::size_t(0xffffffffu), "too many partition vertices for 32-bit ids");
    vertices.push_back(vertex_at(k, f));
    if(m_keep_keys) m_origins.push_back(Origin{ k, std::uint32_t(f) });
    return vertices.size() - 1;
  }

  // The id of a key, seen from face f. Without hashing: corners by mesh vertex; bisector
  // crossings among those named by the edge's faces (the one processed first names them);
  // triple points among those of the current face.
  std::size_t id_of(const Vertex_key& k, std::size_t f)
  {
    if(k.kind == Vertex_key::MESH_VERTEX)
    {
      std::uint32_t& id = m_corner_id[static_cast<std::size_t>(k.element)];
      if(id == no_id) id = std::uint32_t(new_id(k, f));
      return id;
    }
    if(k.kind == Vertex_key::EDGE_CROSSING)
    {
      const std::size_t e = static_cast<std::size_t>(k.element);
      auto find_in = [&](std::size_t begin, std::size_t end) -> std::size_t {
        for(std::size_t j = begin; j < end; ++j)
        {
          const Edge_crossing_entry& x = m_edge_crossings[j];
          if(x.edge == e && x.low_site == k.sites[0] && x.high_site == k.sites[1]) return x.id;
        }
        return no_site;
      };
      for(int l = 0; l < 3; ++l)
        if(m_mesh.edges[f][l] == e)
        {
          const std::size_t g = m_mesh.neighbors[f][l];
          if(g != Mesh::none && g < f)
          {
            const std::size_t id = find_in(m_edge_crossings_begin[g], m_edge_crossings_begin[g + 1]);
            if(id != no_site) return id;
          }
        }
      std::size_t id = find_in(m_edge_crossings_begin[f], m_edge_crossings.size());
      if(id != no_site) return id;
      id = new_id(k, f);
      m_edge_crossings.push_back(Edge_crossing_entry{ std::uint32_t(e), k.sites[0], k.sites[1], std::uint32_t(id) });
      return id;
    }
    for(const std::pair<Vertex_key, std::uint32_t>& x : m_face_triples)
      if(x.first == k) return x.second;
    const std::size_t id = new_id(k, f);
    m_face_triples.emplace_back(k, std::uint32_t(id));
    return id;
  }

  // Appends the pieces of face f to `pieces` in order, each vertex named `id(key)`. A face
  // reached by nobody, or owned whole by its only candidate (as the cutter's one piece would
  // be), is one piece: its three corners.
  template <class Id>
  void name_face(std::size_t f, std::vector<Partition::Piece>& pieces, const Id& id)
  {
    m_face_triples.clear();
    if(m_candidates[f].empty() || m_cuts[f].whole_face)
    {
      pieces.push_back(Partition::Piece{ std::uint32_t(f), m_candidates[f].empty() ? no_site : m_candidates[f][0].site, {}, 0. });
      for(int k = 0; k < 3; ++k) pieces.back().vertices.push_back(std::uint32_t(id(Vertex_key::mesh_vertex(m_mesh.triangles[f][k]))));
      return;
    }
    for(const Face_cuts::Piece sp : m_cuts[f].pieces)
    {
      pieces.push_back(Partition::Piece{ std::uint32_t(f), m_candidates[f][sp.candidate].site, {}, 0. });
      pieces.back().vertices.reserve(sp.vertices.size());
      for(const Symbolic_vertex& v : sp.vertices) pieces.back().vertices.push_back(std::uint32_t(id(key_of(f, sp.candidate, v))));
    }
  }

  std::size_t number_of_pieces(std::size_t f) const
  {
    return (m_candidates[f].empty() || m_cuts[f].whole_face) ? 1 : m_cuts[f].pieces.size();
  }

  // Step 1: every piece as a list of vertex ids, and every vertex placed; faces nobody
  // reached are one piece of no site. The keys are kept only for the exact ties' welding.
  // `beside`, if any, runs meanwhile (after it without `m_parallel`).
  void name_vertices(const std::function<void()>& beside)
  {
    const std::size_t nf = m_mesh.number_of_faces();
    Partition& out = *m_out;
    m_corner_id.assign(m_mesh.number_of_vertices(), no_id);
    m_edge_crossings_begin.assign(nf + 1, 0);
    m_keep_keys = false;
    for(std::size_t f = 0; f < nf && !m_keep_keys; ++f) m_keep_keys = m_cuts[f].degenerate;
    out.face_begin.assign(nf + 1, 0);
    std::size_t pieces = 0;
    for(std::size_t f = 0; f < nf; ++f) pieces += number_of_pieces(f);
    // reserved, since growing by doubling moved every piece built so far and touched fresh
    // pages each time; vertices: the corners, and about three more per piece beyond one a face
    CGAL_precondition_msg(pieces < std::size_t(0xffffffffu), "too many partition pieces for 32-bit offsets");
    out.pieces.reserve(pieces);
    const std::size_t expected_vertices = m_mesh.number_of_vertices() + 3 * (pieces - (std::min)(pieces, nf));
    out.vertices.reserve(expected_vertices);
    if(m_keep_keys) m_origins.reserve(expected_vertices);
    m_edge_crossings.reserve(2 * (pieces - (std::min)(pieces, nf)) + 16);   // about one per piece beyond one a face
    auto name_faces = [&]() {
      for(std::size_t f = 0; f < nf; ++f)
      {
        out.face_begin[f] = std::uint32_t(out.pieces.size());
        m_edge_crossings_begin[f] = std::uint32_t(m_edge_crossings.size());
        name_face(f, out.pieces, [&](const Vertex_key& k) { return id_of(k, f); });
      }
      out.face_begin[nf] = std::uint32_t(out.pieces.size());
      m_edge_crossings_begin[nf] = std::uint32_t(m_edge_crossings.size());
    };
    if(beside)
      run_beside(m_parallel, name_faces, beside);
    else
      name_faces();
  }

  const double* values_of(std::size_t f, std::uint32_t site) const { return internal::values_of(m_candidates[f], site); }

  // A key's vertex, placed by the values of its sites in face f.
  Partition::Vertex vertex_at(const Vertex_key& k, std::size_t f) const
  {
    if(k.kind == Vertex_key::MESH_VERTEX)
      return Partition::Vertex{ m_mesh.points[k.element], 0., k.element, Partition::AT_CORNER };
    if(k.kind == Vertex_key::EDGE_CROSSING)
    {
      const std::size_t e = static_cast<std::size_t>(k.element);
      const std::size_t va = m_mesh.edge_vertices[e][0], vb = m_mesh.edge_vertices[e][1];
      const int ca = m_mesh.corner_of(f, va), cb = m_mesh.corner_of(f, vb);
      const double t = edge_crossing_parameter(values_of(f, k.sites[0]), values_of(f, k.sites[1]), ca, cb);
      const Point_d& pa = m_mesh.points[va];
      const Point_d& pb = m_mesh.points[vb];
      return Partition::Vertex{ pa + t * (pb - pa), t, k.element, Partition::ON_EDGE };
    }
    const Barycentric b = triple_point_barycentric(values_of(f, k.sites[0]), values_of(f, k.sites[1]), values_of(f, k.sites[2]));
    return Partition::Vertex{ m_mesh.point_at(f, b), 0., std::uint32_t(f), Partition::IN_FACE };
  }

  bool is_representative(std::size_t id) const { return m_representative.empty() || m_representative[id] == id; }

  // Where a vertex lies, exactly: at a corner, on an edge at parameter c[0], or in a face
  // with barycentric coordinates c.
  struct Exact_location
  {
    Partition::Location_kind kind;
    std::size_t element;
    std::array<Exact_number, 3> c;
    bool operator<(const Exact_location& o) const { return std::tie(kind, element, c) < std::tie(o.kind, o.element, o.c); }
  };

  Exact_location exact_location(std::size_t id) const
  {
    const Vertex_key& k = m_origins[id].key;
    const std::size_t f = m_origins[id].face;
    if(k.kind == Vertex_key::MESH_VERTEX) return Exact_location{ Partition::AT_CORNER, static_cast<std::size_t>(k.element), {} };
    if(k.kind == Vertex_key::EDGE_CROSSING)
    {
      const std::size_t e = static_cast<std::size_t>(k.element);
      const int ca = m_mesh.corner_of(f, m_mesh.edge_vertices[e][0]), cb = m_mesh.corner_of(f, m_mesh.edge_vertices[e][1]);
      const double* lo = values_of(f, k.sites[0]);
      const double* hi = values_of(f, k.sites[1]);
      const Exact_number da = Exact_number(lo[ca]) - Exact_number(hi[ca]), db = Exact_number(lo[cb]) - Exact_number(hi[cb]);
      Exact_location l{ Partition::ON_EDGE, e, {} };
      l.c[0] = da / (da - db);
      return l;
    }
    std::array<Exact_number, 3> b;
    if(!exact_triple_barycentric(values_of(f, k.sites[0]), values_of(f, k.sites[1]), values_of(f, k.sites[2]), b))
      return Exact_location{ Partition::IN_FACE, f, {{ Exact_number(1) / 3, Exact_number(1) / 3, Exact_number(1) / 3 }} };
    int zeros = 0, nonzero = -1;
    for(int c = 0; c < 3; ++c)
    {
      if(CGAL::is_zero(b[c])) ++zeros;
      else nonzero = c;
    }
    if(zeros == 2)
      return Exact_location{ Partition::AT_CORNER, m_mesh.triangles[f][nonzero], {} };
    if(zeros == 1)
    {
      int z = 0;
      while(!CGAL::is_zero(b[z])) ++z;
      // on the local edge opposite corner z: corners z+1 -> z+2 form local edge z+1
      const int k1 = (z + 1) % 3;
      const std::size_t e = m_mesh.edges[f][k1];
      const int cb = (m_mesh.triangles[f][k1] == m_mesh.edge_vertices[e][0]) ? (k1 + 1) % 3 : k1;
      Exact_location l{ Partition::ON_EDGE, e, {} };
      l.c[0] = b[cb];
      return l;
    }
    return Exact_location{ Partition::IN_FACE, f, b };
  }

  // Step 3: around faces where the cutter met an exact tie, vertices at the same exact
  // location become one (only possible there, and rare: rationals are slow).
  void weld_exact_ties()
  {
    const std::size_t nf = m_mesh.number_of_faces();
    if(!m_keep_keys) return;
    Partition& out = *m_out;
    m_representative.resize(out.vertices.size());
    std::iota(m_representative.begin(), m_representative.end(), std::size_t(0));
    std::map<Exact_location, std::size_t> groups;
    std::vector<std::uint8_t> seen(m_origins.size(), 0);
    for(std::size_t f = 0; f < nf; ++f)
    {
      if(!m_cuts[f].degenerate) continue;
      // the degenerate face and its neighbours: a point on a shared edge has keys in both
      const std::size_t faces_to_scan[4] = { f, m_mesh.neighbors[f][0], m_mesh.neighbors[f][1], m_mesh.neighbors[f][2] };
      for(std::size_t g : faces_to_scan)
      {
        if(g == Mesh::none) continue;
        for(std::size_t p = out.face_begin[g]; p < out.face_begin[g + 1]; ++p)
          for(std::size_t id : out.pieces[p].vertices)
          {
            if(seen[id]) continue;
            seen[id] = 1;
            const Exact_location l = exact_location(id);
            if(l.kind == Partition::AT_CORNER)
            {
              // a corner: represented by the corner's own key
              const std::size_t cid = id_of(Vertex_key::mesh_vertex(l.element), m_origins[id].face);
              if(cid >= m_representative.size())
              {
                // named just now: no piece had that corner as a corner
                m_representative.push_back(cid);
                seen.push_back(1);
              }
              m_representative[id] = cid;
              continue;
            }
            auto r = groups.emplace(l, id);
            if(!r.second)
              m_representative[id] = r.first->second;
            else if(l.kind == Partition::ON_EDGE && m_origins[id].key.kind == Vertex_key::TRIPLE_POINT)
            {
              // a triple point exactly on a mesh edge: it becomes an edge vertex
              out.vertices[id].kind = Partition::ON_EDGE;
              out.vertices[id].element = std::uint32_t(l.element);
              out.vertices[id].t = CGAL::to_double(l.c[0]);
            }
          }
      }
    }
    for(std::size_t id = 0; id < m_representative.size(); ++id)
      if(m_representative[id] != id) ++out.welded_vertices;
    for(Partition::Piece& p : out.pieces)
    {
      for(std::uint32_t& id : p.vertices) id = std::uint32_t(m_representative[id]);
      remove_cyclic_repeats(p.vertices);
    }
    const std::size_t before = out.pieces.size();
    out.pieces.erase(std::remove_if(out.pieces.begin(), out.pieces.end(),
                                    [](const Partition::Piece& p) { return p.vertices.size() < 3; }),
                     out.pieces.end());
    out.dropped_pieces += before - out.pieces.size();
    out.rebuild_face_begin(nf);
  }

  // The keys and their lookup tables are not read after the exact ties are welded; the
  // partition's own vertices and pieces grow from here on.
  void release_naming()
  {
    std::vector<Origin>().swap(m_origins);
    std::vector<std::pair<Vertex_key, std::uint32_t> >().swap(m_face_triples);
    std::vector<std::uint32_t>().swap(m_corner_id);
    std::vector<Edge_crossing_entry>().swap(m_edge_crossings);
    std::vector<std::uint32_t>().swap(m_edge_crossings_begin);
  }

  // Step 4: every vertex on a mesh edge goes into the piece edges that run along that edge.
  void insert_edge_points()
  {
    Partition& out = *m_out;
    // the points of each edge, sorted by parameter, in one flat array grouped by edge with a
    // counting sort (a global sort and a binary search per piece edge cost far more)
    struct Edge_point { double t; std::size_t id; };
    const std::size_t ne = m_mesh.number_of_edges();
    CGAL_precondition(out.vertices.size() < std::size_t(std::uint32_t(-1)));
    // In concurrent chunks: the counts and the slots are taken by atomic increments, in an
    // order that varies
    // with the threads, and each edge's points are then sorted by (t, id), an order that does
    // not.
    const std::size_t chunk = 8192;
    auto on_edge = [&](std::size_t id) { return is_representative(id) && out.vertices[id].kind == Partition::ON_EDGE; };
    std::vector<std::atomic<std::uint32_t> > slot(ne);   // value-initialized: zero
    for_each_chunk(out.vertices.size(), chunk, m_parallel, [&](std::size_t begin, std::size_t end, std::size_t) {
      for(std::size_t id = begin; id < end; ++id)
        if(on_edge(id)) slot[out.vertices[id].element].fetch_add(1, std::memory_order_relaxed);
    });
    const std::vector<std::size_t> chunk_first = chunk_offsets(ne, chunk, m_parallel, [&](std::size_t begin, std::size_t end) {
      std::size_t points = 0;
      for(std::size_t e = begin; e < end; ++e) points += slot[e].load(std::memory_order_relaxed);
      return points;
    });
    std::vector<std::uint32_t> edge_begin(ne + 1);
    edge_begin[ne] = std::uint32_t(chunk_first.back());
    for_each_chunk(ne, chunk, m_parallel, [&](std::size_t begin, std::size_t end, std::size_t c) {
      std::size_t first = chunk_first[c];
      for(std::size_t e = begin; e < end; ++e)
      {
        const std::uint32_t n = slot[e].load(std::memory_order_relaxed);
        edge_begin[e] = std::uint32_t(first);
        slot[e].store(std::uint32_t(first), std::memory_order_relaxed);   // the edge's next slot
        first += n;
      }
    });
    std::vector<Edge_point> edge_points(edge_begin[ne]);
    for_each_chunk(out.vertices.size(), chunk, m_parallel, [&](std::size_t begin, std::size_t end, std::size_t) {
      for(std::size_t id = begin; id < end; ++id)
        if(on_edge(id))
        {
          const std::uint32_t k = slot[out.vertices[id].element].fetch_add(1, std::memory_order_relaxed);
          edge_points[k] = Edge_point{ out.vertices[id].t, id };
        }
    });
    std::vector<std::atomic<std::uint32_t> >().swap(slot);
    for_each_chunk(ne, chunk, m_parallel, [&](std::size_t begin, std::size_t end, std::size_t) {
      for(std::size_t e = begin; e < end; ++e)
        if(edge_begin[e + 1] - edge_begin[e] > 1)
          std::sort(edge_points.begin() + edge_begin[e], edge_points.begin() + edge_begin[e + 1],
                    [](const Edge_point& a, const Edge_point& b) { return a.t < b.t || (a.t == b.t && a.id < b.id); });
    });
    auto has_points = [&](std::size_t e) { return edge_begin[e + 1] > edge_begin[e]; };
    auto points = [&](std::size_t e, double lo, double hi, const auto& add) {
      for(std::uint32_t j = edge_begin[e]; j < edge_begin[e + 1]; ++j)
        if(edge_points[j].t > lo && edge_points[j].t < hi) add(edge_points[j].id);
    };
    std::vector<std::size_t> inserted(number_of_chunks(out.pieces.size(), chunk), 0);
    for_each_chunk(out.pieces.size(), chunk, m_parallel, [&](std::size_t begin, std::size_t end, std::size_t c) {
      std::vector<std::size_t> refined;
      for(std::size_t piece = begin; piece < end; ++piece)
      {
        Partition::Piece& p = out.pieces[piece];
        // a piece whose face has no point on its edges has nothing to receive
        bool receives = false;
        for(int le = 0; le < 3; ++le) receives |= has_points(m_mesh.edges[p.face][le]);
        if(!receives) continue;
        refine(p.vertices, p.face, points, refined);
        if(refined.size() == p.vertices.size()) continue;
        inserted[c] += refined.size() - p.vertices.size();
        p.vertices.assign(refined.begin(), refined.end());
      }
    });
    for(std::size_t n : inserted) out.inserted_vertices += n;
  }

  // Step 5: features smaller than double precision. Vertices whose computed positions are
  // bit-identical are one vertex (two vertices can only coincide if some face uses both, so
  // each face is compared on its own); the survivor keeps the most specific location.
  void weld_coincident_positions()
  {
    Partition& out = *m_out;
    Disjoint_sets welded(out.vertices.size());
    bool any = false;
    // the coincident pairs, found face by face (in chunks), then welded in face order
    const std::size_t nf = out.face_begin.size() - 1, chunk = 8192;
    typedef std::pair<std::size_t, std::size_t> Vertex_pair;
    const std::vector<Vertex_pair> coincident = gather_in_chunk_order<Vertex_pair>(nf, chunk, m_parallel,
        [&](std::size_t begin, std::size_t end, std::vector<Vertex_pair>& found) {
      // (position, id), sorted by position then id: the points copied, not looked up per comparison
      std::vector<std::pair<Point_d, std::size_t> > used;
      for(std::size_t f = begin; f < end; ++f)
      {
        // a face that is one piece through its three corners alone (most faces) has nothing
        // to weld: its corners are distinct points, since the mesh has no face without area
        if(out.face_begin[f + 1] == out.face_begin[f] + 1)
        {
          const Partition::Vertex_cycle& ids = out.pieces[out.face_begin[f]].vertices;
          if(ids.size() == 3 && out.vertices[ids[0]].kind == Partition::AT_CORNER && out.vertices[ids[1]].kind == Partition::AT_CORNER
             && out.vertices[ids[2]].kind == Partition::AT_CORNER)
            continue;
        }
        find_coincident(out.pieces.begin() + out.face_begin[f], out.pieces.begin() + out.face_begin[f + 1], used,
                        [&](std::size_t a, std::size_t b) { found.emplace_back(a, b); });
      }
    });
    for(const Vertex_pair& pair : coincident)
    {
      const std::size_t a = welded.find(pair.first), b = welded.find(pair.second);
      if(a == b) continue;
      // a corner before an edge point before a face point
      const bool a_first = out.vertices[a].kind < out.vertices[b].kind
                           || (out.vertices[a].kind == out.vertices[b].kind && a < b);
      if(a_first) welded.link(b, a); else welded.link(a, b);
      any = true;
    }
    if(any)
    {
      for(std::size_t id = 0; id < welded.size(); ++id)
        if(welded.find(id) != id) ++out.welded_vertices;
      for(Partition::Piece& p : out.pieces)
      {
        for(std::uint32_t& id : p.vertices) id = std::uint32_t(welded.find(id));
        remove_cyclic_repeats(p.vertices);
      }
    }
    parallel_for_each_index(out.pieces.size(), m_parallel, [&](std::size_t k) {
      Partition::Piece& p = out.pieces[k];
      p.area = p.vertices.size() < 3 ? 0. : piece_area(p.vertices);
    });
  }

  // The vertices of the piece `cycle` of face f into `refined`, with the points strictly inside
  // each of its edges that runs along a mesh edge, in order: `points(e, lo, hi, add)` calls
  // `add(id)` for the points of mesh edge e with parameters in (lo, hi), ascending.
  template <class Points, class Cycle>
  void refine(const Partition::Vertex_cycle& cycle, std::size_t f, const Points& points, Cycle& refined) const
  {
    refined.clear();
    for(std::size_t k = 0; k < cycle.size(); ++k)
    {
      const std::size_t u = cycle[k], w = cycle[(k + 1) % cycle.size()];
      refined.push_back(u);
      for(int l = 0; l < 3; ++l)
      {
        const std::size_t e = m_mesh.edges[f][l];
        double tu, tw;
        if(!m_out->on_mesh_edge(m_mesh, u, e, tu) || !m_out->on_mesh_edge(m_mesh, w, e, tw)) continue;
        const std::size_t before = refined.size();
        points(e, (std::min)(tu, tw), (std::max)(tu, tw), [&](std::size_t id) {
          if(id != u && id != w) refined.push_back(id);
        });
        if(tu > tw) std::reverse(refined.begin() + std::ptrdiff_t(before), refined.end());
        break;   // a piece edge lies along one mesh edge at most
      }
    }
  }

  // Calls `found(a, b)` for each two vertices a, b of the pieces [first, last) at one
  // position, next to each other in (position, id) order; `used` is scratch.
  template <class Piece_iterator, class Found>
  void find_coincident(Piece_iterator first, Piece_iterator last, std::vector<std::pair<Point_d, std::size_t> >& used,
                       const Found& found) const
  {
    used.clear();
    for(; first != last; ++first)
      for(std::size_t v : first->vertices) used.emplace_back(m_out->vertices[v].point, v);
    std::sort(used.begin(), used.end());
    for(std::size_t k = 1; k < used.size(); ++k)
      if(used[k].second != used[k - 1].second && used[k].first == used[k - 1].first) found(used[k - 1].second, used[k].second);
  }

  double piece_area(const Partition::Vertex_cycle& ids) const
  {
    const Partition& out = *m_out;
    Vector_d s(0., 0., 0.);
    const Point_d& o = out.vertices[ids[0]].point;
    for(std::size_t k = 1; k + 1 < ids.size(); ++k)
      s = s + CGAL::cross_product(out.vertices[ids[k]].point - o, out.vertices[ids[k + 1]].point - o);
    return 0.5 * std::sqrt(s.squared_length());
  }

  bool is_collinear_polygon(const Partition::Vertex_cycle& ids) const
  {
    typedef Exact_predicates_kernel::Point_3 P;
    auto point = [&](std::size_t id) {
      const Point_d& p = m_out->vertices[id].point;
      return P(p[0], p[1], p[2]);
    };
    const P a = point(ids[0]);
    std::size_t k = 1;
    while(k < ids.size() && point(ids[k]) == a) ++k;
    if(k == ids.size()) return true;
    const P b = point(ids[k]);
    for(std::size_t j = k + 1; j < ids.size(); ++j)
      if(!CGAL::collinear(a, b, point(ids[j]))) return false;
    return true;
  }

  // Pieces left without area by welding are removed; a piece whose corners are collinear
  // hands its middle vertices to the pieces across its long side.
  void drop_collinear_pieces()
  {
    Partition& out = *m_out;
    // found in concurrent chunks, kept in piece order
    const std::size_t chunk = 16384;
    const std::vector<std::size_t> degenerate = gather_in_chunk_order<std::size_t>(out.pieces.size(), chunk, m_parallel,
        [&](std::size_t begin, std::size_t end, std::vector<std::size_t>& found) {
      for(std::size_t k = begin; k < end; ++k)
      {
        const Partition::Piece& p = out.pieces[k];
        // only a piece without area in double can be exactly collinear
        if(p.vertices.size() < 3 || (p.area <= 1e-12 * m_mesh.face_areas[p.face] && is_collinear_polygon(p.vertices)))
          found.push_back(k);
      }
    });
    if(degenerate.empty()) return;
    out.dropped_pieces += degenerate.size();
    std::unordered_map<std::uint64_t, std::size_t> edge_owner;   // directed edge -> piece
    const std::uint64_t nv = out.vertices.size();
    std::vector<std::uint8_t> dropped(out.pieces.size(), 0);
    for(std::size_t k : degenerate) dropped[k] = 1;
    for(std::size_t k = 0; k < out.pieces.size(); ++k)
    {
      if(dropped[k]) continue;
      const auto& v = out.pieces[k].vertices;
      for(std::size_t j = 0; j < v.size(); ++j)
        edge_owner[std::uint64_t(v[j]) * nv + v[(j + 1) % v.size()]] = k;
    }
    for(std::size_t k : degenerate)
    {
      const auto& v = out.pieces[k].vertices;
      if(v.size() < 3) continue;   // two vertices: the pieces on both sides already share the edge
      // order the vertices along the line, from the first towards the farthest
      const Point_d& o = out.vertices[v[0]].point;
      Vector_d direction(0., 0., 0.);
      double best = -1;
      for(std::size_t id : v)
      {
        const Vector_d d = out.vertices[id].point - o;
        if(d.squared_length() > best) { best = d.squared_length(); direction = d; }
      }
      auto along = [&](std::size_t id) { return (out.vertices[id].point - o) * direction; };
      std::vector<std::size_t> sorted(v.begin(), v.end());
      std::sort(sorted.begin(), sorted.end(), [&](std::size_t a, std::size_t b) { return along(a) < along(b); });
      sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
      // every edge (u, w) of the dropped piece: the piece across it, owning (w, u), gets the
      // vertices strictly between w and u
      for(std::size_t j = 0; j < v.size(); ++j)
      {
        const std::size_t u = v[j], w = v[(j + 1) % v.size()];
        auto it = edge_owner.find(std::uint64_t(w) * nv + u);
        if(it == edge_owner.end()) continue;
        const double tw = along(w), tu = along(u);
        std::vector<std::size_t> between;
        for(std::size_t id : sorted)
          if(id != u && id != w && along(id) > (std::min)(tu, tw) && along(id) < (std::max)(tu, tw)) between.push_back(id);
        if(between.empty()) continue;
        if(tw > tu) std::reverse(between.begin(), between.end());
        auto& q = out.pieces[it->second].vertices;
        for(std::size_t i = 0; i < q.size(); ++i)
          if(q[i] == w && q[(i + 1) % q.size()] == u)
          {
            q.insert(q.begin() + std::ptrdiff_t(i + 1), between.begin(), between.end());
            out.inserted_vertices += between.size();
            break;
          }
      }
    }
    std::vector<Partition::Piece> kept;
    kept.reserve(out.pieces.size());
    for(std::size_t k = 0; k < out.pieces.size(); ++k)
      if(!dropped[k]) kept.push_back(std::move(out.pieces[k]));
    out.pieces.swap(kept);
    out.rebuild_face_begin(out.face_begin.size() - 1);
  }

  const Mesh& m_mesh;
  const Candidate_table& m_candidates;
  const Face_cuts& m_cuts;
  bool m_parallel;
  Partition* m_out = nullptr;
  bool m_keep_keys = false;                           // some face has an exact tie
  std::vector<Origin> m_origins;                      // by vertex id, if m_keep_keys
  std::vector<std::pair<Vertex_key, std::uint32_t> > m_face_triples;   // the current face's
  static constexpr std::uint32_t no_id = std::uint32_t(-1);
  std::vector<std::uint32_t> m_corner_id;             // by mesh vertex (ids are 32-bit)
  std::vector<Edge_crossing_entry> m_edge_crossings;  // grouped by the face that named them
  std::vector<std::uint32_t> m_edge_crossings_begin;
  std::vector<std::size_t> m_representative;          // by weld_exact_ties, if m_keep_keys
};

/// Builds the partition from the candidate lists and the per-face cuts; `beside` as in
/// `Stitcher::run()`.
template <class TriangleMesh>
void stitch(const Indexed_mesh<TriangleMesh>& mesh, const Candidate_table& candidates,
            const Face_cuts& cuts, Partition& out, bool parallel = false,
            const std::function<void()>& beside = std::function<void()>())
{
  Stitcher<TriangleMesh>(mesh, candidates, cuts, parallel).run(out, beside);
}

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_STITCHING_STITCHER_H
