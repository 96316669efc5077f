// Copyright (c) 2026 The Surface_voronoi_diagram authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Reading of input meshes for the surface_voronoi program (the benchmarks include it too, to
// time what the program does). Not part of the library: its users read meshes with
// CGAL::IO::read_polygon_mesh().
//
// A mesh is read as a polygon soup rather than directly into a halfedge data
// structure, because a halfedge structure cannot even represent most defects
// (non-manifold edges, dangling indices), so the builders either fail silently
// or abort. On the soup every defect can be detected and reported with the
// index of the offending vertex or face as it appears in the file.
//
// The files are parsed by the program's own bounded parsers (mesh_file_parsers.h), not by
// CGAL's stream readers: no file can crash the reader, make it loop or allocate beyond a
// small multiple of its size, and every error in a file's structure names the line (text
// formats) or the element (binary formats). Limits: a mesh file has at most
// `max_mesh_file_bytes` bytes (2 GiB), a polygon at most `max_polygon_corners` corners
// (10 million). `read_checked_triangle_mesh_from_memory()` is the fuzzing entry point.
//
// Contract (relied upon by outside checks of the program):
//  - vertex index = order of the vertex in the file, 0-based (for STL, which has
//    no shared vertices, the order of first appearance of each distinct point);
//  - face index = order of the polygon in the file, 0-based;
//  - polygons with more than 3 vertices are triangulated (ear clipping up to 256 corners,
//    as always; a constrained Delaunay triangulation in O(n log n) above);
//  - a non-finite coordinate, a zero-area face, a non-manifold edge or vertex,
//    a non-orientable surface or an empty mesh is an error naming the element;
//  - inconsistently oriented faces are re-oriented, not rejected;
//  - points used by no face are dropped (and counted), not rejected.

#ifndef SVD_PROGRAM_READ_CHECKED_MESH_H
#define SVD_PROGRAM_READ_CHECKED_MESH_H

#include "errors.h"
#include "input_file.h"
#include "mesh_file_parsers.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Constrained_triangulation_face_base_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh/Surface_mesh_fwd.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/Dynamic_property_map.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>
#include <cstdlib>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace svd_program {

/// What happened while a mesh was read and turned into a triangle mesh, for the
/// caller to log: none of these is an error.
struct Mesh_reading_report
{
  /// points in the input, including the isolated ones
  std::size_t number_of_points = 0;
  /// polygons in the input
  std::size_t number_of_polygons = 0;
  /// triangles of the built mesh
  std::size_t number_of_triangles = 0;
  /// input polygons with more than 3 vertices, which were triangulated
  std::size_t polygons_triangulated = 0;
  /// whether some faces had to be flipped to orient the surface consistently
  bool reoriented = false;
  /// input points used by no polygon, left out of the built mesh
  std::size_t isolated_points = 0;
  /// for each input point (file order), the index of its vertex in the built mesh (in the
  /// order of `vertices(mesh)`), or `std::size_t(-1)` for an isolated point
  std::vector<std::size_t> mesh_vertex_of_point;
};

namespace internal {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Checking_kernel;

inline std::string non_finite_name(double v)
{
  if(std::isnan(v))
    return "nan";
  return v > 0 ? "inf" : "-inf";
}

// Predicates are evaluated on the double approximation of the coordinates with
// an exact kernel, so a face is zero-area exactly when its stored coordinates
// are collinear: a tolerance would make the answer depend on the mesh scale.
template <class Point_3>
Checking_kernel::Point_3 to_checking_point(const Point_3& p)
{
  return Checking_kernel::Point_3(CGAL::to_double(p.x()), CGAL::to_double(p.y()),
                                  CGAL::to_double(p.z()));
}

template <class Point_3>
bool is_finite_point(const Point_3& p, double& bad_value)
{
  const double c[3] = { CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()) };
  for(double v : c)
  {
    if(!std::isfinite(v))
    {
      bad_value = v;
      return false;
    }
  }
  return true;
}

// A polygon has zero area when all its corners lie on one line (or one point).
template <class Point_3, class Polygon>
bool has_all_corners_collinear(const std::vector<Point_3>& points, const Polygon& polygon)
{
  const std::size_t n = polygon.size();
  const Checking_kernel::Point_3 p0 = to_checking_point(points[polygon[0]]);
  std::size_t k = 1;
  Checking_kernel::Point_3 pk;
  for(; k < n; ++k)
  {
    pk = to_checking_point(points[polygon[k]]);
    if(pk != p0)
      break;
  }
  if(k == n)
    return true;
  for(std::size_t j = k + 1; j < n; ++j)
    if(!CGAL::collinear(p0, pk, to_checking_point(points[polygon[j]])))
      return false;
  return true;
}

// One side of an edge as seen from one polygon, stored in the group of the edge's lower
// vertex. Sorting a group by (hi, face) orders the polygons around each undirected edge
// deterministically, which keeps error messages reproducible, without any hashing. Indices
// are 32-bit when the soup allows (half the memory, which is most of the check's time).
template <class Index>
struct Soup_half_edge
{
  Index hi, face;
  Index corner_lo, corner_hi; // the polygon's corners at lo and at hi
  bool forward;               // the polygon walks the edge from lo to hi
};

template <class Index>
struct Face_link
{
  Index face_a, face_b, lo, hi;
  bool same_direction;
};

// Names faces in messages: the triangles made from a polygon report the index
// of that polygon, since it is the only face index the user knows.
class Face_namer
{
public:
  Face_namer(const std::vector<std::size_t>* ids, const std::string& context)
    : ids_(ids), context_(context)
  {}
  std::size_t operator()(std::size_t f) const { return ids_ == nullptr ? f : (*ids_)[f]; }
  const std::string& context() const { return context_; }

private:
  const std::vector<std::size_t>* ids_;
  std::string context_;
};

// Disjoint sets of the indices 0..n-1 in two flat arrays (path halving, union by size):
// only which elements share a set matters to the callers, not which one represents it.
template <class Index>
class Index_union_find
{
public:
  explicit Index_union_find(std::size_t n) : parent_(n), size_(n, 1)
  {
    for(std::size_t i = 0; i < n; ++i)
      parent_[i] = static_cast<Index>(i);
  }
  Index find(Index i)
  {
    while(parent_[i] != i)
    {
      parent_[i] = parent_[parent_[i]];
      i = parent_[i];
    }
    return i;
  }
  void unite(Index a, Index b)
  {
    a = find(a);
    b = find(b);
    if(a == b)
      return;
    if(size_[a] < size_[b])
      std::swap(a, b);
    parent_[b] = a;
    size_[a] += size_[b];
  }

private:
  std::vector<Index> parent_, size_;
};

