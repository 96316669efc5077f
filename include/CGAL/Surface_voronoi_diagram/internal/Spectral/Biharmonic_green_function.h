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
// The Green's function of the biharmonic operator of a triangle mesh, one column at a time:
// g(x, s) = sum over all non-zero eigenpairs of phi_k(x) phi_k(s) / lambda_k^2, computed by
// two solves with the cotangent Laplacian instead of an eigen-decomposition.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_SPECTRAL_BIHARMONIC_GREEN_FUNCTION_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_SPECTRAL_BIHARMONIC_GREEN_FUNCTION_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/internal/Double_kernel.h>
#include <CGAL/Surface_voronoi_diagram/internal/Spectral/cotangent_laplacian.h>
#include <CGAL/Surface_voronoi_diagram/internal/Spectral/generalized_eigensolver.h>

#include <CGAL/assertions.h>

#include <Eigen/OrderingMethods>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <array>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

// With L the cotangent stiffness matrix and M the lumped mass matrix, the eigenpairs
// L phi = lambda M phi (phi M-orthonormal) give the Green's function
//   G = sum_{lambda_k > 0} phi_k phi_k^T / lambda_k^2 = S M S,   S = sum phi_k phi_k^T / lambda_k,
// and S b is the solution u of L u = b (b summing to zero over each component) whose
// mass-weighted mean over each component is zero. So a column G e_s takes two solves with L,
// made definite by pinning one vertex per component: a compatible right-hand side (summing to
// zero) is solved exactly by the pinned system, whose row at the pinned vertex is dropped.
// A surface point s = sum w_k v_k (its face's corners) has the column sum w_k G e_{v_k}, as
// the embedding interpolates linearly over a face.
class Biharmonic_green_function
{
public:
  // the point sum_k weights[k] * corners[k]
  struct Point
  {
    std::array<std::size_t, 3> corners;
    std::array<double, 3> weights;
  };

  Biharmonic_green_function() {}

  // false if the pinned Laplacian is not numerically positive definite; `face_component`
  // and `components` are the mesh's connected components (those of Indexed_mesh)
  template <class Index>
  bool build(const std::vector<Point_d>& points, const std::vector<std::array<Index, 3> >& triangles,
             const std::vector<Index>& face_component, std::size_t components)
  {
    const std::size_t n = points.size();
    Eigen::SparseMatrix<double> L, M;
    assemble_cotangent_laplacian(points, triangles, L, M);
    m_mass.assign(M.diagonal().data(), M.diagonal().data() + n);

    // the components of the vertices, those of their faces; a vertex in no face is one alone
    m_component.assign(n, none);
    for(std::size_t f = 0; f < triangles.size(); ++f)
      for(int k = 0; k < 3; ++k) m_component[std::size_t(triangles[f][k])] = std::size_t(face_component[f]);
    for(std::size_t v = 0; v < n; ++v)
      if(m_component[v] == none) m_component[v] = components++;
    m_area.assign(components, 0.);
    for(std::size_t v = 0; v < n; ++v) m_area[m_component[v]] += m_mass[v];
    m_first.assign(components + 1, 0);
    for(std::size_t v = 0; v < n; ++v) ++m_first[m_component[v] + 1];
    for(std::size_t c = 0; c < components; ++c) m_first[c + 1] += m_first[c];
    m_members.assign(n, 0);
    std::vector<std::size_t> at(m_first.begin(), m_first.end() - 1);
    for(std::size_t v = 0; v < n; ++v) m_members[at[m_component[v]]++] = v;
    m_pinned.resize(components);
    for(std::size_t c = 0; c < components; ++c) m_pinned[c] = *members_begin(c);   // its lowest index

    std::vector<char> pinned(n, 0);
    for(std::size_t v : m_pinned) pinned[v] = 1;
    for(Eigen::Index j = 0; j < L.outerSize(); ++j)
      for(Eigen::SparseMatrix<double>::InnerIterator it(L, j); it; ++it)
        if(pinned[std::size_t(it.row())] || pinned[std::size_t(it.col())])
          it.valueRef() = (it.row() == it.col()) ? 1. : 0.;
    L.prune(0.);

    // a fill-reducing numbering, in which the factorization works and solves
    Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> order;
    Default_fill_reducing_ordering()(L, order);
    // order.indices()[k] is the vertex eliminated k-th
    const Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> position = order.inverse();
    Eigen::SparseMatrix<double> ordered;
    ordered = L.selfadjointView<Eigen::Lower>().twistedBy(position);
    m_position.assign(n, 0);
    for(std::size_t v = 0; v < n; ++v) m_position[v] = std::size_t(position.indices()[Eigen::Index(v)]);
    m_cholesky.compute(ordered);
    return m_cholesky.info() == Eigen::Success;
  }

