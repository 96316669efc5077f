// Copyright (c) 2026 The Surface_voronoi_diagram authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// surface_voronoi: the command-line program. Its interface is a contract (see the manual):
//
//   surface_voronoi MESH (--sites FILE | --random N | --blue-noise N) [--seed S] [--metric NAME]
//                   [--dimension D|auto|full] [--insert-sites] [--output OUT.ply] [--sites-out FILE]
//                   [--max-site-distance R] [--breaklines FILE] [--sharp-edges ANGLE] [--dual OUT.off] [--valid-dual] [--lloyd K]
//                   [--threads N] [--stats]
//
// Exit codes: 0 success (also when some area is reached by no site, or when a power weight
// empties some cells: a warning says so),
// 1 bad input (mesh, sites file), 2 bad command line, 3 numerical failure, 4 cannot write.
// Every error is one line on stderr.
//
// The program's own file handling (the checked mesh reader, the sites and breaklines files,
// the coloured PLY) lives beside this file, in namespace svd_program: it is not part of the
// library.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Biharmonic_embedding.h>
#include <CGAL/Surface_voronoi_diagram/Biharmonic_green_metric.h>
#include <CGAL/Surface_voronoi_diagram.h>
#include <CGAL/Surface_voronoi_diagram/Euclidean_embedding.h>
#include <CGAL/Surface_voronoi_diagram/Geodesic_metric.h>
#include <CGAL/Surface_voronoi_diagram/refinement.h>
#include <CGAL/Surface_voronoi_diagram/dual_triangulation.h>
#include <CGAL/Surface_voronoi_diagram/dual_validity.h>
#include <CGAL/Surface_voronoi_diagram/valid_dual_sites.h>
#include <CGAL/Surface_voronoi_diagram/valid_geodesic_dual_sites.h>
#include <CGAL/Surface_voronoi_diagram/curvature_density.h>
#include <CGAL/Surface_voronoi_diagram/feature_sites.h>
#include <CGAL/Surface_voronoi_diagram/lloyd_relaxation.h>
#include <CGAL/Surface_voronoi_diagram/sampling.h>
#include <CGAL/Surface_voronoi_diagram/site_insertion.h>
#include <CGAL/Surface_voronoi_diagram/Prepared_mesh.h>
#include <CGAL/Surface_voronoi_diagram/Diagram_statistics.h>
#include <CGAL/Surface_voronoi_diagram/locate_in_face.h>

#include <CGAL/IO/OFF.h>

#ifdef SVD_PROGRAM_USES_CHOLMOD
#include <CGAL/Eigen_solver_traits.h>
#include <Eigen/CholmodSupport>
// OpenBLAS's, when CHOLMOD's BLAS is OpenBLAS; weak: null with another BLAS
extern "C" void openblas_set_num_threads(int) __attribute__((weak));
#endif

#include "large_blocks.h"
#include "output_file.h"
#include "read_checked_mesh.h"
#include "sites_file.h"
#include "write_arrangement_PLY.h"

#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/Random.h>
#include <CGAL/property_map.h>
#include <CGAL/tags.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
#include <optional>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef CGAL::Polygon_mesh_processing::Face_location<Mesh, double> Location;
namespace SV = CGAL::Surface_voronoi;

