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
// Output: the arrangement, i.e. the input surface refined along every bisector, written into
// any MutableFaceGraph (Surface_mesh, Polyhedron_3, ...). Every face is a convex planar
// polygon inside one input triangle and inside one cell.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_ARRANGEMENT_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_ARRANGEMENT_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/parameters.h>
#include <CGAL/Surface_voronoi_diagram/internal/Diagram_data.h>

#include <CGAL/assertions.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Dynamic_property_map.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {

namespace internal {
template <class Value>
Value site_value(std::size_t site)
{
  return site == std::size_t(-1) ? static_cast<Value>(-1) : static_cast<Value>(site);
}

// Reserves the output's elements (CGAL's `reserve()` of the MutableFaceGraph models, which
// `copy_face_graph()` calls too): growing by doubling held up to three times the output's
// connectivity at once, the largest allocation of a diagram on a million-face mesh. The
// edges are counted exactly: the pieces' sides, each shared by two pieces but on the border,
// whose sides are the mesh's border edges split at the partition's vertices on them.
template <class TriangleMesh, class PolygonMesh>
void reserve_for_partition(const Partition& partition, const Indexed_mesh<TriangleMesh>& mesh, PolygonMesh& out)
{
  typedef boost::graph_traits<PolygonMesh> GT;
  std::size_t sides = 0;
  for(const Partition::Piece& piece : partition.pieces) sides += piece.vertices.size();
  std::vector<std::uint8_t> on_border(mesh.number_of_edges(), 0);
  std::size_t border_sides = 0;
  for(std::size_t f = 0; f < mesh.number_of_faces(); ++f)
    for(int k = 0; k < 3; ++k)
      if(mesh.neighbors[f][k] == Indexed_mesh<TriangleMesh>::none)
      {
        on_border[mesh.edges[f][k]] = 1;
        ++border_sides;
      }
  for(const Partition::Vertex& v : partition.vertices)
    if(v.kind == Partition::ON_EDGE && on_border[v.element]) ++border_sides;
  reserve(out, static_cast<typename GT::vertices_size_type>(vertices(out).size() + partition.vertices.size()),
          static_cast<typename GT::edges_size_type>(edges(out).size() + (sides + border_sides) / 2),
          static_cast<typename GT::faces_size_type>(faces(out).size() + partition.pieces.size()));
}

} // namespace internal

