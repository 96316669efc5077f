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
// A supernodal (multifrontal) sparse Cholesky factorization A = L L^T, in the order the
// matrix comes in, for the eigen-solver's shift-invert on large meshes.
//
// Why not Eigen's SimplicialLLT: it updates the factor one column at a time through scattered
// sparse loops (at 537k vertices the factorization alone took 4 s, a third of the
// embedding). Here columns with the same structure below the diagonal are grouped into
// supernodes, each factorized as one dense block with Eigen's dense kernels, which run
// several times faster. Why not CHOLMOD's supernodal code: it goes through the BLAS, whose
// rounding depends on the BLAS build and thread count (see nested_dissection_ordering.h);
// Eigen's dense kernels are this package's own compiled code, single-threaded, so the
// factor is the same bits on every run.
//
// The factor's values are stored per supernode as one dense column-major block (its rows:
// its own columns, then the rows below), 8 bytes per entry instead of the 12 of a
// compressed column, which the solves, bound by memory bandwidth, read twice per operator
// application.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_SPECTRAL_SUPERNODAL_CHOLESKY_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_SPECTRAL_SUPERNODAL_CHOLESKY_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/assertions.h>
#include <CGAL/Surface_voronoi_diagram/internal/parallel.h>
#include <CGAL/Surface_voronoi_diagram/internal/Spectral/Fixed_dense_blocking.h>

#include <Eigen/Cholesky>
#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

class Supernodal_cholesky
{
public:
  typedef Eigen::SparseMatrix<double> Sparse_matrix;

  /// The elimination tree of the lower triangle of `A` (column-major, the diagonal and
  /// either or both triangles stored): `parent[j]` is the parent of column j, -1 at a root.
  static std::vector<int> elimination_tree(const Sparse_matrix& A)
  {
    const Sparse_matrix upper = upper_pattern(A);
    return elimination_tree_of_upper(upper);
  }

  /// A postorder of the forest `parent`: `order[k]` is the k-th column visited, children in
  /// increasing order before their parent. Renumbering a matrix by it leaves its factor's
  /// non-zeros as they are and makes the columns of every subtree consecutive.
  static std::vector<int> postorder(const std::vector<int>& parent)
  {
    const int n = static_cast<int>(parent.size());
    std::vector<int> head(static_cast<std::size_t>(n), -1), next(static_cast<std::size_t>(n), -1), order, stack;
    order.reserve(parent.size());
    for(int j = n - 1; j >= 0; --j)   // children lists in increasing order
      if(parent[j] >= 0)
      {
        next[j] = head[parent[j]];
        head[parent[j]] = j;
      }
    for(int root = 0; root < n; ++root)
    {
      if(parent[root] >= 0)
        continue;
      stack.push_back(root);
      while(!stack.empty())
      {
        const int j = stack.back();
        const int child = head[j];
        if(child < 0)
        {
          stack.pop_back();
          order.push_back(j);
        }
        else
        {
          head[j] = next[child];
          stack.push_back(child);
        }
      }
    }
    return order;
  }

  /// Factorizes the symmetric matrix whose lower triangle `A` holds (the upper triangle, if
  /// stored, is not read). False if it is not numerically positive definite. Any numbering
  /// works; one in a postorder of the elimination tree (see `postorder()`) saves permuting
  /// the vector of every solve.
  bool factor(const Sparse_matrix& A)
  {
    CGAL_precondition(A.rows() == A.cols());
    const Fixed_dense_blocking same_bits_on_every_machine;
    m_ok = false;
    const Sparse_matrix upper = upper_pattern(A);
    const std::vector<int> parent = elimination_tree_of_upper(upper);
    const std::vector<int> post = postorder(parent);
    m_permutation.clear();
    for(std::size_t k = 0; k < post.size(); ++k)
      if(post[k] != static_cast<int>(k))
      {
        m_permutation = post;
        break;
      }
    if(m_permutation.empty())
    {
      analyze(A, upper, parent);
      m_ok = factorize(A);
    }
    else
    {
      Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> p(A.rows());
      for(std::size_t k = 0; k < post.size(); ++k) p.indices()[static_cast<Eigen::Index>(k)] = post[k];
      Sparse_matrix B;
      B = A.selfadjointView<Eigen::Lower>().twistedBy(p.inverse());
      const Sparse_matrix upper_of_B = upper_pattern(B);
      analyze(B, upper_of_B, elimination_tree_of_upper(upper_of_B));
      m_ok = factorize(B);
      m_permuted.resize(A.rows());
    }
    return m_ok;
  }

