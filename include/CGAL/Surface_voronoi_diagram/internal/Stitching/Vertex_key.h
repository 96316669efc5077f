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
// The combinatorial name of a partition vertex: a mesh vertex; the bisector of two sites
// crossing a mesh edge; or the point of a face where three sites are equidistant. Both faces
// of an edge derive the same name for the same vertex from the sites alone, which is what
// lets stitching share vertices across faces without comparing coordinates.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_STITCHING_VERTEX_KEY_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_STITCHING_VERTEX_KEY_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <algorithm>
#include <array>
#include <cstdint>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

struct Vertex_key
{
  enum Kind : std::uint8_t { MESH_VERTEX, EDGE_CROSSING, TRIPLE_POINT };

  Kind kind;
  std::uint32_t element;                 // the mesh vertex, the mesh edge, or the face (32-bit, as Indexed_mesh)
  std::array<std::uint32_t, 3> sites;    // ascending; EDGE_CROSSING uses two, MESH_VERTEX none

  static Vertex_key mesh_vertex(std::size_t v)
  {
    return Vertex_key{ MESH_VERTEX, std::uint32_t(v), {{ 0, 0, 0 }} };
  }
  static Vertex_key edge_crossing(std::size_t e, std::uint32_t s, std::uint32_t t)
  {
    return Vertex_key{ EDGE_CROSSING, std::uint32_t(e), {{ (std::min)(s, t), (std::max)(s, t), 0 }} };
  }
  static Vertex_key triple_point(std::size_t f, std::uint32_t a, std::uint32_t b, std::uint32_t c)
  {
    std::array<std::uint32_t, 3> s = {{ a, b, c }};
    std::sort(s.begin(), s.end());
    return Vertex_key{ TRIPLE_POINT, std::uint32_t(f), s };
  }

  bool operator==(const Vertex_key& o) const { return kind == o.kind && element == o.element && sites == o.sites; }
};

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_STITCHING_VERTEX_KEY_H
