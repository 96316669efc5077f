// Breaklines (paper 4.7.2): mesh edges marked in an `edge_is_constrained_map` are never
// crossed by a cell. Here two closed loops of edges, the meridians y = 0 of a torus around the
// z axis (data/torus.off: 64 x 24 vertices, radii 1 and 0.35), cut it into two halves; with
// them no cell reaches from one half into the other.
//   breaklines [SITES] [OUT.ply]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>

#include <CGAL/Surface_voronoi_diagram.h>
#include <CGAL/Surface_voronoi_diagram/Euclidean_embedding.h>
#include <CGAL/Surface_voronoi_diagram/sampling.h>
#include <CGAL/Surface_voronoi_diagram/site_colors.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>

typedef CGAL::Surface_mesh<CGAL::Epick::Point_3> Mesh;
namespace SV = CGAL::Surface_voronoi;

// The arrangement, with the site of each face as the property `f:site`.
template <class Diagram>
Mesh arrangement_of(const Diagram& diagram)
{
  Mesh out;
  auto site = out.add_property_map<Mesh::Face_index, std::int32_t>("f:site", -1).first;
  SV::make_arrangement(diagram, out, CGAL::parameters::face_patch_map(site));
  return out;
}

// faces of the arrangement whose site lies in the other half of the torus
template <class Diagram>
std::size_t faces_across(const Diagram& diagram)
{
  const Mesh arrangement = arrangement_of(diagram);
  auto site = arrangement.property_map<Mesh::Face_index, std::int32_t>("f:site").first;
  std::size_t across = 0;
  for(auto f : arrangement.faces())
  {
    double y = 0;   // the centroid's y, up to a positive factor
    for(auto v : vertices_around_face(halfedge(f, arrangement), arrangement)) y += arrangement.point(v).y();
    across += site[f] >= 0 && (y > 0) != (diagram.site_point(std::size_t(site[f])).y() > 0);
  }
  return across;
}

// The arrangement as a binary PLY with a site (`f:site`) and a colour (`f:color`) per face.
template <class Diagram>
bool write_cells_PLY(const std::string& file, const Diagram& diagram)
{
  Mesh out = arrangement_of(diagram);
  auto site = out.property_map<Mesh::Face_index, std::int32_t>("f:site").first;
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
    std::cerr << "usage: breaklines [SITES] [OUT.ply]" << std::endl;
    return EXIT_FAILURE;
  }
  char* end = nullptr;
  const long n = argc > 1 ? std::strtol(argv[1], &end, 10) : 30;
  if(argc > 1 && (*end != '\0' || n < 2 || n > 10000))
  {
    std::cerr << "breaklines: SITES must be an integer between 2 and 10000, got '" << argv[1] << "'" << std::endl;
    return EXIT_FAILURE;
  }
  const std::string out = argc > 2 ? argv[2] : "breaklines.ply";
  try
  {
    const std::string file = "data/torus.off";
    Mesh mesh;
    if(!CGAL::IO::read_polygon_mesh(file, mesh) || !CGAL::is_triangle_mesh(mesh))
    {
      std::cerr << "breaklines: cannot read a triangle mesh from " << file << std::endl;
      return EXIT_FAILURE;
    }
    auto breakline = mesh.add_property_map<Mesh::Edge_index, bool>("e:breakline", false).first;
    std::size_t marked = 0;
    for(Mesh::Edge_index e : mesh.edges())
    {
      const auto& a = mesh.point(mesh.vertex(e, 0));
      const auto& b = mesh.point(mesh.vertex(e, 1));
      breakline[e] = std::abs(a.y()) < 1e-9 && std::abs(b.y()) < 1e-9;
      marked += breakline[e];
    }
    SV::Euclidean_embedding<Mesh> metric(mesh);
    const auto sites = SV::blue_noise_sites(mesh, std::size_t(n), CGAL::parameters::random_seed(3));
    typedef CGAL::Surface_voronoi_diagram<Mesh, SV::Euclidean_embedding<Mesh> > Diagram;
    Diagram free_cells(mesh, metric, sites);
    Diagram kept(mesh, metric, sites, CGAL::parameters::edge_is_constrained_map(breakline));

    std::cout << marked << " breakline edges (two closed loops)" << std::endl;
    std::cout << "arrangement faces owned from the other half: " << faces_across(free_cells)
              << " without breaklines, " << faces_across(kept) << " with them" << std::endl;
    if(!write_cells_PLY(out, kept))
    {
      std::cerr << "breaklines: cannot write " << out << std::endl;
      return EXIT_FAILURE;
    }
    std::cout << "written to " << out << std::endl;
    return faces_across(kept) == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
  }
  catch(const std::exception& e)
  {
    std::cerr << "breaklines: " << e.what() << std::endl;
    return EXIT_FAILURE;
  }
}
