// Copyright (c) 2026 The Surface_voronoi_diagram authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// benchmark_surface_voronoi: timings of the biharmonic embedding and of the diagram, printed
// as GitHub markdown tables, with a final block comparing against the package's stretch
// targets. It is a measurement program, not a test: it never fails on a slow result.
//
//   benchmark_surface_voronoi [--data DIR] [--quick] [--max-vertices N]
//                             [--section embedding|solvers|sites|all]
//
// Sections:
//   1 embedding  assembly + eigen-solve time against the dimension d (on a ~20k-vertex mesh)
//                and against the mesh size at d = 10 (Loop-subdivided generated shells)
//   2 solvers    the shift-invert factorization: Eigen::SimplicialLDLT in AMD order (the
//                library's default until its METIS-ordered LLT), Spectra's own SymShiftInvert
//                (SparseLU) and CHOLMOD when built in
//   3 sites      the diagram's stages for 1k to 100k random sites
// Peak memory (VmHWM) is printed after each section; the larger configurations run in a
// forked child process whose peak is reset first, so each reported peak is its own.
//
// Everything runs on one thread. Progress goes to stderr, tables to stdout.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Biharmonic_embedding.h>
#include <CGAL/Surface_voronoi_diagram.h>
#include <CGAL/Surface_voronoi_diagram/Euclidean_embedding.h>
#include <CGAL/Surface_voronoi_diagram/internal/Indexed_mesh.h>
#include <CGAL/Surface_voronoi_diagram/internal/Spectral/cotangent_laplacian.h>
#include <CGAL/Surface_voronoi_diagram/internal/Spectral/generalized_eigensolver.h>

// the surface_voronoi program's mesh reader and PLY arrangement, timed as the program runs them
#include <surface_voronoi/read_checked_mesh.h>
#include <surface_voronoi/write_arrangement_PLY.h>
#include <test_meshes.h>   // the generated test shells

#include <CGAL/IO/OFF.h>
#include <CGAL/Random.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <Spectra/MatOp/SparseSymMatProd.h>
#include <Spectra/MatOp/SymShiftInvert.h>
#include <Spectra/SymGEigsShiftSolver.h>
#ifdef SVD_BENCH_HAS_CHOLMOD
#include <Eigen/CholmodSupport>
#endif

#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#ifndef SVD_BENCH_DATA_DIR
#define SVD_BENCH_DATA_DIR ""
#endif
#ifndef SVD_BENCH_CGAL_MESHES
#define SVD_BENCH_CGAL_MESHES ""
#endif

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef CGAL::Polygon_mesh_processing::Face_location<Mesh, double> Location;
typedef CGAL::Biharmonic_embedding<Mesh> Biharmonic;
typedef CGAL::Surface_voronoi::Euclidean_embedding<Mesh> Euclidean;
typedef std::chrono::steady_clock Clock;
namespace SV = CGAL::Surface_voronoi;

const char* const program = "benchmark_surface_voronoi";
const double nan_value = std::numeric_limits<double>::quiet_NaN();

double seconds_since(Clock::time_point t0)
{
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// ---------------------------------------------------------------------------------------
// Command line

struct Usage_error
{
  std::string message;
};

const char* const usage_text =
  "usage: benchmark_surface_voronoi [--data DIR] [--quick] [--max-vertices N]\n"
  "                                 [--section embedding|solvers|sites|all]\n"
  "  --data DIR        folder of real meshes (boot.off is the ~20k-vertex mesh); default: the\n"
  "                    configured SVD_DATA_DIR when it exists, else generated meshes are used\n"
  "  --quick           small sizes only (finishes in well under a minute)\n"
  "  --max-vertices N  largest generated mesh (default 1000000): caps the size sweep, and the\n"
  "                    ~180k (solvers) and ~500k (sites) meshes are skipped above it\n"
  "  --section S       which section to run (default all)\n";

struct Settings
{
  std::string data_dir;
  bool data_given = false;
  bool quick = false;
  std::size_t max_vertices = 1000000;
  std::string section = "all";
};

bool is_directory(const std::string& path)
{
  struct stat st;
  return !path.empty() && ::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode);
}

bool is_file(const std::string& path)
{
  struct stat st;
  return !path.empty() && ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}

Settings parse_arguments(int argc, char** argv)
{
  Settings s;
  for(int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if(i + 1 >= argc)
        throw Usage_error{ arg + " expects a value" };
      return argv[++i];
    };
    if(arg == "--data")
    {
      s.data_dir = value();
      s.data_given = true;
    }
    else if(arg == "--quick")
      s.quick = true;
    else if(arg == "--max-vertices")
    {
      const std::string text = value();
      char* end = nullptr;
      errno = 0;
      const unsigned long long v = std::strtoull(text.c_str(), &end, 10);
      if(text.empty() || text[0] == '-' || end != text.c_str() + text.size() || errno != 0 || v < 1)
        throw Usage_error{ "--max-vertices expects a positive integer, got '" + text + "'" };
      s.max_vertices = static_cast<std::size_t>(v);
    }
    else if(arg == "--section")
    {
      s.section = value();
      if(s.section != "embedding" && s.section != "solvers" && s.section != "sites" && s.section != "all")
        throw Usage_error{ "--section expects embedding, solvers, sites or all, got '" + s.section + "'" };
    }
    else if(arg == "--help" || arg == "-h")
      throw Usage_error{ "" };
    else
      throw Usage_error{ "unknown argument '" + arg + "' (see --help)" };
  }
  if(!s.data_given)
    s.data_dir = SVD_BENCH_DATA_DIR;
  return s;
}

