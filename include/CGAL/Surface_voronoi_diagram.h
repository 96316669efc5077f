// Copyright (c) 2026 The Surface_voronoi_diagram authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Voronoi diagrams restricted to a triangle-mesh surface, for any metric given per vertex
// (an embedding such as the biharmonic one) or lazily per (site, vertex): SurfaceVoronoi's
// propagate-and-cut with exact per-face cutting, stitched into one consistent partition,
// with every cell checked (and repaired) to be one connected region.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_H

#include <CGAL/Biharmonic_embedding.h>
#include <CGAL/Surface_voronoi_diagram/exceptions.h>
#include <CGAL/Surface_voronoi_diagram/metric_concepts.h>
#include <CGAL/Surface_voronoi_diagram/options.h>
#include <CGAL/Surface_voronoi_diagram/parameters.h>
#include <CGAL/Surface_voronoi_diagram/internal/Indexed_mesh.h>
#include <CGAL/Surface_voronoi_diagram/internal/connectivity.h>
#include <CGAL/Surface_voronoi_diagram/internal/cutting.h>
#include <CGAL/Surface_voronoi_diagram/internal/global_nearest.h>
#include <CGAL/Surface_voronoi_diagram/internal/propagation.h>
#include <CGAL/Surface_voronoi_diagram/internal/site_fields.h>
#include <CGAL/Surface_voronoi_diagram/internal/sites.h>
#include <CGAL/Surface_voronoi_diagram/internal/stitching.h>

#include <CGAL/Default.h>
#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Polygon_mesh_processing/locate.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <memory>
#include <sstream>
#include <string>
#include <type_traits>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace CGAL {

/// \ingroup PkgSurfaceVoronoiDiagramRef
///
/// The Voronoi diagram of sites on a triangle-mesh surface under a metric given by a model
/// of `SurfaceVoronoiMetric` (typically a `SurfaceVoronoiEmbedding` such as
/// `CGAL::Biharmonic_embedding`). The diagram is computed once at construction and then
/// answers queries; outputs (the arrangement, labels) read it.
///
/// \tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
/// \tparam Metric a model of `SurfaceVoronoiMetric`
/// \tparam VertexPointMap a readable property map from vertices to 3D points
template <class TriangleMesh,
          class Metric = Biharmonic_embedding<TriangleMesh>,
          class VertexPointMap = Default>
class Surface_voronoi_diagram
{
public:
  typedef TriangleMesh Triangle_mesh;
  typedef Metric Metric_type;
  typedef boost::graph_traits<TriangleMesh> Graph_traits;
  typedef typename Graph_traits::vertex_descriptor vertex_descriptor;
  typedef typename Graph_traits::face_descriptor face_descriptor;
  typedef typename Default::Get<VertexPointMap,
            typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>::type Vertex_point_map;
  typedef typename boost::property_traits<Vertex_point_map>::value_type Point_3;
  typedef CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double> Face_location;
  typedef Surface_voronoi::internal::Partition Partition;

  /// the index returned where no site reaches
  static constexpr std::size_t no_site = std::size_t(-1);

