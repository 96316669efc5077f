// A metric of one's own. Two concepts: a SurfaceVoronoiEmbedding gives coordinates per
// vertex (cutting is then exact); a SurfaceVoronoiLazyMetric gives the squared distance
// between a site and a vertex when the diagram asks. This lazy metric measures distances in
// space with the z axis stretched (an anisotropic metric), and counts the queries: the
// diagram asks only where a site can win, a small multiple of the number of vertices.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/Surface_voronoi_diagram.h>
#include <CGAL/Surface_voronoi_diagram/sampling.h>

#include <iostream>
#include <vector>

typedef CGAL::Epick K;
typedef K::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
namespace SV = CGAL::Surface_voronoi;

// a model of SurfaceVoronoiLazyMetric
class Stretched_metric
{
public:
  typedef Mesh Triangle_mesh;
  typedef SV::Lazy_metric_tag Metric_category;

  Stretched_metric(const Mesh& mesh, double stretch) : m_mesh(&mesh), m_stretch(stretch) {}

  // the mesh the metric belongs to: the diagram checks it is its own
  const Mesh& triangle_mesh() const { return *m_mesh; }

  // called once by the diagram, before any distance
  void set_sites(const std::vector<CGAL::Polygon_mesh_processing::Face_location<Mesh, double> >& sites)
  {
    m_sites.clear();
    for(const auto& l : sites) m_sites.push_back(CGAL::Polygon_mesh_processing::construct_point(l, *m_mesh));
    queries = 0;
  }

  // the squared distance between site i and vertex v; power weights are in these units
  double squared_distance(std::size_t i, Mesh::Vertex_index v)
  {
    ++queries;
    const Point& p = m_mesh->point(v);
    const double dx = p.x() - m_sites[i].x(), dy = p.y() - m_sites[i].y(), dz = m_stretch * (p.z() - m_sites[i].z());
    return dx * dx + dy * dy + dz * dz;
  }

  std::size_t queries = 0;

private:
  const Mesh* m_mesh;
  double m_stretch;
  std::vector<Point> m_sites;
};

int main(int argc, char** argv)
{
  const std::string file = argc > 1 ? argv[1] : "data/lampshade_thin.off";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(file, mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "user_metric: cannot read a triangle mesh from " << file << std::endl;
    return EXIT_FAILURE;
  }
  Stretched_metric metric(mesh, 3.0);
  const auto sites = SV::random_sites(mesh, 80, CGAL::parameters::random_seed(7));
  const CGAL::Surface_voronoi_diagram<Mesh, Stretched_metric> diagram(mesh, metric, sites);
  std::cout << diagram.statistics().cells << " cells, " << metric.queries << " distances asked for "
            << num_vertices(mesh) << " vertices and " << sites.size() << " sites" << std::endl;
  return diagram.statistics().broken_cells == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
