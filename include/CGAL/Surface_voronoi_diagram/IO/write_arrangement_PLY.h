// Copyright (c) 2026 The Surface_voronoi_diagram authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Writes a diagram's arrangement as a coloured PLY that MeshLab and ParaView show as is:
// vertices `double x y z`, faces `vertex_indices`, `int site` (-1 where no site reaches)
// and `uchar red green blue alpha`.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_IO_WRITE_ARRANGEMENT_PLY_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_IO_WRITE_ARRANGEMENT_PLY_H

#include <CGAL/Surface_voronoi_diagram/arrangement.h>
#include <CGAL/Surface_voronoi_diagram/exceptions.h>

#include <CGAL/IO/Color.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh/IO/PLY.h>

#include <cstdint>
#include <fstream>
#include <string>

namespace CGAL {
namespace Surface_voronoi {
namespace IO {

/// \ingroup PkgSurfaceVoronoiDiagramIO
/// A colour per site, deterministic and well spread (golden-ratio hues); grey for -1.
inline CGAL::IO::Color site_color(std::int64_t site)
{
  if(site < 0) return CGAL::IO::Color(160, 160, 160, 255);
  const double h = std::fmod(0.1 + 0.6180339887498949 * double(site), 1.0) * 6.0;
  const double s = 0.45 + 0.4 * std::fmod(0.7548776662466927 * double(site), 1.0);
  const double v = 0.95 - 0.25 * std::fmod(0.5698402909980532 * double(site), 1.0);
  const int i = int(h);
  const double f = h - i, p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
  double r = v, g = t, b = p;
  switch(i % 6)
  {
  case 0: r = v; g = t; b = p; break;
  case 1: r = q; g = v; b = p; break;
  case 2: r = p; g = v; b = t; break;
  case 3: r = p; g = q; b = v; break;
  case 4: r = t; g = p; b = v; break;
  default: r = v; g = p; b = q; break;
  }
  return CGAL::IO::Color(static_cast<unsigned char>(255 * r), static_cast<unsigned char>(255 * g),
                         static_cast<unsigned char>(255 * b), 255);
}

/// \ingroup PkgSurfaceVoronoiDiagramIO
/// The arrangement as a `Surface_mesh` of double points with the face properties
/// `f:site` (`std::int32_t`) and `f:color`, ready for CGAL's PLY writer.
template <class Diagram>
CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3> arrangement_for_PLY(const Diagram& diagram)
{
  typedef CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3> Mesh;
  Mesh out;
  auto site = out.add_property_map<Mesh::Face_index, std::int32_t>("f:site", -1).first;
  make_arrangement(diagram, out, CGAL::parameters::face_patch_map(site));
  auto color = out.add_property_map<Mesh::Face_index, CGAL::IO::Color>("f:color").first;
  for(Mesh::Face_index f : out.faces()) color[f] = site_color(site[f]);
  return out;
}

/// \ingroup PkgSurfaceVoronoiDiagramIO
/// Writes the arrangement to `filename` (binary little-endian PLY, or ASCII with 17 digits).
/// \throws Surface_voronoi::Error if the file cannot be written
template <class Diagram>
void write_arrangement_PLY(const std::string& filename, const Diagram& diagram, bool binary = true)
{
  auto mesh = arrangement_for_PLY(diagram);
  std::ofstream os(filename, binary ? std::ios::binary : std::ios::out);
  if(!os)
    throw Error("cannot open '" + filename + "' for writing");
  if(binary)
    CGAL::IO::set_binary_mode(os);
  else
  {
    CGAL::IO::set_ascii_mode(os);
    os.precision(17);
  }
  if(!CGAL::IO::write_PLY(os, mesh, "surface_voronoi arrangement") || !os)
    throw Error("failed to write '" + filename + "'");
}

} // namespace IO
} // namespace Surface_voronoi
} // namespace CGAL

#endif