namespace svd_program {
namespace {

// The program's limits (the manual's troubleshooting section lists them).
// The most sites --random, --blue-noise or a sites file may give.
const long long max_sites = 10000000;
// The most sites one input face may hold before the sites are inserted. A face is cut among
// its candidate sites at a cost that grows faster than their square; beyond this many, the
// program inserts the sites as vertices (as --insert-sites does), or refines the mesh for
// them (the geodesic metric), so that a coarse mesh takes many sites without a flag. An
// inserted site is placed by a scan of its face's pieces, whose cost bounds the second limit.
const std::size_t max_sites_per_face = 256;
const std::size_t max_inserted_sites_per_face = 2048;
// The geodesic refinement's cap: at most this many vertices per input vertex and site (the
// regression models need up to 64), and never more than the ceiling, so that a strip of
// needle triangles cannot make the refinement run for minutes.
const std::size_t refinement_vertices_per_element = 256;
const std::size_t refinement_max_vertices = 1000000;
// Meshes whose largest coordinate is beyond 2^100, or whose bounding box is smaller than
// 2^-100, are scaled by a power of two (exact) into [0.5, 1) and their outputs scaled back:
// the library's range (validate_input) is far wider, ordinary meshes are never scaled.
const int normalize_above_exponent = 100;

struct Failure
{
  int code;
  std::string message;
};

[[noreturn]] void fail(int code, const std::string& message) { throw Failure{ code, message }; }

struct Arguments
{
  std::string mesh, sites, output, sites_out, breaklines, dual, metric = "biharmonic";
  long long random = -1, blue_noise = -1;
  unsigned int seed = 0;
  bool seed_given = false, dimension_given = false, insert_sites = false, stats = false, no_refine = false;
  bool dimension_auto = false;   // --dimension auto: the full spectrum if it fits, else biharmonic_dimension_for_sites()
  bool dimension_full = false;   // --dimension full, or auto's choice: Biharmonic_green_metric
  bool valid_dual = false;   // sites added until the dual is a valid mesh
  std::size_t dimension = 10;
  std::size_t lloyd = 0;
  std::size_t threads = 0;   // 0: all cores
  double max_site_distance = 0.01;
  double sharp_edges = -1;   // --sharp-edges ANGLE (degrees): breaklines where the normals turn more
  double curvature_density = 0;   // --curvature-density R: more sites where the surface bends, up to R times
  int scale = 0;   // the mesh is computed on scaled by 2^-scale (normalization_exponent())
  // of the sites drawn, those placed on breaklines and the border; -1 when none were looked for
  long long feature_sites = -1;
};

const char* usage =
  "usage: surface_voronoi MESH (--sites FILE | --random N | --blue-noise N) [--seed S] [--metric biharmonic|euclidean|rvd|geodesic]\n"
  "                       [--dimension D|auto|full] [--insert-sites] [--no-refine] [--output OUT.ply] [--sites-out FILE]\n"
  "                       [--max-site-distance R] [--breaklines FILE] [--sharp-edges ANGLE] [--dual OUT.off] [--valid-dual] [--lloyd K]\n"
  "                       [--curvature-density R] [--threads N] [--stats]";

double parse_number(const std::string& flag, const std::string& text)
{
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if(text.empty() || end != text.c_str() + text.size() || !std::isfinite(v))
    fail(2, flag + " expects a number, got '" + text + "'");
  return v;
}

long long parse_integer(const std::string& flag, const std::string& text, long long lo, long long hi)
{
  char* end = nullptr;
  errno = 0;
  const long long v = std::strtoll(text.c_str(), &end, 10);
  if(text.empty() || end != text.c_str() + text.size() || errno != 0 || v < lo || v > hi)
    fail(2, flag + " expects an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got '" + text + "'");
  return v;
}

Arguments parse(int argc, char** argv)
{
  Arguments a;
  for(int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if(i + 1 >= argc) fail(2, arg + " needs a value");
      return argv[++i];
    };
    if(arg == "--help" || arg == "-h") { std::cout << usage << std::endl; std::exit(0); }
    else if(arg == "--sites") a.sites = value();
    else if(arg == "--random") a.random = parse_integer(arg, value(), 1, max_sites);
    else if(arg == "--blue-noise") a.blue_noise = parse_integer(arg, value(), 1, max_sites);
    else if(arg == "--seed") { a.seed = static_cast<unsigned int>(parse_integer(arg, value(), 0, 4294967295LL)); a.seed_given = true; }
    else if(arg == "--metric") a.metric = value();
    else if(arg == "--no-refine") a.no_refine = true;
    else if(arg == "--dimension")
    {
      const std::string d = value();
      a.dimension_given = true;
      if(d == "auto") a.dimension_auto = true;
      else if(d == "full") a.dimension_full = true;
      else a.dimension = static_cast<std::size_t>(parse_integer(arg, d, 1, 10000));
    }
    else if(arg == "--insert-sites") a.insert_sites = true;
    else if(arg == "--output") a.output = value();
    else if(arg == "--sites-out") a.sites_out = value();
    else if(arg == "--max-site-distance")
    {
      a.max_site_distance = parse_number(arg, value());
      if(a.max_site_distance < 0) fail(2, "--max-site-distance must not be negative");
    }
    else if(arg == "--stats") a.stats = true;
    else if(arg == "--breaklines") a.breaklines = value();
    else if(arg == "--sharp-edges")
    {
      a.sharp_edges = parse_number(arg, value());
      if(!(a.sharp_edges > 0 && a.sharp_edges < 180)) fail(2, "--sharp-edges expects an angle in degrees between 0 and 180 (exclusive)");
    }
    else if(arg == "--dual") a.dual = value();
    else if(arg == "--valid-dual") a.valid_dual = true;
    else if(arg == "--curvature-density")
    {
      a.curvature_density = parse_number(arg, value());
      if(!(a.curvature_density >= 1))
        fail(2, "--curvature-density expects the largest density ratio, a number of at least 1");
    }
    else if(arg == "--lloyd") a.lloyd = static_cast<std::size_t>(parse_integer(arg, value(), 0, 10000));
    else if(arg == "--threads") a.threads = static_cast<std::size_t>(parse_integer(arg, value(), 1, 4096));
    else if(!arg.empty() && arg[0] == '-') fail(2, "unknown option '" + arg + "'");
    else if(a.mesh.empty()) a.mesh = arg;
    else fail(2, "unexpected argument '" + arg + "' (only one mesh)");
  }
  if(a.mesh.empty()) fail(2, "no mesh given");
  if(int(!a.sites.empty()) + int(a.random >= 0) + int(a.blue_noise >= 0) != 1)
    fail(2, "give exactly one of --sites FILE, --random N and --blue-noise N");
  if(a.seed_given && a.random < 0 && a.blue_noise < 0) fail(2, "--seed applies to --random and --blue-noise only");
  if(a.metric != "biharmonic" && a.metric != "euclidean" && a.metric != "rvd" && a.metric != "geodesic")
    fail(2, "unknown metric '" + a.metric + "' (biharmonic, euclidean, rvd or geodesic)");
  if(a.dimension_given && a.metric != "biharmonic") fail(2, "--dimension applies to the biharmonic metric only");
  if(a.valid_dual && a.dual.empty()) fail(2, "--valid-dual applies to --dual only");
  if(a.curvature_density > 0 && a.random < 0 && a.blue_noise < 0 && a.lloyd == 0)
    fail(2, "--curvature-density applies to --random, --blue-noise and --lloyd only");
  return a;
}

// What the command line asks of every diagram: the candidate selection (every globally
// nearest site for --metric rvd) and, for a power diagram, the weights in site order.
struct Diagram_choices
{
  SV::Candidate_selection candidates = SV::Candidate_selection::PROPAGATION;
  std::vector<double> weights;   // empty unless some weight is not zero
};

// Calls f with the named parameters of `choices` added to the chain `np`: the weights are
// passed (by site index) only for a power diagram, as a plain diagram has none.
template <class NamedParameters, class Function>
auto with_diagram_parameters(const Diagram_choices& choices, const NamedParameters& np, const Function& f)
{
  const auto chain = SV::parameters::candidate_selection(choices.candidates, np);
  if(choices.weights.empty()) return f(chain);
  return f(SV::parameters::site_weight_map(CGAL::make_property_map(choices.weights), chain));
}

// The most vertices the geodesic metric's refinement for `sites` sites may give `mesh`: the
// cap bounds the vertices added, so that a mesh of over a million vertices can still be
// refined a little.
std::size_t refinement_cap(const Mesh& mesh, std::size_t sites)
{
  return num_vertices(mesh) + (std::min)(refinement_max_vertices, refinement_vertices_per_element * (num_vertices(mesh) + sites));
}

// the metric of --dimension full, and of auto when its columns fit
typedef SV::Biharmonic_green_metric<Mesh, CGAL::Default, CGAL::Parallel_if_available_tag> Full_spectrum_metric;
// A mesh prepared once (the input after reading, or its working copy) for the validation, the
// metric, Lloyd and the diagram; each would prepare its own otherwise. The reader has checked
// the topology on the polygon soup, and the library's refinement and insertion keep it.
typedef SV::Prepared_mesh<Mesh, CGAL::Parallel_if_available_tag> Prepared_mesh;
// The embedding's linear algebra: CHOLMOD's supernodal Cholesky when CMake found SuiteSparse
// (faster on large meshes), else the library's default.
#ifdef SVD_PROGRAM_USES_CHOLMOD
typedef CGAL::Eigen_solver_traits<Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double> > > Embedding_LA;
#else
typedef CGAL::Default Embedding_LA;
#endif
typedef CGAL::Biharmonic_embedding<Mesh, CGAL::Default, CGAL::Default, Embedding_LA, CGAL::Parallel_if_available_tag> Embedding_metric;

// The metric --metric names on the input mesh (the biharmonic one of the dimension given to
// build()), built once and shared by the stages that work on that mesh: Lloyd, --valid-dual
// and the final diagram. They thus share one eigen-solve or factorization, and the full
// spectrum's columns of the sites that do not move (two solves per site otherwise computed
// again by each stage).
// A metric is the same object whichever stage builds it, so sharing it changes no result.
class Input_metric
{
public:
  // `prepared`: the mesh prepared, or none yet (prepared by the first build)
  Input_metric(const Arguments& args, const Mesh& mesh, std::optional<Prepared_mesh>& prepared)
    : m_args(args), m_mesh(mesh), m_prepared(prepared) {}

