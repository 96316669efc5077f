// Copyright (c) 2026 The Surface_voronoi_diagram authors.
// All rights reserved.
//
// This file is part of the Surface_voronoi_diagram package for CGAL (www.cgal.org).
//
// $URL$
// $Id$
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : The Surface_voronoi_diagram authors
//
// Cells of prescribed area are semi-discrete optimal transport: the areas of the restricted
// power diagram are the gradient of a concave function of the weights, so a damped Newton
// iteration converges from any weights that leave no cell empty (Kitagawa, Merigot and
// Thibert). Propagated cells lose this: they empty when their site leaves them.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_CELL_AREAS_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_CELL_AREAS_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/bisector_polylines.h>
#include <CGAL/Surface_voronoi_diagram/exceptions.h>
#include <CGAL/Surface_voronoi_diagram/power_weights.h>

#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {

/// \ingroup PkgSurfaceVoronoiDiagramMetrics
/// What `fit_power_weights_to_areas()` reached.
struct Area_fit_result
{
  /// the number of Newton steps taken
  std::size_t iterations = 0;
  /// the largest of the cells' \f$ |a_i - t_i| / t_i \f$ at the end
  double max_relative_error = 0;
};

/// \ingroup PkgSurfaceVoronoiDiagramMetrics
/// Sets the power weights of the sites of `diagram` (with `set_site_weight()` and `update()`)
/// so that the area of the cell of every site `i` comes within `tolerance`, relative, of
/// `target_areas[i]`.
///
/// A damped Newton iteration on the weights \cgalCite{cgal:kmt-cnasot-19}: the derivative
/// of the area of cell `i` in the weight of a neighbour `j` is minus the length of their
/// common boundary divided by the norm of the gradient of the difference of their squared
/// distances along the surface, taken as twice the squared distance between the embedded sites
/// over their distance in space (exact where the embedding stretches all directions alike
/// between the sites, as the Euclidean one does in a plane). A step that empties a cell or
/// does not lower the error enough is halved.
///
/// \tparam Diagram a `Surface_voronoi_diagram` over an embedding, whose update state was not
///         released
/// \tparam Metric a model of `SurfaceVoronoiEmbedding`, the type of the metric the diagram was
///         constructed with
/// \param diagram the diagram; its weights are the starting point, and its cells must not be
///        empty. Construct it with `Surface_voronoi::parameters::candidate_selection(Candidate_selection::GLOBAL_NEAREST)`:
///        its cells are then the restricted power diagram, whose areas move smoothly with the
///        weights. A propagated cell is, as a rule, empty once its site leaves it, so that the
///        areas jump and the iteration stalls where the targets need such a cell.
/// \param metric the metric the diagram was constructed with
/// \param target_areas one positive area per site, adding up to the area the sites reach
///        (`surface_area() - unreached_area()`)
/// \param tolerance the largest relative error accepted
/// \param max_iterations the most Newton steps taken
/// \returns the steps taken and the largest relative error reached, which is above
///          `tolerance` if `max_iterations` steps did not reach it
/// \throws Input_error if `target_areas` does not have one positive area per site
template <class Diagram, class Metric>
Area_fit_result fit_power_weights_to_areas(Diagram& diagram, Metric& metric,
                                           const std::vector<double>& target_areas,
                                           double tolerance = 0.01, std::size_t max_iterations = 50)
{
  diagram.update();   // the changes recorded before, if any
  const std::size_t n = diagram.number_of_sites();
  if(target_areas.size() != n || *std::min_element(target_areas.begin(), target_areas.end()) <= 0)
    throw Input_error("fit_power_weights_to_areas: one positive target area per site is needed");
  Area_fit_result result;
  Eigen::VectorXd gap(n), weights(n), c(metric.dimension());
  Eigen::MatrixXd embedded = Eigen::MatrixXd::Zero(c.size(), n);   // the sites in the embedding
  auto measure = [&]() { // the gap to the targets, and the L2 norm of the relative gap
    result.max_relative_error = 0;
    for(std::size_t i = 0; i < n; ++i)
    {
      gap[i] = target_areas[i] - diagram.cell_area(i);
      result.max_relative_error = (std::max)(result.max_relative_error, std::abs(gap[i]) / target_areas[i]);
    }
    return (gap.array() / Eigen::Map<const Eigen::ArrayXd>(target_areas.data(), n)).matrix().norm();
  };
  auto set = [&](const Eigen::VectorXd& w) {
    for(std::size_t i = 0; i < n; ++i) diagram.set_site_weight(i, w[i]);
    diagram.update();
    return measure();
  };
  for(std::size_t i = 0; i < n; ++i)
  {
    weights[i] = diagram.site_weight(i);
    const auto site = diagram.site_location(i);
    const auto corners = internal::face_corners(site.first, metric.triangle_mesh());
    for(int k = 0; k < 3; ++k)
    {
      metric.coordinates(corners[k], c.data());
      embedded.col(i) += site.second[k] * c;
    }
  }
  double error = measure();
  for(bool done = true; done && result.max_relative_error > tolerance && result.iterations < max_iterations;)
  {
    ++result.iterations;
    std::vector<Bisector_polyline<typename Diagram::Point_3> > boundaries;
    bisector_polylines(diagram, std::back_inserter(boundaries));
    std::vector<Eigen::Triplet<double> > entries;
    for(const auto& b : boundaries)
    {
      const int i = int(b.sites[0]), j = int(b.sites[1]);
      if(b.sites[1] >= n) continue;   // against area no site reaches: no weight moves it
      double h = 0;
      for(std::size_t k = 1; k < b.points.size(); ++k) h += std::sqrt(CGAL::squared_distance(b.points[k - 1], b.points[k]));
      h *= std::sqrt(CGAL::squared_distance(diagram.site_point(i), diagram.site_point(j)))
           / (2 * (embedded.col(i) - embedded.col(j)).squaredNorm());
      entries.insert(entries.end(), { { i, i, h }, { j, j, h }, { i, j, -h }, { j, i, -h } });
    }
    Eigen::SparseMatrix<double> hessian(n, n);
    hessian.setFromTriplets(entries.begin(), entries.end());
    // the weights are defined up to a constant: a small shift makes the Laplacian definite
    hessian.diagonal().array() += 1e-9 * hessian.diagonal().maxCoeff();
    Eigen::VectorXd step = Eigen::SimplicialLDLT<Eigen::SparseMatrix<double> >(hessian).solve(gap);
    step.array() -= step.mean();   // the diagram does not change with a constant added
    done = false;
    for(double fraction = 1; fraction >= 1. / 64 && !done; fraction /= 2)
    {
      const Eigen::VectorXd trial = weights + fraction * step;
      const double e = set(trial);
      if((done = diagram.statistics().empty_cells == 0 && e < (1 - fraction / 8) * error)) { error = e; weights = trial; }
    }
    if(!done) set(weights);   // no progress: back to the last weights
  }
  return result;
}

} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_CELL_AREAS_H
