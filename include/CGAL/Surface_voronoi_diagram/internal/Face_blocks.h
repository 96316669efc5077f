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
// Blocks of faces that are close in space, for a propagation that runs block by block: the
// faces in the order of their centroids' cells along a Morton curve, cut into runs of equal
// size. The blocks depend on the mesh and on their number only (not on threads), so that what
// is computed block by block is the same on any number of threads.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_FACE_BLOCKS_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_FACE_BLOCKS_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/internal/Indexed_mesh.h>
#include <CGAL/Surface_voronoi_diagram/internal/parallel.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

// the bits of a 6-bit cell coordinate spread to every third position
inline std::uint32_t spread_bits(std::uint32_t x)
{
  std::uint32_t r = 0;
  for(int b = 0; b < 6; ++b) r |= ((x >> b) & 1u) << (3 * b);
  return r;
}

/// The block of every face: `count` blocks of consecutive faces along a Morton curve through a
/// 64 x 64 x 64 grid on the bounding box of the face centroids (a counting sort: linear in the
/// number of faces), in curve order.
/// \pre `0 < count <= number of faces`
template <class TriangleMesh>
std::vector<std::uint32_t> face_blocks(const Indexed_mesh<TriangleMesh>& mesh, std::size_t count, bool parallel = false)
{
  const std::size_t nf = mesh.number_of_faces();
  CGAL_precondition(count > 0 && count <= nf);
  constexpr std::uint32_t grid = 64;
  auto centroid = [&](std::size_t f, int axis) {
    const auto& t = mesh.triangles[f];
    return (mesh.points[t[0]][axis] + mesh.points[t[1]][axis] + mesh.points[t[2]][axis]) / 3.;
  };
  // the box of the centroids, by chunks (a minimum and a maximum are the same in any order)
  typedef std::array<std::array<double, 3>, 2> Box;
  const std::size_t chunk = 65536;
  std::vector<Box> box_of_chunk(number_of_chunks(nf, chunk));
  for_each_chunk(nf, chunk, parallel, [&](std::size_t begin, std::size_t end, std::size_t c) {
    Box& b = box_of_chunk[c];
    for(int a = 0; a < 3; ++a) b[0][a] = b[1][a] = centroid(begin, a);
    for(std::size_t f = begin + 1; f < end; ++f)
      for(int a = 0; a < 3; ++a)
      {
        const double x = centroid(f, a);
        b[0][a] = (std::min)(b[0][a], x);
        b[1][a] = (std::max)(b[1][a], x);
      }
  });
  std::array<double, 3> lo = box_of_chunk[0][0], hi = box_of_chunk[0][1];
  for(const Box& b : box_of_chunk)
    for(int a = 0; a < 3; ++a)
    {
      lo[a] = (std::min)(lo[a], b[0][a]);
      hi[a] = (std::max)(hi[a], b[1][a]);
    }
  std::vector<std::uint32_t> cell(nf);
  for_each_chunk(nf, chunk, parallel, [&](std::size_t begin, std::size_t end, std::size_t) {
    for(std::size_t f = begin; f < end; ++f)
    {
      std::uint32_t code = 0;
      for(int a = 0; a < 3; ++a)
      {
        const double extent = hi[a] - lo[a];
        // a flat box, or a centroid that is not a number, goes to the first cell
        double x = extent > 0 ? (centroid(f, a) - lo[a]) / extent * grid : 0.;
        if(!(x >= 0)) x = 0;
        const std::uint32_t i = (std::min)(grid - 1, static_cast<std::uint32_t>((std::min)(x, double(grid - 1))));
        code |= spread_bits(i) << a;
      }
      cell[f] = code;
    }
  });
  // a counting sort by cell, sequential (262,144 counters)
  std::vector<std::uint32_t> start(grid * grid * grid + 1, 0);
  for(std::size_t f = 0; f < nf; ++f) ++start[cell[f] + 1];
  for(std::size_t c = 1; c < start.size(); ++c) start[c] += start[c - 1];
  std::vector<std::uint32_t> order(nf);
  for(std::size_t f = 0; f < nf; ++f) order[start[cell[f]]++] = static_cast<std::uint32_t>(f);
  std::vector<std::uint32_t> block(nf);
  for(std::size_t i = 0; i < nf; ++i) block[order[i]] = static_cast<std::uint32_t>(i * count / nf);
  return block;
}

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_FACE_BLOCKS_H
