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
// The `callback` named parameter as a std::function (empty when it is not given).

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_CALLBACK_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_CALLBACK_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Named_function_parameters.h>

#include <functional>
#include <type_traits>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

/// the callable `bool(double)` given as `callback`, or an empty function
template <class NamedParameters>
std::function<bool(double)> callback_of(const NamedParameters& np)
{
  if constexpr(CGAL::parameters::is_default_parameter<NamedParameters, CGAL::internal_np::callback_t>::value)
    return std::function<bool(double)>();
  else
    return CGAL::parameters::get_parameter(np, CGAL::internal_np::callback);
}

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_CALLBACK_H
