// Copyright (c) 2026 The Surface_voronoi_diagram authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Lloyd relaxation (centroidal Voronoi): every site moves to the centroid of its cell,
// projected back to the surface, and the diagram is computed again. In interpolation mode the
// metric is built once: no eigen-solve per iteration.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_LLOYD_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_LLOYD_H

#include <CGAL/Surface_voronoi_diagram.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Polygon_mesh_processing/locate.h>

#include <algorithm>
#include <memory>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {

/// \ingroup PkgSurfaceVoronoiDiagramRef
/// What `lloyd_relaxation()` did.
template <class TriangleMesh>
struct Lloyd_result
{
  /// the relaxed sites, as face locations
  std::vector<CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double> > sites;
  /// the energy (`Surface_voronoi_diagram::energy()`) of the initial diagram and after each iteration
  std::vector<double> energies;
  /// sites kept in place because their centroid projected onto another site's point
  std::size_t kept_in_place = 0;
};

/// \ingroup PkgSurfaceVoronoiDiagramRef
/// Runs `iterations` Lloyd steps from `sites` (face locations of `tm`): each site moves to the
/// area-weighted centroid of its cell, projected to the nearest surface point. For the
/// Euclidean embedding with the RVD's candidates the energy cannot increase (both steps
/// minimize it); for the other metrics it is reported. An empty cell keeps its site.
template <class TriangleMesh, class Metric>
Lloyd_result<TriangleMesh>
lloyd_relaxation(const TriangleMesh& tm, Metric& metric,
                 std::vector<CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double> > sites,
                 std::size_t iterations, const Diagram_options& options = Diagram_options())
{
  typedef CGAL::Surface_voronoi_diagram<TriangleMesh, Metric> Diagram;
  typedef typename Diagram::Point_3 Point_3;
  typedef typename CGAL::Kernel_traits<Point_3>::Kernel Kernel;
  typedef CGAL::AABB_face_graph_triangle_primitive<TriangleMesh> Primitive;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive> > Tree;
  Tree tree;
  CGAL::Polygon_mesh_processing::build_AABB_tree(tm, tree);
  tree.accelerate_distance_queries();

  Lloyd_result<TriangleMesh> result;
  std::vector<CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double> > previous = sites;
  for(std::size_t it = 0;; ++it)
  {
    // centroids of two cells may project to one surface point (at a sharp tip, say): the
    // later site then stays where it was
    std::unique_ptr<Diagram> made;
    for(std::size_t attempt = 0; !made; ++attempt)
    {
      try { made.reset(new Diagram(tm, metric, sites, options)); }
      catch(const Coincident_sites_error& e)
      {
        if(attempt > sites.size()) throw;
        auto same = [](const auto& a, const auto& b) { return a.first == b.first && a.second == b.second; };
        // revert the later site, or the earlier one if the later has not moved
        const std::size_t k = same(sites[e.second], previous[e.second]) ? e.first : e.second;
        if(same(sites[k], previous[k])) throw;
        sites[k] = previous[k];
        ++result.kept_in_place;
      }
    }
    const Diagram& diagram = *made;
    previous = sites;
    result.energies.push_back(diagram.energy());
    if(it == iterations) break;
    std::vector<Point_3> moved;
    const std::vector<Point_3> centroids = diagram.cell_centroids();
    for(std::size_t i = 0; i < sites.size(); ++i)
    {
      const auto l = CGAL::Polygon_mesh_processing::locate_with_AABB_tree(centroids[i], tree, tm);
      moved.push_back(CGAL::Polygon_mesh_processing::construct_point(l, tm));
      sites[i] = l;
    }
    // two centroids projecting to one point would make coincident sites: keep the later in place
    std::vector<std::size_t> order(sites.size());
    for(std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return moved[a] < moved[b] || (moved[a] == moved[b] && a < b); });
    for(std::size_t k = 1; k < order.size(); ++k)
      if(moved[order[k]] == moved[order[k - 1]])
      {
        sites[order[k]] = diagram.site_location(order[k]);
        ++result.kept_in_place;
      }
  }
  result.sites = sites;
  return result;
}

} // namespace Surface_voronoi
} // namespace CGAL

#endif
