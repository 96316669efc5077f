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
// Smallest eigenpairs of L phi = lambda M phi (L symmetric positive semi-definite,
// M diagonal positive) by a shift-invert Lanczos iteration, factorizing with a model of
// SparseLinearAlgebraWithFactorTraits_d (as Heat_method_3 does), and with a way to cancel.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_SPECTRAL_GENERALIZED_EIGENSOLVER_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_SPECTRAL_GENERALIZED_EIGENSOLVER_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/exceptions.h>

#include <CGAL/assertions.h>
#include <CGAL/use.h>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#ifdef CGAL_METIS_ENABLED
#include <Eigen/MetisSupport>
#endif
#include <CGAL/Eigen_solver_traits.h>
#include <Spectra/SymGEigsShiftSolver.h>
#include <Spectra/Util/SimpleRandom.h>

#include <algorithm>
#include <functional>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

/// Thrown through Spectra by the operator when the caller's progress callback asks to stop
/// (Spectra has no other way out of a running solve); caught in the embedding, never seen
/// by users.
struct Eigen_solve_cancelled {};

/// The known null space of L: one zero eigenvalue per connected component, its eigenvector
/// the component's indicator (L's rows sum to zero over a component). With many components
/// (CAD assemblies: a hundred and more) a Krylov method asked for them along with the smallest
/// non-zero eigenpairs must resolve a cluster of that many eigenvalues at the shift, and fails;
/// they are known, so the solver works in the M-orthogonal complement of their span instead:
/// `project()` takes away a vector's M-weighted mean over each component. Empty (nothing
/// projected) when the caller lets the solver find the zero modes (one component).
struct Known_null_space
{
  std::vector<int> component;   // of each row; empty: no known null space
  int number_of_components = 0;

  bool empty() const { return component.empty(); }

  /// y := y - sum_c 1_c (1_c^T M y) / (1_c^T M 1_c), M diagonal given by `mass`
  void project(const double* mass, double* y) const
  {
    if(empty()) return;
    std::vector<double> weighted(static_cast<std::size_t>(number_of_components), 0.), total(weighted.size(), 0.);
    for(std::size_t i = 0; i < component.size(); ++i)
    {
      weighted[static_cast<std::size_t>(component[i])] += mass[i] * y[i];
      total[static_cast<std::size_t>(component[i])] += mass[i];
    }
    for(std::size_t c = 0; c < weighted.size(); ++c)
      weighted[c] /= total[c];
    for(std::size_t i = 0; i < component.size(); ++i)
      y[i] -= weighted[static_cast<std::size_t>(component[i])];
  }
};

/// The operator y = (A - sigma B)^{-1} x that Spectra's shift-invert mode needs, minus the
/// eigenpairs already found. Spectra's own `SymShiftInvert` factorizes with SparseLU; a
/// symmetric factorization (Cholesky by default) takes less time and memory, since
/// A - sigma B is symmetric positive definite for sigma < 0.
///
/// Deflation: a Krylov method started from one vector sees one direction per distinct
/// eigenvalue (in exact arithmetic), so repeated eigenvalues (spheres, symmetric shapes) are
/// silently missed. Spectra applies this operator to x = B v; subtracting
/// sum_k phi_k phi_k^T x / (lambda_k - sigma) maps the found eigenpairs to 0 so that a
/// further run finds the missing ones.
template <class LA>
class Shift_invert_operator
{
public:
  typedef double Scalar;

  Shift_invert_operator(const Eigen::SparseMatrix<double>& A, const Eigen::SparseMatrix<double>& B,
                        const std::function<bool()>& keep_going)
    : m_A(A), m_B(B), m_keep_going(keep_going), m_matrix(static_cast<int>(A.rows())),
      m_x(static_cast<int>(A.rows())), m_y(static_cast<int>(A.rows()))
  {}

  Eigen::Index rows() const { return m_A.rows(); }
  Eigen::Index cols() const { return m_A.cols(); }