  /// Computes the diagram.
  /// \param tm the surface; it must stay alive and unchanged while the diagram is used
  /// \param metric the metric, built on `tm` (lazy metrics are told the sites and queried)
  /// \param sites a range of `vertex_descriptor`, `Face_location` or `Point_3` (a point is
  ///        moved to the nearest surface point)
  /// \param options weights, candidate selection, repair
  /// \param np optional `vertex_point_map`, `edge_is_constrained_map` (breaklines: a
  ///        readable map edge -> bool; no cell crosses a constrained edge), and
  ///        `Surface_voronoi::parameters::site_weight_map` (power weights: a readable map from
  ///        the range's sites to `double`; if `options.weights` is given too, both must agree)
  /// \pre `tm` is a triangle mesh without degenerate faces; sites are distinct surface points
  /// \throws Surface_voronoi::Input_error for bad input, with a message naming the element
  template <class SiteRange, class NamedParameters = CGAL::parameters::Default_named_parameters>
  Surface_voronoi_diagram(const TriangleMesh& tm,
                          Metric& metric,
                          const SiteRange& sites,
                          const Surface_voronoi::Diagram_options& options = Surface_voronoi::Diagram_options(),
                          const NamedParameters& np = CGAL::parameters::default_values())
    : m_tm(&tm), m_options(options)
  {
    using CGAL::parameters::choose_parameter;
    using CGAL::parameters::get_parameter;
    using CGAL::parameters::is_default_parameter;
    const auto setup_start = std::chrono::steady_clock::now();
    m_vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                             get_const_property_map(CGAL::vertex_point, tm));
    m_mesh.build(tm, m_vpm);
    check_manifold_vertices();

    // breaklines
    m_blocked_edge.assign(m_mesh.number_of_edges(), 0);
    if(!is_default_parameter<NamedParameters, CGAL::internal_np::edge_is_constrained_t>::value)
    {
      auto ecm = choose_parameter(get_parameter(np, CGAL::internal_np::edge_is_constrained),
                                  CGAL::Constant_property_map<typename Graph_traits::edge_descriptor, bool>(false));
      for(std::size_t f = 0; f < m_mesh.number_of_faces(); ++f)
      {
        auto h = halfedge(m_mesh.face_handles[f], tm);
        for(int k = 0; k < 3; ++k, h = next(h, tm))
          if(get(ecm, edge(h, tm))) m_blocked_edge[m_mesh.edges[f][k]] = 1;
      }
      for(std::size_t e = 0; e < m_mesh.number_of_edges(); ++e)
        if(m_blocked_edge[e])
          m_corner_edge[m_mesh.edge_vertices[e][0] * m_mesh.number_of_vertices() + m_mesh.edge_vertices[e][1]] = e;
    }

    // sites
    Surface_voronoi::internal::Site_locator<TriangleMesh, Vertex_point_map> locator(tm, m_vpm, m_mesh, options.max_site_distance);
    constexpr bool has_weight_map =
        !is_default_parameter<NamedParameters, Surface_voronoi::internal_np::site_weight_map_t>::value;
    std::vector<double> map_weights;
    for(const auto& s : sites)
    {
      m_sites.push_back(locator.locate(s, m_sites.size()));
      if constexpr(has_weight_map)
        map_weights.push_back(static_cast<double>(get(get_parameter(np, Surface_voronoi::internal_np::site_weight_map), s)));
    }
    if(m_sites.empty())
      throw Surface_voronoi::Input_error("there are no sites");
    if(m_sites.size() >= std::size_t(std::numeric_limits<std::uint32_t>::max()))
      throw Surface_voronoi::Input_error("too many sites");
    if constexpr(has_weight_map)
      merge_weight_map(map_weights);
    if(!m_options.weights.empty())
    {
      if(m_options.weights.size() != m_sites.size())
        throw Surface_voronoi::Input_error("there are " + std::to_string(m_options.weights.size()) + " weights for "
                                           + std::to_string(m_sites.size()) + " sites");
      for(std::size_t i = 0; i < m_sites.size(); ++i)
      {
        if(!std::isfinite(m_options.weights[i]))
          throw Surface_voronoi::Input_error("the weight of site " + std::to_string(i) + " is not finite");
        m_sites[i].weight = m_options.weights[i];
      }
    }
    Surface_voronoi::internal::check_distinct_sites(m_mesh, m_sites);

