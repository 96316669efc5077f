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
// The timer behind the named parameter `stage_times` (see `Stage_times`).

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_STAGE_TIMES_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_STAGE_TIMES_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/Diagram_statistics.h>

#include <CGAL/Real_timer.h>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

/// Adds the wall time since the previous `stop()` (or since construction) to a stage.
class Stage_timer
{
public:
  explicit Stage_timer(Stage_times* times) : m_times(times)
  {
    if(m_times) m_timer.start();
  }

  void stop(const char* stage)
  {
    if(!m_times) return;
    m_timer.stop();
    m_times->seconds[stage] += m_timer.time();
    m_timer.reset();
    m_timer.start();
  }

private:
  Stage_times* m_times;
  CGAL::Real_timer m_timer;
};

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_STAGE_TIMES_H
