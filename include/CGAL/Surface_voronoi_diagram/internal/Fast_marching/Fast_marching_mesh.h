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
// The mesh as fast marching needs it, on top of the shared `Indexed_mesh` (no copy of its
// points or triangles): each face's edge lengths, the face corners around each vertex and,
// for each corner with an obtuse angle, a vertex unfolded from the faces beyond the opposite
// edge that splits the corner into two acute virtual triangles (Kimmel and Sethian's remedy).

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_FAST_MARCHING_FAST_MARCHING_MESH_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_FAST_MARCHING_FAST_MARCHING_MESH_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/internal/Double_kernel.h>
#include <CGAL/Surface_voronoi_diagram/internal/Indexed_mesh.h>
#include <CGAL/Surface_voronoi_diagram/internal/Fast_marching/point_source_update.h>

#include <CGAL/assertions.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

template <class TriangleMesh>
class Fast_marching_mesh
{
public:
  typedef Indexed_mesh<TriangleMesh> Mesh;
  static constexpr std::uint32_t none = std::uint32_t(-1);

  /// Corner c of a face, obtuse, with opposite corners a and b: the split vertex d and the
  /// unfolded positions of a, b and d in a plane where c is the origin.
  struct Split
  {
    std::uint32_t face, corner, vertex;
    Point_2d a, b, d;
  };

  /// What an update reads of a face besides its corners: the lengths of its local edges
  /// (edge k joins corners k and k+1) and the split of each obtuse corner. A face's record
  /// is shared by the rings of its three corners, which keeps the rings at 4 bytes per corner.
  struct Face_record
  {
    std::array<double, 3> edge_length;
    std::array<std::uint32_t, 3> split;   // into `splits`, or `none`
  };

  /// \pre the mesh has fewer than 2^32 - 1 vertices and fewer than (2^32 - 1) / 3 faces
  explicit Fast_marching_mesh(const Mesh& mesh) : m_mesh(mesh) { build(); }

  const Mesh& mesh() const { return m_mesh; }
  std::uint32_t vertex(std::size_t f, int k) const { return static_cast<std::uint32_t>(m_mesh.triangles[f][k]); }

  /// the corner `3 f + k` of face `f` (corner k) is a corner of the face around its vertex
  static std::uint32_t face_of_corner(std::uint32_t c) { return c / 3; }
  static int local_corner(std::uint32_t c) { return int(c % 3); }

  std::vector<Face_record> faces;
  std::vector<std::uint32_t> ring_offsets;                  // CSR into `ring`
  std::vector<std::uint32_t> ring;                          // the corners at each vertex
  std::vector<Split> splits;
  std::vector<std::uint32_t> vertex_split_offsets, vertex_splits; // splits whose d is the vertex (CSR)

private:
  static double distance(const Point_d& p, const Point_d& q) { return std::sqrt((q - p).squared_length()); }

  void build()
  {
    const std::size_t n = m_mesh.number_of_vertices(), m = m_mesh.number_of_faces();
    CGAL_precondition(m < std::size_t(none) / 3);
    faces.resize(m);
    splits.clear();
    for(std::size_t f = 0; f < m; ++f)
      for(int k = 0; k < 3; ++k)
      {
        faces[f].edge_length[k] = distance(m_mesh.corner(f, k), m_mesh.corner(f, (k + 1) % 3));
        faces[f].split[k] = none;
        Split s;
        if(find_split(f, k, s))
        {
          faces[f].split[k] = static_cast<std::uint32_t>(splits.size());
          splits.push_back(s);
        }
      }
    // items 0 .. count - 1 grouped by vertex key(i), in increasing order within a vertex (CSR)
    auto group = [n](std::size_t count, const auto& key, std::vector<std::uint32_t>& offsets, std::vector<std::uint32_t>& items) {
      offsets.assign(n + 1, 0);
      for(std::size_t i = 0; i < count; ++i) ++offsets[key(i) + 1];
      for(std::size_t v = 0; v < n; ++v) offsets[v + 1] += offsets[v];
      items.resize(count);
      std::vector<std::uint32_t> fill(offsets.begin(), offsets.end() - 1);
      for(std::size_t i = 0; i < count; ++i) items[fill[key(i)]++] = static_cast<std::uint32_t>(i);
    };
    group(3 * m, [this](std::size_t c) { return vertex(c / 3, int(c % 3)); }, ring_offsets, ring);
    group(splits.size(), [this](std::size_t s) { return splits[s].vertex; }, vertex_split_offsets, vertex_splits);
  }

