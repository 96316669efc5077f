#!/bin/sh
# Fails when the surface_voronoi program (examples/Surface_voronoi_diagram/surface_voronoi)
# uses the library's internal names (namespace Surface_voronoi::internal or internal_np, an
# internal/ header), which a user of the package cannot rely on, or when the library's headers
# declare a `namespace hooks`: named parameters are documented in
# Surface_voronoi::parameters, or internal. Prints file:line for each.
#   sh scripts/check_public_names.sh [ROOT]   (ROOT: the source tree, default this one)
root=${1:-$(cd "$(dirname "$0")/.." && pwd)}
program=$root/examples/Surface_voronoi_diagram/surface_voronoi
[ -d "$root/include/CGAL" ] && [ -d "$program" ] || { echo "no include/CGAL or program in $root" >&2; exit 2; }
status=0
found=$(grep -rnE '(Surface_voronoi|SV)::internal(_np)?\b|CGAL/Surface_voronoi_diagram/internal/' "$program")
if [ -n "$found" ]; then
  echo "$found" | sed "s|^$root/||"
  echo "the program uses internal names of the library (see above)" >&2
  status=1
fi
found=$(grep -rnE '\bnamespace[[:space:]]+hooks\b' "$root/include/CGAL")
if [ -n "$found" ]; then
  echo "$found" | sed "s|^$root/||"
  echo "a namespace hooks in include/CGAL (see above)" >&2
  status=1
fi
[ $status -eq 0 ] && echo "the program uses public names only; include/CGAL has no namespace hooks"
exit $status
