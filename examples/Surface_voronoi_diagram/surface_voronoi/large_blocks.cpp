// Copyright (c) 2026 The Surface_voronoi_diagram authors.
// All rights reserved.
//
// This file is part of the Surface_voronoi_diagram package for CGAL (www.cgal.org).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : The Surface_voronoi_diagram authors
//
// How the program's large blocks of memory are backed (Linux with glibc, without a
// sanitizer; elsewhere the allocation functions are left alone). The library itself sets
// nothing process-wide: a program of one's own may do the same. large_blocks.md, beside this
// file, gives what each setting was measured to change.
//
// - Blocks of 4 MB and more are mapped from the system and go back to it when freed
//   (`mallopt(M_MMAP_THRESHOLD)`). By default glibc raises that threshold to 32 MB after the
//   first large block is freed and keeps the freed blocks below it resident, which raises the
//   peak of the biharmonic runs.
// - The heap keeps up to 16 MB freed at its top instead of 128 KB (`M_TRIM_THRESHOLD`, which
//   glibc stops adjusting once the mmap threshold is set): the diagrams of Lloyd's iterations
//   free and allocate again arrays of a few MB each, which would otherwise be given back and
//   touched afresh every iteration.
// - Those blocks are asked to be backed by transparent huge pages (`madvise(MADV_HUGEPAGE)`,
//   which the kernel honours when its THP mode is `madvise` or `always`): one first touch of a
//   2 MB page instead of 512 of 4 KB pages. A diagram writes most of its memory once, so a
//   large share of its time is first touches, the more so on virtual machines.
// - The main heap, where the blocks below 4 MB live, gets the same advice as it grows, and
//   grows 4 MB at a time (`M_TOP_PAD`), so that the 2 MB ranges its blocks are first written
//   in mostly lie inside it (glibc's `glibc.malloc.hugetlb=1` tunable does the same, but only
//   from the environment at start-up). Larger steps leave huge pages half used at the heap's
//   top.
// - The advice is left out where the kernel gives freed 2 MB blocks back to the hypervisor
//   (free page reporting, from a virtio balloon device, at an order of 9 or less): there every
//   huge page the process gets was handed back and is backed afresh by the host at its first
//   touch, 512 host faults under one guest fault, and the advice makes runs slower.
//   `SVD_HUGE_PAGES=1` gives the advice and `SVD_HUGE_PAGES=0` leaves it out whatever the
//   machine.

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>

#if defined(__linux__) && defined(__GLIBC__) && !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__)
#if defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || __has_feature(memory_sanitizer)
#define SVD_PROGRAM_KEEP_DEFAULT_ALLOCATION
#endif
#endif
#else
#define SVD_PROGRAM_KEEP_DEFAULT_ALLOCATION
#endif

#ifndef SVD_PROGRAM_KEEP_DEFAULT_ALLOCATION
#include <atomic>
#include <dirent.h>
#include <fstream>
#include <string>
#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace svd_program {

#ifndef SVD_PROGRAM_KEEP_DEFAULT_ALLOCATION
extern "C" {
// glibc's own allocation functions, which its malloc, calloc, realloc and free call
void* __libc_malloc(std::size_t) noexcept;
void* __libc_calloc(std::size_t, std::size_t) noexcept;
void* __libc_realloc(void*, std::size_t) noexcept;
void __libc_free(void*) noexcept;
}

namespace {

constexpr std::size_t mapped_block_threshold = std::size_t(4) << 20;
constexpr std::uintptr_t page = 4096;
constexpr std::size_t heap_kept = std::size_t(16) << 20;
constexpr std::size_t heap_step = std::size_t(4) << 20;

// the end of the main heap as far as it has been advised (0: before main(), or no advice)
std::atomic<std::uintptr_t> advised_heap_end{0};
// whether blocks get the huge-page advice (set once, first thing in main())
std::atomic<bool> advise_huge_pages{false};

// The advice on the pages of a block of `n` bytes at `p`, mapped on its own (all blocks from
// the threshold up): its whole mapping; the kernel backs by huge pages the 2 MB ranges of it
// that are aligned.
void advise_mapped_block(void* p, std::size_t n)
{
  const std::uintptr_t begin = reinterpret_cast<std::uintptr_t>(p) & ~(page - 1);
  const std::uintptr_t end = (reinterpret_cast<std::uintptr_t>(p) + n + page - 1) & ~(page - 1);
  madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);   // advice: a refusal changes nothing
}

