// Copyright (c) 2026 The Surface_voronoi_diagram authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// libFuzzer harness of the program's mesh readers (OFF, OBJ, PLY ascii and binary, STL ascii
// and binary) and of the checks that turn a polygon soup into a triangle mesh. The first byte
// picks the format, the rest is the file. Any bytes give a valid triangle mesh or the reader's
// one error (svd_program::Input_error), never a crash, a hang, unbounded memory or a sanitizer
// report.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <surface_voronoi/read_checked_mesh.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if(size == 0) return 0;
  static const char* const formats[] = { "off", "obj", "ply", "stl" };
  typedef CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> Mesh;
  Mesh mesh;
  try
  {
    svd_program::read_checked_triangle_mesh_from_memory(reinterpret_cast<const char*>(data) + 1, size - 1,
                                                        formats[data[0] % 4], mesh);
  }
  catch(const svd_program::Input_error&)
  {
    return 0;
  }
  // what is accepted is a valid triangle mesh
  if(!CGAL::is_valid_polygon_mesh(mesh) || !CGAL::is_triangle_mesh(mesh) || num_faces(mesh) == 0)
    std::abort();
  return 0;
}