    m_fields.reset(new Fields(m_mesh, metric, m_sites, tm));
    const double setup = std::chrono::duration<double>(std::chrono::steady_clock::now() - setup_start).count();
    compute();
    m_stats.setup_seconds = setup;
  }

  // The diagram refers to its own members internally: neither copied nor moved.
  Surface_voronoi_diagram(const Surface_voronoi_diagram&) = delete;
  Surface_voronoi_diagram& operator=(const Surface_voronoi_diagram&) = delete;

  /// \name Sites
  /// @{
  std::size_t number_of_sites() const { return m_sites.size(); }
  Face_location site_location(std::size_t i) const
  {
    return Face_location(m_mesh.face_handles[m_sites[i].face], m_sites[i].barycentric);
  }
  Point_3 site_point(std::size_t i) const
  {
    const std::array<double, 3> p = m_mesh.point_at(m_sites[i].face, m_sites[i].barycentric);
    return Point_3(p[0], p[1], p[2]);
  }
  double site_weight(std::size_t i) const { return m_sites[i].weight; }
  /// @}

  /// \name Queries
  /// @{
  /// the site whose cell contains the point; ties go to the lower site index; `no_site`
  /// where no site reaches
  std::size_t site_of(const Face_location& l) const
  {
    const std::size_t f = get(m_mesh.face_index, l.first);
    std::size_t best = no_site;
    double best_value = 0;
    for(const auto& x : m_candidates[f])
    {
      const double v = l.second[0] * x.value[0] + l.second[1] * x.value[1] + l.second[2] * x.value[2];
      if(best == no_site || v < best_value || (v == best_value && x.site < best))
      {
        best = x.site;
        best_value = v;
      }
    }
    return best;
  }

  /// the site owning vertex `v` of the input mesh (ties to the lower index)
  std::size_t site_of(vertex_descriptor v) const
  {
    return m_vertex_site[get(m_mesh.vertex_index, v)];
  }

  /// the area of the cell of site `i`
  double cell_area(std::size_t i) const { return m_cell_area[i]; }
  /// the number of connected pieces of the cell of site `i` (1 for a good cell, 0 if empty)
  std::size_t number_of_pieces(std::size_t i) const { return m_cell_pieces[i]; }
  /// the sites whose cells share a boundary segment with the cell of `i`, ascending
  const std::vector<std::size_t>& neighbors(std::size_t i) const { return m_neighbors[i]; }
  /// the area no site reaches (components without sites, regions closed off by breaklines)
  double unreached_area() const { return m_stats.unreached_area; }
  std::size_t number_of_unreached_faces() const { return m_stats.unreached_faces; }
  /// the area of the whole surface
  double surface_area() const { return m_mesh.total_area; }
  const Surface_voronoi::Diagram_statistics& statistics() const { return m_stats; }
  /// @}

  /// the area-weighted centroids of all cells in space (not on the surface), in site order;
  /// the site's own point for an empty cell
  std::vector<Point_3> cell_centroids() const
  {
    const std::size_t n = m_sites.size();
    std::vector<double> a(n, 0.), c(3 * n, 0.);
    for(const auto& p : m_partition.pieces)
    {
      if(p.site == no_site) continue;
      for_each_fan_triangle(p, [&](const std::array<double, 3>& o, const std::array<double, 3>& q,
                                   const std::array<double, 3>& r, double t) {
        a[p.site] += t;
        for(int j = 0; j < 3; ++j) c[3 * p.site + j] += t * (o[j] + q[j] + r[j]) / 3.;
      });
    }
    std::vector<Point_3> out;
    out.reserve(n);
    for(std::size_t i = 0; i < n; ++i)
      out.push_back(a[i] > 0 ? Point_3(c[3 * i] / a[i], c[3 * i + 1] / a[i], c[3 * i + 2] / a[i]) : site_point(i));
    return out;
  }

  /// the area-weighted centroid of the cell of site `i` (see `cell_centroids()`)
  Point_3 cell_centroid(std::size_t i) const { return cell_centroids()[i]; }

  /// The energy of the diagram, sum over sites of the integral over their cell of the squared
  /// distance to the site: exact for embeddings (|E(x) - E(s)|^2 is quadratic on a triangle,
  /// integrated with the edge-midpoint rule), and the integral of the linearly interpolated
  /// squared distance for lazy metrics. Weights are not subtracted.
  double energy() const
  {
    double total = 0;
    for(const auto& p : m_partition.pieces)
    {
      if(p.site == no_site) continue;
      const std::size_t f = p.face;
      auto value_at = [&](const std::array<double, 3>& x) { return squared_distance_in_face(p.site, f, x); };
      auto mid = [](const std::array<double, 3>& a, const std::array<double, 3>& b) {
        return std::array<double, 3>{{ 0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.5 * (a[2] + b[2]) }};
      };
      for_each_fan_triangle(p, [&](const std::array<double, 3>& o, const std::array<double, 3>& q,
                                   const std::array<double, 3>& r, double t) {
        if(!(t > 0)) return;
        if(Fields::is_exact())
          total += t / 3. * (value_at(mid(o, q)) + value_at(mid(q, r)) + value_at(mid(r, o)));
        else
          total += t / 3. * (value_at(o) + value_at(q) + value_at(r));
      });
    }
    return total;
  }

  /// \name Access for outputs
  /// @{
  const TriangleMesh& triangle_mesh() const { return *m_tm; }
  Vertex_point_map vertex_point_map() const { return m_vpm; }
  /// the partition: convex pieces, one site each, grouped by face; see `Partition`
  const Partition& partition() const { return m_partition; }
  face_descriptor face_handle(std::size_t face_index) const { return m_mesh.face_handles[face_index]; }
  std::size_t face_index(face_descriptor f) const { return get(m_mesh.face_index, f); }
  std::size_t number_of_faces() const { return m_mesh.number_of_faces(); }
  /// whether the partition vertices `u` and `w` both lie on one breakline edge of the mesh
  bool on_breakline(std::size_t u, std::size_t w) const
  {
    const Partition::Vertex& a = m_partition.vertices[u];
    const Partition::Vertex& b = m_partition.vertices[w];
    auto edges_of = [&](const Partition::Vertex& v, std::size_t e) {
      if(v.kind == Partition::ON_EDGE) return v.element == e;
      if(v.kind == Partition::AT_CORNER) return m_mesh.edge_vertices[e][0] == v.element || m_mesh.edge_vertices[e][1] == v.element;
      return false;
    };
    if(a.kind == Partition::IN_FACE || b.kind == Partition::IN_FACE) return false;
    const std::size_t e = (a.kind == Partition::ON_EDGE) ? a.element : (b.kind == Partition::ON_EDGE ? b.element : no_site);
    if(e != no_site) return m_blocked_edge[e] != 0 && edges_of(a, e) && edges_of(b, e);
    // two corners: the mesh edge joining them, if any
    const auto it = m_corner_edge.find((std::min)(a.element, b.element) * m_mesh.number_of_vertices() + (std::max)(a.element, b.element));
    return it != m_corner_edge.end() && m_blocked_edge[it->second] != 0;
  }
  /// the number of breakline edges of the mesh
  std::size_t number_of_breakline_edges() const
  {
    std::size_t c = 0;
    for(auto b : m_blocked_edge) c += b;
    return c;
  }
  /// the candidate sites kept for face `f` (ascending), after propagation and repair
  std::vector<std::size_t> candidates(face_descriptor f) const
  {
    std::vector<std::size_t> r;
    for(const auto& x : m_candidates[get(m_mesh.face_index, f)]) r.push_back(x.site);
    return r;
  }
  /// @}

