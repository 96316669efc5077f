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
// The cuts of all the faces of a diagram, in flat arrays (a record per face, then the pieces,
// their vertices and their edges' supports) instead of a vector of pieces per face, each with
// its own inline buffers, the largest allocation of a diagram, for what fits in about half. The pieces, vertices and supports are stored chunk by
// chunk of faces, each chunk in arrays of exactly its size, filled from a scratch buffer that
// the next chunk reuses: concurrent chunks then touch no more fresh memory than one sequential
// pass, and nothing is concatenated (first touches of fresh memory can cost more than the
// cutting). The stages read a face's cut through a light view (`operator[]`) with the
// members of `Face_cut`.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_FACE_CUTS_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_FACE_CUTS_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/internal/Candidate_table.h>
#include <CGAL/Surface_voronoi_diagram/internal/Face_cutter.h>
#include <CGAL/Surface_voronoi_diagram/internal/parallel.h>

#include <CGAL/assertions.h>

#include <boost/iterator/counting_iterator.hpp>
#include <boost/iterator/transform_iterator.hpp>
#include <boost/range/iterator_range.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

class Face_cuts
{
  struct Face_record   // 12 bytes, a million on a million-face mesh
  {
    Face_record() : chunk(0), first_piece(0), number_of_pieces(0), whole_face(0), degenerate(0) {}
    std::uint32_t chunk;
    std::uint32_t first_piece;             // in its chunk
    std::uint32_t number_of_pieces : 30;   // up to one per candidate
    std::uint32_t whole_face : 1;
    std::uint32_t degenerate : 1;
  };
  struct Piece_record
  {
    std::uint32_t candidate;
    std::uint32_t first_vertex;   // into the chunk's vertices and supports alike
    std::uint32_t number_of_vertices;
  };
  // the pieces of a chunk of faces, each array of exactly its size
  struct Chunk
  {
    std::vector<Piece_record> pieces;
    std::vector<Symbolic_vertex> vertices;
    std::vector<Piece_edge_support> supports;
  };

public:
  /// a piece as `Symbolic_piece` has it
  struct Piece
  {
    std::uint32_t candidate;
    boost::iterator_range<const Symbolic_vertex*> vertices;      // runs of the chunk's arrays
    boost::iterator_range<const Piece_edge_support*> supports;
  };

  /// the piece of a chunk by its index there
  struct Piece_at
  {
    const Chunk* chunk;   // null for a face without pieces
    Piece operator()(std::size_t p) const { return piece(*chunk, p); }
  };
  /// the pieces of one face
  typedef boost::iterator_range<boost::transform_iterator<Piece_at, boost::counting_iterator<std::size_t> > > Pieces;

  /// one face's cut, as `Face_cut` has it
  struct Cut
  {
    Pieces pieces;
    bool degenerate;
    bool whole_face;
  };

  std::size_t number_of_faces() const { return m_faces.size(); }

  Cut operator[](std::size_t f) const
  {
    const Face_record& r = m_faces[f];
    const Piece_at at{ r.number_of_pieces == 0 ? nullptr : &m_chunks[r.chunk] };
    const boost::counting_iterator<std::size_t> first(r.first_piece), last(r.first_piece + r.number_of_pieces);
    return Cut{ Pieces(boost::make_transform_iterator(first, at), boost::make_transform_iterator(last, at)), r.degenerate != 0,
                r.whole_face != 0 };
  }

  /// every face without a cut (reached by nobody)
  void reset(std::size_t number_of_faces)
  {
    m_faces.assign(number_of_faces, Face_record());
    m_chunks.clear();
  }

