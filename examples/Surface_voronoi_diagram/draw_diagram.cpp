// Shows a biharmonic Voronoi diagram in CGAL's Basic_viewer_qt (needs Qt5; built only when
// CMake finds CGAL's Qt5 component). Without a display, write the arrangement with its cell
// colours to a PLY file instead (see power_diagram.cpp) and open it in MeshLab.
//   draw_diagram [MESH] [SITES]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>

#include <CGAL/Surface_voronoi_diagram.h>
#include <CGAL/Surface_voronoi_diagram/sampling.h>
#include <CGAL/draw_surface_voronoi_diagram.h>

#include <cstdlib>
#include <iostream>

typedef CGAL::Surface_mesh<CGAL::Epick::Point_3> Mesh;
namespace SV = CGAL::Surface_voronoi;

int main(int argc, char** argv)
{
  const std::string file = argc > 1 ? argv[1] : "data/lampshade_thin.off";
  const std::size_t n = argc > 2 ? std::strtoul(argv[2], nullptr, 10) : 60;
  try
  {
    Mesh mesh;
    if(!CGAL::IO::read_polygon_mesh(file, mesh) || !CGAL::is_triangle_mesh(mesh))
    {
      std::cerr << "draw_diagram: cannot read a triangle mesh from " << file << std::endl;
      return EXIT_FAILURE;
    }
    CGAL::Biharmonic_embedding<Mesh> metric(mesh);
    CGAL::Surface_voronoi_diagram<Mesh> diagram(mesh, metric, SV::random_sites(mesh, n, CGAL::parameters::random_seed(1)));
    CGAL::draw(diagram, "Biharmonic Voronoi diagram");
  }
  catch(const std::exception& e)
  {
    std::cerr << "draw_diagram: " << e.what() << std::endl;
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
