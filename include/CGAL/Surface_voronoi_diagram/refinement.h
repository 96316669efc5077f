// Copyright (c) 2026 The Surface_voronoi_diagram authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Refinement for coarse meshes: when sites outnumber the vertices around them (CAD meshes
// with long needle triangles), no metric sampled at vertices can tell the sites apart.
// Longest-edge bisection of a copy of the mesh brings every edge below a length derived from
// the site spacing. New vertices are edge midpoints and faces are split inside their own
// plane, so the surface (and every geodesic on it) is exactly the input's.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_REFINEMENT_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_REFINEMENT_H

#include <CGAL/Surface_voronoi_diagram/exceptions.h>
#include <CGAL/Surface_voronoi_diagram/internal/working_copy.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <array>
#include <cmath>
#include <limits>
#include <queue>
#include <string>
#include <tuple>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {

/// \ingroup PkgSurfaceVoronoiDiagramSites
/// Settings of `refine_for_sites()`.
struct Refinement_options
{
  /// Edges longer than `trigger_ratio` times the site spacing `sqrt(area / number of sites)`
  /// are split, and so, recursively, are the edges the splits create, down to
  /// `edge_length_ratio` times the spacing. Edges that are long but below the trigger are
  /// left alone: a mesh that is merely a little coarse keeps its size, while the needles of a
  /// CAD mesh are refined where they are. Measured with the geodesic metric on the model zoo
  /// (benchmark_metric_study): these defaults keep every model within 3% of the exact
  /// geodesic diagram at 100 and 1000 sites.
  double trigger_ratio = 0.75;
  /// see `trigger_ratio`
  double edge_length_ratio = 0.4;
  /// refusing to grow the mesh beyond this many vertices (an `Input_error`)
  std::size_t max_vertices = 20000000;
};

/// \ingroup PkgSurfaceVoronoiDiagramSites
/// The refined copy made by `refine_for_sites()`.
template <class TriangleMesh, class Point_3>
struct Refinement_result
{
  typedef CGAL::Surface_mesh<Point_3> Mesh;
  typedef CGAL::Polygon_mesh_processing::Face_location<Mesh, double> Location;
  /// the refined mesh: the same surface; edges created by the refinement are not longer
  /// than `target_edge_length`
  Mesh mesh;
  /// the sites as locations on `mesh`, in the input order
  std::vector<Location> sites;
  /// for each face of `mesh`, the input face that contains it
  typename Mesh::template Property_map<typename Mesh::Face_index,
                                       typename boost::graph_traits<TriangleMesh>::face_descriptor> input_face;
  double target_edge_length = 0;
  std::size_t edges_split = 0;
};

/// \ingroup PkgSurfaceVoronoiDiagramSites
/// Copies `tm` and splits its edges longer than `options.trigger_ratio * sqrt(area / sites.size())`
/// at their midpoints (the faces on both sides are split in their own plane), and the edges
/// these splits create until they are no longer than `options.edge_length_ratio` times the
/// same spacing; then locates the sites on the copy. A mesh without edges above the trigger is
/// copied unchanged (`edges_split == 0`).
///
/// Use it before a metric sampled at vertices (`Geodesic_metric`, the embeddings) when the
/// mesh has fewer than about ten vertices per site where the sites are.
/// \param tm a triangle mesh; it is copied, never modified
/// \param sites a range of `Polygon_mesh_processing::Face_location`s of `tm`
/// \param options the target edge length (relative to the site spacing) and a size limit
/// \param np optional `vertex_point_map` of `tm`
/// \throws Input_error if there are no sites, or if the refinement would exceed `options.max_vertices`
template <class TriangleMesh, class LocationRange, class NamedParameters = CGAL::parameters::Default_named_parameters>
Refinement_result<TriangleMesh,
                  typename boost::property_traits<typename GetVertexPointMap<TriangleMesh, NamedParameters>::const_type>::value_type>
