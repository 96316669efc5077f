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
// Site location, interpolation mode: every site, whether given as a vertex, a face location
// or a point in space, becomes a face of the mesh plus barycentric coordinates. The mesh is
// not modified; the site's embedding is the interpolation of its face's corners. Points are
// located in doubles, so every kernel puts a point at the same place.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_SITE_LOCATOR_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_SITE_LOCATOR_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/exceptions.h>
#include <CGAL/Surface_voronoi_diagram/internal/Double_kernel.h>
#include <CGAL/Surface_voronoi_diagram/internal/Face_grid.h>
#include <CGAL/Surface_voronoi_diagram/internal/Indexed_mesh.h>
#include <CGAL/Surface_voronoi_diagram/internal/Site.h>

#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/Surface_mesh/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

// Whether a descriptor belongs to the mesh, where that can be told without reading memory
// the mesh does not own: index-based Surface_mesh descriptors are checked; other graphs'
// descriptors are handles, taken as given.
template <class Graph, class Descriptor>
bool is_element_of(const Graph&, const Descriptor&) { return true; }
template <class P>
bool is_element_of(const CGAL::Surface_mesh<P>& sm, typename CGAL::Surface_mesh<P>::Vertex_index v)
{
  return sm.has_valid_index(v) && !sm.is_removed(v);
}
template <class P>
bool is_element_of(const CGAL::Surface_mesh<P>& sm, typename CGAL::Surface_mesh<P>::Face_index f)
{
  return sm.has_valid_index(f) && !sm.is_removed(f);
}

/// Turns the sites given by the user into `Site`s. The checks here protect memory (a
/// descriptor of another mesh, coordinates that are not numbers): they stay on in every
/// build and throw `Input_error`.
template <class TriangleMesh>
class Site_locator
{
public:
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double> Face_location;

  Site_locator(const TriangleMesh& tm, const Indexed_mesh<TriangleMesh>& mesh, double max_distance)
    : m_tm(tm), m_mesh(mesh), m_max_distance(max_distance)
  {}

  /// the site, or `Input_error` naming what is wrong with it
  template <class Site_description>
  Site locate(const Site_description& site, std::size_t index) const
  {
    Site s;
    const std::string error = try_locate(site, index, s);
    if(error.empty()) return s;
    if(m_too_far) throw Site_too_far_error(error, index, m_too_far_distance);
    throw Input_error(error);
  }

  /// the same, returning the error message (empty if none) instead of throwing
  std::string try_locate(const Face_location& l, std::size_t index, Site& s) const
  {
    m_too_far = false;
    if(l.first == GT::null_face() || !is_element_of(m_tm, l.first))
      return "site " + std::to_string(index) + " is not in a face of the mesh";
    // locate() may return coordinates a little below zero for points on an edge of a thin
    // triangle: those are clamped; clearly invalid ones are an error
    double sum = 0;
    for(double b : l.second)
    {
      if(!std::isfinite(b) || b < -1e-6)
        return "site " + std::to_string(index) + " has invalid barycentric coordinates";
      sum += (std::max)(0., b);
    }
    if(std::abs(sum - 1) > 1e-6)
      return "site " + std::to_string(index) + ": barycentric coordinates do not sum to 1";
    s.face = get(m_mesh.face_index, l.first);
    for(int k = 0; k < 3; ++k) s.barycentric[k] = (std::max)(0., l.second[k]) / sum;
    return std::string();
  }

  std::string try_locate(vertex_descriptor v, std::size_t index, Site& s) const
  {
    m_too_far = false;
    if(v == GT::null_vertex() || !is_element_of(m_tm, v))
      return "site " + std::to_string(index) + " is not a vertex of the mesh";
    for(auto h : CGAL::halfedges_around_target(v, m_tm))
    {
      if(is_border(h, m_tm)) continue;
      s.face = get(m_mesh.face_index, face(h, m_tm));
      for(int k = 0; k < 3; ++k)
        s.barycentric[k] = (m_mesh.triangles[s.face][k] == get(m_mesh.vertex_index, v)) ? 1. : 0.;
      return std::string();
    }
    return "site " + std::to_string(index) + " is a vertex with no incident face";
  }

  template <class Point_3>
  std::string try_locate(const Point_3& point, std::size_t index, Site& s) const
  {
    m_too_far = false;
    const Point_d p = to_point_d(point);
    for(int c = 0; c < 3; ++c)
      if(!std::isfinite(p[c]))
        return "site " + std::to_string(index) + " has a non-finite coordinate";
    if(!m_grid)
      m_grid = std::make_shared<Face_grid>(m_mesh.number_of_faces(), [this](std::size_t f, int k) { return m_mesh.corner(f, k); });
    const Double_kernel kernel;
    auto nearest_point = [&](std::size_t f) {
      return kernel.construct_projected_point_3_object()(Double_kernel::Triangle_3(m_mesh.corner(f, 0), m_mesh.corner(f, 1), m_mesh.corner(f, 2)), p);
    };
    s.face = m_grid->nearest(p, [&](std::size_t f) { return CGAL::squared_distance(nearest_point(f), p); });
    const Barycentric b = m_mesh.barycentric_coordinates(s.face, nearest_point(s.face));
    double sum = 0;
    for(int k = 0; k < 3; ++k) sum += (s.barycentric[k] = (std::max)(0., b[k]));
    for(int k = 0; k < 3; ++k) s.barycentric[k] /= sum;
    const double d = std::sqrt(CGAL::squared_distance(m_mesh.point_at(s.face, s.barycentric), p));
    if(d > m_max_distance)
    {
      m_too_far = true;
      m_too_far_distance = d;
      std::ostringstream os;
      os.precision(6);
      os << "site " << index << " is " << d << " from the surface (more than the allowed " << m_max_distance << ")";
      return os.str();
    }
    return std::string();
  }

  /// whether the last failure was a site too far from the surface
  bool last_was_too_far() const { return m_too_far; }

private:
  const TriangleMesh& m_tm;
  const Indexed_mesh<TriangleMesh>& m_mesh;
  double m_max_distance;
  // built at the first site given as a point
  mutable std::shared_ptr<Face_grid> m_grid;
  mutable bool m_too_far = false;
  mutable double m_too_far_distance = 0;
};

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_SITE_LOCATOR_H