  bool ok() const { return m_ok; }
  /// whether `factor()` factorizes independent subtrees on concurrent threads (the same bits)
  void set_parallel(bool parallel) { m_parallel = parallel; }
  /// the subtrees the last `factor()` ran on concurrent threads (0: none)
  std::size_t number_of_concurrent_subtrees() const { return m_tasks.size(); }
  std::size_t number_of_supernodes() const { return m_first.size() - 1; }

  /// x := A^{-1} x
  void solve_in_place(double* x) const
  {
    CGAL_precondition(m_ok);
    if(m_permutation.empty())
      return solve_postordered(x);
    const std::size_t n = m_permutation.size();
    for(std::size_t k = 0; k < n; ++k) m_permuted[static_cast<Eigen::Index>(k)] = x[m_permutation[k]];
    solve_postordered(m_permuted.data());
    for(std::size_t k = 0; k < n; ++k) x[m_permutation[k]] = m_permuted[static_cast<Eigen::Index>(k)];
  }

  /// X := A^{-1} X for `count` right-hand sides stored row by row: `X[i * count + j]` is row
  /// i of column j. Each pass over the factor serves all the columns, which a solve per
  /// column would read again each time. Column j gets the same numbers whatever the other
  /// columns and `count` (plain loops, without the blocked kernels of `solve_in_place()`,
  /// whose order of summation depends on the sizes), so that a result can be cached and
  /// computed again bit for bit. `workspace` is the caller's, so that threads
  /// can solve at once with one factorization.
  void solve_many_in_place(double* X, std::size_t count, std::vector<double>& workspace) const
  {
    CGAL_precondition(m_ok);
    const std::size_t n = m_first.empty() ? 0 : static_cast<std::size_t>(m_first.back());
    const std::size_t widest = static_cast<std::size_t>(m_scratch.size());
    const std::size_t permuted = m_permutation.empty() ? 0 : n * count;
    workspace.resize(permuted + (widest + 1) * count);
    double* T = workspace.data() + permuted;
    double* Y = X;
    if(permuted > 0)
    {
      Y = workspace.data();
      for(std::size_t k = 0; k < n; ++k)
        std::copy(X + std::size_t(m_permutation[k]) * count, X + (std::size_t(m_permutation[k]) + 1) * count, Y + k * count);
    }
    // a count known at compile time lets the compiler unroll and vectorize the inner loops
    if(count == 16)
      solve_many_postordered(Y, std::integral_constant<std::size_t, 16>(), T);
    else
      solve_many_postordered(Y, count, T);
    if(permuted > 0)
      for(std::size_t k = 0; k < n; ++k)
        std::copy(Y + k * count, Y + (k + 1) * count, X + std::size_t(m_permutation[k]) * count);
  }

private:
  // the loops of solve_postordered() with an innermost loop over the `count` columns; `T`
  // holds (widest + 1) * count numbers
  template <class Count>
  void solve_many_postordered(double* X, Count count_, double* T) const
  {
    const std::size_t count = count_;
    const int ns = static_cast<int>(number_of_supernodes());
    double* v = T + static_cast<std::size_t>(m_scratch.size()) * count;
    for(int s = 0; s < ns; ++s)   // L Y = X
    {
      const int f = m_first[s], k = m_first[s + 1] - f;
      const int r = static_cast<int>(m_row_begin[s + 1] - m_row_begin[s]);
      const int m = k + r;
      const double* B = m_values.data() + m_value_begin[s];
      const int* rows = m_rows.data() + m_row_begin[s];
      std::fill(T, T + std::size_t(r) * count, 0.0);
      for(int c = 0; c < k; ++c)
      {
        const double* column = B + static_cast<std::ptrdiff_t>(c) * m;
        double* xc = X + std::size_t(f + c) * count;
        for(std::size_t j = 0; j < count; ++j) xc[j] /= column[c];
        for(int a = c + 1; a < k; ++a)
        {
          double* xa = X + std::size_t(f + a) * count;
          const double w = column[a];
          for(std::size_t j = 0; j < count; ++j) xa[j] -= w * xc[j];
        }
        for(int q = 0; q < r; ++q)
        {
          double* tq = T + std::size_t(q) * count;
          const double w = column[k + q];
          for(std::size_t j = 0; j < count; ++j) tq[j] += w * xc[j];
        }
      }
      for(int q = 0; q < r; ++q)
      {
        double* xq = X + std::size_t(rows[q]) * count;
        const double* tq = T + std::size_t(q) * count;
        for(std::size_t j = 0; j < count; ++j) xq[j] -= tq[j];
      }
    }
    for(int s = ns - 1; s >= 0; --s)   // L^T X = Y
    {
      const int f = m_first[s], k = m_first[s + 1] - f;
      const int r = static_cast<int>(m_row_begin[s + 1] - m_row_begin[s]);
      const int m = k + r;
      const double* B = m_values.data() + m_value_begin[s];
      const int* rows = m_rows.data() + m_row_begin[s];
      for(int q = 0; q < r; ++q)
        std::copy(X + std::size_t(rows[q]) * count, X + std::size_t(rows[q] + 1) * count, T + std::size_t(q) * count);
      for(int c = k - 1; c >= 0; --c)
      {
        const double* column = B + static_cast<std::ptrdiff_t>(c) * m;
        double* xc = X + std::size_t(f + c) * count;
        std::copy(xc, xc + count, v);
        for(int q = 0; q < r; ++q)
        {
          const double* tq = T + std::size_t(q) * count;
          const double w = column[k + q];
          for(std::size_t j = 0; j < count; ++j) v[j] -= w * tq[j];
        }
        for(int a = c + 1; a < k; ++a)
        {
          const double* xa = X + std::size_t(f + a) * count;
          const double w = column[a];
          for(std::size_t j = 0; j < count; ++j) v[j] -= w * xa[j];
        }
        for(std::size_t j = 0; j < count; ++j) xc[j] = v[j] / column[c];
      }
    }
  }

