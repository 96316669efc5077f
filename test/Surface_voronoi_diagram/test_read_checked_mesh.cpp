// Copyright (c) 2026 The Surface_voronoi_diagram authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Tests of the surface_voronoi program's own mesh parsers (mesh_file_parsers.h), of the
// from-memory entry point and of the record files' open and size checks (issue 11): hostile
// files give one Input_error naming the line or element, within bounded time and memory;
// valid files give exactly what CGAL's readers gave (same doubles, bit for bit, same faces).

#include <surface_voronoi/read_checked_mesh.h>
#include <surface_voronoi/sites_file.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Random.h>
#include <CGAL/Surface_mesh.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

// this file's own names: the suite compiles its files together (see CMakeLists.txt)
namespace svd_test_read_checked_mesh {

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Surface_mesh;
typedef std::vector<std::vector<std::size_t>> Polygons;
namespace SVIO = svd_program;
namespace PMP = CGAL::Polygon_mesh_processing;

// the message of the Input_error that reading `text` as `format` throws, or "" if none
std::string error_of(const std::string& text, const std::string& format)
{
  Surface_mesh mesh;
  try
  {
    SVIO::read_checked_triangle_mesh_from_memory(text.data(), text.size(), format, mesh, "t." + format);
  }
  catch(const SVIO::Input_error& e)
  {
    return e.what();
  }
  return std::string();
}

bool printable_ascii(const std::string& s)
{
  for(char c : s)
    if(static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f)
      return false;
  return true;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof(double)) == 0; }

struct Soup
{
  std::vector<Point> points;
  Polygons polygons;
};

Soup parse(const std::string& text, const std::string& format)
{
  Soup s;
  SVIO::mesh_parsers::parse_mesh(text.data(), text.size(), format, s.points, s.polygons);
  return s;
}

class Temp_dir
{
public:
  explicit Temp_dir(const std::string& name)
  {
    std::random_device device;
    path_ = std::filesystem::temp_directory_path() /
            ("svd_test_read_" + name + "_" + std::to_string(device()) + "_" +
             std::to_string(std::chrono::steady_clock::now().time_since_epoch().count()));
    std::filesystem::create_directories(path_);
  }
  ~Temp_dir()
  {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  std::string file(const std::string& name, const std::string& content) const
  {
    const std::string p = (path_ / name).string();
    std::ofstream out(p, std::ios::binary);
    out << content;
    return p;
  }
  std::string path(const std::string& name) const { return (path_ / name).string(); }

private:
  std::filesystem::path path_;
};

const std::string tet_v = "0 0 0\n1 0 0\n0 1 0\n0 0 1\n";
const std::string tet_f = "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
const std::string tet_off = "OFF\n4 4 0\n" + tet_v + tet_f;
// A trailing comment, so that a small defective OFF still has the bytes its header counts
// need (8 a face line, 6 a vertex line) and the defect, not the bound, is reported.
const std::string pad = "# padding, so that the counts fit the bytes\n";
const double pi = std::acos(-1.0);
const std::string obj_v = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n";

std::string ply_ascii_header(const std::string& faces = "4")
{
  return "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
         "element face " + faces + "\nproperty list uchar int vertex_indices\nend_header\n";
}

template <class T>
void put(std::string& out, T v, bool big)
{
  unsigned char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  if(big)
    for(std::size_t i = 0; i < sizeof(T) / 2; ++i)
      std::swap(b[i], b[sizeof(T) - 1 - i]);
  out.append(reinterpret_cast<const char*>(b), sizeof(T));
}

// A regular n-gon in the plane z = 0, one face, in the given orientation.
std::string polygon_off(std::size_t n, bool counterclockwise = true)
{
  std::ostringstream s;
  s.precision(17);
  s << "OFF\n" << n << " 1 0\n";
  for(std::size_t k = 0; k < n; ++k)
    s << std::cos(2 * pi * double(k) / double(n)) << " " << std::sin(2 * pi * double(k) / double(n)) << " 0\n";
  s << n;
  for(std::size_t k = 0; k < n; ++k)
    s << " " << (counterclockwise ? k : n - 1 - k);
  s << "\n";
  return s.str();
}

} // namespace

// ------------------------------------------------------------------------------------ PLY

TEST_CASE("read: a PLY property before any element is an error naming the header line", "[io][mesh][parsers]")
{
  // 49 bytes; CGAL's PLY reader crashed on it (SIGSEGV)
  const std::string text = "ply\nformat ascii 1.0\nproperty float x\nend_header\n";
  REQUIRE(text.size() == 49);
  CHECK(error_of(text, "ply") == "mesh file 't.ply': line 3: property before any element");
}

