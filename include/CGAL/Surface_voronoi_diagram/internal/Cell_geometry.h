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
// Measures of the cells that Lloyd relaxation needs: area-weighted centroids, and the energy
// (sum over sites of the integral of the squared distance over their cell).

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_CELL_GEOMETRY_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_CELL_GEOMETRY_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/internal/Diagram_data.h>
#include <CGAL/Surface_voronoi_diagram/internal/Double_kernel.h>

#include <vector>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

/// calls `f(o, q, r, area)` for the triangles of a fan over a (convex, planar) piece
template <class F>
void for_each_fan_triangle(const Partition& partition, const Partition::Piece& p, F f)
{
  const Point_d& o = partition.vertices[p.vertices[0]].point;
  for(std::size_t k = 1; k + 1 < p.vertices.size(); ++k)
  {
    const Point_d& q = partition.vertices[p.vertices[k]].point;
    const Point_d& r = partition.vertices[p.vertices[k + 1]].point;
    f(o, q, r, triangle_area(o, q, r));
  }
}

/// the area-weighted centroid of every cell, in space (weighted by Lloyd's density as well,
/// if it has one); the site's own point for an empty cell; from the partition, or from the
/// cuts' measures where the diagram has no partition
template <class TriangleMesh>
std::vector<Point_d> cell_centroids(const Diagram_data<TriangleMesh>& d)
{
  const std::size_t n = d.sites.size();
  std::vector<double> a(n, 0.), c(3 * n, 0.);
  const std::vector<double>* density = d.centroid_density.get();
  if(d.measures.valid)
    for(std::size_t i = 0; i < n; ++i)
    {
      a[i] = density ? d.measures.mass[i] : d.measures.area[i];
      for(int j = 0; j < 3; ++j) c[3 * i + j] = d.measures.moment[i][j];
    }
  const Indexed_mesh<TriangleMesh>& mesh = *d.mesh;
  for(const Partition::Piece& p : d.partition.pieces)
  {
    if(p.site == no_site) continue;
    auto density_at = [&](const Point_d& x) {
      const Barycentric b = mesh.barycentric_coordinates(p.face, x);
      double w = 0;
      for(int k = 0; k < 3; ++k) w += b[k] * (*density)[mesh.triangles[p.face][k]];
      return w;
    };
    for_each_fan_triangle(d.partition, p, [&](const Point_d& o, const Point_d& q, const Point_d& r, double t) {
      if(!density)
      {
        a[p.site] += t;
        for(int j = 0; j < 3; ++j) c[3 * p.site + j] += t * (o[j] + q[j] + r[j]) / 3.;
        return;
      }
      add_weighted_triangle(o, q, r, t, density_at(o), density_at(q), density_at(r), a[p.site], &c[3 * p.site]);
    });
  }
  std::vector<Point_d> out;
  out.reserve(n);
  for(std::size_t i = 0; i < n; ++i)
    out.push_back(a[i] > 0 ? Point_d(c[3 * i] / a[i], c[3 * i + 1] / a[i], c[3 * i + 2] / a[i])
                           : d.mesh->point_at(d.sites[i].face, d.sites[i].barycentric));
  return out;
}

/// the squared distance (weight not subtracted) from site `i` to the point `b` (barycentric)
/// of face `f`: the embedding's for embeddings; for lazy metrics, the corner values the
/// propagation computed, interpolated
template <class TriangleMesh>
double squared_distance_in_face(const Diagram_data<TriangleMesh>& d, std::size_t i, std::size_t f, const Barycentric& b)
{
  const Indexed_mesh<TriangleMesh>& mesh = *d.mesh;
  if(d.embedding)
  {
    const Embedding_values& e = *d.embedding;
    const double* s = e.site_coordinates(i);
    double total = 0;
    for(std::size_t c = 0; c < e.dimension(); ++c)
    {
      double x = 0;
      for(int k = 0; k < 3; ++k) x += b[k] * e.vertex_coordinates(mesh.triangles[f][k])[c];
      total += (x - s[c]) * (x - s[c]);
    }
    return total;
  }
  const double* value = values_of(d.candidates[f], static_cast<std::uint32_t>(i));
  double total = 0;
  for(int k = 0; k < 3; ++k) total += b[k] * (value[k] + d.sites[i].weight);
  return total;
}

/// The energy: exact for embeddings (|E(x) - E(s)|^2 is quadratic on a triangle, integrated
/// with the edge-midpoint rule), the integral of the linearly interpolated squared distance
/// for lazy metrics. Weights are not subtracted. Lloyd's diagrams computed it on the cuts.
template <class TriangleMesh>
double energy(const Diagram_data<TriangleMesh>& d)
{
  if(d.measures.valid) return d.measures.energy;
  const Indexed_mesh<TriangleMesh>& mesh = *d.mesh;
  double total = 0;
  for(const Partition::Piece& p : d.partition.pieces)
  {
    if(p.site == no_site) continue;
    auto value_at = [&](const Point_d& x) {
      return squared_distance_in_face(d, p.site, p.face, mesh.barycentric_coordinates(p.face, x));
    };
    for_each_fan_triangle(d.partition, p, [&](const Point_d& o, const Point_d& q, const Point_d& r, double t) {
      if(!(t > 0)) return;
      if(d.embedding)
        total += t / 3. * (value_at(CGAL::midpoint(o, q)) + value_at(CGAL::midpoint(q, r)) + value_at(CGAL::midpoint(r, o)));
      else
        total += t / 3. * (value_at(o) + value_at(q) + value_at(r));
    });
  }
  return total;
}

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_CELL_GEOMETRY_H
