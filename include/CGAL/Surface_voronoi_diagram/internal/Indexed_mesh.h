// Copyright (c) 2026 The Surface_voronoi_diagram authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A compact, index-based copy of a triangle mesh's connectivity and geometry. Every
// stage of the pipeline works on it, so that propagation and cutting run on flat arrays
// whatever the user's FaceGraph is (Surface_mesh, Polyhedron_3, ...).

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_INDEXED_MESH_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_INDEXED_MESH_H

#include <CGAL/Surface_voronoi_diagram/exceptions.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/Dynamic_property_map.h>

#include <boost/graph/graph_traits.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

template <class TriangleMesh>
struct Indexed_mesh
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::face_descriptor face_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;

  static constexpr std::size_t none = std::size_t(-1);

  std::vector<vertex_descriptor> vertex_handles;                 // index -> descriptor
  std::vector<face_descriptor> face_handles;
  std::vector<std::array<double, 3> > points;
  std::vector<std::array<std::size_t, 3> > triangles;            // corners, counter-clockwise
  // Local edge k of a face joins corners k and k+1; its neighbour across, or `none` on a border.
  std::vector<std::array<std::size_t, 3> > neighbors;
  std::vector<std::array<std::size_t, 3> > edges;                // global edge index of local edge k
  std::vector<std::array<std::size_t, 2> > edge_vertices;        // sorted vertex indices
  std::vector<double> face_areas;
  std::vector<std::size_t> face_component;                       // connected component of each face
  std::size_t number_of_components = 0;
  double total_area = 0;
  double bbox_diagonal = 0;

  typedef typename boost::property_map<TriangleMesh, CGAL::dynamic_vertex_property_t<std::size_t> >::const_type Vertex_index_map;
  typedef typename boost::property_map<TriangleMesh, CGAL::dynamic_face_property_t<std::size_t> >::const_type Face_index_map;
  Vertex_index_map vertex_index;
  Face_index_map face_index;

  Indexed_mesh() {}

  template <class VertexPointMap>
  Indexed_mesh(const TriangleMesh& tm, VertexPointMap vpm)
  {
    build(tm, vpm);
  }

  template <class VertexPointMap>
  void build(const TriangleMesh& tm, VertexPointMap vpm)
  {
    vertex_index = get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm);
    face_index = get(CGAL::dynamic_face_property_t<std::size_t>(), tm);
    for(vertex_descriptor v : vertices(tm))
    {
      put(vertex_index, v, vertex_handles.size());
      vertex_handles.push_back(v);
      const auto& p = get(vpm, v);
      const std::array<double, 3> q = { CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()) };
      for(double c : q)
        if(!std::isfinite(c))
          throw Input_error("vertex " + std::to_string(points.size()) + " has a non-finite coordinate");
      points.push_back(q);
    }
    if(faces(tm).empty())
      throw Input_error("the mesh is empty (no faces)");
    for(face_descriptor f : faces(tm))
    {
      put(face_index, f, face_handles.size());
      face_handles.push_back(f);
    }

    const std::size_t nf = face_handles.size();
    triangles.resize(nf);
    neighbors.assign(nf, std::array<std::size_t, 3>{ none, none, none });
    edges.resize(nf);
    face_areas.resize(nf);
    std::vector<std::size_t> vertex_degree(points.size(), 0);
    for(std::size_t fi = 0; fi < nf; ++fi)
    {
      const halfedge_descriptor h0 = halfedge(face_handles[fi], tm);
      halfedge_descriptor h = h0;
      for(int k = 0; k < 3; ++k)
      {
        // corner k = source of local edge k
        triangles[fi][k] = get(vertex_index, source(h, tm));
        h = next(h, tm);
      }
      if(h != h0)
        throw Input_error("face " + std::to_string(fi) + " is not a triangle");
      for(int k = 0; k < 3; ++k)
      {
        const halfedge_descriptor opp = opposite(h, tm);
        if(!is_border(opp, tm))
          neighbors[fi][k] = get(face_index, face(opp, tm));
        h = next(h, tm);
        ++vertex_degree[triangles[fi][k]];
      }
      face_areas[fi] = triangle_area(fi);
      if(!(face_areas[fi] > 0))
        throw Input_error("face " + std::to_string(fi) + " has zero area");
      total_area += face_areas[fi];
    }
    for(std::size_t v = 0; v < points.size(); ++v)
      if(vertex_degree[v] == 0)
        throw Input_error("vertex " + std::to_string(v) + " belongs to no face");

    // Global edge ids: the face with the smaller index names the edge first.
    for(std::size_t fi = 0; fi < nf; ++fi)
      for(int k = 0; k < 3; ++k)
      {
        const std::size_t g = neighbors[fi][k];
        if(g != none && g < fi)
        {
          const std::size_t a = triangles[fi][k], b = triangles[fi][(k + 1) % 3];
          int kg = -1;
          for(int l = 0; l < 3; ++l)
            if(triangles[g][l] == b && triangles[g][(l + 1) % 3] == a && neighbors[g][l] == fi)
              kg = l;
          if(kg < 0)
            throw Input_error("faces " + std::to_string(g) + " and " + std::to_string(fi) + " are inconsistently connected");
          edges[fi][k] = edges[g][kg];
        }
        else
        {
          edges[fi][k] = edge_vertices.size();
          const std::size_t a = triangles[fi][k], b = triangles[fi][(k + 1) % 3];
          edge_vertices.push_back({ (std::min)(a, b), (std::max)(a, b) });
        }
      }

    compute_components();
    compute_bbox();
  }

  std::size_t number_of_vertices() const { return points.size(); }
  std::size_t number_of_faces() const { return triangles.size(); }
  std::size_t number_of_edges() const { return edge_vertices.size(); }

  double triangle_area(std::size_t f) const
  {
    const std::array<double, 3>& p = points[triangles[f][0]];
    const std::array<double, 3>& q = points[triangles[f][1]];
    const std::array<double, 3>& r = points[triangles[f][2]];
    const double a[3] = { q[0] - p[0], q[1] - p[1], q[2] - p[2] };
    const double b[3] = { r[0] - p[0], r[1] - p[1], r[2] - p[2] };
    const double c[3] = { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
    return 0.5 * std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
  }

  std::array<double, 3> point_at(std::size_t f, const std::array<double, 3>& b) const
  {
    std::array<double, 3> r = { 0, 0, 0 };
    for(int k = 0; k < 3; ++k)
      for(int c = 0; c < 3; ++c)
        r[c] += b[k] * points[triangles[f][k]][c];
    return r;
  }

private:
  void compute_components()
  {
    const std::size_t nf = triangles.size();
    face_component.assign(nf, none);
    number_of_components = 0;
    // Components are connected through edges and through vertices (faces sharing only a
    // vertex are one surface for the Laplacian).
    std::vector<std::size_t> parent(points.size());
    std::iota(parent.begin(), parent.end(), std::size_t(0));
    auto find = [&](std::size_t x) {
      while(parent[x] != x) { parent[x] = parent[parent[x]]; x = parent[x]; }
      return x;
    };
    for(const auto& t : triangles)
      for(int k = 1; k < 3; ++k)
      {
        const std::size_t a = find(t[0]), b = find(t[k]);
        if(a != b) parent[(std::max)(a, b)] = (std::min)(a, b);
      }
    std::vector<std::size_t> root_id(points.size(), none);
    for(std::size_t f = 0; f < nf; ++f)
    {
      const std::size_t r = find(triangles[f][0]);
      if(root_id[r] == none) root_id[r] = number_of_components++;
      face_component[f] = root_id[r];
    }
  }

  void compute_bbox()
  {
    std::array<double, 3> lo = points.front(), hi = points.front();
    for(const auto& p : points)
      for(int c = 0; c < 3; ++c) { lo[c] = (std::min)(lo[c], p[c]); hi[c] = (std::max)(hi[c], p[c]); }
    double s = 0;
    for(int c = 0; c < 3; ++c) s += (hi[c] - lo[c]) * (hi[c] - lo[c]);
    bbox_diagonal = std::sqrt(s);
  }
};

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif
