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
// Site sampling: area-uniform random points, and blue noise by weighted sample elimination
// (Yuksel 2015): draw 5N area-uniform candidates, then repeatedly remove the one most crowded
// by its neighbours until N remain. Deterministic for a seed.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_SAMPLING_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_SAMPLING_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/exceptions.h>
#include <CGAL/Surface_voronoi_diagram/parameters.h>
#include <CGAL/Surface_voronoi_diagram/internal/Double_kernel.h>
#include <CGAL/Surface_voronoi_diagram/internal/Local_site_spacing.h>

#include <CGAL/assertions.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/Random.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <set>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

// The binary exponent e of the largest finite coordinate of the vertices of `tm` (0 if
// none): the points scaled by 2^-e have coordinates below 1, so that neither the squares of
// their edges overflow nor, within the documented range, their areas underflow.
template <class TriangleMesh, class VertexPointMap>
int coordinate_exponent(const TriangleMesh& tm, const VertexPointMap& vpm)
{
  double largest = 0;
  for(auto v : vertices(tm))
  {
    const Point_d p = to_point_d(get(vpm, v));
    for(int c = 0; c < 3; ++c)
      if(std::isfinite(p[c])) largest = (std::max)(largest, std::abs(p[c]));
  }
  int e = 0;
  if(largest > 0) std::frexp(largest, &e);
  return e;
}

inline Point_d scaled_point(const Point_d& p, int e)
{
  return Point_d(std::ldexp(p[0], e), std::ldexp(p[1], e), std::ldexp(p[2], e));
}

// the area of face f on the points scaled by 2^e (0: as they are)
template <class TriangleMesh, class VertexPointMap, class Face>
double scaled_face_area(const TriangleMesh& tm, const VertexPointMap& vpm, Face f, int e)
{
  const auto h = halfedge(f, tm);
  return triangle_area(scaled_point(to_point_d(get(vpm, source(h, tm))), e), scaled_point(to_point_d(get(vpm, target(h, tm))), e),
                       scaled_point(to_point_d(get(vpm, target(next(h, tm), tm))), e));
}

// The areas of the faces `fs`, and the exponent `e` of the scaling they were measured at:
// on the points as they are (`e == 0`) when their total is positive and finite, otherwise on
// the points scaled by 2^-e, e = coordinate_exponent(), faces without a positive finite area
// counting 0 (the total may still be 0).
template <class TriangleMesh, class VertexPointMap, class Face>
std::vector<double> face_areas(const TriangleMesh& tm, const VertexPointMap& vpm, const std::vector<Face>& fs, int& e)
{
  std::vector<double> area(fs.size());
  double total = 0;
  for(std::size_t k = 0; k < fs.size(); ++k)
  {
    area[k] = scaled_face_area(tm, vpm, fs[k], 0);
    total += area[k];
  }
  e = 0;
  if(total > 0 && std::isfinite(total)) return area;
  e = coordinate_exponent(tm, vpm);
  for(std::size_t k = 0; k < fs.size(); ++k)
  {
    const double a = scaled_face_area(tm, vpm, fs[k], -e);
    area[k] = (a > 0 && std::isfinite(a)) ? a : 0.;
  }
  return area;
}

template <class NamedParameters>
using Has_density = std::integral_constant<bool,
    !CGAL::parameters::is_default_parameter<NamedParameters, Surface_voronoi::internal_np::vertex_density_map_t>::value>;

// The density of `np`'s vertex_density_map at the corners of each face of `fs`, in the order
// of a face location's barycentric coordinates; empty without a density map.
template <class TriangleMesh, class Face, class NamedParameters>
std::vector<std::array<double, 3> > face_corner_densities(const TriangleMesh& tm, const std::vector<Face>& fs,
                                                          const NamedParameters& np)
{
  std::vector<std::array<double, 3> > out;
  if constexpr(Has_density<NamedParameters>::value)
  {
    const auto density = CGAL::parameters::get_parameter(np, Surface_voronoi::internal_np::vertex_density_map);
    out.reserve(fs.size());
    for(auto f : fs)
    {
      const auto h = halfedge(f, tm);
      const std::array<double, 3> d = {{ double(get(density, source(h, tm))), double(get(density, target(h, tm))),
                                         double(get(density, target(next(h, tm), tm))) }};
      // checked in every build: a density that is not a number or negative would make the
      // drawing by rejection loop forever
      for(double x : d)
        if(!(std::isfinite(x) && x >= 0)) throw Input_error("the vertex densities must be finite and not negative");
      out.push_back(d);
    }
  }
  return out;
}

