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
// Whether the dual triangulation of a diagram is a valid mesh of the surface, and why not:
// the triangulation's own defects, its topology against the input's, and the cells' defects
// that cause them (the closed-ball property: each cell a closed disk, two cells sharing one
// arc or none, three cells one Voronoi vertex or none).

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_DUAL_VALIDITY_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_DUAL_VALIDITY_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/internal/Dual_cell_defects.h>
#include <CGAL/Surface_voronoi_diagram/internal/Diagram_data.h>
#include <CGAL/Surface_voronoi_diagram/internal/Mesh_topology.h>

#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/assertions.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {

/// \ingroup PkgSurfaceVoronoiDiagramOutputs
/// What `validate_dual_triangulation()` found: whether a dual triangulation is a valid mesh of
/// the surface, what is wrong with it, and which cells cause it.
///
/// The dual is a valid mesh when it is an oriented 2-manifold (closed when the input is
/// closed, with as many boundary loops as the input otherwise), with as many components and
/// the same genus as the input, uses every site, and has no degenerate or flipped triangle.
/// Self-intersections are counted, not held against it.
///
/// The dual of a diagram is such a mesh when the cells have the closed-ball property
/// (Edelsbrunner and Shah): every cell a closed disk, any two cells sharing one arc of their
/// boundaries or none, any three meeting at one Voronoi vertex or none. The `cell` members
/// list where it fails: each is a cause of the triangulation's defects.
struct Dual_validity
{
  /// \name The cells
  /// @{
  /// sites whose cell is not a closed disk: in several pieces, around a handle or a limb
  /// (a ring), a whole closed component, or touching itself at a point
  std::vector<std::size_t> cells_not_disks;
  /// pairs of sites (the lower first) whose cells share several arcs: their dual edge is
  /// made more than once
  std::vector<std::pair<std::size_t, std::size_t> > pairs_in_several_arcs;
  /// triples of sites (increasing) whose cells meet at several Voronoi vertices: their dual
  /// triangle is made more than once
  std::vector<std::array<std::size_t, 3> > triples_at_several_vertices;
  /// Voronoi vertices where more than three cells meet, each split into a fan of triangles
  std::size_t vertices_of_more_than_three_cells = 0;
  /// @}

  /// \name The triangulation
  /// @{
  /// the number of triangles
  std::size_t triangles = 0;
  /// sites that are a corner of no triangle
  std::size_t unused_sites = 0;
  /// edges of more than two triangles, or of two that run it the same way
  std::size_t non_manifold_edges = 0;
  /// sites whose triangles do not form one fan (their link is not one path or one cycle)
  std::size_t non_manifold_vertices = 0;
  /// triangles with a repeated site, or with collinear sites (zero area)
  std::size_t degenerate_triangles = 0;
  /// triangles facing against the surface: against the normal of every face around the
  /// Voronoi vertex the triangle is dual to (so that one across a crease or a thin rim, which
  /// faces along neither side, is not taken for flipped) and against the face of one of its
  /// sites at least (a triangle facing along the surface at all its corners lies on it, even
  /// when its Voronoi vertex is past a bend, as an obtuse triangle's is); for a triangle no
  /// Voronoi vertex makes, against the sum of the normals of its sites' faces
  std::size_t flipped_triangles = 0;
  /// the indices (in the range checked) of the flipped triangles
  std::vector<std::size_t> flipped_triangle_indices;
  /// whether the triangles form an oriented 2-manifold, possibly with border
  /// (`CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh()`)
  bool is_polygon_mesh = false;
  /// pairs of triangles that intersect other than at a shared edge or corner (counted when
  /// `is_polygon_mesh`)
  std::size_t self_intersections = 0;
  /// @}

  /// \name Topology, of the triangulation (when `is_polygon_mesh`) and of the input
  /// @{
  std::size_t components = 0;       ///< connected components of the triangulation
  std::size_t boundary_loops = 0;   ///< its boundary loops
  long genus = -1;                  ///< its genus, summed over its components
  std::size_t input_components = 0;     ///< connected components of the input mesh
  std::size_t input_boundary_loops = 0; ///< its boundary loops
  long input_genus = 0;                 ///< its genus, summed over its components
  /// @}