// check_soup_topology() with indices of type Index, large enough for every corner and vertex.
template <class Index, class PolygonRange>
bool check_soup_topology_with(const PolygonRange& polygons, std::size_t number_of_vertices,
                              std::size_t number_of_corners, const Face_namer& name)
{
  std::vector<Index> corner_offset(polygons.size() + 1, 0);
  for(std::size_t f = 0; f < polygons.size(); ++f)
    corner_offset[f + 1] = static_cast<Index>(corner_offset[f] + polygons[f].size());

  // Half-edges grouped by their lower vertex with a counting sort (linear, unlike a sort of
  // the whole array), then ordered by (hi, face) within each group: the same order as a
  // sort by (lo, hi, face), so messages name the same elements.
  std::vector<Index> edge_begin(number_of_vertices + 1, 0);
  std::vector<Index> corner_begin(number_of_vertices + 1, 0);
  for(const auto& polygon : polygons)
  {
    const std::size_t m = polygon.size();
    for(std::size_t j = 0; j < m; ++j)
    {
      ++edge_begin[(std::min)(polygon[j], polygon[(j + 1) % m]) + 1];
      ++corner_begin[polygon[j] + 1];
    }
  }
  for(std::size_t v = 0; v < number_of_vertices; ++v)
  {
    edge_begin[v + 1] += edge_begin[v];
    corner_begin[v + 1] += corner_begin[v];
  }
  std::vector<Soup_half_edge<Index>> half_edges(number_of_corners);
  std::vector<Index> corners_by_vertex(number_of_corners);
  {
    std::vector<Index> edge_fill(edge_begin.begin(), edge_begin.end() - 1);
    std::vector<Index> corner_fill(corner_begin.begin(), corner_begin.end() - 1);
    for(std::size_t f = 0; f < polygons.size(); ++f)
    {
      const std::size_t m = polygons[f].size();
      for(std::size_t j = 0; j < m; ++j)
      {
        const std::size_t u = polygons[f][j], w = polygons[f][(j + 1) % m];
        const Index cu = static_cast<Index>(corner_offset[f] + j), cw = static_cast<Index>(corner_offset[f] + (j + 1) % m);
        corners_by_vertex[corner_fill[u]++] = cu;
        half_edges[edge_fill[(std::min)(u, w)]++] =
            u < w ? Soup_half_edge<Index>{ static_cast<Index>(w), static_cast<Index>(f), cu, cw, true }
                  : Soup_half_edge<Index>{ static_cast<Index>(u), static_cast<Index>(f), cw, cu, false };
      }
    }
  }
  std::vector<Index>().swap(corner_offset);
  const auto edge_order = [](const Soup_half_edge<Index>& a, const Soup_half_edge<Index>& b) {
    return std::tie(a.hi, a.face, a.corner_lo) < std::tie(b.hi, b.face, b.corner_lo);
  };

  // Corners of the same vertex are glued across every edge shared by exactly
  // two faces; the connected classes of corners of a vertex are its fans.
  Index_union_find<Index> corners(number_of_corners);
  std::vector<Face_link<Index>> links;
  links.reserve(number_of_corners / 2);
  bool consistently_oriented = true;
  for(std::size_t lo = 0; lo < number_of_vertices; ++lo)
  {
    const auto first = half_edges.begin() + std::ptrdiff_t(edge_begin[lo]);
    const auto last = half_edges.begin() + std::ptrdiff_t(edge_begin[lo + 1]);
    if(last - first <= 16)
    {
      for(auto i = first; i != last; ++i)   // insertion sort: groups are a vertex's few edges
        for(auto j = i; j != first && edge_order(*j, *(j - 1)); --j)
          std::iter_swap(j, j - 1);
    }
    else
      std::sort(first, last, edge_order);
    for(auto begin = first; begin != last;)
    {
      auto end = begin + 1;
      while(end != last && end->hi == begin->hi)
        ++end;
      const std::size_t count = std::size_t(end - begin);
      if(count > 2)
      {
        std::ostringstream msg;
        msg << "edge (" << lo << ", " << begin->hi << ") is non-manifold: shared by " << count << " faces (";
        for(auto i = begin; i != end; ++i)
          msg << (i == begin ? "" : ", ") << name(i->face);
        msg << ")" << name.context();
        throw Input_error(msg.str());
      }
      if(count == 2)
      {
        const Soup_half_edge<Index>& a = *begin;
        const Soup_half_edge<Index>& b = *(begin + 1);
        corners.unite(a.corner_lo, b.corner_lo);
        corners.unite(a.corner_hi, b.corner_hi);
        links.push_back(Face_link<Index>{ a.face, b.face, static_cast<Index>(lo), a.hi, a.forward == b.forward });
        if(a.forward == b.forward)
          consistently_oriented = false;
      }
      begin = end;
    }
  }
  std::vector<Soup_half_edge<Index>>().swap(half_edges);
  std::vector<Index>().swap(edge_begin);

  // one fan per vertex: all its corners in one class
  for(std::size_t v = 0; v < number_of_vertices; ++v)
  {
    const std::size_t begin = corner_begin[v], end = corner_begin[v + 1];
    if(begin == end)
      continue;
    const Index root = corners.find(corners_by_vertex[begin]);
    bool one_fan = true;
    for(std::size_t i = begin + 1; i < end && one_fan; ++i)
      one_fan = corners.find(corners_by_vertex[i]) == root;
    if(one_fan)
      continue;
    std::vector<Index> roots;
    for(std::size_t i = begin; i < end; ++i)
      roots.push_back(corners.find(corners_by_vertex[i]));
    std::sort(roots.begin(), roots.end());
    const std::size_t fans = std::size_t(std::unique(roots.begin(), roots.end()) - roots.begin());
    std::ostringstream msg;
    msg << "vertex " << v << " is non-manifold: its faces form " << fans << " separate fans" << name.context();
    throw Input_error(msg.str());
  }
  std::vector<Index>().swap(corners_by_vertex);
  std::vector<Index>().swap(corner_begin);

  // Two-colouring of the face adjacency graph: a face keeps (0) or flips (1)
  // its orientation; a contradiction means no orientation exists at all.
  std::vector<Index> link_offset(polygons.size() + 1, 0);
  for(const Face_link<Index>& l : links)
  {
    ++link_offset[l.face_a + 1];
    ++link_offset[l.face_b + 1];
  }
  for(std::size_t f = 0; f < polygons.size(); ++f)
    link_offset[f + 1] += link_offset[f];
  std::vector<Index> adjacency(link_offset.back());
  {
    std::vector<Index> fill(link_offset.begin(), link_offset.end() - 1);
    for(std::size_t i = 0; i < links.size(); ++i)
    {
      adjacency[fill[links[i].face_a]++] = static_cast<Index>(i);
      adjacency[fill[links[i].face_b]++] = static_cast<Index>(i);
    }
  }
  std::vector<signed char> flip(polygons.size(), -1);
  std::vector<Index> queue;
  for(std::size_t seed = 0; seed < polygons.size(); ++seed)
  {
    if(flip[seed] != -1)
      continue;
    flip[seed] = 0;
    queue.assign(1, static_cast<Index>(seed));
    while(!queue.empty())
    {
      const std::size_t f = queue.back();
      queue.pop_back();
      for(std::size_t k = link_offset[f]; k < link_offset[f + 1]; ++k)
      {
        const Face_link<Index>& l = links[adjacency[k]];
        const std::size_t g = (l.face_a == f) ? l.face_b : l.face_a;
        const signed char wanted = static_cast<signed char>(flip[f] ^ (l.same_direction ? 1 : 0));
        if(flip[g] == -1)
        {
          flip[g] = wanted;
          queue.push_back(static_cast<Index>(g));
        }
        else if(flip[g] != wanted)
        {
          std::ostringstream msg;
          msg << "the mesh is not orientable (like a Moebius strip): faces "
              << name(std::min(f, g)) << " and " << name(std::max(f, g))
              << " cannot be oriented consistently across edge (" << l.lo << ", " << l.hi << ")"
              << name.context();
          throw Input_error(msg.str());
        }
      }
    }
  }
  return consistently_oriented;
}

