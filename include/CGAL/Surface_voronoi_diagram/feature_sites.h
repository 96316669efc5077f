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
// Sites on the feature lines of a mesh (breaklines and the border): one at every corner of
// the feature graph, and along each line between corners as many as the site spacing asks
// for, placed where 1D Lloyd relaxation would leave them. With such sites the dual of the
// diagram has edges along the creases and boundary vertices on the input's border.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_FEATURE_SITES_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_FEATURE_SITES_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/exceptions.h>
#include <CGAL/Surface_voronoi_diagram/parameters.h>
#include <CGAL/Surface_voronoi_diagram/sampling.h>
#include <CGAL/Surface_voronoi_diagram/internal/Double_kernel.h>

#include <CGAL/assertions.h>
#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

// The mean of sqrt(rho) over an edge along which the density rho goes linearly from a to b
// (both finite, not negative): the integral over t in [0, 1] of sqrt(a + (b - a) t), that is
// 2/3 (b^3/2 - a^3/2) / (b - a), written without the cancellation of b close to a.
inline double mean_sqrt_density(double a, double b)
{
  if(a == b) return std::sqrt(a);
  const double sa = std::sqrt(a), sb = std::sqrt(b);
  return (2. / 3.) * (a + sa * sb + b) / (sa + sb);
}

// The parameter t in [0, 1] at which the integral over [0, t] of sqrt(a + (b - a) s) ds
// reaches q (q at most mean_sqrt_density(a, b), up to rounding): with u = sqrt(rho(t)),
// u^3 = a^3/2 + 3/2 (b - a) q, and t = (u^2 - a) / (b - a) = 3/2 q (u + sqrt a) / (u^2 + u sqrt a + a),
// the last form without the cancellation of b close to a.
inline double inverse_sqrt_density_integral(double a, double b, double q)
{
  if(!(q > 0)) return 0.;
  double t;
  if(a == b)
    t = q / std::sqrt(a);
  else
  {
    const double sa = std::sqrt(a);
    const double u = (std::max)(0., std::cbrt(a * sa + 1.5 * (b - a) * q));
    t = 1.5 * q * (u + sa) / (u * u + u * sa + a);
  }
  return (t < 1) ? t : 1.;   // also for a NaN from a zero density at both ends
}

} // namespace internal

