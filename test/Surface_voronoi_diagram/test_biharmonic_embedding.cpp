// Tests of CGAL/Biharmonic_embedding.h: the spectral embedding against its definition.
#include "test_support.h"

#include <CGAL/Biharmonic_embedding.h>
#include <test_meshes.h>
#include <CGAL/Surface_voronoi_diagram/internal/Spectral/cotangent_laplacian.h>
#include <CGAL/Surface_voronoi_diagram/internal/Spectral/generalized_eigensolver.h>
#include <CGAL/Eigen_solver_traits.h>

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cstring>
#include <random>

// this file's own names: the suite compiles its files together (see CMakeLists.txt)
namespace svd_test_biharmonic_embedding {

using namespace svd_test;
namespace SV = CGAL::Surface_voronoi;
namespace GEN = svd_test::meshes;

namespace {

void matrices(const Mesh& m, Eigen::SparseMatrix<double>& L, Eigen::SparseMatrix<double>& M)
{
  SV::internal::Indexed_mesh<Mesh> im(m, get(CGAL::vertex_point, m));
  SV::internal::assemble_cotangent_laplacian(im.points, im.triangles, L, M);
}

// A torus bent out of its symmetry: its Laplacian's eigenvalues are simple, so eigenvectors and
// embedded distances are unique.
void make_bent_torus(Mesh& m, std::size_t nu, std::size_t nv)
{
  GEN::make_torus(m, 1.0, 0.35, nu, nv);
  for(auto v : vertices(m))
  {
    const Point p = m.point(v);
    m.point(v) = Point(p.x() * (1 + 0.3 * p.z()), 1.1 * p.y() + 0.1 * p.x() * p.x(), p.z());
  }
}

// The assembly by triplets (four per corner, in face order) that the direct one replaces.
void triplet_matrices(const std::vector<SV::internal::Point_d>& points, const std::vector<std::array<std::uint32_t, 3> >& triangles,
                      Eigen::SparseMatrix<double>& L, Eigen::SparseMatrix<double>& M)
{
  const Eigen::Index n = Eigen::Index(points.size());
  std::vector<Eigen::Triplet<double> > lt;
  Eigen::VectorXd mass = Eigen::VectorXd::Zero(n);
  for(const auto& t : triangles)
  {
    const SV::internal::Point_d* p[3] = { &points[t[0]], &points[t[1]], &points[t[2]] };
    const double twice_area = std::sqrt(CGAL::cross_product(*p[1] - *p[0], *p[2] - *p[0]).squared_length());
    for(int k = 0; k < 3; ++k)
    {
      const double half_cot = 0.5 * ((*p[(k + 1) % 3] - *p[k]) * (*p[(k + 2) % 3] - *p[k])) / twice_area;
      const Eigen::Index i = Eigen::Index(t[(k + 1) % 3]), j = Eigen::Index(t[(k + 2) % 3]);
      lt.emplace_back(i, j, -half_cot);
      lt.emplace_back(j, i, -half_cot);
      lt.emplace_back(i, i, half_cot);
      lt.emplace_back(j, j, half_cot);
    }
    for(int k = 0; k < 3; ++k) mass[Eigen::Index(t[k])] += twice_area / 6.0;
  }
  L.resize(n, n);
  L.setFromTriplets(lt.begin(), lt.end());
  std::vector<Eigen::Triplet<double> > mt;
  for(Eigen::Index i = 0; i < n; ++i) mt.emplace_back(i, i, mass[i]);
  M.resize(n, n);
  M.setFromTriplets(mt.begin(), mt.end());
}

bool same_bits(const Eigen::SparseMatrix<double>& a, const Eigen::SparseMatrix<double>& b)
{
  if(a.rows() != b.rows() || a.cols() != b.cols() || a.nonZeros() != b.nonZeros() || !a.isCompressed() || !b.isCompressed())
    return false;
  return std::equal(a.outerIndexPtr(), a.outerIndexPtr() + a.outerSize() + 1, b.outerIndexPtr())
         && std::equal(a.innerIndexPtr(), a.innerIndexPtr() + a.nonZeros(), b.innerIndexPtr())
         && std::memcmp(a.valuePtr(), b.valuePtr(), sizeof(double) * std::size_t(a.nonZeros())) == 0;
}

} // namespace

TEST_CASE("embedding: the direct assembly of L and M is the triplet assembly's bits", "[embedding]")
{
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> jitter(-0.2, 0.2);
  for(int shape = 0; shape < 3; ++shape)
  {
    Mesh m;
    if(shape == 0) GEN::make_icosphere(m, 3, 1.0);
    else if(shape == 1) make_bent_torus(m, 40, 16);
    else GEN::make_planar_grid(m, 30, 20);   // with a border, and right angles: zero cotangents
    if(shape > 0)
      for(auto v : vertices(m))
        if(rng() % 2 == 0)
        {
          const Point p = m.point(v);
          m.point(v) = Point(p.x() + 0.1 * jitter(rng), p.y() + 0.1 * jitter(rng), p.z() + 0.01 * jitter(rng));
        }
    SV::internal::Indexed_mesh<Mesh> im(m, get(CGAL::vertex_point, m));
    std::vector<SV::internal::Point_d> points = im.points;
    std::vector<std::array<std::uint32_t, 3> > triangles(im.triangles.begin(), im.triangles.end());
    if(shape == 2) points.push_back(SV::internal::Point_d(5, 5, 5));   // in no triangle: an empty column
    Eigen::SparseMatrix<double> L, M, L_ref, M_ref;
    SV::internal::assemble_cotangent_laplacian(points, triangles, L, M);
    triplet_matrices(points, triangles, L_ref, M_ref);
    INFO("shape " << shape);
    CHECK(same_bits(L, L_ref));
    CHECK(same_bits(M, M_ref));
    CHECK(L.nonZeros() > Eigen::Index(points.size()));
  }
}

TEST_CASE("embedding: eigenvectors are M-orthonormal and solve L phi = lambda M phi", "[embedding]")
{
  Mesh m;
  GEN::make_torus(m, 1.0, 0.35, 48, 20);
  CGAL::Biharmonic_embedding<Mesh> e(m, SV::parameters::embedding_dimension(12));
  Eigen::SparseMatrix<double> L, M;
  matrices(m, L, M);
  const Eigen::MatrixXd& phi = e.computed_eigenvectors();
  const Eigen::VectorXd& lambda = e.computed_eigenvalues();
  REQUIRE(phi.cols() == 13);
  const Eigen::MatrixXd G = phi.transpose() * M * phi;
  CHECK((G - Eigen::MatrixXd::Identity(13, 13)).cwiseAbs().maxCoeff() < 1e-8);
  // the zero mode (constant): L phi_0 vanishes
  CHECK((L * phi.col(0)).norm() < 1e-10 * L.norm() * phi.col(0).norm());
  for(Eigen::Index k = 1; k < phi.cols(); ++k)
  {
    const Eigen::VectorXd r = L * phi.col(k) - lambda[k] * (M * phi.col(k));
    CHECK(r.norm() / (L * phi.col(k)).norm() < 1e-6);
  }
  // the coordinates are phi_k / lambda_k for the non-zero modes
  auto v = *vertices(m).begin();
  std::vector<double> c(e.dimension());
  e.coordinates(v, c.data());
  for(std::size_t k = 0; k < e.dimension(); ++k)
    CHECK(c[k] == Approx(phi(e.vertex_index(v), Eigen::Index(k + 1)) / lambda[Eigen::Index(k + 1)]).epsilon(1e-12));
}

TEST_CASE("embedding: the smallest eigenvalues match a dense reference solver", "[embedding]")
{
  Mesh m;
  GEN::make_icosphere(m, 2, 1.0);   // 162 vertices: small enough for a dense solve
  Eigen::SparseMatrix<double> L, M;
  matrices(m, L, M);
  const Eigen::MatrixXd Ld(L), Md(M);
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> dense(Ld, Md);
  CGAL::Biharmonic_embedding<Mesh> e(m, SV::parameters::embedding_dimension(20));
  for(Eigen::Index k = 0; k < 21; ++k)
    CHECK(e.computed_eigenvalues()[k] == Approx(dense.eigenvalues()[k]).epsilon(1e-8).margin(1e-9));
}

// The icosphere's spectrum is made of exactly repeated eigenvalues (the sphere's 2l + 1 split
// by the icosahedral symmetry); a dimension that cuts through such a cluster needs every copy
// below the cut, which a Krylov method grown from one vector sees one direction at a time.
TEST_CASE("embedding: no copy of a repeated eigenvalue is missed wherever the dimension cuts", "[embedding]")
{
  Mesh m;
  GEN::make_icosphere(m, 3, 1.0);   // 642 vertices
  Eigen::SparseMatrix<double> L, M;
  matrices(m, L, M);
  const Eigen::MatrixXd Ld(L), Md(M);
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> dense(Ld, Md);
  int missed = 0;
  for(std::size_t d = 10; d <= 40; ++d)
  {
    CGAL::Biharmonic_embedding<Mesh> e(m, SV::parameters::embedding_dimension(d));
    for(Eigen::Index k = 0; k <= Eigen::Index(d); ++k)
      if(e.computed_eigenvalues()[k] != Approx(dense.eigenvalues()[k]).epsilon(1e-8).margin(1e-9))
      {
        ++missed;
        INFO("d = " << d << ", eigenvalue " << k << ": " << e.computed_eigenvalues()[k] << " against " << dense.eigenvalues()[k]);
        CHECK(false);
        break;
      }
  }
  CHECK(missed == 0);
}

TEST_CASE("embedding: unit sphere eigenvalues l(l+1) with multiplicities 2l+1", "[embedding]")
{
  Mesh m;
  GEN::make_icosphere(m, 4, 1.0);   // 2562 vertices
  // l = 1, 2, 3 exactly: 3 + 5 + 7
  CGAL::Biharmonic_embedding<Mesh> e(m, SV::parameters::embedding_dimension(15));
  const Eigen::VectorXd& lambda = e.eigenvalues();
  REQUIRE(lambda.size() == 15);
  CHECK(e.number_of_zero_modes() == 1);
  CHECK(std::abs(e.computed_eigenvalues()[0]) < 1e-8);
  int k = 0;
  for(int l = 1; l <= 3; ++l)
    for(int j = 0; j < 2 * l + 1; ++j, ++k)
      CHECK(lambda[k] == Approx(l * (l + 1)).epsilon(0.01));
}

TEST_CASE("embedding: a mesh with two components skips two zero modes", "[embedding]")
{
  Mesh a, b;
  GEN::make_icosphere(a, 3, 1.0);
  GEN::make_icosphere(b, 3, 1.0);
  for(auto v : vertices(b))
    b.point(v) = b.point(v) + K::Vector_3(5, 0, 0);
  Mesh m = a;
  CGAL::copy_face_graph(b, m);
  CGAL::Biharmonic_embedding<Mesh> e(m);
  CHECK(e.number_of_zero_modes() == 2);
  CHECK(std::abs(e.computed_eigenvalues()[0]) < 1e-8);
  CHECK(std::abs(e.computed_eigenvalues()[1]) < 1e-8);
  // the first embedding eigenvalue is a sphere's first non-zero one (each sphere has it x3)
  CHECK(e.eigenvalues()[0] == Approx(2).epsilon(0.02));
  CHECK(e.eigenvalues()[5] == Approx(2).epsilon(0.02));
  CHECK(e.eigenvalues()[6] == Approx(6).epsilon(0.02));
}

TEST_CASE("embedding: Surface_mesh and Polyhedron_3 give the same embedding", "[embedding]")
{
  Mesh m;
  GEN::make_torus(m, 1.0, 0.4, 30, 12);
  Polyhedron p;
  CGAL::copy_face_graph(m, p);
  CGAL::Biharmonic_embedding<Mesh> em(m);
  CGAL::Biharmonic_embedding<Polyhedron> ep(p);
  for(Eigen::Index k = 0; k < em.eigenvalues().size(); ++k)
    CHECK(ep.eigenvalues()[k] == Approx(em.eigenvalues()[k]).epsilon(1e-9));
}

TEST_CASE("embedding: the largest dimension a mesh allows, and the largest works", "[embedding]")
{
  Mesh m;
  GEN::make_icosphere(m, 0, 1.0);   // 12 vertices, one component
  CHECK(CGAL::Biharmonic_embedding<Mesh>::maximum_dimension(m) == 10);
  const CGAL::Biharmonic_embedding<Mesh> e(m, SV::parameters::embedding_dimension(10));
  CHECK(e.dimension() == 10);
  Mesh two = m;
  CGAL::copy_face_graph(m, two);   // a second component: one more zero eigenvalue
  CHECK(CGAL::Biharmonic_embedding<Mesh>::maximum_dimension(two) == 21);
  // unusable meshes are named by validate_input() (the preconditions are tested in test_preconditions.cpp)
  Mesh flat;
  GEN::make_icosphere(flat, 2, 1.0);
  auto h = halfedge(*faces(flat).begin(), flat);
  flat.point(target(h, flat)) = flat.point(source(h, flat));
  const std::vector<Mesh::Vertex_index> site = { *vertices(flat).begin() };
  const auto problems = SV::validate_input(flat, site);
  REQUIRE(!problems.empty());
  CHECK(problems.front().kind == SV::Input_problem::ZERO_AREA_FACE);
  CHECK(problems.front().message.find("zero area") != std::string::npos);
}

#if defined(NDEBUG) || defined(CGAL_NO_PRECONDITIONS)
TEST_CASE("embedding: a dimension above maximum_dimension() is a clear Input_error in release builds", "[embedding][numerics]")
{
  // A tetrahedron allows 2 (4 vertices, one zero eigenvalue); the precondition guards debug
  // builds (test_preconditions.cpp), this error every other one.
  Mesh m;
  const auto a = m.add_vertex(Point(0, 0, 0)), b = m.add_vertex(Point(1, 0, 0));
  const auto c = m.add_vertex(Point(0, 1, 0)), d = m.add_vertex(Point(0, 0, 1));
  m.add_face(a, c, b);
  m.add_face(a, b, d);
  m.add_face(a, d, c);
  m.add_face(b, c, d);
  REQUIRE(CGAL::Biharmonic_embedding<Mesh>::maximum_dimension(m) == 2);
  CHECK_THROWS_AS(CGAL::Biharmonic_embedding<Mesh>(m, SV::parameters::embedding_dimension(10)), SV::Input_error);
  CHECK_THROWS_WITH(CGAL::Biharmonic_embedding<Mesh>(m, SV::parameters::embedding_dimension(3)), Catch::Contains("at most 2"));
  CHECK(CGAL::Biharmonic_embedding<Mesh>(m, SV::parameters::embedding_dimension(2)).dimension() == 2);
}
#endif

TEST_CASE("embedding: a cap of height 1e-12 in a unit square keeps its zero eigenvalue within rounding noise", "[embedding][numerics]")
{
  // Its cotangents (about 1e12) put the computed zero eigenvalue at about 4e-5 for a first
  // non-zero one of 4: above 1e-6 of it, but within the rounding of L's row sums.
  Mesh m;
  const auto a = m.add_vertex(Point(0, 0, 0)), b = m.add_vertex(Point(1, 0, 0)), c = m.add_vertex(Point(1, 1, 0));
  const auto d = m.add_vertex(Point(0, 1, 0)), e = m.add_vertex(Point(0.5, 1e-12, 0));
  m.add_face(a, e, d);
  m.add_face(e, b, c);
  m.add_face(e, c, d);
  m.add_face(a, b, e);
  const CGAL::Biharmonic_embedding<Mesh> embedding(m, SV::parameters::embedding_dimension(2));
  CHECK(embedding.dimension() == 2);
}

TEST_CASE("embedding: the default factorization agrees with a plain AMD-ordered LDLT within 1e-6", "[embedding][numerics]")
{
  // The default orders its Cholesky factorization by METIS nested dissection when METIS is
  // there and looks for missed repeated eigenvalues with a looser check; the reference is
  // Eigen's LDLT in its own AMD ordering. A bent torus has no symmetry, so its eigenvalues are
  // simple and the embedded distances unique.
  Mesh m;
  make_bent_torus(m, 90, 36);
  typedef CGAL::Eigen_solver_traits<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double> > > Reference_LA;
  const CGAL::Biharmonic_embedding<Mesh> fast(m, SV::parameters::embedding_dimension(12));
  const CGAL::Biharmonic_embedding<Mesh, CGAL::Default, CGAL::Default, Reference_LA> reference(m, SV::parameters::embedding_dimension(12));
  const Eigen::VectorXd& a = fast.computed_eigenvalues();
  const Eigen::VectorXd& b = reference.computed_eigenvalues();
  REQUIRE(a.size() == b.size());
  for(Eigen::Index k = 1; k < a.size(); ++k)
  {
    CHECK(a[k] == Approx(b[k]).epsilon(1e-6));
    if(k + 1 < a.size())
      REQUIRE(b[k + 1] > b[k] * (1 + 1e-3));   // simple: the distances below are unique
  }
  double largest = 0, worst = 0;
  std::vector<Mesh::Vertex_index> vs(vertices(m).begin(), vertices(m).end());
  for(std::size_t i = 0; i < vs.size(); i += 37)
    for(std::size_t j = i + 11; j < vs.size(); j += 53)
    {
      const double d = reference.squared_distance(vs[i], vs[j]);
      largest = (std::max)(largest, d);
      worst = (std::max)(worst, std::abs(fast.squared_distance(vs[i], vs[j]) - d));
    }
  REQUIRE(largest > 0);
  CHECK(worst <= 1e-6 * largest);
}

// The library leaves Eigen's process-wide settings alone: its cache sizes, read from the
// progress callback while the eigen-solver runs, are those the program set.
TEST_CASE("embedding: Eigen's cache sizes stay as they are while an embedding runs", "[embedding][callback]")
{
  const std::ptrdiff_t before[3] = { Eigen::l1CacheSize(), Eigen::l2CacheSize(), Eigen::l3CacheSize() };
  // unusual values, which no library default would give
  const std::ptrdiff_t unusual[3] = { 12345 * 8, 234567 * 8, 3456789 * 8 };
  Eigen::setCpuCacheSizes(unusual[0], unusual[1], unusual[2]);
  Mesh m;
  make_bent_torus(m, 60, 24);
  std::size_t calls = 0, changed = 0;
  const auto callback = [&](double) {
    ++calls;
    if(Eigen::l1CacheSize() != unusual[0] || Eigen::l2CacheSize() != unusual[1] || Eigen::l3CacheSize() != unusual[2])
      ++changed;
    return true;
  };
  const CGAL::Biharmonic_embedding<Mesh> e(m, SV::parameters::embedding_dimension(10).callback(callback));
  const std::ptrdiff_t after[3] = { Eigen::l1CacheSize(), Eigen::l2CacheSize(), Eigen::l3CacheSize() };
  Eigen::setCpuCacheSizes(before[0], before[1], before[2]);
  REQUIRE(!e.is_cancelled());
  CHECK(calls > 3);   // called during the solve, not only before and after it
  CHECK(changed == 0);
  CHECK(after[0] == unusual[0]);
  CHECK(after[1] == unusual[1]);
  CHECK(after[2] == unusual[2]);
}

// The rule behind --dimension auto: at least 10, enough for the sites, and no more.
TEST_CASE("biharmonic dimension: the dimension for n sites resolves them, and one less would not", "[biharmonic]")
{
  namespace SV = CGAL::Surface_voronoi;
  for(std::size_t n : { std::size_t(1), std::size_t(299), std::size_t(300), std::size_t(301), std::size_t(3000), std::size_t(100000) })
  {
    const std::size_t d = SV::biharmonic_dimension_for_sites(n);
    INFO("n = " << n << ", d = " << d);
    CHECK(d >= 10);
    CHECK(SV::biharmonic_resolved_sites(d) >= n);
    if(d > 10) CHECK(SV::biharmonic_resolved_sites(d - 1) < n);
  }
  CHECK(SV::biharmonic_resolved_sites(10) == 300);
}

} // namespace svd_test_biharmonic_embedding

