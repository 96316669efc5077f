// Tests of CGAL/Surface_voronoi_diagram/Biharmonic_green_metric.h: its values against the
// biharmonic embedding of full dimension from a dense eigen-decomposition, its diagram
// against the nearest site by that embedding, and the reuse of its columns.
#include "test_support.h"

#include <CGAL/Surface_voronoi_diagram/Biharmonic_green_metric.h>
#include <CGAL/Surface_voronoi_diagram/internal/Spectral/cotangent_laplacian.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <test_meshes.h>

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>

// this file's own names: the suite compiles its files together (see CMakeLists.txt)
namespace svd_test_biharmonic_green_metric {

using namespace svd_test;
namespace SV = CGAL::Surface_voronoi;
namespace GEN = svd_test::meshes;
typedef SV::Biharmonic_green_metric<Mesh> Green;

namespace {

// The oracle: every non-zero eigenpair of L phi = lambda M phi (dense), each vertex embedded at
// phi_k / lambda_k; a surface point at the barycentric mean of its corners' embeddings.
struct Full_embedding
{
  Eigen::MatrixXd coordinates;          // one row per vertex
  std::vector<std::size_t> component;   // of each vertex, by the zero eigenvectors' supports

  explicit Full_embedding(const Mesh& m)
  {
    SV::internal::Indexed_mesh<Mesh> im(m, get(CGAL::vertex_point, m));
    Eigen::SparseMatrix<double> L, M;
    SV::internal::assemble_cotangent_laplacian(im.points, im.triangles, L, M);
    const Eigen::MatrixXd dense_L = L, dense_M = M;
    const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(dense_L, dense_M);
    REQUIRE(solver.info() == Eigen::Success);
    const Eigen::VectorXd& lambda = solver.eigenvalues();
    const Eigen::Index zeros = Eigen::Index(im.number_of_components);
    REQUIRE(std::abs(lambda[zeros - 1]) < 1e-9 * lambda[zeros]);
    const Eigen::Index n = lambda.size();
    coordinates.resize(n, n - zeros);
    for(Eigen::Index k = zeros; k < n; ++k)
      coordinates.col(k - zeros) = solver.eigenvectors().col(k) / lambda[k];
    component.assign(std::size_t(n), 0);
    for(std::size_t f = 0; f < im.triangles.size(); ++f)
      for(auto v : im.triangles[f]) component[v] = im.face_component[f];
  }

  Eigen::RowVectorXd at(const Location<Mesh>& l, const Mesh& m) const
  {
    const auto h = halfedge(l.first, m);
    const Mesh::Vertex_index c[3] = { source(h, m), target(h, m), target(next(h, m), m) };
    Eigen::RowVectorXd e = Eigen::RowVectorXd::Zero(coordinates.cols());
    for(int k = 0; k < 3; ++k) e += l.second[k] * coordinates.row(Eigen::Index(std::size_t(c[k])));
    return e;
  }