  void set_shift(const Scalar& sigma)
  {
    if(m_factorized && sigma == m_sigma)
      return;
    const Eigen::SparseMatrix<double> C = m_A - sigma * m_B;
    assign(C, std::is_constructible<typename LA::Matrix, const Eigen::SparseMatrix<double>&>());
    double denominator = 1;
    if(!m_la.factor(m_matrix, denominator))
      throw Numerical_error("the factorization of L - sigma M failed (is the mesh degenerate?)");
    m_sigma = sigma;
    m_factorized = true;
  }

  // An Eigen-based model takes the matrix whole; any other model coefficient by coefficient.
  void assign(const Eigen::SparseMatrix<double>& C, std::true_type) { m_matrix = typename LA::Matrix(C); }
  void assign(const Eigen::SparseMatrix<double>& C, std::false_type)
  {
    m_matrix = typename LA::Matrix(static_cast<int>(C.rows()));
    for(Eigen::Index col = 0; col < C.outerSize(); ++col)
      for(Eigen::SparseMatrix<double>::InnerIterator it(C, col); it; ++it)
        m_matrix.set_coef(static_cast<int>(it.row()), static_cast<int>(it.col()), it.value(), true);
  }

  /// `vectors` is referred to, not copied (as large as the Krylov basis): it must stay
  /// unchanged while the operator is applied
  void set_deflation(const Eigen::MatrixXd& vectors, const Eigen::VectorXd& eigenvalues)
  {
    m_deflation_vectors = &vectors;
    m_deflation_weights = (eigenvalues.array() - m_sigma).inverse().matrix();
  }

  /// `null_space` and `mass` (B's diagonal; both referred to, not copied) project the
  /// null space out of every result: the operator then works in the B-orthogonal complement
  /// of A's known null space
  void set_null_space(const Known_null_space& null_space, const double* mass)
  {
    m_null_space = &null_space;
    m_mass = mass;
  }

  void perform_op(const Scalar* x, Scalar* y) const
  {
    if(m_keep_going && !m_keep_going()) throw Eigen_solve_cancelled();
    const Eigen::Index n = rows();
    for(Eigen::Index i = 0; i < n; ++i) m_x[static_cast<int>(i)] = x[i];
    if(!m_la.linear_solver(m_x, m_y))
      throw Numerical_error("the solve with the factorization of L - sigma M failed");
    for(Eigen::Index i = 0; i < n; ++i) y[i] = m_y[static_cast<int>(i)];
    if(m_deflation_vectors != nullptr && m_deflation_vectors->cols() > 0)
    {
      Eigen::Map<const Eigen::VectorXd> xv(x, n);
      Eigen::Map<Eigen::VectorXd> yv(y, n);
      const Eigen::VectorXd c = (m_deflation_vectors->transpose() * xv).cwiseProduct(m_deflation_weights);
      yv.noalias() -= *m_deflation_vectors * c;
    }
    // (A - sigma B)^{-1} B maps the null space to itself: projecting it out keeps the
    // operator self-adjoint in the B inner product, and rounding cannot bring it back
    if(m_null_space != nullptr && !m_null_space->empty())
      m_null_space->project(m_mass, y);
  }

private:
  const Eigen::SparseMatrix<double>& m_A;
  const Eigen::SparseMatrix<double>& m_B;
  std::function<bool()> m_keep_going;
  mutable LA m_la;
  typename LA::Matrix m_matrix;   // an Eigen factorization refers to it: kept alive here
  mutable typename LA::Vector m_x, m_y;
  double m_sigma = 0;
  bool m_factorized = false;
  const Eigen::MatrixXd* m_deflation_vectors = nullptr;
  Eigen::VectorXd m_deflation_weights;
  const Known_null_space* m_null_space = nullptr;
  const double* m_mass = nullptr;
};

/// The product by B (the lumped mass matrix) that Spectra's Lanczos takes several times per
/// operator application, for its B inner products: B is diagonal, and multiplying by its
/// diagonal is cheaper than a sparse product, to the same bits (each entry is one product).
class Mass_product
{
public:
  typedef double Scalar;

