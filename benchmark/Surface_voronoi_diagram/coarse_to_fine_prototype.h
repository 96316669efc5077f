// A prototype, not part of the library: the coarse-to-fine eigen-solver tried for issue 55,
// goal 4 (the biharmonic embedding in seconds), kept with the benchmark that measured it
// (benchmark_coarse_to_fine.cpp; figures in results/coarse_to_fine.md). It did not reach the
// goal, so the library keeps its direct shift-invert solve.
//
// Hierarchy: maximal independent vertex sets, prolongations of linear precision (three coarse
// vertices per fine one), Galerkin operators. Coarsest level: the library's shift-invert
// Lanczos. Finer levels: block LOBPCG steps preconditioned by a V-cycle.

#ifndef SVD_BENCHMARK_COARSE_TO_FINE_PROTOTYPE_H
#define SVD_BENCHMARK_COARSE_TO_FINE_PROTOTYPE_H

#include <CGAL/Surface_voronoi_diagram/internal/Spectral/generalized_eigensolver.h>

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <Eigen/Sparse>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdio>
#include <functional>
#include <limits>
#include <vector>

namespace svd_bench {

using CGAL::Surface_voronoi::internal::Eigen_solve_result;
using CGAL::Surface_voronoi::internal::Eigen_solve_cancelled;
using CGAL::Surface_voronoi::internal::Known_null_space;
using CGAL::Surface_voronoi::internal::Shift_invert_operator;
using CGAL::Surface_voronoi::internal::smallest_generalized_eigenpairs;
using CGAL::Surface_voronoi::Numerical_error;

struct Coarse_to_fine_options
{
  std::size_t coarsest = 10000;     // coarsen until a level has at most this many vertices
  int steps = 6;                    // the most block steps per level
  int sweeps = 2;                   // damped Jacobi sweeps per level of the V-cycle
  bool lobpcg = true;               // keep the previous step's directions as a third block
  double ritz_tolerance = 1e-5;     // a level is done when the wanted Ritz values move less
  double coarse_tolerance = 1e-8;   // of the coarsest level's Lanczos
  bool trace = false;               // print the time of each stage
};

/// One coarsening step. The coarse vertices are a maximal independent set of the graph of
/// `A` (greedy, in index order); each other vertex becomes the affine combination of three
/// coarse vertices near it (among the coarse ones within two edges) whose triangle its
/// projection falls in (else the triangle it is least outside of), so that `P`
/// (fine by coarse) reproduces every function linear over that triangle: Galerkin operators
/// without this linear precision bias every eigenvalue and move the cells.
inline Eigen::SparseMatrix<double> coarsening(const Eigen::SparseMatrix<double>& A, const std::vector<Eigen::Vector3d>& x,
                                              std::vector<Eigen::Vector3d>& coarse_x, std::vector<int>& sample)
{
  typedef Eigen::SparseMatrix<double>::InnerIterator It;
  const int n = static_cast<int>(A.rows());
  std::vector<int> id(static_cast<std::size_t>(n), -1), seen(static_cast<std::size_t>(n), -1);
  std::vector<char> blocked(static_cast<std::size_t>(n), 0);
  sample.clear();
  for(int i = 0; i < n; ++i)
    if(!blocked[std::size_t(i)])
    {
      id[std::size_t(i)] = static_cast<int>(sample.size());
      sample.push_back(i);
      for(It it(A, i); it; ++it) blocked[std::size_t(it.row())] = 1;
    }
  coarse_x.clear();
  for(int s : sample) coarse_x.push_back(x[std::size_t(s)]);
  std::vector<Eigen::Triplet<double> > t;
  t.reserve(3 * std::size_t(n));
  std::vector<int> c;
  for(int i = 0; i < n; ++i)
  {
    if(id[std::size_t(i)] >= 0) { t.emplace_back(i, id[std::size_t(i)], 1.); continue; }
    c.clear();
    for(It it(A, i); it; ++it)
      for(It jt(A, static_cast<int>(it.row())); jt; ++jt)
        if(id[std::size_t(jt.row())] >= 0 && seen[std::size_t(jt.row())] != i)
        {
          seen[std::size_t(jt.row())] = i;
          c.push_back(static_cast<int>(jt.row()));
        }
    const Eigen::Vector3d& p = x[std::size_t(i)];
    auto d2 = [&](int k) { return (x[std::size_t(k)] - p).squaredNorm(); };
    std::sort(c.begin(), c.end(), [&](int a, int b) { return d2(a) < d2(b) || (d2(a) == d2(b) && a < b); });
    c.resize((std::min<std::size_t>)(c.size(), 6));   // the nearest: a wider choice rarely wins
    // the triangle (c[0], c[a], c[b]) of the best barycentric coordinates; a segment or the
    // nearest alone when no triangle is proper
    double best = -std::numeric_limits<double>::infinity();
    Eigen::Vector3d w(1, 0, 0);
    int ia = 0, ib = 0;
    const Eigen::Vector3d o = x[std::size_t(c[0])], q = p - o;
    for(std::size_t a = 1; a < c.size(); ++a)
      for(std::size_t b = a + 1; b < c.size(); ++b)
      {
        const Eigen::Vector3d e1 = x[std::size_t(c[a])] - o, e2 = x[std::size_t(c[b])] - o, nn = e1.cross(e2);
        const double area2 = nn.squaredNorm();
        if(!(area2 > 1e-12 * e1.squaredNorm() * e2.squaredNorm())) continue;
        const double s = q.cross(e2).dot(nn) / area2, r = e1.cross(q).dot(nn) / area2;
        // inside (up to rounding): the nearest plane first, so that a vertex on a coarse
        // edge (a midpoint) takes that edge's two ends, not a wider triangle above it
        const double inside = (std::min)({ 1 - s - r, s, r });
        const double score = inside > -1e-9 ? 1 / (1 + q.dot(nn) * q.dot(nn) / (area2 * q.squaredNorm())) : inside;
        if(score > best) { best = score; w = Eigen::Vector3d(1 - s - r, s, r); ia = int(a); ib = int(b); }
      }
    if(best == -std::numeric_limits<double>::infinity() && c.size() > 1)
    {
      const Eigen::Vector3d e = x[std::size_t(c[1])] - o;
      const double s = q.dot(e) / e.squaredNorm();
      w = Eigen::Vector3d(1 - s, s, 0);
      ia = ib = 1;
    }
    t.emplace_back(i, id[std::size_t(c[0])], w[0]);
    if(w[1] != 0) t.emplace_back(i, id[std::size_t(c[std::size_t(ia)])], w[1]);
    if(w[2] != 0) t.emplace_back(i, id[std::size_t(c[std::size_t(ib)])], w[2]);
  }
  Eigen::SparseMatrix<double> P(n, static_cast<Eigen::Index>(sample.size()));
  P.setFromTriplets(t.begin(), t.end());
  return P;
}

/// The `nev` smallest eigenpairs of (L, M) (M diagonal), coarse to fine: the mesh is
/// coarsened until a level has at most `options.coarsest` vertices (Galerkin operators P^T L P and
/// P^T M P), where the exact shift-invert solve gives a few more eigenpairs than asked (so
/// that a cluster cut by the count stays whole). Level by level, the Ritz vectors are then
/// prolonged and refined by a few block steps: Rayleigh-Ritz over the Ritz vectors and
/// their residuals preconditioned by a V-cycle (the coarsest factorization for the smooth
/// error, damped Jacobi sweeps on every finer level), and (LOBPCG) the previous step's
/// directions. The cells
/// need eigenvectors to about 1e-4, not to the direct solve's tolerance.
template <class LA>
Eigen_solve_result coarse_to_fine_eigenpairs(const Eigen::SparseMatrix<double>& L, const Eigen::SparseMatrix<double>& M,
                                             const std::vector<Eigen::Vector3d>& points, Eigen::Index nev,
                                             const Coarse_to_fine_options& options,
                                             const std::function<bool()>& keep_going = std::function<bool()>(),
                                             const Known_null_space& null_space = Known_null_space())
{
  typedef Eigen::SparseMatrix<double> Matrix;
  // a block of vectors row by row: sparse products then read and write whole rows
  typedef Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> Dense;
  const auto start = std::chrono::steady_clock::now();
  auto trace = [&](const char* what, int level, long count) {
    if(options.trace)
      std::printf("  [%.3f s] %s %d: %ld\n", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), what, level, count);
  };
  std::vector<Matrix> As(1, L), Bs(1, M), Ps;   // Ps[k] prolongs level k + 1 to level k
  std::vector<Known_null_space> spaces(1, null_space);
  std::vector<Eigen::Vector3d> x = points, coarse_x;
  std::vector<int> sample;
  const Eigen::Index guard = (std::max<Eigen::Index>)(6, nev / 4), p = nev + guard;
  while(static_cast<std::size_t>(As.back().rows()) > options.coarsest)
  {
    Matrix P = coarsening(As.back(), x, coarse_x, sample);
    if(P.cols() < 4 * (p + null_space.number_of_components) + 32 || 10 * P.cols() > 9 * P.rows())
      break;   // too few left, or no progress
    const Matrix AP = As.back() * P, BP = Bs.back() * P;
    As.push_back(Matrix(P.transpose() * AP));
    Bs.push_back(Matrix(P.transpose() * BP));
    Known_null_space s = null_space;
    if(!s.empty())
    {
      s.component.clear();
      for(int i : sample) s.component.push_back(spaces.back().component[std::size_t(i)]);
    }
    spaces.push_back(std::move(s));
    Ps.push_back(std::move(P));
    x.swap(coarse_x);
    trace("level, vertices", int(As.size() - 1), long(As.back().rows()));
  }
  const std::size_t coarsest = Ps.size();
  if(coarsest == 0) throw Numerical_error("no coarser level");
  // the coarsest mass lumped (row sums), as the shift-invert solver takes it
  const Eigen::VectorXd lumped = Bs.back() * Eigen::VectorXd::Ones(Bs.back().rows());
  const Matrix Mc(lumped.asDiagonal()), Lc = As.back();   // the operators refer to both
  Eigen_solve_result r = smallest_generalized_eigenpairs<LA>(Lc, Mc, p, options.coarse_tolerance, 1000, keep_going, spaces.back());
  // the coarsest factorization again, as the V-cycle's bottom (small: factorized in no time)
  Shift_invert_operator<LA> coarse(Lc, Mc, keep_going);
  coarse.set_shift(-1e-6 * Lc.diagonal().mean() / Mc.diagonal().mean());
  coarse.set_null_space(spaces.back(), lumped.data());
  trace("coarsest solved, operations", int(coarsest), r.operations);
  Dense X = r.eigenvectors, AX, BX;
  Eigen::VectorXd theta;
  // W ~ (A_l - theta B_l)^{-1} R column by column, by a V-cycle: the coarser levels'
  // correction of the residual, then damped Jacobi sweeps for the error at the level's scale
  // (W, AW and BW come out consistent)
  std::function<void(std::size_t, const Dense&, Dense&, Dense&, Dense&)> cycle =
      [&](std::size_t l, const Dense& R, Dense& W, Dense& AW, Dense& BW) {
        if(l == coarsest)
        {
          Eigen::MatrixXd Rc = R, Wc(R.rows(), R.cols());
          for(Eigen::Index j = 0; j < R.cols(); ++j)
            coarse.perform_op(Rc.col(j).data(), Wc.col(j).data());
          W = Wc;
          return;
        }
        Dense Wc, AWc, BWc;
        cycle(l + 1, Ps[l].transpose() * R, Wc, AWc, BWc);
        W = Ps[l] * Wc;
        const Matrix& A = As[l];
        const Matrix& B = Bs[l];
        const Eigen::VectorXd a = A.diagonal(), b = B.diagonal();
        AW = A * W;
        BW = B * W;
        for(int sweep = 0; sweep < options.sweeps; ++sweep)
        {
          for(Eigen::Index i = 0; i < W.rows(); ++i)
            W.row(i).array() += (2. / 3.) * (R.row(i) - AW.row(i) + BW.row(i).cwiseProduct(theta.transpose())).array()
                                / (a[i] - b[i] * theta.transpose().array());
          AW = A * W;
          BW = B * W;
        }
      };
  for(std::size_t k = coarsest; k-- > 0;)
  {
    const Matrix& A = As[k];
    const Matrix& B = Bs[k];
    const Eigen::VectorXd a = A.diagonal(), b = B.diagonal(), m = B * Eigen::VectorXd::Ones(B.rows());
    X = Ps[k] * X;
    // Rayleigh-Ritz over [X W] from the small Gram matrices alone: a basis B-orthonormal in
    // the small space (directions nearly dependent dropped), then the p lowest Ritz pairs;
    // X, AX and BX are updated by the same small transform, without products by A and B
    Dense P, AP, BP;   // the previous step's search directions (LOBPCG's third block)
    auto rayleigh_ritz = [&](Dense& W, Dense& AW, Dense& BW, bool fresh) {
      const Eigen::Index q = X.cols(), w = W.cols();
      if(w > 0)
      {
        // unit B-norm, so that the Gram matrix's spectrum shows dependence, not scale
        const Eigen::RowVectorXd s = (W.cwiseProduct(BW).colwise().sum()).cwiseMax(1e-300).cwiseSqrt().cwiseInverse();
        W = W * s.asDiagonal();
        AW = AW * s.asDiagonal();
        BW = BW * s.asDiagonal();
      }
      Dense GA(q + w, q + w), GB(q + w, q + w);
      if(fresh)   // X prolonged: any basis
      {
        GA.topLeftCorner(q, q) = X.transpose() * AX;
        GB.topLeftCorner(q, q) = X.transpose() * BX;
      }
      else   // X holds B-orthonormal Ritz vectors
      {
        GA.topLeftCorner(q, q) = theta.asDiagonal();
        GB.topLeftCorner(q, q).setIdentity();
      }
      if(w > 0)
      {
        GA.topRightCorner(q, w) = X.transpose() * AW;
        GB.topRightCorner(q, w) = X.transpose() * BW;
        GA.bottomRightCorner(w, w) = W.transpose() * AW;
        GB.bottomRightCorner(w, w) = W.transpose() * BW;
        GA.bottomLeftCorner(w, q) = GA.topRightCorner(q, w).transpose();
        GB.bottomLeftCorner(w, q) = GB.topRightCorner(q, w).transpose();
      }
      Eigen::SelfAdjointEigenSolver<Dense> g(GB);
      const Eigen::VectorXd& e = g.eigenvalues();
      Eigen::Index drop = 0;
      while(drop < e.size() && !(e[drop] > 1e-10 * e[e.size() - 1])) ++drop;
      const Dense T = g.eigenvectors().rightCols(e.size() - drop) * e.tail(e.size() - drop).cwiseSqrt().cwiseInverse().asDiagonal();
      Eigen::SelfAdjointEigenSolver<Dense> rr(T.transpose() * GA * T);
      if(g.info() != Eigen::Success || rr.info() != Eigen::Success || !rr.eigenvalues().allFinite() || T.cols() < p)
        throw Numerical_error("the Rayleigh-Ritz step of the coarse-to-fine eigen-solver failed");
      const Dense C = T * rr.eigenvectors().leftCols(p);
      theta = rr.eigenvalues().head(p);
      // the products by A and B anew: sparse, cheaper than carrying them through the transform
      Dense nx = X * C.topRows(q);
      if(w > 0)
      {
        P = W * C.bottomRows(w);
        nx += P;
        AP = A * P;
        BP = B * P;
      }
      Dense nax = A * nx, nbx = B * nx;
      X.swap(nx); AX.swap(nax); BX.swap(nbx);
    };
    AX = A * X;
    BX = B * X;
    {
      Dense none;
      rayleigh_ritz(none, none, none, true);
    }
    int steps = 0;
    for(int step = 0; step < options.steps; ++step, ++steps)
    {
      if(keep_going && !keep_going()) throw Eigen_solve_cancelled();
      const Dense R = AX - BX * theta.asDiagonal();
      Dense W, AW, BW;
      cycle(k, R, W, AW, BW);
      if(!spaces[k].empty())
      {
        for(Eigen::Index j = 0; j < W.cols(); ++j)
        {
          Eigen::VectorXd w = W.col(j);
          spaces[k].project(m.data(), w.data());
          W.col(j) = w;
        }
        AW = A * W;
        BW = B * W;
      }
      if(P.cols() > 0 && options.lobpcg)
      {
        Dense S(W.rows(), W.cols() + P.cols()), AS(S.rows(), S.cols()), BS(S.rows(), S.cols());
        S << W, P;
        AS << AW, AP;
        BS << BW, BP;
        W.swap(S); AW.swap(AS); BW.swap(BS);
      }
      const Eigen::VectorXd previous = theta;
      rayleigh_ritz(W, AW, BW, false);
      trace("level, step", int(k), step);
      // the wanted Ritz values' error is about the square of the vectors'
      const Eigen::Index first = null_space.empty() ? 1 : 0;
      if(((theta - previous).array().abs() / theta.array().abs()).segment(first, nev - first).maxCoeff() < options.ritz_tolerance)
      {
        ++steps;
        break;
      }
    }
    trace("level refined, steps", int(k), steps);
  }
  r.eigenvalues = theta.head(nev);
  r.eigenvectors = X.leftCols(nev);
  return r;
}

} // namespace svd_bench

#endif // SVD_BENCHMARK_COARSE_TO_FINE_PROTOTYPE_H
