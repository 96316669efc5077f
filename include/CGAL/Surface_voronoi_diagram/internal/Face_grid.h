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
// The nearest face of a point, for points near the surface (sites read from a file, Lloyd's
// centroids): a uniform grid of the faces' bounding boxes, searched in rings of cells around
// the point. The grid is built by counting, in two passes over the faces; a tree over every
// face would sort them, which costs more than all the queries a diagram makes.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_FACE_GRID_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_FACE_GRID_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/internal/Double_kernel.h>

#include <CGAL/Bbox_3.h>

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

class Face_grid
{
public:
  /// `corner(f, k)`: corner k of face f, a `Point_d` with finite coordinates; cells at least
  /// `smallest_cell` wide
  template <class Corner>
  Face_grid(std::size_t number_of_faces, const Corner& corner, double smallest_cell = 0) : m_faces(number_of_faces)
  {
    double extent = 0;
    for(std::size_t f = 0; f < m_faces; ++f)
    {
      const CGAL::Bbox_3 b = box_of(f, corner);
      for(int a = 0; a < 3; ++a)
      {
        m_low[a] = (std::min)(m_low[a], b.min(a));
        m_high[a] = (std::max)(m_high[a], b.max(a));
        extent += (b.max(a) - b.min(a)) / 3;
      }
    }
    if(m_faces == 0) return;
    // cells about the size of a face, but not more than a few per face
    const double volume = (m_high[0] - m_low[0]) * (m_high[1] - m_low[1]) * (m_high[2] - m_low[2]);
    m_h = (std::max)({ extent / double(m_faces), std::cbrt(volume / (4. * double(m_faces))), smallest_cell, 1e-300 });
    for(;; m_h *= 1.25)
    {
      double cells = 1;
      for(int a = 0; a < 3; ++a)
      {
        const double q = (m_high[a] - m_low[a]) / m_h;   // beyond doubles' range: one cell
        cells *= double(m_n[a] = (q < 1e9) ? std::size_t(q) + 1 : 1);
      }
      if(cells <= 4. * double(m_faces) + 64) break;
    }
    // a counting sort of the (cell, face) pairs; a face over many cells is tried by every query
    m_begin.assign(m_n[0] * m_n[1] * m_n[2] + 1, 0);
    std::vector<std::size_t> fill;
    for(int pass = 0; pass < 2; ++pass)
    {
      for(std::size_t f = 0; f < m_faces; ++f)
      {
        const CGAL::Bbox_3 b = box_of(f, corner);
        std::array<std::size_t, 3> lo, hi;
        for(int a = 0; a < 3; ++a) lo[a] = cell(b.min(a), a), hi[a] = cell(b.max(a), a);
        if((hi[0] - lo[0] + 1) * (hi[1] - lo[1] + 1) * (hi[2] - lo[2] + 1) > 64)
        {
          if(pass == 0) m_large.push_back(std::uint32_t(f));
          continue;
        }
        for(std::size_t z = lo[2]; z <= hi[2]; ++z)
          for(std::size_t y = lo[1]; y <= hi[1]; ++y)
            for(std::size_t x = lo[0]; x <= hi[0]; ++x)
            {
              const std::size_t c = x + m_n[0] * (y + m_n[1] * z);
              if(pass == 0) ++m_begin[c + 1];
              else m_entries[fill[c]++] = std::uint32_t(f);
            }
      }
      if(pass == 1) break;
      for(std::size_t c = 1; c < m_begin.size(); ++c) m_begin[c] += m_begin[c - 1];
      m_entries.resize(m_begin.back());
      fill.assign(m_begin.begin(), m_begin.end() - 1);
    }
  }

  /// The face nearest to `p` by `squared_distance(f)` (the lowest index among equals), tried
  /// in boxes around `p` doubling in size until no face outside the box can be as near; far
  /// from the surface the box grows to the whole grid.
  template <class Squared_distance>
  std::size_t nearest(const Point_d& p, const Squared_distance& squared_distance) const
  {
    std::size_t best = m_faces;
    double best_d2 = std::numeric_limits<double>::infinity();
    auto offer = [&](std::size_t f) {
      const double d2 = squared_distance(f);
      if(d2 < best_d2 || (d2 == best_d2 && f < best)) best = f, best_d2 = d2;
    };
    // a face outside the box [p - r, p + r] is at least r away; a box of many cells is a
    // point far from the surface, which tries every face instead
    for(double r = m_h / 4; m_faces > 0; r *= 2)
    {
      if(std::pow(2 * r / m_h + 1, 3) > 4096. + double(m_faces) / 16)
      {
        for(std::size_t f = 0; f < m_faces; ++f) offer(f);
        break;
      }
      const Point_d lo(p.x() - r, p.y() - r, p.z() - r), hi(p.x() + r, p.y() + r, p.z() + r);
      for_each_near(lo, hi, offer);
      bool whole_grid = true;
      for(int a = 0; a < 3; ++a) whole_grid = whole_grid && lo[a] <= m_low[a] && hi[a] >= m_high[a];
      if(whole_grid || best_d2 < r * r) break;
    }
    return best;
  }

  /// Calls `f(i)` for every item `i` stored in a cell that meets the box [lo, hi]
  /// (clamped to the grid), and for the items spanning many cells.
  template <class Function>
  void for_each_near(const Point_d& lo, const Point_d& hi, const Function& f) const
  {
    for(std::uint32_t i : m_large) f(i);
    if(m_faces == 0) return;
    std::array<std::size_t, 3> a, b;
    for(int k = 0; k < 3; ++k) a[k] = cell(lo[k], k), b[k] = cell(hi[k], k);
    for(std::size_t z = a[2]; z <= b[2]; ++z)
      for(std::size_t y = a[1]; y <= b[1]; ++y)
        for(std::size_t x = a[0]; x <= b[0]; ++x)
        {
          const std::size_t c = x + m_n[0] * (y + m_n[1] * z);
          for(std::size_t j = m_begin[c]; j < m_begin[c + 1]; ++j) f(m_entries[j]);
        }
  }

private:
  template <class Corner>
  static CGAL::Bbox_3 box_of(std::size_t f, const Corner& corner)
  {
    return corner(f, 0).bbox() + corner(f, 1).bbox() + corner(f, 2).bbox();
  }

  // the cell of coordinate x along axis a, clamped to the grid
  std::size_t cell(double x, int a) const
  {
    const double t = std::floor((x - m_low[a]) / m_h);
    return (t > 0) ? (std::min)(std::size_t(t), m_n[a] - 1) : 0;
  }

  std::size_t m_faces;
  std::array<double, 3> m_low{ { DBL_MAX, DBL_MAX, DBL_MAX } }, m_high{ { -DBL_MAX, -DBL_MAX, -DBL_MAX } };
  double m_h = 1;
  std::array<std::size_t, 3> m_n{ { 1, 1, 1 } };
  std::vector<std::size_t> m_begin;
  std::vector<std::uint32_t> m_entries, m_large;
};

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_FACE_GRID_H
