// Generates the manual's figures, one PNG per feature, from bundled or generated data only:
//   make_figures OUTPUT_DIR [DATA_DIR]
// DATA_DIR holds lampshade_thin.off (default: examples/Surface_voronoi_diagram/data of the
// source tree, passed by CMake). Everything is seeded: the images are the same on every run.
// One translation unit on purpose: the doc build compiles it, and CGAL headers are slow.
// The renderer and the PNG writer are beside this file (namespace svd_figures): a tool of the
// manual, not part of the library.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <CGAL/Biharmonic_embedding.h>
#include <CGAL/Surface_voronoi_diagram.h>
#include <CGAL/Surface_voronoi_diagram/Euclidean_embedding.h>
#include <CGAL/Surface_voronoi_diagram/Geodesic_metric.h>
#include <CGAL/Surface_voronoi_diagram/cell_areas.h>
#include <CGAL/Surface_voronoi_diagram/dual_triangulation.h>
#include <CGAL/Surface_voronoi_diagram/feature_sites.h>
#include <CGAL/Surface_voronoi_diagram/lloyd_relaxation.h>
#include <CGAL/Surface_voronoi_diagram/sampling.h>

#include "render_PNG.h"
#include <test_meshes.h>   // the generated test shapes (test/Surface_voronoi_diagram/include)

#include <chrono>
#include <cstdlib>
#include <functional>
#include <set>
#include <utility>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

typedef CGAL::Epick K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef CGAL::Polygon_mesh_processing::Face_location<Mesh, double> Location;
namespace SV = CGAL::Surface_voronoi;
namespace GEN = svd_test::meshes;
using svd_figures::Image;
using svd_figures::Render_options;

