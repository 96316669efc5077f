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
// Lloyd's projection of a cell's centroid back to the surface, onto the nearest point of the
// faces the cell reaches. Searching those faces only, and not the whole surface, keeps a site
// on its own side of a thin wall (the centroid of a cell on a thin plate can lie nearer the
// other side), and costs a few projections per site instead of a tree search.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_NEAREST_POINT_OF_CELL_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_NEAREST_POINT_OF_CELL_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/internal/Candidate_table.h>
#include <CGAL/Surface_voronoi_diagram/internal/Double_kernel.h>
#include <CGAL/Surface_voronoi_diagram/internal/Indexed_mesh.h>

#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/squared_distance_3.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

template <class TriangleMesh, class VertexPointMap, class GeomTraits>
class Nearest_point_of_cell
{
public:
  typedef Indexed_mesh<TriangleMesh> Mesh;
  typedef typename GeomTraits::Point_3 Point_3;
  typedef CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double> Location;

  /// the faces' bounding spheres, computed once for all the iterations
  Nearest_point_of_cell(const Mesh& mesh, const TriangleMesh& tm, const VertexPointMap& vpm, const GeomTraits& gt)
    : m_mesh(mesh), m_tm(tm), m_vpm(vpm), m_gt(gt)
  {
    const std::size_t nf = mesh.number_of_faces();
    m_center.resize(nf);
    m_radius.resize(nf);
    for(std::size_t f = 0; f < nf; ++f)
    {
      m_center[f] = CGAL::centroid(mesh.corner(f, 0), mesh.corner(f, 1), mesh.corner(f, 2));
      double r2 = squared_length(mesh.corner(f, 0) - m_center[f]);
      for(int k = 1; k < 3; ++k) r2 = (std::max)(r2, squared_length(mesh.corner(f, k) - m_center[f]));
      m_radius[f] = std::sqrt(r2);
    }
  }

  /// The faces each site is a candidate of, site by site and in face order, from the
  /// diagram's candidates.
  void set_cells(const Candidate_table& candidates, std::size_t number_of_sites)
  {
    m_first.assign(number_of_sites + 1, 0);
    for(std::size_t f = 0; f < candidates.size(); ++f)
      for(const Candidate& x : candidates[f]) ++m_first[x.site + 1];
    for(std::size_t i = 0; i < number_of_sites; ++i) m_first[i + 1] += m_first[i];
    m_faces.resize(m_first.back());
    std::vector<std::uint32_t> next(m_first.begin(), m_first.end() - 1);
    for(std::size_t f = 0; f < candidates.size(); ++f)
      for(const Candidate& x : candidates[f]) m_faces[next[x.site]++] = static_cast<std::uint32_t>(f);
  }

  /// The nearest point to `p` of site i's faces and of `own_face` (the site's face), constructed
  /// by the traits. The search starts from the face of the nearest bounding sphere and looks
  /// at the others in their order, those whose sphere is nearer than the nearest point found;
  /// where faces tie, the first searched keeps it.
  Location locate(const Point_3& p, std::size_t i, std::size_t own_face) const
  {
    const Point_d q = to_point_d(p);
    m_order.clear();
    auto lower_bound = [&](std::size_t f) { return std::sqrt(squared_length(q - m_center[f])) - m_radius[f]; };
    m_order.emplace_back(lower_bound(own_face), own_face);
    for(std::uint32_t k = m_first[i]; k < m_first[i + 1]; ++k)
      if(m_faces[k] != own_face) m_order.emplace_back(lower_bound(m_faces[k]), m_faces[k]);
    const std::size_t first = std::size_t(std::min_element(m_order.begin(), m_order.end()) - m_order.begin());
    std::size_t best_face = m_order[first].second;
    double best_distance = std::sqrt(squared_distance_to_face(q, best_face));
    for(std::size_t k = 0; k < m_order.size(); ++k)
    {
      // no point of the face is nearer than its sphere allows (with a margin for the rounding
      // of both distances: the search may look at a face more, never skip the nearest)
      if(k == first || m_order[k].first > best_distance * (1 + 1e-9) + 1e-300) continue;
      const double d = std::sqrt(squared_distance_to_face(q, m_order[k].second));
      if(d < best_distance)
      {
        best_distance = d;
        best_face = m_order[k].second;
      }
    }
    // the point itself constructed by the traits, on the face chosen in doubles
    const Point_3 best = project(p, best_face);
    return locate_in_face(best, m_mesh.face_handles[best_face], m_tm, m_vpm, m_gt);
  }

private:
  static double squared_length(const Vector_d& v) { return v * v; }

  double squared_distance_to_face(const Point_d& q, std::size_t f) const
  {
    return CGAL::squared_distance(q, Double_kernel::Triangle_3(m_mesh.corner(f, 0), m_mesh.corner(f, 1), m_mesh.corner(f, 2)));
  }

  Point_3 project(const Point_3& p, std::size_t f) const
  {
    const auto h = halfedge(m_mesh.face_handles[f], m_tm);
    const auto triangle = m_gt.construct_triangle_3_object()(get(m_vpm, target(h, m_tm)), get(m_vpm, target(next(h, m_tm), m_tm)),
                                                             get(m_vpm, source(h, m_tm)));
    return m_gt.construct_projected_point_3_object()(triangle, p);
  }

  const Mesh& m_mesh;
  const TriangleMesh& m_tm;
  VertexPointMap m_vpm;
  GeomTraits m_gt;
  std::vector<Point_d> m_center;
  std::vector<double> m_radius;
  std::vector<std::uint32_t> m_first;   // site i's faces: m_faces[m_first[i]] .. m_faces[m_first[i + 1]]
  std::vector<std::uint32_t> m_faces;
  mutable std::vector<std::pair<double, std::size_t> > m_order;   // (sphere's distance, face) of one search
};

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_NEAREST_POINT_OF_CELL_H
