// Copyright (c) 2026 The Surface_voronoi_diagram authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// libFuzzer harness of the whole pipeline on small meshes: the bytes are decoded into a
// polygon soup of at most 16 vertices (coordinates on a grid scaled by any power of two, so
// overflow, underflow, needles and caps are all reachable), a few sites and weights, and a
// metric (Euclidean, geodesic, biharmonic of the full spectrum or of dimension 10). The soup
// goes through the program's checks (build_checked_triangle_mesh), the
// library's validate_input(), then the diagram, whose invariants are checked:
//  - nothing crashes, hangs or trips a sanitizer or a CGAL assertion;
//  - an error is one of the package's exceptions (an input error or a numerical failure);
//  - on success the cell areas and the unreached area add up to the surface area.
// A violated invariant aborts, so libFuzzer keeps the input as a crash.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Biharmonic_embedding.h>
#include <CGAL/Surface_voronoi_diagram.h>
#include <CGAL/Surface_voronoi_diagram/Euclidean_embedding.h>
#include <CGAL/Surface_voronoi_diagram/Biharmonic_green_metric.h>
#include <CGAL/Surface_voronoi_diagram/Geodesic_metric.h>
#include <CGAL/Surface_voronoi_diagram/exceptions.h>
#include <CGAL/Surface_voronoi_diagram/validate_input.h>

#include <surface_voronoi/read_checked_mesh.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef std::pair<Mesh::Face_index, std::array<double, 3> > Location;
namespace SV = CGAL::Surface_voronoi;

class Bytes
{
public:
  Bytes(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  std::uint8_t next() { return at_ < size_ ? data_[at_++] : 0; }
  bool empty() const { return at_ >= size_; }

private:
  const std::uint8_t* data_;
  std::size_t size_, at_ = 0;
};

[[noreturn]] void violated(const char* what)
{
  std::fprintf(stderr, "fuzz_pipeline: invariant violated: %s\n", what);
  std::abort();
}

template <class Metric>
void run_diagram(const Mesh& mesh, Metric& metric, const std::vector<Location>& sites,
                 const std::vector<double>& weights)
{
  typedef CGAL::Surface_voronoi_diagram<Mesh, Metric> Diagram;
  const auto check = [&](const Diagram& vd) {
    double area = vd.statistics().unreached_area;
    for(std::size_t i = 0; i < vd.number_of_sites(); ++i)
    {
      const double a = vd.cell_area(i);
      if(!(a >= 0)) violated("a cell area is negative or NaN");
      area += a;
    }
    const double total = vd.statistics().surface_area;
    // an area computed from corners of size L carries an absolute rounding error of a few
    // ulps of L^2: on a needle (area far below L^2) that is most of the relative error
    double rounding = 0;
    for(auto h : halfedges(mesh))
      rounding += CGAL::to_double(CGAL::squared_distance(mesh.point(source(h, mesh)), mesh.point(target(h, mesh))));
    if(!(std::abs(area - total) <= 1e-6 * total + 64 * std::numeric_limits<double>::epsilon() * rounding))
    {
      std::fprintf(stderr, "cells and unreached: %.17g, surface: %.17g, sites %zu, faces %zu\n", area, total,
                   vd.number_of_sites(), std::size_t(num_faces(mesh)));
      violated("the cell areas do not add up to the surface area");
    }
  };
  if(weights.empty())
    check(Diagram(mesh, metric, sites));
  else
    check(Diagram(mesh, metric, sites, SV::parameters::site_weight_map(CGAL::make_property_map(weights))));
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  Bytes in(data, size);
  const std::uint8_t choice = in.next();
  // one scale for the whole mesh: 2^-1100 .. 2^1100 in steps of 2^9, so that areas and squared
  // lengths can underflow or overflow, and a second, small one for needles
  const int exponent = int(in.next()) * 9 - 1152;
  const int needle = -int(in.next() % 64);
  const std::size_t nv = 3 + in.next() % 14;
  std::vector<K::Point_3> points;
  for(std::size_t v = 0; v < nv; ++v)
  {
    double c[3];
    for(double& x : c)
    {
      const std::uint8_t b = in.next();
      x = std::ldexp(double(int(b & 0x7f) - 64) / 8. + ((b & 0x80) ? std::ldexp(1., needle) : 0.), exponent);
    }
    points.emplace_back(c[0], c[1], c[2]);
  }
  const std::size_t nf = 1 + in.next() % 24;
  std::vector<std::vector<std::size_t> > polygons(nf);
  for(std::vector<std::size_t>& p : polygons)
  {
    const std::size_t degree = 3 + (in.next() % 8 == 0 ? 1 : 0);
    for(std::size_t k = 0; k < degree; ++k) p.push_back(in.next() % nv);
  }

  Mesh mesh;
  try
  {
    svd_program::build_checked_triangle_mesh(points, polygons, mesh);
  }
  catch(const svd_program::Input_error&)
  {
    return 0;   // the reader refuses it, with a message: nothing more to check
  }

  const std::size_t faces = num_faces(mesh);
  const std::size_t ns = 1 + in.next() % 8;
  std::vector<Location> sites;
  std::vector<double> weights;
  const bool weighted = (choice & 0x10) != 0;
  for(std::size_t i = 0; i < ns; ++i)
  {
    const Mesh::Face_index f(Mesh::size_type(in.next() % faces));
    const double a = in.next(), b = in.next(), c = in.next();
    const double sum = a + b + c;
    sites.emplace_back(f, sum > 0 ? std::array<double, 3>{{ a / sum, b / sum, c / sum }}
                                  : std::array<double, 3>{{ 1. / 3, 1. / 3, 1. / 3 }});
    if(weighted) weights.push_back(double(int(in.next()) - 128) / 1024.);
  }
  // what validate_input() refuses is a documented precondition: not a case for the diagram
  const auto problems = weighted
    ? SV::validate_input(mesh, sites, SV::parameters::site_weight_map(CGAL::make_property_map(weights)))
    : SV::validate_input(mesh, sites);
  if(!problems.empty())
    return 0;

  try
  {
    switch(choice % 4)
    {
      case 0:
      {
        SV::Euclidean_embedding<Mesh> metric(mesh);
        run_diagram(mesh, metric, sites, weights);
        break;
      }
      case 1:
      {
        SV::Geodesic_metric<Mesh> metric(mesh);
        run_diagram(mesh, metric, sites, weights);
        break;
      }
      case 2:
      {
        // the full spectrum: a factorization of the Laplacian with one vertex held per
        // component, and two solves per site
        SV::Biharmonic_green_metric<Mesh> metric(mesh);
        run_diagram(mesh, metric, sites, weights);
        break;
      }
      default:
      {
        const std::size_t largest = CGAL::Biharmonic_embedding<Mesh>::maximum_dimension(mesh);
        if(largest == 0) return 0;
        CGAL::Biharmonic_embedding<Mesh> metric(mesh, SV::parameters::embedding_dimension(std::min<std::size_t>(10, largest)));
        run_diagram(mesh, metric, sites, weights);
      }
    }
  }
  catch(const SV::Input_error&) {}       // refused with a message: allowed
  catch(const SV::Numerical_error&) {}   // reported numerical failure: allowed
  return 0;
}