// ---------------------------------------------------------------------------------------
// Memory: VmHWM / VmRSS of this process, in MB (NaN where /proc is unavailable)

double status_mb(const char* key)
{
  std::ifstream in("/proc/self/status");
  std::string line;
  const std::size_t n = std::strlen(key);
  while(std::getline(in, line))
    if(line.compare(0, n, key) == 0 && line.size() > n && line[n] == ':')
      return std::strtod(line.c_str() + n + 1, nullptr) / 1024.0;   // kB
  return nan_value;
}

// Resets the peak RSS to the current RSS (Linux >= 4.0); harmless where unsupported.
void reset_peak_memory()
{
  std::ofstream out("/proc/self/clear_refs");
  out << "5";
}

// ---------------------------------------------------------------------------------------
// Child processes: one configuration, its own peak memory. The child reports through a
// pipe: 'O', then doubles (rss at start, peak, count, values...); or 'E' and a message.

struct Child_result
{
  bool ok = false;
  std::string error;
  std::vector<double> values;
  double start_mb = nan_value;
  double peak_mb = nan_value;
};

void write_all(int fd, const char* data, std::size_t size)
{
  while(size > 0)
  {
    const ssize_t w = ::write(fd, data, size);
    if(w <= 0)
    {
      if(w < 0 && errno == EINTR) continue;
      return;
    }
    data += w;
    size -= static_cast<std::size_t>(w);
  }
}

Child_result run_in_child(const std::function<std::vector<double>()>& task)
{
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  int fds[2];
  if(::pipe(fds) != 0)
    throw std::runtime_error("pipe() failed");
  const pid_t pid = ::fork();
  if(pid < 0)
    throw std::runtime_error("fork() failed");
  if(pid == 0)
  {
    ::close(fds[0]);
    std::string message;
    try
    {
      const double start = status_mb("VmRSS");
      reset_peak_memory();
      const std::vector<double> values = task();
      const double peak = status_mb("VmHWM");
      std::vector<double> out = { start, peak, double(values.size()) };
      out.insert(out.end(), values.begin(), values.end());
      message = "O";
      message.append(reinterpret_cast<const char*>(out.data()), out.size() * sizeof(double));
    }
    catch(const std::exception& e)
    {
      message = std::string("E") + e.what();
    }
    catch(...)
    {
      message = "Eunknown exception";
    }
    write_all(fds[1], message.data(), message.size());
    ::close(fds[1]);
    std::fflush(nullptr);
    ::_exit(0);
  }
  ::close(fds[1]);
  std::string data;
  char buffer[65536];
  for(;;)
  {
    const ssize_t r = ::read(fds[0], buffer, sizeof buffer);
    if(r < 0 && errno == EINTR) continue;
    if(r <= 0) break;
    data.append(buffer, static_cast<std::size_t>(r));
  }
  ::close(fds[0]);
  int status = 0;
  while(::waitpid(pid, &status, 0) < 0 && errno == EINTR) {}

  Child_result result;
  if(WIFSIGNALED(status))
  {
    result.error = "child killed by signal " + std::to_string(WTERMSIG(status))
                   + (WTERMSIG(status) == SIGKILL ? " (out of memory?)" : "");
    return result;
  }
  if(data.empty())
  {
    result.error = "child reported nothing";
    return result;
  }
  if(data[0] == 'E')
  {
    result.error = data.substr(1);
    for(char& c : result.error)
      if(c == '\n') c = ' ';
    return result;
  }
  const std::size_t n = (data.size() - 1) / sizeof(double);
  std::vector<double> all(n);
  std::memcpy(all.data(), data.data() + 1, n * sizeof(double));
  if(n < 3 || all[2] != double(n - 3))
  {
    result.error = "child reported garbled data";
    return result;
  }
  result.ok = true;
  result.start_mb = all[0];
  result.peak_mb = all[1];
  result.values.assign(all.begin() + 3, all.end());
  return result;
}

// ---------------------------------------------------------------------------------------
// Markdown tables, printed row by row as results come in.

std::string fixed(double x, int digits)
{
  if(!std::isfinite(x))
    return "n/a";
  std::ostringstream out;
  out.setf(std::ios::fixed);
  out.precision(digits);
  out << x;
  return out.str();
}

std::string seconds(double x)
{
  return fixed(x, x < 10 ? 4 : 2);
}

std::string scientific(double x)
{
  if(!std::isfinite(x))
    return "n/a";
  if(x == 0)
    return "0";
  std::ostringstream out;
  out.setf(std::ios::scientific);
  out.precision(1);
  out << x;
  return out.str();
}

std::string count(std::size_t n)
{
  std::string digits = std::to_string(n), out;
  for(std::size_t i = 0; i < digits.size(); ++i)
  {
    if(i > 0 && (digits.size() - i) % 3 == 0)
      out += ',';
    out += digits[i];
  }
  return out;
}

std::string short_count(std::size_t n)
{
  if(n >= 1000000 && n % 100000 == 0)
    return fixed(double(n) / 1e6, n % 1000000 == 0 ? 0 : 1) + "M";
  if(n >= 1000 && n % 1000 == 0)
    return std::to_string(n / 1000) + "k";
  return count(n);
}

