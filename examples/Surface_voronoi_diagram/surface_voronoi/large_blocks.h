// Copyright (c) 2026 The Surface_voronoi_diagram authors.
// All rights reserved.
//
// This file is part of the Surface_voronoi_diagram package for CGAL (www.cgal.org).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : The Surface_voronoi_diagram authors
//
// How the program backs its large blocks of memory (large_blocks.cpp says how and why).

#ifndef SVD_PROGRAM_LARGE_BLOCKS_H
#define SVD_PROGRAM_LARGE_BLOCKS_H

namespace svd_program {

/// Blocks of 4 MB and more mapped from the system, returned to it when freed, and backed by
/// transparent huge pages unless the host takes freed huge pages back (free page reporting) or
/// the environment sets `SVD_HUGE_PAGES=0` (`SVD_HUGE_PAGES=1` gives them in any case); Linux
/// with glibc, elsewhere nothing changes. Call it first in `main()`.
void set_large_block_policy();

} // namespace svd_program

#endif // SVD_PROGRAM_LARGE_BLOCKS_H
