// Copyright (c) 2026 The Surface_voronoi_diagram authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The metric study: how far each metric's diagram is from the exact geodesic Voronoi diagram
// (CGAL's Surface_mesh_shortest_path with all sites as sources), on a zoo of thin shells and
// real models, for RVD, Euclidean propagation (EDBVD), the biharmonic embedding at several
// dimensions and the geodesic metric. Per row: the share of the area labelled differently
// from the geodesic diagram, broken cells (before -> after repair), the area reaching
// through a wall, and the wall-clock time including every precomputation (embedding,
// refinement). Prints one markdown table; not a test.
//
//   benchmark_metric_study [--models a,b,...] [--sites 100,1000] [--dims 3,6,10,20,50,100]
//                          [--samples S] [--seed K] [--refine-ratio R] [--trigger-ratio T] [--metrics rvd,euclidean,biharmonic,geodesic] [--data DIR] [--cgal DIR] [--quick]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Biharmonic_embedding.h>
#include <CGAL/Surface_voronoi_diagram.h>
#include <CGAL/Surface_voronoi_diagram/Euclidean_embedding.h>
#include <CGAL/Surface_voronoi_diagram/Geodesic_metric.h>
#include <CGAL/Surface_voronoi_diagram/refinement.h>
#include <CGAL/Surface_voronoi_diagram/sampling.h>

#include <surface_voronoi/read_checked_mesh.h>   // the surface_voronoi program's checked reader
#include <test_meshes.h>                         // the generated test shells

#include "fidelity.h"                            // this folder: the measurement against exact geodesics

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef CGAL::Polygon_mesh_processing::Face_location<Mesh, double> Location;
namespace SV = CGAL::Surface_voronoi;
namespace GEN = svd_test::meshes;

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

std::vector<std::string> split_list(const std::string& s)
{
  std::vector<std::string> out;
  std::stringstream in(s);
  std::string item;
  while(std::getline(in, item, ','))
    if(!item.empty()) out.push_back(item);
  return out;
}

std::vector<std::size_t> split_numbers(const std::string& s)
{
  std::vector<std::size_t> out;
  for(const std::string& x : split_list(s)) out.push_back(std::stoul(x));
  return out;
}

struct Options
{
  std::vector<std::string> models;
  std::vector<std::size_t> sites = { 100, 1000 };
  std::vector<std::size_t> dims = { 3, 6, 10, 20, 50, 100 };
  std::size_t samples = 20000;
  unsigned int seed = 1;
  // the defaults of refine_for_sites's named parameters refinement_edge_length_ratio and
  // refinement_trigger_ratio; --refine-ratio and --trigger-ratio change them
  double refine_ratio = 0.4;
  double trigger_ratio = 0.75;
  std::vector<std::string> metrics = { "rvd", "euclidean", "biharmonic", "geodesic" };
  bool wants(const std::string& metric) const { return std::find(metrics.begin(), metrics.end(), metric) != metrics.end(); }
  std::string data_dir = SVD_BENCH_DATA_DIR, cgal_dir = SVD_BENCH_CGAL_MESHES;
};

const char* generated_models[] = { "lampshade", "vase", "pot", "u_fold", "slab", "bowl", "box" };

// A generated thin shell (wall 0.2% of the size, >= 10k vertices) or a real model file.
bool load_model(const std::string& name, const Options& o, Mesh& m, std::string& what)
{
  for(const char* g : generated_models)
    if(name == g)
    {
      GEN::Shell_options so;
      so.target_vertices = 12000;
      so.thickness = 0.002;
      GEN::make_shape(GEN::shape_from_name(name), m, so);
      what = "generated, wall 0.2%";
      return true;
    }
  for(const std::string& dir : { o.data_dir, o.cgal_dir })
  {
    if(dir.empty()) continue;
    const std::filesystem::path p = std::filesystem::path(dir) / (name + ".off");
    if(std::filesystem::exists(p))
    {
      svd_program::read_checked_triangle_mesh(p.string(), m);
      what = p.parent_path().filename().string();
      return true;
    }
  }
  return false;
}

struct Measured
{
  svd_bench::Fidelity_report fidelity;
  double seconds = 0;
  std::string error;
};

