// Copyright (c) 2026 The Surface_voronoi_diagram authors.
// All rights reserved.
//
// This file is part of the Surface_voronoi_diagram package for CGAL (www.cgal.org).
//
// $URL$
// $Id$
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Loops over fixed-size chunks, run by TBB when the diagram's concurrency tag asks for it.
// The chunks do not depend on the number of threads, and whatever a chunk gathers is merged
// in chunk order afterwards, so a parallel run computes the same bits as a sequential one.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_PARALLEL_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_PARALLEL_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/tags.h>
#include <CGAL/use.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/global_control.h>
#include <tbb/task_arena.h>
#include <tbb/task_group.h>
#endif

#include <algorithm>
#include <cstddef>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

/// Whether `ConcurrencyTag` asks for threads; `Parallel_tag` without TBB is a compile error,
/// as in CGAL's other packages.
template <class ConcurrencyTag>
constexpr bool is_parallel()
{
#ifndef CGAL_LINKED_WITH_TBB
  static_assert(!std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value,
                "Parallel_tag is enabled but TBB is unavailable (link CGAL::TBB_support, or use Parallel_if_available_tag)");
#endif
  return std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value;
}

/// Whether to run the chunked parallel paths now: `ConcurrencyTag` asks for threads and TBB
/// allows more than one (with one, as under `tbb::global_control` limited to 1, the
/// sequential paths do the same work without gathering what the chunks find).
template <class ConcurrencyTag>
bool use_threads()
{
#ifdef CGAL_LINKED_WITH_TBB
  return is_parallel<ConcurrencyTag>() && tbb::this_task_arena::max_concurrency() > 1
         && tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism) > 1;
#else
  return is_parallel<ConcurrencyTag>();
#endif
}

/// Number of chunks `for_each_chunk(n, size, ...)` makes.
inline std::size_t number_of_chunks(std::size_t n, std::size_t size) { return (n + size - 1) / size; }

// The one place TBB's loop is instantiated: `call(context, first, last)` for the chunks
// [first, last) of [0, chunks), in one call when `parallel` is false or TBB is absent,
// concurrently otherwise. The templates below pass their function through `context`, so that
// each of them compiles a small function instead of another copy of TBB's loop.
typedef void (*Chunk_range_call)(const void* context, std::size_t first, std::size_t last);

inline void run_chunk_ranges(std::size_t chunks, bool parallel, Chunk_range_call call, const void* context)
{
#ifdef CGAL_LINKED_WITH_TBB
  if(parallel && chunks > 1)
  {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, chunks, 1),
                      [call, context](const tbb::blocked_range<std::size_t>& r) { call(context, r.begin(), r.end()); });
    return;
  }
#else
  CGAL_USE(parallel);
#endif
  call(context, 0, chunks);
}

/// Calls `f(begin, end, chunk)` for the chunks [chunk * size, (chunk + 1) * size) of [0, n):
/// in order when `parallel` is false or TBB is absent, concurrently otherwise.
template <class Function>
void for_each_chunk(std::size_t n, std::size_t size, bool parallel, const Function& f)
{
  struct Context
  {
    std::size_t n, size;
    const Function* f;
  };
  const Context context{ n, size, &f };
  run_chunk_ranges(number_of_chunks(n, size), parallel, [](const void* p, std::size_t first, std::size_t last) {
    const Context& c = *static_cast<const Context*>(p);
    for(std::size_t chunk = first; chunk != last; ++chunk) (*c.f)(chunk * c.size, (std::min)(c.n, (chunk + 1) * c.size), chunk);
  }, &context);
}

/// Calls `f(i)` for every i in [0, n), concurrently when `parallel`; `f` must not write
/// anything another index reads.
template <class Function>
void parallel_for_each_index(std::size_t n, bool parallel, const Function& f)
{
  for_each_chunk(n, 4096, parallel, [&](std::size_t begin, std::size_t end, std::size_t) {
    for(std::size_t i = begin; i < end; ++i) f(i);
  });
}

/// Where each chunk's share of a total begins, for chunks that fill one array in order:
/// `count(begin, end)` is the share of elements `[begin, end)`; the result has one entry per
/// chunk and a last one, the total.
template <class Count>
std::vector<std::size_t> chunk_offsets(std::size_t n, std::size_t size, bool parallel, const Count& count)
{
  std::vector<std::size_t> first(number_of_chunks(n, size) + 1, 0);
  for_each_chunk(n, size, parallel, [&](std::size_t begin, std::size_t end, std::size_t c) { first[c + 1] = count(begin, end); });
  for(std::size_t c = 1; c < first.size(); ++c) first[c] += first[c - 1];
  return first;
}

/// What `gather(begin, end, found)` appends to `found` for the chunks of [0, n), joined in chunk
/// order: the same vector, in the same order, whether the chunks ran concurrently or not.
template <class T, class Gather>
std::vector<T> gather_in_chunk_order(std::size_t n, std::size_t size, bool parallel, const Gather& gather)
{
  std::vector<std::vector<T> > of_chunk(number_of_chunks(n, size));
  for_each_chunk(n, size, parallel, [&](std::size_t begin, std::size_t end, std::size_t c) { gather(begin, end, of_chunk[c]); });
  std::size_t total = 0;
  for(const std::vector<T>& found : of_chunk) total += found.size();
  std::vector<T> out;
  out.reserve(total);
  for(const std::vector<T>& found : of_chunk) out.insert(out.end(), found.begin(), found.end());
  return out;
}

// The one place TBB's task group is instantiated: `main(main_context)` and
// `beside(beside_context)`, with `parallel` possibly at the same time.
typedef void (*Task_call)(const void* context);

inline void run_two_tasks(bool parallel, Task_call main, const void* main_context, Task_call beside, const void* beside_context)
{
#ifdef CGAL_LINKED_WITH_TBB
  if(parallel)
  {
    tbb::task_group group;
    group.run([beside, beside_context]() { beside(beside_context); });
    main(main_context);
    group.wait();
    return;
  }
#else
  CGAL_USE(parallel);
#endif
  main(main_context);
  beside(beside_context);
}

/// Runs `main` and `beside`, with `parallel` possibly at the same time (`beside` as a task
/// another thread may take while `main` runs); they must not write to the same data.
template <class Main, class Beside>
void run_beside(bool parallel, const Main& main, const Beside& beside)
{
  run_two_tasks(parallel, [](const void* f) { (*static_cast<const Main*>(f))(); }, &main,
                [](const void* f) { (*static_cast<const Beside*>(f))(); }, &beside);
}

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_PARALLEL_H