namespace {

// Panels side by side with a white gap; the manual's captions name them left to right.
Image beside(const std::vector<Image>& panels, std::size_t gap = 8)
{
  std::size_t width = 0, height = 0;
  for(const Image& p : panels)
  {
    width += p.width + (width > 0 ? gap : 0);
    height = (std::max)(height, p.height);
  }
  Image out(width, height);
  std::size_t x0 = 0;
  for(const Image& p : panels)
  {
    for(std::size_t y = 0; y < p.height; ++y)
      for(std::size_t x = 0; x < p.width; ++x) out.set_pixel(x0 + x, y, p.pixel(x, y));
    x0 += p.width + gap;
  }
  return out;
}

Render_options panel(std::size_t width, std::size_t height, std::array<double, 3> view)
{
  Render_options o;
  o.width = width;
  o.height = height;
  o.view_direction = view;
  return o;
}

// The bundled lampshade (the figures need no checks beyond CGAL's reader: the file is ours).
void read_lampshade(const std::string& data, Mesh& mesh)
{
  const std::string file = data + "/lampshade_thin.off";
  if(!CGAL::IO::read_polygon_mesh(file, mesh) || !CGAL::is_triangle_mesh(mesh))
    throw std::runtime_error("cannot read a triangle mesh from " + file);
}

void save(const std::string& dir, const std::string& name, const Image& image)
{
  svd_figures::write_PNG(dir + "/" + name, image);
  std::cout << name << ": " << image.width << " x " << image.height << std::endl;
}

// The same sites under several metrics, one panel each. A row is a name and a function
// that builds the diagram and renders it: add a metric by adding a row.
void metrics_figure(const std::string& dir, const std::string& data)
{
  Mesh mesh;
  read_lampshade(data, mesh);
  const std::vector<Location> sites = SV::random_sites(mesh, 60, CGAL::parameters::random_seed(7));
  // from above and aside: the outside and, through the top opening, the inside wall
  const Render_options o = panel(300, 300, {{-0.6, -1.0, -1.2}});
  struct Row { std::string name; std::function<Image()> render; };
  const std::vector<Row> rows = {
    {"biharmonic", [&] {
       CGAL::Biharmonic_embedding<Mesh> metric(mesh);
       CGAL::Surface_voronoi_diagram<Mesh> diagram(mesh, metric, sites);
       return svd_figures::render_diagram(diagram, o);
     }},
    {"euclidean", [&] {
       SV::Euclidean_embedding<Mesh> metric(mesh);
       CGAL::Surface_voronoi_diagram<Mesh, SV::Euclidean_embedding<Mesh> > diagram(mesh, metric, sites);
       return svd_figures::render_diagram(diagram, o);
     }},
    {"geodesic", [&] {
       SV::Geodesic_metric<Mesh> metric(mesh);
       CGAL::Surface_voronoi_diagram<Mesh, SV::Geodesic_metric<Mesh> > diagram(mesh, metric, sites);
       return svd_figures::render_diagram(diagram, o);
     }},
    {"rvd", [&] {
       SV::Euclidean_embedding<Mesh> metric(mesh);
       CGAL::Surface_voronoi_diagram<Mesh, SV::Euclidean_embedding<Mesh> > diagram(
           mesh, metric, sites, SV::parameters::candidate_selection(SV::Candidate_selection::GLOBAL_NEAREST));
       return svd_figures::render_diagram(diagram, o);
     }},
  };
  std::vector<Image> panels;
  for(const Row& row : rows) panels.push_back(row.render());
  save(dir, "svd_metrics.png", beside(panels));
}

// The README's picture: the biharmonic diagram of the metrics figure, larger.
void readme_figure(const std::string& dir, const std::string& data)
{
  Mesh mesh;
  read_lampshade(data, mesh);
  CGAL::Biharmonic_embedding<Mesh> metric(mesh);
  CGAL::Surface_voronoi_diagram<Mesh> diagram(mesh, metric, SV::random_sites(mesh, 60, CGAL::parameters::random_seed(7)));
  save(dir, "svd_lampshade.png", svd_figures::render_diagram(diagram, panel(480, 360, {{-0.6, -1.0, -1.2}})));
}

// Power diagram on a torus: the same sites without and with weights.
void power_figure(const std::string& dir)
{
  Mesh mesh;
  GEN::make_torus(mesh, 1.0, 0.4, 96, 36);
  const std::vector<Location> sites = SV::random_sites(mesh, 40, CGAL::parameters::random_seed(3));
  SV::Euclidean_embedding<Mesh> metric(mesh);
  const Render_options o = panel(316, 240, {{-0.3, -1.0, -1.0}});
  std::vector<Image> panels;
  std::vector<double> weights(sites.size(), 0.);
  panels.push_back(svd_figures::render_diagram(CGAL::Surface_voronoi_diagram<Mesh, SV::Euclidean_embedding<Mesh> >(mesh, metric, sites), o));
  // every fourth site gets a large weight (squared units: the torus tube radius is 0.4)
  for(std::size_t i = 0; i < sites.size(); i += 4) weights[i] = 0.08;
  panels.push_back(svd_figures::render_diagram(CGAL::Surface_voronoi_diagram<Mesh, SV::Euclidean_embedding<Mesh> >(mesh, metric, sites, SV::parameters::site_weight_map(CGAL::make_property_map(weights))), o));
  save(dir, "svd_power.png", beside(panels));
}

// Cells of prescribed area on a torus (restricted power diagram, Euclidean embedding): the
// weights fitted to equal areas, then to areas growing fourfold along x.
void prescribed_areas_figure(const std::string& dir)
{
  Mesh mesh;
  GEN::make_torus(mesh, 1.0, 0.4, 96, 36);
  SV::Euclidean_embedding<Mesh> metric(mesh);
  const std::vector<Location> sites = SV::blue_noise_sites(mesh, 60, CGAL::parameters::random_seed(3));
  const Render_options o = panel(316, 240, {{-0.3, -1.0, -1.0}});
  std::vector<Image> panels;
  for(double growth : { 0., 3. })
  {
    CGAL::Surface_voronoi_diagram<Mesh, SV::Euclidean_embedding<Mesh> > diagram(
        mesh, metric, sites, SV::parameters::candidate_selection(SV::Candidate_selection::GLOBAL_NEAREST));
    std::vector<double> targets;
    double sum = 0;
    for(std::size_t i = 0; i < sites.size(); ++i)
    {
      targets.push_back(1 + growth * (diagram.site_point(i).x() + 1.4) / 2.8);   // x spans [-1.4, 1.4]
      sum += targets.back();
    }
    for(double& t : targets) t *= diagram.surface_area() / sum;
    const SV::Area_fit_result r = SV::fit_power_weights_to_areas(diagram, metric, targets);
    std::cout << "prescribed areas, growth " << growth << ": " << r.iterations << " steps, largest error "
              << 100 * r.max_relative_error << "%" << std::endl;
    panels.push_back(svd_figures::render_diagram(diagram, o));
  }
  save(dir, "svd_prescribed_areas.png", beside(panels));
}

// Breaklines on a square: an open line and a closed loop, without and with them.
void breaklines_figure(const std::string& dir)
{
  Mesh mesh;
  GEN::make_planar_grid(mesh, 41, 41, 1.0, 1.0);   // unjittered: the lines follow grid edges
  auto breakline = mesh.add_property_map<Mesh::Edge_index, bool>("e:breakline", false).first;
  auto on_lines = [](const K::Point_3& p) {
    const double x = p.x(), y = p.y(), e = 1e-9;
    const bool open_line = std::abs(y - 0.3) < e && x > 0.1 - e && x < 0.6 + e;
    const bool on_loop = ((std::abs(x - 0.55) < e || std::abs(x - 0.85) < e) && y > 0.5 - e && y < 0.9 + e)
                         || ((std::abs(y - 0.5) < e || std::abs(y - 0.9) < e) && x > 0.55 - e && x < 0.85 + e);
    return open_line || on_loop;
  };
  for(Mesh::Edge_index e : mesh.edges())
    breakline[e] = on_lines(mesh.point(mesh.source(mesh.halfedge(e)))) && on_lines(mesh.point(mesh.target(mesh.halfedge(e))));
  std::vector<K::Point_3> sites;
  for(const Location& l : SV::random_sites(mesh, 14, CGAL::parameters::random_seed(11))) sites.push_back(CGAL::Polygon_mesh_processing::construct_point(l, mesh));
  sites.push_back(K::Point_3(0.7, 0.7, 0));   // one site inside the loop
  SV::Euclidean_embedding<Mesh> metric(mesh);
  const Render_options o = panel(316, 300, {{0.0, 0.35, -1.0}});
  std::vector<Image> panels;
  panels.push_back(svd_figures::render_diagram(CGAL::Surface_voronoi_diagram<Mesh, SV::Euclidean_embedding<Mesh> >(mesh, metric, sites), o));
  panels.push_back(svd_figures::render_diagram(CGAL::Surface_voronoi_diagram<Mesh, SV::Euclidean_embedding<Mesh> >(
      mesh, metric, sites, CGAL::parameters::edge_is_constrained_map(breakline)), o));
  save(dir, "svd_breaklines.png", beside(panels));
}

// Lloyd relaxation on a sphere: random sites, then ten steps.
void lloyd_figure(const std::string& dir)
{
  Mesh mesh;
  GEN::make_icosphere(mesh, 4, 1.0);
  const std::vector<Location> sites = SV::random_sites(mesh, 80, CGAL::parameters::random_seed(2));
  SV::Euclidean_embedding<Mesh> metric(mesh);
  const SV::Lloyd_result<Mesh> relaxed = SV::lloyd_relaxation(mesh, metric, sites, CGAL::parameters::number_of_iterations(10));
  const Render_options o = panel(316, 300, {{-0.4, -1.0, -0.5}});
  typedef CGAL::Surface_voronoi_diagram<Mesh, SV::Euclidean_embedding<Mesh> > Diagram;
  save(dir, "svd_lloyd.png", beside({svd_figures::render_diagram(Diagram(mesh, metric, sites), o),
                                     svd_figures::render_diagram(Diagram(mesh, metric, relaxed.sites), o)}));
}

// Remeshing by the dual: blue-noise sites relaxed by Lloyd, their diagram and its dual.
void remeshing_figure(const std::string& dir)
{
  Mesh mesh;
  GEN::make_torus(mesh, 1.0, 0.4, 96, 36);
  SV::Euclidean_embedding<Mesh> metric(mesh);
  const SV::Lloyd_result<Mesh> relaxed = SV::lloyd_relaxation(mesh, metric, SV::blue_noise_sites(mesh, 300, CGAL::parameters::random_seed(1)), CGAL::parameters::number_of_iterations(5));
  CGAL::Surface_voronoi_diagram<Mesh, SV::Euclidean_embedding<Mesh> > diagram(mesh, metric, relaxed.sites);
  std::vector<K::Point_3> points;
  std::vector<std::array<std::size_t, 3> > triangles;
  if(!SV::dual_triangulation(diagram, std::back_inserter(points), std::back_inserter(triangles)))
    throw std::runtime_error("the dual of the torus figure is not a manifold");
  Mesh dual;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, triangles, dual);
  const Render_options o = panel(316, 240, {{-0.3, -1.0, -1.0}});
  // the dual in one colour (all its faces are given site 0) with all its edges and flat
  // shading: the triangles are what matters
  Render_options flat = o;
  flat.crease_angle = 0;
  flat.site_radius = 0;
  flat.edge_width = 1.0;
  const Image dual_image = svd_figures::render_arrangement(dual, CGAL::Constant_property_map<Mesh::Face_index, int>(0),
                                                      std::vector<K::Point_3>(), flat,
                                                      CGAL::parameters::edge_is_constrained_map(
                                                          CGAL::Constant_property_map<Mesh::Edge_index, bool>(true)));
  Render_options cells = o;
  cells.site_radius = 1.5;   // 300 sites: small dots
  save(dir, "svd_remeshing.png", beside({svd_figures::render_diagram(diagram, cells), dual_image}));
}

