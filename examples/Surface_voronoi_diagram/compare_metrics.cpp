// One set of sites on a thin shell, four diagrams: the biharmonic embedding, the Euclidean
// embedding with propagation (EDBVD), the geodesic metric and the restricted Voronoi diagram
// (RVD, every site that is nearest somewhere, no propagation). The RVD reaches through the thin
// wall, so its cells fall into several pieces; propagation keeps every cell in one piece. The
// last column is the share of the area labelled differently from the exact geodesic Voronoi
// diagram (CGAL's Surface_mesh_shortest_path, all sites as sources).
//   compare_metrics [MESH] [SITES]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Surface_voronoi_diagram.h>
#include <CGAL/Surface_voronoi_diagram/Euclidean_embedding.h>
#include <CGAL/Surface_voronoi_diagram/Geodesic_metric.h>
#include <CGAL/Surface_voronoi_diagram/fidelity.h>
#include <CGAL/Surface_voronoi_diagram/IO/read_checked_triangle_mesh.h>
#include <CGAL/Surface_voronoi_diagram/IO/write_arrangement_PLY.h>
#include <CGAL/Surface_voronoi_diagram/sampling.h>

#include <algorithm>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <string>

typedef CGAL::Surface_mesh<CGAL::Epick::Point_3> Mesh;
typedef CGAL::Polygon_mesh_processing::Face_location<Mesh, double> Location;
namespace SV = CGAL::Surface_voronoi;

template <class Metric>
void run(const char* name, const Mesh& mesh, Metric& metric, const std::vector<Location>& sites,
         SV::Candidate_selection candidates, SV::Geodesic_reference<Mesh>& exact)
{
  SV::Diagram_options options;
  options.candidates = candidates;
  const CGAL::Surface_voronoi_diagram<Mesh, Metric> d(mesh, metric, sites, options);
  const SV::Diagram_statistics& s = d.statistics();
  double smallest = d.surface_area(), largest = 0;
  for(std::size_t i = 0; i < d.number_of_sites(); ++i)
    if(d.cell_area(i) > 0)
    {
      smallest = (std::min)(smallest, d.cell_area(i));
      largest = (std::max)(largest, d.cell_area(i));
    }
  const double mean = d.surface_area() / double(d.number_of_sites());
  const double mislabeled = SV::measure_fidelity(d, exact, 5000, 1, 0).mislabeled_share;
  std::cout << std::left << std::setw(11) << name << std::right << std::setw(6) << s.cells << std::setw(8)
            << s.pieces << std::setw(8) << s.broken_cells << std::setw(10) << smallest / mean << std::setw(10)
            << largest / mean << std::setw(11) << 100 * mislabeled << "%" << std::endl;
  SV::IO::write_arrangement_PLY(std::string("compare_") + name + ".ply", d);
}

int main(int argc, char** argv)
{
  if(argc > 3)
  {
    std::cerr << "usage: compare_metrics [MESH] [SITES]" << std::endl;
    return EXIT_FAILURE;
  }
  const std::string file = argc > 1 ? argv[1] : "data/lampshade_thin.off";
  char* end = nullptr;
  const long n = argc > 2 ? std::strtol(argv[2], &end, 10) : 300;
  if(argc > 2 && (end == argv[2] || *end != '\0' || n < 2 || n > 100000))
  {
    std::cerr << "compare_metrics: SITES must be an integer between 2 and 100000, got '" << argv[2] << "'" << std::endl;
    return EXIT_FAILURE;
  }
  try
  {
    Mesh mesh;
    SV::IO::read_checked_triangle_mesh(file, mesh);
    const std::vector<Location> sites = SV::blue_noise_sites(mesh, std::size_t(n), 5);
    CGAL::Biharmonic_embedding<Mesh> biharmonic(mesh);
    SV::Euclidean_embedding<Mesh> euclidean(mesh);
    SV::Geodesic_metric<Mesh> geodesic(mesh);
    SV::Geodesic_reference<Mesh> exact(mesh, sites);
    std::cout << "metric      cells  pieces  broken  min area  max area  mislabeled (areas relative to the mean)" << std::endl;
    run("biharmonic", mesh, biharmonic, sites, SV::Candidate_selection::PROPAGATION, exact);
    run("euclidean", mesh, euclidean, sites, SV::Candidate_selection::PROPAGATION, exact);
    run("geodesic", mesh, geodesic, sites, SV::Candidate_selection::PROPAGATION, exact);
    run("rvd", mesh, euclidean, sites, SV::Candidate_selection::GLOBAL_NEAREST, exact);
    std::cout << "written to compare_biharmonic.ply, compare_euclidean.ply, compare_geodesic.ply and compare_rvd.ply" << std::endl;
  }
  catch(const std::exception& e)
  {
    std::cerr << "compare_metrics: " << e.what() << std::endl;
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
