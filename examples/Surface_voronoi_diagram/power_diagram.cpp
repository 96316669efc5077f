// Power diagrams (paper 4.7.1): site i owns the points where |E(x) - E(s_i)|^2 - w_i is
// smallest. Weights are sized by weight_for_length(), and given twice to the named parameter
// site_weight_map, as a vertex property map and as a vector in site order, to show that both
// forms give the same diagram.
//   power_diagram [MESH] [OUT.ply]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/property_map.h>

#include <CGAL/Surface_voronoi_diagram.h>
#include <CGAL/Surface_voronoi_diagram/site_colors.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

typedef CGAL::Surface_mesh<CGAL::Epick::Point_3> Mesh;
typedef CGAL::Biharmonic_embedding<Mesh> Metric;
namespace SV = CGAL::Surface_voronoi;

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

int main(int argc, char** argv)
{
  if(argc > 3)
  {
    std::cerr << "usage: power_diagram [MESH] [OUT.ply]" << std::endl;
    return EXIT_FAILURE;
  }
  const std::string file = argc > 1 ? argv[1] : "data/lampshade_thin.off";
  const std::string out = argc > 2 ? argv[2] : "power_diagram.ply";
  try
  {
    Mesh mesh;
    if(!CGAL::IO::read_polygon_mesh(file, mesh) || !CGAL::is_triangle_mesh(mesh))
    {
      std::cerr << "power_diagram: cannot read a triangle mesh from " << file << std::endl;
      return EXIT_FAILURE;
    }
    if(num_vertices(mesh) < 400)
    {
      std::cerr << "power_diagram: the mesh needs at least 400 vertices for 40 sites" << std::endl;
      return EXIT_FAILURE;
    }
    Metric metric(mesh);
    std::vector<Mesh::Vertex_index> sites;
    for(std::size_t i = 0; i < 40; ++i)
      sites.push_back(Mesh::Vertex_index(Mesh::size_type(i * (num_vertices(mesh) / 40))));
    CGAL::Surface_voronoi_diagram<Mesh> plain(mesh, metric, sites);

    // Weights are in the squared units of the metric, and they mean something only against
    // the squared spacing of the sites around them. Every eighth site gets the weight for half
    // the distance to its nearest site, measured in the metric around it: its cell grows, and
    // no cell is emptied.
    auto weight = mesh.add_property_map<Mesh::Vertex_index, double>("v:weight", 0.).first;
    for(std::size_t i = 0; i < sites.size(); i += 8)
    {
      double nearest = std::numeric_limits<double>::infinity();
      for(std::size_t j = 0; j < sites.size(); ++j)
        if(j != i) nearest = (std::min)(nearest, std::sqrt(CGAL::squared_distance(mesh.point(sites[i]), mesh.point(sites[j]))));
      weight[sites[i]] = SV::weight_for_length(metric, CGAL::Polygon_mesh_processing::locate_vertex<double>(sites[i], mesh),
                                               nearest / 2);
    }

    // the property-map form (weights keyed like the sites) and the vector form (keyed by the
    // site index: CGAL::make_property_map of a vector in site order)
    CGAL::Surface_voronoi_diagram<Mesh> by_map(mesh, metric, sites, SV::parameters::site_weight_map(weight));
    std::vector<double> weights;
    for(Mesh::Vertex_index v : sites) weights.push_back(weight[v]);
    CGAL::Surface_voronoi_diagram<Mesh> by_vector(mesh, metric, sites,
                                                  SV::parameters::site_weight_map(CGAL::make_property_map(weights)));

    // a weighted cell may still shrink where a neighbour got a larger weight
    bool same = true;
    for(std::size_t i = 0; i < sites.size(); ++i)
    {
      same = same && by_map.cell_area(i) == by_vector.cell_area(i);
      if(weight[sites[i]] > 0)
        std::cout << "site " << i << ": weight " << weight[sites[i]] << ", area " << plain.cell_area(i) << " -> "
                  << by_map.cell_area(i) << std::endl;
    }
    std::cout << "map and vector give the same cells: " << (same ? "yes" : "NO") << std::endl;
    std::cout << "empty cells: " << by_map.statistics().empty_cells << std::endl;
    if(!write_cells_PLY(out, by_map))
    {
      std::cerr << "power_diagram: cannot write " << out << std::endl;
      return EXIT_FAILURE;
    }
    std::cout << "written to " << out << std::endl;
    return same ? EXIT_SUCCESS : EXIT_FAILURE;
  }
  catch(const std::exception& e)
  {
    std::cerr << "power_diagram: " << e.what() << std::endl;
    return EXIT_FAILURE;
  }
}