// Remeshing that keeps the creases: a thin-walled open box remeshed by the dual of 300 blue-noise sites after
// five Lloyd steps, without (left) and with (right) sites on its creases (feature_line_sites()).
void feature_remeshing_figure(const std::string& dir)
{
  Mesh mesh;
  GEN::make_shape(GEN::Shape::box, mesh);
  auto crease = mesh.add_property_map<Mesh::Edge_index, bool>("e:crease", false).first;
  CGAL::Polygon_mesh_processing::detect_sharp_edges(mesh, 60., crease);
  SV::Euclidean_embedding<Mesh> metric(mesh);
  const std::size_t n = 300;
  auto dual_of = [&](bool features) {
    const auto lines = CGAL::parameters::edge_is_constrained_map(crease);
    std::vector<Location> sites = features ? SV::feature_line_sites(mesh, n, lines) : std::vector<Location>();
    const std::size_t fixed = sites.size();
    for(const Location& l : SV::blue_noise_sites(mesh, n - fixed, SV::parameters::placed_sites(sites, CGAL::parameters::random_seed(1))))
      sites.push_back(l);
    std::vector<K::Point_3> points;
    std::vector<std::array<std::size_t, 3> > triangles;
    if(features)
    {
      const auto relaxed = SV::lloyd_relaxation(mesh, metric, sites, SV::parameters::first_moving_site(fixed, lines.number_of_iterations(5)));
      SV::dual_triangulation(CGAL::Surface_voronoi_diagram<Mesh, SV::Euclidean_embedding<Mesh> >(mesh, metric, relaxed.sites, lines),
                             std::back_inserter(points), std::back_inserter(triangles));
    }
    else
    {
      const auto relaxed = SV::lloyd_relaxation(mesh, metric, sites, CGAL::parameters::number_of_iterations(5));
      SV::dual_triangulation(CGAL::Surface_voronoi_diagram<Mesh, SV::Euclidean_embedding<Mesh> >(mesh, metric, relaxed.sites),
                             std::back_inserter(points), std::back_inserter(triangles));
    }
    Mesh dual;
    CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, triangles, dual);
    return dual;
  };
  Render_options flat = panel(316, 280, {{-0.5, -0.9, -1.4}});
  flat.crease_angle = 30;
  flat.site_radius = 0;
  flat.edge_width = 1.0;
  std::vector<Image> panels;
  for(bool features : { false, true })
    panels.push_back(svd_figures::render_arrangement(dual_of(features), CGAL::Constant_property_map<Mesh::Face_index, int>(0),
                                                     std::vector<K::Point_3>(), flat,
                                                     CGAL::parameters::edge_is_constrained_map(
                                                         CGAL::Constant_property_map<Mesh::Edge_index, bool>(true))));
  save(dir, "svd_feature_remeshing.png", beside(panels));
}