  /// whether the dual is a valid mesh of the surface (see above)
  bool is_valid() const
  {
    return triangles > 0 && is_polygon_mesh && unused_sites == 0 && degenerate_triangles == 0 && flipped_triangles == 0
           && components == input_components && boundary_loops == input_boundary_loops && genus == input_genus;
  }

  /// empty if the dual is valid; otherwise what is wrong with it, then its cause in the cells
  std::string reason() const
  {
    if(is_valid()) return std::string();
    std::string what, cause;
    auto append = [](std::string& to, const std::string& text) { to += (to.empty() ? "" : ", ") + text; };
    auto add = [&](std::string& to, std::size_t n, const char* one, const char* many) {
      if(n > 0) append(to, std::to_string(n) + " " + (n == 1 ? one : many));
    };
    if(triangles == 0) what = "no triangle";
    add(what, non_manifold_edges, "non-manifold edge", "non-manifold edges");
    add(what, non_manifold_vertices, "non-manifold vertex", "non-manifold vertices");
    if(what.empty() && !is_polygon_mesh && triangles > 0) what = "not an oriented manifold";
    add(what, degenerate_triangles, "degenerate triangle", "degenerate triangles");
    add(what, flipped_triangles, "flipped triangle", "flipped triangles");
    add(what, unused_sites, "site in no triangle", "sites in no triangle");
    if(is_polygon_mesh && components != input_components)
      append(what, std::to_string(components) + " components (the input has " + std::to_string(input_components) + ")");
    if(is_polygon_mesh && genus != input_genus)
      append(what, "genus " + std::to_string(genus) + " (the input's is " + std::to_string(input_genus) + ")");
    if(is_polygon_mesh && boundary_loops != input_boundary_loops)
      append(what, std::to_string(boundary_loops) + " boundary loops (the input has " + std::to_string(input_boundary_loops) + ")");
    add(cause, cells_not_disks.size(), "cell not a disk", "cells not disks");
    add(cause, pairs_in_several_arcs.size(), "pair of cells sharing several arcs", "pairs of cells sharing several arcs");
    add(cause, triples_at_several_vertices.size(), "triple of cells meeting at several vertices", "triples of cells meeting at several vertices");
    return cause.empty() ? what : what + " (" + cause + ")";
  }
};

