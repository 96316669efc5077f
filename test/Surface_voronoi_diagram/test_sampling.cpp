// Tests of CGAL/Surface_voronoi_diagram/sampling.h: random and blue-noise sites.
#include "test_support.h"

#include <test_meshes.h>
#include <CGAL/Surface_voronoi_diagram/sampling.h>

using namespace svd_test;
namespace SV = CGAL::Surface_voronoi;
namespace GEN = svd_test::meshes;

namespace {
template <class Locations>
double min_distance(const Mesh& m, const Locations& ls)
{
  double best = 1e300;
  for(std::size_t i = 0; i < ls.size(); ++i)
    for(std::size_t j = i + 1; j < ls.size(); ++j)
      best = (std::min)(best, CGAL::to_double(CGAL::squared_distance(point_of(ls[i], m), point_of(ls[j], m))));
  return std::sqrt(best);
}
} // namespace

TEST_CASE("sampling: blue noise is deterministic, has N sites, and keeps them apart", "[sampling]")
{
  Mesh m;
  GEN::make_icosphere(m, 4, 1.0);
  const auto a = SV::blue_noise_sites(m, 300, CGAL::parameters::random_seed(7));
  const auto b = SV::blue_noise_sites(m, 300, CGAL::parameters::random_seed(7));
  const auto c = SV::blue_noise_sites(m, 300, CGAL::parameters::random_seed(8));
  REQUIRE(a.size() == 300);
  bool same = true, differ = false;
  for(std::size_t i = 0; i < a.size(); ++i)
  {
    same &= (a[i].first == b[i].first && a[i].second == b[i].second);
    differ |= !(a[i].first == c[i].first && a[i].second == c[i].second);
  }
  CHECK(same);
  CHECK(differ);
  const auto r = SV::random_sites(m, 300, CGAL::parameters::random_seed(7));
  // on the unit sphere with 300 sites, a hexagonal packing spaces them about 0.22 apart
  const double blue = min_distance(m, a), random = min_distance(m, r);
  INFO("minimum distance: blue noise " << blue << ", random " << random);
  CHECK(blue > 0.1);
  CHECK(blue > 3 * random);
  // a diagram on blue-noise sites has even cells
  CGAL::Biharmonic_embedding<Mesh> e(m);
  CGAL::Surface_voronoi_diagram<Mesh> vd(m, e, a);
  check_invariants(vd);
  double lo = 1e300, hi = 0;
  for(std::size_t i = 0; i < vd.number_of_sites(); ++i) { lo = (std::min)(lo, vd.cell_area(i)); hi = (std::max)(hi, vd.cell_area(i)); }
  CHECK(hi / lo < 4);
}
