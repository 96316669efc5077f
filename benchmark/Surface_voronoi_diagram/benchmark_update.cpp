// The cost of updating a diagram against building it: 10k blue-noise sites (seed 0), 100 of
// them (seed 0) moved by at most a quarter of the mean spacing, then update(); against the
// constructor given the same built metric (the embedding is built once, outside both timings).
// The first update also builds the search tree that locates sites given as points; a later
// update (the sites moved back) is timed apart. One thread, median of --repeat runs.
//
//   benchmark_update MESH.off [MESH.off ...] [--repeat 5] [--sites 10000] [--moved 100]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Random.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Surface_voronoi_diagram.h>
#include <CGAL/Surface_voronoi_diagram/Euclidean_embedding.h>
#include <CGAL/Surface_voronoi_diagram/sampling.h>

#include <surface_voronoi/read_checked_mesh.h>   // the surface_voronoi program's checked reader

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace SV = CGAL::Surface_voronoi;
typedef std::chrono::steady_clock Clock;

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

template <class Metric>
void measure(const std::string& name, const std::string& metric_name, const Mesh& mesh, Metric& metric,
             std::size_t n, std::size_t moved, int repeat)
{
  typedef CGAL::Surface_voronoi_diagram<Mesh, Metric> Diagram;
  const auto sites = SV::blue_noise_sites(mesh, n, CGAL::parameters::random_seed(0));
  CGAL::Random random(0);
  std::vector<std::size_t> which;
  while(which.size() < moved)
  {
    const std::size_t i = std::size_t(random.get_int(0, int(sites.size())));
    if(std::find(which.begin(), which.end(), i) == which.end()) which.push_back(i);
  }
  std::vector<double> build, first, later, build_propagation, later_propagation, later_cutting, later_repair;
  for(int r = 0; r < repeat; ++r)
  {
    SV::Stage_times times;
    const Clock::time_point t0 = Clock::now();
    Diagram vd(mesh, metric, sites, SV::parameters::stage_times(&times));
    build.push_back(seconds_since(t0));
    build_propagation.push_back(times["propagation"]);
    // a quarter of the mean spacing, in a random direction, then onto the surface
    const double step = 0.25 * std::sqrt(vd.surface_area() / double(n));
    std::vector<K::Point_3> targets, back;
    for(std::size_t i : which)
    {
      const K::Vector_3 d(random.get_double(-1, 1), random.get_double(-1, 1), random.get_double(-1, 1));
      const double len = std::sqrt(d.squared_length());
      targets.push_back(vd.site_point(i) + d * (random.get_double(0, step) / (len > 0 ? len : 1)));
      back.push_back(vd.site_point(i));
    }
    // the first update builds the search tree that locates sites given as points
    const Clock::time_point t1 = Clock::now();
    for(std::size_t k = 0; k < which.size(); ++k) vd.move_site(which[k], targets[k]);
    vd.update();
    first.push_back(seconds_since(t1));
    times.seconds.clear();
    const Clock::time_point t2 = Clock::now();
    for(std::size_t k = 0; k < which.size(); ++k) vd.move_site(which[k], back[k]);
    vd.update();
    later.push_back(seconds_since(t2));
    later_propagation.push_back(times["propagation"]);
    later_cutting.push_back(times["cutting"]);
    later_repair.push_back(times["repair"]);
  }
  std::cout << "| " << name << " | " << metric_name << " | " << num_faces(mesh) << " | " << std::fixed << std::setprecision(3)
            << median(build) << " (" << median(build_propagation) << ") | " << median(first) << " | "
            << median(later) << " (" << median(later_propagation) << ", " << median(later_cutting) << ", "
            << median(later_repair) << ") | " << std::setprecision(2)
            << median(later) / median(build) << " |" << std::endl;
}

} // namespace

int main(int argc, char** argv)
{
  std::vector<std::string> files;
  int repeat = 5;
  std::size_t n = 10000, moved = 100;
  for(int a = 1; a < argc; ++a)
  {
    const std::string arg = argv[a];
    if(arg == "--repeat" && a + 1 < argc) repeat = std::atoi(argv[++a]);
    else if(arg == "--sites" && a + 1 < argc) n = std::size_t(std::atol(argv[++a]));
    else if(arg == "--moved" && a + 1 < argc) moved = std::size_t(std::atol(argv[++a]));
    else files.push_back(arg);
  }
  std::cout << n << " sites, " << moved << " moved; seconds, median of " << repeat << " (the constructor's propagation; the\n"
            << "later update's propagation, cutting and stitching, and check)\n\n"
            << "| mesh | metric | faces | constructor | first update | later update | later / constructor |\n"
            << "| --- | --- | ---: | ---: | ---: | ---: | ---: |" << std::endl;
  for(const std::string& file : files)
  {
    Mesh mesh;
    svd_program::read_checked_triangle_mesh(file, mesh);
    const std::string name = file.substr(file.find_last_of('/') + 1);
    SV::Euclidean_embedding<Mesh> euclidean(mesh);
    measure(name, "Euclidean", mesh, euclidean, n, moved, repeat);
    CGAL::Biharmonic_embedding<Mesh> biharmonic(mesh);
    measure(name, "biharmonic", mesh, biharmonic, n, moved, repeat);
  }
  return 0;
}