  // Solves in two sweeps. With the subtrees the factorization ran concurrently, each sweep
  // runs them concurrently too, every supernode with the same numbers in the same order:
  // forward, a subtree updates its own rows directly and its updates of the rows above it
  // (each row's in the order of the supernodes, as one thread makes them) are replayed where
  // the sequential sweep would have made them; backward, the supernodes above every subtree go
  // first, and the subtrees then read only those and their own.
  void solve_postordered(double* x) const
  {
    const int ns = static_cast<int>(number_of_supernodes());
    double* t = m_scratch.data();
    const std::size_t tasks = m_tasks.size();
    if(m_task_scratch.size() != tasks) m_task_scratch.assign(tasks, std::vector<double>(static_cast<std::size_t>(m_scratch.size())));
    if(m_task_log.size() != tasks) m_task_log.assign(tasks, std::vector<double>());
    // L y = x
    for_each_chunk(tasks, 1, true, [&](std::size_t i, std::size_t, std::size_t) {
      const Task& task = m_tasks[i];
      double* tt = m_task_scratch[i].data();
      std::vector<double>& log = m_task_log[i];
      log.clear();
      const int end_column = m_first[task.last + 1];
      for(int s = task.first; s <= task.last; ++s)
      {
        forward_step(s, x, tt);
        const int r = static_cast<int>(m_row_begin[s + 1] - m_row_begin[s]);
        const int* rows = m_rows.data() + m_row_begin[s];
        int q = 0;
        for(; q < r && rows[q] < end_column; ++q) x[rows[q]] -= tt[q];
        if(task.direct)
          for(; q < r; ++q) x[rows[q]] -= tt[q];
        else
          log.insert(log.end(), tt + q, tt + r);
      }
    });
    std::size_t next_task = 0;
    for(int s = 0; s < ns;)
    {
      if(next_task < tasks && s == m_tasks[next_task].first)
      {
        const Task& task = m_tasks[next_task];
        if(!task.direct)
        {
          const int end_column = m_first[task.last + 1];
          const double* log = m_task_log[next_task].data();
          for(int u = task.first; u <= task.last; ++u)
          {
            const int* rows = m_rows.data() + m_row_begin[u];
            const int* past = rows + (m_row_begin[u + 1] - m_row_begin[u]);
            for(const int* row = std::lower_bound(rows, past, end_column); row != past; ++row) x[*row] -= *log++;
          }
        }
        s = task.last + 1;
        ++next_task;
        continue;
      }
      forward_step(s, x, t);
      const int r = static_cast<int>(m_row_begin[s + 1] - m_row_begin[s]);
      const int* rows = m_rows.data() + m_row_begin[s];
      for(int q = 0; q < r; ++q) x[rows[q]] -= t[q];
      ++s;
    }
    // L^T x = y; the tasks are in increasing order: walk them down
    std::size_t task_above = tasks;
    for(int s = ns - 1; s >= 0; --s)
    {
      if(task_above > 0 && s == m_tasks[task_above - 1].last)
      {
        s = m_tasks[--task_above].first;
        continue;
      }
      backward_step(s, x, t);
    }
    for_each_chunk(tasks, 1, true, [&](std::size_t i, std::size_t, std::size_t) {
      double* tt = m_task_scratch[i].data();
      for(int s = m_tasks[i].last; s >= m_tasks[i].first; --s) backward_step(s, x, tt);
    });
  }