  // builds the metric unless it is built; its seconds are those of the first build
  void build(std::size_t dimension)
  {
    if(built()) return;
    const auto start = std::chrono::steady_clock::now();
    const auto& prepared = this->prepared();
    if(m_args.metric == "biharmonic" && m_args.dimension_full)
      m_full.reset(new Full_spectrum_metric(m_mesh, SV::parameters::prepared_mesh(prepared)));
    else if(m_args.metric == "biharmonic")
      m_biharmonic.reset(new Embedding_metric(m_mesh, SV::parameters::embedding_dimension(dimension,
                                                      SV::parameters::prepared_mesh(prepared))));
    else if(m_args.metric == "geodesic")
      m_geodesic.reset(new SV::Geodesic_metric<Mesh>(m_mesh, SV::parameters::prepared_mesh(prepared)));
    else
      m_euclidean.reset(new SV::Euclidean_embedding<Mesh>(m_mesh));
    m_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

  // `f(metric)`, the metric built first if it is not
  template <class Function>
  auto apply(std::size_t dimension, const Function& f)
  {
    build(dimension);
    if(m_full) return f(*m_full);
    if(m_biharmonic) return f(*m_biharmonic);
    if(m_geodesic) return f(*m_geodesic);
    return f(*m_euclidean);
  }

  bool built() const { return m_full || m_biharmonic || m_geodesic || m_euclidean; }
  double build_seconds() const { return m_seconds; }
  // the mesh prepared, prepared first if it is not
  const Prepared_mesh& prepared()
  {
    if(!m_prepared) m_prepared.emplace(m_mesh, SV::parameters::checked_mesh_topology(true));
    return *m_prepared;
  }
  // frees it and the prepared mesh, for a stage that works on another mesh
  void release() { m_full.reset(); m_biharmonic.reset(); m_geodesic.reset(); m_euclidean.reset(); m_prepared.reset(); }

private:
  const Arguments& m_args;
  const Mesh& m_mesh;
  std::optional<Prepared_mesh>& m_prepared;
  std::unique_ptr<Full_spectrum_metric> m_full;
  std::unique_ptr<Embedding_metric> m_biharmonic;
  std::unique_ptr<SV::Geodesic_metric<Mesh> > m_geodesic;
  std::unique_ptr<SV::Euclidean_embedding<Mesh> > m_euclidean;
  double m_seconds = 0;
};

// Sites that --sites-out must give back bit for bit: read back, the point written for a
// site must be located at that very site. Two kinds of sites have that property:
//  - a fixed point: a location inside its face (every coordinate at least 2^-20, so that the
//    nearest face is not in doubt) whose point locates back to it. Locating and
//    constructing again is iterated to find one (a point can drift by an ulp a step);
//  - a grid point, for sites near an edge or a vertex, or whose drift does not settle:
//    barycentric coordinates multiples of 2^-24, a site on an edge or at a vertex being
//    given in the lowest-index face holding it. The written point locates back to
//    coordinates within rounding (some 1e-15) of the grid values, which are recognized
//    (within 2^-44) and snapped back. A site moves by at most 2^-25 of its face.
// Neither needs a search of the surface: only points read from a file are searched for globally.
const double site_grid_step = std::ldexp(1., -24);
const double site_grid_tolerance = std::ldexp(1., -44);
const double site_interior = std::ldexp(1., -20);

bool is_on_site_grid(const Location& l)
{
  for(double x : l.second)
    if(!(std::abs(x - std::round(x / site_grid_step) * site_grid_step) <= site_grid_tolerance)) return false;
  return true;
}

bool is_inside_face(const Location& l)
{
  for(double x : l.second)
    if(!(x >= site_interior)) return false;
  return true;
}

// The face nearest to p among `start` and the faces sharing a vertex with it (the lowest
// index on a tie), and the location there of p's nearest point.
Location locate_near(const Point& p, Mesh::Face_index start, const Mesh& mesh)
{
  const K k;
  // corners in the order of CGAL's AABB face-graph primitives, which located the sites first
  // once: the sites files written then are read back bit for bit
  const auto triangle = [&](Mesh::Face_index f) {
    const Mesh::Halfedge_index h = mesh.halfedge(f);
    return K::Triangle_3(mesh.point(mesh.target(h)), mesh.point(mesh.target(mesh.next(h))), mesh.point(mesh.source(h)));
  };
  Mesh::Face_index best = start;
  Point best_point = k.construct_projected_point_3_object()(triangle(start), p);
  const double best_d2 = CGAL::squared_distance(p, best_point);
  for(Mesh::Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(start), mesh))
    for(Mesh::Face_index f : CGAL::faces_around_target(mesh.halfedge(v), mesh))
    {
      if(f == Mesh::null_face() || f == start) continue;
      // a face whose plane is clearly farther than the best point cannot be nearer (the
      // margin covers the rounding of the distances and of the points' coordinates)
      const K::Triangle_3 t = triangle(f);
      const K::Vector_3 n = CGAL::cross_product(t[1] - t[0], t[2] - t[0]), pt = p - t[0];
      const double n2 = n.squared_length(), plane2 = CGAL::square(n * pt) / n2;
      const double margin = 1e-12 * ((p - CGAL::ORIGIN).squared_length() + pt.squared_length() + (t[1] - t[0]).squared_length()
                                     + (t[2] - t[0]).squared_length());
      if(n2 > 0 && plane2 > best_d2 + margin) continue;
      const Point q = k.construct_projected_point_3_object()(t, p);
      const CGAL::Comparison_result c = k.compare_distance_3_object()(p, q, best_point);
      if(c == CGAL::SMALLER || (c == CGAL::EQUAL && f < best)) { best = f; best_point = q; }
    }
  return SV::locate_in_face(best_point, best, mesh, CGAL::parameters::geom_traits(k));
}

Location on_site_grid(Location l, const Mesh& mesh)
{
  std::array<double, 3>& b = l.second;
  double sum = 0;
  for(double& x : b)
  {
    x = (std::max)(0., std::round(x / site_grid_step) * site_grid_step);   // -0 becomes +0
    sum += x;
  }
  // coordinates sum to 1: the largest one takes the difference (exact, on the grid)
  const int largest = int(std::max_element(b.begin(), b.end()) - b.begin());
  if(sum <= 0) b = {{ 1., 0., 0. }};
  else b[largest] = 1. - (b[(largest + 1) % 3] + b[(largest + 2) % 3]);

  // on an edge or at a vertex: the lowest-index face holding it, the same coordinates per vertex
  const auto where = CGAL::Polygon_mesh_processing::get_descriptor_from_location(l, mesh);
  std::vector<Mesh::Face_index> holders;
  if(const Mesh::Vertex_index* v = boost::get<Mesh::Vertex_index>(&where))
  {
    for(Mesh::Face_index f : CGAL::faces_around_target(mesh.halfedge(*v), mesh))
      if(f != Mesh::null_face()) holders.push_back(f);
  }
  else if(const Mesh::Halfedge_index* h = boost::get<Mesh::Halfedge_index>(&where))
  {
    for(Mesh::Halfedge_index side : { *h, mesh.opposite(*h) })
      if(!mesh.is_border(side)) holders.push_back(mesh.face(side));
  }
  if(holders.empty()) return l;
  return CGAL::Polygon_mesh_processing::locate_in_adjacent_face(l, *std::min_element(holders.begin(), holders.end()), mesh);
}

// The site a location stands for (see above), and its point: what --sites-out writes. A
// drift that ends in a cycle of several locations (a point hopping between two) gives the
// cycle's location of smallest point, which the same iteration finds from any of them.
Location canonical_location(Location l, const Mesh& mesh, Point& point)
{
  std::vector<std::pair<Location, Point> > seen;
  for(int step = 0; step < 64 && !is_on_site_grid(l) && is_inside_face(l); ++step)
  {
    const Point c = CGAL::Polygon_mesh_processing::construct_point(l, mesh);
    seen.emplace_back(l, c);
    l = locate_near(c, l.first, mesh);
    const auto again = std::find_if(seen.begin(), seen.end(), [&](const std::pair<Location, Point>& x) { return x.first == l; });
    if(again != seen.end())
    {
      const auto smallest = std::min_element(again, seen.end(), [](const std::pair<Location, Point>& x,
                                                                   const std::pair<Location, Point>& y) { return x.second < y.second; });
      point = smallest->second;
      return smallest->first;
    }
  }
  l = on_site_grid(l, mesh);
  point = CGAL::Polygon_mesh_processing::construct_point(l, mesh);
  return l;
}

// The power of two 2^e the mesh is scaled by (its points multiplied by 2^-e), 0 for a mesh
// within [2^-100, 2^100]: squares of coordinates, areas and squared areas stay far from
// overflow and underflow on the scaled mesh, and every output is scaled back exactly.
int normalization_exponent(const Mesh& mesh)
{
  double largest = 0, lo[3], hi[3];
  bool first = true;
  for(auto v : vertices(mesh))
  {
    const Point& p = mesh.point(v);
    for(int c = 0; c < 3; ++c)
    {
      if(!std::isfinite(p[c])) return 0;   // validate_input reports it
      largest = (std::max)(largest, std::abs(p[c]));
      lo[c] = first ? p[c] : (std::min)(lo[c], p[c]);
      hi[c] = first ? p[c] : (std::max)(hi[c], p[c]);
    }
    first = false;
  }
  if(first || largest == 0) return 0;
  // the extent, halved so that it cannot overflow
  double extent = 0;
  for(int c = 0; c < 3; ++c) extent = (std::max)(extent, hi[c] / 2 - lo[c] / 2);
  if(largest <= std::ldexp(1., normalize_above_exponent) && !(extent < std::ldexp(1., -normalize_above_exponent - 1)))
    return 0;
  int e = 0;
  std::frexp(largest, &e);   // largest = m 2^e, m in [0.5, 1)
  return e;
}

Point scaled(const Point& p, int e)
{
  return e == 0 ? p : Point(std::ldexp(p.x(), e), std::ldexp(p.y(), e), std::ldexp(p.z(), e));
}

// the start of main(): `end_to_end` runs from there until the diagram's cells exist
std::chrono::steady_clock::time_point program_start;

template <class Diagram>
void report(const Arguments& args, const Diagram& vd, bool power, double end_to_end, double load, double embedding, double output,
            double insertion, std::size_t faces, const SV::Stage_times& times,
            const SV::Dual_validity* dual, std::size_t sites_added)
{
  const SV::Diagram_statistics& s = vd.statistics();
  const auto area = [&](double a) { return std::ldexp(a, 2 * args.scale); };   // in the input's units
  if(s.unreached_faces > 0)
    std::cerr << "surface_voronoi: warning: " << s.unreached_faces << " faces (area " << area(s.unreached_area) << ", "
              << s.unreached_components << " component(s)) are reached by no site and are labelled -1" << std::endl;
  if(power && s.empty_cells > 0)
  {
    std::size_t first = 0;
    while(first + 1 < vd.number_of_sites() && vd.number_of_pieces(first) != 0) ++first;
    std::cerr << "surface_voronoi: warning: " << s.empty_cells << " site(s) have an empty cell (their power weight is "
              << "outweighed by a neighbour's); the first is site " << first << std::endl;
  }
  if(!args.stats) return;
  // nine digits: the regression matrix compares the floating values to a relative 1e-6
  std::cout.precision(9);
  std::cout << "mesh_faces: " << faces << "\n"
            << "metric: " << args.metric << "\n"
            << "sites: " << s.sites << "\n"
            << "cells: " << s.cells << "\n"
            << "empty_cells: " << s.empty_cells << "\n"
            << "merged_sites: " << s.merged_sites << "\n"
            << "pieces: " << s.pieces << "\n"
            << "broken_cells_before_repair: " << s.broken_cells_before_repair << "\n"
            << "broken_cells: " << s.broken_cells << "\n"
            << "repair_rounds: " << s.repair_rounds << "\n"
            << "unreached_faces: " << s.unreached_faces << "\n"
            << "unreached_area: " << area(s.unreached_area) << "\n"
            << "surface_area: " << area(s.surface_area) << "\n"
            << "mean_candidates_per_face: " << s.mean_candidates_per_face << "\n"
            << "load: " << load << "\n"
            << "insertion: " << insertion << "\n"
            << "embedding: " << embedding << "\n"
            << "setup: " << times["setup"] << "\n"
            << "propagation: " << times["propagation"] << "\n"
            << "cutting: " << times["cutting"] << "\n"
            << "repair: " << times["repair"] << "\n"
            << "output: " << output << "\n"
            << "end_to_end: " << end_to_end << std::endl;
  if(args.feature_sites >= 0) std::cout << "feature_sites: " << args.feature_sites << "\n";
  if(!dual) return;
  if(args.valid_dual) std::cout << "sites_added: " << sites_added << "\n";
  std::cout << "dual_triangles: " << dual->triangles << "\n"
            << "dual_valid: " << (dual->is_valid() ? 1 : 0) << "\n"
            << "dual_genus: " << dual->genus << "\n"
            << "dual_self_intersections: " << dual->self_intersections << "\n"
            << "dual_cells_not_disks: " << dual->cells_not_disks.size() << "\n"
            << "dual_pairs_in_several_arcs: " << dual->pairs_in_several_arcs.size() << "\n"
            << "dual_triples_at_several_vertices: " << dual->triples_at_several_vertices.size() << "\n"
            << "dual_vertices_of_more_than_three_cells: " << dual->vertices_of_more_than_three_cells << std::endl;
}

// Runs the diagram on `mesh` with sites given as locations of that mesh.
template <class Metric>
void run(const Arguments& args, const Mesh& mesh, Metric& metric, const std::vector<Location>& sites,
         const Diagram_choices& choices, double load, double embedding, double insertion,
         const std::vector<Point>& site_points, std::size_t sites_added, const Prepared_mesh& prepared)
{
  typedef CGAL::Surface_voronoi_diagram<Mesh, Metric, CGAL::Default, CGAL::Default, CGAL::Parallel_if_available_tag> Diagram;
  const auto breakline = mesh.property_map<Mesh::Edge_index, bool>("e:breakline").first;
  SV::Stage_times times;
  const Diagram vd = with_diagram_parameters(choices,
      SV::parameters::prepared_mesh(prepared, SV::parameters::stage_times(&times, CGAL::parameters::edge_is_constrained_map(breakline))),
      [&](const auto& np) { return Diagram(mesh, metric, sites, np); });
  const auto t0 = std::chrono::steady_clock::now();
  const double end_to_end = std::chrono::duration<double>(t0 - program_start).count();
  // the dual first: with --valid-dual, one that is not valid is an error, and no file is written
  SV::Dual_validity dual_validity;
  std::vector<Point> dual_points;
  std::vector<std::array<std::size_t, 3> > dual_triangles;
  if(!args.dual.empty())
  {
    SV::dual_triangulation(vd, std::back_inserter(dual_points), std::back_inserter(dual_triangles));
    dual_validity = SV::validate_dual_triangulation(vd, dual_points, dual_triangles);
    if(args.valid_dual && !dual_validity.is_valid())
      fail(1, args.mesh + ": no valid dual reached (" + std::to_string(sites_added) + " sites added): " + dual_validity.reason());
  }
  if(!args.output.empty())
  {
    try { write_arrangement_PLY(args.output, vd, true, args.scale); }
    catch(const Write_error& e) { fail(4, e.what()); }
    catch(const SV::Error& e) { fail(4, e.what()); }   // the arrangement could not be built
  }
  (void)site_points;
  if(!args.dual.empty())
  {
    for(Point& p : dual_points) p = scaled(p, args.scale);
    try
    {
      write_output_file(args.dual, false, [&](std::ostream& os) {
        return CGAL::IO::write_OFF(os, dual_points, dual_triangles, CGAL::parameters::stream_precision(17));
      });
    }
    catch(const Write_error& e) { fail(4, e.what()); }
    if(!dual_validity.is_valid())
      std::cerr << "surface_voronoi: warning: the dual triangulation is not a valid mesh: " << dual_validity.reason()
                << std::endl;
  }
  const double output = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  report(args, vd, !choices.weights.empty(), end_to_end, load, embedding, output, insertion, num_faces(mesh), times,
         args.dual.empty() ? nullptr : &dual_validity, sites_added);
}

int run_main(int argc, char** argv)
{
  Arguments args = parse(argc, argv);
#ifdef CGAL_LINKED_WITH_TBB
  // --threads 1 is the sequential run; the output does not depend on the number of threads
  std::unique_ptr<tbb::global_control> thread_limit;
  if(args.threads != 0)
    thread_limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, args.threads);
#endif
  typedef std::chrono::steady_clock Clock;
  const auto t0 = Clock::now();
  Mesh mesh;
  Mesh_reading_report reading;
  try { reading = read_checked_triangle_mesh(args.mesh, mesh); }
  catch(const Input_error& e) { fail(1, e.what()); }
  // a mesh too large or too small for doubles' squares is computed on at a power-of-two scale
  args.scale = normalization_exponent(mesh);
  if(args.scale != 0)
    for(auto v : vertices(mesh)) mesh.point(v) = scaled(mesh.point(v), -args.scale);

