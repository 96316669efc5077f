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
// The site spacing near a point, for the refinement's local rule: the distance from the site
// nearest to the point to that site's own nearest neighbour, or the point's distance to that
// site if larger, kept within [1/16, 1] times the mean spacing (two sites at one point must not ask for edges of length zero, and evenly
// spaced sites get the mean rule). A neighbour is a site whose face does not face away from
// the site's own (positive dot product of the normals): across a thin wall the straight line
// is short while the surface between the two sides is long, and counting such pairs would
// refine thin parts whole. The kd-tree of points that finds the nearest sites here serves the
// blue-noise sampling and the global nearest candidates too.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_LOCAL_SITE_SPACING_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_LOCAL_SITE_SPACING_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/internal/Double_kernel.h>

#include <CGAL/Fuzzy_sphere.h>
#include <CGAL/Kd_tree.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/property_map.h>

#include <boost/iterator/counting_iterator.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

/// the points of `sites` (face locations of `tm`), in doubles, and the normals of their faces
/// (not normalized)
template <class TriangleMesh, class LocationRange, class VertexPointMap>
std::pair<std::vector<Point_d>, std::vector<Vector_d> >
site_points_and_normals(const TriangleMesh& tm, const LocationRange& sites, const VertexPointMap& vpm)
{
  const auto dvpm = make_double_point_map(vpm);
  std::pair<std::vector<Point_d>, std::vector<Vector_d> > out;
  for(const auto& s : sites)
  {
    out.first.push_back(CGAL::Polygon_mesh_processing::construct_point(
        s, tm, CGAL::parameters::vertex_point_map(dvpm).geom_traits(Double_kernel())));
    const auto h = halfedge(s.first, tm);
    const Point_d a = get(dvpm, source(h, tm)), b = get(dvpm, target(h, tm)), c = get(dvpm, target(next(h, tm), tm));
    out.second.push_back(CGAL::cross_product(b - a, c - a));
  }
  return out;
}

// A kd-tree of the indices of `points`, which must outlive it: the searches of the site
// spacing here, of the blue-noise sampling and of the global nearest candidates.
class Point_tree
{
public:
  typedef CGAL::Pointer_property_map<Point_d>::const_type Point_map;
  typedef CGAL::Search_traits_adapter<std::size_t, Point_map, CGAL::Search_traits_3<Double_kernel> > Traits;
  typedef CGAL::Orthogonal_k_neighbor_search<Traits> Search;

  explicit Point_tree(const std::vector<Point_d>& points)
    : m_map(CGAL::make_property_map(points)),
      m_tree(boost::counting_iterator<std::size_t>(0), boost::counting_iterator<std::size_t>(points.size()),
             Search::Tree::Splitter(), Traits(m_map))
  {
    m_tree.build();
  }

  /// the `k` points nearest to `p`, nearest first, as pairs (index, squared distance)
  Search nearest(const Point_d& p, unsigned int k) const { return Search(m_tree, p, k, 0, true, Search::Distance(m_map)); }

  /// appends to `out` the indices of the points within `radius` of `p`
  template <class OutputIterator>
  void within(const Point_d& p, double radius, OutputIterator out) const
  {
    m_tree.search(out, CGAL::Fuzzy_sphere<Traits>(p, radius, 0., Traits(m_map)));
  }

private:
  Point_map m_map;
  Search::Tree m_tree;
};

class Local_site_spacing
{
public:
  /// the smallest spacing, as a fraction of the mean one
  static constexpr double floor_ratio = 1. / 16;

  /// whether two sites whose faces have these normals are neighbours: their faces do not face
  /// away from each other (as the two sides of a thin wall do)
  static bool are_neighbours(const Vector_d& normal_a, const Vector_d& normal_b) { return normal_a * normal_b > 0; }

  /// With no points, every query gives `mean_spacing`.
  Local_site_spacing(std::pair<std::vector<Point_d>, std::vector<Vector_d> > sites, double mean_spacing)
    : m_points(std::move(sites.first)), m_mean(mean_spacing)
  {
    const std::vector<Vector_d>& normals = sites.second;
    if(m_points.empty()) return;
    m_tree.reset(new Point_tree(m_points));
    m_spacing.assign(m_points.size(), m_mean);
    for(std::size_t i = 0; i < m_points.size(); ++i)
    {
      // the nearest neighbour among the few nearest sites (beyond them, the mean spacing)
      double nearest = m_mean;
      for(const auto& found : m_tree->nearest(m_points[i], 8))
        if(found.first != i && are_neighbours(normals[found.first], normals[i]))
        {
          nearest = (std::min)(nearest, std::sqrt(found.second));
          break;   // the search gives them nearest first
        }
      m_spacing[i] = (std::max)(floor_ratio * m_mean, nearest);
    }
  }

  /// the spacing of the site nearest to `x`, or the distance to it if larger (at most the
  /// mean spacing): two close sites ask for short edges near them, not over all their cells
  double operator()(const Point_d& x) const
  {
    if(!m_tree) return m_mean;
    const auto nearest = *m_tree->nearest(x, 1).begin();
    return (std::min)(m_mean, (std::max)(m_spacing[nearest.first], std::sqrt(nearest.second)));
  }

private:
  std::vector<Point_d> m_points;
  double m_mean;
  std::unique_ptr<Point_tree> m_tree;
  std::vector<double> m_spacing;
};

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_LOCAL_SITE_SPACING_H
