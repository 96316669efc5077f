// Cells of prescribed area: the power weights of 200 blue-noise sites on the thin lampshade
// are fitted by fit_power_weights_to_areas() until every cell of the restricted power diagram
// is within 1% of its target, first the same area for all, then areas in proportion to a
// density growing with the height.
//   prescribed_areas [MESH] [SITES]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Surface_voronoi_diagram.h>
#include <CGAL/Surface_voronoi_diagram/Biharmonic_embedding.h>
#include <CGAL/Surface_voronoi_diagram/Euclidean_embedding.h>
#include <CGAL/Surface_voronoi_diagram/cell_areas.h>
#include <CGAL/Surface_voronoi_diagram/sampling.h>
#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Surface_mesh<CGAL::Epick::Point_3> Mesh;
namespace SV = CGAL::Surface_voronoi;

// fits the cells of a diagram over `metric` to equal areas (`by_height` false) or to areas in
// proportion to 1 + the height of the site above the lowest one, relative to the sites' span
template <class Metric>
bool fit(const char* name, const Mesh& mesh, Metric& metric, std::size_t n, bool by_height)
{
  // the restricted power diagram: its areas move smoothly with the weights
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
    sum += (targets[i] = by_height ? 1 + (vd.site_point(i).z() - low) / (high - low) : 1.);
  const double reached = vd.surface_area() - vd.unreached_area();
  for(double& t : targets) t *= reached / sum;
  const SV::Area_fit_result r = SV::fit_power_weights_to_areas(vd, metric, targets, 0.01, 50);
  std::size_t split = 0;   // cells in several pieces: across the thin wall, for the Euclidean metric
  for(std::size_t i = 0; i < n; ++i) split += vd.number_of_pieces(i) > 1;
  std::cout << name << (by_height ? ", areas growing with the height: " : ", equal areas: ")
            << r.iterations << " Newton steps, largest error "
            << 100 * r.max_relative_error << "%, " << split << " cells in several pieces" << std::endl;
  return r.max_relative_error <= 0.01;
}

int main(int argc, char** argv)
{
  const std::string file = argc > 1 ? argv[1] : "data/lampshade_thin.off";
  const std::size_t n = argc > 2 ? std::size_t(std::atol(argv[2])) : 200;
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(file, mesh) || !CGAL::is_triangle_mesh(mesh) || n < 2)
  {
    std::cerr << "usage: prescribed_areas [MESH] [SITES]: cannot read a triangle mesh from " << file << std::endl;
    return EXIT_FAILURE;
  }
  SV::Euclidean_embedding<Mesh> euclidean(mesh);
  CGAL::Biharmonic_embedding<Mesh> biharmonic(mesh);
  bool ok = true;
  for(bool by_height : { false, true })
  {
    ok = fit("Euclidean", mesh, euclidean, n, by_height) && ok;
    ok = fit("biharmonic", mesh, biharmonic, n, by_height) && ok;
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
