#!/bin/sh
# Compile cost of a first program: the README's fifteen-line program against the same file
# around Heat_method_3, Release (-O3 -DNDEBUG), the flags a downstream project gets from the
# package's target, no ccache, one job, RUNS times each. Several source trees (a base commit's
# worktree and this one) are compiled in turn within each run, so that they share the load.
# Prints per tree the median user CPU (s), wall time (s) and peak memory (MB) of the compiler
# and the ratios of the README program to the Heat_method_3 one.
# usage: sh benchmark/Surface_voronoi_diagram/compile_cost.sh [-n RUNS] [SOURCE_TREE ...]
set -e
here=$(cd "$(dirname "$0")" && pwd)
runs=3
if [ "$1" = "-n" ]; then runs=$2; shift 2; fi
[ $# -gt 0 ] || set -- "$here/../.."
work=${COMPILE_COST_BUILD:-$here/../../build/compile_cost}
rm -rf "$work"
mkdir -p "$work"
k=0
for tree in "$@"; do
  tree=$(cd "$tree" && pwd)
  echo "$tree" >"$work/tree$k"
  cmake -S "$here/compile_cost" -B "$work/$k" -DCMAKE_BUILD_TYPE=Release -DSVD_SOURCE_DIR="$tree" >/dev/null
  k=$((k + 1))
done
i=0
while [ $i -lt "$runs" ]; do
  j=0
  while [ $j -lt $k ]; do
    for p in readme_program heat_method_program; do
      rm -f "$work/$j/CMakeFiles/$p.dir/$p.cpp.o"
      cmake --build "$work/$j" --target $p -j1 >/dev/null
    done
    j=$((j + 1))
  done
  i=$((i + 1))
done
median() { sort -n | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
column() { grep -v '^Command' "$1" | awk -v c="$2" '{ print (c == 3) ? $c / 1024 : $c }' | median; }
echo "load: $(cut -d' ' -f1-3 /proc/loadavg)  runs: $runs  compiler: $(c++ --version | head -n 1)"
printf '%-10s %-20s %8s %8s %9s\n' tree program user_s wall_s peak_MB
j=0
while [ $j -lt $k ]; do
  tree=$(cat "$work/tree$j")
  name=$(git -C "$tree" rev-parse --short HEAD 2>/dev/null || echo "$tree")
  for p in readme_program heat_method_program; do
    printf '%-10s %-20s %8s %8s %9.0f\n' "$name" $p "$(column "$work/$j/$p.times" 1)" \
           "$(column "$work/$j/$p.times" 2)" "$(column "$work/$j/$p.times" 3)"
  done
  for c in 1 2 3; do
    eval "r$c=\$(column $work/$j/readme_program.times $c)"
    eval "h$c=\$(column $work/$j/heat_method_program.times $c)"
  done
  awk -v n="$name" -v a="$r1" -v b="$h1" -v c="$r2" -v d="$h2" -v e="$r3" -v f="$h3" \
      'BEGIN { printf "%-10s %-20s %7.2fx %7.2fx %8.2fx\n", n, "ratio", a / b, c / d, e / f }'
  j=$((j + 1))
done
