// Tests of CGAL/Surface_voronoi_diagram/curvature_density.h: a density of sites from curvature.
#include "test_support.h"

#include <CGAL/Surface_voronoi_diagram/curvature_density.h>
#include <test_meshes.h>

#include <algorithm>
#include <cmath>

// this file's own names: the suite compiles its files together (see CMakeLists.txt)
namespace svd_test_curvature_density {

using namespace svd_test;
namespace SV = CGAL::Surface_voronoi;
namespace GEN = svd_test::meshes;

namespace {
std::vector<double> density_of(Mesh& m, double ratio = 16.)
{
  auto map = m.add_property_map<Mesh::Vertex_index, double>("v:test_density", -1.).first;
  SV::curvature_density(m, map, SV::parameters::max_density_ratio(ratio));
  std::vector<double> density(num_vertices(m));
  for(auto v : vertices(m)) density[v.idx()] = map[v];
  m.remove_property_map(map);
  return density;
}
} // namespace

TEST_CASE("curvature density: flat is 1, a sphere is uniform, a torus is denser outside", "[curvature_density]")
{
  Mesh plane;
  GEN::make_planar_grid(plane, 9, 9, 1.0, 1.0);
  for(double x : density_of(plane)) CHECK(x == 1.);

  // a sphere bends the same everywhere: (1 + 1)^2 = 4 at every vertex, up to discretization
  Mesh sphere;
  GEN::make_icosphere(sphere, 3, 2.0);
  for(double x : density_of(sphere)) CHECK(x == Approx(4.).epsilon(0.05));

  // a torus with R = 1, r = 0.4: |H| is 1.61 on the outer equator, 0.42 on the inner one
  Mesh torus;
  GEN::make_torus(torus, 1.0, 0.4, 90, 36);
  const std::vector<double> d = density_of(torus);
  double outer = 0, inner = 1e300;
  for(auto v : vertices(torus))
  {
    const double radius = std::hypot(torus.point(v).x(), torus.point(v).y());
    if(radius > 1.39) outer = (std::max)(outer, d[v.idx()]);
    if(radius < 0.61) inner = (std::min)(inner, d[v.idx()]);
  }
  CHECK(outer > 2 * inner);
  for(double x : d) CHECK((x >= 1. && x <= 16.));
}

TEST_CASE("curvature density: the ratio caps sharp creases", "[curvature_density]")
{
  // a box's creases have a curvature that grows as its faces are refined
  Mesh box;
  GEN::make_shape(GEN::Shape::box, box);
  const std::vector<double> capped = density_of(box, 5.);
  CHECK(*std::max_element(capped.begin(), capped.end()) == 5.);
  CHECK(*std::min_element(capped.begin(), capped.end()) == 1.);   // the flat middles of the walls
}

} // namespace svd_test_curvature_density
