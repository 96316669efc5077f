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
// The largest eigenpairs of an operator that is self-adjoint in the M inner product
// (the shift-inverted (L - sigma M)^{-1} M of the embedding), by a block Krylov-Schur
// iteration: a block Lanczos basis, kept M-orthonormal, restarted from its best Ritz vectors.
//
// Why not Spectra's Lanczos on large meshes: it tests for convergence only at its restarts,
// and orthogonalizes each new vector against the whole basis with up to six passes over it,
// each two matrix-vector products that read the basis from memory. Here the Ritz pairs are
// computed after every block (a run stops as soon as it has converged) and a new block is
// orthogonalized once, or twice when a column lost half its squared length. The eigen-solver
// uses blocks of one vector: larger blocks read the factor once for the block, but needed more
// applications and cost more in total on igea-537k (see generalized_eigensolver.h); they are
// kept for the case where a block pays (tested with 1 to 3).

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_SPECTRAL_BLOCK_KRYLOV_SCHUR_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_SPECTRAL_BLOCK_KRYLOV_SCHUR_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/assertions.h>

#include <Eigen/Dense>
#include <Spectra/Util/SimpleRandom.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

/// the whole space: random vectors are taken as they are
struct Whole_space
{
  void operator()(Eigen::MatrixXd&) const {}
};

struct Block_krylov_schur_result
{
  Eigen::VectorXd values;    // the largest eigenvalues of the operator, descending
  Eigen::MatrixXd vectors;   // their M-orthonormal eigenvectors
  long applications = 0;     // columns the operator was applied to
  long restarts = 0;
  Eigen::Index converged = 0;
};

