#!/bin/sh
# Compile cost of a first program: the README's fifteen-line program against the same file
# around Heat_method_3, Release (-O3 -DNDEBUG), the downstream project's flags, no ccache, one
# job, RUNS times each (interleaved). Prints the median user CPU (s), wall time (s) and peak
# memory (MB) of each compiler run, and the ratios.
# usage: sh benchmark/Surface_voronoi_diagram/compile_cost.sh [SOURCE_TREE] [RUNS]
set -e
here=$(cd "$(dirname "$0")" && pwd)
source_tree=$(cd "${1:-$here/../..}" && pwd)
runs=${2:-3}
build=${COMPILE_COST_BUILD:-$source_tree/build/compile_cost}
rm -rf "$build"
cmake -S "$here/compile_cost" -B "$build" -DCMAKE_BUILD_TYPE=Release -DSVD_SOURCE_DIR="$source_tree" >/dev/null
i=0
while [ $i -lt "$runs" ]; do
  for p in readme_program heat_method_program; do
    rm -f "$build/CMakeFiles/$p.dir/$p.cpp.o"
    cmake --build "$build" --target $p -j1 >/dev/null
  done
  i=$((i + 1))
done
median() { sort -n | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
for p in readme_program heat_method_program; do
  f="$build/$p.times"
  u=$(grep -v '^Command' "$f" | awk '{ print $1 }' | median)
  w=$(grep -v '^Command' "$f" | awk '{ print $2 }' | median)
  m=$(grep -v '^Command' "$f" | awk '{ print $3 / 1024 }' | median)
  eval "${p}_u=$u ${p}_w=$w ${p}_m=$m"
done
echo "load: $(cut -d' ' -f1-3 /proc/loadavg)  source: $source_tree ($(git -C "$source_tree" rev-parse --short HEAD 2>/dev/null || echo '?'))  runs: $runs"
printf '%-22s %10s %10s %12s\n' program user_s wall_s peak_MB
printf '%-22s %10s %10s %12.0f\n' readme_program "$readme_program_u" "$readme_program_w" "$readme_program_m"
printf '%-22s %10s %10s %12.0f\n' heat_method_program "$heat_method_program_u" "$heat_method_program_w" "$heat_method_program_m"
awk -v a="$readme_program_u" -v b="$heat_method_program_u" -v c="$readme_program_w" -v d="$heat_method_program_w" \
    -v e="$readme_program_m" -v f="$heat_method_program_m" \
    'BEGIN { printf "%-22s %9.2fx %9.2fx %11.2fx\n", "ratio", a / b, c / d, e / f }'
