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
// Refinement for coarse meshes: when sites outnumber the vertices around them (CAD meshes
// with long needle triangles), no metric sampled at vertices can tell the sites apart.
// Longest-edge bisection of a copy of the mesh brings every edge below a length derived from
// the site spacing. New vertices are edge midpoints and faces are split inside their own
// plane, so the surface (and every geodesic on it) is exactly the input's.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_REFINEMENT_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_REFINEMENT_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/parameters.h>
#include <CGAL/Surface_voronoi_diagram/internal/Double_kernel.h>
#include <CGAL/Surface_voronoi_diagram/internal/Local_site_spacing.h>

#include <CGAL/assertions.h>
#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <cmath>
#include <iterator>
#include <queue>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {

namespace internal {
// The halfedge an edge is split from. A Surface_mesh edge descriptor remembers the halfedge
// it was made from, so its own halfedge(e) depends on how the descriptor was obtained: take
// the edge's first halfedge instead, as an index-built descriptor has it.
template <class PolygonMesh>
typename boost::graph_traits<PolygonMesh>::halfedge_descriptor
split_halfedge(typename boost::graph_traits<PolygonMesh>::edge_descriptor e, const PolygonMesh& pm)
{
  return halfedge(e, pm);
}
template <class P>
typename CGAL::Surface_mesh<P>::Halfedge_index
split_halfedge(typename CGAL::Surface_mesh<P>::Edge_index e, const CGAL::Surface_mesh<P>& sm)
{
  return sm.halfedge(e, 0);
}
} // namespace internal

/// \ingroup PkgSurfaceVoronoiDiagramSites
/// What `refine_for_sites()` made.
/// \tparam PolygonMesh the type of the refined mesh
template <class PolygonMesh>
struct Refined_sites
{
  /// the sites as locations on the refined mesh, in the input order
  std::vector<CGAL::Polygon_mesh_processing::Face_location<PolygonMesh, double> > sites;
  /// the length the refinement splits edges down to
  double target_edge_length = 0;
  /// the number of edges split (0: the mesh was copied unchanged)
  std::size_t edges_split = 0;
  /// whether the refinement stopped at `refinement_max_vertices` before reaching its target;
  /// `sites` is then empty (and the refined mesh incomplete)
  bool vertex_limit_reached = false;
};

/// \ingroup PkgSurfaceVoronoiDiagramSites
/// Copies `tm` into `out` and splits the copy's edges longer than a trigger length
/// `t * sqrt(area / sites.size())` at their midpoints (the faces on both sides are split in
/// their own plane), and the edges these splits create until they are no longer than
/// `r * sqrt(area / sites.size())`; then locates the sites on `out`. A mesh without edges
/// above the trigger is copied unchanged. Only edges shorter than the edge just split are
/// split next, so that the slivers of a CAD mesh cannot make it run forever.
///
/// Use it before a metric sampled at vertices (`Geodesic_metric`, the embeddings) when the
/// mesh has fewer than about ten vertices per site where the sites are.
///
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \tparam LocationRange a range of `Polygon_mesh_processing::Face_location`s of `tm`
/// \tparam PolygonMesh a model of `MutableFaceGraph`
/// \param tm a triangle mesh; it is copied, never modified
/// \param sites the sites, at least one
/// \param out an empty mesh that receives the refined copy
/// \param np_in an optional sequence of named parameters for `tm` and the refinement:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
///     \cgalParamType{a model of `ReadablePropertyMap`}
///     \cgalParamDefault{`get_const_property_map(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{Surface_voronoi::parameters::refinement_trigger_ratio}
///     \cgalParamDescription{`t`: edges longer than `t` times the site spacing are split}
///     \cgalParamType{`double`}
///     \cgalParamDefault{0.75 (chosen with the geodesic metric against exact geodesic
///       diagrams)}
///   \cgalParamNEnd
///   \cgalParamNBegin{Surface_voronoi::parameters::refinement_edge_length_ratio}
///     \cgalParamDescription{`r`: the length, relative to the site spacing, that splitting goes down to}
///     \cgalParamType{`double`}
///     \cgalParamDefault{0.4}
///     \cgalParamExtra{`0 < r <= t`}
///   \cgalParamNEnd
///   \cgalParamNBegin{Surface_voronoi::parameters::refinement_max_vertices}
///     \cgalParamDescription{the refinement stops before the copy has more vertices than this,
///       and says so in `vertex_limit_reached`}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{20,000,000}
///   \cgalParamNEnd
///   \cgalParamNBegin{Surface_voronoi::parameters::refinement_local_spacing}
///     \cgalParamDescription{whether the site spacing is measured locally: at an edge, as the
///       distance from the site nearest to the edge's midpoint to that site's own nearest
///       neighbour, or the midpoint's distance to that site if larger (straight-line
///       distances; a site whose face faces away, across a thin wall, is no neighbour), within
///       [1/16, 1] times the mean spacing. Where
///       sites crowd (a thin bar that several rings of sites go around, as
///       `add_sites_for_valid_dual()` places them), the mesh is refined in proportion; where
///       they are evenly spaced, as after Lloyd steps, it is close to the mean rule.}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false`: the mean spacing `sqrt(area / sites.size())` everywhere}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \param np_out an optional sequence of named parameters for `out`:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `out`}
///     \cgalParamType{a model of `ReadWritePropertyMap`}
///     \cgalParamDefault{`get(CGAL::vertex_point, out)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{Surface_voronoi::parameters::input_face_map}
///     \cgalParamDescription{receives, for each face of `out`, the face of `tm` that contains it}
///     \cgalParamType{a model of `WritablePropertyMap` from the faces of `out` to those of `tm`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the sites located on `out`, the target edge length, the number of edges split,
///          and whether the vertex limit stopped the refinement (then without the sites)
/// \pre `tm` is a triangle mesh, `sites` is not empty, `out` is empty
template <class TriangleMesh, class LocationRange, class PolygonMesh,
          class NamedParametersIn = CGAL::parameters::Default_named_parameters,
          class NamedParametersOut = CGAL::parameters::Default_named_parameters
          >
