// Copyright (c) 2026 The Surface_voronoi_diagram authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The errors of the surface_voronoi program's own file handling (mesh reader, sites and
// breaklines files, PLY writer). The program turns each into one line on stderr and an exit
// code: an Input_error is bad input (1), a Write_error an output it cannot write (4).

#ifndef SVD_PROGRAM_ERRORS_H
#define SVD_PROGRAM_ERRORS_H

#include <stdexcept>
#include <string>

namespace svd_program {

/// A file the program reads breaks its contract; the message says what and where.
class Input_error : public std::runtime_error
{
public:
  explicit Input_error(const std::string& what) : std::runtime_error(what) {}
};

/// A file the program writes cannot be opened or written.
class Write_error : public std::runtime_error
{
public:
  explicit Write_error(const std::string& what) : std::runtime_error(what) {}
};

} // namespace svd_program

#endif // SVD_PROGRAM_ERRORS_H
