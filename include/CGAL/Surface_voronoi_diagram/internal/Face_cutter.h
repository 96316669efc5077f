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
// Cutting (SurfaceVoronoi, stage 2): inside one face, the lower envelope of the candidate
// fields. With squared distances interpolated linearly, the difference of two fields is
// affine, so every site's piece is a convex polygon obtained by clipping the triangle with
// one half-plane per competitor. Vertices are kept symbolic (a corner, a bisector crossing
// a mesh edge, or a triple point) so that stitching can identify them across faces.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_FACE_CUTTER_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_FACE_CUTTER_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/internal/Candidate.h>
#include <CGAL/Surface_voronoi_diagram/internal/exact_predicates.h>

#include <boost/container/small_vector.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

/// A vertex of a piece, in terms of the face's candidate list (indices into it).
struct Symbolic_vertex
{
  enum Kind : std::uint8_t { CORNER, EDGE, TRIPLE };
  Kind kind;
  std::uint8_t local;    // CORNER: the corner; EDGE: the local edge (corner local -> local+1)
  std::uint32_t other;   // EDGE: the other site of the bisector; TRIPLE: first other site
  std::uint32_t third;   // TRIPLE: second other site
};

/// What a piece's edge lies on: a local edge of the face, or the bisector with another site.
struct Piece_edge_support
{
  bool on_mesh_edge;
  std::uint8_t local;    // the local edge when on_mesh_edge
  std::uint32_t other;   // the other site (candidate index) otherwise
};

/// A clipped triangle has at most 3 + (candidates - 1) vertices, and most cut faces have two
/// or three candidates: six are kept inline, so that a piece allocates nothing of its own
/// (and the vector of pieces is reused face after face, see `Face_cutter::cut(Face_cut&)`).
struct Symbolic_piece
{
  typedef boost::container::small_vector<Symbolic_vertex, 6> Vertex_list;
  typedef boost::container::small_vector<Piece_edge_support, 6> Support_list;
  std::uint32_t candidate;    // index into the face's candidate list
  Vertex_list vertices;       // counter-clockwise, as the face
  Support_list supports;      // supports[n]: edge vertices[n] -> vertices[n+1]
};

struct Face_cut
{
  std::vector<Symbolic_piece> pieces;
  bool degenerate = false;                    // some vertex lies exactly on a further bisector
  // The only candidate owns the whole triangle, and `pieces` is left empty: the cut of most
  // faces, stitched without allocating anything for it.
  bool whole_face = false;

  /// no pieces, no flags: its storage kept for the next cut
  void clear()
  {
    pieces.clear();
    degenerate = false;
    whole_face = false;
  }
};

class Face_cutter
{
public:
  explicit Face_cutter(Candidate_range candidates) : m_candidates(candidates) {}
  explicit Face_cutter(const Candidate_list& c) : m_candidates(c.data(), c.data() + c.size()) {}

  /// sign of h_il = D_i - D_l at vertex `v` of the piece of candidate i
  int sign_at(const Symbolic_vertex& v, std::uint32_t i, std::uint32_t l) const
  {
    const double* Di = m_candidates[i].value.data();
    const double* Dl = m_candidates[l].value.data();
    switch(v.kind)
    {
    case Symbolic_vertex::CORNER:
      return (Di[v.local] > Dl[v.local]) - (Di[v.local] < Dl[v.local]);
    case Symbolic_vertex::EDGE:
    {
      const int k0 = v.local, k1 = (v.local + 1) % 3;
      const double* Dj = m_candidates[v.other].value.data();
      // The crossing of bisector (i,j) with the edge is at t = A / (A - B); there
      // h_il = (A*D - B*C) / (A - B), and A - B has the sign of A.
      const int sA = (Di[k0] > Dj[k0]) - (Di[k0] < Dj[k0]);
      const int s = sign_of_det2_of_differences(Di[k0], Dj[k0], Di[k1], Dj[k1], Di[k0], Dl[k0], Di[k1], Dl[k1]);
      // A*D - B*C with A=(Di-Dj)(k0), B=(Di-Dj)(k1), C=(Di-Dl)(k0), D=(Di-Dl)(k1)
      return s * sA;
    }
    case Symbolic_vertex::TRIPLE:
    default:
    {
      const double* Dj = m_candidates[v.other].value.data();
      const double* Dm = m_candidates[v.third].value.data();
      const Difference_row rij = { Di, Dj }, rim = { Di, Dm }, ril = { Di, Dl };
      return sign_of_det3_of_differences(rij, rim, &ril) * sign_of_det3_of_differences(rij, rim, nullptr);
    }
    }
  }

  Face_cut cut() const
  {
    Face_cut result;
    cut(result);
    return result;
  }