  // breaklines: pairs of vertex indices of the file, each an edge of the mesh
  auto breakline = mesh.add_property_map<Mesh::Edge_index, bool>("e:breakline", false).first;
  if(!args.breaklines.empty())
  {
    std::vector<Index_pair_record> pairs;
    try { pairs = read_breaklines_file(args.breaklines); }
    catch(const Input_error& e) { fail(1, e.what()); }
    for(const Index_pair_record& r : pairs)
    {
      const std::string where = "breaklines file line " + std::to_string(r.line) + ": ";
      if(r.first >= reading.mesh_vertex_of_point.size() || r.second >= reading.mesh_vertex_of_point.size())
        fail(1, where + "vertex index out of range (the mesh has " + std::to_string(reading.mesh_vertex_of_point.size()) + " vertices)");
      const std::size_t a = reading.mesh_vertex_of_point[r.first], b = reading.mesh_vertex_of_point[r.second];
      if(a == std::size_t(-1) || b == std::size_t(-1))
        fail(1, where + "vertex " + std::to_string(a == std::size_t(-1) ? r.first : r.second) + " belongs to no face");
      const auto h = CGAL::halfedge(Mesh::Vertex_index(Mesh::size_type(a)), Mesh::Vertex_index(Mesh::size_type(b)), mesh);
      if(!h.second)
        fail(1, where + "vertices " + std::to_string(r.first) + " and " + std::to_string(r.second) + " are not joined by an edge");
      breakline[edge(h.first, mesh)] = true;
    }
  }
  // --sharp-edges: the edges whose faces' normals turn by more than the angle are breaklines
  // too (PMP::detect_sharp_edges(); it marks the border as well, which needs no breakline)
  if(args.sharp_edges > 0)
  {
    auto sharp = mesh.add_property_map<Mesh::Edge_index, bool>("e:sharp", false).first;
    CGAL::Polygon_mesh_processing::detect_sharp_edges(mesh, args.sharp_edges, sharp);
    for(Mesh::Edge_index e : mesh.edges())
      if(sharp[e] && !mesh.is_border(e)) breakline[e] = true;
    mesh.remove_property_map(sharp);
  }
  const bool has_breaklines = std::any_of(mesh.edges().begin(), mesh.edges().end(), [&](Mesh::Edge_index e) { return breakline[e]; });
  // --curvature-density: sites drawn and relaxed more densely where the surface bends
  std::optional<Mesh::Property_map<Mesh::Vertex_index, double> > density;
  if(args.curvature_density > 0)
  {
    density = mesh.add_property_map<Mesh::Vertex_index, double>("v:svd_density", 1.).first;
    SV::curvature_density(mesh, *density, SV::parameters::max_density_ratio(args.curvature_density));
  }

