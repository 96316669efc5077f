// Breaklines (paper 4.7.2): mesh edges marked in an `edge_is_constrained_map` are never
// crossed by a cell. Here two closed loops of edges, the meridians y = 0 of a torus, cut it
// into two halves; with them no cell reaches from one half into the other.
//   breaklines [SITES] [OUT.ply]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Surface_voronoi_diagram.h>
#include <CGAL/Surface_voronoi_diagram/Euclidean_embedding.h>
#include <CGAL/Surface_voronoi_diagram/IO/write_arrangement_PLY.h>
#include <CGAL/Surface_voronoi_diagram/mesh_generators.h>
#include <CGAL/Surface_voronoi_diagram/sampling.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>

typedef CGAL::Surface_mesh<CGAL::Epick::Point_3> Mesh;
namespace SV = CGAL::Surface_voronoi;

// faces of the arrangement whose site lies in the other half of the torus
template <class Diagram>
std::size_t faces_across(const Diagram& diagram)
{
  typedef CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3> Out;
  const Out arrangement = SV::IO::arrangement_for_PLY(diagram);
  auto site = arrangement.property_map<Out::Face_index, std::int32_t>("f:site").first;
  std::size_t across = 0;
  for(auto f : arrangement.faces())
  {
    double y = 0;   // the centroid's y, up to a positive factor
    for(auto v : vertices_around_face(halfedge(f, arrangement), arrangement)) y += arrangement.point(v).y();
    across += site[f] >= 0 && (y > 0) != (diagram.site_point(std::size_t(site[f])).y() > 0);
  }
  return across;
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
    Mesh mesh;
    SV::generators::make_torus(mesh, 1.0, 0.35, 64, 24);
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
    const auto sites = SV::blue_noise_sites(mesh, std::size_t(n), 3);
    typedef CGAL::Surface_voronoi_diagram<Mesh, SV::Euclidean_embedding<Mesh> > Diagram;
    Diagram free_cells(mesh, metric, sites);
    Diagram kept(mesh, metric, sites, SV::Diagram_options(), CGAL::parameters::edge_is_constrained_map(breakline));

    std::cout << marked << " breakline edges (two closed loops)" << std::endl;
    std::cout << "arrangement faces owned from the other half: " << faces_across(free_cells)
              << " without breaklines, " << faces_across(kept) << " with them" << std::endl;
    SV::IO::write_arrangement_PLY(out, kept);
    std::cout << "written to " << out << std::endl;
    return faces_across(kept) == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
  }
  catch(const std::exception& e)
  {
    std::cerr << "breaklines: " << e.what() << std::endl;
    return EXIT_FAILURE;
  }
}
