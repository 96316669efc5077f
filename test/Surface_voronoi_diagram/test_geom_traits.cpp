// The kernel of the user's points does not change the diagram: the pipeline reads the points
// as doubles once, so Epick, Epeck and Simple_cartesian<double> meshes give the same labels
// (and Polyhedron_3 the same as Surface_mesh); the points the diagram returns are of the
// user's kernel.
#include "test_support.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_voronoi_diagram/Euclidean_embedding.h>
#include <CGAL/Surface_voronoi_diagram/Geodesic_metric.h>
#include <test_meshes.h>

#include <type_traits>

// this file's own names: the suite compiles its files together (see CMakeLists.txt)
namespace svd_test_geom_traits {

using namespace svd_test;
namespace SV = CGAL::Surface_voronoi;
namespace GEN = svd_test::meshes;

namespace {

template <class Kernel>
CGAL::Surface_mesh<typename Kernel::Point_3> copy_to_kernel(const Mesh& m)
{
  CGAL::Surface_mesh<typename Kernel::Point_3> out;
  CGAL::copy_face_graph(m, out);
  return out;
}

// the site of every face (at its centroid) and of every vertex, and the cell areas
template <class Diagram>
std::vector<double> labels(const Diagram& d)
{
  typedef typename Diagram::Triangle_mesh TM;
  const TM& tm = d.triangle_mesh();
  std::vector<double> out;
  for(auto f : faces(tm))
    out.push_back(double(d.site_of(typename Diagram::Face_location(f, {{ 1. / 3, 1. / 3, 1. / 3 }}))));
  for(auto v : vertices(tm)) out.push_back(double(d.site_of(v)));
  for(std::size_t i = 0; i < d.number_of_sites(); ++i) out.push_back(d.cell_area(i));
  return out;
}

template <class Kernel, template <class> class Metric_of>
std::vector<double> labels_with(const Mesh& m, const std::vector<Point>& sites)
{
  typedef CGAL::Surface_mesh<typename Kernel::Point_3> TM;
  const TM tm = copy_to_kernel<Kernel>(m);
  std::vector<typename Kernel::Point_3> kernel_sites;
  for(const Point& p : sites) kernel_sites.emplace_back(p.x(), p.y(), p.z());
  Metric_of<TM> metric(tm);
  const CGAL::Surface_voronoi_diagram<TM, Metric_of<TM> > d(tm, metric, kernel_sites);
  static_assert(std::is_same<typename CGAL::Surface_voronoi_diagram<TM, Metric_of<TM> >::Point_3,
                             typename Kernel::Point_3>::value, "points of the user's kernel");
  return labels(d);
}

template <class TM> using Euclidean_of = SV::Euclidean_embedding<TM>;
template <class TM> using Geodesic_of = SV::Geodesic_metric<TM>;
template <class TM> using Biharmonic_of = CGAL::Biharmonic_embedding<TM>;

} // namespace

TEST_CASE("geometric traits: Epick, Epeck and Simple_cartesian<double> give identical labels", "[traits]")
{
  Mesh m;
  GEN::make_torus(m, 1.0, 0.35, 40, 16);
  std::vector<Point> sites;
  for(const auto& l : area_uniform_locations(m, 60, 11)) sites.push_back(point_of(l, m));

  const auto epick = labels_with<CGAL::Epick, Euclidean_of>(m, sites);
  CHECK(labels_with<CGAL::Epeck, Euclidean_of>(m, sites) == epick);
  CHECK(labels_with<CGAL::Simple_cartesian<double>, Euclidean_of>(m, sites) == epick);

  const auto geodesic = labels_with<CGAL::Epick, Geodesic_of>(m, sites);
  CHECK(labels_with<CGAL::Epeck, Geodesic_of>(m, sites) == geodesic);
  CHECK(labels_with<CGAL::Simple_cartesian<double>, Geodesic_of>(m, sites) == geodesic);

  const auto biharmonic = labels_with<CGAL::Epick, Biharmonic_of>(m, sites);
  CHECK(labels_with<CGAL::Epeck, Biharmonic_of>(m, sites) == biharmonic);
  CHECK(labels_with<CGAL::Simple_cartesian<double>, Biharmonic_of>(m, sites) == biharmonic);
  // the labels are not all alike (the comparison could fail)
  CHECK(epick != geodesic);
}

TEST_CASE("geometric traits: site points and centroids are of the traits' point type", "[traits]")
{
  typedef CGAL::Surface_mesh<CGAL::Epeck::Point_3> Exact_mesh;
  Mesh m;
  GEN::make_icosphere(m, 2, 1.0);
  const Exact_mesh em = copy_to_kernel<CGAL::Epeck>(m);
  SV::Euclidean_embedding<Exact_mesh> e(em);
  const std::vector<Exact_mesh::Vertex_index> sites = { Exact_mesh::Vertex_index(0), Exact_mesh::Vertex_index(40) };
  const CGAL::Surface_voronoi_diagram<Exact_mesh, SV::Euclidean_embedding<Exact_mesh> > d(em, e, sites);
  const CGAL::Epeck::Point_3 p = d.site_point(0);
  CHECK(p == em.point(Exact_mesh::Vertex_index(0)));
  const CGAL::Epeck::Point_3 c = d.cell_centroid(1);
  // two cells on a sphere are about hemispheres: the centroid of each is nearer its own site
  CHECK(CGAL::squared_distance(c, em.point(Exact_mesh::Vertex_index(40))) < CGAL::squared_distance(c, em.point(Exact_mesh::Vertex_index(0))));
}

} // namespace svd_test_geom_traits
