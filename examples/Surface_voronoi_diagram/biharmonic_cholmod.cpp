// The biharmonic embedding with SuiteSparse's CHOLMOD as its linear algebra (the LA template
// parameter), through Eigen's CholmodSupport: a supernodal factorization, for large meshes.
// Built only when CMake finds CHOLMOD (Debian: libsuitesparse-dev).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Surface_voronoi_diagram.h>
#include <CGAL/Eigen_solver_traits.h>

#include <Eigen/CholmodSupport>

#include <iostream>

typedef CGAL::Surface_mesh<CGAL::Epick::Point_3> Mesh;
// L - sigma M is symmetric positive definite: a supernodal Cholesky factorization fits
typedef CGAL::Eigen_solver_traits<Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double> > > Cholmod_LA;
typedef CGAL::Biharmonic_embedding<Mesh, CGAL::Default, CGAL::Default, Cholmod_LA> Embedding;

int main(int argc, char** argv)
{
  const std::string file = argc > 1 ? argv[1] : "data/lampshade_thin.off";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(file, mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "biharmonic_cholmod: cannot read a triangle mesh from " << file << std::endl;
    return EXIT_FAILURE;
  }
  Embedding metric(mesh, CGAL::Surface_voronoi::parameters::embedding_dimension(10));
  std::cout << "eigenvalues:";
  for(Eigen::Index k = 0; k < metric.eigenvalues().size(); ++k)
    std::cout << " " << metric.eigenvalues()[k];
  std::cout << std::endl;

  // the embedding is used as any other: a diagram of a few vertex sites
  std::vector<Mesh::Vertex_index> sites;
  for(std::size_t i = 0; i < num_vertices(mesh); i += num_vertices(mesh) / 20)
    sites.push_back(Mesh::Vertex_index(Mesh::size_type(i)));
  CGAL::Surface_voronoi_diagram<Mesh, Embedding> diagram(mesh, metric, sites);
  std::cout << diagram.number_of_sites() << " cells" << std::endl;
  return EXIT_SUCCESS;
}