/// `apply(X, Y)`: Y = Op X for an n x b block X; `mass(X, Y)`: Y = M X (X an
/// `Eigen::Ref<const Eigen::MatrixXd>`, Y an `Eigen::MatrixXd` of X's size). Finds the `count`
/// largest eigenpairs to a residual of `tolerance` times the eigenvalue, with a basis of at
/// most `basis_size` vectors grown `block` at a time, from `seed`'s random start block.
/// `to_space(X)` maps random vectors, in place, into the space the operator works in (the
/// complement of a known null space).
template <class Apply, class Mass, class To_space = Whole_space>
Block_krylov_schur_result block_krylov_schur(const Apply& apply, const Mass& mass, Eigen::Index n, Eigen::Index count,
                                             Eigen::Index block, Eigen::Index basis_size, double tolerance,
                                             long max_restarts, unsigned long seed, const To_space& to_space = To_space())
{
  using Eigen::Index;
  using Eigen::MatrixXd;
  using Eigen::VectorXd;
  const Index b = block;
  const Index m = basis_size;
  CGAL_precondition(count >= 1 && b >= 1 && m >= count + 2 * b && m <= n);

  Block_krylov_schur_result r;
  MatrixXd V(n, m);        // columns [0, p) applied to, [p, p + b) waiting
  MatrixXd H = MatrixXd::Zero(m, m);   // Op V[:, 0:p] = V[:, 0:p+b] H[0:p+b, 0:p]
  MatrixXd Z(n, b), MZ(n, b), C, ritz;
  Spectra::SimpleRandom<double> rng(seed);

  // Orthogonalizes Z's columns against V[:, 0:q] (once or twice) and among themselves (Cholesky
  // QR); a column that has nothing left is replaced by a random one. Returns the
  // coefficients of the old Z on V (first q rows) and on the new Z (last b rows).
  // the squared M norms of X's columns, MX = M X given
  auto squared_norms = [](const MatrixXd& X, const MatrixXd& MX) -> VectorXd { return X.cwiseProduct(MX).colwise().sum().transpose(); };
  auto orthonormalize = [&](Index q) -> MatrixXd {
    MatrixXd coefficients = MatrixXd::Zero(q + b, b);
    mass(Z, MZ);
    const VectorXd original = squared_norms(Z, MZ);
    VectorXd before = original;
    for(int pass = 0; pass < 2 && q > 0; ++pass)
    {
      if(pass > 0)
      {
        mass(Z, MZ);
        before = squared_norms(Z, MZ);
      }
      C.noalias() = V.leftCols(q).transpose() * MZ;
      Z.noalias() -= V.leftCols(q) * C;
      coefficients.topRows(q) += C;
      // twice is enough, and once when no column lost half its squared length (the test of
      // Daniel, Gragg, Kaufman and Stewart): what is left is then orthogonal to rounding
      const VectorXd after = before - C.colwise().squaredNorm().transpose();
      if((after.array() > 0.5 * before.array()).all())
        break;
    }
    // Cholesky QR, twice for a block (the second pass restores what the first lost to the
    // Gram matrix's condition); a single vector is normalized once
    MatrixXd R = MatrixXd::Identity(b, b);
    for(int pass = 0; pass < (b > 1 ? 2 : 1); ++pass)
    {
      mass(Z, MZ);
      MatrixXd G = Z.transpose() * MZ;
      G = (G + G.transpose()) / 2;
      const double largest = G.diagonal().maxCoeff();
      Eigen::LLT<MatrixXd> llt(G);
      bool ok = llt.info() == Eigen::Success && largest > 0;
      if(ok)
      {
        const MatrixXd U = llt.matrixU();
        // a column with less than 1e-10 of its length left is in the basis already (an
        // invariant subspace), not a direction to add
        for(Index j = 0; j < b && ok; ++j)
          ok = U(j, j) > 1e-7 * std::sqrt(largest) && (pass > 0 || G(j, j) > 1e-20 * original[j]);
      }
      if(ok)
      {
        const MatrixXd U = llt.matrixU();
        Z = Z * U.triangularView<Eigen::Upper>().solve(MatrixXd::Identity(b, b));
        R = U * R;
        continue;
      }
      // rank deficient: column by column, a column that vanished replaced by a random one
      // (its own coefficient then zero)
      MatrixXd U = MatrixXd::Zero(b, b);
      MatrixXd z(n, 1), mz(n, 1);
      for(Index j = 0; j < b; ++j)
      {
        z = Z.col(j);
        bool recorded = true;
        for(int attempt = 0; attempt < 4; ++attempt)
        {
          mass(z, mz);
          // measured against the column's length before any orthogonalization when it has one
          const double length = std::sqrt((std::max)(0.0, (recorded && pass == 0) ? original[j] : squared_norms(z, mz)[0]));
          for(int sweep = 0; sweep < 2; ++sweep)
          {
            if(sweep > 0) mass(z, mz);
            if(q > 0)
              z.col(0).noalias() -= V.leftCols(q) * (V.leftCols(q).transpose() * mz.col(0));
            if(j > 0)
            {
              const VectorXd c = Z.leftCols(j).transpose() * mz.col(0);
              z.col(0).noalias() -= Z.leftCols(j) * c;
              if(recorded) U.col(j).head(j) += c;
            }
          }
          mass(z, mz);
          const double after = std::sqrt((std::max)(0.0, squared_norms(z, mz)[0]));
          if(length > 0 && after > 1e-10 * length)
          {
            if(recorded) U(j, j) = after;
            z /= after;
            break;
          }
          z.col(0) = rng.random_vec(n);
          to_space(z);
          recorded = false;
        }
        Z.col(j) = z.col(0);
      }
      R = U * R;
    }
    coefficients.bottomRows(b) = R;
    return coefficients;
  };

  // the start block
  for(Index j = 0; j < b; ++j)
    Z.col(j) = rng.random_vec(n);
  to_space(Z);
  orthonormalize(0);
  V.leftCols(b) = Z;
  Index p = 0;

  const double eps23 = std::pow(std::numeric_limits<double>::epsilon(), 2.0 / 3.0);
  for(;;)
  {
    // one block more, then the Ritz pairs of the applied columns: the test after every block
    // (a dense eigen-solve of at most m x m) stops a run as soon as it has converged. Not
    // before the first basis is half grown: a loose tolerance could be met by a Ritz pair of
    // a space too small to have seen the largest eigenvalues yet.
    apply(V.middleCols(p, b), Z);
    r.applications += b;
    const MatrixXd coefficients = orthonormalize(p + b);
    H.block(0, p, p + 2 * b, b) = coefficients;
    V.middleCols(p + b, b) = Z;
    p += b;
    const bool full = p + 2 * b > m;
    if(!full && r.restarts == 0 && p < count + (m - count) / 2)
      continue;
    MatrixXd S = H.topLeftCorner(p, p);
    S = (S + S.transpose()) / 2;
    Eigen::SelfAdjointEigenSolver<MatrixXd> eig(S);
    const VectorXd& theta = eig.eigenvalues();      // ascending
    const MatrixXd& Y = eig.eigenvectors();
    const MatrixXd E = H.block(p, 0, b, p) * Y;     // the residuals' coefficients on the waiting block
    Index converged = 0;
    for(Index i = 0; i < count; ++i)
    {
      const Index k = p - 1 - i;
      if(E.col(k).norm() <= tolerance * (std::max)(eps23, std::abs(theta[k])))
        ++converged;
      else
        break;
    }
    r.converged = converged;
    if(converged == count || (full && r.restarts >= max_restarts))
    {
      r.values.resize(count);
      ritz = Y.rightCols(count).rowwise().reverse();
      r.vectors.noalias() = V.leftCols(p) * ritz;
      for(Index i = 0; i < count; ++i)
        r.values[i] = theta[p - 1 - i];
      return r;
    }
    if(!full)
      continue;
    // restart from the best k Ritz vectors, leaving room for at least one block
    const Index keep = (std::min)(m - 2 * b, count + (std::min)(converged + b, (m - 2 * b - count) / 2));
    ritz = Y.rightCols(keep);
    const MatrixXd kept = V.leftCols(p) * ritz;
    const MatrixXd waiting = V.middleCols(p, b);
    V.leftCols(keep) = kept;
    V.middleCols(keep, b) = waiting;
    H.setZero();
    H.topLeftCorner(keep, keep).diagonal() = theta.tail(keep);
    H.block(keep, 0, b, keep) = E.rightCols(keep);
    p = keep;
    ++r.restarts;
  }
}

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_SPECTRAL_BLOCK_KRYLOV_SCHUR_H