// The cells out as a polygon mesh, as polylines and Voronoi vertices, and as labels of the
// input's faces: one figure each, all on the same torus diagram.
typedef CGAL::Surface_voronoi_diagram<Mesh, SV::Euclidean_embedding<Mesh> > Euclidean_diagram;

// The Voronoi diagram as a polygon mesh (left: the diagram; right: its polygon mesh, each
// face fanned from its centroid for the rasterizer, which fills planar polygons only, with
// the faces' own edges as lines and the Voronoi vertices as dots).
void polygon_mesh_figure(const std::string& dir, const Euclidean_diagram& diagram, const Render_options& o)
{
  Mesh cells;
  auto site = cells.add_property_map<Mesh::Face_index, int>("f:site", -1).first;
  auto voronoi = cells.add_property_map<Mesh::Vertex_index, bool>("v:voronoi", false).first;
  if(!SV::make_voronoi_polygon_mesh(diagram, cells, CGAL::parameters::face_patch_map(site).vertex_is_constrained_map(voronoi)).empty())
    throw std::runtime_error("a cell of the polygon mesh figure is not a disk");
  std::vector<K::Point_3> voronoi_points;
  for(Mesh::Vertex_index v : cells.vertices())
    if(voronoi[v]) voronoi_points.push_back(cells.point(v));
  auto polygon_edge = cells.add_property_map<Mesh::Edge_index, bool>("e:polygon", true).first;
  const std::vector<Mesh::Face_index> polygons(cells.faces().begin(), cells.faces().end());
  for(Mesh::Face_index f : polygons)
  {
    K::Vector_3 sum(0, 0, 0);
    std::size_t corners = 0;
    for(Mesh::Vertex_index v : CGAL::vertices_around_face(cells.halfedge(f), cells)) { sum = sum + (cells.point(v) - CGAL::ORIGIN); ++corners; }
    const int s = site[f];
    const Mesh::Halfedge_index spoke = CGAL::Euler::add_center_vertex(cells.halfedge(f), cells);
    cells.point(cells.target(spoke)) = CGAL::ORIGIN + sum / double(corners);
    for(Mesh::Halfedge_index h : CGAL::halfedges_around_target(spoke, cells))
    {
      site[cells.face(h)] = s;
      polygon_edge[cells.edge(h)] = false;
    }
  }
  Render_options flat = o;
  flat.crease_angle = 0;
  flat.site_radius = 2.0;
  Render_options with_sites = o;
  with_sites.site_radius = 2.0;
  save(dir, "svd_polygon_mesh.png",
       beside({svd_figures::render_diagram(diagram, with_sites),
               svd_figures::render_arrangement(cells, site, voronoi_points, flat, CGAL::parameters::edge_is_constrained_map(polygon_edge))}));
}

