// Copyright (c) 2026 The Surface_voronoi_diagram authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Writes one of the generated test shapes to an OFF file, so that the thin
// shells can be looked at, fed to other tools or stored as test data (the
// regression matrix's meshes were written this way). A tool of the test suite,
// built with it (-DSVD_BUILD_TESTS=ON), not an example of the library.
//
//   make_test_mesh KIND OUT.off [--vertices N] [--thickness T] [--digits D]
//
// KIND is one of sphere, torus, grid, lampshade, vase, pot, u_fold, slab, bowl,
// box. Exit status 0 on success, 2 on bad arguments, 1 if the file cannot be
// written.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <test_meshes.h>
#include <CGAL/boost/graph/IO/OFF.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>

namespace {

namespace SVG = svd_test::meshes;

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;

struct Usage_error : std::invalid_argument
{
  explicit Usage_error(const std::string& what) : std::invalid_argument(what) {}
};

void print_usage(std::ostream& os)
{
  os << "usage: make_test_mesh KIND OUT.off [--vertices N] [--thickness T] [--digits D]\n"
        "  KIND         sphere, torus, grid, lampshade, vase, pot, u_fold, slab, bowl or box\n"
        "  --vertices   wanted number of vertices (default 10000)\n"
        "  --thickness  wall thickness of the thin shells, relative to the shape's\n"
        "               bounding-box diagonal of 1 (default 0.005)\n"
        "  --digits     significant digits of the coordinates (default 17, lossless)\n";
}

// Whole-string parses: "12abc", "" or "-3" for a count must be rejected, not
// silently truncated as std::stoul and std::atof would.
std::size_t parse_count(const std::string& option, const std::string& text)
{
  if(text.empty() || text.find_first_not_of("0123456789") != std::string::npos)
    throw Usage_error(option + " expects a positive integer, got '" + text + "'");
  errno = 0;
  const unsigned long long value = std::strtoull(text.c_str(), nullptr, 10);
  if(errno == ERANGE || value == 0)
    throw Usage_error(option + " expects a positive integer, got '" + text + "'");
  return static_cast<std::size_t>(value);
}

double parse_number(const std::string& option, const std::string& text)
{
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(text.c_str(), &end);
  if(text.empty() || end != text.c_str() + text.size() || errno == ERANGE || !std::isfinite(value))
    throw Usage_error(option + " expects a number, got '" + text + "'");
  return value;
}

} // namespace

int main(int argc, char** argv)
{
  std::string kind, output;
  SVG::Shell_options options;
  std::size_t digits = 17;
  try {
    for(int i = 1; i < argc; ++i) {
      const std::string arg = argv[i];
      if(arg == "-h" || arg == "--help") {
        print_usage(std::cout);
        return 0;
      }
      if(arg == "--vertices" || arg == "--thickness" || arg == "--digits") {
        if(i + 1 >= argc)
          throw Usage_error(arg + " needs a value");
        const std::string value = argv[++i];
        if(arg == "--vertices")
          options.target_vertices = parse_count(arg, value);
        else if(arg == "--thickness")
          options.thickness = parse_number(arg, value);
        else {
          digits = parse_count(arg, value);
          if(digits > 17)
            throw Usage_error("--digits must be between 1 and 17, got '" + value + "'");
        }
      } else if(arg.size() > 1 && arg[0] == '-') {
        throw Usage_error("unknown option '" + arg + "'");
      } else if(kind.empty()) {
        kind = arg;
      } else if(output.empty()) {
        output = arg;
      } else {
        throw Usage_error("unexpected argument '" + arg + "'");
      }
    }
    if(kind.empty() || output.empty())
      throw Usage_error("expected KIND and OUT.off (run make_test_mesh --help)");

    Mesh mesh;
    SVG::make_shape(SVG::shape_from_name(kind), mesh, options);
    // Opened here rather than by CGAL, which reports a failure on its own
    // line before ours.
    std::ofstream os(output);
    if(!os || !CGAL::IO::write_OFF(os, mesh, CGAL::parameters::stream_precision(static_cast<int>(digits))) ||
       !os.flush()) {
      std::cerr << "make_test_mesh: error: cannot write '" << output << "'\n";
      return 1;
    }
    std::cout << kind << ": " << num_vertices(mesh) << " vertices, " << num_faces(mesh) << " faces -> " << output
              << "\n";
  } catch(const std::invalid_argument& e) {
    // Bad arguments and parameters the generators reject are both the
    // caller's to fix.
    std::cerr << "make_test_mesh: error: " << e.what() << "\n";
    return 2;
  } catch(const std::exception& e) {
    std::cerr << "make_test_mesh: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
