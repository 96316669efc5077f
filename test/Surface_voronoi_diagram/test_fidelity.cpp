// Tests of benchmark/Surface_voronoi_diagram/fidelity.h (the metric study's measurement): the
// exact geodesic reference and the fidelity figures.
#include "test_support.h"

#include <CGAL/Surface_voronoi_diagram/Euclidean_embedding.h>
#include <test_meshes.h>
#include <fidelity.h>   // benchmark/Surface_voronoi_diagram: the fidelity measurement

// this file's own names: the suite compiles its files together (see CMakeLists.txt)
namespace svd_test_fidelity {

using namespace svd_test;
namespace SV = CGAL::Surface_voronoi;
namespace GEN = svd_test::meshes;
typedef SV::Euclidean_embedding<Mesh> Euclidean;

TEST_CASE("fidelity: on a plane the geodesic reference is the nearest site", "[fidelity]")
{
  Mesh m;
  GEN::make_planar_grid(m, 21, 21, 1.0, 1.0, 0.2, 1);
  const auto sites = area_uniform_locations(m, 25, 4);
  svd_bench::Geodesic_reference<Mesh> reference(m, sites);
  std::size_t checked = 0, wrong = 0;
  for(const auto& l : area_uniform_locations(m, 500, 5))
  {
    const Point p = point_of(l, m);
    std::vector<std::pair<double, std::size_t> > d;
    for(std::size_t i = 0; i < sites.size(); ++i) d.emplace_back(std::sqrt(CGAL::to_double(CGAL::squared_distance(p, point_of(sites[i], m)))), i);
    std::sort(d.begin(), d.end());
    if(d[1].first - d[0].first < 1e-9) continue;
    const auto r = reference.nearest(l);
    CHECK(r.first == Approx(d[0].first).epsilon(1e-9));
    wrong += (r.second != d[0].second);
    if(checked < 20)   // one exact single-source tree per call: a few suffice
      CHECK(reference.distance(d[1].second, l) == Approx(d[1].first).epsilon(1e-9));
    ++checked;
  }
  CHECK(wrong == 0);
  CHECK(checked > 450);

  // and the Euclidean diagram of a plane is the geodesic one
  Euclidean e(m);
  CGAL::Surface_voronoi_diagram<Mesh, Euclidean> vd(m, e, sites);
  const svd_bench::Fidelity_report f = svd_bench::measure_fidelity(vd, 1000, 3);
  CHECK(f.mislabeled_share <= 0.002);   // only samples within rounding of a bisector
  CHECK(f.through_wall_upper == 0);
  CHECK(f.unreached_share == 0);
  CHECK(f.broken_cells == 0);
}

TEST_CASE("fidelity: RVD on a U-fold reaches through the gap, biharmonic does not", "[fidelity]")
{
  Mesh m;
  GEN::U_fold_options uo;
  uo.target_vertices = 2500;
  GEN::make_u_fold(m, uo);
  const auto sites = area_uniform_locations(m, 30, 8);
  Euclidean e(m);
  CGAL::Surface_voronoi_diagram<Mesh, Euclidean> rvd(m, e, sites,
                                                     SV::parameters::candidate_selection(SV::Candidate_selection::GLOBAL_NEAREST));
  CGAL::Biharmonic_embedding<Mesh> b(m);
  CGAL::Surface_voronoi_diagram<Mesh> bvd(m, b, sites);
  const svd_bench::Fidelity_report fr = svd_bench::measure_fidelity(rvd, 1500, 2, 8);
  const svd_bench::Fidelity_report fb = svd_bench::measure_fidelity(bvd, 1500, 2, 64);
  INFO("RVD mislabeled " << fr.mislabeled_share << " through " << fr.through_wall_lower << "; biharmonic "
       << fb.mislabeled_share << " through <= " << fb.through_wall_upper);
  CHECK(fr.through_wall_lower > 0.05);
  CHECK(fb.through_wall_upper == 0);
  CHECK(fr.mislabeled_share > fb.through_wall_upper);
  CHECK(fr.broken_cells > 0);     // RVD is never repaired
  CHECK(fb.broken_cells == 0);
}

} // namespace svd_test_fidelity
