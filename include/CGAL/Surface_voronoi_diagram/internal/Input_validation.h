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
// The checks behind `validate_input()` and the diagram's preconditions.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_INPUT_VALIDATION_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_INPUT_VALIDATION_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/Input_problem.h>
#include <CGAL/Surface_voronoi_diagram/exceptions.h>
#include <CGAL/Surface_voronoi_diagram/parameters.h>
#include <CGAL/Surface_voronoi_diagram/internal/Indexed_mesh.h>
#include <CGAL/Surface_voronoi_diagram/internal/Site.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/iterator.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

/// A list of problems keeping at most `per_kind` of each kind.
class Problem_list
{
public:
  Problem_list(std::vector<Input_problem>& problems, std::size_t per_kind) : m_problems(problems), m_per_kind(per_kind) {}
  void add(Input_problem::Kind kind, std::size_t element, const std::string& message, std::size_t other = 0)
  {
    if(m_count[kind]++ < m_per_kind) m_problems.push_back(Input_problem{ kind, element, other, message });
  }

private:
  std::vector<Input_problem>& m_problems;
  std::size_t m_per_kind;
  std::map<Input_problem::Kind, std::size_t> m_count;
};

/// reports the faces that are not triangles; returns true if there is none
template <class TriangleMesh>
bool find_non_triangles(const TriangleMesh& tm, Problem_list& list)
{
  bool ok = true;
  std::size_t index = 0;
  for(auto f : faces(tm))
  {
    if(CGAL::halfedges_around_face(halfedge(f, tm), tm).size() != 3)
    {
      list.add(Input_problem::NOT_A_TRIANGLE, index, "face " + std::to_string(index) + " is not a triangle");
      ok = false;
    }
    ++index;
  }
  return ok;
}

/// The vertices whose faces form several fans, in a valid polygon mesh (the diagram's
/// precondition, which `validate_input()` checks first). There the halfedge cycle around a
/// vertex reaches all its faces (`is_valid_polygon_mesh()` counts the halfedges the cycles
/// reach), and it can pass from one fan to another only along the border: a vertex has
/// several fans exactly when several are open. An open fan has one first corner, the one
/// whose incoming edge (local edge k + 2 at corner k) is on the border. One pass over the
/// faces, without a walk around the vertices.
template <class TriangleMesh>
std::vector<std::size_t> non_manifold_vertices(const Indexed_mesh<TriangleMesh>& mesh)
{
  std::vector<std::uint8_t> open_fans(mesh.number_of_vertices(), 0);
  std::vector<std::size_t> bad;
  for(std::size_t f = 0; f < mesh.number_of_faces(); ++f)
    for(int k = 0; k < 3; ++k)
      if(mesh.neighbors[f][(k + 2) % 3] == Indexed_mesh<TriangleMesh>::none)
      {
        std::uint8_t& fans = open_fans[mesh.triangles[f][k]];
        if(fans < 2 && ++fans == 2) bad.push_back(mesh.triangles[f][k]);
      }
  std::sort(bad.begin(), bad.end());
  return bad;
}

/// The documented coordinate range: no coordinate beyond 2^200 in magnitude (so that
/// squared areas, of the fourth power of the coordinates, cannot overflow) ...
constexpr double max_coordinate = 0x1p200;
/// ... and no face whose longest edge is shorter than 2^-200 (so that the squared area of a
/// face at the needle threshold, 2^-88 times the fourth power of that edge, cannot underflow).
constexpr double min_longest_edge = 0x1p-200;
/// A face whose area is below 2^-44 (about 5.7e-14) times its squared longest edge (its
/// height below about 1.1e-13 of that edge) is degenerate: its area, computed with an error
/// of a few 2^-53 of the squared edge, has lost more than 3 of its digits, and its cotangents
/// (above 2^43) swamp the Laplacian. Needles and caps above it are computed with (see
/// `needle_gram_ratio` for the barycentric coordinates).
constexpr double min_relative_area = 0x1p-44;