// The advice on the main heap's new pages once it has grown: each growth is a mapping of its
// own, without the advice of the one below, until advised (which merges them again).
void advise_heap_growth()
{
  const std::uintptr_t end = reinterpret_cast<std::uintptr_t>(sbrk(0));   // no system call
  std::uintptr_t advised = advised_heap_end.load(std::memory_order_relaxed);
  if(advised == 0 || end == advised || end == std::uintptr_t(-1)) return;
  if(!advised_heap_end.compare_exchange_strong(advised, end, std::memory_order_relaxed)) return;
  if(end < advised) return;   // trimmed: its next growth is advised from the new end
  const std::uintptr_t begin = advised & ~(page - 1);
  madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);   // advice: a refusal changes nothing
}

// The advice for a block just allocated (or null): on its own mapping, or on the heap it grew.
void* advise(void* p, std::size_t n)
{
  if(p == nullptr || !advise_huge_pages.load(std::memory_order_relaxed)) return p;
  if(n >= mapped_block_threshold)
    advise_mapped_block(p, n);
  else
    advise_heap_growth();
  return p;
}

// Whether freed 2 MB blocks go back to the hypervisor: a virtio balloon device (id 5) that
// offers free page reporting (feature bit 5), and a reporting order of at most 9 (2 MB).
bool host_takes_back_huge_pages()
{
  std::ifstream order_file("/sys/module/page_reporting/parameters/page_reporting_order");
  int order = 0;
  if(!(order_file >> order) || order > 9) return false;
  DIR* devices = opendir("/sys/bus/virtio/devices");
  if(devices == nullptr) return false;
  bool reporting = false;
  while(const dirent* entry = readdir(devices))
  {
    const std::string device = std::string("/sys/bus/virtio/devices/") + entry->d_name;
    std::string id, features;
    std::ifstream(device + "/device") >> id;
    std::ifstream(device + "/features") >> features;   // one character per feature bit, bit 0 first
    if(id == "0x0005" && features.size() > 5 && features[5] == '1') reporting = true;
  }
  closedir(devices);
  return reporting;
}

} // namespace
#endif

/// Called first thing in `main()`.
void set_large_block_policy()
{
#ifndef SVD_PROGRAM_KEEP_DEFAULT_ALLOCATION
  mallopt(M_MMAP_THRESHOLD, static_cast<int>(mapped_block_threshold));
  mallopt(M_TRIM_THRESHOLD, static_cast<int>(heap_kept));
  mallopt(M_TOP_PAD, static_cast<int>(heap_step));
  const char* huge_pages = std::getenv("SVD_HUGE_PAGES");
  if(huge_pages != nullptr && std::strcmp(huge_pages, "0") == 0) return;
  if(!(huge_pages != nullptr && std::strcmp(huge_pages, "1") == 0) && host_takes_back_huge_pages()) return;
  advised_heap_end.store(reinterpret_cast<std::uintptr_t>(sbrk(0)), std::memory_order_relaxed);   // from here up
  advise_huge_pages.store(true, std::memory_order_relaxed);
#endif
}

} // namespace svd_program

#ifndef SVD_PROGRAM_KEEP_DEFAULT_ALLOCATION
// glibc's allocator, with the advice on large blocks: the program's definitions replace the
// library's for every caller, the C++ allocation functions, Eigen, Spectra and METIS included
// (glibc manual, "Replacing malloc"), and they call glibc's own, so every block still comes
// from, and goes back to, the one allocator.
extern "C" {
void* malloc(std::size_t n) noexcept { return svd_program::advise(svd_program::__libc_malloc(n), n); }
void* calloc(std::size_t count, std::size_t size) noexcept
{
  void* p = svd_program::__libc_calloc(count, size);
  return p == nullptr ? p : svd_program::advise(p, count * size);   // no overflow: it succeeded
}
void* realloc(void* p, std::size_t n) noexcept { return svd_program::advise(svd_program::__libc_realloc(p, n), n); }
void free(void* p) noexcept { svd_program::__libc_free(p); }
}
#endif