// Checks what depends only on the indices: every edge has at most two faces,
// the faces around every vertex form one fan, and the surface is orientable.
// Returns whether the faces are already consistently oriented.
template <class PolygonRange>
bool check_soup_topology(const PolygonRange& polygons, const Face_namer& name)
{
  std::size_t number_of_vertices = 0, number_of_corners = 0;
  for(const auto& polygon : polygons)
  {
    number_of_corners += polygon.size();
    for(std::size_t v : polygon)
      number_of_vertices = (std::max)(number_of_vertices, std::size_t(v) + 1);
  }
  // Index must hold every corner, vertex and face, and the counts one past them
  const std::size_t largest = (std::max)(number_of_corners, number_of_vertices) + 1;
  if(largest < std::size_t((std::numeric_limits<std::uint32_t>::max)()))
    return check_soup_topology_with<std::uint32_t>(polygons, number_of_vertices, number_of_corners, name);
  return check_soup_topology_with<std::size_t>(polygons, number_of_vertices, number_of_corners, name);
}

// Checks of single elements: coordinates, then each face on its own.
template <class Point_3>
void check_soup_elements(const std::vector<Point_3>& points,
                         const std::vector<std::vector<std::size_t>>& polygons)
{
  if(polygons.empty())
    throw Input_error("the mesh is empty (no faces)");

  for(std::size_t i = 0; i < points.size(); ++i)
  {
    double bad = 0;
    if(!is_finite_point(points[i], bad))
      throw Input_error("vertex " + std::to_string(i) + " has a non-finite coordinate (" +
                        non_finite_name(bad) + ")");
  }

  std::vector<std::size_t> sorted;
  for(std::size_t f = 0; f < polygons.size(); ++f)
  {
    const std::vector<std::size_t>& polygon = polygons[f];
    auto face = [f] { return "face " + std::to_string(f); };   // built only for a message
    if(polygon.size() < 3)
      throw Input_error(face() + " has fewer than 3 vertices");
    for(std::size_t v : polygon)
      if(v >= points.size())
        throw Input_error(face() + " references vertex " + std::to_string(v) + " but the mesh has " +
                          std::to_string(points.size()) + " vertices");
    if(polygon.size() > 3 || polygon[0] == polygon[1] || polygon[1] == polygon[2] || polygon[2] == polygon[0])
    {
      sorted.assign(polygon.begin(), polygon.end());
      std::sort(sorted.begin(), sorted.end());
      const auto repeated = std::adjacent_find(sorted.begin(), sorted.end());
      if(repeated != sorted.end())
        throw Input_error(face() + " repeats vertex " + std::to_string(*repeated));
    }
    if(has_all_corners_collinear(points, polygon))
      throw Input_error(face() + " has zero area");
  }
}

// The coordinate plane a polygon is projected to: the axis closest to its Newell normal is
// dropped; `u_axis`, `v_axis` are the kept ones in cyclic order, so that counterclockwise in
// 2D means along +axis in 3D when `counterclockwise`. False when the normal is zero.
struct Projection_plane
{
  int u_axis, v_axis;
  bool counterclockwise;
};

template <class Point_3>
bool projection_plane(const std::vector<Point_3>& points, const std::vector<std::size_t>& polygon,
                      Projection_plane& plane)
{
  const std::size_t n = polygon.size();
  double normal[3] = { 0, 0, 0 };
  for(std::size_t j = 0; j < n; ++j)
  {
    const Checking_kernel::Point_3 a = to_checking_point(points[polygon[j]]);
    const Checking_kernel::Point_3 b = to_checking_point(points[polygon[(j + 1) % n]]);
    normal[0] += (a.y() - b.y()) * (a.z() + b.z());
    normal[1] += (a.z() - b.z()) * (a.x() + b.x());
    normal[2] += (a.x() - b.x()) * (a.y() + b.y());
  }
  int axis = 0;
  for(int k = 1; k < 3; ++k)
    if(std::abs(normal[k]) > std::abs(normal[axis]))
      axis = k;
  if(!(std::abs(normal[axis]) > 0))
    return false;
  plane.u_axis = (axis + 1) % 3;
  plane.v_axis = (axis + 2) % 3;
  plane.counterclockwise = normal[axis] > 0;
  return true;
}