  /// \pre `B` is compressed with exactly entry (j, j) in column j
  explicit Mass_product(const Eigen::SparseMatrix<double>& B) : m_n(B.rows()), m_diagonal(B.valuePtr())
  {
    bool diagonal = B.isCompressed() && B.rows() == B.cols() && B.nonZeros() == B.rows();
    for(Eigen::Index j = 0; j < B.outerSize() && diagonal; ++j)
      diagonal = B.outerIndexPtr()[j] == j && B.innerIndexPtr()[j] == j;
    CGAL_precondition_msg(diagonal, "the mass matrix must be diagonal");
    CGAL_USE(diagonal);
  }

  Eigen::Index rows() const { return m_n; }
  Eigen::Index cols() const { return m_n; }

  void perform_op(const Scalar* x, Scalar* y) const
  {
    for(Eigen::Index i = 0; i < m_n; ++i) y[i] = m_diagonal[i] * x[i];
  }

private:
  Eigen::Index m_n;
  const double* m_diagonal;   // B's values
};

/// The default fill-reducing order: METIS's nested dissection for large matrices when CGAL is
/// configured with METIS (`CGAL_METIS_ENABLED`, CGAL's METIS support), Eigen's approximate
/// minimum degree otherwise. Nested dissection fills less only on large meshes; below about
/// a hundred thousand rows the minimum degree order is found faster and factorizes as fast.
struct Default_fill_reducing_ordering
{
  typedef Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> PermutationType;

  template <class MatrixType>
  void operator()(const MatrixType& A, PermutationType& order) const
  {
#ifdef CGAL_METIS_ENABLED
    if(A.rows() >= 100000)
    {
      Eigen::MetisOrdering<int>()(A, order);
      return;
    }
#endif
    Eigen::AMDOrdering<int>()(A, order);
  }
};

/// The default linear algebra: Eigen's simplicial LLT in the default fill-reducing order.
typedef CGAL::Eigen_solver_traits<Eigen::SimplicialLLT<Eigen::SparseMatrix<double>, Eigen::Lower,
                                                       Default_fill_reducing_ordering> > Default_eigen_LA;

struct Eigen_solve_result
{
  Eigen::VectorXd eigenvalues;   // ascending
  Eigen::MatrixXd eigenvectors;  // M-orthonormal columns
  long iterations = 0;
  long operations = 0;
  int rounds = 0;                // Lanczos runs (1 + deflated runs that looked for missed ones)
};

/// The error of a run that stopped with `converged` of `count` eigenpairs after `restarts`
inline Numerical_error not_converged(Eigen::Index converged, Eigen::Index count, long restarts)
{
  return Numerical_error("the eigen-solver did not converge: " + std::to_string(converged) + " of "
                         + std::to_string(count) + " eigenpairs after " + std::to_string(restarts)
                         + " restarts (try a smaller dimension, or check the mesh for degenerate triangles)");
}

/// One Lanczos run by Spectra: the `count` smallest eigenpairs,
/// from Spectra's own start vector in the first round and from a random one after.
template <class Op>
void spectra_solve(Op& op, Mass_product& bop, Eigen::Index count, Eigen::Index ncv, double sigma, double tol,
                   Eigen::Index max_iterations, int round, const Known_null_space& null_space, const double* mass,
                   Eigen::VectorXd& new_values, Eigen::MatrixXd& new_vectors, Eigen_solve_result& r)
{
  const Eigen::Index n = op.rows();
  Spectra::SymGEigsShiftSolver<Op, Mass_product, Spectra::GEigsMode::ShiftInvert> solver(op, bop, count, ncv, sigma);
  Eigen::Index converged = 0;
  try
  {
    // The first round starts from Spectra's own start vector (seed 0), in the complement of
    // the known null space. A later round must not start where the first did: the first
    // start vector's part in an eigenspace of several dimensions is the direction already
    // found there, and deflated, so a Krylov space grown from it again is blind to the other
    // copies of a repeated eigenvalue (seeds 0 and 1 are the first's).
    Spectra::SimpleRandom<double> rng(round == 0 ? 0ul : static_cast<unsigned long>(round) + 1);
    Eigen::VectorXd start = rng.random_vec(n);
    null_space.project(mass, start.data());
    solver.init(start.data());
    converged = solver.compute(Spectra::SortRule::LargestMagn, max_iterations, tol, Spectra::SortRule::SmallestAlge);
  }
  catch(const std::runtime_error& e)
  {
    // Spectra throws when a dense step meets non-finite values (its tridiagonal
    // eigen-decomposition, its QR): a numerical failure of this mesh, not a bug
    throw Numerical_error(std::string("the eigen-solver failed (") + e.what()
                          + "); check the mesh for degenerate triangles or extreme coordinates");
  }
  r.iterations += static_cast<long>(solver.num_iterations());
  r.operations += static_cast<long>(solver.num_operations());
  ++r.rounds;
  if(solver.info() != Spectra::CompInfo::Successful || converged < count)
    throw not_converged(converged, count, static_cast<long>(solver.num_iterations()));
  new_values = solver.eigenvalues();
  new_vectors = solver.eigenvectors();
  if(!new_values.allFinite() || !new_vectors.allFinite())
    throw Numerical_error("the eigen-solver returned non-finite values");
}

