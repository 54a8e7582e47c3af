// Measured frame timing of the clock-level kernel ==
// golden::frame_timing_tof_lockin, cycle for cycle, over pulse widths,
// accumulation counts, ADC bits, duty cycles and both stepping modes.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include "core/user_error.h"
#include "golden/common/evaluate_sensor.h"
#include "lockin_sc_test_util.h"
#include "golden/tof_lockin/model.h"

namespace rangesim::systemc::lockin {
namespace {

using test::Edit;

void check_timing(const std::vector<Edit>& edits, const LockinSimOptions& opt) {
  const ParamSet params = test::edited_params(edits);
  const TofLockinConfig cfg = tof_lockin_from_params(params);
  const golden::FrameTiming ft = golden::frame_timing_tof_lockin(params);
  const long long frames = 3;
  TofLockinSensorKernel k(cfg, opt, 2, 3, test::uniform(6, 1e-10, 1e-11, 3.0), frames);
  k.run();
  ASSERT_TRUE(k.done());
  ASSERT_EQ(static_cast<long long>(k.frame_records().size()), frames);
  ASSERT_EQ(ft.phases.size(), static_cast<std::size_t>(kPhaseCount));
  for (const LockinFrameRecord& r : k.frame_records()) {
    long long sum = 0;
    for (int p = 0; p < kPhaseCount; ++p) {
      EXPECT_EQ(ft.phases[p].name, phase_name(static_cast<LockinPhase>(p + 1)));
      EXPECT_EQ(r.cycles[p], ft.phases[p].cycles) << ft.phases[p].name << " frame " << r.frame;
      sum += r.cycles[p];
    }
    EXPECT_EQ(sum, ft.frame_cycles);
    EXPECT_NEAR(r.end_s - r.start_s, ft.frame_time_s, 1e-12 * ft.frame_time_s);
  }
  EXPECT_NEAR(k.time_s(), frames * ft.frame_time_s, 1e-12 * frames * ft.frame_time_s);
  EXPECT_EQ(ft.frames_per_range_map, cfg.readout.ambient_subtraction ? 2 : 1);
  EXPECT_EQ(k.range_maps(), cfg.readout.ambient_subtraction ? 1 : 3);
}

TEST(LockinTiming, MatchesGoldenOverPulseWidthsAccumulationsAdcBits) {
  for (const char* t0 : {"10e-9", "40e-9", "100e-9"})
    for (const char* nacc : {"1", "7", "50"})
      for (int bits : {8, 12}) {
        SCOPED_TRACE(fmt::format("T0 {} N_acc {} bits {}", t0, nacc, bits));
        const std::vector<Edit> e = {{"source", "pulse_width_s", t0},
                                     {"gates", "accumulations_per_frame", nacc},
                                     {"readout", "adc_bits", std::to_string(bits)},
                                     {"readout", "adc_conversion_cycles", std::to_string(1 << bits)},
                                     {"pixel", "rows", "5"}};
        check_timing(e, LockinSimOptions{false, true, false, 1});
        check_timing(e, LockinSimOptions{true, true, true, 1});
      }
}

TEST(LockinTiming, TickingCountsTheSameCycles) {
  const std::vector<Edit> e = {{"source", "pulse_width_s", "40e-9"},
                               {"gates", "accumulations_per_frame", "3"},
                               {"readout", "adc_bits", "8"},
                               {"readout", "adc_conversion_cycles", "256"},
                               {"pixel", "rows", "3"}};
  check_timing(e, LockinSimOptions{true, false, false, 1});
}

TEST(LockinTiming, DutyHalfAndNoAmbientFrame) {
  check_timing({{"source", "duty_cycle", "0.5"}, {"gates", "accumulations_per_frame", "4"}, {"pixel", "rows", "2"}},
               LockinSimOptions{true, false, false, 1});
  check_timing({{"readout", "ambient_subtraction", "false"}, {"pixel", "rows", "2"}},
               LockinSimOptions{true, true, false, 1});
}

TEST(LockinTiming, PresetFrameRateIsThePublished30fps) {
  const golden::FrameTiming ft = golden::frame_timing_tof_lockin(test::edited_params({}));
  EXPECT_EQ(ft.frame_cycles, 50 * 100 + 252LL * (4096 + 672));
  EXPECT_NEAR(ft.frame_access_rate_Hz, 29.9, 0.05);
  EXPECT_NEAR(ft.range_maps_per_s, ft.frame_access_rate_Hz / 2, 1e-9);
  EXPECT_EQ(ft.frames_per_range_map, 2);
}

TEST(LockinTiming, PeriodOffTheClockGridIsAUserError) {
  const TofLockinConfig cfg = test::edited_config({{"source", "duty_cycle", "0.3"}});
  EXPECT_THROW(LockinGateGeneratorKernel{cfg}, rangesim::UserError);
}

TEST(LockinGates, PatternOfOnePeriod) {
  const TofLockinConfig cfg = test::edited_config({{"source", "pulse_width_s", "40e-9"}});  // 4 + 4 + 32 cycles
  LockinGateGeneratorKernel g(cfg);
  g.start();
  for (long long c = 0; c < g.period_cycles(); ++c) {
    EXPECT_EQ(g.tx1(), c < 4) << c;
    EXPECT_EQ(g.tx2(), c >= 4 && c < 8) << c;
    EXPECT_EQ(g.txd(), c >= 8) << c;
    EXPECT_EQ(g.light(), c < 4) << c;
    EXPECT_EQ(g.tx1() + g.tx2() + g.txd(), 1);  // exactly one gate open
    g.advance(1);
  }
  EXPECT_EQ(g.accumulation(), 1);
}

}  // namespace
}  // namespace rangesim::systemc::lockin

namespace rangesim::systemc::lockin {
namespace {
TEST(LockinTiming, GoldenScheduleRejectsPeriodOffTheClockGrid) {
  EXPECT_THROW(golden::frame_timing_tof_lockin(test::edited_params({{"source", "duty_cycle", "0.3"}})),
               rangesim::UserError);
}
}  // namespace
}  // namespace rangesim::systemc::lockin
