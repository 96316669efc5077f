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
// A density of sites from the curvature of the surface: more sites where it bends, for the
// vertex_density_map of the sampling functions and of Lloyd relaxation.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_CURVATURE_DENSITY_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_CURVATURE_DENSITY_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/parameters.h>
#include <CGAL/Surface_voronoi_diagram/internal/Double_kernel.h>
#include <CGAL/Surface_voronoi_diagram/internal/Indexed_mesh.h>

#include <CGAL/assertions.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {

/// \ingroup PkgSurfaceVoronoiDiagramSites
/// Writes a density of sites for `vertex_density_map`: at vertex v,
/// \f$ \rho(v) = \min\left(R, (1 + \kappa(v) / \bar\kappa)^2\right) \f$, where \f$ \kappa \f$
/// is the magnitude of the mean curvature (half the norm of the cotangent Laplacian of the
/// positions over the mixed Voronoi area around v, after Meyer, Desbrun, Schroeder and Barr,
/// "Discrete Differential-Geometry Operators for Triangulated 2-Manifolds", 2003; below \f$ 10^{-9} \f$ of
/// the inverse square root of the surface area, zero), \f$ \bar\kappa \f$ its
/// mean over the surface weighted by those areas, and R the `max_density_ratio`. Sites are
/// then spaced as \f$ 1 / (1 + \kappa / \bar\kappa) \f$: where the surface bends as much as
/// on average, at half the spacing of its flat parts. A plane gets 1 everywhere. A border
/// vertex, whose Laplacian measures the border rather than the bending, takes the mean
/// curvature of its inner neighbours. The mean curvature of a saddle whose principal
/// curvatures cancel is zero: such a saddle gets the density of a flat part.
///
/// \tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
/// \tparam VertexDensityMap a model of `WritablePropertyMap` with the vertex descriptor as key
///         and `double` as value
/// \param tm the mesh
/// \param density the map written
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
///     \cgalParamType{a model of `ReadablePropertyMap`}
///     \cgalParamDefault{`get_const_property_map(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{Surface_voronoi::parameters::max_density_ratio}
///     \cgalParamDescription{the largest density written (sharp creases have a curvature that
///       grows without bound as the mesh is refined)}
///     \cgalParamType{`double`, at least 1}
///     \cgalParamDefault{16}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \pre `tm` is a triangle mesh with at least one face, and `max_density_ratio` is at least 1
template <class TriangleMesh, class VertexDensityMap, typename CGAL_NP_TEMPLATE_PARAMETERS>
void curvature_density(const TriangleMesh& tm, VertexDensityMap density, const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef internal::Vector_d Vector;
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm));
  const double ratio = choose_parameter(get_parameter(np, Surface_voronoi::internal_np::max_density_ratio), 16.);
  CGAL_precondition_msg(ratio >= 1, "max_density_ratio must be at least 1");
  CGAL_precondition_msg(is_triangle_mesh(tm), "the mesh must be a triangle mesh");
  const internal::Indexed_mesh<TriangleMesh> mesh(tm, vpm);
  const std::size_t n = mesh.number_of_vertices();
  CGAL_precondition_msg(mesh.number_of_faces() > 0, "the mesh is empty (no faces)");

  // the cotangent Laplacian of the positions, and the area around each vertex
  std::vector<Vector> laplacian(n, Vector(0, 0, 0));
  std::vector<double> area(n, 0.);
  std::vector<char> on_border(n, 0);
  for(std::size_t f = 0; f < mesh.number_of_faces(); ++f)
  {
    std::array<double, 3> cotangent;
    bool obtuse = false;
    for(int k = 0; k < 3; ++k)
    {
      if(mesh.neighbors[f][k] == internal::Indexed_mesh<TriangleMesh>::none)
        on_border[mesh.triangles[f][k]] = on_border[mesh.triangles[f][(k + 1) % 3]] = 1;
      // the angle at corner k weighs the opposite edge
      const std::size_t a = mesh.triangles[f][k], b = mesh.triangles[f][(k + 1) % 3], c = mesh.triangles[f][(k + 2) % 3];
      const Vector u = mesh.points[b] - mesh.points[a], w = mesh.points[c] - mesh.points[a];
      const double sine = std::sqrt(CGAL::cross_product(u, w).squared_length());
      cotangent[k] = (sine > 0) ? (u * w) / sine : 0.;   // a degenerate face bends nothing
      obtuse = obtuse || (u * w) < 0;
      const Vector bc = mesh.points[c] - mesh.points[b];
      laplacian[b] = laplacian[b] + cotangent[k] * bc;
      laplacian[c] = laplacian[c] - cotangent[k] * bc;
    }
    // the mixed Voronoi area of Meyer et al.: each corner's Voronoi region in an acute face,
    // half the face at an obtuse corner and a quarter at the others
    for(int k = 0; k < 3; ++k)
    {
      const std::size_t a = mesh.triangles[f][k], b = mesh.triangles[f][(k + 1) % 3], c = mesh.triangles[f][(k + 2) % 3];
      if(obtuse)
      {
        const double ab_ac = (mesh.points[b] - mesh.points[a]) * (mesh.points[c] - mesh.points[a]);
        area[a] += mesh.face_areas[f] / (ab_ac < 0 ? 2 : 4);
      }
      else
        area[a] += ((mesh.points[b] - mesh.points[a]).squared_length() * cotangent[(k + 2) % 3]
                    + (mesh.points[c] - mesh.points[a]).squared_length() * cotangent[(k + 1) % 3]) / 8;
    }
  }
  std::vector<double> curvature(n, 0.);
  for(std::size_t v = 0; v < n; ++v)
    if(!on_border[v] && area[v] > 0)
      curvature[v] = std::sqrt(laplacian[v].squared_length()) / (4 * area[v]);
  // border vertices: the mean of their inner neighbours
  std::vector<double> inner_sum(n, 0.);
  std::vector<int> inner_count(n, 0);
  for(std::size_t f = 0; f < mesh.number_of_faces(); ++f)
    for(int k = 0; k < 3; ++k)
    {
      const std::size_t a = mesh.triangles[f][k], b = mesh.triangles[f][(k + 1) % 3];
      if(on_border[a] && !on_border[b]) { inner_sum[a] += curvature[b]; ++inner_count[a]; }
      if(on_border[b] && !on_border[a]) { inner_sum[b] += curvature[a]; ++inner_count[b]; }
    }
  double total_area = 0;
  for(std::size_t v = 0; v < n; ++v) total_area += area[v];
  // a flat part's Laplacian is rounding noise, which the division by the mean would blow up
  // on a plane: curvatures below a billionth of the surface's inverse size count as none
  const double noise = 1e-9 / std::sqrt(total_area);
  double weighted = 0;
  for(std::size_t v = 0; v < n; ++v)
  {
    if(on_border[v]) curvature[v] = inner_count[v] > 0 ? inner_sum[v] / inner_count[v] : 0.;
    if(!std::isfinite(curvature[v]) || !(curvature[v] > noise)) curvature[v] = 0;
    weighted += area[v] * curvature[v];
  }
  const double mean = (total_area > 0) ? weighted / total_area : 0.;
  for(std::size_t v = 0; v < n; ++v)
  {
    const double x = (mean > 0 && std::isfinite(mean)) ? 1 + curvature[v] / mean : 1.;
    put(density, mesh.vertex_handles[v], (std::min)(ratio, x * x));
  }
}

} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_CURVATURE_DENSITY_H