/// non-finite points and coordinates out of range, faces without area, degenerate or too
/// small, isolated vertices, and (unless the caller has checked them) non-manifold vertices
template <class TriangleMesh>
void find_mesh_problems(const Indexed_mesh<TriangleMesh>& mesh, Problem_list& list, bool check_vertex_fans = true)
{
  std::vector<std::uint8_t> used(mesh.number_of_vertices(), 0), finite(mesh.number_of_vertices(), 1);
  for(std::size_t v = 0; v < mesh.number_of_vertices(); ++v)
    for(int c = 0; c < 3; ++c)
      if(!std::isfinite(mesh.points[v][c]))
      {
        list.add(Input_problem::NON_FINITE_POINT, v, "vertex " + std::to_string(v) + " has a non-finite coordinate");
        finite[v] = 0;
        break;
      }
      else if(std::abs(mesh.points[v][c]) > max_coordinate)
      {
        list.add(Input_problem::COORDINATE_OUT_OF_RANGE, v, "vertex " + std::to_string(v)
                 + " has a coordinate beyond 2^200 (1.6e60) in magnitude, outside the range the diagram computes in; scale the mesh");
        finite[v] = 0;
        break;
      }
  for(std::size_t f = 0; f < mesh.number_of_faces(); ++f)
  {
    bool in_range = true;
    for(std::size_t v : mesh.triangles[f])
    {
      used[v] = 1;
      in_range = in_range && finite[v];
    }
    if(!in_range) continue;   // its vertex is reported
    double longest2 = 0;
    for(int k = 0; k < 3; ++k)
      longest2 = (std::max)(longest2, CGAL::squared_distance(mesh.corner(f, k), mesh.corner(f, (k + 1) % 3)));
    const double area = mesh.face_areas[f];
    if(!(std::sqrt(longest2) >= min_longest_edge) && longest2 < 1)   // (not a NaN from an overflow)
      list.add(Input_problem::ZERO_AREA_FACE, f, "face " + std::to_string(f)
               + " is too small: its longest edge is below 2^-200 (6.2e-61), outside the range the diagram computes in; scale the mesh");
    else if(!(area > 0) || !std::isfinite(area))
      list.add(Input_problem::ZERO_AREA_FACE, f, "face " + std::to_string(f) + " has zero area");
    else if(!(area >= min_relative_area * longest2))
      list.add(Input_problem::ZERO_AREA_FACE, f, "face " + std::to_string(f)
               + " is degenerate: its area is below 2^-44 (5.7e-14) times its squared longest edge (a needle or a cap too thin to compute with)");
  }
  for(std::size_t v = 0; v < used.size(); ++v)
    if(!used[v]) list.add(Input_problem::ISOLATED_VERTEX, v, "vertex " + std::to_string(v) + " belongs to no face");
  if(!check_vertex_fans) return;
  for(std::size_t v : non_manifold_vertices(mesh))
    list.add(Input_problem::NON_MANIFOLD_VERTEX, v, "vertex " + std::to_string(v) + " is non-manifold: its faces form separate fans");
}

/// The diagram's checks of the mesh, in every build: throws `Input_error` with the first
/// problem `find_mesh_problems()` finds (vertices first, then faces). A copy found valid is
/// not checked again.
template <class TriangleMesh>
void throw_mesh_problems(const Indexed_mesh<TriangleMesh>& mesh, bool check_vertex_fans)
{
  const Mesh_check_level::Level level = check_vertex_fans ? Mesh_check_level::WITH_FANS : Mesh_check_level::WITHOUT_FANS;
  if(mesh.checked.reached(level)) return;
  std::vector<Input_problem> problems;
  Problem_list list(problems, 1);
  find_mesh_problems(mesh, list, check_vertex_fans);
  if(!problems.empty()) throw Input_error(problems.front().message);
  mesh.checked.raise(level);
}

/// A metric's check of the mesh, in every build: what it computes with must be finite.
template <class TriangleMesh>
void throw_non_finite_points(const Indexed_mesh<TriangleMesh>& mesh)
{
  for(std::size_t v = 0; v < mesh.number_of_vertices(); ++v)
  {
    const Point_d& p = mesh.points[v];
    if(!(std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z())))
      throw Input_error("vertex " + std::to_string(v) + " has a non-finite coordinate");
  }
}

/// Pairs (first, later) of sites at the same surface point, each later site paired with the
/// lowest index of its group, ordered by the later site.
template <class TriangleMesh>
std::vector<std::pair<std::size_t, std::size_t> > find_coincident_sites(const Indexed_mesh<TriangleMesh>& mesh,
                                                                          const std::vector<Site>& sites)
{
  std::vector<Point_d> p(sites.size());
  for(std::size_t i = 0; i < sites.size(); ++i)
    p[i] = mesh.point_at(sites[i].face, sites[i].barycentric);
  std::vector<std::size_t> order(sites.size());
  for(std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return p[a] < p[b] || (p[a] == p[b] && a < b);
  });
  std::vector<std::pair<std::size_t, std::size_t> > pairs;
  std::size_t first = 0;
  for(std::size_t k = 1; k < order.size(); ++k)
  {
    if(p[order[k]] != p[order[k - 1]]) { first = k; continue; }
    pairs.emplace_back(order[first], order[k]);
  }
  std::sort(pairs.begin(), pairs.end(), [](const auto& a, const auto& b) { return a.second < b.second; });
  return pairs;
}

// A weight map is keyed either by the sites as the range holds them, or by site index.
template <class Map, class Site_description>
double site_weight(const Map& map, const Site_description& site, std::size_t index)
{
  typedef typename boost::property_traits<Map>::key_type Key;
  if constexpr(std::is_integral<Key>::value && !std::is_integral<Site_description>::value)
    return static_cast<double>(get(map, static_cast<Key>(index)));
  else
    return static_cast<double>(get(map, site));
}

template <class SiteRange, class NamedParameters>
void check_weights(const SiteRange& sites, const NamedParameters& np, Problem_list& list)
{
  if constexpr(!CGAL::parameters::is_default_parameter<NamedParameters, internal_np::site_weight_map_t>::value)
  {
    const auto& map = CGAL::parameters::get_parameter(np, internal_np::site_weight_map);
    std::size_t index = 0;
    for(const auto& s : sites)
    {
      if(!std::isfinite(site_weight(map, s, index)))
        list.add(Input_problem::NON_FINITE_WEIGHT, index, "the weight of site " + std::to_string(index) + " is not finite");
      ++index;
    }
  }
}

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_INPUT_VALIDATION_H