  /// Cuts the faces `faces[0 .. count)` (`face(k)` gives the k-th) on their candidate lists,
  /// in concurrent chunks when `parallel`. A face cut again keeps its old pieces in the
  /// arrays unused (repair rounds cut few faces again); the chunks depend on `faces` alone,
  /// not on the threads.
  template <class FaceOfIndex>
  void cut(const Candidate_table& candidates, std::size_t count, const FaceOfIndex& face, bool parallel)
  {
    const std::size_t chunk_size = 8192;
    const std::size_t first_chunk = m_chunks.size(), chunks = number_of_chunks(count, chunk_size);
    CGAL_precondition_msg(first_chunk + chunks < std::size_t(0xffffffffu), "too many chunks of cut faces");
    m_chunks.resize(first_chunk + chunks);
    // a scratch buffer per group of chunks (one group without `parallel`), reused by its chunks
    // in turn: the groups do not depend on the threads, and which buffer a chunk uses changes
    // nothing it stores
    const std::size_t chunks_per_group = parallel ? 8 : (std::max)(chunks, std::size_t(1));
    std::vector<Buffer> buffers(number_of_chunks(chunks, chunks_per_group));
    for_each_chunk(chunks, chunks_per_group, parallel, [&](std::size_t first, std::size_t last, std::size_t g) {
      for(std::size_t c = first; c < last; ++c)
      {
        buffers[g].clear();
        for(std::size_t k = c * chunk_size; k < (std::min)(count, (c + 1) * chunk_size); ++k) cut_face(candidates, face(k), buffers[g]);
        store(buffers[g], first_chunk + c);
      }
    });
  }

  /// sets face f's cut to `c` (tests build cuts face by face)
  void set(std::size_t f, const Face_cut& c)
  {
    Buffer buffer;
    buffer.add(f, c);
    m_chunks.emplace_back();
    store(buffer, m_chunks.size() - 1);
  }

private:
  // what a chunk of faces cut: records with offsets into its own arrays
  struct Buffer : Chunk
  {
    std::vector<std::pair<std::size_t, Face_record> > faces;
    Face_cut scratch;   // one face's cut, its storage reused face after face

    void clear()
    {
      faces.clear();
      pieces.clear();
      vertices.clear();
      supports.clear();
    }

    void add(std::size_t f, const Face_cut& c)
    {
      Face_record r;
      r.first_piece = std::uint32_t(pieces.size());
      r.whole_face = c.whole_face;
      r.degenerate = c.degenerate;
      CGAL_precondition_msg(c.pieces.size() < (std::size_t(1) << 30), "too many pieces in one face");
      r.number_of_pieces = std::uint32_t(c.pieces.size());
      for(const Symbolic_piece& p : c.pieces)
      {
        pieces.push_back(Piece_record{ p.candidate, std::uint32_t(vertices.size()), std::uint32_t(p.vertices.size()) });
        vertices.insert(vertices.end(), p.vertices.begin(), p.vertices.end());
        supports.insert(supports.end(), p.supports.begin(), p.supports.end());
      }
      faces.emplace_back(f, r);
    }
  };

  static void cut_face(const Candidate_table& candidates, std::size_t f, Buffer& buffer)
  {
    const Candidate_range list = candidates[f];
    Face_cut& c = buffer.scratch;
    if(list.size() > 1)
      Face_cutter(list).cut(c);
    else
    {
      c.clear();
      c.whole_face = (list.size() == 1);   // the only candidate owns the whole triangle: no piece stored
    }
    buffer.add(f, c);
  }

  // the chunk's arrays as copies of the buffer's, of exactly their size; its faces' records
  // (each face belongs to one chunk of a cut, so concurrent chunks write different records)
  void store(const Buffer& b, std::size_t c)
  {
    CGAL_precondition_msg(b.vertices.size() < std::size_t(0xffffffffu) && b.pieces.size() < std::size_t(0xffffffffu),
                          "too many cut pieces for 32-bit offsets");
    m_chunks[c] = static_cast<const Chunk&>(b);   // its pieces, vertices and supports
    for(const auto& fr : b.faces)
    {
      Face_record r = fr.second;
      r.chunk = static_cast<std::uint32_t>(c);
      m_faces[fr.first] = r;
    }
  }

  static Piece piece(const Chunk& chunk, std::size_t p)
  {
    const Piece_record& r = chunk.pieces[p];
    const Symbolic_vertex* vertices = chunk.vertices.data() + r.first_vertex;
    const Piece_edge_support* supports = chunk.supports.data() + r.first_vertex;
    return Piece{ r.candidate, boost::make_iterator_range(vertices, vertices + r.number_of_vertices),
                  boost::make_iterator_range(supports, supports + r.number_of_vertices) };
  }

  std::vector<Face_record> m_faces;
  std::vector<Chunk> m_chunks;
};

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_FACE_CUTS_H
