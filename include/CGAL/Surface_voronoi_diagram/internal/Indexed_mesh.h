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
// A compact, index-based copy of a triangle mesh's connectivity and geometry (in doubles).
// Every stage works on it, so that propagation and cutting run on flat arrays whatever the
// user's FaceGraph is. It is built once and shared (std::shared_ptr) by the diagram and the
// metric built on the same mesh.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_INDEXED_MESH_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_INDEXED_MESH_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/exceptions.h>
#include <CGAL/Surface_voronoi_diagram/internal/Disjoint_sets.h>
#include <CGAL/Surface_voronoi_diagram/internal/Double_kernel.h>
#include <CGAL/Surface_voronoi_diagram/internal/parallel.h>

#include <CGAL/assertions.h>
#include <CGAL/Bbox_3.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/Dynamic_property_map.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

// Whether descriptors of a graph are numbered like indices (`Surface_mesh`'s): converted to
// and from an integer. Whether the numbering is the index order is checked at run time.
template <class Descriptor, class = void>
struct Is_numbered_descriptor : std::false_type {};
template <class Descriptor>
struct Is_numbered_descriptor<Descriptor, decltype(void(static_cast<std::size_t>(std::declval<const Descriptor&>())),
                                                    void(Descriptor(std::uint32_t(0))))> : std::true_type {};

// Index -> descriptor and descriptor -> index of one kind of element. Where the descriptors
// are the indices themselves (a `Surface_mesh` without removed elements) nothing is stored,
// which spares 8 bytes a vertex and a face on the meshes the package is built for.
template <class Descriptor, class DynamicIndexMap>
class Element_numbering
{
public:
  typedef std::uint32_t Index;

  /// index -> descriptor
  Descriptor operator[](std::size_t i) const { return m_index.identity ? make(i, Is_numbered_descriptor<Descriptor>()) : m_handles[i]; }
  std::size_t size() const { return m_size; }

  /// the descriptor -> index property map (a handle: copies read the same numbering)
  struct Index_map
  {
    typedef Descriptor key_type;
    typedef Index value_type;
    typedef Index reference;
    typedef boost::readable_property_map_tag category;

    bool identity = false;
    std::optional<DynamicIndexMap> map;
    friend Index get(const Index_map& m, const Descriptor& d)
    {
      return m.identity ? Index(number(d, Is_numbered_descriptor<Descriptor>())) : get(*m.map, d);
    }
  };
  const Index_map& index_map() const { return m_index; }

  template <class Range, class Graph, class DynamicTag>
  void build(const Range& elements, const Graph& g, DynamicTag tag)
  {
    m_size = 0;
    bool identity = Is_numbered_descriptor<Descriptor>::value;
    for(const Descriptor& d : elements)
    {
      identity = identity && number(d, Is_numbered_descriptor<Descriptor>()) == m_size;
      ++m_size;
    }
    m_handles.clear();
    m_index = Index_map();
    m_index.identity = identity;
    if(identity) return;
    m_index.map = get(tag, g);
    m_handles.reserve(m_size);
    for(const Descriptor& d : elements)
    {
      put(*m_index.map, d, Index(m_handles.size()));
      m_handles.push_back(d);
    }
  }

  bool is_identity() const { return m_index.identity; }

  static Descriptor make(std::size_t i, std::true_type) { return Descriptor(static_cast<std::uint32_t>(i)); }
  static Descriptor make(std::size_t, std::false_type) { CGAL_assertion(false); return Descriptor(); }
  static std::size_t number(const Descriptor& d, std::true_type) { return static_cast<std::size_t>(d); }
  static std::size_t number(const Descriptor&, std::false_type) { return std::size_t(-1); }

private:
  std::size_t m_size = 0;
  std::vector<Descriptor> m_handles;
  Index_map m_index;
};

/// How far the checks of a diagram's input went on an indexed copy, which never changes once
/// built: the stages that share the copy (Lloyd's steps, the program's) check it once. A
/// copy of the copy keeps the level.
class Mesh_check_level
{
public:
  enum Level { NONE, WITHOUT_FANS, WITH_FANS };
  Mesh_check_level() {}
  Mesh_check_level(const Mesh_check_level& other) : m_level(other.m_level.load()) {}
  Mesh_check_level& operator=(const Mesh_check_level& other) { m_level = other.m_level.load(); return *this; }
  bool reached(Level level) const { return m_level.load() >= level; }
  void raise(Level level) const
  {
    int current = m_level.load();
    while(current < level && !m_level.compare_exchange_weak(current, level)) {}
  }

private:
  mutable std::atomic<int> m_level{ NONE };
};

