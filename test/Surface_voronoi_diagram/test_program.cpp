// Copyright (c) 2026 The Surface_voronoi_diagram authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Black-box tests of the command-line program `surface_voronoi` (SVD_PROGRAM): its
// interface is a contract that outside checks rely on, so these tests only use what
// the contract states: arguments, exit codes, the number of lines on stderr, the
// numbers that error messages must cite, the layout of the output PLY, the sites file
// written by --sites-out and the keys printed by --stats.
//
// Every mesh is generated here and written as a small text (or binary PLY) file in a
// fresh temporary directory, so each run of the program takes well under a second.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh/IO/OFF.h>
#include <CGAL/Surface_mesh/IO/PLY.h>

#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <locale>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

// this file's own names: the suite compiles its files together (see CMakeLists.txt)
namespace svd_test_program {

namespace svd_program_test {
namespace {

namespace fs = std::filesystem;

typedef CGAL::Exact_predicates_inexact_constructions_kernel PK;
typedef PK::Point_3 PPoint;
typedef PK::Triangle_3 PTriangle;
typedef std::array<double, 3> V3;

// ---------------------------------------------------------------------------------------
// Small vector algebra on V3

V3 sub(const V3& a, const V3& b) { return {{ a[0] - b[0], a[1] - b[1], a[2] - b[2] }}; }
V3 add(const V3& a, const V3& b) { return {{ a[0] + b[0], a[1] + b[1], a[2] + b[2] }}; }
V3 scaled(const V3& a, double s) { return {{ a[0] * s, a[1] * s, a[2] * s }}; }
double dot(const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
V3 cross(const V3& a, const V3& b)
{
  return {{ a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] }};
}
double norm(const V3& a) { return std::sqrt(dot(a, a)); }
double distance(const V3& a, const V3& b) { return norm(sub(a, b)); }
PPoint to_point(const V3& a) { return PPoint(a[0], a[1], a[2]); }

// ---------------------------------------------------------------------------------------
// Polygon soups: the meshes handed to the program

struct Soup
{
  std::vector<V3> points;
  std::vector<std::vector<std::size_t>> faces;
};

// Renumbers the points in order of first use by the faces, so that every format
// (including STL, whose reader numbers points by first appearance) gives the same soup.
Soup renumbered_by_first_use(const Soup& s)
{
  const std::size_t unused = std::numeric_limits<std::size_t>::max();
  std::vector<std::size_t> index(s.points.size(), unused);
  Soup out;
  for(const std::vector<std::size_t>& f : s.faces)
  {
    std::vector<std::size_t> g;
    for(std::size_t v : f)
    {
      if(index[v] == unused)
      {
        index[v] = out.points.size();
        out.points.push_back(s.points[v]);
      }
      g.push_back(index[v]);
    }
    out.faces.push_back(g);
  }
  return out;
}

// An octahedron subdivided `levels` times, its points pushed onto a sphere:
// 6, 18, 66, 258 points for levels 0..3, and 8 * 4^levels triangles.
Soup octahedral_sphere(int levels, const V3& center = {{ 0, 0, 0 }}, double radius = 1)
{
  std::vector<V3> p = { {{ 1, 0, 0 }}, {{ -1, 0, 0 }}, {{ 0, 1, 0 }}, {{ 0, -1, 0 }}, {{ 0, 0, 1 }}, {{ 0, 0, -1 }} };
  std::vector<std::array<std::size_t, 3>> t = { {{ 0, 2, 4 }}, {{ 2, 1, 4 }}, {{ 1, 3, 4 }}, {{ 3, 0, 4 }},
                                                {{ 2, 0, 5 }}, {{ 1, 2, 5 }}, {{ 3, 1, 5 }}, {{ 0, 3, 5 }} };
  for(int level = 0; level < levels; ++level)
  {
    std::map<std::pair<std::size_t, std::size_t>, std::size_t> middle;
    auto mid = [&](std::size_t a, std::size_t b) {
      const std::pair<std::size_t, std::size_t> key(std::min(a, b), std::max(a, b));
      auto it = middle.find(key);
      if(it != middle.end())
        return it->second;
      p.push_back(scaled(add(p[a], p[b]), 0.5));
      middle[key] = p.size() - 1;
      return p.size() - 1;
    };
    std::vector<std::array<std::size_t, 3>> finer;
    for(const auto& f : t)
    {
      const std::size_t ab = mid(f[0], f[1]), bc = mid(f[1], f[2]), ca = mid(f[2], f[0]);
      finer.push_back({{ f[0], ab, ca }});
      finer.push_back({{ ab, f[1], bc }});
      finer.push_back({{ ca, bc, f[2] }});
      finer.push_back({{ ab, bc, ca }});
    }
    t.swap(finer);
  }
  Soup s;
  for(const V3& q : p)
    s.points.push_back(add(center, scaled(q, radius / norm(q))));
  for(const auto& f : t)
    s.faces.push_back({ f[0], f[1], f[2] });
  return renumbered_by_first_use(s);
}

// The closed cube [o, o + size]^3, made of 12 outward triangles or of 6 quads.
Soup cube(bool quads = false, const V3& o = {{ 0, 0, 0 }}, double size = 1)
{
  Soup s;
  for(int k = 0; k < 8; ++k)
  {
    const int x = (k == 1 || k == 2 || k == 5 || k == 6) ? 1 : 0;
    const int y = (k == 2 || k == 3 || k == 6 || k == 7) ? 1 : 0;
    const int z = k >= 4 ? 1 : 0;
    s.points.push_back({{ o[0] + size * x, o[1] + size * y, o[2] + size * z }});
  }
  if(quads)
    s.faces = { { 0, 3, 2, 1 }, { 4, 5, 6, 7 }, { 0, 1, 5, 4 }, { 1, 2, 6, 5 }, { 2, 3, 7, 6 }, { 3, 0, 4, 7 } };
  else
    s.faces = { { 0, 2, 1 }, { 0, 3, 2 }, { 4, 5, 6 }, { 4, 6, 7 }, { 0, 1, 5 }, { 0, 5, 4 },
                { 1, 2, 6 }, { 1, 6, 5 }, { 2, 3, 7 }, { 2, 7, 6 }, { 3, 0, 4 }, { 3, 4, 7 } };
  return s;
}

Soup tetrahedron(const V3& o, double size)
{
  Soup s;
  s.points = { o, add(o, {{ size, 0, 0 }}), add(o, {{ 0, size, 0 }}), add(o, {{ 0, 0, size }}) };
  s.faces = { { 0, 2, 1 }, { 0, 1, 3 }, { 0, 3, 2 }, { 1, 2, 3 } };
  return s;
}

// A torus around the z axis: nu segments around the axis, nv around the tube.
Soup torus_soup(double major, double minor, std::size_t nu, std::size_t nv)
{
  const double pi = std::acos(-1.);
  Soup s;
  for(std::size_t i = 0; i < nu; ++i)
    for(std::size_t j = 0; j < nv; ++j)
    {
      const double u = 2 * pi * double(i) / double(nu), v = 2 * pi * double(j) / double(nv);
      s.points.push_back({{ (major + minor * std::cos(v)) * std::cos(u), (major + minor * std::cos(v)) * std::sin(u), minor * std::sin(v) }});
    }
  auto at = [&](std::size_t i, std::size_t j) { return (i % nu) * nv + (j % nv); };
  for(std::size_t i = 0; i < nu; ++i)
    for(std::size_t j = 0; j < nv; ++j)
    {
      s.faces.push_back({ at(i, j), at(i + 1, j), at(i + 1, j + 1) });
      s.faces.push_back({ at(i, j), at(i + 1, j + 1), at(i, j + 1) });
    }
  return s;
}

Soup merged(const Soup& a, const Soup& b)
{
  Soup s = a;
  const std::size_t n = a.points.size();
  s.points.insert(s.points.end(), b.points.begin(), b.points.end());
  for(std::vector<std::size_t> f : b.faces)
  {
    for(std::size_t& v : f)
      v += n;
    s.faces.push_back(f);
  }
  return s;
}

// Area of a convex planar polygon, as a fan of triangles.
double polygon_area(const std::vector<V3>& p)
{
  double area = 0;
  for(std::size_t i = 1; i + 1 < p.size(); ++i)
    area += 0.5 * norm(cross(sub(p[i], p[0]), sub(p[i + 1], p[0])));
  return area;
}

std::vector<V3> corners(const Soup& s, std::size_t f)
{
  std::vector<V3> c;
  for(std::size_t v : s.faces[f])
    c.push_back(s.points[v]);
  return c;
}

double soup_area(const Soup& s)
{
  double area = 0;
  for(std::size_t f = 0; f < s.faces.size(); ++f)
    area += polygon_area(corners(s, f));
  return area;
}

double bbox_diagonal(const std::vector<V3>& points)
{
  V3 lo = points.front(), hi = points.front();
  for(const V3& p : points)
    for(int k = 0; k < 3; ++k)
    {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
  return distance(lo, hi);
}

V3 centroid(const std::vector<V3>& p)
{
  V3 c = {{ 0, 0, 0 }};
  for(const V3& q : p)
    c = add(c, q);
  return scaled(c, 1.0 / double(p.size()));
}

// Squared distance from q to a convex polygon, through its fan triangles.
double squared_distance_to_polygon(const V3& q, const std::vector<V3>& p)
{
  double best = std::numeric_limits<double>::infinity();
  const PPoint x = to_point(q);
  for(std::size_t i = 1; i + 1 < p.size(); ++i)
    best = std::min(best, CGAL::to_double(CGAL::squared_distance(
                            x, PTriangle(to_point(p[0]), to_point(p[i]), to_point(p[i + 1])))));
  return best;
}

double distance_to_soup(const V3& q, const Soup& s)
{
  double best = std::numeric_limits<double>::infinity();
  for(std::size_t f = 0; f < s.faces.size(); ++f)
    best = std::min(best, squared_distance_to_polygon(q, corners(s, f)));
  return std::sqrt(best);
}

// ---------------------------------------------------------------------------------------
// Writing mesh and sites files

std::string number_text(double v)
{
  std::ostringstream os;
  os.imbue(std::locale::classic());
  os.precision(17);
  os << v; // NaN and infinities come out as "nan", "inf", "-inf"
  return os.str();
}

std::string point_text(const V3& p)
{
  return number_text(p[0]) + " " + number_text(p[1]) + " " + number_text(p[2]);
}

void write_bytes(const fs::path& path, const std::string& bytes)
{
  std::ofstream os(path, std::ios::binary);
  os << bytes;
  os.close();
  REQUIRE(os.good());
}

std::string read_bytes(const fs::path& path)
{
  std::ifstream in(path, std::ios::binary);
  if(!in)
    return std::string();
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Byte comparisons of output files that describe, rather than print, binary content.
bool same_content(const std::string& x, const std::string& y, const std::string& what)
{
  if(x.empty() || y.empty())
  {
    UNSCOPED_INFO(what << ": " << (x.empty() ? "the first" : "the second") << " is empty or missing");
    return false;
  }
  if(x == y)
    return true;
  std::size_t k = 0;
  while(k < x.size() && k < y.size() && x[k] == y[k])
    ++k;
  UNSCOPED_INFO(what << " differ: sizes " << x.size() << " and " << y.size() << ", first difference at byte " << k);
  return false;
}

bool different_content(const std::string& x, const std::string& y, const std::string& what)
{
  if(x.empty() || y.empty())
  {
    UNSCOPED_INFO(what << ": " << (x.empty() ? "the first" : "the second") << " is empty or missing");
    return false;
  }
  if(x == y)
    UNSCOPED_INFO(what << " are identical");
  return x != y;
}

bool same_files(const fs::path& a, const fs::path& b)
{
  return same_content(read_bytes(a), read_bytes(b), a.filename().string() + " and " + b.filename().string());
}

bool different_files(const fs::path& a, const fs::path& b)
{
  return different_content(read_bytes(a), read_bytes(b), a.filename().string() + " and " + b.filename().string());
}

std::string off_text(const Soup& s)
{
  std::string t = "OFF\n" + std::to_string(s.points.size()) + " " + std::to_string(s.faces.size()) + " 0\n";
  for(const V3& p : s.points)
    t += point_text(p) + "\n";
  for(const auto& f : s.faces)
  {
    t += std::to_string(f.size());
    for(std::size_t v : f)
      t += " " + std::to_string(v);
    t += "\n";
  }
  return t;
}

std::string obj_text(const Soup& s)
{
  std::string t = "# written by test_program\n";
  for(const V3& p : s.points)
    t += "v " + point_text(p) + "\n";
  for(const auto& f : s.faces)
  {
    t += "f";
    for(std::size_t v : f)
      t += " " + std::to_string(v + 1);
    t += "\n";
  }
  return t;
}

std::string ply_ascii_text(const Soup& s)
{
  std::string t = "ply\nformat ascii 1.0\nelement vertex " + std::to_string(s.points.size()) +
                  "\nproperty double x\nproperty double y\nproperty double z\nelement face " +
                  std::to_string(s.faces.size()) + "\nproperty list uchar int vertex_indices\nend_header\n";
  for(const V3& p : s.points)
    t += point_text(p) + "\n";
  for(const auto& f : s.faces)
  {
    t += std::to_string(f.size());
    for(std::size_t v : f)
      t += " " + std::to_string(v);
    t += "\n";
  }
  return t;
}

std::string stl_ascii_text(const Soup& s)
{
  std::string t = "solid test\n";
  for(const auto& f : s.faces)
  {
    REQUIRE(f.size() == 3);
    const V3 n = cross(sub(s.points[f[1]], s.points[f[0]]), sub(s.points[f[2]], s.points[f[0]]));
    t += "facet normal " + point_text(scaled(n, 1 / norm(n))) + "\nouter loop\n";
    for(std::size_t v : f)
      t += "vertex " + point_text(s.points[v]) + "\n";
    t += "endloop\nendfacet\n";
  }
  return t + "endsolid test\n";
}

std::string ply_binary_bytes(const Soup& s)
{
  std::string t = "ply\nformat binary_little_endian 1.0\nelement vertex " + std::to_string(s.points.size()) +
                  "\nproperty double x\nproperty double y\nproperty double z\nelement face " +
                  std::to_string(s.faces.size()) + "\nproperty list uchar int vertex_indices\nend_header\n";
  auto put = [&t](const void* data, std::size_t size) {
    t.append(static_cast<const char*>(data), size); // the test machines are little-endian
  };
  for(const V3& p : s.points)
    put(p.data(), 3 * sizeof(double));
  for(const auto& f : s.faces)
  {
    const unsigned char n = static_cast<unsigned char>(f.size());
    put(&n, 1);
    for(std::size_t v : f)
    {
      const std::int32_t i = static_cast<std::int32_t>(v);
      put(&i, 4);
    }
  }
  return t;
}

// Writes the soup in the format of the path's extension.
void write_mesh(const fs::path& path, const Soup& s)
{
  const std::string ext = path.extension().string();
  if(ext == ".off")
    write_bytes(path, off_text(s));
  else if(ext == ".obj")
    write_bytes(path, obj_text(s));
  else if(ext == ".ply")
    write_bytes(path, ply_ascii_text(s));
  else if(ext == ".stl")
    write_bytes(path, stl_ascii_text(s));
  else
    FAIL("no writer for " << path);
}

void write_sites(const fs::path& path, const std::vector<V3>& sites)
{
  std::string t;
  for(const V3& p : sites)
    t += point_text(p) + "\n";
  write_bytes(path, t);
}

// Reads a file written by --sites-out, checking that it follows the sites-file format
// as the program writes it: one `x y z` line per site, nothing else.
std::vector<V3> read_sites_out(const fs::path& path)
{
  const std::string text = read_bytes(path);
  std::vector<V3> sites;
  std::istringstream in(text);
  std::string line;
  std::size_t number = 0, bad = 0;
  while(std::getline(in, line))
  {
    ++number;
    std::istringstream fields(line);
    std::vector<std::string> tokens;
    std::string token;
    while(fields >> token)
      tokens.push_back(token);
    V3 p = {{ 0, 0, 0 }};
    bool ok = tokens.size() == 3;
    for(std::size_t k = 0; ok && k < 3; ++k)
    {
      char* end = nullptr;
      p[k] = std::strtod(tokens[k].c_str(), &end);
      ok = end == tokens[k].c_str() + tokens[k].size() && std::isfinite(p[k]);
    }
    if(!ok)
    {
      ++bad;
      UNSCOPED_INFO("sites-out line " << number << " is not 'x y z': '" << line << "'");
    }
    sites.push_back(p);
  }
  CHECK(bad == 0);
  CHECK((text.empty() || text.back() == '\n'));
  return sites;
}

// One point inside each of a few triangles spread over the mesh: sites on the surface.
// By default at barycentric coordinates (0.47, 0.31, 0.22), which keeps the sites in
// general position; with `centroids`, at the centroids, where the symmetry of the
// octahedral sphere makes bisectors run exactly through mesh vertices.
std::vector<V3> face_sites(const Soup& s, std::size_t n, std::size_t step, bool centroids = false)
{
  std::vector<V3> sites;
  for(std::size_t i = 0; i < n; ++i)
  {
    const std::vector<V3> c = corners(s, (i * step) % s.faces.size());
    if(centroids)
      sites.push_back(centroid(c));
    else
      sites.push_back(add(add(scaled(c[0], 0.47), scaled(c[1], 0.31)), scaled(c[2], 0.22)));
  }
  return sites;
}

// ---------------------------------------------------------------------------------------
// Running the program

class Temp_dir
{
public:
  Temp_dir()
  {
    static int counter = 0;
    path_ = fs::temp_directory_path() /
            ("svd_program_test_" + std::to_string(::getpid()) + "_" + std::to_string(++counter));
    std::error_code ec;
    fs::remove_all(path_, ec);
    fs::create_directories(path_);
  }
  ~Temp_dir()
  {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  Temp_dir(const Temp_dir&) = delete;
  Temp_dir& operator=(const Temp_dir&) = delete;

  fs::path operator/(const std::string& name) const { return path_ / name; }
  const fs::path& path() const { return path_; }

private:
  fs::path path_;
};

struct Run
{
  std::string command;
  int code = -1; // the exit status, or -1 when the program did not exit normally
  std::string out, err;
};

std::string shell_quoted(const std::string& s)
{
  std::string q = "'";
  for(char c : s)
  {
    if(c == '\'')
      q += "'\\''";
    else
      q += c;
  }
  return q + "'";
}

// `environment`: assignments put before the command, such as "SVD_HUGE_PAGES=0"
Run run_program(const Temp_dir& dir, const std::vector<std::string>& args, const std::string& environment = std::string())
{
  static int counter = 0;
  ++counter;
  const fs::path out = dir / ("stdout_run_" + std::to_string(counter) + ".txt");
  const fs::path err = dir / ("stderr_run_" + std::to_string(counter) + ".txt");
  // outputs of an earlier run must not pass for outputs of this one
  for(std::size_t i = 0; i + 1 < args.size(); ++i)
    if((args[i] == "--output" || args[i] == "--sites-out") && fs::is_regular_file(args[i + 1]))
    {
      std::error_code ec;   // only files: a device such as /dev/full is an output under test
      fs::remove(args[i + 1], ec);
    }
  Run r;
  r.command = shell_quoted(SVD_PROGRAM);
  for(const std::string& a : args)
    r.command += " " + shell_quoted(a);
  const std::string full = (environment.empty() ? std::string() : environment + " ") + r.command + " <" +
                           shell_quoted("/dev/null") + " >" + shell_quoted(out.string()) + " 2>" + shell_quoted(err.string());
  const int status = std::system(full.c_str());
  if(status != -1 && WIFEXITED(status))
    r.code = WEXITSTATUS(status);
  r.out = read_bytes(out);
  r.err = read_bytes(err);
  return r;
}

std::size_t count_lines(const std::string& s)
{
  std::size_t n = static_cast<std::size_t>(std::count(s.begin(), s.end(), '\n'));
  if(!s.empty() && s.back() != '\n')
    ++n;
  return n;
}

std::string lower(std::string s)
{
  for(char& c : s)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// The numbers a message cites, once the paths of the temporary directory (whose name
// holds digits) are taken out.
std::vector<double> numbers_in(std::string text, const std::string& remove)
{
  for(std::size_t at = text.find(remove); !remove.empty() && at != std::string::npos; at = text.find(remove))
    text.erase(at, remove.size());
  std::vector<double> numbers;
  std::size_t i = 0;
  while(i < text.size())
  {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    const bool next_digit = i + 1 < text.size() && std::isdigit(static_cast<unsigned char>(text[i + 1]));
    if(std::isdigit(c) || ((c == '-' || c == '.') && next_digit))
    {
      char* end = nullptr;
      const double v = std::strtod(text.c_str() + i, &end);
      const std::size_t used = static_cast<std::size_t>(end - (text.c_str() + i));
      if(used == 0)
      {
        ++i;
        continue;
      }
      numbers.push_back(v);
      i += used;
    }
    else
      ++i;
  }
  return numbers;
}

// Whether the message on stderr cites `value` (to the 6 significant digits that a
// message may print).
bool cites(const Run& r, const Temp_dir& dir, double value)
{
  for(double x : numbers_in(r.err, dir.path().string()))
    if(std::abs(x - value) <= 5e-6 * std::max(1.0, std::abs(value)))
      return true;
  return false;
}

// A failed run: the expected exit code and exactly one non-empty line on stderr.
void check_one_line_error(const Run& r, int code)
{
  INFO("command: " << r.command << "\nstderr: " << r.err);
  CHECK(r.code == code);
  CHECK(count_lines(r.err) == 1);
  CHECK(r.err.find_first_not_of(" \t\r\n") != std::string::npos);
}

void check_success(const Run& r)
{
  INFO("command: " << r.command << "\nstderr: " << r.err);
  REQUIRE(r.code == 0);
}

std::map<std::string, std::string> parse_stats(const std::string& out)
{
  std::map<std::string, std::string> stats;
  std::istringstream in(out);
  std::string line;
  while(std::getline(in, line))
  {
    const std::size_t colon = line.find(": ");
    if(colon == std::string::npos)
      continue;
    stats[line.substr(0, colon)] = line.substr(colon + 2);
  }
  return stats;
}

// The value of a stats key, checked to be one finite number; NaN when absent or bad.
double stat_value(const std::map<std::string, std::string>& stats, const std::string& key)
{
  auto it = stats.find(key);
  INFO("stats key '" << key << "'");
  CHECK(it != stats.end());
  if(it == stats.end())
    return std::numeric_limits<double>::quiet_NaN();
  char* end = nullptr;
  const double v = std::strtod(it->second.c_str(), &end);
  const bool whole = !it->second.empty() && end == it->second.c_str() + it->second.size();
  INFO("value '" << it->second << "'");
  CHECK(whole);
  CHECK(std::isfinite(v));
  return whole ? v : std::numeric_limits<double>::quiet_NaN();
}

// ---------------------------------------------------------------------------------------
// The output PLY

struct Arrangement_ply
{
  std::vector<V3> vertices;
  std::vector<std::vector<std::size_t>> faces;
  std::vector<int> sites;
  std::vector<std::array<unsigned char, 4>> colors;
  std::vector<int> input_faces;
};

// Reads the binary PLY written by the program, checking its header line by line
// against the contract (comment lines aside) and that the body has exactly the
// announced size.
Arrangement_ply read_arrangement(const fs::path& path)
{
  const std::string bytes = read_bytes(path);
  INFO("PLY file " << path);
  REQUIRE(!bytes.empty());

  std::vector<std::string> lines; // the header without its comment lines
  std::size_t pos = 0;
  for(;;)
  {
    const std::size_t eol = bytes.find('\n', pos);
    REQUIRE(eol != std::string::npos);
    const std::string line = bytes.substr(pos, eol - pos);
    pos = eol + 1;
    if(line.compare(0, 8, "comment ") != 0 && line != "comment")
      lines.push_back(line);
    if(line == "end_header")
      break;
    REQUIRE(lines.size() < 64);
  }
  REQUIRE(lines.size() >= 7);
  const std::string vertex_prefix = "element vertex ", face_prefix = "element face ";
  REQUIRE(lines[2].compare(0, vertex_prefix.size(), vertex_prefix) == 0);
  REQUIRE(lines[6].compare(0, face_prefix.size(), face_prefix) == 0);
  const std::size_t nv = std::stoul(lines[2].substr(vertex_prefix.size()));
  const std::size_t nf = std::stoul(lines[6].substr(face_prefix.size()));
  const std::vector<std::string> expected = {
    "ply", "format binary_little_endian 1.0", "element vertex " + std::to_string(nv),
    "property double x", "property double y", "property double z",
    "element face " + std::to_string(nf), "property list uchar int vertex_indices", "property int site",
    "property uchar red", "property uchar green", "property uchar blue", "property uchar alpha",
    "property int input_face", "end_header"
  };
  REQUIRE(lines == expected);

  Arrangement_ply a;
  bool truncated = false;
  auto take = [&](void* data, std::size_t size) {
    if(pos + size > bytes.size())
    {
      truncated = true;
      std::memset(data, 0, size);
      return;
    }
    std::memcpy(data, bytes.data() + pos, size); // the test machines are little-endian
    pos += size;
  };
  a.vertices.resize(nv);
  for(V3& p : a.vertices)
    take(p.data(), 3 * sizeof(double));
  a.faces.resize(nf);
  a.sites.resize(nf);
  a.colors.resize(nf);
  a.input_faces.resize(nf);
  for(std::size_t f = 0; f < nf && !truncated; ++f)
  {
    unsigned char n = 0;
    take(&n, 1);
    for(unsigned char k = 0; k < n; ++k)
    {
      std::int32_t v = 0;
      take(&v, 4);
      a.faces[f].push_back(v < 0 ? std::numeric_limits<std::size_t>::max() : static_cast<std::size_t>(v));
    }
    std::int32_t site = 0;
    take(&site, 4);
    a.sites[f] = site;
    take(a.colors[f].data(), 4);
    std::int32_t input_face = 0;
    take(&input_face, 4);
    a.input_faces[f] = input_face;
  }
  REQUIRE(!truncated);
  CHECK(pos == bytes.size());
  return a;
}

// CGAL's own PLY reader must read the file back into a Surface_mesh with an
// int32 face property "f:site" equal to what the byte-level reader found.
void check_cgal_reads_back(const fs::path& path, const Arrangement_ply& a)
{
  typedef CGAL::Surface_mesh<PPoint> SM;
  SM sm;
  std::ifstream in(path, std::ios::binary);
  REQUIRE(in);
  REQUIRE(CGAL::IO::read_PLY(in, sm));
  REQUIRE(num_vertices(sm) == a.vertices.size());
  REQUIRE(num_faces(sm) == a.faces.size());
  auto site = sm.property_map<SM::Face_index, std::int32_t>("f:site");
  auto input_face = sm.property_map<SM::Face_index, std::int32_t>("f:input_face");
  REQUIRE(site.second);
  REQUIRE(input_face.second);
  std::size_t k = 0, site_mismatch = 0, input_face_mismatch = 0, point_mismatch = 0;
  for(SM::Face_index f : sm.faces())
  {
    if(site.first[f] != a.sites[k])
      ++site_mismatch;
    if(input_face.first[f] != a.input_faces[k])
      ++input_face_mismatch;
    ++k;
  }
  k = 0;
  for(SM::Vertex_index v : sm.vertices())
  {
    const PPoint& p = sm.point(v);
    const V3& q = a.vertices[k++];
    if(p.x() != q[0] || p.y() != q[1] || p.z() != q[2])
      ++point_mismatch;
  }
  CHECK(site_mismatch == 0);
  CHECK(input_face_mismatch == 0);
  CHECK(point_mismatch == 0);
}

std::vector<V3> face_points(const Arrangement_ply& a, std::size_t f)
{
  std::vector<V3> p;
  for(std::size_t v : a.faces[f])
    p.push_back(a.vertices[v]);
  return p;
}

struct Arrangement_summary
{
  double area = 0;
  std::map<int, double> area_per_site;
  std::set<int> labels;
};

// Checks the arrangement against the contract and the input soup:
//  - every face is a convex planar polygon with valid, distinct vertex indices;
//  - every face's site is -1 or in [0, n_sites);
//  - every face lies inside one input polygon (one input triangle for triangle meshes);
//  - the faces inside each input polygon cover exactly its area, so the total area
//    equals the mesh area (1e-9 relative).
Arrangement_summary check_arrangement(const Arrangement_ply& a, const Soup& input, std::size_t n_sites)
{
  const double input_area = soup_area(input);
  const double diag = bbox_diagonal(input.points);
  const double tol = 1e-9 * diag;

  // bounding boxes of the input polygons, widened by the tolerance
  std::vector<std::array<V3, 2>> boxes;
  for(std::size_t g = 0; g < input.faces.size(); ++g)
  {
    V3 lo = input.points[input.faces[g][0]], hi = lo;
    for(const V3& p : corners(input, g))
      for(int k = 0; k < 3; ++k)
      {
        lo[k] = std::min(lo[k], p[k] - tol);
        hi[k] = std::max(hi[k], p[k] + tol);
      }
    boxes.push_back({{ lo, hi }});
  }
  auto in_box = [&](const V3& p, std::size_t g) {
    for(int k = 0; k < 3; ++k)
      if(p[k] < boxes[g][0][k] || p[k] > boxes[g][1][k])
        return false;
    return true;
  };

  // one tally per kind of defect, with the first face showing it
  struct Tally
  {
    std::size_t count = 0;
    std::string first;
    void add(const std::string& element, std::size_t index, const std::string& what)
    {
      if(count++ == 0)
        first = element + " " + std::to_string(index) + ": " + what;
    }
  };
  Tally non_finite, bad_index, bad_site, degenerate, repeated_corner, non_planar, non_convex, outside, split_input_face;
  // each face of the program's mesh lies inside one input polygon: the pieces naming one
  // input_face lie in one (slivers narrower than the tolerance may sit on a shared side)
  std::map<int, std::size_t> host_of_input_face;
  for(std::size_t v = 0; v < a.vertices.size(); ++v)
  {
    const V3& p = a.vertices[v];
    if(!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      non_finite.add("vertex", v, "non-finite coordinate");
  }

  Arrangement_summary summary;
  std::vector<double> covered(input.faces.size(), 0.0);
  for(std::size_t f = 0; f < a.faces.size(); ++f)
  {
    const std::vector<std::size_t>& face = a.faces[f];
    std::vector<std::size_t> sorted = face;
    std::sort(sorted.begin(), sorted.end());
    if(face.size() < 3 || sorted.back() >= a.vertices.size() ||
       std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
    {
      bad_index.add("face", f, "bad vertex indices");
      continue;
    }
    const int site = a.sites[f];
    if(site < -1 || (site >= 0 && static_cast<std::size_t>(site) >= n_sites))
    {
      bad_site.add("face", f, "site " + std::to_string(site) + " out of range");
    }
    summary.labels.insert(site);

    const std::vector<V3> p = face_points(a, f);
    const double area = polygon_area(p);
    summary.area += area;
    summary.area_per_site[site] += area;

    // A polygon whose corners all lie on one line (exact predicate), or with two
    // consecutive corners at the same point, is not a proper convex polygon.
    bool repeated = false;
    for(std::size_t i = 0; i < p.size(); ++i)
      if(p[i] == p[(i + 1) % p.size()])
        repeated = true;
    bool collinear = true;
    {
      std::size_t k = 1;
      while(k < p.size() && p[k] == p[0])
        ++k;
      for(std::size_t j = k + 1; j < p.size() && collinear; ++j)
        if(!CGAL::collinear(to_point(p[0]), to_point(p[k]), to_point(p[j])))
          collinear = false;
    }
    if(repeated)
    {
      repeated_corner.add("face", f, "two consecutive corners at the same point");
    }
    if(collinear)
    {
      degenerate.add("face", f, "zero area: all corners on one line");
    }
    else
    {
      // normal from differences to the first corner: accurate for tiny faces too
      V3 n = {{ 0, 0, 0 }};
      for(std::size_t i = 1; i + 1 < p.size(); ++i)
        n = add(n, cross(sub(p[i], p[0]), sub(p[i + 1], p[0])));
      const double length = norm(n);
      if(length > 0)
      {
        n = scaled(n, 1 / length);
        for(const V3& q : p)
          if(std::abs(dot(sub(q, p[0]), n)) > tol)
          {
            non_planar.add("face", f, "not planar");
            break;
          }
        // a reflex corner farther than the tolerance from the line of its neighbours
        for(std::size_t i = 0; i < p.size(); ++i)
        {
          const V3& a = p[i];
          const V3& b = p[(i + 1) % p.size()];
          const V3& c = p[(i + 2) % p.size()];
          const double turn = dot(cross(sub(b, a), sub(c, b)), n);
          const double span = distance(a, c);
          if(turn < 0 && (span == 0 || -turn / span > tol))
          {
            non_convex.add("face", f, "not convex at corner " + std::to_string(i + 1));
            break;
          }
        }
      }
    }

    // the input polygon holding the face: one near the centroid holding every corner
    const V3 c = centroid(p);
    std::size_t host = input.faces.size();
    for(std::size_t g = 0; g < input.faces.size() && host == input.faces.size(); ++g)
    {
      if(!in_box(c, g))
        continue;
      const std::vector<V3> q = corners(input, g);
      if(squared_distance_to_polygon(c, q) > tol * tol)
        continue;
      bool all = true;
      for(const V3& x : p)
        if(squared_distance_to_polygon(x, q) > tol * tol)
        {
          all = false;
          break;
        }
      if(all)
        host = g;
    }
    if(host == input.faces.size())
    {
      outside.add("face", f, "inside no single input face");
    }
    else
    {
      covered[host] += area;
      double perimeter = 0;
      for(std::size_t i = 0; i < p.size(); ++i)
        perimeter += distance(p[i], p[(i + 1) % p.size()]);
      if(a.input_faces[f] < 0)
        split_input_face.add("face", f, "input_face " + std::to_string(a.input_faces[f]));
      else if(area > tol * perimeter)
      {
        const auto known = host_of_input_face.emplace(a.input_faces[f], host);
        if(known.first->second != host)
          split_input_face.add("face", f, "input_face " + std::to_string(a.input_faces[f]) + " lies in input polygons "
                               + std::to_string(known.first->second) + " and " + std::to_string(host));
      }
    }
  }

  double worst_cover = 0;
  std::size_t worst_face = 0;
  for(std::size_t g = 0; g < input.faces.size(); ++g)
  {
    const double d = std::abs(covered[g] - polygon_area(corners(input, g)));
    if(d > worst_cover)
    {
      worst_cover = d;
      worst_face = g;
    }
  }

  CHECK(!a.faces.empty());
  for(const auto& tally : { std::make_pair("non-finite vertices", &non_finite),
                            std::make_pair("faces with bad vertex indices", &bad_index),
                            std::make_pair("faces with a site out of range", &bad_site),
                            std::make_pair("zero-area faces", &degenerate),
                            std::make_pair("faces with a repeated corner", &repeated_corner),
                            std::make_pair("non-planar faces", &non_planar),
                            std::make_pair("non-convex faces", &non_convex),
                            std::make_pair("faces inside no single input face", &outside),
                            std::make_pair("faces naming a wrong input face", &split_input_face) })
  {
    INFO(tally.first << ": " << tally.second->count << ", first " << tally.second->first);
    CHECK(tally.second->count == 0);
  }
  {
    INFO("input face " << worst_face << " is covered up to " << worst_cover);
    CHECK(worst_cover <= 1e-9 * input_area);
  }
  INFO("arrangement area " << number_text(summary.area) << ", mesh area " << number_text(input_area));
  CHECK(std::abs(summary.area - input_area) <= 1e-9 * input_area);
  return summary;
}

// Full check of an output file: header and body, CGAL's reader, geometry.
Arrangement_summary check_output(const fs::path& ply, const Soup& input, std::size_t n_sites)
{
  const Arrangement_ply a = read_arrangement(ply);
  check_cgal_reads_back(ply, a);
  return check_arrangement(a, input, n_sites);
}

// Each site lies in a face of its own cell.
void check_sites_in_own_cells(const Arrangement_ply& a, const std::vector<V3>& sites, double tol)
{
  std::size_t homeless = 0;
  std::string first;
  for(std::size_t i = 0; i < sites.size(); ++i)
  {
    bool found = false;
    for(std::size_t f = 0; f < a.faces.size() && !found; ++f)
      if(a.sites[f] == static_cast<int>(i) && squared_distance_to_polygon(sites[i], face_points(a, f)) <= tol * tol)
        found = true;
    if(!found)
    {
      ++homeless;
      if(first.empty())
        first = "site " + std::to_string(i) + " at " + point_text(sites[i]);
    }
  }
  INFO("first site outside its own cell: " << first);
  CHECK(homeless == 0);
}

// `got` holds the `expected` points, in the same order, within `tol`.
void check_same_points(const std::vector<V3>& got, const std::vector<V3>& expected, double tol)
{
  REQUIRE(got.size() == expected.size());
  double worst = 0;
  std::size_t worst_index = 0;
  for(std::size_t i = 0; i < got.size(); ++i)
  {
    const double d = distance(got[i], expected[i]);
    if(d > worst)
    {
      worst = d;
      worst_index = i;
    }
  }
  INFO("site " << worst_index << " is " << worst << " from the expected point");
  CHECK(worst <= tol);
}

const std::vector<std::string> required_stats = { "sites", "cells", "pieces", "unreached_area", "load",
                                                  "embedding", "propagation", "cutting", "repair", "output", "end_to_end" };

} // namespace

// =======================================================================================
// Good runs

TEST_CASE("program: a good run per metric gives a valid arrangement covering the mesh", "[program]")
{
  Temp_dir dir;
  const Soup sphere = octahedral_sphere(3); // 258 vertices: enough for the biharmonic dimension 10
  const double diag = bbox_diagonal(sphere.points);
  write_mesh(dir / "sphere.off", sphere);
  const std::vector<V3> sites = face_sites(sphere, 12, 41);
  write_sites(dir / "sites.txt", sites);

  for(const std::string metric : { "biharmonic", "euclidean", "rvd", "geodesic" })
  {
    INFO("metric " << metric);
    const Run r = run_program(dir, { (dir / "sphere.off").string(), "--sites", (dir / "sites.txt").string(),
                                     "--metric", metric, "--output", (dir / "out.ply").string(),
                                     "--sites-out", (dir / "final.txt").string() });
    check_success(r);
    CHECK(r.err.empty());
    const Arrangement_ply a = read_arrangement(dir / "out.ply");
    check_cgal_reads_back(dir / "out.ply", a);
    const Arrangement_summary s = check_arrangement(a, sphere, sites.size());
    // 12 sites spread over a closed sphere: every site has a cell, no area is unreached
    CHECK(s.labels.count(-1) == 0);
    CHECK(s.labels.size() == sites.size());
    const std::vector<V3> final_sites = read_sites_out(dir / "final.txt");
    check_same_points(final_sites, sites, 1e-12 * diag);
    check_sites_in_own_cells(a, final_sites, 1e-9 * diag);

    if(metric == "rvd")
    {
      // the restricted Voronoi diagram: every piece is nearest (in space) to its own site
      std::size_t wrong = 0;
      for(std::size_t f = 0; f < a.faces.size(); ++f)
      {
        const V3 c = centroid(face_points(a, f));
        double nearest = std::numeric_limits<double>::infinity();
        for(const V3& q : final_sites)
          nearest = std::min(nearest, distance(c, q));
        const int site = a.sites[f];
        if(site < 0 || distance(c, final_sites[static_cast<std::size_t>(site)]) > nearest + 1e-9 * diag)
          ++wrong;
      }
      CHECK(wrong == 0);
    }
  }
}

TEST_CASE("program: the geodesic metric refines a coarse mesh, says so, and keeps the input surface", "[program]")
{
  Temp_dir dir;
  const Soup coarse = octahedral_sphere(1);   // 18 vertices for 30 sites
  const double diag = bbox_diagonal(coarse.points);
  write_mesh(dir / "coarse.off", coarse);
  const std::vector<V3> sites = face_sites(coarse, 30, 7);
  write_sites(dir / "sites.txt", sites);
  const Run refined = run_program(dir, { (dir / "coarse.off").string(), "--sites", (dir / "sites.txt").string(),
                                         "--metric", "geodesic", "--output", (dir / "refined.ply").string(), "--stats" });
  check_success(refined);
  CHECK(refined.err.find("refined") != std::string::npos);
  CHECK(std::count(refined.err.begin(), refined.err.end(), '\n') == 1);
  const Arrangement_ply a = read_arrangement(dir / "refined.ply");
  const Arrangement_summary s = check_arrangement(a, coarse, sites.size());   // the same surface, refined
  CHECK(s.labels.size() == sites.size());
  check_sites_in_own_cells(a, sites, 1e-9 * diag);
  CHECK(stat_value(parse_stats(refined.out), "insertion") > 0);

  const Run kept = run_program(dir, { (dir / "coarse.off").string(), "--sites", (dir / "sites.txt").string(),
                                      "--metric", "geodesic", "--no-refine", "--output", (dir / "kept.ply").string() });
  check_success(kept);
  CHECK(kept.err.empty());
  check_arrangement(read_arrangement(dir / "kept.ply"), coarse, sites.size());
}

TEST_CASE("program: sites in symmetric position (ties through mesh vertices) give proper faces", "[program]")
{
  // Sites at face centroids of the octahedral sphere: bisectors run exactly through
  // mesh vertices, the hard case for cutting. The output must still be made of
  // convex planar polygons (no zero-area face, no repeated corner) covering the mesh.
  Temp_dir dir;
  const Soup sphere = octahedral_sphere(3);
  write_mesh(dir / "sphere.off", sphere);
  write_sites(dir / "sites.txt", face_sites(sphere, 12, 41, true));
  for(const std::string metric : { "biharmonic", "euclidean", "rvd", "geodesic" })
    for(const bool insert : { false, true })
    {
      INFO("metric " << metric << (insert ? " with --insert-sites" : ""));
      std::vector<std::string> args = { (dir / "sphere.off").string(), "--sites", (dir / "sites.txt").string(),
                                        "--metric", metric, "--output", (dir / "out.ply").string() };
      if(insert)
        args.push_back("--insert-sites");
      check_success(run_program(dir, args));
      const Arrangement_summary s = check_output(dir / "out.ply", sphere, 12);
      CHECK(s.labels.size() == 12);
    }
}

TEST_CASE("program: biharmonic is the default metric and --dimension is honoured", "[program]")
{
  Temp_dir dir;
  const Soup sphere = octahedral_sphere(3);
  write_mesh(dir / "sphere.off", sphere);
  const std::string mesh = (dir / "sphere.off").string();

  const Run implicit_metric = run_program(dir, { mesh, "--random", "9", "--output", (dir / "default.ply").string() });
  const Run explicit_metric = run_program(
      dir, { mesh, "--random", "9", "--metric", "biharmonic", "--output", (dir / "biharmonic.ply").string() });
  const Run explicit_dimension = run_program(dir, { mesh, "--random", "9", "--metric", "biharmonic", "--dimension",
                                                    "10", "--output", (dir / "ten.ply").string() });
  const Run other_dimension = run_program(dir, { mesh, "--random", "9", "--dimension", "4", "--output",
                                                 (dir / "four.ply").string() });
  check_success(implicit_metric);
  check_success(explicit_metric);
  check_success(explicit_dimension);
  check_success(other_dimension);
  CHECK(same_files(dir / "default.ply", dir / "biharmonic.ply"));
  CHECK(same_files(dir / "default.ply", dir / "ten.ply"));
  check_output(dir / "four.ply", sphere, 9);
  // a 4-dimensional embedding is a different metric: the diagram changes
  CHECK(different_files(dir / "four.ply", dir / "default.ply"));
}

// --dimension auto is the full spectrum (Biharmonic_green_metric) whenever its columns fit in
// 2 GiB, as here: the same diagram as --dimension full, another than --dimension 24
// (biharmonic_dimension_for_sites(700), auto's choice when they do not fit). 10 resolves 300
// cells, and is warned about, once, naming what auto would take.
TEST_CASE("program: --dimension auto takes the full spectrum when it fits, and a dimension too small for the sites is warned about", "[program]")
{
  Temp_dir dir;
  const Soup sphere = octahedral_sphere(4);
  write_mesh(dir / "sphere.off", sphere);
  const std::string mesh = (dir / "sphere.off").string();

  const Run automatic = run_program(dir, { mesh, "--random", "700", "--dimension", "auto", "--output", (dir / "auto.ply").string() });
  const Run full = run_program(dir, { mesh, "--random", "700", "--dimension", "full", "--output", (dir / "full.ply").string() });
  const Run by_hand = run_program(dir, { mesh, "--random", "700", "--dimension", "24", "--output", (dir / "24.ply").string() });
  const Run too_small = run_program(dir, { mesh, "--random", "700", "--output", (dir / "10.ply").string() });
  const Run few_sites = run_program(dir, { mesh, "--random", "300", "--output", (dir / "300.ply").string() });
  check_success(automatic);
  check_success(full);
  check_success(by_hand);
  check_success(too_small);
  check_success(few_sites);
  check_output(dir / "full.ply", sphere, 700);
  CHECK(same_files(dir / "auto.ply", dir / "full.ply"));
  CHECK(different_files(dir / "auto.ply", dir / "24.ply"));
  CHECK(different_files(dir / "auto.ply", dir / "10.ply"));
  CHECK(automatic.err.find("warning") == std::string::npos);
  CHECK(full.err.find("warning") == std::string::npos);
  CHECK(by_hand.err.find("warning") == std::string::npos);
  CHECK(few_sites.err.find("warning") == std::string::npos);
  CHECK(too_small.err == "surface_voronoi: warning: an embedding of dimension 10 resolves about 300 cells, fewer than the 700 sites: "
                         "cells may come out in pieces (--dimension auto takes the full spectrum)\n");

  const Run other_metric = run_program(dir, { mesh, "--random", "9", "--metric", "euclidean", "--dimension", "auto" });
  CHECK(other_metric.code == 2);
  const Run other_metric_full = run_program(dir, { mesh, "--random", "9", "--metric", "geodesic", "--dimension", "full" });
  CHECK(other_metric_full.code == 2);
  const Run bad_word = run_program(dir, { mesh, "--random", "9", "--dimension", "automatic" });
  CHECK(bad_word.code == 2);
}

TEST_CASE("program: every mesh format reads the same surface, and polygons are triangulated", "[program]")
{
  Temp_dir dir;
  const Soup box = renumbered_by_first_use(cube(false));
  const std::vector<V3> sites = { {{ 0.2, 0.7, 1 }}, {{ 0.5, 0.5, 0 }}, {{ 0, 0.3, 0.6 }}, {{ 1, 0.25, 0.4 }} };
  write_sites(dir / "sites.txt", sites);
  std::vector<std::string> outputs;
  for(const std::string ext : { "off", "obj", "ply", "stl", "OFF" })
  {
    INFO("format " << ext);
    const fs::path mesh = dir / ("box." + ext);
    if(ext == "OFF")
      write_bytes(mesh, off_text(box)); // the extension is case-insensitive
    else
      write_mesh(mesh, box);
    const fs::path out = dir / ("out_" + ext + ".ply");
    const Run r = run_program(dir, { mesh.string(), "--sites", (dir / "sites.txt").string(), "--metric",
                                     "euclidean", "--output", out.string() });
    check_success(r);
    check_output(out, box, sites.size());
    outputs.push_back(read_bytes(out));
  }
  for(std::size_t k = 1; k < outputs.size(); ++k)
    CHECK(same_content(outputs[k], outputs[0], "outputs " + std::to_string(k) + " and 0"));

  // the same cube made of quads: triangulated, each piece inside one quad, area 6
  const Soup quads = cube(true);
  write_mesh(dir / "quads.off", quads);
  const Run r = run_program(dir, { (dir / "quads.off").string(), "--sites", (dir / "sites.txt").string(),
                                   "--metric", "euclidean", "--output", (dir / "quads.ply").string(), "--stats" });
  check_success(r);
  const Arrangement_summary s = check_output(dir / "quads.ply", quads, sites.size());
  CHECK(std::abs(s.area - 6.0) <= 1e-9 * 6.0);
  CHECK(s.labels == std::set<int>({ 0, 1, 2, 3 }));
  CHECK(stat_value(parse_stats(r.out), "sites") == 4);
}

TEST_CASE("program: --insert-sites gives a valid arrangement of the input mesh", "[program]")
{
  Temp_dir dir;
  const Soup sphere = octahedral_sphere(3);
  const double diag = bbox_diagonal(sphere.points);
  write_mesh(dir / "sphere.obj", sphere);
  const std::vector<V3> sites = face_sites(sphere, 10, 53);
  write_sites(dir / "sites.txt", sites);
  for(const std::string metric : { "biharmonic", "euclidean", "rvd", "geodesic" })
  {
    INFO("metric " << metric);
    const Run r = run_program(dir, { (dir / "sphere.obj").string(), "--sites", (dir / "sites.txt").string(),
                                     "--insert-sites", "--metric", metric, "--output", (dir / "out.ply").string(),
                                     "--sites-out", (dir / "final.txt").string(), "--stats" });
    check_success(r);
    CHECK(r.err.empty());
    const Arrangement_ply a = read_arrangement(dir / "out.ply");
    check_cgal_reads_back(dir / "out.ply", a);
    // the arrangement refines the input mesh, whatever was inserted into it
    const Arrangement_summary s = check_arrangement(a, sphere, sites.size());
    CHECK(s.labels.size() == sites.size());
    CHECK(s.labels.count(-1) == 0);
    const std::vector<V3> final_sites = read_sites_out(dir / "final.txt");
    check_same_points(final_sites, sites, 1e-12 * diag);
    check_sites_in_own_cells(a, final_sites, 1e-9 * diag);
    const auto stats = parse_stats(r.out);
    CHECK(stat_value(stats, "sites") == 10);
    CHECK(stat_value(stats, "unreached_area") == 0);
  }
  // random sites too
  const Run r = run_program(dir, { (dir / "sphere.obj").string(), "--random", "7", "--seed", "3", "--insert-sites",
                                   "--output", (dir / "random.ply").string() });
  check_success(r);
  CHECK(check_output(dir / "random.ply", sphere, 7).labels.size() == 7);
}

TEST_CASE("program: --stats prints every required key with a numeric value", "[program]")
{
  Temp_dir dir;
  const Soup sphere = octahedral_sphere(3);
  write_mesh(dir / "sphere.ply", sphere);
  for(const std::string metric : { "biharmonic", "euclidean", "rvd", "geodesic" })
  {
    INFO("metric " << metric);
    const Run r = run_program(dir, { (dir / "sphere.ply").string(), "--random", "15", "--metric", metric,
                                     "--stats", "--output", (dir / "out.ply").string() });
    check_success(r);
    INFO("stdout:\n" << r.out);
    const auto stats = parse_stats(r.out);
    for(const std::string& key : required_stats)
    {
      const double v = stat_value(stats, key);
      CHECK(v >= 0);
    }
    const Arrangement_summary s = check_output(dir / "out.ply", sphere, 15);
    CHECK(stat_value(stats, "sites") == 15);
    // cells: the sites that own some area; pieces: at least one per cell
    std::size_t owned = 0;
    for(int label : s.labels)
      if(label >= 0)
        ++owned;
    CHECK(stat_value(stats, "cells") == double(owned));
    CHECK(stat_value(stats, "pieces") >= stat_value(stats, "cells"));
    CHECK(stat_value(stats, "unreached_area") == 0);
    // every stats line is `key: value`
    std::istringstream in(r.out);
    std::string line;
    std::size_t malformed = 0;
    while(std::getline(in, line))
      if(line.find(": ") == std::string::npos || line.find(": ") == 0)
        ++malformed;
    CHECK(malformed == 0);
    CHECK(stat_value(stats, "lloyd") == 0);
  }
  // with --lloyd K: the seconds of the relaxation and the energy after each of the K + 1 diagrams
  const Run r = run_program(dir, { (dir / "sphere.ply").string(), "--random", "15", "--metric", "euclidean",
                                   "--lloyd", "2", "--stats" });
  check_success(r);
  const auto stats = parse_stats(r.out);
  CHECK(stat_value(stats, "lloyd") > 0);
  CHECK(stat_value(stats, "lloyd_energy_2") >= 0);
  CHECK(stat_value(stats, "lloyd_energy_2") <= stat_value(stats, "lloyd_energy_0"));
  // and the seconds of each of the K steps, which the relaxation's time holds
  CHECK(stat_value(stats, "lloyd_step_1") > 0);
  CHECK(stat_value(stats, "lloyd_step_2") > 0);
  CHECK(stat_value(stats, "lloyd_step_1") + stat_value(stats, "lloyd_step_2") <= stat_value(stats, "lloyd"));
  CHECK(stats.count("lloyd_step_3") == 0);
}

TEST_CASE("program: --valid-dual appends sites until the dual is valid, the given sites first and unmoved", "[program][dual]")
{
  Temp_dir dir;
  write_mesh(dir / "torus.off", torus_soup(1.0, 0.4, 90, 36));
  // three sites around the torus: three rings, whose dual is no mesh at all
  write_sites(dir / "sites.txt", { {{ 1.4, 0, 0 }}, {{ -0.7, 1.2124355652982142, 0 }}, {{ -0.7, -1.2124355652982142, 0 }} });
  const std::string mesh = (dir / "torus.off").string(), sites = (dir / "sites.txt").string();
  const Run plain = run_program(dir, { mesh, "--sites", sites, "--metric", "euclidean", "--dual", (dir / "plain.off").string(),
                                       "--sites-out", (dir / "plain_sites.txt").string(), "--stats" });
  check_success(plain);
  CHECK(stat_value(parse_stats(plain.out), "dual_valid") == 0);
  CHECK(plain.err.find("not a valid mesh") != std::string::npos);

  const Run valid = run_program(dir, { mesh, "--sites", sites, "--metric", "euclidean", "--dual", (dir / "valid.off").string(),
                                       "--valid-dual", "--sites-out", (dir / "valid_sites.txt").string(),
                                       "--output", (dir / "valid.ply").string(), "--stats" });
  check_success(valid);
  INFO(valid.err);
  const auto stats = parse_stats(valid.out);
  CHECK(stat_value(stats, "dual_valid") == 1);
  CHECK(stat_value(stats, "dual_genus") == 1);
  const double added = stat_value(stats, "sites_added");
  CHECK(added > 0);
  CHECK(stat_value(stats, "sites") == 3 + added);
  CHECK(valid.err.find("not a valid mesh") == std::string::npos);
  // the given sites first, where they were; the added ones after them
  const std::vector<V3> before = read_sites_out(dir / "plain_sites.txt"), after = read_sites_out(dir / "valid_sites.txt");
  REQUIRE(after.size() == 3 + std::size_t(added));
  for(std::size_t i = 0; i < 3; ++i) CHECK(after[i] == before[i]);
  // the final sites read back give the same dual, byte for byte, and it is valid
  const Run again = run_program(dir, { mesh, "--sites", (dir / "valid_sites.txt").string(), "--metric", "euclidean",
                                       "--dual", (dir / "again.off").string(), "--stats" });
  check_success(again);
  CHECK(stat_value(parse_stats(again.out), "dual_valid") == 1);
  CHECK(same_files(dir / "valid.off", dir / "again.off"));
}

TEST_CASE("program: --valid-dual that reaches no valid dual exits 1 with one line and writes nothing", "[program][dual]")
{
  // two spheres, every site on the first: the second is reached by no site, so no dual of
  // these sites has the input's two components, and no site added inside a cell changes that
  Temp_dir dir;
  write_mesh(dir / "two.off", merged(octahedral_sphere(4), octahedral_sphere(3, {{ 4, 0, 0 }})));
  std::vector<V3> sites;
  const double golden = std::acos(-1.) * (3. - std::sqrt(5.));
  for(int k = 0; k < 40; ++k)
  {
    const double z = 1. - 2. * (k + 0.5) / 40., r = std::sqrt(1. - z * z);
    sites.push_back({{ r * std::cos(golden * k), r * std::sin(golden * k), z }});
  }
  write_sites(dir / "sites.txt", sites);
  const std::string out = (dir / "out.ply").string(), dual = (dir / "dual.off").string(), sites_out = (dir / "final.txt").string();
  const Run r = run_program(dir, { (dir / "two.off").string(), "--sites", (dir / "sites.txt").string(), "--metric", "euclidean",
                                   "--dual", dual, "--valid-dual", "--output", out, "--sites-out", sites_out });
  check_one_line_error(r, 1);
  CHECK(r.err.find("no valid dual reached") != std::string::npos);
  CHECK(r.err.find("components") != std::string::npos);
  CHECK(r.err.find("too few for the surface's topology") != std::string::npos);
  CHECK(!fs::exists(out));
  CHECK(!fs::exists(dual));
  CHECK(!fs::exists(sites_out));
}

TEST_CASE("program: --sites-out round trip reproduces the diagram byte for byte", "[program]")
{
  Temp_dir dir;
  const Soup sphere = octahedral_sphere(3);
  write_mesh(dir / "sphere.off", sphere);
  const std::string mesh = (dir / "sphere.off").string();
  for(const std::string metric : { "biharmonic", "euclidean", "rvd", "geodesic" })
  {
    INFO("metric " << metric);
    const Run first = run_program(dir, { mesh, "--random", "20", "--seed", "5", "--metric", metric, "--output",
                                         (dir / "first.ply").string(), "--sites-out", (dir / "sites.txt").string() });
    check_success(first);
    const Run second = run_program(dir, { mesh, "--sites", (dir / "sites.txt").string(), "--metric", metric,
                                          "--output", (dir / "second.ply").string(), "--sites-out",
                                          (dir / "sites_again.txt").string() });
    check_success(second);
    CHECK(read_sites_out(dir / "sites.txt").size() == 20);
    // what the contract promises: the same diagram, identical PLY bytes
    CHECK(same_files(dir / "first.ply", dir / "second.ply"));
    CHECK(same_files(dir / "sites.txt", dir / "sites_again.txt"));
    // and, to tell how far apart they are when they differ: the same faces and
    // labels, and vertices at most a rounding error apart
    const Arrangement_ply a = read_arrangement(dir / "first.ply"), b = read_arrangement(dir / "second.ply");
    const bool same_faces = a.faces == b.faces, same_labels = a.sites == b.sites;
    CHECK(same_faces);
    CHECK(same_labels);
    REQUIRE(a.vertices.size() == b.vertices.size());
    double moved = 0;
    for(std::size_t v = 0; v < a.vertices.size(); ++v)
      moved = std::max(moved, distance(a.vertices[v], b.vertices[v]));
    INFO("largest vertex displacement " << moved);
    CHECK(moved <= 1e-12);
  }
}

TEST_CASE("program: random, blue-noise and relaxed sites round-trip on a thin wall, without the AABB tree", "[program]")
{
  // Drawn and relaxed sites are made canonical by a search around their own face, and a
  // sites file's points by an AABB tree's nearest face followed by the same search: both
  // must reach the same locations. Two spheres 0.2% of their radius apart (a thin wall),
  // thousands of sites (many of them near edges and vertices, where ties happen).
  Temp_dir dir;
  write_mesh(dir / "wall.off", merged(octahedral_sphere(4), octahedral_sphere(4, {{ 0, 0, 0 }}, 0.998)));
  const std::string mesh = (dir / "wall.off").string();
  const std::vector<std::vector<std::string> > drawings = {
    { "--random", "3000", "--seed", "7", "--metric", "euclidean" },
    { "--blue-noise", "1500", "--seed", "8", "--metric", "rvd" },
    { "--random", "400", "--seed", "9", "--metric", "euclidean", "--lloyd", "3" },
    { "--random", "200", "--seed", "10", "--metric", "geodesic", "--lloyd", "2" } };
  for(const std::vector<std::string>& drawing : drawings)
  {
    INFO(drawing[0] << " " << drawing[1] << " " << drawing.back());
    std::vector<std::string> args = { mesh };
    args.insert(args.end(), drawing.begin(), drawing.end());
    args.insert(args.end(), { "--output", (dir / "first.ply").string(), "--sites-out", (dir / "sites.txt").string() });
    check_success(run_program(dir, args));
    const Run second = run_program(dir, { mesh, "--sites", (dir / "sites.txt").string(), "--metric", drawing[5],
                                          "--output", (dir / "second.ply").string(), "--sites-out",
                                          (dir / "sites_again.txt").string() });
    check_success(second);
    CHECK(same_files(dir / "first.ply", dir / "second.ply"));
    CHECK(same_files(dir / "sites.txt", dir / "sites_again.txt"));
  }
}

TEST_CASE("program: --sites-out keeps the power weights, so a weighted run round-trips", "[program]")
{
  Temp_dir dir;
  const Soup sphere = octahedral_sphere(3);
  write_mesh(dir / "sphere.off", sphere);
  const std::string mesh = (dir / "sphere.off").string();
  // weighted sites: every third of 24 sites gets a weight, one of them negative
  const std::vector<V3> sites = face_sites(sphere, 24, 7);
  std::string text;
  for(std::size_t i = 0; i < sites.size(); ++i)
    text += point_text(sites[i]) + (i % 3 == 0 ? (i == 3 ? " -0.0125" : " 0.03") : " 0") + "\n";
  write_bytes(dir / "weighted.txt", text);
  for(const std::string metric : { "euclidean", "biharmonic" })
  {
    INFO("metric " << metric);
    const Run first = run_program(dir, { mesh, "--sites", (dir / "weighted.txt").string(), "--metric", metric,
                                         "--output", (dir / "first.ply").string(), "--sites-out",
                                         (dir / "out.txt").string() });
    check_success(first);
    const Run plain = run_program(dir, { mesh, "--sites", (dir / "weighted.txt").string(), "--metric", metric,
                                         "--output", (dir / "plain.ply").string() });
    const Run second = run_program(dir, { mesh, "--sites", (dir / "out.txt").string(), "--metric", metric,
                                          "--output", (dir / "second.ply").string() });
    check_success(second);
    CHECK(same_files(dir / "first.ply", dir / "second.ply"));
    // every line carries its weight, and the weights are the ones given
    std::istringstream in(read_bytes(dir / "out.txt"));
    std::string line;
    std::size_t i = 0, weighted = 0;
    while(std::getline(in, line))
    {
      std::istringstream fields(line);
      std::vector<double> values;
      double v;
      while(fields >> v) values.push_back(v);
      REQUIRE(values.size() == 4);
      CHECK(values[3] == (i % 3 == 0 ? (i == 3 ? -0.0125 : 0.03) : 0.));
      weighted += values[3] != 0;
      ++i;
    }
    CHECK(i == sites.size());
    CHECK(weighted == 8);
  }
  // without weights the file keeps three columns (the unweighted round trip is tested above)
  const Run unweighted = run_program(dir, { mesh, "--random", "12", "--sites-out", (dir / "three.txt").string() });
  check_success(unweighted);
  CHECK(read_sites_out(dir / "three.txt").size() == 12);
}

TEST_CASE("program: a write that fails is exit 4 with one line, and leaves no file", "[program]")
{
  Temp_dir dir;
  const Soup sphere = octahedral_sphere(2);
  write_mesh(dir / "sphere.off", sphere);
  const std::string mesh = (dir / "sphere.off").string();
  for(const std::string flag : { "--output", "--sites-out", "--dual" })
  {
    INFO(flag);
    // a device that refuses data: the failure shows only when the stream is flushed
    const Run full = run_program(dir, { mesh, "--random", "30", flag, "/dev/full" });
    CHECK(full.code == 4);
    CHECK(count_lines(full.err) == 1);
    CHECK(full.err.find("/dev/full") != std::string::npos);
    // a folder that does not exist, and a folder given as the file
    const Run missing = run_program(dir, { mesh, "--random", "30", flag, (dir / "no" / "x.out").string() });
    CHECK(missing.code == 4);
    CHECK(count_lines(missing.err) == 1);
    const Run folder = run_program(dir, { mesh, "--random", "30", flag, dir.path().string() });
    CHECK(folder.code == 4);
    CHECK(folder.err.find("is a directory") != std::string::npos);
  }
  // an existing file is replaced whole on success, keeping its permissions (run_program
  // removes the files of --output and --sites-out before a run, not that of --dual)
  write_bytes(dir / "old.off", std::string(1 << 20, 'x'));
  fs::permissions(dir / "old.off", fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  const Run replaced = run_program(dir, { mesh, "--random", "30", "--dual", (dir / "old.off").string() });
  check_success(replaced);
  CHECK(read_bytes(dir / "old.off").find("xxxx") == std::string::npos);
  CHECK(fs::status(dir / "old.off").permissions() == (fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read));
  // nothing but the files written on purpose is in the folder: no temporary left behind
  for(const auto& entry : fs::directory_iterator(dir.path()))
    CHECK(entry.path().filename().string().find(".partial-") == std::string::npos);
}

TEST_CASE("program: the same command twice gives byte-identical output", "[program]")
{
  Temp_dir dir;
  const Soup sphere = octahedral_sphere(3);
  write_mesh(dir / "sphere.off", sphere);
  for(const std::string metric : { "biharmonic", "euclidean", "rvd", "geodesic" })
  {
    INFO("metric " << metric);
    std::vector<std::string> plys, sites, stats;
    for(int k = 0; k < 2; ++k)
    {
      const std::string tag = std::string(k == 0 ? "a" : "b");
      const Run r = run_program(dir, { (dir / "sphere.off").string(), "--random", "25", "--metric", metric,
                                       "--output", (dir / (tag + ".ply")).string(), "--sites-out",
                                       (dir / (tag + ".txt")).string(), "--stats" });
      check_success(r);
      plys.push_back(read_bytes(dir / (tag + ".ply")));
      sites.push_back(read_bytes(dir / (tag + ".txt")));
      // the counts (not the timings) must agree too
      const auto s = parse_stats(r.out);
      stats.push_back(s.count("cells") ? s.at("cells") + "/" + s.at("pieces") : std::string("missing"));
    }
    CHECK(same_content(plys[0], plys[1], "the two PLY files"));
    CHECK(sites[0] == sites[1]);
    CHECK(stats[0] == stats[1]);
  }
}

TEST_CASE("program: --threads 1 (sequential) and --threads 2 give byte-identical output", "[program][parallel]")
{
  // A mesh of several of the parallel loops' chunks (8192 faces each), with every metric; two
  // Lloyd steps, the second of which starts from the first's diagram.
  Temp_dir dir;
  write_mesh(dir / "sphere.off", octahedral_sphere(6));
  for(const std::string metric : { "biharmonic", "euclidean", "geodesic" })
  {
    INFO("metric " << metric);
    std::vector<std::string> plys, duals;
    for(const std::string threads : { "1", "2" })
    {
      const Run r = run_program(dir, { (dir / "sphere.off").string(), "--random", "700", "--metric", metric,
                                       "--lloyd", "2", "--threads", threads, "--output", (dir / (threads + ".ply")).string(),
                                       "--dual", (dir / (threads + ".off")).string() });
      check_success(r);
      plys.push_back(read_bytes(dir / (threads + ".ply")));
      duals.push_back(read_bytes(dir / (threads + ".off")));
    }
    CHECK(same_content(plys[0], plys[1], "the two PLY files"));
    CHECK(duals[0] == duals[1]);
  }
}

TEST_CASE("program: --random is reproducible for a seed and changes with the seed", "[program]")
{
  Temp_dir dir;
  const Soup sphere = octahedral_sphere(3);
  const double diag = bbox_diagonal(sphere.points);
  write_mesh(dir / "sphere.off", sphere);
  auto run_seed = [&](const std::string& name, const std::vector<std::string>& seed) {
    std::vector<std::string> args = { (dir / "sphere.off").string(), "--random", "12", "--metric", "euclidean",
                                      "--output", (dir / (name + ".ply")).string(), "--sites-out",
                                      (dir / (name + ".txt")).string() };
    args.insert(args.end(), seed.begin(), seed.end());
    check_success(run_program(dir, args));
  };
  run_seed("default", {});
  run_seed("zero", { "--seed", "0" });
  run_seed("one", { "--seed", "1" });
  run_seed("one_again", { "--seed", "1" });
  run_seed("two", { "--seed", "2" });

  CHECK(same_files(dir / "default.ply", dir / "zero.ply")); // S = 0 by default
  CHECK(same_files(dir / "default.txt", dir / "zero.txt"));
  CHECK(same_files(dir / "one.ply", dir / "one_again.ply"));
  CHECK(same_files(dir / "one.txt", dir / "one_again.txt"));
  CHECK(different_files(dir / "one.ply", dir / "two.ply"));
  CHECK(different_files(dir / "one.ply", dir / "zero.ply"));

  // the drawn sites: N of them, distinct, on the surface
  for(const std::string name : { "zero", "one", "two" })
  {
    INFO("seed file " << name);
    const std::vector<V3> s = read_sites_out(dir / (name + ".txt"));
    CHECK(s.size() == 12);
    double farthest = 0;
    for(const V3& p : s)
      farthest = std::max(farthest, distance_to_soup(p, sphere));
    CHECK(farthest <= 1e-9 * diag);
    check_output(dir / (name + ".ply"), sphere, 12);
  }
  const std::vector<V3> one = read_sites_out(dir / "one.txt"), two = read_sites_out(dir / "two.txt");
  CHECK(one != two);
}

TEST_CASE("program: --random draws area-uniform points", "[program]")
{
  // A small sphere of 512 triangles next to a big tetrahedron of 4 triangles with about
  // the same area: area-uniform sampling puts about half the sites on the tetrahedron,
  // whereas picking faces uniformly would put less than 1% there.
  Temp_dir dir;
  const Soup sphere = octahedral_sphere(3);
  const Soup tetra = tetrahedron({{ 3, 0, 0 }}, 2.3);
  const Soup both = merged(sphere, tetra);
  write_mesh(dir / "both.off", both);
  const double fraction = soup_area(tetra) / soup_area(both);
  REQUIRE(fraction > 0.4);
  REQUIRE(fraction < 0.6);
  const std::size_t n = 400;
  const Run r = run_program(dir, { (dir / "both.off").string(), "--random", std::to_string(n), "--seed", "11",
                                   "--metric", "euclidean", "--sites-out", (dir / "sites.txt").string() });
  check_success(r);
  const std::vector<V3> sites = read_sites_out(dir / "sites.txt");
  REQUIRE(sites.size() == n);
  std::size_t on_tetra = 0;
  double farthest = 0;
  for(const V3& p : sites)
  {
    if(p[0] > 2)
      ++on_tetra;
    farthest = std::max(farthest, distance_to_soup(p, both));
  }
  CHECK(farthest <= 1e-9 * bbox_diagonal(both.points));
  // binomial: mean n * fraction (about 200), standard deviation about 10
  INFO("sites on the tetrahedron: " << on_tetra << ", expected about " << double(n) * fraction);
  CHECK(std::abs(double(on_tetra) - double(n) * fraction) <= 50);
}

TEST_CASE("program: a component without sites is labelled -1 with one warning line", "[program]")
{
  Temp_dir dir;
  const Soup sphere = octahedral_sphere(3);
  const Soup tetra = tetrahedron({{ 3, 0, 0 }}, 1);
  const Soup both = merged(sphere, tetra);
  const double tetra_area = soup_area(tetra);
  write_mesh(dir / "both.off", both);
  const std::vector<V3> sites = face_sites(sphere, 8, 67); // all on the sphere
  write_sites(dir / "sites.txt", sites);
  for(const std::string metric : { "biharmonic", "euclidean" })
  {
    INFO("metric " << metric);
    const Run r = run_program(dir, { (dir / "both.off").string(), "--sites", (dir / "sites.txt").string(),
                                     "--metric", metric, "--output", (dir / "out.ply").string(), "--stats" });
    INFO("stderr: " << r.err);
    REQUIRE(r.code == 0);
    CHECK(count_lines(r.err) == 1);
    CHECK(lower(r.err).find("warning") != std::string::npos);
    const Arrangement_ply a = read_arrangement(dir / "out.ply");
    check_cgal_reads_back(dir / "out.ply", a);
    const Arrangement_summary s = check_arrangement(a, both, sites.size());
    // the unreached faces are exactly the tetrahedron
    const double unlabelled = s.area_per_site.count(-1) ? s.area_per_site.at(-1) : 0.0;
    CHECK(std::abs(unlabelled - tetra_area) <= 1e-9 * tetra_area);
    std::size_t wrong = 0;
    for(std::size_t f = 0; f < a.faces.size(); ++f)
    {
      const bool on_tetra = centroid(face_points(a, f))[0] > 2;
      if(on_tetra != (a.sites[f] == -1))
        ++wrong;
    }
    CHECK(wrong == 0);
    CHECK(s.labels.size() == sites.size() + 1);
    const double unreached = stat_value(parse_stats(r.out), "unreached_area");
    CHECK(std::abs(unreached - tetra_area) <= 1e-5 * tetra_area);
  }
}

// =======================================================================================
// Bad command lines: exit 2, one line

TEST_CASE("program: command-line errors exit 2 with one line on stderr", "[program]")
{
  Temp_dir dir;
  write_mesh(dir / "sphere.off", octahedral_sphere(3));
  write_sites(dir / "sites.txt", { {{ 1, 0, 0 }}, {{ 0, 1, 0 }} });
  const std::string mesh = (dir / "sphere.off").string(), sites = (dir / "sites.txt").string();
  const std::string out = (dir / "out.ply").string();

  SECTION("neither --sites nor --random")
  {
    const Run r = run_program(dir, { mesh, "--output", out });
    check_one_line_error(r, 2);
    CHECK(!fs::exists(out));
  }
  SECTION("--valid-dual without --dual")
  {
    const Run r = run_program(dir, { mesh, "--sites", sites, "--valid-dual", "--output", out });
    check_one_line_error(r, 2);
    CHECK(!fs::exists(out));
  }
  SECTION("both --sites and --random")
  {
    const Run r = run_program(dir, { mesh, "--sites", sites, "--random", "4", "--output", out });
    check_one_line_error(r, 2);
    CHECK(!fs::exists(out));
  }
  SECTION("--dimension with the euclidean metric")
  {
    check_one_line_error(run_program(dir, { mesh, "--random", "4", "--metric", "euclidean", "--dimension", "5" }), 2);
  }
  SECTION("--dimension with the rvd metric")
  {
    check_one_line_error(run_program(dir, { mesh, "--random", "4", "--dimension", "5", "--metric", "rvd" }), 2);
  }
  SECTION("--threads 0, or not a number")
  {
    check_one_line_error(run_program(dir, { mesh, "--random", "4", "--threads", "0" }), 2);
    check_one_line_error(run_program(dir, { mesh, "--random", "4", "--threads", "two" }), 2);
  }
  SECTION("unknown metric, named in the message")
  {
    const Run r = run_program(dir, { mesh, "--random", "4", "--metric", "geodesicx" });
    check_one_line_error(r, 2);
    CHECK(r.err.find("geodesicx") != std::string::npos);
  }
  SECTION("unknown flag, named in the message")
  {
    const Run r = run_program(dir, { mesh, "--random", "4", "--frobnicate" });
    check_one_line_error(r, 2);
    CHECK(r.err.find("--frobnicate") != std::string::npos);
  }
  SECTION("no mesh")
  {
    check_one_line_error(run_program(dir, { "--random", "4" }), 2);
  }
  SECTION("a flag without its value")
  {
    check_one_line_error(run_program(dir, { mesh, "--random" }), 2);
  }
  SECTION("--random with a count that is not a positive integer")
  {
    check_one_line_error(run_program(dir, { mesh, "--random", "abc" }), 2);
    check_one_line_error(run_program(dir, { mesh, "--random", "0" }), 2);
  }
}

TEST_CASE("program: a file that cannot be written exits 4 with one line", "[program]")
{
  Temp_dir dir;
  write_mesh(dir / "box.off", cube());
  const std::string mesh = (dir / "box.off").string();
  const std::string nowhere = (dir / "no_such_folder" / "x").string();
  check_one_line_error(
      run_program(dir, { mesh, "--random", "3", "--metric", "euclidean", "--output", nowhere + ".ply" }), 4);
  check_one_line_error(
      run_program(dir, { mesh, "--random", "3", "--metric", "euclidean", "--sites-out", nowhere + ".txt" }), 4);
}

// =======================================================================================
// Bad meshes: exit 1, one line naming the element

TEST_CASE("program: a missing mesh file is an error naming the file", "[program]")
{
  Temp_dir dir;
  const Run r = run_program(dir, { (dir / "absent.off").string(), "--random", "3" });
  check_one_line_error(r, 1);
  CHECK(r.err.find("absent.off") != std::string::npos);
}

TEST_CASE("program: an unknown mesh extension is an error naming it", "[program]")
{
  Temp_dir dir;
  write_bytes(dir / "box.xyz", off_text(cube())); // valid OFF content, unsupported extension
  const Run r = run_program(dir, { (dir / "box.xyz").string(), "--random", "3", "--metric", "euclidean" });
  INFO("stderr: " << r.err);
  // the contract does not say whether this is bad input (1) or a bad command line (2)
  CHECK((r.code == 1 || r.code == 2));
  CHECK(count_lines(r.err) == 1);
  CHECK(r.err.find("xyz") != std::string::npos);
}

TEST_CASE("program: an empty mesh is an error", "[program]")
{
  Temp_dir dir;
  SECTION("no vertices, no faces")
  {
    write_bytes(dir / "empty.off", "OFF\n0 0 0\n");
  }
  SECTION("vertices but no faces")
  {
    write_bytes(dir / "empty.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n");
  }
  const Run r = run_program(dir, { (dir / "empty.off").string(), "--random", "3", "--metric", "euclidean" });
  check_one_line_error(r, 1);
  const std::string message = lower(r.err);
  CHECK((message.find("empty") != std::string::npos || message.find("no face") != std::string::npos));
}

TEST_CASE("program: a NaN or infinite coordinate in a binary PLY names the vertex", "[program]")
{
  Temp_dir dir;
  Soup box = cube();
  SECTION("NaN")
  {
    box.points[6][1] = std::numeric_limits<double>::quiet_NaN();
  }
  SECTION("infinity")
  {
    box.points[6][2] = -std::numeric_limits<double>::infinity();
  }
  write_bytes(dir / "box.ply", ply_binary_bytes(box));
  const Run r = run_program(dir, { (dir / "box.ply").string(), "--random", "3", "--metric", "euclidean" });
  check_one_line_error(r, 1);
  INFO("stderr: " << r.err);
  CHECK(cites(r, dir, 6));
}

TEST_CASE("program: a NaN or infinite coordinate written as text names the vertex", "[program]")
{
  // Text formats write such coordinates as "nan", "inf" (what C++ streams and printf
  // produce); the contract asks for the vertex index whatever the format.
  Temp_dir dir;
  Soup box = cube();
  SECTION("NaN in OFF")
  {
    box.points[5][0] = std::numeric_limits<double>::quiet_NaN();
  }
  SECTION("infinity in OFF")
  {
    box.points[5][1] = std::numeric_limits<double>::infinity();
  }
  write_mesh(dir / "box.off", box);
  const std::string text = read_bytes(dir / "box.off");
  REQUIRE((text.find("nan") != std::string::npos || text.find("inf") != std::string::npos));
  const Run r = run_program(dir, { (dir / "box.off").string(), "--random", "3", "--metric", "euclidean" });
  check_one_line_error(r, 1);
  INFO("stderr: " << r.err);
  CHECK(cites(r, dir, 5));
}

TEST_CASE("program: a zero-area face names the face", "[program]")
{
  Temp_dir dir;
  // the cube plus, as face 9, a separate triangle whose corners lie on one line
  Soup s = cube();
  s.points.push_back({{ 3, 0, 0 }});
  s.points.push_back({{ 4, 1, 1 }});
  s.points.push_back({{ 5, 2, 2 }});
  s.faces.insert(s.faces.begin() + 9, std::vector<std::size_t>{ 8, 9, 10 });
  write_mesh(dir / "flat.off", s);
  const Run r = run_program(dir, { (dir / "flat.off").string(), "--random", "3", "--metric", "euclidean" });
  check_one_line_error(r, 1);
  INFO("stderr: " << r.err);
  CHECK(cites(r, dir, 9));
}

TEST_CASE("program: a non-manifold edge names the edge", "[program]")
{
  Temp_dir dir;
  // a fin: a third triangle on an edge (a, b) of a closed sphere
  Soup s = octahedral_sphere(2);
  const std::size_t a = s.faces[37][0], b = s.faces[37][1];
  REQUIRE(a != b);
  s.points.push_back(scaled(add(s.points[a], s.points[b]), 1.5));
  s.faces.push_back({ a, b, s.points.size() - 1 });
  write_mesh(dir / "fin.off", s);
  const Run r = run_program(dir, { (dir / "fin.off").string(), "--random", "3", "--metric", "euclidean" });
  check_one_line_error(r, 1);
  INFO("edge (" << a << ", " << b << "), stderr: " << r.err);
  CHECK(cites(r, dir, double(a)));
  CHECK(cites(r, dir, double(b)));
}

TEST_CASE("program: a non-manifold vertex names the vertex", "[program]")
{
  Temp_dir dir;
  // two tetrahedra sharing vertex 4 only
  Soup s;
  s.points = { {{ 1, 0, 0 }}, {{ 0, 1, 0 }}, {{ 1, 1, 0 }}, {{ -1, 0, 1 }}, {{ 0, 0, 0 }},
               {{ 0, -1, 1 }}, {{ -1, -1, 0 }} };
  s.faces = { { 4, 1, 0 }, { 4, 0, 2 }, { 4, 2, 1 }, { 0, 1, 2 },
              { 4, 5, 3 }, { 4, 6, 5 }, { 4, 3, 6 }, { 3, 5, 6 } };
  write_mesh(dir / "pinched.off", s);
  const Run r = run_program(dir, { (dir / "pinched.off").string(), "--random", "3", "--metric", "euclidean" });
  check_one_line_error(r, 1);
  INFO("stderr: " << r.err);
  CHECK(cites(r, dir, 4));
}

// =======================================================================================
// Sites files

namespace {

// Runs the program on the unit cube with the given sites file content.
Run run_on_cube_with_sites(const Temp_dir& dir, const std::string& sites_text,
                           const std::vector<std::string>& extra = {})
{
  write_mesh(dir / "box.off", cube());
  write_bytes(dir / "sites.txt", sites_text);
  std::vector<std::string> args = { (dir / "box.off").string(), "--sites", (dir / "sites.txt").string(),
                                    "--metric", "euclidean" };
  args.insert(args.end(), extra.begin(), extra.end());
  return run_program(dir, args);
}

} // namespace

TEST_CASE("program: sites file: a bad token names the line", "[program]")
{
  Temp_dir dir;
  const Run r = run_on_cube_with_sites(dir, "0.2 0.7 1\n# a comment\n\n0.5 0.5 0\n\n0.5 0.5x 1\n0 0.5 0.5\n");
  check_one_line_error(r, 1);
  INFO("stderr: " << r.err);
  CHECK(cites(r, dir, 6));
}

TEST_CASE("program: sites file: a wrong number of fields names the line", "[program]")
{
  Temp_dir dir;
  SECTION("two numbers")
  {
    const Run r = run_on_cube_with_sites(dir, "0.2 0.7 1\n0.5 0.5 0\n\n\n0 0.5\n");
    check_one_line_error(r, 1);
    INFO("stderr: " << r.err);
    CHECK(cites(r, dir, 5));
  }
  SECTION("five numbers")
  {
    const Run r = run_on_cube_with_sites(dir, "0.2 0.7 1\n# comment\n0.5 0.5 0 0 0\n");
    check_one_line_error(r, 1);
    INFO("stderr: " << r.err);
    CHECK(cites(r, dir, 3));
  }
}

TEST_CASE("program: sites file: NaN or infinity names the line", "[program]")
{
  Temp_dir dir;
  SECTION("nan")
  {
    const Run r = run_on_cube_with_sites(dir, "0.2 0.7 1\n\n\n\n0.5 nan 0\n");
    check_one_line_error(r, 1);
    INFO("stderr: " << r.err);
    CHECK(cites(r, dir, 5));
  }
  SECTION("inf")
  {
    const Run r = run_on_cube_with_sites(dir, "# header\n0.2 0.7 1\n0.5 0.5 inf\n");
    check_one_line_error(r, 1);
    INFO("stderr: " << r.err);
    CHECK(cites(r, dir, 3));
  }
  SECTION("overflow")
  {
    const Run r = run_on_cube_with_sites(dir, "0.2 0.7 1\n0.5 0.5 1e999\n");
    check_one_line_error(r, 1);
    INFO("stderr: " << r.err);
    CHECK(cites(r, dir, 2));
  }
}

TEST_CASE("program: sites file: CRLF, tabs, comments and blank lines are accepted", "[program]")
{
  Temp_dir dir;
  const Run plain = run_on_cube_with_sites(dir, "0.2 0.7 1\n0.5 0.5 0\n0 0.3 0.6\n",
                                           { "--output", (dir / "plain.ply").string() });
  check_success(plain);
  const Run messy = run_on_cube_with_sites(
      dir, "# sites\r\n\r\n0.2\t0.7 1   # first\r\n   \t\r\n  0.5 0.5\t0 0\r\n#0 0 0\r\n0 0.3 0.6\r\n",
      { "--output", (dir / "messy.ply").string(), "--sites-out", (dir / "final.txt").string() });
  check_success(messy);
  CHECK(messy.err.empty());
  CHECK(same_files(dir / "plain.ply", dir / "messy.ply"));
  check_same_points(read_sites_out(dir / "final.txt"),
                    { {{ 0.2, 0.7, 1 }}, {{ 0.5, 0.5, 0 }}, {{ 0, 0.3, 0.6 }} }, 1e-12);
  CHECK(check_output(dir / "messy.ply", cube(), 3).labels == std::set<int>({ 0, 1, 2 }));
}

TEST_CASE("program: sites file: a site too far from the surface names the line and the distance", "[program]")
{
  Temp_dir dir;
  // (0.5, 0.5, 1.25) is 0.25 from the unit cube; the limit is 0.01 * sqrt(3)
  const std::string text = "0.2 0.7 1\n# comment\n0.5 0.5 0\n\n0.5 0.5 1.25\n";
  const Run r = run_on_cube_with_sites(dir, text);
  check_one_line_error(r, 1);
  INFO("stderr: " << r.err);
  CHECK(cites(r, dir, 5));
  CHECK(cites(r, dir, 0.25));

  // within a larger --max-site-distance, the site moves to the nearest surface point
  const Run accepted = run_on_cube_with_sites(dir, text, { "--max-site-distance", "0.2", "--sites-out",
                                                           (dir / "final.txt").string(), "--output",
                                                           (dir / "out.ply").string() });
  check_success(accepted);
  check_same_points(read_sites_out(dir / "final.txt"), { {{ 0.2, 0.7, 1 }}, {{ 0.5, 0.5, 0 }}, {{ 0.5, 0.5, 1 }} },
                    1e-12);
  check_output(dir / "out.ply", cube(), 3);

  // a slightly-off site within the default limit is moved too
  const Run near = run_on_cube_with_sites(dir, "0.2 0.7 1.004\n0.5 0.5 -0.003\n",
                                          { "--sites-out", (dir / "near.txt").string() });
  check_success(near);
  check_same_points(read_sites_out(dir / "near.txt"), { {{ 0.2, 0.7, 1 }}, {{ 0.5, 0.5, 0 }} }, 1e-12);
}

TEST_CASE("program: sites file: two sites at the same surface point name both lines", "[program]")
{
  Temp_dir dir;
  // lines 2 and 6 both land on (0.2, 0.7, 1)
  const Run r = run_on_cube_with_sites(dir, "# two sites collide\n0.2 0.7 1\n0.5 0.5 0\n\n0 0.3 0.6\n0.2 0.7 1.001\n");
  check_one_line_error(r, 1);
  INFO("stderr: " << r.err);
  CHECK(cites(r, dir, 2));
  CHECK(cites(r, dir, 6));
}

TEST_CASE("program: sites file: a weight makes a power diagram, a zero weight changes nothing", "[program]")
{
  Temp_dir dir;
  const Run plain = run_on_cube_with_sites(dir, "0.2 0.7 1\n0.5 0.5 0\n", { "--output", (dir / "plain.ply").string() });
  check_success(plain);
  const Run zero = run_on_cube_with_sites(dir, "0.2 0.7 1 0\n0.5 0.5 0 0.0\n", { "--output", (dir / "zero.ply").string() });
  check_success(zero);
  CHECK(same_files(dir / "plain.ply", dir / "zero.ply"));

  const Run heavy = run_on_cube_with_sites(dir, "0.2 0.7 1 0\n0.5 0.5 0 0.5\n", { "--output", (dir / "heavy.ply").string() });
  check_success(heavy);
  const Arrangement_summary a = check_output(dir / "plain.ply", cube(), 2);
  const Arrangement_summary b = check_output(dir / "heavy.ply", cube(), 2);
  CHECK(b.area_per_site.at(1) > a.area_per_site.at(1) + 0.1);

  const Run bad = run_on_cube_with_sites(dir, "0.2 0.7 1 0\n\n\n0.5 0.5 0 nan\n");
  check_one_line_error(bad, 1);
  INFO("stderr: " << bad.err);
  CHECK(cites(bad, dir, 4));
}

TEST_CASE("program: --breaklines reads mesh edges and refuses a pair that is not an edge", "[program]")
{
  Temp_dir dir;
  write_mesh(dir / "box.off", cube());
  write_bytes(dir / "sites.txt", "0.2 0.7 1\n0.5 0.5 0\n");
  write_bytes(dir / "lines.txt", "# first edge of face 0, then a pair that is no edge\n0 1\n\n0 6\n");
  const Run r = run_program(dir, { (dir / "box.off").string(), "--sites", (dir / "sites.txt").string(), "--metric",
                                   "euclidean", "--breaklines", (dir / "lines.txt").string() });
  check_one_line_error(r, 1);
  INFO("stderr: " << r.err);
  CHECK(cites(r, dir, 4));
  write_bytes(dir / "ok.txt", "0 1\n");
  const Run ok = run_program(dir, { (dir / "box.off").string(), "--sites", (dir / "sites.txt").string(), "--metric",
                                    "euclidean", "--breaklines", (dir / "ok.txt").string(), "--output",
                                    (dir / "out.ply").string() });
  check_success(ok);
  write_bytes(dir / "junk.txt", "0 x\n");
  const Run junk = run_program(dir, { (dir / "box.off").string(), "--sites", (dir / "sites.txt").string(),
                                      "--breaklines", (dir / "junk.txt").string() });
  check_one_line_error(junk, 1);
}

// --sharp-edges 60 on a unit cube (its normals turn by 90 degrees at every edge) makes the 12
// edges breaklines: each of six sites, one per side and off its centre, keeps exactly its side
// (area 1). Without it, or with an angle above 90, the sites off centre reach across edges.
TEST_CASE("program: --sharp-edges makes the edges where the surface turns by more than the angle breaklines", "[program]")
{
  Temp_dir dir;
  write_mesh(dir / "box.off", cube());
  write_bytes(dir / "sites.txt", "0.1 0.1 1\n0.9 0.9 0\n0 0.1 0.8\n1 0.9 0.2\n0.8 0 0.9\n0.2 1 0.1\n");
  auto run_with = [&](const std::string& name, std::vector<std::string> extra) {
    std::vector<std::string> args = { (dir / "box.off").string(), "--sites", (dir / "sites.txt").string(), "--metric",
                                      "euclidean", "--output", (dir / name).string() };
    args.insert(args.end(), extra.begin(), extra.end());
    const Run r = run_program(dir, args);
    check_success(r);
    return check_output(dir / name, cube(), 6);
  };
  const Arrangement_summary sharp = run_with("sharp.ply", { "--sharp-edges", "60" });
  for(int site = 0; site < 6; ++site)
  {
    INFO("site " << site);
    CHECK(std::abs(sharp.area_per_site.at(site) - 1.0) <= 1e-9);
  }
  const Arrangement_summary plain = run_with("plain.ply", {});
  const Arrangement_summary blunt = run_with("blunt.ply", { "--sharp-edges", "100" });
  bool some_side_shared = false;
  for(int site = 0; site < 6; ++site) some_side_shared |= std::abs(plain.area_per_site.at(site) - 1.0) > 1e-3;
  CHECK(some_side_shared);
  CHECK(same_files(dir / "plain.ply", dir / "blunt.ply"));
  for(const std::string bad : { "0", "180", "-5", "ninety" })
  {
    const Run r = run_program(dir, { (dir / "box.off").string(), "--random", "5", "--sharp-edges", bad });
    check_one_line_error(r, 2);
  }
}

// An open roof over the unit square, its ridge along x = 0.5 (the slopes turn by 2 atan(0.6),
// 62 degrees, there): n x n squares of two triangles each.
Soup roof(std::size_t n)
{
  Soup s;
  for(std::size_t j = 0; j <= n; ++j)
    for(std::size_t i = 0; i <= n; ++i)
    {
      const double x = double(i) / double(n), y = double(j) / double(n);
      s.points.push_back({{ x, y, 0.3 * (1 - std::abs(2 * x - 1)) }});
    }
  auto at = [&](std::size_t i, std::size_t j) { return j * (n + 1) + i; };
  for(std::size_t j = 0; j < n; ++j)
    for(std::size_t i = 0; i < n; ++i)
    {
      s.faces.push_back({ at(i, j), at(i + 1, j), at(i + 1, j + 1) });
      s.faces.push_back({ at(i, j), at(i + 1, j + 1), at(i, j + 1) });
    }
  return s;
}

// The remesh (--dual) as a surface mesh, and the length of its edges that `on_line` holds at
// both ends, of its border edges, and whether every border vertex satisfies `on_border`.
struct Dual_lines
{
  double line_length = 0, border_length = 0;
  bool border_vertices_on_border = true;
};
template <class Line, class Border>
Dual_lines dual_lines(const fs::path& path, const Line& on_line, const Border& on_border)
{
  CGAL::Surface_mesh<PPoint> dual;
  REQUIRE(CGAL::IO::read_OFF(path.string(), dual));
  Dual_lines r;
  auto v3 = [&](CGAL::Surface_mesh<PPoint>::Vertex_index v) { const PPoint& p = dual.point(v); return V3{{ p.x(), p.y(), p.z() }}; };
  for(auto e : dual.edges())
  {
    const V3 a = v3(dual.vertex(e, 0)), b = v3(dual.vertex(e, 1));
    if(on_line(a) && on_line(b)) r.line_length += distance(a, b);
    if(dual.is_border(e))
    {
      r.border_length += distance(a, b);
      r.border_vertices_on_border = r.border_vertices_on_border && on_border(a) && on_border(b);
    }
  }
  return r;
}

// Sampled sites with breaklines (--sharp-edges) start on them, evenly spaced, and with --dual
// on the border too; they are part of N, stay through --lloyd, and the remesh's edges run along
// the ridge and its border along the input's border. Too few sites for the lines is exit 2.
TEST_CASE("program: sampled sites start on the breaklines and, for a remesh, on the border", "[program][dual]")
{
  Temp_dir dir;
  write_mesh(dir / "roof.off", roof(40));
  const std::string mesh = (dir / "roof.off").string();
  auto near = [](double a, double b) { return std::abs(a - b) <= 1e-9; };
  auto on_ridge = [&](const V3& p) { return near(p[0], 0.5) && near(p[2], 0.3); };
  auto on_border = [&](const V3& p) { return near(p[0], 0) || near(p[0], 1) || near(p[1], 0) || near(p[1], 1); };
  auto run_with = [&](const std::string& name, std::vector<std::string> extra) {
    std::vector<std::string> args = { mesh, "--blue-noise", "300", "--seed", "1", "--metric", "euclidean", "--lloyd", "5",
                                      "--sites-out", (dir / (name + ".xyz")).string(), "--stats" };
    args.insert(args.end(), extra.begin(), extra.end());
    const Run r = run_program(dir, args);
    check_success(r);
    return parse_stats(r.out);
  };
  // the ridge only: its sites first, then the others, none of those on it
  const auto ridge = run_with("ridge", { "--sharp-edges", "30" });
  const std::size_t k = std::size_t(stat_value(ridge, "feature_sites"));
  CHECK(stat_value(ridge, "sites") == 300);
  CHECK((k >= 15 && k <= 25));   // about 1 / h for 300 sites on a surface of area 1.17
  const std::vector<V3> ridge_sites = read_sites_out(dir / "ridge.xyz");
  REQUIRE(ridge_sites.size() == 300);
  for(std::size_t i = 0; i < ridge_sites.size(); ++i) CHECK(on_ridge(ridge_sites[i]) == (i < k));
  // evenly spaced, from end to end
  std::vector<double> ys;
  for(std::size_t i = 0; i < k; ++i) ys.push_back(ridge_sites[i][1]);
  std::sort(ys.begin(), ys.end());
  CHECK(ys.front() == 0.);
  CHECK(ys.back() == 1.);
  for(std::size_t i = 1; i < ys.size(); ++i) CHECK(std::abs((ys[i] - ys[i - 1]) * double(k - 1) - 1) < 1e-6);
  // they stay through Lloyd: the same sites without it
  run_with("ridge_unrelaxed", { "--sharp-edges", "30", "--lloyd", "0" });
  const std::vector<V3> unrelaxed = read_sites_out(dir / "ridge_unrelaxed.xyz");
  REQUIRE(unrelaxed.size() == 300);
  for(std::size_t i = 0; i < k; ++i) CHECK(unrelaxed[i] == ridge_sites[i]);

  // a remesh: the border as well, and the remesh follows the ridge and the border
  const auto remesh = run_with("remesh", { "--sharp-edges", "30", "--dual", (dir / "remesh.off").string() });
  const std::size_t with_border = std::size_t(stat_value(remesh, "feature_sites"));
  CHECK(with_border > k + 50);
  CHECK(stat_value(remesh, "dual_valid") == 1);
  const Dual_lines lines = dual_lines(dir / "remesh.off", on_ridge, on_border);
  CHECK(lines.line_length == Approx(1.0).epsilon(1e-9));
  CHECK(lines.border_vertices_on_border);
  CHECK(lines.border_length == Approx(2 + 2 * 2 * std::hypot(0.5, 0.3)).epsilon(1e-9));
  // no breakline and no remesh: every site drawn
  const Run random = run_program(dir, { mesh, "--random", "300", "--seed", "1", "--metric", "euclidean", "--stats" });
  check_success(random);
  CHECK(parse_stats(random.out).count("feature_sites") == 0);   // no breakline, no remesh: all drawn

  // sites read from a file are never added to, breaklines or not
  const Run from_file = run_program(dir, { mesh, "--sites", (dir / "remesh.xyz").string(), "--metric", "euclidean",
                                           "--sharp-edges", "30", "--dual", (dir / "again.off").string(), "--stats" });
  check_success(from_file);
  CHECK(stat_value(parse_stats(from_file.out), "sites") == 300);
  CHECK(parse_stats(from_file.out).count("feature_sites") == 0);
  CHECK(same_files(dir / "remesh.off", dir / "again.off"));

  // the lines alone would take all the sites: say so
  check_one_line_error(run_program(dir, { mesh, "--blue-noise", "6", "--sharp-edges", "30", "--dual", (dir / "few.off").string() }), 2);
  CHECK(!fs::exists(dir / "few.off"));
}

// --curvature-density on a torus (R = 1, r = 0.4): its outer equator bends four times as much
// as its inner one, so blue-noise sites drawn and relaxed with the flag crowd outwards more
// than without it; the ratio must be a number of at least 1, and the flag needs sites drawn
// or relaxed.
TEST_CASE("program: --curvature-density puts more sites where the surface bends", "[program]")
{
  Temp_dir dir;
  write_mesh(dir / "torus.off", torus_soup(1.0, 0.4, 80, 32));
  auto outer_fraction = [&](const std::string& name, std::vector<std::string> extra) {
    std::vector<std::string> args = { (dir / "torus.off").string(), "--blue-noise", "400", "--metric", "euclidean",
                                      "--lloyd", "5", "--sites-out", (dir / name).string() };
    args.insert(args.end(), extra.begin(), extra.end());
    check_success(run_program(dir, args));
    const std::vector<V3> sites = read_sites_out(dir / name);
    REQUIRE(sites.size() == 400);
    std::size_t outer = 0;
    for(const V3& p : sites) outer += (std::hypot(p[0], p[1]) > 1.0);
    return double(outer) / double(sites.size());
  };
  const double plain = outer_fraction("plain.xyz", {});
  const double dense = outer_fraction("dense.xyz", { "--curvature-density", "16" });
  CHECK(plain < 0.68);   // the outer half has 0.63 of the area
  CHECK(dense > plain + 0.08);
  for(const std::string bad : { "0.5", "-1", "many" })
    check_one_line_error(run_program(dir, { (dir / "torus.off").string(), "--random", "5", "--curvature-density", bad }), 2);
  write_sites(dir / "sites.txt", { {{ 1.4, 0, 0 }} });
  check_one_line_error(run_program(dir, { (dir / "torus.off").string(), "--sites", (dir / "sites.txt").string(),
                                          "--curvature-density", "4" }), 2);
}

TEST_CASE("program: sites file: a missing sites file is an error naming it", "[program]")
{
  Temp_dir dir;
  write_mesh(dir / "box.off", cube());
  const Run r = run_program(dir, { (dir / "box.off").string(), "--sites", (dir / "absent_sites.txt").string(),
                                   "--metric", "euclidean" });
  check_one_line_error(r, 1);
  CHECK(r.err.find("absent_sites.txt") != std::string::npos);
}

namespace {

// ---------------------------------------------------------------------------------------
// Numerical robustness and limits (issue 11): needles, extreme coordinates, the refinement
// cap, site counts, the default biharmonic dimension on small meshes

const char* const rhombus_off = "OFF\n4 2 0\n-0.5 0 0\n0.5 0 0\n0 1e-9 0\n0 -1e-9 0\n3 0 1 2\n3 1 0 3\n";

std::string tetrahedron_off(const std::string& s)
{
  const std::string z = "0";
  return "OFF\n4 4 0\n" + z + " 0 0\n" + s + " 0 0\n0 " + s + " 0\n0 0 " + s + "\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
}

double seconds_since(const std::chrono::steady_clock::time_point& t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

TEST_CASE("program: needles and caps (a 1 x 2e-9 rhombus) work with every metric", "[program][numerics]")
{
  // Before: SIGFPE for every metric (PMP's locate divided by a Gram determinant that
  // cancels to 0, and NaN barycentric coordinates reached GMP).
  Temp_dir dir;
  write_bytes(dir / "rhombus.off", rhombus_off);
  write_sites(dir / "sites.txt", { {{ -0.25, 2.5e-10, 0 }}, {{ 0.25, -2.5e-10, 0 }}, {{ 0.1, 0, 0 }}, {{ -0.4, -1e-10, 0 }} });
  for(const std::string metric : { "biharmonic", "euclidean", "rvd", "geodesic" })
  {
    std::vector<std::string> extra;
    if(metric == "geodesic") extra.push_back("--no-refine");
    for(const bool from_file : { false, true })
    {
      std::vector<std::string> args = { (dir / "rhombus.off").string(), "--metric", metric, "--output",
                                        (dir / "out.ply").string(), "--stats" };
      if(from_file) { args.push_back("--sites"); args.push_back((dir / "sites.txt").string()); }
      else { args.push_back("--random"); args.push_back("10"); }
      args.insert(args.end(), extra.begin(), extra.end());
      const Run r = run_program(dir, args);
      check_success(r);
      const auto stats = parse_stats(r.out);
      CHECK(stats.at("cells") == (from_file ? "4" : "10"));
      CHECK(stats.at("unreached_faces") == "0");
      CHECK(std::abs(std::stod(stats.at("surface_area")) - 1e-9) < 1e-15);
      const Arrangement_ply a = read_arrangement(dir / "out.ply");
      for(const V3& v : a.vertices)
        for(double c : v) CHECK(std::isfinite(c));
    }
  }
  // the geodesic refinement cannot refine the needles down to the area-derived length: it
  // stops at its cap and says to use --no-refine
  const Run refined = run_program(dir, { (dir / "rhombus.off").string(), "--random", "10", "--metric", "geodesic" });
  check_one_line_error(refined, 1);
  CHECK(refined.err.find("--no-refine") != std::string::npos);
}

TEST_CASE("program: coordinates near 1e308 and 1e-310 work, the outputs in the input's units", "[program][numerics]")
{
  // Before: 1e308 recursed without end in random_sites (areas overflow), with a sites file
  // SIGFPE; 1e-310 (areas underflow to 0) looped forever.
  Temp_dir dir;
  struct Case { std::string scale; double s; V3 site; };
  for(const Case& c : { Case{ "1.5e308", 1.5e308, {{ 0.25e308, 0.25e308, 1.0e308 }} },
                        Case{ "1e-310", 1e-310, {{ 0.3e-310, 0.3e-310, 0.4e-310 }} } })
    for(const std::string metric : { "biharmonic", "euclidean", "rvd", "geodesic" })
      for(const bool from_file : { false, true })
      {
        INFO("scale " << c.scale << ", metric " << metric << (from_file ? ", sites file" : ", --random"));
        write_bytes(dir / "tet.off", tetrahedron_off(c.scale));
        write_sites(dir / "sites.txt", { c.site, {{ 0, 0.5 * c.s, 0.2 * c.s }}, {{ 0.3 * c.s, 0.3 * c.s, 0 }} });
        std::vector<std::string> args = { (dir / "tet.off").string(), "--metric", metric, "--output",
                                          (dir / "out.ply").string(), "--sites-out", (dir / "out.xyz").string(),
                                          "--dual", (dir / "dual.off").string() };
        if(from_file) { args.push_back("--sites"); args.push_back((dir / "sites.txt").string()); }
        else { args.push_back("--random"); args.push_back("6"); }
        const auto t0 = std::chrono::steady_clock::now();
        const Run r = run_program(dir, args);
        CHECK(seconds_since(t0) < 10);
        check_success(r);
        // every output is back in the input's units: on the tetrahedron of side c.s
        const Arrangement_ply a = read_arrangement(dir / "out.ply");
        double largest = 0;
        for(const V3& v : a.vertices)
          for(double x : v) { REQUIRE(std::isfinite(x)); CHECK(x >= -1e-6 * c.s); largest = (std::max)(largest, x); }
        CHECK(largest == c.s);
        for(const V3& p : read_sites_out(dir / "out.xyz"))
        {
          CHECK(p[0] + p[1] + p[2] <= c.s * (1 + 1e-9));
          CHECK((std::min)((std::min)(p[0], p[1]), p[2]) >= 0);
          CHECK((std::max)((std::max)(p[0], p[1]), p[2]) > 1e-3 * c.s);
        }
      }
  // ordinary meshes are not scaled (the regression matrix checks them bit for bit)
}

// The program's memory policy (huge pages or not) is not allowed to change a bit of its outputs.
TEST_CASE("program: the huge-page advice, given (SVD_HUGE_PAGES=1), left out (=0) or chosen by the machine, changes no output", "[program]")
{
  Temp_dir dir;
  const Soup sphere = octahedral_sphere(5);   // 4098 vertices
  write_mesh(dir / "sphere.off", sphere);
  for(const std::string metric : { "euclidean", "geodesic" })
  {
    INFO("metric " << metric);
    auto args = [&](const std::string& name) {
      return std::vector<std::string>{ (dir / "sphere.off").string(), "--random", "300", "--seed", "3", "--metric", metric,
                                       "--output", (dir / (name + ".ply")).string(), "--sites-out", (dir / (name + ".txt")).string() };
    };
    const Run chosen = run_program(dir, args("chosen"));
    const Run plain = run_program(dir, args("plain"), "SVD_HUGE_PAGES=0");
    const Run forced = run_program(dir, args("forced"), "SVD_HUGE_PAGES=1");
    check_success(chosen);
    check_success(plain);
    check_success(forced);
    CHECK(plain.err == chosen.err);
    CHECK(forced.err == chosen.err);
    CHECK(read_bytes(dir / "plain.ply") == read_bytes(dir / "chosen.ply"));
    CHECK(read_bytes(dir / "plain.txt") == read_bytes(dir / "chosen.txt"));
    CHECK(read_bytes(dir / "forced.ply") == read_bytes(dir / "chosen.ply"));
    CHECK(read_bytes(dir / "forced.txt") == read_bytes(dir / "chosen.txt"));
    CHECK(!read_bytes(dir / "plain.ply").empty());
  }
}

TEST_CASE("program: the geodesic refinement stops at its cap quickly, exit 1 naming --no-refine", "[program][numerics]")
{
  // Without the cap, a 1 x 1e-6 strip of two needles is refined without end: each split
  // leaves needles as long as before.
  Temp_dir dir;
  write_bytes(dir / "strip.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1e-6 0\n0 1e-6 0\n3 0 1 2\n3 0 2 3\n");
  for(const std::string n : { "2", "10", "200" })
  {
    const auto t0 = std::chrono::steady_clock::now();
    const Run r = run_program(dir, { (dir / "strip.off").string(), "--random", n, "--metric", "geodesic" });
    CHECK(seconds_since(t0) < 10);
    check_one_line_error(r, 1);
    CHECK(r.err.find("cap") != std::string::npos);
    CHECK(r.err.find("--no-refine") != std::string::npos);
    CHECK(r.err.find("fewer sites") != std::string::npos);
    // the cap bounds the vertices added to the input's (a cap on the total would forbid any
    // refinement of a mesh of over a million vertices): 4 + 256 x (4 + sites)
    const std::string cap = "cap of " + std::to_string(4 + 256 * (4 + std::stoul(n))) + " vertices";
    INFO("expected '" << cap << "' in: " << r.err);
    CHECK(r.err.find(cap) != std::string::npos);
  }
  check_success(run_program(dir, { (dir / "strip.off").string(), "--random", "10", "--metric", "geodesic", "--no-refine" }));
}

TEST_CASE("program: site counts are limited (10,000,000 in all; 2048 per face)", "[program][numerics]")
{
  // Without the limits, --random 100000000 on a tetrahedron runs for minutes without a
  // message, and --random 10000 makes every site a candidate of every face.
  Temp_dir dir;
  write_bytes(dir / "tet.off", tetrahedron_off("1"));
  const std::string mesh = (dir / "tet.off").string();
  for(const std::string flag : { "--random", "--blue-noise" })
  {
    const Run over = run_program(dir, { mesh, flag, "10000001" });
    check_one_line_error(over, 2);
    CHECK(over.err.find("10000000") != std::string::npos);
    for(const std::string n : { "10000000", "1000000" })
      for(const std::string metric : { "biharmonic", "euclidean", "rvd", "geodesic" })
      {
        const auto t0 = std::chrono::steady_clock::now();
        const Run r = run_program(dir, { mesh, flag, n, "--metric", metric });
        CHECK(seconds_since(t0) < 2);
        check_one_line_error(r, 2);
        CHECK(r.err.find("2048 sites per face") != std::string::npos);
        const Run inserted = run_program(dir, { mesh, flag, n, "--metric", metric, "--insert-sites" });
        check_one_line_error(inserted, 2);
        CHECK(inserted.err.find("2048 sites per face") != std::string::npos);
      }
  }
  // the count per face after the draw: 1000 random sites put more than 256 on the largest
  // face, and are inserted as vertices, with a note (before: an error)
  const Run drawn = run_program(dir, { mesh, "--random", "1000", "--metric", "euclidean" });
  check_success(drawn);
  CHECK(count_lines(drawn.err) == 1);
  CHECK(drawn.err.find("note: face") != std::string::npos);
  CHECK(drawn.err.find("inserted as vertices") != std::string::npos);
  // a sites file with 300 sites in one face: inserted too; the same output as --insert-sites
  std::vector<V3> many;
  for(int i = 0; i < 300; ++i) many.push_back({{ 0.001 + 0.003 * (i % 20), 0.001 + 0.003 * (i / 20), 0 }});
  write_sites(dir / "many.txt", many);
  const Run file = run_program(dir, { mesh, "--sites", (dir / "many.txt").string(), "--metric", "euclidean",
                                      "--output", (dir / "auto.ply").string() });
  check_success(file);
  CHECK(file.err.find("holds 300 sites") != std::string::npos);
  check_success(run_program(dir, { mesh, "--sites", (dir / "many.txt").string(), "--metric", "euclidean", "--insert-sites",
                                   "--output", (dir / "flag.ply").string() }));
  CHECK(same_files(dir / "auto.ply", dir / "flag.ply"));
  // with the geodesic metric the mesh is refined for them instead
  const Run refined = run_program(dir, { mesh, "--sites", (dir / "many.txt").string(), "--metric", "geodesic" });
  check_success(refined);
  CHECK(refined.err.find("refined for the sites") != std::string::npos);
  CHECK(refined.err.find("inserted") == std::string::npos);
  // within the limits the largest runs finish quickly
  const auto t0 = std::chrono::steady_clock::now();
  check_success(run_program(dir, { mesh, "--random", "650", "--metric", "euclidean" }));
  CHECK(seconds_since(t0) < 5);
}

// issue 52: a coarse CAD mesh takes many sites without a flag, for every metric (before: "face
// 2 holds more than 256 sites" with each of them). The sites are inserted (biharmonic,
// Euclidean, RVD) or the mesh refined for them (geodesic); the output keeps its contract.
TEST_CASE("program: a 12-triangle cube with 3000 random sites works with every metric", "[program][coarse]")
{
  Temp_dir dir;
  const Soup box = cube();
  write_mesh(dir / "cube.off", box);
  const double diag = bbox_diagonal(box.points);
  for(const std::string metric : { "biharmonic", "euclidean", "rvd", "geodesic" })
  {
    INFO("metric " << metric);
    const auto t0 = std::chrono::steady_clock::now();
    const Run r = run_program(dir, { (dir / "cube.off").string(), "--random", "3000", "--metric", metric, "--stats",
                                     "--output", (dir / "out.ply").string(), "--sites-out", (dir / "sites.txt").string() });
    const double seconds = seconds_since(t0);
    check_success(r);
    UNSCOPED_INFO("cube, 3000 sites, " << metric << ": " << seconds << " s");
    CHECK(seconds < 30);
    CHECK(r.err.find(metric == "geodesic" ? "refined for the sites" : "inserted as vertices") != std::string::npos);
    const std::map<std::string, std::string> stats = parse_stats(r.out);
    CHECK(stat_value(stats, "sites") == 3000);
    CHECK(stat_value(stats, "empty_cells") == 0);
    if(metric != "rvd")   // the RVD is not repaired: a cell may come in pieces
      CHECK(stat_value(stats, "pieces") == 3000);
    // faces inside one input triangle, covering it exactly (the areas sum to the cube's)
    const Arrangement_ply a = read_arrangement(dir / "out.ply");
    const Arrangement_summary s = check_arrangement(a, box, 3000);
    CHECK(s.labels.count(-1) == 0);
    CHECK(s.labels.size() == 3000);   // every cell non-empty
    const std::vector<V3> sites = read_sites_out(dir / "sites.txt");
    REQUIRE(sites.size() == 3000);
    check_sites_in_own_cells(a, sites, 1e-9 * diag);
    if(metric == "euclidean" || metric == "rvd")
    {
      // the brute-force nearest site, at each output face's centroid (away from ties)
      std::size_t wrong = 0, checked = 0;
      for(std::size_t f = 0; f < a.faces.size(); ++f)
      {
        V3 c = {{ 0, 0, 0 }};
        for(std::size_t v : a.faces[f])
          for(int k = 0; k < 3; ++k) c[std::size_t(k)] += a.vertices[v][std::size_t(k)] / double(a.faces[f].size());
        std::vector<std::pair<double, int> > d;
        for(std::size_t i = 0; i < sites.size(); ++i) d.emplace_back(distance(c, sites[i]), int(i));
        std::partial_sort(d.begin(), d.begin() + 2, d.end());
        if(d[1].first - d[0].first < 1e-9 * diag) continue;
        ++checked;
        wrong += (d[0].second != a.sites[f]);
      }
      CHECK(checked > a.faces.size() / 2);
      CHECK(wrong == 0);
    }
    // --sites-out reads back to the same diagram, bit for bit
    const Run again = run_program(dir, { (dir / "cube.off").string(), "--sites", (dir / "sites.txt").string(), "--metric", metric,
                                         "--output", (dir / "again.ply").string() });
    check_success(again);
    CHECK(same_files(dir / "out.ply", dir / "again.ply"));
  }
}

TEST_CASE("program: the default biharmonic dimension is lowered on small meshes, with a note", "[program][numerics]")
{
  // Before: every mesh of up to 11 vertices (CGAL's tetrahedron, cube, octahedron) was
  // refused with the default dimension 10.
  Temp_dir dir;
  write_bytes(dir / "tet.off", tetrahedron_off("1"));
  const std::string mesh = (dir / "tet.off").string();
  const Run r = run_program(dir, { mesh, "--random", "5", "--output", (dir / "out.ply").string() });
  check_success(r);
  CHECK(count_lines(r.err) == 1);
  CHECK(r.err.rfind("surface_voronoi: note: ", 0) == 0);
  CHECK(r.err.find("at most 2") != std::string::npos);
  // the same diagram as an explicit --dimension 2
  const Run two = run_program(dir, { mesh, "--random", "5", "--dimension", "2", "--output", (dir / "two.ply").string() });
  check_success(two);
  CHECK(two.err.empty());
  CHECK(same_files(dir / "out.ply", dir / "two.ply"));
  // an explicit dimension too large stays an error that names the maximum
  const Run explicit_too_large = run_program(dir, { mesh, "--random", "5", "--dimension", "3" });
  check_one_line_error(explicit_too_large, 1);
  CHECK(explicit_too_large.err.find("at most 2") != std::string::npos);
}

} // namespace
} // namespace svd_program_test

} // namespace svd_test_program
