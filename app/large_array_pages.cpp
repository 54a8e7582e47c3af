// The rangesim executable's memory on transparent huge pages: its new[] for large arrays, and its
// heap (heap_on_huge_pages).
//
// Why: SystemC's library allocates and clears a 3 MB scratch heap when it is loaded
// (sc_core::sc_temp_heap), before main, in every rangesim process. With 4 KB pages that is 768
// page faults, which on a virtual machine cost about a third of the process start-up (measured:
// `evaluate tof-lockin --trials 2` 44 ms of CPU, 1279 page faults; with this 32 ms, 518).
// Start-up counts in every short command and in the bench's whole-process figures.
//
// What: arrays of 2 MB or more are allocated 2 MB-aligned in whole 2 MB pages with
// madvise(MADV_HUGEPAGE) (honoured where transparent huge pages are on "madvise" or "always",
// ignored otherwise); anything smaller, and any failure, takes the default path. Deallocation is
// unchanged: the default operator delete[] frees through free(), which takes aligned_alloc's
// memory. Only this executable replaces new[] (a replaceable allocation function, [new.delete]);
// the libraries and the Python module keep the default.
#include "app/large_array_pages.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <new>

#ifdef __linux__
#include <sys/mman.h>
#endif
#if defined(__linux__) && defined(__GLIBC__)
#include <malloc.h>
#include <unistd.h>
#endif

void* operator new[](std::size_t n) {
#ifdef __linux__
  constexpr std::size_t kHuge = std::size_t{1} << 21;
  if (n >= kHuge) {
    const std::size_t rounded = (n + kHuge - 1) & ~(kHuge - 1);
    if (void* p = std::aligned_alloc(kHuge, rounded)) {
      madvise(p, rounded, MADV_HUGEPAGE);  // advice only
      return p;
    }
  }
#endif
  return ::operator new(n);
}

// The heap. Why: a process's results (the kernel's frame results, the maps, the points table, the
// output buffers) are tens of MB of freshly touched heap, and on a virtual machine a 4 KB page's
// first touch costs about 13 us (measured: `simulate ls-conventional --scene scenes/plane.toml
// --kernel-only` took 2450 page faults and 85 ms of CPU, 620 and 57 ms with this). What: the heap
// is grown once by 64 MB of address space (M_TOP_PAD; memory is only used where touched) and that
// range is advised onto transparent huge pages, as glibc's own glibc.malloc.hugetlb=1 tunable
// does for every extension; allocations up to 32 MB stay in it (M_MMAP_THRESHOLD) and freed
// memory is kept up to 128 MB (M_TRIM_THRESHOLD) rather than returned and faulted in again. Growth
// beyond the 64 MB takes ordinary pages. glibc on Linux only; advice, ignored where transparent
// huge pages are off. Only `simulate` asks for it: a Monte Carlo evaluation allocates its large
// arrays in its worker threads' own arenas, where the main heap's advice does not reach, and there
// the larger mmap threshold cost 5 ms of 64 (`evaluate tof-lockin --trials 1e6`, more page faults).
void rangesim::app::heap_on_huge_pages() {
#if defined(__linux__) && defined(__GLIBC__)
  constexpr std::size_t kHuge = std::size_t{1} << 21;
  constexpr int kPad = 64 << 20;
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 128 << 20);
  mallopt(M_TOP_PAD, kPad);
  void* p = std::malloc(16 << 20);  // below the mmap threshold: grows the heap by it and the pad
  if (p == nullptr) return;
  const auto first = (reinterpret_cast<std::uintptr_t>(p) + kHuge - 1) & ~(kHuge - 1);
  const auto top = reinterpret_cast<std::uintptr_t>(sbrk(0));
  if (top > first) madvise(reinterpret_cast<void*>(first), (top - first) & ~(kHuge - 1), MADV_HUGEPAGE);
  std::free(p);
#endif
}