template <class TriangleMesh>
struct Indexed_mesh
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::face_descriptor face_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;

  /// Vertex, face and edge indices: 32 bits, which halves the connectivity arrays of a
  /// million-face mesh (a mesh with 2^32 - 1 elements or more is rejected by `build()`).
  typedef std::uint32_t Index;
  static constexpr Index none = Index(-1);

  typedef typename boost::property_map<TriangleMesh, CGAL::dynamic_vertex_property_t<Index> >::const_type Dynamic_vertex_index_map;
  typedef typename boost::property_map<TriangleMesh, CGAL::dynamic_face_property_t<Index> >::const_type Dynamic_face_index_map;

  const TriangleMesh* source_mesh = nullptr;                     // the mesh this is a copy of
  Element_numbering<vertex_descriptor, Dynamic_vertex_index_map> vertex_handles;   // index -> descriptor
  Element_numbering<face_descriptor, Dynamic_face_index_map> face_handles;
  std::vector<Point_d> points;
  std::vector<std::array<Index, 3> > triangles;                  // corners, counter-clockwise
  // Local edge k of a face joins corners k and k+1; its neighbour across, or `none` on a border.
  std::vector<std::array<Index, 3> > neighbors;
  std::vector<std::array<Index, 3> > edges;                      // global edge index of local edge k
  std::vector<std::array<Index, 2> > edge_vertices;              // sorted vertex indices
  std::vector<double> face_areas;
  std::vector<Index> face_component;                             // connected component of each face
  std::size_t number_of_components = 0;
  double total_area = 0;
  double bbox_diagonal = 0;
  Mesh_check_level checked;                                      // see `throw_mesh_problems()`

  typedef typename Element_numbering<vertex_descriptor, Dynamic_vertex_index_map>::Index_map Vertex_index_map;
  typedef typename Element_numbering<face_descriptor, Dynamic_face_index_map>::Index_map Face_index_map;
  Vertex_index_map vertex_index;                                 // descriptor -> index
  Face_index_map face_index;

  Indexed_mesh() {}

  /// With `parallel`, the copy runs in concurrent chunks of faces where the mesh numbers its
  /// elements itself (a `Surface_mesh` without removed elements), with the sequential result.
  template <class VertexPointMap>
  Indexed_mesh(const TriangleMesh& tm, VertexPointMap vpm, bool parallel = false)
  {
    build(tm, vpm, parallel);
  }

  /// \pre `tm` is a valid polygon mesh with at least one face
  /// \throws Input_error if a face is not a triangle
  template <class VertexPointMap>
  void build(const TriangleMesh& tm, VertexPointMap vpm, bool parallel = false)
  {
    CGAL_precondition_msg(num_vertices(tm) < std::size_t(none) && num_faces(tm) < std::size_t(none) / 2,
                          "the mesh has too many elements for 32-bit indices");
    source_mesh = &tm;
    vertex_handles.build(vertices(tm), tm, CGAL::dynamic_vertex_property_t<Index>());
    face_handles.build(faces(tm), tm, CGAL::dynamic_face_property_t<Index>());
    vertex_index = vertex_handles.index_map();
    face_index = face_handles.index_map();
    // in parallel only where descriptors are indices: the maps of other meshes may not be
    // read from several threads at once
    parallel = parallel && vertex_handles.is_identity() && face_handles.is_identity();
    const std::size_t nv = vertex_handles.size(), nf = face_handles.size(), chunk = 8192;
    points.resize(nv);
    for_each_chunk(nv, chunk, parallel, [&](std::size_t begin, std::size_t end, std::size_t) {
      for(std::size_t v = begin; v < end; ++v) points[v] = to_point_d(get(vpm, vertex_handles[v]));
    });

    triangles.resize(nf);
    neighbors.resize(nf);
    edges.resize(nf);
    face_areas.resize(nf);
    // the first face of each chunk that is not a triangle (its first three corners are read,
    // harmlessly), reported once the threads are done
    std::vector<Index> not_a_triangle(number_of_chunks(nf, chunk), none);
    for_each_chunk(nf, chunk, parallel, [&](std::size_t begin, std::size_t end, std::size_t c) {
      for(std::size_t fi = begin; fi < end; ++fi)
      {
        halfedge_descriptor h = halfedge(face_handles[fi], tm);
        for(int k = 0; k < 3; ++k)
        {
          // corner k = source of local edge k
          triangles[fi][k] = get(vertex_index, source(h, tm));
          const halfedge_descriptor opp = opposite(h, tm);
          neighbors[fi][k] = is_border(opp, tm) ? none : get(face_index, face(opp, tm));
          h = next(h, tm);
        }
        if(h != halfedge(face_handles[fi], tm) && not_a_triangle[c] == none) not_a_triangle[c] = Index(fi);
        face_areas[fi] = triangle_area(fi);
      }
    });
    for(Index f : not_a_triangle)
      if(f != none) throw Input_error("face " + std::to_string(f) + " is not a triangle");
    for(std::size_t fi = 0; fi < nf; ++fi) total_area += face_areas[fi];   // in face order, whatever the threads

    // Global edge ids: the face with the smaller index names the edge first, in face order
    // (the new edges of each chunk counted first, so that every chunk knows its first id).
    const std::vector<std::size_t> chunk_first_edge = chunk_offsets(nf, chunk, parallel, [&](std::size_t begin, std::size_t end) {
      std::size_t new_edges = 0;
      for(std::size_t fi = begin; fi < end; ++fi)
        for(int k = 0; k < 3; ++k) new_edges += (neighbors[fi][k] == none || neighbors[fi][k] > fi);
      return new_edges;
    });
    edge_vertices.resize(chunk_first_edge.back());
    for_each_chunk(nf, chunk, parallel, [&](std::size_t begin, std::size_t end, std::size_t c) {
      std::size_t e = chunk_first_edge[c];
      for(std::size_t fi = begin; fi < end; ++fi)
        for(int k = 0; k < 3; ++k)
          if(neighbors[fi][k] == none || neighbors[fi][k] > fi)
          {
            edges[fi][k] = Index(e);
            const Index a = triangles[fi][k], b = triangles[fi][(k + 1) % 3];
            edge_vertices[e++] = { (std::min)(a, b), (std::max)(a, b) };
          }
    });
    // the edges named by the neighbour: all named now
    for_each_chunk(nf, chunk, parallel, [&](std::size_t begin, std::size_t end, std::size_t) {
      for(std::size_t fi = begin; fi < end; ++fi)
        for(int k = 0; k < 3; ++k)
        {
          const Index g = neighbors[fi][k];
          if(g == none || g > fi) continue;
          const Index a = triangles[fi][k], b = triangles[fi][(k + 1) % 3];
          int kg = -1;
          for(int l = 0; l < 3; ++l)
            if(triangles[g][l] == b && triangles[g][(l + 1) % 3] == a && neighbors[g][l] == fi)
              kg = l;
          CGAL_assertion(kg >= 0);   // a valid halfedge structure pairs the two faces
          edges[fi][k] = edges[g][kg];
        }
    });

    compute_components();
    compute_bbox();
  }

  std::size_t number_of_vertices() const { return points.size(); }
  std::size_t number_of_faces() const { return triangles.size(); }
  std::size_t number_of_edges() const { return edge_vertices.size(); }

  const Point_d& corner(std::size_t f, int k) const { return points[triangles[f][k]]; }

  double triangle_area(std::size_t f) const
  {
    return internal::triangle_area(corner(f, 0), corner(f, 1), corner(f, 2));
  }

  Point_d point_at(std::size_t f, const Barycentric& b) const
  {
    return internal::point_at(corner(f, 0), corner(f, 1), corner(f, 2), b);
  }

  Barycentric barycentric_coordinates(std::size_t f, const Point_d& x) const
  {
    return internal::barycentric_coordinates(corner(f, 0), corner(f, 1), corner(f, 2), x);
  }

  /// the local index (0, 1, 2) of vertex `v` in face `f`, or -1
  int corner_of(std::size_t f, std::size_t v) const
  {
    for(int k = 0; k < 3; ++k)
      if(triangles[f][k] == v) return k;
    return -1;
  }

private:
  void compute_components()
  {
    // Components are connected through edges and through vertices (faces sharing only a
    // vertex are one surface for the Laplacian).
    Disjoint_sets sets(points.size());
    for(const auto& t : triangles)
      for(int k = 1; k < 3; ++k) sets.unite(t[0], t[k]);
    const std::size_t nf = triangles.size();
    face_component.assign(nf, none);
    number_of_components = 0;
    std::vector<Index> root_id(points.size(), none);
    for(std::size_t f = 0; f < nf; ++f)
    {
      const std::size_t r = sets.find(triangles[f][0]);
      if(root_id[r] == none) root_id[r] = Index(number_of_components++);
      face_component[f] = root_id[r];
    }
  }

  void compute_bbox()
  {
    if(points.empty()) return;
    const Bbox_3 box = CGAL::bbox_3(points.begin(), points.end());
    bbox_diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin())
                              + CGAL::square(box.zmax() - box.zmin()));
  }
};

/// `given` if it is an indexed copy of `tm` with the points of `vpm`, else a new copy. The
/// named parameter `prepared_mesh` hands one copy to every stage (a program's validation,
/// metric, Lloyd and diagram), which would otherwise each build their own.
template <class TriangleMesh, class VertexPointMap>
std::shared_ptr<const Indexed_mesh<TriangleMesh> >
shared_or_new_indexed_mesh(const std::shared_ptr<const Indexed_mesh<TriangleMesh> >& given, const TriangleMesh& tm,
                           VertexPointMap vpm, bool parallel = false)
{
  if(given && given->source_mesh == &tm && given->number_of_vertices() == num_vertices(tm)
     && given->number_of_faces() == num_faces(tm))
  {
    bool same_points = true;
    for(std::size_t v = 0; v < given->number_of_vertices() && same_points; ++v)
      same_points = (to_point_d(get(vpm, given->vertex_handles[v])) == given->points[v]);
    if(same_points) return given;
  }
  return std::make_shared<const Indexed_mesh<TriangleMesh> >(tm, vpm, parallel);
}

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_INDEXED_MESH_H