  // Supernode s's part of L y = x: its columns of y, in place, and in `t` what they take
  // off the rows below (not yet taken off).
  void forward_step(int s, double* x, double* t) const
  {
    const int f = m_first[s], k = m_first[s + 1] - f;
    const int r = static_cast<int>(m_row_begin[s + 1] - m_row_begin[s]);
    const int m = k + r;
    const double* B = m_values.data() + m_value_begin[s];
    if(k <= small_width)
    {
      // most supernodes are a few columns wide: plain loops, where a call into Eigen's
      // kernels would cost more than its arithmetic
      std::fill(t, t + r, 0.0);
      for(int c = 0; c < k; ++c)
      {
        const double* column = B + static_cast<std::ptrdiff_t>(c) * m;
        const double v = x[f + c] / column[c];
        x[f + c] = v;
        for(int a = c + 1; a < k; ++a) x[f + a] -= column[a] * v;
        for(int q = 0; q < r; ++q) t[q] += column[k + q] * v;
      }
    }
    else
    {
      const Block block(B, m, k);
      Eigen::Map<Eigen::VectorXd> y(x + f, k);
      block.topRows(k).triangularView<Eigen::Lower>().solveInPlace(y);
      Eigen::Map<Eigen::VectorXd>(t, r).noalias() = block.bottomRows(r) * y;
    }
  }

  // Supernode s's part of L^T x = y, from the rows below it, already solved; `t` is scratch.
  void backward_step(int s, double* x, double* t) const
  {
    const int f = m_first[s], k = m_first[s + 1] - f;
    const int r = static_cast<int>(m_row_begin[s + 1] - m_row_begin[s]);
    const int m = k + r;
    const double* B = m_values.data() + m_value_begin[s];
    const int* rows = m_rows.data() + m_row_begin[s];
    for(int q = 0; q < r; ++q) t[q] = x[rows[q]];
    if(k <= small_width)
    {
      for(int c = k - 1; c >= 0; --c)
      {
        const double* column = B + static_cast<std::ptrdiff_t>(c) * m;
        double v = x[f + c];
        for(int q = 0; q < r; ++q) v -= column[k + q] * t[q];
        for(int a = c + 1; a < k; ++a) v -= column[a] * x[f + a];
        x[f + c] = v / column[c];
      }
    }
    else
    {
      const Block block(B, m, k);
      Eigen::Map<Eigen::VectorXd> y(x + f, k);
      if(r > 0)
        y.noalias() -= block.bottomRows(r).transpose() * Eigen::Map<const Eigen::VectorXd>(t, r);
      block.topRows(k).triangularView<Eigen::Lower>().transpose().solveInPlace(y);
    }
  }

  typedef Eigen::Map<const Eigen::MatrixXd> Block;
  // Up to this many columns a supernode's solve runs as plain loops: on igea-537k (122k
  // supernodes, 4.4 columns on average) Eigen's kernels for every supernode made a solve 1.7x
  // slower than the loops up to 32 columns and the kernels beyond (0.062 against 0.037 s).
  static constexpr int small_width = 32;

  static Sparse_matrix upper_pattern(const Sparse_matrix& A)
  {
    Sparse_matrix lower = A.triangularView<Eigen::Lower>();
    return lower.transpose();
  }

  static std::vector<int> elimination_tree_of_upper(const Sparse_matrix& upper)
  {
    const int n = static_cast<int>(upper.cols());
    std::vector<int> parent(static_cast<std::size_t>(n), -1), ancestor(static_cast<std::size_t>(n), -1);
    for(int k = 0; k < n; ++k)
      for(Sparse_matrix::InnerIterator it(upper, k); it; ++it)
        for(int i = static_cast<int>(it.row()); i >= 0 && i < k;)
        {
          const int up = ancestor[i];
          ancestor[i] = k;
          if(up < 0)
            parent[i] = k;
          i = up;
        }
    return parent;
  }

