// Tests of internal/Spectral/Supernodal_cholesky.h, the factorization of the eigen-solver's
// shift-invert on large meshes: its solves against Eigen's simplicial LLT and against the
// matrix itself, on mesh Laplacians and on random patterns built to reach every branch (wide
// supernodes solved by Eigen's kernels, narrow ones by loops, forests, a single row).
#include "test_support.h"

#include <test_meshes.h>
#include <CGAL/Surface_voronoi_diagram/internal/Spectral/Fixed_dense_blocking.h>
#include <CGAL/Surface_voronoi_diagram/internal/Spectral/Supernodal_cholesky.h>
#include <CGAL/Surface_voronoi_diagram/internal/Spectral/cotangent_laplacian.h>

#include <Eigen/SparseCholesky>

#include <random>

// this file's own names: the suite compiles its files together (see CMakeLists.txt)
namespace svd_test_supernodal_cholesky {

using namespace svd_test;
namespace SV = CGAL::Surface_voronoi;
namespace GEN = svd_test::meshes;

namespace {

typedef Eigen::SparseMatrix<double> Sparse;
typedef SV::internal::Supernodal_cholesky Cholesky;

// the symmetric matrix renumbered in a postorder of its elimination tree, as the eigen-solver
// hands it over
Sparse postordered(const Sparse& A)
{
  const std::vector<int> post = Cholesky::postorder(Cholesky::elimination_tree(A));
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> p(A.rows());
  for(std::size_t k = 0; k < post.size(); ++k) p.indices()[static_cast<Eigen::Index>(k)] = post[k];
  Sparse B;
  B = A.selfadjointView<Eigen::Lower>().twistedBy(p.inverse());
  return B;
}

// A random symmetric positive definite matrix: `coupling` random off-diagonal entries per row,
// a dense block of `block` rows at the end (their supernode is wider than the loops'
// limit), and a dominant diagonal.
Sparse random_spd(int n, int coupling, int block, unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> row(0, n - 1);
  std::uniform_real_distribution<double> value(-1, 1);
  std::vector<Eigen::Triplet<double> > t;
  std::vector<double> diagonal(static_cast<std::size_t>(n), 1.0);
  auto add = [&](int i, int j) {
    if(i == j) return;
    const double v = value(rng);
    t.emplace_back(i, j, v);
    t.emplace_back(j, i, v);
    diagonal[static_cast<std::size_t>(i)] += std::abs(v);
    diagonal[static_cast<std::size_t>(j)] += std::abs(v);
  };
  for(int i = 0; i < n; ++i)
    for(int c = 0; c < coupling; ++c) add(i, row(rng));
  for(int i = n - block; i < n; ++i)
    for(int j = n - block; j < i; ++j) add(i, j);
  for(int i = 0; i < n; ++i) t.emplace_back(i, i, diagonal[static_cast<std::size_t>(i)]);
  Sparse A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

// A torus's cotangent Laplacian shifted as the eigen-solver shifts it, renumbered by AMD and
// then in a postorder
Sparse shifted_torus_laplacian(int around, int across)
{
  Mesh m;
  GEN::make_torus(m, 1.0, 0.35, around, across);
  SV::internal::Indexed_mesh<Mesh> im(m, get(CGAL::vertex_point, m));
  Sparse L, M;
  SV::internal::assemble_cotangent_laplacian(im.points, im.triangles, L, M);
  const double sigma = -1e-6 * L.diagonal().mean() / M.diagonal().mean();
  const Sparse C = L - sigma * M;
  Eigen::AMDOrdering<int>::PermutationType p;
  Eigen::AMDOrdering<int>()(C, p);
  Sparse amd_ordered;
  amd_ordered = C.selfadjointView<Eigen::Lower>().twistedBy(p.inverse());
  return postordered(amd_ordered);
}

void check_solves(const Sparse& A)
{
  Cholesky cholesky;
  REQUIRE(cholesky.factor(A));
  Eigen::SimplicialLLT<Sparse, Eigen::Lower, Eigen::NaturalOrdering<int> > reference(A);
  REQUIRE(reference.info() == Eigen::Success);
  for(int k = 0; k < 3; ++k)
  {
    Eigen::VectorXd b(A.rows());
    for(Eigen::Index i = 0; i < b.size(); ++i) b[i] = std::sin(0.7 * double(i) + k + 1) + 0.25 * k;
    Eigen::VectorXd x = b;
    cholesky.solve_in_place(x.data());
    const Eigen::VectorXd y = reference.solve(b);
    // as accurate as the reference, whose residual grows with the condition number (the
    // shifted Laplacian's is about 1e7)
    const double residual = (A.selfadjointView<Eigen::Lower>() * x - b).norm() / b.norm();
    const double reference_residual = (A.selfadjointView<Eigen::Lower>() * y - b).norm() / b.norm();
    CHECK(residual <= (std::max)(1e-13, 4 * reference_residual));
    CHECK((x - y).norm() <= 1e-8 * y.norm());
  }
}

} // namespace

TEST_CASE("supernodal Cholesky: solves agree with Eigen's simplicial LLT", "[embedding][numerics]")
{
  SECTION("a mesh Laplacian shifted as the eigen-solver shifts it")
  {
    check_solves(shifted_torus_laplacian(60, 24));
  }
  SECTION("random patterns with a block wider than the loops take")
  {
    check_solves(postordered(random_spd(500, 2, 80, 1)));
    check_solves(postordered(random_spd(2000, 1, 40, 2)));
  }
  SECTION("a numbering that is not a postorder, which the factorization permutes inside")
  {
    const Sparse A = random_spd(600, 2, 40, 7);
    const std::vector<int> post = Cholesky::postorder(Cholesky::elimination_tree(A));
    bool identity = true;
    for(std::size_t k = 0; k < post.size(); ++k) identity = identity && post[k] == static_cast<int>(k);
    REQUIRE_FALSE(identity);
    check_solves(A);
  }
  SECTION("a forest: no coupling at all, and one row")
  {
    check_solves(postordered(random_spd(300, 0, 0, 3)));
    check_solves(postordered(random_spd(1, 0, 0, 4)));
  }
}

// The concurrent factorization and solves must give the sequential ones' bits: every front
// and every update in the same order, whichever thread makes it.
void check_concurrent_bits(const Sparse& A, bool expect_subtrees)
{
  Cholesky sequential, concurrent;
  concurrent.set_parallel(true);
  REQUIRE(sequential.factor(A));
  REQUIRE(concurrent.factor(A));
  CHECK(sequential.number_of_concurrent_subtrees() == 0);
  if(expect_subtrees) CHECK(concurrent.number_of_concurrent_subtrees() >= 2);
  for(int k = 0; k < 3; ++k)
  {
    Eigen::VectorXd x(A.rows());
    for(Eigen::Index i = 0; i < x.size(); ++i) x[i] = std::cos(0.3 * double(i) * (k + 1)) - 0.5 * k;
    Eigen::VectorXd y = x;
    sequential.solve_in_place(x.data());
    concurrent.solve_in_place(y.data());
    for(Eigen::Index i = 0; i < x.size(); ++i)
      if(x[i] != y[i]) FAIL("row " << i << ": " << x[i] << " sequentially, " << y[i] << " on threads");
  }
}

TEST_CASE("supernodal Cholesky: on concurrent threads, the same bits", "[embedding][numerics]")
{
  SECTION("a mesh Laplacian, whose elimination tree branches into sizable subtrees")
  {
    check_concurrent_bits(shifted_torus_laplacian(120, 48), true);
  }
  SECTION("random patterns, a forest, one row")
  {
    check_concurrent_bits(postordered(random_spd(2000, 1, 40, 2)), false);
    check_concurrent_bits(random_spd(600, 2, 40, 7), false);   // not a postorder: permuted inside
    check_concurrent_bits(postordered(random_spd(300, 0, 0, 3)), false);
    check_concurrent_bits(postordered(random_spd(1, 0, 0, 4)), false);
  }
}

TEST_CASE("supernodal Cholesky: the same bits whatever cache sizes Eigen has read", "[embedding][numerics]")
{
  // Eigen blocks the fronts' dense kernels by the cache sizes it reads from the processor:
  // without the factor's own fixed blocking, a front 700 rows wide is summed in another
  // order under small caches than under large ones
  const Sparse A = postordered(random_spd(1200, 1, 700, 11));
  const std::ptrdiff_t l1 = Eigen::l1CacheSize(), l2 = Eigen::l2CacheSize(), l3 = Eigen::l3CacheSize();
  std::vector<Eigen::VectorXd> solutions;
  const std::ptrdiff_t sizes[3][3] = { { 16 * 1024, 128 * 1024, 1024 * 1024 },
                                       { 64 * 1024, 4 * 1024 * 1024, 64 * 1024 * 1024 },
                                       { 48 * 1024, 2 * 1024 * 1024, 96 * 1024 * 1024 } };
  for(const auto& s : sizes)
  {
    const SV::internal::Fixed_dense_blocking machine(s[0], s[1], s[2]);   // as if the processor had these caches
    Cholesky cholesky;
    REQUIRE(cholesky.factor(A));
    CHECK(Eigen::l1CacheSize() == s[0]);   // the factor put back what it found
    CHECK(Eigen::l2CacheSize() == s[1]);
    CHECK(Eigen::l3CacheSize() == s[2]);
    Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(A.rows(), -1, 2);
    cholesky.solve_in_place(x.data());
    solutions.push_back(x);
  }
  CHECK(Eigen::l1CacheSize() == l1);
  CHECK(Eigen::l2CacheSize() == l2);
  CHECK(Eigen::l3CacheSize() == l3);
  for(std::size_t k = 1; k < solutions.size(); ++k)
    for(Eigen::Index i = 0; i < solutions[0].size(); ++i)
      if(solutions[k][i] != solutions[0][i])
        FAIL("row " << i << ": " << solutions[0][i] << " under the first cache sizes, " << solutions[k][i] << " under set " << k);
}

TEST_CASE("supernodal Cholesky: new values on the same pattern are factorized anew", "[embedding][numerics]")
{
  const Sparse A = postordered(random_spd(800, 2, 50, 5));
  Cholesky cholesky;
  REQUIRE(cholesky.factor(A));
  Sparse B = A;
  for(Eigen::Index j = 0; j < B.outerSize(); ++j)
    for(Sparse::InnerIterator it(B, j); it; ++it)
      if(it.row() == it.col()) it.valueRef() *= 3;
  REQUIRE(cholesky.factor(B));
  Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(B.rows(), -1, 2), x = b;
  cholesky.solve_in_place(x.data());
  CHECK((B.selfadjointView<Eigen::Lower>() * x - b).norm() <= 1e-11 * b.norm());
}

TEST_CASE("supernodal Cholesky: a matrix that is not positive definite is refused", "[embedding][numerics]")
{
  Sparse A = postordered(random_spd(400, 2, 60, 6));
  SV::internal::Supernodal_cholesky_traits traits;
  double determinant = 0;
  REQUIRE(traits.factor(A, determinant));
  // a row in the wide block, then a row of a narrow supernode, made negative
  for(const Eigen::Index bad : { A.rows() - 3, Eigen::Index(7) })
  {
    Sparse B = A;
    B.coeffRef(bad, bad) = -B.coeff(bad, bad);
    CHECK_FALSE(traits.factor(B, determinant));
    CHECK_FALSE(traits.factorization().ok());
    Eigen::VectorXd b = Eigen::VectorXd::Ones(B.rows()), x;
    CHECK_FALSE(traits.linear_solver(b, x));
  }
}

TEST_CASE("supernodal Cholesky: a postorder keeps every subtree's columns consecutive", "[embedding][numerics]")
{
  for(unsigned seed = 10; seed < 14; ++seed)
  {
    const Sparse A = random_spd(700, 1, 0, seed);   // sparse enough for a forest of several trees
    const std::vector<int> parent = Cholesky::elimination_tree(A);
    const std::vector<int> post = Cholesky::postorder(parent);
    REQUIRE(post.size() == parent.size());
    std::vector<int> position(post.size(), -1);
    for(std::size_t k = 0; k < post.size(); ++k)
    {
      REQUIRE(position[static_cast<std::size_t>(post[k])] == -1);
      position[static_cast<std::size_t>(post[k])] = static_cast<int>(k);
    }
    // a subtree of s descendants ends at s and starts s positions before: every node's
    // descendants fill the positions just before it
    std::vector<int> size(parent.size(), 1);
    for(int v : post)
      if(parent[static_cast<std::size_t>(v)] >= 0) size[static_cast<std::size_t>(parent[static_cast<std::size_t>(v)])] += size[static_cast<std::size_t>(v)];
    for(std::size_t v = 0; v < parent.size(); ++v)
    {
      if(parent[v] >= 0)
      {
        const int p = parent[v];
        CHECK(position[static_cast<std::size_t>(p)] > position[v]);
        CHECK(position[v] >= position[static_cast<std::size_t>(p)] - size[static_cast<std::size_t>(p)] + 1);
      }
    }
    // renumbered by it, the tree's parents all come later
    const std::vector<int> renumbered = Cholesky::elimination_tree(postordered(A));
    for(std::size_t j = 0; j < renumbered.size(); ++j)
      CHECK((renumbered[j] < 0 || renumbered[j] > static_cast<int>(j)));
  }
}

TEST_CASE("supernodal Cholesky: several right-hand sides at once, each as if alone", "[embedding][numerics]")
{
  // a postordered matrix with a block wider than the loops' limit, and one the factorization
  // permutes inside
  for(const Sparse& A : { postordered(random_spd(700, 2, 60, 11)), random_spd(500, 2, 40, 12) })
  {
    Cholesky cholesky;
    REQUIRE(cholesky.factor(A));
    const std::size_t n = std::size_t(A.rows());
    auto rhs = [&](std::size_t i, std::size_t j) { return std::cos(0.37 * double(i) + 1.9 * double(j)) + 0.1 * double(j); };
    std::vector<double> workspace;
    // column j solved alone, the reference for the same column among others
    std::vector<std::vector<double> > alone(17, std::vector<double>(n));
    for(std::size_t j = 0; j < alone.size(); ++j)
    {
      for(std::size_t i = 0; i < n; ++i) alone[j][i] = rhs(i, j);
      cholesky.solve_many_in_place(alone[j].data(), 1, workspace);
      Eigen::VectorXd b(A.rows()), x = Eigen::Map<Eigen::VectorXd>(alone[j].data(), A.rows());
      for(std::size_t i = 0; i < n; ++i) b[Eigen::Index(i)] = rhs(i, j);
      CHECK((A.selfadjointView<Eigen::Lower>() * x - b).norm() <= 1e-11 * b.norm());
    }
    for(std::size_t count : { std::size_t(3), std::size_t(16), std::size_t(17) })
    {
      std::vector<double> X(n * count);
      for(std::size_t i = 0; i < n; ++i)
        for(std::size_t j = 0; j < count; ++j) X[i * count + j] = rhs(i, j);
      cholesky.solve_many_in_place(X.data(), count, workspace);
      bool same = true;
      for(std::size_t i = 0; i < n; ++i)
        for(std::size_t j = 0; j < count; ++j) same = same && X[i * count + j] == alone[j][i];
      CHECK(same);
    }
  }
}

} // namespace svd_test_supernodal_cholesky
