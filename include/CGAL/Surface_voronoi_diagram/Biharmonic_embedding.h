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
// The biharmonic embedding of a triangle mesh (\cgalCite{cgal:lrf-bd-10}): vertex v goes to
// (phi_1(v)/lambda_1, ..., phi_d(v)/lambda_d) in R^d, where L phi = lambda M phi are the
// smallest non-zero eigenpairs of the cotangent Laplacian, so that Euclidean distance in
// R^d is the (truncated) biharmonic distance.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_BIHARMONIC_EMBEDDING_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_BIHARMONIC_EMBEDDING_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/disable_warnings.h>

#include <CGAL/Surface_voronoi_diagram/biharmonic_dimension.h>
#include <CGAL/Surface_voronoi_diagram/exceptions.h>
#include <CGAL/Surface_voronoi_diagram/metric_concepts.h>
#include <CGAL/Surface_voronoi_diagram/parameters.h>
#include <CGAL/Surface_voronoi_diagram/Prepared_mesh.h>
#include <CGAL/Surface_voronoi_diagram/internal/Indexed_mesh.h>
#include <CGAL/Surface_voronoi_diagram/internal/Input_validation.h>
#include <CGAL/Surface_voronoi_diagram/internal/callback.h>
#include <CGAL/Surface_voronoi_diagram/internal/Stage_times.h>
#include <CGAL/Surface_voronoi_diagram/internal/parallel.h>
#include <CGAL/Surface_voronoi_diagram/internal/Spectral/cotangent_laplacian.h>
#include <CGAL/Surface_voronoi_diagram/internal/Spectral/generalized_eigensolver.h>

#include <CGAL/assertions.h>
#include <CGAL/Default.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {

