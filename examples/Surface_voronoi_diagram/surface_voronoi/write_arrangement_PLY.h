// Copyright (c) 2026 The Surface_voronoi_diagram authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The surface_voronoi program's --output file: a diagram's arrangement as a coloured PLY that
// MeshLab and ParaView show as is. Vertices `double x y z`; faces `vertex_indices`, `int site`
// (-1 where no site reaches) and `uchar red green blue alpha` (the library's site_color()).
// Outside checks compare these bytes: the layout must not change.

#ifndef SVD_PROGRAM_WRITE_ARRANGEMENT_PLY_H
#define SVD_PROGRAM_WRITE_ARRANGEMENT_PLY_H

#include "errors.h"

#include <CGAL/Surface_voronoi_diagram/arrangement.h>
#include <CGAL/Surface_voronoi_diagram/site_colors.h>

#include <CGAL/IO/Color.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh/IO/PLY.h>

#include "output_file.h"

#include <cmath>
#include <cstdint>
#include <fstream>
#include <string>

namespace svd_program {

/// The arrangement as a `Surface_mesh` of double points with the face properties
/// `f:site` (`std::int32_t`) and `f:color`, ready for CGAL's PLY writer.
template <class Diagram>
CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3> arrangement_for_PLY(const Diagram& diagram)
{
  typedef CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3> Mesh;
  Mesh out;
  auto site = out.add_property_map<Mesh::Face_index, std::int32_t>("f:site", -1).first;
  CGAL::Surface_voronoi::make_arrangement(diagram, out, CGAL::parameters::face_patch_map(site));
  auto color = out.add_property_map<Mesh::Face_index, CGAL::IO::Color>("f:color").first;
  for(Mesh::Face_index f : out.faces())
    color[f] = CGAL::Surface_voronoi::site_color(site[f]);
  return out;
}

/// Writes the arrangement to `filename` (binary little-endian PLY, or ASCII with 17 digits),
/// its points multiplied by 2^`scale_exponent` (the program's normalization, undone exactly),
/// with `write_output_file()`: a failed write leaves no partial file.
/// \throws Write_error if the file cannot be written
template <class Diagram>
void write_arrangement_PLY(const std::string& filename, const Diagram& diagram, bool binary = true, int scale_exponent = 0)
{
  auto mesh = arrangement_for_PLY(diagram);
  if(scale_exponent != 0)
    for(auto v : mesh.vertices())
    {
      const auto& p = mesh.point(v);
      mesh.point(v) = typename decltype(mesh)::Point(std::ldexp(p.x(), scale_exponent), std::ldexp(p.y(), scale_exponent),
                                                     std::ldexp(p.z(), scale_exponent));
    }
  write_output_file(filename, binary, [&](std::ostream& os) {
    if(binary)
      CGAL::IO::set_binary_mode(os);
    else
    {
      CGAL::IO::set_ascii_mode(os);
      os.precision(17);
    }
    return CGAL::IO::write_PLY(os, mesh, "surface_voronoi arrangement") && static_cast<bool>(os);
  });
}

} // namespace svd_program

#endif // SVD_PROGRAM_WRITE_ARRANGEMENT_PLY_H
