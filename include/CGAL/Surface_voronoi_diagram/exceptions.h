// Copyright (c) 2026 The Surface_voronoi_diagram authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Errors thrown by the package. Every failure the caller can cause (bad mesh,
// bad sites, solver breakdown) is reported as one of these, with a message that
// says what is wrong and where; the package never aborts on bad input.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_EXCEPTIONS_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_EXCEPTIONS_H

#include <stdexcept>
#include <cstddef>
#include <string>

namespace CGAL {
namespace Surface_voronoi {

/// \ingroup PkgSurfaceVoronoiDiagramRef
/// Base class of every error thrown by the package.
class Error : public std::runtime_error
{
public:
  explicit Error(const std::string& what) : std::runtime_error(what) {}
};

/// \ingroup PkgSurfaceVoronoiDiagramRef
/// The input (mesh, sites, options or files) violates a documented precondition.
class Input_error : public Error
{
public:
  explicit Input_error(const std::string& what) : Error(what) {}
};

/// \ingroup PkgSurfaceVoronoiDiagramRef
/// Two sites are at the same surface point; `first` and `second` are their indices.
class Coincident_sites_error : public Input_error
{
public:
  Coincident_sites_error(const std::string& what, std::size_t first, std::size_t second)
    : Input_error(what), first(first), second(second)
  {}
  std::size_t first, second;
};

/// \ingroup PkgSurfaceVoronoiDiagramRef
/// A site given as a point is farther from the surface than the allowed distance.
class Site_too_far_error : public Input_error
{
public:
  Site_too_far_error(const std::string& what, std::size_t site, double distance)
    : Input_error(what), site(site), distance(distance)
  {}
  std::size_t site;
  double distance;
};

/// \ingroup PkgSurfaceVoronoiDiagramRef
/// A numerical computation failed (eigen-solver did not converge, factorization failed).
class Numerical_error : public Error
{
public:
  explicit Numerical_error(const std::string& what) : Error(what) {}
};

} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_EXCEPTIONS_H
