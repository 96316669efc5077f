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
// The partition of the surface that the pipeline produces and every output reads: convex
// pieces, each inside one face and owned by one site, with vertices shared across faces.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_PARTITION_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_PARTITION_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/internal/Double_kernel.h>

#include <CGAL/assertions.h>

#include <boost/container/small_vector.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

/// the site index of what no site reaches
constexpr std::size_t no_site = std::size_t(-1);

/// A site index stored in 32 bits, read and written as a `std::size_t` that keeps `no_site`.
class Site_index_32
{
public:
  Site_index_32(std::size_t site = no_site) : m_site(site == no_site ? none : static_cast<std::uint32_t>(site))
  {
    CGAL_precondition_msg(site == no_site || site < none, "too many sites for 32-bit indices");
  }
  operator std::size_t() const { return m_site == none ? no_site : std::size_t(m_site); }

private:
  static constexpr std::uint32_t none = 0xffffffffu;
  std::uint32_t m_site;
};

struct Partition
{
  enum Location_kind : std::uint8_t { AT_CORNER, ON_EDGE, IN_FACE };
  struct Vertex   // 40 bytes: a million-face mesh's diagram has about as many
  {
    Point_d point;
    double t;                // ON_EDGE: parameter from the edge's lower vertex index
    std::uint32_t element;   // mesh vertex, mesh edge or face (32-bit, as Indexed_mesh)
    Location_kind kind;
  };
  /// A piece's vertex ids: 3 or 4 for most pieces, kept inline, so that a
  /// million pieces are not a million heap blocks to allocate and free.
  typedef boost::container::small_vector<std::uint32_t, 4> Vertex_cycle;

  struct Piece
  {
    std::uint32_t face;
    Site_index_32 site;    // no_site where no site reaches
    Vertex_cycle vertices;   // counter-clockwise, as the face
    double area;
  };

  std::vector<Vertex> vertices;
  std::vector<Piece> pieces;                // grouped by face, in face order, sites ascending
  // pieces of face f: [face_begin[f], face_begin[f+1]); 32-bit like the partition's ids (the
  // stitcher checks the count)
  std::vector<std::uint32_t> face_begin;
  std::size_t welded_vertices = 0;
  std::size_t inserted_vertices = 0;
  std::size_t dropped_pieces = 0;          // pieces left without area by welding or collinear

  /// the piece of `site` in face `f`, or no_site
  std::size_t piece_of(std::size_t f, std::size_t site) const
  {
    for(std::size_t p = face_begin[f]; p < face_begin[f + 1]; ++p)
      if(pieces[p].site == site) return p;
    return no_site;
  }

  /// Whether vertex `id` lies on edge `e` of `mesh` (an `Indexed_mesh`), a corner of the edge
  /// included; `t` receives its parameter from the edge's lower vertex index.
  template <class Mesh>
  bool on_mesh_edge(const Mesh& mesh, std::size_t id, std::size_t e, double& t) const
  {
    const Vertex& v = vertices[id];
    t = (v.kind == AT_CORNER) ? (v.element == mesh.edge_vertices[e][0] ? 0. : 1.) : v.t;
    if(v.kind == AT_CORNER) return v.element == mesh.edge_vertices[e][0] || v.element == mesh.edge_vertices[e][1];
    return v.kind == ON_EDGE && v.element == e;
  }

  /// Replaces the pieces of the faces `faces` (ascending) by `fresh` (grouped by face in the
  /// same order), moving the pieces between them in place, each run of them by the change in
  /// the number of pieces before it.
  void replace_pieces(const std::vector<std::size_t>& faces, std::vector<Piece>& fresh)
  {
    const std::size_t n = faces.size(), old_size = pieces.size();
    std::vector<std::size_t> first(n + 1, 0);   // of each face's pieces in `fresh`
    std::vector<std::ptrdiff_t> shift(n);       // of the run of pieces after faces[i]
    std::ptrdiff_t s = 0;
    for(std::size_t i = 0, r = 0; i < n; ++i)
    {
      first[i] = r;
      while(r < fresh.size() && fresh[r].face == faces[i]) ++r;
      first[i + 1] = r;
      s += std::ptrdiff_t(r - first[i]) - std::ptrdiff_t(face_begin[faces[i] + 1] - face_begin[faces[i]]);
      shift[i] = s;
    }
    CGAL_precondition(first[n] == fresh.size() && std::ptrdiff_t(old_size) + s < std::ptrdiff_t(0xffffffffu));
    auto run = [&](std::size_t i) {   // the pieces after faces[i], up to the next one
      return std::make_pair(pieces.begin() + face_begin[faces[i] + 1], pieces.begin() + (i + 1 < n ? face_begin[faces[i + 1]] : old_size));
    };
    if(s > 0) pieces.resize(old_size + std::size_t(s));
    // runs moving down in order, runs moving up in reverse: none overwrites one still to move
    for(std::size_t i = 0; i < n; ++i)
      if(shift[i] < 0) std::move(run(i).first, run(i).second, run(i).first + shift[i]);
    for(std::size_t i = n; i-- > 0;)
      if(shift[i] > 0) std::move_backward(run(i).first, run(i).second, run(i).second + shift[i]);
    for(std::size_t i = 0; i < n; ++i)
      std::move(fresh.begin() + first[i], fresh.begin() + first[i + 1], pieces.begin() + face_begin[faces[i]] + (i ? shift[i - 1] : 0));
    if(s < 0) pieces.resize(std::size_t(std::ptrdiff_t(old_size) + s));
    for(std::size_t i = 0; i < n; ++i)
      for(std::size_t f = faces[i] + 1; f <= (i + 1 < n ? faces[i + 1] : face_begin.size() - 1); ++f)
        face_begin[f] = std::uint32_t(std::ptrdiff_t(face_begin[f]) + shift[i]);
  }

  /// face_begin again after pieces were removed (faces left without a piece get an empty range)
  void rebuild_face_begin(std::size_t number_of_faces)
  {
    CGAL_precondition(pieces.size() < std::size_t(0xffffffffu));
    face_begin.assign(number_of_faces + 1, std::uint32_t(pieces.size()));
    for(std::size_t p = pieces.size(); p-- > 0;)
      face_begin[pieces[p].face] = std::uint32_t(p);
    for(std::size_t f = number_of_faces; f-- > 0;)
      if(face_begin[f] > face_begin[f + 1]) face_begin[f] = face_begin[f + 1];
  }
};

/// Removes consecutive repeats from a cyclic vertex list (the last and the first are
/// consecutive too), as welding leaves them.
inline void remove_cyclic_repeats(Partition::Vertex_cycle& cycle)
{
  std::size_t kept = 0;
  for(std::size_t k = 0; k < cycle.size(); ++k)
    if(kept == 0 || cycle[kept - 1] != cycle[k]) cycle[kept++] = cycle[k];
  cycle.resize(kept);
  while(cycle.size() > 1 && cycle.front() == cycle.back()) cycle.pop_back();
}

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_PARTITION_H
