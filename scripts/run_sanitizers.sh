#!/bin/sh
# The sanitizer job (.ci/run calls it after the test suite): one Clang build with AddressSanitizer
# and UndefinedBehaviorSanitizer, without NDEBUG (so CGAL's assertions and preconditions are
# on), of the program, the precondition tests and the libFuzzer harnesses. It then runs
#  1. the precondition tests;
#  2. the program over the whole bad-input corpus (test/Surface_voronoi_diagram/bad_input);
#  3. the program on two small real meshes of CGAL's data set (the bundled meshes without it);
#  4. each fuzzer over its committed seed corpus, then for a fixed seed and number of runs,
#     so that the job is deterministic (SVD_FUZZ_RUNS overrides the number of runs).
# Any sanitizer report, failed case or crash fails the job.
set -e
cd "$(dirname "$0")/.."

need=""
for p in clang libclang-rt-14-dev; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || need="$need $p"
done
if [ -n "$need" ]; then
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  echo "installing:$need"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends $need >/dev/null
fi

build=build/sanitize
# line tables are all a sanitizer report needs (file:line in its stack); full debug information
# took a tenth more of the compile time and twice the object size
flags="-O1 -gline-tables-only -fno-omit-frame-pointer -fsanitize=address,undefined -fno-sanitize-recover=all"
CXX=clang++ cmake -S . -B $build -DCMAKE_BUILD_TYPE=Sanitize -DCMAKE_CXX_FLAGS_SANITIZE="$flags" \
  -DSVD_BUILD_TESTS=ON -DSVD_BUILD_FUZZERS=ON >/dev/null
cmake --build $build -j2 --target svd_sanitizer_binaries

export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:allocator_may_return_null=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
program=$build/surface_voronoi
fuzz=$build/test/Surface_voronoi_diagram/fuzz
work=$build/sanitizer_runs
rm -rf $work && mkdir -p $work

echo "== precondition tests (ASan+UBSan, assertions on)"
$build/test/Surface_voronoi_diagram/svd_precondition_tests

echo "== the program over the bad-input corpus"
# every case stays within 10 s under the sanitizers too (slowest measured: 5 s, loaded machine);
# the factor 2 is margin for a slower CI machine. Their shadow memory needs more than 4 GiB.
python3 test/Surface_voronoi_diagram/bad_input/run_bad_input.py $program --work $work/bad_input \
  --time-factor 2 --no-memory-limit

echo "== the program on small real meshes"
meshes=$build/cgal_data/data/meshes
if [ -f $meshes/elephant.off ] && [ -f $meshes/cactus.off ]; then
  first=$meshes/elephant.off second=$meshes/cactus.off
else
  first=examples/Surface_voronoi_diagram/data/torus.off second=examples/Surface_voronoi_diagram/data/lampshade_thin.off
fi
for metric in biharmonic geodesic; do
  $program $first --random 200 --metric $metric --lloyd 2 --output $work/first.ply --dual $work/first.off --stats >/dev/null
done
$program $second --blue-noise 60 --metric euclidean --insert-sites --output $work/second.ply --sites-out $work/second.xyz
$program $second --sites $work/second.xyz --metric rvd --output $work/second_rvd.ply

echo "== fuzzers: the seed corpus, then a fixed seed and number of runs"
# runs per harness, sized so that the three take about a minute together
for harness_runs in fuzz_mesh_reader:30000 fuzz_sites_reader:100000 fuzz_pipeline:15000; do
  harness=${harness_runs%%:*}
  runs=${SVD_FUZZ_RUNS:-${harness_runs#*:}}
  corpus=test/Surface_voronoi_diagram/fuzz/corpus/${harness#fuzz_}
  # the committed corpus stays as it is: new inputs go to a copy
  rm -rf $work/$harness && mkdir -p $work/$harness && cp $corpus/* $work/$harness/
  $fuzz/$harness -runs=0 $corpus
  if ! $fuzz/$harness -seed=1 -runs=$runs -max_len=4096 -timeout=20 -rss_limit_mb=4096 \
       -artifact_prefix=$work/ $work/$harness >$work/$harness.log 2>&1; then
    tail -n 60 $work/$harness.log
    echo "$harness failed: the input is in $work/ (crash-*, timeout-* or oom-*)"
    exit 1
  fi
  grep "^Done" $work/$harness.log
done
echo "sanitizer job passed"
