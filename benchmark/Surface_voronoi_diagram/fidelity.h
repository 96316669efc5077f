// Copyright (c) 2026 The Surface_voronoi_diagram authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// How far a diagram is from the exact geodesic Voronoi diagram: the geodesic reference
// (CGAL's Surface_mesh_shortest_path with all sites as sources: exact polyhedral geodesics)
// and, on area-uniform samples, the share of the area labelled differently, the area that
// reaches through a wall, and the cells that are empty or broken. A measurement method of the
// benchmarks (the metric study) and the tests, not part of the library.

#ifndef SVD_BENCH_FIDELITY_H
#define SVD_BENCH_FIDELITY_H

#include <CGAL/Surface_voronoi_diagram/Geodesic_metric.h>
#include <CGAL/Surface_voronoi_diagram/sampling.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/Surface_mesh_shortest_path.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <queue>
#include <stdexcept>
#include <utility>
#include <vector>

namespace svd_bench {

/// Exact geodesic Voronoi labels: the site at the smallest polyhedral geodesic distance,
/// computed by `CGAL::Surface_mesh_shortest_path` with every site as a source. Distances to
/// one given site are computed on demand by a single-source tree.
/// \tparam TriangleMesh a triangle mesh with internal vertex, halfedge and face indices
///         (`Surface_mesh`, or `Polyhedron_3` with ids)
template <class TriangleMesh>
class Geodesic_reference
{
public:
  typedef typename boost::property_traits<typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>::value_type Point_3;
  typedef typename CGAL::Kernel_traits<Point_3>::Kernel Kernel;
  typedef CGAL::Surface_mesh_shortest_path_traits<Kernel, TriangleMesh> Traits;
  typedef CGAL::Surface_mesh_shortest_path<Traits> Shortest_path;
  typedef CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double> Face_location;

  Geodesic_reference(const TriangleMesh& tm, const std::vector<Face_location>& sites)
    : m_tm(tm), m_sites(sites), m_all(tm)
  {
    if(sites.empty()) throw std::invalid_argument("the geodesic reference needs at least one site");
    for(const Face_location& s : sites) m_all.add_source_point(to_sp(s));
    m_all.build_sequence_tree();
  }

  /// the geodesic distance to the nearest site, and that site's index
  std::pair<double, std::size_t> nearest(const Face_location& l) const
  {
    const auto r = m_all.shortest_distance_to_source_points(l.first, to_sp(l).second);
    std::size_t index = 0;
    for(auto it = m_all.source_points_begin(); it != r.second; ++it) ++index;
    return std::make_pair(r.first, index);
  }

  /// the geodesic distances from site `i` to each of `ls`, by one exact single-source tree
  /// (built here and freed on return: a tree over the whole mesh is costly in time and memory)
  std::vector<double> distances(std::size_t i, const std::vector<Face_location>& ls) const
  {
    Shortest_path tree(m_tm);
    tree.add_source_point(to_sp(m_sites[i]));
    tree.build_sequence_tree();
    std::vector<double> out;
    out.reserve(ls.size());
    for(const Face_location& l : ls) out.push_back(tree.shortest_distance_to_source_points(l.first, to_sp(l).second).first);
    return out;
  }

  /// the geodesic distance from site `i` to `l` (one exact single-source tree)
  double distance(std::size_t i, const Face_location& l) const { return distances(i, { l }).front(); }

  std::size_t number_of_sites() const { return m_sites.size(); }

private:
  static typename Shortest_path::Face_location to_sp(const Face_location& l)
  {
    typename Shortest_path::Barycentric_coordinates b = {{ l.second[0], l.second[1], l.second[2] }};
    return typename Shortest_path::Face_location(l.first, b);
  }

