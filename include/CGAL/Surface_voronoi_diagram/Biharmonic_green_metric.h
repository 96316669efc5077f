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
// The biharmonic distance with its whole spectrum, from the Green's function of the
// biharmonic operator: one column per site, by two solves with the cotangent Laplacian.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_BIHARMONIC_GREEN_METRIC_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_BIHARMONIC_GREEN_METRIC_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/biharmonic_dimension.h>
#include <CGAL/Surface_voronoi_diagram/exceptions.h>
#include <CGAL/Surface_voronoi_diagram/parameters.h>
#include <CGAL/Surface_voronoi_diagram/Prepared_mesh.h>
#include <CGAL/Surface_voronoi_diagram/metric_concepts.h>
#include <CGAL/Surface_voronoi_diagram/internal/Indexed_mesh.h>
#include <CGAL/Surface_voronoi_diagram/internal/Input_validation.h>
#include <CGAL/Surface_voronoi_diagram/internal/Site_locator.h>
#include <CGAL/Surface_voronoi_diagram/internal/parallel.h>
#include <CGAL/Surface_voronoi_diagram/internal/Spectral/Biharmonic_green_function.h>

#include <CGAL/assertions.h>
#include <CGAL/Default.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {

/// \ingroup PkgSurfaceVoronoiDiagramMetrics
/// The biharmonic distance \cgalCite{cgal:lrf-bd-10} with its whole spectrum: the limit of
/// `CGAL::Biharmonic_embedding` as its dimension grows to the number of vertices, computed
/// without eigenvectors. With \f$ g \f$ the Green's function of the biharmonic operator,
/// \f$ g(x, y) = \sum_{\lambda_k > 0} \phi_k(x) \phi_k(y) / \lambda_k^2 \f$, the squared
/// distance is \f$ d^2(x, s) = g(x, x) + g(s, s) - 2 g(x, s) \f$ (the reference paper's
/// second form, \cgalCite{cgal:bddvd} section 3.2). The column \f$ g(\cdot, s) \f$ of a
/// site takes two solves with the cotangent Laplacian, factorized once at construction;
/// inside a face, as for the embedding, everything is interpolated linearly, so that the
/// diagram's cuts are those of the embedding of full dimension.
///
/// <b>When to use it.</b> An embedding of dimension \f$ d \f$ does not tell apart cells
/// smaller than its shortest wavelength (`biharmonic_resolved_sites()`): with thousands of
/// sites, cells come out in pieces or wrapped around thin parts, and the dimension it would
/// take costs more than this metric. The `surface_voronoi` program's `--dimension auto`
/// picks this metric whenever its columns fit in 2 GiB
/// (`biharmonic_full_spectrum_for_sites()`). It does not make the biharmonic distance a
/// length metric: around a rod thinner than the cells, cells still come out as rings (see the
/// manual's section on the full spectrum).
///
/// <b>Values.</b> `squared_distance(i, v)` returns \f$ d^2(v, s_i) - \min_j d^2(v, s_j) \f$:
/// the squared distance in excess of that of the nearest site. The diagram only compares
/// sites at one point, which the term \f$ \min_j d^2(v, s_j) \f$ common to all of them does not
/// change, and the Green's function's diagonal \f$ g(v, v) \f$ it removes would take two solves
/// per vertex. Power weights are in these squared units, those of \f$ g \f$ (area squared).
/// For the same reason a diagram's `energy()` with this metric is not the biharmonic
/// centroidal energy: at a vertex of its own cell a site's value is zero, and what is left is
/// the excess of the interpolated values inside faces that cells cut (Lloyd's energies from
/// this metric need not decrease).
///
/// <b>Cost.</b> Memory: one column of `num_vertices(tm)` doubles per site (3,000 sites on a
/// mesh of 20,000 vertices: 480 MB), bounded by the named parameter `maximum_column_memory`
/// (4 GiB by default: more sites are an `Input_error`). A new set of sites frees the columns
/// it does not reuse before computing its own, so Lloyd relaxation holds one set at a time. Time: two solves per new site, in blocks of 16 sites
/// that share each pass over the factor, on every core with `CGAL::Parallel_tag`. Columns
/// are kept from one `set_sites()` to the next for the sites that did not move (Lloyd
/// relaxation moves them all; adding sites until the dual is valid moves a few).
///
/// \tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
/// \tparam VertexPointMap a model of `ReadablePropertyMap` from vertices to points; default:
///         the mesh's internal `CGAL::vertex_point` map
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` (the default), `CGAL::Parallel_tag` or
///         `CGAL::Parallel_if_available_tag`: whether `set_sites()` solves on every core. The
///         values are the same bit for bit either way.
///
/// \cgalModels `SurfaceVoronoiLazyMetric`
template <class TriangleMesh, class VertexPointMap = Default, class ConcurrencyTag = CGAL::Sequential_tag>
class Biharmonic_green_metric
{
  typedef internal::Indexed_mesh<TriangleMesh> Indexed;
  typedef internal::Biharmonic_green_function Green_function;
  typedef std::array<double, 4> Key;   // face index and barycentric coordinates
  typedef std::shared_ptr<const std::vector<double> > Column;

public:
  /// \name Types
  /// @{

  /// the mesh type
  typedef TriangleMesh Triangle_mesh;
  /// `Lazy_metric_tag`
  typedef Lazy_metric_tag Metric_category;
  /// a vertex of the mesh
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  /// the vertex point map: `VertexPointMap`, or by default the mesh's internal
  /// `CGAL::vertex_point` map
  typedef typename Default::Get<VertexPointMap,
            typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>::type Vertex_point_map;
  /// a point in a face: the face and barycentric coordinates
  typedef CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double> Face_location;
  /// @}

  /// Assembles the cotangent Laplacian of `tm` and factorizes it (one vertex of each
  /// connected component held fixed). The mesh must stay alive, and unchanged, while the
  /// metric is used.
  ///
  /// \param tm the mesh
  /// \param np an optional sequence of named parameters among the ones listed below
  ///
  /// \cgalNamedParamsBegin
  ///   \cgalParamNBegin{vertex_point_map}
  ///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
  ///     \cgalParamType{`Vertex_point_map`}
  ///     \cgalParamDefault{`get_const_property_map(CGAL::vertex_point, tm)`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{Surface_voronoi::parameters::prepared_mesh}
  ///     \cgalParamDescription{the mesh prepared once, shared with the other calls given it}
  ///     \cgalParamType{`Surface_voronoi::Prepared_mesh<TriangleMesh, C>`, `C` any concurrency tag}
  ///     \cgalParamDefault{the mesh prepared by this call}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{maximum_column_memory}
  ///     \cgalParamDescription{the most memory, in bytes, that the columns of the sites of one
  ///                           `set_sites()` may take (`biharmonic_green_metric_bytes()`): more
  ///                           sites are an `Input_error`, not an allocation that fails or
  ///                           exhausts the machine}
  ///     \cgalParamType{`double`}
  ///     \cgalParamDefault{4 GiB}
  ///   \cgalParamNEnd
  /// \cgalNamedParamsEnd
  ///
  /// \pre `tm` is a valid polygon mesh without faces of zero area, with fewer than
  ///      \f$ 2^{32} - 1 \f$ vertices and faces
  /// \throws Input_error in every build if a face of `tm` is not a triangle or a vertex has a
  ///         coordinate that is not a finite number (the message names the face or vertex, by
  ///         its position in `faces(tm)` or `vertices(tm)`)
  /// \throws Numerical_error if the Laplacian cannot be factorized (degenerate faces)
  template <class NamedParameters = CGAL::parameters::Default_named_parameters>
  explicit Biharmonic_green_metric(const TriangleMesh& tm, const NamedParameters& np = CGAL::parameters::default_values())
  {
    const Vertex_point_map vpm = CGAL::parameters::choose_parameter(
        CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm));
    m_maximum_bytes = CGAL::parameters::choose_parameter(
        CGAL::parameters::get_parameter(np, Surface_voronoi::internal_np::maximum_column_memory), 4294967296.);
    CGAL_precondition_msg(m_maximum_bytes >= 0, "maximum_column_memory must not be negative");
    m_mesh = internal::shared_or_new_indexed_mesh(internal::prepared_mesh_of<TriangleMesh>(np).indexed_mesh(), tm, vpm);
    internal::throw_non_finite_points(*m_mesh);   // (the copy refuses faces that are not triangles)
    auto green = std::make_shared<Green_function>();
    if(!green->build(m_mesh->points, m_mesh->triangles, m_mesh->face_component, m_mesh->number_of_components))
      throw Numerical_error("Biharmonic_green_metric: the cotangent Laplacian is not positive definite once a vertex of "
                            "each component is fixed; is the mesh degenerate?");
    m_green = green;
  }

  /// the mesh the metric was built on
  const Triangle_mesh& triangle_mesh() const { return *m_mesh->source_mesh; }

  /// Takes these sites: the columns of the sites kept from the previous call (same face,
  /// same barycentric coordinates) are reused, those of the others computed. The columns of
  /// the previous sites that are not reused are freed before the new ones are computed.
  /// \throws Input_error if a site is not in a face of the mesh, or if the columns of
  ///         `sites` would take more than `maximum_column_memory`; the metric is then
  ///         unchanged
  void set_sites(const std::vector<Face_location>& sites)
  {
    const double bytes = biharmonic_green_metric_bytes(m_mesh->number_of_vertices(), sites.size());
    if(bytes > m_maximum_bytes)
      throw Input_error("Biharmonic_green_metric: the columns of " + std::to_string(sites.size()) + " sites on "
                        + std::to_string(m_mesh->number_of_vertices()) + " vertices would take "
                        + std::to_string(static_cast<long long>(std::ceil(bytes / 1048576.))) + " MiB, more than the "
                        + std::to_string(static_cast<long long>(m_maximum_bytes / 1048576.))
                        + " MiB of maximum_column_memory");
    const internal::Site_locator<TriangleMesh> locator(triangle_mesh(), *m_mesh, std::numeric_limits<double>::infinity());
    std::vector<Key> keys(sites.size());
    std::vector<Green_function::Point> points(sites.size());
    for(std::size_t i = 0; i < sites.size(); ++i)
    {
      const std::size_t f = locator.locate(sites[i], i).face;
      keys[i] = { double(f), sites[i].second[0], sites[i].second[1], sites[i].second[2] };
      for(int k = 0; k < 3; ++k)
      {
        points[i].corners[k] = m_mesh->triangles[f][k];
        points[i].weights[k] = sites[i].second[k];
      }
    }
    std::map<Key, std::size_t> kept;
    for(std::size_t i = 0; i < m_keys.size(); ++i) kept.emplace(m_keys[i], i);
    std::vector<Column> columns(sites.size());
    std::vector<double> self(sites.size(), 0.);
    std::vector<std::size_t> missing;
    for(std::size_t i = 0; i < sites.size(); ++i)
    {
      const auto at = kept.find(keys[i]);
      if(at != kept.end())
      {
        columns[i] = m_columns[at->second];
        self[i] = m_self[at->second];
      }
      else
        missing.push_back(i);
    }
    // the columns not reused go before the new ones come (Lloyd moves every site: the peak
    // would otherwise be twice the columns)
    m_columns.clear();
    m_keys.clear();
    m_self.clear();
    compute_columns(points, missing, columns, self);
    m_columns = std::move(columns);
    m_self = std::move(self);
    m_keys = std::move(keys);
    compute_offset(points);
  }

  /// the squared biharmonic distance between site `i` and vertex `v`, minus the smallest one
  /// of any site to `v` (see the class's description)
  /// \pre `set_sites()` was called
  /// \throws Input_error if `i` is not a site index
  double squared_distance(std::size_t i, vertex_descriptor v)
  {
    return indexed_squared_distance(i, get(m_mesh->vertex_index, v));
  }

  /// the number of columns of the Green's function computed since construction: two
  /// solves each
  std::size_t number_of_computed_columns() const { return m_computed; }

  /// the mesh as the metric prepared it, which the diagrams built with it share
  Prepared_mesh<TriangleMesh> prepared_mesh() const { return Prepared_mesh<TriangleMesh>(m_mesh); }

  /// `squared_distance(i, v)` for the `k`-th vertex `v` in the order of `vertices(tm)`
  /// \pre `set_sites()` was called
  /// \throws Input_error if `i` is not a site index or `k` not a vertex index
  double indexed_squared_distance(std::size_t i, std::size_t k)
  {
    if(i >= m_columns.size())
      throw Input_error("Biharmonic_green_metric: " + std::to_string(i) + " is not a site index");
    if(k >= m_mesh->number_of_vertices()) throw Input_error("Biharmonic_green_metric: the vertex is not a vertex of the mesh");
    // exactly zero for the nearest site: fl(a - b) = -fl(b - a)
    const double d = (m_self[i] - 2 * (*m_columns[i])[k]) + m_offset[k];
    return d > 0 ? d : 0.;
  }

private:
  // the columns of the sites `missing`, in blocks of the Green's function's block size, runs
  // of blocks concurrently with a parallel tag; each column depends on its site only
  void compute_columns(const std::vector<Green_function::Point>& points, const std::vector<std::size_t>& missing,
                       std::vector<Column>& columns, std::vector<double>& self)
  {
    const std::size_t block = Green_function::block_size;
    const std::size_t n = m_mesh->number_of_vertices();
    const Green_function& green = *m_green;
    // a run of 8 blocks reuses its buffers (n * 16 doubles each)
    internal::for_each_chunk(missing.size(), 8 * block, internal::use_threads<ConcurrencyTag>(),
                             [&](std::size_t run_begin, std::size_t run_end, std::size_t) {
      std::vector<double> X, workspace;
      for(std::size_t begin = run_begin; begin < run_end; begin += block)
      {
        const std::size_t end = (std::min)(run_end, begin + block);
        Green_function::Point block_points[block];
        std::shared_ptr<std::vector<double> > made[block];
        double* outputs[block];
        double values[block];
        for(std::size_t k = begin; k < end; ++k)
        {
          block_points[k - begin] = points[missing[k]];
          made[k - begin] = std::make_shared<std::vector<double> >(n, 0.);
          outputs[k - begin] = made[k - begin]->data();
        }
        green.columns(block_points, end - begin, outputs, values, X, workspace);
        for(std::size_t k = begin; k < end; ++k)
        {
          columns[missing[k]] = std::move(made[k - begin]);
          self[missing[k]] = values[k - begin];
        }
      }
    });
    m_computed += missing.size();
  }

  // min_j d^2(v, s_j) - g(v, v) = -max_j (2 g(v, s_j) - g(s_j, s_j)), over the sites of v's
  // component (zero where there is none)
  void compute_offset(const std::vector<Green_function::Point>& points)
  {
    const Green_function& green = *m_green;
    const std::size_t n = m_mesh->number_of_vertices();
    std::vector<double> largest(n, -std::numeric_limits<double>::infinity());
    for(std::size_t i = 0; i < m_columns.size(); ++i)
    {
      const std::vector<double>& column = *m_columns[i];
      const std::size_t c = green.component(points[i].corners[0]);
      for(const std::size_t* v = green.members_begin(c); v != green.members_end(c); ++v)
        largest[*v] = (std::max)(largest[*v], 2 * column[*v] - m_self[i]);
    }
    m_offset.resize(n);
    for(std::size_t v = 0; v < n; ++v)
      m_offset[v] = (largest[v] == -std::numeric_limits<double>::infinity()) ? 0. : largest[v];
  }

  std::shared_ptr<const Indexed> m_mesh;                 // immutable: shared by copies
  std::shared_ptr<const Green_function> m_green;         // immutable: shared by copies
  std::vector<Column> m_columns;                         // immutable columns: copies may share them
  std::vector<double> m_self;                            // g(s_i, s_i)
  std::vector<Key> m_keys;
  std::vector<double> m_offset;                         // max_j (2 g(v, s_j) - g(s_j, s_j))
  std::size_t m_computed = 0;
  double m_maximum_bytes = 0;
};

} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_BIHARMONIC_GREEN_METRIC_H
