// One set of sites on a thin shell, four diagrams: the biharmonic embedding, the Euclidean
// embedding with propagation (EDBVD), the geodesic metric and the restricted Voronoi diagram
// (RVD, every site that is nearest somewhere, no propagation). The RVD reaches through the thin
// wall, so its cells fall into several pieces; propagation keeps every cell in one piece. The
// last column is the share of the area labelled differently from the exact geodesic Voronoi
// diagram, on 5000 area-uniform samples: the exact label of a sample is its geodesic nearest
// site, from CGAL's Surface_mesh_shortest_path with all sites as sources.
//   compare_metrics [MESH] [SITES]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Surface_mesh_shortest_path.h>

#include <CGAL/Surface_voronoi_diagram.h>
#include <CGAL/Surface_voronoi_diagram/Euclidean_embedding.h>
#include <CGAL/Surface_voronoi_diagram/Geodesic_metric.h>
#include <CGAL/Surface_voronoi_diagram/sampling.h>
#include <CGAL/Surface_voronoi_diagram/site_colors.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Epick K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef CGAL::Polygon_mesh_processing::Face_location<Mesh, double> Location;
typedef CGAL::Surface_mesh_shortest_path<CGAL::Surface_mesh_shortest_path_traits<K, Mesh> > Shortest_path;
namespace SV = CGAL::Surface_voronoi;

// The geodesic nearest site of each sample (exact polyhedral geodesics).
std::vector<std::size_t> geodesic_labels(const Mesh& mesh, const std::vector<Location>& sites,
                                         const std::vector<Location>& samples)
{
  Shortest_path paths(mesh);
  for(const Location& s : sites) paths.add_source_point(s);
  paths.build_sequence_tree();
  std::vector<std::size_t> labels;
  for(const Location& l : samples)
  {
    const auto nearest = paths.shortest_distance_to_source_points(l.first, l.second);
    std::size_t index = 0;   // sources are listed in the order they were added
    for(auto it = paths.source_points_begin(); it != nearest.second; ++it) ++index;
    labels.push_back(index);
  }
  return labels;
}

// The arrangement as a binary PLY with a site (`f:site`) and a colour (`f:color`) per face.
template <class Diagram>
bool write_cells_PLY(const std::string& file, const Diagram& diagram)
{
  Mesh out;
  auto site = out.add_property_map<Mesh::Face_index, std::int32_t>("f:site", -1).first;
  SV::make_arrangement(diagram, out, CGAL::parameters::face_patch_map(site));
  auto color = out.add_property_map<Mesh::Face_index, CGAL::IO::Color>("f:color").first;
  for(Mesh::Face_index f : out.faces()) color[f] = SV::site_color(site[f]);
  std::ofstream os(file, std::ios::binary);
  CGAL::IO::set_binary_mode(os);
  return CGAL::IO::write_PLY(os, out) && os.flush();
}

template <class Metric>
bool run(const char* name, const Mesh& mesh, Metric& metric, const std::vector<Location>& sites,
         SV::Candidate_selection candidates, const std::vector<Location>& samples,
         const std::vector<std::size_t>& exact)
{
  const CGAL::Surface_voronoi_diagram<Mesh, Metric> d(mesh, metric, sites,
                                                      SV::parameters::candidate_selection(candidates));
  const SV::Diagram_statistics& s = d.statistics();
  double smallest = d.surface_area(), largest = 0;
  for(std::size_t i = 0; i < d.number_of_sites(); ++i)
    if(d.cell_area(i) > 0)
    {
      smallest = (std::min)(smallest, d.cell_area(i));
      largest = (std::max)(largest, d.cell_area(i));
    }
  const double mean = d.surface_area() / double(d.number_of_sites());
  std::size_t mislabeled = 0;   // unreached samples (no site) count as mislabeled
  for(std::size_t j = 0; j < samples.size(); ++j) mislabeled += (d.site_of(samples[j]) != exact[j]);
  std::cout << std::left << std::setw(11) << name << std::right << std::setw(6) << s.cells << std::setw(8)
            << s.pieces << std::setw(8) << s.broken_cells << std::setw(10) << smallest / mean << std::setw(10)
            << largest / mean << std::setw(11) << 100 * double(mislabeled) / double(samples.size()) << "%" << std::endl;
  return write_cells_PLY(std::string("compare_") + name + ".ply", d);
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
    if(!CGAL::IO::read_polygon_mesh(file, mesh) || !CGAL::is_triangle_mesh(mesh))
    {
      std::cerr << "compare_metrics: cannot read a triangle mesh from " << file << std::endl;
      return EXIT_FAILURE;
    }
    const std::vector<Location> sites = SV::blue_noise_sites(mesh, std::size_t(n), CGAL::parameters::random_seed(5));
    const std::vector<Location> samples = SV::random_sites(mesh, 5000, CGAL::parameters::random_seed(1));
    const std::vector<std::size_t> exact = geodesic_labels(mesh, sites, samples);
    CGAL::Biharmonic_embedding<Mesh> biharmonic(mesh);
    SV::Euclidean_embedding<Mesh> euclidean(mesh);
    SV::Geodesic_metric<Mesh> geodesic(mesh);
    std::cout << "metric      cells  pieces  broken  min area  max area  mislabeled (areas relative to the mean)" << std::endl;
    bool written = run("biharmonic", mesh, biharmonic, sites, SV::Candidate_selection::PROPAGATION, samples, exact);
    written = run("euclidean", mesh, euclidean, sites, SV::Candidate_selection::PROPAGATION, samples, exact) && written;
    written = run("geodesic", mesh, geodesic, sites, SV::Candidate_selection::PROPAGATION, samples, exact) && written;
    written = run("rvd", mesh, euclidean, sites, SV::Candidate_selection::GLOBAL_NEAREST, samples, exact) && written;
    if(!written)
    {
      std::cerr << "compare_metrics: cannot write the PLY files" << std::endl;
      return EXIT_FAILURE;
    }
    std::cout << "written to compare_biharmonic.ply, compare_euclidean.ply, compare_geodesic.ply and compare_rvd.ply" << std::endl;
  }
  catch(const std::exception& e)
  {
    std::cerr << "compare_metrics: " << e.what() << std::endl;
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
