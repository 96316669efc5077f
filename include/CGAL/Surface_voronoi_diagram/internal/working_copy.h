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
// The working copy that site insertion and refinement both start from: a Surface_mesh copy
// of the input whose faces remember the input face they lie in.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_WORKING_COPY_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_WORKING_COPY_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/helpers.h>

#include <iterator>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

/// Copies `tm` into `copy` (cleared by the caller) and returns its input-face map
/// ("f:svd_input_face"), filled for every face; `f2f` receives the (input face, copy face)
/// pairs in the input's face order.
template <class TriangleMesh, class VertexPointMap, class Mesh>
typename Mesh::template Property_map<typename Mesh::Face_index, typename boost::graph_traits<TriangleMesh>::face_descriptor>
copy_with_input_faces(const TriangleMesh& tm, VertexPointMap vpm, Mesh& copy,
                      std::vector<std::pair<typename boost::graph_traits<TriangleMesh>::face_descriptor,
                                            typename Mesh::Face_index> >& f2f)
{
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor Input_face;
  CGAL::copy_face_graph(tm, copy, CGAL::parameters::vertex_point_map(vpm).face_to_face_output_iterator(std::back_inserter(f2f)));
  auto input_face = copy.template add_property_map<typename Mesh::Face_index, Input_face>(
                          "f:svd_input_face", boost::graph_traits<TriangleMesh>::null_face()).first;
  for(const auto& p : f2f) input_face[p.second] = p.first;
  return input_face;
}

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif
