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
// Output: the Voronoi diagram as a polygon mesh, one face per cell, written into any
// MutableFaceGraph.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_VORONOI_POLYGON_MESH_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_VORONOI_POLYGON_MESH_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/arrangement.h>
#include <CGAL/Surface_voronoi_diagram/internal/Labelled_arrangement.h>

#include <CGAL/assertions.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {

/// \ingroup PkgSurfaceVoronoiDiagramOutputs
///
/// Writes the Voronoi diagram of `diagram` into `out` (added to what `out` holds) as a
/// polygon mesh with one face per cell. The boundary of a cell is the face's boundary: its
/// vertices are the Voronoi vertices (where three or more cells meet, the surface border and
/// the area no site reaches each counting as one) and every point where the boundary bends
/// (where a bisector crosses an edge of the input, and the input's vertices along its border),
/// so the faces follow the surface and are in general neither planar nor convex. Faces are
/// oriented as the input.
///
/// Only a cell that is a closed disk can be one face. A cell in several pieces, with holes,
/// around a handle, touching itself at a point, or empty, is not written: the function
/// returns its site. Where such cells (or the border, or the area no site reaches) leave
/// several fans of faces around one point, each fan gets its own vertex there, so that `out`
/// is always a valid polygon mesh (`CGAL::is_valid_polygon_mesh()`). When every cell is a
/// disk and every point is reached, the faces tile the surface: on a closed input `out` is
/// closed, and its Euler characteristic is the input's.
///
/// \tparam Diagram a `CGAL::Surface_voronoi_diagram`
/// \tparam PolygonMesh a model of `MutableFaceGraph`
/// \param diagram the diagram
/// \param out the output mesh
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the property map of the points of `out`}
///     \cgalParamType{a model of `WritablePropertyMap` with `PolygonMesh`'s vertices as key}
///     \cgalParamDefault{`get(CGAL::vertex_point, out)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{face_patch_map}
///     \cgalParamDescription{receives the site of each output face}
///     \cgalParamType{a model of `WritablePropertyMap` with `PolygonMesh`'s faces as key and an integer type as value}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_is_constrained_map}
///     \cgalParamDescription{receives `true` at Voronoi vertices, `false` at the points where
///       a boundary only bends}
///     \cgalParamType{a model of `WritablePropertyMap` with `PolygonMesh`'s vertices as key and `bool` as value}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the sites whose cell was not written, ascending; empty when every cell is a face
/// \pre `!diagram.is_cancelled()`
/// \sa `make_arrangement()`, which writes every cell (as many convex pieces) whatever its shape
template <class Diagram, class PolygonMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
std::vector<std::size_t> make_voronoi_polygon_mesh(const Diagram& diagram, PolygonMesh& out,
                                                   const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef boost::graph_traits<PolygonMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::face_descriptor face_descriptor;
  typedef typename GetVertexPointMap<PolygonMesh, NamedParameters>::type VPM;
  typedef typename boost::property_traits<VPM>::value_type Point;
  typedef internal::Labelled_arrangement Arrangement;
  typedef Arrangement::Vertex Vertex;
  typedef Arrangement::Halfedge Halfedge;

  VPM vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_property_map(CGAL::vertex_point, out));
  auto face_site = choose_parameter(get_parameter(np, CGAL::internal_np::face_patch),
                                    CGAL::Constant_property_map<face_descriptor, int>(0));
  auto vertex_voronoi = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_is_constrained),
                                         CGAL::Constant_property_map<vertex_descriptor, bool>(false));
  typedef typename boost::property_traits<decltype(face_site)>::value_type Site_value;

  CGAL_precondition_msg(!diagram.is_cancelled(), "the diagram was cancelled: it has no cells");
  const Arrangement arrangement(diagram);
  const Arrangement::Mesh& mesh = arrangement.mesh();
  const std::size_t n = diagram.number_of_sites();
  std::vector<std::size_t> not_written;
  arrangement.cells_not_disks(n, not_written);
  std::vector<std::uint8_t> is_face(n, 1);
  for(std::size_t s : not_written) is_face[s] = 0;
  auto becomes_face = [&](std::int64_t label) { return label >= 0 && is_face[std::size_t(label)] != 0; };

  // one boundary halfedge of each disk cell, its region on the left
  std::vector<Halfedge> first(n, Halfedge());
  for(Halfedge h : mesh.halfedges())
  {
    const std::int64_t s = arrangement.label(h);
    if(becomes_face(s) && first[std::size_t(s)] == Halfedge() && arrangement.is_region_boundary(h))
      first[std::size_t(s)] = h;
  }

  // The output vertex of the corner of cell s at arrangement vertex v: the cells written
  // around v, in runs between the others, share one vertex per run (a fan of faces).
  std::map<std::pair<Vertex, std::int64_t>, vertex_descriptor> corner;
  std::vector<std::int64_t> ring;
  std::vector<vertex_descriptor> created;
  auto vertex_of = [&](Vertex v, std::int64_t s) {
    const auto found = corner.find(std::make_pair(v, s));
    if(found != corner.end()) return found->second;
    arrangement.labels_around(v, ring);
    const std::size_t m = ring.size();
    std::size_t gap = m;
    for(std::size_t k = 0; k < m && gap == m; ++k)
      if(!becomes_face(ring[k])) gap = k;
    const bool voronoi = arrangement.is_voronoi_vertex(v);
    const internal::Point_d& p = mesh.point(v);
    vertex_descriptor run_vertex = GT::null_vertex();
    for(std::size_t j = 1; j <= m; ++j)
    {
      const std::int64_t label = ring[(gap + j) % m];   // starts after a gap, if there is one
      if(!becomes_face(label)) { run_vertex = GT::null_vertex(); continue; }
      if(run_vertex == GT::null_vertex())
      {
        run_vertex = add_vertex(out);
        put(vpm, run_vertex, Point(p.x(), p.y(), p.z()));
        put(vertex_voronoi, run_vertex, voronoi);
        created.push_back(run_vertex);
      }
      corner.emplace(std::make_pair(v, label), run_vertex);
    }
    return corner.at(std::make_pair(v, s));
  };

  std::vector<vertex_descriptor> polygon;
  for(std::size_t s = 0; s < n; ++s)
  {
    if(!is_face[s]) continue;
    polygon.clear();
    // a disk cell passes each vertex of its boundary once
    // (a cell with no boundary halfedge is not closed)
    const Halfedge start = first[s];
    Halfedge h = start;
    bool closed = false;
    for(std::size_t steps = 0; start != Halfedge() && steps < mesh.number_of_halfedges() && !closed; ++steps)
    {
      polygon.push_back(vertex_of(mesh.source(h), std::int64_t(s)));
      h = arrangement.next_on_region_boundary(h);
      closed = (h == start);
    }
    const face_descriptor f = (closed && polygon.size() >= 3) ? CGAL::Euler::add_face(polygon, out) : GT::null_face();
    if(f == GT::null_face()) not_written.push_back(s);
    else put(face_site, f, internal::site_value<Site_value>(s));
  }
  // the corners of faces that could not be added
  for(vertex_descriptor v : created)
    if(halfedge(v, out) == GT::null_halfedge()) remove_vertex(v, out);
  std::sort(not_written.begin(), not_written.end());
  return not_written;
}

} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_VORONOI_POLYGON_MESH_H
