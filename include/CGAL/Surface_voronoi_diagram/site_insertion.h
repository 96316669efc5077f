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
// Site insertion, the paper's mode (\cgalCite{cgal:bddvd}, section 3.1): every site becomes a vertex of a working
// copy of the mesh, and each face holding sites is re-triangulated (Delaunay inside the
// face, the face's edges kept), so that the embedding is computed on the augmented mesh.
// A site on an edge splits the edge (no perturbation is needed); a site at a vertex is
// that vertex. The input mesh is never modified.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_SITE_INSERTION_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_SITE_INSERTION_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/exceptions.h>
#include <CGAL/Surface_voronoi_diagram/internal/Double_kernel.h>
#include <CGAL/Surface_voronoi_diagram/internal/working_copy.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <array>
#include <cmath>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {

/// \ingroup PkgSurfaceVoronoiDiagramSites
/// The augmented mesh of `insert_sites()`.
/// \tparam TriangleMesh the type of the input mesh
/// \tparam Point_3 the point type of the input mesh's vertex point map
template <class TriangleMesh, class Point_3>
struct Site_insertion_result
{
  /// the type of the augmented mesh
  typedef CGAL::Surface_mesh<Point_3> Mesh;
  /// the augmented mesh (sites are vertices)
  Mesh mesh;
  /// the vertex of `mesh` at each site, in site order
  std::vector<typename Mesh::Vertex_index> site_vertices;
  /// for each face of `mesh`, the input face that contains it
  typename Mesh::template Property_map<typename Mesh::Face_index,
                                       typename boost::graph_traits<TriangleMesh>::face_descriptor> input_face;
  /// \name Counts
  /// @{

  /// the numbers of faces split, of edges split and of Delaunay flips done (one declaration:
  /// the three members share this description)
  std::size_t faces_split = 0, edges_split = 0, flips = 0;
  /// @}
};

/// \ingroup PkgSurfaceVoronoiDiagramSites
/// Inserts the sites (face locations of `tm`) as vertices of a copy of `tm`, the paper's mode
/// \cgalCite{cgal:bddvd} (section 3.1): each face holding sites is re-triangulated (Delaunay
/// inside the face, its edges kept), a site on an edge splits the edge, and a site at a vertex
/// is that vertex. A metric built on the augmented mesh then has each site at a vertex.
/// \tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
/// \tparam LocationRange a range of `Polygon_mesh_processing::Face_location<TriangleMesh, double>`
/// \param tm the mesh; it is copied, never modified
/// \param sites the sites, face locations of `tm`
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
///     \cgalParamType{a model of `ReadablePropertyMap`}
///     \cgalParamDefault{`get_const_property_map(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the augmented mesh, the vertex of each site and the input face of each face
/// \throws Input_error if the face of a site is not a face of `tm`
template <class TriangleMesh, class LocationRange, class NamedParameters = CGAL::parameters::Default_named_parameters>
Site_insertion_result<TriangleMesh,
                      typename boost::property_traits<typename GetVertexPointMap<TriangleMesh, NamedParameters>::const_type>::value_type>
