// The embedding's eigen-solve, direct (the library's shift-invert Lanczos) against the
// coarse-to-fine prototype (coarse_to_fine_prototype.h), alternately, on one mesh: the time of
// each (wall and process CPU: the machine is shared), the largest relative eigenvalue error,
// and the share of the area (lumped mass) whose nearest of 1,000 random vertex sites in the
// embedding is the same under both solves, a proxy for the cells' agreement.
//
// usage: benchmark_coarse_to_fine MESH.off D [--repeat R] [--coarsest N] [--steps S]
//        [--sweeps J] [--no-lobpcg] [--ritz-tolerance T] [--trace]

#include "coarse_to_fine_prototype.h"

#include <CGAL/Surface_voronoi_diagram/internal/Double_kernel.h>
#include <CGAL/Surface_voronoi_diagram/internal/Spectral/cotangent_laplacian.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <random>
#include <string>
#include <vector>

namespace SVi = CGAL::Surface_voronoi::internal;

namespace {

struct Clock
{
  std::chrono::steady_clock::time_point wall = std::chrono::steady_clock::now();
  std::clock_t cpu = std::clock();
  double wall_seconds() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - wall).count(); }
  double cpu_seconds() const { return double(std::clock() - cpu) / CLOCKS_PER_SEC; }
};

double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v.empty() ? 0. : v[v.size() / 2];
}

} // namespace

int main(int argc, char** argv)
{
  if(argc < 3)
  {
    std::fprintf(stderr, "usage: %s MESH.off D [--repeat R] [--coarsest N] [--steps S] [--sweeps J] "
                         "[--no-lobpcg] [--ritz-tolerance T] [--trace]\n", argv[0]);
    return 2;
  }
  const std::string file = argv[1];
  const int d = std::atoi(argv[2]);
  int repeat = 3;
  svd_bench::Coarse_to_fine_options options;
  for(int i = 3; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto next = [&]() { return i + 1 < argc ? std::string(argv[++i]) : std::string("0"); };
    if(a == "--repeat") repeat = std::stoi(next());
    else if(a == "--coarsest") options.coarsest = std::stoul(next());
    else if(a == "--steps") options.steps = std::stoi(next());
    else if(a == "--sweeps") options.sweeps = std::stoi(next());
    else if(a == "--no-lobpcg") options.lobpcg = false;
    else if(a == "--ritz-tolerance") options.ritz_tolerance = std::stod(next());
    else if(a == "--trace") options.trace = true;
    else { std::fprintf(stderr, "unknown option %s\n", a.c_str()); return 2; }
  }

  // a plain OFF triangle mesh
  std::ifstream in(file);
  std::string header;
  std::size_t nv = 0, nf = 0, ne = 0;
  in >> header >> nv >> nf >> ne;
  std::vector<SVi::Point_d> points(nv);
  std::vector<Eigen::Vector3d> x(nv);
  for(std::size_t i = 0; i < nv; ++i)
  {
    in >> x[i][0] >> x[i][1] >> x[i][2];
    points[i] = SVi::Point_d(x[i][0], x[i][1], x[i][2]);
  }
  std::vector<std::array<int, 3> > triangles(nf);
  for(auto& t : triangles)
  {
    int k = 0;
    in >> k >> t[0] >> t[1] >> t[2];
  }
  if(!in || header != "OFF") { std::fprintf(stderr, "cannot read %s\n", file.c_str()); return 1; }
  Eigen::SparseMatrix<double> L, M;
  SVi::assemble_cotangent_laplacian(points, triangles, L, M);
  const Eigen::Index nev = d + 1;   // one component: the zero mode comes first

  std::vector<double> direct_wall, direct_cpu, fast_wall, fast_cpu;
  SVi::Eigen_solve_result exact, fast;
  for(int r = 0; r < repeat; ++r)
  {
    Clock c;
    exact = SVi::smallest_generalized_eigenpairs<SVi::Default_eigen_LA>(L, M, nev);
    direct_wall.push_back(c.wall_seconds());
    direct_cpu.push_back(c.cpu_seconds());
    Clock f;
    fast = svd_bench::coarse_to_fine_eigenpairs<SVi::Default_eigen_LA>(L, M, x, nev, options);
    fast_wall.push_back(f.wall_seconds());
    fast_cpu.push_back(f.cpu_seconds());
    std::printf("run %d: direct %.3f s (cpu %.3f), coarse to fine %.3f s (cpu %.3f)\n", r, direct_wall.back(),
                direct_cpu.back(), fast_wall.back(), fast_cpu.back());
  }

  double error = 0;
  for(Eigen::Index k = 1; k < nev; ++k)
    error = (std::max)(error, std::abs(fast.eigenvalues[k] / exact.eigenvalues[k] - 1));
  std::mt19937 rng(7);
  std::vector<Eigen::Index> sites(1000);
  for(auto& s : sites) s = Eigen::Index(rng() % nv);
  auto nearest_site = [&](const SVi::Eigen_solve_result& e) {
    Eigen::MatrixXd E(L.rows(), d);
    for(int k = 0; k < d; ++k) E.col(k) = e.eigenvectors.col(k + 1) / e.eigenvalues[k + 1];
    std::vector<int> label(nv);
    for(std::size_t i = 0; i < nv; ++i)
    {
      double best = std::numeric_limits<double>::infinity();
      for(std::size_t s = 0; s < sites.size(); ++s)
      {
        const double q = (E.row(sites[s]) - E.row(Eigen::Index(i))).squaredNorm();
        if(q < best) { best = q; label[i] = int(s); }
      }
    }
    return label;
  };
  const std::vector<int> a = nearest_site(exact), b = nearest_site(fast);
  double same = 0, total = 0;
  for(std::size_t i = 0; i < nv; ++i)
  {
    const double w = M.coeff(Eigen::Index(i), Eigen::Index(i));
    total += w;
    if(a[i] == b[i]) same += w;
  }
  std::printf("%s: %zu vertices, d = %d: direct %.3f s (cpu %.3f), coarse to fine %.3f s (cpu %.3f), ratio %.2f (cpu %.2f); "
              "eigenvalue error %.1e, area agreement %.3f%%\n",
              file.c_str(), nv, d, median(direct_wall), median(direct_cpu), median(fast_wall), median(fast_cpu),
              median(fast_wall) / median(direct_wall), median(fast_cpu) / median(direct_cpu), error, 100 * same / total);
  return 0;
}