// The bisector polylines and the Voronoi vertices on the bare surface: the lines drawn are
// the edges of the arrangement between consecutive points of a polyline.
void polylines_figure(const std::string& dir, const Euclidean_diagram& diagram, const Render_options& o)
{
  std::vector<SV::Bisector_polyline<K::Point_3> > polylines;
  std::vector<SV::Voronoi_vertex<K::Point_3> > vertices;
  SV::bisector_polylines(diagram, std::back_inserter(polylines));
  SV::voronoi_vertices(diagram, std::back_inserter(vertices));
  std::set<std::pair<K::Point_3, K::Point_3> > segments;
  for(const auto& polyline : polylines)
    for(std::size_t k = 0; k + 1 < polyline.points.size(); ++k)
    {
      segments.insert(std::make_pair(polyline.points[k], polyline.points[k + 1]));
      segments.insert(std::make_pair(polyline.points[k + 1], polyline.points[k]));
    }
  Mesh arrangement;
  SV::make_arrangement(diagram, arrangement);
  auto on_polyline = arrangement.add_property_map<Mesh::Edge_index, bool>("e:polyline", false).first;
  for(Mesh::Edge_index e : arrangement.edges())
    on_polyline[e] = segments.count(std::make_pair(arrangement.point(arrangement.source(arrangement.halfedge(e))),
                                                   arrangement.point(arrangement.target(arrangement.halfedge(e))))) > 0;
  std::vector<K::Point_3> points;
  for(const auto& v : vertices) points.push_back(v.point);
  Render_options lines = o;
  lines.site_radius = 2.0;
  save(dir, "svd_polylines.png",
       svd_figures::render_arrangement(arrangement, CGAL::Constant_property_map<Mesh::Face_index, int>(-1), points, lines,
                                       CGAL::parameters::edge_is_constrained_map(on_polyline)));
}