  // sites as surface locations, remembering the sites file's lines for error messages
  std::vector<std::size_t> lines;
  std::vector<Location> locations;
  std::vector<Location> feature_sites;   // sampled sites on breaklines and the border, first in `locations`
  const double diagonal = [&] {
    const CGAL::Bbox_3 b = CGAL::Polygon_mesh_processing::bbox(mesh);
    return std::sqrt(CGAL::square(b.xmax() - b.xmin()) + CGAL::square(b.ymax() - b.ymin()) + CGAL::square(b.zmax() - b.zmin()));
  }();
  std::vector<Point> site_points;
  std::vector<double> weights;
  // the geodesic metric refines a mesh too coarse for the sites: its faces' counts are
  // checked after the refinement; the other metrics insert the sites when a face holds more
  // than max_sites_per_face (below)
  const bool refines_for_sites = args.metric == "geodesic" && !args.insert_sites && !args.no_refine;
  const std::string per_face_advice = " (the limit per input face, the sites inserted as vertices); use a finer mesh or fewer sites";
  if(!args.sites.empty())
  {
    std::vector<Site_record> records;
    try { records = read_sites_file(args.sites); }
    catch(const Input_error& e) { fail(1, e.what()); }
    if(records.empty()) fail(1, args.sites + ": the sites file has no sites");
    if(records.size() > std::size_t(max_sites))
      fail(1, args.sites + ": the sites file has " + std::to_string(records.size()) + " sites, more than the limit of "
              + std::to_string(max_sites));
    const double limit = args.max_site_distance * diagonal;
    // only points read from a file need a search over the whole surface
    std::vector<Point> points;
    points.reserve(records.size());
    for(const Site_record& r : records) points.push_back(scaled(Point(r.x, r.y, r.z), -args.scale));
    const std::vector<Location> nearest = SV::locate_points(mesh, points);
    for(std::size_t i = 0; i < records.size(); ++i)
    {
      const Site_record& r = records[i];
      const Point& p = points[i];
      Point q = p;
      const Location l = canonical_location(nearest[i], mesh, q);
      const double d = std::sqrt(CGAL::to_double(CGAL::squared_distance(p, q)));
      if(d > limit)
      {
        std::ostringstream os;
        os.precision(6);
        os << "sites file line " << r.line << ": the site is " << std::ldexp(d, args.scale) << " from the surface, more than "
           << args.max_site_distance << " x the bounding-box diagonal (" << std::ldexp(limit, args.scale) << ")";
        fail(1, os.str());
      }
      locations.push_back(l);
      site_points.push_back(q);
      lines.push_back(r.line);
      weights.push_back(r.has_weight ? r.weight : 0.);   // in the metric's squared units
    }
  }
  else
  {
    // a face cannot hold more than max_inserted_sites_per_face sites: fail before drawing them
    const long long count = args.random >= 0 ? args.random : args.blue_noise;
    const std::string option = std::string(args.random >= 0 ? "--random " : "--blue-noise ") + std::to_string(count);
    if(std::size_t(count) > max_inserted_sites_per_face * num_faces(mesh))
      fail(2, option + ": more than "
              + std::to_string(max_inserted_sites_per_face) + " sites per face of a mesh of " + std::to_string(num_faces(mesh)) + " faces"
              + per_face_advice);
    // First the sites on the feature lines: the breaklines and, for a remesh (--dual), the
    // border, evenly spaced for `count` sites in all; then the others, drawn. The feature
    // sites stay in place under --lloyd.
    const bool on_feature_lines = has_breaklines || !args.dual.empty();
    if(on_feature_lines)
    {
      const auto on_lines = SV::parameters::sample_border(!args.dual.empty(), CGAL::parameters::edge_is_constrained_map(breakline));
      try
      {
        feature_sites = density ? SV::feature_line_sites(mesh, std::size_t(count), SV::parameters::vertex_density_map(*density, on_lines))
                                : SV::feature_line_sites(mesh, std::size_t(count), on_lines);
      }
      catch(const SV::Input_error& e) { fail(1, args.mesh + ": " + e.what()); }
      if(feature_sites.size() >= std::size_t(count))
        fail(2, option + ": the " + (has_breaklines ? (args.dual.empty() ? "breaklines" : "breaklines and the border") : "border")
                + " alone take " + std::to_string(feature_sites.size()) + " sites at the spacing of " + std::to_string(count)
                + " sites: ask for more sites");
    }
    const std::size_t free_sites = std::size_t(count) - feature_sites.size();
    if(on_feature_lines) args.feature_sites = static_cast<long long>(feature_sites.size());
    auto draw = [&](const auto& np) {
      return args.random >= 0 ? SV::random_sites(mesh, free_sites, np)
                              : SV::blue_noise_sites(mesh, free_sites, SV::parameters::placed_sites(feature_sites, np));
    };
    std::vector<Location> drawn = feature_sites;
    for(const Location& l : density ? draw(SV::parameters::vertex_density_map(*density, CGAL::parameters::random_seed(args.seed)))
                                    : draw(CGAL::parameters::random_seed(args.seed)))
      drawn.push_back(l);
    for(const Location& l : drawn)
    {
      Point q;
      locations.push_back(canonical_location(l, mesh, q));
      site_points.push_back(q);
    }
  }
  // the sites of the fullest input face (the geodesic metric's are checked on the refined
  // mesh): beyond max_sites_per_face they are inserted, beyond max_inserted_sites_per_face
  // it is an error
  auto check_sites_per_face = [&](const std::vector<Location>& sites, bool refined) {
    std::map<Mesh::Face_index, std::size_t> per_face;
    std::pair<std::size_t, Mesh::Face_index> fullest(0, Mesh::Face_index());
    for(const Location& l : sites)
      fullest = (std::max)(fullest, std::make_pair(++per_face[l.first], l.first));
    const std::size_t limit = refined ? max_sites_per_face : max_inserted_sites_per_face;
    if(fullest.first > limit)
    {
      const std::string what = (refined ? "face " + std::to_string(std::size_t(fullest.second)) + " of the mesh refined for the sites"
                                        : "face " + std::to_string(std::size_t(fullest.second)))
                               + " holds more than " + std::to_string(limit) + " sites"
                               + (refined ? std::string(" (the limit per face of the refined mesh); use --insert-sites, a finer mesh or fewer sites")
                                          : per_face_advice);
      if(!lines.empty()) fail(1, args.sites + ": " + what);
      fail(2, std::string(args.random >= 0 ? "--random " : "--blue-noise ") + std::to_string(sites.size()) + ": " + what);
    }
    if(!refined && !args.insert_sites && fullest.first > max_sites_per_face)
    {
      args.insert_sites = true;
      std::cerr << "surface_voronoi: note: face " << std::size_t(fullest.second) << " holds " << fullest.first << " sites, more than "
                << max_sites_per_face << ": the sites are inserted as vertices (as with --insert-sites)" << std::endl;
    }
  };
  if(!refines_for_sites)
    check_sites_per_face(locations, false);
  // The library's preconditions, checked here so that every build gives one readable line
  // (what the reader has checked on the soup, validate_input() does not check again); part
  // of the loading, as the copy it checks on, which every stage shares
  std::optional<Prepared_mesh> prepared(std::in_place, mesh, SV::parameters::checked_mesh_topology(true));
  for(const SV::Input_problem& p : SV::validate_input(mesh, locations, SV::parameters::prepared_mesh(*prepared)))
  {
    if(p.kind == SV::Input_problem::COINCIDENT_SITES && !lines.empty())
      fail(1, "sites file lines " + std::to_string(lines[p.element]) + " and " + std::to_string(lines[p.other])
              + ": the two sites are at the same surface point");
    fail(1, args.mesh + ": " + p.message);
  }
  const double load = std::chrono::duration<double>(Clock::now() - t0).count();
  // --dimension auto takes the full spectrum when its columns fit (biharmonic_full_spectrum_for_sites(),
  // with the vertices --insert-sites adds and the sites --valid-dual may add), and otherwise a
  // dimension growing with the sites given; a dimension that resolves fewer cells than there
  // are sites is warned about
  const std::size_t most_sites = locations.size() + (args.valid_dual ? SV::default_maximum_number_of_added_sites(locations.size()) : 0);
  const std::size_t most_vertices = num_vertices(mesh) + (args.insert_sites ? locations.size() : 0);
  const bool full_fits = SV::biharmonic_full_spectrum_for_sites(most_vertices, most_sites);
  const std::string full_size = std::to_string(static_cast<long long>(std::ceil(SV::biharmonic_green_metric_bytes(most_vertices, most_sites) / 1048576.)))
                                + " MiB for " + std::to_string(most_sites) + " sites on " + std::to_string(most_vertices) + " vertices";
  if(args.metric == "biharmonic" && args.dimension_full && !full_fits)
    fail(1, "--dimension full: the full spectrum would take " + full_size + ", more than the 2 GiB the program allows; "
            "give a dimension or --dimension auto");
  Input_metric input_metric(args, mesh, prepared);
  if(args.metric == "biharmonic" && args.dimension_auto)
  {
    args.dimension_full = full_fits;
    if(!full_fits)
      std::cerr << "surface_voronoi: note: the full spectrum would take " << full_size << " (more than 2 GiB): using an embedding of dimension "
                << SV::biharmonic_dimension_for_sites(locations.size()) << std::endl;
    // a mesh whose Laplacian is not definite in floating point once a vertex is held (caps of
    // height 1e-9) keeps the eigen-solver, which shifts it instead
    if(full_fits)
      try { input_metric.build(0); }
      catch(const SV::Numerical_error&)
      {
        args.dimension_full = false;
        std::cerr << "surface_voronoi: note: the full spectrum cannot be computed on this mesh (its Laplacian is not positive "
                     "definite in floating point): using an embedding of dimension " << SV::biharmonic_dimension_for_sites(locations.size())
                  << std::endl;
      }
  }
  const std::size_t asked_dimension = args.dimension_auto ? SV::biharmonic_dimension_for_sites(locations.size()) : args.dimension;
  if(args.metric == "biharmonic" && !args.dimension_auto && !args.dimension_full
     && locations.size() > SV::biharmonic_resolved_sites(asked_dimension))
    std::cerr << "surface_voronoi: warning: an embedding of dimension " << asked_dimension << " resolves about "
              << SV::biharmonic_resolved_sites(asked_dimension) << " cells, fewer than the " << locations.size()
              << " sites: cells may come out in pieces (--dimension auto takes "
              << (full_fits ? std::string("the full spectrum") : std::to_string(SV::biharmonic_dimension_for_sites(locations.size())))
              << ")" << std::endl;
  // The biharmonic embedding needs more vertices than eigenpairs (on the mesh it is built
  // on): without a number for --dimension, the dimension is lowered to what the mesh allows,
  // with a note.
  auto dimension_for = [&](const Mesh& m) {
    if(args.metric != "biharmonic" || args.dimension_full) return asked_dimension;
    const std::size_t largest = (&m == &mesh && prepared) ? CGAL::Biharmonic_embedding<Mesh>::maximum_dimension(*prepared)
                                                         : CGAL::Biharmonic_embedding<Mesh>::maximum_dimension(m);
    if(asked_dimension <= largest) return asked_dimension;
    const std::size_t nv = num_vertices(m), components = nv - 1 - largest;
    const std::string what = "the mesh has " + std::to_string(nv) + " vertices and " + std::to_string(components)
                             + " component(s): an embedding of dimension at most " + std::to_string(largest);
    if((args.dimension_given && !args.dimension_auto) || largest == 0)
      fail(1, args.mesh + ": " + what + (largest == 0 ? " (none is possible)" : "")
              + ", too few for dimension " + std::to_string(asked_dimension));
    static std::size_t noted = 0;
    if(noted != largest)
      std::cerr << "surface_voronoi: note: " << what << " (" << (args.dimension_auto ? "--dimension auto asks for " : "the default is ")
                << asked_dimension << "): using " << largest << std::endl;
    noted = largest;
    return largest;
  };
  if(!args.insert_sites) dimension_for(mesh);