inline double density_at(const std::array<double, 3>& d, const std::array<double, 3>& b)
{
  return b[0] * d[0] + b[1] * d[1] + b[2] * d[2];
}

} // namespace internal

/// \ingroup PkgSurfaceVoronoiDiagramSites
/// `n` area-uniform random face locations of `tm`, deterministic for a seed.
///
/// \tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
/// \param tm a triangle mesh with at least one face
/// \param n the number of locations
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
///     \cgalParamType{a model of `ReadablePropertyMap`}
///     \cgalParamDefault{`get_const_property_map(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{random_seed}
///     \cgalParamDescription{the seed of the `CGAL::Random` generator: the same seed gives the same locations}
///     \cgalParamType{`unsigned int`}
///     \cgalParamDefault{0}
///   \cgalParamNEnd
///   \cgalParamNBegin{Surface_voronoi::parameters::vertex_density_map}
///     \cgalParamDescription{the wanted number of sites per unit area, up to a constant factor,
///       at each vertex, interpolated linearly across faces: a face is drawn with probability
///       proportional to its area times its mean density, and a point in it by rejection
///       against the interpolated density}
///     \cgalParamType{a model of `ReadablePropertyMap` with the vertex descriptor as key and a
///       value type convertible to `double` (finite, not negative, not zero on every face)}
///     \cgalParamDefault{a uniform density}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// Runs in time linear in the size of `tm` and `n` for any finite coordinates (outside the
/// coordinate range that `validate_input()` checks, the areas are measured on the points
/// scaled by a power of two; a mesh without any measurable area is sampled face by face).
///
/// \pre `tm` has at least one face
/// \throws Surface_voronoi::Input_error if a density is negative or not a finite number, or
///         is zero on every face (checked in every build)
template <class TriangleMesh, typename CGAL_NP_TEMPLATE_PARAMETERS>
std::vector<CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double> >
random_sites(const TriangleMesh& tm, std::size_t n, const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  typedef CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double> Location;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm));
  CGAL::Random rng(choose_parameter(get_parameter(np, CGAL::internal_np::random_seed), 0u));
  std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor> fs(faces(tm).begin(), faces(tm).end());
  CGAL_precondition_msg(!fs.empty(), "the mesh is empty (no faces)");
  // Drawing in [0, total) loops forever for a total of 0 and recurses without end for an
  // infinite one (Boost's uniform_real): outside the documented coordinate range, areas are
  // measured on the points scaled by a power of two (the same distribution), and a mesh
  // without any measurable area is sampled by face index.
  int e;
  std::vector<double> cumulative = internal::face_areas(tm, vpm, fs, e);
  std::partial_sum(cumulative.begin(), cumulative.end(), cumulative.begin());
  double total = cumulative.back();
  if(!(total > 0 && std::isfinite(total)))
  {
    for(std::size_t k = 0; k < cumulative.size(); ++k) cumulative[k] = double(k + 1);
    total = double(cumulative.size());
  }
  // with a density: faces drawn by area times mean density, points in them by rejection
  const std::vector<std::array<double, 3> > density = internal::face_corner_densities(tm, fs, np);
  if(!density.empty())
  {
    double previous = 0, weighted = 0;
    for(std::size_t k = 0; k < fs.size(); ++k)
    {
      const double area = cumulative[k] - previous;
      previous = cumulative[k];
      weighted += area * (density[k][0] + density[k][1] + density[k][2]) / 3;
      cumulative[k] = weighted;
    }
    if(!(weighted > 0 && std::isfinite(weighted))) throw Input_error("the vertex density must not be zero on every face");
    total = weighted;
  }
  std::vector<Location> out;
  out.reserve(n);
  for(std::size_t i = 0; i < n; ++i)
  {
    std::size_t k = std::upper_bound(cumulative.begin(), cumulative.end(), rng.get_double(0, total)) - cumulative.begin();
    k = (std::min)(k, fs.size() - 1);
    for(;;)
    {
      const double r1 = std::sqrt(rng.get_double()), r2 = rng.get_double();
      const std::array<double, 3> b = {{ 1 - r1, r1 * (1 - r2), r1 * r2 }};
      // a face drawn has a positive density at some corner, so this ends (after at most
      // max/mean draws on average)
      if(!density.empty() && !(rng.get_double(0, (std::max)({ density[k][0], density[k][1], density[k][2] }))
                               < internal::density_at(density[k], b)))
        continue;
      out.push_back(Location(fs[k], b));
      break;
    }
  }
  return out;
}