  /// the same into `result`, whose storage is reused (one cut after another allocates nothing)
  void cut(Face_cut& result) const
  {
    result.clear();
    const std::uint32_t n = static_cast<std::uint32_t>(m_candidates.size());
    // Built in place: a piece holds its vertices inline, so moving one copies them. No
    // reallocation moves them either, since there is at most one piece per candidate.
    result.pieces.reserve(n);
    const std::size_t most_vertices = std::size_t(n) + 3;
    if(m_out_vertices.size() < most_vertices)
    {
      m_signs.resize(most_vertices);
      m_out_vertices.resize(most_vertices);
      m_origin.resize(most_vertices);
      m_crossing.resize(most_vertices);
      m_out_supports.resize(most_vertices);
    }
    for(std::uint32_t i = 0; i < n; ++i)
    {
      result.pieces.resize(result.pieces.size() + 1);
      Symbolic_piece& piece = result.pieces.back();
      piece.candidate = i;
      for(std::uint8_t k = 0; k < 3; ++k)
      {
        piece.vertices.push_back(Symbolic_vertex{ Symbolic_vertex::CORNER, k, 0, 0 });
        piece.supports.push_back(Piece_edge_support{ true, k, 0 });
      }
      bool empty = false;
      for(std::uint32_t l = 0; l < n && !empty; ++l)
      {
        if(l == i)
          continue;
        const double* Di = m_candidates[i].value.data();
        const double* Dl = m_candidates[l].value.data();
        if(Di[0] == Dl[0] && Di[1] == Dl[1] && Di[2] == Dl[2])
        {
          // identical fields on this face: the lower site index takes it all
          if(m_candidates[l].site < m_candidates[i].site) empty = true;
          continue;
        }
        if(Dl[0] > Di[0] && Dl[1] > Di[1] && Dl[2] > Di[2])
          continue;   // l is above i on the whole face
        empty = !clip(piece, i, l, result.degenerate);
      }
      if(empty)
        result.pieces.pop_back();
    }
  }

private:
  // Clips the piece of candidate i by {h_il <= 0}; returns false if nothing of positive
  // area remains. Works in the cutter's scratch arrays, sized by cut() for the largest piece.
  bool clip(Symbolic_piece& piece, std::uint32_t i, std::uint32_t l, bool& degenerate) const
  {
    const std::size_t n = piece.vertices.size();
    CGAL_assertion(n + 1 <= m_out_vertices.size());
    int* signs = m_signs.data();
    bool any_positive = false, any_negative = false;
    for(std::size_t k = 0; k < n; ++k)
    {
      signs[k] = sign_at(piece.vertices[k], i, l);
      any_positive |= (signs[k] > 0);
      any_negative |= (signs[k] < 0);
      if(signs[k] == 0) degenerate = true;
    }
    if(!any_positive)
      return true;
    if(!any_negative)
      return false;

    // each output vertex, and where it comes from: input vertex k, or the crossing on input
    // edge k (from vertex k to k + 1)
    Symbolic_vertex* out = m_out_vertices.data();
    std::uint32_t* origin = m_origin.data();
    bool* crossing = m_crossing.data();
    std::size_t m = 0;
    for(std::size_t k = 0; k < n; ++k)
    {
      const std::size_t k1 = (k + 1 == n) ? 0 : k + 1;
      if(signs[k] <= 0)
      {
        out[m] = piece.vertices[k];
        origin[m] = std::uint32_t(k);
        crossing[m++] = false;
      }
      if(signs[k] * signs[k1] < 0)
      {
        const Piece_edge_support& s = piece.supports[k];
        out[m] = s.on_mesh_edge ? Symbolic_vertex{ Symbolic_vertex::EDGE, s.local, l, 0 }
                                : Symbolic_vertex{ Symbolic_vertex::TRIPLE, 0, s.other, l };
        origin[m] = std::uint32_t(k);
        crossing[m++] = true;
      }
    }
    if(m < 3)
      return false;
    Piece_edge_support* supports = m_out_supports.data();
    for(std::size_t k = 0; k < m; ++k)
    {
      const std::size_t w = (k + 1 == m) ? 0 : k + 1;
      // the output edge follows input edge origin[k] directly iff w is on that same edge
      const std::uint32_t next = (origin[k] + 1 == n) ? 0 : origin[k] + 1;
      const bool direct = crossing[w] ? origin[w] == origin[k] : origin[w] == next;
      supports[k] = direct ? piece.supports[origin[k]] : Piece_edge_support{ false, 0, l };
    }
    piece.vertices.assign(out, out + m);
    piece.supports.assign(supports, supports + m);
    return true;
  }

  Candidate_range m_candidates;
  // scratch of clip(): a piece starts with 3 vertices and gains at most one per clip
  mutable boost::container::small_vector<int, 16> m_signs;
  mutable boost::container::small_vector<Symbolic_vertex, 16> m_out_vertices;
  mutable boost::container::small_vector<std::uint32_t, 16> m_origin;
  mutable boost::container::small_vector<bool, 16> m_crossing;
  mutable boost::container::small_vector<Piece_edge_support, 16> m_out_supports;
};

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_FACE_CUTTER_H