  Block block(int s) const
  {
    const int k = m_first[s + 1] - m_first[s];
    const int m = k + static_cast<int>(m_row_begin[s + 1] - m_row_begin[s]);
    return Block(m_values.data() + m_value_begin[s], m, k);
  }

  // Supernodes, their row structures and where their blocks go; `upper` and `parent` are
  // A's upper pattern and elimination tree, which factor() has already computed.
  void analyze(const Sparse_matrix& A, const Sparse_matrix& upper, const std::vector<int>& parent)
  {
    const int n = static_cast<int>(A.rows());

    // In a postorder (factor() made sure) the columns of a subtree are consecutive, and the
    // update matrices of a supernode's children are the last ones on the stack.

    // Column counts of L, row by row: the non-zeros of row k are the columns met climbing
    // the tree from each non-zero of A's row k up to k.
    std::vector<int> count(static_cast<std::size_t>(n), 1), mark(static_cast<std::size_t>(n), -1), children(static_cast<std::size_t>(n), 0);
    for(int k = 0; k < n; ++k)
    {
      mark[k] = k;
      for(Sparse_matrix::InnerIterator it(upper, k); it; ++it)
        for(int i = static_cast<int>(it.row()); i < k && mark[i] != k; i = parent[i])
        {
          mark[i] = k;
          ++count[i];
        }
      if(parent[k] >= 0)
        ++children[parent[k]];
    }

    // Fundamental supernodes: a column joins the previous one's supernode if it is that
    // column's parent, its only child, and has one non-zero fewer.
    std::vector<int> first;
    for(int j = 0; j < n; ++j)
      if(j == 0 || parent[j - 1] != j || children[j] != 1 || count[j - 1] != count[j] + 1)
        first.push_back(j);
    first.push_back(n);

    // Relaxed amalgamation: small supernodes merge with their parent at the cost of a few
    // explicit zeros, for larger dense blocks (CHOLMOD's default limits).
    const int nf = static_cast<int>(first.size()) - 1;
    std::vector<int> super_of(static_cast<std::size_t>(n));
    for(int s = 0; s < nf; ++s)
      for(int j = first[s]; j < first[s + 1]; ++j) super_of[j] = s;
    struct Group { int first, columns; long long height; double entries, zeros; };
    std::vector<Group> groups;   // the merged supernodes so far, in order
    std::vector<int> group_of(static_cast<std::size_t>(nf), -1);
    auto stored = [](long long height, int columns) { return double(columns) * double(height) - 0.5 * double(columns) * double(columns - 1); };
    for(int s = 0; s < nf; ++s)
    {
      Group g;
      g.first = first[s];
      g.columns = first[s + 1] - first[s];
      g.height = count[first[s]];
      g.entries = 0;
      for(int j = first[s]; j < first[s + 1]; ++j) g.entries += count[j];
      g.zeros = stored(g.height, g.columns) - g.entries;
      // the child merged last is the group just before, if its tree parent is this one
      while(!groups.empty())
      {
        const Group& c = groups.back();
        const int last = c.first + c.columns - 1;
        if(last + 1 != g.first || parent[last] != g.first)
          break;
        const int columns = c.columns + g.columns;
        const long long height = c.columns + g.height;
        const double total = stored(height, columns);
        const double zeros = total - c.entries - g.entries;
        const double fraction = zeros / total;
        const bool merge = columns <= 4 || (columns <= 16 && fraction < 0.8) || (columns <= 48 && fraction < 0.1) || fraction < 0.05;
        if(!merge)
          break;
        g.first = c.first;
        g.columns = columns;
        g.height = height;
        g.entries += c.entries;
        g.zeros = zeros;
        groups.pop_back();
      }
      groups.push_back(g);
    }
    m_first.clear();
    for(const Group& g : groups) m_first.push_back(g.first);
    m_first.push_back(n);
    const int ns = static_cast<int>(groups.size());
    for(int s = 0; s < ns; ++s)
      for(int j = m_first[s]; j < m_first[s + 1]; ++j) super_of[j] = s;

    // Row structures, children first: the rows below a supernode's columns in A's columns
    // and in its children's structures.
    m_row_begin.assign(1, 0);
    m_rows.clear();
    m_parent.assign(static_cast<std::size_t>(ns), -1);
    m_child_count.assign(static_cast<std::size_t>(ns), 0);
    std::vector<std::vector<int> > child_lists(static_cast<std::size_t>(ns));
    std::fill(mark.begin(), mark.end(), -1);
    std::vector<int> rows;
    for(int s = 0; s < ns; ++s)
    {
      const int f = m_first[s], l = m_first[s + 1] - 1;
      rows.clear();
      for(int j = f; j <= l; ++j)
        for(Sparse_matrix::InnerIterator it(A, j); it; ++it)
        {
          const int i = static_cast<int>(it.row());
          if(i > l && mark[i] != s) { mark[i] = s; rows.push_back(i); }
        }
      for(int c : child_lists[s])
        for(std::size_t q = m_row_begin[c]; q < m_row_begin[c + 1]; ++q)
        {
          const int i = m_rows[q];
          if(i > l && mark[i] != s) { mark[i] = s; rows.push_back(i); }
        }
      std::sort(rows.begin(), rows.end());
      m_rows.insert(m_rows.end(), rows.begin(), rows.end());
      m_row_begin.push_back(m_rows.size());
      if(!rows.empty())
      {
        const int p = super_of[rows.front()];   // the tree parent of the last column
        CGAL_assertion(parent[l] == rows.front());
        m_parent[s] = p;
        ++m_child_count[p];
        child_lists[p].push_back(s);
      }
      std::vector<int>().swap(child_lists[s]);
    }
    m_value_begin.assign(1, 0);
    for(int s = 0; s < ns; ++s)
    {
      const std::size_t k = static_cast<std::size_t>(m_first[s + 1] - m_first[s]);
      m_value_begin.push_back(m_value_begin.back() + k * (k + m_row_begin[s + 1] - m_row_begin[s]));
    }
    m_relative.assign(static_cast<std::size_t>(n), 0);
  }