class Table
{
public:
  Table(const std::string& title, const std::vector<std::string>& header) : m_columns(header.size())
  {
    std::cout << "\n### " << title << "\n\n|";
    for(const std::string& h : header)
      std::cout << ' ' << h << " |";
    std::cout << "\n|";
    for(std::size_t i = 0; i < header.size(); ++i)
      std::cout << (i == 0 ? " --- |" : " ---: |");
    std::cout << std::endl;
  }

  void row(const std::vector<std::string>& cells) const
  {
    std::cout << '|';
    for(std::size_t i = 0; i < m_columns; ++i)
      std::cout << ' ' << (i < cells.size() ? cells[i] : std::string()) << " |";
    std::cout << std::endl;
  }

  // A configuration that failed: its first cells, then the error across the rest.
  void failed(std::vector<std::string> cells, const std::string& error) const
  {
    std::string e = error;
    for(char& c : e)
      if(c == '|') c = '/';
    cells.push_back("failed: " + e);
    row(cells);
  }

private:
  std::size_t m_columns;
};

void note(const std::string& text)
{
  std::cout << "\n" << text << std::endl;
}

void progress(const std::string& text)
{
  std::cerr << "[" << program << "] " << text << std::endl;
}

void print_peak(const std::string& section)
{
  std::cout << "\nPeak memory of the main process after " << section << ": VmHWM = "
            << fixed(status_mb("VmHWM"), 1) << " MB (children report their own peaks above)" << std::endl;
}

// ---------------------------------------------------------------------------------------
// Meshes

std::size_t nv(const Mesh& m) { return static_cast<std::size_t>(num_vertices(m)); }
std::size_t nf(const Mesh& m) { return static_cast<std::size_t>(num_faces(m)); }

double load_mesh(const std::string& file, Mesh& mesh)
{
  const Clock::time_point t0 = Clock::now();
  svd_program::read_checked_triangle_mesh(file, mesh);
  return seconds_since(t0);
}

void loop_subdivide(Mesh& mesh, int levels)
{
  if(levels > 0)
    CGAL::Subdivision_method_3::Loop_subdivision(mesh, CGAL::parameters::number_of_iterations(levels));
}

// A generated mesh of about `target` vertices: a thin lampshade (a closed shell, genus 1,
// so each Loop level multiplies the vertex count by exactly 4) of target / 4^k vertices,
// refined by k Loop levels, k the largest level leaving at least 5000 base vertices.
// Falls back on CGAL's elephant when the generator is unavailable. Returns a description.
std::string make_mesh_of_size(std::size_t target, Mesh& mesh)
{
  int levels = 0;
  std::size_t base = target;
  while(base / 4 >= 5000)
  {
    base /= 4;
    ++levels;
  }
  try
  {
    svd_test::meshes::Lampshade_options o;
    o.target_vertices = (std::max<std::size_t>)(base, 100);
    svd_test::meshes::make_thin_lampshade(mesh, o);
    loop_subdivide(mesh, levels);
    return "lampshade " + short_count(nv(mesh) >> (2 * levels)) + " + " + std::to_string(levels) + " Loop";
  }
  catch(const std::exception& e)
  {
    const std::string elephant = std::string(SVD_BENCH_CGAL_MESHES) + "/elephant.off";
    if(!is_file(elephant))
      throw std::runtime_error(std::string("cannot generate a mesh (") + e.what() + ") and CGAL's elephant.off is not available");
    progress(std::string("mesh generator failed (") + e.what() + "): subdividing CGAL's elephant instead");
    load_mesh(elephant, mesh);
    int k = 0;
    while(double(nv(mesh)) * 4 < 1.3 * double(target))
    {
      loop_subdivide(mesh, 1);
      ++k;
    }
    return "elephant + " + std::to_string(k) + " Loop";
  }
}

// The ~20k-vertex mesh of sections 1-3: the real boot.off when the data folder has it,
// otherwise a generated thin lampshade of 20k vertices.
struct Named_mesh
{
  std::string name;     // for the tables
  std::string file;     // where the mesh was (or can be) loaded from; empty if generated only
  Mesh mesh;
};

bool data_folder_usable(const Settings& s)
{
  return is_directory(s.data_dir);
}

void get_mesh_20k(const Settings& s, Named_mesh& out)
{
  const std::string boot = s.data_dir + "/boot.off";
  if(data_folder_usable(s) && is_file(boot))
  {
    load_mesh(boot, out.mesh);
    out.name = "boot.off";
    out.file = boot;
    return;
  }
  svd_test::meshes::Lampshade_options o;
  o.target_vertices = 20000;
  try
  {
    svd_test::meshes::make_thin_lampshade(out.mesh, o);
    out.name = "lampshade 20k";
  }
  catch(const std::exception&)
  {
    out.name = make_mesh_of_size(20000, out.mesh);
  }
  out.file.clear();
}

// A temporary OFF file, removed when the object dies (in the parent only: children _exit).
struct Temporary_file
{
  std::string path;
  const pid_t owner = ::getpid();
  ~Temporary_file()
  {
    if(!path.empty() && ::getpid() == owner)
      std::remove(path.c_str());
  }
};

