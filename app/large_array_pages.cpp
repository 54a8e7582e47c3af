// The rangesim executable's new[] for large arrays: backed by transparent huge pages.
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
#include <cstddef>
#include <cstdlib>
#include <new>

#ifdef __linux__
#include <sys/mman.h>
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