  // squared distances of every vertex to every site: rows vertices, columns sites (infinite
  // across components)
  Eigen::MatrixXd squared_distances(const std::vector<Location<Mesh> >& sites, const Mesh& m) const
  {
    Eigen::MatrixXd d(coordinates.rows(), Eigen::Index(sites.size()));
    for(std::size_t i = 0; i < sites.size(); ++i)
    {
      const Eigen::RowVectorXd s = at(sites[i], m);
      const std::size_t c = component[std::size_t(source(halfedge(sites[i].first, m), m))];
      for(Eigen::Index v = 0; v < d.rows(); ++v)
        d(v, Eigen::Index(i)) = component[std::size_t(v)] == c ? (coordinates.row(v) - s).squaredNorm()
                                                                  : std::numeric_limits<double>::infinity();
    }
    return d;
  }
};

// the metric's values against the oracle's squared distances minus the nearest site's
void check_values(const Mesh& m, const std::vector<Location<Mesh> >& sites)
{
  const Full_embedding exact(m);
  const Eigen::MatrixXd d = exact.squared_distances(sites, m);
  Green green(m);
  green.set_sites(sites);
  const double scale = d.array().isFinite().select(d, 0.).maxCoeff();
  REQUIRE(scale > 0);
  double worst = 0;
  std::size_t compared = 0;
  for(auto v : vertices(m))
  {
    const Eigen::Index r = Eigen::Index(std::size_t(v));
    const double nearest = d.row(r).minCoeff();
    for(std::size_t i = 0; i < sites.size(); ++i)
    {
      if(!std::isfinite(d(r, Eigen::Index(i)))) continue;
      const double value = green.squared_distance(i, v);
      CHECK(value >= 0);
      worst = (std::max)(worst, std::abs(value - (d(r, Eigen::Index(i)) - nearest)));
      ++compared;
    }
  }
  CHECK(compared > sites.size());
  CHECK(worst <= 1e-9 * scale);
}

} // namespace

TEST_CASE("biharmonic Green metric: the full-spectrum biharmonic distance, in excess of the nearest site's", "[biharmonic][green]")
{
  SECTION("a closed surface")
  {
    Mesh m;
    GEN::make_torus(m, 1.0, 0.4, 18, 9);
    check_values(m, area_uniform_locations(m, 7, 3));
  }
  SECTION("a surface with a border (the Laplacian's natural boundary condition)")
  {
    Mesh m;
    GEN::make_planar_grid(m, 11, 9, 2.0);
    check_values(m, area_uniform_locations(m, 5, 4));
  }
  SECTION("two components, each with its own sites")
  {
    Mesh a, b;
    GEN::make_icosphere(a, 2, 1.0);
    GEN::make_torus(b, 1.0, 0.3, 14, 8);
    for(auto v : vertices(b)) b.point(v) = b.point(v) + K::Vector_3(5, 0, 0);
    CGAL::copy_face_graph(b, a);
    std::vector<Location<Mesh> > sites = area_uniform_locations(a, 9, 5);
    std::set<std::size_t> components;
    const Full_embedding exact(a);
    for(const auto& s : sites) components.insert(exact.component[std::size_t(source(halfedge(s.first, a), a))]);
    REQUIRE(components.size() == 2);
    check_values(a, sites);
  }
  SECTION("150 components (a CAD assembly), most with sites of their own")
  {
    // each component's Laplacian is held at one vertex of its own; the eigen-solver of the
    // embedding needed the zero modes deflated for as many components (issue 52)
    Mesh m;
    for(int i = 0; i < 150; ++i)
    {
      Mesh shell;
      GEN::make_icosphere(shell, 0, 1.0 + 0.002 * i);
      for(auto v : vertices(shell))
        shell.point(v) = shell.point(v) + K::Vector_3(3 * (i % 15), 3 * (i / 15), 0.1 * std::sin(double(i)));
      CGAL::copy_face_graph(shell, m);
    }
    const std::vector<Location<Mesh> > sites = area_uniform_locations(m, 300, 9);
    check_values(m, sites);
    Green green(m);
    const CGAL::Surface_voronoi_diagram<Mesh, Green> vd(m, green, sites);
    check_invariants(vd);
  }
  SECTION("a site at a vertex, one on an edge")
  {
    Mesh m;
    GEN::make_icosphere(m, 2, 1.0);
    std::vector<Location<Mesh> > sites = area_uniform_locations(m, 4, 6);
    const Mesh::Face_index f = *faces(m).begin();
    sites.push_back({ f, {{ 1., 0., 0. }} });
    sites.push_back({ *std::next(faces(m).begin(), 7), {{ 0.5, 0.5, 0. }} });
    check_values(m, sites);
  }
}

TEST_CASE("biharmonic Green metric: the diagram's cells are those of the nearest site by the full embedding", "[biharmonic][green]")
{
  Mesh m;
  GEN::make_torus(m, 1.0, 0.35, 48, 20);
  const std::vector<Location<Mesh> > sites = area_uniform_locations(m, 24, 8);
  Green green(m);
  const CGAL::Surface_voronoi_diagram<Mesh, Green> vd(m, green, sites);
  check_invariants(vd);

  const Full_embedding exact(m);
  const Eigen::MatrixXd d = exact.squared_distances(sites, m);
  std::size_t checked = 0;
  for(auto v : vertices(m))
  {
    const Eigen::Index r = Eigen::Index(std::size_t(v));
    Eigen::Index nearest;
    const double best = d.row(r).minCoeff(&nearest);
    double second = std::numeric_limits<double>::infinity();
    for(Eigen::Index i = 0; i < d.cols(); ++i)
      if(i != nearest) second = (std::min)(second, d(r, i));
    if(second - best <= 1e-6 * second) continue;   // a tie within rounding: either may win
    CHECK(vd.site_of(v) == std::size_t(nearest));
    ++checked;
  }
  CHECK(checked > num_vertices(m) * 9 / 10);
}

TEST_CASE("biharmonic Green metric: columns kept for the sites that stay, the same bit for bit", "[biharmonic][green]")
{
  Mesh m;
  GEN::make_torus(m, 1.0, 0.35, 30, 12);
  const std::vector<Location<Mesh> > first = area_uniform_locations(m, 40, 9);
  // the same sites in another order, two of them moved, three added: 5 new columns
  std::vector<Location<Mesh> > second(first.rbegin(), first.rend());
  second[3].second = {{ 0.2, 0.3, 0.5 }};
  second[11].second = {{ 0.6, 0.2, 0.2 }};
  for(const auto& l : area_uniform_locations(m, 3, 10)) second.push_back(l);

  Green reused(m);
  reused.set_sites(first);
  CHECK(reused.number_of_computed_columns() == first.size());
  reused.set_sites(second);
  CHECK(reused.number_of_computed_columns() == first.size() + 5);

  Green fresh(m);
  fresh.set_sites(second);
  const Green copy = fresh;
  Green copied = copy;
  copied.set_sites(first);   // a copy's sites are its own
  bool same = true;
  for(auto v : vertices(m))
    for(std::size_t i = 0; i < second.size(); ++i)
      same = same && reused.squared_distance(i, v) == fresh.squared_distance(i, v);
  CHECK(same);
#ifdef CGAL_LINKED_WITH_TBB
  SV::Biharmonic_green_metric<Mesh, CGAL::Default, CGAL::Parallel_tag> parallel(m);
  parallel.set_sites(second);
  bool same_in_parallel = true;
  for(auto v : vertices(m))
    for(std::size_t i = 0; i < second.size(); ++i)
      same_in_parallel = same_in_parallel && parallel.squared_distance(i, v) == fresh.squared_distance(i, v);
  CHECK(same_in_parallel);
#endif
  CHECK_THROWS_AS(fresh.squared_distance(second.size(), *vertices(m).begin()), SV::Input_error);
}

TEST_CASE("biharmonic Green metric: more columns than maximum_column_memory allows are an input error", "[biharmonic][green]")
{
  Mesh m;
  GEN::make_torus(m, 1.0, 0.35, 30, 12);
  const std::size_t n = num_vertices(m);
  const std::vector<Location<Mesh> > sites = area_uniform_locations(m, 12, 3);
  // room for exactly 10 columns
  Green bounded(m, SV::parameters::maximum_column_memory(SV::biharmonic_green_metric_bytes(n, 10)));
  const std::vector<Location<Mesh> > ten(sites.begin(), sites.begin() + 10);
  bounded.set_sites(ten);
  CHECK(bounded.number_of_computed_columns() == 10);
  std::vector<double> before;
  for(auto v : vertices(m))
    for(std::size_t i = 0; i < ten.size(); ++i) before.push_back(bounded.squared_distance(i, v));

  CHECK_THROWS_AS(bounded.set_sites(sites), SV::Input_error);
  // nothing computed, and the ten sites are still the metric's
  CHECK(bounded.number_of_computed_columns() == 10);
  std::vector<double> after;
  for(auto v : vertices(m))
    for(std::size_t i = 0; i < ten.size(); ++i) after.push_back(bounded.squared_distance(i, v));
  CHECK(after == before);
  CHECK_THROWS_AS(bounded.squared_distance(10, *vertices(m).begin()), SV::Input_error);

  // the default (4 GiB) takes them
  Green unbounded(m);
  unbounded.set_sites(sites);
  CHECK(unbounded.number_of_computed_columns() == sites.size());
}

} // namespace svd_test_biharmonic_green_metric