void write_temporary(const Mesh& mesh, const std::string& tag, Temporary_file& file)
{
  const char* tmp = std::getenv("TMPDIR");
  const std::string dir = (tmp != nullptr && is_directory(tmp)) ? tmp : "/tmp";
  file.path = dir + "/svd_benchmark_" + std::to_string(::getpid()) + "_" + tag + ".off";
  if(!CGAL::IO::write_OFF(file.path, mesh, CGAL::parameters::stream_precision(17)))
    throw std::runtime_error("cannot write the temporary mesh file " + file.path);
}

// Area-uniform random sites: a face with probability proportional to its area, then a
// uniform point of it.
std::vector<Location> random_sites(const Mesh& mesh, std::size_t n, unsigned int seed)
{
  CGAL::Random rng(seed);
  std::vector<Mesh::Face_index> faces(mesh.faces().begin(), mesh.faces().end());
  std::vector<double> cumulative;
  cumulative.reserve(faces.size());
  double total = 0;
  for(Mesh::Face_index f : faces)
  {
    const Mesh::Halfedge_index h = mesh.halfedge(f);
    total += std::sqrt(CGAL::squared_area(mesh.point(mesh.source(h)), mesh.point(mesh.target(h)),
                                          mesh.point(mesh.target(mesh.next(h)))));
    cumulative.push_back(total);
  }
  std::vector<Location> sites;
  sites.reserve(n);
  for(std::size_t i = 0; i < n; ++i)
  {
    const double x = rng.get_double(0, total);
    std::size_t k = static_cast<std::size_t>(std::upper_bound(cumulative.begin(), cumulative.end(), x) - cumulative.begin());
    k = (std::min)(k, faces.size() - 1);
    const double r1 = std::sqrt(rng.get_double()), r2 = rng.get_double();
    sites.push_back(Location(faces[k], { { 1 - r1, r1 * (1 - r2), r1 * r2 } }));
  }
  return sites;
}

// ---------------------------------------------------------------------------------------
// What the targets block needs

struct Ratio_measure
{
  std::string label;
  double ratio;
};

struct Measured
{
  double embedding_20k = nan_value;
  std::string embedding_20k_mesh;
  double pcr_10k = nan_value;
  std::string pcr_10k_mesh;
  std::vector<Ratio_measure> per_site_ratios;
};

// ---------------------------------------------------------------------------------------
// Section 1: the embedding

struct Embedding_time
{
  double assembly = nan_value, solve = nan_value, total = nan_value;
  long operations = 0;
};

// best (by total) of `runs` constructions of the embedding of dimension d
Embedding_time time_embedding(const Mesh& mesh, std::size_t d, int runs)
{
  Embedding_time best;
  for(int r = 0; r < runs; ++r)
  {
    SV::Stage_times times;
    const Clock::time_point t0 = Clock::now();
    Biharmonic e(mesh, SV::parameters::embedding_dimension(d, SV::parameters::stage_times(&times)));
    const double total = seconds_since(t0);
    if(!(total >= best.total))
    {
      best.total = total;
      best.assembly = times["assembly"];
      best.solve = times["solve"];
      best.operations = long(times.counts["eigen_operations"]);
    }
  }
  return best;
}

// The size sweep: ~5k, 20k, 80k, 320k, 1.28M vertices, the last one inside the cap
// replaced by the cap itself when the next 4x step would overshoot it.
std::vector<std::size_t> sweep_sizes(const Settings& s)
{
  std::vector<std::size_t> all = { 5000, 20000, 80000, 320000, 1280000 };
  if(s.quick)
    all = { 5000, 20000 };
  std::vector<std::size_t> sizes;
  for(std::size_t t : all)
  {
    if(t <= s.max_vertices)
      sizes.push_back(t);
    else
    {
      if(!s.quick && (sizes.empty() || double(s.max_vertices) > 1.5 * double(sizes.back())) && s.max_vertices >= 1000)
        sizes.push_back(s.max_vertices);
      break;
    }
  }
  return sizes;
}

