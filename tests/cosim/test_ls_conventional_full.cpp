// One full-size ls-conventional frame access (375 x 365, four samplings) co-simulated: the
// uninstrumented Vls_conventional_readout beside the clock-level model.
#include <gtest/gtest.h>

#include <cstdio>

#include "tb/ls_conventional/cosim.h"

namespace rangesim::tb {
namespace {

TEST(LsConventionalCosimFull, OneFrameAccessFourSamplings) {
  LsConventionalCosimOptions o;
  o.full_size = true;
  o.frames = 1;
  o.seed = 1;  // noise-free: every row also checked against golden
  const auto res = run_ls_conventional_cosim(o);
  const CosimReport& r = res.report;
  EXPECT_EQ(res.frames, 1);
  EXPECT_EQ(r.cycles, 100u);  // 4 + 4 (1 + 2 + 18) + 12
  EXPECT_EQ(r.mismatches, 0u);
  EXPECT_EQ(r.golden_checks, 365u);
  EXPECT_GT(r.transactions, 365u);
  std::printf("full-size frame access co-simulated: %.2f s wall (elaboration included)\n", res.wall_time_s);
}

}  // namespace
}  // namespace rangesim::tb