  // What one thread's factorization works with: the update matrices waiting for their
  // parents (a stack: in a postorder the children's are the last pushed), a front, and each
  // matrix row's row in the current front.
  struct Front_workspace
  {
    std::vector<double> stack;            // update matrices, column-major, one after the other
    std::vector<std::size_t> stack_begin;
    std::vector<int> stack_owner;
    std::vector<double> buffer;
    std::vector<int> relative;
  };

  std::size_t front_rows(int s) const
  {
    return static_cast<std::size_t>(m_first[s + 1] - m_first[s]) + (m_row_begin[s + 1] - m_row_begin[s]);
  }

  // Multifrontal: each supernode's front gathers its columns of A and its children's update
  // matrices, is partly factorized as a dense block, and leaves its own update matrix for its
  // parent. With `m_parallel`, the subtrees below the first branching of the tree are
  // factorized on concurrent threads, each with its own workspace, and the rest in postorder
  // after them, each subtree's update matrix put on the stack where its root would have
  // pushed it: every front is assembled and factorized with the same numbers in the same
  // order, so the factor is the same bits on any number of threads.
  bool factorize(const Sparse_matrix& A)
  {
    const int ns = static_cast<int>(number_of_supernodes());
    m_values.assign(m_value_begin.back(), 0.0);
    std::size_t widest = 0;
    for(int s = 0; s < ns; ++s)
      widest = (std::max)(widest, m_row_begin[s + 1] - m_row_begin[s]);
    m_scratch.resize(static_cast<Eigen::Index>(widest));

    m_tasks.clear();
    m_task_scratch.clear();
    m_task_log.clear();
    if(m_parallel)
    {
      // in a postorder, the subtree of s is the supernodes s - subtree_size[s] + 1 .. s
      std::vector<int> subtree_size(static_cast<std::size_t>(ns), 1);
      for(int s = 0; s < ns; ++s)
        if(m_parent[s] >= 0) subtree_size[m_parent[s]] += subtree_size[s];
      for(int root : concurrent_subtrees(subtree_size))
      {
        const int first = root - subtree_size[root] + 1;
        m_tasks.push_back(Task{ first, root, first == 0 && m_tasks.empty() });
      }
    }
    std::vector<Front_workspace> done(m_tasks.size());
    std::vector<std::uint8_t> ok(m_tasks.size(), 0);
    for_each_chunk(m_tasks.size(), 1, true, [&](std::size_t t, std::size_t, std::size_t) {
      done[t].relative.resize(m_relative.size());
      ok[t] = factorize_supernodes(A, m_tasks[t].first, m_tasks[t].last + 1, done[t]);
    });
    if(std::find(ok.begin(), ok.end(), std::uint8_t(0)) != ok.end())
      return false;

    // the supernodes before each subtree, then the subtree's root update, the only matrix
    // left on its stack; then those after the last
    Front_workspace main;
    main.relative.swap(m_relative);
    bool good = true;
    int s = 0;
    for(std::size_t t = 0; good; ++t)
    {
      good = factorize_supernodes(A, s, t < m_tasks.size() ? m_tasks[t].first : ns, main);
      if(t == m_tasks.size()) break;
      Front_workspace& w = done[t];
      CGAL_assertion(w.stack_owner.size() == 1 && w.stack_owner.front() == m_tasks[t].last && w.stack_begin.front() == 0);
      main.stack_begin.push_back(main.stack.size());
      main.stack_owner.push_back(m_tasks[t].last);
      main.stack.insert(main.stack.end(), w.stack.begin(), w.stack.end());
      std::vector<double>().swap(w.stack);
      s = m_tasks[t].last + 1;
    }
    main.relative.swap(m_relative);
    CGAL_assertion(!good || main.stack.empty());
    return good;
  }