template <class Diagram_maker>
Measured measure(svd_bench::Geodesic_reference<Mesh>& reference, const Options& o, double precomputation, Diagram_maker make)
{
  Measured r;
  try
  {
    const auto t0 = std::chrono::steady_clock::now();
    auto diagram = make();
    r.seconds = precomputation + seconds_since(t0);
    r.fidelity = svd_bench::measure_fidelity(*diagram, reference, o.samples, o.seed + 7, 2);
  }
  catch(const std::exception& e)
  {
    r.error = e.what();
  }
  return r;
}

void print_row(const std::string& model, std::size_t nv, std::size_t sites, const std::string& metric, const Measured& r)
{
  if(!r.error.empty())
  {
    std::printf("| %s | %zu | %zu | %s | error: %s | | | |\n", model.c_str(), nv, sites, metric.c_str(), r.error.c_str());
    return;
  }
  const svd_bench::Fidelity_report& f = r.fidelity;
  char wall[64];
  if(f.through_wall_lower == f.through_wall_upper) std::snprintf(wall, sizeof wall, "%.2f%%", 100 * f.through_wall_lower);
  else std::snprintf(wall, sizeof wall, "%.2f-%.2f%%", 100 * f.through_wall_lower, 100 * f.through_wall_upper);
  std::printf("| %s | %zu | %zu | %s | %.2f%% | %zu -> %zu | %s | %.3f |\n", model.c_str(), nv, sites, metric.c_str(),
              100 * f.mislabeled_share, f.broken_cells_before_repair, f.broken_cells, wall, r.seconds);
  std::fflush(stdout);
}

void study(const std::string& name, const Options& o)
{
  Mesh m;
  std::string what;
  try
  {
    if(!load_model(name, o, m, what))
    {
      std::fprintf(stderr, "skipped %s: not found\n", name.c_str());
      return;
    }
  }
  catch(const std::exception& e)
  {
    std::fprintf(stderr, "skipped %s: %s\n", name.c_str(), e.what());
    return;
  }
  const std::size_t nv = num_vertices(m);

  // one exact reference per number of sites, shared by every metric
  std::vector<std::vector<Location> > site_sets;
  std::vector<std::unique_ptr<svd_bench::Geodesic_reference<Mesh> > > references;
  for(std::size_t n : o.sites)
  {
    site_sets.push_back(SV::random_sites(m, n, CGAL::parameters::random_seed(o.seed)));
    const auto t0 = std::chrono::steady_clock::now();
    references.emplace_back(new svd_bench::Geodesic_reference<Mesh>(m, site_sets.back()));
    std::printf("| %s | %zu | %zu | GVD (exact, SMSP) | 0 (reference) | | | %.3f |\n", name.c_str(), nv, n, seconds_since(t0));
  }

  typedef CGAL::Surface_voronoi_diagram<Mesh, SV::Euclidean_embedding<Mesh> > Euclidean_diagram;
  for(std::size_t k = 0; k < o.sites.size(); ++k)
  {
    if(o.wants("rvd")) print_row(name, nv, o.sites[k], "RVD", measure(*references[k], o, 0., [&] {
      SV::Euclidean_embedding<Mesh> xyz(m);
      return std::make_unique<Euclidean_diagram>(m, xyz, site_sets[k],
                 SV::parameters::candidate_selection(SV::Candidate_selection::GLOBAL_NEAREST));
    }));
    if(o.wants("euclidean")) print_row(name, nv, o.sites[k], "EDBVD (euclidean)", measure(*references[k], o, 0., [&] {
      SV::Euclidean_embedding<Mesh> xyz(m);
      return std::make_unique<Euclidean_diagram>(m, xyz, site_sets[k]);
    }));
  }

  typedef CGAL::Biharmonic_embedding<Mesh> Biharmonic;
  for(std::size_t d : o.dims)
  {
    if(!o.wants("biharmonic")) break;
    std::unique_ptr<Biharmonic> embedding;
    double embedding_seconds = 0;
    std::string error;
    try
    {
      const auto t0 = std::chrono::steady_clock::now();
      embedding.reset(new Biharmonic(m, SV::parameters::embedding_dimension(d)));
      embedding_seconds = seconds_since(t0);
    }
    catch(const std::exception& e) { error = e.what(); }
    for(std::size_t k = 0; k < o.sites.size(); ++k)
    {
      const std::string label = "biharmonic d=" + std::to_string(d);
      if(!embedding)
      {
        Measured r;
        r.error = error;
        print_row(name, nv, o.sites[k], label, r);
        continue;
      }
      print_row(name, nv, o.sites[k], label, measure(*references[k], o, embedding_seconds, [&] {
        return std::make_unique<CGAL::Surface_voronoi_diagram<Mesh, Biharmonic> >(m, *embedding, site_sets[k]);
      }));
    }
  }

  // the geodesic metric, with the refinement it asks for on coarse meshes (timed); the
  // refined mesh is the same surface, but the reference must be rebuilt on it
  for(std::size_t k = 0; k < o.sites.size() && o.wants("geodesic"); ++k)
  {
    typedef SV::Geodesic_metric<Mesh> Geodesic;
    const auto t0 = std::chrono::steady_clock::now();
    Mesh refined_mesh;
    const auto refined = SV::refine_for_sites(m, site_sets[k], refined_mesh,
                                              SV::parameters::refinement_edge_length_ratio(o.refine_ratio,
                                              SV::parameters::refinement_trigger_ratio(o.trigger_ratio)));
    const double refinement = seconds_since(t0);
    std::string label = "geodesic";
    if(refined.vertex_limit_reached)
    {
      Measured r;
      r.error = "the refinement reached its vertex limit at " + std::to_string(num_vertices(refined_mesh)) + " vertices";
      print_row(name, nv, o.sites[k], label, r);
      continue;
    }
    svd_bench::Geodesic_reference<Mesh>* reference = references[k].get();
    std::unique_ptr<svd_bench::Geodesic_reference<Mesh> > refined_reference;
    if(refined.edges_split > 0)
    {
      label += " (refined to " + std::to_string(num_vertices(refined_mesh)) + " v)";
      refined_reference.reset(new svd_bench::Geodesic_reference<Mesh>(refined_mesh, refined.sites));
      reference = refined_reference.get();
    }
    const Mesh& work = refined.edges_split > 0 ? refined_mesh : m;
    const auto& work_sites = refined.edges_split > 0 ? refined.sites : site_sets[k];
    print_row(name, nv, o.sites[k], label, measure(*reference, o, refinement, [&] {
      Geodesic metric(work);
      return std::make_unique<CGAL::Surface_voronoi_diagram<Mesh, Geodesic> >(work, metric, work_sites);
    }));
  }
}