TEST_CASE("read: PLY header defects name the header line", "[io][mesh][parsers]")
{
  CHECK_THAT(error_of("ply\nformat ascii 1.0\nelement vertex 3\nproperty quad x\nend_header\n", "ply"),
             Catch::Contains("line 4: unknown type 'quad'"));
  CHECK_THAT(error_of("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                      "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0\n1 0\n0 1\n3 0 1 2\n", "ply"),
             Catch::Contains("line 3: element 'vertex' has no property 'z'"));
  CHECK_THAT(error_of("ply\nformat binary_middle_endian 1.0\n", "ply"), Catch::Contains("line 2: unknown format"));
  CHECK_THAT(error_of("ply\nformat ascii 1.0\nelement vertex 3\n", "ply"), Catch::Contains("before 'end_header'"));
  CHECK_THAT(error_of("plyx\n", "ply"), Catch::Contains("line 1: expected the PLY signature 'ply'"));
  CHECK_THAT(error_of("ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                      "element face 4\nproperty list uchar float vertex_indices\nend_header\n", "ply"),
             Catch::Contains("line 8: face property 'vertex_indices' must hold integers"));
  CHECK_THAT(error_of("ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                      "element face 4\nproperty int vertex_indices\nend_header\n", "ply"),
             Catch::Contains("line 8: face property 'vertex_indices' is not a list"));
  CHECK_THAT(error_of("ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                      "end_header\n" + tet_v, "ply"),
             Catch::Contains("no element 'face'"));
  CHECK_THAT(error_of("ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nbogus line\n", "ply"),
             Catch::Contains("line 5: unknown header keyword 'bogus'"));
}

TEST_CASE("read: PLY counts are bounded by the bytes left before anything is allocated", "[io][mesh][parsers]")
{
  CHECK_THAT(error_of(ply_ascii_header("2147483648") + tet_v + tet_f, "ply"),
             Catch::Contains("line 7: element 'face' declares 2147483648 records, but the rest of the file can hold at most"));
  // binary: a face list count of 2^31 - 1
  std::string bin = "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                    "property float z\nelement face 4\nproperty list int int vertex_indices\nend_header\n";
  const float v[12] = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  for(float c : v)
    put(bin, c, false);
  put(bin, std::int32_t(2147483647), false);
  for(std::int32_t i : { 0, 2, 1 })
    put(bin, i, false);
  const auto start = std::chrono::steady_clock::now();
  CHECK_THAT(error_of(bin, "ply"), Catch::Contains("face 0: list 'vertex_indices' declares 2147483647 items"));
  CHECK(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < 1.0);
  // binary: a vertex count the bytes cannot hold
  std::string big = bin;
  big.replace(big.find("vertex 4"), 8, "vertex 4000000000");
  CHECK_THAT(error_of(big, "ply"), Catch::Contains("line 3: element 'vertex' declares 4000000000 records"));
  // a negative list count in a signed count type
  std::string neg = bin;
  neg.replace(neg.size() - 16, 4, std::string("\xff\xff\xff\xff", 4));
  CHECK_THAT(error_of(neg, "ply"), Catch::Contains("face 0: list 'vertex_indices' has a negative count -1"));
}

TEST_CASE("read: PLY indices are integers in range; values fit their type", "[io][mesh][parsers]")
{
  CHECK_THAT(error_of(ply_ascii_header() + tet_v + "3 0 2 1\n3 0 1 3.5\n3 0 3 2\n3 1 2 3\n", "ply"),
             Catch::Contains("line 15: face 1: list 'vertex_indices' '3.5' is not an integer"));
  CHECK_THAT(error_of(ply_ascii_header() + tet_v + "3 0 2 1\n3 0 1 -1\n3 0 3 2\n3 1 2 3\n", "ply"),
             Catch::Contains("line 15: face 1: vertex index -1 is negative"));
  CHECK_THAT(error_of(ply_ascii_header() + tet_v + "3 0 2 1\n3 0 1 9\n3 0 3 2\n3 1 2 3\n", "ply"),
             Catch::Contains("line 15: face 1: vertex index 9 is out of range (the file has 4 vertices)"));
  CHECK_THAT(error_of(ply_ascii_header() + tet_v + "3 0 2 1\n300 0 1 2\n3 0 3 2\n3 1 2 3\n", "ply"),
             Catch::Contains("line 15: face 1: list count 'vertex_indices' '300' is out of range for its type"));
  CHECK_THAT(error_of(ply_ascii_header() + tet_v + "3 0 2 1\n2 0 1\n3 0 3 2\n3 1 2 3\n", "ply"),
             Catch::Contains("line 15: face 1 has 2 vertices (a face needs at least 3)"));
  CHECK_THAT(error_of(ply_ascii_header() + tet_v + "3 0 2 1\n3 0 1", "ply"),
             Catch::Contains("line 15: face 1: list 'vertex_indices' declares 3 items but the rest of the file cannot hold them"));
  CHECK_THAT(error_of(ply_ascii_header() + tet_v + "3 0 2 1\n3 0 1           ", "ply"),
             Catch::Contains("line 15: the file ends inside face 1"));
  CHECK_THAT(error_of(ply_ascii_header() + "0 0 0\n1 nan 0\n0 1 0\n0 0 1\n" + tet_f, "ply"),
             Catch::Contains("line 11: vertex 1 has a non-finite coordinate 'nan'"));
}

TEST_CASE("read: PLY in every encoding, with any scalar types and skipped elements, gives the tetrahedron",
          "[io][mesh][parsers]")
{
  for(int encoding = 0; encoding < 3; ++encoding)
  {
    INFO("encoding " << encoding);
    const bool big = (encoding == 2);
    std::string text = std::string("ply\nformat ") +
                       (encoding == 0 ? "ascii" : big ? "binary_big_endian" : "binary_little_endian") +
                       " 1.0\ncomment skipped\nobj_info skipped\nelement material 1\nproperty uchar red\n"
                       "property list ushort short junk\nelement vertex 4\nproperty int16 id\nproperty double z\n"
                       "property uchar red\nproperty float64 x\nproperty list uint8 float normal\nproperty int y\n"
                       "element face 4\nproperty uint flags\nproperty list uint16 uint32 vertex_index\n"
                       "element edge 1\nproperty int a\nend_header\n";
    const double p[4][3] = { { 0, 0, 0 }, { 1.0 / 3, 0, 0 }, { 0, 1, 0 }, { 0, 0, 0.1 } };
    const std::uint32_t f[4][3] = { { 0, 2, 1 }, { 0, 1, 3 }, { 0, 3, 2 }, { 1, 2, 3 } };
    std::ostringstream a;
    a.precision(17);
    if(encoding == 0)
    {
      a << "7 2 -1 5\n";
      for(int i = 0; i < 4; ++i)
        a << -i << " " << p[i][2] << " 255 " << p[i][0] << " 2 0.5 0.25 " << int(p[i][1]) << "\n";
      for(int i = 0; i < 4; ++i)
        a << "9 3 " << f[i][0] << " " << f[i][1] << " " << f[i][2] << "\n";
      a << "-4\n";
      text += a.str();
    }
    else
    {
      put(text, std::uint8_t(7), big);
      put(text, std::uint16_t(2), big);
      put(text, std::int16_t(-1), big);
      put(text, std::int16_t(5), big);
      for(int i = 0; i < 4; ++i)
      {
        put(text, std::int16_t(-i), big);
        put(text, p[i][2], big);
        put(text, std::uint8_t(255), big);
        put(text, p[i][0], big);
        put(text, std::uint8_t(2), big);
        put(text, 0.5f, big);
        put(text, 0.25f, big);
        put(text, std::int32_t(p[i][1]), big);
      }
      for(int i = 0; i < 4; ++i)
      {
        put(text, std::uint32_t(9), big);
        put(text, std::uint16_t(3), big);
        for(int k = 0; k < 3; ++k)
          put(text, f[i][k], big);
      }
      put(text, std::int32_t(-4), big);
    }
    const Soup s = parse(text, "ply");
    REQUIRE(s.points.size() == 4);
    for(int i = 0; i < 4; ++i)
      for(int k = 0; k < 3; ++k)
        CHECK(same_bits(s.points[std::size_t(i)][k], p[i][k]));
    REQUIRE(s.polygons.size() == 4);
    for(int i = 0; i < 4; ++i)
      CHECK(s.polygons[std::size_t(i)] == std::vector<std::size_t>{ f[i][0], f[i][1], f[i][2] });
  }
}

// ------------------------------------------------------------------------------------ OFF

TEST_CASE("read: OFF degrees and indices are integers in range, bounded by the line", "[io][mesh][parsers]")
{
  // 2^31 - 1 corners declared in a tiny file: an error at once, not a growing allocation
  const auto start = std::chrono::steady_clock::now();
  CHECK(error_of("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2147483647 0 1 2\n", "off") ==
        "mesh file 't.off': line 6: face 0 declares 2147483647 vertices but the file ends after 3");
  CHECK(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < 1.0);
  CHECK_THAT(error_of("OFF\n4 4 0\n" + tet_v + "3 0 2 1\n4 0 1 3\n3 0 3 2\n3 1 2 3\n", "off"),
             Catch::Contains("line 8: face 1 declares 4 vertices but its line holds only 3"));
  CHECK_THAT(error_of("OFF\n4 4 0\n" + tet_v + "3 0 2 1\n3.5 0 1 3\n3 0 3 2\n3 1 2 3\n", "off"),
             Catch::Contains("line 8: face 1: the number of vertices '3.5' is not a non-negative integer"));
  CHECK_THAT(error_of("OFF\n4 4 0\n" + tet_v + "3 0 2 1\n99999999999999999999999 0 1 3\n", "off"),
             Catch::Contains("line 8: face 1 declares 99999999999999999999999 vertices"));
  CHECK_THAT(error_of("OFF\n4 4 0\n" + tet_v + "3 0 2 1\n3 0 1 4294967296\n3 0 3 2\n3 1 2 3\n", "off"),
             Catch::Contains("line 8: face 1: vertex index 4294967296 is out of range (the file has 4 vertices)"));
  CHECK_THAT(error_of("OFF\n4 4 0\n" + tet_v + "3 0 2 1\n3 0 -1 3\n3 0 3 2\n3 1 2 3\n", "off"),
             Catch::Contains("line 8: face 1: vertex index '-1' is not a non-negative integer"));
  CHECK_THAT(error_of("OFF\n4 4 0\n" + tet_v + "3 0 2 1\n3 0 1 3e0\n3 0 3 2\n3 1 2 3\n", "off"),
             Catch::Contains("line 8: face 1: vertex index '3e0' is not a non-negative integer"));
  CHECK_THAT(error_of("OFF\n4 4 0\n" + tet_v + "3 0 2 1\n2 0 1\n3 0 3 2\n3 1 2 3\n" + pad, "off"),
             Catch::Contains("line 8: face 1 has 2 vertices (a face needs at least 3)"));
}

TEST_CASE("read: OFF header counts are bounded by the file, and must match its content", "[io][mesh][parsers]")
{
  CHECK_THAT(error_of("OFF\n4 2147483648 0\n" + tet_v + tet_f, "off"),
             Catch::Contains("line 2: the header declares 4 vertices and 2147483648 faces, but the remaining"));
  CHECK_THAT(error_of("OFF\n4 2 0\n" + tet_v + tet_f, "off"),
             Catch::Contains("line 9: unexpected content after the 2 faces the header declares"));
  // one vertex line missing: the first face line is read as the last vertex (a line holding
  // at least 3 numbers), so the faces come up short
  CHECK_THAT(error_of("OFF\n5 4 0\n" + tet_v + tet_f + pad, "off"),
             Catch::Contains("line 11: the file ends after 3 of the 4 faces the header declares"));
  CHECK_THAT(error_of("OFF\n5 1 0\n0.0 0.0 0.0\n0.0 0.0 0.0\n0.0 0.0 0.0\n0.0 0.0 0.0\n0.0 0.0 0.0\n", "off"),
             Catch::Contains("line 7: the file ends after 0 of the 1 faces the header declares"));
  CHECK_THAT(error_of("OFF\n5 1 0\n0.0 0.0 0.0\n0.0 0.0 0.0\n0.0 0.0 0.0\n0.0 0.0 0.0\n", "off"),
             Catch::Contains("line 6: the file ends after 4 of the 5 vertices the header declares"));
  CHECK_THAT(error_of("OFF\n4 4 0\n0 0 0\n1 0\n0 1 0\n0 0 1\n" + tet_f + pad, "off"),
             Catch::Contains("line 4: vertex 1 has 2 coordinates, expected 3 (x y z)"));
  CHECK_THAT(error_of("OFFF\n4 4 0\n", "off"), Catch::Contains("line 1: expected the keyword OFF, found 'OFFF'"));
  CHECK_THAT(error_of("4OFF\n4 4 0\n", "off"), Catch::Contains("line 1: the OFF variant '4OFF' is not supported"));
  CHECK_THAT(error_of("COFF BINARY\n", "off"), Catch::Contains("binary COFF is not supported"));
  CHECK_THAT(error_of("OFF\n4 four 0\n", "off"), Catch::Contains("line 2: expected the counts 'vertices faces edges', found 'four'"));
  CHECK_THAT(error_of("", "off"), Catch::Contains("the file is empty"));
  // a COFF line cut inside its colour (CGAL's colour scanner read past the buffer)
  CHECK_THAT(error_of("COFF\n4 4 0\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n0 1 0 0 0 255 255\n0 0 1 25", "off"),
             Catch::Contains("line 6: the file ends after 0 of the 4 faces the header declares"));
}

TEST_CASE("read: OFF variants, comments and colours give the same tetrahedron", "[io][mesh][parsers]")
{
  const Soup plain = parse(tet_off, "off");
  const std::vector<std::string> variants = {
    "# comment first\nOFF 4 4 0\n" + tet_v + tet_f,
    "COFF\n4 4 0\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n0 1 0 1 1 1 1\n0 0 1 0.5 0.5 0.5 1\n"
    "3 0 2 1 255 0 0\n3 0 1 3 0.5 0.5 0.5 1\n3 0 3 2\n3 1 2 3 7\n",
    "NOFF\r\n4 4 0\r\n0 0 0 0 0 1\r\n1 0 0 0 0 1\r\n0 1 0 0 0 1\r\n0 0 1 0 0 1\r\n3 0 2 1\r\n3 0 1 3\r\n3 0 3 2\r\n3 1 2 3\r\n",
    "CNOFF\n4 4\n\n# vertices\n0 0 0 0 0 1 1 1 1\n1 0 0 0 0 1 1 1 1 # x\n+0 1 0 0 0 1 1 1 1\n0 0 1.0e0 0 0 1 1 1 1\n" + tet_f + "\n# end\n",
    "STOFF\n4 4 0\n0 0 0 0.5 0.5\n1 0 0 0.5 0.5\n0 1 0 0.5 0.5\n0 0 1 0.5 0.5\n" + tet_f,
    "OFF\n4 4 0\n" + tet_v + "3\t0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3" };
  for(const std::string& text : variants)
  {
    INFO(text);
    const Soup s = parse(text, "off");
    CHECK(s.points == plain.points);
    CHECK(s.polygons == plain.polygons);
  }
}

TEST_CASE("read: binary OFF gives the tetrahedron; its counts and indices are checked", "[io][mesh][parsers]")
{
  for(bool normals : { false, true })
  {
    std::string bin = normals ? "# c\nNOFF BINARY\n" : "OFF BINARY\n";
    for(std::int32_t c : { 4, 4, 0 })
      put(bin, c, true);
    const float v[4][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
    for(const auto& p : v)
    {
      for(float c : p)
        put(bin, c, true);
      if(normals)
        for(float c : { 0.f, 0.f, 1.f })
          put(bin, c, true);
    }
    const std::int32_t f[4][3] = { { 0, 2, 1 }, { 0, 1, 3 }, { 0, 3, 2 }, { 1, 2, 3 } };
    for(int i = 0; i < 4; ++i)
    {
      put(bin, std::int32_t(3), true);
      for(std::int32_t k : f[i])
        put(bin, k, true);
      put(bin, std::int32_t(i % 2 ? 3 : 0), true); // colour components
      for(int k = 0; k < (i % 2 ? 3 : 0); ++k)
        put(bin, 0.5f, true);
    }
    const Soup s = parse(bin, "off");
    const Soup t = parse(tet_off, "off");
    CHECK(s.points == t.points);
    CHECK(s.polygons == t.polygons);
    std::string huge = bin;
    huge.replace(huge.find("BINARY\n") + 7 + 4, 4, std::string("\x7f\xff\xff\xff", 4));
    CHECK_THAT(error_of(huge, "off"), Catch::Contains("binary OFF: the header declares 4 vertices and 2147483647 faces"));
    std::string index = bin;
    index.replace(index.size() - 12 - 4 - 4, 4, std::string("\0\0\0\x09", 4)); // last face, last index
    CHECK_THAT(error_of(index, "off"), Catch::Contains("face 3: vertex index 9 is out of range"));
    CHECK_THAT(error_of(bin + "x", "off"), Catch::Contains("binary OFF: 1 bytes after the 4 faces"));
  }
}

TEST_CASE("read: a malformed coordinate in a small OFF is reported at once, naming line and vertex",
          "[io][mesh][parsers]")
{
  std::string text = "OFF\n60 1 0\n";
  for(int i = 0; i < 60; ++i)
    text += (i == 37 ? std::string("0.5 0.5.25 1") : std::to_string(i) + " 0.123456 0.654321") + "\n";
  text += "3 0 1 2\n";
  const auto start = std::chrono::steady_clock::now();
  CHECK_THAT(error_of(text, "off"), Catch::Contains("line 40: vertex 37: coordinate '0.5.25' is not a number"));
  CHECK(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < 1.0);
  CHECK_THAT(error_of("OFF\n4 4 0\n0 0 0\n1 inf 0\n0 1 0\n0 0 1\n" + tet_f, "off"),
             Catch::Contains("line 4: vertex 1 has a non-finite coordinate 'inf'"));
  CHECK_THAT(error_of("OFF\n4 4 0\n0 0 0\n1 1e999 0\n0 1 0\n0 0 1\n" + tet_f, "off"),
             Catch::Contains("line 4: vertex 1 has a non-finite coordinate '1e999'"));
  CHECK_THAT(error_of("OFF\n4 4 0\n0 0 0\n1 0x1p3 0\n0 1 0\n0 0 1\n" + tet_f, "off"),
             Catch::Contains("line 4: vertex 1: coordinate '0x1p3' is not a number"));
}

// ------------------------------------------------------------------------------------ OBJ

TEST_CASE("read: OBJ corners, relative indices and skipped records", "[io][mesh][parsers]")
{
  const Soup s = parse("# c\nmtllib x.mtl\no tet\n" + obj_v +
                           "vt 0 0\nvn 0 0 1\ng a\nusemtl m\ns off\nf -4/1/1 -2/1/1 -3/1/1\nf 1//1 2//1 4//1\n"
                           "f 1/1 4/1 3/1\nl 1 2\nf 2 3 4 # last\n",
                       "obj");
  REQUIRE(s.points.size() == 4);
  CHECK(s.polygons == Polygons{ { 0, 2, 1 }, { 0, 1, 3 }, { 0, 3, 2 }, { 1, 2, 3 } });
}

TEST_CASE("read: OBJ index errors and a truncated file name the line", "[io][mesh][parsers]")
{
  CHECK_THAT(error_of(obj_v + "f 1 3 2\nf 1 2 100000000000\nf 1 4 3\nf 2 3 4\n", "obj"),
             Catch::Contains("line 6: face 1: vertex index 100000000000 is out of range (the file has 4 vertices)"));
  CHECK_THAT(error_of(obj_v + "f 1 3 2\nf 1 2 99999999999999999999999\n", "obj"),
             Catch::Contains("line 6: face 1: vertex index 99999999999999999999999 is out of range"));
  CHECK_THAT(error_of(obj_v + "f 1 3 2\nf 1 2 1e11\nf 1 4 3\nf 2 3 4\n", "obj"),
             Catch::Contains("line 6: face 1: vertex index '1e11' is not an integer"));
  CHECK_THAT(error_of(obj_v + "f 1 3 2\nf 0 2 4\n", "obj"),
             Catch::Contains("line 6: face 1: vertex index 0 is not valid (OBJ indices start at 1)"));
  CHECK_THAT(error_of(obj_v + "f 1 3 2\nf -1 -2 -5\n", "obj"),
             Catch::Contains("line 6: face 1: relative vertex index -5 is out of range (4 vertices so far in the file)"));
  CHECK_THAT(error_of(obj_v + "f 1 3 2\nf 1/ 2 4\n", "obj"),
             Catch::Contains("line 6: face 1: corner '1/' is not of the form i, i/t, i//n or i/t/n"));
  CHECK_THAT(error_of(obj_v + "f 1 3 2\nf 1 2\n", "obj"),
             Catch::Contains("line 6: face 1 has 2 vertices (a face needs at least 3)"));
  CHECK_THAT(error_of("v 0 0\n", "obj"), Catch::Contains("line 1: vertex 0 has 2 coordinates, expected 3"));
  // cut short in the middle of the last face line: an error, not a damaged face
  CHECK_THAT(error_of(obj_v + "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3", "obj"),
             Catch::Contains("line 8: face 3: the file ends in the middle of the face's line"));
}

// ------------------------------------------------------------------------------------ STL

TEST_CASE("read: STL binary size must match its triangle count; ASCII structure names the line",
          "[io][mesh][parsers]")
{
  std::string stl(80, ' ');
  put(stl, std::uint32_t(2), false);
  for(int t = 0; t < 2; ++t)
  {
    for(int k = 0; k < 12; ++k)
      put(stl, float(k % 4 == 0 ? 0 : (k + t) % 3), false);
    stl += std::string(2, '\0');
  }
  REQUIRE(stl.size() == 184);
  CHECK_THAT(error_of(stl + "xyz", "stl"),
             Catch::Contains("its header declares 2 triangles, which take 184 bytes, but the file has 187"));
  std::string huge = stl;
  huge.replace(80, 4, std::string("\0\0\0\x80", 4));
  CHECK_THAT(error_of(huge, "stl"), Catch::Contains("its header declares 2147483648 triangles"));
  CHECK_THAT(error_of("solid t\nfacet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 1 1 0\n"
                      "vertex 0 1 0\nendloop\nendfacet\nendsolid t\n", "stl"),
             Catch::Contains("line 7: facet 0 has more than 3 vertices"));
  CHECK_THAT(error_of("solid t\nfacet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 1 1 0\n"
                      "endloop\nendfacet\n", "stl"),
             Catch::Contains("the file ends without 'endsolid'"));
  CHECK_THAT(error_of("solid t\nfacet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex 1 0,5 0\n", "stl"),
             Catch::Contains("line 5: facet 0: coordinate '0,5' is not a number"));
  CHECK_THAT(error_of("solid t\nfacet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 1 1 0\n", "stl"),
             Catch::Contains("the file ends inside facet 0"));
  CHECK_THAT(error_of("hello", "stl"), Catch::Contains("neither ASCII STL"));
}

// ---------------------------------------------------------------- same result as CGAL's readers

TEST_CASE("read: valid files of every format give CGAL's points bit for bit and the same faces",
          "[io][mesh][parsers]")
{
  // a closed surface with awkward coordinates: a perturbed octahedron subdivided once
  CGAL::Random random(17);
  std::vector<Point> points;
  Polygons faces;
  {
    std::vector<Point> p = { Point(1, 0, 0), Point(-1, 0, 0), Point(0, 1, 0),
                             Point(0, -1, 0), Point(0, 0, 1), Point(0, 0, -1) };
    for(Point& q : p)
      q = Point(q.x() * 1e3 + random.get_double(-1, 1) * 1e-7, q.y() * 3.7 + random.get_double(-1, 1),
                q.z() / 3 + random.get_double(-1, 1) * 1e-300);
    points = p;
    faces = { { 0, 2, 4 }, { 2, 1, 4 }, { 1, 3, 4 }, { 3, 0, 4 }, { 2, 0, 5 }, { 1, 2, 5 }, { 3, 1, 5 }, { 0, 3, 5 } };
  }
  Temp_dir dir("cgal_same");
  struct Case { std::string name; bool binary; };
  for(const Case& c : { Case{ "m.off", false }, Case{ "m.obj", false }, Case{ "m_ascii.ply", false },
                        Case{ "m_binary.ply", true }, Case{ "m_ascii.stl", false }, Case{ "m_binary.stl", true } })
  {
    INFO(c.name);
    const std::string path = dir.path(c.name);
    REQUIRE(CGAL::IO::write_polygon_soup(path, points, faces,
                                         CGAL::parameters::stream_precision(17).use_binary_mode(c.binary)));
    std::vector<Point> cgal_points;
    Polygons cgal_faces;
    REQUIRE(CGAL::IO::read_polygon_soup(path, cgal_points, cgal_faces));
    std::string bytes;
    SVIO::read_whole_file(path, path, SVIO::max_mesh_file_bytes, bytes);
    const std::string ext = SVIO::internal::lower_case_extension(path);
    const Soup ours = parse(bytes, ext);
    REQUIRE(ours.points.size() == cgal_points.size());
    for(std::size_t i = 0; i < cgal_points.size(); ++i)
      for(int k = 0; k < 3; ++k)
        CHECK(same_bits(ours.points[i][k], cgal_points[i][k]));
    CHECK(ours.polygons == cgal_faces);
  }
}

TEST_CASE("read: from memory gives what the file gives, named as asked", "[io][mesh][parsers]")
{
  Temp_dir dir("memory");
  const std::string path = dir.file("tet.off", tet_off);
  Surface_mesh from_file, from_memory;
  const SVIO::Mesh_reading_report a = SVIO::read_checked_triangle_mesh(path, from_file);
  const SVIO::Mesh_reading_report b =
      SVIO::read_checked_triangle_mesh_from_memory(tet_off.data(), tet_off.size(), "off", from_memory);
  CHECK(a.number_of_triangles == b.number_of_triangles);
  CHECK(a.mesh_vertex_of_point == b.mesh_vertex_of_point);
  REQUIRE(from_file.number_of_vertices() == from_memory.number_of_vertices());
  for(auto v : vertices(from_file))
    CHECK(from_file.point(v) == from_memory.point(v));
  CHECK(error_of(tet_off, "xyz") == "mesh file 't.xyz': unknown format 'xyz' (expected off, obj, ply or stl)");
  // the size is checked before a byte is read
  Surface_mesh m;
  REQUIRE_THROWS_WITH(SVIO::read_checked_triangle_mesh_from_memory(tet_off.data(), SVIO::max_mesh_file_bytes + 1,
                                                                   "off", m, "big"),
                      Catch::Contains("mesh file 'big': the file is too large"));
  const std::string bad = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n";
  const std::string file_message = [&] {
    try { SVIO::read_checked_triangle_mesh(dir.file("bad.off", bad), m); }
    catch(const SVIO::Input_error& e) { return std::string(e.what()); }
    return std::string();
  }();
  CHECK(file_message == "mesh file '" + dir.path("bad.off") + "': " + error_of(bad, "off").substr(std::string("mesh file 't.off': ").size()));
}

// --------------------------------------------------------------------------- messages

TEST_CASE("read: messages escape bytes outside printable ASCII and cap echoed tokens", "[io][mesh][parsers]")
{
  const std::string utf8 = error_of("OFF\n4 4 0\n0 0 0\n1\xC3\xA9 0 0\n0 1 0\n0 0 1\n" + tet_f, "off");
  CHECK_THAT(utf8, Catch::Contains("line 4: vertex 1: coordinate '1\\xC3\\xA9' is not a number"));
  CHECK(printable_ascii(utf8));
  const std::string long_token = error_of("OFF\n4 4 0\n0 0 0\n1 " + std::string(5000, 'x') + " 0\n", "off");
  CHECK_THAT(long_token, Catch::Contains("'" + std::string(40, 'x') + "...'"));
  CHECK(long_token.size() < 200);
  const std::string nul = error_of(std::string("OFF\n4 4 0\n0 0 0\n1 \0 0\n", 22) + "0 1 0\n0 0 1\n" + tet_f, "off");
  CHECK_THAT(nul, Catch::Contains("'\\x00'"));
  // the file's own name is escaped too
  Temp_dir dir("names");
  Surface_mesh m;
  const std::string odd = dir.path("caf\xC3\xA9\x01.off");
  REQUIRE_THROWS_WITH(SVIO::read_checked_triangle_mesh(odd, m),
                      Catch::Contains("caf\\xC3\\xA9\\x01.off'") && Catch::Contains("no such file"));
}

TEST_CASE("read: a mesh path that is a folder or missing says so", "[io][mesh][parsers]")
{
  Temp_dir dir("folder");
  std::filesystem::create_directories(dir.path("mesh.off"));
  Surface_mesh m;
  REQUIRE_THROWS_WITH(SVIO::read_checked_triangle_mesh(dir.path("mesh.off"), m),
                      "mesh file '" + dir.path("mesh.off") + "': is a directory, not a file");
  REQUIRE_THROWS_WITH(SVIO::read_checked_triangle_mesh(dir.path("none.off"), m),
                      "mesh file '" + dir.path("none.off") + "': cannot open the file: no such file");
}

// ------------------------------------------------------------------- zero-area faces

TEST_CASE("read: an exactly collinear face is refused, a thin but valid one is not", "[io][mesh][parsers]")
{
  // exact zero area: no normal, a real defect
  CHECK_THAT(error_of("OFF\n7 5 0\n" + tet_v + "3 0 0\n4 1 1\n5 2 2\n" + tet_f + "3 4 5 6\n", "off"),
             Catch::Contains("face 4 has zero area"));
  // a 1 x 2e-9 rhombus made of two triangles (and a tetrahedron far away): the reader takes it,
  // whatever the library later decides about needles
  Surface_mesh mesh;
  const std::string rhombus = "OFF\n4 2 0\n0 0 0\n1 1e-9 0\n2 0 0\n1 -1e-9 0\n3 0 3 2\n3 0 2 1\n";
  REQUIRE_NOTHROW(SVIO::read_checked_triangle_mesh_from_memory(rhombus.data(), rhombus.size(), "off", mesh));
  CHECK(faces(mesh).size() == 2);
}

// ---------------------------------------------------------------- polygon triangulation

TEST_CASE("read: a 100,000-gon is triangulated fast, with the polygon's area and orientation",
          "[io][mesh][parsers]")
{
  for(bool ccw : { true, false })
  {
    INFO("counterclockwise " << ccw);
    const std::size_t n = 100000;
    const std::string text = polygon_off(n, ccw);
    Surface_mesh mesh;
    const auto start = std::chrono::steady_clock::now();
    const SVIO::Mesh_reading_report report =
        SVIO::read_checked_triangle_mesh_from_memory(text.data(), text.size(), "off", mesh);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    CHECK(seconds < 10.0);
    CHECK(report.polygons_triangulated == 1);
    CHECK(faces(mesh).size() == n - 2);
    const double area = 0.5 * double(n) * std::sin(2 * pi / double(n));
    CHECK(PMP::area(mesh) == Approx(area).epsilon(1e-9));
    std::size_t wrong = 0;
    for(auto f : faces(mesh))
      if(PMP::compute_face_normal(f, mesh).z() != (ccw ? 1.0 : -1.0))
        ++wrong;
    CHECK(wrong == 0);
  }
}

TEST_CASE("read: a large non-convex polygon is triangulated inside, a non-simple one is refused",
          "[io][mesh][parsers]")
{
  // a comb: 600 teeth along x, 2401 corners, area known
  const int teeth = 600;
  std::vector<std::array<double, 2>> c;
  for(int t = 0; t < teeth; ++t)
  {
    c.push_back({ { double(2 * t), 0 } });
    c.push_back({ { double(2 * t), 10 } });
    c.push_back({ { double(2 * t + 1), 10 } });
    c.push_back({ { double(2 * t + 1), 1 } });
  }
  c.push_back({ { double(2 * teeth), 1 } });
  c.push_back({ { double(2 * teeth), -1 } });
  std::reverse(c.begin(), c.end()); // counterclockwise
  auto off_of = [](const std::vector<std::array<double, 2>>& corners) {
    std::ostringstream s;
    s << "OFF\n" << corners.size() << " 1 0\n";
    for(const auto& p : corners)
      s << p[0] << " " << p[1] << " 0\n";
    s << corners.size();
    for(std::size_t k = 0; k < corners.size(); ++k)
      s << " " << k;
    s << "\n";
    return s.str();
  };
  double area = 0;
  for(std::size_t k = 0; k < c.size(); ++k)
    area += c[k][0] * c[(k + 1) % c.size()][1] - c[(k + 1) % c.size()][0] * c[k][1];
  area = std::abs(area) / 2;
  const std::string comb = off_of(c);
  Surface_mesh mesh;
  REQUIRE_NOTHROW(SVIO::read_checked_triangle_mesh_from_memory(comb.data(), comb.size(), "off", mesh));
  CHECK(faces(mesh).size() == c.size() - 2);
  CHECK(PMP::area(mesh) == Approx(area));

  // a corner moved beyond the comb's end: its two edges cross the teeth
  std::vector<std::array<double, 2>> crossing = c;
  crossing[101] = { { double(2 * teeth + 50), 5 } };
  CHECK_THAT(error_of(off_of(crossing), "off"),
             Catch::Contains("face 0 cannot be triangulated: it is not a simple planar polygon"));
  // a corner on another edge (the polygon touches itself)
  // two corners on one point (the polygon touches itself there)
  std::vector<std::array<double, 2>> touching = c;
  touching[700] = touching[500];
  CHECK_THAT(error_of(off_of(touching), "off"), Catch::Contains("face 0 cannot be triangulated"));
  // the same regular 20,000-gon with two corners swapped, as in the corpus: refused fast
  std::string star = polygon_off(20000);
  const auto start = std::chrono::steady_clock::now();
  Polygons p;
  std::vector<Point> q;
  SVIO::mesh_parsers::parse_mesh(star.data(), star.size(), "off", q, p);
  std::swap(p[0][7000], p[0][7001]);
  REQUIRE_THROWS_WITH(SVIO::build_checked_triangle_mesh(q, p, mesh),
                      "face 0 cannot be triangulated: it is not a simple planar polygon");
  CHECK(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < 5.0);
}

// ------------------------------------------------------------------------ record files

TEST_CASE("read: a sites or breaklines path that is a folder, missing, or unreadable says so",
          "[io][sites][breaklines]")
{
  Temp_dir dir("records");
  std::filesystem::create_directories(dir.path("folder"));
  REQUIRE_THROWS_WITH(SVIO::read_sites_file(dir.path("folder")),
                      "sites file '" + dir.path("folder") + "': is a directory, not a file");
  REQUIRE_THROWS_WITH(SVIO::read_sites_file(dir.path("none.xyz")),
                      "sites file '" + dir.path("none.xyz") + "': cannot open the file: no such file");
  REQUIRE_THROWS_WITH(SVIO::read_breaklines_file(dir.path("folder")),
                      "breaklines file '" + dir.path("folder") + "': is a directory, not a file");
  REQUIRE_THROWS_WITH(SVIO::read_breaklines_file(dir.path("none.txt")),
                      "breaklines file '" + dir.path("none.txt") + "': cannot open the file: no such file");
  const std::string locked = dir.file("locked.xyz", "0 0 0\n");
  std::filesystem::permissions(locked, std::filesystem::perms::none);
  if(::geteuid() != 0) // root reads anything
    REQUIRE_THROWS_WITH(SVIO::read_sites_file(locked), Catch::Contains("permission denied"));
  const std::string pairs = dir.file("lines.txt", "0 1\n# c\n2 3\n");
  const std::vector<SVIO::Index_pair_record> read = SVIO::read_breaklines_file(pairs);
  REQUIRE(read.size() == 2);
  CHECK(read[1].line == 3);
}

TEST_CASE("read: record files hold one bounded line at a time and escape what they echo", "[io][sites]")
{
  std::istringstream non_ascii("0.5 0.5 0\n0.5 0.5 1\xff\xfe\n");
  REQUIRE_THROWS_WITH(SVIO::read_sites_file(non_ascii), "sites file line 2: '1\\xFF\\xFE' is not a number");
  std::istringstream long_line("0.5 0.5 0\n" + std::string(70000, ' ') + "1 2 3\n");
  REQUIRE_THROWS_WITH(SVIO::read_sites_file(long_line), "sites file line 2: the line is longer than 65536 bytes");
  std::istringstream pairs("0 1\n1 \xC3\xA9\n");
  REQUIRE_THROWS_WITH(SVIO::parse_index_pairs(pairs), "breaklines file line 2: '\\xC3\\xA9' is not a non-negative integer");
  // no line end at the end of the file: the last line still counts
  std::istringstream last("1 2 3\n4 5 6");
  CHECK(SVIO::read_sites_file(last).size() == 2);
}

} // namespace svd_test_read_checked_mesh
