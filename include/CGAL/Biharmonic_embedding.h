// Copyright (c) 2026 The Surface_voronoi_diagram authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The biharmonic embedding of a triangle mesh: vertex v goes to
// (phi_1(v)/lambda_1, ..., phi_d(v)/lambda_d) in R^d, where L phi = lambda M phi are the
// smallest non-zero eigenpairs of the cotangent Laplacian. Euclidean distance in R^d is the
// (truncated) biharmonic distance of Lipman et al.

#ifndef CGAL_BIHARMONIC_EMBEDDING_H
#define CGAL_BIHARMONIC_EMBEDDING_H

#include <CGAL/Surface_voronoi_diagram/exceptions.h>
#include <CGAL/Surface_voronoi_diagram/metric_concepts.h>
#include <CGAL/Surface_voronoi_diagram/internal/Indexed_mesh.h>
#include <CGAL/Surface_voronoi_diagram/internal/spectral/cotangent_laplacian.h>
#include <CGAL/Surface_voronoi_diagram/internal/spectral/generalized_eigensolver.h>

#include <CGAL/Default.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Polygon_mesh_processing/locate.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <chrono>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {

/// \ingroup PkgSurfaceVoronoiDiagramMetrics
/// Options of `CGAL::Biharmonic_embedding` (a plain struct, geometry-central style: CGAL 5.5's
/// list of named parameters is closed to external packages).
struct Biharmonic_options
{
  /// number of non-zero eigenpairs used, `d` (the paper's default is 10)
  std::size_t dimension = 10;
  /// relative tolerance of the Lanczos iteration
  double tolerance = 1e-10;
  /// maximum number of Lanczos restarts before `Numerical_error` is thrown
  std::size_t max_iterations = 1000;
};

} // namespace Surface_voronoi

/// \ingroup PkgSurfaceVoronoiDiagramMetrics
///
/// The biharmonic embedding of a triangle mesh, computed once at construction.
///
/// \tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
/// \tparam VertexPointMap a readable property map from vertices to 3D points;
///         default: the internal `CGAL::vertex_point` map
/// \tparam SparseSolver an Eigen-style sparse symmetric solver (`compute`, `solve`, `info`)
///         used for the shift-invert factorization; default `Eigen::SimplicialLDLT`
///
/// \cgalModels `SurfaceVoronoiEmbedding`
template <class TriangleMesh,
          class VertexPointMap = Default,
          class SparseSolver = Default>
class Biharmonic_embedding
{
public:
  typedef TriangleMesh Triangle_mesh;
  typedef Surface_voronoi::Embedding_tag Metric_category;
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  typedef typename Default::Get<VertexPointMap,
            typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>::type Vertex_point_map;
  typedef typename Default::Get<SparseSolver,
            Eigen::SimplicialLDLT<Eigen::SparseMatrix<double> > >::type Sparse_solver;
  typedef CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double> Face_location;

  /// Computes the embedding.
  /// \param tm the mesh; it must outlive nothing here: all data are copied
  /// \param options dimension and solver settings
  /// \param np optional `vertex_point_map`
  /// \throws Surface_voronoi::Input_error on an empty mesh, a degenerate face, or too few vertices
  /// \throws Surface_voronoi::Numerical_error if the eigen-solver fails
  template <class NamedParameters = CGAL::parameters::Default_named_parameters>
  Biharmonic_embedding(const TriangleMesh& tm,
                       const Surface_voronoi::Biharmonic_options& options = Surface_voronoi::Biharmonic_options(),
                       const NamedParameters& np = CGAL::parameters::default_values())
    : m_options(options)
  {
    using CGAL::parameters::choose_parameter;
    using CGAL::parameters::get_parameter;
    Vertex_point_map vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                            get_const_property_map(CGAL::vertex_point, tm));
    if(options.dimension < 1)
      throw Surface_voronoi::Input_error("the embedding dimension must be at least 1");

    const auto t0 = std::chrono::steady_clock::now();
    Surface_voronoi::internal::Indexed_mesh<TriangleMesh> mesh(tm, vpm);
    m_vertex_index = mesh.vertex_index;
    Eigen::SparseMatrix<double> L, M;
    Surface_voronoi::internal::assemble_cotangent_laplacian(mesh.points, mesh.triangles, L, M);
    const auto t1 = std::chrono::steady_clock::now();

    // One zero eigenvalue per connected component: skip all of them.
    m_zero_modes = mesh.number_of_components;
    const Eigen::Index nev = static_cast<Eigen::Index>(options.dimension + m_zero_modes);
    if(static_cast<std::size_t>(nev) >= mesh.number_of_vertices())
      throw Surface_voronoi::Input_error("the mesh has " + std::to_string(mesh.number_of_vertices())
          + " vertices and " + std::to_string(m_zero_modes) + " component(s): too few for an embedding of dimension "
          + std::to_string(options.dimension));

    Surface_voronoi::internal::Eigen_solve_result r =
      Surface_voronoi::internal::smallest_generalized_eigenpairs<Sparse_solver>(
        L, M, nev, options.tolerance, static_cast<Eigen::Index>(options.max_iterations));
    const auto t2 = std::chrono::steady_clock::now();

