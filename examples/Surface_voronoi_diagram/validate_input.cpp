// Checking input that may be invalid with validate_input() before building a diagram: it runs
// in every build and names what is wrong. Here the last site repeats the first one; the
// example drops the second site of each coincident pair, checks again and builds the diagram.
//   validate_input [MESH]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>

#include <CGAL/Surface_voronoi_diagram.h>

#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Surface_mesh<CGAL::Epick::Point_3> Mesh;
namespace SV = CGAL::Surface_voronoi;

int main(int argc, char** argv)
{
  const std::string file = argc > 1 ? argv[1] : "data/lampshade_thin.off";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(file, mesh))
  {
    std::cerr << "validate_input: cannot read " << file << std::endl;
    return EXIT_FAILURE;
  }
  std::vector<Mesh::Vertex_index> sites;
  for(std::size_t i = 0; i < 20; ++i)
    sites.push_back(Mesh::Vertex_index(Mesh::size_type(i * (num_vertices(mesh) / 20))));
  sites.push_back(sites.front());

  // the mesh's problems come first: a diagram cannot be built on such a mesh at all
  std::vector<SV::Input_problem> problems = SV::validate_input(mesh, sites);
  std::vector<bool> dropped(sites.size(), false);
  for(const SV::Input_problem& p : problems)
  {
    std::cout << p.message << std::endl;
    if(p.kind != SV::Input_problem::COINCIDENT_SITES) return EXIT_FAILURE;
    dropped[p.other] = true;
  }
  std::vector<Mesh::Vertex_index> kept;
  for(std::size_t i = 0; i < sites.size(); ++i)
    if(!dropped[i]) kept.push_back(sites[i]);
  if(!SV::validate_input(mesh, kept).empty()) return EXIT_FAILURE;

  CGAL::Biharmonic_embedding<Mesh> metric(mesh);
  CGAL::Surface_voronoi_diagram<Mesh> diagram(mesh, metric, kept);
  std::cout << problems.size() << " problem(s) found; " << diagram.number_of_sites() << " cells built from "
            << sites.size() << " sites" << std::endl;
  return problems.size() == 1 ? EXIT_SUCCESS : EXIT_FAILURE;
}