/// \ingroup PkgSurfaceVoronoiDiagramSites
/// `n` blue-noise face locations of `tm` by weighted sample elimination
/// \cgalCite{cgal:y-segpd-15} over `5 n` area-uniform candidates (`random_sites()`): the
/// candidate most crowded by its neighbours within twice the packing radius is removed until
/// `n` remain. Distances between candidates are straight-line ones, so on a shell thinner than
/// that distance a candidate also crowds those across the wall.
///
/// \tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
/// \param tm a triangle mesh with at least one face
/// \param n the number of locations
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
///     \cgalParamType{a model of `ReadablePropertyMap`}
///     \cgalParamDefault{`get_const_property_map(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{random_seed}
///     \cgalParamDescription{the seed of the candidates' `CGAL::Random` generator: the same seed
///       gives the same locations}
///     \cgalParamType{`unsigned int`}
///     \cgalParamDefault{0}
///   \cgalParamNEnd
///   \cgalParamNBegin{Surface_voronoi::parameters::vertex_density_map}
///     \cgalParamDescription{the wanted number of sites per unit area, up to a constant factor,
///       at each vertex: the candidates are drawn with it (as by `random_sites()`), the packing
///       radius is computed on its integral instead of the area, and a candidate where the
///       density is \f$ \rho \f$ has the radius \f$ r_{max} / \sqrt{\rho} \f$; two candidates
///       crowd each other within the sum of their radii}
///     \cgalParamType{a model of `ReadablePropertyMap` with the vertex descriptor as key and a
///       value type convertible to `double` (finite, not negative, not zero on every face)}
///     \cgalParamDefault{a uniform density}
///   \cgalParamNEnd
///   \cgalParamNBegin{Surface_voronoi::parameters::placed_sites}
///     \cgalParamDescription{sites already placed (such as those of `feature_line_sites()`), not
///       returned: they take part in the elimination as candidates that are never removed, so
///       the `n` new locations keep away from them, and the packing radius is that of `n` plus
///       their number}
///     \cgalParamType{`std::vector<CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double> >`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \pre `tm` has at least one face, or `n == 0`
/// \throws Surface_voronoi::Input_error as `random_sites()`
template <class TriangleMesh, typename CGAL_NP_TEMPLATE_PARAMETERS>
std::vector<CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double> >
blue_noise_sites(const TriangleMesh& tm, std::size_t n, const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  typedef CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double> Location;
  typedef internal::Double_kernel K;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  if(n == 0) return std::vector<Location>();
  const auto vpm = internal::make_double_point_map(
      choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm)));
  // the candidates that may be removed, then the placed sites, which stay
  std::vector<Location> candidates = random_sites(tm, 5 * n, np);
  const std::size_t m = candidates.size();
  const std::vector<Location> placed = choose_parameter(get_parameter(np, Surface_voronoi::internal_np::placed_sites), std::vector<Location>());
  candidates.insert(candidates.end(), placed.begin(), placed.end());
  const std::size_t all = candidates.size();
  std::vector<internal::Point_d> points;
  points.reserve(m);
  // the faces' areas, kept for the density's integral below
  const std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor> fs(faces(tm).begin(), faces(tm).end());
  // outside the documented coordinate range, on the points scaled by a power of two
  int e;
  const std::vector<double> face_area = internal::face_areas(tm, vpm, fs, e);
  double area = std::accumulate(face_area.begin(), face_area.end(), 0.);
  for(const Location& l : candidates)
    points.push_back(internal::scaled_point(
        CGAL::Polygon_mesh_processing::construct_point(l, tm, CGAL::parameters::vertex_point_map(vpm).geom_traits(K())), -e));
  // with a density, each candidate's radius shrinks as the square root of its density, so
  // that a disk holds as many sites wherever it is; the packing is then of the mass (the
  // integral of the density) instead of the area
  std::vector<double> radius_scale(all, 1.);
  if constexpr(internal::Has_density<CGAL_NP_CLASS>::value)
  {
    const std::vector<std::array<double, 3> > density = internal::face_corner_densities(tm, fs, np);
    double mass = 0;
    for(std::size_t k = 0; k < fs.size(); ++k)
      mass += face_area[k] * (density[k][0] + density[k][1] + density[k][2]) / 3;
    std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor> candidate_faces;
    for(const Location& l : candidates) candidate_faces.push_back(l.first);
    const std::vector<std::array<double, 3> > at_candidates = internal::face_corner_densities(tm, candidate_faces, np);
    for(std::size_t i = 0; i < all; ++i)
      radius_scale[i] = 1 / std::sqrt(internal::density_at(at_candidates[i], candidates[i].second));
    area = mass;
  }
  // the largest radius of n disks packed on the area (hexagonal packing), as in Yuksel 2015
  const double r_max = std::sqrt(area / (2 * std::sqrt(3.) * double(n + placed.size())));
  const double reach = 2 * r_max;

  const internal::Point_tree tree(points);

  std::vector<std::vector<std::pair<std::size_t, double> > > neighbours(all);
  std::vector<double> weight(all, 0.);
  std::vector<std::size_t> found;
  // two candidates crowd each other within the sum of their radii: each searches twice its
  // own radius, so the one with the larger radius finds the pair
  std::vector<std::pair<std::size_t, std::size_t> > pairs;
  for(std::size_t i = 0; i < all; ++i)
  {
    found.clear();
    tree.within(points[i], reach * radius_scale[i], std::back_inserter(found));
    for(std::size_t j : found)
      if(j != i && std::sqrt(CGAL::squared_distance(points[i], points[j])) < r_max * (radius_scale[i] + radius_scale[j]))
        pairs.emplace_back((std::min)(i, j), (std::max)(i, j));
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  for(const auto& p : pairs)
  {
    const double d = std::sqrt(CGAL::squared_distance(points[p.first], points[p.second]));
    const double w = std::pow(1 - d / (r_max * (radius_scale[p.first] + radius_scale[p.second])), 8);
    neighbours[p.first].emplace_back(p.second, w);
    neighbours[p.second].emplace_back(p.first, w);
    // each candidate's weight summed in increasing neighbour order, as the pairs are sorted
    weight[p.first] += w;
    weight[p.second] += w;
  }
  // eliminate the most crowded candidate first; ties to the higher index, for determinism
  std::set<std::pair<double, std::size_t> > heap;
  for(std::size_t i = 0; i < m; ++i) heap.emplace(weight[i], i);
  std::vector<std::uint8_t> removed(all, 0);
  for(std::size_t left = m; left > n; --left)
  {
    const auto top = std::prev(heap.end());
    const std::size_t i = top->second;
    heap.erase(top);
    removed[i] = 1;
    for(const auto& nw : neighbours[i])
    {
      const std::size_t j = nw.first;
      if(removed[j] || j >= m) continue;   // a placed site is in no heap
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

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_SAMPLING_H