  std::size_t number_of_vertices() const { return m_mass.size(); }
  std::size_t component(std::size_t v) const { return m_component[v]; }
  // the vertices of component c, ascending
  const std::size_t* members_begin(std::size_t c) const { return m_members.data() + m_first[c]; }
  const std::size_t* members_end(std::size_t c) const { return m_members.data() + m_first[c + 1]; }

  // For `count` points (at most `block_size`), writes g(v, s_j) to columns[j][v] for every
  // vertex v of s_j's component (the others are left as they are) and g(s_j, s_j) to self[j].
  // Each column depends on its point only, not on the others solved with it.
  static constexpr std::size_t block_size = 16;
  void columns(const Point* s, std::size_t count, double* const* columns, double* self,
               std::vector<double>& X, std::vector<double>& workspace) const
  {
    CGAL_precondition(count >= 1 && count <= block_size);
    const std::size_t n = number_of_vertices();
    // always block_size columns (the unused ones zero), the width the solve is compiled for
    const std::size_t w = block_size;
    X.assign(n * w, 0.);
    for(std::size_t j = 0; j < count; ++j)
    {
      // e_s minus its component's mass distribution: sums to zero over the component
      const std::size_t c = m_component[s[j].corners[0]];
      for(const std::size_t* v = members_begin(c); v != members_end(c); ++v)
        X[m_position[*v] * w + j] = -m_mass[*v] / m_area[c];
      for(int k = 0; k < 3; ++k)
        X[m_position[s[j].corners[k]] * w + j] += s[j].weights[k];
    }
    pinned_solve(s, count, X, workspace);
    for(std::size_t v = 0; v < n; ++v)
      for(std::size_t j = 0; j < w; ++j)
        X[m_position[v] * w + j] *= m_mass[v];
    pinned_solve(s, count, X, workspace);
    for(std::size_t j = 0; j < count; ++j)
    {
      const std::size_t c = m_component[s[j].corners[0]];
      for(const std::size_t* v = members_begin(c); v != members_end(c); ++v)
        columns[j][*v] = X[m_position[*v] * w + j];
      self[j] = 0;
      for(int k = 0; k < 3; ++k)
        self[j] += s[j].weights[k] * columns[j][s[j].corners[k]];
    }
  }

private:
  static constexpr std::size_t none = (std::numeric_limits<std::size_t>::max)();

  // X := S X for right-hand sides summing to zero over their points' components
  // (X has block_size columns, of which the first `count` are the points')
  void pinned_solve(const Point* s, std::size_t count, std::vector<double>& X, std::vector<double>& workspace) const
  {
    const std::size_t w = block_size;
    for(std::size_t p : m_pinned)
      for(std::size_t j = 0; j < w; ++j) X[m_position[p] * w + j] = 0;
    // the triangular solves run down columns: through a column-major copy of the block
    const Eigen::Index n = Eigen::Index(number_of_vertices());
    Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> > rows(X.data(), n, Eigen::Index(w));
    workspace.resize(X.size());
    Eigen::Map<Eigen::MatrixXd> block(workspace.data(), n, Eigen::Index(w));
    block = rows;
    m_cholesky.matrixL().solveInPlace(block);
    m_cholesky.matrixU().solveInPlace(block);
    rows = block;
    for(std::size_t j = 0; j < count; ++j)
    {
      // the mass-weighted mean over the component, to zero
      const std::size_t c = m_component[s[j].corners[0]];
      double mean = 0;
      for(const std::size_t* v = members_begin(c); v != members_end(c); ++v)
        mean += m_mass[*v] * X[m_position[*v] * w + j];
      mean /= m_area[c];
      for(const std::size_t* v = members_begin(c); v != members_end(c); ++v)
        X[m_position[*v] * w + j] -= mean;
    }
  }

  std::vector<double> m_mass, m_area;
  std::vector<std::size_t> m_component, m_pinned, m_first, m_members, m_position;
  // already in a fill-reducing numbering (m_position): factorized as it is
  Eigen::SimplicialLLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::NaturalOrdering<int> > m_cholesky;
};

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_SPECTRAL_BIHARMONIC_GREEN_FUNCTION_H