/// \ingroup PkgSurfaceVoronoiDiagramOutputs
///
/// Writes the arrangement of `diagram` into `out` (added to what `out` holds): the input
/// surface refined along every bisector. Every face is a convex planar polygon inside one
/// input triangle and inside one cell; the result passes `CGAL::is_valid_polygon_mesh()`.
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
///     \cgalParamDescription{receives the site of each output face (`-1`, converted to the
///       value type, where no site reaches)}
///     \cgalParamType{a model of `WritablePropertyMap` with `PolygonMesh`'s faces as key and an integer type as value}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{edge_is_constrained_map}
///     \cgalParamDescription{receives `true` for the edges on cell boundaries: bisectors (edges
///       whose two faces belong to different sites, or to a site and the unreached area) and
///       breakline edges; `false` for the others}
///     \cgalParamType{a model of `WritablePropertyMap` with `PolygonMesh`'s edges as key and `bool` as value}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_is_constrained_map}
///     \cgalParamDescription{receives `true` at Voronoi vertices (three or more cells meet, the
///       surface border counting as one), `false` elsewhere}
///     \cgalParamType{a model of `WritablePropertyMap` with `PolygonMesh`'s vertices as key and `bool` as value}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{Surface_voronoi::parameters::input_face_map}
///     \cgalParamDescription{receives the face of the diagram's mesh containing each output face}
///     \cgalParamType{a model of `WritablePropertyMap` with `PolygonMesh`'s faces as key and the diagram's faces as value}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \pre `!diagram.is_cancelled()`
template <class Diagram, class PolygonMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
void make_arrangement(const Diagram& diagram, PolygonMesh& out,
                      const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef boost::graph_traits<PolygonMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::face_descriptor face_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GetVertexPointMap<PolygonMesh, NamedParameters>::type VPM;
  typedef typename boost::property_traits<VPM>::value_type Point;

  VPM vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_property_map(CGAL::vertex_point, out));
  auto face_site = choose_parameter(get_parameter(np, CGAL::internal_np::face_patch),
                                    CGAL::Constant_property_map<face_descriptor, int>(0));
  auto edge_bisector = choose_parameter(get_parameter(np, CGAL::internal_np::edge_is_constrained),
                                        CGAL::Constant_property_map<typename GT::edge_descriptor, bool>(false));
  auto vertex_voronoi = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_is_constrained),
                                         CGAL::Constant_property_map<vertex_descriptor, bool>(false));
  auto input_face = choose_parameter(get_parameter(np, internal_np::input_face_map),
                                     CGAL::Constant_property_map<face_descriptor, typename Diagram::face_descriptor>());
  typedef typename boost::property_traits<decltype(face_site)>::value_type Site_value;

  CGAL_precondition_msg(!diagram.is_cancelled(), "the diagram was cancelled: it has no cells");
  const auto& data = internal::Diagram_access::data(diagram);
  const internal::Partition& partition = data.partition;
  std::vector<vertex_descriptor> vmap(partition.vertices.size(), GT::null_vertex());
  std::vector<std::size_t> site_of_face;
  std::vector<face_descriptor> created;
  created.reserve(partition.pieces.size());
  reserve_for_partition(partition, *data.mesh, out);
  std::vector<vertex_descriptor> polygon;
  for(const auto& piece : partition.pieces)
  {
    polygon.clear();
    for(std::size_t id : piece.vertices)
    {
      if(vmap[id] == GT::null_vertex())
      {
        vmap[id] = add_vertex(out);
        const auto& p = partition.vertices[id].point;
        put(vpm, vmap[id], Point(p.x(), p.y(), p.z()));
      }
      polygon.push_back(vmap[id]);
    }
    const face_descriptor f = CGAL::Euler::add_face(polygon, out);
    // stitching makes the pieces a valid polygon mesh: a piece that does not fit is a bug
    CGAL_assertion_msg(f != GT::null_face(), "a piece of the partition does not fit its neighbours");
    if(f == GT::null_face()) continue;
    put(face_site, f, internal::site_value<Site_value>(piece.site));
    put(input_face, f, data.mesh->face_handles[piece.face]);
    created.push_back(f);
    site_of_face.push_back(piece.site);
  }

  // bisectors and Voronoi vertices from the labels around them, if asked for
  const bool want_edges = !CGAL::parameters::is_default_parameter<NamedParameters, CGAL::internal_np::edge_is_constrained_t>::value;
  const bool want_vertices = !CGAL::parameters::is_default_parameter<NamedParameters, CGAL::internal_np::vertex_is_constrained_t>::value;
  if(!want_edges && !want_vertices) return;
  // 1 + index into `created`; 0 for faces that were in `out` before
  auto index_of = get(CGAL::dynamic_face_property_t<std::size_t>(), out);
  for(face_descriptor f : faces(out)) put(index_of, f, 0);
  for(std::size_t k = 0; k < created.size(); ++k) put(index_of, created[k], k + 1);
  auto label = [&](halfedge_descriptor h) -> std::size_t {
    if(is_border(h, out)) return std::size_t(-2);
    const std::size_t k = get(index_of, face(h, out));
    return k == 0 ? std::size_t(-3) : site_of_face[k - 1];
  };
  // partition vertex of each output vertex (1 + id), to find the edges on breaklines
  auto partition_id = get(CGAL::dynamic_vertex_property_t<std::size_t>(), out);
  const bool has_breaklines = !data.breaklines.empty();
  if(has_breaklines)
  {
    for(vertex_descriptor v : vertices(out)) put(partition_id, v, 0);
    for(std::size_t id = 0; id < vmap.size(); ++id)
      if(vmap[id] != GT::null_vertex()) put(partition_id, vmap[id], id + 1);
  }
  auto on_breakline = [&](halfedge_descriptor h) {
    if(!has_breaklines) return false;
    const std::size_t a = get(partition_id, source(h, out)), b = get(partition_id, target(h, out));
    return a > 0 && b > 0 && data.breaklines.joins(*data.mesh, partition, a - 1, b - 1);
  };
  if(want_edges)
  for(face_descriptor f : created)
    for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, out), out))
    {
      const halfedge_descriptor o = opposite(h, out);
      // cell boundaries: bisectors, and breaklines (a cell reaching both sides of a
      // breakline around its end still has the breakline as a boundary)
      put(edge_bisector, edge(h, out), !is_border(o, out) && (label(h) != label(o) || on_breakline(h)));
    }
  std::vector<std::size_t> labels;
  if(want_vertices)
  for(vertex_descriptor v : vmap)
  {
    if(v == GT::null_vertex()) continue;
    labels.clear();
    for(halfedge_descriptor h : CGAL::halfedges_around_target(v, out))
      labels.push_back(label(h));
    std::sort(labels.begin(), labels.end());
    put(vertex_voronoi, v, std::unique(labels.begin(), labels.end()) - labels.begin() >= 3);
  }
}

} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_ARRANGEMENT_H
