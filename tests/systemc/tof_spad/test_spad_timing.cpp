// Measured frame timing of the kernel's sequencer == golden::frame_timing_tof_spad, cycle for cycle.
#include <gtest/gtest.h>

#include "golden/common/evaluate_sensor.h"
#include "spad_clock_helpers.h"
#include "golden/tof_spad/model.h"

namespace rangesim::systemc::spad {
namespace {

TEST(SpadTiming, KernelFrameCyclesEqualGoldenSchedule) {
  for (double integ : {1e-5, 2.5e-5, 1e-4}) {
    const ParamSet p = test::small_preset(integ, 6);
    const golden::FrameTiming gt = golden::frame_timing_tof_spad(p);
    const TofSpadKernel k(tof_spad_from_params(p), 6, static_cast<int>(p.integer("array.columns")), {});
    PixelSelection sel{{1, 4}, 2, 3};
    const FrameResult f = k.run_frame(0, sel, test::flat(1e6, 1e6, 20e-9));
    ASSERT_EQ(gt.phases.size(), 2u);
    EXPECT_EQ(f.phase_cycles[0], gt.phases[0].cycles) << gt.phases[0].name;
    EXPECT_EQ(f.phase_cycles[1], gt.phases[1].cycles) << gt.phases[1].name;
    EXPECT_EQ(f.cycles, gt.frame_cycles);
    EXPECT_DOUBLE_EQ(k.clock_Hz(), gt.clock_Hz);
    EXPECT_NEAR(f.cycles / k.clock_Hz(), gt.frame_time_s, 1e-12 * gt.frame_time_s);
  }
}

TEST(SpadTiming, PresetScheduleFigures) {
  const golden::FrameTiming gt = golden::frame_timing_tof_spad(test::preset());
  // 128 rows x (2e6 laser cycles x 256 + 4 x 256 words x 103 cycles)
  EXPECT_EQ(gt.phases[0].name, "laser_cycles");
  EXPECT_EQ(gt.phases[0].cycles, 128LL * 2000000 * 256);
  EXPECT_EQ(gt.phases[1].cycles, 128LL * 1024 * 103);
  EXPECT_EQ(gt.frames_per_range_map, 1);
  EXPECT_NEAR(gt.frame_access_rate_Hz, 1.0 / gt.frame_time_s, 1e-12);
}

TEST(SpadTiming, TdcCodeMatchesGoldenEdges) {
  const ParamSet p = test::preset();
  const TofSpadKernel k(tof_spad_from_params(p), 1, 4, {});
  const auto& b = k.bins();
  for (int i = 0; i < b.phase_bins; ++i) {
    const double e0 = b.edges_s[static_cast<size_t>(i)], e1 = b.edges_s[static_cast<size_t>(i) + 1];
    EXPECT_EQ(k.phase_bin(e0), i);
    EXPECT_EQ(k.phase_bin(0.5 * (e0 + e1)), i);
    EXPECT_EQ(k.phase_bin(std::nextafter(e1, 0.0)), i);
  }
}

}  // namespace
}  // namespace rangesim::systemc::spad