/// Computes the `nev` smallest eigenpairs (with a known null space, the `nev` smallest of the
/// M-orthogonal complement of its span: its zero eigenvalues are not among them). The shift
/// is negative and scaled to the mesh (eigenvalues scale as 1/size^2), so L - sigma M is
/// positive definite; a shift of exactly 0 factorizes a singular matrix and returns garbage
/// without complaint.
/// `keep_going`, if set, is asked before every application of the operator; returning
/// false throws `Eigen_solve_cancelled`.
template <class LA = Default_eigen_LA>
Eigen_solve_result smallest_generalized_eigenpairs(const Eigen::SparseMatrix<double>& L,
                                                   const Eigen::SparseMatrix<double>& M,
                                                   Eigen::Index nev,
                                                   double tolerance = 1e-10,
                                                   Eigen::Index max_iterations = 1000,
                                                   const std::function<bool()>& keep_going = std::function<bool()>(),
                                                   const Known_null_space& null_space = Known_null_space())
{
  const Eigen::Index n = L.rows();
  CGAL_precondition_msg(nev >= 1 && nev + null_space.number_of_components < n, "more vertices than eigenpairs are needed");
  CGAL_precondition(null_space.empty() || static_cast<Eigen::Index>(null_space.component.size()) == n);

  const double mean_l = L.diagonal().mean();
  const double mean_m = M.diagonal().mean();
  if(!(mean_l > 0) || !(mean_m > 0))
    throw Numerical_error("the Laplacian or mass matrix is degenerate (zero diagonal)");
  const double sigma = -1e-6 * mean_l / mean_m;

  typedef Shift_invert_operator<LA> Op;
  typedef Mass_product BOp;
  // on the heap, to free the factorization before the result is put together
  std::unique_ptr<Op> op(new Op(L, M, keep_going));
  BOp bop(M);
  op->set_shift(sigma);
  // the projection on the known null space's complement takes M's diagonal (M is lumped)
  Eigen::VectorXd mass;
  if(!null_space.empty())
  {
    mass = M.diagonal();
    op->set_null_space(null_space, mass.data());
  }

  Eigen_solve_result r;
  Eigen::VectorXd values;
  Eigen::MatrixXd vectors(n, 0);
  const int max_rounds = 8;
  for(int round = 0; round < max_rounds; ++round)
  {
    // The first run asks for everything; later runs only check for missed eigenvalues
    // below the largest one kept, so a few suffice.
    const Eigen::Index found = vectors.cols();
    const Eigen::Index room = n - null_space.number_of_components - found - 1;
    const Eigen::Index want = (std::min<Eigen::Index>)((round == 0) ? nev : (std::min<Eigen::Index>)(nev, 4), room);
    if(want < 1)
      break;
    op->set_deflation(vectors, values);
    auto solve = [&](Eigen::Index count, Eigen::Index ncv, double tol, Eigen::VectorXd& new_values, Eigen::MatrixXd& new_vectors) {
      ncv = (std::min)(n, ncv);
      spectra_solve(*op, bop, count, ncv, sigma, tol, max_iterations, round, null_space, mass.data(), new_values, new_vectors, r);
    };
    Eigen::VectorXd new_values;
    Eigen::MatrixXd new_vectors;
    // The Krylov basis is ncv vectors of the mesh's size, the embedding's largest block of
    // memory. Spectra asks for ncv >= 2 nev; with the shift near 0 the wanted eigenvalues are
    // the dominant ones, and twice the count converges about as fast as a wider basis.
    const Eigen::Index accurate_ncv = (std::max<Eigen::Index>)(2 * want + 1, 20);
    if(round == 0)
      solve(want, accurate_ncv, tolerance, new_values, new_vectors);
    else
    {
      // A cheap look for anything missed: the smallest eigenvalue of the deflated problem
      // alone, to a loose tolerance (a Ritz value of the shift-inverted operator lies above
      // the eigenvalue it converges to, so a value below the limit is never a false alarm).
      // Only if one shows up are a few solved accurately: looking for several to the full
      // tolerance every round would cost about as much as the first run.
      solve(1, 16, (std::max)(tolerance, 1e-3), new_values, new_vectors);
      const double limit = values[(std::min)(nev, found) - 1];
      if((new_values.array() < limit * (1 - 1e-6)).any())
        solve(want, accurate_ncv, tolerance, new_values, new_vectors);
    }

    const double threshold = (found >= nev) ? values[nev - 1] : std::numeric_limits<double>::infinity();
    // Only eigenpairs below the current nev-th one matter; the deflated zero eigenvalues
    // (lambda = sigma + 1/0 = inf) are never among them.
    std::vector<Eigen::Index> keep;
    for(Eigen::Index k = 0; k < new_values.size(); ++k)
      if(new_values[k] < threshold * (1 - 1e-12))
        keep.push_back(k);
    if(round > 0 && keep.empty())
      break;
    Eigen::MatrixXd merged_vectors(n, found + static_cast<Eigen::Index>(keep.size()));
    Eigen::VectorXd merged_values(found + static_cast<Eigen::Index>(keep.size()));
    merged_vectors.leftCols(found) = vectors;
    merged_values.head(found) = values;
    for(std::size_t j = 0; j < keep.size(); ++j)
    {
      Eigen::VectorXd v = new_vectors.col(keep[j]);
      // re-orthogonalize against what was found (M inner product), as rounding leaks
      null_space.project(mass.data(), v.data());
      if(found > 0)   // in steps: the products' types are those of the other products here
      {
        const Eigen::VectorXd mv = M * v, c = vectors.transpose() * mv;
        v -= vectors * c;
      }
      v /= std::sqrt(v.dot(M * v));
      merged_vectors.col(found + static_cast<Eigen::Index>(j)) = v;
      merged_values[found + static_cast<Eigen::Index>(j)] = v.dot(L * v);
    }
    std::vector<Eigen::Index> order(static_cast<std::size_t>(merged_values.size()));
    for(std::size_t k = 0; k < order.size(); ++k) order[k] = static_cast<Eigen::Index>(k);
    // by value, ties in index order (as a stable sort, which would compile a second sort)
    std::sort(order.begin(), order.end(), [&](Eigen::Index a, Eigen::Index b) {
      return merged_values[a] < merged_values[b] || (!(merged_values[b] < merged_values[a]) && a < b);
    });
    const Eigen::Index kept = (std::min<Eigen::Index>)(static_cast<Eigen::Index>(order.size()), nev + 8);
    values.resize(kept);
    vectors.resize(n, kept);
    for(Eigen::Index k = 0; k < kept; ++k)
    {
      values[k] = merged_values[order[static_cast<std::size_t>(k)]];
      vectors.col(k) = merged_vectors.col(order[static_cast<std::size_t>(k)]);
    }
    if(round == max_rounds - 1)
      break;
  }
  op.reset();
  r.eigenvalues = values.head(nev);
  if(vectors.cols() == nev)
    r.eigenvectors = std::move(vectors);
  else
    r.eigenvectors = vectors.leftCols(nev);
  return r;
}

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_SPECTRAL_GENERALIZED_EIGENSOLVER_H