  Diagram_choices choices;
  if(args.metric == "rvd") choices.candidates = SV::Candidate_selection::GLOBAL_NEAREST;
  if(std::any_of(weights.begin(), weights.end(), [](double w) { return w != 0; }))
  {
    choices.weights = weights;   // power diagram: |E(x) - E(s)|^2 - w, in the metric's squared units
    for(double& w : choices.weights) w = std::ldexp(w, -2 * args.scale);
  }
  // Lloyd relaxation on the input mesh (interpolation mode: one embedding for all steps);
  // with --insert-sites the relaxed sites are inserted afterwards
  std::vector<double> lloyd_energies;
  double lloyd_seconds = 0;   // every iteration (the metric they share built before)
  // When each of the K + 1 diagrams was done: the callback is told (k + f) / (K + 1) while
  // diagram k is computed, and (k + 1) / (K + 1) once it is. Step k is diagram k's time and the
  // moving of the sites before it.
  std::vector<Clock::time_point> lloyd_done;
  const std::function<bool(double)> lloyd_progress = [&](double fraction) {
    if(fraction * double(args.lloyd + 1) >= double(lloyd_done.size() + 1) - 1e-9) lloyd_done.push_back(Clock::now());
    return true;
  };
  if(args.lloyd > 0)
  {
    try
    {
      input_metric.build(dimension_for(mesh));
      const auto lloyd_start = Clock::now();
      auto relax = [&](auto& metric) {
        auto run = [&](const auto& np) { return SV::lloyd_relaxation<CGAL::Parallel_if_available_tag>(mesh, metric, locations, np); };
        const auto steps = SV::parameters::prepared_mesh(input_metric.prepared(),
            SV::parameters::first_moving_site(feature_sites.size(),
                CGAL::parameters::number_of_iterations(args.lloyd).callback(lloyd_progress)));
        return density
          ? with_diagram_parameters(choices, SV::parameters::vertex_density_map(*density, steps), run)
          : with_diagram_parameters(choices, steps, run);
      };
      const SV::Lloyd_result<Mesh> r = input_metric.apply(dimension_for(mesh), relax);
      lloyd_energies = r.energies;
      for(std::size_t i = 0; i < r.sites.size(); ++i)
        locations[i] = canonical_location(r.sites[i], mesh, site_points[i]);
      lloyd_seconds = std::chrono::duration<double>(Clock::now() - lloyd_start).count();
    }
    catch(const SV::Input_error& e) { fail(1, args.mesh + ": " + e.what()); }
    catch(const SV::Numerical_error& e) { fail(3, e.what()); }
  }
  if(density) mesh.remove_property_map(*density);

