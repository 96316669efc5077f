// Copyright (c) 2026 The Surface_voronoi_diagram authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Site sampling: area-uniform random points, and blue noise by weighted sample elimination
// (Yuksel 2015): draw 5N area-uniform candidates, then repeatedly remove the one most crowded
// by its neighbours until N remain. Deterministic for a seed.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_SAMPLING_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_SAMPLING_H

#include <CGAL/Surface_voronoi_diagram/exceptions.h>

#include <CGAL/Fuzzy_sphere.h>
#include <CGAL/Kd_tree.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Random.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Simple_cartesian.h>
#include <boost/iterator/counting_iterator.hpp>

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {

/// \ingroup PkgSurfaceVoronoiDiagramSites
/// `n` area-uniform random face locations of `tm`, drawn with `CGAL::Random(seed)`.
template <class TriangleMesh>
std::vector<CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double> >
random_sites(const TriangleMesh& tm, std::size_t n, unsigned int seed = 0)
{
  typedef CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double> Location;
  CGAL::Random rng(seed);
  std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor> fs(faces(tm).begin(), faces(tm).end());
  if(fs.empty()) throw Input_error("the mesh is empty (no faces)");
  std::vector<double> cumulative;
  double total = 0;
  for(auto f : fs)
  {
    total += CGAL::to_double(CGAL::Polygon_mesh_processing::face_area(f, tm));
    cumulative.push_back(total);
  }
  std::vector<Location> out;
  out.reserve(n);
  for(std::size_t i = 0; i < n; ++i)
  {
    std::size_t k = std::upper_bound(cumulative.begin(), cumulative.end(), rng.get_double(0, total)) - cumulative.begin();
    k = (std::min)(k, fs.size() - 1);
    const double r1 = std::sqrt(rng.get_double()), r2 = rng.get_double();
    out.push_back(Location(fs[k], {{ 1 - r1, r1 * (1 - r2), r1 * r2 }}));
  }
  return out;
}

/// \ingroup PkgSurfaceVoronoiDiagramSites
/// `n` blue-noise face locations of `tm` by weighted sample elimination over `5 n` random
/// candidates (straight-line distances between candidates). Deterministic for a seed.
template <class TriangleMesh>
std::vector<CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double> >
blue_noise_sites(const TriangleMesh& tm, std::size_t n, unsigned int seed = 0)
{
  typedef CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double> Location;
  if(n == 0) return std::vector<Location>();
  const std::vector<Location> candidates = random_sites(tm, 5 * n, seed);
  const std::size_t m = candidates.size();
  typedef CGAL::Simple_cartesian<double> K;
  typedef K::Point_3 P;
  std::vector<P> points;
  points.reserve(m);
  for(const Location& l : candidates)
  {
    const auto p = CGAL::Polygon_mesh_processing::construct_point(l, tm);
    points.push_back(P(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())));
  }
  const double area = CGAL::to_double(CGAL::Polygon_mesh_processing::area(tm));
  // the largest radius of n disks packed on the area (hexagonal packing), as in Yuksel 2015
  const double r_max = std::sqrt(area / (2 * std::sqrt(3.) * double(n)));
  const double reach = 2 * r_max;

  typedef CGAL::Search_traits_3<K> Base;
  typedef CGAL::Search_traits_adapter<std::size_t, CGAL::Pointer_property_map<P>::type, Base> Traits;
  typedef CGAL::Kd_tree<Traits> Tree;
  CGAL::Pointer_property_map<P>::type ppm = CGAL::make_property_map(points);
  Tree tree(boost::counting_iterator<std::size_t>(0), boost::counting_iterator<std::size_t>(m),
            typename Tree::Splitter(), Traits(ppm));
  tree.build();

  std::vector<std::vector<std::pair<std::size_t, double> > > neighbours(m);
  std::vector<double> weight(m, 0.);
  std::vector<std::size_t> found;
  for(std::size_t i = 0; i < m; ++i)
  {
    found.clear();
    tree.search(std::back_inserter(found), CGAL::Fuzzy_sphere<Traits>(points[i], reach, 0., Traits(ppm)));
    std::sort(found.begin(), found.end());
    for(std::size_t j : found)
    {
      if(j == i) continue;
      const double d = std::sqrt(CGAL::squared_distance(points[i], points[j]));
      if(d >= reach) continue;
      const double w = std::pow(1 - d / reach, 8);
      neighbours[i].emplace_back(j, w);
      weight[i] += w;
    }
  }
  // eliminate the most crowded candidate first; ties to the higher index, for determinism
  std::set<std::pair<double, std::size_t> > heap;
  for(std::size_t i = 0; i < m; ++i) heap.emplace(weight[i], i);
  std::vector<std::uint8_t> removed(m, 0);
  for(std::size_t left = m; left > n; --left)
  {
    const auto top = std::prev(heap.end());
    const std::size_t i = top->second;
    heap.erase(top);
    removed[i] = 1;
    for(const auto& nw : neighbours[i])
    {
      const std::size_t j = nw.first;
      if(removed[j]) continue;
      heap.erase(std::make_pair(weight[j], j));
      weight[j] -= nw.second;
      heap.emplace(weight[j], j);
    }
  }
  std::vector<Location> out;
  out.reserve(n);
  for(std::size_t i = 0; i < m; ++i)
    if(!removed[i]) out.push_back(candidates[i]);
  return out;
}

} // namespace Surface_voronoi
} // namespace CGAL

#endif
