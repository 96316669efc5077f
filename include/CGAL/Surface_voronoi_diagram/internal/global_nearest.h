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
// Candidate selection of the restricted Voronoi diagram baseline (RVD): every site that is
// the nearest one (in the embedding) somewhere in the face, with no propagation. Cutting
// these candidates gives the exact RVD of the embedded surface.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_GLOBAL_NEAREST_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_GLOBAL_NEAREST_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/internal/Candidate.h>
#include <CGAL/Surface_voronoi_diagram/internal/Double_kernel.h>
#include <CGAL/Surface_voronoi_diagram/internal/Indexed_mesh.h>
#include <CGAL/Surface_voronoi_diagram/internal/Local_site_spacing.h>


#include <algorithm>
#include <cmath>
#include <iterator>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

template <class TriangleMesh, class Fields>
void global_nearest_candidates(const Indexed_mesh<TriangleMesh>& mesh,
                               const Fields& fields,
                               std::size_t number_of_sites,
                               bool has_weights,
                               Candidate_lists& candidates)
{
  const std::size_t nf = mesh.number_of_faces();
  const std::size_t d = fields.dimension();
  candidates.assign(nf, Candidate_list());

  auto add = [&](std::size_t f, std::size_t site) {
    Candidate x;
    x.site = static_cast<std::uint32_t>(site);
    for(int k = 0; k < 3; ++k) x.value[k] = fields.value(site, mesh.triangles[f][k]);
    candidates[f].push_back(x);
  };

  if(d == 3 && !has_weights)
  {
    std::vector<Point_d> site_points(number_of_sites);
    for(std::size_t i = 0; i < number_of_sites; ++i)
    {
      const double* s = fields.site_coordinates(i);
      site_points[i] = Point_d(s[0], s[1], s[2]);
    }
    const Point_tree tree(site_points);

    std::vector<double> nearest(mesh.number_of_vertices());
    for(std::size_t v = 0; v < nearest.size(); ++v)
    {
      const double* x = fields.vertex_coordinates(v);
      nearest[v] = std::sqrt(tree.nearest(Point_d(x[0], x[1], x[2]), 1).begin()->second);
    }
    std::vector<std::size_t> found;
    for(std::size_t f = 0; f < nf; ++f)
    {
      const double* X[3] = { fields.vertex_coordinates(mesh.triangles[f][0]),
                             fields.vertex_coordinates(mesh.triangles[f][1]),
                             fields.vertex_coordinates(mesh.triangles[f][2]) };
      double c[3];
      for(int j = 0; j < 3; ++j) c[j] = (X[0][j] + X[1][j] + X[2][j]) / 3.;
      double rho = 0, ell = 0, dmin = nearest[mesh.triangles[f][0]];
      for(int k = 0; k < 3; ++k)
      {
        double a = 0, b = 0;
        for(int j = 0; j < 3; ++j)
        {
          a += (X[k][j] - c[j]) * (X[k][j] - c[j]);
          b += (X[k][j] - X[(k + 1) % 3][j]) * (X[k][j] - X[(k + 1) % 3][j]);
        }
        rho = (std::max)(rho, std::sqrt(a));
        ell = (std::max)(ell, std::sqrt(b));
        dmin = (std::min)(dmin, nearest[mesh.triangles[f][k]]);
      }
      // A site winning at x in the face is within |x - v_k| + nearest(v_k) of x, so within
      // rho + ell + min_k nearest(v_k) of the centroid (slightly enlarged for rounding).
      const double r = (rho + ell + dmin) * (1 + 1e-9) + 1e-300;
      found.clear();
      tree.within(Point_d(c[0], c[1], c[2]), r, std::back_inserter(found));
      std::sort(found.begin(), found.end());
      for(std::size_t s : found) add(f, s);
    }
  }
  else
  {
    for(std::size_t f = 0; f < nf; ++f)
      for(std::size_t s = 0; s < number_of_sites; ++s) add(f, s);
  }

  for(Candidate_list& list : candidates)
    clean_candidate_list(list);
}

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_GLOBAL_NEAREST_H