void section_embedding(const Settings& s, const Named_mesh& m20k, Measured& measured)
{
  std::cout << "\n## 1. Biharmonic embedding (cotangent assembly + shift-invert Lanczos eigen-solve)" << std::endl;
  const int runs_small = 3;
  {
    Table t("Embedding time against the dimension d on " + m20k.name + " (" + count(nv(m20k.mesh))
              + " vertices), best of " + std::to_string(runs_small) + " runs",
            { "d", "assembly s", "eigen-solve s", "total s", "Lanczos ops", "total / total(d=10)" });
    std::vector<std::pair<std::size_t, Embedding_time> > rows;
    double t10 = nan_value;
    for(std::size_t d = 2; d <= 20; d += 2)
    {
      progress("embedding d = " + std::to_string(d) + " on " + m20k.name);
      try
      {
        const Embedding_time e = time_embedding(m20k.mesh, d, runs_small);
        rows.emplace_back(d, e);
        if(d == 10) t10 = e.total;
      }
      catch(const std::exception& e)
      {
        t.failed({ std::to_string(d) }, e.what());
      }
    }
    for(const auto& r : rows)
      t.row({ std::to_string(r.first), seconds(r.second.assembly), seconds(r.second.solve), seconds(r.second.total),
              std::to_string(r.second.operations), fixed(r.second.total / t10, 2) });
    measured.embedding_20k = t10;
    measured.embedding_20k_mesh = m20k.name + ", " + count(nv(m20k.mesh)) + " vertices";
  }

  const std::vector<std::size_t> sizes = sweep_sizes(s);
  Table t("Embedding time at d = 10 against the mesh size (generated meshes; each size in its own child "
          "process; best of 3 runs below 100k vertices)",
          { "vertices", "mesh", "assembly s", "eigen-solve s", "total s", "us / vertex", "growth exponent",
            "Lanczos ops", "RSS at start MB", "peak MB" });
  double previous_n = nan_value, previous_t = nan_value;
  for(std::size_t target : sizes)
  {
    Mesh mesh;
    progress("generating a mesh of ~" + count(target) + " vertices");
    std::string name;
    try
    {
      name = make_mesh_of_size(target, mesh);
    }
    catch(const std::exception& e)
    {
      t.failed({ "~" + count(target) }, e.what());
      continue;
    }
    const std::size_t n = nv(mesh);
    progress("embedding d = 10 on " + count(n) + " vertices");
    const int runs = n < 100000 ? 3 : 1;
    const Child_result r = run_in_child([&]() {
      const Embedding_time e = time_embedding(mesh, 10, runs);
      return std::vector<double>{ e.assembly, e.solve, e.total, double(e.operations) };
    });
    if(!r.ok)
    {
      t.failed({ count(n), name }, r.error);
      continue;
    }
    const double total = r.values[2];
    const double exponent = std::isfinite(previous_n) ? std::log(total / previous_t) / std::log(double(n) / previous_n) : nan_value;
    t.row({ count(n), name, seconds(r.values[0]), seconds(r.values[1]), seconds(total), fixed(1e6 * total / double(n), 2),
            fixed(exponent, 2), fixed(r.values[3], 0), fixed(r.start_mb, 1), fixed(r.peak_mb, 1) });
    previous_n = double(n);
    previous_t = total;
  }
  if(sizes.empty())
    note("(size sweep skipped: --max-vertices is below 5000)");
  print_peak("section 1");
}

// ---------------------------------------------------------------------------------------
// Section 2: the factorization

struct Spectral_problem
{
  Eigen::SparseMatrix<double> L, M;
  Eigen::Index nev = 0;
  double sigma = 0;
  std::size_t zero_modes = 0;
};

Spectral_problem make_problem(const Mesh& mesh, std::size_t d)
{
  Spectral_problem p;
  SV::internal::Indexed_mesh<Mesh> im(mesh, get(CGAL::vertex_point, mesh));
  SV::internal::assemble_cotangent_laplacian(im.points, im.triangles, p.L, p.M);
  p.zero_modes = im.number_of_components;
  p.nev = static_cast<Eigen::Index>(d + p.zero_modes);
  // the library's shift (generalized_eigensolver.h)
  p.sigma = -1e-6 * p.L.diagonal().mean() / p.M.diagonal().mean();
  return p;
}

// values: factor s, total s, operations, then the nev eigenvalues
template <class Solver>
std::vector<double> time_library_solver(const Spectral_problem& p, int runs)
{
  double factor = nan_value, total = nan_value;
  SV::internal::Eigen_solve_result best;
  for(int r = 0; r < runs; ++r)
  {
    {
      const Clock::time_point t0 = Clock::now();
      const Eigen::SparseMatrix<double> C = p.L - p.sigma * p.M;
      Solver solver;
      solver.compute(C);
      if(solver.info() != Eigen::Success)
        throw std::runtime_error("the factorization failed");
      const double t = seconds_since(t0);
      if(!(t >= factor)) factor = t;
    }
    const Clock::time_point t0 = Clock::now();
    SV::internal::Eigen_solve_result res =
        SV::internal::smallest_generalized_eigenpairs<CGAL::Eigen_solver_traits<Solver> >(p.L, p.M, p.nev);
    const double t = seconds_since(t0);
    if(!(t >= total))
    {
      total = t;
      best = std::move(res);
    }
  }
  std::vector<double> out = { factor, total, double(best.operations) };
  for(Eigen::Index k = 0; k < best.eigenvalues.size(); ++k)
    out.push_back(best.eigenvalues[k]);
  return out;
}

// Spectra's own shift-invert operator (SparseLU), in the library's settings.
std::vector<double> time_spectra_sparse_lu(const Spectral_problem& p, int runs)
{
  typedef Spectra::SymShiftInvert<double, Eigen::Sparse, Eigen::Sparse> Op;
  typedef Spectra::SparseSymMatProd<double> BOp;
  const Eigen::Index n = p.L.rows();
  const Eigen::Index ncv = (std::min)(n, (std::max<Eigen::Index>)(4 * p.nev, 40));
  double factor = nan_value, total = nan_value, operations = 0;
  Eigen::VectorXd values;
  for(int r = 0; r < runs; ++r)
  {
    {
      const Clock::time_point t0 = Clock::now();
      Op op(p.L, p.M);
      op.set_shift(p.sigma);
      const double t = seconds_since(t0);
      if(!(t >= factor)) factor = t;
    }
    const Clock::time_point t0 = Clock::now();
    Op op(p.L, p.M);
    BOp bop(p.M);
    Spectra::SymGEigsShiftSolver<Op, BOp, Spectra::GEigsMode::ShiftInvert> solver(op, bop, p.nev, ncv, p.sigma);
    solver.init();
    const Eigen::Index converged = solver.compute(Spectra::SortRule::LargestMagn, 1000, 1e-10, Spectra::SortRule::SmallestAlge);
    if(solver.info() != Spectra::CompInfo::Successful || converged < p.nev)
      throw std::runtime_error("Spectra did not converge (" + std::to_string(converged) + " of " + std::to_string(p.nev) + ")");
    Eigen::VectorXd v = solver.eigenvalues();
    const double t = seconds_since(t0);
    if(!(t >= total))
    {
      total = t;
      operations = double(solver.num_operations());
      values = v;
    }
  }
  std::vector<double> out = { factor, total, operations };
  // ascending, as the library's
  std::vector<double> sorted(values.data(), values.data() + values.size());
  std::sort(sorted.begin(), sorted.end());
  out.insert(out.end(), sorted.begin(), sorted.end());
  return out;
}

