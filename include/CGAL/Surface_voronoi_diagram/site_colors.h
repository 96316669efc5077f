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
// The package's one colour scheme for cells: a colour per site index, the same in the
// program's PLY files, in draw() and in the manual's figures.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_SITE_COLORS_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_SITE_COLORS_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/IO/Color.h>

#include <cmath>
#include <cstdint>

namespace CGAL {
namespace Surface_voronoi {

/// \ingroup PkgSurfaceVoronoiDiagramOutputs
///
/// The colour of the cell of site `site`, for output meshes and pictures: opaque, the same
/// for a site index on every run and platform, and well spread over the sites. The hue of
/// site \f$ i \f$ steps by the golden ratio (\f$ 0.1 + 0.618\ldots i \f$ turns), so that
/// sites of close indices get far-apart hues; saturation and value vary over the sites by
/// two other irrational steps, so that sites of similar hue still differ. A negative site
/// (area that no site reaches, labelled -1 by `make_arrangement()`) is grey (160, 160, 160).
///
/// To colour an arrangement, put `site_color(site[f])` into a face property map, e.g. the
/// `f:color` property of a `Surface_mesh`, which `CGAL::IO::write_PLY()` writes as the
/// `red green blue alpha` of each face.
///
/// \param site a site index, or a negative value for no site
/// \returns the colour of `site`, with alpha 255
inline CGAL::IO::Color site_color(std::int64_t site)
{
  if(site < 0)
    return CGAL::IO::Color(160, 160, 160, 255);
  const double i = double(site);
  const double hue = std::fmod(0.1 + 0.6180339887498949 * i, 1.0) * 6.0;   // in sixths of a turn
  const double saturation = 0.45 + 0.4 * std::fmod(0.7548776662466927 * i, 1.0);
  const double value = 0.95 - 0.25 * std::fmod(0.5698402909980532 * i, 1.0);
  // HSV to RGB: `sector` is the sixth of the hue circle, `f` the position inside it
  const int sector = int(hue);
  const double f = hue - sector;
  const double lowest = value * (1 - saturation);
  const double falling = value * (1 - saturation * f);
  const double rising = value * (1 - saturation * (1 - f));
  double rgb[3];
  switch(sector % 6)
  {
  case 0: rgb[0] = value; rgb[1] = rising; rgb[2] = lowest; break;
  case 1: rgb[0] = falling; rgb[1] = value; rgb[2] = lowest; break;
  case 2: rgb[0] = lowest; rgb[1] = value; rgb[2] = rising; break;
  case 3: rgb[0] = lowest; rgb[1] = falling; rgb[2] = value; break;
  case 4: rgb[0] = rising; rgb[1] = lowest; rgb[2] = value; break;
  default: rgb[0] = value; rgb[1] = lowest; rgb[2] = falling; break;
  }
  return CGAL::IO::Color(static_cast<unsigned char>(255 * rgb[0]), static_cast<unsigned char>(255 * rgb[1]),
                         static_cast<unsigned char>(255 * rgb[2]), 255);
}

} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_SITE_COLORS_H