namespace svd_test_biharmonic_embedding {
namespace {

// `count` small closed shells, apart: ellipsoids of `levels`-times subdivided icospheres, each
// with axes of its own (no two components share an eigenvalue by symmetry)
void make_many_shells(Mesh& m, std::size_t count, int levels)
{
  m.clear();
  for(std::size_t i = 0; i < count; ++i)
  {
    Mesh shell;
    GEN::make_icosphere(shell, levels, 1.0);
    const double a = 1 + 0.37 * std::sin(1.3 * double(i)), b = 1 + 0.29 * std::cos(0.7 * double(i)), c = 0.8 + 0.003 * double(i);
    const K::Vector_3 at(3 * double(i % 15), 3 * double(i / 15), 0);
    for(auto v : vertices(shell))
    {
      const Point p = shell.point(v);
      shell.point(v) = Point(a * p.x(), b * p.y(), c * p.z()) + at;
    }
    CGAL::copy_face_graph(shell, m);
  }
}

// the smallest non-zero eigenvalues of each component, by a dense solve on the component
// alone, all together ascending
std::vector<double> componentwise_spectrum(const Mesh& m)
{
  SV::internal::Indexed_mesh<Mesh> im(m, get(CGAL::vertex_point, m));
  std::vector<double> values;
  for(std::size_t c = 0; c < im.number_of_components; ++c)
  {
    std::vector<int> local(im.points.size(), -1);
    std::vector<SV::internal::Point_d> points;
    std::vector<std::array<std::uint32_t, 3> > triangles;
    for(std::size_t f = 0; f < im.triangles.size(); ++f)
    {
      if(std::size_t(im.face_component[f]) != c) continue;
      std::array<std::uint32_t, 3> t;
      for(int k = 0; k < 3; ++k)
      {
        int& l = local[std::size_t(im.triangles[f][k])];
        if(l < 0) { l = int(points.size()); points.push_back(im.points[std::size_t(im.triangles[f][k])]); }
        t[std::size_t(k)] = std::uint32_t(l);
      }
      triangles.push_back(t);
    }
    Eigen::SparseMatrix<double> L, M;
    SV::internal::assemble_cotangent_laplacian(points, triangles, L, M);
    const Eigen::MatrixXd Ld(L), Md(M);
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> dense(Ld, Md);
    for(Eigen::Index k = 1; k < dense.eigenvalues().size(); ++k)   // the first is the component's zero
      values.push_back(dense.eigenvalues()[k]);
  }
  std::sort(values.begin(), values.end());
  return values;
}

// The oracle of an eigen-solve with the zero modes known: `phi` solves L phi = lambda M phi,
// is M-orthonormal and M-orthogonal to every component's indicator, and `lambda` are the
// smallest of the components' own non-zero eigenvalues.
void check_deflated_eigenpairs(const Eigen::SparseMatrix<double>& L, const Eigen::SparseMatrix<double>& M,
                               const std::vector<int>& component, std::size_t components,
                               const Eigen::VectorXd& lambda, const Eigen::MatrixXd& phi, const std::vector<double>& expected)
{
  const Eigen::Index d = lambda.size();
  REQUIRE(phi.cols() == d);
  const Eigen::MatrixXd G = phi.transpose() * M * phi;
  CHECK((G - Eigen::MatrixXd::Identity(d, d)).cwiseAbs().maxCoeff() < 1e-8);
  double worst_indicator = 0, worst_residual = 0, worst_value = 0;
  for(Eigen::Index k = 0; k < d; ++k)
  {
    const Eigen::VectorXd Mphi = M * phi.col(k);
    std::vector<double> on(components, 0.), mass(components, 0.);
    for(std::size_t i = 0; i < component.size(); ++i)
    {
      on[std::size_t(component[i])] += Mphi[Eigen::Index(i)];
      mass[std::size_t(component[i])] += M.coeff(Eigen::Index(i), Eigen::Index(i));
    }
    for(std::size_t c = 0; c < components; ++c)   // against the M-normalized indicator
      worst_indicator = (std::max)(worst_indicator, std::abs(on[c]) / std::sqrt(mass[c]));
    const Eigen::VectorXd r = L * phi.col(k) - lambda[k] * Mphi;
    worst_residual = (std::max)(worst_residual, r.norm() / (L * phi.col(k)).norm());
    worst_value = (std::max)(worst_value, std::abs(lambda[k] - expected[std::size_t(k)]) / expected[std::size_t(k)]);
  }
  CHECK(worst_indicator < 1e-10);
  CHECK(worst_residual < 1e-6);
  CHECK(worst_value < 1e-8);
}

std::vector<int> vertex_components(const Mesh& m)
{
  SV::internal::Indexed_mesh<Mesh> im(m, get(CGAL::vertex_point, m));
  std::vector<int> component(im.points.size(), -1);
  for(std::size_t f = 0; f < im.triangles.size(); ++f)
    for(int k = 0; k < 3; ++k)
      component[std::size_t(im.triangles[f][k])] = int(im.face_component[f]);
  return component;
}

} // namespace

// CAD assemblies come in a hundred parts and more (CGAL's boeing.off: 122): a Lanczos run
// asked for as many zero eigenvalues at the shift besides the embedding's failed to resolve
// them. The zero modes are known and deflated; the solver finds only the non-zero ones.
TEST_CASE("embedding: a mesh of 150 components gets its embedding, the zero modes deflated", "[embedding][components]")
{
  Mesh m;
  make_many_shells(m, 150, 1);   // 42 vertices each
  Eigen::SparseMatrix<double> L, M;
  matrices(m, L, M);
  const std::vector<int> component = vertex_components(m);
  const std::vector<double> expected = componentwise_spectrum(m);
  for(std::size_t d : { std::size_t(10), std::size_t(40) })
  {
    INFO("d = " << d);
    CGAL::Biharmonic_embedding<Mesh> e(m, SV::parameters::embedding_dimension(d));
    REQUIRE(e.number_of_zero_modes() == 150);
    REQUIRE(e.dimension() == d);
    REQUIRE(e.computed_eigenvalues().size() == Eigen::Index(150 + d));
    REQUIRE(e.computed_eigenvectors().cols() == Eigen::Index(150 + d));
    // the zero modes first: each an M-normalized indicator in L's null space
    const Eigen::MatrixXd& all = e.computed_eigenvectors();
    const Eigen::MatrixXd Z = all.leftCols(150);
    CHECK((Z.transpose() * M * Z - Eigen::MatrixXd::Identity(150, 150)).cwiseAbs().maxCoeff() < 1e-12);
    CHECK((L * Z).cwiseAbs().maxCoeff() < 1e-10 * L.diagonal().maxCoeff());
    CHECK(e.computed_eigenvalues().head(150).cwiseAbs().maxCoeff() == 0);
    check_deflated_eigenpairs(L, M, component, 150, e.eigenvalues(), all.rightCols(Eigen::Index(d)), expected);
    // the coordinates are phi_k / lambda_k
    auto v = *vertices(m).begin();
    std::vector<double> c(d);
    e.coordinates(v, c.data());
    for(std::size_t k = 0; k < d; ++k)
      CHECK(c[k] == Approx(all(Eigen::Index(e.vertex_index(v)), Eigen::Index(150 + k)) / e.eigenvalues()[Eigen::Index(k)]).epsilon(1e-12));
  }
}

} // namespace svd_test_biharmonic_embedding
