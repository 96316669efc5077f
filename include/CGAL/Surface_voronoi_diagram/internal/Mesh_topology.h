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
// Components, boundary loops and genus of a polygon mesh, to compare a remesh with its input.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_MESH_TOPOLOGY_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_MESH_TOPOLOGY_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <cstddef>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

struct Mesh_topology
{
  std::size_t components = 0;       // connected components of faces
  std::size_t boundary_loops = 0;
  long genus = 0;                   // summed over the components
};

// Each component of Euler characteristic V - E + F = 2 - 2g - b; vertices and edges of no
// face are not counted.
template <class PolygonMesh>
Mesh_topology mesh_topology(const PolygonMesh& pm)
{
  typedef boost::graph_traits<PolygonMesh> GT;
  Mesh_topology t;
  auto component = get(CGAL::dynamic_face_property_t<std::size_t>(), pm);
  t.components = CGAL::Polygon_mesh_processing::connected_components(pm, component);

  auto seen = get(CGAL::dynamic_halfedge_property_t<bool>(), pm);
  for(typename GT::halfedge_descriptor h : halfedges(pm)) put(seen, h, false);
  for(typename GT::halfedge_descriptor h : halfedges(pm))
  {
    if(!is_border(h, pm) || get(seen, h)) continue;
    ++t.boundary_loops;
    for(typename GT::halfedge_descriptor g : CGAL::halfedges_around_face(h, pm)) put(seen, g, true);
  }

  long v = 0, e = 0, f = 0;
  for(typename GT::vertex_descriptor x : vertices(pm))
    v += (halfedge(x, pm) != GT::null_halfedge());
  for(typename GT::edge_descriptor x : edges(pm))
    e += !(is_border(halfedge(x, pm), pm) && is_border(opposite(halfedge(x, pm), pm), pm));
  f = static_cast<long>(num_faces(pm));
  const long euler = v - e + f;
  t.genus = (2 * static_cast<long>(t.components) - static_cast<long>(t.boundary_loops) - euler) / 2;
  return t;
}

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_MESH_TOPOLOGY_H
