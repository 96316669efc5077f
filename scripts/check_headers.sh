#!/bin/sh
# Fails, naming each offending file, when a header under include/CGAL lacks the preamble the
# package's headers share: the copyright line first, the SPDX licence identifier in the
# comment block that follows, and CGAL/license/Surface_voronoi_diagram.h as the first include
# (the licence file itself only needs the preamble).
cd "$(dirname "$0")/.." || exit 1
license_include='#include <CGAL/license/Surface_voronoi_diagram.h>'
spdx='// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial'
failed=0
for header in $(find include/CGAL -name '*.h' | LC_ALL=C sort); do
  if ! head -n 1 "$header" | grep -Eq '^// Copyright \(c\) [0-9]{4}(-[0-9]{4})? The Surface_voronoi_diagram authors\.$'; then
    echo "$header: the first line is not the copyright line"
    failed=1
  fi
  if ! sed -n '1,/^[^/]/p' "$header" | grep -Fxq "$spdx"; then
    echo "$header: no '$spdx' in the opening comment"
    failed=1
  fi
  [ "$header" = include/CGAL/license/Surface_voronoi_diagram.h ] && continue
  if [ "$(grep -m 1 '^[[:space:]]*#[[:space:]]*include' "$header")" != "$license_include" ]; then
    echo "$header: the first include is not $license_include"
    failed=1
  fi
done
[ $failed -eq 0 ] && echo "headers: every header under include/CGAL has the copyright, SPDX and licence include"
exit $failed