void section_solvers(const Settings& s, const Named_mesh& m20k)
{
  std::cout << "\n## 2. Shift-invert factorization at d = 10 (nev = d + zero modes, ncv = max(4 nev, 40), "
               "sigma = -1e-6 mean(diag L) / mean(diag M))" << std::endl;
  note("\"factor s\" is one factorization of L - sigma M alone; \"eigen-solve s\" is the whole eigen-solve, "
       "one factorization included (the library's path also runs a deflated check round for missed "
       "multiple eigenvalues; Spectra's own path does not). \"max rel. diff\" compares the non-zero "
       "eigenvalues with SimplicialLDLT's.");
#ifndef SVD_BENCH_HAS_CHOLMOD
  note("(CHOLMOD was not found at configure time: install libsuitesparse-dev and reconfigure to time it)");
#endif
  struct Mesh_case
  {
    std::string name;
    const Mesh* mesh;
  };
  Mesh big;
  std::vector<Mesh_case> cases = { { m20k.name, &m20k.mesh } };
  if(!s.quick && s.max_vertices >= 180000)
  {
    progress("generating a mesh of ~180,000 vertices");
    try
    {
      const std::string name = make_mesh_of_size(180000, big);
      cases.push_back({ name, &big });
    }
    catch(const std::exception& e)
    {
      note(std::string("(the ~180k-vertex mesh could not be made: ") + e.what() + ")");
    }
  }
  else
    note(s.quick ? "(--quick: the ~180k-vertex mesh is skipped)" : "(the ~180k-vertex mesh is above --max-vertices: skipped)");

  Table t("Factorizations (each in its own child process; best of 3 runs below 100k vertices)",
          { "mesh", "vertices", "solver", "factor s", "eigen-solve s", "Lanczos s (rest)", "ops",
            "eigen-solve / LDLT", "factor / LDLT", "max rel. diff", "peak MB" });
  for(const Mesh_case& c : cases)
  {
    const std::size_t n = nv(*c.mesh);
    const int runs = n < 100000 ? 3 : 1;
    const Spectral_problem p = make_problem(*c.mesh, 10);
    struct Solver_case
    {
      std::string name;
      std::function<std::vector<double>()> run;
    };
    std::vector<Solver_case> solvers;
    solvers.push_back({ "Eigen::SimplicialLDLT (AMD)", [&]() {
      return time_library_solver<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double> > >(p, runs); } });
    solvers.push_back({ "Spectra SymShiftInvert (SparseLU)", [&]() { return time_spectra_sparse_lu(p, runs); } });
#ifdef SVD_BENCH_HAS_CHOLMOD
    solvers.push_back({ "Eigen::CholmodSupernodalLLT", [&]() {
      return time_library_solver<Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double> > >(p, runs); } });
#endif
    std::vector<double> reference;
    double ref_total = nan_value, ref_factor = nan_value;
    for(const Solver_case& sc : solvers)
    {
      progress("eigen-solve with " + sc.name + " on " + count(n) + " vertices");
      const Child_result r = run_in_child(sc.run);
      if(!r.ok)
      {
        t.failed({ c.name, count(n), sc.name }, r.error);
        continue;
      }
      const double factor = r.values[0], total = r.values[1];
      const std::vector<double> ev(r.values.begin() + 3, r.values.end());
      double diff = nan_value;
      if(reference.empty())
      {
        reference = ev;
        ref_total = total;
        ref_factor = factor;
        diff = 0;
      }
      else if(ev.size() == reference.size())
      {
        diff = 0;
        for(std::size_t k = p.zero_modes; k < ev.size(); ++k)
          diff = (std::max)(diff, std::abs(ev[k] - reference[k]) / std::abs(reference[k]));
      }
      t.row({ c.name, count(n), sc.name, seconds(factor), seconds(total), seconds(total - factor),
              fixed(r.values[2], 0), fixed(total / ref_total, 2), fixed(factor / ref_factor, 2),
              scientific(diff),
              fixed(r.peak_mb, 1) });
    }
  }
  print_peak("section 2");
}

// ---------------------------------------------------------------------------------------
// Section 3: the diagram

// values: constructor s, propagation, cutting, repair, output, mean candidates, broken
// before repair, repair rounds, unreached faces, arrangement faces
template <class Metric>
std::vector<double> time_diagram(const Mesh& mesh, Metric& metric, const std::vector<Location>& sites)
{
  SV::Stage_times times;
  const Clock::time_point t0 = Clock::now();
  CGAL::Surface_voronoi_diagram<Mesh, Metric> vd(mesh, metric, sites, SV::parameters::stage_times(&times));
  const double construction = seconds_since(t0);
  const Clock::time_point t1 = Clock::now();
  const auto arrangement = svd_program::arrangement_for_PLY(vd);
  const double output = seconds_since(t1);
  const SV::Diagram_statistics& st = vd.statistics();
  return { construction, times["propagation"], times["cutting"], times["repair"], output,
           st.mean_candidates_per_face, double(st.broken_cells_before_repair), double(st.repair_rounds),
           double(st.unreached_faces), double(num_faces(arrangement)) };
}