// Ear clipping in a coordinate plane. The polygon is projected along the axis
// closest to its Newell normal (dropping that coordinate), which maps a planar
// polygon onto a simple polygon of the same orientation as the best-fit plane
// does, but keeps the coordinates exact, so the 2D orientation predicates are
// exact and non-convex corners are never mistaken for ears.
// Returns false when no ear can be found, i.e. the polygon is not simple in
// that projection (self-intersecting, or too warped).
template <class Point_3>
bool ear_clip_polygon(const std::vector<Point_3>& points, const std::vector<std::size_t>& polygon,
                      std::vector<std::array<std::size_t, 3>>& triangles)
{
  typedef Checking_kernel::Point_2 Point_2;
  const std::size_t n = polygon.size();

  Projection_plane plane;
  if(!projection_plane(points, polygon, plane))
    return false;
  const int u_axis = plane.u_axis, v_axis = plane.v_axis;
  const CGAL::Orientation convex = plane.counterclockwise ? CGAL::LEFT_TURN : CGAL::RIGHT_TURN;
  const CGAL::Orientation concave = plane.counterclockwise ? CGAL::RIGHT_TURN : CGAL::LEFT_TURN;

  const std::vector<std::size_t>& ring = polygon;
  std::vector<Point_2> q(n);
  for(std::size_t j = 0; j < n; ++j)
  {
    const Checking_kernel::Point_3 p = to_checking_point(points[polygon[j]]);
    q[j] = Point_2(p[u_axis], p[v_axis]);
  }

  auto is_ear = [&](std::size_t a, std::size_t b, std::size_t c) {
    if(CGAL::orientation(q[a], q[b], q[c]) != convex)
      return false;
    for(std::size_t j = 0; j < q.size(); ++j)
    {
      if(j == a || j == b || j == c)
        continue;
      // A copy of a corner touches the ear without entering it (polygons
      // touching themselves at a point).
      if(q[j] == q[a] || q[j] == q[b] || q[j] == q[c])
        continue;
      if(CGAL::orientation(q[a], q[b], q[j]) != concave &&
         CGAL::orientation(q[b], q[c], q[j]) != concave &&
         CGAL::orientation(q[c], q[a], q[j]) != concave)
        return false;
    }
    return true;
  };

  std::vector<std::size_t> live(n); // positions in q of the vertices still in the ring
  for(std::size_t j = 0; j < n; ++j)
    live[j] = j;

  std::size_t i = 0, misses = 0;
  while(live.size() > 4)
  {
    const std::size_t m = live.size();
    const std::size_t prev = (i + m - 1) % m, next = (i + 1) % m;
    if(is_ear(live[prev], live[i], live[next]))
    {
      triangles.push_back({ ring[live[prev]], ring[live[i]], ring[live[next]] });
      live.erase(live.begin() + static_cast<std::ptrdiff_t>(i));
      if(i == live.size())
        i = 0;
      misses = 0;
    }
    else
    {
      i = next;
      if(++misses > m)
        return false;
    }
  }
  if(live.size() == 4)
  {
    // Of the two diagonals, the shorter one gives the better-shaped triangles.
    const bool ear0 = is_ear(live[3], live[0], live[1]); // diagonal (1, 3)
    const bool ear1 = is_ear(live[0], live[1], live[2]); // diagonal (0, 2)
    if(!ear0 && !ear1)
      return false;
    bool use_13 = ear0;
    if(ear0 && ear1)
    {
      const auto p = [&](std::size_t k) { return to_checking_point(points[ring[live[k]]]); };
      use_13 = CGAL::squared_distance(p(1), p(3)) <= CGAL::squared_distance(p(0), p(2));
    }
    const std::size_t* r = live.data();
    if(use_13)
    {
      triangles.push_back({ ring[r[3]], ring[r[0]], ring[r[1]] });
      triangles.push_back({ ring[r[1]], ring[r[2]], ring[r[3]] });
    }
    else
    {
      triangles.push_back({ ring[r[0]], ring[r[1]], ring[r[2]] });
      triangles.push_back({ ring[r[2]], ring[r[3]], ring[r[0]] });
    }
  }
  else
    triangles.push_back({ ring[live[0]], ring[live[1]], ring[live[2]] });
  return true;
}

// Polygons with more corners than this are triangulated by `cdt_triangulate_polygon()`,
// the others by ear clipping (quadratic, but its triangles are the ones the program has
// always made, so small polygons keep their triangulation bit for bit).
constexpr std::size_t ear_clipping_max_corners = 256;

// Triangulation of a large polygon in O(n log n): the constrained Delaunay triangulation
// of its projection (the same coordinate plane as `ear_clip_polygon()`), with the polygon's
// edges as constraints and no Steiner point, keeping the triangles inside. Returns false
// when the projected polygon is not simple: two corners project to one point, two edges
// cross or overlap, or an edge runs through a corner (the triangulation throws, or the
// polygon's edges are not all edges of it, or it has other than n - 2 inner triangles).
template <class Point_3>
bool cdt_triangulate_polygon(const std::vector<Point_3>& points, const std::vector<std::size_t>& polygon,
                             std::vector<std::array<std::size_t, 3>>& triangles)
{
  typedef Checking_kernel K;
  typedef CGAL::Triangulation_vertex_base_with_info_2<std::size_t, K> Vb;
  typedef CGAL::Constrained_triangulation_face_base_2<K> Cfb;
  typedef CGAL::Triangulation_face_base_with_info_2<int, K, Cfb> Fb; // nesting level, -1 unset
  typedef CGAL::Triangulation_data_structure_2<Vb, Fb> Tds;
  typedef CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::No_constraint_intersection_tag> CDT;
  typedef typename CDT::Vertex_handle Vertex_handle;
  typedef typename CDT::Face_handle Face_handle;
  const std::size_t n = polygon.size();

  Projection_plane plane;
  if(!projection_plane(points, polygon, plane))
    return false;
  const int u_axis = plane.u_axis, v_axis = plane.v_axis;
  const bool counterclockwise = plane.counterclockwise;

  std::vector<std::pair<K::Point_2, std::size_t>> q(n);
  for(std::size_t j = 0; j < n; ++j)
  {
    const Checking_kernel::Point_3 p = to_checking_point(points[polygon[j]]);
    q[j] = std::make_pair(K::Point_2(p[u_axis], p[v_axis]), j);
  }
  CDT cdt;
  std::vector<Vertex_handle> handle(n);
  try
  {
    cdt.insert(q.begin(), q.end());
    if(cdt.number_of_vertices() != n || cdt.dimension() != 2)
      return false; // two corners on one point
    for(Vertex_handle v : cdt.finite_vertex_handles())
      handle[v->info()] = v;
    for(std::size_t j = 0; j < n; ++j)
      cdt.insert_constraint(handle[j], handle[(j + 1) % n]);
  }
  catch(const typename CDT::Intersection_of_constraints_exception&)
  {
    return false;
  }
  for(std::size_t j = 0; j < n; ++j)
    if(!cdt.is_edge(handle[j], handle[(j + 1) % n]))
      return false; // an edge was split by a corner lying on it
  if(cdt.number_of_vertices() != n)
    return false;

  // Faces reached from the outside crossing an odd number of constraints are inside.
  for(Face_handle f : cdt.all_face_handles())
    f->info() = -1;
  std::vector<Face_handle> stack, next_stack;
  stack.push_back(cdt.infinite_face());
  cdt.infinite_face()->info() = 0;
  int depth = 0;
  while(!stack.empty())
  {
    while(!stack.empty())
    {
      const Face_handle f = stack.back();
      stack.pop_back();
      for(int i = 0; i < 3; ++i)
      {
        const Face_handle g = f->neighbor(i);
        if(g->info() != -1)
          continue;
        if(f->is_constrained(i))
          next_stack.push_back(g);
        else
        {
          g->info() = depth;
          stack.push_back(g);
        }
      }
    }
    ++depth;
    for(const Face_handle& g : next_stack)
      if(g->info() == -1)
      {
        g->info() = depth;
        stack.push_back(g);
      }
    next_stack.clear();
  }
  const std::size_t first = triangles.size();
  for(Face_handle f : cdt.finite_face_handles())
  {
    if(f->info() != 1)
      continue;
    const std::size_t a = f->vertex(0)->info(), b = f->vertex(1)->info(), c = f->vertex(2)->info();
    if(counterclockwise)
      triangles.push_back({ polygon[a], polygon[b], polygon[c] });
    else
      triangles.push_back({ polygon[a], polygon[c], polygon[b] });
  }
  if(triangles.size() - first != n - 2)
  {
    triangles.resize(first);
    return false;
  }
  return true;
}

