#!/bin/sh
# Fails when the library's headers (include/CGAL) name a call that changes process-wide state
# or asks the operating system or the processor directly: Eigen's global cache sizes, the
# allocator's settings, memory advice, system queries, prefetch hints. Prints file:line for each.
#   sh scripts/check_forbidden_names.sh [ROOT]   (ROOT: the source tree, default this one)
root=${1:-$(cd "$(dirname "$0")/.." && pwd)}
[ -d "$root/include/CGAL" ] || { echo "no include/CGAL in $root" >&2; exit 2; }
found=$(grep -rnwE 'setCpuCacheSizes|madvise|mallopt|sysconf|__builtin_prefetch' "$root/include/CGAL")
if [ -n "$found" ]; then
  echo "$found" | sed "s|^$root/||"
  echo "forbidden names in include/CGAL (see above)" >&2
  exit 1
fi
echo "include/CGAL: no forbidden names"