  const TriangleMesh& m_tm;
  std::vector<Face_location> m_sites;
  mutable Shortest_path m_all;
};

/// The fidelity figures of a diagram against the exact geodesic Voronoi diagram.
struct Fidelity_report
{
  std::size_t samples = 0;
  /// share of the area (samples) whose site differs from the geodesic Voronoi site
  double mislabeled_share = 0;
  /// share of the area no site reaches
  double unreached_share = 0;
  /// share of the area assigned to a site more than 3x farther (geodesically) than the
  /// geodesic Voronoi site, bracketed: lower counts what was decided, upper adds what was left
  /// undecided when `max_exact_trees` ran out. A sample is decided by a fast-marching
  /// distance when that is more than 10% away from the threshold, by an exact tree otherwise.
  double through_wall_lower = 0, through_wall_upper = 0;
  std::size_t empty_cells = 0;
  std::size_t broken_cells_before_repair = 0;
  std::size_t broken_cells = 0;
};

/// Measures `diagram` on `samples` area-uniform points (seeded), against a geodesic
/// reference built on the diagram's sites. A sample whose assigned site is not the geodesic
/// one is classified "through a wall" or not by its fast-marching distance to the assigned
/// site (`Geodesic_metric`) when that is more than 10% away from the threshold, otherwise by
/// an exact single-source tree, at most `max_exact_trees` of them (each costs seconds on a
/// mesh of 10k vertices).
///
/// This overload reuses `reference`, which must have been built on the same mesh and the
/// same sites as `diagram` (to compare several metrics on one set of sites at the cost of
/// one reference).
template <class Diagram>
Fidelity_report measure_fidelity(const Diagram& diagram, Geodesic_reference<typename Diagram::Triangle_mesh>& reference,
                                 std::size_t samples, unsigned int seed = 0, std::size_t max_exact_trees = 8)
{
  typedef typename Diagram::Triangle_mesh Mesh;
  typedef typename Diagram::Face_location Face_location;
  const Mesh& tm = diagram.triangle_mesh();
  auto vpm = diagram.vertex_point_map();
  std::vector<Face_location> sites;
  for(std::size_t i = 0; i < diagram.number_of_sites(); ++i) sites.push_back(diagram.site_location(i));
  if(sites.size() != reference.number_of_sites())
    throw std::invalid_argument("measure_fidelity: the reference was built on other sites");

  const std::vector<Face_location> locs = CGAL::Surface_voronoi::random_sites(tm, samples, CGAL::parameters::random_seed(seed));

  Fidelity_report report;
  report.samples = samples;
  report.empty_cells = diagram.statistics().empty_cells;
  report.broken_cells_before_repair = diagram.statistics().broken_cells_before_repair;
  report.broken_cells = diagram.statistics().broken_cells;

  std::vector<double> g_star(samples);
  std::map<std::size_t, std::vector<std::size_t> > undecided;
  std::size_t mislabeled = 0, unreached = 0;
  for(std::size_t j = 0; j < samples; ++j)
  {
    const auto r = reference.nearest(locs[j]);
    g_star[j] = r.first;
    const std::size_t assigned = diagram.site_of(locs[j]);
    if(assigned == Diagram::no_site) { ++unreached; ++mislabeled; continue; }
    if(assigned != r.second)
    {
      ++mislabeled;
      undecided[assigned].push_back(j);
    }
  }
  // Distance to the assigned site: a fast-marching estimate first (one front per site, over
  // as much of the mesh as needed); samples whose estimate is within 10% of the threshold
  // are decided by an exact single-source tree, at most `max_exact_trees` of them.
  const double band = 1.1;
  CGAL::Surface_voronoi::Geodesic_metric<Mesh, decltype(vpm)> marching(tm, CGAL::parameters::vertex_point_map(vpm));
  std::size_t through = 0, left = 0;
  std::map<std::size_t, std::vector<std::size_t> > exact_needed;
  for(const auto& entry : undecided)
  {
    const std::size_t s = entry.first;
    marching.set_sites(std::vector<Face_location>(1, sites[s]));
    for(std::size_t j : entry.second)
    {
      const double estimate = marching.distance(0, locs[j]);
      if(estimate > band * 3 * g_star[j]) ++through;
      else if(estimate * band >= 3 * g_star[j]) exact_needed[s].push_back(j);
    }
  }
  std::vector<std::pair<std::size_t, std::size_t> > order;
  for(const auto& entry : exact_needed) order.emplace_back(entry.second.size(), entry.first);
  std::sort(order.rbegin(), order.rend());
  for(std::size_t k = 0; k < order.size(); ++k)
  {
    const std::vector<std::size_t>& js = exact_needed[order[k].second];
    if(k >= max_exact_trees) { left += js.size(); continue; }
    std::vector<Face_location> targets;
    for(std::size_t j : js) targets.push_back(locs[j]);
    const std::vector<double> d = reference.distances(order[k].second, targets);
    for(std::size_t t = 0; t < js.size(); ++t) through += (d[t] > 3 * g_star[js[t]]);
  }
  const double n = double(samples);
  report.mislabeled_share = double(mislabeled) / n;
  report.unreached_share = double(unreached) / n;
  report.through_wall_lower = double(through) / n;
  report.through_wall_upper = double(through + left) / n;
  return report;
}

/// Measures `diagram` against a geodesic reference built here on the diagram's sites.
template <class Diagram>
Fidelity_report measure_fidelity(const Diagram& diagram, std::size_t samples, unsigned int seed = 0,
                                 std::size_t max_exact_trees = 8)
{
  std::vector<typename Diagram::Face_location> sites;
  for(std::size_t i = 0; i < diagram.number_of_sites(); ++i) sites.push_back(diagram.site_location(i));
  Geodesic_reference<typename Diagram::Triangle_mesh> reference(diagram.triangle_mesh(), sites);
  return measure_fidelity(diagram, reference, samples, seed, max_exact_trees);
}

} // namespace svd_bench

#endif // SVD_BENCH_FIDELITY_H
