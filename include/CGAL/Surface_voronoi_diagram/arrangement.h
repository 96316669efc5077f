// Copyright (c) 2026 The Surface_voronoi_diagram authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Output: the arrangement, i.e. the input surface refined along every bisector, written into
// any MutableFaceGraph (Surface_mesh, Polyhedron_3, ...). Every face is a convex planar
// polygon inside one input triangle and inside one cell.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_ARRANGEMENT_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_ARRANGEMENT_H

#include <CGAL/Surface_voronoi_diagram/exceptions.h>
#include <CGAL/Surface_voronoi_diagram/parameters.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Dynamic_property_map.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <set>
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
} // namespace internal

/// \ingroup PkgSurfaceVoronoiDiagramOutputs
///
/// Writes the arrangement of `diagram` into `out` (appended to what `out` holds).
///
/// \tparam Diagram a `CGAL::Surface_voronoi_diagram`
/// \tparam PolygonMesh a model of `MutableFaceGraph`
/// \param diagram the diagram
/// \param out the output mesh; the arrangement is added to it
/// \param np optional named parameters:
///   - `vertex_point_map`: the output's point map (default: internal `vertex_point`)
///   - `face_patch_map`: writable, output face -> site index (`-1` converted to the value
///      type where no site reaches)
///   - `edge_is_constrained_map`: writable, output edge -> `true` on cell boundaries: bisectors
///      (edges whose two faces belong to different sites, or to a site and the unreached
///      area) and breakline edges
///   - `vertex_is_constrained_map`: writable, output vertex -> `true` at Voronoi vertices
///      (three or more cells meet, the surface border counting as one)
///   - `Surface_voronoi::parameters::input_face_map`: writable, output face -> the input
///      face containing it
/// \throws Surface_voronoi::Error if the pieces do not form a valid polygon mesh (a bug)
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

  const typename Diagram::Partition& partition = diagram.partition();
  std::vector<vertex_descriptor> vmap(partition.vertices.size(), GT::null_vertex());
  std::vector<std::size_t> site_of_face;
  std::vector<face_descriptor> created;
  created.reserve(partition.pieces.size());
  for(const auto& piece : partition.pieces)
  {
    std::vector<vertex_descriptor> polygon;
    polygon.reserve(piece.vertices.size());
    for(std::size_t id : piece.vertices)
    {
      if(vmap[id] == GT::null_vertex())
      {
        vmap[id] = add_vertex(out);
        const auto& p = partition.vertices[id].point;
        put(vpm, vmap[id], Point(p[0], p[1], p[2]));
      }
      polygon.push_back(vmap[id]);
    }
    const face_descriptor f = CGAL::Euler::add_face(polygon, out);
    if(f == GT::null_face())
      throw Error("the arrangement could not be built: piece of site " + std::to_string(piece.site) + " in face "
                  + std::to_string(piece.face) + " does not fit (please report this mesh)");
    put(face_site, f, internal::site_value<Site_value>(piece.site));
    put(input_face, f, diagram.face_handle(piece.face));
    created.push_back(f);
    site_of_face.push_back(piece.site);
  }

  // bisectors and Voronoi vertices from the labels around them
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
  const bool has_breaklines = diagram.number_of_breakline_edges() > 0;
  if(has_breaklines)
  {
    for(vertex_descriptor v : vertices(out)) put(partition_id, v, 0);
    for(std::size_t id = 0; id < vmap.size(); ++id)
      if(vmap[id] != GT::null_vertex()) put(partition_id, vmap[id], id + 1);
  }
  auto on_breakline = [&](halfedge_descriptor h) {
    if(!has_breaklines) return false;
    const std::size_t a = get(partition_id, source(h, out)), b = get(partition_id, target(h, out));
    return a > 0 && b > 0 && diagram.on_breakline(a - 1, b - 1);
  };
  for(face_descriptor f : created)
    for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, out), out))
    {
      const halfedge_descriptor o = opposite(h, out);
      // cell boundaries: bisectors, and breaklines (a cell reaching both sides of a
      // breakline around its end still has the breakline as a boundary)
      if(!is_border(o, out) && (label(h) != label(o) || on_breakline(h)))
        put(edge_bisector, edge(h, out), true);
      else
        put(edge_bisector, edge(h, out), false);
    }
  for(vertex_descriptor v : vmap)
  {
    if(v == GT::null_vertex()) continue;
    std::set<std::size_t> labels;
    for(halfedge_descriptor h : CGAL::halfedges_around_target(v, out))
      labels.insert(label(h));
    put(vertex_voronoi, v, labels.size() >= 3);
  }
}

} // namespace Surface_voronoi
} // namespace CGAL

#endif