// Triangulates a polygon: ear clipping up to `ear_clipping_max_corners` corners, a
// constrained Delaunay triangulation above. Returns false if the polygon is not simple.
template <class Point_3>
bool triangulate_polygon(const std::vector<Point_3>& points, const std::vector<std::size_t>& polygon,
                         std::vector<std::array<std::size_t, 3>>& triangles)
{
  if(polygon.size() <= ear_clipping_max_corners)
    return ear_clip_polygon(points, polygon, triangles);
  return cdt_triangulate_polygon(points, polygon, triangles);
}

inline std::string lower_case_extension(const std::string& filename)
{
  const std::size_t dot = filename.find_last_of('.');
  const std::size_t slash = filename.find_last_of("/\\");
  if(dot == std::string::npos || (slash != std::string::npos && dot < slash))
    return std::string();
  std::string ext = filename.substr(dot + 1);
  for(char& c : ext)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

template <class TriangleMesh>
struct Mesh_point
{
  typedef typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type Map;
  typedef typename boost::property_traits<Map>::value_type type;
};

} // namespace internal

/// Checks that a polygon soup describes a manifold, orientable surface with
/// finite coordinates and no zero-area face. Faces need not be consistently
/// oriented (an edge walked twice in the same direction is not an error).
/// Points used by no polygon are allowed (but must have finite coordinates).
///
/// Errors name vertices and faces by their index in `points` and `polygons`.
/// The checks run in this order, and the first failure is reported: no face;
/// a non-finite coordinate; for each face in order, fewer than 3 vertices, an
/// out-of-range index, a repeated vertex, all corners collinear (exact
/// predicate); an edge shared by more than 2 faces; a vertex whose faces,
/// linked through the edges incident to it, form more than one fan; a
/// non-orientable surface.
///
/// \tparam Point_3 a point type with `x()`, `y()`, `z()` accepted by `CGAL::to_double()`
/// \param points the points of the soup
/// \param polygons each polygon as the indices of its corners in `points`
/// \pre nothing: any defect of the soup is reported by an exception
/// \throws svd_program::Input_error with a one-line message naming the
///         offending element, e.g. `edge (4, 9) is non-manifold: shared by 3 faces (1, 5, 8)`
template <class Point_3>
void check_polygon_soup(const std::vector<Point_3>& points,
                        const std::vector<std::vector<std::size_t>>& polygons)
{
  internal::check_soup_elements(points, polygons);
  internal::check_soup_topology(polygons, internal::Face_namer(nullptr, std::string()));
}

namespace internal {

// The halfedges of a triangle soup paired: corner c = 3 t + i stands for the halfedge from
// corner i to corner i + 1 of triangle t, and twins[c] is the corner of the halfedge back
// (3 x the number of triangles on a border). Empty unless the soup is an oriented manifold
// surface: an edge in one direction twice or in more than two triangles, or a vertex whose
// triangles form several fans, is left to check_soup_topology() to name.
template <class TriangleRange>
std::vector<std::uint32_t> oriented_manifold_twins(const TriangleRange& triangles, std::size_t number_of_points)
{
  const std::size_t corners = 3 * triangles.size();
  const std::size_t largest = std::size_t((std::numeric_limits<std::uint32_t>::max)());
  if(corners >= largest || number_of_points >= largest) return {};
  const std::uint32_t none = std::uint32_t(corners);
  auto corner_at = [&](std::size_t c) { return std::size_t(triangles[c / 3][c % 3]); };
  auto prev = [](std::uint32_t c) { return c - c % 3 + (c + 2) % 3; };
  // the corners of each vertex, with the vertex their halfedge leads to
  std::vector<std::uint32_t> begin(number_of_points + 1, 0);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> leaving(corners);   // (head, corner)
  for(std::size_t c = 0; c < corners; ++c) ++begin[corner_at(c) + 1];
  for(std::size_t v = 0; v < number_of_points; ++v) begin[v + 1] += begin[v];
  {
    std::vector<std::uint32_t> fill(begin.begin(), begin.end() - 1);
    for(std::size_t c = 0; c < corners; ++c)
      leaving[fill[corner_at(c)]++] = { std::uint32_t(corner_at(c - c % 3 + (c + 1) % 3)), std::uint32_t(c) };
  }
  std::vector<std::uint32_t> twins(corners, none);
  for(std::size_t u = 0; u < number_of_points; ++u)
    for(std::uint32_t j = begin[u]; j < begin[u + 1]; ++j)
    {
      // an edge twice in one direction has two halfedges back, or none and then two corners
      // without a twin at its tail, which the fans below refuse
      const std::uint32_t w = leaving[j].first;
      std::size_t back = 0;
      for(std::uint32_t k = begin[w]; k < begin[w + 1]; ++k)
        if(leaving[k].first == u) ++back, twins[leaving[j].second] = leaving[k].second;
      if(back > 1) return {};
    }
  // one fan per vertex: its corners, turned through the twins (c to twins[prev(c)]), are one
  // chain from the corner without a twin, or one cycle
  for(std::size_t v = 0; v < number_of_points; ++v)
  {
    const std::uint32_t n = begin[v + 1] - begin[v];
    std::uint32_t start = n == 0 ? none : leaving[begin[v]].second, starts = 0;
    for(std::uint32_t j = begin[v]; j < begin[v + 1]; ++j)
      if(twins[leaving[j].second] == none) start = leaving[j].second, ++starts;
    if(starts > 1) return {};
    std::uint32_t count = 0;
    for(std::uint32_t c = start; c != none && count <= n; c = twins[prev(c)])
      if(++count > 1 && c == start) { --count; break; }
    if(count != n) return {};
  }
  return twins;
}

// A triangle soup that is an oriented manifold surface without isolated points, built into
// `mesh` as polygon_soup_to_polygon_mesh() builds it.
template <class Point_3, class TriangleMesh>
void build_oriented_triangle_mesh(const std::vector<Point_3>& points,
                                  const std::vector<std::array<std::size_t, 3>>& triangles,
                                  const std::vector<std::uint32_t>&, TriangleMesh& mesh)
{
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, triangles, mesh);
}