// Labels of the input: each face a cell covers whole in its cell's colour, the faces a
// bisector cuts in grey, the input's edges drawn (left); the diagram on the same mesh (right).
void site_maps_figure(const std::string& dir, const Euclidean_diagram& diagram, const Render_options& o)
{
  const Mesh& mesh = diagram.triangle_mesh();
  std::vector<int> face_site(mesh.number_of_faces(), -1);
  SV::compute_face_sites(diagram, CGAL::make_property_map(face_site));
  Render_options thin = o;
  thin.edge_width = 0.75;
  thin.site_radius = 0;
  thin.crease_angle = 0;
  save(dir, "svd_site_maps.png",
       beside({svd_figures::render_arrangement(mesh, CGAL::make_property_map(face_site), std::vector<K::Point_3>(), thin,
                                               CGAL::parameters::edge_is_constrained_map(CGAL::Constant_property_map<Mesh::Edge_index, bool>(true))),
               svd_figures::render_diagram(diagram, o)}));
}

void cell_output_figures(const std::string& dir)
{
  Mesh coarse;
  GEN::make_torus(coarse, 1.0, 0.4, 48, 18);
  SV::Euclidean_embedding<Mesh> metric(coarse);
  const SV::Lloyd_result<Mesh> relaxed = SV::lloyd_relaxation(coarse, metric, SV::blue_noise_sites(coarse, 40, CGAL::parameters::random_seed(5)), CGAL::parameters::number_of_iterations(5));
  const Euclidean_diagram diagram(coarse, metric, relaxed.sites);
  const Render_options o = panel(316, 240, {{-0.3, -1.0, -1.0}});
  polygon_mesh_figure(dir, diagram, o);
  polylines_figure(dir, diagram, panel(480, 360, {{-0.3, -1.0, -1.0}}));
  site_maps_figure(dir, diagram, o);
}

} // namespace

int main(int argc, char** argv)
{
  if(argc < 2)
  {
    std::cerr << "usage: make_figures OUTPUT_DIR [DATA_DIR]" << std::endl;
    return 2;
  }
  const std::string dir = argv[1];
  const std::string data = argc > 2 ? argv[2] : "examples/Surface_voronoi_diagram/data";
  const auto start = std::chrono::steady_clock::now();
  try
  {
    metrics_figure(dir, data);
    readme_figure(dir, data);
    power_figure(dir);
    prescribed_areas_figure(dir);
    breaklines_figure(dir);
    lloyd_figure(dir);
    remeshing_figure(dir);
    feature_remeshing_figure(dir);
    cell_output_figures(dir);
  }
  catch(const std::exception& e)
  {
    std::cerr << "make_figures: " << e.what() << std::endl;
    return 1;
  }
  std::cout << "figures written to " << dir << " in "
            << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() << " s" << std::endl;
  return 0;
}
