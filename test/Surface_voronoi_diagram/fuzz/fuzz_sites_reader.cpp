// Copyright (c) 2026 The Surface_voronoi_diagram authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// libFuzzer harness of the program's sites and breaklines readers: any bytes give records or
// the reader's one error (svd_program::Input_error), never a crash, a hang or a sanitizer
// report. The first byte picks the reader; a record that is returned must hold finite numbers.

#include <surface_voronoi/sites_file.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if(size == 0) return 0;
  std::istringstream in(std::string(reinterpret_cast<const char*>(data) + 1, size - 1));
  try
  {
    if(data[0] % 2 == 0)
    {
      for(const svd_program::Site_record& r : svd_program::read_sites_file(in))
        if(!std::isfinite(r.x) || !std::isfinite(r.y) || !std::isfinite(r.z) || (r.has_weight && !std::isfinite(r.weight)))
          std::abort();   // the reader promises finite values
    }
    else
      svd_program::parse_index_pairs(in);
  }
  catch(const svd_program::Input_error&)
  {
  }
  return 0;
}
