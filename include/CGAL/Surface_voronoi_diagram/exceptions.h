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
// The exceptions of the package. Invalid input is a failed precondition
// (`CGAL_precondition_msg`; `validate_input()` reports it in every build). Exceptions are
// thrown only where the check protects memory and stays on in every build (a site that is
// not on the mesh, a metric built on another mesh), where the caller asked for a check
// (`max_site_distance`), and for failures that valid input can still meet (the eigen-solver).

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_EXCEPTIONS_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_EXCEPTIONS_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/config.h>

#include <cstddef>
#include <stdexcept>
#include <string>

namespace CGAL {
namespace Surface_voronoi {

/// \ingroup PkgSurfaceVoronoiDiagramRef
/// Base class of every exception thrown by the package.
class Error : public std::runtime_error
{
public:
  /// an error with the message `what`
  explicit Error(const std::string& what) : std::runtime_error(what) {}
};

/// \ingroup PkgSurfaceVoronoiDiagramRef
/// An input that would make the computation read memory it must not: a site that is not on
/// the mesh (a descriptor of another mesh, non-finite coordinates), a metric built on
/// another mesh, a `Vertex_embedding` whose map gives a number of coordinates other than its
/// dimension. These checks stay on in every build.
class Input_error : public Error
{
public:
  /// an error with the message `what`
  explicit Input_error(const std::string& what) : Error(what) {}
};

/// \ingroup PkgSurfaceVoronoiDiagramRef
/// A site given as a point is farther from the surface than the named parameter
/// `max_site_distance` allows.
class Site_too_far_error : public Input_error
{
public:
  /// site `site` is `distance` away from the surface
  Site_too_far_error(const std::string& what, std::size_t site, double distance)
    : Input_error(what), site(site), distance(distance)
  {}
  /// the index of the site
  std::size_t site;
  /// its distance from the surface
  double distance;
};

/// \ingroup PkgSurfaceVoronoiDiagramRef
/// A numerical computation failed although the input was valid (the eigen-solver did not
/// converge, a factorization failed, a metric returned a value that is not a number).
class Numerical_error : public Error
{
public:
  /// an error with the message `what`
  explicit Numerical_error(const std::string& what) : Error(what) {}
};

/// \ingroup PkgSurfaceVoronoiDiagramDeprecated
/// \deprecated Coincident sites are a precondition violation now (see `validate_input()`
/// and the named parameter `Surface_voronoi::parameters::coincident_sites`, whose
/// `Coincident_sites::MERGE` accepts them); nothing throws this any more.
class CGAL_DEPRECATED_MSG("coincident sites are a precondition; see the named parameter coincident_sites")
Coincident_sites_error : public Input_error
{
public:
  /// sites `first` and `second` are at the same surface point
  Coincident_sites_error(const std::string& what, std::size_t first, std::size_t second)
    : Input_error(what), first(first), second(second)
  {}
  /// the lower index
  std::size_t first;
  /// the higher index
  std::size_t second;
};

} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_EXCEPTIONS_H