  // The roots of the subtrees to factorize concurrently: the children of the first supernode,
  // from the top of the heaviest tree, whose second-heaviest child holds a tenth of its work
  // (the nested-dissection ordering's first separator). None if there is no such branching.
  std::vector<int> concurrent_subtrees(const std::vector<int>& subtree_size) const
  {
    const int ns = static_cast<int>(number_of_supernodes());
    std::vector<double> work(static_cast<std::size_t>(ns), 0.);
    int top = -1;
    for(int s = 0; s < ns; ++s)
    {
      const double k = double(m_first[s + 1] - m_first[s]), m = double(front_rows(s));
      work[s] += k * m * m;
      if(m_parent[s] >= 0)
        work[m_parent[s]] += work[s];
      else if(top < 0 || work[s] > work[top])
        top = s;
    }
    for(int node = top; node >= 0;)
    {
      // its children in increasing order: in a postorder the last is node - 1, and each
      // earlier one ends where the next one's subtree begins
      std::vector<int> c(static_cast<std::size_t>(m_child_count[node]));
      for(int k = m_child_count[node] - 1, child = node - 1; k >= 0; child -= subtree_size[child], --k)
      {
        CGAL_assertion(child >= 0 && m_parent[child] == node);
        c[static_cast<std::size_t>(k)] = child;
      }
      if(c.empty()) break;
      std::vector<int> by_work(c);
      std::sort(by_work.begin(), by_work.end(), [&](int a, int b) { return work[a] > work[b] || (work[a] == work[b] && a < b); });
      if(by_work.size() >= 2 && work[by_work[1]] >= 0.1 * work[node])
      {
        // sizable subtrees only: a thread's start costs more than a small one's factorization
        std::vector<int> roots;
        for(int r : c)
          if(subtree_size[r] > 1) roots.push_back(r);
        return roots;
      }
      node = by_work.front();
    }
    return std::vector<int>();
  }