void section_sites(const Settings& s, const Named_mesh& m20k, Measured& measured)
{
  std::cout << "\n## 3. Diagram stages against the number of sites (random area-uniform sites, CGAL::Random seeded "
               "by the site count)" << std::endl;
  note("load = read_checked_triangle_mesh of the mesh file (generated meshes are written to a temporary OFF "
       "first); embedding = metric construction, once per mesh and metric; other = the diagram constructor "
       "minus the propagation, cutting and repair seconds of its statistics (indexing, manifold check, site "
       "location, site fields, and whatever runs between the timed stages, such as freeing each round's cuts); "
       "output = arrangement_for_PLY. Each row runs in its own child process (the peak includes the mesh "
       "and the embedding). P+C+R = propagation + cutting + repair; total = other + P+C+R + output.");

  std::vector<std::size_t> counts = { 1000, 5000, 10000, 100000 };
  if(s.quick)
  {
    counts.pop_back();
    note("(--quick: 100k sites are skipped, so the per-site ratio below is 10k against 1k sites)");
  }

  struct Mesh_case
  {
    std::string name;
    std::size_t target;   // 0: the ~20k mesh
  };
  std::vector<Mesh_case> cases = { { m20k.name, 0 } };
  if(!s.quick && s.max_vertices >= 500000)
    cases.push_back({ "", 500000 });
  else
    note(s.quick ? "(--quick: the ~500k-vertex mesh is skipped)" : "(the ~500k-vertex mesh is above --max-vertices: skipped)");

  Table t("Diagram time per stage",
          { "mesh", "metric", "sites", "load s", "embedding s", "other s", "propagation s", "cutting s", "repair s",
            "output s", "P+C+R us/site", "total us/site", "cand./face", "broken / rounds", "peak MB" });
  struct Per_site
  {
    std::string label;
    double first = nan_value, last = nan_value;
    std::size_t first_count = 0, last_count = 0;
  };
  std::vector<Per_site> per_site;

  for(const Mesh_case& c : cases)
  {
    Temporary_file temporary;
    std::string file = c.target == 0 ? m20k.file : std::string();
    std::string name = c.name;
    if(file.empty())
    {
      Mesh generated;
      if(c.target == 0)
        generated = m20k.mesh;
      else
      {
        progress("generating a mesh of ~" + count(c.target) + " vertices");
        try
        {
          name = make_mesh_of_size(c.target, generated);
        }
        catch(const std::exception& e)
        {
          t.failed({ "~" + count(c.target) }, e.what());
          continue;
        }
      }
      write_temporary(generated, c.target == 0 ? "20k" : "big", temporary);
      file = temporary.path;
    }
    Mesh mesh;
    progress("loading " + file);
    double load = nan_value;
    try
    {
      load = load_mesh(file, mesh);
    }
    catch(const std::exception& e)
    {
      t.failed({ name }, e.what());
      continue;
    }
    const std::string mesh_label = name + " (" + short_count((nv(mesh) + 500) / 1000 * 1000) + " v)";

    for(int metric_kind = 0; metric_kind < 2; ++metric_kind)
    {
      const std::string metric_name = metric_kind == 0 ? "biharmonic d=10" : "euclidean";
      Per_site ps;
      ps.label = mesh_label + ", " + metric_name;
      progress("embedding " + metric_name + " on " + mesh_label);
      std::unique_ptr<Biharmonic> biharmonic;
      std::unique_ptr<Euclidean> euclidean;
      const Clock::time_point t0 = Clock::now();
      try
      {
        if(metric_kind == 0)
        {
          biharmonic.reset(new Biharmonic(mesh, SV::parameters::embedding_dimension(10)));
        }
        else
          euclidean.reset(new Euclidean(mesh));
      }
      catch(const std::exception& e)
      {
        t.failed({ mesh_label, metric_name }, e.what());
        continue;
      }
      const double embedding = seconds_since(t0);

      for(std::size_t n : counts)
      {
        const std::vector<Location> sites = random_sites(mesh, n, static_cast<unsigned int>(n));
        progress("diagram: " + metric_name + ", " + count(n) + " sites on " + mesh_label);
        const Child_result r = run_in_child([&]() {
          return metric_kind == 0 ? time_diagram(mesh, *biharmonic, sites) : time_diagram(mesh, *euclidean, sites);
        });
        if(!r.ok)
        {
          t.failed({ mesh_label, metric_name, count(n) }, r.error);
          continue;
        }
        const std::vector<double>& v = r.values;
        const double pcr = v[1] + v[2] + v[3];
        const double setup = v[0] - pcr;
        const double total = v[0] + v[4];
        t.row({ mesh_label, metric_name, count(n), seconds(load), seconds(embedding), seconds(setup), seconds(v[1]),
                seconds(v[2]), seconds(v[3]), seconds(v[4]), fixed(1e6 * pcr / double(n), 2),
                fixed(1e6 * total / double(n), 2), fixed(v[5], 2),
                fixed(v[6], 0) + " / " + fixed(v[7], 0), fixed(r.peak_mb, 1) });
        const double per = pcr / double(n);
        if(ps.first_count == 0 || n < ps.first_count) { ps.first = per; ps.first_count = n; }
        if(n > ps.last_count) { ps.last = per; ps.last_count = n; }
        if(c.target == 0 && metric_kind == 0 && n == 10000)
        {
          measured.pcr_10k = pcr;
          measured.pcr_10k_mesh = mesh_label;
        }
      }
      per_site.push_back(ps);
    }
  }

  Table r("Per-site cost of propagation + cutting + repair, largest against smallest site count",
          { "mesh, metric", "sites", "P+C+R us/site (first)", "P+C+R us/site (last)", "ratio" });
  for(const Per_site& ps : per_site)
  {
    if(ps.first_count == 0 || ps.last_count == ps.first_count)
    {
      r.row({ ps.label, "", "", "", "n/a" });
      continue;
    }
    const double ratio = ps.last / ps.first;
    r.row({ ps.label, short_count(ps.last_count) + " vs " + short_count(ps.first_count), fixed(1e6 * ps.first, 2),
            fixed(1e6 * ps.last, 2), fixed(ratio, 2) });
    if(ps.first_count == 1000 && ps.last_count == 100000)
      measured.per_site_ratios.push_back({ ps.label, ratio });
  }
  print_peak("section 3");
}

