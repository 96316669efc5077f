// Copyright (c) 2026 The Surface_voronoi_diagram authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Site insertion, interpolation mode: every site, whether given as a vertex, a face
// location or a point in space, becomes a face of the mesh plus barycentric coordinates.
// The mesh is not modified; the site's embedding is the interpolation of its face's corners.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_SITES_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_SITES_H

#include <CGAL/Surface_voronoi_diagram/exceptions.h>
#include <CGAL/Surface_voronoi_diagram/internal/Indexed_mesh.h>
#include <CGAL/Surface_voronoi_diagram/internal/site_fields.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Polygon_mesh_processing/locate.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

template <class TriangleMesh, class VertexPointMap>
class Site_locator
{
public:
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::face_descriptor face_descriptor;
  typedef typename boost::property_traits<VertexPointMap>::value_type Point_3;
  typedef typename CGAL::Kernel_traits<Point_3>::Kernel Kernel;
  typedef CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double> Face_location;
  typedef CGAL::AABB_face_graph_triangle_primitive<TriangleMesh, VertexPointMap> Primitive;
  typedef CGAL::AABB_traits<Kernel, Primitive> AABB_traits;
  typedef CGAL::AABB_tree<AABB_traits> AABB_tree;

  Site_locator(const TriangleMesh& tm, VertexPointMap vpm, const Indexed_mesh<TriangleMesh>& mesh, double max_distance)
    : m_tm(tm), m_vpm(vpm), m_mesh(mesh), m_max_distance(max_distance)
  {}

  Site locate(const Face_location& l, std::size_t index) const
  {
    // locate() may return coordinates a little below zero for points on an edge of a thin
    // triangle: those are clamped; clearly invalid ones are an error
    double sum = 0;
    for(double b : l.second)
    {
      if(!std::isfinite(b) || b < -1e-6)
        throw Input_error("site " + std::to_string(index) + " has invalid barycentric coordinates");
      sum += (std::max)(0., b);
    }
    if(std::abs(sum - 1) > 1e-6)
      throw Input_error("site " + std::to_string(index) + ": barycentric coordinates do not sum to 1");
    if(l.first == GT::null_face())
      throw Input_error("site " + std::to_string(index) + " is in the null face");
    Site s;
    s.face = get(m_mesh.face_index, l.first);
    for(int k = 0; k < 3; ++k) s.barycentric[k] = (std::max)(0., l.second[k]) / sum;
    return s;
  }

  Site locate(vertex_descriptor v, std::size_t index) const
  {
    for(auto h : CGAL::halfedges_around_target(v, m_tm))
    {
      if(is_border(h, m_tm)) continue;
      Site s;
      s.face = get(m_mesh.face_index, face(h, m_tm));
      for(int k = 0; k < 3; ++k)
        s.barycentric[k] = (m_mesh.triangles[s.face][k] == get(m_mesh.vertex_index, v)) ? 1. : 0.;
      return s;
    }
    throw Input_error("site " + std::to_string(index) + " is a vertex with no incident face");
  }

  Site locate(const Point_3& p, std::size_t index) const
  {
    for(int c = 0; c < 3; ++c)
      if(!std::isfinite(CGAL::to_double(p[c])))
        throw Input_error("site " + std::to_string(index) + " has a non-finite coordinate");
    if(!m_tree)
    {
      m_tree.reset(new AABB_tree());
      CGAL::Polygon_mesh_processing::build_AABB_tree(m_tm, *m_tree, CGAL::parameters::vertex_point_map(m_vpm));
      m_tree->accelerate_distance_queries();
    }
    const Face_location l = CGAL::Polygon_mesh_processing::locate_with_AABB_tree(
        p, *m_tree, m_tm, CGAL::parameters::vertex_point_map(m_vpm));
    Site s = locate(l, index);
    const std::array<double, 3> q = m_mesh.point_at(s.face, s.barycentric);
    double d2 = 0;
    for(int c = 0; c < 3; ++c) d2 += (q[c] - CGAL::to_double(p[c])) * (q[c] - CGAL::to_double(p[c]));
    const double d = std::sqrt(d2);
    if(d > m_max_distance)
    {
      std::ostringstream os;
      os.precision(6);
      os << "site " << index << " is " << d << " from the surface (more than the allowed " << m_max_distance << ")";
      throw Site_too_far_error(os.str(), index, d);
    }
    return s;
  }

private:
  const TriangleMesh& m_tm;
  VertexPointMap m_vpm;
  const Indexed_mesh<TriangleMesh>& m_mesh;
  double m_max_distance;
  mutable std::unique_ptr<AABB_tree> m_tree;
};

/// Two sites at the same surface point would give one of them an empty cell: refuse them.
template <class TriangleMesh>
void check_distinct_sites(const Indexed_mesh<TriangleMesh>& mesh, const std::vector<Site>& sites)
{
  std::vector<std::array<double, 3> > p(sites.size());
  for(std::size_t i = 0; i < sites.size(); ++i)
    p[i] = mesh.point_at(sites[i].face, sites[i].barycentric);
  std::vector<std::size_t> order(sites.size());
  for(std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return p[a] < p[b] || (p[a] == p[b] && a < b);
  });
  for(std::size_t k = 1; k < order.size(); ++k)
  {
    const std::size_t a = order[k - 1], b = order[k];
    if(p[a] == p[b])
    {
      std::ostringstream os;
      os.precision(17);
      os << "sites " << a << " and " << b << " are at the same surface point (" << p[a][0] << ", "
         << p[a][1] << ", " << p[a][2] << ")";
      throw Coincident_sites_error(os.str(), a, b);
    }
  }
}

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif
