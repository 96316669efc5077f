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
// The cells' areas, centroids and energy measured on the per-face cuts, without stitching
// them into a partition: what Lloyd's diagrams need, once the cuts have decided that every
// cell is whole. The vertices are placed as stitching places them (Bisector_points.h).

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_CUT_CELL_MEASURES_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_CUT_CELL_MEASURES_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/internal/Bisector_points.h>
#include <CGAL/Surface_voronoi_diagram/internal/Candidate_table.h>
#include <CGAL/Surface_voronoi_diagram/internal/Double_kernel.h>
#include <CGAL/Surface_voronoi_diagram/internal/Face_cuts.h>
#include <CGAL/Surface_voronoi_diagram/internal/Indexed_mesh.h>
#include <CGAL/Surface_voronoi_diagram/internal/Site.h>
#include <CGAL/Surface_voronoi_diagram/internal/Site_fields.h>

#include <algorithm>
#include <array>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

/// Per site: the area and the area-weighted sum of centroids of its cell; and the diagram's
/// energy (see `energy()` in Cell_geometry.h for the quadrature, which is the same).
struct Cell_measures
{
  bool valid = false;
  std::vector<double> area;
  std::vector<std::array<double, 3> > moment;   // with a density, density-weighted
  std::vector<double> mass;                      // with a density: its integral over the cell
  double energy = 0;
  double unreached_area = 0;
};

/// Adds to `mass` and `moment` a triangle's integrals of a density w and of w x, w linear and
/// given at the corners o, q, r; t is the triangle's area. w x is quadratic on the triangle,
/// which the edge-midpoint rule integrates exactly.
inline void add_weighted_triangle(const Point_d& o, const Point_d& q, const Point_d& r, double t,
                                  double wo, double wq, double wr, double& mass, double* moment)
{
  mass += t * (wo + wq + wr) / 3.;
  for(int j = 0; j < 3; ++j)
    moment[j] += t / 3. * ((wo + wq) * (o[j] + q[j]) + (wq + wr) * (q[j] + r[j]) + (wr + wo) * (r[j] + o[j])) / 4.;
}

template <class TriangleMesh>
class Cut_cell_measurer
{
public:
  typedef Indexed_mesh<TriangleMesh> Mesh;

  Cut_cell_measurer(const Mesh& mesh, const Candidate_table& candidates, const Face_cuts& cuts,
                    const std::vector<Site>& sites, const Embedding_values* embedding,
                    const std::vector<double>* density = nullptr)
    : m_mesh(mesh), m_candidates(candidates), m_cuts(cuts), m_sites(sites), m_embedding(embedding), m_density(density)
  {}

  /// faces in order, pieces in order: the sums do not depend on threads
  Cell_measures run()
  {
    Cell_measures out;
    out.valid = true;
    out.area.assign(m_sites.size(), 0.);
    out.moment.assign(m_sites.size(), {{ 0., 0., 0. }});
    if(m_density) out.mass.assign(m_sites.size(), 0.);
    Polygon polygon;
    for(std::size_t f = 0; f < m_mesh.number_of_faces(); ++f)
    {
      const Candidate_range list = m_candidates[f];
      if(list.empty())
      {
        out.unreached_area += m_mesh.face_areas[f];
        continue;
      }
      const Face_cuts::Cut cut = m_cuts[f];
      if(cut.whole_face)
      {
        if(m_density)
        {
          const std::array<Polygon_vertex, 3> triangle = {{
              Polygon_vertex{ m_mesh.corner(f, 0), {{ 1., 0., 0. }} },
              Polygon_vertex{ m_mesh.corner(f, 1), {{ 0., 1., 0. }} },
              Polygon_vertex{ m_mesh.corner(f, 2), {{ 0., 0., 1. }} } }};
          add(out, f, 0, triangle.data(), triangle.size());
        }
        else
          add_whole_face(out, f, list[0]);
        continue;
      }
      for(const Face_cuts::Piece piece : cut.pieces)
      {
        // placed where they are kept: a vertex built aside and then copied in stalled on
        // its barycentric coordinates, written one by one and read back in pairs
        if(polygon.size() < piece.vertices.size()) polygon.resize(piece.vertices.size());
        std::size_t size = 0;
        for(const Symbolic_vertex& v : piece.vertices) place(f, piece.candidate, v, polygon[size++]);
        add(out, f, piece.candidate, polygon.data(), size);
      }
    }
    return out;
  }

private:
  struct Polygon_vertex
  {
    Point_d point;
    Barycentric b;
  };
  typedef std::vector<Polygon_vertex> Polygon;   // one buffer for all the pieces

  void place(std::size_t f, std::uint32_t owner, const Symbolic_vertex& v, Polygon_vertex& out) const
  {
    const Candidate_range list = m_candidates[f];
    Barycentric& b = out.b;
    b = {{ 0., 0., 0. }};
    if(v.kind == Symbolic_vertex::CORNER)
    {
      b[v.local] = 1.;
      out.point = m_mesh.points[m_mesh.triangles[f][v.local]];
      return;
    }
    if(v.kind == Symbolic_vertex::EDGE)
    {
      // as stitching does: along the edge's sorted vertices, the lower site's field first
      const std::size_t e = m_mesh.edges[f][v.local];
      const std::size_t va = m_mesh.edge_vertices[e][0], vb = m_mesh.edge_vertices[e][1];
      const int ca = m_mesh.corner_of(f, va), cb = m_mesh.corner_of(f, vb);
      const bool owner_low = list[owner].site < list[v.other].site;
      const double* lo = list[owner_low ? owner : v.other].value.data();
      const double* hi = list[owner_low ? v.other : owner].value.data();
      const double t = edge_crossing_parameter(lo, hi, ca, cb);
      const Point_d& pa = m_mesh.points[va];
      const Point_d& pb = m_mesh.points[vb];
      b[ca] = 1. - t;
      b[cb] = t;
      out.point = pa + t * (pb - pa);
      return;
    }
    // the three fields in site order (lists are sorted by site), as stitching orders them
    std::array<std::uint32_t, 3> c = {{ owner, v.other, v.third }};
    std::sort(c.begin(), c.end());
    b = triple_point_barycentric(list[c[0]].value.data(), list[c[1]].value.data(), list[c[2]].value.data());
    out.point = m_mesh.point_at(f, b);
  }

  // the squared distance to the site at barycentric point b of face f: a quadratic form in b
  // for an embedding (its Gram matrix of corner offsets), else the interpolated values
  struct Piece_field
  {
    std::array<std::array<double, 3>, 3> gram;
    std::array<double, 3> corner_value;
    bool quadratic;

    double at(const Barycentric& b) const
    {
      if(!quadratic) return b[0] * corner_value[0] + b[1] * corner_value[1] + b[2] * corner_value[2];
      double total = 0;
      for(int j = 0; j < 3; ++j)
        for(int k = 0; k < 3; ++k) total += b[j] * b[k] * gram[j][k];
      return total;
    }
  };

  Piece_field field_of(std::size_t f, const Candidate& x) const
  {
    Piece_field p;
    p.quadratic = (m_embedding != nullptr);
    if(!p.quadratic)
    {
      for(int k = 0; k < 3; ++k) p.corner_value[k] = x.value[k] + m_sites[x.site].weight;
      return p;
    }
    const std::size_t d = m_embedding->dimension();
    const double* s = m_embedding->site_coordinates(x.site);
    std::array<const double*, 3> e;
    for(int k = 0; k < 3; ++k) e[k] = m_embedding->vertex_coordinates(m_mesh.triangles[f][k]);
    for(int j = 0; j < 3; ++j)
      for(int k = j; k < 3; ++k)
      {
        double g = 0;
        for(std::size_t c = 0; c < d; ++c) g += (e[j][c] - s[c]) * (e[k][c] - s[c]);
        p.gram[j][k] = p.gram[k][j] = g;
      }
    return p;
  }

  static Barycentric midpoint(const Barycentric& a, const Barycentric& b)
  {
    return {{ (a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2 }};
  }

  void add(Cell_measures& out, std::size_t f, std::uint32_t candidate, const Polygon_vertex* polygon, std::size_t size) const
  {
    const Candidate& x = m_candidates[f][candidate];
    const Piece_field field = field_of(f, x);
    double& area = out.area[x.site];
    std::array<double, 3>& moment = out.moment[x.site];
    const Polygon_vertex& o = polygon[0];
    for(std::size_t k = 1; k + 1 < size; ++k)
    {
      const Polygon_vertex& q = polygon[k];
      const Polygon_vertex& r = polygon[k + 1];
      const double t = triangle_area(o.point, q.point, r.point);
      area += t;
      if(m_density)
        add_weighted_triangle(o.point, q.point, r.point, t, density_at(f, o.b), density_at(f, q.b), density_at(f, r.b),
                              out.mass[x.site], moment.data());
      else
        for(int j = 0; j < 3; ++j) moment[j] += t * (o.point[j] + q.point[j] + r.point[j]) / 3.;
      if(!(t > 0)) continue;
      // the edge-midpoint rule, exact for the quadratic squared distance of an embedding
      if(field.quadratic)
        out.energy += t / 3. * (field.at(midpoint(o.b, q.b)) + field.at(midpoint(q.b, r.b)) + field.at(midpoint(r.b, o.b)));
      else
        out.energy += t / 3. * (field.at(o.b) + field.at(q.b) + field.at(r.b));
    }
  }

  // A face one candidate owns, without a density (most faces): the same area and moment as
  // add() takes, and the integral of the squared distance in closed form, (t / 12)
  // (|u0 + u1 + u2|^2 + |u0|^2 + |u1|^2 + |u2|^2) for the corners' offsets u from the site in
  // an embedding (what the edge-midpoint rule sums to), t/3 (v0 + v1 + v2) otherwise.
  void add_whole_face(Cell_measures& out, std::size_t f, const Candidate& x) const
  {
    const Point_d& o = m_mesh.corner(f, 0);
    const Point_d& q = m_mesh.corner(f, 1);
    const Point_d& r = m_mesh.corner(f, 2);
    const double t = m_mesh.face_areas[f];   // triangle_area(o, q, r), computed once by the mesh
    out.area[x.site] += t;
    std::array<double, 3>& moment = out.moment[x.site];
    for(int j = 0; j < 3; ++j) moment[j] += t * (o[j] + q[j] + r[j]) / 3.;
    if(!(t > 0)) return;
    if(!m_embedding)
    {
      const double w = m_sites[x.site].weight;
      out.energy += t / 3. * ((x.value[0] + w) + (x.value[1] + w) + (x.value[2] + w));
      return;
    }
    const std::size_t d = m_embedding->dimension();
    const double* s = m_embedding->site_coordinates(x.site);
    const double* e0 = m_embedding->vertex_coordinates(m_mesh.triangles[f][0]);
    const double* e1 = m_embedding->vertex_coordinates(m_mesh.triangles[f][1]);
    const double* e2 = m_embedding->vertex_coordinates(m_mesh.triangles[f][2]);
    double sum = 0, squares = 0;
    for(std::size_t c = 0; c < d; ++c)
    {
      const double u0 = e0[c] - s[c], u1 = e1[c] - s[c], u2 = e2[c] - s[c];
      sum += (u0 + u1 + u2) * (u0 + u1 + u2);
      squares += u0 * u0 + u1 * u1 + u2 * u2;
    }
    out.energy += t / 12. * (sum + squares);
  }

  double density_at(std::size_t f, const Barycentric& b) const
  {
    const std::vector<double>& w = *m_density;
    return b[0] * w[m_mesh.triangles[f][0]] + b[1] * w[m_mesh.triangles[f][1]] + b[2] * w[m_mesh.triangles[f][2]];
  }

  const Mesh& m_mesh;
  const Candidate_table& m_candidates;
  const Face_cuts& m_cuts;
  const std::vector<Site>& m_sites;
  const Embedding_values* m_embedding;
  const std::vector<double>* m_density;   // by vertex, or null
};

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_CUT_CELL_MEASURES_H