/// \ingroup PkgSurfaceVoronoiDiagramSites
/// Sites on the feature lines of `tm`, for a diagram of about `n` sites in all whose dual
/// follows the creases and the border: with sites on the feature lines, dual edges run along
/// the creases, and the boundary vertices of the dual lie on the border of `tm`.
///
/// The feature lines are the edges marked by `edge_is_constrained_map` and, unless
/// `sample_border` is `false`, the border edges. A vertex where their number is not 2 (an end
/// of a line, or a junction of three lines or more), or where the two feature edges turn by
/// more than `corner_angle` (the angle between their directions, 0 on a straight line), is a
/// corner, and gets a site at the vertex. The feature lines, cut at the corners, are chains:
/// polylines from corner to corner, and closed loops without any corner. Along a chain the
/// wanted spacing is \f$ h(x) = \sqrt{2 D / (\sqrt{3}\, n\, \rho(x))} \f$, where
/// \f$ \rho \f$ is the density and \f$ D \f$ its integral over the surface (with a uniform
/// density, \f$ h = \sqrt{2 A / (\sqrt{3}\, n)} \f$ for the area \f$ A \f$: the spacing of
/// `n` sites packed hexagonally, each owning \f$ \sqrt{3} h^2 / 2 \f$), and with
/// \f$ N = \int ds / h(s) \f$ over the chain,
/// - an open chain gets \f$ k = \max(0, \mathrm{round}(N) - 1) \f$ sites inside, the j-th
///   (from 1) where \f$ \int_0^s dt / h(t) = j N / (k + 1) \f$;
/// - a closed loop gets \f$ k = \max(3, \mathrm{round}(N)) \f$ sites, the j-th (from 0) where
///   \f$ \int_0^s dt / h(t) = j N / k \f$, so that the first is at the loop's vertex of
///   smallest index.
///
/// This equidistribution is the fixed point of Lloyd relaxation in one dimension for that
/// spacing (each site at the centroid of its interval under the density): the sites are as
/// evenly spread along each chain as the spacing asks, and the chain's ends stay at the
/// corners. Along an edge the density goes linearly from one end's value to the other's, and
/// \f$ \int \sqrt{\rho} \f$ is integrated and inverted exactly (in closed form). A loop along
/// which the density is zero everywhere gets its 3 sites evenly spread by length; an open
/// chain there gets none.
///
/// The order is deterministic: the corners by increasing vertex index first, then the chains
/// by increasing smallest edge index, the sites of each in the order of a walk along it. An
/// open chain is walked from its end of smaller vertex index (a chain from a corner back to
/// it, from its edge of smaller index there), a loop from its vertex of smallest index along
/// its edge of smaller index there. The index of a vertex or an edge is its position in
/// `vertices(tm)` or `edges(tm)`. A corner shared by several chains has one site, and no two
/// sites are at the same point (unless the spacing is below the resolution of doubles).
///
/// A site inside an edge is a location in one of the edge's faces (the face of
/// `halfedge(e, tm)`, or its opposite on a border) whose barycentric coordinate at the corner
/// opposite the edge is exactly 0; a site at a vertex `v` (a corner, the start of a loop) is
/// a location in the first face around `v` from `halfedge(v, tm)` with the coordinates
/// exactly 1 at `v` and 0 at the two other corners. A consumer can thus tell by the zero
/// coordinates which sites lie on an edge or at a vertex.
///
/// The caller adds free sites elsewhere to reach `n` (for instance by `random_sites()` or
/// `blue_noise_sites()` and, keeping the feature sites in place, `lloyd_relaxation()`). On a
/// mesh with long feature lines and a small `n`, the feature sites alone can reach or exceed
/// `n`: they are returned all the same, and the caller checks their number.
///
/// \tparam TriangleMesh a model of `FaceListGraph` and `EdgeListGraph` whose faces are triangles
/// \param tm a triangle mesh
/// \param n the total number of sites wanted on the whole surface (these and the free sites
///        the caller adds), which sets the spacing
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
///     \cgalParamType{a model of `ReadablePropertyMap`}
///     \cgalParamDefault{`get_const_property_map(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{edge_is_constrained_map}
///     \cgalParamDescription{the breaklines: the edges `e` with `get(map, e)` true are feature lines}
///     \cgalParamType{a model of `ReadablePropertyMap` with the edge descriptor as key and
///       `bool` as value}
///     \cgalParamDefault{no breakline}
///   \cgalParamNEnd
///   \cgalParamNBegin{Surface_voronoi::parameters::sample_border}
///     \cgalParamDescription{whether the border edges of `tm` are feature lines}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{Surface_voronoi::parameters::corner_angle}
///     \cgalParamDescription{the turn, in degrees, above which a vertex with two feature edges is
///       a corner: the angle between the directions of the two edges, 0 where the line goes
///       straight on and 180 where it turns back}
///     \cgalParamType{`double`}
///     \cgalParamDefault{60}
///   \cgalParamNEnd
///   \cgalParamNBegin{Surface_voronoi::parameters::vertex_density_map}
///     \cgalParamDescription{the wanted number of sites per unit area, up to a constant factor,
///       at each vertex, interpolated linearly across faces and along edges: the spacing at a
///       point of density \f$ \rho \f$ is that of `n` sites over the integral \f$ D \f$ of the
///       density, \f$ \sqrt{2 D / (\sqrt{3}\, n\, \rho)} \f$}
///     \cgalParamType{a model of `ReadablePropertyMap` with the vertex descriptor as key and a
///       value type convertible to `double` (finite, not negative, not zero on every face)}
///     \cgalParamDefault{a uniform density}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// Lengths, areas and angles are measured in doubles on the points scaled by a power of two
/// (which changes none of the ratios), so any finite coordinates work. Runs in time linear in
/// the size of `tm` and the number of sites returned, but for sorting the chains.
///
/// \returns the corners' sites, then the chains' sites; empty if `tm` has no feature edge
/// \pre `tm` is a triangle mesh, and `n > 0`
/// \throws Surface_voronoi::Input_error if a density is negative or not a finite number, or
///         is zero on every face, or if the surface has no positive finite area while it has
///         feature edges (checked in every build)
template <class TriangleMesh, typename CGAL_NP_TEMPLATE_PARAMETERS>
std::vector<CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double> >
feature_line_sites(const TriangleMesh& tm, std::size_t n, const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  typedef CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double> Location;
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::edge_descriptor edge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;
  typedef internal::Vector_d Vector_d;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;

  CGAL_precondition_msg(CGAL::is_triangle_mesh(tm), "the mesh must be a triangle mesh");
  CGAL_precondition_msg(n > 0, "the number of sites must be positive");

  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm));
  const auto constrained = choose_parameter(get_parameter(np, CGAL::internal_np::edge_is_constrained),
                                            CGAL::Constant_property_map<edge_descriptor, bool>(false));
  const bool with_border = choose_parameter(get_parameter(np, Surface_voronoi::internal_np::sample_border), true);
  const double corner_degrees = choose_parameter(get_parameter(np, Surface_voronoi::internal_np::corner_angle), 60.);

  // vertices and edges by index (their position in vertices(tm) and edges(tm))
  std::vector<vertex_descriptor> vertex_handles(vertices(tm).begin(), vertices(tm).end());
  std::vector<edge_descriptor> edge_handles(edges(tm).begin(), edges(tm).end());
  const auto vertex_index = get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm);
  for(std::size_t i = 0; i < vertex_handles.size(); ++i) put(vertex_index, vertex_handles[i], i);

  // the feature edges, their ends, and each vertex's feature edges by increasing index
  std::vector<std::uint8_t> is_feature(edge_handles.size(), 0);
  std::vector<std::array<std::size_t, 2> > ends(edge_handles.size());
  std::vector<std::vector<std::size_t> > incident(vertex_handles.size());
  for(std::size_t k = 0; k < edge_handles.size(); ++k)
  {
    const edge_descriptor e = edge_handles[k];
    if(!(get(constrained, e) || (with_border && CGAL::is_border(e, tm)))) continue;
    const halfedge_descriptor h = halfedge(e, tm);
    ends[k] = {{ get(vertex_index, source(h, tm)), get(vertex_index, target(h, tm)) }};
    is_feature[k] = 1;
    for(std::size_t end : ends[k]) incident[end].push_back(k);
  }
  if(std::count(is_feature.begin(), is_feature.end(), 1) == 0) return std::vector<Location>();
  auto other_end = [&](std::size_t k, std::size_t v) { return ends[k][0] == v ? ends[k][1] : ends[k][0]; };
  auto other_edge = [&](std::size_t v, std::size_t k) {   // at a vertex of degree 2
    return incident[v][0] == k ? incident[v][1] : incident[v][0];
  };

  // the points, scaled by a power of two so that no square overflows or underflows
  const int exponent = internal::coordinate_exponent(tm, vpm);
  std::vector<internal::Point_d> points;
  points.reserve(vertex_handles.size());
  for(vertex_descriptor v : vertex_handles) points.push_back(internal::scaled_point(internal::to_point_d(get(vpm, v)), -exponent));

  // the area, or the integral of the density, and the density at the vertices of the lines
  const std::vector<face_descriptor> fs(faces(tm).begin(), faces(tm).end());
  const std::vector<std::array<double, 3> > corner_density =
      internal::face_corner_densities(tm, fs, np);
  double mass = 0;
  for(std::size_t k = 0; k < fs.size(); ++k)
  {
    const halfedge_descriptor h = halfedge(fs[k], tm);
    const double area = internal::triangle_area(points[get(vertex_index, source(h, tm))], points[get(vertex_index, target(h, tm))],
                                                points[get(vertex_index, target(next(h, tm), tm))]);
    mass += corner_density.empty() ? area : area * (corner_density[k][0] + corner_density[k][1] + corner_density[k][2]) / 3;
  }
  std::vector<double> density(vertex_handles.size(), 1.);
  if constexpr(internal::Has_density<CGAL_NP_CLASS>::value)
  {
    const auto density_map = get_parameter(np, Surface_voronoi::internal_np::vertex_density_map);
    for(std::size_t i = 0; i < vertex_handles.size(); ++i)
      if(!incident[i].empty())
      {
        density[i] = double(get(density_map, vertex_handles[i]));
        if(!(std::isfinite(density[i]) && density[i] >= 0)) throw Input_error("the vertex densities must be finite and not negative");
      }
    if(!(mass > 0 && std::isfinite(mass))) throw Input_error("the vertex density must not be zero on every face");
  }
  if(!(mass > 0 && std::isfinite(mass))) throw Input_error("the mesh has no positive finite area");
  // the integral of ds / h is `scale` times the integral of sqrt(rho) ds
  const double scale = std::sqrt(std::sqrt(3.) * double(n) / (2 * mass));

  // the corners: ends, junctions, and sharp turns
  const double turn_limit = corner_degrees * CGAL_PI / 180;
  std::vector<std::uint8_t> is_corner(vertex_handles.size(), 0);
  for(std::size_t v = 0; v < vertex_handles.size(); ++v)
  {
    if(incident[v].empty()) continue;
    if(incident[v].size() != 2) { is_corner[v] = 1; continue; }
    const Vector_d in = points[v] - points[other_end(incident[v][0], v)];
    const Vector_d out = points[other_end(incident[v][1], v)] - points[v];
    const double turn = std::atan2(std::sqrt(CGAL::cross_product(in, out).squared_length()), in * out);
    is_corner[v] = (turn > turn_limit);
  }

  // the chains: from each corner (by increasing index) along each of its edges not walked
  // yet (by increasing index) to the next corner, then the loops without a corner
  struct Chain
  {
    std::vector<std::size_t> vertices;   // one more than the edges; a loop ends at its start
    std::vector<std::size_t> edges;
    bool closed;
    std::size_t smallest_edge;
  };
  std::vector<Chain> chains;
  std::vector<std::uint8_t> walked(edge_handles.size(), 0);
  auto walk = [&](std::size_t start, std::size_t edge, bool closed) {
    Chain c;
    c.closed = closed;
    c.vertices.push_back(start);
    std::size_t v = start;
    for(;;)
    {
      walked[edge] = 1;
      c.edges.push_back(edge);
      v = other_end(edge, v);
      c.vertices.push_back(v);
      if(is_corner[v] || v == start) break;
      edge = other_edge(v, edge);
    }
    c.smallest_edge = *std::min_element(c.edges.begin(), c.edges.end());
    chains.push_back(std::move(c));
  };
  for(std::size_t v = 0; v < vertex_handles.size(); ++v)
    if(is_corner[v])
      for(std::size_t k : incident[v])
        if(!walked[k]) walk(v, k, false);
  for(std::size_t k = 0; k < edge_handles.size(); ++k)
  {
    if(!is_feature[k] || walked[k]) continue;
    // a loop of vertices of degree 2, none a corner: start at its smallest vertex
    std::size_t smallest = ends[k][0], v = ends[k][0], edge = k;
    do
    {
      v = other_end(edge, v);
      smallest = (std::min)(smallest, v);
      edge = other_edge(v, edge);
    } while(v != ends[k][0]);
    walk(smallest, incident[smallest][0], true);
  }
  std::sort(chains.begin(), chains.end(), [](const Chain& a, const Chain& b) { return a.smallest_edge < b.smallest_edge; });

  // the locations: at a vertex, and at parameter t from `from` to the other end of edge k
  // (not PMP::locate_on_halfedge(), which would give 1 - (1 - t) where the face's halfedge
  // runs the other way: not t to the last bit)
  auto vertex_location = [&](std::size_t v) { return CGAL::Polygon_mesh_processing::locate_vertex<double>(vertex_handles[v], tm); };
  auto edge_location = [&](std::size_t k, std::size_t from, double t) {
    halfedge_descriptor h = halfedge(edge_handles[k], tm);
    if(CGAL::is_border(h, tm)) h = opposite(h, tm);
    const face_descriptor f = face(h, tm);
    const halfedge_descriptor h0 = halfedge(f, tm);
    const std::array<vertex_descriptor, 3> corner = {{ source(h0, tm), target(h0, tm), target(next(h0, tm), tm) }};
    const vertex_descriptor a = vertex_handles[from], b = vertex_handles[other_end(k, from)];
    std::array<double, 3> c = {{ 0., 0., 0. }};
    for(int i = 0; i < 3; ++i)
    {
      if(corner[i] == a) c[i] = 1 - t;
      else if(corner[i] == b) c[i] = t;
    }
    return Location(f, c);
  };

  std::vector<Location> out;
  for(std::size_t v = 0; v < vertex_handles.size(); ++v)
    if(is_corner[v]) out.push_back(vertex_location(v));

  std::vector<double> length, start;   // per edge of a chain: its length, and the integral of sqrt(rho) before it
  std::vector<std::array<double, 2> > rho;
  for(const Chain& c : chains)
  {
    const std::size_t m = c.edges.size();
    length.assign(m, 0.);
    start.assign(m + 1, 0.);
    rho.assign(m, std::array<double, 2>());
    auto integrate = [&](bool uniform) {
      for(std::size_t i = 0; i < m; ++i)
      {
        const std::size_t a = c.vertices[i], b = c.vertices[i + 1];
        length[i] = std::sqrt((points[b] - points[a]).squared_length());
        rho[i] = uniform ? std::array<double, 2>{{ 1., 1. }} : std::array<double, 2>{{ density[a], density[b] }};
        start[i + 1] = start[i] + length[i] * internal::mean_sqrt_density(rho[i][0], rho[i][1]);
      }
    };
    integrate(false);
    const double wanted = scale * start[m];   // the integral of ds / h along the chain
    if(!(wanted < 0x1p52)) throw Input_error("the feature lines are too long for the spacing of the sites to be counted");
    const double rounded = std::round(wanted);
    std::size_t k;
    if(c.closed) k = (std::max)(std::size_t(3), std::size_t(rounded));
    else k = (rounded > 1) ? std::size_t(rounded) - 1 : 0;
    // a loop along which the density is zero everywhere: its 3 sites spread by length
    if(c.closed && !(start[m] > 0)) integrate(true);
    const double total = start[m];
    const std::size_t parts = c.closed ? k : k + 1;
    std::size_t i = 0;
    for(std::size_t j = c.closed ? 0 : 1; j < parts; ++j)
    {
      if(j == 0) { out.push_back(vertex_location(c.vertices[0])); continue; }
      const double target = total * (double(j) / double(parts));
      while(i + 1 < m && start[i + 1] <= target) ++i;
      const double t = (length[i] > 0) ? internal::inverse_sqrt_density_integral(rho[i][0], rho[i][1], (target - start[i]) / length[i]) : 0.;
      out.push_back(edge_location(c.edges[i], c.vertices[i], t));
    }
  }
  return out;
}

} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_FEATURE_SITES_H