    m_all_eigenvalues = r.eigenvalues;
    const double lambda_first = r.eigenvalues[static_cast<Eigen::Index>(m_zero_modes)];
    const double lambda_last_zero = m_zero_modes > 0 ? r.eigenvalues[static_cast<Eigen::Index>(m_zero_modes) - 1] : 0.;
    if(!(lambda_first > 0) || !(std::abs(lambda_last_zero) < 1e-6 * lambda_first))
      throw Surface_voronoi::Numerical_error("the spectrum does not have the expected "
          + std::to_string(m_zero_modes) + " zero eigenvalue(s) (one per connected component); is the mesh degenerate?");

    const std::size_t n = mesh.number_of_vertices();
    const std::size_t d = options.dimension;
    m_eigenvalues.resize(static_cast<Eigen::Index>(d));
    m_coordinates.resize(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(d));
    for(std::size_t k = 0; k < d; ++k)
    {
      const Eigen::Index col = static_cast<Eigen::Index>(k + m_zero_modes);
      const double lambda = r.eigenvalues[col];
      m_eigenvalues[static_cast<Eigen::Index>(k)] = lambda;
      // Divide by lambda, not lambda^2: the squared distance then sums (dphi)^2 / lambda^2.
      m_coordinates.col(static_cast<Eigen::Index>(k)) = r.eigenvectors.col(col) / lambda;
    }
    m_eigenvectors = r.eigenvectors;
    m_solver_operations = r.operations;
    m_assembly_seconds = std::chrono::duration<double>(t1 - t0).count();
    m_solve_seconds = std::chrono::duration<double>(t2 - t1).count();
  }

  /// \name SurfaceVoronoiEmbedding
  /// @{
  /// the dimension `d` of the embedding space
  std::size_t dimension() const { return static_cast<std::size_t>(m_coordinates.cols()); }

  /// writes the `dimension()` coordinates of `v` to `out`
  void coordinates(vertex_descriptor v, double* out) const
  {
    const Eigen::Index i = static_cast<Eigen::Index>(get(m_vertex_index, v));
    for(Eigen::Index k = 0; k < m_coordinates.cols(); ++k)
      out[k] = m_coordinates(i, k);
  }
  /// @}

  /// the embedding of a surface point given by its face location (barycentric interpolation)
  std::vector<double> embedding(const Face_location& location, const TriangleMesh& tm) const
  {
    std::vector<double> e(dimension(), 0.), c(dimension());
    const auto h = halfedge(location.first, tm);
    const vertex_descriptor corners[3] = { source(h, tm), target(h, tm), target(next(h, tm), tm) };
    for(int k = 0; k < 3; ++k)
    {
      coordinates(corners[k], c.data());
      for(std::size_t j = 0; j < c.size(); ++j)
        e[j] += location.second[k] * c[j];
    }
    return e;
  }

  /// squared biharmonic (embedding) distance between two vertices
  double squared_distance(vertex_descriptor u, vertex_descriptor v) const
  {
    const Eigen::Index i = static_cast<Eigen::Index>(get(m_vertex_index, u));
    const Eigen::Index j = static_cast<Eigen::Index>(get(m_vertex_index, v));
    return (m_coordinates.row(i) - m_coordinates.row(j)).squaredNorm();
  }

  /// the `d` eigenvalues used, ascending (zero modes excluded)
  const Eigen::VectorXd& eigenvalues() const { return m_eigenvalues; }
  /// every eigenvalue computed, zero modes included
  const Eigen::VectorXd& computed_eigenvalues() const { return m_all_eigenvalues; }
  /// every eigenvector computed (M-orthonormal columns, zero modes first), rows in vertex order
  const Eigen::MatrixXd& computed_eigenvectors() const { return m_eigenvectors; }
  /// the number of zero eigenvalues skipped (= connected components)
  std::size_t number_of_zero_modes() const { return m_zero_modes; }
  /// the row of `v` in the matrices above (the order of `vertices(tm)`)
  std::size_t vertex_index(vertex_descriptor v) const { return get(m_vertex_index, v); }
  /// seconds spent assembling the matrices and solving the eigenproblem
  double assembly_seconds() const { return m_assembly_seconds; }
  double solve_seconds() const { return m_solve_seconds; }
  long number_of_solver_operations() const { return m_solver_operations; }
  const Surface_voronoi::Biharmonic_options& options() const { return m_options; }

private:
  Surface_voronoi::Biharmonic_options m_options;
  typename Surface_voronoi::internal::Indexed_mesh<TriangleMesh>::Vertex_index_map m_vertex_index;
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> m_coordinates;
  Eigen::VectorXd m_eigenvalues, m_all_eigenvalues;
  Eigen::MatrixXd m_eigenvectors;
  std::size_t m_zero_modes = 0;
  long m_solver_operations = 0;
  double m_assembly_seconds = 0, m_solve_seconds = 0;
};

} // namespace CGAL

#endif // CGAL_BIHARMONIC_EMBEDDING_H
