#pragma once
// A two-sample comparison (app/bench/bench_stats.h) in one line, for a failure message or the
// printed record of a skipping test.
#include <gtest/gtest.h>

#include <string>

#include "app/bench/bench_stats.h"

namespace rangesim::app::bench {

// The comparison in one line, for a failure message or the printed record.
inline std::string describe(const TwoSampleComparison& c) {
  return ::testing::PrintToString(c.mean_z) + " SE (mean), " + ::testing::PrintToString(c.var_z) +
         " SE (variance), KS p " + ::testing::PrintToString(c.ks_p);
}

}  // namespace rangesim::app::bench