// The same for a Surface_mesh, in linear time and with the same indices of every element and
// the same halfedge of every face and vertex: each triangle in turn creates the edges not
// created before (the halfedge from its corner i to i+1 first), its halfedge is the one from
// corner 2 to 0; a vertex's halfedge is its incoming border halfedge, or else its incoming
// halfedge in the last triangle around it. The soup's checks rule out every case in which
// CGAL::Euler::add_face() relinks.
template <class Point_3, class P>
void build_oriented_triangle_mesh(const std::vector<Point_3>& points,
                                  const std::vector<std::array<std::size_t, 3>>& triangles,
                                  std::vector<std::uint32_t> twins, CGAL::Surface_mesh<P>& mesh)
{
  typedef CGAL::Surface_mesh<P> Mesh;
  typedef typename Mesh::Halfedge_index H;
  typedef typename Mesh::size_type Size;
  const std::size_t corners = 3 * triangles.size(), none = corners;
  if(twins.empty()) twins = oriented_manifold_twins(triangles, points.size());
  if(twins.empty() || corners >= std::size_t((std::numeric_limits<Size>::max)()) / 2)
    return CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, triangles, mesh);
  // each corner's halfedge: a new edge's first halfedge, or the twin's opposite
  std::vector<H> halfedge_of(corners);
  Size edges = 0;
  for(std::size_t c = 0; c < corners; ++c)
    halfedge_of[c] = (twins[c] < c) ? H(Size(halfedge_of[twins[c]]) ^ 1) : H(2 * edges++);
  mesh.resize(Size(points.size()), edges, Size(triangles.size()));
  for(std::size_t v = 0; v < points.size(); ++v) mesh.point(typename Mesh::Vertex_index(Size(v))) = P(points[v]);
  std::vector<H> leaving_border(points.size());
  for(std::size_t t = 0; t < triangles.size(); ++t)
  {
    const typename Mesh::Face_index f(static_cast<Size>(t));
    mesh.set_halfedge(f, halfedge_of[3 * t + 2]);
    for(std::size_t i = 0; i < 3; ++i)
    {
      const std::size_t c = 3 * t + i;
      const H h = halfedge_of[c];
      const typename Mesh::Vertex_index u{ Size(triangles[t][i]) }, w{ Size(triangles[t][(i + 1) % 3]) };
      mesh.set_target(h, w);
      mesh.set_next(h, halfedge_of[3 * t + (i + 1) % 3]);
      mesh.set_face(h, f);
      mesh.set_halfedge(w, h);
      if(twins[c] == none)
      {
        mesh.set_target(mesh.opposite(h), u);
        mesh.set_face(mesh.opposite(h), Mesh::null_face());
        leaving_border[Size(w)] = mesh.opposite(h);
      }
    }
  }
  // each border vertex has one incoming and one outgoing border halfedge; the incoming one is its halfedge
  for(std::size_t c = 0; c < corners; ++c)
    if(twins[c] == none)
    {
      const H b = mesh.opposite(halfedge_of[c]);
      mesh.set_next(b, leaving_border[Size(mesh.target(b))]);
      mesh.set_halfedge(mesh.target(b), b);
    }
}

} // namespace internal

