// The kernel's cycle count is what the analytic frame timing (golden/common/frame_timing.h) charges
// for one sampling: latch + search + addresses_per_sampling * address_bits.
#include <gtest/gtest.h>

#include "core/ls_conventional/config.h"
#include "golden/ls_conventional/frame_timing.h"
#include "systemc/common/address_search_kernel.h"

TEST(AddressSearchKernel, AgreesWithGoldenFrameTiming) {
  const rangesim::FrameTimingConfig timing;
  rangesim::AddressSearchConfig search;
  search.address_bits = timing.address_bits;
  search.addresses_per_sampling = timing.addresses_per_sampling;
  rangesim::systemc::AddressSearchKernel k(search, timing.search_cycles);
  rangesim::systemc::ActivationRow row(search.columns);
  row.set(search.columns / 2);
  for (int samplings : {1, 2, 4, 8}) {
    long long cycles = timing.reset_cycles + timing.output_cycles;
    for (int n = 0; n < samplings; ++n) {
      const long long before = k.edges();
      k.run(row);  // the comparator latch is the start cycle
      cycles += k.edges() - before;
    }
    EXPECT_EQ(rangesim::golden::frame_timing(timing, samplings).frame_cycles, cycles) << samplings;
  }
}
