// The package's colour scheme, CGAL/Surface_voronoi_diagram/site_colors.h. The program's PLY
// files carry these colours and the regression matrix hashes those files, so the values are
// pinned here: a change of formula fails this test before it changes every output.
#include <CGAL/Surface_voronoi_diagram/site_colors.h>

#include <catch2/catch.hpp>

#include <array>
#include <cstdint>
#include <cstdlib>
#include <set>

// this file's own names: the suite compiles its files together (see CMakeLists.txt)
namespace svd_test_site_colors {

namespace {

std::array<int, 4> rgba(const CGAL::IO::Color& c) { return {{c.red(), c.green(), c.blue(), c.alpha()}}; }

} // namespace

TEST_CASE("site_color: pinned values, grey for no site, opaque", "[colors]")
{
  using CGAL::Surface_voronoi::site_color;
  CHECK(rgba(site_color(0)) == std::array<int, 4>{{242, 198, 133, 255}});
  CHECK(rgba(site_color(1)) == std::array<int, 4>{{98, 51, 205, 255}});
  CHECK(rgba(site_color(2)) == std::array<int, 4>{{80, 233, 83, 255}});
  CHECK(rgba(site_color(3)) == std::array<int, 4>{{197, 87, 117, 255}});
  CHECK(rgba(site_color(7)) == std::array<int, 4>{{78, 179, 134, 255}});
  CHECK(rgba(site_color(100)) == std::array<int, 4>{{179, 63, 130, 255}});
  CHECK(rgba(site_color(12345)) == std::array<int, 4>{{95, 32, 199, 255}});
  CHECK(rgba(site_color(-1)) == std::array<int, 4>{{160, 160, 160, 255}});
  CHECK(rgba(site_color(-7)) == rgba(site_color(-1)));
}

TEST_CASE("site_color: consecutive sites differ, and colours spread over many sites", "[colors]")
{
  using CGAL::Surface_voronoi::site_color;
  std::set<std::array<int, 4> > distinct;
  for(std::int64_t i = 0; i < 1000; ++i)
  {
    const CGAL::IO::Color a = site_color(i), b = site_color(i + 1);
    const int difference = std::abs(a.red() - b.red()) + std::abs(a.green() - b.green()) + std::abs(a.blue() - b.blue());
    CHECK(difference > 40);
    CHECK(a.alpha() == 255);
    CHECK(rgba(a) != rgba(site_color(-1)));
    distinct.insert(rgba(a));
  }
  CHECK(distinct.size() > 900);
}

} // namespace svd_test_site_colors