  // --valid-dual: sites appended (the given ones keep their places and indices) until the
  // dual is a valid mesh, on the input mesh like Lloyd; the final diagram is checked again
  std::size_t sites_added = 0;
  if(args.valid_dual)
  {
    const std::size_t given = locations.size(), max_added = SV::default_maximum_number_of_added_sites(given);
    // the added sites weigh nothing: the weight map covers every index they may take
    if(!choices.weights.empty()) choices.weights.resize(given + max_added, 0.);
    try
    {
      auto add = [&](auto& metric) {
        return with_diagram_parameters(choices,
            SV::parameters::maximum_number_of_added_sites(max_added, CGAL::parameters::edge_is_constrained_map(breakline)),
            [&](const auto& np) { return SV::add_sites_for_valid_dual<CGAL::Parallel_if_available_tag>(mesh, metric, locations, np); });
      };
      SV::Valid_dual_result<Mesh> r;
      if(args.metric == "geodesic" && !args.insert_sites && !args.no_refine)
      {
        // The final diagram is built on the mesh refined for all the sites, so the sites are
        // added on refined meshes (add_sites_for_valid_geodesic_dual()), which the final run's
        // refinement (by the local spacing) makes again. The sites it adds are then moved to
        // this program's canonical locations (by up to 2^-25 of a face), which can tip a tie
        // of the dual: it is called again on them until it adds none, so that the validity it
        // reports is that of exactly the final diagram.
        input_metric.release();   // Lloyd's, on the mesh not refined
        std::vector<Location> current = locations;
        std::size_t added = 0, rounds = 0;
        for(int attempt = 0; attempt < 4; ++attempt)
        {
          r = with_diagram_parameters(choices,
              SV::parameters::maximum_number_of_added_sites(max_added - added,
                  SV::parameters::refinement_max_vertices(refinement_cap(mesh, given + max_added))),
              [&](const auto& np) { return SV::add_sites_for_valid_geodesic_dual<CGAL::Parallel_if_available_tag>(mesh, current, np); });
          added += r.sites_added;
          rounds += r.rounds;
          for(std::size_t i = current.size(); i < r.sites.size(); ++i)
          {
            Point q;
            current.push_back(canonical_location(r.sites[i], mesh, q));
          }
          if(r.sites_added == 0 || !r.validity.is_valid()) break;
        }
        r.sites = current;
        r.sites_added = added;
        r.rounds = rounds;
      }
      else
        r = input_metric.apply(dimension_for(mesh), add);
      if(!r.validity.is_valid())
        fail(1, args.mesh + ": no valid dual reached (" + std::to_string(r.sites_added) + " sites added, at most "
                + std::to_string(max_added) + "): " + r.validity.reason()
                + (r.nothing_to_cut ? "; no cell is left to cut: the sites are too few for the surface's topology, or a component holds none" : "")
                + (r.no_room_for_sites ? "; every site it would add falls beside an existing one" : ""));
      sites_added = r.sites_added;
      for(std::size_t i = given; i < r.sites.size(); ++i)
      {
        Point q;
        locations.push_back(canonical_location(r.sites[i], mesh, q));
        site_points.push_back(q);
      }
      if(!choices.weights.empty()) choices.weights.resize(locations.size());
    }
    catch(const SV::Input_error& e) { fail(1, args.mesh + ": " + e.what()); }
    catch(const SV::Numerical_error& e) { fail(3, e.what()); }
  }