int usage(const char* why)
{
  std::fprintf(stderr, "benchmark_metric_study: %s\n", why);
  std::fprintf(stderr, "usage: benchmark_metric_study [--models a,b] [--sites 100,1000] [--dims 3,6,10] "
                       "[--samples S] [--seed K] [--refine-ratio R] [--trigger-ratio T] [--metrics rvd,euclidean,biharmonic,geodesic] [--data DIR] [--cgal DIR] [--quick]\n");
  return 1;
}

} // namespace

int main(int argc, char** argv)
{
  Options o;
  o.models = { "lampshade", "vase", "pot", "u_fold", "slab", "bowl", "box",
               "boot", "sword", "armadillo", "bear", "elephant", "fandisk_large", "couplingdown", "rotor" };
  try
  {
    for(int i = 1; i < argc; ++i)
    {
      const std::string a = argv[i];
      auto value = [&]() -> std::string {
        if(i + 1 >= argc) throw std::invalid_argument(a + " needs a value");
        return argv[++i];
      };
      if(a == "--models") o.models = split_list(value());
      else if(a == "--sites") o.sites = split_numbers(value());
      else if(a == "--dims") o.dims = split_numbers(value());
      else if(a == "--samples") o.samples = std::stoul(value());
      else if(a == "--seed") o.seed = static_cast<unsigned int>(std::stoul(value()));
      else if(a == "--refine-ratio") o.refine_ratio = std::stod(value());
      else if(a == "--metrics") o.metrics = split_list(value());
      else if(a == "--trigger-ratio") o.trigger_ratio = std::stod(value());
      else if(a == "--data") o.data_dir = value();
      else if(a == "--cgal") o.cgal_dir = value();
      else if(a == "--quick") { o.models = { "u_fold", "lampshade" }; o.sites = { 100 }; o.dims = { 10 }; o.samples = 5000; }
      else return usage(("unknown option " + a).c_str());
    }
  }
  catch(const std::exception& e)
  {
    return usage(e.what());
  }

  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  std::printf("Metric study: %zu area-uniform samples, seed %u; time = wall clock incl. precomputation (1 thread)\n\n",
              o.samples, o.seed);
  std::printf("| model | vertices | sites | metric | mislabeled | broken cells (before -> after repair) | through a wall | time (s) |\n");
  std::printf("|---|---|---|---|---|---|---|---|\n");
  for(const std::string& model : o.models) study(model, o);
  return 0;
}