/// \ingroup PkgSurfaceVoronoiDiagramOutputs
/// Checks a dual triangulation of `diagram` (as `dual_triangulation()` writes it: the sites
/// as points, in site order, and triangles of site indices) and finds the cells' defects
/// that make it fail; see `Dual_validity`.
/// \tparam Diagram a `CGAL::Surface_voronoi_diagram`
/// \tparam PointRange a random access range of `Diagram::Point_3`
/// \tparam TriangleRange a range of `std::array<std::size_t, 3>`
/// \pre `!diagram.is_cancelled()`, `points.size() == diagram.number_of_sites()`, and every
///      index in `triangles` is less than `points.size()`
template <class Diagram, class PointRange, class TriangleRange>
Dual_validity validate_dual_triangulation(const Diagram& diagram, const PointRange& points, const TriangleRange& triangles)
{
  typedef typename Diagram::Geom_traits Geom_traits;
  typedef typename Geom_traits::Point_3 Point_3;
  CGAL_precondition_msg(!diagram.is_cancelled(), "the diagram was cancelled: it has no cells");
  CGAL_precondition(points.size() == diagram.number_of_sites());
  const auto& data = internal::Diagram_access::data(diagram);
  const std::size_t n = points.size();

  Dual_validity r;
  std::map<std::array<std::size_t, 3>, std::vector<std::array<double, 3> > > surface_normals;
  internal::find_dual_cell_defects(diagram, r.cells_not_disks, r.pairs_in_several_arcs, r.triples_at_several_vertices,
                                   r.vertices_of_more_than_three_cells, surface_normals);

  // the triangles one by one, their edges, and the sites' links
  std::vector<std::array<std::size_t, 3> > soup(triangles.begin(), triangles.end());
  r.triangles = soup.size();
  std::vector<std::uint8_t> used(n, 0);
  // each edge (lower site first): the triangles running it that way, and the other way
  std::map<std::pair<std::size_t, std::size_t>, std::pair<std::size_t, std::size_t> > edge_uses;
  const Geom_traits traits = diagram.geom_traits();
  for(std::size_t index = 0; index < soup.size(); ++index)
  {
    const std::array<std::size_t, 3>& t = soup[index];
    for(std::size_t v : t) CGAL_precondition(v < n);
    for(std::size_t v : t) used[v] = 1;
    if(t[0] == t[1] || t[1] == t[2] || t[0] == t[2] || traits.collinear_3_object()(points[t[0]], points[t[1]], points[t[2]]))
    {
      ++r.degenerate_triangles;
      continue;
    }
    for(int k = 0; k < 3; ++k)
    {
      const std::size_t a = t[k], b = t[(k + 1) % 3];
      auto& uses = edge_uses[std::make_pair((std::min)(a, b), (std::max)(a, b))];
      ++(a < b ? uses.first : uses.second);
    }
    // against the surface at the Voronoi vertex it is dual to, or else at its three sites
    const auto normal = traits.construct_cross_product_vector_3_object()(
        traits.construct_vector_3_object()(points[t[0]], points[t[1]]), traits.construct_vector_3_object()(points[t[0]], points[t[2]]));
    std::array<std::size_t, 3> key = t;
    std::sort(key.begin(), key.end());
    const double nx = CGAL::to_double(normal.x()), ny = CGAL::to_double(normal.y()), nz = CGAL::to_double(normal.z());
    auto against = [&](const std::array<double, 3>& up) { return nx * up[0] + ny * up[1] + nz * up[2] < 0; };
    const auto at_vertex = surface_normals.find(key);
    const bool flipped = (at_vertex != surface_normals.end() && !at_vertex->second.empty())
        ? std::all_of(at_vertex->second.begin(), at_vertex->second.end(), against)
          && std::any_of(t.begin(), t.end(), [&](std::size_t s) { return against(internal::site_face_normal(*data.mesh, data.sites[s])); })
        : against(internal::sum_of_site_face_normals(*data.mesh, data.sites, t));
    if(flipped) r.flipped_triangle_indices.push_back(index);
  }
  r.flipped_triangles = r.flipped_triangle_indices.size();
  r.unused_sites = std::size_t(std::count(used.begin(), used.end(), std::uint8_t(0)));
  for(const auto& e : edge_uses)
    r.non_manifold_edges += (e.second.first > 1 || e.second.second > 1);
  r.non_manifold_vertices = internal::number_of_non_manifold_soup_vertices(n, soup);

  // topology of the input
  const internal::Mesh_topology input = internal::mesh_topology(diagram.triangle_mesh());
  r.input_components = input.components;
  r.input_boundary_loops = input.boundary_loops;
  r.input_genus = input.genus;

  // topology of the triangulation, when it is a mesh
  r.is_polygon_mesh = !soup.empty() && CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(soup);
  if(r.is_polygon_mesh)
  {
    typedef CGAL::Surface_mesh<Point_3> Dual_mesh;
    Dual_mesh dual;
    std::vector<Point_3> copied(points.begin(), points.end());
    CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(copied, soup, dual);
    const internal::Mesh_topology topology = internal::mesh_topology(dual);
    r.components = topology.components;
    r.boundary_loops = topology.boundary_loops;
    r.genus = topology.genus;
    std::vector<std::pair<typename Dual_mesh::Face_index, typename Dual_mesh::Face_index> > pairs;
    CGAL::Polygon_mesh_processing::self_intersections(dual, std::back_inserter(pairs),
                                                      CGAL::parameters::geom_traits(traits));
    r.self_intersections = pairs.size();
  }
  return r;
}

} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_DUAL_VALIDITY_H