/// Builds a triangle mesh from a polygon soup held in memory, after checking it
/// with `check_polygon_soup()`.
///
/// Polygons with more than 3 vertices are triangulated in a projection onto the
/// coordinate plane closest to the polygon's plane, which is correct for simple planar
/// polygons, convex or not (and for mildly warped ones): by ear clipping up to
/// `internal::ear_clipping_max_corners` (256) corners, above by a constrained Delaunay
/// triangulation of the projected polygon without Steiner points (O(n log n); a polygon
/// whose projection is not simple is refused). Faces are re-oriented consistently with
/// `CGAL::Polygon_mesh_processing::orient_polygon_soup()` when needed. Points
/// used by no polygon are left out of `mesh`, but errors still use the indices
/// of `points`; errors about a triangle made from a polygon name the polygon.
///
/// \tparam Point_3 a point type convertible to the point type of `TriangleMesh`
/// \tparam TriangleMesh a model of `MutableFaceGraph` with an internal
///         `CGAL::vertex_point_t` property map, e.g. `CGAL::Surface_mesh` or `CGAL::Polyhedron_3`
/// \param points the points of the soup
/// \param polygons each polygon as the indices of its corners in `points`
/// \param mesh the output; cleared first, and left untouched if an error is thrown
/// \pre nothing: any defect of the soup is reported by an exception
/// \throws svd_program::Input_error as `check_polygon_soup()`, and when a
///         polygon cannot be triangulated or yields a zero-area triangle
/// \returns what was done to the soup (triangulation, re-orientation, isolated points)
template <class Point_3, class TriangleMesh>
Mesh_reading_report build_checked_triangle_mesh(const std::vector<Point_3>& points,
                                                const std::vector<std::vector<std::size_t>>& polygons,
                                                TriangleMesh& mesh)
{
  internal::check_soup_elements(points, polygons);
  // a soup of triangles is checked by pairing its halfedges, which the mesh is built from;
  // the full check names what is wrong, or orients and triangulates
  std::vector<std::uint32_t> twins;
  if(std::all_of(polygons.begin(), polygons.end(), [](const std::vector<std::size_t>& p) { return p.size() == 3; }))
    twins = internal::oriented_manifold_twins(polygons, points.size());
  bool consistently_oriented =
      !twins.empty() || internal::check_soup_topology(polygons, internal::Face_namer(nullptr, std::string()));

  Mesh_reading_report report;
  report.number_of_points = points.size();
  report.number_of_polygons = polygons.size();

  std::vector<std::array<std::size_t, 3>> triangles;
  std::vector<std::size_t> triangle_face; // index of the polygon each triangle comes from
  triangles.reserve(polygons.size());
  triangle_face.reserve(polygons.size());
  for(std::size_t f = 0; f < polygons.size(); ++f)
  {
    const std::vector<std::size_t>& polygon = polygons[f];
    if(polygon.size() == 3)
    {
      triangles.push_back({ polygon[0], polygon[1], polygon[2] });
      triangle_face.push_back(f);
      continue;
    }
    ++report.polygons_triangulated;
    const std::size_t first = triangles.size();
    if(!internal::triangulate_polygon(points, polygon, triangles))
      throw Input_error("face " + std::to_string(f) +
                        " cannot be triangulated: it is not a simple planar polygon");
    for(std::size_t t = first; t < triangles.size(); ++t)
    {
      const std::array<std::size_t, 3>& tri = triangles[t];
      if(CGAL::collinear(internal::to_checking_point(points[tri[0]]),
                         internal::to_checking_point(points[tri[1]]),
                         internal::to_checking_point(points[tri[2]])))
        throw Input_error("face " + std::to_string(f) +
                          " has a zero-area triangle after triangulation (vertices " +
                          std::to_string(tri[0]) + ", " + std::to_string(tri[1]) + ", " +
                          std::to_string(tri[2]) + ")");
      triangle_face.push_back(f);
    }
  }

  if(report.polygons_triangulated > 0)
  {
    // A diagonal may coincide with an edge elsewhere in the soup, so the
    // triangle soup can be non-manifold even when the polygons were not.
    consistently_oriented = internal::check_soup_topology(
        triangles, internal::Face_namer(&triangle_face, " after triangulating polygons"));
  }

  std::vector<Point_3> kept_points(points);
  if(!consistently_oriented)
  {
    // The soup was checked orientable and manifold, so the orienter has no
    // reason to duplicate points; if it does, our checks missed a case.
    if(!CGAL::Polygon_mesh_processing::orient_polygon_soup(kept_points, triangles))
      throw Input_error("the mesh cannot be oriented consistently (it is not an orientable manifold surface)");
    report.reoriented = true;
  }

  std::vector<std::size_t> new_index(kept_points.size(), 0);
  std::vector<bool> used(kept_points.size(), false);
  for(const std::array<std::size_t, 3>& tri : triangles)
    for(std::size_t v : tri)
      used[v] = true;
  std::size_t kept = 0;
  for(std::size_t v = 0; v < kept_points.size(); ++v)
  {
    if(used[v])
    {
      new_index[v] = kept;
      kept_points[kept++] = kept_points[v];
    }
  }
  report.isolated_points = kept_points.size() - kept;
  report.mesh_vertex_of_point.assign(points.size(), std::size_t(-1));
  for(std::size_t v = 0; v < points.size() && v < used.size(); ++v)
    if(used[v]) report.mesh_vertex_of_point[v] = new_index[v];
  kept_points.resize(kept);
  for(std::array<std::size_t, 3>& tri : triangles)
    for(std::size_t& v : tri)
      v = new_index[v];

  // The checks above are those of PMP::is_polygon_soup_a_polygon_mesh() (manifold edges and
  // vertices, no repeated corner) in linear time; after a re-orientation, the same checks
  // confirm it (a soup the orienter could not fix is refused, not built).
  if(report.reoriented &&
     !internal::check_soup_topology(triangles, internal::Face_namer(&triangle_face, " after re-orienting faces")))
    throw Input_error("the mesh cannot be oriented consistently (it is not an orientable manifold surface)");

  CGAL::clear(mesh);
  if(report.polygons_triangulated > 0 || report.reoriented) twins.clear();
  internal::build_oriented_triangle_mesh(kept_points, triangles, twins, mesh);
  report.number_of_triangles = triangles.size();
  return report;
}



namespace internal {

// Parses a whole file held in memory and builds the checked mesh; `where` names the file.
template <class TriangleMesh>
Mesh_reading_report read_checked_triangle_mesh_from_buffer(const char* data, std::size_t size,
                                                           const std::string& format, const std::string& where,
                                                           TriangleMesh& mesh)
{
  typedef typename internal::Mesh_point<TriangleMesh>::type Point;
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  try
  {
    mesh_parsers::parse_mesh(data, size, format, points, polygons);
    return build_checked_triangle_mesh(points, polygons, mesh);
  }
  catch(const Input_error& e)
  {
    throw Input_error(where + ": " + e.what());
  }
}

} // namespace internal

/// Reads a triangle mesh from a mesh file as a polygon soup, checks it and builds a triangle mesh
/// with `build_checked_triangle_mesh()`.
///
/// The format is chosen from the extension (case-insensitive): `.off`, `.obj`,
/// `.ply` or `.stl`; the grammar accepted for each is described in mesh_file_parsers.h.
/// The file is read into memory in one piece, and may have at most `max_mesh_file_bytes`
/// bytes (2 GiB); every count in it is bounded by what its bytes can hold before anything
/// is allocated, so no file makes the reader crash, hang or exhaust memory.
/// Vertex indices in messages are the order of the vertices in
/// the file (0-based); for STL, which repeats the corners of every triangle,
/// identical points are merged by the reader and numbered in order of first
/// appearance. Face indices are the order of the polygons in the file. Errors in the
/// file's structure name the line (text formats) or the element (binary formats).
///
/// \tparam TriangleMesh a model of `MutableFaceGraph` with an internal
///         `CGAL::vertex_point_t` property map, e.g. `CGAL::Surface_mesh` or `CGAL::Polyhedron_3`
/// \param filename the file to read
/// \param mesh the output; cleared first, and left untouched if an error is thrown
/// \pre nothing: any defect of the file is reported by an exception
/// \throws svd_program::Input_error when the extension is not one of the
///         above, the file cannot be opened (missing, a directory, unreadable) or is too
///         large, cannot be parsed (e.g. `mesh file 'x.off': line 7: face 1 declares
///         2147483647 vertices but the file ends after 3`), or the soup fails the
///         checks of `build_checked_triangle_mesh()`; the message starts with
///         `mesh file 'FILE'` and holds printable ASCII only
/// \returns what was done to the soup (triangulation, re-orientation, isolated points)
template <class TriangleMesh>
Mesh_reading_report read_checked_triangle_mesh(const std::string& filename, TriangleMesh& mesh)
{
  const std::string where = "mesh file '" + printable_text(filename) + "'";

  const std::string ext = internal::lower_case_extension(filename);
  if(ext.empty())
    throw Input_error(where + ": no file extension to tell the format (expected .off, .obj, .ply or .stl)");
  if(ext != "off" && ext != "obj" && ext != "ply" && ext != "stl")
    throw Input_error(where + ": unknown extension '." + printable_text(ext, max_echoed_token_length) +
                      "' (expected .off, .obj, .ply or .stl)");
  std::string contents;
  read_whole_file(filename, where, max_mesh_file_bytes, contents);
  return internal::read_checked_triangle_mesh_from_buffer(contents.data(), contents.size(), ext, where, mesh);
}

