// Tests of CGAL/Surface_voronoi_diagram/Vertex_embedding.h and of the lazy-metric path of
// the SurfaceVoronoiMetric concept: a user's embedding and a lazy metric that give the same
// distances as the Euclidean embedding must give the same diagram.
#include "test_support.h"

#include <CGAL/Surface_voronoi_diagram/Euclidean_embedding.h>
#include <CGAL/Surface_voronoi_diagram/Vertex_embedding.h>
#include <test_meshes.h>

// this file's own names: the suite compiles its files together (see CMakeLists.txt)
namespace svd_test_vertex_embedding {

using namespace svd_test;
namespace SV = CGAL::Surface_voronoi;
namespace GEN = svd_test::meshes;

namespace {

// A lazy metric: squared Euclidean distance from the site's point, computed on demand, and
// counting how often it is asked (it must be asked only where sites propagate).
struct Lazy_euclidean
{
  typedef Mesh Triangle_mesh;
  typedef SV::Lazy_metric_tag Metric_category;
  const Mesh* mesh;
  std::vector<Point> sites;
  std::size_t queries = 0;

  explicit Lazy_euclidean(const Mesh& m) : mesh(&m) {}
  const Mesh& triangle_mesh() const { return *mesh; }
  void set_sites(const std::vector<Location<Mesh> >& locations)
  {
    sites.clear();
    for(const auto& l : locations) sites.push_back(point_of(l, *mesh));
  }
  double squared_distance(std::size_t i, Mesh::Vertex_index v)
  {
    ++queries;
    return CGAL::to_double(CGAL::squared_distance(mesh->point(v), sites[i]));
  }
};

} // namespace

TEST_CASE("vertex embedding: a user map equal to xyz gives the Euclidean diagram", "[metric]")
{
  Mesh m;
  GEN::make_torus(m, 1.0, 0.3, 40, 16);
  auto coords = m.add_property_map<Mesh::Vertex_index, std::array<double, 3> >("v:coords").first;
  for(auto v : vertices(m))
    coords[v] = {{ CGAL::to_double(m.point(v).x()), CGAL::to_double(m.point(v).y()), CGAL::to_double(m.point(v).z()) }};
  auto user = SV::make_vertex_embedding(m, coords, 3);
  SV::Euclidean_embedding<Mesh> xyz(m);
  const auto sites = area_uniform_locations(m, 70, 3);
  CGAL::Surface_voronoi_diagram<Mesh, decltype(user)> a(m, user, sites);
  CGAL::Surface_voronoi_diagram<Mesh, SV::Euclidean_embedding<Mesh> > b(m, xyz, sites);
  check_invariants(a);
  for(std::size_t i = 0; i < sites.size(); ++i)
    CHECK(a.cell_area(i) == b.cell_area(i));

  // a wrong dimension is a clear error
  auto wrong = SV::make_vertex_embedding(m, coords, 4);
  CHECK_THROWS_WITH((CGAL::Surface_voronoi_diagram<Mesh, decltype(wrong)>(m, wrong, sites)), Catch::Contains("expected 4"));
}

TEST_CASE("lazy metric: computed only where sites propagate, same diagram as the embedding", "[metric]")
{
  Mesh m;
  GEN::make_icosphere(m, 4, 1.0);
  const auto sites = area_uniform_locations(m, 200, 5);
  Lazy_euclidean lazy(m);
  SV::Euclidean_embedding<Mesh> xyz(m);
  CGAL::Surface_voronoi_diagram<Mesh, Lazy_euclidean> a(m, lazy, sites);
  CGAL::Surface_voronoi_diagram<Mesh, SV::Euclidean_embedding<Mesh> > b(m, xyz, sites);
  check_invariants(a);
  for(std::size_t i = 0; i < sites.size(); ++i)
    CHECK(a.cell_area(i) == Approx(b.cell_area(i)).epsilon(1e-12));
  // far fewer queries than sites x vertices
  CHECK(lazy.queries < num_vertices(m) * sites.size() / 10);
}

} // namespace svd_test_vertex_embedding