// ---------------------------------------------------------------------------------------
// Targets

void print_targets(const Measured& m)
{
  std::cout << "\n## Targets\n";
  Table t("Stretch targets", { "target", "measured", "limit", "result" });
  auto verdict = [](double value, bool pass) { return std::isfinite(value) ? (pass ? "PASS" : "MISS") : "not measured"; };
  t.row({ "embedding d=10 on ~20k vertices" + (m.embedding_20k_mesh.empty() ? std::string() : " (" + m.embedding_20k_mesh + ")"),
          std::isfinite(m.embedding_20k) ? seconds(m.embedding_20k) + " s" : "-", "<= 0.15 s",
          verdict(m.embedding_20k, m.embedding_20k <= 0.15) });
  t.row({ "propagation+cutting+repair, 10k sites on ~20k vertices, biharmonic d=10"
            + (m.pcr_10k_mesh.empty() ? std::string() : " (" + m.pcr_10k_mesh + ")"),
          std::isfinite(m.pcr_10k) ? seconds(m.pcr_10k) + " s" : "-", "<= 0.1 s", verdict(m.pcr_10k, m.pcr_10k <= 0.1) });
  if(m.per_site_ratios.empty())
    t.row({ "time per site constant within 20% from 1k to 100k sites (needs section sites without --quick)", "-",
            "ratio in [0.8, 1.2]", "not measured" });
  for(const Ratio_measure& r : m.per_site_ratios)
    t.row({ "time per site (P+C+R) 100k vs 1k sites: " + r.label, "ratio " + fixed(r.ratio, 2), "ratio in [0.8, 1.2]",
            verdict(r.ratio, r.ratio >= 0.8 && r.ratio <= 1.2) });
}

int run(const Settings& s)
{
  const Clock::time_point start = Clock::now();
  std::cout << "# Surface_voronoi_diagram benchmark" << (s.quick ? " (--quick)" : "") << "\n\n";
  std::cout << "single-threaded; section: " << s.section << "; --max-vertices " << count(s.max_vertices) << "\n";
  {
    std::ifstream in("/proc/loadavg");
    double load1 = nan_value;
    if(in >> load1)
      std::cout << "load average at start: " << fixed(load1, 2) << " on " << ::sysconf(_SC_NPROCESSORS_ONLN)
                << " core(s) (timings are noisy when other jobs run)\n";
  }
  if(data_folder_usable(s))
    std::cout << "data folder: " << s.data_dir << "\n";
  else if(s.data_dir.empty())
    std::cout << "no data folder configured: using generated meshes\n";
  else
    std::cout << "data folder '" << s.data_dir << "' not found: using generated meshes\n";
  std::cout.flush();

  Named_mesh m20k;
  progress("preparing the ~20k-vertex mesh");
  get_mesh_20k(s, m20k);
  std::cout << "~20k-vertex mesh: " << m20k.name << " (" << count(nv(m20k.mesh)) << " vertices, " << count(nf(m20k.mesh))
            << " faces)" << std::endl;

  Measured measured;
  const bool all = (s.section == "all");
  if(all || s.section == "embedding") section_embedding(s, m20k, measured);
  if(all || s.section == "solvers") section_solvers(s, m20k);
  if(all || s.section == "sites") section_sites(s, m20k, measured);
  print_targets(measured);
  std::cout << "\nfinished in " << fixed(seconds_since(start), 1) << " s" << std::endl;
  return 0;
}

} // namespace

int main(int argc, char** argv)
{
  Settings settings;
  try
  {
    settings = parse_arguments(argc, argv);
  }
  catch(const Usage_error& e)
  {
    if(e.message.empty())
    {
      std::cout << usage_text;
      return 0;
    }
    std::cerr << program << ": error: " << e.message << std::endl;
    return 2;
  }
  try
  {
    return run(settings);
  }
  catch(const std::exception& e)
  {
    std::cerr << program << ": error: " << e.what() << std::endl;
    return 1;
  }
}