private:
  typedef Surface_voronoi::internal::Site_fields<TriangleMesh, Metric> Fields;

  // The map's weights become `m_options.weights`, which the rest of the construction reads.
  // Both given is accepted only when they agree: silently preferring one would hide a mistake.
  void merge_weight_map(const std::vector<double>& map_weights)
  {
    for(std::size_t i = 0; i < map_weights.size(); ++i)
      if(!std::isfinite(map_weights[i]))
        throw Surface_voronoi::Input_error("the weight of site " + std::to_string(i) + " (from site_weight_map) is not finite");
    if(m_options.weights.empty())
    {
      m_options.weights = map_weights;
      return;
    }
    if(m_options.weights.size() != map_weights.size())
      throw Surface_voronoi::Input_error("Diagram_options::weights has " + std::to_string(m_options.weights.size())
                                         + " weights but site_weight_map gives one for each of the "
                                         + std::to_string(map_weights.size()) + " sites");
    for(std::size_t i = 0; i < map_weights.size(); ++i)
      if(m_options.weights[i] != map_weights[i])
      {
        std::ostringstream os;
        os.precision(17);
        os << "site " << i << " has two different weights, " << m_options.weights[i]
           << " in Diagram_options::weights and " << map_weights[i] << " from site_weight_map";
        throw Surface_voronoi::Input_error(os.str());
      }
  }

  void check_manifold_vertices() const
  {
    // The corners around a vertex must form one fan: union the corners of adjacent faces.
    const std::size_t nf = m_mesh.number_of_faces();
    std::vector<std::size_t> parent(3 * nf);
    for(std::size_t i = 0; i < parent.size(); ++i) parent[i] = i;
    auto find = [&](std::size_t x) {
      while(parent[x] != x) { parent[x] = parent[parent[x]]; x = parent[x]; }
      return x;
    };
    for(std::size_t f = 0; f < nf; ++f)
      for(int k = 0; k < 3; ++k)
      {
        const std::size_t g = m_mesh.neighbors[f][k];
        if(g == Surface_voronoi::internal::Indexed_mesh<TriangleMesh>::none) continue;
        // local edge k joins corners k and k+1; the same vertices are corners of g
        for(int c : { k, (k + 1) % 3 })
          for(int l = 0; l < 3; ++l)
            if(m_mesh.triangles[g][l] == m_mesh.triangles[f][c])
            {
              const std::size_t a = find(3 * f + c), b = find(3 * g + l);
              if(a != b) parent[(std::max)(a, b)] = (std::min)(a, b);
            }
      }
    std::vector<std::size_t> fan(m_mesh.number_of_vertices(), std::size_t(-1));
    for(std::size_t f = 0; f < nf; ++f)
      for(int k = 0; k < 3; ++k)
      {
        const std::size_t v = m_mesh.triangles[f][k];
        const std::size_t r = find(3 * f + k);
        if(fan[v] == std::size_t(-1)) fan[v] = r;
        else if(fan[v] != r)
          throw Surface_voronoi::Input_error("vertex " + std::to_string(v) + " is non-manifold: its faces form separate fans");
      }
  }

  bool blocked(std::size_t f, int k) const { return m_blocked_edge[m_mesh.edges[f][k]] != 0; }

  // calls f(o, q, r, area) for the triangles of a fan over a (convex, planar) piece
  template <class F>
  void for_each_fan_triangle(const typename Partition::Piece& p, F f) const
  {
    const auto& o = m_partition.vertices[p.vertices[0]].point;
    for(std::size_t k = 1; k + 1 < p.vertices.size(); ++k)
    {
      const auto& q = m_partition.vertices[p.vertices[k]].point;
      const auto& r = m_partition.vertices[p.vertices[k + 1]].point;
      const double u[3] = { q[0] - o[0], q[1] - o[1], q[2] - o[2] }, w[3] = { r[0] - o[0], r[1] - o[1], r[2] - o[2] };
      const double x = u[1] * w[2] - u[2] * w[1], y = u[2] * w[0] - u[0] * w[2], z = u[0] * w[1] - u[1] * w[0];
      f(o, q, r, 0.5 * std::sqrt(x * x + y * y + z * z));
    }
  }

  // barycentric coordinates of a point of face f (least-squares in the face's plane)
  std::array<double, 3> barycentric_in_face(std::size_t f, const std::array<double, 3>& x) const
  {
    const auto& a = m_mesh.points[m_mesh.triangles[f][0]];
    const auto& b = m_mesh.points[m_mesh.triangles[f][1]];
    const auto& c = m_mesh.points[m_mesh.triangles[f][2]];
    double e1[3], e2[3], d[3];
    for(int j = 0; j < 3; ++j) { e1[j] = b[j] - a[j]; e2[j] = c[j] - a[j]; d[j] = x[j] - a[j]; }
    const double g11 = e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2], g12 = e1[0] * e2[0] + e1[1] * e2[1] + e1[2] * e2[2];
    const double g22 = e2[0] * e2[0] + e2[1] * e2[1] + e2[2] * e2[2];
    const double r1 = d[0] * e1[0] + d[1] * e1[1] + d[2] * e1[2], r2 = d[0] * e2[0] + d[1] * e2[1] + d[2] * e2[2];
    const double det = g11 * g22 - g12 * g12;
    const double u = (r1 * g22 - r2 * g12) / det, v = (r2 * g11 - r1 * g12) / det;
    return {{ 1 - u - v, u, v }};
  }

  // squared distance (without weight) from site i to point x of face f: the embedding's for
  // embeddings, the interpolated corner values for lazy metrics
  double squared_distance_in_face(std::size_t i, std::size_t f, const std::array<double, 3>& x) const
  {
    const std::array<double, 3> b = barycentric_in_face(f, x);
    if constexpr(Fields::is_exact())
    {
      const std::size_t d = m_fields->dimension();
      const double* s = m_fields->site_coordinates(i);
      double total = 0;
      for(std::size_t c = 0; c < d; ++c)
      {
        double e = 0;
        for(int k = 0; k < 3; ++k) e += b[k] * m_fields->vertex_coordinates(m_mesh.triangles[f][k])[c];
        total += (e - s[c]) * (e - s[c]);
      }
      return total;
    }
    else
    {
      double total = 0;
      for(int k = 0; k < 3; ++k) total += b[k] * (m_fields->value(i, m_mesh.triangles[f][k]) + m_sites[i].weight);
      return total;
    }
  }

  void compute()
  {
    typedef std::chrono::steady_clock Clock;
    const std::size_t n = m_sites.size();
    std::vector<std::size_t> site_faces(n);
    for(std::size_t i = 0; i < n; ++i) site_faces[i] = m_sites[i].face;
    std::unordered_set<std::uint64_t> banned;
    const std::uint64_t nf = m_mesh.number_of_faces();
    auto is_banned = [&](std::size_t site, std::size_t f) {
      return !banned.empty() && banned.count(std::uint64_t(site) * nf + f) != 0;
    };
    auto is_blocked = [this](std::size_t f, int k) { return blocked(f, k); };
    auto blocked_edge = [&](std::size_t e) { return m_blocked_edge[e] != 0; };
    const bool rvd = (m_options.candidates == Surface_voronoi::Candidate_selection::GLOBAL_NEAREST);

    m_stats = Surface_voronoi::Diagram_statistics();
    m_stats.sites = n;
    m_stats.surface_area = m_mesh.total_area;

    // propagation (or the RVD's global candidates)
    auto t0 = Clock::now();
    typedef Surface_voronoi::internal::Propagation<TriangleMesh, Fields, decltype(is_blocked)> Propagation;
    Propagation propagation(m_mesh, *m_fields, site_faces, is_blocked);
    if(rvd)
    {
      if constexpr(Fields::is_exact())
        Surface_voronoi::internal::global_nearest_candidates(m_mesh, *m_fields, n, !m_options.weights.empty(),
                                                             propagation.candidates);
      else
        throw Surface_voronoi::Input_error("the restricted Voronoi diagram baseline needs an embedding metric");
    }
    else
      propagation.run();
    const std::vector<std::vector<Surface_voronoi::internal::Face_field> >& candidates = propagation.candidates;
    auto t1 = Clock::now();

    // cutting and stitching
    std::vector<Surface_voronoi::internal::Face_cut> cuts(m_mesh.number_of_faces());
    auto cut_faces = [&](const std::vector<std::size_t>* which) {
      const std::size_t count = which ? which->size() : cuts.size();
      for(std::size_t k = 0; k < count; ++k)
      {
        const std::size_t f = which ? (*which)[k] : k;
        cuts[f] = candidates[f].empty() ? Surface_voronoi::internal::Face_cut()
                                        : Surface_voronoi::internal::Face_cutter(candidates[f]).cut();
      }
    };
    cut_faces(nullptr);
    Surface_voronoi::internal::stitch(m_mesh, candidates, cuts, m_partition);
    auto t2 = Clock::now();
    m_stats.propagation_seconds = std::chrono::duration<double>(t1 - t0).count();
    m_stats.cutting_seconds = std::chrono::duration<double>(t2 - t1).count();
    m_stats.propagation_events = propagation.statistics.events;
    m_stats.admitted_fields = propagation.statistics.admitted;

    // connectivity check and repair: orphan pieces of a cell are banned for their site,
    // and the propagation is re-run locally from the neighbours of the banned faces
    Surface_voronoi::internal::Cell_components cc;
    std::vector<std::size_t> touched;
    for(std::size_t round = 0;; ++round)
    {
      cc = Surface_voronoi::internal::cell_components(m_mesh, m_partition, n, blocked_edge);
      std::size_t broken = 0;
      std::vector<std::size_t> orphan_components;
      for(std::size_t i = 0; i < n; ++i)
      {
        const std::vector<std::size_t>& comps = cc.site_components[i];
        if(comps.size() <= 1) continue;
        ++broken;
        const std::size_t principal = principal_component(i, cc);
        for(std::size_t c : comps)
          if(c != principal) orphan_components.push_back(c);
      }
      if(round == 0) m_stats.broken_cells_before_repair = broken;
      m_stats.broken_cells = broken;
      if(broken == 0 || rvd || !m_options.repair || round >= m_options.max_repair_rounds)
        break;
      std::vector<std::uint8_t> is_orphan(cc.component_site.size(), 0);
      for(std::size_t c : orphan_components) is_orphan[c] = 1;
      std::vector<std::size_t> dirty;
      for(std::size_t p = 0; p < m_partition.pieces.size(); ++p)
        if(is_orphan[cc.piece_component[p]])
        {
          const auto& piece = m_partition.pieces[p];
          banned.insert(std::uint64_t(piece.site) * nf + piece.face);
          dirty.push_back(piece.face);
        }
      std::sort(dirty.begin(), dirty.end());
      dirty.erase(std::unique(dirty.begin(), dirty.end()), dirty.end());
      propagation.repropagate(dirty, is_banned, touched);
      cut_faces(&touched);
      Surface_voronoi::internal::stitch(m_mesh, candidates, cuts, m_partition);
      m_stats.repair_rounds = round + 1;
      m_stats.banned_fields = banned.size();
    }
    m_candidates = std::move(propagation.candidates);
    summarize(cc);
    m_stats.repair_seconds = std::chrono::duration<double>(Clock::now() - t2).count();
  }

  // The component holding the site's own location; with weights a site may not own its
  // location, and then its largest component is kept.
  std::size_t principal_component(std::size_t i, const Surface_voronoi::internal::Cell_components& cc) const
  {
    const std::size_t f = m_sites[i].face;
    for(std::size_t p = m_partition.face_begin[f]; p < m_partition.face_begin[f + 1]; ++p)
      if(m_partition.pieces[p].site == i) return cc.piece_component[p];
    std::size_t best = cc.site_components[i].front();
    for(std::size_t c : cc.site_components[i])
      if(cc.component_area[c] > cc.component_area[best]) best = c;
    return best;
  }

  void summarize(const Surface_voronoi::internal::Cell_components& cc)
  {
    const std::size_t n = m_sites.size();
    m_cell_area.assign(n, 0.);
    m_cell_pieces.assign(n, 0);
    for(const auto& p : m_partition.pieces)
    {
      if(p.site == no_site) m_stats.unreached_area += p.area;
      else m_cell_area[p.site] += p.area;
    }
    for(std::size_t i = 0; i < n; ++i)
    {
      m_cell_pieces[i] = cc.site_components[i].size();
      if(m_cell_pieces[i] == 0) ++m_stats.empty_cells;
      else ++m_stats.cells;
      m_stats.pieces += m_cell_pieces[i];
    }
    std::vector<std::uint8_t> unreached_component(m_mesh.number_of_components, 0);
    std::size_t total_candidates = 0;
    for(std::size_t f = 0; f < m_mesh.number_of_faces(); ++f)
    {
      total_candidates += m_candidates[f].size();
      m_stats.max_candidates_per_face = (std::max)(m_stats.max_candidates_per_face, m_candidates[f].size());
      if(m_candidates[f].empty())
      {
        ++m_stats.unreached_faces;
        unreached_component[m_mesh.face_component[f]] = 1;
      }
    }
    for(auto u : unreached_component) m_stats.unreached_components += u;
    m_stats.mean_candidates_per_face = double(total_candidates) / double(m_mesh.number_of_faces());
    m_stats.welded_vertices = m_partition.welded_vertices;
    m_stats.inserted_vertices = m_partition.inserted_vertices;

    // vertex owners
    m_vertex_site.assign(m_mesh.number_of_vertices(), no_site);
    std::vector<double> best(m_mesh.number_of_vertices(), 0.);
    for(std::size_t f = 0; f < m_mesh.number_of_faces(); ++f)
      for(const auto& x : m_candidates[f])
        for(int k = 0; k < 3; ++k)
        {
          const std::size_t v = m_mesh.triangles[f][k];
          if(m_vertex_site[v] == no_site || x.value[k] < best[v] || (x.value[k] == best[v] && x.site < m_vertex_site[v]))
          {
            m_vertex_site[v] = x.site;
            best[v] = x.value[k];
          }
        }

    // neighbours: sites on both sides of a piece edge
    m_neighbors.assign(n, std::vector<std::size_t>());
    Surface_voronoi::internal::for_each_piece_adjacency(m_mesh, m_partition, [&](std::size_t p, std::size_t q, std::size_t) {
      const std::size_t a = m_partition.pieces[p].site, b = m_partition.pieces[q].site;
      if(a != b && a != no_site && b != no_site) { m_neighbors[a].push_back(b); m_neighbors[b].push_back(a); }
    });
    for(std::vector<std::size_t>& list : m_neighbors)
    {
      std::sort(list.begin(), list.end());
      list.erase(std::unique(list.begin(), list.end()), list.end());
    }
  }

  const TriangleMesh* m_tm;
  Surface_voronoi::Diagram_options m_options;
  Vertex_point_map m_vpm;
  Surface_voronoi::internal::Indexed_mesh<TriangleMesh> m_mesh;
  std::vector<std::uint8_t> m_blocked_edge;
  std::unordered_map<std::size_t, std::size_t> m_corner_edge;   // breakline edges by their sorted vertex pair
  std::vector<Surface_voronoi::internal::Site> m_sites;
  std::unique_ptr<Fields> m_fields;
  std::vector<std::vector<Surface_voronoi::internal::Face_field> > m_candidates;
  Partition m_partition;
  std::vector<double> m_cell_area;
  std::vector<std::size_t> m_cell_pieces;
  std::vector<std::size_t> m_vertex_site;
  std::vector<std::vector<std::size_t> > m_neighbors;
  Surface_voronoi::Diagram_statistics m_stats;
};

} // namespace CGAL

#include <CGAL/Surface_voronoi_diagram/arrangement.h>

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_H
