#pragma once
// SystemC allows one elaboration per process. ctest runs every test in its
// own process (gtest_discover_tests); run by hand, a second elaborating test in the same process
// skips itself instead of failing. One flag for the whole binary (inline function, C++17).
#include <gtest/gtest.h>

namespace rangesim::systemc::test {

inline bool claim_elaboration() {
  static bool used = false;
  const bool first = !used;
  used = true;
  return first;
}

}  // namespace rangesim::systemc::test

#define REQUIRE_FRESH_ELABORATION()                    \
  if (!::rangesim::systemc::test::claim_elaboration()) \
  GTEST_SKIP() << "one SystemC elaboration per process: run this test alone (ctest does)"