Refined_sites<PolygonMesh>
refine_for_sites(const TriangleMesh& tm, const LocationRange& sites, PolygonMesh& out,
                 const NamedParametersIn& np_in = CGAL::parameters::default_values(),
                 const NamedParametersOut& np_out = CGAL::parameters::default_values())
{
  typedef boost::graph_traits<PolygonMesh> GT;
  typedef typename GT::face_descriptor F;
  typedef typename GT::edge_descriptor E;
  typedef typename GT::halfedge_descriptor H;
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor Input_face;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;

  const double trigger_ratio = choose_parameter(get_parameter(np_in, internal_np::refinement_trigger_ratio), 0.75);
  const double edge_length_ratio = choose_parameter(get_parameter(np_in, internal_np::refinement_edge_length_ratio), 0.4);
  const std::size_t max_vertices = choose_parameter(get_parameter(np_in, internal_np::refinement_max_vertices), std::size_t(20000000));
  const bool local_spacing = choose_parameter(get_parameter(np_in, internal_np::refinement_local_spacing), false);
  CGAL_precondition_msg(edge_length_ratio > 0 && std::isfinite(edge_length_ratio) && trigger_ratio >= edge_length_ratio
                        && std::isfinite(trigger_ratio), "refinement_edge_length_ratio must be positive and at most refinement_trigger_ratio");
  const std::size_t n = static_cast<std::size_t>(std::distance(std::begin(sites), std::end(sites)));
  CGAL_precondition_msg(n > 0, "refine_for_sites needs sites");
  CGAL_precondition_msg(faces(out).empty(), "the output mesh must be empty");

  const auto vpm = choose_parameter(get_parameter(np_in, CGAL::internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm));
  const auto ovpm = choose_parameter(get_parameter(np_out, CGAL::internal_np::vertex_point), get_property_map(CGAL::vertex_point, out));
  typedef typename boost::property_traits<typename std::remove_const<decltype(ovpm)>::type>::value_type Point;

  // the copy, each face knowing the input face it lies in
  std::vector<std::pair<Input_face, F> > f2f;
  CGAL::copy_face_graph(tm, out, CGAL::parameters::vertex_point_map(vpm).face_to_face_output_iterator(std::back_inserter(f2f)),
                        CGAL::parameters::vertex_point_map(ovpm));
  auto input_face = get(CGAL::dynamic_face_property_t<Input_face>(), out);
  for(const auto& p : f2f) put(input_face, p.second, p.first);

  Refined_sites<PolygonMesh> r;
  double area = 0;
  for(F f : faces(out))
  {
    const H h = halfedge(f, out);
    area += internal::triangle_area(internal::to_point_d(get(ovpm, source(h, out))), internal::to_point_d(get(ovpm, target(h, out))),
                                    internal::to_point_d(get(ovpm, target(next(h, out), out))));
  }
  const double mean_spacing = std::sqrt(area / double(n));
  r.target_edge_length = edge_length_ratio * mean_spacing;
  auto length2 = [&](E e) {
    return CGAL::to_double(CGAL::squared_distance(get(ovpm, source(halfedge(e, out), out)), get(ovpm, target(halfedge(e, out), out))));
  };
  // the spacing at an edge: the mean one, or the local one of the site nearest its midpoint
  const internal::Local_site_spacing spacing_near(
      local_spacing ? internal::site_points_and_normals(tm, sites, vpm) : std::pair<std::vector<internal::Point_d>, std::vector<internal::Vector_d> >(),
      mean_spacing);
  auto spacing = [&](E e) {
    if(!local_spacing) return mean_spacing;
    const auto p = internal::to_point_d(get(ovpm, source(halfedge(e, out), out)));
    const auto q = internal::to_point_d(get(ovpm, target(halfedge(e, out), out)));
    return spacing_near(CGAL::midpoint(p, q));
  };
  auto above = [&](E e, double ratio) { return length2(e) > CGAL::square(ratio * spacing(e)); };

  // Edges get ids in the order they are created, so that ties between equal lengths are
  // broken the same way whatever the mesh type.
  std::vector<E> edge_of_id;
  auto edge_id = get(CGAL::dynamic_edge_property_t<std::size_t>(), out);
  auto id_of = [&](E e) {
    std::size_t id = get(edge_id, e);
    if(id >= edge_of_id.size() || edge_of_id[id] != e)
    {
      id = edge_of_id.size();
      edge_of_id.push_back(e);
      put(edge_id, e, id);
    }
    return id;
  };
  for(E e : edges(out)) id_of(e);

  // longest first; ties by id
  typedef std::pair<double, std::size_t> Item;
  std::priority_queue<Item> queue;
  for(E e : edges(out))
    if(above(e, trigger_ratio)) queue.push(Item(length2(e), id_of(e)));
  while(!queue.empty())
  {
    const Item top = queue.top();
    queue.pop();
    const E e = edge_of_id[top.second];
    if(length2(e) != top.first) continue;   // split already
    if(num_vertices(out) >= max_vertices)
    {
      r.vertex_limit_reached = true;
      break;
    }
    const H h = internal::split_halfedge(e, out);
    const Point mid = CGAL::midpoint(get(ovpm, source(h, out)), get(ovpm, target(h, out)));
    // split_edge: hnew runs from the old source to the new vertex, followed by h
    const H hnew = CGAL::Euler::split_edge(h, out);
    put(ovpm, target(hnew, out), mid);
    std::vector<E> touched = { edge(hnew, out), edge(h, out) };
    id_of(edge(hnew, out));   // one of the two edges is new: it gets the next id
    id_of(edge(h, out));
    for(const H side : { hnew, opposite(h, out) })
    {
      if(is_border(side, out)) continue;
      const F old_face = face(side, out);
      // the face is now a quad: connect the new vertex to the opposite corner
      const H to_new = (target(side, out) == target(hnew, out)) ? side : opposite(hnew, out);
      const H to_corner = next(next(to_new, out), out);
      const H diagonal = CGAL::Euler::split_face(to_new, to_corner, out);
      put(input_face, face(diagonal, out), get(input_face, old_face));
      put(input_face, face(opposite(diagonal, out), out), get(input_face, old_face));
      touched.push_back(edge(diagonal, out));
      id_of(edge(diagonal, out));
    }
    ++r.edges_split;
    // Only edges shorter than the one split go on: splitting the longest edge of a face
    // always gives shorter ones, so a diagonal as long as the split edge means a sliver
    // on the other side (a CAD mesh's needle), whose refinement would never end.
    for(E t : touched)
      if(length2(t) < top.first && above(t, edge_length_ratio)) queue.push(Item(length2(t), id_of(t)));
  }

  if(!CGAL::parameters::is_default_parameter<NamedParametersOut, internal_np::input_face_map_t>::value)
  {
    auto user_map = choose_parameter(get_parameter(np_out, internal_np::input_face_map), CGAL::Constant_property_map<F, Input_face>());
    for(F f : faces(out)) put(user_map, f, get(input_face, f));
  }

  // the caller must know the refinement is incomplete: locating the sites among the pieces
  // of their faces would only cost time (up to the number of pieces per site)
  if(r.vertex_limit_reached) return r;

  // the sites: each lies in one of the pieces of its input face
  std::vector<std::vector<F> > pieces(f2f.size());
  auto copy_index = get(CGAL::dynamic_face_property_t<std::size_t>(), tm);
  for(std::size_t k = 0; k < f2f.size(); ++k) put(copy_index, f2f[k].first, k);
  for(F f : faces(out)) pieces[get(copy_index, get(input_face, f))].push_back(f);
  const auto dvpm = internal::make_double_point_map(vpm);
  for(const auto& s : sites)
  {
    const internal::Point_d p = CGAL::Polygon_mesh_processing::construct_point(
        s, tm, CGAL::parameters::vertex_point_map(dvpm).geom_traits(internal::Double_kernel()));
    auto best = internal::innermost_face(pieces[get(copy_index, s.first)], out, ovpm, p);
    // a site exactly on an input edge or vertex (a breakline's sites own both sides of it)
    // stays exactly on the piece's edge or vertex there, not a rounding error beside it
    const bool on_input_edge = s.second[0] == 0. || s.second[1] == 0. || s.second[2] == 0.;
    if(on_input_edge)
      for(double& c : best.second)
        if(std::abs(c) < 1e-9) c = 0.;
    r.sites.emplace_back(best.first, internal::clamped_barycentric(best.second));
  }
  return r;
}


} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_REFINEMENT_H