  // Factorizes supernodes [first, last) in order, with `w`'s stack: a whole subtree, or the
  // next supernode of the postorder.
  bool factorize_supernodes(const Sparse_matrix& A, int first, int last, Front_workspace& w)
  {
    std::size_t largest = 0;
    for(int s = first; s < last; ++s) largest = (std::max)(largest, front_rows(s) * front_rows(s));
    if(w.buffer.size() < largest) w.buffer.resize(largest);
    std::vector<int>& relative = w.relative;
    for(int s = first; s < last; ++s)
    {
      const int f = m_first[s], k = m_first[s + 1] - f;
      const int r = static_cast<int>(m_row_begin[s + 1] - m_row_begin[s]);
      const int m = k + r;
      const int* rows = m_rows.data() + m_row_begin[s];
      for(int t = 0; t < k; ++t) relative[f + t] = t;
      for(int q = 0; q < r; ++q) relative[rows[q]] = k + q;
      Eigen::Map<Eigen::MatrixXd> front(w.buffer.data(), m, m);
      front.setZero();
      for(int j = f; j < f + k; ++j)
        for(Sparse_matrix::InnerIterator it(A, j); it; ++it)
          if(it.row() >= j)
            front(relative[it.row()], j - f) += it.value();
      for(int c = 0; c < m_child_count[s]; ++c)
      {
        CGAL_assertion(!w.stack_owner.empty() && m_parent[w.stack_owner.back()] == s);
        const int child = w.stack_owner.back();
        const int rc = static_cast<int>(m_row_begin[child + 1] - m_row_begin[child]);
        const int* crows = m_rows.data() + m_row_begin[child];
        const double* U = w.stack.data() + w.stack_begin.back();
        for(int b = 0; b < rc; ++b)
        {
          const int cb = relative[crows[b]];
          double* column = front.data() + static_cast<std::ptrdiff_t>(cb) * m;
          const double* source = U + static_cast<std::ptrdiff_t>(b) * rc;
          for(int a = b; a < rc; ++a) column[relative[crows[a]]] += source[a];
        }
        w.stack.resize(w.stack_begin.back());
        w.stack_begin.pop_back();
        w.stack_owner.pop_back();
      }
      auto F11 = front.topLeftCorner(k, k);
      Eigen::LLT<Eigen::Ref<Eigen::MatrixXd>, Eigen::Lower> llt(F11);
      if(llt.info() != Eigen::Success)
        return false;
      if(r > 0)
      {
        auto F21 = front.bottomLeftCorner(r, k);
        F11.triangularView<Eigen::Lower>().transpose().solveInPlace<Eigen::OnTheRight>(F21);
        auto F22 = front.bottomRightCorner(r, r);
        F22.selfadjointView<Eigen::Lower>().rankUpdate(F21, -1.0);
        w.stack_begin.push_back(w.stack.size());
        w.stack_owner.push_back(s);
        w.stack.resize(w.stack.size() + static_cast<std::size_t>(r) * static_cast<std::size_t>(r));
        Eigen::Map<Eigen::MatrixXd>(w.stack.data() + w.stack_begin.back(), r, r).triangularView<Eigen::Lower>() = F22.triangularView<Eigen::Lower>();
      }
      Eigen::Map<Eigen::MatrixXd>(m_values.data() + m_value_begin[s], m, k) = front.leftCols(k);
      if(!front.leftCols(k).allFinite())
        return false;
    }
    return true;
  }

  std::vector<int> m_first;                // supernode s: columns m_first[s] .. m_first[s + 1] - 1
  std::vector<std::size_t> m_row_begin;    // its rows below them: m_rows[m_row_begin[s] ..]
  std::vector<int> m_rows;
  std::vector<int> m_parent, m_child_count;
  std::vector<std::size_t> m_value_begin;  // its dense block: m_values[m_value_begin[s] ..]
  std::vector<double> m_values;
  std::vector<int> m_relative;             // a front's row of each matrix row, while factorizing
  mutable Eigen::VectorXd m_scratch;
  std::vector<int> m_permutation;          // empty, or the postorder the factor is in
  bool m_parallel = false;
  // the subtrees factorized, and solved, concurrently: supernodes first .. last, in
  // increasing order; `direct`: the first of the postorder, whose updates of the rows above
  // it come before any other's and are made in place
  struct Task { int first, last; bool direct; };
  std::vector<Task> m_tasks;
  mutable std::vector<std::vector<double> > m_task_scratch, m_task_log;
  mutable Eigen::VectorXd m_permuted;
  bool m_ok = false;
};

/// The factorization as a model of `SparseLinearAlgebraWithFactorTraits_d` for the
/// eigen-solver's shift-invert operator. `smallest_generalized_eigenpairs()` hands it a
/// matrix in a postorder of its elimination tree, which its solves need not permute.
class Supernodal_cholesky_traits
{
public:
  class Matrix
  {
  public:
    explicit Matrix(int n) : m_matrix(n, n) {}
    Matrix(const Eigen::SparseMatrix<double>& m) : m_matrix(m) {}
    void set_coef(int i, int j, double value, bool /* new_coef */) { m_matrix.coeffRef(i, j) = value; }
    const Eigen::SparseMatrix<double>& eigen_object() const { return m_matrix; }
  private:
    Eigen::SparseMatrix<double> m_matrix;
  };
  typedef Eigen::VectorXd Vector;

  bool factor(const Matrix& A, double& D)
  {
    D = 1;
    return m_cholesky.factor(A.eigen_object());
  }

  bool linear_solver(const Vector& b, Vector& x)
  {
    if(!m_cholesky.ok())
      return false;
    x = b;
    m_cholesky.solve_in_place(x.data());
    return true;
  }

  const Supernodal_cholesky& factorization() const { return m_cholesky; }
  /// see `Supernodal_cholesky::set_parallel()`
  void set_parallel(bool parallel) { m_cholesky.set_parallel(parallel); }

private:
  Supernodal_cholesky m_cholesky;
};

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_SPECTRAL_SUPERNODAL_CHOLESKY_H
