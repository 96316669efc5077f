// Tests of fit_power_weights_to_areas() on the thin lampshade with 200 blue-noise sites, for
// the Euclidean and biharmonic embeddings: equal targets and targets in proportion to a
// density growing with the height, each cell within 1% in at most 50 Newton steps.
#include "test_support.h"

#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Surface_voronoi_diagram/Biharmonic_embedding.h>
#include <CGAL/Surface_voronoi_diagram/Euclidean_embedding.h>
#include <CGAL/Surface_voronoi_diagram/cell_areas.h>
#include <CGAL/Surface_voronoi_diagram/sampling.h>

#include <algorithm>
#include <string>
#include <vector>

// this file's own names: the suite compiles its files together (see CMakeLists.txt)
namespace svd_test_prescribed_areas {

using namespace svd_test;
namespace SV = CGAL::Surface_voronoi;

namespace {

// Fits the cells of a diagram over `metric` on `mesh` to equal areas or to areas growing with
// the sites' height, and checks what the fit reached.
template <class Metric>
void fit(const Mesh& mesh, Metric& metric, bool by_height)
{
  const std::size_t n = 200;
  CGAL::Surface_voronoi_diagram<Mesh, Metric> vd(
      mesh, metric, SV::blue_noise_sites(mesh, n),
      SV::parameters::candidate_selection(SV::Candidate_selection::GLOBAL_NEAREST));
  double low = vd.site_point(0).z(), high = low;
  for(std::size_t i = 0; i < n; ++i)
  {
    low = (std::min)(low, vd.site_point(i).z());
    high = (std::max)(high, vd.site_point(i).z());
  }
  std::vector<double> targets(n);
  double sum = 0;
  for(std::size_t i = 0; i < n; ++i)
    sum += (targets[i] = by_height ? 1 + 2 * (vd.site_point(i).z() - low) / (high - low) : 1.);
  const double reached = vd.surface_area() - vd.unreached_area();
  for(double& t : targets) t *= reached / sum;
  double before = 0;
  for(std::size_t i = 0; i < n; ++i) before = (std::max)(before, std::abs(vd.cell_area(i) - targets[i]) / targets[i]);
  CHECK_THROWS_AS(SV::fit_power_weights_to_areas(vd, metric, std::vector<double>(n - 1, 1.)), SV::Input_error);
  const SV::Area_fit_result r = SV::fit_power_weights_to_areas(vd, metric, targets, 0.01, 50);
  // the areas add up to the surface, no cell is empty, and every cell is within 1%
  double total = vd.unreached_area(), worst = 0;
  for(std::size_t i = 0; i < n; ++i)
  {
    total += vd.cell_area(i);
    worst = (std::max)(worst, std::abs(vd.cell_area(i) - targets[i]) / targets[i]);
  }
  CHECK(std::abs(total - vd.surface_area()) <= 1e-9 * vd.surface_area());
  CHECK(vd.statistics().empty_cells == 0);
  CHECK(worst == Approx(r.max_relative_error));
  CHECK(r.max_relative_error <= before);
  CHECK(worst <= 0.01);
  CHECK(r.iterations <= 50);
}

Mesh example_mesh(const std::string& name)
{
  Mesh m;
  REQUIRE(CGAL::IO::read_polygon_mesh(std::string(SVD_SOURCE_DIR) + "/examples/Surface_voronoi_diagram/data/" + name, m));
  return m;
}

} // namespace

// The goal of issue 54: every cell within 1% in at most 50 Newton steps.
TEST_CASE("prescribed areas: every cell within 1% on the thin lampshade", "[prescribed_areas]")
{
  const Mesh m = example_mesh("lampshade_thin.off");
  SV::Euclidean_embedding<Mesh> euclidean(m);
  CGAL::Biharmonic_embedding<Mesh> biharmonic(m);
  for(bool by_height : { false, true })
  {
    INFO("by height " << by_height);
    fit(m, euclidean, by_height);
    fit(m, biharmonic, by_height);
  }
}

} // namespace svd_test_prescribed_areas