  try
  {
    {
      const Mesh* work = &mesh;
      // the final diagram on a copy of the mesh (sites inserted, or refined for the geodesic
      // metric) has a metric of its own: the input mesh's is freed first
      if(args.insert_sites || (args.metric == "geodesic" && !args.no_refine))
        input_metric.release();
      std::vector<Location> work_sites = locations;
      SV::Site_insertion_result<Mesh, Point> inserted;
      Mesh refined;   // the refined copy, each face knowing the input face it lies in
      auto refined_input_face = refined.add_property_map<Mesh::Face_index, Mesh::Face_index>("f:input_face").first;
      double insertion = 0;
      // marks the edges of a working copy that lie on an input breakline
      auto carry_breaklines = [&](Mesh& copy, const auto& input_face) {
        auto marked = copy.add_property_map<Mesh::Edge_index, bool>("e:breakline", false).first;
        if(args.breaklines.empty() && args.sharp_edges <= 0) return;
        for(auto e : edges(copy))
        {
          const auto h = halfedge(e, copy), o = opposite(h, copy);
          if(is_border(h, copy) || is_border(o, copy)) continue;
          const auto f1 = input_face[face(h, copy)], f2 = input_face[face(o, copy)];
          if(f1 == f2) continue;
          for(auto g : CGAL::halfedges_around_face(halfedge(f1, mesh), mesh))
            if(face(opposite(g, mesh), mesh) == f2 && breakline[edge(g, mesh)]) marked[e] = true;
        }
      };
      if(args.metric == "geodesic" && !args.insert_sites && !args.no_refine)
      {
        // a metric sampled at vertices needs vertices between the sites (coarse CAD meshes)
        const auto ti = Clock::now();
        const std::size_t max_vertices = refinement_cap(mesh, locations.size());
        // (with --valid-dual, by the local spacing, as the sites were added on such meshes)
        const SV::Refined_sites<Mesh> r = SV::refine_for_sites(mesh, locations, refined,
            SV::parameters::refinement_max_vertices(max_vertices, SV::parameters::refinement_local_spacing(args.valid_dual)),
            SV::parameters::input_face_map(refined_input_face));
        if(r.vertex_limit_reached)
          fail(1, args.mesh + ": the refinement for the sites reached its cap of " + std::to_string(max_vertices)
                  + " vertices (the input's and at most " + std::to_string(refinement_vertices_per_element)
                  + " more per input vertex and site, at most " + std::to_string(refinement_max_vertices)
                  + " more; thin faces need many): use --no-refine, --insert-sites or fewer sites");
        check_sites_per_face(r.sites, true);
        if(r.edges_split > 0)
        {
          work = &refined;
          work_sites = r.sites;
          carry_breaklines(refined, refined_input_face);
          mesh = Mesh();   // not read again: its memory goes to the diagram
          std::cerr << "surface_voronoi: note: the mesh was refined for the sites (" << r.edges_split
                    << " edges split, " << num_vertices(refined) << " vertices; --no-refine to keep it)" << std::endl;
        }
        else
          refined = Mesh();   // an unchanged copy, not read again: its memory goes to the diagram
        insertion = std::chrono::duration<double>(Clock::now() - ti).count();
      }
      if(args.insert_sites)
      {
        const auto ti = Clock::now();
        inserted = SV::insert_sites(mesh, locations);
        work = &inserted.mesh;
        work_sites.clear();
        for(auto v : inserted.site_vertices)
        {
          // the site as a location of the augmented mesh, at its vertex
          auto h = halfedge(v, inserted.mesh);
          if(is_border(h, inserted.mesh)) h = opposite(next(h, inserted.mesh), inserted.mesh);
          const auto f = face(h, inserted.mesh);
          std::array<double, 3> b = {{ 0, 0, 0 }};
          auto g = halfedge(f, inserted.mesh);
          for(int k = 0; k < 3; ++k, g = next(g, inserted.mesh))
            if(source(g, inserted.mesh) == v) b[k] = 1;
          work_sites.push_back(Location(f, b));
        }
        // an edge of the augmented mesh between two input faces lies on their common edge
        carry_breaklines(inserted.mesh, inserted.input_face);
        insertion = std::chrono::duration<double>(Clock::now() - ti).count();
      }
      const std::size_t dimension = dimension_for(*work);
      if(work == &mesh)
        input_metric.apply(dimension, [&](auto& metric) {
          const double embedding = args.metric == "biharmonic" ? input_metric.build_seconds() : 0.;
          run(args, *work, metric, work_sites, choices, load, embedding, insertion, site_points, sites_added, input_metric.prepared());
        });
      else
      {
        std::optional<Prepared_mesh> work_prepared;
        Input_metric metric(args, *work, work_prepared);
        metric.apply(dimension, [&](auto& m) {
          const double embedding = args.metric == "biharmonic" ? metric.build_seconds() : 0.;
          run(args, *work, m, work_sites, choices, load, embedding, insertion, site_points, sites_added, metric.prepared());
        });
      }
    }
  }
  catch(const SV::Input_error& e) { fail(1, args.mesh + ": " + e.what()); }
  catch(const SV::Numerical_error& e) { fail(3, e.what()); }

  if(args.stats)
    std::cout << "lloyd: " << lloyd_seconds << "\n";
  if(args.stats)
    for(std::size_t k = 0; k < lloyd_energies.size(); ++k)
      std::cout << "lloyd_energy_" << k << ": " << std::ldexp(lloyd_energies[k], 4 * args.scale) << "\n";   // area x squared length
  if(args.stats && lloyd_done.size() == args.lloyd + 1)
    for(std::size_t k = 1; k < lloyd_done.size(); ++k)
      std::cout << "lloyd_step_" << k << ": " << std::chrono::duration<double>(lloyd_done[k] - lloyd_done[k - 1]).count() << "\n";
  if(!args.sites_out.empty())
  {
    // the weights go with the sites, so that a power diagram reads back as the same diagram;
    // both in the units of the input (the normalization undone exactly)
    for(Point& p : site_points) p = scaled(p, args.scale);
    std::vector<double> weights_out = choices.weights;
    for(double& w : weights_out) w = std::ldexp(w, 2 * args.scale);
    try
    {
      write_output_file(args.sites_out, false, [&](std::ostream& os) {
        try { write_sites_file(os, site_points, weights_out); }
        catch(const Input_error&) { if(os) throw; }   // a failed stream: the system says why
        return static_cast<bool>(os);
      });
    }
    catch(const Write_error& e) { fail(4, e.what()); }
    catch(const Input_error& e) { fail(4, "cannot write '" + args.sites_out + "': " + e.what()); }
  }
  return 0;
}

} // namespace
} // namespace svd_program

int main(int argc, char** argv)
{
  svd_program::program_start = std::chrono::steady_clock::now();
  // A write past a file-size limit must fail with an error the program reports (exit 4), not
  // end the process before it can remove its partial file.
  std::signal(SIGXFSZ, SIG_IGN);
  svd_program::set_large_block_policy();
#ifdef SVD_PROGRAM_USES_CHOLMOD
  // CHOLMOD's dense blocks go through the BLAS: OpenBLAS on one thread, since its pool would
  // spin on the other cores and its rounding changes with its number of threads (the output
  // must not depend on --threads)
  if(openblas_set_num_threads != nullptr)
    openblas_set_num_threads(1);
#endif
  try
  {
    return svd_program::run_main(argc, argv);
  }
  catch(const svd_program::Failure& f)
  {
    // whatever a message quotes from a file or the command line, it prints as one line of printable ASCII
    std::cerr << "surface_voronoi: error: " << svd_program::printable_text(f.message) << (f.code == 2 ? " (see --help)" : "")
              << std::endl;
    return f.code;
  }
  catch(const std::bad_alloc&)
  {
    std::cerr << "surface_voronoi: error: out of memory" << std::endl;
    return 3;
  }
  catch(const std::exception& e)
  {
    std::cerr << "surface_voronoi: error: " << svd_program::printable_text(e.what()) << std::endl;
    return 3;
  }
}
