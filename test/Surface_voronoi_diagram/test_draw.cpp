// CGAL::draw() for a diagram (CGAL/draw_surface_voronoi_diagram.h) without the Qt viewer: it
// compiles, prints a message and returns.
#include "test_support.h"

#include <CGAL/draw_surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/Euclidean_embedding.h>
#include <test_meshes.h>

#include <sstream>
#include <string>

// this file's own names: the suite compiles its files together (see CMakeLists.txt)
namespace svd_test_draw {

using namespace svd_test;
namespace SV = CGAL::Surface_voronoi;
namespace GEN = svd_test::meshes;
typedef SV::Euclidean_embedding<Mesh> Euclidean;

namespace {

// what `f` writes to std::cerr
template <class F>
std::string captured_cerr(F f)
{
  std::ostringstream captured;
  std::streambuf* old = std::cerr.rdbuf(captured.rdbuf());
  f();
  std::cerr.rdbuf(old);
  return captured.str();
}

} // namespace

TEST_CASE("draw: without the Qt viewer it compiles, prints a message and returns", "[draw]")
{
  Mesh m;
  GEN::make_planar_grid(m, 5, 5, 1.0, 1.0);
  Euclidean e(m);
  CGAL::Surface_voronoi_diagram<Mesh, Euclidean> vd(m, e, std::vector<Point>{Point(0.2, 0.2, 0), Point(0.8, 0.7, 0)});
#ifndef CGAL_USE_BASIC_VIEWER
  CHECK(captured_cerr([&] { CGAL::draw(vd); }).find("CGAL_USE_BASIC_VIEWER") != std::string::npos);
  CHECK(captured_cerr([&] { CGAL::draw(vd, "a title"); }).find("CGAL_USE_BASIC_VIEWER") != std::string::npos);
#endif
}

} // namespace svd_test_draw
