// Tests of internal/Spectral/block_krylov_schur.h, the eigen-solver of large meshes: against
// known spectra (a diagonal operator, single vectors and blocks), against a dense generalized
// solve on mesh Laplacians through the shift-invert of smallest_generalized_eigenpairs (repeated
// eigenvalues included), a Krylov space that closes before the basis is full, cancellation and
// a solve that does not converge.
#include "test_support.h"

#include <test_meshes.h>
#include <CGAL/Surface_voronoi_diagram/internal/Spectral/Fixed_dense_blocking.h>
#include <CGAL/Surface_voronoi_diagram/internal/Spectral/block_krylov_schur.h>
#include <CGAL/Surface_voronoi_diagram/internal/Spectral/cotangent_laplacian.h>
#include <CGAL/Surface_voronoi_diagram/internal/Spectral/generalized_eigensolver.h>
#include <CGAL/Surface_voronoi_diagram/internal/Indexed_mesh.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <functional>
#include <vector>

// this file's own names: the suite compiles its files together (see CMakeLists.txt)
namespace svd_test_block_krylov_schur {

using namespace svd_test;
namespace SV = CGAL::Surface_voronoi;
namespace GEN = svd_test::meshes;

namespace {

typedef Eigen::SparseMatrix<double> Sparse;

void mesh_matrices(const Mesh& m, Sparse& L, Sparse& M)
{
  SV::internal::Indexed_mesh<Mesh> im(m, get(CGAL::vertex_point, m));
  SV::internal::assemble_cotangent_laplacian(im.points, im.triangles, L, M);
}

// Op = diag(d), self-adjoint in the plain inner product
struct Diagonal_operator
{
  Eigen::VectorXd d;
  void operator()(const Eigen::Ref<const Eigen::MatrixXd>& X, Eigen::MatrixXd& Y) const { Y = d.asDiagonal() * X; }
};

struct Identity_mass
{
  void operator()(const Eigen::Ref<const Eigen::MatrixXd>& X, Eigen::MatrixXd& Y) const { Y = X; }
};

typedef CGAL::Eigen_solver_traits<Eigen::SimplicialLLT<Sparse, Eigen::Lower, Eigen::AMDOrdering<int> > > Reference_LA;

} // namespace

TEST_CASE("block Krylov-Schur: the largest eigenpairs of a known spectrum, one vector or a block at a time", "[embedding][numerics]")
{
  const Eigen::Index n = 400;
  Diagonal_operator op;
  op.d.resize(n);
  // distinct values in a scrambled order, the largest well apart as in a shift-invert
  for(Eigen::Index i = 0; i < n; ++i)
    op.d[(i * 37) % n] = 1.0 / (1.0 + double(i) + 0.01 * double(i * i));
  const Eigen::Index count = 8;
  for(Eigen::Index block : { 1, 2, 3 })
  {
    INFO("block " << block);
    const SV::internal::Block_krylov_schur_result r =
      SV::internal::block_krylov_schur(op, Identity_mass(), n, count, block, count + 2 * block + 8, 1e-12, 1000, 1);
    REQUIRE(r.converged == count);
    REQUIRE(r.values.size() == count);
    for(Eigen::Index k = 0; k < count; ++k)
    {
      const double expected = 1.0 / (1.0 + double(k) + 0.01 * double(k * k));
      CHECK(r.values[k] == Approx(expected).epsilon(1e-11));
      // the eigenvector is the unit vector of that value, up to its sign
      CHECK(std::abs(r.vectors(Eigen::Index((k * 37) % n), k)) == Approx(1.0).epsilon(1e-10));
    }
    const Eigen::MatrixXd gram = r.vectors.transpose() * r.vectors;
    CHECK((gram - Eigen::MatrixXd::Identity(count, count)).cwiseAbs().maxCoeff() < 1e-12);
    CHECK(r.applications % block == 0);
  }
}

TEST_CASE("block Krylov-Schur: a Krylov space that closes before the basis is full goes on from a new direction", "[embedding][numerics]")
{
  // three distinct values, ten copies each: a Krylov space grown from one vector has three
  // dimensions, and the fourth vector has nothing left after orthogonalization
  const Eigen::Index n = 30;
  Diagonal_operator op;
  op.d.resize(n);
  for(Eigen::Index i = 0; i < n; ++i)
    op.d[i] = (i % 3 == 0) ? 4.0 : (i % 3 == 1) ? 2.0 : 1.0;
  const Eigen::Index count = 3;
  const SV::internal::Block_krylov_schur_result r =
    SV::internal::block_krylov_schur(op, Identity_mass(), n, count, 1, 12, 1e-12, 100, 1);
  REQUIRE(r.converged == count);
  // three copies of the largest value: the closed space was left for new random directions
  for(Eigen::Index k = 0; k < count; ++k)
  {
    CHECK(r.values[k] == Approx(4.0).epsilon(1e-11));
    CHECK((op.d.asDiagonal() * r.vectors.col(k) - 4.0 * r.vectors.col(k)).norm() < 1e-9);
  }
  const Eigen::MatrixXd gram = r.vectors.transpose() * r.vectors;
  CHECK((gram - Eigen::MatrixXd::Identity(count, count)).cwiseAbs().maxCoeff() < 1e-10);
}

TEST_CASE("block Krylov-Schur: the shift-inverted mesh problem agrees with a dense generalized solve", "[embedding][numerics]")
{
  // the supernodal path of smallest_generalized_eigenpairs_in_order() is the only user of the
  // Krylov-Schur iteration; here on meshes small enough for a dense solve, closed and open
  for(int shape = 0; shape < 2; ++shape)
  {
    Mesh m;
    if(shape == 0) GEN::make_torus(m, 1.0, 0.3, 40, 14);
    else GEN::make_planar_grid(m, 24, 20, 1.0, 0.7, 0.2);   // with a border, jittered
    Sparse L, M;
    mesh_matrices(m, L, M);
    const Eigen::MatrixXd Ld(L), Md(M);
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> dense(Ld.selfadjointView<Eigen::Lower>(), Md);
    const Eigen::Index nev = 12;
    const SV::internal::Eigen_solve_result r =
      SV::internal::smallest_generalized_eigenpairs_in_order<SV::internal::Supernodal_cholesky_traits>(L, M, nev, 1e-10, 1000, std::function<bool()>());
    REQUIRE(r.eigenvalues.size() == nev);
    INFO("shape " << shape);
    for(Eigen::Index k = 0; k < nev; ++k)
      CHECK(r.eigenvalues[k] == Approx(dense.eigenvalues()[k]).epsilon(1e-9).margin(1e-9));
    // M-orthonormal, and each eigenvector of a simple eigenvalue the dense one up to its sign
    const Eigen::MatrixXd gram = r.eigenvectors.transpose() * (M * r.eigenvectors);
    CHECK((gram - Eigen::MatrixXd::Identity(nev, nev)).cwiseAbs().maxCoeff() < 1e-9);
    for(Eigen::Index k = 1; k + 1 < nev; ++k)
    {
      const double lo = dense.eigenvalues()[k - 1], mid = dense.eigenvalues()[k], hi = dense.eigenvalues()[k + 1];
      if(mid < lo * (1 + 1e-3) || hi < mid * (1 + 1e-3))
        continue;
      const Eigen::VectorXd reference = dense.eigenvectors().col(k) / std::sqrt(dense.eigenvectors().col(k).dot(M * dense.eigenvectors().col(k)));
      CHECK(std::abs(r.eigenvectors.col(k).dot(M * reference)) == Approx(1.0).epsilon(1e-8));
    }
  }
}

TEST_CASE("block Krylov-Schur: no copy of a repeated eigenvalue is missed wherever the count cuts", "[embedding][numerics]")
{
  Mesh m;
  GEN::make_icosphere(m, 3, 1.0);   // 642 vertices, eigenvalues repeated up to 9 times
  Sparse L, M;
  mesh_matrices(m, L, M);
  const Eigen::MatrixXd Ld(L), Md(M);
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> dense(Ld.selfadjointView<Eigen::Lower>(), Md);
  int missed = 0;
  for(Eigen::Index nev = 11; nev <= 41; nev += 3)
  {
    const SV::internal::Eigen_solve_result r =
      SV::internal::smallest_generalized_eigenpairs_in_order<SV::internal::Supernodal_cholesky_traits>(L, M, nev, 1e-10, 1000, std::function<bool()>());
    for(Eigen::Index k = 0; k < nev; ++k)
      if(r.eigenvalues[k] != Approx(dense.eigenvalues()[k]).epsilon(1e-8).margin(1e-9))
      {
        ++missed;
        INFO("nev = " << nev << ", eigenvalue " << k << ": " << r.eigenvalues[k] << " against " << dense.eigenvalues()[k]);
        CHECK(false);
        break;
      }
  }
  CHECK(missed == 0);
}

TEST_CASE("block Krylov-Schur: the same bits whatever cache sizes Eigen has read", "[embedding][numerics]")
{
  // At 40 eigenpairs the basis has 81 vectors, and the restarts' and Ritz pairs' products are
  // blocked along them by the L1 size Eigen reads: under a 2 KiB L1 the sums split into
  // blocks of 16, and 32 of the 40 eigenvalues came out other bits (the solver's own fixed
  // blocking removed)
  Mesh m;
  GEN::make_torus(m, 1.0, 0.3, 40, 14);
  Sparse L, M;
  mesh_matrices(m, L, M);
  const std::ptrdiff_t sizes[2][3] = { { 2 * 1024, 16 * 1024, 64 * 1024 }, { 64 * 1024, 4 * 1024 * 1024, 64 * 1024 * 1024 } };
  std::vector<SV::internal::Eigen_solve_result> results;
  for(const auto& s : sizes)
  {
    const SV::internal::Fixed_dense_blocking machine(s[0], s[1], s[2]);   // as if the processor had these caches
    results.push_back(SV::internal::smallest_generalized_eigenpairs_in_order<SV::internal::Supernodal_cholesky_traits>(
        L, M, 40, 1e-10, 1000, std::function<bool()>()));
  }
  REQUIRE(results[0].eigenvalues.size() == 40);
  REQUIRE(results[1].eigenvalues.size() == 40);
  for(Eigen::Index k = 0; k < 40; ++k)
    if(results[0].eigenvalues[k] != results[1].eigenvalues[k])
      FAIL("eigenvalue " << k << ": " << results[0].eigenvalues[k] << " against " << results[1].eigenvalues[k]);
  CHECK((results[0].eigenvectors.array() == results[1].eigenvectors.array()).all());
}

TEST_CASE("block Krylov-Schur: a cancelled solve stops, and one that cannot converge says so", "[embedding][numerics]")
{
  Mesh m;
  GEN::make_torus(m, 1.0, 0.3, 30, 12);
  Sparse L, M;
  mesh_matrices(m, L, M);
  long asked = 0;
  const std::function<bool()> stop_after_five = [&]() { return ++asked <= 5; };
  CHECK_THROWS_AS((SV::internal::smallest_generalized_eigenpairs_in_order<SV::internal::Supernodal_cholesky_traits>(L, M, 8, 1e-10, 1000, stop_after_five)),
                  SV::internal::Eigen_solve_cancelled);
  CHECK(asked == 6);
  // a zero tolerance is never met, and no restart is allowed
  CHECK_THROWS_WITH((SV::internal::smallest_generalized_eigenpairs_in_order<SV::internal::Supernodal_cholesky_traits>(L, M, 8, 0.0, 0, std::function<bool()>())),
                    Catch::Contains("did not converge"));
}

} // namespace svd_test_block_krylov_schur