insert_sites(const TriangleMesh& tm, const LocationRange& sites,
             const NamedParameters& np = CGAL::parameters::default_values())
{
  typedef typename GetVertexPointMap<TriangleMesh, NamedParameters>::const_type VPM;
  typedef typename boost::property_traits<VPM>::value_type Point_3;
  typedef Site_insertion_result<TriangleMesh, Point_3> Result;
  typedef typename Result::Mesh Mesh;
  typedef typename Mesh::Vertex_index V;
  typedef typename Mesh::Face_index F;
  typedef typename Mesh::Halfedge_index H;
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor Input_face;
  typedef internal::Exact_predicates_kernel EK;

  VPM vpm = CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                                               get_const_property_map(CGAL::vertex_point, tm));
  Result r;
  Mesh& m = r.mesh;
  std::vector<std::pair<Input_face, F> > f2f;
  r.input_face = internal::copy_with_input_faces(tm, vpm, m, f2f);
  std::vector<std::vector<F> > sub_faces(f2f.size());           // by index in f2f order
  std::unordered_map<Input_face, std::size_t, boost::hash<Input_face> > input_index;
  for(std::size_t k = 0; k < f2f.size(); ++k)
  {
    input_index[f2f[k].first] = k;
    sub_faces[k].push_back(f2f[k].second);
  }
  auto origin_of = [&](F f) { return input_index.at(get(r.input_face, f)); };

  // Each input face has a 2D frame in its plane; all its sub-faces live there.
  auto frame_of = [&](std::size_t k) {
    const F f = f2f[k].second;
    const H h = halfedge(f, m);
    const internal::Point_d a = internal::to_point_d(m.point(source(h, m)));
    const internal::Vector_d u = internal::to_point_d(m.point(target(h, m))) - a;
    const internal::Vector_d v = internal::to_point_d(m.point(target(next(h, m), m))) - a;
    const internal::Vector_d x = u / std::sqrt(u.squared_length());
    internal::Vector_d normal = CGAL::cross_product(x, v);
    normal = normal / std::sqrt(normal.squared_length());
    return std::make_pair(a, std::make_pair(x, CGAL::cross_product(normal, x)));   // origin, in-plane axes
  };
  typedef decltype(frame_of(0)) Frame;
  auto to_2d = [&](const Frame& fr, const Point_3& p) {
    const internal::Vector_d d = internal::to_point_d(p) - fr.first;
    return EK::Point_2(d * fr.second.first, d * fr.second.second);
  };

  // Lawson flips around a new vertex; edges between two input faces (and borders) are kept.
  auto restore_delaunay = [&](V v) {
    std::vector<H> stack;
    for(H h : CGAL::halfedges_around_target(v, m))
      if(!is_border(h, m)) stack.push_back(next(next(h, m), m));   // the edge opposite v
    std::size_t guard = 0;
    while(!stack.empty() && guard++ < 100000)
    {
      const H h = stack.back();
      stack.pop_back();
      const H o = opposite(h, m);
      if(is_border(o, m) || is_border(h, m)) continue;
      if(get(r.input_face, face(h, m)) != get(r.input_face, face(o, m))) continue;
      if(target(next(h, m), m) != v) continue;   // h no longer faces v
      const std::size_t k = origin_of(face(h, m));
      const auto fr = frame_of(k);
      const EK::Point_2 a = to_2d(fr, m.point(source(h, m))), b = to_2d(fr, m.point(target(h, m)));
      const EK::Point_2 pv = to_2d(fr, m.point(v)), c = to_2d(fr, m.point(target(next(o, m), m)));
      // (a, b, v) is counter-clockwise in the frame; flip when c is inside its circle and
      // the quad is strictly convex
      if(CGAL::side_of_oriented_circle(a, b, pv, c) != CGAL::ON_POSITIVE_SIDE) continue;
      const CGAL::Orientation side_a = CGAL::orientation(pv, c, a), side_b = CGAL::orientation(pv, c, b);
      if(side_a == side_b || side_a == CGAL::COLLINEAR || side_b == CGAL::COLLINEAR) continue;
      CGAL::Euler::flip_edge(h, m);
      ++r.flips;
      // after the flip the link of v changed: check its edges again
      for(H g : CGAL::halfedges_around_target(v, m))
        if(!is_border(g, m)) stack.push_back(next(next(g, m), m));
    }
  };

  std::size_t index = 0;
  for(const auto& loc : sites)
  {
    const Input_face fin = loc.first;
    auto it = input_index.find(fin);
    if(it == input_index.end())
      throw Input_error("site " + std::to_string(index) + " is not on a face of the mesh");
    const std::size_t k = it->second;
    Point_3 p = CGAL::Polygon_mesh_processing::construct_point(loc, tm, CGAL::parameters::vertex_point_map(vpm));

    // the sub-face that contains the site best (largest smallest barycentric coordinate)
    const auto [best, best_b] = internal::innermost_face(sub_faces[k], m, m.points(), internal::to_point_d(p));
    const H h0 = halfedge(best, m);
    const std::array<H, 3> best_h = {{ h0, next(h0, m), next(next(h0, m), m) }};
    const double eps = 1e-10;
    int small = 0;
    for(double x : best_b) small += (x <= eps);
    V nv;
    if(small >= 2)
    {
      int j = 0;
      while(best_b[j] <= eps) ++j;
      nv = source(best_h[j], m);   // the site is (numerically) at this vertex
    }
    else if(small == 1)
    {
      int j = 0;
      while(best_b[j] > eps) ++j;
      // the edge opposite corner j runs from corner j+1 to corner j+2: halfedge best_h[j+1]
      const H h = best_h[(j + 1) % 3];
      const H o = opposite(h, m);
      const bool other_side = !is_border(o, m);
      const F f1 = face(h, m);
      const F f2 = other_side ? face(o, m) : F();
      const H hnew = CGAL::Euler::split_edge(h, m);
      nv = target(hnew, m);
      m.point(nv) = p;
      const H n1 = CGAL::Euler::split_face(hnew, next(h, m), m);
      put(r.input_face, face(opposite(n1, m), m), get(r.input_face, f1));
      sub_faces[origin_of(f1)].push_back(face(opposite(n1, m), m));
      if(other_side)
      {
        const H n2 = CGAL::Euler::split_face(opposite(h, m), next(opposite(hnew, m), m), m);
        put(r.input_face, face(opposite(n2, m), m), get(r.input_face, f2));
        sub_faces[origin_of(f2)].push_back(face(opposite(n2, m), m));
      }
      ++r.edges_split;
      restore_delaunay(nv);
    }
    else
    {
      const H hc = CGAL::Euler::add_center_vertex(halfedge(best, m), m);
      nv = target(hc, m);
      m.point(nv) = p;
      for(H g : CGAL::halfedges_around_target(nv, m))
      {
        const F f = face(g, m);
        if(get(r.input_face, f) == boost::graph_traits<TriangleMesh>::null_face())
        {
          put(r.input_face, f, fin);
          sub_faces[k].push_back(f);
        }
      }
      ++r.faces_split;
      restore_delaunay(nv);
    }
    r.site_vertices.push_back(nv);
    ++index;
  }
  return r;
}

} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_SITE_INSERTION_H