refine_for_sites(const TriangleMesh& tm, const LocationRange& sites, const Refinement_options& options = Refinement_options(),
                 const NamedParameters& np = CGAL::parameters::default_values())
{
  typedef typename GetVertexPointMap<TriangleMesh, NamedParameters>::const_type VPM;
  typedef typename boost::property_traits<VPM>::value_type Point_3;
  typedef Refinement_result<TriangleMesh, Point_3> Result;
  typedef typename Result::Mesh Mesh;
  typedef typename Mesh::Face_index F;
  typedef typename Mesh::Edge_index E;
  typedef typename Mesh::Halfedge_index H;
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor Input_face;

  if(!(options.edge_length_ratio > 0) || !std::isfinite(options.edge_length_ratio) ||
     !(options.trigger_ratio >= options.edge_length_ratio) || !std::isfinite(options.trigger_ratio))
    throw Input_error("refine_for_sites: edge_length_ratio must be positive and trigger_ratio at least as large");
  const std::size_t n = static_cast<std::size_t>(std::distance(std::begin(sites), std::end(sites)));
  if(n == 0) throw Input_error("refine_for_sites: no sites");

  VPM vpm = CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                                               get_const_property_map(CGAL::vertex_point, tm));
  Result r;
  Mesh& m = r.mesh;
  std::vector<std::pair<Input_face, F> > f2f;
  r.input_face = internal::copy_with_input_faces(tm, vpm, m, f2f);

  const double area = CGAL::to_double(CGAL::Polygon_mesh_processing::area(m));
  r.target_edge_length = options.edge_length_ratio * std::sqrt(area / double(n));
  const double trigger = options.trigger_ratio * std::sqrt(area / double(n));
  const double limit2 = r.target_edge_length * r.target_edge_length;
  auto length2 = [&](E e) { return CGAL::to_double(CGAL::squared_distance(m.point(source(halfedge(e, m), m)), m.point(target(halfedge(e, m), m)))); };

  // longest first; ties by index, so that the result does not depend on anything else
  typedef std::pair<double, std::size_t> Item;
  std::priority_queue<Item> queue;
  for(E e : edges(m))
    if(length2(e) > trigger * trigger) queue.push(Item(length2(e), std::size_t(e)));
  while(!queue.empty())
  {
    const Item top = queue.top();
    queue.pop();
    const E e(static_cast<typename E::size_type>(top.second));
    if(length2(e) != top.first) continue;   // split already
    if(num_vertices(m) >= options.max_vertices)
      throw Input_error("refine_for_sites: the refined mesh would exceed " + std::to_string(options.max_vertices) + " vertices");
    const H h = halfedge(e, m);
    const Point_3 mid = CGAL::midpoint(m.point(source(h, m)), m.point(target(h, m)));
    // split_edge: hnew runs from the old source to the new vertex, followed by h
    const H hnew = CGAL::Euler::split_edge(h, m);
    m.point(target(hnew, m)) = mid;
    std::vector<E> touched = { edge(hnew, m), edge(h, m) };
    for(const H side : { hnew, opposite(h, m) })
    {
      if(is_border(side, m)) continue;
      const F old_face = face(side, m);
      // the face is now a quad: connect the new vertex to the opposite corner
      const H to_new = (target(side, m) == target(hnew, m)) ? side : opposite(hnew, m);
      const H to_corner = next(next(to_new, m), m);
      const H diagonal = CGAL::Euler::split_face(to_new, to_corner, m);
      r.input_face[face(diagonal, m)] = r.input_face[old_face];
      r.input_face[face(opposite(diagonal, m), m)] = r.input_face[old_face];
      touched.push_back(edge(diagonal, m));
    }
    ++r.edges_split;
    // Only edges shorter than the one split go on: splitting the longest edge of a face
    // always gives shorter ones, so a diagonal as long as the split edge means a sliver
    // on the other side (a CAD mesh's needle), whose refinement would never end.
    for(E t : touched)
      if(length2(t) > limit2 && length2(t) < top.first) queue.push(Item(length2(t), std::size_t(t)));
  }

  // the sites: each lies in one of the pieces of its input face
  std::vector<std::vector<F> > pieces(f2f.size());
  {
    auto copy_index = get(CGAL::dynamic_face_property_t<std::size_t>(), tm);
    for(std::size_t k = 0; k < f2f.size(); ++k) put(copy_index, f2f[k].first, k);
    for(F f : faces(m)) pieces[get(copy_index, r.input_face[f])].push_back(f);
    for(const auto& s : sites)
    {
      const Point_3 p = CGAL::Polygon_mesh_processing::construct_point(s, tm, CGAL::parameters::vertex_point_map(vpm));
      F best;
      std::array<double, 3> best_b = {{ 1., 0., 0. }};
      double best_min = -std::numeric_limits<double>::infinity();
      for(F f : pieces[get(copy_index, s.first)])
      {
        const auto b = CGAL::Polygon_mesh_processing::barycentric_coordinates(
            m.point(source(halfedge(f, m), m)), m.point(target(halfedge(f, m), m)),
            m.point(target(next(halfedge(f, m), m), m)), p);
        const double lo = (std::min)((std::min)(CGAL::to_double(b[0]), CGAL::to_double(b[1])), CGAL::to_double(b[2]));
        if(lo > best_min)
        {
          best_min = lo;
          best = f;
          best_b = {{ CGAL::to_double(b[0]), CGAL::to_double(b[1]), CGAL::to_double(b[2]) }};
        }
      }
      // rounding may leave a coordinate a few ulps below zero: clamp and renormalize
      double sum = 0;
      for(double& c : best_b) { c = (std::max)(c, 0.); sum += c; }
      for(double& c : best_b) c /= sum;
      r.sites.emplace_back(best, best_b);
    }
  }
  return r;
}

} // namespace Surface_voronoi
} // namespace CGAL

#endif