  // Unfolds the faces beyond the edge opposite an obtuse corner, one after the other, until a
  // vertex falls in the cone of directions that make a right or acute angle with both sides
  // of the corner. Gives up after a few faces or at a border.
  bool find_split(std::size_t f, int k, Split& split) const
  {
    const auto& points = m_mesh.points;
    const std::uint32_t vc = vertex(f, k), va = vertex(f, (k + 1) % 3), vb = vertex(f, (k + 2) % 3);
    const Vector_d ca = points[va] - points[vc], cb = points[vb] - points[vc];
    if(ca * cb >= 0) return false;   // not obtuse
    const double la = std::sqrt(ca.squared_length());
    if(!(la > 0)) return false;
    const double bx = (cb * ca) / la;
    const double by2 = cb * cb - bx * bx;
    if(!(by2 > 0)) return false;
    const Point_2d pa(la, 0.), pb(bx, std::sqrt(by2));

    std::size_t face = f;
    std::uint32_t ea = va, eb = vb;     // the edge to unfold across, and its unfolded ends
    Point_2d qa = pa, qb = pb;
    for(int step = 0; step < 10; ++step)
    {
      std::size_t g = Mesh::none;
      for(int j = 0; j < 3; ++j)
        if((vertex(face, j) == ea && vertex(face, (j + 1) % 3) == eb) || (vertex(face, j) == eb && vertex(face, (j + 1) % 3) == ea))
          g = m_mesh.neighbors[face][j];
      if(g == Mesh::none) return false;
      std::uint32_t d = none;
      for(int j = 0; j < 3; ++j)
        if(vertex(g, j) != ea && vertex(g, j) != eb) d = vertex(g, j);
      if(d == none || d == vc) return false;
      // d keeps its distances to ea and eb, on the far side of qa-qb from c
      const double L = std::sqrt((qb.x() - qa.x()) * (qb.x() - qa.x()) + (qb.y() - qa.y()) * (qb.y() - qa.y()));
      if(!(L > 0)) return false;
      const double la_d = distance(points[ea], points[d]);
      const double lb_d = distance(points[eb], points[d]);
      const double dx = (la_d * la_d - lb_d * lb_d + L * L) / (2 * L);
      const double dy2 = la_d * la_d - dx * dx;
      if(!(dy2 > 0)) return false;
      const double u[2] = { (qb.x() - qa.x()) / L, (qb.y() - qa.y()) / L };
      double w[2] = { -u[1], u[0] };
      if(w[0] * qa.x() + w[1] * qa.y() < 0) { w[0] = -w[0]; w[1] = -w[1]; }   // away from c
      const double dy = std::sqrt(dy2);
      const Point_2d pd(qa.x() + dx * u[0] + dy * w[0], qa.y() + dx * u[1] + dy * w[1]);
      const bool right_of_a = pd.x() * pa.x() + pd.y() * pa.y() >= 0;   // angle a-c-d at most 90 degrees
      const bool right_of_b = pd.x() * pb.x() + pd.y() * pb.y() >= 0;
      if(right_of_a && right_of_b)
      {
        split = Split{ static_cast<std::uint32_t>(f), static_cast<std::uint32_t>(k), d, pa, pb, pd };
        return true;
      }
      if(!right_of_b) { qa = pd; ea = d; }   // the cone lies between d and b
      else            { qb = pd; eb = d; }   // between a and d
      face = g;
    }
    return false;
  }

  const Mesh& m_mesh;
};

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_FAST_MARCHING_FAST_MARCHING_MESH_H
