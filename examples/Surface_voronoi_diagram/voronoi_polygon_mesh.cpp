// The Voronoi diagram as a polygon mesh: one face per cell, bounded by the cell's boundary,
// its Voronoi vertices marked. Cells that are not disks (a ring around a handle, a cell with
// a hole) cannot be one face: the function returns them and leaves them out.
//   voronoi_polygon_mesh [MESH] [OUT.off]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>

#include <CGAL/Surface_voronoi_diagram.h>
#include <CGAL/Surface_voronoi_diagram/sampling.h>

#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Surface_mesh<CGAL::Epick::Point_3> Mesh;
namespace SV = CGAL::Surface_voronoi;

int main(int argc, char** argv)
{
  const std::string file = argc > 1 ? argv[1] : "data/torus.off";
  const std::string out_file = argc > 2 ? argv[2] : "voronoi_cells.off";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(file, mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "voronoi_polygon_mesh: cannot read a triangle mesh from " << file << std::endl;
    return EXIT_FAILURE;
  }
  CGAL::Biharmonic_embedding<Mesh> metric(mesh);
  const CGAL::Surface_voronoi_diagram<Mesh> diagram(mesh, metric, SV::blue_noise_sites(mesh, 100, CGAL::parameters::random_seed(1)));

  Mesh cells;
  auto site = cells.add_property_map<Mesh::Face_index, std::size_t>("f:site", 0).first;
  auto is_voronoi_vertex = cells.add_property_map<Mesh::Vertex_index, bool>("v:voronoi", false).first;
  const std::vector<std::size_t> left_out = SV::make_voronoi_polygon_mesh(
      diagram, cells, CGAL::parameters::face_patch_map(site).vertex_is_constrained_map(is_voronoi_vertex));

  std::size_t voronoi_vertices = 0;
  for(Mesh::Vertex_index v : cells.vertices()) voronoi_vertices += is_voronoi_vertex[v];
  const long euler = long(cells.number_of_vertices()) - long(cells.number_of_edges()) + long(cells.number_of_faces());
  std::cout << diagram.number_of_sites() << " sites: " << cells.number_of_faces() << " faces, "
            << left_out.size() << " cells left out, " << voronoi_vertices << " Voronoi vertices and "
            << cells.number_of_vertices() - voronoi_vertices << " bend points; "
            << (CGAL::is_closed(cells) ? "closed" : "with border") << ", Euler characteristic " << euler << std::endl;
  for(std::size_t s : left_out) std::cout << "  the cell of site " << s << " is not a disk" << std::endl;

  // the faces are not planar: a renderer that wants triangles can fan them from their centroid
  if(!CGAL::IO::write_polygon_mesh(out_file, cells, CGAL::parameters::stream_precision(17)))
  {
    std::cerr << "voronoi_polygon_mesh: cannot write " << out_file << std::endl;
    return EXIT_FAILURE;
  }
  return CGAL::is_valid_polygon_mesh(cells) ? EXIT_SUCCESS : EXIT_FAILURE;
}
