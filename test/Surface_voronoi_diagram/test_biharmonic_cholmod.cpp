// CHOLMOD as the biharmonic embedding's linear algebra (the LA parameter, through Eigen's
// CholmodSupport): the same embedding as the default's, up to the sign of each eigenvector
// (the eigenvalues are simple here, so the embedded distances are unique). Compiled only when
// CMake finds CHOLMOD (test/Surface_voronoi_diagram/CMakeLists.txt).
#include "test_support.h"

#include <CGAL/Biharmonic_embedding.h>
#include <CGAL/Eigen_solver_traits.h>
#include <CGAL/Surface_voronoi_diagram.h>
#include <test_meshes.h>

#include <Eigen/CholmodSupport>

#include <algorithm>
#include <cmath>
#include <vector>

// OpenBLAS's, when CHOLMOD's BLAS is OpenBLAS (weak: null with another BLAS)
extern "C" void openblas_set_num_threads(int) __attribute__((weak));

// this file's own names: the suite compiles its files together (see CMakeLists.txt)
namespace svd_test_biharmonic_cholmod {

using namespace svd_test;
namespace SV = CGAL::Surface_voronoi;
namespace GEN = svd_test::meshes;

namespace {

typedef CGAL::Eigen_solver_traits<Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double> > > Cholmod_LA;
typedef CGAL::Biharmonic_embedding<Mesh, CGAL::Default, CGAL::Default, Cholmod_LA> Cholmod_embedding;

// a torus bent out of its symmetry (simple eigenvalues), scaled by `scale`, moved by `shift` along x
void add_bent_torus(Mesh& m, std::size_t nu, std::size_t nv, double shift, double scale = 1)
{
  Mesh t;
  GEN::make_torus(t, 1.0, 0.35, nu, nv);
  for(auto v : vertices(t))
  {
    const Point p = t.point(v);
    t.point(v) = Point(shift + scale * p.x() * (1 + 0.3 * p.z()), scale * (1.1 * p.y() + 0.1 * p.x() * p.x()), scale * p.z());
  }
  m.join(t);
}

void check_same_embedding(const Mesh& m, std::size_t d)
{
  if(openblas_set_num_threads != nullptr)
    openblas_set_num_threads(1);
  const CGAL::Biharmonic_embedding<Mesh> reference(m, SV::parameters::embedding_dimension(d));
  const Cholmod_embedding cholmod(m, SV::parameters::embedding_dimension(d));
  REQUIRE(cholmod.dimension() == d);
  REQUIRE(cholmod.number_of_zero_modes() == reference.number_of_zero_modes());
  const Eigen::VectorXd& a = cholmod.eigenvalues();
  const Eigen::VectorXd& b = reference.eigenvalues();
  REQUIRE(a.size() == b.size());
  for(Eigen::Index k = 0; k < a.size(); ++k)
  {
    CHECK(a[k] == Approx(b[k]).epsilon(1e-8));
    if(k + 1 < a.size())
      REQUIRE(b[k + 1] > b[k] * (1 + 1e-3));   // simple: the distances below are unique
  }
  double largest = 0, worst = 0;
  const std::vector<Mesh::Vertex_index> vs(vertices(m).begin(), vertices(m).end());
  for(std::size_t i = 0; i < vs.size(); i += 29)
    for(std::size_t j = i + 7; j < vs.size(); j += 41)
    {
      const double s = reference.squared_distance(vs[i], vs[j]);
      largest = (std::max)(largest, s);
      worst = (std::max)(worst, std::abs(cholmod.squared_distance(vs[i], vs[j]) - s));
    }
  REQUIRE(largest > 0);
  CHECK(worst <= 1e-7 * largest);
}

} // namespace

TEST_CASE("embedding with CHOLMOD: the default's eigenvalues and distances", "[embedding][cholmod]")
{
  Mesh m;
  add_bent_torus(m, 90, 36, 0);
  check_same_embedding(m, 12);
}

TEST_CASE("embedding with CHOLMOD: two components, zero modes known", "[embedding][cholmod][components]")
{
  // the eigen-solver works in the complement of the components' indicators with any LA
  Mesh m;
  add_bent_torus(m, 60, 24, 0);
  add_bent_torus(m, 50, 20, 4, 1.3);
  check_same_embedding(m, 8);
}

TEST_CASE("embedding with CHOLMOD: the same diagram as the default's", "[embedding][cholmod]")
{
  if(openblas_set_num_threads != nullptr)
    openblas_set_num_threads(1);
  Mesh m;
  add_bent_torus(m, 90, 36, 0);
  CGAL::Biharmonic_embedding<Mesh> reference(m);
  Cholmod_embedding cholmod(m);
  std::vector<Mesh::Vertex_index> sites;
  for(std::size_t i = 0; i < num_vertices(m); i += 97)
    sites.push_back(Mesh::Vertex_index(Mesh::size_type(i)));
  const CGAL::Surface_voronoi_diagram<Mesh> a(m, reference, sites);
  const CGAL::Surface_voronoi_diagram<Mesh, Cholmod_embedding> b(m, cholmod, sites);
  REQUIRE(a.number_of_sites() == b.number_of_sites());
  // every vertex owned by the same site (the sites are spread: no vertex is near a tie)
  std::size_t differ = 0;
  for(auto v : vertices(m))
    if(a.site_of(v) != b.site_of(v)) ++differ;
  CHECK(differ == 0);
}

} // namespace svd_test_biharmonic_cholmod