/// \ingroup PkgSurfaceVoronoiDiagramMetrics
///
/// The biharmonic embedding of a triangle mesh \cgalCite{cgal:lrf-bd-10}, computed once at
/// construction: the metric of the reference paper \cgalCite{cgal:bddvd}. Vertex \f$ v \f$ is
/// embedded at \f$ (\phi_1(v)/\lambda_1, \dots, \phi_d(v)/\lambda_d) \f$, where
/// \f$ L \phi_k = \lambda_k M \phi_k \f$ are the \f$ d \f$ smallest non-zero eigenpairs of the
/// cotangent Laplacian (one zero eigenvalue per connected component is skipped), so that the
/// squared Euclidean distance of two embedded points is their truncated squared biharmonic
/// distance. On a mesh of several components the zero modes are known (each component's
/// indicator) and deflated: the eigen-solver is asked only for the \f$ d \f$ non-zero
/// eigenpairs, so that an assembly of a hundred parts and more works like one part.
///
/// <b>Units.</b> The embedding scales like the mesh, but its squared distances are smaller than
/// squared lengths, by a ratio that depends on \f$ d \f$, varies over the mesh, and differs
/// from one direction to another where \f$ d \f$ is low against the size of a part (around a
/// limb, say). Power weights are in these squared units:
/// `Surface_voronoi::weight_for_length()` gives the weight for a length at a site, measured
/// around that site.
///
/// \tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
/// \tparam VertexPointMap a model of `ReadablePropertyMap` from vertices to points;
///         default: the mesh's internal `CGAL::vertex_point` map
/// \tparam GeomTraits a model of `Kernel`; default: the kernel of the point type
/// \tparam LA a model of `SparseLinearAlgebraWithFactorTraits_d` for the shift-invert
///         factorization of \f$ L - \sigma M \f$ (symmetric positive definite); default:
///         `CGAL::Eigen_solver_traits` over `Eigen::SimplicialLLT` in the fill-reducing order
///         `Eigen::AMDOrdering<int>`, or `Eigen::MetisOrdering<int>` from a hundred thousand
///         vertices when the macro `CGAL_METIS_ENABLED` is defined (CGAL's METIS support,
///         `CGAL::METIS_support`, defines it; so does the package's CMake target when it finds
///         METIS). On large meshes a supernodal
///         factorization is faster: CHOLMOD's through Eigen's `CholmodSupport`, as
///         `CGAL::Eigen_solver_traits<Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double> > >`
///         (see the example `biharmonic_cholmod.cpp`). Its dense blocks go through the BLAS,
///         whose rounding may change with the number of BLAS threads: a program that wants
///         the same embedding whatever the thread count runs the BLAS on one thread.
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` (the default), `CGAL::Parallel_tag` or
///         `CGAL::Parallel_if_available_tag`: with threads (TBB), the indexed copy of the mesh
///         is built on all cores; the eigen-solver runs on one thread.
///
/// \cgalModels `SurfaceVoronoiEmbedding`
template <class TriangleMesh,
          class VertexPointMap = Default,
          class GeomTraits = Default,
          class LA = Default,
          class ConcurrencyTag = CGAL::Sequential_tag>
class Biharmonic_embedding
{
public:
  /// \name Types
  /// @{

  /// the mesh type
  typedef TriangleMesh Triangle_mesh;
  /// `Surface_voronoi::Embedding_tag`
  typedef Surface_voronoi::Embedding_tag Metric_category;
  /// a vertex of the mesh
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  /// a face of the mesh
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  /// the vertex point map: `VertexPointMap`, or by default the mesh's internal
  /// `CGAL::vertex_point` map
  typedef typename Default::Get<VertexPointMap,
            typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>::type Vertex_point_map;
  /// the geometric traits: `GeomTraits`, or by default the kernel of the points of
  /// `Vertex_point_map` (the embedding itself is computed in `double`)
  typedef typename Default::Get<GeomTraits,
            typename Kernel_traits<typename boost::property_traits<Vertex_point_map>::value_type>::Kernel>::type Geom_traits;
  /// the linear algebra traits: `LA`, or by default `CGAL::Eigen_solver_traits` over
  /// Eigen's simplicial Cholesky factorization (see the template parameter `LA`)
  typedef typename Default::Get<LA, Surface_voronoi::internal::Default_eigen_LA>::type Linear_algebra_traits;
  /// a point in a face: the face and barycentric coordinates
  typedef CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double> Face_location;
  /// @}

  /// Computes the embedding of `tm`.
  ///
  /// \param tm the mesh; it must stay alive while the embedding is used
  /// \param np an optional sequence of named parameters among the ones listed below
  ///
  /// \cgalNamedParamsBegin
  ///   \cgalParamNBegin{vertex_point_map}
  ///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
  ///     \cgalParamType{`VertexPointMap`}
  ///     \cgalParamDefault{`get_const_property_map(CGAL::vertex_point, tm)`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{geom_traits}
  ///     \cgalParamDescription{an instance of the geometric traits}
  ///     \cgalParamType{`Geom_traits`}
  ///     \cgalParamDefault{a default-constructed `Geom_traits`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{Surface_voronoi::parameters::embedding_dimension}
  ///     \cgalParamDescription{the number `d` of non-zero eigenpairs used}
  ///     \cgalParamType{`std::size_t`}
  ///     \cgalParamDefault{10 (the paper's)}
  ///     \cgalParamExtra{at most `maximum_dimension(tm)`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{Surface_voronoi::parameters::eigen_tolerance}
  ///     \cgalParamDescription{the relative tolerance of the Lanczos iteration}
  ///     \cgalParamType{`double`}
  ///     \cgalParamDefault{`1e-10`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{Surface_voronoi::parameters::max_eigen_solver_restarts}
  ///     \cgalParamDescription{the most Lanczos restarts before `Surface_voronoi::Numerical_error` is thrown}
  ///     \cgalParamType{`std::size_t`}
  ///     \cgalParamDefault{1000}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{Surface_voronoi::parameters::prepared_mesh}
  ///     \cgalParamDescription{the mesh prepared once, shared with the other calls given it}
  ///     \cgalParamType{`Surface_voronoi::Prepared_mesh<TriangleMesh, C>`, `C` any concurrency tag}
  ///     \cgalParamDefault{the mesh prepared by this call}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{Surface_voronoi::parameters::stage_times}
  ///     \cgalParamDescription{receives the seconds of the stages `"assembly"` and `"solve"` (see `Surface_voronoi::Stage_times`)}
  ///     \cgalParamType{`Surface_voronoi::Stage_times*`}
  ///     \cgalParamDefault{`nullptr`: nothing is timed}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{callback}
  ///     \cgalParamDescription{called from time to time with the fraction of the work done (in
  ///       [0, 1]) for progress reports; returning `false` stops the computation, which returns
  ///       normally: the embedding is then `is_cancelled()` and must not be given to a diagram}
  ///     \cgalParamType{a callable `bool(double)`}
  ///     \cgalParamDefault{none}
  ///   \cgalParamNEnd
  /// \cgalNamedParamsEnd
  ///
  /// \pre `tm` is a valid polygon mesh without faces of zero area
  /// \pre `1 <= d <= maximum_dimension(tm)`
  /// \throws Surface_voronoi::Input_error in every build if a face of `tm` is not a triangle or
  ///         a vertex has a coordinate that is not a finite number (the message names the
  ///         face or vertex, by its position in `faces(tm)` or `vertices(tm)`)
  /// \throws Surface_voronoi::Input_error in every build if `d > maximum_dimension(tm)` (the
  ///         message names the maximum); the library does not lower `d` by itself (the
  ///         `surface_voronoi` program lowers its default of 10 to the maximum, with a note)
  /// \throws Surface_voronoi::Numerical_error if the eigen-solver fails
  template <class NamedParameters = CGAL::parameters::Default_named_parameters>
  explicit Biharmonic_embedding(const TriangleMesh& tm,
                                const NamedParameters& np = CGAL::parameters::default_values())
  {
    using CGAL::parameters::choose_parameter;
    using CGAL::parameters::get_parameter;
    using CGAL::parameters::is_default_parameter;
    namespace SVnp = Surface_voronoi::internal_np;
    const Vertex_point_map vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                                  get_const_property_map(CGAL::vertex_point, tm));
    const std::size_t dimension = choose_parameter(get_parameter(np, SVnp::embedding_dimension), std::size_t(10));
    const double tolerance = choose_parameter(get_parameter(np, SVnp::eigen_tolerance), 1e-10);
    const std::size_t restarts = choose_parameter(get_parameter(np, SVnp::max_eigen_solver_restarts), std::size_t(1000));
    Surface_voronoi::Stage_times* times =
        choose_parameter(get_parameter(np, SVnp::stage_times), static_cast<Surface_voronoi::Stage_times*>(nullptr));
    const std::function<bool(double)> callback = Surface_voronoi::internal::callback_of(np);
    compute(tm, vpm, Surface_voronoi::internal::prepared_mesh_of<TriangleMesh>(np).indexed_mesh(), dimension, tolerance, restarts,
            callback, times);
  }

  /// the largest dimension `tm` allows: its number of vertices minus its number of connected
  /// components (one zero eigenvalue each) minus one
  static std::size_t maximum_dimension(const TriangleMesh& tm) { return maximum_dimension(Surface_voronoi::Prepared_mesh<TriangleMesh>(tm)); }

  /// the largest dimension the mesh of `mesh` allows (see above), without preparing it again
  template <class ConcurrencyTag_>
  static std::size_t maximum_dimension(const Surface_voronoi::Prepared_mesh<TriangleMesh, ConcurrencyTag_>& mesh)
  {
    const std::size_t used = mesh.indexed_mesh()->number_of_components + 1, n = mesh.indexed_mesh()->number_of_vertices();
    return n > used ? n - used : 0;
  }

  /// \name SurfaceVoronoiEmbedding
  /// @{

  /// the mesh the embedding was computed on
  const Triangle_mesh& triangle_mesh() const { return *m_mesh->source_mesh; }

  /// the dimension `d` of the embedding space (0 if the computation was cancelled)
  std::size_t dimension() const { return static_cast<std::size_t>(m_coordinates.cols()); }

  /// writes the `dimension()` coordinates of `v` to `out`
  template <class OutputIterator>
  OutputIterator coordinates(vertex_descriptor v, OutputIterator out) const
  {
    const Eigen::Index i = static_cast<Eigen::Index>(vertex_index(v));
    for(Eigen::Index k = 0; k < m_coordinates.cols(); ++k)
      *out++ = m_coordinates(i, k);
    return out;
  }
  /// @}

  /// whether the `callback` named parameter stopped the computation; the embedding then has
  /// no coordinates and must not be used
  bool is_cancelled() const { return m_cancelled; }

  /// the embedding of a surface point given by its face location (barycentric interpolation)
  std::vector<double> embedding(const Face_location& location) const
  {
    std::vector<double> e(dimension(), 0.), c(dimension());
    const TriangleMesh& tm = triangle_mesh();
    const auto h = halfedge(location.first, tm);
    const vertex_descriptor corners[3] = { source(h, tm), target(h, tm), target(next(h, tm), tm) };
    for(int k = 0; k < 3; ++k)
    {
      coordinates(corners[k], c.begin());
      for(std::size_t j = 0; j < c.size(); ++j)
        e[j] += location.second[k] * c[j];
    }
    return e;
  }

  /// squared biharmonic (embedding) distance between two vertices
  double squared_distance(vertex_descriptor u, vertex_descriptor v) const
  {
    const Eigen::Index i = static_cast<Eigen::Index>(vertex_index(u));
    const Eigen::Index j = static_cast<Eigen::Index>(vertex_index(v));
    return (m_coordinates.row(i) - m_coordinates.row(j)).squaredNorm();
  }

  /// the `d` eigenvalues used, ascending (zero modes excluded)
  const Eigen::VectorXd& eigenvalues() const { return m_eigenvalues; }
  /// every eigenvalue computed, zero modes included
  const Eigen::VectorXd& computed_eigenvalues() const { return m_all_eigenvalues; }
  /// every eigenvector computed (M-orthonormal columns, zero modes first: on a mesh of several
  /// components, each component's indicator, M-normalized), rows in vertex order
  const Eigen::MatrixXd& computed_eigenvectors() const { return m_eigenvectors; }
  /// the number of zero eigenvalues skipped (= connected components)
  std::size_t number_of_zero_modes() const { return m_zero_modes; }
  /// the row of `v` in the matrices above (the order of `vertices(tm)`)
  std::size_t vertex_index(vertex_descriptor v) const { return get(m_mesh->vertex_index, v); }

  /// the mesh as the embedding prepared it, which the diagrams built with it share
  Surface_voronoi::Prepared_mesh<TriangleMesh> prepared_mesh() const { return Surface_voronoi::Prepared_mesh<TriangleMesh>(m_mesh); }

private:
  void compute(const TriangleMesh& tm, const Vertex_point_map& vpm,
               const std::shared_ptr<const Surface_voronoi::internal::Indexed_mesh<TriangleMesh> >& given,
               std::size_t dimension, double tolerance,
               std::size_t restarts, const std::function<bool(double)>& callback,
               Surface_voronoi::Stage_times* times)
  {
    namespace SVi = Surface_voronoi::internal;
    CGAL_precondition_msg(dimension >= 1, "the embedding dimension must be at least 1");
    SVi::Stage_timer timer(times);
    // (the copy refuses faces that are not triangles)
    const auto mesh = SVi::shared_or_new_indexed_mesh(given, tm, vpm, SVi::use_threads<ConcurrencyTag>());
    SVi::throw_non_finite_points(*mesh);
    m_mesh = mesh;
    Eigen::SparseMatrix<double> L, M;
    SVi::assemble_cotangent_laplacian(mesh->points, mesh->triangles, L, M);
    timer.stop("assembly");

    // One zero eigenvalue per connected component: skip all of them. With one component the
    // eigen-solver finds it with the others; with several, their eigenvectors (the components'
    // indicators) are known, and the solver works in the complement of their span: a cluster
    // of a hundred zero eigenvalues at the shift is more than a Lanczos run resolves.
    m_zero_modes = mesh->number_of_components;
    const bool known_zero_modes = m_zero_modes > 1;
    const Eigen::Index nev = static_cast<Eigen::Index>(dimension + (known_zero_modes ? 0 : m_zero_modes));
    CGAL_precondition_msg(dimension + m_zero_modes < mesh->number_of_vertices(),
                          "the mesh has too few vertices for an embedding of this dimension (see maximum_dimension())");
    // also in release builds: the eigen-solver cannot give more eigenpairs than vertices
    if(dimension + m_zero_modes >= mesh->number_of_vertices())
    {
      const std::size_t largest = mesh->number_of_vertices() > m_zero_modes + 1 ? mesh->number_of_vertices() - m_zero_modes - 1 : 0;
      throw Surface_voronoi::Input_error("the mesh has too few vertices for an embedding of dimension " + std::to_string(dimension)
                                         + ": " + std::to_string(mesh->number_of_vertices()) + " vertices and "
                                         + std::to_string(m_zero_modes) + " component(s) allow at most "
                                         + std::to_string(largest) + " (maximum_dimension())");
    }
    if(callback && !callback(0.1)) { cancel(); return; }
    // the rounding noise of a zero eigenvalue (see below)
    const double noise = 0x1p-52 * L.diagonal().sum() / M.diagonal().sum();
    SVi::Known_null_space null_space;
    std::vector<double> component_mass;   // 1^T M 1 over each component
    if(known_zero_modes)
    {
      // a vertex's component is its faces' (a vertex in no face has a zero row in L and M,
      // which the factorization refuses before this matters)
      null_space.number_of_components = static_cast<int>(m_zero_modes);
      null_space.component.assign(mesh->number_of_vertices(), 0);
      for(std::size_t f = 0; f < mesh->triangles.size(); ++f)
        for(int k = 0; k < 3; ++k)
          null_space.component[static_cast<std::size_t>(mesh->triangles[f][k])] = static_cast<int>(mesh->face_component[f]);
      component_mass.assign(m_zero_modes, 0.);
      for(std::size_t i = 0; i < mesh->number_of_vertices(); ++i)
        component_mass[static_cast<std::size_t>(null_space.component[i])] += M.diagonal()[static_cast<Eigen::Index>(i)];
    }

    // progress during the solve: the number of operator applications, on a saturating scale
    long applications = 0;
    std::function<bool()> keep_going;
    if(callback)
      keep_going = [&]() {
        ++applications;
        return callback(0.1 + 0.85 * double(applications) / double(applications + 200));
      };
    SVi::Eigen_solve_result r;
    try
    {
      r = SVi::smallest_generalized_eigenpairs<Linear_algebra_traits>(L, M, nev, tolerance,
                                                                       static_cast<Eigen::Index>(restarts), keep_going,
                                                                       null_space);
    }
    catch(const SVi::Eigen_solve_cancelled&)
    {
      cancel();
      return;
    }
    timer.stop("solve");
    if(times)
      times->counts["eigen_operations"] += double(r.operations);

    if(known_zero_modes)
      put_known_zero_modes_first(null_space, component_mass, r);
    m_all_eigenvalues = r.eigenvalues;
    const double lambda_first = r.eigenvalues[static_cast<Eigen::Index>(m_zero_modes)];
    const double lambda_last_zero = m_zero_modes > 0 ? r.eigenvalues[static_cast<Eigen::Index>(m_zero_modes) - 1] : 0.;
    // A zero eigenvalue is computed as the Rayleigh quotient of a nearly constant vector: the
    // rows of L sum to zero only up to rounding, about 2^-52 times their diagonal, so it is
    // known to about 2^-52 trace(L) / trace(M), which caps with huge cotangents (a cap of
    // height 1e-12 in a unit square) push above 1e-6 lambda_1. Zero within that noise, with
    // lambda_1 a hundred times above it, passes too (valid input passing before is unchanged).
    // Zero modes known exactly: the smallest eigenvalue computed must stand clear of zero (a
    // component that is nearly two, for the Laplacian, has one within rounding of zero).
    const bool separated = lambda_first > 0 && std::abs(lambda_last_zero) < 1e-6 * lambda_first
                           && (!known_zero_modes || lambda_first > 100 * noise);
    const bool zero_within_noise = lambda_first > 100 * noise && std::abs(lambda_last_zero) < noise;
    if(!separated && !zero_within_noise)
      throw Surface_voronoi::Numerical_error("the spectrum does not have the expected "
          + std::to_string(m_zero_modes) + " zero eigenvalue(s) (one per connected component); is the mesh degenerate?");

    const std::size_t n = mesh->number_of_vertices();
    m_eigenvalues.resize(static_cast<Eigen::Index>(dimension));
    m_coordinates.resize(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(dimension));
    for(std::size_t k = 0; k < dimension; ++k)
    {
      const Eigen::Index col = static_cast<Eigen::Index>(k + m_zero_modes);
      const double lambda = r.eigenvalues[col];
      m_eigenvalues[static_cast<Eigen::Index>(k)] = lambda;
      // Divide by lambda, not lambda^2: the squared distance then sums (dphi)^2 / lambda^2.
      m_coordinates.col(static_cast<Eigen::Index>(k)) = r.eigenvectors.col(col) / lambda;
    }
    m_eigenvectors = std::move(r.eigenvectors);
    if(callback) callback(1.);
  }

  // the zero modes, exactly, before the computed eigenpairs: each component's indicator,
  // M-normalized, with eigenvalue 0
  void put_known_zero_modes_first(const Surface_voronoi::internal::Known_null_space& null_space,
                                  const std::vector<double>& area, Surface_voronoi::internal::Eigen_solve_result& r) const
  {
    const std::size_t n = null_space.component.size();
    const Eigen::Index c = static_cast<Eigen::Index>(m_zero_modes), d = r.eigenvalues.size();
    Eigen::VectorXd values = Eigen::VectorXd::Zero(c + d);
    values.tail(d) = r.eigenvalues;
    Eigen::MatrixXd vectors = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(n), c + d);
    for(std::size_t i = 0; i < n; ++i)
    {
      const int k = null_space.component[i];
      vectors(static_cast<Eigen::Index>(i), k) = 1 / std::sqrt(area[static_cast<std::size_t>(k)]);
    }
    vectors.rightCols(d) = r.eigenvectors;
    r.eigenvalues = std::move(values);
    r.eigenvectors = std::move(vectors);
  }

  void cancel()
  {
    m_cancelled = true;
    m_coordinates.resize(0, 0);
  }

  std::shared_ptr<const Surface_voronoi::internal::Indexed_mesh<TriangleMesh> > m_mesh;
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> m_coordinates;
  Eigen::VectorXd m_eigenvalues, m_all_eigenvalues;
  Eigen::MatrixXd m_eigenvectors;
  std::size_t m_zero_modes = 0;
  bool m_cancelled = false;
};

} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_BIHARMONIC_EMBEDDING_H