/// Reads a triangle mesh from a mesh file held in memory: the same parsing, checks and
/// messages as `read_checked_triangle_mesh(filename, mesh)`, without touching the disk.
///
/// This is the entry point of the mesh readers' fuzzing harnesses: any `data` must give
/// either a mesh or an svd_program::Input_error (never a crash, a hang, or memory beyond a
/// small multiple of `size`), so a harness can call it on every input and catch
/// `Input_error` only; anything else it sees is a bug.
///
/// \tparam TriangleMesh as for `read_checked_triangle_mesh()`
/// \param data the bytes of the file (need not be null-terminated)
/// \param size the number of bytes; at most `max_mesh_file_bytes`
/// \param format `off`, `obj`, `ply` or `stl` (lower case)
/// \param mesh the output; cleared first, and left untouched if an error is thrown
/// \param name how messages name the data, as `mesh file 'NAME'`
/// \pre nothing
/// \throws svd_program::Input_error as `read_checked_triangle_mesh()`, and for an unknown format
/// \returns what was done to the soup
template <class TriangleMesh>
Mesh_reading_report read_checked_triangle_mesh_from_memory(const char* data, std::size_t size,
                                                           const std::string& format, TriangleMesh& mesh,
                                                           const std::string& name = "memory")
{
  const std::string where = "mesh file '" + printable_text(name) + "'";
  if(format != "off" && format != "obj" && format != "ply" && format != "stl")
    throw Input_error(where + ": unknown format " + quoted_token(format) + " (expected off, obj, ply or stl)");
  if(size > max_mesh_file_bytes)
    throw Input_error(where + ": the file is too large (" + std::to_string(size) + " bytes; the largest file read is " +
                      std::to_string(max_mesh_file_bytes) + " bytes)");
  return internal::read_checked_triangle_mesh_from_buffer(data, size, format, where, mesh);
}

/// Checks a triangle mesh already in memory, for the same defects as
/// `check_polygon_soup()` that a halfedge data structure can hold.
///
/// Vertices and faces are named by their position in the iteration order of
/// `vertices(tm)` and `faces(tm)` (0-based). The checks run in this order:
/// no face; a non-finite coordinate; for each face, not a triangle, then
/// collinear corners (exact predicate); a non-manifold vertex (its faces form
/// several umbrellas, or it is pinched between boundaries).
///
/// \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
/// \tparam VertexPointMap a model of `ReadablePropertyMap` from vertex descriptors to points
/// \param tm the mesh
/// \param vpm the positions of the vertices of `tm`
/// \pre `tm` is a valid halfedge graph (`CGAL::is_valid_polygon_mesh()`)
/// \throws svd_program::Input_error with a one-line message naming the element
template <class TriangleMesh, class VertexPointMap>
void check_triangle_mesh(const TriangleMesh& tm, VertexPointMap vpm)
{
  typedef boost::graph_traits<TriangleMesh> Traits;
  typedef typename Traits::vertex_descriptor vertex_descriptor;
  typedef typename Traits::halfedge_descriptor halfedge_descriptor;
  typedef typename Traits::face_descriptor face_descriptor;

  if(faces(tm).begin() == faces(tm).end())
    throw Input_error("the mesh is empty (no faces)");

  typedef CGAL::dynamic_vertex_property_t<std::size_t> Index_tag;
  typename boost::property_map<TriangleMesh, Index_tag>::const_type position = get(Index_tag(), tm);
  std::size_t i = 0;
  for(vertex_descriptor v : vertices(tm))
  {
    double bad = 0;
    if(!internal::is_finite_point(get(vpm, v), bad))
      throw Input_error("vertex " + std::to_string(i) + " has a non-finite coordinate (" +
                        internal::non_finite_name(bad) + ")");
    put(position, v, i++);
  }

  i = 0;
  for(face_descriptor f : faces(tm))
  {
    std::vector<internal::Checking_kernel::Point_3> corners;
    for(vertex_descriptor v : CGAL::vertices_around_face(halfedge(f, tm), tm))
      corners.push_back(internal::to_checking_point(get(vpm, v)));
    if(corners.size() != 3)
      throw Input_error("face " + std::to_string(i) + " is not a triangle (it has " +
                        std::to_string(corners.size()) + " vertices)");
    if(CGAL::collinear(corners[0], corners[1], corners[2]))
      throw Input_error("face " + std::to_string(i) + " has zero area");
    ++i;
  }

  std::vector<halfedge_descriptor> umbrellas;
  CGAL::Polygon_mesh_processing::non_manifold_vertices(tm, std::back_inserter(umbrellas));
  if(!umbrellas.empty())
  {
    // Report the first one in iteration order, whatever order the search used.
    std::vector<std::size_t> where;
    for(halfedge_descriptor h : umbrellas)
      where.push_back(get(position, target(h, tm)));
    std::sort(where.begin(), where.end());
    const std::size_t v = where.front();
    const std::size_t count =
        static_cast<std::size_t>(std::upper_bound(where.begin(), where.end(), v) - where.begin());
    if(count > 1)
      throw Input_error("vertex " + std::to_string(v) + " is non-manifold: its faces form " +
                        std::to_string(count) + " separate fans");
    throw Input_error("vertex " + std::to_string(v) +
                      " is non-manifold: its faces do not form a single fan (the surface is pinched there)");
  }
}

/// Same as `check_triangle_mesh(tm, vpm)` with the internal vertex point map of `tm`.
/// \param tm the mesh
/// \pre `tm` is a valid halfedge graph
/// \throws svd_program::Input_error as `check_triangle_mesh(tm, vpm)`
template <class TriangleMesh>
void check_triangle_mesh(const TriangleMesh& tm)
{
  check_triangle_mesh(tm, get(CGAL::vertex_point, tm));
}

} // namespace svd_program

#endif // SVD_PROGRAM_READ_CHECKED_MESH_H
